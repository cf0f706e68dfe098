// B-spline curves of any order m (degree m - 1, 1 <= m <= bspline_max_order = 16) on non-uniform
// knots: P(u) = sum_i N_{i,m}(u) P_i, control points P_0 .. P_{n-1}, knots t_0 .. t_{n+m-1},
// domain [t_{m-1}, t_n] (indexing and the conventions at knots: see the comment above the class).
// Evaluation by de Boor's algorithm (default; m(m-1)/2 convex combinations, O(m^2 Dim)) or the
// Cox-de Boor basis sum (O(m^2)), both in stack arrays; derivatives by the precomputed derivative
// control points (order m - r for the r-th); continuity C^{m-1-mu} at a knot of multiplicity mu.
// Also: Boehm knot insertion, knot-vector builders (uniform, clamped, periodic) and, for m = 4,
// conversion to the piecewise_cubic engine. Bad data throw invalid_input naming what and where;
// u outside the domain std::domain_error.
// Sources: seed 000 (the Cox-de Boor recursion), seed 001 (the property table); de Boor (1978);
// Boehm (1980); Piegl & Tiller (1997), ch. 2-5.
// Cost: O(m^2) per value, no allocation; construction O(n m). Accuracy: backward stable, error
// ~m ulps of the control-point scale; derivative differences lose relative accuracy only where
// control points nearly coincide.
#pragma once

#include "curvebench/core/curve.hpp"
#include "curvebench/core/error.hpp"
#include "curvebench/core/point.hpp"
#include "curvebench/core/real.hpp"
#include "curvebench/curves/detail/bspline_core.hpp"
#include "curvebench/curves/piecewise_cubic.hpp"

#include <algorithm>
#include <array>
#include <cstddef>
#include <limits>
#include <span>
#include <string>
#include <utility>
#include <vector>

