// Points and vectors of curvebench: Eigen fixed-size column vectors.
//
// `point<Real, Dim>` is `Eigen::Matrix<Real, Dim, 1>` for Dim in 1..4. Fixed size keeps every
// evaluation allocation-free; C++17 aligned new makes std::vector<point<...>> safe for the
// vectorizable sizes. Control data are stored as std::vector<point<Real, Dim>>.
#pragma once

#include "curvebench/core/real.hpp"

#include <Eigen/Core>

#include <cmath>
#include <limits>
#include <span>
#include <string_view>
#include <vector>

namespace curvebench {

/// Largest dimension the library is instantiated and tested for.
inline constexpr int max_dimension = 4;

/// Real must be a real_number (core/real.hpp): every curve family, and through the curve concept
/// every arc-length and motion template, is built on this alias, so an integer or other
/// non-floating Real is rejected here, at compile time, instead of computing with integer
/// division (Real(1) / Real(2) == 0).
template <real_number Real, int Dim>
requires(Dim >= 1 && Dim <= max_dimension) using point = Eigen::Matrix<Real, Dim, 1>;

/// A list of control points.
template <class Real, int Dim>
using point_list = std::vector<point<Real, Dim>>;

/// The zero vector of the given type (Eigen's Zero() spelled once for generic code).
template <class Real, int Dim>
[[nodiscard]] point<Real, Dim> zero_point() {
  return point<Real, Dim>::Zero();
}

/// |v|, the Euclidean norm, without the overflow and underflow of sqrt(v . v): the squares of
/// coordinates past sqrt(max) ~ 1e154 (double) overflow to inf, and those below sqrt(min) ~ 1e-154
/// fall into the subnormals or to 0, where relative accuracy is lost. The plain formula is kept
/// while v . v is a normal number far enough from both ends (no rounding beyond its own); otherwise
/// the coordinates are scaled by the largest |v_i| first, which is exact in binary arithmetic when
/// the scale is a power of two. Cost: one squaredNorm and two comparisons on the fast path.
/// Accuracy: within (Dim/2 + 2) eps of |v| relative on both paths. inf or NaN in v give inf / NaN.
template <class Real, int Dim>
[[nodiscard]] Real safe_norm_scaled(const point<Real, Dim>& v);

// The fast path of safe_norm is forced inline: it runs once per quadrature node, and GCC left it
// out of line behind a call that cost as much as the square root.
#if defined(__GNUC__)
#define CURVEBENCH_NORM_INLINE [[gnu::always_inline]] inline
#else
#define CURVEBENCH_NORM_INLINE inline
#endif

template <class Real, int Dim>
[[nodiscard]] CURVEBENCH_NORM_INLINE Real safe_norm(const point<Real, Dim>& v) {
  using std::sqrt;
  const Real s = v.squaredNorm();
  // Squares below min / eps may have lost bits in the subnormals; above max / 2^Dim they may be near inf.
  const Real lo = std::numeric_limits<Real>::min() / std::numeric_limits<Real>::epsilon();
  const Real hi = std::numeric_limits<Real>::max() / Real(16);
  if (s >= lo && s <= hi) return sqrt(s);
  return safe_norm_scaled(v);  // out of line: the fast path above inlines into every speed
}

/// The scaled path of safe_norm (any v; used when v . v is not safely normal).
template <class Real, int Dim>
[[nodiscard]] Real safe_norm_scaled(const point<Real, Dim>& v) {
  using std::abs;
  using std::sqrt;
  Real m(0);
  for (int d = 0; d < Dim; ++d) {
    const Real a = abs(v[d]);
    if (!(a <= m)) m = a;  // a NaN coordinate is kept, so the result is NaN
  }
  if (!(m > Real(0)) || !is_finite(m)) return m == Real(0) ? Real(0) : m;
  // Scale by the power of two nearest below m: exact, so only the sum and the root round.
  int e = 0;
  using std::frexp;
  using std::ldexp;
  (void)frexp(m, &e);
  Real t(0);
  for (int d = 0; d < Dim; ++d) {
    const Real x = ldexp(v[d], -e);
    t += x * x;
  }
  return ldexp(sqrt(t), e);
}

/// Converts a point to another Real type (e.g. double control data to the 50-digit reference).
/// Conversion from a narrower binary type to a wider one is exact.
template <class To, class From, int Dim>
[[nodiscard]] point<To, Dim> point_cast(const point<From, Dim>& p) {
  point<To, Dim> q;
  for (int d = 0; d < Dim; ++d) q[d] = To(p[d]);
  return q;
}

/// Converts a list of points to another Real type.
template <class To, class From, int Dim>
[[nodiscard]] point_list<To, Dim> points_cast(std::span<const point<From, Dim>> ps) {
  point_list<To, Dim> out;
  out.reserve(ps.size());
  for (const auto& p : ps) out.push_back(point_cast<To>(p));
  return out;
}

}  // namespace curvebench
