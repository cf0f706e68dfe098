// The spec of tool "maya" (channel/tools/maya.hpp): a Maya animCurve (channel/maya.hpp): keys
// with in/out tangent types and fixed tangent vectors, weighted or not, pre and post infinity;
// solver default isolate_brent.
#pragma once

#include "curvebench/channel/maya.hpp"
#include "curvebench/channel/tools/maya.hpp"
#include "curvebench/io/family.hpp"
#include "curvebench/io/tools/common.hpp"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <string>
#include <string_view>

namespace curvebench::io {

namespace detail {

// The keys of a Maya animCurve (channel/maya.hpp): tangent types per side and, for fixed
// tangents, the tangent vectors (x, y), x > 0.
template <class Real>
channel::maya_curve<Real> maya_curve_of(const field& spec) {
  channel::maya_curve<Real> c;
  const field keys = spec.member("keys", "tool \"maya\" takes keys");
  static constexpr std::string_view tangents[] = {"fixed",  "linear",  "flat",    "step", "step_next",
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
    key.time = k.member("time").number_as<Real>();
    key.value = k.member("value").number_as<Real>();
    key.in_type = tangent(k, "in_type");
    key.out_type = tangent(k, "out_type");
    const channel::handle<Real> in = handle_of<Real>(k, "in"), out = handle_of<Real>(k, "out");
    if (k.has("in")) key.in_x = in.dt, key.in_y = in.dv;
    if (k.has("out")) key.out_x = out.dt, key.out_y = out.dv;
    // A fixed tangent's vector, checked here in the spec's words ("in": [x, y]) before the curve
    // checks it as in_x, in_y (the library's field names, which the spec does not have).
    const auto vector = [&](std::string_view side, channel::maya_tangent type, const Real& x, const Real& y) {
      if (!k.has(side)) return;
      if (type != channel::maya_tangent::fixed)
        k.member(side).fail("a tangent vector is used by a fixed tangent only, and this side's type is " +
                            std::string(channel::to_string(type)) + " (which would ignore it): give \"" +
                            std::string(side) + "_type\": \"fixed\" or drop it");
      if (!(x > Real(0)))
        k.member(side).fail("x = " + to_text(static_cast<double>(x)) +
                            ": a fixed tangent's x must be > 0 (the vector points forwards in time)");
      // In double, as Maya holds it, whatever Real: at 50 digits 1e300 / 1e-300 is finite, and the
      // truth sampled a spec that the tool model (and `length`) refused.
      if (!std::isfinite(static_cast<double>(y) / static_cast<double>(x)))
        k.member(side).fail("the slope y / x = " + to_text(static_cast<double>(y)) + " / " +
                            to_text(static_cast<double>(x)) + " overflows double");
    };
    vector("in", key.in_type, key.in_x, key.in_y);
    vector("out", key.out_type, key.out_x, key.out_y);
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

template <>
struct tool_spec<channel::tools::maya> {
  static constexpr field_doc fields[] = {
      {"keys",
       "[{time, value, in_type, out_type, in: [x, y], out: [x, y]}, ...] (tangent types fixed, linear, flat, "
       "step, step_next, spline, clamped, plateau, auto; in/out the fixed tangent vectors, x > 0)"},
      {"weighted", "weighted tangents (bezier segments) or not (hermite)"},
      {"pre", "pre infinity: constant, linear, cycle, cycle_relative, oscillate"},
      {"post", "post infinity (the same names)"},
  };
  static constexpr std::string_view example =
      R"({"type": "channel", "tool": "maya", "keys": [{"time": 0, "value": 0}, {"time": 10, "value": 4, "in_type": "clamped", "out_type": "clamped"}, {"time": 20, "value": 4}], "post": "oscillate"})";

  template <class Real>
  static channel::tools::maya::model<Real> parse(const field& spec) {
    return channel::tools::maya::model<Real>(detail::maya_curve_of<Real>(spec),
                                             detail::solver_of(spec, channel::tools::maya::default_solver));
  }
};

}  // namespace curvebench::io
