// Registry entry "kochanek_bartels" (see io/family.hpp): TCB splines, interpolating cubics whose
// tangents are shaped per key by tension, continuity and bias.
#pragma once

#include "curvebench/curves/kochanek_bartels.hpp"
#include "curvebench/io/families/cubic_engine.hpp"

namespace curvebench::io {

struct kochanek_bartels_family : audited_by_points {
  static constexpr std::string_view name = "kochanek_bartels";
  static constexpr std::string_view summary =
      "interpolating cubic spline with per-key tension, continuity, bias (0, 0, 0: Catmull-Rom)";
  static constexpr field_doc fields[] = {
      {"points", "the keys", presence::required},
      {"tension", "a number for every key or one per key (default 0)"},
      {"continuity", "a number for every key or one per key (default 0)"},
      {"bias", "a number for every key or one per key (default 0); +1 weights the arriving chord"},
      {"closed", "true: the keys wrap around, the last segment returns to the first key (default false)"},
      {"time_adjust", "scale the tangents by the neighbouring knot intervals (C1 on any knots; default true)"},
      {"knots", "the parameter of each key, increasing (default 0, 1, 2, ...; one more when closed)"},
  };
  static constexpr std::string_view examples[] = {
      R"({"type": "kochanek_bartels", "points": [[0,0],[2,2],[4,0],[5,3]], "tension": [0,0.3,-0.3,0], "continuity": 0, "bias": 0.2, "closed": false})",
  };
  static constexpr std::array<std::string_view, 3> algorithms = detail::cubic_engine_algorithms;

  template <class Real, int Dim>
  static any_curve<Real, Dim> build(const field& spec) {
    const point_list<Real, Dim> p = detail::spec_points<Real, Dim>(spec);
    const std::vector<Real> t = detail::per_key<Real>(spec, "tension", p.size());
    const std::vector<Real> c = detail::per_key<Real>(spec, "continuity", p.size());
    const std::vector<Real> b = detail::per_key<Real>(spec, "bias", p.size());
    std::vector<tcb<Real>> keys(p.size());
    for (std::size_t i = 0; i < p.size(); ++i) keys[i] = {t[i], c[i], b[i]};
    typename kochanek_bartels<Real, Dim>::options opt;
    if (spec.has("closed")) opt.closed = spec.member("closed").boolean();
    if (spec.has("time_adjust")) opt.time_adjust = spec.member("time_adjust").boolean();
    if (spec.has("knots")) return kochanek_bartels<Real, Dim>(spec.member("knots").reals<Real>(), p, keys, opt);
    return kochanek_bartels<Real, Dim>(p, keys, opt);
  }

  template <int Dim>
  static evaluator_fn<Dim> evaluator(const any_curve<double, Dim>& c, const json&, std::string_view algorithm) {
    return detail::cubic_engine_evaluator<kochanek_bartels<double, Dim>>(c, name, algorithm);
  }
};

}  // namespace curvebench::io
