// Named cubic basis matrices and conversions between them.
// Convention (everywhere in curvebench): P(t) = T(t) · M · G, T(t) = [1 t t^2 t^3], t in [0, 1],
// G the 4 x Dim geometry (one control item per row); row k of M gives the coefficient of t^k
// (seeds 000 and 002 print [t^3 t^2 t 1], the same M with its rows reversed). Geometries:
// hermite [P0, P1, T0, T1]; bezier [P0, P1, P2, P3]; cardinal [P_-1, P0, P1, P2] with tangents
// s (P1 - P_-1), s (P2 - P0) (s = 1/2 Catmull-Rom); bspline [P_-1, P0, P1, P2] (uniform).
// geometry_conversion gives G_b = M_b^-1 M_a G_a (the same curve in another basis).
// Sources: seeds 000, 001, 002 (seed 002's Catmull-Rom matrix lacks the factor 1/2);
// Foley et al. (1990), 11.2. Cost: O(1). Accuracy: exact rationals, one rounding per entry.
#pragma once

#include "curvebench/core/error.hpp"
#include "curvebench/core/real.hpp"

#include <Eigen/Core>
#include <Eigen/LU>

namespace curvebench::basis {

template <class Real>
using matrix4 = Eigen::Matrix<Real, 4, 4>;

/// The power row T(t) = [1 t t^2 t^3] or its derivative of the given order (d/dt T = [0 1 2t 3t^2]...).
template <class Real>
[[nodiscard]] Eigen::Matrix<Real, 1, 4> power_row(const Real& t, int order = 0) {
  validate::derivative_order(order);
  Eigen::Matrix<Real, 1, 4> row = Eigen::Matrix<Real, 1, 4>::Zero();
  // d^order/dt^order t^k = k!/(k-order)! t^(k-order)
  Real tp(1);
  for (int k = order; k < 4; ++k) {
    Real falling(1);
    for (int j = 0; j < order; ++j) falling *= Real(k - j);
    row(k) = falling * tp;
    tp *= t;
  }
  return row;
}

namespace detail {
template <class Real>
matrix4<Real> integer_matrix(const int (&m)[4][4], const Real& scale) {
  matrix4<Real> r;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) r(i, j) = Real(m[i][j]) * scale;
  return r;
}
}  // namespace detail

/// Hermite: a0 = P0, a1 = T0, a2 = -3P0 + 3P1 - 2T0 - T1, a3 = 2P0 - 2P1 + T0 + T1.
template <class Real>
[[nodiscard]] matrix4<Real> hermite_matrix() {
  static constexpr int m[4][4] = {{1, 0, 0, 0}, {0, 0, 1, 0}, {-3, 3, -2, -1}, {2, -2, 1, 1}};
  return detail::integer_matrix<Real>(m, Real(1));
}

/// Bezier: the expanded cubic Bernstein polynomials.
template <class Real>
[[nodiscard]] matrix4<Real> bezier_matrix() {
  static constexpr int m[4][4] = {{1, 0, 0, 0}, {-3, 3, 0, 0}, {3, -6, 3, 0}, {-1, 3, -3, 1}};
  return detail::integer_matrix<Real>(m, Real(1));
}

/// Cardinal spline with tangent scale s: Hermite applied to [P0, P1, s(P1 - P_{-1}), s(P2 - P0)].
template <class Real>
[[nodiscard]] matrix4<Real> cardinal_matrix(const Real& s) {
  validate::finite("s", s);
  matrix4<Real> k = matrix4<Real>::Zero();  // Hermite geometry = k · cardinal geometry
  k(0, 1) = Real(1);
  k(1, 2) = Real(1);
  k(2, 0) = -s;
  k(2, 2) = s;
  k(3, 1) = -s;
  k(3, 3) = s;
  return hermite_matrix<Real>() * k;
}

/// Catmull-Rom: the cardinal matrix with s = 1/2.
template <class Real>
[[nodiscard]] matrix4<Real> catmull_rom_matrix() {
  return cardinal_matrix<Real>(Real(1) / Real(2));
}

/// Uniform cubic B-spline: (1/6) [1 4 1 0; -3 0 3 0; 3 -6 3 0; -1 3 -3 1].
template <class Real>
[[nodiscard]] matrix4<Real> uniform_bspline_matrix() {
  static constexpr int m[4][4] = {{1, 4, 1, 0}, {-3, 0, 3, 0}, {3, -6, 3, 0}, {-1, 3, -3, 1}};
  return detail::integer_matrix<Real>(m, Real(1) / Real(6));
}

/// The matrix C with G_to = C · G_from for the same curve: C = M_to^{-1} M_from.
/// Throws invalid_input when M_to is singular (e.g. a cardinal matrix with s = 0).
template <class Real>
[[nodiscard]] matrix4<Real> geometry_conversion(const matrix4<Real>& from, const matrix4<Real>& to) {
  Eigen::FullPivLU<matrix4<Real>> lu(to);
  if (!lu.isInvertible())
    validate::fail("to: basis matrix is singular (rank " + std::to_string(lu.rank()) +
                   " of 4); geometry cannot be expressed in it");
  return lu.solve(from);
}

/// Bezier control polygon -> Hermite geometry: [P0, P3, 3(P1 - P0), 3(P3 - P2)].
template <class Real>
[[nodiscard]] matrix4<Real> bezier_to_hermite() {
  static constexpr int m[4][4] = {{1, 0, 0, 0}, {0, 0, 0, 1}, {-3, 3, 0, 0}, {0, 0, -3, 3}};
  return detail::integer_matrix<Real>(m, Real(1));
}

}  // namespace curvebench::basis
