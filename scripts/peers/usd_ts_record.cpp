// Records what OpenUSD's Ts library computes for the splines of a request written by
// scripts/peers/usd_ts_request.py: each channel's "usd" spec is built as a TsSpline (double
// values, the spec's curve type, knots with their interpolation, value, pre-value, tangent widths
// and slopes, extrapolation, inner-loop parameters), with the spec's anti_regression mode as Ts's
// authoring mode (TsAntiRegressionAuthoringSelector while the knots are set, so that SetKnots
// adjusts regressive tangents as an authoring tool would), then evaluated at each requested time
// with TsSpline::Eval (the value) and TsSpline::EvalPreValue (the value an instant before). The
// output is tests/data/recorded/usd_ts_splines.json in the common recording format, plus per channel the
// tangent widths Ts holds after authoring ("ts_widths": [pre, post] per knot), its pre-values, and
// the internal checks Ts reported failed while evaluating ("ts_errors": time and message).
// A channel whose spline has a Hermite curve segment gets "unverified" and no values: at the
// recorded commit TsSpline::Eval does not evaluate Hermite segments (it warns "Hermite evaluation
// is not yet implemented" and returns 0).
//
// This program is the project's own code; it uses OpenUSD only through its public headers and
// libraries, built locally (nothing is downloaded). Build: scripts/peers/usd_ts_build.sh extracts
// pxr/base of OpenUSD at the recorded commit from a local git clone into /tmp/usd/src, builds the
// `ts` target in /tmp/usd/build (CMake Release with -DPXR_ENABLE_PYTHON_SUPPORT=OFF
// -DPXR_BUILD_IMAGING=OFF -DPXR_BUILD_USD_IMAGING=OFF -DPXR_BUILD_TESTS=OFF and the other
// optional parts off, Debian's libtbb-dev) and compiles this file against it:
//   g++ -std=c++17 -O2 -I/tmp/usd/build/include -I/tmp/usd/src \
//     scripts/peers/usd_ts_record.cpp -o /tmp/usd/usd_ts_record \
//     -L/tmp/usd/build/pxr/base/ts -lusd_ts ... (vt gf tf trace js arch) -ltbb
// Then:
//   python3 scripts/peers/usd_ts_request.py > /tmp/usd_ts_request.json
//   /tmp/usd/usd_ts_record /tmp/usd_ts_request.json tests/data/recorded/usd_ts_splines.json
//   CURVEBENCH_SOURCE_DIR=$PWD build-test/tests/test_usd_ts |
//       python3 scripts/peers/usd_ts_refusals.py tests/data/recorded/usd_ts_splines.json
// (the last step records which specs curvebench's reader refuses, and why).
#include "pxr/base/tf/errorMark.h"
#include "pxr/base/tf/type.h"
#include "pxr/base/ts/knot.h"
#include "pxr/base/ts/knotMap.h"
#include "pxr/base/ts/raii.h"
#include "pxr/base/ts/spline.h"
#include "pxr/base/ts/types.h"

#include <nlohmann/json.hpp>

#include <cstdio>
#include <fstream>
#include <iostream>
#include <stdexcept>
#include <string>

PXR_NAMESPACE_USING_DIRECTIVE

