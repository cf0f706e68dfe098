// The spec of tool "usd" (channel/tools/usd.hpp): an OpenUSD Ts spline (channel/usd.hpp): knots
// with interpolation held / linear / curve, pre / post tangent width and slope, a pre_value for a
// dual-valued knot; curve_type, anti_regression, extrapolation before / after with USD's mode
// names and slopes, inner loops; solver default closed_form (USD's). A dual-valued knot after a
// linear or curve segment has no curve view: the model evaluates it (sample --at, check, fidelity),
// the curve (length, accuracy) is refused naming the knot (io::channel_model's source()).
#pragma once

#include "curvebench/channel/tools/usd.hpp"
#include "curvebench/channel/usd.hpp"
#include "curvebench/io/family.hpp"
#include "curvebench/io/tools/common.hpp"

#include <string>
#include <string_view>

namespace curvebench::io {

namespace detail {

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
    u.time = k.member("time").number_as<Real>();
    u.value = k.member("value").number_as<Real>();
    if (k.has("interpolation"))
      u.next_interp = channel::from_string<channel::usd_interpolation>(
          k.member("interpolation").one_of({"held", "linear", "curve"}));
    auto real = [&](std::string_view f, Real& out) {
      if (k.has(f)) out = k.member(f).number_as<Real>();
    };
    real("pre_width", u.pre_width);
    real("pre_slope", u.pre_slope);
    real("post_width", u.post_width);
    real("post_slope", u.post_slope);
    if (k.has("pre_value")) u.dual_valued = true, u.pre_value = k.member("pre_value").number_as<Real>();
    s.knots.push_back(u);
  }
  if (spec.has("curve_type"))
    s.curve_type =
        channel::from_string<channel::usd_curve_type>(spec.member("curve_type").one_of({"bezier", "hermite"}));
  if (spec.has("anti_regression"))
    s.anti_regression = channel::from_string<channel::usd_anti_regression>(
        spec.member("anti_regression").one_of({"none", "contain", "keep_ratio", "keep_start"}));
  auto extrapolation = [&](std::string_view side, std::string_view slope) {
    channel::usd_extrapolation<Real> e;
    if (spec.has(side))
      e.mode = channel::from_string<channel::usd_extrapolation_mode>(
          spec.member(side).one_of({"held", "linear", "sloped", "loop_repeat", "loop_reset", "loop_oscillate"}));
    if (spec.has(slope)) {
      if (e.mode != channel::usd_extrapolation_mode::sloped)
        spec.member(slope).fail("a slope is only read by sloped extrapolation");
      e.slope = spec.member(slope).number_as<Real>();
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
    s.inner_loops.proto_start = l.member("proto_start", "inner loops need proto_start").number_as<Real>();
    s.inner_loops.proto_end = l.member("proto_end", "inner loops need proto_end").number_as<Real>();
    auto count = [&](std::string_view f) {
      if (!l.has(f)) return 0;
      const long long n = l.member(f).integer();
      if (n < 0 || n > 100000) l.member(f).fail(std::to_string(n) + " is not a loop count in [0, 100000]");
      return static_cast<int>(n);
    };
    s.inner_loops.num_pre_loops = count("pre_loops");
    s.inner_loops.num_post_loops = count("post_loops");
    if (l.has("value_offset")) s.inner_loops.value_offset = l.member("value_offset").number_as<Real>();
  }
  return s;
}

}  // namespace detail

template <>
struct tool_spec<channel::tools::usd> {
  static constexpr field_doc fields[] = {
      {"knots",
       "[{time, value, interpolation (held, linear, curve), pre_width, pre_slope, post_width, "
       "post_slope, pre_value (makes the knot dual-valued)}, ...]"},
      {"curve_type", "bezier or hermite"},
      {"anti_regression", "none, contain, keep_ratio (the default) or keep_start"},
      {"before", "held, linear, sloped, loop_repeat, loop_reset, loop_oscillate"},
      {"after", "the same names"},
      {"slope_before", "the slope of sloped extrapolation before the first knot"},
      {"slope_after", "the slope of sloped extrapolation after the last knot"},
      {"inner_loops", "{proto_start, proto_end, pre_loops, post_loops, value_offset}"},
  };
  static constexpr std::string_view example =
      R"({"type": "channel", "tool": "usd", "knots": [{"time": 0, "value": 0, "post_width": 4, "post_slope": 1}, {"time": 6, "value": 3, "pre_width": 4, "pre_slope": 0}], "anti_regression": "keep_ratio", "after": "loop_repeat"})";

  template <class Real>
  static channel::tools::usd::model<Real> parse(const field& spec) {
    const channel::usd_model<Real> u(detail::usd_spline_of<Real>(spec),
                                     detail::solver_of(spec, channel::tools::usd::default_solver));
    return channel::tools::usd::model<Real>(u);
  }
};

}  // namespace curvebench::io
