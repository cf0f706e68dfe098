// Property audit: measures, on a curve family built from control data, the six properties of seed
// 001's table ("there is no single best representation of cubic spline"): interpolation, local
// control, continuity at knots, affine invariance, convex hull, variation diminishing (VD).
// Algorithm: the curve is sampled on `samples_per_segment` cells per breakpoint segment; the family
// is rebuilt from perturbed or affinely mapped copies of its items; distances are relative to the
// bounding-box diagonal of the point items. Each `measure_*` function below says what it measures
// and when it answers yes; `audit_properties` runs all six.
// Source: seed 001 (the table; affine invariance, convex hull), seed 000 (Bezier properties, VD:
// "no straight line cuts the curve more times than it cuts the control polygon"; C^k at knots).
// Cost: O(items x samples) evaluations and items + 2 rebuilds for the whole audit, plus
// O(lines x samples) for VD.
// Accuracy: tolerances scale with eps(Real) (`audit_options::defaults`). Sampling can only miss a
// crossing or an excursion, so a VD "no" is a real counterexample and "yes" means none was found.
// Errors: invalid_input for no items, roles of the wrong length, or options out of range.
// The audit reports; tests decide what the answer should be.
#pragma once

#include "curvebench/core/curve.hpp"
#include "curvebench/core/point.hpp"
#include "curvebench/core/real.hpp"

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace curvebench::analysis {

/// What a control item is: a point the curve may pass through, or a tangent (a vector).
enum class control_role { point, tangent };

/// Which point items the curve passes through.
enum class interpolation_kind { all, all_but_ends, ends_only, none, partial };

/// A property that holds, fails, or does not apply (tangent items, or Dim != 2).
enum class audit_verdict { yes, no, not_applicable };

[[nodiscard]] inline const char* to_string(interpolation_kind k) {
  switch (k) {
    case interpolation_kind::all: return "all";
    case interpolation_kind::all_but_ends: return "all but ends";
    case interpolation_kind::ends_only: return "ends only";
    case interpolation_kind::none: return "none";
    case interpolation_kind::partial: return "partial";
  }
  return "unknown";
}

[[nodiscard]] inline const char* to_string(audit_verdict v) {
  switch (v) {
    case audit_verdict::yes: return "yes";
    case audit_verdict::no: return "no";
    case audit_verdict::not_applicable: return "n/a";
  }
  return "unknown";
}

/// Tuning of the audit; `audit_options<Real>::defaults()` scales the tolerances with eps(Real).
template <class Real>
struct audit_options {
  int samples_per_segment = 48;  ///< grid cells per breakpoint segment (>= 2)
  int max_continuity_order = 3;  ///< highest derivative order compared at knots (>= 0)
  int random_lines = 400;        ///< VD: random lines through the data (>= 0)
  int directions = 72;           ///< VD: directions n whose extrema of n . C(u) are cut (>= 0)
  std::uint64_t seed = 1;        ///< seeds the perturbations, the affine map and the random lines
  Real interpolation_tolerance;  ///< distance / scale at or below which a point is interpolated
  Real move_threshold;           ///< change / perturbation above which a sample "moved"
  Real continuity_tolerance;     ///< jump / derivative scale above which a derivative is discontinuous
  Real affine_tolerance;         ///< deviation / scale above which affine invariance fails
  Real hull_tolerance;           ///< distance outside the hull / scale above which the hull is left

  [[nodiscard]] static audit_options defaults() {
    using std::sqrt;
    const Real e = epsilon<Real>();
    audit_options o;
    const Real e34 = sqrt(e) * sqrt(sqrt(e));  // eps^(3/4): 1.8e-12 in double
    o.interpolation_tolerance = Real(64) * e34;
    o.move_threshold = e34;
    o.continuity_tolerance = Real(64) * sqrt(e);
    o.affine_tolerance = Real(64) * e34;
    o.hull_tolerance = Real(64) * e34;
    return o;
  }
};

template <class Real>
struct interpolation_result {
  interpolation_kind kind = interpolation_kind::none;
  std::vector<Real> distance;  ///< per item: distance from the curve / scale (NaN for tangents)
};

template <class Real>
struct local_control_result {
  bool local = false;
  std::vector<interval<Real>> moved_range;  ///< per item: first..last moved parameter (lo > hi: none)
  std::vector<Real> moved_fraction;         ///< per item: fraction of grid cells that moved
  Real max_moved_fraction = Real(0);
};

/// Continuity measured at one interior breakpoint.
template <class Real>
struct knot_continuity {
  Real u;
  int order;                        ///< highest k with jumps 0..k below tolerance; -1: the curve jumps
  std::vector<Real> relative_jump;  ///< |D_k(u+) - D_k(u-)| / max_grid |D_k|, k = 0..max
};

template <class Real>
struct continuity_result {
  bool one_piece = true;  ///< no interior breakpoint (one polynomial or rational piece)
  int order = 0;          ///< min over interior breakpoints; max_order means "at least"
  int max_order = 3;
  std::vector<knot_continuity<Real>> knots;
};

template <class Real>
struct affine_result {
  bool invariant = false;
  Real deviation = Real(0);  ///< largest |rebuilt - mapped| / scale of the mapped data
};

template <class Real>
struct convex_hull_result {
  audit_verdict verdict = audit_verdict::not_applicable;
  Real violation = Real(0);  ///< largest distance outside the hull / scale
};

struct variation_diminishing_result {
  audit_verdict verdict = audit_verdict::not_applicable;
  int lines_tested = 0;
  int worst_excess = 0;  ///< max over lines of (curve crossings - polygon crossings)
};

/// All six measurements of one family on one set of items.
template <class Real>
struct property_report {
  std::size_t items = 0;
  interpolation_result<Real> interpolation;
  local_control_result<Real> local_control;
  continuity_result<Real> continuity;
  affine_result<Real> affine;
  convex_hull_result<Real> convex_hull;
  variation_diminishing_result variation_diminishing;
};

// In every function: `items` are the control data, `roles` says which items are tangents (empty:
// all are points), and a `build` maps a span of items to a curve of the items' Real and Dim.
// Nothing about the family is assumed beyond the curve concept.

/// Interpolation: the distance from each point item to `c` (best grid sample, then safeguarded
/// Newton on (C(u) - P) . C'(u) = 0); a point is on the curve when distance / scale <=
/// interpolation_tolerance. Summary over the point items in order: all, all but the two ends, the
/// two ends only, none, or partial (any other pattern).
template <curve Curve>
[[nodiscard]] interpolation_result<typename Curve::real_type> measure_interpolation(
    const Curve& c, std::span<const point<typename Curve::real_type, Curve::dimension>> items,
    std::span<const control_role> roles = {},
    const audit_options<typename Curve::real_type>& opt = audit_options<typename Curve::real_type>::defaults());

/// Local control: each item in turn is moved by scale / 8 in a random direction and the family
/// rebuilt; a grid sample moved when the curve changed there (compared at the same normalized
/// parameter) by more than move_threshold times the perturbation. Local when every item leaves at
/// least one whole grid cell unmoved, so a global family whose influence only vanishes at isolated
/// parameters (a Bezier curve at its ends) is not local.
template <class Real, int Dim, class Builder>
[[nodiscard]] local_control_result<Real> measure_local_control(
    Builder&& build, std::span<const point<Real, Dim>> items, std::span<const control_role> roles = {},
    const audit_options<Real>& opt = audit_options<Real>::defaults());

/// Continuity at every interior breakpoint b: one-sided limits of derivative(u, k), k = 0..max,
/// extrapolated quadratically from b -/+ h, 2h, 3h (exact for a cubic's derivatives; h = eps^(1/4)
/// times the shorter neighbouring segment), the jump divided by the largest |derivative(u, k)| on
/// the grid. C^k at b when jumps 0..k are all below continuity_tolerance; the curve's order is the
/// minimum over breakpoints (max_continuity_order means "at least"; -1 means a jump).
template <curve Curve>
[[nodiscard]] continuity_result<typename Curve::real_type> measure_continuity(
    const Curve& c,
    const audit_options<typename Curve::real_type>& opt = audit_options<typename Curve::real_type>::defaults());

/// Affine invariance: a random well-conditioned affine map x -> A x + b with a shear (not a
/// similarity) is applied to the point items (A v to tangent items) and the family rebuilt; the
/// rebuilt curve is compared with the mapped curve at the same normalized parameter on the grid.
/// Invariant when the deviation / scale of the mapped data <= affine_tolerance.
template <class Real, int Dim, class Builder>
[[nodiscard]] affine_result<Real> measure_affine_invariance(
    Builder&& build, std::span<const point<Real, Dim>> items, std::span<const control_role> roles = {},
    const audit_options<Real>& opt = audit_options<Real>::defaults());

/// Convex hull (Dim = 2, every item a point; otherwise not applicable): every grid sample of `c`
/// within hull_tolerance x scale of the exact convex hull of the items (Andrew's monotone chain).
template <curve Curve>
[[nodiscard]] convex_hull_result<typename Curve::real_type> measure_convex_hull(
    const Curve& c, std::span<const point<typename Curve::real_type, Curve::dimension>> items,
    std::span<const control_role> roles = {},
    const audit_options<typename Curve::real_type>& opt = audit_options<typename Curve::real_type>::defaults());

/// Variation diminishing (Dim = 2, every item a point; otherwise not applicable): for random lines
/// and for lines just inside every local extremum of n . C(u) over `directions` directions n, the
/// sign changes of the signed distance along the sampled curve minus those along the control
/// polygon (the items in order). Yes when no line gives a positive excess.
template <curve Curve>
[[nodiscard]] variation_diminishing_result measure_variation_diminishing(
    const Curve& c, std::span<const point<typename Curve::real_type, Curve::dimension>> items,
    std::span<const control_role> roles = {},
    const audit_options<typename Curve::real_type>& opt = audit_options<typename Curve::real_type>::defaults());

/// All six on the curve build(items), sharing one grid and one random stream (drawn by local
/// control, then the affine map, then the VD lines: the first equals measure_local_control with the
/// same seed; the map and lines differ from the standalone calls', the verdicts' meaning does not).
template <class Real, int Dim, class Builder>
[[nodiscard]] property_report<Real> audit_properties(Builder&& build, std::span<const point<Real, Dim>> items,
                                                     std::span<const control_role> roles = {},
                                                     const audit_options<Real>& opt = audit_options<Real>::defaults());

}  // namespace curvebench::analysis

#include "curvebench/analysis/detail/property_audit_impl.hpp"
