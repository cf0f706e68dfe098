// Registry entry "channel" (see io/family.hpp): a keyframe channel, a value over time, as one
// animation tool evaluates it (channel/channel.hpp). The "tool" field chooses the rules applied to
// the keys and names the tool's own fields:
//   exact  keys with per-side handles and the interpolation of each segment, extrapolation before
//          and after, and the time solver (default exact: the inversion solved to the precision of
//          the evaluation);
//   css    one CSS easing function ("easing": "cubic-bezier(x1, y1, x2, y2)", "steps(n, jump-end)",
//          "linear(0, 0.25 75%, 1)", or a keyword) on progress [0, 1]: cubic-bezier is one bezier
//          segment from (0, 0) to (1, 1); steps() constant segments whose values follow the
//          specification's step algorithm; linear() linear segments through the stops (a jump,
//          two stops at one input, is refused). Time solver default table_newton (the WebKit /
//          Chromium scheme). Outside [0, 1] the value holds (constant extrapolation);
//   maya   a Maya animCurve (channel/maya.hpp): keys with in/out tangent types and fixed tangent
//          vectors, weighted or not, pre and post infinity; solver default isolate_brent;
//   gltf   a scalar glTF 2.0 sampler ("interpolation": step, linear or cubicspline, "times" and
//          "values" as glTF stores them: one value per key, or in-tangent, value, out-tangent per
//          key for cubicspline), clamped outside the keys (channel/gltf.hpp has the sampler itself).
// The spec's curve is the channel's planar curve P(u) = (t(u), v(u)) (2D; segment i on [i, i + 1]),
// so arc length and the accuracy sweep apply; `curvebench sample SPEC --at T1,T2` and `--frames
// A:B:STEP` evaluate the value at times through channel_of_spec. Keys in a spec:
//   {"time": 0, "value": 1, "interpolation": "bezier", "in": [-0.5, 0], "out": [0.5, 0.2]}
// with in/out the handle offsets (dt, dv) from the key (default [0, 0]), interpolation one of
// constant, step_next, linear, bezier, hermite (default bezier; the last key's is unused).
#pragma once

#include "curvebench/channel/channel.hpp"
#include "curvebench/channel/css_easing.hpp"
#include "curvebench/channel/gltf.hpp"
#include "curvebench/channel/maya.hpp"
#include "curvebench/io/family.hpp"

#include <algorithm>
#include <functional>
#include <string>
#include <vector>

