// Registry entry "polyline" (see io/family.hpp): straight segments through the points.
#pragma once

#include "curvebench/curves/polyline.hpp"
#include "curvebench/io/family.hpp"

namespace curvebench::io {

struct polyline_family : audited_by_points {
  static constexpr std::string_view name = "polyline";
  static constexpr std::string_view summary = "straight segments between consecutive points (C0)";
  static constexpr field_doc fields[] = {
      {"points", "the vertices, at least 2", presence::required},
      {"params", "the parameter of each vertex, increasing (default 0, 1, 2, ...)"},
  };
  static constexpr std::string_view examples[] = {
      R"({"type": "polyline", "points": [[0,0],[1,1],[2,0]], "params": [0, 0.5, 2]})",
  };

  template <class Real, int Dim>
  static any_curve<Real, Dim> build(const field& spec) {
    const point_list<Real, Dim> p = detail::spec_points<Real, Dim>(spec);
    if (spec.has("params")) {
      const std::vector<Real> u = spec.member("params").reals<Real>();
      return polyline<Real, Dim>(std::span<const point<Real, Dim>>(p), std::span<const Real>(u));
    }
    return polyline<Real, Dim>(std::span<const point<Real, Dim>>(p));
  }
};

}  // namespace curvebench::io
