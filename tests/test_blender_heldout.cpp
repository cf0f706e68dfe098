// The "blender" tool model against Blender 3.4.1 on held-out F-curves
// (tests/data/recorded/blender_heldout.json, the common recording format; made by
// scripts/peers/blender_fcurves_request.py --heldout and scripts/peers/blender_fcurves.py --common):
// seeded random key layouts that were not used to find the rules, over every handle type with each
// extrapolation, free handles (broken, long, crossing), every interpolation and easing at and between
// the key times, the Cycles modifier with every handle type and smoothing, frames far from 0, the end
// key's own interpolation under linear extrapolation, single keys. Each spec is read by curvebench's
// reader and evaluated as the tool does (harness::channel_values_of, against tool: float32 at
// float(t), Blender's own arithmetic), and compared with Blender's recorded fcurve.evaluate.
// Refused channels (the reader or the float model says "not modelled") are counted and listed
// exactly: a new refusal fails the test.
#include "harness/check.hpp"
#include "support/source_dir.hpp"

#include "curvebench/io/json_fields.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace {

using curvebench::harness::channel_values;
using curvebench::harness::channel_values_of;
using curvebench::harness::check_against;

// value_tol, in eps_float (2^-23) of the scale |v| + extent + (|t| + |t_first| + T) S
// (extent: the largest |value| of a key or handle, and a key's value plus elastic's amplitude;
// T: the keyed span; S: the larger of |dv/dt| at t and the steepest chord between keys): Blender
// and the model are both float32 evaluations of the same formulas, so they differ by the rounding
// of the values they carry (the magnitudes) and of the times: a time rounded to float near t, a
// cycle's wrapped time near t_first and T, and the absolute frames Blender computes the automatic
// handles in (near frame 1e4 its handles differ from the model's, and from its own at frame 0 for
// the same keys, by 3e-4 in value: far/10000/quad/wide against far/0/quad/wide), a slope error
// carried along an extrapolated line. Each moves the value by a time rounding times a slope: the
// local one, or a handle's, which follows the chords. Measured 3.65 (far/10000/auto_clamped/narrow:
// 45 frames past the last key along a handle 0.83 frames long at frame 1e4); 2.5 away from far
// frames (easing/sine/out, the sine's rounding near its end key); 8 leaves a factor 2.2.
constexpr double value_tol = 8;
// The fidelity criterion: the error relative to the channel's recorded value range; held
// by every channel but those far from frame 0 (up to 2.7e-4 at frame 1e4, from Blender's
// rounding of absolute frames in its handles, above; their frame-0 twins far/0/* hold it).
constexpr double range_tol = 1e-5;

nlohmann::json load(const std::string& file) {
  std::ifstream in(curvebench::testing::source_dir() + "/tests/data/recorded/" + file);
  if (!in) throw std::runtime_error("tests/data/recorded/" + file + " not found");
  return nlohmann::json::parse(in);
}

const nlohmann::json& recording() {
  static const nlohmann::json doc = load("blender_heldout.json");
  return doc;
}

// Curves mixing auto keys with vector, aligned and free ones (scripts/peers/blender_fcurves_request.py
// --mixed), recorded as the held-out ones are.
const nlohmann::json& mixed_recording() {
  static const nlohmann::json doc = load("blender_mixed.json");
  return doc;
}

// The steepest chord between consecutive keys (0 for a single key).
double steepest_chord(const nlohmann::json& spec) {
  double s = 0;
  const auto& keys = spec.at("keys");
  for (std::size_t i = 1; i < keys.size(); ++i)
    s = std::max(s, std::abs(keys[i].at("value").get<double>() - keys[i - 1].at("value").get<double>()) /
                        (keys[i].at("time").get<double>() - keys[i - 1].at("time").get<double>()));
  return s;
}

// The largest |value| of a key or handle in the spec, and a key's value plus elastic's amplitude.
double extent_of(const nlohmann::json& spec) {
  double e = 0;
  for (const auto& k : spec.at("keys")) {
    const double v = std::abs(k.at("value").get<double>());
    e = std::max(e, v);
    for (const char* side : {"handle_left", "handle_right"})
      if (k.contains(side)) e = std::max(e, std::abs(k.at(side)[1].get<double>()));
    if (k.contains("amplitude")) e = std::max(e, v + k.at("amplitude").get<double>());
  }
  return e;
}

struct feature_stats {
  std::size_t channels = 0, samples = 0, refused = 0;
  double worst = 0;        // eps_float of the scale
  double worst_range = 0;  // relative to the value range
};

// The channels curvebench refuses, each with the reason: only these may be refused (none).
const std::set<std::string> expected_refused{};

TEST(blender_heldout, recording_is_in_the_common_format) {
  const auto& doc = recording();
  EXPECT_EQ(doc.at("tool"), "blender");
  const auto& src = doc.at("source");
  for (const char* f : {"implementation", "repository", "commit", "version", "build", "recorded", "command"})
    EXPECT_TRUE(src.contains(f)) << f;
  EXPECT_EQ(src.at("version"), "3.4.1");
  EXPECT_GE(doc.at("channels").size(), 100u);
  for (const auto& c : doc.at("channels")) {
    EXPECT_EQ(c.at("spec").at("tool"), "blender") << c.at("name");
    EXPECT_EQ(c.at("t").size(), c.at("value").size()) << c.at("name");
    EXPECT_FALSE(c.at("features").empty()) << c.at("name");
  }
}

