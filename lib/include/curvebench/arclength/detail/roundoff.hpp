// Private: roundoff detection for adaptive bisection (QUADPACK's idea, in a simpler form), shared
// by curvebench's Gauss-Kronrod integrators and the 50-digit reference's bisection of Boost's rule.
//
// An error estimate |K - G| measures truncation only while truncation dominates. When the
// integrand itself is rounded worse than the rule's rounding floor assumes (an ill-conditioned
// evaluation: degree-20 Lagrange on equispaced nodes has a Lebesgue constant near 1e4 and rounds
// its speed to ~1e4 eps near the ends), the estimate becomes that noise and no bisection reduces
// it: a recursion that only knows the tolerance then bisects to its depth cap (2^17 rules per
// integral at depth 16). A resolved analytic panel loses orders of magnitude per bisection, a
// kink inside a panel 4x, an endpoint singularity x^a (a > 0) 2^(1 + a).
//
// One stagnation is not evidence: |K - G| also comes out small by coincidence on an unresolved
// panel (a near-cusp can do it). So a bisection stops only at the second stagnation in a row,
// parent to halves and then half to quarters: a coincidence in the parent is exposed by its
// halves' genuine estimates.
#pragma once

#include "curvebench/core/real.hpp"

namespace curvebench::arclength::detail {

/// The rounding floor of a Gauss-Kronrod or Gauss-Legendre sum, in eps of its magnitude (the
/// integral of |f|): each speed value carries a few eps (a square root of a sum of Dim squared
/// derivatives, themselves sums of rounded terms), and a weighted sum of the up to 31 values of
/// the default rules adds at most ~31 eps in the worst case; 50 covers both with a little margin.
/// Every panel estimate includes it, and no tolerance below it is met (rounding_limited).
inline constexpr int rounding_floor_eps = 50;

/// The floor above, in Real: 50 eps * magnitude.
template <class Real>
[[nodiscard]] Real rounding_floor(const Real& magnitude) {
  return Real(rounding_floor_eps) * epsilon<Real>() * magnitude;
}

/// How far inside a segment [a, b] its one-sided speeds at the knots are evaluated, in eps of
/// |a| + |b|: far enough (16 ulps of the larger end) that a +- d rounds to a parameter strictly
/// inside the segment for every Real, near enough that the speed there differs from the one-sided
/// limit by d |P''|, below the speed's own rounding. Used by segment_lengths (the first guess of
/// Newton) and the parameterization's knot split, which must see the same one-sided speeds.
inline constexpr int knot_offset_eps = 16;

/// The offset above for a segment whose ends have magnitudes summing to `scale`.
template <class Real>
[[nodiscard]] Real knot_offset(const Real& scale) {
  return Real(knot_offset_eps) * epsilon<Real>() * scale;
}

/// The smallest arc-length gap, in eps of the total length L, between two positions the
/// parameterization's table treats as distinct (a knot and a table node, or two knots): the
/// cumulative segment lengths and the nodes are each known to a few eps L (compensated sums,
/// Newton to rounding), so a piece narrower than 64 eps L would have ends as uncertain as its
/// width and a slope 1/width made of rounding.
inline constexpr int knot_gap_eps = 64;

/// Whether bisecting a panel did not pay: its estimate was already below sqrt(eps) of its
/// magnitude (integral of |f|) and its two halves' estimates together are not below half of it.
template <class Real>
[[nodiscard]] bool bisection_stagnated(const Real& parent_error, const Real& halves_error, const Real& magnitude) {
  using std::sqrt;
  return parent_error <= sqrt(epsilon<Real>()) * magnitude && halves_error > parent_error / Real(2);
}

}  // namespace curvebench::arclength::detail
