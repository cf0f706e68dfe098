// The keyframe-channel measurements of the accuracy runner (harness/sweep_channel.cpp) and the
// tools' models of the same keys (harness/channel_models.hpp): the records cover every solver in
// both precisions with vocabulary ids, the measure sees a coarse solver's error and passes an
// accurate one, and each tool's import of the keys agrees with the exact keys wherever the tool's
// rules leave them unchanged (and differs by the documented rule where they do not).
#include "harness/accuracy.hpp"
#include "harness/channel_models.hpp"
#include "harness/setting.hpp"
#include "harness/vocabulary.hpp"
#include "harness/vocabulary_json.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <vector>

namespace cbc = curvebench::channel;
namespace hv = curvebench::harness::vocab;
namespace fs = std::filesystem;
using nlohmann::json;

namespace {

// The bold S of the stress corpus: handles of 0.9 of the interval from each end (a + c = 1.8 > 1,
// still monotone in time since (1 - a - c)^2 = 0.64 <= a c = 0.81).
const char* bold_s = R"({"name": "bold_s", "group": "channel", "reason": "test", "type": "channel", "tool": "exact",
  "keys": [{"time": 0, "value": 0, "out": [1.8, 0]}, {"time": 2, "value": 1, "in": [-1.8, 0]}]})";

json run_bold_s() {
  const fs::path dir = fs::temp_directory_path() / "curvebench_channel_sweep";
  fs::remove_all(dir);
  fs::create_directories(dir);
  std::ofstream(dir / "bold_s.json") << bold_s;
  const auto cases = curvebench::harness::load_cases(dir.string());
  const json out = curvebench::harness::run_case(cases.at(0), true);
  fs::remove_all(dir);
  return out;
}

// (quantity, solver, bits) -> record
std::map<std::string, json> channel_records(const json& out) {
  std::map<std::string, json> m;
  for (const auto& r : out["records"]) {
    const std::string q = r["quantity"];
    if (q.rfind("channel_", 0) == 0)
      m[q + "/" + r["method"].get<std::string>() + "/" + r["setting"].get<std::string>()] = r;
  }
  return m;
}

json run_spec(const std::string& name, const std::string& text) {
  const fs::path dir = fs::temp_directory_path() / "curvebench_channel_sweep";
  fs::remove_all(dir);
  fs::create_directories(dir);
  std::ofstream(dir / (name + ".json")) << text;
  const auto cases = curvebench::harness::load_cases(dir.string());
  const json out = curvebench::harness::run_case(cases.at(0), true);
  fs::remove_all(dir);
  return out;
}

}  // namespace

// A glTF rotation case: channel_rotation records only (it has no curve view), slerp and nlerp for a
// linear sampler, in both precisions, within the 16 eps that tests/test_gltf.cpp derives for a
// segment; the summary's largest segment angle is the keys' 120 degrees about z.
TEST(channel_sweep, rotation_cases_are_measured_as_angles) {
  const json out = run_spec("rot", R"({"name": "rot", "group": "channel", "reason": "test", "type": "channel",
    "tool": "gltf", "path": "rotation", "interpolation": "linear", "times": [0, 1, 2],
    "values": [0, 0, 0, 1, 0, 0, 0.8660254037844386, 0.5, 0, 0, 0.7071067811865476, -0.7071067811865476]})");
  std::map<std::string, double> err;
  for (const auto& r : out["records"]) {
    ASSERT_EQ(r["quantity"], "channel_rotation");
    err[r["method"].get<std::string>() + "/" + r["setting"].get<std::string>()] = r["error"].get<double>();
    EXPECT_LE(r["norm"].get<double>(), 4.0);  // a unit result: the keys' rounding and the normalization
  }
  EXPECT_EQ(err.size(), 4u);
  for (const char* k :
       {"rotation_slerp/bits=64", "rotation_slerp/bits=32", "rotation_nlerp/bits=64", "rotation_nlerp/bits=32"}) {
    ASSERT_EQ(err.count(k), 1u) << k;
    EXPECT_LE(err[k], 16.0) << k;
  }
  const json& c = out["case"]["channel"];
  EXPECT_EQ(c["path"], "rotation");
  EXPECT_EQ(c["keys"], 3);
  // Key 1 -> key 2: 120 degrees about z, then 270 degrees stored, whose short path is 150 degrees.
  EXPECT_NEAR(c["largest_segment_angle"].get<double>(), 150 * M_PI / 180, 1e-14);
  EXPECT_EQ(out["case"]["dimension"], 4);
}

