// Inversion of the arc length: u with s(u) = s*, by Newton's method inside a bracket.
//
// The segment lengths are computed once (segment_lengths: adaptive Gauss-Kronrod with estimates);
// a query finds its segment by binary search on the cumulative lengths, the first bracket. Optional
// length prefix (this is a small table of s(u), not of u(s)): P equal sub-panels in u per segment,
// each integrated once by adaptive Gauss-Kronrod with its estimate, so s and a bound of its error
// are known at P - 1 interior points; the bracket is then the sub-panel holding s* (found in O(1)
// expected from the constant-speed estimate). parameterization's newton method builds it with
// P = 32; plain segment_lengths(c) does not. The first guess inverts a monotone cubic Hermite model
// of s(u) from the bracket's end lengths and speeds. Each iteration integrates from the nearest
// known point (a bracket end) by recursive Gauss-Kronrod (G15-K31, or the G7-K15 short-step rule
// for steps under 1/32 of the segment), shrinks the bracket and steps u <- u - (s(u) - s*) / |P'(u)|,
// bisecting when the step leaves the bracket or |P'| = 0. Stops when |s(u) - s*| + its error bound
// <= tolerance (converged), at the iteration cap or the evaluation budget (cap_hit: the best
// iterate, its bound still reported) or when the bracket cannot shrink in Real (rounding_limited).
// Where the curve bounds |P''| (core/curve.hpp: piecewise cubics do), a step is also accepted
// without integrating over it when the bound on its error (detail::bounded_step_error: the
// residual before it, the step's own rounding and M D^2 / 2 for a step D) meets the tolerance.
// Every error bound (segment lengths, prefix points, |s(u) - s*|) includes the curve's own rounding
// over the stretch integrated, rounding_bound(c, 1) |u - u_known| (length.hpp); a curve without a
// bound is solved all the same and its answers say not_guaranteed (+inf).
// Sources: seed 002 (find u2 with arclength(u1, u2) = s); Guenter & Parent (1990); Eberly (2008).
// Cost: O(log segments) + 32 evaluations per long and 16 per short iteration; without the prefix
// typically one long and two or three short, with it two short (one step and its check), or one
// short and one speed where the step is bounded without its check (16 evaluations; the bound's
// two values of P'' come from the curve's coefficients and are not counted); at most
// max_evaluations (2^16) per query; no allocation per query. segment_lengths: at most
// adaptive_options::max_evaluations (2^24) over the whole curve, plus a few per segment; the
// prefix at most as many again (P panels of 2n + 1 evaluations per smooth segment).
// Accuracy: quadratic convergence in u where |P'| > 0; linear (bisection) where it vanishes.
#pragma once

#include "curvebench/arclength/gauss_kronrod.hpp"
#include "curvebench/arclength/length.hpp"
#include "curvebench/arclength/result.hpp"
#include "curvebench/core/curve.hpp"
#include "curvebench/core/detail/segment_lookup.hpp"
#include "curvebench/core/error.hpp"

#include <algorithm>
#include <cstddef>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

namespace curvebench::arclength {

namespace detail {
template <class Real>
[[noreturn]] void throw_outside_arc_length(const Real& s, const Real& length) {
  throw std::domain_error("s = " + to_text(s) + " is outside the arc-length range [0, " + to_text(length) + "]");
}
}  // namespace detail

/// Throws std::domain_error unless 0 <= s <= length (NaN fails too):
/// "s = 2 is outside the arc-length range [0, 1.5]".
template <class Real>
inline void check_arc_length(const Real& s, const Real& length) {
  if (s >= Real(0) && s <= length) [[likely]]
    return;
  detail::throw_outside_arc_length(s, length);  // out of line: the check inlines into every query
}

/// A bracket with known arc lengths at its ends (and their error bounds), and a first guess.
template <class Real>
struct newton_bracket {
  Real u_lo, s_lo, s_lo_error;
  Real u_hi, s_hi, s_hi_error;
  Real guess;  ///< used when strictly inside (u_lo, u_hi); otherwise the linear guess in s
  /// The width that short steps are measured against (newton_options::short_fraction): the
  /// segment's when the bracket is a sub-panel of it; 0: the bracket's own width.
  Real scale{0};
};

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
  explicit segment_lengths(const C& c, const adaptive_options<Real>& opt = default_options())
      : segment_lengths(c, opt, 0) {}

