// Gaussian arc length of any curve: s = integral |P'(u)| du, split at every breakpoint.
//
// speed(c, u) = |P'(u)| (one derivative evaluation). gauss_length: the fixed n-point
// Gauss-Legendre rule per segment; with fixed_estimate::nested each segment is first split at its
// deep speed minima (detail/speed_minima.hpp), each piece integrated as 1, 2 and 4 panels, Q4
// reported with estimate |Q2 - Q4| + |Q1 - Q2| / 15 + rounding floor + the floor of its nodes'
// placement (Q4's error is at most |Q2 - Q4| plus Q2's, which |Q1 - Q2| / 15 bounds where the
// first halving gained a factor 16), trusted only at an observed order >= 4
// (|Q1 - Q2| >= 16 |Q2 - Q4|); a piece that fails that test is halved and each half tried again by
// the same rule, up to 4 levels (a pre-asymptotic piece of a many-segment spline: see fixed_segment),
// and a part still failing gets no bound; a piece ending at a near-cusp whose branch point is within
// 1/8 of its width gets no bound (not_guaranteed, +inf), and so does a piece with a shallow speed
// minimum inside whose branch points are that close to the real axis. Every result that is not
// converged names why (result.hpp's reason: the bound, the segment, the part, the numbers).
// composite_gauss_length: m equal panels of n points,
// no bound. adaptive_length: adaptive Gauss-Kronrod (gauss_kronrod.hpp); each segment's first panel
// is G15-K31, and its 31 node speeds screen for a low speed minimum (screen_flags); a segment that
// shows one gets the same split as the nested rule, with split points graded geometrically
// (m +- delta 4^k) towards a near-cusp so every panel is at least a third of its width from the
// branch point (Bernstein-ellipse parameter >= 3); a smooth segment refines from its first panel.
// Sources: seed 002; Guenter & Parent (1990); Trefethen (2013), ch. 19, for the Bernstein-ellipse
// error of Gauss rules. Cost: n evaluations per segment (7n per piece nested, up to 31 x 7n where
// a piece is halved); adaptive: 31 per
// segment, then per the tolerance, plus, where the screen flags, its samples and log4(width / delta)
// + 1 panels per side of a near-cusp.
// Every bounded estimate also holds the curve's own rounding, rounding_bound(c, 1) |b - a|
// (core/curve.hpp; +inf, i.e. not_guaranteed, for a curve that knows no bound; an adaptive result
// whose estimate it lifts above the tolerance is rounding_limited): O(1) per result.
// Accuracy: geometric in n where the speed is analytic near the segment; algebraic at a kink.
#pragma once

#include "curvebench/arclength/detail/speed_minima.hpp"
#include "curvebench/arclength/gauss_kronrod.hpp"
#include "curvebench/arclength/gauss_legendre.hpp"
#include "curvebench/arclength/result.hpp"
#include "curvebench/core/curve.hpp"
#include "curvebench/core/detail/segment_lookup.hpp"
#include "curvebench/core/error.hpp"

#include <algorithm>
#include <array>
#include <cstddef>
#include <span>
#include <utility>
#include <vector>