TEST(channel_sweep, every_solver_in_both_precisions_with_vocabulary_ids) {
  const json out = run_bold_s();
  const auto m = channel_records(out);
  // 8 solvers x 2 precisions x 4 quantities, nothing refused for these keys.
  EXPECT_EQ(m.size(), std::size(hv::time_solver_methods) * 2 * 4);
  for (const hv::method* s : hv::time_solver_methods)
    for (const char* q : {"channel_value", "channel_keys", "channel_monotone", "channel_time"})
      for (const char* bits : {"bits=32", "bits=64"}) {
        SCOPED_TRACE(std::string(q) + " " + std::string(s->id) + " " + bits);
        ASSERT_EQ(m.count(std::string(q) + "/" + std::string(s->id) + "/" + bits), 1u);
        EXPECT_NE(hv::find_quantity(q), nullptr);
        EXPECT_NE(hv::find_method(s->id), nullptr);
      }
  const json& c = out["case"]["channel"];
  EXPECT_EQ(c["tool"], "exact");
  EXPECT_EQ(c["keys"], 2);
  EXPECT_DOUBLE_EQ(c["value_range"].get<double>(), 1.0);  // the S runs from 0 to 1, flat outside
  EXPECT_EQ(c["picture"]["t"].size(), 401u);
  EXPECT_EQ(c["picture"]["keys"].size(), 2u);
  EXPECT_TRUE(c["refused"].empty());
}

TEST(channel_sweep, the_measure_sees_a_coarse_solver_and_passes_an_accurate_one) {
  const auto m = channel_records(run_bold_s());
  // The goal for curvebench's solver: within 4 ulps of the value range in double, monotone.
  EXPECT_LE(m.at("channel_value/curvebench/bits=64")["error"].get<double>(), 4);
  EXPECT_LE(m.at("channel_value/exact/bits=64")["error"].get<double>(), 4);
  EXPECT_EQ(m.at("channel_monotone/curvebench/bits=64")["error"].get<double>(), 0);
  EXPECT_EQ(m.at("channel_monotone/curvebench/bits=32")["error"].get<double>(), 0);
  // The exact inversion's time residual is rounding: a few ulps of the segment's duration.
  EXPECT_LE(m.at("channel_time/exact/bits=64")["error"].get<double>(), 4);
  // 12 bisection steps leave u within 2^-13 of the root: on the bold S, whose slope reaches 2.5 /
  // interval, that is ~1e-4 of the range, ~1e11 ulps in double. The measure must see it.
  EXPECT_GE(m.at("channel_value/bisection12/bits=64")["error"].get<double>(), 1e8);
  EXPECT_EQ(m.at("channel_time/bisection12/bits=64")["iterations_max"].get<double>(), 12);
  // In float the data's rounding sets a floor of about half an ulp; the error stays below 16 ulps.
  EXPECT_LE(m.at("channel_value/curvebench/bits=32")["error"].get<double>(), 16);
  EXPECT_GE(m.at("channel_value/curvebench/bits=32")["rms"].get<double>(), 0);
}

