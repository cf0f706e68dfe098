// Adaptive subdivision arc length: the curve is cut into pieces, each measured by its chord, and the
// piece whose error bound is largest is halved next (best first, a binary heap), until the bounds
// sum to the target, the evaluation budget is spent or no piece can be halved usefully.
// The bound of a piece [a, b] (h = b - a) is a bracket from P and P' at its ends: its length lies
// between the chord |P(b) - P(a)| and the length of the control polygon P(a), P(a) + h/3 P'(a),
// P(b) - h/3 P'(b), P(b). For a polynomial piece of degree <= 3 that polygon is the piece's Bezier
// polygon and the bracket is a theorem. The piece's value is the bracket's midpoint (chord +
// polygon) / 2, so half the gap bounds its error (plus the rounding of P, P' and of the arithmetic,
// included); for a cubic that midpoint is Gravesen's estimate (2 chord + (n - 1) polygon) / (n + 1),
// whose error falls as h^4 per piece where the chord's (Parent's chord sum) falls as h^2: with the
// chord as value, a tolerance of 1e-8 left errors of 5e-9, with the midpoint they are far below the
// bound, which is still the bracket's half-width. The chord
// test of Parent (compare a chord with its halves') bounded nothing: on a hairpin (a clamped natural
// cubic with end slope 7.8e7) the halves and quarters agree while the tip is missed, and it
// reported 0.0021 for an error of 656. For a piece of higher degree or a rational one the polygon is
// the bound of its Hermite cubic, off by O(h^4): with look_ahead (default), each halving checks that
// the halves' polygons do not exceed their parent's (a theorem for cubics), and any excess is added
// to both halves' bounds, so such pieces are refined until the cubic model holds. No sampling method
// is proof against a non-polynomial curve designed to pass at every level.
// P' at a segment's right end is taken just inside it (interior breakpoints belong to the segment on
// their right), at b - d with d a few ulps, its error bounded with |P''| there (one more evaluation);
// P there is the limit from the left (value_from_left, core/curve.hpp), so that a jump between
// segments that do not meet (a composite_bezier may have them) is not measured: previously the
// first bracket of such a segment ran from its start to the next segment's, and a 2-segment curve
// with a gap of 59 was reported 123.25 converged with an estimate of 1.2e-10 (L = 64.12).
// The target is max(tolerance, relative_tolerance * size), size the length of the polygon through
// the breakpoints and the segments' midpoints (a lower bound of L): by default 1e-6 relative, so
// the same work measures a curve of size 1e10 or 1e-10.
// Estimate: the sum of the pieces' bounds plus the rounding of the sum; a curve's own rounding is
// rounding_bound(c, 0) and (c, 1) (core/curve.hpp; not_guaranteed, +inf, for a curve without a
// bound). Status: converged when the estimate is <= the target; otherwise cap_hit when the budget
// or max_depth stopped it (the estimate is still a bound: best first, it is the smallest the
// budget allowed this way), rounding_limited when the pieces left are at their rounding floor or too
// narrow to halve. A budget too small to measure every segment once gives cap_hit with +inf.
// Reasons (result.hpp): the first segment the budget could not reach; the budget (estimate against
// target) or else the first piece stopped at max_depth (its segment, its depth against the cap); the
// piece at its rounding floor with the largest bound (its segment, its bound against its rounding
// part); the missing rounding bound or the first piece whose bracket overflowed.
// Sources: Parent (2012), 3.2.2 (the chord sum, here the bracket's lower end); seed 002; the
// Bezier bracket chord <= L <= polygon, its refinement under subdivision and the midpoint estimate,
// Gravesen (1997), in references.md.
// Cost: 2 evaluations (P and P') per halving, 6 per segment to start (7 when its right end is an
// interior breakpoint); never more than max_evaluations (2^22) in all. Memory: one node (u, P, P')
// per halving and one heap entry per piece, bounded by the budget: about 90 bytes per halving in
// 3D, 190 MB at the default budget when neither the target nor the rounding floor stops it (the
// vectors' growth may hold up to twice that while they reallocate). Accuracy: order 2 in the piece
// size on smooth pieces for the bound (the half-gap); the midpoint's error is of order 4 on cubic
// pieces, so the value is usually far better than its bound.
#pragma once

