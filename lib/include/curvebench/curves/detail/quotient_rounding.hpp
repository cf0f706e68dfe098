// Private: the rounding bound of a rational curve C = A / W evaluated as a quotient of two
// polynomial curves (rational_bezier.hpp: numerator and denominator by de Casteljau; nurbs.hpp: the
// homogeneous B-spline by de Boor), and of its derivative C' = (A' - W' C) / W, from bounds on the
// errors of A, W, A', W' and on the sizes involved (core/curve.hpp, rounding_bound).
//   C:  |A^/W^ - A/W| <= (dA + |C| dW) / (W - dW), plus the division's rounding;
//   C': the product W'C and the difference round once each, the errors of A', W' and C enter through
//       (A' - W'C), and the division as for C.
// With W >= min w (positive weights, a partition of unity) and |C| <= max |P| (convex hull), the
// bound is a constant; +inf when dW could reach min w (no bound).
#pragma once

#include "curvebench/core/real.hpp"

#include <array>
#include <limits>

namespace curvebench::detail {

template <class Real>
struct quotient_rounding {
  Real a0, w0;          // bounds on the errors of A and W
  Real a1, w1;          // of A' and W'
  Real max_a1, max_w1;  // bounds on |A'| and |W'|
  Real max_c;           // bound on |C| (the largest control point)
  Real min_w;           // lower bound on W (the smallest weight)
};

/// {bound on C's rounding, bound on C''s}, each with 1% for second-order terms.
template <class Real>
[[nodiscard]] std::array<Real, 2> quotient_rounding_bound(const quotient_rounding<Real>& q) {
  const Real eps = epsilon<Real>();
  const Real wlow = q.min_w - q.w0;
  if (!(wlow > Real(0))) return {std::numeric_limits<Real>::infinity(), std::numeric_limits<Real>::infinity()};
  const Real margin = Real(101) / Real(100);
  const Real b0 = (q.a0 + q.max_c * q.w0) / wlow + eps * q.max_c;
  const Real n = q.max_a1 + q.max_w1 * q.max_c;  // |A' - W'C|
  const Real dn = q.a1 + (q.max_w1 + q.w1) * b0 * margin + q.max_c * q.w1 + eps * n;
  const Real b1 = dn / wlow + n * q.w0 / (wlow * q.min_w) + eps * (n + dn) / wlow;
  return {b0 * margin, b1 * margin};
}

}  // namespace curvebench::detail
