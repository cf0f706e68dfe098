// Forward-differencing arc-length table: the curve sampled at N equal steps per segment
// (breakpoints are nodes; a segment ends at its limit from the left, so that a jump between
// segments that do not meet is not length, core/curve.hpp), chord lengths accumulated; s(u) by
// linear interpolation, u(s) by binary search and linear interpolation; Richardson extrapolation
// of two tables.
// Error: a chord falls short of its arc by kappa^2 |P'|^3 h^3 / 24, so the length has error
// c h^2 + O(h^4). Estimate: with the coarser sums L_2h, L_4h over the same samples, d2 = L_h - L_2h
// bounds L - L_h when the ratio r = (L_2h - L_4h) / d2 lies in [3, 6] (observed order about 2),
// N >= 16, N divisible by 4, and no two consecutive 4h chords of a segment turn by more than 60
// degrees; otherwise not_guaranteed, since features the table does not resolve make chord sums
// creep, stall and jump. Richardson R = L_h + d2 / 3, estimate d2 / 3 under the same
// check. Both estimates add the curve's own rounding, 3 rounding_bound(c, 0) per chord
// (core/curve.hpp; no bound, not_guaranteed, for a curve without one). A result without a bound
// names the check that failed (result.hpp's reason): the steps, the turn with the segment where the
// 4h chords turned most, the missing rounding bound, or the ratio d1 / d2 against the end of [3, 6].
// Sources: seed 002 ("Forward Differencing", table lookup); Parent, Computer Animation (2012), 3.2.
// Cost: N position evaluations per segment and one more (and one per interior breakpoint for a
// curve that may jump there) to build, at most 2^24 in all unless the caller allows more (checked
// before the work); s(u), u(s) O(log N), no evaluation.
// Accuracy: O(h^2) (the table and its interpolation), Richardson O(h^4) on smooth segments.
#pragma once

#include "curvebench/arclength/newton_inversion.hpp"
#include "curvebench/arclength/result.hpp"
#include "curvebench/core/curve.hpp"
#include "curvebench/core/detail/segment_lookup.hpp"
#include "curvebench/core/error.hpp"

#include <algorithm>
#include <cstddef>
#include <span>
#include <string>
#include <vector>

namespace curvebench::arclength {

/// The default limit of a table's evaluations (and nodes: two Reals each), checked before it is built.
inline constexpr std::size_t max_forward_difference_evaluations = std::size_t(1) << 24;

template <class Real>
class forward_difference_table {
 public:
  /// N = steps_per_segment >= 1 equal parameter steps in every segment. The cost, N x segments + 1
  /// nodes and as many position evaluations (segments - 1 more for a curve that declares
  /// value_from_left), is checked before the work: above max_evaluations it
  /// throws invalid_input naming steps_per_segment, the segments and the limit.
  template <curve C>
  requires std::same_as<typename C::real_type, Real> forward_difference_table(
      const C& c, std::size_t steps_per_segment, std::size_t max_evaluations = max_forward_difference_evaluations)
      : steps_(steps_per_segment) {
    if (steps_per_segment < 1)
      validate::fail("steps_per_segment = " + std::to_string(steps_per_segment) + ": must be >= 1");
    const std::span<const Real> bp = c.breakpoints();
    validate::count_at_least("breakpoints", bp.size(), 2, "a curve has at least one segment");
    const std::size_t segments = bp.size() - 1;
    // A curve that may jump at its breakpoints (value_from_left, core/curve.hpp) costs one more
    // evaluation per interior breakpoint: its segment's end from the left, the next one's start.
    const std::size_t joins = declares_value_from_left<C> ? segments - 1 : 0;
    if (joins >= max_evaluations || steps_per_segment > (max_evaluations - 1 - joins) / segments)
      validate::fail("steps_per_segment = " + std::to_string(steps_per_segment) + ": " + std::to_string(segments) +
                     (segments == 1 ? " segment" : " segments") + " x " + std::to_string(steps_per_segment) +
                     " steps is more than the limit of " + std::to_string(max_evaluations) +
                     " evaluations (table nodes)");
    u_.reserve(segments * steps_ + 1);
    s_.reserve(segments * steps_ + 1);
    typename C::point_type prev = c(bp[0]);
    u_.push_back(bp[0]);
    s_.push_back(Real(0));
    evaluations_ = 1;
    Real coarse(0), coarser(0);
    position_bound_ = rounding_bound(c, 0);
    for (std::size_t i = 0; i + 1 < bp.size(); ++i) {
      if (!(bp[i + 1] > bp[i])) continue;
      if constexpr (declares_value_from_left<C>) {
        if (i > 0) {  // the segment starts at P(b_i), its own start; the last one ended at P(b_i-)
          prev = c(bp[i]);
          ++evaluations_;
        }
      }
      const Real h = (bp[i + 1] - bp[i]) / Real(static_cast<long long>(steps_));
      typename C::point_type even = prev;                      // the node two steps back, for L_2h
      typename C::point_type fourth = prev;                    // the node four steps back, for L_4h
      typename C::point_type last_4h = C::point_type::Zero();  // the previous 4h chord's direction
      for (std::size_t k = 1; k <= steps_; ++k) {
        const Real u = k == steps_ ? bp[i + 1] : bp[i] + h * Real(static_cast<long long>(k));
        // A segment's last node: its end, from the left at an interior breakpoint.
        const typename C::point_type p = k == steps_ && i + 2 < bp.size() ? value_from_left(c, u) : c(u);
        ++evaluations_;
        const typename C::point_type d = p - prev;
        u_.push_back(u);
        s_.push_back(s_.back() + safe_norm(d));
        if (k % 2 == 0) {
          const typename C::point_type e = p - even;
          coarse += safe_norm(e);
          even = p;
        }
        if (k % 4 == 0) {
          const typename C::point_type e = p - fourth;
          const Real le = safe_norm(e);
          coarser += le;
          // The turn between consecutive 4h chords, from their directions (unit vectors: no square of
          // a 1e200 or 1e-170 chord); zero chords (a hold, or the segment's first) are skipped.
          if (le > Real(0)) {
            const typename C::point_type dir = e / le;
            if (last_4h != C::point_type::Zero()) {
              const Real cosine = dir.dot(last_4h);
              if (!(cosine >= min_cosine_)) {
                min_cosine_ = cosine;
                min_cosine_segment_ = i;
                min_cosine_a_ = bp[i];
                min_cosine_b_ = bp[i + 1];
              }
            }
            last_4h = dir;
          }
          fourth = p;
        }
        prev = p;
      }
    }
    coarse_ = coarse;
    coarser_ = coarser;
  }

