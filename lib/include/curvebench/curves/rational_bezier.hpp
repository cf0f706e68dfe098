// Rational Bezier curves of any degree L (1 <= L <= bezier_max_degree) with positive weights:
// C(t) = sum_k B_k^L w_k P_k / sum_k B_k^L w_k = A(t) / w(t), and the rational quadratic conics
// (w < 1 ellipse, w = 1 parabola, w > 1 hyperbola; the circular arc of sweep theta has middle
// weight cos(theta / 2)). Numerator and denominator are evaluated by de Casteljau and divided;
// derivatives of any order exactly by Leibniz's rule on A = w C (details above the class). Bad
// data (point or weight counts, non-finite values, weights <= 0, a bad domain) throw invalid_input;
// u outside the domain std::domain_error.
// Sources: seed 000 ("Rational Parametric"); Farin (2002), ch. 13; Piegl & Tiller (1997), 2.5, 7.5.
// Cost: O(L^2) per value, O(k L (L + Dim)) for derivative k, no allocation.
// Accuracy: ~L ulps of the scale (w(t) >= min w_k > 0, so the division loses nothing).
// rounding_bound(order), order 0 or 1 (core/curve.hpp): the numerator's and the denominator's
// de Casteljau bounds (bezier.hpp), plus the rounding of w_k P_k (u max |w_k P_k|, and 2L/(b - a)
// times that in A'), through the quotient (detail/quotient_rounding.hpp) with W >= min w_k and
// |C| <= max |P_k|.
#pragma once

#include "curvebench/core/curve.hpp"
#include "curvebench/core/error.hpp"
#include "curvebench/core/point.hpp"
#include "curvebench/core/real.hpp"
#include "curvebench/curves/bezier.hpp"
#include "curvebench/curves/detail/quotient_rounding.hpp"

#include <boost/math/constants/constants.hpp>

#include <algorithm>
#include <array>
#include <cstddef>
#include <limits>
#include <span>
#include <string>
#include <vector>

namespace curvebench {

/// The kind of a rational quadratic conic, from its shape factor w1^2 / (w0 w2).
enum class conic_kind { ellipse, parabola, hyperbola };

[[nodiscard]] inline const char* to_string(conic_kind k) {
  switch (k) {
    case conic_kind::ellipse: return "ellipse";
    case conic_kind::parabola: return "parabola";
    case conic_kind::hyperbola: return "hyperbola";
  }
  return "unknown";
}

namespace detail {

/// C(m, j) in Real for any m >= 0: exact integer arithmetic while it fits (m <= 62), otherwise the
/// multiplicative formula in Real (rounded; only reached for derivative orders above 62).
template <class Real>
[[nodiscard]] Real bezier_binomial(int m, int j) {
  if (m <= 62) return binomial<Real>(m, j);
  if (j < 0 || j > m) return Real(0);
  Real c(1);
  for (int i = 1; i <= j; ++i) c = c * Real(m - j + i) / Real(i);
  return c;
}

}  // namespace detail

// Evaluation: homogeneous coordinates. The numerator A (control points w_k P_k) and the
// denominator w (control values w_k) are polynomial Bezier curves (bezier.hpp), both evaluated by
// de Casteljau, then divided: O(L^2), backward stable in the homogeneous space; with positive
// weights w(t) >= min w_k > 0, so the division loses nothing: error ~ L ulps of the scale.
// Derivatives of any order k, exact: A = w C differentiated k times by Leibniz gives
//   C^(k) = (A^(k) - sum_{j=1..min(k,L)} C(k, j) w^(j) C^(k-j)) / w,
// a recurrence over the previous L derivatives (w^(j) = 0 for j > L), kept in a stack ring buffer
// of L + 1 points: O(k L (L + Dim)), no allocation. Unlike the polynomial case, derivatives of order
// > L do not vanish.
template <class Real, int Dim>
class rational_bezier {
 public:
  using real_type = Real;
  using point_type = point<Real, Dim>;
  static constexpr int dimension = Dim;

  /// A rational Bezier curve with one positive weight per control point, on `domain`.
  rational_bezier(std::span<const point_type> control_points, std::span<const Real> weights,
                  interval<Real> domain = {Real(0), Real(1)})
      : points_(validated(control_points, weights, domain)),
        weights_(weights.begin(), weights.end()),
        numerator_(homogeneous(points_, weights_), domain),
        denominator_(weight_points(weights_), domain) {
    build_rounding_bounds();
  }

