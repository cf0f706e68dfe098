// NURBS curves of any order m <= 16: C(u) = sum_i N_{i,m}(u) w_i P_i / sum_i N_{i,m}(u) w_i, w_i > 0.
// The homogeneous curve (A, W) = sum_i N_{i,m} (w_i P_i, w_i) is a B-spline in Dim + 1 dimensions
// on the same knots (indexing and conventions of bspline.hpp), evaluated by the shared engine
// (detail/bspline_core.hpp), then C = A / W. Derivatives of any order exactly, by Leibniz's
// quotient rule C^(k) = (A^(k) - sum_{i=1..k} C(k, i) W^(i) C^(k-i)) / W. nurbs_circle_9 and
// nurbs_circle_7 build exact circles (9-point square, 7-point triangle).
// Errors (invalid_input): the B-spline's, a weight count mismatch, a weight not finite or <= 0.
// Sources: seed 000 (rational quadratic conics), seed 001 (rational bases and perspective);
// Piegl & Tiller (1997), ch. 4 (eq. 4.8) and ch. 7 (circles).
// Cost: one homogeneous de Boor, O(m^2 (Dim + 1)), plus a division; O(k m^2 + k^2) for derivative
// k; no allocation for k < 32. Accuracy: value ~m ulps of the control scale times max w / min w;
// derivatives lose ~(m / h)^k like any B-spline's. rounding_bound(order), order 0 or 1
// (core/curve.hpp): de Boor's bound on each part of the homogeneous curve (A, W) and of its
// derivative (detail/bspline_core.hpp), plus the rounding of w_i P_i (u max |w_i P_i| in A, and
// (m - 1) 2u max |w_i P_i| / min knot span in A'), through the quotient
// (detail/quotient_rounding.hpp) with W >= min w_i and |C| <= max |P_i|.
#pragma once

#include "curvebench/core/curve.hpp"
#include "curvebench/core/error.hpp"
#include "curvebench/core/point.hpp"
#include "curvebench/core/real.hpp"
#include "curvebench/curves/detail/bspline_core.hpp"
#include "curvebench/curves/detail/quotient_rounding.hpp"

#include <boost/math/constants/constants.hpp>

#include <Eigen/Core>

#include <algorithm>
#include <array>
#include <cstddef>
#include <limits>
#include <span>
#include <string>
#include <utility>
#include <vector>

namespace curvebench {

template <class Real, int Dim>
class nurbs {
 public:
  using real_type = Real;
  using point_type = point<Real, Dim>;
  static constexpr int dimension = Dim;
  /// (w P, w): a homogeneous control point / curve value.
  using homogeneous_type = Eigen::Matrix<Real, Dim + 1, 1>;

  /// order m in [1, 16], knots: control_points.size() + m values, one weight > 0 per point.
  nurbs(int order, std::vector<Real> knots, point_list<Real, Dim> control_points, std::vector<Real> weights)
      : points_(std::move(control_points)), weights_(std::move(weights)) {
    validate::finite_points<Real, Dim>("control_points", points_);
    validate::same_count("weights", weights_.size(), "control_points", points_.size());
    for (std::size_t i = 0; i < weights_.size(); ++i) validate::positive("weights", weights_[i], i);
    std::vector<homogeneous_type> h(points_.size());
    for (std::size_t i = 0; i < points_.size(); ++i) {
      h[i].template head<Dim>() = weights_[i] * points_[i];
      h[i][Dim] = weights_[i];
    }
    core_ = detail::bspline_core<Real, homogeneous_type>(order, std::move(knots), std::move(h));
    build_rounding_bounds();
  }

  /// Upper bound on the rounding of the default evaluation of C (order 0) or C' (order 1) over the
  /// domain (see the header); +inf for other orders.
  [[nodiscard]] Real rounding_bound(int order) const {
    if (order < 0 || order > 1) return std::numeric_limits<Real>::infinity();
    return rounding_bound_[static_cast<std::size_t>(order)];
  }

  [[nodiscard]] int order() const { return core_.order(); }
  [[nodiscard]] int degree() const { return core_.order() - 1; }
  [[nodiscard]] std::span<const Real> knots() const { return core_.knots(); }
  [[nodiscard]] std::span<const point_type> control_points() const { return points_; }
  [[nodiscard]] std::span<const Real> weights() const { return weights_; }

