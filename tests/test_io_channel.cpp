// The "channel" spec type (io/families/channel.hpp): each tool's spec evaluates as the tool's own
// evaluator does (css_easing, the glTF sampler, the Maya model), the exact tool against the 50-digit
// twin of the same keys, the curve view is the channel's planar curve, and bad specs name the field.
//
// Tolerances (one table):
//   - css cubic-bezier through the channel against css_easing with the same solver (table_newton,
//     epsilon 1e-7 on the normalized time residual): 4e-7 of the value range, the residual times
//     the largest |dy/dx| of these easings (below 4 on the grid used);
//   - steps(), linear(), glTF and Maya: the same arithmetic on the same data, 4 ulps of the scale
//     (the order of the operations may differ by a rounding or two);
//   - exact tool in double against its real50 twin with the exact solver: 8 ulps of the value
//     range (the solver's bound 4 plus the rounding of the query time, as test_channel derives).
#include "support/accuracy.hpp"
#include "support/fixtures.hpp"

#include "curvebench/channel/css_easing.hpp"
#include "curvebench/channel/gltf.hpp"
#include "curvebench/channel/maya.hpp"
#include "curvebench/io/spec.hpp"
#include "curvebench/reference/multiprecision.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <string>
#include <vector>

namespace cb = curvebench;
namespace cbt = curvebench::testing;
namespace ch = curvebench::channel;
using R = cb::real50;

namespace {

nlohmann::json read_case(const std::string& name) {
  std::ifstream in(std::string(CURVEBENCH_SOURCE_DIR) + "/bench/cases/" + name + ".json");
  return nlohmann::json::parse(in);
}

cb::io::field spec_of(const nlohmann::json& j) { return cb::io::root(j, "spec.json"); }

std::vector<double> grid(double lo, double hi, int n) {
  std::vector<double> t;
  for (int i = 0; i <= n; ++i) t.push_back(lo + (hi - lo) * i / n);
  return t;
}

}  // namespace

TEST(io_channel, css_cubic_bezier_matches_css_easing) {
  for (const char* e : {"cubic-bezier(0.25, 0.1, 0.25, 1)", "cubic-bezier(1, 0, 0, 1)", "cubic-bezier(0.3, 1.5, 0.7, -0.5)",
                        "ease-in-out"}) {
    SCOPED_TRACE(e);
    const nlohmann::json j = {{"type", "channel"}, {"tool", "css"}, {"easing", e}};
    const auto m = cb::io::channel_model_of_spec<double>(spec_of(j));
    const auto css = ch::parse_css_easing<double>(e, ch::time_solver::table_newton);
    for (double x : grid(0, 1, 1000)) EXPECT_NEAR(m.at(x, 0), css(x), 4e-7) << "x = " << x;
  }
}

TEST(io_channel, css_steps_and_linear_match_css_easing) {
  for (const char* e : {"steps(4, jump-start)", "steps(4, jump-end)", "steps(5, jump-none)", "steps(3, jump-both)",
                        "step-start", "step-end", "linear(0, 0.25 75%, 1)", "linear(0, 1.2 40%, 0.8 60%, 1)"}) {
    SCOPED_TRACE(e);
    const nlohmann::json j = {{"type", "channel"}, {"tool", "css"}, {"easing", e}};
    const auto m = cb::io::channel_model_of_spec<double>(spec_of(j));
    const auto css = ch::parse_css_easing<double>(e);
    // Off the step boundaries (k / n for n up to 5): 997 is prime to every n.
    for (double x : grid(0.0005, 0.9995, 997)) EXPECT_NEAR(m.at(x, 0), css(x), 4 * cb::epsilon<double>()) << x;
    EXPECT_EQ(m.at(1.0, 0), css(1.0));
    EXPECT_EQ(m.at(0.0, 0), css(0.0));
  }
}

TEST(io_channel, gltf_matches_the_sampler) {
  const std::vector<double> times{0, 0.5, 2, 2.25};
  const std::vector<double> cubic{0, 0, 1, 2, 1, -1, 0.5, -0.5, 0, 0, 2, 0};
  const std::vector<double> plain{0, 1, -0.5, 2};
  for (const std::string mode : {"step", "linear", "cubicspline"}) {
    SCOPED_TRACE(mode);
    const std::vector<double>& values = mode == "cubicspline" ? cubic : plain;
    const nlohmann::json j = {
        {"type", "channel"}, {"tool", "gltf"}, {"interpolation", mode}, {"times", times}, {"values", values}};
    const auto m = cb::io::channel_model_of_spec<double>(spec_of(j));
    const ch::gltf::sampler<double, 1> s(times, std::span<const double>(values),
                                         ch::gltf::from_string<ch::gltf::interpolation>(mode));
    for (double t : grid(-0.5, 2.75, 1301)) {
      EXPECT_NEAR(m.at(t, 0), s.scalar(t), 4 * cb::epsilon<double>() * 2) << "t = " << t;
      if (mode == "cubicspline" && t > 0 && t < 2.25) {
        EXPECT_NEAR(m.at(t, 1), s.derivative(t, 1)[0], 64 * cb::epsilon<double>() * 8) << "t = " << t;
      }
    }
  }
}

