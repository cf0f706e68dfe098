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
//   gltf   a glTF 2.0 sampler ("interpolation": step, linear or cubicspline, "times" and
//          "values" as glTF stores them: one value per key, or in-tangent, value, out-tangent per
//          key for cubicspline), clamped outside the keys (channel/gltf.hpp has the sampler itself).
//          "path": "weights" (the default: a scalar channel, one morph weight) or "rotation": the
//          values are unit quaternions x y z w, four numbers each, interpolated by "blend": slerp
//          (the default, the spec's) or nlerp for linear, normalized Hermite for cubicspline. A
//          rotation's value is a quaternion, not a number over time: rotation_of_spec gives the
//          sampler, `curvebench sample SPEC --at` prints t, x, y, z, w, and the curve view and
//          channel_model_of_spec refuse it naming the path;
//   blender  a Blender F-curve (channel/blender.hpp): keys with absolute handle_left / handle_right,
//          handle types, interpolation (constant, linear, bezier or a Penner family) with easing
//          and back / amplitude / period; extrapolation constant or linear, auto-handle smoothing,
//          the Cycles modifier; evaluated in the precision asked (float is Blender's own), solver
//          default exact. An eased segment has no curve view (the planar curve is refused naming
//          the key; `sample --at` evaluates it);
//   usd    an OpenUSD Ts spline (channel/usd.hpp): knots with interpolation held / linear / curve,
//          pre / post tangent width and slope, a pre_value for a dual-valued knot; curve_type,
//          anti_regression, extrapolation before / after with USD's mode names and slopes, inner
//          loops; solver default closed_form (USD's). A dual-valued knot has no curve view.
// The spec's curve is the channel's planar curve P(u) = (t(u), v(u)) (2D; segment i on [i, i + 1]),
// so arc length and the accuracy sweep apply; `curvebench sample SPEC --at T1,T2` and `--frames
// A:B:STEP` evaluate the value at times through channel_of_spec. Keys in a spec:
//   {"time": 0, "value": 1, "interpolation": "bezier", "in": [-0.5, 0], "out": [0.5, 0.2]}
// with in/out the handle offsets (dt, dv) from the key (default [0, 0]), interpolation one of
// constant, step_next, linear, bezier, hermite (default bezier; the last key's is unused).
#pragma once

#include "curvebench/channel/blender.hpp"
#include "curvebench/channel/channel.hpp"
#include "curvebench/channel/css_easing.hpp"
#include "curvebench/channel/gltf.hpp"
#include "curvebench/channel/maya.hpp"
#include "curvebench/channel/usd.hpp"
#include "curvebench/io/family.hpp"

#include <algorithm>
#include <cmath>
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

// Generated keys, so that a channel of 1e5 keys stays a few lines of JSON:
//   {"generate": "wave", "count": n, "start": t0, "step": h}
// n keys at t0 + i h (defaults 0 and 1) with values sin(0.37 i) + sin(1.91 i) / 2 (a bounded,
// never periodic wiggle), bezier segments whose handles follow the Catmull-Rom slope
// (v_{i+1} - v_{i-1}) / 2h (one-sided at the ends) with time lengths 0.25 h and 0.45 h alternating
// per key (a + c <= 0.9: every segment monotone in time). Computed in double and converted exactly
// to Real, so every precision sees the same keys.
inline nlohmann::json generate_keys(const field& g) {
  static constexpr std::string_view fields[] = {"generate", "count", "start", "step"};
  g.only_members(fields, " in a key generator");
  (void)g.member("generate").one_of({"wave"});
  const long long count = g.member("count").integer();
  if (count < 2 || count > static_cast<long long>(max_generated_points))
    g.member("count").fail(std::to_string(count) + " is not allowed (2 to " + std::to_string(max_generated_points) +
                           " keys)");
  const double t0 = g.has("start") ? g.member("start").number() : 0, h = g.has("step") ? g.member("step").number() : 1;
  if (!std::isfinite(t0)) g.member("start").fail("must be finite");
  if (!(h > 0) || !std::isfinite(h)) g.member("step").fail("must be finite and > 0");
  const auto n = static_cast<std::size_t>(count);
  std::vector<double> v(n);
  for (std::size_t i = 0; i < n; ++i) v[i] = std::sin(0.37 * static_cast<double>(i)) + std::sin(1.91 * static_cast<double>(i)) / 2;
  nlohmann::json keys = nlohmann::json::array();
  for (std::size_t i = 0; i < n; ++i) {
    const double m = i == 0 ? (v[1] - v[0]) / h : i + 1 == n ? (v[i] - v[i - 1]) / h : (v[i + 1] - v[i - 1]) / (2 * h);
    const double a = (i % 2 == 0 ? 0.25 : 0.45) * h, c = (i % 2 == 0 ? 0.45 : 0.25) * h;
    keys.push_back({{"time", t0 + static_cast<double>(i) * h},
                    {"value", v[i]},
                    {"interpolation", "bezier"},
                    {"in", {-c, -c * m}},
                    {"out", {a, a * m}}});
  }
  return keys;
}