  // ---- the curve concept ----
  [[nodiscard]] interval<Real> domain() const { return {core_.lo(), core_.hi()}; }
  [[nodiscard]] std::span<const Real> breakpoints() const { return core_.breakpoints(); }
  [[nodiscard]] point_type operator()(const Real& u) const { return evaluate(u, 0, bspline_evaluation::de_boor); }
  [[nodiscard]] point_type derivative(const Real& u, int order) const {
    return evaluate(u, order, bspline_evaluation::de_boor);
  }

  /// The homogeneous curve (A, W) or its derivative of the given order at u.
  [[nodiscard]] homogeneous_type homogeneous(const Real& u, int order,
                                             bspline_evaluation algorithm = bspline_evaluation::de_boor) const {
    validate::derivative_order(order);
    check_parameter(u, domain());
    return algorithm == bspline_evaluation::de_boor ? core_.de_boor(u, order) : core_.basis_sum(u, order);
  }

  /// d^order C / du^order at u, the homogeneous derivatives computed by the chosen algorithm.
  [[nodiscard]] point_type evaluate(const Real& u, int order, bspline_evaluation algorithm) const {
    validate::derivative_order(order);
    check_parameter(u, domain());
    const auto k = static_cast<std::size_t>(order);
    if (k < small) {
      std::array<point_type, small> c;
      return quotient_rule(u, k, algorithm, c.data());
    }
    std::vector<point_type> c(k + 1);
    return quotient_rule(u, k, algorithm, c.data());
  }

 private:
  static constexpr std::size_t small = 32;

  [[nodiscard]] homogeneous_type level(const Real& u, std::size_t j, std::size_t span, bspline_evaluation a) const {
    if (j >= static_cast<std::size_t>(order())) return homogeneous_type::Zero();
    if (a == bspline_evaluation::de_boor) return core_.de_boor_at(u, static_cast<int>(j), span);
    return core_.basis_sum(u, static_cast<int>(j));
  }

  // c[0..k] receives C, C', ..., C^(k); returns C^(k).
  point_type quotient_rule(const Real& u, std::size_t k, bspline_evaluation a, point_type* c) const {
    const std::size_t span = core_.find_span(u);
    const homogeneous_type h0 = level(u, 0, span, a);
    const Real w = h0[Dim];
    c[0] = h0.template head<Dim>() / w;
    const std::size_t m = static_cast<std::size_t>(order());
    std::array<Real, bspline_max_order> wd;  // W^(j), j < m
    wd[0] = w;
    for (std::size_t j = 1; j <= k; ++j) {
      const homogeneous_type hj = level(u, j, span, a);
      if (j < m) wd[j] = hj[Dim];
      point_type acc = hj.template head<Dim>();
      Real binom(1);  // C(j, i), built incrementally (exact while it fits in the significand)
      for (std::size_t i = 1; i <= j; ++i) {
        binom = binom * Real(static_cast<long long>(j - i + 1)) / Real(static_cast<long long>(i));
        if (i >= m) break;  // W^(i) = 0 from here on
        acc -= (binom * wd[i]) * c[j - i];
      }
      c[j] = acc / w;
    }
    return c[k];
  }

  // The quotient bound per span, from the control data active there (W >= their smallest weight,
  // |C| <= their largest point); the largest over the spans.
  void build_rounding_bounds() {
    using std::abs;
    const Real f0 = core_.de_boor_rounding_factor(0), f1 = core_.de_boor_rounding_factor(1);
    const auto m = static_cast<std::size_t>(order());
    rounding_bound_ = {Real(0), Real(0)};
    for (std::size_t k : core_.spans()) {
      Real max_wp(0), max_p(0), max_w(0), min_w = std::numeric_limits<Real>::infinity(), max_a1(0), max_w1(0);
      for (std::size_t i = k + 1 - m; i <= k; ++i) {
        max_wp = std::max(max_wp, safe_norm(point_type(core_.control(0)[i].template head<Dim>())));
        max_p = std::max(max_p, safe_norm(points_[i]));
        max_w = std::max(max_w, weights_[i]);
        min_w = std::min(min_w, weights_[i]);
      }
      if (m > 1)
        for (const homogeneous_type& q : core_.active_control(1, k)) {
          max_a1 = std::max(max_a1, safe_norm(point_type(q.template head<Dim>())));
          max_w1 = std::max(max_w1, Real(abs(q[Dim])));
        }
      const Real data = epsilon<Real>() / Real(2) * max_wp;  // fl(w_i P_i)
      const Real data1 =
          m > 1 ? from_int<Real>(2 * (static_cast<long long>(m) - 1)) * data / core_.level1_min_span(k) : Real(0);
      const detail::quotient_rounding<Real> q{
          f0 * max_wp + data, f0 * max_w, f1 * max_a1 + data1, f1 * max_w1, max_a1, max_w1, max_p, min_w};
      const std::array<Real, 2> b = detail::quotient_rounding_bound(q);
      rounding_bound_ = {std::max(rounding_bound_[0], b[0]), std::max(rounding_bound_[1], b[1])};
    }
  }