namespace curvebench {

/// Name of an evaluation algorithm (benchmark and report labels).
[[nodiscard]] inline const char* to_string(bspline_evaluation a) {
  switch (a) {
    case bspline_evaluation::de_boor: return "de_boor";
    case bspline_evaluation::basis_sum: return "basis_sum";
  }
  return "unknown";
}

namespace detail {
inline void bspline_check_order(int order) {
  if (order < 1 || order > bspline_max_order)
    validate::fail("order = " + std::to_string(order) + ": must be in [1, " + std::to_string(bspline_max_order) +
                   "] (degree + 1)");
}
}  // namespace detail

// ---------------------------------------------------------------------------------------------
// Knot-vector builders. Each returns count + order knots for `count` control points.

/// Uniform knots t_j = lo + j step, j = 0 .. count + order - 1; domain [lo + (m-1) step, lo + count step].
/// The curve is not clamped: it starts near, not at, the first control point.
template <class Real>
[[nodiscard]] std::vector<Real> bspline_uniform_knots(std::size_t count, int order, const Real& lo = Real(0),
                                                      const Real& step = Real(1)) {
  detail::bspline_check_order(order);
  validate::count_at_least("count", count, static_cast<std::size_t>(order), "a B-spline needs at least order points");
  validate::finite("lo", lo);
  validate::positive("step", step);
  std::vector<Real> t(count + static_cast<std::size_t>(order));
  for (std::size_t j = 0; j < t.size(); ++j) t[j] = lo + Real(static_cast<long long>(j)) * step;
  return t;
}

/// Clamped (open) knots on given breakpoints b_0 < ... < b_s: b_0 and b_s repeated m times, the
/// interior breakpoints once. count = s + m - 1 control points; domain [b_0, b_s]; the curve
/// interpolates its first and last control points and is C^{m-2} at interior breakpoints.
template <class Real>
[[nodiscard]] std::vector<Real> bspline_clamped_knots(std::span<const Real> breaks, int order) {
  detail::bspline_check_order(order);
  validate::count_at_least("breaks", breaks.size(), 2, "a domain needs two breakpoints");
  validate::increasing<Real>("breaks", breaks);
  const auto m = static_cast<std::size_t>(order);
  std::vector<Real> t;
  t.reserve(breaks.size() - 2 + 2 * m);
  t.insert(t.end(), m, breaks.front());
  t.insert(t.end(), breaks.begin() + 1, breaks.end() - 1);
  t.insert(t.end(), m, breaks.back());
  return t;
}

/// Clamped knots for `count` control points with uniformly spaced interior knots on [lo, hi].
template <class Real>
[[nodiscard]] std::vector<Real> bspline_clamped_knots(std::size_t count, int order, const Real& lo = Real(0),
                                                      const Real& hi = Real(1)) {
  detail::bspline_check_order(order);
  validate::count_at_least("count", count, static_cast<std::size_t>(order), "a B-spline needs at least order points");
  validate::finite("lo", lo);
  validate::finite("hi", hi);
  if (!(lo < hi)) validate::fail("hi = " + to_text(hi) + ": must be > lo = " + to_text(lo));
  const std::size_t segments = count - static_cast<std::size_t>(order) + 1;
  std::vector<Real> breaks(segments + 1);
  for (std::size_t j = 0; j <= segments; ++j)
    breaks[j] = lo + (hi - lo) * Real(static_cast<long long>(j)) / Real(static_cast<long long>(segments));
  breaks.back() = hi;
  return bspline_clamped_knots<Real>(std::span<const Real>(breaks), order);
}

/// Periodic knots for a closed curve on breakpoints b_0 < ... < b_s (period T = b_s - b_0, s >= 1
/// segments): the breakpoints extended periodically by m - 1 knots on each side,
/// t_{m-1+j} = b_{j mod s} + floor(j / s) T for j = -(m-1) .. s + m - 1, so s + 2m - 1 knots for
/// s + m - 1 control points (the s distinct points followed by the first m - 1 again, see
/// `periodic_bspline`). Domain [b_0, b_s]; the curve and its derivatives up to m - 2 match at the seam.
template <class Real>
[[nodiscard]] std::vector<Real> bspline_periodic_knots(std::span<const Real> breaks, int order) {
  detail::bspline_check_order(order);
  validate::count_at_least("breaks", breaks.size(), 2, "a period needs two breakpoints");
  validate::increasing<Real>("breaks", breaks);
  const auto m = static_cast<long long>(order);
  const auto s = static_cast<long long>(breaks.size()) - 1;
  const Real period = breaks.back() - breaks.front();
  std::vector<Real> t;
  t.reserve(static_cast<std::size_t>(s + 2 * m - 1));
  for (long long j = -(m - 1); j <= s + m - 1; ++j) {
    long long q = j / s;
    long long r = j % s;
    if (r < 0) {
      r += s;
      --q;
    }
    t.push_back(breaks[static_cast<std::size_t>(r)] + Real(q) * period);
  }
  return t;
}

// ---------------------------------------------------------------------------------------------

// Indexing (stated once, used everywhere): control points P_0 .. P_{n-1} (n >= m), knots
// t_0 <= t_1 <= ... <= t_{n+m-1} (n + m of them), domain [t_{m-1}, t_n]. (With the seed's
// L + 1 = n points P_0..P_L this is the usual [t_{m-1}, t_{L+1}].) Breakpoints are the distinct
// knots inside the domain.
// Conventions:
//   - 0/0 = 0 in the recursion (more generally x/0 = 0: a zero-length knot interval carries a zero
//     basis function, so the term it would divide vanishes);
//   - spans are half-open, [t_k, t_{k+1}): at an interior knot the curve takes the value from the
//     right (it matters only where the curve is discontinuous, i.e. multiplicity m);
//   - the right end u = t_n is special: with the half-open rule every N_{i,1} would vanish there
//     (and a clamped curve would evaluate to 0); instead the last non-empty span is used, which
//     gives the limit from the left, so a clamped curve ends exactly at P_{n-1}.
// Evaluation, two algorithms selectable per call (`evaluate(u, order, algorithm)`):
//   - de Boor (default): m(m-1)/2 convex combinations of control points for u in the domain,
//     O(m^2 Dim), backward stable: error ~ m ulps of the control-point scale;
//   - basis sum: the m non-zero N_{i,m}(u) by the Cox-de Boor recursion (triangular form, O(m^2)),
//     then sum N_i P_i (O(m Dim)); every N >= 0 and they sum to 1, so the error is also ~ m ulps.
//   Both run in stack arrays of bspline_max_order entries: no allocation.
// Derivatives: the r-th derivative is the B-spline of order m - r with control
//   Q^r_i = (m - r) (Q^{r-1}_{i+1} - Q^{r-1}_i) / (t_{i+m} - t_{i+r})  (0/0 = 0), knots t_r..t_{n+m-1-r},
// precomputed for every r < m in the constructor (n m points); order >= m is zero. Exact up to
// rounding: the differences lose relative accuracy only where control points nearly coincide.
// Continuity at an interior knot of multiplicity mu: C^{m-1-mu}.
template <class Real, int Dim>
class bspline {
 public:
  using real_type = Real;
  using point_type = point<Real, Dim>;
  static constexpr int dimension = Dim;