  /// The same, with prefix_panels sub-panels per segment for the length prefix (0 or 1: none).
  /// Throws invalid_input above max_prefix_panels.
  template <curve C>
  requires std::same_as<typename C::real_type, Real> segment_lengths(const C& c, const adaptive_options<Real>& opt,
                                                                     std::size_t prefix_panels) {
    if (prefix_panels > max_prefix_panels)
      validate::fail("prefix_panels = " + std::to_string(prefix_panels) +
                     ": must be <= " + std::to_string(max_prefix_panels));
    prefix_panels_ = prefix_panels > 1 ? prefix_panels : 0;
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
      std::vector<Real> ends;
      if (bp[i + 1] > bp[i]) {
        std::size_t extra = 0;
        ends = detail::with_speed_minima(c, std::vector<Real>{bp[i], bp[i + 1]}, opt.speed_minimum_samples, extra);
        adaptive_options<Real> seg_opt = opt;
        const std::size_t reserve = (segments - 1 - i) * least, spent = total_.evaluations + extra;
        seg_opt.max_evaluations = opt.max_evaluations > spent + reserve ? opt.max_evaluations - spent - reserve : 0;
        r = integrate_adaptive(f, std::span<const Real>(ends), seg_opt);
        r.evaluations += extra;
        // The curve's own rounding; a curve without a bound leaves the total without one, but the
        // cumulative bounds stay finite for the brackets of inversions (which then report none).
        using std::max;
        const Real ev = evaluation_error(c, bp[i], bp[i + 1]);
        if (is_finite(ev))
          add_evaluation_error(r, ev, max(opt.absolute_tolerance, opt.relative_tolerance * abs(r.value)));
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
      prefix_first_.push_back(prefix_u_.size());
      if (prefix_panels_ > 0 && bp[i + 1] > bp[i] && r.value > Real(0) && is_finite(r.value))
        add_prefix(c, opt, i, ends);
    }
    prefix_first_.push_back(prefix_u_.size());
    total_.value = cumulative_.back();
    total_.error_estimate = cumulative_error_.back();
    if (!is_finite(rounding_bound(c, 1))) {
      total_.error_estimate = no_bound<Real>();
      total_.status = result_status::not_guaranteed;
      total_.reason = global_reason<Real>(reasons::no_rounding_bound);
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
    return curvebench::detail::segment_of<Real>(cumulative_, s);
  }
  /// |P'| just inside segment i at its start and at its end (detail::knot_offset inside, so the
  /// segment's own where the curve is only C0 at a breakpoint); 0 for a segment too narrow for it.
  [[nodiscard]] Real start_speed(std::size_t i) const { return start_speed_[i]; }
  [[nodiscard]] Real end_speed(std::size_t i) const { return end_speed_[i]; }

  /// A first guess of u(s) in segment i from the monotone cubic Hermite model of s(u) with the
  /// segment's end lengths and end speeds (no curve evaluation).
  [[nodiscard]] Real guess(std::size_t i, const Real& s) const {
    return hermite_guess(params_[i], params_[i + 1], cumulative_[i], cumulative_[i + 1], start_speed_[i], end_speed_[i],
                         s, 8, Real(0));
  }

  /// The Newton bracket of s (0 <= s <= length()): the segment holding s, narrowed to the
  /// sub-panel of the length prefix holding it when the segment has a prefix, with the arc lengths
  /// and error bounds at its ends and the first guess of the Hermite model over it (no curve
  /// evaluation). The bracket's scale is the segment's width.
  [[nodiscard]] newton_bracket<Real> bracket(const Real& s) const {
    const std::size_t i = segment_for_s(s);
    const std::size_t first = prefix_first_.empty() ? 0 : prefix_first_[i];
    const std::size_t n = prefix_first_.empty() ? 0 : prefix_first_[i + 1] - first;
    const Real w = params_[i + 1] - params_[i];
    if (n == 0)
      return {params_[i],         cumulative_[i],           cumulative_error_[i], params_[i + 1],
              cumulative_[i + 1], cumulative_error_[i + 1], guess(i, s),          w};
    // j = the number of prefix points with s_k <= s (upper bound), found from the estimate of a
    // constant speed and corrected by steps: O(1) where the speed varies by a bounded factor.
    const Real* ps = prefix_s_.data() + first;
    const Real x = (s - cumulative_[i]) / (cumulative_[i + 1] - cumulative_[i]) * Real(static_cast<long long>(n + 1));
    std::size_t j = x > Real(0) ? std::min(static_cast<std::size_t>(static_cast<long long>(x)), n) : 0;
    while (j > 0 && ps[j - 1] > s) --j;
    while (j < n && !(ps[j] > s)) ++j;
    newton_bracket<Real> br;
    if (j == 0) {
      br.u_lo = params_[i], br.s_lo = cumulative_[i], br.s_lo_error = cumulative_error_[i];
    } else {
      br.u_lo = prefix_u_[first + j - 1], br.s_lo = ps[j - 1], br.s_lo_error = prefix_error_[first + j - 1];
    }
    if (j == n) {
      br.u_hi = params_[i + 1], br.s_hi = cumulative_[i + 1], br.s_hi_error = cumulative_error_[i + 1];
    } else {
      br.u_hi = prefix_u_[first + j], br.s_hi = ps[j], br.s_hi_error = prefix_error_[first + j];
    }
    const Real sp0 = j == 0 ? start_speed_[i] : prefix_speed_[first + j - 1];
    const Real sp1 = j == n ? end_speed_[i] : prefix_speed_[first + j];
    // Within a sub-panel the model is close to linear: its Newton iteration converges in a few
    // steps, stopped once the step is below eps^(1/3) of the sub-panel (what is left, ~ the step
    // squared, eps^(2/3), is far below the model's own error there).
    using std::cbrt;
    br.guess = hermite_guess(br.u_lo, br.u_hi, br.s_lo, br.s_hi, sp0, sp1, s, 8, Real(cbrt(epsilon<Real>())));
    br.scale = w;
    return br;
  }

  /// Sub-panels per segment of the length prefix that parameterization's newton method builds:
  /// the cubic Hermite model of s(u) over 1/32 of a segment puts the first guess within ~1e-7 of
  /// the segment's length on smooth segments, so one Newton step and its check usually converge.
  static constexpr std::size_t newton_prefix_panels = 32;
  /// The most sub-panels per segment accepted.
  static constexpr std::size_t max_prefix_panels = 1024;
  /// Sub-panels per segment of the length prefix (0: none).
  [[nodiscard]] std::size_t prefix_panels() const { return prefix_panels_; }
  /// Curve-derivative evaluations spent on the length prefix (not part of total()).
  [[nodiscard]] std::size_t prefix_evaluations() const { return prefix_evaluations_; }
  /// The prefix points (u, s, bound of s) of segment i: empty when it has no prefix.
  [[nodiscard]] std::span<const Real> prefix_parameters(std::size_t i) const { return prefix_of(prefix_u_, i); }
  [[nodiscard]] std::span<const Real> prefix_lengths(std::size_t i) const { return prefix_of(prefix_s_, i); }
  [[nodiscard]] std::span<const Real> prefix_errors(std::size_t i) const { return prefix_of(prefix_error_, i); }

 private:
  [[nodiscard]] std::span<const Real> prefix_of(const std::vector<Real>& v, std::size_t i) const {
    if (i + 1 >= prefix_first_.size()) return {};
    return std::span<const Real>(v).subspan(prefix_first_[i], prefix_first_[i + 1] - prefix_first_[i]);
  }

  // u in [u0, u1] where the monotone cubic Hermite model of s(u) from (u0, s0, speed sp0) to
  // (u1, s1, sp1) reaches s, by at most `iterations` safeguarded Newton steps on the model, stopped
  // early once a step in the model's variable t is below `stop`.
  [[nodiscard]] static Real hermite_guess(const Real& u0, const Real& u1, const Real& s0, const Real& s1,
                                          const Real& sp0, const Real& sp1, const Real& s, int iterations,
                                          const Real& stop) {
    using std::abs;
    using std::sqrt;
    const Real w = u1 - u0, ds = s1 - s0;
    if (!(ds > Real(0))) return u0;
    Real d0 = w * sp0, d1 = w * sp1;
    const Real a = d0 / ds, b = d1 / ds, r2 = a * a + b * b;
    if (r2 > Real(9)) {  // Fritsch-Carlson: keep the model monotone
      const Real tau = Real(3) / sqrt(r2);
      d0 *= tau;
      d1 *= tau;
    }
    const Real c2 = Real(3) * ds - Real(2) * d0 - d1, c3 = d0 + d1 - Real(2) * ds;
    const Real target = s - s0;
    Real lo(0), hi(1), t = target / ds;
    for (int it = 0; it < iterations; ++it) {
      const Real h = ((c3 * t + c2) * t + d0) * t - target;
      const Real dh = (Real(3) * c3 * t + Real(2) * c2) * t + d0;
      // Converged to rounding: a step below a few eps would land on the bracket end just set and
      // the safeguard below would bisect away from the root (it did: the guess ended up to 5e-5
      // of the bracket off after the remaining iterations bisected, instead of ~1e-7).
      if (dh > Real(0) && abs(h) <= Real(4) * epsilon<Real>() * dh) break;
      if (h < Real(0))
        lo = t;
      else
        hi = t;
      Real next = dh > Real(0) ? t - h / dh : (lo + hi) / Real(2);
      if (!(next > lo && next < hi)) next = (lo + hi) / Real(2);
      const bool done = abs(next - t) <= stop;
      t = next;
      if (done) break;
    }
    return u0 + t * w;
  }

 public:
  /// The segment i with parameters[i] <= u <= parameters[i + 1].
  [[nodiscard]] std::size_t segment_for_u(const Real& u) const {
    return curvebench::detail::segment_of<Real>(params_, u);
  }

 private:
  std::vector<Real> params_;
  std::vector<Real> cumulative_;
  std::vector<Real> cumulative_error_;
  std::vector<Real> start_speed_, end_speed_;
  quadrature_result<Real> total_;
  // The length prefix: interior points of each segment, prefix_first_[i] .. prefix_first_[i + 1] - 1.
  std::size_t prefix_panels_{0}, prefix_evaluations_{0};
  std::vector<std::size_t> prefix_first_;
  std::vector<Real> prefix_u_, prefix_s_, prefix_error_, prefix_speed_;

  // The prefix of segment i (its cumulative values already stored): prefix_panels_ equal
  // sub-panels in u, each integrated by adaptive Gauss-Kronrod (split at the segment's speed minima
  // and graded points `ends` inside it) to the segment's tolerance divided among them. s at each
  // interior point is the segment start's value plus the sub-panels' sum; its bound is the start's
  // bound, the sub-panels' estimates, the curve's rounding over [u_i, x] and the sums' rounding.
  // All or nothing: a sub-panel that ran out of budget (cap_hit), has no bound, or does not leave
  // the points strictly inside the segment's lengths leaves the segment without a prefix.
  template <curve C>
  void add_prefix(const C& c, const adaptive_options<Real>& opt, std::size_t i, const std::vector<Real>& ends) {
    using std::abs;
    using std::max;
    const Real a = params_[i], b = params_[i + 1], w = b - a;
    const Real s_start = cumulative_[i], s_end = cumulative_[i + 1];
    const Real seg_len = s_end - s_start;
    if (!(seg_len > Real(0))) return;
    const Real m = Real(static_cast<long long>(prefix_panels_));
    adaptive_options<Real> o = opt;
    o.relative_tolerance = Real(0);
    o.absolute_tolerance = max(Real(opt.relative_tolerance * seg_len), opt.absolute_tolerance) / m;
    if (!(o.absolute_tolerance > Real(0))) return;
    auto f = [&c](const Real& u) { return speed(c, u); };
    std::vector<Real> us, ss, es, sp, splits;
    Real s = s_start, quad_error(0), x0 = a;
    std::size_t next_end = 1;  // ends[0] = a, ends.back() = b
    for (std::size_t k = 1; k < prefix_panels_; ++k) {
      const Real x1 = a + w * Real(static_cast<long long>(k)) / m;
      if (!(x1 > x0 && x1 < b)) return;  // the segment is too narrow to hold the sub-panels in Real
      splits.assign(1, x0);
      for (; next_end + 1 < ends.size() && ends[next_end] < x1; ++next_end)
        if (ends[next_end] > x0) splits.push_back(ends[next_end]);
      splits.push_back(x1);
      for (std::size_t j = 1; j < splits.size(); ++j)  // a far domain's sub-panels: no prefix, not an error
        if (splits[j] > splits[j - 1] && !validate::is_resolvable(splits[j - 1], splits[j])) return;
      o.max_evaluations = opt.max_evaluations > prefix_evaluations_ ? opt.max_evaluations - prefix_evaluations_ : 0;
      if (o.max_evaluations == 0) return;
      const quadrature_result<Real> q = integrate_adaptive(f, std::span<const Real>(splits), o);
      prefix_evaluations_ += q.evaluations + 1;
      if (q.status == result_status::cap_hit || q.status == result_status::not_guaranteed) return;
      if (!is_finite(q.error_estimate) || !(q.value > Real(0)) || !is_finite(q.value)) return;
      s += q.value;
      quad_error += q.error_estimate;
      if (!(s < s_end)) return;
      const Real ev = evaluation_error(c, a, x1);
      us.push_back(x1);
      ss.push_back(s);
      es.push_back(cumulative_error_[i] + quad_error + (is_finite(ev) ? ev : Real(0)) +
                   Real(static_cast<long long>(k + 4)) * epsilon<Real>() * abs(s));
      sp.push_back(speed(c, x1));
      x0 = x1;
    }
    prefix_u_.insert(prefix_u_.end(), us.begin(), us.end());
    prefix_s_.insert(prefix_s_.end(), ss.begin(), ss.end());
    prefix_error_.insert(prefix_error_.end(), es.begin(), es.end());
    prefix_speed_.insert(prefix_speed_.end(), sp.begin(), sp.end());
  }
};

/// Options of Newton inversion.
template <class Real>
struct newton_options {
  /// Target on |s(u) - s*| plus its error bound, relative to the curve's total length. The bound
  /// includes the segment lengths' estimates (<= 128 eps L) and the inner integrals' rounding
  /// floors, so the default is 400 eps (8.9e-14 in double); true errors are usually ~eps L.
  Real relative_tolerance{Real(400) * epsilon<Real>()};
  int max_iterations{60};
  int gauss_points{15};  ///< n of the inner G_n - K_{2n+1} pair for long steps (G15-K31: one panel
                         ///< is usually enough for half a polynomial segment)
  int max_depth{16};     ///< recursion cap of each inner adaptive integral
  /// Inner integrals over less than 1/short_fraction of the bracket's scale (its width, or the
  /// segment's when the bracket is a sub-panel of the length prefix) use detail::short_step_rule
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

namespace detail {

/// The Gauss-Kronrod pair of every short arc-length step: Newton's steps shorter than
/// 1/short_fraction of the bracket's scale and the table polish of parameterization.hpp. G7-K15, because
/// the |G - K| estimate of G3-K7 can be fooled by a feature narrower than the step that both rules
/// miss alike (tests: arclength_honesty's Runge cases).
template <class Real>
[[nodiscard]] const gauss_kronrod_rule<Real>& short_step_rule() {
  return gauss_kronrod<Real>(7);
}

/// A bound on |s(next) - s*| after the Newton step next = u - fu / sp from u, where s(u) - s* was
/// computed as fu with |s(u) - s* - fu| <= eu and sp = fl(|P'(u)|), without integrating over the
/// step: s(next) - s* = s(u) - s* + integral of |P'| from u to next, and with D = next - u,
/// |integral - D sp| <= 3 r |D| + M D^2 / 2, r = rounding_bound(c, 1) (|P'| as evaluated, and as
/// the stored coefficients give it exactly, are each within r of the curve's), M =
/// second_derivative_bound(c, u, next) (|P'| is Lipschitz with M there: ||a| - |b|| <= |a - b|).
/// So |s(next) - s*| <= eu + |fu + sp D| + 3 r |D| + M D^2 / 2; the computed fu + sp D is within
/// 3 u (|fu| + sp |D|) of the exact one (the subtraction that made fu, next - u, the product and
/// the sum), charged as 8 u, and D^2 is raised by 4 u for D's own rounding. +inf when the curve
/// bounds no second derivative over [u, next] (a knot between them, or no declaration).
template <curve C>
[[nodiscard]] typename C::real_type bounded_step_error(const C& c, const typename C::real_type& u,
                                                       const typename C::real_type& fu, const typename C::real_type& eu,
                                                       const typename C::real_type& sp,
                                                       const typename C::real_type& next) {
  using Real = typename C::real_type;
  using std::abs;
  const Real m = second_derivative_bound(c, u < next ? u : next, u < next ? next : u);
  if (!is_finite(m)) return no_bound<Real>();
  const Real d = abs(next - u);
  const Real half_eps = epsilon<Real>() / Real(2);
  const Real b = eu + abs(fu + sp * (next - u)) + Real(8) * half_eps * (abs(fu) + sp * d) +
                 Real(3) * rounding_bound(c, 1) * d + m * d * d / Real(2) * (Real(1) + Real(4) * half_eps);
  return b * (Real(1) + Real(8) * half_eps);
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
[[nodiscard]] inversion_result<typename C::real_type> newton_invert(const C& c, const typename C::real_type& s_target,
                                                                    const newton_bracket<typename C::real_type>& br,
                                                                    const typename C::real_type& tolerance,
                                                                    const newton_options<typename C::real_type>& opt) {
  using Real = typename C::real_type;
  using std::abs;
  const gauss_kronrod_rule<Real>& rule = gauss_kronrod<Real>(opt.gauss_points);
  const gauss_kronrod_rule<Real>& short_rule = detail::short_step_rule<Real>();
  // Inlined into the panels' loops (CURVEBENCH_LAMBDA_INLINE): out of line, each node's call waited
  // on its square root before the next could start.
  auto f = [&c](const Real& u) CURVEBENCH_LAMBDA_INLINE { return speed(c, u); };
  const Real width = br.scale > Real(0) ? br.scale : Real(br.u_hi - br.u_lo);
  auto pick = [&](const Real& len) -> const gauss_kronrod_rule<Real>& {
    return opt.short_fraction > 0 && len * Real(opt.short_fraction) < width ? short_rule : rule;
  };
  inversion_result<Real> out;
  // The curve's own rounding over the integrated stretch (length.hpp). A curve without a bound is
  // solved as if it had none to add, and the answer then carries no bound (not_guaranteed, +inf).
  const bool bounded = is_finite(rounding_bound(c, 1));
  auto ev = [&](const Real& x, const Real& y) { return bounded ? evaluation_error(c, x, y) : Real(0); };
  auto finish = [&](inversion_result<Real>& o) {
    if (o.status == result_status::cap_hit && o.reason.empty())
      o.reason = segment_reason(reasons::newton_cap, status_reason<Real>::npos, br.u_lo, br.u_hi, o.s_error_estimate,
                                tolerance);
    if (bounded) return;
    o.s_error_estimate = no_bound<Real>();
    o.status = result_status::not_guaranteed;
    o.reason = global_reason<Real>(reasons::no_rounding_bound);
  };
  auto at_end = [&](inversion_result<Real>& o) {
    if (o.status != result_status::converged)
      o.reason = segment_reason(reasons::bracket_end_bound, status_reason<Real>::npos, br.u_lo, br.u_hi,
                                o.s_error_estimate, tolerance);
  };
  Real lo = br.u_lo, slo = br.s_lo, elo = br.s_lo_error;
  Real hi = br.u_hi, shi = br.s_hi, ehi = br.s_hi_error;
  if (s_target == slo || !(hi > lo)) {
    out.u = lo;
    out.residual = slo - s_target;
    out.s_error_estimate = abs(out.residual) + elo;
    out.status = out.s_error_estimate <= tolerance ? result_status::converged : result_status::rounding_limited;
    at_end(out);
    finish(out);
    return out;
  }
  if (s_target == shi) {
    out.u = hi;
    out.residual = Real(0);
    out.s_error_estimate = ehi;
    out.status = ehi <= tolerance ? result_status::converged : result_status::rounding_limited;
    at_end(out);
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
      out.reason = segment_reason(reasons::bracket_at_rounding, status_reason<Real>::npos, lo, hi, best_f, tolerance);
      break;
    }
    // The step bounded without integrating it (detail::bounded_step_error), where the curve bounds
    // its second derivative: one speed instead of a short integral. Not for final_step's table
    // nodes, which want the residual taken to rounding level.
    if (bounded && !opt.final_step) {
      const Real b = detail::bounded_step_error(c, u, fu, eu, sp, next);
      if (b <= tolerance) {
        out.u = next;
        out.residual = fu + sp * (next - u);
        out.s_error_estimate = b;
        out.status = result_status::converged;
        break;
      }
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
  detail::check_newton_options(opt);
  check_arc_length(s, segments.length());
  return newton_invert(c, s, segments.bracket(s), opt.relative_tolerance * segments.length(), opt);
}

}  // namespace curvebench::arclength
