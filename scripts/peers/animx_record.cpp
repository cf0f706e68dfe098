// Records Maya animCurve values from Autodesk AnimX (Apache-2.0, github.com/Autodesk/animx), Maya's
// own animation-curve evaluator published as a library: the peer behind tests/data/recorded/animx_curves.json.
// This file is curvebench's code; it only calls AnimX's public entry points (evaluateCurve,
// autoTangent) and its flat-tangent helper, through AnimX's header. It downloads nothing.
//
// Build against a local AnimX checkout in /tmp (never inside this repository), 64-bit time as in
// Maya since 2017 update 3 (AnimX's CMake option MAYA_64BIT_TIME_PRECISION, its default: time and
// tangents are double, 141120000 ticks per second). AnimX's src/internal/math.h uses
// std::numeric_limits without including <limits>, hence the -include.
//   cmake -S /tmp/animx -B /tmp/animx/build -DCMAKE_BUILD_TYPE=Release -DMAYA_64BIT_TIME_PRECISION=ON
//         -DANIMX_BUILD_MAYA_TESTSUITE=OFF -DANIMX_BUILD_SHARED=OFF -DANIMX_BUILD_STATIC=ON
//         "-DCMAKE_CXX_FLAGS=-include limits"
//   cmake --build /tmp/animx/build
//   g++ -std=c++17 -O2 -DMAYA_64BIT_TIME_PRECISION -I/tmp/animx/src scripts/peers/animx_record.cpp
//       /tmp/animx/build/src/libAnimX.a -o /tmp/animx_record
// Run:
//   python3 scripts/peers/animx_request.py --commit <AnimX commit> > /tmp/animx_request.json
//   /tmp/animx_record /tmp/animx_request.json tests/data/recorded/animx_curves.json
//
// The request (scripts/peers/animx_request.py) is {"source": {...}, "channels": [{"name", "features",
// "weighted", "pre", "post", "keys": [{"time", "value", "in_type", "out_type", "in": [x, y],
// "out": [x, y]}], "t": [...]}]}, times in seconds (AnimX's unit: it rounds wrapped infinity times
// to Maya's ticks of 1/141120000 s). The output is the common recording format: the source copied,
// each channel's "spec" (a curvebench "tool": "maya" channel spec of the same keys) with "t" and
// AnimX's "value" at each t, 17 significant digits.
//
// What Maya would store per tangent type (AnimX evaluates the stored tangent (x, y), the Bezier
// control point being key +- (x, y) / 3, and computes only the auto family):
//  - fixed: the request's (x, y).
//  - auto: AnimX's autoTangent (legacy Auto; at an end key it gives the flat tangent).
//  - flat, and the tangent beside a step / step_next side: AnimX's flat-tangent helper (value 0,
//    time the adjacent segment's duration); curvebench's model also takes slope 0 for a step side.
//  - linear: the chord to the neighbour on that side (the end key's missing side: the chord on
//    the other side), time the segment's duration; a span whose start key's out and end key's in
//    are both linear is flagged linearInterpolation (AnimX then interpolates it linearly), as
//    AnimX's header documents the flag. These two are this driver's rule (Maya Help), not AnimX's.
// Non-weighted curves get their tangents normalized to unit length, as AnimX's tangent functions
// do for Hermite curves (the slope y / x is what the Hermite segment uses).
#include <animx.h>

#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <stdexcept>
#include <string>
#include <vector>

namespace adsk {
// AnimX's flat tangent (src/animx.cpp; external linkage, not declared in animx.h).
void flatTangent(bool calculateInTangent, KeyTimeValue key, const KeyTimeValue* prevKey, const KeyTimeValue* nextKey,
                 CurveInterpolatorMethod curveInterpolationMethod, seconds& newTanX, seconds& newTanY);
}  // namespace adsk

