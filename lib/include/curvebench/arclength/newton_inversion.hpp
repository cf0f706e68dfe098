// Inversion of the arc length: u with s(u) = s*, by Newton's method inside a bracket.
//
// The segment lengths are computed once (segment_lengths: adaptive Gauss-Kronrod with estimates);
// a query finds its segment by binary search on the cumulative lengths, the first bracket. The
// first guess inverts a monotone cubic Hermite model of s(u) from the segment's end lengths and
// speeds. Each iteration integrates from the nearest known point (a bracket end) by recursive
// Gauss-Kronrod (G15-K31, or the G7-K15 short-step rule for steps under 1/32 of the bracket),
// shrinks the bracket and steps u <- u - (s(u) - s*) / |P'(u)|, bisecting when the step leaves
// the bracket or |P'| = 0. Stops when |s(u) - s*| + its error bound <= tolerance (converged), at
// the iteration cap or the evaluation budget (cap_hit: the best iterate, its bound still reported)
// or when the bracket cannot shrink in Real (rounding_limited). Every error bound (segment lengths,
// |s(u) - s*|) includes the curve's own rounding over the stretch integrated, rounding_bound(c, 1)
// |u - u_known| (length.hpp); a curve without a bound is solved all the same and its answers say
// not_guaranteed (+inf).
// Sources: seed 002 (find u2 with arclength(u1, u2) = s); Guenter & Parent (1990); Eberly (2008).
// Cost: O(log segments) + 32 evaluations per long and 16 per short iteration, typically one long
// and two or three short, at most max_evaluations (2^16) per query; no allocation per query.
// segment_lengths: at most adaptive_options::max_evaluations (2^24) over the whole curve, plus a
// few per segment.
// Accuracy: quadratic convergence in u where |P'| > 0; linear (bisection) where it vanishes.
#pragma once

#include "curvebench/arclength/gauss_kronrod.hpp"
#include "curvebench/arclength/length.hpp"
#include "curvebench/arclength/result.hpp"
#include "curvebench/core/curve.hpp"
#include "curvebench/core/error.hpp"

#include <algorithm>
#include <cstddef>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

namespace curvebench::arclength {

/// Throws std::domain_error unless 0 <= s <= length (NaN fails too):
/// "s = 2 is outside the arc-length range [0, 1.5]".
template <class Real>
void check_arc_length(const Real& s, const Real& length) {
  if (s >= Real(0) && s <= length) return;
  throw std::domain_error("s = " + to_text(s) + " is outside the arc-length range [0, " + to_text(length) + "]");
}

/// Cumulative lengths of a curve's segments (between consecutive breakpoints), computed once by
/// adaptive Gauss-Kronrod with their error estimates. Copyable; holds no reference to the curve.
template <class Real>
class segment_lengths {
 public:
  segment_lengths() = default;