void reproduces(const nlohmann::json& doc, const std::set<std::string>& refusals) {
  const double eps_f = std::numeric_limits<float>::epsilon();
  std::map<std::string, feature_stats> by_feature;
  feature_stats all;
  std::set<std::string> refused;
  for (const auto& c : doc.at("channels")) {
    const std::string name = c.at("name");
    const nlohmann::json& spec = c.at("spec");
    const curvebench::io::field f = curvebench::io::root(spec, name);
    std::optional<channel_values> tool;
    std::string why;
    try {
      tool = channel_values_of(f, check_against::tool);
      // The float model is built on first evaluation for some specs: evaluate once here.
      (void)tool->at(c.at("t")[0].get<double>(), 0);
    } catch (const std::exception& e) {
      why = e.what();
      tool.reset();
    }
    std::vector<feature_stats*> stats{&all};
    for (const auto& ft : c.at("features")) stats.push_back(&by_feature[ft.get<std::string>()]);
    for (feature_stats* s : stats) ++s->channels;
    if (!tool) {
      refused.insert(name);
      for (feature_stats* s : stats) ++s->refused;
      // The recording holds the CLI's message for the same refusal.
      ASSERT_TRUE(c.contains("refused")) << name << ": refused here (" << why << ") but not when recorded";
      EXPECT_NE(c.at("refused").get<std::string>().find(why.substr(0, 40)), std::string::npos)
          << name << ": recorded '" << c.at("refused") << "', now '" << why << "'";
      continue;
    }
    EXPECT_FALSE(c.contains("refused")) << name << ": recorded as refused, evaluated now";
    const auto& ts = c.at("t");
    const auto& vs = c.at("value");
    double lo = vs[0].get<double>(), hi = lo;
    for (const auto& v : vs) lo = std::min(lo, v.get<double>()), hi = std::max(hi, v.get<double>());
    const double range = hi > lo ? hi - lo : std::max(1.0, std::abs(hi));
    const double extent = extent_of(spec), chord = steepest_chord(spec);
    const double t0 = spec.at("keys").front().at("time"), period = spec.at("keys").back().at("time").get<double>() - t0;
    const bool far = name.rfind("far/", 0) == 0 && name.rfind("far/0/", 0) != 0;
    double worst = 0, worst_range = 0;
    for (std::size_t i = 0; i < ts.size(); ++i) {
      const double t = ts[i], blender = vs[i];
      const std::optional<double> v = tool->at(t, 0);
      ASSERT_TRUE(v.has_value()) << name << " t=" << t;
      const std::optional<double> d1 = tool->at(t, 1);
      const double slope = d1 && std::isfinite(*d1) ? std::abs(*d1) : 0.0;
      const double scale = std::abs(blender) + extent + (std::abs(t) + std::abs(t0) + period) * std::max(slope, chord);
      const double e = std::abs(*v - blender) / (eps_f * scale);
      const double er = std::abs(*v - blender) / range;
      EXPECT_LE(e, value_tol) << name << " t=" << t << " Blender " << blender << " model " << *v;
      // Away from far frames the time's rounding carries nothing: the fidelity criterion holds.
      if (!far) {
        EXPECT_LE(er, range_tol) << name << " t=" << t << " Blender " << blender << " model " << *v;
      }
      worst = std::max(worst, e);
      worst_range = std::max(worst_range, er);
    }
    for (feature_stats* s : stats) {
      s->samples += ts.size();
      s->worst = std::max(s->worst, worst);
      s->worst_range = std::max(s->worst_range, worst_range);
    }
  }
  EXPECT_EQ(refused, refusals);
  std::printf("%-32s %8s %8s %8s %14s %14s\n", "feature", "channels", "refused", "samples", "eps_f(scale)", "of range");
  for (const auto& [name, s] : by_feature)
    std::printf("%-32s %8zu %8zu %8zu %14.3g %14.3g\n", name.c_str(), s.channels, s.refused, s.samples, s.worst,
                s.worst_range);
  std::printf("%-32s %8zu %8zu %8zu %14.3g %14.3g\n", "all", all.channels, all.refused, all.samples, all.worst,
              all.worst_range);
  EXPECT_EQ(all.channels, doc.at("channels").size());
  EXPECT_EQ(all.refused, refusals.size());
}

}  // namespace

TEST(blender_heldout, tool_model_reproduces_blender) { reproduces(recording(), expected_refused); }

// Before the runs of auto keys were smoothed on their own (blender_smooth_run), every one of these
// was refused (and the cyclic ones wrap their runs past the joint); all 52 are checked by the same
// tolerances.
TEST(blender_heldout, mixed_handles_reproduce_blender) {
  const auto& doc = mixed_recording();
  EXPECT_EQ(doc.at("source").at("version"), "3.4.1");
  EXPECT_GE(doc.at("channels").size(), 50u);
  reproduces(doc, expected_refused);
}