template <class Real>
std::vector<channel::key<Real>> channel_keys(const field& spec) {
  const field given = spec.member("keys", "tool \"exact\" takes keys");
  const nlohmann::json generated = given.value.is_object() ? generate_keys(given) : nlohmann::json();
  const field keys = given.value.is_object() ? field{generated, given.path} : given;
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

// A gltf spec's "path": weights (scalar, the default) or rotation.
inline bool is_gltf_rotation(const field& spec) {
  if (!spec.has("tool") || spec.member("tool").string() != "gltf" || !spec.has("path")) return false;
  return spec.member("path").one_of({"weights", "rotation"}) == "rotation";
}

// The refusal of a scalar view (the channel, its curve) of a rotation spec.
[[noreturn]] inline void refuse_rotation(const field& spec, std::string_view what) {
  spec.member("path").fail("a rotation channel's value is a unit quaternion, so it has no " + std::string(what) +
                           "; `curvebench sample SPEC --at T1,T2` evaluates it (t, x, y, z, w)");
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

// The Blender F-curve of a "blender" spec (see the header): handle types per side, the
// interpolation of the segment starting at each key with its easing, extrapolation, smoothing
// and the Cycles modifier.
template <class Real>
channel::blender_fcurve<Real> blender_fcurve_of(const field& spec) {
  channel::blender_fcurve<Real> c;
  const field keys = spec.member("keys", "tool \"blender\" takes keys");
  auto point_of = [](const field& k, std::string_view side, const Real& t, const Real& v) {
    if (!k.has(side)) return channel::blender_point<Real>{t, v};
    const field f = k.member(side);
    const std::vector<Real> p = f.reals<Real>();
    if (p.size() != 2) f.fail("expected [frame, value], two numbers, got " + std::to_string(p.size()));
    return channel::blender_point<Real>{p[0], p[1]};
  };
  auto handle = [](const field& k, std::string_view side) {
    if (!k.has(side)) return channel::handle_type::auto_clamped;
    const std::string h = k.member(side).one_of({"free", "aligned", "vector", "auto", "auto_clamped"});
    for (channel::handle_type t : {channel::handle_type::free, channel::handle_type::aligned, channel::handle_type::vector,
                                   channel::handle_type::automatic, channel::handle_type::auto_clamped})
      if (h == channel::to_string(t)) return t;
    return channel::handle_type::auto_clamped;
  };
  for (std::size_t i = 0; i < keys.array_size(); ++i) {
    const field k = keys.element(i);
    static constexpr std::string_view key_fields[] = {"time",          "value",    "handle_left", "handle_right",
                                                      "handle_left_type", "handle_right_type", "interpolation",
                                                      "easing",        "back",     "amplitude",   "period"};
    k.only_members(key_fields, " in a Blender key");
    channel::blender_key<Real> b;
    b.time = Real(k.member("time").number());
    b.value = Real(k.member("value").number());
    b.handle_left = point_of(k, "handle_left", b.time, b.value);
    b.handle_right = point_of(k, "handle_right", b.time, b.value);
    b.handle_left_type = handle(k, "handle_left_type");
    b.handle_right_type = handle(k, "handle_right_type");
    if (k.has("interpolation")) {
      const std::string name = k.member("interpolation").one_of({"constant", "linear", "bezier", "sine", "quad", "cubic",
                                                                 "quart", "quint", "expo", "circ", "back", "bounce",
                                                                 "elastic"});
      for (int j = 0; j <= static_cast<int>(channel::blender_interpolation::elastic); ++j)
        if (name == channel::to_string(static_cast<channel::blender_interpolation>(j)))
          b.interpolation = static_cast<channel::blender_interpolation>(j);
    }
    if (k.has("easing")) {
      const std::string e = k.member("easing").one_of({"auto", "in", "out", "in_out"});
      b.easing = e == "auto" ? channel::ease_mode::automatic : channel::ease_mode_from_string(e);
    }
    if (k.has("back")) b.params.back = Real(k.member("back").number());
    if (k.has("amplitude")) b.params.amplitude = Real(k.member("amplitude").number());
    if (k.has("period")) b.params.period = Real(k.member("period").number());
    c.keys.push_back(b);
  }
  if (spec.has("extrapolation"))
    c.extrapolation = spec.member("extrapolation").one_of({"constant", "linear"}) == "linear"
                          ? channel::blender_extrapolation::linear
                          : channel::blender_extrapolation::constant;
  if (spec.has("smoothing"))
    c.smoothing = spec.member("smoothing").one_of({"none", "cont_accel"}) == "none" ? channel::auto_smoothing::none
                                                                                   : channel::auto_smoothing::cont_accel;
  if (spec.has("cycles")) {
    const field cy = spec.member("cycles");
    static constexpr std::string_view cycle_fields[] = {"before", "after", "count_before", "count_after"};
    cy.only_members(cycle_fields, " in the Cycles modifier");
    auto mode = [&](std::string_view side) {
      if (!cy.has(side)) return channel::cycles_mode::repeat;
      const std::string m = cy.member(side).one_of({"none", "repeat", "repeat_offset", "mirror"});
      return m == "none" ? channel::cycles_mode::none
             : m == "repeat_offset" ? channel::cycles_mode::repeat_offset
             : m == "mirror" ? channel::cycles_mode::mirror
                              : channel::cycles_mode::repeat;
    };
    auto count = [&](std::string_view side) {
      if (!cy.has(side)) return 0;
      const long long n = cy.member(side).integer();
      if (n < 0 || n > 1000000) cy.member(side).fail("a cycle count in [0, 1000000] (0: infinite)");
      return static_cast<int>(n);
    };
    c.cycles = {true, mode("before"), mode("after"), count("count_before"), count("count_after")};
  }
  return c;
}

// The Ts spline of a "usd" spec (see the header).
template <class Real>
channel::usd_spline<Real> usd_spline_of(const field& spec) {
  channel::usd_spline<Real> s;
  const field knots = spec.member("knots", "tool \"usd\" takes knots");
  for (std::size_t i = 0; i < knots.array_size(); ++i) {
    const field k = knots.element(i);
    static constexpr std::string_view knot_fields[] = {"time",      "value",      "interpolation", "pre_width",
                                                       "pre_slope", "post_width", "post_slope",    "pre_value"};
    k.only_members(knot_fields, " in a USD knot");
    channel::usd_knot<Real> u;
    u.time = Real(k.member("time").number());
    u.value = Real(k.member("value").number());
    if (k.has("interpolation"))
      u.next_interp = channel::from_string<channel::usd_interpolation>(k.member("interpolation").one_of({"held", "linear", "curve"}));
    auto real = [&](std::string_view f, Real& out) {
      if (k.has(f)) out = Real(k.member(f).number());
    };
    real("pre_width", u.pre_width);
    real("pre_slope", u.pre_slope);
    real("post_width", u.post_width);
    real("post_slope", u.post_slope);
    if (k.has("pre_value")) u.dual_valued = true, u.pre_value = Real(k.member("pre_value").number());
    s.knots.push_back(u);
  }
  if (spec.has("curve_type"))
    s.curve_type = channel::from_string<channel::usd_curve_type>(spec.member("curve_type").one_of({"bezier", "hermite"}));
  if (spec.has("anti_regression"))
    s.anti_regression = channel::from_string<channel::usd_anti_regression>(
        spec.member("anti_regression").one_of({"none", "contain", "keep_ratio", "keep_start"}));
  auto extrapolation = [&](std::string_view side, std::string_view slope) {
    channel::usd_extrapolation<Real> e;
    if (spec.has(side))
      e.mode = channel::from_string<channel::usd_extrapolation_mode>(spec.member(side).one_of(
          {"held", "linear", "sloped", "loop_repeat", "loop_reset", "loop_oscillate"}));
    if (spec.has(slope)) {
      if (e.mode != channel::usd_extrapolation_mode::sloped)
        spec.member(slope).fail("a slope is only read by sloped extrapolation");
      e.slope = Real(spec.member(slope).number());
    }
    return e;
  };
  s.pre = extrapolation("before", "slope_before");
  s.post = extrapolation("after", "slope_after");
  if (spec.has("inner_loops")) {
    const field l = spec.member("inner_loops");
    static constexpr std::string_view loop_fields[] = {"proto_start", "proto_end", "pre_loops", "post_loops",
                                                       "value_offset"};
    l.only_members(loop_fields, " in inner_loops");
    s.inner_loops.proto_start = Real(l.member("proto_start", "inner loops need proto_start").number());
    s.inner_loops.proto_end = Real(l.member("proto_end", "inner loops need proto_end").number());
    auto count = [&](std::string_view f) {
      if (!l.has(f)) return 0;
      const long long n = l.member(f).integer();
      if (n < 0 || n > 100000) l.member(f).fail("a loop count in [0, 100000]");
      return static_cast<int>(n);
    };
    s.inner_loops.num_pre_loops = count("pre_loops");
    s.inner_loops.num_post_loops = count("post_loops");
    if (l.has("value_offset")) s.inner_loops.value_offset = Real(l.member("value_offset").number());
  }
  return s;
}

// The keys of a resolved USD spline as one channel (the curve view over the knots); a dual-valued
// knot (a jump at the knot) has none.
template <class Real>
std::vector<channel::key<Real>> usd_channel_keys(const channel::usd_spline<Real>& r, const field& spec) {
  std::vector<channel::key<Real>> keys;
  for (std::size_t i = 0; i < r.knots.size(); ++i) {
    if (r.knots[i].dual_valued && i > 0 && r.knots[i - 1].next_interp != channel::usd_interpolation::held)
      spec.fail("knots[" + std::to_string(i) + "] is dual-valued: a jump at a knot has no curve view (sample --at "
                "evaluates it)");
    keys.push_back({r.knots[i].time, r.knots[i].value, {}, {}, channel::interpolation::linear});
  }
  for (std::size_t i = 0; i + 1 < r.knots.size(); ++i) {
    const std::vector<channel::key<Real>> seg = channel::usd_segment_keys(r, i);
    keys[i].interp = seg[0].interp;
    keys[i].out = seg[0].out;
    keys[i + 1].in = seg[1].in;
  }
  return keys;
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

/// The rotation sampler of a gltf spec with "path": "rotation" (see the header): its times, its
/// quaternions (x y z w; in-tangent, value, out-tangent per key for cubicspline) and its blend.
/// The sampler validates them as glTF does, naming output[i] and the key's role (unit values,
/// | |q| - 1 | <= 0.00769). invalid_input for another tool or path.
template <class Real>
channel::gltf::rotation_sampler<Real> rotation_of_spec(const field& spec) {
  if (!detail::is_gltf_rotation(spec))
    spec.fail("a rotation sampler needs \"tool\": \"gltf\" and \"path\": \"rotation\"");
  namespace g = channel::gltf;
  const g::interpolation mode = g::from_string<g::interpolation>(
      spec.member("interpolation", "tool \"gltf\" takes an interpolation").one_of({"step", "linear", "cubicspline"}));
  const g::rotation_blend blend =
      spec.has("blend") ? g::from_string<g::rotation_blend>(spec.member("blend").one_of({"slerp", "nlerp"}))
                        : g::rotation_blend::slerp;
  std::vector<Real> t = spec.member("times", "tool \"gltf\" takes times").reals<Real>();
  const field vf = spec.member("values", "tool \"gltf\" takes values");
  const std::vector<Real> v = vf.reals<Real>();
  if (v.size() % 4 != 0)
    vf.fail(std::to_string(v.size()) + " numbers given: a rotation's values are quaternions, 4 numbers (x y z w) each");
  std::vector<point<Real, 4>> q(v.size() / 4);
  for (std::size_t i = 0; i < q.size(); ++i) q[i] = point<Real, 4>(v[4 * i], v[4 * i + 1], v[4 * i + 2], v[4 * i + 3]);
  return g::rotation_sampler<Real>(std::move(t), std::span<const point<Real, 4>>(q), mode, blend);
}

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
  const std::string tool = spec.member("tool", "a channel names the tool whose rules evaluate it")
                               .one_of({"exact", "css", "gltf", "maya", "blender", "usd"});
  if (detail::is_gltf_rotation(spec)) detail::refuse_rotation(spec, "scalar value v(t)");
  if (tool == "blender") {
    const channel::blender_evaluator<Real> b(detail::blender_fcurve_of<Real>(spec),
                                             detail::solver_of(spec, channel::time_solver::exact));
    return {b.underlying(), [b](const Real& t, int order) { return b.derivative(t, order); }};
  }
  if (tool == "usd") {
    const channel::usd_model<Real> u(detail::usd_spline_of<Real>(spec),
                                     detail::solver_of(spec, channel::time_solver::closed_form));
    const channel::channel<Real> c(detail::usd_channel_keys(u.resolved(), spec), channel::extrapolation::constant,
                                   channel::extrapolation::constant, u.solver());
    return {c, [u](const Real& t, int order) { return u.derivative(t, order); }};
  }
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
      {"tool", "whose rules evaluate the keys: exact, css, gltf, maya, blender or usd", presence::required},
      {"keys", "exact: [{time, value, interpolation, in: [dt, dv], out: [dt, dv]}, ...] in time order, or "
               "{generate: wave, count, start, step} (generated bezier keys); maya: "
               "[{time, value, in_type, out_type, in: [x, y], out: [x, y]}, ...] (tangent types fixed, linear, flat, "
               "step, step_next, spline, clamped, plateau, auto; in/out the fixed tangent vectors, x > 0); blender: "
               "[{time, value, handle_left: [frame, value], handle_right: [frame, value], handle_left_type, "
               "handle_right_type (free, aligned, vector, auto, auto_clamped), interpolation (constant, linear, "
               "bezier, sine, quad, cubic, quart, quint, expo, circ, back, bounce, elastic), easing (auto, in, out, "
               "in_out), back, amplitude, period}, ...]"},
      {"knots", "usd: [{time, value, interpolation (held, linear, curve), pre_width, pre_slope, post_width, "
                "post_slope, pre_value (makes the knot dual-valued)}, ...]"},
      {"extrapolation", "blender: constant or linear"},
      {"smoothing", "blender: auto-handle smoothing, none or cont_accel (the default, as for new F-curves)"},
      {"cycles", "blender: the Cycles modifier {before, after: none, repeat, repeat_offset, mirror; count_before, "
                 "count_after: repeats, 0 = infinite}"},
      {"curve_type", "usd: bezier or hermite"},
      {"anti_regression", "usd: none, contain, keep_ratio (the default) or keep_start"},
      {"slope_before", "usd: the slope of sloped extrapolation before the first knot"},
      {"slope_after", "usd: the slope of sloped extrapolation after the last knot"},
      {"inner_loops", "usd: {proto_start, proto_end, pre_loops, post_loops, value_offset}"},
      {"weighted", "maya: weighted tangents (bezier segments) or not (hermite)"},
      {"pre", "maya: pre infinity: constant, linear, cycle, cycle_relative, oscillate"},
      {"post", "maya: post infinity (the same names)"},
      {"before", "exact: extrapolation before the first key: constant, linear, cycle, cycle_offset, oscillate; usd: "
                 "held, linear, sloped, loop_repeat, loop_reset, loop_oscillate"},
      {"after", "exact, usd: extrapolation after the last key (the same names)"},
      {"solver", "the time solver of bezier segments (closed_form, table_newton, newton_bisection, bisection12, "
                 "bisection30, isolate_brent, curvebench, exact)"},
      {"easing", "css: cubic-bezier(x1, y1, x2, y2), steps(n, jump-start|jump-end|jump-none|jump-both), "
                 "linear(...) or a keyword"},
      {"interpolation", "gltf: step, linear or cubicspline"},
      {"times", "gltf: the key times (the sampler's input)"},
      {"values", "gltf: the sampler's output (cubicspline: in-tangent, value, out-tangent per key; rotation: "
                 "4 numbers x y z w per quaternion)"},
      {"path", "gltf: weights (a scalar channel, the default) or rotation (unit quaternion keys)"},
      {"blend", "gltf rotation: slerp (the default) or nlerp for linear interpolation"},
  };
  static constexpr std::string_view examples[] = {
      R"({"type": "channel", "tool": "exact", "keys": [{"time": 0, "value": 0, "out": [0.5, 0]}, {"time": 2, "value": 1, "in": [-0.5, 0.4]}], "after": "cycle_offset"})",
      R"j({"type": "channel", "tool": "css", "easing": "cubic-bezier(0.25, 0.1, 0.25, 1)"})j",
      R"({"type": "channel", "tool": "gltf", "interpolation": "cubicspline", "times": [0, 1, 3], "values": [0, 0, 1, 1, 2, 0, 0, 1, 0]})",
      R"({"type": "channel", "tool": "maya", "keys": [{"time": 0, "value": 0}, {"time": 10, "value": 4, "in_type": "clamped", "out_type": "clamped"}, {"time": 20, "value": 4}], "post": "oscillate"})",
      R"({"type": "channel", "tool": "blender", "keys": [{"time": 1, "value": 0}, {"time": 11, "value": 5}, {"time": 21, "value": 2}], "extrapolation": "linear"})",
      R"({"type": "channel", "tool": "usd", "knots": [{"time": 0, "value": 0, "post_width": 4, "post_slope": 1}, {"time": 6, "value": 3, "pre_width": 4, "pre_slope": 0}], "anti_regression": "keep_ratio", "after": "loop_repeat"})",
  };

  // A rotation is 4 numbers over time, not the planar (t, v): 4D, so that the runners that take 2D
  // and 3D curves pass it by; build refuses its curve view whatever the dimension asked.
  static int dimension(const field& spec) { return detail::is_gltf_rotation(spec) ? 4 : 2; }

  template <class Real, int Dim>
  static any_curve<Real, Dim> build(const field& spec) {
    if (detail::is_gltf_rotation(spec)) detail::refuse_rotation(spec, "planar curve view (t(u), v(u))");
    if constexpr (Dim == 2) {
      // Blender's eased segments are Penner's functions of time, not (t(u), v(u)) cubics: the
      // channel under them holds their chords, which is not their graph.
      if (spec.member("tool").string() == "blender") {
        const field keys = spec.member("keys");
        for (std::size_t i = 0; i + 1 < keys.array_size(); ++i) {
          const field k = keys.element(i);
          if (!k.has("interpolation")) continue;
          const std::string interp = k.member("interpolation").string();
          if (interp != "constant" && interp != "linear" && interp != "bezier")
            k.member("interpolation").fail("an eased segment (" + interp + ") has no curve view (t(u), v(u)); "
                                           "`curvebench sample SPEC --at T1,T2` evaluates it at times");
        }
      }
      return any_curve<Real, 2>(channel_of_spec<Real>(spec).curve(), std::string(name));
    } else {
      spec.fail("a channel is the planar curve (t(u), v(u)), 2D; a " + std::to_string(Dim) + "D curve was asked for");
    }
  }
};

}  // namespace curvebench::io
