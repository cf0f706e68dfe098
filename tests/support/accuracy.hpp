// Test support: closeness in ulps / relative error against a value computed in higher precision.
//
// The reference is always given in real50 (or any wider type); the actual value is in the Real
// under test. Distances are measured in units of the Real's epsilon so that one tolerance table
// serves float, double, long double and real50:
//   - ulps(actual, ref)             |actual - ref| / (eps(Real) * |ref|)   (relative, in ulps)
//   - scaled_ulps(actual, ref, s)   |actual - ref| / (eps(Real) * s)       (relative to a scale s,
//                                    e.g. the curve's extent, for values that may cross zero)
// On failure both values are printed in hexfloat (IEEE types) or 50 digits, with the distance.
#pragma once

#include "curvebench/core/point.hpp"
#include "curvebench/core/real.hpp"
#include "curvebench/reference/multiprecision.hpp"

#include <gtest/gtest.h>

#include <iomanip>
#include <sstream>
#include <string>

namespace curvebench::testing {

#ifndef CURVEBENCH_SANITIZE_TYPED_REALS
/// The four Real types every numerical family is tested on.
using all_reals = ::testing::Types<float, double, long double, real50>;
/// The IEEE types (for tests whose reference is a real50 instantiation of the same template).
using ieee_reals = ::testing::Types<float, double, long double>;
#else
// The sanitizer build (scripts/test.sh --sanitize, tests/CMakeLists.txt) runs the typed tests in
// float and double only. What AddressSanitizer and UBSan look for (an index out of range, a read
// past a buffer, a signed overflow, a bad cast) follows the template's control flow, which is the
// same for every Real; long double and real50 run in scripts/test.sh's own build, and the
// real50 references of every test still run here. Measured: test_bspline.cpp compiles in 31 s
// instead of 60 s at -Og with both sanitizers, test_cardinal_spline.cpp in 45 s instead of 81 s.
using all_reals = ::testing::Types<float, double>;
using ieee_reals = ::testing::Types<float, double>;
#endif

/// Whether this is the sanitizer build: tests whose cost is many 50-digit reference integrals over
/// sample points that all take the same code path may thin those points there (say so where they
/// do); the -O2 build runs them all.
#ifdef CURVEBENCH_SANITIZE_TYPED_REALS
inline constexpr bool sanitizer_build = true;
#else
inline constexpr bool sanitizer_build = false;
#endif

/// Text for diagnostics: hexfloat and decimal for IEEE types, 50 digits for multiprecision.
template <class T>
std::string exact_text(const T& x) {
  std::ostringstream os;
  if constexpr (std::is_floating_point_v<T>) {
    os << std::hexfloat << x << " (" << std::defaultfloat << std::setprecision(std::numeric_limits<T>::max_digits10)
       << x << ")";
  } else {
    os << std::setprecision(std::numeric_limits<T>::digits10) << x;
  }
  return os.str();
}

/// |actual - ref| measured in eps(Real) units of `scale` (scale > 0), computed in real50.
template <class Real>
real50 scaled_ulps(const Real& actual, const real50& ref, const real50& scale) {
  using std::abs;
  return abs(real50(actual) - ref) / (real50(epsilon<Real>()) * scale);
}

/// Relative distance in eps(Real) units; for ref == 0 the scale is 1.
template <class Real>
real50 ulps(const Real& actual, const real50& ref) {
  using std::abs;
  const real50 s = ref == 0 ? real50(1) : real50(abs(ref));
  return scaled_ulps(actual, ref, s);
}

/// Asserts |actual - ref| <= max_ulps * eps(Real) * |ref|.
template <class Real>
::testing::AssertionResult within_ulps(const Real& actual, const real50& ref, double max_ulps) {
  const real50 d = ulps(actual, ref);
  if (d <= real50(max_ulps)) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << "actual    " << exact_text(actual) << "\nreference " << exact_text(ref)
                                       << "\ndistance  " << exact_text(static_cast<double>(d)) << " ulps > allowed "
                                       << max_ulps;
}

/// Asserts |actual - ref| <= max_ulps * eps(Real) * scale (errors relative to a problem scale).
template <class Real>
::testing::AssertionResult within_scaled_ulps(const Real& actual, const real50& ref, const real50& scale,
                                              double max_ulps) {
  const real50 d = scaled_ulps(actual, ref, scale);
  if (d <= real50(max_ulps)) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << "actual    " << exact_text(actual) << "\nreference " << exact_text(ref)
                                       << "\nscale     " << exact_text(scale) << "\ndistance  "
                                       << static_cast<double>(d) << " eps*scale > allowed " << max_ulps;
}

/// Asserts every coordinate of a point is within max_ulps * eps(Real) * scale of the reference.
template <class Real, int Dim>
::testing::AssertionResult point_within(const point<Real, Dim>& actual, const point<real50, Dim>& ref,
                                        const real50& scale, double max_ulps) {
  for (int d = 0; d < Dim; ++d) {
    auto r = within_scaled_ulps(actual[d], ref[d], scale, max_ulps);
    if (!r) return r << "\n(coordinate " << d << ")";
  }
  return ::testing::AssertionSuccess();
}

/// Asserts |actual - ref| <= rel * max(|ref|, floor) (a plain relative-error check).
template <class Real>
::testing::AssertionResult within_relative(const Real& actual, const real50& ref, double rel, double floor = 0) {
  using std::abs;
  using std::max;
  const real50 bound = real50(rel) * max(real50(abs(ref)), real50(floor));
  const real50 err = abs(real50(actual) - ref);
  if (err <= bound) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << "actual    " << exact_text(actual) << "\nreference " << exact_text(ref)
                                       << "\nerror     " << static_cast<double>(err) << " > allowed "
                                       << static_cast<double>(bound);
}

}  // namespace curvebench::testing
