// The Maya animCurve model (channel/maya.hpp, tool "maya") against Autodesk AnimX, Maya's own
// evaluator: tests/data/recorded/animx_curves.json holds curves and AnimX's values at given times, recorded
// by scripts/peers/animx_record.cpp from AnimX built with 64-bit time (the file's "source" says
// which commit and how). Every channel's spec is read with curvebench's own reader (the
// "channel" family, tool "maya"), evaluated by the double model at each recorded time and compared
// with AnimX's value; the largest error is printed per feature (tangent type, weighting,
// regression, infinity mode on each side). A channel the model refuses is counted and fails.
#include "curvebench/io/families/channel.hpp"
#include "curvebench/io/spec.hpp"
#include "support/source_dir.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <fstream>
#include <iostream>
#include <limits>
#include <map>
#include <string>

namespace cb = curvebench;

namespace {

// The tolerance, in eps(double) of the channel's scale S(t) = V + |dv/dt(t)| (|t| + H): V the
// largest |value| of the channel (its keys and AnimX's values, so that cycle_relative's offsets
// far from the keys count), H its longest segment. Both sides evaluate the same polynomials in
// double by different routes, and each route rounds:
//  - AnimX evaluates a non-weighted segment in power form from the control points (slope =
//    (y1 - y0) / (x1 - x0) with x1 = t0 + x / 3, which loses the bits of t0 relative to the
//    handle: a few eps of |t| times the slope), normalizes non-weighted tangents to unit length,
//    evaluates linear infinity as tan(atan(slope)), and solves a weighted segment's time by
//    isolating the roots of its power form: a few eps of V + |slope| H each;
//  - outside the keys it wraps time as range * |frac((t - t_first) / range)| and rounds it to
//    Maya's ticks, and cycle_relative adds (cycles + 1) * (v_last - v_first): eps |t| times the
//    slope and a few eps of V; the model wraps with the same ratio and offsets (maya.hpp), and
//    snaps to a key where AnimX's tick rounding does, so the side of a period boundary agrees.
// Summed without cancellation that is about 16 eps of S; the bound is 32, twice that, for the
// terms not counted (the root isolation's last bits). The first comparison with AnimX
// measured agreeing curves at 1.5e-14 of the range, about 70 eps of it. Measured worst over the
// 112 recorded curves: 7.5 eps (linear infinity and auto tangents); the test prints it per feature.
constexpr double tolerance_eps = 32;

struct feature_stats {
  std::size_t channels = 0, agree = 0;
  double worst = 0;  // in eps(double) of S(t)
};

}  // namespace

TEST(maya_animx, model_reproduces_animx_values) {
  std::ifstream in(curvebench::testing::source_dir() + "/tests/data/recorded/animx_curves.json");
  ASSERT_TRUE(in) << "tests/data/recorded/animx_curves.json not found";
  const nlohmann::json data = nlohmann::json::parse(in);
  ASSERT_EQ(data.at("tool"), "maya");
  const auto& source = data.at("source");
  ASSERT_EQ(source.at("commit").get<std::string>().size(), 40u) << "the AnimX commit the values came from";

  const double eps = std::numeric_limits<double>::epsilon();
  std::map<std::string, feature_stats> by_feature;
  feature_stats all;
  std::size_t values = 0, refused = 0;
  for (const auto& c : data.at("channels")) {
    const std::string name = c.at("name");
    SCOPED_TRACE(name);
    const auto& ts = c.at("t");
    const auto& vs = c.at("value");
    ASSERT_EQ(ts.size(), vs.size());
    double worst = 0;
    if (c.contains("refused")) {
      ++refused;
      ADD_FAILURE() << "recorded as refused: " << c.at("refused");
      worst = std::numeric_limits<double>::infinity();
    } else {
      const auto m = cb::io::channel_model_of_spec<double>(cb::io::root(c.at("spec"), name));
      double v_max = 0, h_max = 0;
      const auto& keys = c.at("spec").at("keys");
      for (std::size_t i = 0; i < keys.size(); ++i) {
        v_max = std::max(v_max, std::abs(keys[i].at("value").get<double>()));
        if (i > 0) h_max = std::max(h_max, keys[i].at("time").get<double>() - keys[i - 1].at("time").get<double>());
      }
      for (const auto& v : vs) v_max = std::max(v_max, std::abs(v.get<double>()));
      for (std::size_t j = 0; j < ts.size(); ++j) {
        const double t = ts[j], animx = vs[j];
        const double model = m.at(t, 0);
        const double scale = v_max + std::abs(m.at(t, 1)) * (std::abs(t) + h_max);
        const double err = std::abs(model - animx) / (eps * scale);
        worst = std::max(worst, err);
        EXPECT_LE(err, tolerance_eps) << "t = " << t << ": model " << model << ", AnimX " << animx;
        ++values;
      }
    }
    const bool agrees = worst <= tolerance_eps;
    for (const auto& f : c.at("features")) {
      auto& s = by_feature[f.get<std::string>()];
      ++s.channels;
      s.agree += agrees ? 1 : 0;
      s.worst = std::max(s.worst, worst);
    }
    ++all.channels;
    all.agree += agrees ? 1 : 0;
    all.worst = std::max(all.worst, worst);
  }
  std::cout << "AnimX " << source.at("commit").get<std::string>() << ": " << all.agree << " of " << all.channels
            << " channels agree within " << tolerance_eps << " eps of V + |v'| (|t| + H) (" << values << " values, "
            << refused << " refused), worst " << all.worst << " eps\n";
  for (const auto& [feature, s] : by_feature)
    std::cout << "  " << feature << ": " << s.agree << " / " << s.channels << ", worst " << s.worst << " eps\n";
  // The recording covers every tangent type AnimX evaluates, both weightings, the regression
  // correction and every infinity mode on both sides (a regenerated file that lost one fails).
  for (const char* f :
       {"tangent:fixed", "tangent:auto", "tangent:flat", "tangent:linear", "tangent:step", "tangent:step_next",
        "weighted", "non_weighted", "regression", "pre:constant", "pre:linear", "pre:cycle", "pre:cycle_relative",
        "pre:oscillate", "post:constant", "post:linear", "post:cycle", "post:cycle_relative", "post:oscillate"})
    EXPECT_GE(by_feature[f].channels, 5u) << f;
  EXPECT_GE(all.channels, 60u);
}
