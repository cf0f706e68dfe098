// Registry entries "bezier" and "rational_bezier" (see io/family.hpp): one polynomial or rational
// Bezier segment.
#pragma once

#include "curvebench/curves/bezier.hpp"
#include "curvebench/curves/rational_bezier.hpp"
#include "curvebench/io/family.hpp"

namespace curvebench::io {

namespace detail {

template <class Real>
interval<Real> bezier_domain(const field& spec) {
  if (!spec.has("domain")) return {Real(0), Real(1)};
  const std::vector<Real> d = spec.member("domain").reals<Real>();
  if (d.size() != 2) spec.member("domain").fail("expected [lo, hi], got " + spec.member("domain").shown());
  return {d[0], d[1]};
}

}  // namespace detail

struct bezier_family : audited_by_points {
  static constexpr std::string_view name = "bezier";
  static constexpr std::string_view summary = "one Bezier segment of degree n (n + 1 control points, n <= 60)";
  static constexpr field_doc fields[] = {
      {"points", "the control points", presence::required},
      {"domain", "[lo, hi], the parameter interval (default [0, 1])"},
  };
  static constexpr std::string_view examples[] = {
      R"({"type": "bezier", "points": [[0,0],[1,2],[3,2],[4,0]], "domain": [0, 1]})",
  };
  static constexpr std::array<std::string_view, 3> algorithms{"de_casteljau", "bernstein_sum", "horner"};

  template <class Real, int Dim>
  static any_curve<Real, Dim> build(const field& spec) {
    const point_list<Real, Dim> p = detail::spec_points<Real, Dim>(spec);
    return bezier<Real, Dim>(std::span<const point<Real, Dim>>(p), detail::bezier_domain<Real>(spec));
  }

  template <int Dim>
  static evaluator_fn<Dim> evaluator(const any_curve<double, Dim>& c, const json&, std::string_view algorithm) {
    const bezier_algorithm a = detail::named(
        name, algorithm, {bezier_algorithm::de_casteljau, bezier_algorithm::bernstein_sum, bezier_algorithm::horner});
    return detail::on_target<bezier<double, Dim>>(c, name, [a](const auto& b, double u) { return b.evaluate(u, a); });
  }
};

struct rational_bezier_family : audited_by_points {
  static constexpr std::string_view name = "rational_bezier";
  static constexpr std::string_view summary = "one rational Bezier segment: control points with positive weights";
  static constexpr field_doc fields[] = {
      {"points", "the control points", presence::required},
      {"weights", "one weight > 0 per point", presence::required},
      {"domain", "[lo, hi], the parameter interval (default [0, 1])"},
  };
  static constexpr std::string_view examples[] = {
      R"({"type": "rational_bezier", "points": [[1,0],[1,1],[0,1]], "weights": [1, 0.7071067811865476, 1]})",
  };

  template <class Real, int Dim>
  static any_curve<Real, Dim> build(const field& spec) {
    const point_list<Real, Dim> p = detail::spec_points<Real, Dim>(spec);
    const interval<Real> dom = detail::bezier_domain<Real>(spec);
    const std::vector<Real> w =
        spec.member("weights", "a rational Bezier curve has one weight per point").reals<Real>();
    return rational_bezier<Real, Dim>(std::span<const point<Real, Dim>>(p), std::span<const Real>(w), dom);
  }
};

}  // namespace curvebench::io