namespace curvebench::io {

namespace detail {

template <class Real>
channel::handle<Real> handle_of(const field& key, std::string_view side) {
  if (!key.has(side)) return {Real(0), Real(0)};
  const field h = key.member(side);
  const std::vector<Real> v = h.reals<Real>();
  if (v.size() != 2) h.fail("expected [dt, dv], two numbers, got " + std::to_string(v.size()));
  return {v[0], v[1]};
}

template <class Real>
std::vector<channel::key<Real>> channel_keys(const field& spec) {
  const field keys = spec.member("keys", "tool \"exact\" takes keys");
  const std::size_t n = keys.array_size();
  std::vector<channel::key<Real>> out;
  out.reserve(n);
  for (std::size_t i = 0; i < n; ++i) {
    const field k = keys.element(i);
    static constexpr std::string_view key_fields[] = {"time", "value", "interpolation", "in", "out"};
    k.only_members(key_fields, " in a channel key");
    channel::key<Real> key;
    key.time = Real(k.member("time").number());
    key.value = Real(k.member("value").number());
    key.in = handle_of<Real>(k, "in");
    key.out = handle_of<Real>(k, "out");
    key.interp = k.has("interpolation")
                     ? channel::from_string<channel::interpolation>(
                           k.member("interpolation").one_of({"constant", "step_next", "linear", "bezier", "hermite"}))
                     : channel::interpolation::bezier;
    out.push_back(key);
  }
  return out;
}

inline channel::extrapolation extrapolation_of(const field& spec, std::string_view side) {
  if (!spec.has(side)) return channel::extrapolation::constant;
  return channel::from_string<channel::extrapolation>(
      spec.member(side).one_of({"constant", "linear", "cycle", "cycle_offset", "oscillate"}));
}

inline channel::time_solver solver_of(const field& spec, channel::time_solver fallback) {
  if (!spec.has("solver")) return fallback;
  const field f = spec.member("solver");
  const std::string id = f.string();
  for (channel::time_solver s : channel::all_time_solvers)
    if (channel::to_string(s) == id) return s;
  std::string list;
  for (channel::time_solver s : channel::all_time_solvers) list += (list.empty() ? "" : ", ") + std::string(to_string(s));
  f.fail("not a time solver: one of " + list);
  return fallback;
}

// The keys of a CSS easing (see the header).
template <class Real>
std::vector<channel::key<Real>> css_keys(const field& spec) {
  const field e = spec.member("easing", "tool \"css\" takes an easing");
  const channel::css_easing<double> f = [&] {
    try {
      return channel::parse_css_easing<double>(e.string());
    } catch (const invalid_input& x) {
      e.fail(x.what());
    }
  }();
  std::vector<channel::key<Real>> keys;
  using K = channel::css_easing<double>::kind;
  if (f.type() == K::cubic_bezier) {
    const auto& p = f.control();  // x1, y1, x2, y2
    keys.push_back({Real(0), Real(0), {}, {Real(p[0]), Real(p[1])}, channel::interpolation::bezier});
    keys.push_back({Real(1), Real(1), {Real(p[2]) - Real(1), Real(p[3]) - Real(1)}, {}, channel::interpolation::bezier});
  } else if (f.type() == K::steps) {
    // CSS Easing 1, the step algorithm at x = k / n: floor(n x) = k steps, one more with a jump at
    // the start, the output that over the jumps (n, n - 1 without jumps at the ends, n + 1 with both),
    // at most 1. The value holds until the next step: constant segments, right-continuous like CSS.
    const long long n = f.step_count();
    const channel::step_position pos = f.position();
    const bool start = pos == channel::step_position::jump_start || pos == channel::step_position::jump_both;
    const long long jumps = pos == channel::step_position::jump_none ? n - 1 : pos == channel::step_position::jump_both ? n + 1 : n;
    for (long long k = 0; k <= n; ++k) {
      const long long step = std::min(k + (start ? 1 : 0), jumps);
      keys.push_back({Real(k) / Real(n), Real(step) / Real(jumps), {}, {}, channel::interpolation::constant});
    }
  } else {
    const auto pts = f.points();
    for (std::size_t i = 0; i < pts.size(); ++i) {
      if (i > 0 && !(pts[i].input > pts[i - 1].input))
        e.fail("stops " + std::to_string(i - 1) + " and " + std::to_string(i) + " share the input " +
               to_text(pts[i].input) + ": a jump, which a channel (one value per time) does not hold");
      keys.push_back({Real(pts[i].input), Real(pts[i].output), {}, {}, channel::interpolation::linear});
    }
  }
  return keys;
}

// The keys of a scalar glTF sampler (see the header).
template <class Real>
std::vector<channel::key<Real>> gltf_keys(const field& spec) {
  const std::string mode = spec.member("interpolation", "tool \"gltf\" takes an interpolation")
                                .one_of({"step", "linear", "cubicspline"});
  const std::vector<Real> t = spec.member("times", "tool \"gltf\" takes times").reals<Real>();
  const field vf = spec.member("values", "tool \"gltf\" takes values");
  const std::vector<Real> v = vf.reals<Real>();
  // The sampler validates the counts, times and values as glTF does (in double).
  const std::vector<double> td = spec.member("times").reals<double>(), vd = vf.reals<double>();
  (void)channel::gltf::sampler<double, 1>(td, std::span<const double>(vd), channel::gltf::from_string<channel::gltf::interpolation>(mode));
  std::vector<channel::key<Real>> keys;
  for (std::size_t k = 0; k < t.size(); ++k) {
    channel::key<Real> key;
    key.time = t[k];
    if (mode == "cubicspline") {
      // glTF's tangents are slopes per unit time (the spec multiplies them by the key interval).
      key.value = v[3 * k + 1];
      key.in = {Real(-1), -v[3 * k]};
      key.out = {Real(1), v[3 * k + 2]};
      key.interp = channel::interpolation::hermite;
    } else {
      key.value = v[k];
      key.interp = mode == "step" ? channel::interpolation::constant : channel::interpolation::linear;
    }
    keys.push_back(key);
  }
  return keys;
}

// The keys of a Maya animCurve (channel/maya.hpp): tangent types per side and, for fixed
// tangents, the tangent vectors (x, y), x > 0.
template <class Real>
channel::maya_curve<Real> maya_curve_of(const field& spec) {
  channel::maya_curve<Real> c;
  const field keys = spec.member("keys", "tool \"maya\" takes keys");
  static constexpr std::string_view tangents[] = {"fixed",  "linear", "flat",    "step", "step_next",
                                                  "spline", "clamped", "plateau", "auto"};
  auto tangent = [&](const field& k, std::string_view side) {
    if (!k.has(side)) return channel::maya_tangent::spline;
    const field f = k.member(side);
    const std::string name = f.string();
    if (std::find(std::begin(tangents), std::end(tangents), name) == std::end(tangents))
      f.fail("not a Maya tangent type: fixed, linear, flat, step, step_next, spline, clamped, plateau or auto");
    return channel::from_string<channel::maya_tangent>(name);
  };
  for (std::size_t i = 0; i < keys.array_size(); ++i) {
    const field k = keys.element(i);
    static constexpr std::string_view key_fields[] = {"time", "value", "in_type", "out_type", "in", "out"};
    k.only_members(key_fields, " in a Maya key");
    channel::maya_key<Real> key;
    key.time = Real(k.member("time").number());
    key.value = Real(k.member("value").number());
    key.in_type = tangent(k, "in_type");
    key.out_type = tangent(k, "out_type");
    const channel::handle<Real> in = handle_of<Real>(k, "in"), out = handle_of<Real>(k, "out");
    if (k.has("in")) key.in_x = in.dt, key.in_y = in.dv;
    if (k.has("out")) key.out_x = out.dt, key.out_y = out.dv;
    c.keys.push_back(key);
  }
  if (spec.has("weighted")) c.weighted = spec.member("weighted").boolean();
  auto infinity = [&](std::string_view side) {
    if (!spec.has(side)) return channel::maya_infinity::constant;
    return channel::from_string<channel::maya_infinity>(
        spec.member(side).one_of({"constant", "linear", "cycle", "cycle_relative", "oscillate"}));
  };
  c.pre = infinity("pre");
  c.post = infinity("post");
  return c;
}

}  // namespace detail

/// A channel spec under its tool's rules: the channel whose curve() is the spec's curve, and the
/// value and time derivatives (orders 0 to 2) at a time as the tool evaluates them (for most tools
/// the channel's own; Maya's linear infinity follows its end tangents, channel/maya.hpp).
template <class Real>
struct channel_model {
  channel::channel<Real> source;
  std::function<Real(const Real&, int)> at;
};

template <class Real>
channel_model<Real> channel_model_of_spec(const field& spec);

/// The channel a "channel" spec describes, under its tool's rules, in Real (see the header).
template <class Real>
channel::channel<Real> channel_of_spec(const field& spec) {
  return channel_model_of_spec<Real>(spec).source;
}

namespace detail {

template <class Real>
channel::channel<Real> plain_channel_of_spec(const field& spec, const std::string& tool) {
  if (tool == "exact")
    return channel::channel<Real>(detail::channel_keys<Real>(spec), detail::extrapolation_of(spec, "before"),
                                  detail::extrapolation_of(spec, "after"),
                                  detail::solver_of(spec, channel::time_solver::exact));
  if (tool == "css")
    return channel::channel<Real>(detail::css_keys<Real>(spec), channel::extrapolation::constant,
                                  channel::extrapolation::constant,
                                  detail::solver_of(spec, channel::time_solver::table_newton));
  return channel::channel<Real>(detail::gltf_keys<Real>(spec), channel::extrapolation::constant,
                                channel::extrapolation::constant,
                                detail::solver_of(spec, channel::time_solver::exact));
}

}  // namespace detail

template <class Real>
channel_model<Real> channel_model_of_spec(const field& spec) {
  const std::string tool =
      spec.member("tool", "a channel names the tool whose rules evaluate it").one_of({"exact", "css", "gltf", "maya"});
  if (tool == "maya") {
    const channel::maya_evaluator<Real> m(detail::maya_curve_of<Real>(spec),
                                          detail::solver_of(spec, channel::time_solver::isolate_brent));
    return {m.underlying(), [m](const Real& t, int order) { return m.derivative(t, order); }};
  }
  const channel::channel<Real> c = detail::plain_channel_of_spec<Real>(spec, tool);
  return {c, [c](const Real& t, int order) { return c.derivative(t, order); }};
}

struct channel_family : family_defaults {
  static constexpr std::string_view name = "channel";
  static constexpr std::string_view summary =
      "a keyframe channel (value over time) under one tool's rules, as the planar curve (t(u), v(u))";
  static constexpr field_doc fields[] = {
      {"tool", "whose rules evaluate the keys: exact, css, gltf or maya", presence::required},
      {"keys", "exact: [{time, value, interpolation, in: [dt, dv], out: [dt, dv]}, ...] in time order; maya: "
               "[{time, value, in_type, out_type, in: [x, y], out: [x, y]}, ...] (tangent types fixed, linear, flat, "
               "step, step_next, spline, clamped, plateau, auto; in/out the fixed tangent vectors, x > 0)"},
      {"weighted", "maya: weighted tangents (bezier segments) or not (hermite)"},
      {"pre", "maya: pre infinity: constant, linear, cycle, cycle_relative, oscillate"},
      {"post", "maya: post infinity (the same names)"},
      {"before", "exact: extrapolation before the first key: constant, linear, cycle, cycle_offset, oscillate"},
      {"after", "exact: extrapolation after the last key (the same names)"},
      {"solver", "the time solver of bezier segments (closed_form, table_newton, newton_bisection, bisection12, "
                 "bisection30, isolate_brent, curvebench, exact)"},
      {"easing", "css: cubic-bezier(x1, y1, x2, y2), steps(n, jump-start|jump-end|jump-none|jump-both), "
                 "linear(...) or a keyword"},
      {"interpolation", "gltf: step, linear or cubicspline"},
      {"times", "gltf: the key times (the sampler's input)"},
      {"values", "gltf: the sampler's output (cubicspline: in-tangent, value, out-tangent per key)"},
  };
  static constexpr std::string_view examples[] = {
      R"({"type": "channel", "tool": "exact", "keys": [{"time": 0, "value": 0, "out": [0.5, 0]}, {"time": 2, "value": 1, "in": [-0.5, 0.4]}], "after": "cycle_offset"})",
      R"j({"type": "channel", "tool": "css", "easing": "cubic-bezier(0.25, 0.1, 0.25, 1)"})j",
      R"({"type": "channel", "tool": "gltf", "interpolation": "cubicspline", "times": [0, 1, 3], "values": [0, 0, 1, 1, 2, 0, 0, 1, 0]})",
      R"({"type": "channel", "tool": "maya", "keys": [{"time": 0, "value": 0}, {"time": 10, "value": 4, "in_type": "clamped", "out_type": "clamped"}, {"time": 20, "value": 4}], "post": "oscillate"})",
  };

  static int dimension(const field&) { return 2; }

  template <class Real, int Dim>
  static any_curve<Real, Dim> build(const field& spec) {
    if constexpr (Dim == 2) {
      return any_curve<Real, 2>(channel_of_spec<Real>(spec).curve(), std::string(name));
    } else {
      spec.fail("a channel is the planar curve (t(u), v(u)), 2D; a " + std::to_string(Dim) + "D curve was asked for");
    }
  }
};

}  // namespace curvebench::io