TEST(io_channel, maya_matches_the_model) {
  const nlohmann::json j = nlohmann::json::parse(R"({"type": "channel", "tool": "maya", "weighted": true,
    "keys": [{"time": 0, "value": 0, "out_type": "fixed", "out": [3, 6]}, {"time": 10, "value": 4, "in_type": "clamped", "out_type": "clamped"},
             {"time": 20, "value": 4, "in_type": "plateau", "out_type": "plateau"}, {"time": 24, "value": -1}], "post": "linear", "pre": "oscillate"})");
  const auto m = cb::io::channel_model_of_spec<double>(spec_of(j));
  ch::maya_curve<double> c;
  c.weighted = true;
  c.pre = ch::maya_infinity::oscillate;
  c.post = ch::maya_infinity::linear;
  c.keys = {{0, 0, ch::maya_tangent::spline, ch::maya_tangent::fixed, 1, 0, 3, 6},
            {10, 4, ch::maya_tangent::clamped, ch::maya_tangent::clamped, 1, 0, 1, 0},
            {20, 4, ch::maya_tangent::plateau, ch::maya_tangent::plateau, 1, 0, 1, 0},
            {24, -1, ch::maya_tangent::spline, ch::maya_tangent::spline, 1, 0, 1, 0}};
  const auto model = ch::maya_model(c);
  for (double t : grid(-30, 40, 1400)) {
    EXPECT_EQ(m.at(t, 0), model.value(t)) << "t = " << t;
    EXPECT_EQ(m.at(t, 1), model.derivative(t, 1)) << "t = " << t;
  }
}

TEST(io_channel, exact_tool_against_its_50_digit_twin) {
  for (const char* name : {"channel_regression_limit", "channel_bold_s", "channel_holds", "channel_far_frames"}) {
    SCOPED_TRACE(name);
    const nlohmann::json j = read_case(name);
    const auto m = cb::io::channel_model_of_spec<double>(spec_of(j));
    const auto truth = cb::io::channel_model_of_spec<R>(spec_of(j));
    double lo = m.source.keys().front().time, hi = m.source.keys().back().time, vmin = 0, vmax = 0;
    for (const auto& k : m.source.keys()) vmin = std::min(vmin, k.value), vmax = std::max(vmax, k.value);
    const R range = R(vmax - vmin) + R(1e-300);
    for (double t : grid(lo - 1, hi + 1, 3001)) {
      const R err = abs(R(m.at(t, 0)) - truth.at(R(t), 0)) / (range * R(cb::epsilon<double>()));
      EXPECT_LE(static_cast<double>(err), 8.0) << "t = " << t;
    }
  }
}

TEST(io_channel, curve_view_and_registry) {
  const nlohmann::json j = read_case("channel_holds");
  const auto c = cb::io::curve_from_spec<double, 2>(spec_of(j));
  EXPECT_EQ(cb::io::spec_dimension(spec_of(j)), 2);
  EXPECT_EQ(c.domain().hi, 5.0);  // 6 keys, 5 segments on [0, 5]
  EXPECT_EQ(c(2.0)[0], 2.5);      // P(i) is key i
  EXPECT_EQ(c(2.0)[1], 1.0);
}

TEST(io_channel, bad_specs_name_the_field) {
  auto message = [](const char* text) {
    const nlohmann::json j = nlohmann::json::parse(text);
    return cbt::message_of([&] { (void)cb::io::channel_model_of_spec<double>(spec_of(j)); });
  };
  EXPECT_NE(message(R"({"type": "channel", "tool": "houdini"})").find("spec.json.tool"), std::string::npos);
  EXPECT_NE(message(R"({"type": "channel", "tool": "exact"})").find("keys"), std::string::npos);
  EXPECT_NE(message(R"({"type": "channel", "tool": "exact", "keys": [{"time": 0, "value": 0, "tangent": 1}]})")
                .find("tangent"),
            std::string::npos);
  EXPECT_NE(message(R"({"type": "channel", "tool": "exact", "keys": [{"time": 0, "value": 0, "in": [1]}]})")
                .find("spec.json.keys[0].in"),
            std::string::npos);
  EXPECT_NE(message(R"({"type": "channel", "tool": "exact", "keys": [{"time": 1, "value": 0}, {"time": 0, "value": 0}]})")
                .find("keys[1]"),
            std::string::npos);
  EXPECT_NE(message(R"({"type": "channel", "tool": "exact", "solver": "guess", "keys": [{"time": 0, "value": 0}]})")
                .find("spec.json.solver"),
            std::string::npos);
  EXPECT_NE(message(R"j({"type": "channel", "tool": "css", "easing": "cubic-bezier(2, 0, 0, 1)"})j").find("spec.json.easing"),
            std::string::npos);
  EXPECT_NE(message(R"j({"type": "channel", "tool": "css", "easing": "linear(0, 0.5 50%, 0.7 50%, 1)"})j").find("jump"),
            std::string::npos);
  EXPECT_NE(message(R"({"type": "channel", "tool": "maya", "keys": [{"time": 0, "value": 0, "in_type": "smooth"}]})")
                .find("in_type"),
            std::string::npos);
}
