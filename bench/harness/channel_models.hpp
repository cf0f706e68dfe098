// The tools' models of the same keys: a channel's keys (time, value, per-side handles, constant /
// linear / bezier segments) imported into each animation tool's model as that tool would hold
// them, so that the accuracy runner can measure where the tools disagree on the same keys
// (harness/sweep_channel.cpp) and the benchmarks can time each tool's evaluator on the same data
// (bench/bench_channel.cpp). Keyed range only: the extrapolation is each tool's default.
//   maya     weighted curve, fixed tangents (the tangent vector is 3 x the handle, maya.hpp); a
//            handle that passes the other key on a segment whose time regresses is pulled back
//            to the monotone region (AnimX's rule, maya.hpp); double, isolate_brent;
//   usd      bezier knots with width and slope, keep_ratio anti-regression, closed-form solver, double;
//   blender  free handles at absolute positions in float32, each handle limited to its segment's
//            duration (blender.hpp), exact solver;
//   gltf     a cubicspline sampler: one slope per side, the handle lengths lost (1/3 of the interval).
// Keys a tool cannot hold (step_next or hermite segments, zero-length or vertical handles where
// the tool needs a direction, mixed interpolations for glTF) leave that tool out: `skipped` gets
// the tool's name and the reason.
#pragma once

#include "curvebench/channel/blender.hpp"
#include "curvebench/channel/channel.hpp"
#include "curvebench/channel/gltf.hpp"
#include "curvebench/channel/maya.hpp"
#include "curvebench/channel/usd.hpp"
#include "curvebench/core/error.hpp"

