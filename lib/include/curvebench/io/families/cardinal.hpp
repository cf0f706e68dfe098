// Registry entries "cardinal" and "catmull_rom" (see io/family.hpp): interpolating cubic splines
// whose slopes come from the neighbouring points; Catmull-Rom is the cardinal spline with s = 1/2.
#pragma once

#include "curvebench/curves/cardinal_spline.hpp"
#include "curvebench/io/families/cubic_engine.hpp"

namespace curvebench::io {

namespace detail {

/// The cardinal spline of a spec; s is 1/2 unless the spec gives s or tension (cardinal only).
template <class Real, int Dim>
any_curve<Real, Dim> build_cardinal(const field& spec) {
  const point_list<Real, Dim> p = spec_points<Real, Dim>(spec);
  cardinal_options<Real, Dim> opt;
  if (spec.has("s") && spec.has("tension")) spec.member("s").fail("give either s or tension (s = (1 - tension)/2)");
  if (spec.has("s")) opt.s = spec.member("s").number_as<Real>();
  if (spec.has("tension")) opt.s = (Real(1) - spec.member("tension").number_as<Real>()) / Real(2);
  opt.alpha = real_or<Real>(spec, "alpha", Real(0));
  if (spec.has("end")) {
    const std::string e = spec.member("end").one_of({"phantom", "one_sided", "tangents", "closed", "control_points"});
    // ("duplicate" is resolved into control_points before a build: resolve_duplicate_ends.)
    opt.end = e == "phantom"     ? cardinal_end::phantom
              : e == "one_sided" ? cardinal_end::one_sided
              : e == "tangents"  ? cardinal_end::given_tangents
              : e == "closed"    ? cardinal_end::closed
                                 : cardinal_end::control_points;
  }
  if (opt.end == cardinal_end::given_tangents) {
    opt.start_tangent = one_point<Real, Dim>(spec.member("start_tangent", "end is \"tangents\""));
    opt.end_tangent = one_point<Real, Dim>(spec.member("end_tangent", "end is \"tangents\""));
  }
  if (spec.has("knots")) return cardinal_spline<Real, Dim>(spec.member("knots").reals<Real>(), p, opt);
  return cardinal_spline<Real, Dim>(p, opt);
}

/// The "end" field's doc, shared by cardinal and catmull_rom.
inline constexpr std::string_view end_doc =
    "phantom (extrapolated end points, default), one_sided (2nd-order differences), tangents, closed, "
    "control_points (the textbook form: the first and last points only shape the end segments, the curve "
    "runs from the second point to the second-to-last on [u_1, u_n-2]; at least 4 points), duplicate (game "
    "engines' clamped index: P_-1 = P_0 and P_n+1 = P_n, the end slope half the end chord's; u = i at point i, "
    "the curve on [0, n-1] as an engine indexes it; uniform knots only, alpha 0)";

/// end "duplicate" as control_points with the end points repeated (computed once in double): the
/// curve runs from the first point to the last on the knots -1, 0, 1, ..., n, so that u = i at
/// point i and the domain is [0, n-1], the parameter an engine's clamped index gives (without them
/// the repeated first point took u = 0 and the curve started at u = 1). A repeated point is a
/// zero-length chord, so alpha > 0 (and given knots) are refused, naming the field.
inline json resolve_duplicate_ends(json r, const field& spec) {
  if (!spec.has("end") || spec.member("end").string() != "duplicate") return r;
  if (spec.has("alpha") && spec.member("alpha").number() != 0)
    spec.member("alpha").fail("end \"duplicate\" repeats the end points, a zero-length chord: alpha must be 0");
  if (spec.has("knots")) spec.member("knots").fail("end \"duplicate\" takes uniform knots: give no knots");
  json& p = r["points"];
  if (!p.is_array() || p.size() < 2) spec.member("points").fail("end \"duplicate\" needs at least 2 points");
  p.insert(p.begin(), p.front());
  p.push_back(p.back());
  json knots = json::array();
  for (std::size_t i = 0; i < p.size(); ++i) knots.push_back(static_cast<double>(i) - 1);
  r["knots"] = knots;
  r["end"] = "control_points";
  return r;
}

/// Knots from |dP|^alpha (alpha > 0, no knots given) computed once in double, from all the points
/// (closed: with the closing chord; control_points: the end points' chords too); alpha becomes 0.
template <int Dim>
json resolve_alpha_knots(const field& spec) {
  json r = spec.value;
  if (!spec.has("knots") && spec.has("alpha")) {
    const double alpha = spec.member("alpha").number();
    if (alpha != 0) {
      const bool closed = spec.has("end") && spec.member("end").string() == "closed";
      const point_list<double, Dim> p = spec.member("points").points<double, Dim>();
      r["knots"] = alpha_knots<double, Dim>(std::span<const point<double, Dim>>(p), alpha, closed);
      r["alpha"] = 0;
    }
  }
  return r;
}

}  // namespace detail

struct cardinal_family : audited_by_points {
  static constexpr std::string_view name = "cardinal";
  static constexpr std::string_view summary =
      "interpolating C1 cubic spline, slope at P_i = 2s x the parabola's through P_i-1, P_i, P_i+1";
  static constexpr field_doc fields[] = {
      {"points", "the interpolated points", presence::required},
      {"s", "the slope scale (default 1/2: Catmull-Rom); not with tension"},
      {"tension", "1 - 2s (default 0); not with s"},
      {"alpha", "knots u_i+1 - u_i = |P_i+1 - P_i|^alpha: 0 uniform (default), 0.5 centripetal, 1 chordal"},
      {"end", detail::end_doc},
      {"start_tangent", "dP/du at the first point (end \"tangents\")"},
      {"end_tangent", "dP/du at the last point (end \"tangents\")"},
      {"knots", "the parameter of each point, increasing (instead of alpha's)"},
  };
  static constexpr std::string_view examples[] = {
      R"({"type": "cardinal", "points": [[0,0],[1,2],[3,3],[4,0]], "tension": 0.5, "alpha": 0.5, "end": "one_sided"})",
  };
  static constexpr std::array<std::string_view, 3> algorithms = detail::cubic_engine_algorithms;

