// JSON curve specs -> curves: the format the `curvebench` tool and the case suite read.
//
// A spec is an object {"type": "...", "points": [[x, y(, z)], ...], <the family's own fields>}.
// Every spec may also carry the metadata fields "name", "group", "reason" and "quick" (the case
// suite uses them); any other unknown field is an error, so a misspelled option never passes silently.
// The dimension is the length of the points (circle and arc specs are 2D). The README documents
// each type with an example; `spec_types()` lists them.
//
// Numbers are JSON doubles converted exactly to Real, so a spec instantiated at real50 is the
// exact 50-digit twin of the double curve (the harness's reference). Errors: io::spec_error
// (an invalid_input) naming the field path; family constructors' own invalid_input messages
// are prefixed with the spec's path. Cost: one construction of the family.
#pragma once

#include "curvebench/core/any_curve.hpp"
#include "curvebench/curves/bezier.hpp"
#include "curvebench/curves/bspline.hpp"
#include "curvebench/curves/cardinal_spline.hpp"
#include "curvebench/curves/composite_bezier.hpp"
#include "curvebench/curves/hermite_spline.hpp"
#include "curvebench/curves/kochanek_bartels.hpp"
#include "curvebench/curves/lagrange.hpp"
#include "curvebench/curves/natural_cubic_spline.hpp"
#include "curvebench/curves/nurbs.hpp"
#include "curvebench/curves/polyline.hpp"
#include "curvebench/curves/rational_bezier.hpp"
#include "curvebench/io/json_fields.hpp"

#include <boost/math/constants/constants.hpp>

#include <cmath>
#include <string>
#include <string_view>
#include <vector>