#include <nlohmann/json.hpp>

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace curvebench::harness {

using channel_evaluator = std::function<double(double)>;

struct tool_model {
  std::string name;
  std::string rules;  ///< what was applied, for the report
  channel_evaluator at;
};

namespace detail {

inline std::optional<std::string> not_bezier_linear_constant(const std::vector<channel::key<double>>& keys) {
  for (std::size_t i = 0; i + 1 < keys.size(); ++i) {
    const auto p = keys[i].interp;
    if (p == channel::interpolation::step_next || p == channel::interpolation::hermite)
      return "keys[" + std::to_string(i) + "] is " + channel::to_string(p);
  }
  return std::nullopt;
}

}  // namespace detail

/// The models of maya, usd, blender and gltf that can hold `keys` (see the header); the others
/// are named in `skipped` with the reason.
inline std::vector<tool_model> tool_models(const std::vector<channel::key<double>>& keys, nlohmann::json& skipped) {
  std::vector<tool_model> out;
  if (const auto why = detail::not_bezier_linear_constant(keys)) {
    for (const char* t : {"maya", "usd", "blender", "gltf"}) skipped[t] = *why;
    return out;
  }
  // Maya: weighted fixed tangents, the tangent vector 3 x the handle (maya.hpp), which corrects
  // regressive handles that pass the other key.
  try {
    channel::maya_curve<double> c;
    c.weighted = true;
    for (std::size_t i = 0; i < keys.size(); ++i) {
      const auto& k = keys[i];
      channel::maya_key<double> m;
      m.time = k.time;
      m.value = k.value;
      // Only the sides of bezier segments carry a handle; the others keep Maya's default type.
      const bool bez_in = i > 0 && keys[i - 1].interp == channel::interpolation::bezier;
      const bool bez_out = i + 1 < keys.size() && k.interp == channel::interpolation::bezier;
      if ((bez_in && k.in.dt == 0) || (bez_out && k.out.dt == 0))
        throw invalid_input(validate::indexed("keys", i) +
                            ": a handle of zero time length has no Maya tangent (its x must be > 0)");
      if (bez_in) m.in_type = channel::maya_tangent::fixed, m.in_x = -3 * k.in.dt, m.in_y = -3 * k.in.dv;
      if (bez_out) m.out_type = channel::maya_tangent::fixed, m.out_x = 3 * k.out.dt, m.out_y = 3 * k.out.dv;
      if (k.interp == channel::interpolation::linear) m.out_type = channel::maya_tangent::linear;
      if (i > 0 && keys[i - 1].interp == channel::interpolation::linear) m.in_type = channel::maya_tangent::linear;
      if (k.interp == channel::interpolation::constant) m.out_type = channel::maya_tangent::step;
      c.keys.push_back(m);
    }
    const channel::maya_evaluator<double> e = channel::maya_model(c);
    out.push_back({"maya", "weighted fixed tangents; regressive handles past the other key pulled back (AnimX)",
                   [e](double t) { return e.value(t); }});
  } catch (const std::exception& x) {
    skipped["maya"] = x.what();
  }
  // USD: bezier knots with widths and slopes, keep_ratio anti-regression, closed-form solver.
  try {
    channel::usd_spline<double> s;
    for (const auto& k : keys) {
      channel::usd_knot<double> u;
      u.time = k.time;
      u.value = k.value;
      u.next_interp = k.interp == channel::interpolation::bezier   ? channel::usd_interpolation::curve
                      : k.interp == channel::interpolation::linear ? channel::usd_interpolation::linear
                                                                   : channel::usd_interpolation::held;
      if ((k.in.dt == 0 && k.in.dv != 0) || (k.out.dt == 0 && k.out.dv != 0))
        throw invalid_input("a vertical handle (zero time length, nonzero value) has no slope in USD");
      u.pre_width = -k.in.dt, u.pre_slope = k.in.dt != 0 ? k.in.dv / k.in.dt : 0;
      u.post_width = k.out.dt, u.post_slope = k.out.dt != 0 ? k.out.dv / k.out.dt : 0;
      s.knots.push_back(u);
    }
    const channel::usd_model<double> m(s);
    out.push_back({"usd", "bezier knots (width, slope), keep_ratio anti-regression, closed-form solver",
                   [m](double t) { return m.value(t); }});
  } catch (const std::exception& x) {
    skipped["usd"] = x.what();
  }
  // Blender: free handles at absolute positions, float32, Blender's handle correction.
  try {
    channel::blender_fcurve<float> f;
    f.smoothing = channel::auto_smoothing::none;
    for (const auto& k : keys) {
      channel::blender_key<float> b;
      b.time = static_cast<float>(k.time);
      b.value = static_cast<float>(k.value);
      b.handle_left = {static_cast<float>(k.time + k.in.dt), static_cast<float>(k.value + k.in.dv)};
      b.handle_right = {static_cast<float>(k.time + k.out.dt), static_cast<float>(k.value + k.out.dv)};
      b.handle_left_type = b.handle_right_type = channel::handle_type::free;
      b.interpolation = k.interp == channel::interpolation::bezier   ? channel::blender_interpolation::bezier
                        : k.interp == channel::interpolation::linear ? channel::blender_interpolation::linear
                                                                     : channel::blender_interpolation::constant;
      f.keys.push_back(b);
    }
    const channel::blender_evaluator<float> e = channel::blender_model(f);
    out.push_back({"blender", "free handles in float32; each handle limited to its segment's duration",
                   [e](double t) { return static_cast<double>(e.value(static_cast<float>(t))); }});
  } catch (const std::exception& x) {
    skipped["blender"] = x.what();
  }
  // glTF: a cubicspline sampler holds one tangent per side as a slope; handle lengths are lost.
  try {
    bool all_bezier = true;
    for (std::size_t i = 0; i + 1 < keys.size(); ++i) all_bezier = all_bezier && keys[i].interp == channel::interpolation::bezier;
    if (!all_bezier) throw invalid_input("a glTF sampler has one interpolation for all keys; these mix them");
    std::vector<double> times, values;
    for (const auto& k : keys) {
      if ((k.in.dt == 0 && k.in.dv != 0) || (k.out.dt == 0 && k.out.dv != 0))
        throw invalid_input("a vertical handle has no finite glTF tangent");
      times.push_back(k.time);
      values.push_back(k.in.dt != 0 ? k.in.dv / k.in.dt : 0);
      values.push_back(k.value);
      values.push_back(k.out.dt != 0 ? k.out.dv / k.out.dt : 0);
    }
    const auto s = std::make_shared<channel::gltf::sampler<double, 1>>(times, std::span<const double>(values),
                                                                       channel::gltf::interpolation::cubicspline);
    out.push_back({"gltf", "cubicspline: the handles' slopes, lengths dropped (1/3 of the interval)",
                   [s](double t) { return (*s)(t)[0]; }});
  } catch (const std::exception& x) {
    skipped["gltf"] = x.what();
  }
  return out;
}

}  // namespace curvebench::harness