  template <class Real, int Dim>
  static any_curve<Real, Dim> build(const field& spec) {
    return detail::build_cardinal<Real, Dim>(spec);
  }

  /// Alpha knots, and s from tension, computed once in double.
  template <int Dim>
  static json resolve(const field& spec) {
    json r = detail::resolve_duplicate_ends(detail::resolve_alpha_knots<Dim>(spec), spec);
    if (spec.has("tension") && !spec.has("s")) {
      r["s"] = (1 - spec.member("tension").number()) / 2;
      r.erase("tension");
    }
    return r;
  }

  template <int Dim>
  static evaluator_fn<Dim> evaluator(const any_curve<double, Dim>& c, const json&, std::string_view algorithm) {
    return detail::cubic_engine_evaluator<cardinal_spline<double, Dim>>(c, name, algorithm);
  }
};

struct catmull_rom_family : audited_by_points {
  static constexpr std::string_view name = "catmull_rom";
  static constexpr std::string_view summary = "the cardinal spline with s = 1/2 (Barry-Goldman for alpha > 0)";
  static constexpr field_doc fields[] = {
      {"points", "the interpolated points", presence::required},
      {"alpha", "knots u_i+1 - u_i = |P_i+1 - P_i|^alpha: 0 uniform (default), 0.5 centripetal, 1 chordal"},
      {"end", detail::end_doc},
      {"start_tangent", "dP/du at the first point (end \"tangents\")"},
      {"end_tangent", "dP/du at the last point (end \"tangents\")"},
      {"knots", "the parameter of each point, increasing (instead of alpha's)"},
  };
  static constexpr std::string_view examples[] = {
      R"({"type": "catmull_rom", "points": [[0,0],[1,2],[3,3],[4,0]], "end": "tangents", "start_tangent": [1,0], "end_tangent": [1,0]})",
      R"({"type": "catmull_rom", "points": [[0,0],[1,2],[3,3],[4,0],[6,1],[7,4]], "alpha": 0.5, "end": "control_points"})",
  };
  static constexpr std::array<std::string_view, 3> algorithms = detail::cubic_engine_algorithms;

  template <class Real, int Dim>
  static any_curve<Real, Dim> build(const field& spec) {
    return detail::build_cardinal<Real, Dim>(spec);
  }

  /// Alpha knots and duplicated ends computed once in double.
  template <int Dim>
  static json resolve(const field& spec) {
    return detail::resolve_duplicate_ends(detail::resolve_alpha_knots<Dim>(spec), spec);
  }

  template <int Dim>
  static evaluator_fn<Dim> evaluator(const any_curve<double, Dim>& c, const json&, std::string_view algorithm) {
    return detail::cubic_engine_evaluator<cardinal_spline<double, Dim>>(c, name, algorithm);
  }
};

}  // namespace curvebench::io