namespace {

using json = nlohmann::json;

adsk::TangentType tangent_type(const std::string& name) {
  if (name == "fixed") return adsk::TangentType::Fixed;
  if (name == "linear") return adsk::TangentType::Linear;
  if (name == "flat") return adsk::TangentType::Flat;
  if (name == "step") return adsk::TangentType::Step;
  if (name == "step_next") return adsk::TangentType::StepNext;
  if (name == "auto") return adsk::TangentType::Auto;
  throw std::runtime_error("tangent type '" + name + "': AnimX computes fixed, linear, flat, step, step_next, auto");
}

adsk::InfinityType infinity_type(const std::string& name) {
  if (name == "constant") return adsk::InfinityType::Constant;
  if (name == "linear") return adsk::InfinityType::Linear;
  if (name == "cycle") return adsk::InfinityType::Cycle;
  if (name == "cycle_relative") return adsk::InfinityType::CycleRelative;
  if (name == "oscillate") return adsk::InfinityType::Oscillate;
  throw std::runtime_error("infinity '" + name + "'");
}

// An ICurve over keys held in memory, with every tangent already resolved.
class memory_curve : public adsk::ICurve {
 public:
  std::vector<adsk::Keyframe> keys;
  adsk::InfinityType pre = adsk::InfinityType::Constant, post = adsk::InfinityType::Constant;
  bool weighted = false;