  /// Upper bound on the rounding of this curve's evaluation of C (order 0) or C' (order 1) over the
  /// domain (see the header); +inf for other orders.
  [[nodiscard]] Real rounding_bound(int order) const {
    if (order < 0 || order > 1) return std::numeric_limits<Real>::infinity();
    return rounding_bound_[static_cast<std::size_t>(order)];
  }

  [[nodiscard]] int degree() const { return numerator_.degree(); }
  [[nodiscard]] interval<Real> domain() const { return numerator_.domain(); }
  [[nodiscard]] std::span<const Real> breakpoints() const { return numerator_.breakpoints(); }
  [[nodiscard]] std::span<const point_type> control_points() const { return points_; }
  [[nodiscard]] std::span<const Real> weights() const { return weights_; }
  /// A(t) = sum B_k w_k P_k, the numerator in homogeneous coordinates.
  [[nodiscard]] const bezier<Real, Dim>& numerator() const { return numerator_; }
  /// w(t) = sum B_k w_k, the denominator, as a one-dimensional Bezier curve.
  [[nodiscard]] const bezier<Real, 1>& denominator() const { return denominator_; }

  /// The value A(u) / w(u), both by de Casteljau.
  [[nodiscard]] point_type operator()(const Real& u) const {
    check_parameter(u, domain());
    const point_type a = numerator_(u);
    return a / denominator_(u)[0];
  }

  /// d^order C / du^order by the Leibniz recurrence (exact; see the comment above the class).
  [[nodiscard]] point_type derivative(const Real& u, int order) const {
    validate::derivative_order(order);
    check_parameter(u, domain());
    if (order == 0) return (*this)(u);
    const int L = degree();
    const auto ring_size = static_cast<std::size_t>(L) + 1;
    // w^(j)(u), j = 0..min(order, L). Zeroed first: only those are read, but GCC cannot tie the
    // reads below to the loop's bound and warned at -O3 that wd[0] and wd[1] may be uninitialized.
    std::array<Real, bezier_max_degree + 1> wd{};
    const int jmax = std::min(order, L);
    for (int j = 0; j <= jmax; ++j) wd[static_cast<std::size_t>(j)] = denominator_.derivative(u, j)[0];
    std::array<point_type, bezier_max_degree + 1> ring;  // C^(m) at m mod (L + 1)
    for (int m = 0; m <= order; ++m) {
      point_type num = m <= L ? numerator_.derivative(u, m) : zero_point<Real, Dim>();
      for (int j = 1; j <= std::min(m, L); ++j) {
        const Real c = detail::bezier_binomial<Real>(m, j) * wd[static_cast<std::size_t>(j)];
        num -= c * ring[static_cast<std::size_t>(m - j) % ring_size];
      }
      ring[static_cast<std::size_t>(m) % ring_size] = num / wd[0];
    }
    return ring[static_cast<std::size_t>(order) % ring_size];
  }

  /// For a quadratic: ellipse, parabola or hyperbola as w1^2 / (w0 w2) is <, = or > 1 (the shape
  /// factor is invariant under the reparameterizations that normalize w0 = w2 = 1; compared exactly).
  [[nodiscard]] conic_kind conic_type() const {
    if (degree() != 2)
      validate::fail("conic_type: degree = " + std::to_string(degree()) + ", only a rational quadratic is a conic");
    const Real lhs = weights_[1] * weights_[1];
    const Real rhs = weights_[0] * weights_[2];
    if (lhs < rhs) return conic_kind::ellipse;
    if (lhs > rhs) return conic_kind::hyperbola;
    return conic_kind::parabola;
  }

 private:
  static std::vector<point_type> validated(std::span<const point_type> p, std::span<const Real> w,
                                           const interval<Real>& domain) {
    validate::count_at_least("control_points", p.size(), 2,
                             "a rational Bezier curve of degree L >= 1 has L + 1 control points");
    validate::same_count("weights", w.size(), "control_points", p.size());
    validate::finite_points<Real, Dim>("control_points", p);
    for (std::size_t i = 0; i < w.size(); ++i) validate::positive("weights", w[i], i);
    detail::check_bezier_domain("domain", domain);
    return std::vector<point_type>(p.begin(), p.end());
  }
  static std::vector<point_type> homogeneous(const std::vector<point_type>& p, const std::vector<Real>& w) {
    std::vector<point_type> h;
    h.reserve(p.size());
    for (std::size_t i = 0; i < p.size(); ++i) h.push_back(point_type(w[i] * p[i]));
    return h;
  }
  static std::vector<point<Real, 1>> weight_points(const std::vector<Real>& w) {
    std::vector<point<Real, 1>> h;
    h.reserve(w.size());
    for (const Real& x : w) h.push_back(point<Real, 1>(x));
    return h;
  }

