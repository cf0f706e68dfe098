// Registry entry "hermite" (see io/family.hpp): cubic Hermite interpolation of points and slopes.
#pragma once

#include "curvebench/curves/hermite_spline.hpp"
#include "curvebench/io/families/cubic_engine.hpp"

namespace curvebench::io {

struct hermite_family : family_defaults {
  static constexpr std::string_view name = "hermite";
  static constexpr std::string_view summary = "cubic Hermite pieces through the points with the given slopes dP/du";
  static constexpr field_doc fields[] = {
      {"points", "the interpolated points", presence::required},
      {"slopes", "one slope dP/du per point (C1); or give incoming and outgoing"},
      {"incoming", "the slope arriving at each point (with outgoing: a broken, C0 spline)"},
      {"outgoing", "the slope leaving each point (with incoming)"},
      {"knots", "the parameter of each point, increasing (default 0, 1, 2, ...)"},
  };
  static constexpr std::string_view examples[] = {
      R"({"type": "hermite", "knots": [0, 1, 2.5], "points": [[0,0],[2,1],[3,3]], "slopes": [[1,0],[1,1],[0,2]]})",
      R"({"type": "hermite", "points": [[0,0],[2,1],[3,3]], "incoming": [[1,0],[1,1],[0,2]], "outgoing": [[1,0],[2,-1],[0,2]]})",
  };
  static constexpr std::array<std::string_view, 3> algorithms = detail::cubic_engine_algorithms;
  static constexpr std::string_view audit =
      "the points and, as tangents, the slopes (2D, at most 40 points; not with incoming/outgoing)";

  template <class Real, int Dim>
  static any_curve<Real, Dim> build(const field& spec) {
    using pl = point_list<Real, Dim>;
    const pl p = detail::spec_points<Real, Dim>(spec);
    std::vector<Real> k = detail::knots_or_uniform<Real>(spec, p.size());
    if (spec.has("slopes")) {
      if (spec.has("incoming") || spec.has("outgoing"))
        spec.member("slopes").fail("give either slopes or incoming and outgoing, not both");
      return hermite_spline<Real, Dim>(std::move(k), p, spec.member("slopes").points<Real, Dim>());
    }
    pl in = spec.member("incoming", "give slopes, or incoming and outgoing").points<Real, Dim>();
    pl out = spec.member("outgoing", "give slopes, or incoming and outgoing").points<Real, Dim>();
    return hermite_spline<Real, Dim>(std::move(k), p, std::move(in), std::move(out));
  }

  template <int Dim>
  static evaluator_fn<Dim> evaluator(const any_curve<double, Dim>& c, const json&, std::string_view algorithm) {
    return detail::cubic_engine_evaluator<hermite_spline<double, Dim>>(c, name, algorithm);
  }

  /// The points, then the slopes as tangent items.
  static std::optional<audit_items> audit_items_of(const field& spec) {
    std::optional<audit_items> a = audited_by_points::audit_items_of(spec);
    if (!a || !spec.has("slopes")) return std::nullopt;
    const point_list<double, 2> slopes = spec.member("slopes").points<double, 2>();
    a->items.insert(a->items.end(), slopes.begin(), slopes.end());
    a->roles.resize(a->items.size(), audit_role::tangent);
    return a;
  }

  /// items = the points, then the slopes (as many as the spec's points).
  static json with_items(const json& spec, std::span<const point<double, 2>> items) {
    const std::size_t n = spec.at("points").size();
    if (items.size() != 2 * n)
      throw invalid_input("with_items: " + std::to_string(items.size()) + " items, a hermite spec with " +
                          std::to_string(n) + " points takes " + std::to_string(2 * n));
    json s = spec;
    s["points"] = detail::points_json<2>(items.first(n));
    s["slopes"] = detail::points_json<2>(items.subspan(n));
    return s;
  }
};

}  // namespace curvebench::io