  bool keyframeAtIndex(int index, adsk::Keyframe& key) const override {
    if (index < 0 || index >= static_cast<int>(keys.size())) return false;
    key = keys[static_cast<std::size_t>(index)];
    return true;
  }
  bool keyframe(double time, adsk::Keyframe& key) const override {
    if (keys.empty()) return false;
    for (const auto& k : keys)
      if (k.time >= time) {
        key = k;
        return true;
      }
    key = keys.back();
    return true;
  }
  bool first(adsk::Keyframe& key) const override { return keyframeAtIndex(0, key); }
  bool last(adsk::Keyframe& key) const override { return keyframeAtIndex(static_cast<int>(keys.size()) - 1, key); }
  adsk::InfinityType preInfinityType() const override { return pre; }
  adsk::InfinityType postInfinityType() const override { return post; }
  bool isWeighted() const override { return weighted; }
  unsigned int keyframeCount() const override { return static_cast<unsigned int>(keys.size()); }
  bool isStatic() const override { return false; }
};

void normalize(adsk::seconds& x, adsk::seconds& y) {
  const double length = std::sqrt(x * x + y * y);
  if (length > 0) x /= length, y /= length;
}

// The stored tangent of key i on one side (see the header).
adsk::Tangent resolve(const json& request_keys, std::size_t i, bool in_side, bool weighted) {
  const json& k = request_keys[i];
  const std::size_t n = request_keys.size();
  const std::string type_name = k.value(in_side ? "in_type" : "out_type", std::string("auto"));
  adsk::Tangent tan{tangent_type(type_name), 0, 0};
  adsk::KeyTimeValue key{k.at("time").get<double>(), k.at("value").get<double>()}, prev{}, next{};
  const bool has_prev = i > 0, has_next = i + 1 < n;
  if (has_prev) prev = {request_keys[i - 1].at("time").get<double>(), request_keys[i - 1].at("value").get<double>()};
  if (has_next) next = {request_keys[i + 1].at("time").get<double>(), request_keys[i + 1].at("value").get<double>()};
  const auto method = weighted ? adsk::CurveInterpolatorMethod::Bezier : adsk::CurveInterpolatorMethod::Hermite;
  switch (tan.type) {
    case adsk::TangentType::Fixed: {
      const json& v = k.at(in_side ? "in" : "out");
      tan.x = v.at(0).get<double>();
      tan.y = v.at(1).get<double>();
      break;
    }
    case adsk::TangentType::Auto:
      adsk::autoTangent(in_side, tan.type, key, has_prev ? &prev : nullptr, has_next ? &next : nullptr, method, tan.x,
                        tan.y);
      break;
    case adsk::TangentType::Flat:
    case adsk::TangentType::Step:
    case adsk::TangentType::StepNext:
      adsk::flatTangent(in_side, key, has_prev ? &prev : nullptr, has_next ? &next : nullptr, method, tan.x, tan.y);
      break;
    case adsk::TangentType::Linear: {
      const bool toward_prev = has_prev && (in_side || !has_next);
      const adsk::KeyTimeValue& a = toward_prev ? prev : key;
      const adsk::KeyTimeValue& b = toward_prev ? key : next;
      tan.x = b.time - a.time;
      tan.y = b.value - a.value;
      if (!weighted) normalize(tan.x, tan.y);
      break;
    }
    default: break;
  }
  return tan;
}

std::string repr(double v) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 3) {
    std::cerr << "usage: animx_record REQUEST.json OUT.json\n";
    return 2;
  }
  try {
    std::ifstream in(argv[1]);
    const json request = json::parse(in);
    json out_channels = json::array();
    std::string body;
    for (const json& ch : request.at("channels")) {
      const json& rk = ch.at("keys");
      memory_curve curve;
      curve.weighted = ch.value("weighted", false);
      curve.pre = infinity_type(ch.value("pre", std::string("constant")));
      curve.post = infinity_type(ch.value("post", std::string("constant")));
      for (std::size_t i = 0; i < rk.size(); ++i) {
        adsk::Keyframe k{};
        k.time = rk[i].at("time").get<double>();
        k.value = rk[i].at("value").get<double>();
        k.index = static_cast<int>(i);
        k.tanIn = resolve(rk, i, true, curve.weighted);
        k.tanOut = resolve(rk, i, false, curve.weighted);
        k.quaternionW = 1.0;
        k.linearInterpolation = i + 1 < rk.size() && k.tanOut.type == adsk::TangentType::Linear &&
                                rk[i + 1].value("in_type", std::string("auto")) == "linear";
        curve.keys.push_back(k);
      }
      // The spec curvebench reads: the same keys and types, fixed tangents' vectors.
      json spec = {{"type", "channel"}, {"tool", "maya"}, {"weighted", curve.weighted}};
      json spec_keys = json::array();
      for (const json& k : rk) {
        json s = {{"time", k.at("time")}, {"value", k.at("value")}};
        s["in_type"] = k.value("in_type", std::string("auto"));
        s["out_type"] = k.value("out_type", std::string("auto"));
        if (s["in_type"] == "fixed") s["in"] = k.at("in");
        if (s["out_type"] == "fixed") s["out"] = k.at("out");
        spec_keys.push_back(s);
      }
      spec["keys"] = spec_keys;
      spec["pre"] = ch.value("pre", std::string("constant"));
      spec["post"] = ch.value("post", std::string("constant"));
      // Written by hand so that every number keeps 17 significant digits.
      std::string t_text, v_text;
      for (const json& t : ch.at("t")) {
        const double time = t.get<double>();
        const double value = adsk::evaluateCurve(time, curve);
        t_text += (t_text.empty() ? "" : ", ") + repr(time);
        v_text += (v_text.empty() ? "" : ", ") + repr(value);
      }
      std::string spec_text = spec.dump();
      if (!body.empty()) body += ",\n";
      body += "  {\"name\": " + json(ch.at("name")).dump() + ", \"features\": " + ch.at("features").dump() +
              ",\n   \"spec\": " + spec_text + ",\n   \"t\": [" + t_text + "],\n   \"value\": [" + v_text + "]}";
    }
    std::ofstream out(argv[2]);
    out << "{\"tool\": \"maya\",\n \"source\": " << request.at("source").dump() << ",\n \"channels\": [\n"
        << body << "\n ]}\n";
    return 0;
  } catch (const std::exception& e) {
    std::cerr << "animx_record: " << e.what() << "\n";
    return 1;
  }
}
