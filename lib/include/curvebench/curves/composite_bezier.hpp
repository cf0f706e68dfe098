// Composite Bezier curves: a chain of Bezier segments (bezier.hpp) of any, mixed, degrees on
// strictly increasing knots u_0 < ... < u_n; segment i is its Bezier curve on [u_i, u_{i+1}]. With
// rational segments (rational_bezier.hpp, weights per segment) it is composite_rational_bezier.
// Evaluation: binary search for the segment, then its de Casteljau; the batch evaluate keeps the
// previous segment while u stays in it (O(1) lookups for sorted parameters). Derivatives of any
// order by the chain rule (h_i^-k). An interior knot belongs to the segment on its right (right
// limits and right derivatives there), u_n to the last; value_from_left(u) is the left segment's
// end (core/curve.hpp). Segments need not meet (stepped keys);
// continuity_at_joins(tol) reports C0, C1 and G1 per interior knot. Bad data (no segment, bad
// point counts, non-finite values, bad knots) throw invalid_input; u outside std::domain_error.
// Sources: seeds 000, 002 (piecewise curves, continuity at joins); Farin (2002), ch. 7.
// Cost: O(log n) + O(L^2) per value. Accuracy: as bezier.hpp, ~L ulps of the segment's
// control-point scale; rounding_bound(order) (core/curve.hpp) is the largest of the segments'.
#pragma once

#include "curvebench/core/curve.hpp"
#include "curvebench/core/detail/segment_lookup.hpp"
#include "curvebench/core/error.hpp"
#include "curvebench/core/point.hpp"
#include "curvebench/core/real.hpp"
#include "curvebench/curves/bezier.hpp"
#include "curvebench/curves/rational_bezier.hpp"

#include <algorithm>
#include <array>
#include <cstddef>
#include <limits>
#include <span>
#include <string>
#include <type_traits>
#include <vector>

namespace curvebench {

/// The continuity found at one interior knot of a composite curve (see continuity_at_joins).
template <class Real>
struct join_continuity {
  std::size_t join = 0;    ///< index i of the knot u_i, 0 < i < n
  Real knot{};             ///< u_i
  Real gap{};              ///< |P_left(u_i) - P_right(u_i)| / scale
  Real derivative_jump{};  ///< |P'_left - P'_right| / max(|P'_left|, |P'_right|) (0 if both vanish)
  Real tangent_jump{};     ///< |T_left - T_right| of the unit tangents (0 unless `regular`)
  bool regular = false;    ///< both one-sided first derivatives are non-zero
  bool c0 = false;         ///< gap <= tol
  bool c1 = false;         ///< c0 and derivative_jump <= tol
  bool g1 = false;         ///< c0 and (c1 or (regular and tangent_jump <= tol))
};

template <class Real, int Dim, class Segment = bezier<Real, Dim>>
class composite_bezier {
 public:
  using real_type = Real;
  using point_type = point<Real, Dim>;
  static constexpr int dimension = Dim;
  using segment_type = Segment;
  /// Whether the segments are rational Bezier curves (composite_rational_bezier).
  static constexpr bool rational = std::is_same_v<Segment, rational_bezier<Real, Dim>>;
  static_assert(rational || std::is_same_v<Segment, bezier<Real, Dim>>, "segments are bezier or rational_bezier");

  /// segments[i] are the control points of segment i (any degree >= 1), on [knots[i], knots[i+1]].
  composite_bezier(std::span<const point_list<Real, Dim>> segments, std::span<const Real> knots) requires(!rational) {
    init(segments, {}, knots);
  }

  /// Rational segments: weights[i] are segment i's weights, one > 0 per control point.
  /// `data_error`, empty or one per segment: how far each segment's stored control data may be from
  /// the data it stands for (rational_bezier.hpp, control_data_error).
  composite_bezier(std::span<const point_list<Real, Dim>> segments, std::span<const std::vector<Real>> weights,
                   std::span<const Real> knots,
                   std::span<const control_data_error<Real>> data_error = {}) requires(rational) {
    init(segments, weights, knots, data_error);
  }