  /// order m in [1, 16], knots: control_points.size() + m values (see the comment above the class).
  bspline(int order, std::vector<Real> knots, point_list<Real, Dim> control_points) {
    validate::finite_points<Real, Dim>("control_points", control_points);
    core_ = detail::bspline_core<Real, point_type>(order, std::move(knots), std::move(control_points));
    for (int level = 0; level <= 1 && level < core_.order(); ++level) {
      Real biggest(0);
      for (std::size_t k : core_.spans())
        for (const point_type& q : core_.active_control(level, k)) biggest = std::max(biggest, safe_norm(q));
      rounding_bound_[static_cast<std::size_t>(level)] =
          core_.de_boor_rounding_factor(level) * biggest * (Real(101) / Real(100));
    }
  }

  [[nodiscard]] int order() const { return core_.order(); }
  [[nodiscard]] int degree() const { return core_.order() - 1; }

  /// Upper bound on the rounding of the default de Boor evaluation of P (order 0) or P' (order 1)
  /// over the domain: the largest over the spans of (9p + 4) eps max |P_i| and (9(p - 1) + 6) eps
  /// max |Q^1_i| over the control data active there (detail/bspline_core.hpp,
  /// de_boor_rounding_factor), 1% more, computed at construction; +inf for other orders.
  [[nodiscard]] Real rounding_bound(int order) const {
    if (order < 0 || order > 1) return std::numeric_limits<Real>::infinity();
    return rounding_bound_[static_cast<std::size_t>(order)];
  }
  [[nodiscard]] std::span<const Real> knots() const { return core_.knots(); }
  [[nodiscard]] std::span<const point_type> control_points() const { return core_.control(0); }
  /// Control points of the r-th derivative curve (order m - r, on knots t_r .. t_{n+m-1-r}), r < m.
  [[nodiscard]] std::span<const point_type> derivative_control_points(int r) const {
    if (r < 0 || r >= order())
      validate::fail("r = " + std::to_string(r) + ": derivative level must be in [0, " + std::to_string(order() - 1) +
                     "]");
    return core_.control(static_cast<std::size_t>(r));
  }

  // ---- the curve concept ----
  [[nodiscard]] interval<Real> domain() const { return {core_.lo(), core_.hi()}; }
  [[nodiscard]] std::span<const Real> breakpoints() const { return core_.breakpoints(); }
  [[nodiscard]] point_type operator()(const Real& u) const {
    check_parameter(u, domain());
    return core_.de_boor(u, 0);
  }
  [[nodiscard]] point_type derivative(const Real& u, int order) const {
    return evaluate(u, order, bspline_evaluation::de_boor);
  }

  /// d^order P / du^order at u by the chosen algorithm (both exact in exact arithmetic).
  [[nodiscard]] point_type evaluate(const Real& u, int order, bspline_evaluation algorithm) const {
    validate::derivative_order(order);
    check_parameter(u, domain());
    return algorithm == bspline_evaluation::de_boor ? core_.de_boor(u, order) : core_.basis_sum(u, order);
  }

