// Reference curves with closed-form derivatives of every order, independent of the curve families:
// they exercise the arc-length methods and carry the closed-form lengths of closed_forms.hpp.
//
// - piecewise_polynomial<Real, Dim>: segments in power form in the local variable t = u - u_i,
//   P(u) = sum_k c_{i,k} t^k on [u_i, u_{i+1}]; Horner for the value and every derivative
//   (O(degree) per coordinate). Lines with non-uniform or back-tracking parameterization, cusps
//   (P'(t0) = 0), loops and many-segment splines are all written in it.
// - helix<Real>: (r cos(w u), r sin(w u), c u), constant speed sqrt(r^2 w^2 + c^2).
// - circle<Real>: (r cos(w u + phi), r sin(w u + phi)), constant speed |r w|.
// - rational_quadratic<Real, Dim>: the rational quadratic Bezier (P0, P1, P2; weights 1, w, 1);
//   derivatives of any order by Leibniz's rule on A = w(u) P(u): P^(k) = (A^(k) - sum_{i=1}^{k}
//   C(k, i) w^(i) P^(k-i)) / w (Farin, "Curves and Surfaces for CAGD", 13). With w = cos(theta/2)
//   and P1 at the intersection of the end tangents it is an exact circular arc of angle theta.
// All satisfy curvebench::curve; inputs are validated at construction; evaluation outside the
// domain throws std::domain_error.
#pragma once

#include "curvebench/core/curve.hpp"
#include "curvebench/core/detail/segment_lookup.hpp"
#include "curvebench/core/error.hpp"
#include "curvebench/core/point.hpp"
#include "curvebench/core/real.hpp"

#include <array>
#include <cstddef>
#include <span>
#include <string>
#include <vector>

namespace curvebench::reference {

/// A piecewise polynomial curve in local power form.
template <class Real, int Dim>
class piecewise_polynomial {
 public:
  using real_type = Real;
  using point_type = point<Real, Dim>;
  static constexpr int dimension = Dim;

  /// breakpoints: increasing, size segments + 1; coefficients[i][k] multiplies (u - u_i)^k on
  /// segment i (each segment at least one coefficient).
  piecewise_polynomial(std::vector<Real> breakpoints, std::vector<point_list<Real, Dim>> coefficients)
      : breaks_(std::move(breakpoints)), coef_(std::move(coefficients)) {
    validate::count_at_least("breakpoints", breaks_.size(), 2, "a curve has at least one segment");
    validate::increasing<Real>("breakpoints", breaks_);
    validate::same_count("coefficients", coef_.size(), "segments (breakpoints - 1)", breaks_.size() - 1);
    for (std::size_t i = 0; i < coef_.size(); ++i) {
      validate::count_at_least(validate::indexed("coefficients", i), coef_[i].size(), 1);
      validate::finite_points<Real, Dim>(validate::indexed("coefficients", i), coef_[i]);
    }
  }

  /// One segment on [u0, u1]: P(u) = sum_k c_k (u - u0)^k.
  piecewise_polynomial(const Real& u0, const Real& u1, point_list<Real, Dim> coefficients)
      : piecewise_polynomial(std::vector<Real>{u0, u1}, std::vector<point_list<Real, Dim>>{std::move(coefficients)}) {}

  [[nodiscard]] interval<Real> domain() const { return {breaks_.front(), breaks_.back()}; }
  [[nodiscard]] std::span<const Real> breakpoints() const { return breaks_; }
  [[nodiscard]] point_type operator()(const Real& u) const { return derivative(u, 0); }

  [[nodiscard]] point_type derivative(const Real& u, int order) const {
    validate::derivative_order(order);
    const std::size_t i = curvebench::detail::checked_segment_of<Real>(breaks_, u);
    const Real t = u - breaks_[i];
    const point_list<Real, Dim>& c = coef_[i];
    point_type acc = zero_point<Real, Dim>();
    const int deg = static_cast<int>(c.size()) - 1;
    for (int k = deg; k >= order; --k) {
      Real falling(1);  // k (k-1) ... (k-order+1)
      for (int j = 0; j < order; ++j) falling *= Real(k - j);
      point_type term = falling * c[static_cast<std::size_t>(k)];
      acc = point_type(acc * t + term);
    }
    return acc;
  }

  [[nodiscard]] const std::vector<point_list<Real, Dim>>& coefficients() const { return coef_; }

 private:
  std::vector<Real> breaks_;
  std::vector<point_list<Real, Dim>> coef_;
};

/// (r cos(w u), r sin(w u), c u) on [u0, u1].
template <class Real>
class helix {
 public:
  using real_type = Real;
  using point_type = point<Real, 3>;
  static constexpr int dimension = 3;