namespace {

const char* const kCommit = "899c19efdc20786bc6cfc2c8202b8d32c3a5c794";

TsInterpMode interp_of(const std::string& s) {
  if (s == "held") return TsInterpHeld;
  if (s == "linear") return TsInterpLinear;
  if (s == "curve") return TsInterpCurve;
  throw std::runtime_error("interpolation " + s);
}

TsExtrapMode extrap_of(const std::string& s) {
  if (s == "held") return TsExtrapHeld;
  if (s == "linear") return TsExtrapLinear;
  if (s == "sloped") return TsExtrapSloped;
  if (s == "loop_repeat") return TsExtrapLoopRepeat;
  if (s == "loop_reset") return TsExtrapLoopReset;
  if (s == "loop_oscillate") return TsExtrapLoopOscillate;
  throw std::runtime_error("extrapolation " + s);
}

TsAntiRegressionMode mode_of(const std::string& s) {
  if (s == "none") return TsAntiRegressionNone;
  if (s == "contain") return TsAntiRegressionContain;
  if (s == "keep_ratio") return TsAntiRegressionKeepRatio;
  if (s == "keep_start") return TsAntiRegressionKeepStart;
  throw std::runtime_error("anti_regression " + s);
}

double num(const nlohmann::json& j, const char* key, double fallback) {
  return j.contains(key) ? j.at(key).get<double>() : fallback;
}

// The spline of a "usd" spec (the fields of io/tools/usd.hpp), knots set under the spec's
// anti-regression authoring mode (keep_ratio when absent, curvebench's default and Ts's).
TsSpline spline_of(const nlohmann::json& spec, bool* hermite_curve) {
  const TsCurveType curve_type =
      spec.value("curve_type", std::string("bezier")) == "hermite" ? TsCurveTypeHermite : TsCurveTypeBezier;
  TsSpline spline(TfType::Find<double>());
  spline.SetCurveType(curve_type);
  TsKnotMap knots;
  const auto& ks = spec.at("knots");
  *hermite_curve = false;
  for (std::size_t i = 0; i < ks.size(); ++i) {
    const auto& k = ks[i];
    TsKnot knot(TfType::Find<double>(), curve_type);
    knot.SetTime(k.at("time").get<double>());
    knot.SetValue(k.at("value").get<double>());
    const TsInterpMode interp = interp_of(k.value("interpolation", std::string("curve")));
    knot.SetNextInterpolation(interp);
    if (curve_type == TsCurveTypeHermite && interp == TsInterpCurve && i + 1 < ks.size()) *hermite_curve = true;
    if (k.contains("pre_value")) knot.SetPreValue(k.at("pre_value").get<double>());
    if (curve_type == TsCurveTypeBezier) {
      knot.SetPreTanWidth(num(k, "pre_width", 0));
      knot.SetPostTanWidth(num(k, "post_width", 0));
    }
    knot.SetPreTanSlope(num(k, "pre_slope", 0));
    knot.SetPostTanSlope(num(k, "post_slope", 0));
    knots.insert(knot);
  }
  TsExtrapolation pre(extrap_of(spec.value("before", std::string("held"))));
  TsExtrapolation post(extrap_of(spec.value("after", std::string("held"))));
  pre.slope = num(spec, "slope_before", 0);
  post.slope = num(spec, "slope_after", 0);
  spline.SetPreExtrapolation(pre);
  spline.SetPostExtrapolation(post);
  if (spec.contains("inner_loops")) {
    const auto& l = spec.at("inner_loops");
    TsLoopParams p;
    p.protoStart = num(l, "proto_start", 0);
    p.protoEnd = num(l, "proto_end", 0);
    p.numPreLoops = l.value("pre_loops", 0);
    p.numPostLoops = l.value("post_loops", 0);
    p.valueOffset = num(l, "value_offset", 0);
    spline.SetInnerLoopParams(p);
  }
  {
    TsAntiRegressionAuthoringSelector selector(mode_of(spec.value("anti_regression", std::string("keep_ratio"))));
    spline.SetKnots(knots);
  }
  return spline;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: usd_ts_record REQUEST.json OUT.json\n");
    return 2;
  }
  std::ifstream in(argv[1]);
  const nlohmann::json request = nlohmann::json::parse(in);
  nlohmann::json out;
  out["tool"] = "usd";
  out["source"] = {
      {"implementation",
       "OpenUSD Ts (pxr/base/ts): TsSpline::Eval and TsSpline::EvalPreValue, knots set with "
       "TsSpline::SetKnots under TsAntiRegressionAuthoringSelector(the spec's anti_regression)"},
      {"repository", "https://github.com/PixarAnimationStudios/OpenUSD"},
      {"commit", kCommit},
      {"version", "24.11 (tag v24.11-rc1, branch dev, 2024-10-17); pxr_version 0.24.11"},
      {"build",
       "only pxr/base (arch, tf, gf, pegtl, js, trace, work, plug, vt, ts), target ts, CMake Release "
       "(-O3 -DNDEBUG), GCC 12.2, Debian's oneTBB 2021.8, Python, imaging, usd, tests off; double "
       "values and double time (TsTime)"},
      {"recorded", "2026-11-26"},
      {"command",
       "python3 scripts/peers/usd_ts_request.py > /tmp/usd_ts_request.json && bash scripts/peers/usd_ts_build.sh "
       "&& /tmp/usd/usd_ts_record /tmp/usd_ts_request.json tests/data/recorded/usd_ts_splines.json && "
       "CURVEBENCH_SOURCE_DIR=$PWD build-test/tests/test_usd_ts | python3 scripts/peers/usd_ts_refusals.py "
       "tests/data/recorded/usd_ts_splines.json"}};
  out["channels"] = nlohmann::json::array();
  for (const auto& c : request.at("channels")) {
    nlohmann::json r = c;
    bool hermite_curve = false;
    const TsSpline spline = spline_of(c.at("spec"), &hermite_curve);
    nlohmann::json widths = nlohmann::json::array();
    for (const TsKnot& k : spline.GetKnots())
      widths.push_back(spline.GetCurveType() == TsCurveTypeBezier
                           ? nlohmann::json::array({k.GetPreTanWidth(), k.GetPostTanWidth()})
                           : nlohmann::json::array());
    r["ts_widths"] = widths;
    if (hermite_curve) {
      r["unverified"] =
          "OpenUSD Ts at this commit does not evaluate Hermite curve segments (TsSpline::Eval warns "
          "\"Hermite evaluation is not yet implemented\" and returns 0): no values recorded";
      out["channels"].push_back(r);
      continue;
    }
    nlohmann::json values = nlohmann::json::array(), pre_values = nlohmann::json::array();
    nlohmann::json errors = nlohmann::json::array();
    for (const auto& tj : c.at("t")) {
      const double t = tj.get<double>();
      double v = 0, pv = 0;
      TfErrorMark mark;  // Ts's failed internal checks (TF_VERIFY) at this time, recorded with it
      if (!spline.Eval(t, &v) || !spline.EvalPreValue(t, &pv))
        throw std::runtime_error(c.at("name").get<std::string>() + ": no value at " + std::to_string(t));
      for (auto it = mark.GetBegin(); it != mark.GetEnd(); ++it)
        errors.push_back({{"t", t}, {"message", it->GetCommentary()}});
      mark.Clear();
      values.push_back(v);
      pre_values.push_back(pv);
    }
    r["value"] = values;
    r["pre_value"] = pre_values;
    if (!errors.empty()) r["ts_errors"] = errors;
    out["channels"].push_back(r);
  }
  std::ofstream(argv[2]) << out.dump(1) << "\n";
  std::fprintf(stderr, "%zu channels\n", out["channels"].size());
  return 0;
}
