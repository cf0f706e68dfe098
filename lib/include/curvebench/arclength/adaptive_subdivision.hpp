// Adaptive subdivision arc length (Parent's chord test): compare an interval's chord with the sum
// of its halves' chords; accept the halves within the tolerance, else recurse with half of it.
// Three points can be fooled (collinear, evenly spaced samples of a wandering curve such as
// (u, u^3 - u) on [-1, 1]), so two guards are on by default: min_depth levels before trusting the
// test, and look_ahead (the quarter chords must agree too, at an observed order >= log2 3). No
// sampling method is proof against a curve designed to pass at every level.
// The target is max(tolerance, relative_tolerance * size), size the length of the polygon through
// the breakpoints and the segments' midpoints (a lower bound of L): by default 1e-6 relative, so
// the same work measures a curve of size 1e10 or 1e-10.
// Estimate: the accepted differences (order >= 1 assumed without look-ahead, checked with it) plus
// rounding, the curve's own included: 2 rounding_bound(c, 0) per position evaluated (core/curve.hpp;
// not_guaranteed, +inf, for a curve without a bound). Status: converged when every leaf passed;
// rounding_limited when a leaf's share of the target was below its chords' rounding (16 eps of their
// length) and it was accepted at that level; cap_hit when max_depth or the evaluation budget forced
// a leaf (at max_depth its last difference is its estimate, as for a passed leaf without look-ahead;
// a leaf the budget stopped has no bound, and the estimate is then +inf).
// Sources: Parent (2012), 3.2.2; seed 002 ("adaptive forward differencing").
// Cost: ~2 position evaluations per accepted leaf (+2 with look-ahead), ~(L / target)^(1/2)
// leaves; at most max_evaluations (2^22), plus 5 per segment and 3 per level of the recursion (a
// half pending when the budget ran out evaluates its midpoint before it stops). Accuracy: order 2 in the leaf size
// on smooth pieces.
#pragma once

#include "curvebench/arclength/result.hpp"
#include "curvebench/core/curve.hpp"
#include "curvebench/core/error.hpp"

#include <algorithm>
#include <cstddef>
#include <span>
#include <string>

namespace curvebench::arclength {

template <class Real>
struct subdivision_options {
  Real tolerance{0};  ///< absolute, in length units, over the whole curve (0: relative only)
  /// Relative to the curve's size (see the header); the target is the larger of the two.
  Real relative_tolerance{Real(1) / Real(1000000)};
  int min_depth{2};
  int max_depth{40};
  bool look_ahead{true};
  /// Position evaluations allowed: no leaf is refined once they are spent (cap_hit); each segment
  /// still costs its ends and midpoint (and look-ahead), 5 at most, and each half pending on the
  /// recursion stack 3.
  std::size_t max_evaluations{std::size_t(1) << 22};
};

namespace detail {

template <curve C>
struct subdivider {
  using Real = typename C::real_type;
  using P = typename C::point_type;
  const C& c;
  const subdivision_options<Real>& opt;
  quadrature_result<Real> out{};

  static Real dist(const P& a, const P& b) { return safe_norm(P(b - a)); }