namespace {

double max_difference(const curvebench::harness::channel_evaluator& f, const cbc::channel<double>& g, double t0,
                      double t1) {
  double d = 0;
  for (int j = 0; j <= 2000; ++j) {
    const double t = t0 + (t1 - t0) * j / 2000;
    d = std::max(d, std::abs(f(t) - g.value(t)));
  }
  return d;
}

std::map<std::string, curvebench::harness::keys_model> by_name(const std::vector<curvebench::harness::keys_model>& v) {
  std::map<std::string, curvebench::harness::keys_model> m;
  for (const auto& x : v) m.emplace(std::string(x.name), x);
  return m;
}

// Keys whose handles at each segment add up to at most the interval (a + c <= 1): no tool changes them.
std::vector<cbc::key<double>> tame_keys(double a, double c) {
  std::vector<cbc::key<double>> k{{0, 0, {}, {}, cbc::interpolation::bezier},
                                  {1, 1.5, {}, {}, cbc::interpolation::bezier},
                                  {3, -0.5, {}, {}, cbc::interpolation::bezier},
                                  {4, 0.25, {}, {}, cbc::interpolation::bezier}};
  const double slopes[] = {0.7, -0.4, 1.1, 2.0};
  for (std::size_t i = 0; i + 1 < k.size(); ++i) {
    const double h = k[i + 1].time - k[i].time;
    k[i].out = {a * h, slopes[i] * a * h};
    k[i + 1].in = {-c * h, -slopes[i + 1] * c * h};
  }
  return k;
}

}  // namespace

TEST(channel_models, agree_with_the_exact_keys_where_no_rule_changes_them) {
  const auto keys = tame_keys(0.4, 0.5);
  const cbc::channel<double> exact(keys, cbc::extrapolation::constant, cbc::extrapolation::constant,
                                   cbc::time_solver::exact);
  json skipped = json::object();
  const auto m = by_name(curvebench::harness::tool_models(keys, skipped));
  // Every tool but CSS (an easing on [0, 1]) holds them; exact is the reference, not a model.
  EXPECT_EQ(skipped.size(), 1u) << skipped.dump();
  EXPECT_NE(skipped["css"].get<std::string>().find("from time 0 to time 1"), std::string::npos) << skipped.dump();
  EXPECT_EQ(m.size() + skipped.size() + 1, curvebench::io::all_tools::size);
  EXPECT_EQ(m.count("exact"), 0u);
  EXPECT_EQ(m.at("blender").storage_bits, 32);
  EXPECT_EQ(m.at("maya").storage_bits, 64);
  // Value range about 2: Maya (isolate_brent) and USD (closed form, measured up to 58 ulps on the
  // stress corpus) in double within 1e-13; Blender in float within 64 float ulps of the range.
  EXPECT_LE(max_difference(m.at("maya").at, exact, 0, 4), 1e-13);
  EXPECT_LE(max_difference(m.at("usd").at, exact, 0, 4), 1e-13);
  EXPECT_LE(max_difference(m.at("blender").at, exact, 0, 4), 64 * 2 * 1.2e-7);
  // glTF keeps the slopes but not the lengths: these handles (0.4 and 0.5 of the interval, not
  // 1/3) make a visibly different curve.
  EXPECT_GE(max_difference(m.at("gltf").at, exact, 0, 4), 1e-3);
  // With handles at thirds the cubicspline sampler is the same cubic.
  const auto thirds = tame_keys(1.0 / 3, 1.0 / 3);
  const cbc::channel<double> exact3(thirds, cbc::extrapolation::constant, cbc::extrapolation::constant,
                                    cbc::time_solver::exact);
  const auto m3 = by_name(curvebench::harness::tool_models(thirds, skipped));
  EXPECT_LE(max_difference(m3.at("gltf").at, exact3, 0, 4), 1e-13);
}