  [[nodiscard]] interval<Real> domain() const { return {knots_.front(), knots_.back()}; }
  [[nodiscard]] std::span<const Real> breakpoints() const { return knots_; }
  [[nodiscard]] std::span<const Real> knots() const { return knots_; }
  [[nodiscard]] std::size_t segment_count() const { return segments_.size(); }
  [[nodiscard]] const segment_type& segment(std::size_t i) const {
    if (i >= segments_.size())
      validate::fail("i = " + std::to_string(i) + ": segment index must be < " + std::to_string(segments_.size()));
    return segments_[i];
  }
  /// The position scale of the join check: the largest absolute control coordinate (1 if all are 0).
  [[nodiscard]] Real scale() const { return scale_; }

  /// The segment holding u: the i with u_i <= u < u_{i+1}, or the last one at u = u_n (binary search).
  [[nodiscard]] std::size_t segment_index(const Real& u) const { return detail::checked_segment_of<Real>(knots_, u); }

  [[nodiscard]] point_type operator()(const Real& u) const { return segments_[segment_index(u)](u); }

  /// P(u-), the limit from the left: at an interior knot u_i the end of segment i - 1 (where the
  /// segments do not meet, not P(u_i)); elsewhere P(u) (u_0 belongs to the first segment).
  [[nodiscard]] point_type value_from_left(const Real& u) const {
    check_parameter(u, domain());
    return segments_[detail::segment_of_from_left<Real>(knots_, u)](u);
  }

  /// Upper bound on the rounding of P (order 0) or P' (order 1) over the domain: the largest of the
  /// segments' de Casteljau bounds (bezier.hpp), taken at construction; +inf for other orders.
  [[nodiscard]] Real rounding_bound(int order) const {
    if (order < 0 || order > 1) return std::numeric_limits<Real>::infinity();
    return rounding_bound_[static_cast<std::size_t>(order)];
  }

  /// d^order P / du^order: the segment's derivative (chain rule 1 / h_i^order included).
  [[nodiscard]] point_type derivative(const Real& u, int order) const {
    validate::derivative_order(order);
    return segments_[segment_index(u)].derivative(u, order);
  }

  /// Batch evaluation: out[i] = the order-th derivative at us[i]. The segment of the previous
  /// parameter is tried first and the binary search runs only when u leaves it, so sorted
  /// parameters cost O(1) lookups each (any order is correct). Sizes must match (invalid_input);
  /// every parameter is checked (std::domain_error). No allocation.
  void evaluate(std::span<const Real> us, std::span<point_type> out, int order = 0) const {
    validate::same_count("out", out.size(), "us", us.size());
    validate::derivative_order(order);
    std::size_t seg = 0;
    for (std::size_t i = 0; i < us.size(); ++i) {
      const Real& u = us[i];
      if (!detail::in_segment<Real>(knots_, seg, u)) {
        check_parameter(u, domain(), "us", i);  // NaN is never inside: it ends here
        seg = segment_index(u);
      }
      out[i] = segments_[seg].derivative(u, order);
    }
  }