  point_list<Real, Dim> points_;
  std::vector<Real> weights_;
  detail::bspline_core<Real, homogeneous_type> core_;
  std::array<Real, 2> rounding_bound_{};
};

/// The full circle of center c and radius r as a quadratic NURBS on [0, 1]: 9 control points on
/// the circumscribed square (start at c + (r, 0), counter-clockwise), weights 1 at the 4 points on
/// the circle and sqrt(2)/2 at the corners, knots 0 0 0 1/4 1/4 1/2 1/2 3/4 3/4 1 1 1.
/// Each quarter is a rational quadratic Bezier arc with w = cos(45 deg). Not arc-length parameterized.
template <class Real>
[[nodiscard]] nurbs<Real, 2> nurbs_circle_9(const point<Real, 2>& center, const Real& radius) {
  validate::finite_point<Real, 2>("center", 0, center);
  validate::positive("radius", radius);
  const Real s = boost::math::constants::half_root_two<Real>();
  const int dx[9] = {1, 1, 0, -1, -1, -1, 0, 1, 1};
  const int dy[9] = {0, 1, 1, 1, 0, -1, -1, -1, 0};
  point_list<Real, 2> p;
  std::vector<Real> w;
  for (int i = 0; i < 9; ++i) {
    p.emplace_back(center[0] + Real(dx[i]) * radius, center[1] + Real(dy[i]) * radius);
    w.push_back(i % 2 == 0 ? Real(1) : s);
  }
  const Real q = Real(1) / Real(4);
  const Real h = Real(1) / Real(2);
  const Real tq = Real(3) / Real(4);
  std::vector<Real> t{Real(0), Real(0), Real(0), q, q, h, h, tq, tq, Real(1), Real(1), Real(1)};
  return nurbs<Real, 2>(3, std::move(t), std::move(p), std::move(w));
}

/// The full circle as a quadratic NURBS on [0, 1] with 7 control points on the circumscribed
/// equilateral triangle (vertices at distance 2r, mid-sides on the circle, start at c + (r, 0)),
/// weights 1 on the circle and 1/2 at the vertices (cos 60 deg), knots 0 0 0 1/3 1/3 2/3 2/3 1 1 1.
template <class Real>
[[nodiscard]] nurbs<Real, 2> nurbs_circle_7(const point<Real, 2>& center, const Real& radius) {
  validate::finite_point<Real, 2>("center", 0, center);
  validate::positive("radius", radius);
  const Real r3 = boost::math::constants::root_three<Real>();
  const Real h = Real(1) / Real(2);
  // Unit-circle control points: (1, 0), (1, sqrt3), (-1/2, sqrt3/2), (-2, 0), (-1/2, -sqrt3/2), (1, -sqrt3), (1, 0).
  const std::array<std::array<Real, 2>, 7> unit{{{Real(1), Real(0)},
                                                 {Real(1), r3},
                                                 {-h, r3 * h},
                                                 {Real(-2), Real(0)},
                                                 {-h, -(r3 * h)},
                                                 {Real(1), -r3},
                                                 {Real(1), Real(0)}}};
  point_list<Real, 2> p;
  std::vector<Real> w;
  for (std::size_t i = 0; i < 7; ++i) {
    p.emplace_back(center[0] + unit[i][0] * radius, center[1] + unit[i][1] * radius);
    w.push_back(i % 2 == 0 ? Real(1) : h);
  }
  const Real a = Real(1) / Real(3);
  const Real b = Real(2) / Real(3);
  std::vector<Real> t{Real(0), Real(0), Real(0), a, a, b, b, Real(1), Real(1), Real(1)};
  return nurbs<Real, 2>(3, std::move(t), std::move(p), std::move(w));
}

}  // namespace curvebench
