// Private helpers shared by the cubic spline families built on piecewise_cubic: the curve-concept
// forwarding base (every family IS a curve and exposes its engine), and the slope formulas of
// three-point parabolas used by cardinal / Catmull-Rom and natural splines.
#pragma once

#include "curvebench/core/curve.hpp"
#include "curvebench/core/point.hpp"
#include "curvebench/curves/piecewise_cubic.hpp"

#include <span>
#include <utility>

namespace curvebench::detail {

/// Holds the engine and forwards the curve concept to it; families derive from this.
template <class Real, int Dim>
class cubic_family {
 public:
  using real_type = Real;
  using point_type = point<Real, Dim>;
  static constexpr int dimension = Dim;
  using engine_type = piecewise_cubic<Real, Dim>;

  [[nodiscard]] interval<Real> domain() const { return engine_.domain(); }
  [[nodiscard]] std::span<const Real> breakpoints() const { return engine_.breakpoints(); }
  [[nodiscard]] point_type operator()(const Real& u) const { return engine_(u); }
  [[nodiscard]] point_type derivative(const Real& u, int order) const { return engine_.derivative(u, order); }
  /// The engine's bound on its own rounding, the family's slope errors included (core/curve.hpp).
  [[nodiscard]] Real rounding_bound(int order) const { return engine_.rounding_bound(order); }
  /// The engine's bound on |P''| over [a, b] within one segment (core/curve.hpp).
  [[nodiscard]] Real second_derivative_bound(const Real& a, const Real& b) const {
    return engine_.second_derivative_bound(a, b);
  }
  /// The evaluation engine (algorithms, batched and sorted evaluation, per-segment data).
  [[nodiscard]] const engine_type& engine() const { return engine_; }

 protected:
  explicit cubic_family(engine_type e) : engine_(std::move(e)) {}

 private:
  engine_type engine_;
};

/// Derivative at the middle knot of the parabola through (u-h0, pm), (u, p0), (u+h1, pp):
/// (h1 D0 + h0 D1) / (h0 + h1), D0 = (p0 - pm)/h0, D1 = (pp - p0)/h1 (seed 000 with its erratum fixed).
template <class Real, int Dim>
[[nodiscard]] point<Real, Dim> parabola_slope_mid(const Real& h0, const Real& h1, const point<Real, Dim>& pm,
                                                  const point<Real, Dim>& p0, const point<Real, Dim>& pp) {
  const point<Real, Dim> d0 = (p0 - pm) / h0;
  const point<Real, Dim> d1 = (pp - p0) / h1;
  return (h1 * d0 + h0 * d1) / (h0 + h1);
}

/// Derivative at the FIRST of three knots u, u+h0, u+h0+h1 of the parabola through p0, p1, p2:
/// ((2 h0 + h1) D0 - h0 D1) / (h0 + h1) (seed 000's one-sided second-order difference). The
/// derivative at the LAST knot is the mirror image: ((2 h1 + h0) D1 - h1 D0) / (h0 + h1).
template <class Real, int Dim>
[[nodiscard]] point<Real, Dim> parabola_slope_start(const Real& h0, const Real& h1, const point<Real, Dim>& p0,
                                                    const point<Real, Dim>& p1, const point<Real, Dim>& p2) {
  const point<Real, Dim> d0 = (p1 - p0) / h0;
  const point<Real, Dim> d1 = (p2 - p1) / h1;
  return ((Real(2) * h0 + h1) * d0 - h0 * d1) / (h0 + h1);
}

template <class Real, int Dim>
[[nodiscard]] point<Real, Dim> parabola_slope_end(const Real& h0, const Real& h1, const point<Real, Dim>& p0,
                                                  const point<Real, Dim>& p1, const point<Real, Dim>& p2) {
  const point<Real, Dim> d0 = (p1 - p0) / h0;
  const point<Real, Dim> d1 = (p2 - p1) / h1;
  return ((Real(2) * h1 + h0) * d1 - h1 * d0) / (h0 + h1);
}

/// Bounds on the rounding of the three parabola slopes above, for the families' slope errors
/// (piecewise_cubic::from_hermite). The points are data, so each divided difference D = fl(p_b -
/// p_a) / fl(h) is within 3 u of itself; the rest (products with rounded intervals, the sum, the
/// division by fl(h0 + h1), the family's scale factor) adds at most 7 roundings relative to the
/// terms: within 10 u = 5 eps of the same formula on |D0|, |D1| with the difference made a sum
/// (Higham 2002, 3.1); 8 eps keeps the 1.5x for the norms taken of computed differences.
/// `scale` is the factor the family multiplies the slope by.
template <class Real, int Dim>
[[nodiscard]] Real parabola_slope_mid_error(const Real& h0, const Real& h1, const point<Real, Dim>& pm,
                                            const point<Real, Dim>& p0, const point<Real, Dim>& pp, const Real& scale) {
  using std::abs;
  const Real d0 = safe_norm(point<Real, Dim>(p0 - pm)) / h0, d1 = safe_norm(point<Real, Dim>(pp - p0)) / h1;
  return Real(8) * epsilon<Real>() * abs(scale) * ((h1 * d0 + h0 * d1) / (h0 + h1));
}

/// For parabola_slope_start (p0 the end point) and, with the points and intervals mirrored,
/// parabola_slope_end.
template <class Real, int Dim>
[[nodiscard]] Real parabola_slope_end_error(const Real& h0, const Real& h1, const point<Real, Dim>& p0,
                                            const point<Real, Dim>& p1, const point<Real, Dim>& p2, const Real& scale) {
  using std::abs;
  const Real d0 = safe_norm(point<Real, Dim>(p1 - p0)) / h0, d1 = safe_norm(point<Real, Dim>(p2 - p1)) / h1;
  return Real(8) * epsilon<Real>() * abs(scale) * (((Real(2) * h0 + h1) * d0 + h0 * d1) / (h0 + h1));
}

}  // namespace curvebench::detail