  /// Integrates every segment (split at its speed minima) to relative_tolerance (relative to that
  /// segment's length) with options `opt` otherwise; opt.max_evaluations is the budget of the whole
  /// curve (cap_hit in total() when a segment ran out). Throws invalid_input for bad tolerances.
  template <curve C>
    requires std::same_as<typename C::real_type, Real>
  explicit segment_lengths(const C& c, const adaptive_options<Real>& opt = default_options()) {
    const std::span<const Real> bp = c.breakpoints();
    validate::count_at_least("breakpoints", bp.size(), 2, "a curve has at least one segment");
    params_.assign(bp.begin(), bp.end());
    cumulative_.assign(1, Real(0));
    cumulative_error_.assign(1, Real(0));
    auto f = [&c](const Real& u) { return speed(c, u); };
    total_ = quadrature_result<Real>{};
    // Cumulative sums by Neumaier's compensated summation: each cumulative value is within
    // ~2 eps of the exact sum of the segment values, whatever the number of segments.
    Real sum(0), comp(0), err_sum(0);
    using std::abs;
    // The budget opt.max_evaluations is shared: segment i may spend what is left after keeping, for
    // each later segment, the least it costs (its speed samples, one panel, its two end speeds), so
    // a hard segment early cannot starve the rest; a segment that runs out ends in cap_hit.
    const std::size_t least = opt.speed_minimum_samples + 1 + gauss_kronrod<Real>(opt.gauss_points).nodes.size() + 2;
    const std::size_t segments = bp.size() - 1;
    for (std::size_t i = 0; i + 1 < bp.size(); ++i) {
      quadrature_result<Real> r;
      if (bp[i + 1] > bp[i]) {
        std::size_t extra = 0;
        const std::vector<Real> ends =
            detail::with_speed_minima(c, std::vector<Real>{bp[i], bp[i + 1]}, opt.speed_minimum_samples, extra);
        adaptive_options<Real> seg_opt = opt;
        const std::size_t reserve = (segments - 1 - i) * least, spent = total_.evaluations + extra;
        seg_opt.max_evaluations = opt.max_evaluations > spent + reserve ? opt.max_evaluations - spent - reserve : 0;
        r = integrate_adaptive(f, std::span<const Real>(ends), seg_opt);
        r.evaluations += extra;
        // The curve's own rounding; a curve without a bound leaves the total without one, but the
        // cumulative bounds stay finite for the brackets of inversions (which then report none).
        using std::max;
        const Real ev = evaluation_error(c, bp[i], bp[i + 1]);
        if (is_finite(ev)) add_evaluation_error(r, ev, max(opt.absolute_tolerance, opt.relative_tolerance * abs(r.value)));
      }
      total_ += r;
      const Real t = sum + r.value;
      comp += abs(sum) >= abs(r.value) ? (sum - t) + r.value : (r.value - t) + sum;
      sum = t;
      err_sum += r.error_estimate;
      const Real cum = sum + comp;
      cumulative_.push_back(cum);
      cumulative_error_.push_back(err_sum + Real(4) * epsilon<Real>() * abs(cum));
      // One-sided end speeds (just inside the segment) for the initial guess of inversions.
      const Real w = bp[i + 1] - bp[i];
      const Real d = detail::knot_offset(Real(abs(bp[i]) + abs(bp[i + 1])));
      start_speed_.push_back(w > Real(2) * d ? speed(c, Real(bp[i] + d)) : Real(0));
      end_speed_.push_back(w > Real(2) * d ? speed(c, Real(bp[i + 1] - d)) : Real(0));
      total_.evaluations += 2;
    }
    total_.value = cumulative_.back();
    total_.error_estimate = cumulative_error_.back();
    if (!is_finite(rounding_bound(c, 1))) {
      total_.error_estimate = no_bound<Real>();
      total_.status = result_status::not_guaranteed;
    }
  }

  /// G7-K15 to 128 eps relative per segment (above the panels' rounding floor), at most 4000
  /// panels per segment.
  [[nodiscard]] static adaptive_options<Real> default_options() { return adaptive_options<Real>{}; }

  [[nodiscard]] std::span<const Real> parameters() const { return params_; }
  /// s at each breakpoint (first 0, last the total length).
  [[nodiscard]] std::span<const Real> cumulative() const { return cumulative_; }
  /// Error bound of each cumulative value.
  [[nodiscard]] std::span<const Real> cumulative_error() const { return cumulative_error_; }
  [[nodiscard]] std::size_t segment_count() const { return params_.empty() ? 0 : params_.size() - 1; }
  [[nodiscard]] Real length() const { return cumulative_.empty() ? Real(0) : cumulative_.back(); }
  /// The total: value, summed estimate, evaluations, worst status.
  [[nodiscard]] const quadrature_result<Real>& total() const { return total_; }