  /// The span k with t_k <= u < t_{k+1} (the last non-empty span at the right end).
  [[nodiscard]] std::size_t span_index(const Real& u) const {
    check_parameter(u, domain());
    return core_.find_span(u);
  }

  /// The m basis functions N_{k-m+1, m}(u) .. N_{k, m}(u) that may be non-zero at u (out.size() == order),
  /// by the triangular Cox-de Boor recursion; returns the span k.
  std::size_t nonzero_basis(const Real& u, std::span<Real> out) const {
    validate::same_count("out", out.size(), "order", static_cast<std::size_t>(order()));
    check_parameter(u, domain());
    std::array<Real, bspline_max_order> b;
    const std::size_t k = core_.nonzero_basis(u, 0, b);
    for (std::size_t j = 0; j < out.size(); ++j) out[j] = b[j];
    return k;
  }

  /// N_{i, q}(u) for 1 <= q <= m and i + q < knots().size(), by the literal recursion of seed 000
  /// (cost O(2^q), meant for tests and teaching), with 0/0 = 0. The order-1 indicator follows the
  /// half-open rule, except at the right end of the domain where span_index(u) gets the 1.
  [[nodiscard]] Real basis(std::size_t i, int q, const Real& u) const {
    if (q < 1 || q > order())
      validate::fail("q = " + std::to_string(q) + ": basis order must be in [1, " + std::to_string(order()) + "]");
    if (i + static_cast<std::size_t>(q) >= knots().size())
      validate::fail("i = " + std::to_string(i) + ": N_{i," + std::to_string(q) + "} needs i + q < " +
                     std::to_string(knots().size()));
    check_parameter(u, domain());
    return basis_recursive(i, static_cast<std::size_t>(q), u, core_.find_span(u));
  }

  /// The derivative as a B-spline of order m - 1 (knots t_1 .. t_{n+m-2}, same domain).
  /// Throws invalid_input for m = 1 (the derivative is 0, and order 0 does not exist) and when an
  /// interior knot has multiplicity m (the curve jumps there; its derivative is no B-spline).
  [[nodiscard]] bspline derivative_curve() const {
    if (order() < 2) validate::fail("derivative_curve: order 1 B-spline has derivative 0; no order-0 B-spline exists");
    const auto t = knots();
    std::vector<Real> k(t.begin() + 1, t.end() - 1);
    const auto q = core_.control(1);
    return bspline(order() - 1, std::move(k), point_list<Real, Dim>(q.begin(), q.end()));
  }

  /// Boehm's knot insertion: the same curve with the knot u added (u in the domain). Control points
  /// k-m+2 .. k become convex combinations of their neighbours (k the span of u); O(n).
  [[nodiscard]] bspline insert_knot(const Real& u) const {
    validate::finite("u", u);
    check_parameter(u, domain());
    const auto t = knots();
    const auto p = control_points();
    const std::size_t m = static_cast<std::size_t>(order());
    const std::size_t k = core_.find_span(u);
    point_list<Real, Dim> q;
    q.reserve(p.size() + 1);
    for (std::size_t i = 0; i + m <= k + 1; ++i) q.push_back(p[i]);  // i <= k - m + 1
    for (std::size_t i = k + 2 - m; i <= k; ++i) {
      // a_i = (u - t_i) / (t_{i+m-1} - t_i); t_{i+m-1} >= t_{k+1} > t_k >= t_i: no 0/0.
      const Real a = (u - t[i]) / (t[i + m - 1] - t[i]);
      q.push_back((Real(1) - a) * p[i - 1] + a * p[i]);
    }
    for (std::size_t i = k + 1; i <= p.size(); ++i) q.push_back(p[i - 1]);
    std::vector<Real> nt(t.begin(), t.end());
    nt.insert(nt.begin() + static_cast<std::ptrdiff_t>(k + 1), u);
    return bspline(order(), std::move(nt), std::move(q));
  }