  [[nodiscard]] std::size_t steps_per_segment() const { return steps_; }
  [[nodiscard]] std::span<const Real> parameters() const { return u_; }
  [[nodiscard]] std::span<const Real> arc_lengths() const { return s_; }
  /// Position evaluations spent building the table.
  [[nodiscard]] std::size_t evaluations() const { return evaluations_; }

  /// The chord sum L_h, estimate L_h - L_2h (+ rounding) when N >= 16 is divisible by 4 and the chord
  /// sums converge at a ratio in [3, 6] (see the header); otherwise no bound (not_guaranteed).
  [[nodiscard]] quadrature_result<Real> length() const {
    using std::abs;
    quadrature_result<Real> r;
    r.value = s_.back();
    r.evaluations = evaluations_;
    if (const status_reason<Real> why = untrusted(); !why.empty()) {
      r.error_estimate = no_bound<Real>();
      r.status = result_status::not_guaranteed;
      r.reason = why;
      return r;
    }
    r.error_estimate = abs(r.value - coarse_) + rounding(r.value);
    r.status = result_status::converged;
    return r;
  }

  /// The coarser chord sum L_2h (every other node), for Richardson extrapolation; needs even N.
  [[nodiscard]] Real coarse_length() const {
    if (steps_ % 2 != 0)
      validate::fail("steps_per_segment = " + std::to_string(steps_) + ": the coarse table needs an even number");
    return coarse_;
  }

  /// Richardson: R = L_h + (L_h - L_2h) / 3, under the same check as length(), otherwise no bound
  /// (not_guaranteed); needs even N. Estimate 2 |R - L_h| (+ rounding): a chord sum never exceeds
  /// the length, so 0 <= L - L_h <= L_h - L_2h (the bound length() trusts) and R - L lies in
  /// [-2/3, 1/3] (L_h - L_2h). |R - L_h| alone assumes the asymptotic ratio 4 exactly; a Runge
  /// polynomial through 9 Chebyshev nodes passes the ratio check at N = 64 with an error 1.2 times it.
  [[nodiscard]] quadrature_result<Real> richardson_length() const {
    using std::abs;
    quadrature_result<Real> r;
    const Real fine = s_.back();
    r.value = fine + (fine - coarse_length()) / Real(3);
    r.evaluations = evaluations_;
    if (const status_reason<Real> why = untrusted(); !why.empty()) {
      r.error_estimate = no_bound<Real>();
      r.status = result_status::not_guaranteed;
      r.reason = why;
      return r;
    }
    r.error_estimate = Real(2) * abs(r.value - fine) + rounding(fine);
    r.status = result_status::converged;
    return r;
  }