  void build_rounding_bounds() {
    using std::abs;
    Real max_wp(0), max_p(0), min_w = weights_.front(), max_a1(0), max_w1(0);
    for (std::size_t k = 0; k < points_.size(); ++k) {
      max_wp = std::max(max_wp, safe_norm(numerator_.control_points()[k]));
      max_p = std::max(max_p, safe_norm(points_[k]));
      min_w = std::min(min_w, weights_[k]);
    }
    for (const point_type& d : numerator_.derivative_control_points(1)) max_a1 = std::max(max_a1, safe_norm(d));
    for (const point<Real, 1>& d : denominator_.derivative_control_points(1))
      max_w1 = std::max(max_w1, Real(abs(d[0])));
    const Real data = epsilon<Real>() / Real(2) * max_wp;  // fl(w_k P_k)
    const Real width = domain().hi - domain().lo;
    detail::quotient_rounding<Real> q{numerator_.rounding_bound(0) + data,
                                      denominator_.rounding_bound(0),
                                      numerator_.rounding_bound(1) + Real(2 * degree()) * data / width,
                                      denominator_.rounding_bound(1),
                                      max_a1,
                                      max_w1,
                                      max_p,
                                      min_w};
    rounding_bound_ = detail::quotient_rounding_bound(q);
  }

  std::vector<point_type> points_;
  std::vector<Real> weights_;
  bezier<Real, Dim> numerator_;
  bezier<Real, 1> denominator_;
  std::array<Real, 2> rounding_bound_{};
};

/// The rational quadratic of seed 000 with end weights 1 and middle weight w > 0:
/// w < 1 ellipse, w = 1 parabola (the quadratic Bezier curve), w > 1 hyperbola.
template <class Real, int Dim>
[[nodiscard]] rational_bezier<Real, Dim> conic(const point<Real, Dim>& p0, const point<Real, Dim>& p1,
                                               const point<Real, Dim>& p2, const Real& w,
                                               interval<Real> domain = {Real(0), Real(1)}) {
  validate::positive("w", w);
  const std::array<point<Real, Dim>, 3> p{p0, p1, p2};
  const std::array<Real, 3> weights{Real(1), w, Real(1)};
  return rational_bezier<Real, Dim>(std::span<const point<Real, Dim>>(p), std::span<const Real>(weights), domain);
}

/// The circular arc of radius r around `center` from angle `start` (radians, counter-clockwise)
/// through the angle `sweep` in (0, pi), as a rational quadratic: the end points on the circle, the
/// middle control point at the intersection of the end tangents (distance r / cos(sweep/2) from the
/// center, at the mid angle), middle weight cos(sweep / 2). Exactly on the circle in exact arithmetic.
template <class Real>
[[nodiscard]] rational_bezier<Real, 2> circular_arc(const point<Real, 2>& center, const Real& radius, const Real& start,
                                                    const Real& sweep, interval<Real> domain = {Real(0), Real(1)}) {
  using std::cos;
  using std::sin;
  validate::positive("radius", radius);
  validate::finite("start", start);
  validate::finite("sweep", sweep);
  const Real pi = boost::math::constants::pi<Real>();
  if (!(sweep > Real(0) && sweep < pi))
    validate::fail("sweep = " + to_text(sweep) + ": must be in (0, pi) (one rational quadratic per arc)");
  const Real half = sweep / Real(2);
  const Real w = cos(half);
  const Real mid = start + half;
  const Real end = start + sweep;
  const Real far = radius / w;
  const point<Real, 2> p0(center[0] + radius * cos(start), center[1] + radius * sin(start));
  const point<Real, 2> p1(center[0] + far * cos(mid), center[1] + far * sin(mid));
  const point<Real, 2> p2(center[0] + radius * cos(end), center[1] + radius * sin(end));
  return conic<Real, 2>(p0, p1, p2, w, domain);
}

}  // namespace curvebench