  helix(const Real& radius, const Real& angular_rate, const Real& climb_rate, const Real& u0, const Real& u1)
      : r_(radius), w_(angular_rate), c_(climb_rate), breaks_{u0, u1} {
    validate::finite("radius", radius);
    validate::finite("angular_rate", angular_rate);
    validate::finite("climb_rate", climb_rate);
    validate::increasing<Real>("domain", breaks_);
  }
  [[nodiscard]] interval<Real> domain() const { return {breaks_[0], breaks_[1]}; }
  [[nodiscard]] std::span<const Real> breakpoints() const { return breaks_; }
  [[nodiscard]] point_type operator()(const Real& u) const { return derivative(u, 0); }
  [[nodiscard]] point_type derivative(const Real& u, int order) const {
    validate::derivative_order(order);
    check_parameter(u, domain());
    using std::cos;
    using std::sin;
    Real scale(1);
    for (int k = 0; k < order; ++k) scale *= w_;
    Real x = cos(w_ * u), y = sin(w_ * u);
    for (int k = 0; k < order % 4; ++k) {  // each derivative rotates (cos, sin) by 90 degrees
      const Real nx = -y;
      y = x;
      x = nx;
    }
    point_type p;
    p << r_ * scale * x, r_ * scale * y, order == 0 ? c_ * u : (order == 1 ? c_ : Real(0));
    return p;
  }

 private:
  Real r_, w_, c_;
  std::array<Real, 2> breaks_;
};

/// (r cos(w u + phi), r sin(w u + phi)) on [u0, u1].
template <class Real>
class circle {
 public:
  using real_type = Real;
  using point_type = point<Real, 2>;
  static constexpr int dimension = 2;

  circle(const Real& radius, const Real& angular_rate, const Real& phase, const Real& u0, const Real& u1)
      : r_(radius), w_(angular_rate), phi_(phase), breaks_{u0, u1} {
    validate::finite("radius", radius);
    validate::finite("angular_rate", angular_rate);
    validate::finite("phase", phase);
    validate::increasing<Real>("domain", breaks_);
  }
  [[nodiscard]] interval<Real> domain() const { return {breaks_[0], breaks_[1]}; }
  [[nodiscard]] std::span<const Real> breakpoints() const { return breaks_; }
  [[nodiscard]] point_type operator()(const Real& u) const { return derivative(u, 0); }
  [[nodiscard]] point_type derivative(const Real& u, int order) const {
    validate::derivative_order(order);
    check_parameter(u, domain());
    using std::cos;
    using std::sin;
    Real scale(r_);
    for (int k = 0; k < order; ++k) scale *= w_;
    Real x = cos(w_ * u + phi_), y = sin(w_ * u + phi_);
    for (int k = 0; k < order % 4; ++k) {
      const Real nx = -y;
      y = x;
      x = nx;
    }
    point_type p;
    p << scale * x, scale * y;
    return p;
  }

 private:
  Real r_, w_, phi_;
  std::array<Real, 2> breaks_;
};

/// The rational quadratic Bezier curve with weights (1, w, 1) on [0, 1].
template <class Real, int Dim>
class rational_quadratic {
 public:
  using real_type = Real;
  using point_type = point<Real, Dim>;
  static constexpr int dimension = Dim;

  rational_quadratic(const point_type& p0, const point_type& p1, const point_type& p2, const Real& w)
      : p_{p0, p1, p2}, w_(w) {
    for (std::size_t i = 0; i < 3; ++i) validate::finite_point<Real, Dim>("control_points", i, p_[i]);
    validate::positive("weight", w);
  }
  [[nodiscard]] interval<Real> domain() const { return {Real(0), Real(1)}; }
  [[nodiscard]] std::span<const Real> breakpoints() const { return breaks_; }
  [[nodiscard]] point_type operator()(const Real& u) const { return derivative(u, 0); }
  [[nodiscard]] point_type derivative(const Real& u, int order) const {
    validate::derivative_order(order);
    check_parameter(u, domain());
    // A(u) = sum B_i^2(u) w_i P_i and W(u) = sum B_i^2(u) w_i, with their derivatives (degree 2).
    const Real s = Real(1) - u;
    const std::array<Real, 3> b{s * s, Real(2) * u * s, u * u};
    const std::array<Real, 3> db{Real(-2) * s, Real(2) - Real(4) * u, Real(2) * u};
    const std::array<Real, 3> ddb{Real(2), Real(-4), Real(2)};
    const std::array<Real, 3> wi{Real(1), w_, Real(1)};
    auto a_der = [&](int k) {
      point_type r = zero_point<Real, Dim>();
      if (k > 2) return r;
      for (std::size_t i = 0; i < 3; ++i) {
        const Real bi = k == 0 ? b[i] : (k == 1 ? db[i] : ddb[i]);
        r += (bi * wi[i]) * p_[i];
      }
      return r;
    };
    auto w_der = [&](int k) {
      if (k > 2) return Real(0);
      Real r(0);
      for (std::size_t i = 0; i < 3; ++i) r += (k == 0 ? b[i] : (k == 1 ? db[i] : ddb[i])) * wi[i];
      return r;
    };
    const Real w0 = w_der(0);
    std::vector<point_type> d(static_cast<std::size_t>(order) + 1);
    for (int k = 0; k <= order; ++k) {
      point_type num = a_der(k);
      for (int i = 1; i <= k && i <= 2; ++i)
        num -= (binomial<Real>(k, i) * w_der(i)) * d[static_cast<std::size_t>(k - i)];
      d[static_cast<std::size_t>(k)] = num / w0;
    }
    return d[static_cast<std::size_t>(order)];
  }

 private:
  std::array<point_type, 3> p_;
  Real w_;
  std::array<Real, 2> breaks_{Real(0), Real(1)};
};

}  // namespace curvebench::reference