  /// s(u) by linear interpolation between the nodes around u (binary search). Throws
  /// std::domain_error outside the table's domain.
  [[nodiscard]] Real s(const Real& u) const {
    const std::size_t j = curvebench::detail::checked_segment_of<Real>(u_, u);  // u_[j] <= u < u_[j+1]
    if (!(u < u_.back())) return s_.back();                                     // the last node exactly
    const Real t = (u - u_[j]) / (u_[j + 1] - u_[j]);
    return s_[j] + t * (s_[j + 1] - s_[j]);
  }

  /// u(s) by binary search on the arc lengths + linear interpolation (seed 002). Throws
  /// std::domain_error for s outside [0, L_h] or NaN.
  [[nodiscard]] Real u(const Real& s) const {
    check_arc_length(s, s_.back());
    if (!(s < s_.back())) return u_.back();
    // s_[j] <= s < s_[j+1]: past any zero-length chords, so the difference below is positive.
    const std::size_t j = curvebench::detail::segment_of<Real>(s_, s);
    const Real t = (s - s_[j]) / (s_[j + 1] - s_[j]);
    return u_[j] + t * (u_[j + 1] - u_[j]);
  }

 private:
  // Each chord is a few roundings, summed sequentially over the table; and each chord's ends are
  // off by the curve's own rounding (rounding_bound(c, 0) each, core/curve.hpp), so N chords by at
  // most 2 N times it, and Richardson's (4 L_h - L_2h) / 3 by (4/3) 2N + (1/3) N = 3N times it.
  [[nodiscard]] Real rounding(const Real& value) const {
    const Real n = Real(static_cast<long long>(s_.size() + 8));
    return n * epsilon<Real>() * value + (position_bound_ > Real(0) ? Real(3) * n * position_bound_ : Real(0));
  }

  // 3 d2 <= d1 <= 6 d2 (d1 = L_2h - L_4h, d2 = L_h - L_2h): the chord sums converge at an
  // observed order between log2 3 and log2 6 around the theoretical 2 (see the header); or both
  // differences are rounding. And the 4h chords resolve the curve: consecutive ones within a
  // segment turn by at most 60 degrees (16 chords of the cubic Bezier (0,0), (1,1), (0.5,1), (1,0)
  // turn by up to 52). Where they turn back (a hairpin the grid straddles: a clamped
  // natural cubic with end slope 1e4 to 1e10, 128 steps) the missed tip makes every chord sum short
  // by an amount that varies erratically with the grid, and the ratio test passed by coincidence
  // with an estimate 0.7x of the error.
  // Why the estimate is not trusted (empty when it is): the first check that fails, the turn with
  // the segment where the chords turned most, the ratio with d1 / d2 against the end it passed.
  // A curve without a rounding bound has no bound either.
  [[nodiscard]] status_reason<Real> untrusted() const {
    using R = status_reason<Real>;
    if (steps_ % 4 != 0 || steps_ < 16)
      return global_reason<Real>(reasons::table_steps, Real(static_cast<long long>(steps_)), Real(16));
    if (!(min_cosine_ >= Real(1) / Real(2)))
      return R{reasons::table_turn, min_cosine_segment_, min_cosine_a_, min_cosine_b_, min_cosine_, Real(1) / Real(2)};
    if (!is_finite(position_bound_)) return global_reason<Real>(reasons::no_rounding_bound);
    const Real fine = s_.back();
    const Real d2 = fine - coarse_, d1 = coarse_ - coarser_, noise = rounding(fine);
    if (d1 <= noise && d2 <= noise) return R{};
    if (d2 > Real(0) && d1 >= Real(3) * d2 && d1 <= Real(6) * d2) return R{};
    if (!(d2 > Real(0))) return global_reason<Real>(reasons::table_ratio, d2, noise);  // L_h - L_2h against the noise
    const Real ratio = d1 / d2;
    return global_reason<Real>(reasons::table_ratio, ratio, ratio < Real(3) ? Real(3) : Real(6));
  }

  std::size_t steps_;
  std::vector<Real> u_, s_;
  Real coarse_{0}, coarser_{0};
  Real min_cosine_{1};                 // the smallest cosine of the turn between consecutive 4h chords of a segment
  std::size_t min_cosine_segment_{0};  // the segment where it was found
  Real min_cosine_a_{0}, min_cosine_b_{0};  // and its parameter interval
  Real position_bound_{0};
  std::size_t evaluations_{0};
};

}  // namespace curvebench::arclength