#include "curvebench/arclength/result.hpp"
#include "curvebench/core/curve.hpp"
#include "curvebench/core/detail/segment_lookup.hpp"
#include "curvebench/core/error.hpp"

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace curvebench::arclength {

template <class Real>
struct subdivision_options {
  Real tolerance{0};  ///< absolute, in length units, over the whole curve (0: relative only)
  /// Relative to the curve's size (see the header); the target is the larger of the two.
  Real relative_tolerance{Real(1) / Real(1000000)};
  /// Every piece is halved until it is min_depth levels below its segment (each segment is halved
  /// once in any case: its midpoint measures the size and checks the first bracket).
  int min_depth{2};
  /// A piece this many levels below its segment is not halved (cap_hit if the target is not met).
  int max_depth{40};
  /// Check each halving's polygons against their parent's, adding any excess to the bound (a piece
  /// that is not a cubic polynomial); false trusts the bracket as for a cubic.
  bool look_ahead{true};
  /// Evaluations (positions and derivatives) allowed in all, never exceeded (see the header).
  std::size_t max_evaluations{std::size_t(1) << 22};
};

namespace detail {

template <curve C>
class subdivider {
 public:
  using Real = typename C::real_type;
  using P = typename C::point_type;

  subdivider(const C& curve, const subdivision_options<Real>& options) : c_(curve), opt_(options) {}

  quadrature_result<Real> run() {
    using std::max;
    const Real r0 = rounding_bound(c_, 0), r1 = rounding_bound(c_, 1);
    if (!is_finite(r0) || !is_finite(r1)) {
      not_guaranteed_ = true;
      why_not_ = global_reason<Real>(reasons::no_rounding_bound);
    }
    r0_ = is_finite(r0) ? r0 : Real(0);
    r1_ = is_finite(r1) ? r1 : Real(0);
    const std::span<const Real> bp = c_.breakpoints();
    total_ = bp.back() - bp.front();
    Real size(0);
    for (std::size_t i = 0; i + 1 < bp.size(); ++i) {
      if (!(bp[i + 1] > bp[i])) continue;
      if (!start_segment(bp[i], bp[i + 1], i + 2 < bp.size(), size)) {
        unmeasured_ = true;
        why_unmeasured_ = segment_reason(reasons::budget_unmeasured, i, bp[i], bp[i + 1],
                                         Real(static_cast<long long>(out_.evaluations)),
                                         Real(static_cast<long long>(opt_.max_evaluations)));
        break;
      }
    }
    target_ = max(opt_.tolerance, Real(opt_.relative_tolerance * size));
    refine();
    return finish();
  }

 private:
  struct node {
    Real u;
    P p;         // P(u)
    P d;         // P'(u) of the segment the node belongs to
    Real d_err;  // error of d beyond the curve's rounding (a right end taken just inside)
  };
  struct leaf {
    Real est;  // the piece's bound (bracket, rounding, look-ahead excess)
    std::uint32_t a, b;
    int depth;
  };
  struct bracket {
    Real chord, gap, err;  // chord, polygon - chord (>= 0), rounding of both
    /// The piece's value: the bracket's midpoint, within gap / 2 + err of the piece's length.
    [[nodiscard]] Real value() const { return chord + gap / Real(2); }
  };

  const C& c_;
  const subdivision_options<Real>& opt_;
  Real r0_{0}, r1_{0}, total_{0}, target_{0};
  std::vector<node> nodes_;
  std::vector<leaf> heap_;
  quadrature_result<Real> out_{};
  Real running_est_{0}, running_value_{0};  // sums over every leaf, updated as leaves split
  Real retired_est_{0}, retired_value_{0};  // leaves taken out of the heap (not to be halved)
  std::size_t leaves_{0};
  bool not_guaranteed_{false}, unmeasured_{false}, capped_{false}, floor_{false};
  bool budget_capped_{false};  // the budget (not max_depth) stopped the refinement
  // Why, for the reasons (result.hpp): the first piece without a bound, the first segment the budget
  // could not reach, the first piece at max_depth, the piece at its rounding floor with the largest bound.
  status_reason<Real> why_not_{}, why_unmeasured_{}, why_depth_{}, why_floor_{};

  // The segment of the curve that holds the piece starting at u (its breakpoints, core/detail).
  [[nodiscard]] std::size_t segment_at(const Real& u) const {
    return curvebench::detail::segment_of<Real>(c_.breakpoints(), u);
  }
  [[nodiscard]] status_reason<Real> piece_reason(std::string_view what, const leaf& l, const Real& measured,
                                                 const Real& limit) const {
    const Real& a = nodes_[l.a].u;
    return segment_reason(what, segment_at(a), a, nodes_[l.b].u, measured, limit);
  }

  [[nodiscard]] bool affordable(std::size_t n) const {
    return out_.evaluations <= opt_.max_evaluations && n <= opt_.max_evaluations - out_.evaluations &&
           nodes_.size() < std::numeric_limits<std::uint32_t>::max() - 4;
  }
  [[nodiscard]] Real key(const leaf& l) const {
    return l.depth < opt_.min_depth ? std::numeric_limits<Real>::infinity() : l.est;
  }
  std::uint32_t add(const Real& u, const P& p, const P& d, const Real& d_err) {
    nodes_.push_back(node{u, p, d, d_err});
    return static_cast<std::uint32_t>(nodes_.size() - 1);
  }

  // The bracket of the piece between nodes A and B (see the header for the rounding terms).
  [[nodiscard]] bracket measure(const node& A, const node& B) const {
    using std::max;
    const Real third = (B.u - A.u) / Real(3);
    const Real chord = safe_norm(P(B.p - A.p));
    const Real da = safe_norm(A.d), db = safe_norm(B.d);
    const Real middle = safe_norm(P(B.p - A.p - third * P(A.d + B.d)));
    const Real arms = third * (da + db);
    const Real poly = arms + middle;
    // The curve's rounding: 2 r0 in the chord, 2 r0 + 4 (h/3) r1 in the polygon (its middle leg and
    // arms). The arithmetic rounds relative to what it forms: a difference of two coordinates is
    // within eps/2 of its own value, so the chord's error is relative to the chord, the middle leg's
    // to the chord and the arms, and the rest (h, h/3, the norms' squares and roots, the sums) to
    // the terms: at most 8 eps of chord + arms + polygon for Dim <= 4, 16 with a 2x margin.
    const Real err = Real(4) * r0_ + third * (Real(4) * r1_ + Real(2) * (A.d_err + B.d_err)) +
                     Real(16) * epsilon<Real>() * (chord + arms + poly);
    return {chord, max(Real(poly - chord), Real(0)), err};
  }

  // Evaluates a segment's ends and midpoint (6 evaluations, 7 with an interior right end) and
  // enters its two halves; false when the budget cannot pay for it.
  bool start_segment(const Real& a, const Real& b, bool interior_end, Real& size) {
    using std::abs;
    using std::max;
    if (!affordable(interior_end ? 7 : 6)) return false;
    // P(b) of this segment: at an interior breakpoint its limit from the left (where segments do
    // not meet, P(b) is the next segment's start and the chord would count the jump as length).
    const P pa = c_(a), da = c_.derivative(a, 1), pb = interior_end ? value_from_left(c_, b) : c_(b);
    // P'(b) would be the next segment's: take it a few ulps inside, within [a, b).
    Real inner = b;
    Real d_err(0);
    if (interior_end) {
      inner = b - Real(4) * epsilon<Real>() * max(abs(a), abs(b));
      if (!(inner > a)) inner = a;
      // P'(b-) - P'(inner) = (b - inner) P''(xi); twice |P''(inner)| covers the variation of P''
      // over a few ulps.
      d_err = Real(2) * (b - inner) * safe_norm(P(c_.derivative(inner, 2)));
      ++out_.evaluations;
    }
    const P db = c_.derivative(inner, 1);
    out_.evaluations += 4;
    const Real m = (a + b) / Real(2);
    const P pm = c_(m), dm = c_.derivative(m, 1);
    out_.evaluations += 2;
    size += safe_norm(P(pm - pa)) + safe_norm(P(pb - pm));
    const std::uint32_t ia = add(a, pa, da, Real(0));
    const std::uint32_t ib = add(b, pb, db, d_err);
    if (!(m > a && m < b)) {  // too narrow to halve: one piece
      enter(ia, ib, 0, Real(0), measure(nodes_[ia], nodes_[ib]));
      return true;
    }
    const std::uint32_t im = add(m, pm, dm, Real(0));
    enter_halves(ia, im, ib, 1, measure(nodes_[ia], nodes_[ib]));
    return true;
  }

  // Enters the halves [ia, im] and [im, ib] of a piece (bracket whole) at depth, with the
  // look-ahead excess.
  void enter_halves(std::uint32_t ia, std::uint32_t im, std::uint32_t ib, int depth, const bracket& whole) {
    using std::max;
    const bracket left = measure(nodes_[ia], nodes_[im]);
    const bracket right = measure(nodes_[im], nodes_[ib]);
    Real excess(0);
    if (opt_.look_ahead) {
      // For a cubic the halves' polygons are the de Casteljau halves of the whole one: never longer.
      const Real upper = whole.chord + whole.gap + whole.err + left.err + right.err;
      excess = max(Real(left.chord + left.gap + right.chord + right.gap - upper), Real(0));
    }
    enter(ia, im, depth, excess, left);
    enter(im, ib, depth, excess, right);
  }

  void enter(std::uint32_t ia, std::uint32_t ib, int depth, const Real& excess, const bracket& br) {
    const Real est = br.gap / Real(2) + br.err + excess;
    ++leaves_;
    running_value_ += br.value();
    if (!is_finite(est) || !is_finite(br.value())) {  // overflow or NaN: no bound, nothing to halve
      if (!not_guaranteed_)
        why_not_ = piece_reason(reasons::bracket_not_finite, leaf{est, ia, ib, depth}, Real(0), Real(0));
      not_guaranteed_ = true;
      retired_value_ += br.value();
      return;
    }
    running_est_ += est;
    heap_.push_back(leaf{est, ia, ib, depth});
    std::push_heap(heap_.begin(), heap_.end(), [this](const leaf& x, const leaf& y) { return key(x) < key(y); });
  }

  [[nodiscard]] Real rounding_of_sum(const Real& value) const {
    using std::abs;
    return Real(static_cast<long long>(leaves_ + 8)) * epsilon<Real>() * abs(value);
  }

  // The exact sums over the heap and the retired leaves (the running sums drift by rounding).
  void resum() {
    Real est = retired_est_, value = retired_value_;
    for (const leaf& l : heap_) {
      est += l.est;
      value += measure(nodes_[l.a], nodes_[l.b]).value();
    }
    running_est_ = est;
    running_value_ = value;
  }

  void retire(const leaf& l, const bracket& br) {
    retired_est_ += l.est;
    retired_value_ += br.value();
  }

  void refine() {
    const auto less = [this](const leaf& x, const leaf& y) { return key(x) < key(y); };
    while (!heap_.empty()) {
      const leaf& top = heap_.front();
      if (top.depth >= opt_.min_depth && running_est_ + rounding_of_sum(running_value_) <= target_) {
        resum();
        if (running_est_ + rounding_of_sum(running_value_) <= target_) return;
      }
      if (!(key(top) > Real(0))) return;  // every bound is 0: nothing to gain
      if (!affordable(2)) {
        capped_ = true;
        budget_capped_ = true;
        return;
      }
      std::pop_heap(heap_.begin(), heap_.end(), less);
      const leaf l = heap_.back();
      heap_.pop_back();
      const node& A = nodes_[l.a];
      const node& B = nodes_[l.b];
      const bracket br = measure(A, B);
      const Real m = (A.u + B.u) / Real(2);
      if (l.depth >= opt_.max_depth) {
        if (why_depth_.empty()) why_depth_ = piece_reason(reasons::max_depth, l, Real(l.depth), Real(opt_.max_depth));
        capped_ = true;
        retire(l, br);
        continue;
      }
      // Too narrow to halve, or at the rounding floor: halving adds the rounding of two pieces for
      // less than the part of the bound it can reduce (the gap falls ~4x, the excess vanishes).
      if (!(m > A.u && m < B.u) || (l.depth >= opt_.min_depth && Real(3) * (l.est - br.err) <= Real(4) * br.err)) {
        if (!floor_ || l.est > why_floor_.measured)
          why_floor_ = piece_reason(reasons::pieces_at_floor, l, l.est, br.err);
        floor_ = true;
        retire(l, br);
        continue;
      }
      const P pm = c_(m), dm = c_.derivative(m, 1);
      out_.evaluations += 2;
      running_est_ -= l.est;
      running_value_ -= br.value();
      --leaves_;
      const std::uint32_t im = add(m, pm, dm, Real(0));
      enter_halves(l.a, im, l.b, l.depth + 1, br);
    }
  }

  quadrature_result<Real> finish() {
    resum();
    out_.value = running_value_;
    out_.error_estimate = running_est_ + rounding_of_sum(running_value_);
    if (not_guaranteed_ || !is_finite(out_.error_estimate)) {
      out_.error_estimate = no_bound<Real>();
      out_.status = result_status::not_guaranteed;
      out_.reason = not_guaranteed_ ? why_not_ : global_reason<Real>(reasons::estimate_not_finite);
    } else if (unmeasured_) {  // segments the budget could not reach: no bound for them
      out_.error_estimate = no_bound<Real>();
      out_.status = result_status::cap_hit;
      out_.reason = why_unmeasured_;
    } else if (out_.error_estimate <= target_) {
      out_.status = result_status::converged;
    } else if (capped_) {
      out_.status = result_status::cap_hit;
      // The budget ends the whole refinement: the estimate against the target. Without it, the first
      // piece stopped at max_depth (its depth against the cap).
      out_.reason = budget_capped_ || why_depth_.empty()
                        ? global_reason<Real>(reasons::budget, out_.error_estimate, target_)
                        : why_depth_;
    } else {
      out_.status = result_status::rounding_limited;
      // The piece at its floor with the largest bound (its bound against its rounding part), or, when
      // no piece was retired at its floor (every bound 0, nothing to halve), the estimate and target.
      out_.reason = floor_ ? why_floor_ : global_reason<Real>(reasons::pieces_at_floor, out_.error_estimate, target_);
    }
    return out_;
  }
};

}  // namespace detail

/// Length by adaptive subdivision, best first under a budget, with a chord / control-polygon
/// bracket per piece (see the header). Throws invalid_input for a negative or non-finite
/// tolerance, both tolerances 0, negative depths, max_depth < min_depth.
template <curve C>
[[nodiscard]] quadrature_result<typename C::real_type> subdivision_length(
    const C& c, const subdivision_options<typename C::real_type>& opt = {}) {
  using Real = typename C::real_type;
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
  return detail::subdivider<C>(c, opt).run();
}

}  // namespace curvebench::arclength
