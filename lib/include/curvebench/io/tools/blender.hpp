// The spec of tool "blender" (channel/tools/blender.hpp): a Blender F-curve (channel/blender.hpp):
// keys with absolute handle_left / handle_right, handle types (the handles recomputed by their
// rules, or with handles: stored evaluated as given), interpolation (constant, linear,
// bezier or a Penner family) with easing and back / amplitude / period; extrapolation constant or
// linear, auto-handle smoothing, the Cycles modifier; evaluated in the precision asked (float is
// Blender's own, with Blender's root finding unless the spec names a solver; exact at other precisions). An eased
// segment has no curve view (the planar curve is refused naming the key; `sample --at` evaluates it).
#pragma once

#include "curvebench/channel/blender.hpp"
#include "curvebench/channel/tools/blender.hpp"
#include "curvebench/io/family.hpp"
#include "curvebench/io/tools/common.hpp"

#include <cmath>
#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace curvebench::io {

namespace detail {

// The Blender F-curve of a "blender" spec (see the header): handle types per side, the
// interpolation of the segment starting at each key with its easing, extrapolation, smoothing
// and the Cycles modifier.
template <class Real>
channel::blender_fcurve<Real> blender_fcurve_of(const field& spec) {
  channel::blender_fcurve<Real> c;
  const field keys = spec.member("keys", "tool \"blender\" takes keys");
  // Blender stores an F-curve in float32: a number past float's range is no Blender F-curve, in
  // any precision (the truth at 50 digits refuses it as the tool does), said in those words rather
  // than as the inf it becomes.
  auto stored = [](const field& f, double x) {
    if (std::abs(x) > static_cast<double>(std::numeric_limits<float>::max()))
      f.fail(channel::tools::blender::past_float(x));
    return Real(x);
  };
  auto number = [&](const field& k, std::string_view name) {
    const field f = k.member(name);
    return stored(f, f.number());
  };
  auto point_of = [&](const field& k, std::string_view side, const Real& t, const Real& v) {
    if (!k.has(side)) return channel::blender_point<Real>{t, v};
    const field f = k.member(side);
    const std::vector<double> p = f.reals<double>();
    if (p.size() != 2) f.fail("expected [frame, value], two numbers, got " + std::to_string(p.size()));
    return channel::blender_point<Real>{stored(f.element(0), p[0]), stored(f.element(1), p[1])};
  };
  auto handle = [](const field& k, std::string_view side) {
    if (!k.has(side)) return channel::handle_type::auto_clamped;
    const std::string h = k.member(side).one_of({"free", "aligned", "vector", "auto", "auto_clamped"});
    for (channel::handle_type t :
         {channel::handle_type::free, channel::handle_type::aligned, channel::handle_type::vector,
          channel::handle_type::automatic, channel::handle_type::auto_clamped})
      if (h == channel::to_string(t)) return t;
    return channel::handle_type::auto_clamped;
  };
  for (std::size_t i = 0; i < keys.array_size(); ++i) {
    const field k = keys.element(i);
    static constexpr std::string_view key_fields[] = {
        "time",   "value", "handle_left", "handle_right", "handle_left_type", "handle_right_type", "interpolation",
        "easing", "back",  "amplitude",   "period"};
    k.only_members(key_fields, " in a Blender key");
    channel::blender_key<Real> b;
    b.time = number(k, "time");
    b.value = number(k, "value");
    // Two times a double tells apart may be one float: said so, not "keys[1].time <= keys[0].time".
    if (i > 0) {
      const double t0 = keys.element(i - 1).member("time").number(), t1 = k.member("time").number();
      if (t1 > t0 && !(static_cast<float>(t1) > static_cast<float>(t0)))
        k.member("time").fail(to_text(t1) + " rounds to the float " + to_text(static_cast<float>(t1)) +
                              ", not after keys[" + std::to_string(i - 1) + "].time " + to_text(t0) +
                              ": Blender stores frames in float32 (a spacing of " +
                              to_text(static_cast<double>(std::nextafter(static_cast<float>(t0), INFINITY)) -
                                      static_cast<double>(static_cast<float>(t0))) +
                              " there)");
    }
    b.handle_left = point_of(k, "handle_left", b.time, b.value);
    b.handle_right = point_of(k, "handle_right", b.time, b.value);
    b.handle_left_type = handle(k, "handle_left_type");
    b.handle_right_type = handle(k, "handle_right_type");
    if (k.has("interpolation")) {
      const std::string name = k.member("interpolation")
                                   .one_of({"constant", "linear", "bezier", "sine", "quad", "cubic", "quart", "quint",
                                            "expo", "circ", "back", "bounce", "elastic"});
      for (int j = 0; j <= static_cast<int>(channel::blender_interpolation::elastic); ++j)
        if (name == channel::to_string(static_cast<channel::blender_interpolation>(j)))
          b.interpolation = static_cast<channel::blender_interpolation>(j);
    }
    if (k.has("easing")) {
      const std::string e = k.member("easing").one_of({"auto", "in", "out", "in_out"});
      b.easing = e == "auto" ? channel::ease_mode::automatic : channel::ease_mode_from_string(e);
    }
    if (k.has("back")) b.params.back = number(k, "back");
    if (k.has("amplitude")) b.params.amplitude = number(k, "amplitude");
    if (k.has("period")) b.params.period = number(k, "period");
    c.keys.push_back(b);
  }
  if (spec.has("handles")) c.stored_handles = spec.member("handles").one_of({"by_type", "stored"}) == "stored";
  if (spec.has("extrapolation"))
    c.extrapolation = spec.member("extrapolation").one_of({"constant", "linear"}) == "linear"
                          ? channel::blender_extrapolation::linear
                          : channel::blender_extrapolation::constant;
  if (spec.has("smoothing"))
    c.smoothing = spec.member("smoothing").one_of({"none", "cont_accel"}) == "none"
                      ? channel::auto_smoothing::none
                      : channel::auto_smoothing::cont_accel;
  if (spec.has("cycles")) {
    const field cy = spec.member("cycles");
    static constexpr std::string_view cycle_fields[] = {"before", "after", "count_before", "count_after"};
    cy.only_members(cycle_fields, " in the Cycles modifier");
    auto mode = [&](std::string_view side) {
      if (!cy.has(side)) return channel::cycles_mode::repeat;
      const std::string m = cy.member(side).one_of({"none", "repeat", "repeat_offset", "mirror"});
      return m == "none"            ? channel::cycles_mode::none
             : m == "repeat_offset" ? channel::cycles_mode::repeat_offset
             : m == "mirror"        ? channel::cycles_mode::mirror
                                    : channel::cycles_mode::repeat;
    };
    auto count = [&](std::string_view side) {
      if (!cy.has(side)) return 0;
      const long long n = cy.member(side).integer();
      if (n < 0 || n > 1000000)
        cy.member(side).fail(std::to_string(n) + " is not a cycle count in [0, 1000000] (0: infinite)");
      return static_cast<int>(n);
    };
    c.cycles = {true, mode("before"), mode("after"), count("count_before"), count("count_after")};
  }
  return c;
}

}  // namespace detail