  /// The segment i with cumulative[i] <= s <= cumulative[i + 1], preferring one of positive length.
  [[nodiscard]] std::size_t segment_for_s(const Real& s) const {
    const auto it = std::upper_bound(cumulative_.begin(), cumulative_.end(), s);
    std::size_t i = it == cumulative_.begin() ? 0 : static_cast<std::size_t>(it - cumulative_.begin()) - 1;
    return std::min(i, segment_count() - 1);
  }
  /// A first guess of u(s) in segment i from the monotone cubic Hermite model of s(u) with the
  /// segment's end lengths and end speeds (no curve evaluation).
  [[nodiscard]] Real guess(std::size_t i, const Real& s) const {
    using std::sqrt;
    const Real u0 = params_[i], w = params_[i + 1] - params_[i];
    const Real s0 = cumulative_[i], ds = cumulative_[i + 1] - cumulative_[i];
    if (!(ds > Real(0))) return u0;
    Real d0 = w * start_speed_[i], d1 = w * end_speed_[i];
    const Real a = d0 / ds, b = d1 / ds, r2 = a * a + b * b;
    if (r2 > Real(9)) {  // Fritsch-Carlson: keep the model monotone
      const Real tau = Real(3) / sqrt(r2);
      d0 *= tau;
      d1 *= tau;
    }
    const Real c2 = Real(3) * ds - Real(2) * d0 - d1, c3 = d0 + d1 - Real(2) * ds;
    const Real target = s - s0;
    Real lo(0), hi(1), t = target / ds;
    for (int it = 0; it < 8; ++it) {
      const Real h = ((c3 * t + c2) * t + d0) * t - target;
      const Real dh = (Real(3) * c3 * t + Real(2) * c2) * t + d0;
      if (h < Real(0)) lo = t; else hi = t;
      Real next = dh > Real(0) ? t - h / dh : (lo + hi) / Real(2);
      if (!(next > lo && next < hi)) next = (lo + hi) / Real(2);
      t = next;
    }
    return u0 + t * w;
  }

  /// The segment i with parameters[i] <= u <= parameters[i + 1].
  [[nodiscard]] std::size_t segment_for_u(const Real& u) const {
    const auto it = std::upper_bound(params_.begin(), params_.end(), u);
    std::size_t i = it == params_.begin() ? 0 : static_cast<std::size_t>(it - params_.begin()) - 1;
    return std::min(i, segment_count() - 1);
  }