namespace curvebench::io {

/// One line per spec type: its name and its fields (required first, [optional] after).
struct spec_type_info {
  std::string_view type;
  std::string_view fields;
};

[[nodiscard]] inline std::span<const spec_type_info> spec_types() {
  static constexpr spec_type_info types[] = {
      {"polyline", "points [params]"},
      {"lagrange", "points [params | nodes: equispaced|chebyshev] [algorithm: barycentric|monomial]"},
      {"bezier", "points [domain]"},
      {"rational_bezier", "points weights [domain]"},
      {"composite_bezier", "segments (one point list per segment) [knots]"},
      {"conic", "points (3) w"},
      {"arc", "center radius start sweep   (2D rational quadratic, sweep in (0, pi))"},
      {"circle", "center radius [control: 9|7]   (2D quadratic NURBS)"},
      {"hermite", "points (slopes | incoming outgoing) [knots]"},
      {"cardinal", "points [s | tension] [alpha] [end: phantom|one_sided|tangents|closed] [start_tangent end_tangent] [knots]"},
      {"catmull_rom", "points [alpha] [end] [start_tangent end_tangent] [knots]   (cardinal with s = 1/2)"},
      {"kochanek_bartels", "points [tension continuity bias: number or one per key] [closed] [time_adjust] [knots]"},
      {"natural_cubic", "points [end: natural|clamped|not_a_knot|periodic] [start_slope end_slope] [knots]"},
      {"bspline", "points degree [knots | knot_vector: clamped|uniform|periodic]"},
      {"nurbs", "points weights degree [knots | knot_vector: clamped|uniform]"},
  };
  return types;
}

/// The dimension of the curve a spec describes (1..4).
[[nodiscard]] inline int spec_dimension(const field& spec) {
  const std::string type = spec.member("type").string();
  if (type == "circle" || type == "arc") return 2;
  if (type == "composite_bezier") {
    const field segs = spec.member("segments", "a composite Bezier curve is a list of segments");
    if (segs.array_size() == 0) segs.fail("expected at least one segment, got []");
    return segs.element(0).point_dimension();
  }
  const field pts = spec.member("points", "every spec of type \"" + type + "\" has points");
  if (pts.value.is_object()) {
    const std::string kind = pts.member("generate").one_of({"helix", "lissajous", "spiral", "runge"});
    return kind == "helix" ? 3 : 2;
  }
  return pts.point_dimension();
}

namespace detail {

/// Generated point sets, so that a case with 1e5 points stays a few lines of JSON:
///   {"generate": "helix", "count": n, "radius": r, "pitch": c, "turns": k}      3D
///   {"generate": "lissajous", "count": n, "a": 3, "b": 2, "turns": 1}           2D
///   {"generate": "spiral", "count": n, "turns": k}                               2D
///   {"generate": "runge", "count": n, "nodes": "equispaced" | "chebyshev"}      2D graph of 1/(1+25x^2)
/// Computed in double (std::sin/cos of the double angle) and converted exactly to Real, so every
/// precision sees the same data.
inline std::vector<std::vector<double>> generate_points(const field& g) {
  g.only_members({"generate", "count", "radius", "pitch", "turns", "a", "b", "nodes"});
  const std::string kind = g.member("generate").one_of({"helix", "lissajous", "spiral", "runge"});
  const long long count = g.member("count").integer();
  if (count < 2 || count > 10000000)
    g.member("count").fail(std::to_string(count) + " is not allowed (2 to 10000000 points)");
  const auto n = static_cast<std::size_t>(count);
  const double two_pi = 2 * boost::math::constants::pi<double>();
  const auto num = [&](std::string_view key, double fallback) { return g.has(key) ? g.member(key).number() : fallback; };
  std::vector<std::vector<double>> out(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double f = static_cast<double>(i) / static_cast<double>(n - 1);
    if (kind == "helix") {
      const double th = two_pi * num("turns", 1) * f;
      out[i] = {num("radius", 1) * std::cos(th), num("radius", 1) * std::sin(th), num("pitch", 1) * th / two_pi};
    } else if (kind == "lissajous") {
      const double th = two_pi * num("turns", 1) * f;
      out[i] = {std::sin(num("a", 3) * th + two_pi / 4), std::sin(num("b", 2) * th)};
    } else if (kind == "spiral") {
      const double th = two_pi * num("turns", 1) * f;
      out[i] = {f * std::cos(th), f * std::sin(th)};
    } else {
      const std::string nodes = g.has("nodes") ? g.member("nodes").one_of({"equispaced", "chebyshev"}) : "equispaced";
      const double x = nodes == "equispaced" ? -1 + 2 * f : -std::cos(boost::math::constants::pi<double>() * f);
      out[i] = {x, 1 / (1 + 25 * x * x)};
    }
  }
  return out;
}

/// The points of a spec: an array of points, or a generator object.
template <class Real, int Dim>
point_list<Real, Dim> spec_points(const field& spec) {
  const field f = spec.member("points");
  if (!f.value.is_object()) return f.points<Real, Dim>();
  const json generated(generate_points(f));
  return field{generated, f.path}.points<Real, Dim>();
}

inline constexpr std::string_view metadata[] = {"type", "name", "group", "reason", "quick"};

/// only_members with the metadata fields added.
inline void allow(const field& spec, std::initializer_list<std::string_view> fields) {
  std::vector<std::string_view> all(std::begin(metadata), std::end(metadata));
  all.insert(all.end(), fields.begin(), fields.end());
  spec.only_members(all, " for type \"" + spec.member("type").string() + "\"");
}

template <class Real>
std::vector<Real> knots_or_uniform(const field& spec, std::size_t count) {
  if (spec.has("knots")) return spec.member("knots").reals<Real>();
  std::vector<Real> k(count);
  for (std::size_t i = 0; i < count; ++i) k[i] = Real(static_cast<long long>(i));
  return k;
}

template <class Real>
Real real_or(const field& spec, std::string_view key, const Real& fallback) {
  return spec.has(key) ? Real(spec.member(key).number()) : fallback;
}

template <class Real, int Dim>
point<Real, Dim> one_point(const field& f) {
  const json wrapped = json::array({f.value});
  const field list{wrapped, f.path};
  const point_list<Real, Dim> p = list.points<Real, Dim>();
  return p[0];
}

/// tension/continuity/bias: absent (0), one number for every key, or one per key.
template <class Real>
std::vector<Real> per_key(const field& spec, std::string_view key, std::size_t keys) {
  if (!spec.has(key)) return std::vector<Real>(keys, Real(0));
  const field f = spec.member(key);
  if (f.value.is_number()) return std::vector<Real>(keys, Real(f.number()));
  std::vector<Real> v = f.reals<Real>();
  if (v.size() != keys)
    f.fail("expected a number or " + std::to_string(keys) + " numbers (one per key), got " + std::to_string(v.size()));
  return v;
}

template <class Real, int Dim>
any_curve<Real, Dim> build(const field& spec, const std::string& type) {
  using pl = point_list<Real, Dim>;
  const auto pts = [&] { return spec_points<Real, Dim>(spec); };
  if (type == "polyline") {
    allow(spec, {"points", "params"});
    const pl p = pts();
    if (spec.has("params")) {
      const std::vector<Real> u = spec.member("params").reals<Real>();
      return {polyline<Real, Dim>(std::span<const point<Real, Dim>>(p), std::span<const Real>(u)), type};
    }
    return {polyline<Real, Dim>(std::span<const point<Real, Dim>>(p)), type};
  }
  if (type == "lagrange") {
    allow(spec, {"points", "params", "nodes", "algorithm"});
    const pl p = pts();
    const lagrange_algorithm algorithm =
        spec.has("algorithm") && spec.member("algorithm").one_of({"barycentric", "monomial"}) == "monomial"
            ? lagrange_algorithm::monomial
            : lagrange_algorithm::barycentric;
    if (spec.has("params") && spec.has("nodes")) spec.member("params").fail("give either params or nodes");
    std::vector<Real> u;
    if (spec.has("params")) {
      u = spec.member("params").reals<Real>();
    } else if (spec.has("nodes") && spec.member("nodes").one_of({"equispaced", "chebyshev"}) == "chebyshev") {
      u = chebyshev_parameters<Real>(p.size());
    } else {
      u = equispaced_parameters<Real>(p.size());
    }
    return {lagrange<Real, Dim>(std::span<const point<Real, Dim>>(p), std::span<const Real>(u), algorithm), type};
  }
  if (type == "composite_bezier") {
    allow(spec, {"segments", "knots"});
    const field segs = spec.member("segments");
    std::vector<pl> segments(segs.array_size());
    for (std::size_t i = 0; i < segments.size(); ++i) segments[i] = segs.element(i).points<Real, Dim>();
    const std::vector<Real> k = knots_or_uniform<Real>(spec, segments.size() + 1);
    return {composite_bezier<Real, Dim>(std::span<const pl>(segments), std::span<const Real>(k)), type};
  }
  if (type == "bezier" || type == "rational_bezier") {
    const bool rational = type == "rational_bezier";
    if (rational)
      allow(spec, {"points", "weights", "domain"});
    else
      allow(spec, {"points", "domain"});
    const pl p = pts();
    interval<Real> dom{Real(0), Real(1)};
    if (spec.has("domain")) {
      const std::vector<Real> d = spec.member("domain").reals<Real>();
      if (d.size() != 2) spec.member("domain").fail("expected [lo, hi], got " + spec.member("domain").shown());
      dom = {d[0], d[1]};
    }
    if (!rational) return {bezier<Real, Dim>(std::span<const point<Real, Dim>>(p), dom), type};
    const std::vector<Real> w = spec.member("weights", "a rational Bezier curve has one weight per point").reals<Real>();
    return {rational_bezier<Real, Dim>(std::span<const point<Real, Dim>>(p), std::span<const Real>(w), dom), type};
  }
  if (type == "conic") {
    allow(spec, {"points", "w"});
    const pl p = pts();
    if (p.size() != 3) spec.member("points").fail("a conic has exactly 3 points, got " + std::to_string(p.size()));
    return {conic<Real, Dim>(p[0], p[1], p[2], Real(spec.member("w").number())), type};
  }
  if (type == "hermite") {
    allow(spec, {"points", "slopes", "incoming", "outgoing", "knots"});
    const pl p = pts();
    std::vector<Real> k = knots_or_uniform<Real>(spec, p.size());
    if (spec.has("slopes")) {
      if (spec.has("incoming") || spec.has("outgoing"))
        spec.member("slopes").fail("give either slopes or incoming and outgoing, not both");
      return {hermite_spline<Real, Dim>(std::move(k), p, spec.member("slopes").points<Real, Dim>()), type};
    }
    pl in = spec.member("incoming", "give slopes, or incoming and outgoing").points<Real, Dim>();
    pl out = spec.member("outgoing", "give slopes, or incoming and outgoing").points<Real, Dim>();
    return {hermite_spline<Real, Dim>(std::move(k), p, std::move(in), std::move(out)), type};
  }
  if (type == "cardinal" || type == "catmull_rom") {
    if (type == "cardinal")
      allow(spec, {"points", "s", "tension", "alpha", "end", "start_tangent", "end_tangent", "knots"});
    else
      allow(spec, {"points", "alpha", "end", "start_tangent", "end_tangent", "knots"});
    const pl p = pts();
    cardinal_options<Real, Dim> opt;
    if (spec.has("s") && spec.has("tension")) spec.member("s").fail("give either s or tension (s = (1 - tension)/2)");
    if (spec.has("s")) opt.s = Real(spec.member("s").number());
    if (spec.has("tension")) opt.s = (Real(1) - Real(spec.member("tension").number())) / Real(2);
    opt.alpha = real_or<Real>(spec, "alpha", Real(0));
    if (spec.has("end")) {
      const std::string e = spec.member("end").one_of({"phantom", "one_sided", "tangents", "closed"});
      opt.end = e == "phantom"     ? cardinal_end::phantom
                : e == "one_sided" ? cardinal_end::one_sided
                : e == "tangents"  ? cardinal_end::given_tangents
                                   : cardinal_end::closed;
    }
    if (opt.end == cardinal_end::given_tangents) {
      opt.start_tangent = one_point<Real, Dim>(spec.member("start_tangent", "end is \"tangents\""));
      opt.end_tangent = one_point<Real, Dim>(spec.member("end_tangent", "end is \"tangents\""));
    }
    if (spec.has("knots")) return {cardinal_spline<Real, Dim>(spec.member("knots").reals<Real>(), p, opt), type};
    return {cardinal_spline<Real, Dim>(p, opt), type};
  }
  if (type == "kochanek_bartels") {
    allow(spec, {"points", "tension", "continuity", "bias", "closed", "time_adjust", "knots"});
    const pl p = pts();
    const std::vector<Real> t = per_key<Real>(spec, "tension", p.size());
    const std::vector<Real> c = per_key<Real>(spec, "continuity", p.size());
    const std::vector<Real> b = per_key<Real>(spec, "bias", p.size());
    std::vector<tcb<Real>> keys(p.size());
    for (std::size_t i = 0; i < p.size(); ++i) keys[i] = {t[i], c[i], b[i]};
    typename kochanek_bartels<Real, Dim>::options opt;
    if (spec.has("closed")) opt.closed = spec.member("closed").boolean();
    if (spec.has("time_adjust")) opt.time_adjust = spec.member("time_adjust").boolean();
    if (spec.has("knots")) return {kochanek_bartels<Real, Dim>(spec.member("knots").reals<Real>(), p, keys, opt), type};
    return {kochanek_bartels<Real, Dim>(p, keys, opt), type};
  }
  if (type == "natural_cubic") {
    allow(spec, {"points", "end", "start_slope", "end_slope", "knots"});
    const pl p = pts();
    const std::vector<Real> k = knots_or_uniform<Real>(spec, p.size());
    const std::string e =
        spec.has("end") ? spec.member("end").one_of({"natural", "clamped", "not_a_knot", "periodic"}) : "natural";
    if (e == "clamped") {
      const point<Real, Dim> start = one_point<Real, Dim>(spec.member("start_slope", "end is \"clamped\""));
      const point<Real, Dim> end = one_point<Real, Dim>(spec.member("end_slope", "end is \"clamped\""));
      return {natural_cubic_spline<Real, Dim>(k, p, start, end), type};
    }
    const spline_end end = e == "natural" ? spline_end::natural : e == "not_a_knot" ? spline_end::not_a_knot
                                                                                    : spline_end::periodic;
    return {natural_cubic_spline<Real, Dim>(k, p, end), type};
  }
  if (type == "bspline" || type == "nurbs") {
    const bool rational = type == "nurbs";
    if (rational)
      allow(spec, {"points", "weights", "degree", "knots", "knot_vector"});
    else
      allow(spec, {"points", "degree", "knots", "knot_vector"});
    const pl p = pts();
    const long long degree = spec.member("degree", "the polynomial degree of the pieces").integer();
    if (degree < 0 || degree >= bspline_max_order)
      spec.member("degree").fail(std::to_string(degree) + " is not allowed (0 to " +
                                 std::to_string(bspline_max_order - 1) + ")");
    const int order = static_cast<int>(degree) + 1;
    if (spec.has("knots") && spec.has("knot_vector")) spec.member("knots").fail("give either knots or knot_vector");
    std::string kind = "clamped";
    if (spec.has("knot_vector"))
      kind = rational ? spec.member("knot_vector").one_of({"clamped", "uniform"})
                      : spec.member("knot_vector").one_of({"clamped", "uniform", "periodic"});
    if (!rational && kind == "periodic") return {periodic_bspline<Real, Dim>(order, std::span<const point<Real, Dim>>(p)), type};
    std::vector<Real> k = spec.has("knots")     ? spec.member("knots").reals<Real>()
                          : kind == "uniform" ? bspline_uniform_knots<Real>(p.size(), order)
                                              : bspline_clamped_knots<Real>(p.size(), order);
    if (!rational) return {bspline<Real, Dim>(order, std::move(k), p), type};
    return {nurbs<Real, Dim>(order, std::move(k), p,
                             spec.member("weights", "a NURBS curve has one weight per point").reals<Real>()),
            type};
  }
  if constexpr (Dim == 2) {
    if (type == "circle") {
      allow(spec, {"center", "radius", "control"});
      const point<Real, 2> c = one_point<Real, 2>(spec.member("center"));
      const Real r(spec.member("radius").number());
      const long long control = spec.has("control") ? spec.member("control").integer() : 9;
      if (control != 9 && control != 7) spec.member("control").fail(std::to_string(control) + " is not allowed (9 or 7 control points)");
      return {control == 9 ? nurbs_circle_9<Real>(c, r) : nurbs_circle_7<Real>(c, r), type};
    }
    if (type == "arc") {
      allow(spec, {"center", "radius", "start", "sweep"});
      const point<Real, 2> c = one_point<Real, 2>(spec.member("center"));
      const Real r(spec.member("radius").number());
      const Real start(spec.member("start").number());
      const Real sweep(spec.member("sweep").number());
      return {circular_arc<Real>(c, r, start, sweep), type};
    }
  }
  std::string list;
  for (const auto& t : spec_types()) list += (list.empty() ? "" : ", ") + std::string(t.type);
  spec.member("type").fail("\"" + type + "\" is not a curve type (types: " + list + ")");
}

template <int Dim>
json points_json(std::span<const point<double, Dim>> ps) {
  json a = json::array();
  for (const auto& p : ps) {
    json q = json::array();
    for (int d = 0; d < Dim; ++d) q.push_back(p[d]);
    a.push_back(std::move(q));
  }
  return a;
}

/// The spec with every derived quantity computed once, in double, and written out as data:
/// generated points, alpha (centripetal/chordal) knots, s from tension, Lagrange parameters,
/// clamped/uniform B-spline knots, and the control data of circles and arcs. Building any Real
/// from the resolved spec then gives the exact twin of the double curve (same knots, same
/// control data), which is what a 50-digit reference must be: computing e.g. |dP|^(1/2) again in
/// 50 digits would give a different curve, with a different domain, by an ulp.
template <int Dim>
json resolve(const field& spec, const std::string& type) {
  json r = spec.value;
  if (spec.has("points") && spec.member("points").value.is_object())
    r["points"] = points_json<Dim>(spec_points<double, Dim>(spec));
  const field rf{r, spec.path};
  if ((type == "cardinal" || type == "catmull_rom") && !rf.has("knots") && rf.has("alpha")) {
    const double alpha = rf.member("alpha").number();
    if (alpha != 0) {
      const bool closed = rf.has("end") && rf.member("end").string() == "closed";
      const point_list<double, Dim> p = rf.member("points").points<double, Dim>();
      const std::vector<double> k = alpha_knots<double, Dim>(std::span<const point<double, Dim>>(p), alpha, closed);
      r["knots"] = k;
      r["alpha"] = 0;
    }
  }
  if (type == "cardinal" && rf.has("tension") && !rf.has("s")) {
    r["s"] = (1 - rf.member("tension").number()) / 2;
    r.erase("tension");
  }
  if (type == "lagrange" && !rf.has("params")) {
    const std::size_t n = rf.member("points").array_size();
    const bool cheb = rf.has("nodes") && rf.member("nodes").one_of({"equispaced", "chebyshev"}) == "chebyshev";
    r["params"] = cheb ? chebyshev_parameters<double>(n) : equispaced_parameters<double>(n);
    r.erase("nodes");
  }
  if ((type == "bspline" || type == "nurbs") && !rf.has("knots") && rf.has("degree") && rf.member("degree").value.is_number_integer()) {
    const std::string kind = rf.has("knot_vector") ? rf.member("knot_vector").string() : "clamped";
    const long long degree = rf.member("degree").integer();
    if ((kind == "clamped" || kind == "uniform") && degree >= 0 && degree < bspline_max_order) {
      const std::size_t n = rf.member("points").array_size();
      const int order = static_cast<int>(degree) + 1;
      r["knots"] = kind == "uniform" ? bspline_uniform_knots<double>(n, order) : bspline_clamped_knots<double>(n, order);
      r.erase("knot_vector");
    }
  }
  if constexpr (Dim == 2) {
    if (type == "circle" || type == "arc") {
      // Built once in double by the library's own constructors; the spec becomes their data.
      const any_curve<double, 2> c = build<double, 2>(rf, type);
      if (const auto* n = c.template target<nurbs<double, 2>>()) {
        return {{"type", "nurbs"}, {"degree", n->degree()}, {"points", points_json<2>(n->control_points())},
                {"weights", std::vector<double>(n->weights().begin(), n->weights().end())},
                {"knots", std::vector<double>(n->knots().begin(), n->knots().end())}};
      }
      if (const auto* b = c.template target<rational_bezier<double, 2>>()) {
        return {{"type", "rational_bezier"}, {"points", points_json<2>(b->control_points())},
                {"weights", std::vector<double>(b->weights().begin(), b->weights().end())}};
      }
    }
  }
  return r;
}

}  // namespace detail

/// The curve a spec describes, in Real and Dim (Dim must equal spec_dimension(spec)).
template <class Real, int Dim>
[[nodiscard]] any_curve<Real, Dim> curve_from_spec(const field& spec) {
  const std::string type = spec.member("type").string();
  const int dim = spec_dimension(spec);
  if (dim != Dim)
    spec.fail("describes a " + std::to_string(dim) + "D curve, but a " + std::to_string(Dim) + "D one was asked for");
  try {
    // Derived data is computed once in double, then every precision builds from the same data.
    const json resolved = detail::resolve<Dim>(spec, type);
    const field r{resolved, spec.path};
    const std::string resolved_type = r.member("type").string();
    any_curve<Real, Dim> c = detail::build<Real, Dim>(r, resolved_type);
    if (resolved_type == type) return c;
    return c.renamed(type);  // keep the family name the user gave ("circle", "arc")
  } catch (const spec_error&) {
    throw;
  } catch (const invalid_input& e) {  // a family's own validation: say which spec it came from
    throw spec_error(spec.path + " (type \"" + type + "\"): " + e.what());
  }
}

}  // namespace curvebench::io