TEST(channel_models, maya_corrects_only_handles_that_pass_the_other_key_and_regress) {
  // a + c = 1.5 but neither handle passes the other key and time stays monotone ((1 - a - c)^2 =
  // 0.25 <= a c = 0.54): exact, USD and Maya (AnimX's rule, maya.hpp) all keep the handles.
  const auto bold = tame_keys(0.6, 0.9);
  const cbc::channel<double> exact(bold, cbc::extrapolation::constant, cbc::extrapolation::constant,
                                   cbc::time_solver::exact);
  json skipped = json::object();
  const auto m = by_name(curvebench::harness::tool_models(bold, skipped));
  EXPECT_LE(max_difference(m.at("usd").at, exact, 0, 4), 1e-13);
  EXPECT_LE(max_difference(m.at("maya").at, exact, 0, 4), 1e-13);
  // a = 1.2 passes the next key and (a, c) = (1.2, 0.9) lies outside the monotone ellipse
  // a^2 + a c + c^2 - 2a - 2c + 1 <= 0 (0.13 > 0): Maya keeps the out handle and pulls the in handle
  // along its direction to the ellipse's upper edge c = (2 - a + sqrt(a (4 - 3a))) / 2, less the
  // 1e-10 margin. The corrected segment has a vertical tangent inside (x' has a double root at the
  // edge, split by the margin), where a time error dt moves the value by |dv/dt| dt: 1e-9 of the
  // value range allows isolate_brent's residual there against the exact inversion.
  const auto regressive = tame_keys(1.2, 0.9);
  const auto mr = by_name(curvebench::harness::tool_models(regressive, skipped));
  auto corrected = regressive;
  const double c_new = (2 - 1.2 + std::sqrt(1.2 * (4 - 3 * 1.2))) / 2 - 1e-10;
  for (std::size_t i = 1; i < corrected.size(); ++i)
    corrected[i].in = {corrected[i].in.dt * (c_new / 0.9), corrected[i].in.dv * (c_new / 0.9)};
  const cbc::channel<double> maya_rule(corrected, cbc::extrapolation::constant, cbc::extrapolation::constant,
                                       cbc::time_solver::exact);
  EXPECT_LE(max_difference(mr.at("maya").at, maya_rule, 0, 4), 1e-9 * 2);
  // The old rule (both handles scaled by 1 / (a + c)) is a different curve: the test can tell.
  auto scaled = regressive;
  for (std::size_t i = 0; i + 1 < scaled.size(); ++i) {
    scaled[i].out = {scaled[i].out.dt / 2.1, scaled[i].out.dv / 2.1};
    scaled[i + 1].in = {scaled[i + 1].in.dt / 2.1, scaled[i + 1].in.dv / 2.1};
  }
  const cbc::channel<double> old_rule(scaled, cbc::extrapolation::constant, cbc::extrapolation::constant,
                                      cbc::time_solver::exact);
  EXPECT_GE(max_difference(mr.at("maya").at, old_rule, 0, 4), 1e-3);
}

TEST(channel_models, keys_a_tool_cannot_hold_are_named_with_the_reason) {
  auto keys = tame_keys(0.4, 0.5);
  keys[1].interp = cbc::interpolation::hermite;
  json skipped = json::object();
  EXPECT_TRUE(curvebench::harness::tool_models(keys, skipped).empty());
  EXPECT_EQ(skipped.size(), curvebench::io::all_tools::size - 1);  // all but exact, the keys themselves
  for (const char* tool : {"maya", "usd", "blender", "gltf", "css"})
    EXPECT_NE(skipped[tool].get<std::string>().find("keys[1] is hermite"), std::string::npos) << tool;
  auto vertical = tame_keys(0.4, 0.5);
  vertical[0].out = {0, 0.5};
  skipped = json::object();
  const auto m = by_name(curvebench::harness::tool_models(vertical, skipped));
  EXPECT_EQ(m.count("blender"), 1u);
  EXPECT_NE(skipped["usd"].get<std::string>().find("vertical"), std::string::npos);
  EXPECT_NE(skipped["maya"].get<std::string>().find("keys[0]"), std::string::npos);
}

TEST(channel_models, the_vocabulary_carries_every_tool_by_its_one_name) {
  const json v = curvebench::harness::vocabulary_json();
  ASSERT_EQ(v["tools"].size(), curvebench::io::all_tools::size);
  for (std::size_t i = 0; i < curvebench::io::all_tool_names.size(); ++i) {
    EXPECT_EQ(v["tools"][i]["id"], std::string(curvebench::io::all_tool_names[i]));
    EXPECT_EQ(v["tools"][i]["settings"], json::array({"bits"}));
  }
  EXPECT_EQ(v["tools"][4]["id"], "blender");
  EXPECT_EQ(v["tools"][4]["storage_bits"], 32);
  EXPECT_EQ(v["tools"][3]["storage_bits"], 64);
  EXPECT_EQ(v["tools"][3]["default_solver"], "isolate_brent");
  // The tools are not algorithms of their own besides (one name, one entry).
  for (const auto& a : v["algorithms"])
    for (const auto& t : v["tools"]) EXPECT_NE(a["id"], t["id"]);
}
