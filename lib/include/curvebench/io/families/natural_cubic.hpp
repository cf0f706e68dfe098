// Registry entry "natural_cubic" (see io/family.hpp): the C2 interpolating cubic spline.
#pragma once

#include "curvebench/curves/natural_cubic_spline.hpp"
#include "curvebench/io/families/cubic_engine.hpp"

namespace curvebench::io {

struct natural_cubic_family : audited_by_points {
  static constexpr std::string_view name = "natural_cubic";
  static constexpr std::string_view summary = "the C2 cubic spline through the points (one tridiagonal solve)";
  static constexpr field_doc fields[] = {
      {"points", "the interpolated points", presence::required},
      {"end", "natural (zero 2nd derivative, default), clamped (given slopes), not_a_knot, periodic"},
      {"start_slope", "dP/du at the first point (end \"clamped\")"},
      {"end_slope", "dP/du at the last point (end \"clamped\")"},
      {"knots", "the parameter of each point, increasing (default 0, 1, 2, ...)"},
  };
  static constexpr std::string_view examples[] = {
      R"({"type": "natural_cubic", "points": [[0,0],[1,2],[3,3],[4,0]], "end": "clamped", "start_slope": [1,0], "end_slope": [1,-1]})",
  };
  static constexpr std::array<std::string_view, 3> algorithms = detail::cubic_engine_algorithms;

  template <class Real, int Dim>
  static any_curve<Real, Dim> build(const field& spec) {
    const point_list<Real, Dim> p = detail::spec_points<Real, Dim>(spec);
    const std::vector<Real> k = detail::knots_or_uniform<Real>(spec, p.size());
    const std::string e =
        spec.has("end") ? spec.member("end").one_of({"natural", "clamped", "not_a_knot", "periodic"}) : "natural";
    if (e == "clamped") {
      const point<Real, Dim> start = detail::one_point<Real, Dim>(spec.member("start_slope", "end is \"clamped\""));
      const point<Real, Dim> end = detail::one_point<Real, Dim>(spec.member("end_slope", "end is \"clamped\""));
      return natural_cubic_spline<Real, Dim>(k, p, start, end);
    }
    const spline_end end = e == "natural"      ? spline_end::natural
                           : e == "not_a_knot" ? spline_end::not_a_knot
                                               : spline_end::periodic;
    return natural_cubic_spline<Real, Dim>(k, p, end);
  }

  template <int Dim>
  static evaluator_fn<Dim> evaluator(const any_curve<double, Dim>& c, const json&, std::string_view algorithm) {
    return detail::cubic_engine_evaluator<natural_cubic_spline<double, Dim>>(c, name, algorithm);
  }
};

}  // namespace curvebench::io
