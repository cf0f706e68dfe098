// Real utilities shared by every numerical template in curvebench.
//
// All numerical code is templated on `Real` (float, double, long double,
// boost::multiprecision::cpp_bin_float_50). This header holds the few helpers that make one
// code path correct for all of them: the `real_number` concept, finiteness tests that work for
// multiprecision types, exact small-integer constants, and text formatting with enough digits to
// round-trip (used by error messages and test diagnostics).
//
// Generic code calls functions through ADL (`using std::abs; abs(x)`) so that Boost.Multiprecision
// overloads are found, and writes constants as Real(1) / Real(2), never as double literals.
#pragma once

#include <boost/math/special_functions/fpclassify.hpp>

#include <charconv>
#include <concepts>
#include <cstddef>
#include <iomanip>
#include <limits>
#include <sstream>
#include <string>
#include <type_traits>

namespace curvebench {

/// A floating-point type curvebench can compute in: IEEE types and Boost.Multiprecision binary
/// floats. What matters is numeric_limits (epsilon, digits) and the arithmetic operators.
template <class Real>
concept real_number =
    std::numeric_limits<Real>::is_specialized && !std::numeric_limits<Real>::is_integer && requires(Real a, Real b) {
  {a + b};
  {a * b};
  {a / b};
  { a < b } -> std::convertible_to<bool>;
};

/// True when x is neither NaN nor infinite (works for multiprecision types too).
template <class Real>
[[nodiscard]] bool is_finite(const Real& x) {
  return (boost::math::isfinite)(x);
}

/// Machine epsilon of Real.
template <class Real>
[[nodiscard]] Real epsilon() {
  return std::numeric_limits<Real>::epsilon();
}

/// The exact value of a small integer in Real (no rounding for |n| < 2^digits).
template <class Real>
[[nodiscard]] Real from_int(long long n) {
  return Real(n);
}

/// Binomial coefficient C(n, k) in Real, computed by the multiplicative formula in exact integer
/// arithmetic while it fits in 64 bits (n <= 62 covers every degree we build), then converted.
template <class Real>
[[nodiscard]] Real binomial(int n, int k) {
  if (k < 0 || k > n) return Real(0);
  if (k > n - k) k = n - k;
  unsigned long long c = 1;
  for (int j = 1; j <= k; ++j) {
    // c * (n - k + j) / j is always an integer; divide first by the gcd-free order that keeps it exact.
    c = c / static_cast<unsigned long long>(j) * static_cast<unsigned long long>(n - k + j) +
        c % static_cast<unsigned long long>(j) * static_cast<unsigned long long>(n - k + j) /
            static_cast<unsigned long long>(j);
  }
  return Real(c);
}

/// Text for a value, with enough significant digits to round-trip in its own type. A
/// multiprecision value that is a double exactly (a number the user wrote, read as double and
/// widened) shows the double's shortest text, which reads back to it: "1e+300", not the 50 digits
/// of its binary expansion.
template <class T>
[[nodiscard]] std::string to_text(const T& value) {
  if constexpr (std::numeric_limits<T>::is_specialized && !std::numeric_limits<T>::is_integer &&
                !std::is_floating_point_v<T>) {
    const double d = static_cast<double>(value);
    if ((boost::math::isfinite)(d) && T(d) == value) {
      char buf[32];
      const auto r = std::to_chars(buf, buf + sizeof buf, d);
      return std::string(buf, r.ptr);
    }
  }
  std::ostringstream os;
  if constexpr (std::numeric_limits<T>::is_specialized && !std::numeric_limits<T>::is_integer) {
    os << std::setprecision(std::numeric_limits<T>::max_digits10 > 0 ? std::numeric_limits<T>::max_digits10
                                                                     : std::numeric_limits<T>::digits10 + 2);
  }
  os << value;
  return os.str();
}

}  // namespace curvebench
