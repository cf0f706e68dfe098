// Closed-form arc lengths, the independent references of the arc-length tests: a segment |b - a|;
// a straight line traversed back and forth (p0 + x(t) d, the total travel of x between the zeros
// of x'); a circular arc r |theta| and s(u) of its rational quadratic Bezier form; a quadratic
// Bezier (parabola) by the integral of sqrt(quadratic) with Lagrange's identity for the
// discriminant, the collinear and straight cases separately; a helix sqrt(r^2 w^2 + c^2) |du|; the
// semicubical cusp (t^2, t^3) by an odd antiderivative continuous through the cusp. The
// derivations are with the functions.
// Sources: Farin (2002), conics as rational quadratics; Gradshteyn & Ryzhik 2.262.
// Cost: O(1) (O(degree) for the straight polynomial). Accuracy: a few ulps of Real (use real50
// for 50-digit references).
#pragma once

#include "curvebench/core/error.hpp"
#include "curvebench/core/point.hpp"
#include "curvebench/core/real.hpp"

#include <boost/math/constants/constants.hpp>

#include <algorithm>
#include <array>
#include <cstddef>
#include <span>
#include <vector>

namespace curvebench::reference {

template <class Real, int Dim>
[[nodiscard]] Real segment_length(const point<Real, Dim>& a, const point<Real, Dim>& b) {
  using std::sqrt;
  const point<Real, Dim> d = b - a;
  return sqrt(d.squaredNorm());
}

/// Length of p0 + x(t) d (|d| = 1) on [t0, t1], x(t) = sum_k c_k t^k: the total travel of x.
template <class Real>
[[nodiscard]] Real straight_polynomial_length(std::span<const Real> c, const Real& t0, const Real& t1) {
  using std::abs;
  using std::sqrt;
  auto x = [&](const Real& t) {
    Real acc(0);
    for (std::size_t k = c.size(); k-- > 0;) acc = acc * t + c[k];
    return acc;
  };
  // Zeros of x' for degree <= 3 (x' at most quadratic): closed form.
  std::vector<Real> pts{t0};
  const Real a1 = c.size() > 1 ? c[1] : Real(0);
  const Real a2 = c.size() > 2 ? Real(2) * c[2] : Real(0);
  const Real a3 = c.size() > 3 ? Real(3) * c[3] : Real(0);
  if (c.size() > 4)
    validate::fail("straight_polynomial_length: degree <= 3 supported, " + std::to_string(c.size() - 1) + " given");
  std::vector<Real> roots;
  if (a3 != Real(0)) {
    const Real disc = a2 * a2 - Real(4) * a3 * a1;
    if (disc >= Real(0)) {
      const Real sq = sqrt(disc);
      const Real q = a2 >= Real(0) ? -(a2 + sq) / Real(2) : -(a2 - sq) / Real(2);  // stable pair
      if (q != Real(0))
        roots = {q / a3, a1 / q};
      else
        roots = {Real(0)};
    }
  } else if (a2 != Real(0)) {
    roots = {-a1 / a2};
  }
  std::sort(roots.begin(), roots.end());
  for (const Real& r : roots)
    if (r > t0 && r < t1) pts.push_back(r);
  pts.push_back(t1);
  Real len(0);
  for (std::size_t i = 0; i + 1 < pts.size(); ++i) len += abs(x(pts[i + 1]) - x(pts[i]));
  return len;
}

/// Circular arc length r |theta|.
template <class Real>
[[nodiscard]] Real circular_arc_length(const Real& radius, const Real& theta) {
  using std::abs;
  return abs(radius) * abs(theta);
}

/// Control data of a circular arc as a rational quadratic Bezier: center c, radius r, from angle
/// phi0 to phi0 + theta (0 < theta < pi): P0, P1, P2 and the middle weight cos(theta / 2).
template <class Real>
struct rational_arc {
  point<Real, 2> p0, p1, p2;
  Real weight;
};
template <class Real>
[[nodiscard]] rational_arc<Real> circular_arc_rational(const point<Real, 2>& center, const Real& radius,
                                                       const Real& phi0, const Real& theta) {
  using std::cos;
  using std::sin;
  validate::positive("radius", radius);
  validate::in_range("theta", theta, Real(0), boost::math::constants::pi<Real>());
  if (!(theta > Real(0)) || !(theta < boost::math::constants::pi<Real>()))
    validate::fail("theta = " + to_text(theta) + ": must be in (0, pi) for one rational quadratic");
  const Real mid = phi0 + theta / Real(2);
  const Real far = radius / cos(theta / Real(2));  // the end tangents meet on the bisector at r / cos(theta/2)
  rational_arc<Real> a;
  a.p0 = center + radius * point<Real, 2>(cos(phi0), sin(phi0));
  a.p1 = center + far * point<Real, 2>(cos(mid), sin(mid));
  a.p2 = center + radius * point<Real, 2>(cos(phi0 + theta), sin(phi0 + theta));
  a.weight = cos(theta / Real(2));
  return a;
}

// Circular arc of radius r and angle theta: r |theta|. As a rational quadratic Bezier with
// weights (1, cos(theta/2), 1) (`circular_arc_rational`), a proper degree-2 rational
// parameterization of the circle, like the stereographic one tan(phi/2); two such differ by a
// Mobius map, symmetric about u = 1/2 here, hence linear: tan(phi/2) = tan(theta/4) (2u - 1) with
// phi measured from the arc's bisector, so s(u) = r (2 atan(tan(theta/4) (2u - 1)) + theta/2).
/// s(u) of that rational quadratic arc: r (2 atan(tan(theta/4) (2u - 1)) + theta/2).
template <class Real>
[[nodiscard]] Real circular_arc_rational_s(const Real& radius, const Real& theta, const Real& u) {
  using std::atan;
  using std::tan;
  return radius * (Real(2) * atan(tan(theta / Real(4)) * (Real(2) * u - Real(1))) + theta / Real(2));
}

// Quadratic Bezier (parabola) P0, P1, P2: P'(t) = 2 (a + t b), a = P1 - P0, b = P0 - 2 P1 + P2;
// |P'| = 2 sqrt(Q), Q = A t^2 + B t + C, A = |b|^2, B = 2 a.b, C = |a|^2. With
// D = 4AC - B^2 = 4 |a ^ b|^2 (Lagrange's identity, computed that way: no cancellation) > 0,
//   integral sqrt(Q) = (2At + B) sqrt(Q) / (4A) + D / (8 A^(3/2)) asinh((2At + B) / sqrt(D)),
// derived by differentiating (the asinh term contributes D / (8 A sqrt(Q)), using
// D + (2At + B)^2 = 4 A Q). D = 0 (collinear control points): sqrt(Q) = sqrt(A) |t - t*|,
// t* = -B / (2A), integrated piecewise. A = 0: straight, uniform speed 2 sqrt(C).
/// Arc length from t = 0 to t of the quadratic Bezier P0, P1, P2 (t in [0, 1]).
template <class Real, int Dim>
[[nodiscard]] Real quadratic_bezier_length(const point<Real, Dim>& p0, const point<Real, Dim>& p1,
                                           const point<Real, Dim>& p2, const Real& t = Real(1)) {
  using std::abs;
  using std::asinh;
  using std::sqrt;
  const point<Real, Dim> a = p1 - p0;
  const point<Real, Dim> b = p0 - Real(2) * p1 + p2;
  const Real A = b.squaredNorm();
  const Real B = Real(2) * a.dot(b);
  const Real C = a.squaredNorm();
  if (A == Real(0)) return Real(2) * sqrt(C) * t;
  Real wedge(0);  // |a ^ b|^2 = sum_{i<j} (a_i b_j - a_j b_i)^2
  for (int i = 0; i < Dim; ++i)
    for (int j = i + 1; j < Dim; ++j) {
      const Real m = a[i] * b[j] - a[j] * b[i];
      wedge += m * m;
    }
  const Real D = Real(4) * wedge;
  if (D == Real(0)) {
    // sqrt(Q) = sqrt(A) |x - ts|: integral over [0, t] of |x - ts|
    const Real ts = -B / (Real(2) * A);
    auto prim = [&](const Real& x) { return (x - ts) * abs(x - ts) / Real(2); };  // antiderivative of |x - ts|
    return Real(2) * sqrt(A) * (prim(t) - prim(Real(0)));
  }
  const Real sD = sqrt(D);
  auto F = [&](const Real& x) {
    const Real q = (A * x + B) * x + C;
    const Real l = Real(2) * A * x + B;
    return l * sqrt(q) / (Real(4) * A) + D / (Real(8) * A * sqrt(A)) * asinh(l / sD);
  };
  return Real(2) * (F(t) - F(Real(0)));
}

/// Helix length: sqrt(r^2 w^2 + c^2) |u1 - u0|.
template <class Real>
[[nodiscard]] Real helix_length(const Real& radius, const Real& angular_rate, const Real& climb_rate, const Real& u0,
                                const Real& u1) {
  using std::abs;
  using std::sqrt;
  return sqrt(radius * radius * angular_rate * angular_rate + climb_rate * climb_rate) * abs(u1 - u0);
}

/// Length of the semicubical cusp (t^2, t^3) from t0 to t1 (t0 <= t1; the cusp at t = 0 may lie
/// inside): with the odd antiderivative G(t) = sign(t) ((4 + 9 t^2)^(3/2) - 8) / 27 of
/// |t| sqrt(4 + 9 t^2), continuous through the cusp, the length is G(t1) - G(t0).
template <class Real>
[[nodiscard]] Real semicubical_length(const Real& t0, const Real& t1) {
  using std::sqrt;
  auto prim = [](const Real& t) {
    const Real q = Real(4) + Real(9) * t * t;
    const Real v = (q * sqrt(q) - Real(8)) / Real(27);
    return t < Real(0) ? Real(-v) : v;
  };
  return prim(t1) - prim(t0);
}

}  // namespace curvebench::reference