template <>
struct tool_spec<channel::tools::blender> {
  static constexpr field_doc fields[] = {
      {"keys",
       "[{time, value, handle_left: [frame, value], handle_right: [frame, value], handle_left_type, "
       "handle_right_type (free, aligned, vector, auto, auto_clamped), interpolation (constant, linear, "
       "bezier, sine, quad, cubic, quart, quint, expo, circ, back, bounce, elastic), easing (auto, in, out, "
       "in_out), back, amplitude, period}, ...]"},
      {"handles",
       "by_type (the default: auto, auto_clamped, vector and aligned handles recomputed by Blender's rules) "
       "or stored (every handle as given, as Blender evaluates the handles it stored; "
       "scripts/blender_export.py writes stored)"},
      {"extrapolation", "constant or linear"},
      {"smoothing", "auto-handle smoothing, none or cont_accel (the default, as for new F-curves)"},
      {"cycles",
       "the Cycles modifier {before, after: none, repeat, repeat_offset, mirror; count_before, "
       "count_after: repeats, 0 = infinite}"},
  };
  static constexpr std::string_view example =
      R"({"type": "channel", "tool": "blender", "keys": [{"time": 1, "value": 0}, {"time": 11, "value": 5}, {"time": 21, "value": 2}], "extrapolation": "linear"})";

  template <class Real>
  static channel::tools::blender::model<Real> parse(const field& spec) {
    // No solver named: Blender's own root finding in float, exact at other precisions.
    std::optional<channel::time_solver> solver;
    if (spec.has("solver")) solver = detail::solver_of(spec, channel::tools::blender::default_solver);
    return channel::tools::blender::model<Real>(detail::blender_fcurve_of<Real>(spec), solver);
  }

  // Blender's eased segments are Penner's functions of time, not (t(u), v(u)) cubics: the
  // channel under them holds their chords, which is not their graph.
  static void check_curve_view(const field& spec, int dim) {
    if (dim != 2 || !spec.has("keys")) return;
    const field keys = spec.member("keys");
    for (std::size_t i = 0; i + 1 < keys.array_size(); ++i) {
      const field k = keys.element(i);
      if (!k.has("interpolation")) continue;
      const std::string interp = k.member("interpolation").string();
      if (interp != "constant" && interp != "linear" && interp != "bezier")
        k.member("interpolation")
            .fail("an eased segment (" + interp +
                  ") has no curve view (t(u), v(u)); "
                  "`curvebench sample SPEC --at T1,T2` evaluates it at times");
    }
  }
};

}  // namespace curvebench::io
