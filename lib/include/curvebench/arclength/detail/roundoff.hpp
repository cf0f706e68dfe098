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
// panel (seen on a near-cusp, where the halves' estimates were 5e5 times the parent's). So a
// bisection stops only at the second stagnation in a row, parent to halves and then half to
// quarters: a coincidence in the parent is exposed by its halves' genuine estimates.
#pragma once

#include "curvebench/core/real.hpp"

namespace curvebench::arclength::detail {

/// Whether bisecting a panel did not pay: its estimate was already below sqrt(eps) of its
/// magnitude (integral of |f|) and its two halves' estimates together are not below half of it.
template <class Real>
[[nodiscard]] bool bisection_stagnated(const Real& parent_error, const Real& halves_error, const Real& magnitude) {
  using std::sqrt;
  return parent_error <= sqrt(epsilon<Real>()) * magnitude && halves_error > parent_error / Real(2);
}

}  // namespace curvebench::arclength::detail