namespace curvebench::arclength {

// speed() is forced inline into the quadrature loops that call it (left to its heuristics GCC
// calls it out of line once per node, and the call costs as much as a cubic's derivative).
#if defined(__GNUC__)
#define CURVEBENCH_SPEED_INLINE [[gnu::always_inline]] inline
#define CURVEBENCH_LAMBDA_INLINE __attribute__((always_inline))
#else
#define CURVEBENCH_SPEED_INLINE inline
#define CURVEBENCH_LAMBDA_INLINE
#endif

/// |P'(u)|, the speed of the curve at u (one derivative evaluation), without overflow or underflow
/// of the squares (safe_norm): finite for every finite P'(u).
template <curve C>
[[nodiscard]] CURVEBENCH_SPEED_INLINE typename C::real_type speed(const C& c, const typename C::real_type& u) {
  return safe_norm(typename C::point_type(c.derivative(u, 1)));
}

/// The arc-length error the curve's own rounding can cause over [a, b]: rounding_bound(c, 1) |b - a|
/// (core/curve.hpp): |P'| is off by at most the bound at every u. +inf when the curve knows no bound.
template <curve C>
[[nodiscard]] typename C::real_type evaluation_error(const C& c, const typename C::real_type& a,
                                                     const typename C::real_type& b) {
  using Real = typename C::real_type;
  using std::abs;
  if (!(b != a)) return Real(0);
  return rounding_bound(c, 1) * Real(abs(b - a));
}

/// Adds e (an evaluation_error) to a result's estimate. An infinite e leaves no bound
/// (not_guaranteed, +inf); an estimate that e takes above `target` (the tolerance asked for) means
/// the curve's own rounding is what stops the method: rounding_limited.
/// The reasons name [a, b], the interval e covers.
template <class Real>
void add_evaluation_error(quadrature_result<Real>& r, const Real& e, const Real& target, const Real& a = Real(0),
                          const Real& b = Real(0)) {
  if (r.status == result_status::not_guaranteed || !(e > Real(0))) return;
  if (!is_finite(e)) {
    r.error_estimate = no_bound<Real>();
    r.status = result_status::not_guaranteed;
    r.reason = status_reason<Real>{reasons::no_rounding_bound, status_reason<Real>::npos, a, b};
    return;
  }
  r.error_estimate += e;
  if (r.error_estimate > target)
    r.degrade(result_status::rounding_limited,
              status_reason<Real>{reasons::rounding_over_tolerance, status_reason<Real>::npos, a, b, e, target});
}

/// How a fixed Gauss-Legendre length estimates its error.
enum class fixed_estimate {
  none,   ///< n evaluations per segment, no bound (status not_guaranteed)
  nested  ///< 7n evaluations per segment: the rule on 1, 2 and 4 panels, see gauss_length
};

namespace detail {

/// Names the segment of a reason that has a parameter interval but no segment (a panel of the
/// adaptive refinement): the segment of breakpoints bp that holds its start.
template <class Real>
void locate_segment(status_reason<Real>& r, std::span<const Real> bp) {
  if (r.empty() || r.segment != status_reason<Real>::npos || !(r.b > r.a) || bp.size() < 2) return;
  r.segment = curvebench::detail::segment_of<Real>(bp, r.a);
}

/// a, the breakpoints strictly inside (min(a,b), max(a,b)), b (ascending; a <= b required).
template <curve C>
std::vector<typename C::real_type> split_points(const C& c, const typename C::real_type& a,
                                                const typename C::real_type& b) {
  std::vector<typename C::real_type> s;
  s.push_back(a);
  for (const auto& t : c.breakpoints())
    if (t > a && t < b) s.push_back(t);
  s.push_back(b);
  return s;
}

/// One panel by a fixed rule, with the optional nested estimate.
template <class Real, class F>
quadrature_result<Real> fixed_panel(F&& f, const Real& a, const Real& b, const gauss_legendre_rule<Real>& rule,
                                    fixed_estimate est) {
  using std::abs;
  quadrature_result<Real> r;
  const Real whole = rule.integrate(f, a, b);
  r.evaluations = rule.nodes.size();
  if (est == fixed_estimate::none) {
    r.value = whole;
    r.error_estimate = no_bound<Real>();
    r.status = result_status::not_guaranteed;
    r.reason.what = reasons::no_estimate;
    r.reason.a = a;
    r.reason.b = b;
    return r;
  }
  const Real h = (b - a) / Real(4);
  const Real q1 = a + h, mid = (a + b) / Real(2), q3 = b - h;
  Real fmin = whole / (b - a), fmax = fmin;  // the range of f over the nodes (starting at its mean)
  auto g = [&](const Real& u) {
    const Real v = f(u);
    fmin = std::min(fmin, v);
    fmax = std::max(fmax, v);
    return v;
  };
  const Real l = rule.integrate(g, a, q1), ml = rule.integrate(g, q1, mid), mr = rule.integrate(g, mid, q3),
             r4 = rule.integrate(g, q3, b);
  const Real halves = rule.integrate(g, a, mid) + rule.integrate(g, mid, b);
  const Real quarters = (l + ml) + (mr + r4);
  r.evaluations += 6 * rule.nodes.size();
  r.value = quarters;
  // The speed is >= 0, so |integral| bounds integral |f|: the rounding floor covers the rounding of f
  // and the sums. Each node is placed within eps (|a| + |b|) of where the rule puts it, which moves
  // the value by up to that times the variation of f over the piece: 2 eps (|a| + |b|) (max f - min f)
  // holds it where f has at most one extremum in the piece (as gauss_kronrod.hpp's resolution_floor).
  // Q1, Q2 and Q4 need not show it (a domain [1e20, 1e20 + 1e10]: d2 was 3e-9 of an error of 9e-8).
  const Real floor = rounding_floor(abs(quarters)) + Real(2) * epsilon<Real>() * (abs(a) + abs(b)) * (fmax - fmin);
  const Real d1 = abs(whole - halves), d2 = abs(halves - quarters);
  // Q4's error is at most d2 + |Q2's error|, and Q2's at most d1 / 15 when the first halving gained
  // the factor 16 the order test asks for (|e1| >= 16 |e2|). d2 alone assumed the second halving did
  // too, and a coarse value accurate by accident breaks that: a quarter of the 10 x 5 ellipse by
  // 2-point panels has errors 1.1e-1, 3.9e-6 and 3.8e-5 on 1, 2 and 4 panels, d2 = 3.4e-5.
  r.error_estimate = d2 + d1 / Real(15) + floor;
  // On a smooth speed the rule converges at order 2n >= 4 (n >= 2) once the panels resolve it:
  // d1 >= 16 d2. A kink (cusp) gives order 2 with a constant that depends on where the kink falls
  // in the panels, and a feature narrower than the panels gives anything: not trusted.
  // An untrusted estimate is not reported as a number (result.hpp: not_guaranteed means +inf).
  const bool trusted = d1 >= Real(16) * d2 || (d1 <= floor && d2 <= floor);
  r.status = trusted ? result_status::converged : result_status::not_guaranteed;
  if (!trusted) {
    r.error_estimate = no_bound<Real>();
    r.reason = status_reason<Real>{reasons::order_test, status_reason<Real>::npos, a, b, d1, Real(16) * d2};
  }
  return r;
}

/// The most times a piece that fails the nested rule's order test is halved (each half tried again
/// by the same rule): at most 2^4 = 16 parts of it and 31 tries, 31 x 7n evaluations in all.
inline constexpr int nested_split_levels = 4;

/// One piece by the nested rule, halved where it fails the order test (see fixed_segment): its
/// halves are tried again, up to `levels` more times. Every try is counted; a part still failing at
/// the last level keeps not_guaranteed with the order test's reason.
template <class Real, class F>
quadrature_result<Real> nested_piece(F&& f, const Real& a, const Real& b, const gauss_legendre_rule<Real>& rule,
                                     int levels) {
  quadrature_result<Real> r = fixed_panel(f, a, b, rule, fixed_estimate::nested);
  if (r.status != result_status::not_guaranteed || levels <= 0) return r;
  const Real mid = (a + b) / Real(2);
  if (!(mid > a && mid < b)) return r;  // too narrow to halve in Real
  quadrature_result<Real> halves = nested_piece(f, a, mid, rule, levels - 1);
  halves += nested_piece(f, mid, b, rule, levels - 1);
  halves.evaluations += r.evaluations;  // the failed try was paid for
  return halves;
}

template <class Real>
void check_order(const Real& a, const Real& b, bool& flipped, Real& lo, Real& hi) {
  flipped = b < a;
  lo = flipped ? b : a;
  hi = flipped ? a : b;
}

/// Samples of |P'|^2 per segment for the speed-minimum search of the nested fixed rule.
inline constexpr std::size_t fixed_minimum_samples = 16;

/// One segment [a, b] (segment index `segment` of the curve, named in the reasons) by the fixed
/// rule. With the nested estimate: split at the deep interior speed minima first; a piece that ends
/// at a near-cusp whose branch point is closer than 1/8 of the piece's width gets no bound (see the
/// header); a piece that fails the order test is halved and its halves tried again (nested_piece).
/// Why halving: on a 1000-segment centripetal Catmull-Rom road 19 segments failed the order test
/// with |Q1 - Q2| / |Q2 - Q4| between 8 and 13 where 16 is asked. The rule on a quarter of such a
/// segment is still pre-asymptotic (the speed varies on a scale near the quarter's width, so the
/// ratio has not reached 2^(2n)), one such piece left the whole sum without a bound, and with 100
/// segments of the same road none failed only by luck. On a half, the same rule's panels are half
/// as wide and the order test passes where the speed is analytic near the piece; the estimate of
/// each part is the same |Q2 - Q4| + |Q1 - Q2| / 15 + floors, so the sum keeps a true bound. A near-cusp is not
/// halved: halving leaves the branch point as close to the half that ends there.
template <curve C, class F>
quadrature_result<typename C::real_type> fixed_segment(const C& c, F&& f, const typename C::real_type& a,
                                                       const typename C::real_type& b,
                                                       const gauss_legendre_rule<typename C::real_type>& rule,
                                                       fixed_estimate est, std::size_t segment) {
  using Real = typename C::real_type;
  if (est == fixed_estimate::none) {
    quadrature_result<Real> r = fixed_panel(f, a, b, rule, est);
    r.reason.segment = segment;
    return r;
  }
  std::size_t extra = 0;
  std::vector<speed_minimum<Real>> shallow;
  const std::vector<speed_minimum<Real>> pts = speed_features(c, a, b, fixed_minimum_samples, extra, &shallow);
  quadrature_result<Real> r;
  auto near_cusp = [](const speed_minimum<Real>& m, const Real& width) {
    return branch_point_matters(m.delta, width) && m.delta < width / Real(8);
  };
  for (std::size_t k = 0; k + 1 < pts.size(); ++k) {
    if (!(pts[k + 1].u > pts[k].u)) continue;
    const Real w = pts[k + 1].u - pts[k].u;
    // A shallow minimum inside the piece whose branch points are nearer the real axis than w / 8, the
    // half-width of the quarter panels: the quarter panel under it sees the speed analytic only in a
    // Bernstein ellipse of parameter < 1 + sqrt(2), the halves' and the whole's ellipses are smaller
    // still, and the three values need not converge in order; their differences can then agree by
    // coincidence and pass the order test (Runge's graph through 21 Chebyshev points, n = 8: the
    // test passed with |Q2 - Q4| = 2.8e-4 L against a true error of 1.2e-3 L).
    const auto shallow_near = std::find_if(shallow.begin(), shallow.end(), [&](const speed_minimum<Real>& m) {
      return m.u > pts[k].u && m.u < pts[k + 1].u && near_cusp(m, w);
    });
    quadrature_result<Real> piece;
    if (shallow_near != shallow.end() || near_cusp(pts[k], w) || near_cusp(pts[k + 1], w)) {
      piece = fixed_panel(f, pts[k].u, pts[k + 1].u, rule, est);
      piece.error_estimate = no_bound<Real>();
      piece.status = result_status::not_guaranteed;
      const Real delta = shallow_near != shallow.end() ? shallow_near->delta
                         : near_cusp(pts[k], w)        ? pts[k].delta
                                                       : pts[k + 1].delta;
      piece.reason = segment_reason(shallow_near != shallow.end() ? reasons::shallow_near : reasons::near_cusp, segment,
                                    pts[k].u, pts[k + 1].u, delta, w / Real(8));
    } else {
      piece = nested_piece(f, pts[k].u, pts[k + 1].u, rule, nested_split_levels);
      if (!piece.reason.empty()) piece.reason.segment = segment;
    }
    r += piece;
  }
  r.evaluations += extra;
  return r;
}

}  // namespace detail

/// Length of the part from a to b (signed: negative when b < a) by the fixed n-point rule on each
/// piece between breakpoints. Throws std::domain_error when a or b is outside the domain.
template <curve C>
[[nodiscard]] quadrature_result<typename C::real_type> gauss_length(
    const C& c, const typename C::real_type& a, const typename C::real_type& b,
    const gauss_legendre_rule<typename C::real_type>& rule, fixed_estimate est = fixed_estimate::none) {
  using Real = typename C::real_type;
  check_parameter(a, interval<Real>(c.domain()));
  check_parameter(b, interval<Real>(c.domain()));
  bool flipped;
  Real lo, hi;
  detail::check_order(a, b, flipped, lo, hi);
  auto f = [&c](const Real& u) { return speed(c, u); };
  quadrature_result<Real> total;
  total.status = est == fixed_estimate::none ? result_status::not_guaranteed : result_status::converged;
  const std::span<const Real> bp = c.breakpoints();
  Real prev = lo;
  std::size_t seg = curvebench::detail::segment_of<Real>(bp, lo);  // the segment holding [prev, next]
  for (std::size_t i = 0; i < bp.size(); ++i) {
    const Real& t = bp[i];
    if (!(t > lo && t < hi)) continue;
    total += detail::fixed_segment(c, f, prev, t, rule, est, seg);
    prev = t;
    seg = i;
  }
  if (hi > prev) total += detail::fixed_segment(c, f, prev, hi, rule, est, seg);
  if (est == fixed_estimate::none) {
    total.error_estimate = no_bound<Real>();
    total.reason = global_reason<Real>(reasons::no_estimate);
  }
  add_evaluation_error(total, evaluation_error(c, lo, hi), no_bound<Real>(), lo, hi);
  if (flipped) total.value = -total.value;
  return total;
}

/// Total length by the fixed rule on every segment (with estimate::none no allocation: the hot
/// path of the benchmarks; fetch the rule once with gauss_legendre<Real>(n)).
template <curve C>
[[nodiscard]] quadrature_result<typename C::real_type> gauss_length(
    const C& c, const gauss_legendre_rule<typename C::real_type>& rule, fixed_estimate est = fixed_estimate::none) {
  using Real = typename C::real_type;
  auto f = [&c](const Real& u) { return speed(c, u); };
  const std::span<const Real> bp = c.breakpoints();
  quadrature_result<Real> total;
  total.status = est == fixed_estimate::none ? result_status::not_guaranteed : result_status::converged;
  for (std::size_t i = 0; i + 1 < bp.size(); ++i)
    if (bp[i + 1] > bp[i]) total += detail::fixed_segment(c, f, bp[i], bp[i + 1], rule, est, i);
  if (est == fixed_estimate::none) {
    total.error_estimate = no_bound<Real>();
    total.reason = global_reason<Real>(reasons::no_estimate);  // not one segment's: the rule's
  }
  add_evaluation_error(total, evaluation_error(c, bp.front(), bp.back()), no_bound<Real>(), bp.front(), bp.back());
  return total;
}

/// Total length by the fixed n-point rule per segment (cached rule).
template <curve C>
[[nodiscard]] quadrature_result<typename C::real_type> gauss_length(const C& c, int n,
                                                                    fixed_estimate est = fixed_estimate::none) {
  return gauss_length(c, gauss_legendre<typename C::real_type>(n), est);
}

/// Total length by the composite rule: `panels` equal panels per segment, the rule on each.
/// No error bound (status not_guaranteed); tests measure its order O(h^(2n)).
template <curve C>
[[nodiscard]] quadrature_result<typename C::real_type> composite_gauss_length(
    const C& c, int panels, const gauss_legendre_rule<typename C::real_type>& rule) {
  using Real = typename C::real_type;
  if (panels < 1) validate::fail("panels = " + std::to_string(panels) + ": must be >= 1");
  auto f = [&c](const Real& u) { return speed(c, u); };
  const std::span<const Real> bp = c.breakpoints();
  quadrature_result<Real> total;
  for (std::size_t i = 0; i + 1 < bp.size(); ++i) {
    if (!(bp[i + 1] > bp[i])) continue;
    total.value += integrate_composite(f, bp[i], bp[i + 1], panels, rule);
    total.evaluations += static_cast<std::size_t>(panels) * rule.nodes.size();
  }
  total.error_estimate = no_bound<Real>();
  total.status = result_status::not_guaranteed;
  total.reason = global_reason<Real>(reasons::composite_no_estimate);
  return total;
}

namespace detail {

/// Appends lo.u and the split points graded towards whichever end of [lo.u, hi.u] is a near-cusp
/// (see the header): m +- delta 4^k, k = 0, 1, ... while delta 4^(k+1) < the span graded, so the
/// last panel is at most 3x as wide as its distance delta 4^K to the minimum, and the first,
/// [m, m + delta], is as wide as the branch point is far. A piece with near-cusps at both ends is
/// cut in the middle and each half graded from its own end.
template <class Real>
void append_graded(const speed_minimum<Real>& lo, const speed_minimum<Real>& hi, std::vector<Real>& out) {
  out.push_back(lo.u);
  const Real w = hi.u - lo.u;
  const bool grade_lo = branch_point_matters(lo.delta, w), grade_hi = branch_point_matters(hi.delta, w);
  if (!grade_lo && !grade_hi) return;
  const Real mid = (lo.u + hi.u) / Real(2);
  if (grade_lo) {
    const Real span = grade_hi ? mid - lo.u : w;
    for (Real d = lo.delta; Real(4) * d < span; d *= Real(4)) out.push_back(lo.u + d);
  }
  if (grade_lo && grade_hi) out.push_back(mid);
  if (grade_hi) {
    const Real span = grade_lo ? hi.u - mid : w;
    const std::size_t first = out.size();
    for (Real d = hi.delta; Real(4) * d < span; d *= Real(4)) out.push_back(hi.u - d);
    std::reverse(out.begin() + static_cast<std::ptrdiff_t>(first), out.end());
  }
}

/// The split points with the interior speed minima of every piece inserted, and graded towards
/// the near-cusps among them (when enabled).
template <curve C>
std::vector<typename C::real_type> with_speed_minima(const C& c, const std::vector<typename C::real_type>& s,
                                                     std::size_t samples, std::size_t& evaluations) {
  using Real = typename C::real_type;
  if (samples == 0) return s;
  std::vector<Real> out;
  std::vector<speed_minimum<Real>> pts;
  for (std::size_t i = 0; i + 1 < s.size(); ++i) {
    if (!(s[i + 1] > s[i])) {
      out.push_back(s[i]);
      continue;
    }
    pts = speed_features(c, s[i], s[i + 1], samples, evaluations);
    for (std::size_t k = 0; k + 1 < pts.size(); ++k) append_graded(pts[k], pts[k + 1], out);
  }
  out.push_back(s.back());
  return out;
}

/// The speed-minimum screen on a piece's first panel: whether the node speeds v (ascending nodes)
/// show what speed_features examines, an interior node at a local minimum or an end node with the
/// speed falling towards the end, at most half the largest node speed (speed_features' level is a
/// quarter, on 17 equally spaced samples: the level here is more cautious, and the 31 G15-K31 nodes
/// are nowhere further apart than 0.05 of the piece, closer than those samples' 1/16). A flagged
/// piece only costs the examination; an unflagged one is integrated from the panel as it is.
template <class Real>
[[nodiscard]] inline bool screen_flags(std::span<const Real> v) {
  const std::size_t m = v.size();
  if (m < 3) return true;
  // The top and the lowest speed, each by four independent chains (one chain through 31 nodes
  // waited on every compare); a NaN node is passed over, as by the comparisons below.
  Real t0(0), t1(0), t2(0), t3(0), b0 = v[0], b1 = v[0], b2 = v[0], b3 = v[0];
  std::size_t j = 0;
  for (; j + 4 <= m; j += 4) {
    t0 = std::max(t0, v[j]), t1 = std::max(t1, v[j + 1]), t2 = std::max(t2, v[j + 2]), t3 = std::max(t3, v[j + 3]);
    b0 = std::min(b0, v[j]), b1 = std::min(b1, v[j + 1]), b2 = std::min(b2, v[j + 2]), b3 = std::min(b3, v[j + 3]);
  }
  for (; j < m; ++j) t0 = std::max(t0, v[j]), b0 = std::min(b0, v[j]);
  const Real top = std::max(std::max(t0, t1), std::max(t2, t3));
  const Real level = top / Real(2);
  if (!(top > Real(0))) return true;
  if (std::min(std::min(b0, b1), std::min(b2, b3)) > level) return false;  // no node low enough
  // Without data-dependent branches: every node is looked at, which costs less than mispredicting.
  // (int, not bool, operands: '&' on bools reads as a mistaken '&&' to clang's -Wbitwise-instead-of-logical.)
  int flag = int(v[0] <= v[1]) & int(v[0] <= level);
  flag |= int(v[m - 1] <= v[m - 2]) & int(v[m - 1] <= level);
  for (std::size_t k = 1; k + 1 < m; ++k) flag |= int(v[k] <= v[k - 1]) & int(v[k] <= v[k + 1]) & int(v[k] <= level);
  return flag != 0;
}

/// The length of c over the pieces between the split points s (ascending) by adaptive
/// Gauss-Kronrod, with the speed-minimum screen (adaptive_options::speed_minimum_samples): each
/// piece's first panel by G15-K31, its node speeds screened (screen_flags); a flagged piece is split
/// at its interior speed minima and graded towards its near-cusps (speed_features, append_graded)
/// and those parts get first panels by opt's rule, unless nothing is found to split at (the G15-K31
/// panel is then kept). Then the global refinement of integrate_adaptive. Evaluations include the
/// screen's and the examination's.
template <curve C>
[[nodiscard]] quadrature_result<typename C::real_type> screened_length(
    const C& c, std::span<const typename C::real_type> s, const adaptive_options<typename C::real_type>& opt) {
  using Real = typename C::real_type;
  // s is a curve's breakpoints or split_points (at least 2, ascending: the curve validated them);
  // checking them again per call cost a tenth of a smooth segment's length.
  check_tolerances(opt.absolute_tolerance, opt.relative_tolerance);
  auto f = [&c](const Real& u) CURVEBENCH_LAMBDA_INLINE { return speed(c, u); };
  const gauss_kronrod_rule<Real>& rule = gauss_kronrod<Real>(opt.gauss_points);
  constexpr int screen_points = 15;  // G15-K31: 31 nodes, at most 0.05 of the piece apart
  const gauss_kronrod_rule<Real>& screen = gauss_kronrod<Real>(screen_points);
  std::vector<heap_panel<Real>> heap;
  quadrature_result<Real> out;
  std::array<Real, 2 * screen_points + 1> v;  // the screen rule's node speeds
  std::vector<Real> parts;
  std::vector<speed_minimum<Real>> pts;
  for (std::size_t i = 0; i + 1 < s.size(); ++i) {
    const Real a = s[i], b = s[i + 1];
    if (!(b > a)) continue;  // empty interval: contributes 0
    if (opt.speed_minimum_samples == 0) {
      heap.push_back({a, b, rule.apply(f, a, b, opt.model)});
      out.evaluations += heap.back().r.evaluations;
      continue;
    }
    const kronrod_panel<Real> first = screen.apply(f, a, b, opt.model, v.data());
    out.evaluations += first.evaluations;
    if (!screen_flags(std::span<const Real>(v.data(), screen.nodes.size()))) {
      // One piece whose first panel meets the target already: refine_adaptive's answer for it
      // (one panel: its value, its estimate plus the summation term), without the panel list.
      using std::abs;
      using std::max;
      const Real estimate = first.error_estimate + Real(4) * epsilon<Real>() * abs(first.kronrod);
      if (s.size() == 2 && estimate <= max(opt.absolute_tolerance, opt.relative_tolerance * abs(first.kronrod)))
        return {first.kronrod, estimate, out.evaluations, result_status::converged};
      heap.push_back({a, b, first});
      continue;
    }
    pts = speed_features(c, a, b, opt.speed_minimum_samples, out.evaluations);
    parts.clear();
    for (std::size_t k = 0; k + 1 < pts.size(); ++k) append_graded(pts[k], pts[k + 1], parts);
    parts.push_back(b);
    if (parts.size() == 2) {  // nothing to split at or grade towards
      heap.push_back({a, b, first});
      continue;
    }
    for (std::size_t k = 0; k + 1 < parts.size(); ++k) {
      if (!(parts[k + 1] > parts[k])) continue;
      heap.push_back({parts[k], parts[k + 1], rule.apply(f, parts[k], parts[k + 1], opt.model)});
      out.evaluations += heap.back().r.evaluations;
    }
  }
  return refine_adaptive(f, rule, opt, std::move(heap), out);
}

}  // namespace detail

/// Length from a to b (signed) by adaptive Gauss-Kronrod, split at the breakpoints in between and
/// at the interior speed minima (opt.speed_minimum_samples). Throws std::domain_error for a or b
/// outside the domain, invalid_input for bad tolerances.
template <curve C>
[[nodiscard]] quadrature_result<typename C::real_type> adaptive_length(
    const C& c, const typename C::real_type& a, const typename C::real_type& b,
    const adaptive_options<typename C::real_type>& opt = {}) {
  using Real = typename C::real_type;
  check_parameter(a, interval<Real>(c.domain()));
  check_parameter(b, interval<Real>(c.domain()));
  bool flipped;
  Real lo, hi;
  detail::check_order(a, b, flipped, lo, hi);
  const std::vector<Real> s = detail::split_points(c, lo, hi);
  quadrature_result<Real> r = detail::screened_length(c, std::span<const Real>(s), opt);
  detail::locate_segment(r.reason, c.breakpoints());
  using std::abs;
  using std::max;
  add_evaluation_error(r, evaluation_error(c, lo, hi),
                       max(opt.absolute_tolerance, opt.relative_tolerance * abs(r.value)), lo, hi);
  if (flipped) r.value = -r.value;
  return r;
}

/// Total length by adaptive Gauss-Kronrod over all segments (split at breakpoints and speed minima).
template <curve C>
[[nodiscard]] quadrature_result<typename C::real_type> adaptive_length(
    const C& c, const adaptive_options<typename C::real_type>& opt = {}) {
  using Real = typename C::real_type;
  const std::span<const Real> bp = c.breakpoints();
  quadrature_result<Real> r = detail::screened_length(c, bp, opt);
  detail::locate_segment(r.reason, bp);
  using std::abs;
  using std::max;
  add_evaluation_error(r, evaluation_error(c, bp.front(), bp.back()),
                       max(opt.absolute_tolerance, opt.relative_tolerance * abs(r.value)), bp.front(), bp.back());
  return r;
}

}  // namespace curvebench::arclength