  /// For a cubic (m = 4): the same curve in the piecewise_cubic engine, one segment per non-empty
  /// span, as the Hermite geometry [P(t_k+), P(t_{k+1}-), h P'(t_k+), h P'(t_{k+1}-)] (one-sided
  /// values, so a curve with a knot of multiplicity 4 converts too).
  [[nodiscard]] piecewise_cubic<Real, Dim> to_piecewise_cubic() const {
    if (order() != 4)
      validate::fail("order = " + std::to_string(order()) +
                     ": only a cubic (order 4) B-spline converts to piecewise_cubic");
    const auto t = knots();
    const auto br = breakpoints();
    std::vector<Real> ks(br.begin(), br.end());
    std::vector<typename piecewise_cubic<Real, Dim>::geometry_type> g;
    g.reserve(ks.size() - 1);
    for (std::size_t k = 3; k + 1 < t.size() - 3; ++k) {
      if (!(t[k] < t[k + 1])) continue;
      const Real h = t[k + 1] - t[k];
      typename piecewise_cubic<Real, Dim>::geometry_type gi;
      gi.row(0) = core_.de_boor_at(t[k], 0, k).transpose();
      gi.row(1) = core_.de_boor_at(t[k + 1], 0, k).transpose();
      gi.row(2) = (h * core_.de_boor_at(t[k], 1, k)).transpose();
      gi.row(3) = (h * core_.de_boor_at(t[k + 1], 1, k)).transpose();
      g.push_back(gi);
    }
    return piecewise_cubic<Real, Dim>(std::move(ks), std::move(g), basis::hermite_matrix<Real>());
  }

 private:
  [[nodiscard]] Real basis_recursive(std::size_t i, std::size_t q, const Real& u, std::size_t span) const {
    const auto t = knots();
    if (q == 1) return i == span ? Real(1) : Real(0);
    Real v = detail::bspline_ratio<Real>(u - t[i], t[i + q - 1] - t[i]) * basis_recursive(i, q - 1, u, span);
    v += detail::bspline_ratio<Real>(t[i + q] - u, t[i + q] - t[i + 1]) * basis_recursive(i + 1, q - 1, u, span);
    return v;
  }

  detail::bspline_core<Real, point_type> core_;
  std::array<Real, 2> rounding_bound_{};  // 0 at levels >= order (exact zeros)
};

/// A closed (periodic) B-spline with the control loop P_0 .. P_{s-1} (s >= 2 points), on
/// breakpoints b_0 < ... < b_s (s + 1 values, period b_s - b_0): control points P_0..P_{s-1},
/// P_0..P_{m-2} on bspline_periodic_knots(breaks, m). The curve is C^{m-2} everywhere, including
/// the seam u = b_0 ~ b_s.
template <class Real, int Dim>
[[nodiscard]] bspline<Real, Dim> periodic_bspline(int order, std::span<const point<Real, Dim>> loop,
                                                  std::span<const Real> breaks) {
  detail::bspline_check_order(order);
  validate::count_at_least("loop", loop.size(), 2, "a closed curve needs at least two points");
  validate::same_count("breaks", breaks.size(), "loop points + 1", loop.size() + 1);
  point_list<Real, Dim> p(loop.begin(), loop.end());
  for (std::size_t j = 0; j + 1 < static_cast<std::size_t>(order); ++j) p.push_back(loop[j % loop.size()]);
  return bspline<Real, Dim>(order, bspline_periodic_knots<Real>(breaks, order), std::move(p));
}

/// A closed B-spline on uniform breakpoints 0, 1, ..., s.
template <class Real, int Dim>
[[nodiscard]] bspline<Real, Dim> periodic_bspline(int order, std::span<const point<Real, Dim>> loop) {
  std::vector<Real> breaks(loop.size() + 1);
  for (std::size_t j = 0; j < breaks.size(); ++j) breaks[j] = Real(static_cast<long long>(j));
  return periodic_bspline<Real, Dim>(order, loop, std::span<const Real>(breaks));
}

}  // namespace curvebench