  /// Per interior knot u_i (i = 1..n-1): the one-sided values and first derivatives of segments i-1
  /// and i compared with the relative tolerance `tol` (>= 0): C0 when the gap is <= tol * scale(),
  /// C1 when also the derivatives differ by <= tol relative to the larger, G1 when C0 and the unit
  /// tangents differ by <= tol (C1 implies G1, also when both derivatives vanish).
  [[nodiscard]] std::vector<join_continuity<Real>> continuity_at_joins(const Real& tol) const {
    validate::finite("tol", tol);
    if (tol < Real(0)) validate::fail("tol = " + to_text(tol) + ": must be >= 0");
    std::vector<join_continuity<Real>> out;
    out.reserve(segments_.size() - 1);
    for (std::size_t i = 1; i < segments_.size(); ++i) {
      const segment_type& left = segments_[i - 1];
      const segment_type& right = segments_[i];
      const Real u = knots_[i];
      join_continuity<Real> j;
      j.join = i;
      j.knot = u;
      const point_type dp = left(u) - right(u);
      j.gap = dp.norm() / scale_;
      const point_type dl = left.derivative(u, 1);
      const point_type dr = right.derivative(u, 1);
      const Real nl = dl.norm();
      const Real nr = dr.norm();
      const Real nmax = std::max(nl, nr);
      const point_type dd = dl - dr;
      j.derivative_jump = nmax > Real(0) ? Real(dd.norm() / nmax) : Real(0);
      j.regular = nl > Real(0) && nr > Real(0);
      if (j.regular) {
        const point_type dt = dl / nl - dr / nr;
        j.tangent_jump = dt.norm();
      }
      j.c0 = j.gap <= tol;
      j.c1 = j.c0 && j.derivative_jump <= tol;
      j.g1 = j.c0 && (j.c1 || (j.regular && j.tangent_jump <= tol));
      out.push_back(j);
    }
    return out;
  }

 private:
  void init(std::span<const point_list<Real, Dim>> segments, std::span<const std::vector<Real>> weights,
            std::span<const Real> knots, std::span<const control_data_error<Real>> data_error = {}) {
    validate::count_at_least("segments", segments.size(), 1);
    validate::same_count("knots", knots.size(), "segments + 1", segments.size() + 1);
    validate::increasing("knots", knots);
    if constexpr (rational) {
      validate::same_count("weights", weights.size(), "segments", segments.size());
      if (!data_error.empty()) validate::same_count("data_error", data_error.size(), "segments", segments.size());
    }
    for (std::size_t i = 0; i < segments.size(); ++i) {
      const std::string name = validate::indexed("segments", i);
      validate::count_at_least(name, segments[i].size(), 2, "a Bezier segment of degree L >= 1 has L + 1 points");
      validate::finite_points<Real, Dim>(name, segments[i]);
      if constexpr (rational) {
        const std::string w = validate::indexed("weights", i);
        validate::same_count(w, weights[i].size(), "points of " + name, segments[i].size());
        for (std::size_t k = 0; k < weights[i].size(); ++k) validate::positive(w, weights[i][k], k);
      }
    }
    knots_.assign(knots.begin(), knots.end());
    segments_.reserve(segments.size());
    using std::abs;
    scale_ = Real(0);
    for (std::size_t i = 0; i < segments.size(); ++i) {
      const interval<Real> on{knots_[i], knots_[i + 1]};
      if constexpr (rational)
        segments_.emplace_back(std::span<const point_type>(segments[i]), std::span<const Real>(weights[i]), on,
                               data_error.empty() ? control_data_error<Real>{} : data_error[i]);
      else
        segments_.emplace_back(std::span<const point_type>(segments[i]), on);
      for (const auto& p : segments[i])
        for (int d = 0; d < Dim; ++d) scale_ = std::max(scale_, Real(abs(p[d])));
    }
    if (scale_ == Real(0)) scale_ = Real(1);
    for (const segment_type& seg : segments_)
      for (std::size_t k = 0; k < 2; ++k)
        rounding_bound_[k] = std::max(rounding_bound_[k], seg.rounding_bound(static_cast<int>(k)));
  }

  std::vector<Real> knots_;
  std::vector<segment_type> segments_;
  std::array<Real, 2> rounding_bound_{};
  Real scale_{};
};

/// A chain of rational Bezier segments (rational_bezier.hpp), e.g. an SVG path whose elliptical
/// arcs are rational quadratics (io/families/svg_path.hpp).
template <class Real, int Dim>
using composite_rational_bezier = composite_bezier<Real, Dim, rational_bezier<Real, Dim>>;

}  // namespace curvebench