  // Length of [a, b] with end points pa, pb; tol is this interval's share.
  void run(const Real& a, const Real& b, const P& pa, const P& pb, const Real& tol, int depth) {
    using std::abs;
    const Real m = (a + b) / Real(2);
    const P pm = c(m);
    ++out.evaluations;
    const Real whole = dist(pa, pb);
    const Real halves = dist(pa, pm) + dist(pm, pb);
    const Real diff = abs(halves - whole);
    bool accept = depth >= opt.min_depth && diff <= tol;
    if (accept && opt.look_ahead) {
      const P q1 = c((a + m) / Real(2));
      const P q3 = c((m + b) / Real(2));
      out.evaluations += 2;
      const Real quarters = dist(pa, q1) + dist(q1, pm) + dist(pm, q3) + dist(q3, pb);
      const Real d2 = abs(quarters - halves);
      const Real noise = Real(16) * epsilon<Real>() * quarters;
      // A share below the chords' rounding is met at the rounding level (rounding_limited).
      if (!(d2 <= tol) && d2 <= noise && diff <= noise) {
        out.value += quarters;
        out.error_estimate += d2 + noise;
        out.status = worst(out.status, result_status::rounding_limited);
        return;
      }
      // Accept the quarters when the chord sums converge at an observed order >= log2(3) (diff >=
      // 3 d2; smooth pieces tend to order 2): then |L - quarters| <= d2 / (2^p - 1) <= d2 / 2, a 2x
      // margin for the order still drifting. Both differences at rounding level also accept.
      // Otherwise (a coincidence of three points, or a cusp-like piece still pre-asymptotic) refine.
      if (d2 <= tol && (diff >= Real(3) * d2 || (d2 <= noise && diff <= noise))) {
        out.value += quarters;
        out.error_estimate += d2 + noise;
        return;
      }
      accept = false;
    }
    if (accept) {
      out.value += halves;
      out.error_estimate += diff;
      return;
    }
    if (depth >= opt.max_depth || !(m > a && m < b) || out.evaluations + 6 > opt.max_evaluations) {
      out.value += halves;
      // At the depth cap (or where the midpoint no longer splits) the leaf is 2^-depth of its segment
      // and its last difference measures it. A leaf the budget stopped can be any size: the recursion
      // is depth first, so the budget may run out with most of the curve still coarse, where a chord
      // difference bounds nothing (a degree-20 Runge polynomial at 1e-8: estimate 1.3e-3 L, error
      // 0.5 L). No bound, then: the estimate is +inf, the status cap_hit.
      out.error_estimate += depth >= opt.max_depth || !(m > a && m < b) ? diff : no_bound<Real>();
      out.status = worst(out.status, result_status::cap_hit);
      return;
    }
    run(a, m, pa, pm, tol / Real(2), depth + 1);
    run(m, b, pm, pb, tol / Real(2), depth + 1);
  }
};

}  // namespace detail

/// Length by adaptive subdivision with Parent's chord test, segment by segment (the target is
/// shared in proportion to the segments' parameter lengths). Throws invalid_input for a negative
/// or non-finite tolerance, both tolerances 0, or negative depths.
template <curve C>
[[nodiscard]] quadrature_result<typename C::real_type> subdivision_length(
    const C& c, const subdivision_options<typename C::real_type>& opt = {}) {
  using Real = typename C::real_type;
  using std::max;
  validate::finite("tolerance", opt.tolerance);
  validate::finite("relative_tolerance", opt.relative_tolerance);
  if (opt.tolerance < Real(0)) validate::fail("tolerance = " + to_text(opt.tolerance) + ": must be >= 0");
  if (opt.relative_tolerance < Real(0))
    validate::fail("relative_tolerance = " + to_text(opt.relative_tolerance) + ": must be >= 0");
  if (!(opt.tolerance > Real(0)) && !(opt.relative_tolerance > Real(0)))
    validate::fail("tolerance = " + to_text(opt.tolerance) +
                   " and relative_tolerance = " + to_text(opt.relative_tolerance) + ": at least one must be > 0");
  if (opt.min_depth < 0) validate::fail("min_depth = " + std::to_string(opt.min_depth) + ": must be >= 0");
  if (opt.max_depth < opt.min_depth)
    validate::fail("max_depth = " + std::to_string(opt.max_depth) +
                   ": must be >= min_depth = " + std::to_string(opt.min_depth));
  const std::span<const Real> bp = c.breakpoints();
  detail::subdivider<C> sub{c, opt};
  const Real total = bp.back() - bp.front();
  // The size: the polygon through the breakpoints and the segments' midpoints (evaluations counted).
  Real size(0);
  for (std::size_t i = 0; i + 1 < bp.size() && opt.relative_tolerance > Real(0); ++i) {
    if (!(bp[i + 1] > bp[i])) continue;
    const typename C::point_type pa = c(bp[i]), pm = c((bp[i] + bp[i + 1]) / Real(2)), pb = c(bp[i + 1]);
    sub.out.evaluations += 3;
    size += sub.dist(pa, pm) + sub.dist(pm, pb);
  }
  const Real target = max(opt.tolerance, Real(opt.relative_tolerance * size));
  for (std::size_t i = 0; i + 1 < bp.size(); ++i) {
    if (!(bp[i + 1] > bp[i])) continue;
    const typename C::point_type pa = c(bp[i]);
    const typename C::point_type pb = c(bp[i + 1]);
    sub.out.evaluations += 2;
    sub.run(bp[i], bp[i + 1], pa, pb, target * (bp[i + 1] - bp[i]) / total, 0);
  }
  using std::abs;
  sub.out.error_estimate +=
      Real(static_cast<long long>(sub.out.evaluations + 8)) * epsilon<Real>() * abs(sub.out.value);
  // The curve's own rounding (core/curve.hpp): every chord end is off by at most rounding_bound(c,
  // 0), and the chords summed are fewer than the positions evaluated.
  const Real b0 = rounding_bound(c, 0);
  if (!is_finite(b0)) {
    sub.out.error_estimate = no_bound<Real>();
    sub.out.status = result_status::not_guaranteed;
  } else if (b0 > Real(0)) {
    sub.out.error_estimate += Real(2) * Real(static_cast<long long>(sub.out.evaluations)) * b0;
  }
  return sub.out;
}

}  // namespace curvebench::arclength