 private:
  std::vector<Real> params_;
  std::vector<Real> cumulative_;
  std::vector<Real> cumulative_error_;
  std::vector<Real> start_speed_, end_speed_;
  quadrature_result<Real> total_;
};

/// Options of Newton inversion.
template <class Real>
struct newton_options {
  /// Target on |s(u) - s*| plus its error bound, relative to the curve's total length. The bound
  /// includes the segment lengths' estimates (<= 128 eps L) and the inner integrals' rounding
  /// floors, so the default is 400 eps (8.9e-14 in double); true errors are usually ~eps L.
  Real relative_tolerance{Real(400) * epsilon<Real>()};
  int max_iterations{60};
  int gauss_points{15};   ///< n of the inner G_n - K_{2n+1} pair for long steps (G15-K31: one panel
                          ///< is usually enough for half a polynomial segment)
  int max_depth{16};      ///< recursion cap of each inner adaptive integral
  /// Inner integrals over less than 1/short_fraction of the bracket use detail::short_step_rule
  /// (G7-K15, 15 evaluations instead of 31): near convergence the steps are tiny and 15 points are
  /// exact to rounding there. 0 disables.
  int short_fraction{32};
  /// After convergence, one more Newton step (one short integral and one speed evaluation): the
  /// quadratic convergence takes the residual from the tolerance down to rounding level. Used for
  /// table nodes, which every later query interpolates.
  bool final_step{false};
  /// Total curve-derivative evaluations of one inversion (its inner integrals and speeds): the
  /// iteration stops with cap_hit, keeping the best iterate and its bound, once they are spent.
  std::size_t max_evaluations{std::size_t(1) << 16};
};

/// A bracket with known arc lengths at its ends (and their error bounds), and a first guess.
template <class Real>
struct newton_bracket {
  Real u_lo, s_lo, s_lo_error;
  Real u_hi, s_hi, s_hi_error;
  Real guess;  ///< used when strictly inside (u_lo, u_hi); otherwise the linear guess in s
};

namespace detail {

/// The Gauss-Kronrod pair of every short arc-length step: Newton's steps shorter than
/// 1/short_fraction of the bracket and the table polish of parameterization.hpp. G7-K15, because
/// the |G - K| estimate of G3-K7 can be fooled by a feature narrower than the step that both rules
/// miss alike (tests: arclength_honesty's Runge cases).
template <class Real>
[[nodiscard]] const gauss_kronrod_rule<Real>& short_step_rule() {
  return gauss_kronrod<Real>(7);
}

template <class Real>
void check_newton_options(const newton_options<Real>& opt) {
  validate::positive("relative_tolerance", opt.relative_tolerance);
  if (opt.max_iterations < 1)
    validate::fail("max_iterations = " + std::to_string(opt.max_iterations) + ": must be >= 1");
  if (opt.max_depth < 0) validate::fail("max_depth = " + std::to_string(opt.max_depth) + ": must be >= 0");
  if (opt.max_evaluations < 1) validate::fail("max_evaluations = 0: must be >= 1");
}

}  // namespace detail

/// u with s(u) = s_target inside the bracket (s_lo <= s_target <= s_hi), to an absolute arc-length
/// tolerance. The work horse of every inversion; no allocation.
template <curve C>
[[nodiscard]] inversion_result<typename C::real_type> newton_invert(const C& c,
                                                                    const typename C::real_type& s_target,
                                                                    const newton_bracket<typename C::real_type>& br,
                                                                    const typename C::real_type& tolerance,
                                                                    const newton_options<typename C::real_type>& opt) {
  using Real = typename C::real_type;
  using std::abs;
  const gauss_kronrod_rule<Real>& rule = gauss_kronrod<Real>(opt.gauss_points);
  const gauss_kronrod_rule<Real>& short_rule = detail::short_step_rule<Real>();
  auto f = [&c](const Real& u) { return speed(c, u); };
  const Real width = br.u_hi - br.u_lo;
  auto pick = [&](const Real& len) -> const gauss_kronrod_rule<Real>& {
    return opt.short_fraction > 0 && len * Real(opt.short_fraction) < width ? short_rule : rule;
  };
  inversion_result<Real> out;
  // The curve's own rounding over the integrated stretch (length.hpp). A curve without a bound is
  // solved as if it had none to add, and the answer then carries no bound (not_guaranteed, +inf).
  const bool bounded = is_finite(rounding_bound(c, 1));
  auto ev = [&](const Real& x, const Real& y) { return bounded ? evaluation_error(c, x, y) : Real(0); };
  auto finish = [&](inversion_result<Real>& o) {
    if (bounded) return;
    o.s_error_estimate = no_bound<Real>();
    o.status = result_status::not_guaranteed;
  };
  Real lo = br.u_lo, slo = br.s_lo, elo = br.s_lo_error;
  Real hi = br.u_hi, shi = br.s_hi, ehi = br.s_hi_error;
  if (s_target == slo || !(hi > lo)) {
    out.u = lo;
    out.residual = slo - s_target;
    out.s_error_estimate = abs(out.residual) + elo;
    out.status = out.s_error_estimate <= tolerance ? result_status::converged : result_status::rounding_limited;
    finish(out);
    return out;
  }
  if (s_target == shi) {
    out.u = hi;
    out.residual = Real(0);
    out.s_error_estimate = ehi;
    out.status = ehi <= tolerance ? result_status::converged : result_status::rounding_limited;
    finish(out);
    return out;
  }
  Real u = br.guess;
  if (!(u > lo && u < hi)) {
    u = shi > slo ? lo + (s_target - slo) / (shi - slo) * (hi - lo) : (lo + hi) / Real(2);
    if (!(u > lo && u < hi)) u = (lo + hi) / Real(2);
  }
  const Real inner_tol = tolerance / Real(8);
  Real best_f = no_bound<Real>();
  out.status = result_status::cap_hit;
  auto left = [&] { return opt.max_evaluations > out.evaluations ? opt.max_evaluations - out.evaluations : 0; };
  for (int it = 1; it <= opt.max_iterations; ++it) {
    if (it > 1 && left() == 0) break;  // the budget is spent: cap_hit with the best iterate so far
    out.iterations = it;
    Real su, eu;
    if (u - lo <= hi - u) {
      const quadrature_result<Real> q = integrate_recursive(f, lo, u, inner_tol, pick(u - lo), opt.max_depth, left());
      su = slo + q.value;
      eu = elo + q.error_estimate + ev(lo, u);
      out.evaluations += q.evaluations;
    } else {
      const quadrature_result<Real> q = integrate_recursive(f, u, hi, inner_tol, pick(hi - u), opt.max_depth, left());
      su = shi - q.value;
      eu = ehi + q.error_estimate + ev(u, hi);
      out.evaluations += q.evaluations;
    }
    const Real fu = su - s_target;
    if (abs(fu) < best_f) {
      best_f = abs(fu);
      out.u = u;
      out.residual = fu;
      out.s_error_estimate = abs(fu) + eu;
    }
    if (abs(fu) + eu <= tolerance) {
      out.status = result_status::converged;
      if (opt.final_step && fu != Real(0) && left() > 0) {
        const Real sp = f(u);
        ++out.evaluations;
        const Real next = sp > Real(0) ? u - fu / sp : u;
        if (next > lo && next < hi && next != u) {
          const quadrature_result<Real> q =
              integrate_recursive(f, u, next, inner_tol, pick(abs(next - u)), opt.max_depth, left());
          out.evaluations += q.evaluations;
          const Real fn = su + q.value - s_target;
          if (abs(fn) < abs(fu)) {
            out.u = next;
            out.residual = fn;
            out.s_error_estimate = abs(fn) + eu + q.error_estimate + ev(u, next);
          }
        }
      }
      break;
    }
    if (fu < Real(0)) {
      lo = u, slo = su, elo = eu;
    } else {
      hi = u, shi = su, ehi = eu;
    }
    const Real sp = f(u);
    ++out.evaluations;
    Real next = sp > Real(0) ? u - fu / sp : lo;
    if (!(next > lo && next < hi)) next = (lo + hi) / Real(2);
    if (!(next > lo && next < hi) || next == u) {
      out.status = result_status::rounding_limited;  // the bracket cannot shrink further in Real
      break;
    }
    u = next;
  }
  finish(out);
  return out;
}

/// u with s(u) = s (0 <= s <= total length) on a curve whose segment lengths are known: bracket by
/// binary search on the cumulative lengths, then Newton. Throws std::domain_error for s outside
/// [0, L] or NaN, invalid_input for bad options.
template <curve C>
[[nodiscard]] inversion_result<typename C::real_type> newton_invert(
    const C& c, const segment_lengths<typename C::real_type>& segments, const typename C::real_type& s,
    const newton_options<typename C::real_type>& opt = {}) {
  using Real = typename C::real_type;
  detail::check_newton_options(opt);
  check_arc_length(s, segments.length());
  const std::size_t i = segments.segment_for_s(s);
  const auto p = segments.parameters();
  const auto cum = segments.cumulative();
  const auto err = segments.cumulative_error();
  const newton_bracket<Real> br{p[i], cum[i], err[i], p[i + 1], cum[i + 1], err[i + 1], segments.guess(i, s)};
  return newton_invert(c, s, br, opt.relative_tolerance * segments.length(), opt);
}

}  // namespace curvebench::arclength
