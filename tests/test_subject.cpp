// The subject API (harness/subject.hpp) on a straight polyline whose points, s(u) and u(s) are
// exact in closed form, and on a curvebench curve measured as its own subject: the records carry
// the subject's name, the sweeps' sample counts and the errors of the check core; the gate reads
// them; bad subjects get errors naming them.
#include "harness/subject.hpp"

#include "harness/sweep.hpp"

#include "curvebench/core/error.hpp"
#include "curvebench/io/spec.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <stdexcept>
#include <string>

using namespace curvebench::harness;
using curvebench::invalid_input;
using curvebench::point;
using ::testing::HasSubstr;

namespace {

constexpr double eps = std::numeric_limits<double>::epsilon();

const subject_options quick = [] {
  subject_options o;
  o.quick = true;
  return o;
}();

// (0,0) -> (3,4) -> (3,10) at parameters 0, 1, 2: s(u) = 5u on [0, 1], 5 + 6 (u - 1) on [1, 2];
// L = 11; the size (largest coordinate magnitude) is 10.
const nlohmann::json bent = nlohmann::json::parse(
    R"({"name": "bent", "group": "straight", "type": "polyline", "points": [[0,0],[3,4],[3,10]]})");

point<double, 2> bent_at(double u) {
  return u <= 1 ? point<double, 2>(3 * u, 4 * u) : point<double, 2>(3, 4 + 6 * (u - 1));
}
double bent_s(double u) { return u <= 1 ? 5 * u : 5 + 6 * (u - 1); }
double bent_u(double s) { return s <= 5 ? s / 5 : 1 + (s - 5) / 6; }

subject<2> exact_subject() {
  subject<2> s;
  s.name = "exact";
  s.eval = bent_at;
  s.length = [](double u0, double u1) { return bent_s(u1) - bent_s(u0); };
  s.inverse = bent_u;
  return s;
}

const nlohmann::json& record(const nlohmann::json& results, const std::string& quantity) {
  for (const auto& r : results["records"])
    if (r["quantity"] == quantity) return r;
  throw std::runtime_error("no " + quantity + " record");
}

TEST(Subject, ExactSubjectMeasuresRoundingOnlyWithTheSweepsSampleCounts) {
  const auto results = measure_spec(bent, exact_subject(), quick);
  ASSERT_EQ(results["records"].size(), 4u);
  for (const auto& r : results["records"]) {
    EXPECT_EQ(r["method"], "exact");
    EXPECT_EQ(r["case"], "bent");
    EXPECT_EQ(r["group"], "straight");
    EXPECT_TRUE(r["subject"].get<bool>());
  }
  const sweep w = settings(true);
  // Points: 3u and 4 + 6(u - 1) round once, half an ulp of values <= 10 at most: < 0.5 ulps of size.
  EXPECT_LT(record(results, "eval")["error"].get<double>(), 0.5);
  EXPECT_EQ(record(results, "eval")["evaluations"].get<double>(), static_cast<double>(w.eval_params));
  // Lengths and u(s): a few roundings of numbers <= 11, relative to L = 11: within 4 eps.
  EXPECT_LT(record(results, "length")["error"].get<double>(), 4 * eps);
  EXPECT_LT(record(results, "s_of_u")["error"].get<double>(), 4 * eps);
  EXPECT_EQ(record(results, "s_of_u")["evaluations"].get<double>(), static_cast<double>(w.params));
  EXPECT_LT(record(results, "u_of_s")["error"].get<double>(), 4 * eps);
  EXPECT_EQ(record(results, "u_of_s")["evaluations"].get<double>(), static_cast<double>(w.params));
  ASSERT_EQ(results["cases"].size(), 1u);
  EXPECT_EQ(results["cases"][0]["family"], "polyline");
}

TEST(Subject, InjectedErrorsAreMeasured) {
  subject<2> s = exact_subject();
  s.name = "off";
  // 80 eps is a multiple of the ulp of every x < 4, so x + 80 eps is exact: 8 ulps of size 10.
  s.eval = [](double u) { return point<double, 2>(bent_at(u) + point<double, 2>(80 * eps, 0)); };
  s.length = [](double u0, double u1) { return (bent_s(u1) - bent_s(u0)) * (1 + 1e-6); };
  s.inverse = [](double t) { return std::min(bent_u(t) + 1e-3, 2.0); };
  const auto results = measure_spec(bent, s, quick);
  EXPECT_NEAR(record(results, "eval")["error"].get<double>(), 8.0, 1e-6);
  // The whole length 11 (1 + 1e-6): 1e-6 of L; s(u) the largest at u = 2, also 1e-6.
  EXPECT_NEAR(record(results, "length")["error"].get<double>(), 1e-6, 1e-12);
  EXPECT_NEAR(record(results, "s_of_u")["error"].get<double>(), 1e-6, 1e-12);
  // u + 1e-3 moves s by 5e-3 or 6e-3: at most 6e-3 / 11.
  EXPECT_NEAR(record(results, "u_of_s")["error"].get<double>(), 6e-3 / 11, 1e-9);
}

TEST(Subject, CurveSubjectOfTheSpecsOwnCurveIsWithinRounding) {
  const nlohmann::json arch = nlohmann::json::parse(R"({"type": "bezier", "points": [[0,0],[1,2],[3,2],[4,0]]})");
  const auto c = curvebench::io::curve_from_spec<double, 2>(curvebench::io::root(arch, "arch"));
  const auto results = measure_spec(arch, curve_subject("library_bezier", c), quick);
  ASSERT_EQ(results["records"].size(), 1u);
  // de Casteljau in double: a few roundings of values <= 4 (the accuracy runner measures ~1 ulp).
  EXPECT_LT(record(results, "eval")["error"].get<double>(), 4.0);
  EXPECT_EQ(record(results, "eval")["method"], "library_bezier");
}

TEST(Subject, GateReadsSubjectRecords) {
  subject<2> s;
  s.name = "off";
  s.eval = [](double u) { return point<double, 2>(bent_at(u) + point<double, 2>(80 * eps, 0)); };  // 8 ulps
  const auto results = measure_spec(bent, s, quick);
  const auto dir = std::filesystem::temp_directory_path() / "curvebench_test_subject";
  std::filesystem::create_directories(dir);
  const std::string pass = (dir / "pass.json").string(), fail = (dir / "fail.json").string(),
                    unknown = (dir / "unknown.json").string();
  std::ofstream(pass) << R"({"rules": [{"quantity": "eval", "method": "off", "max_error": 16}]})";
  std::ofstream(fail) << R"({"rules": [{"quantity": "eval", "method": "off", "max_error": 1}]})";
  std::ofstream(unknown) << R"({"rules": [{"quantity": "eval", "method": "other", "max_error": 1}]})";
  EXPECT_TRUE(subject_gate(results, pass).empty());
  const auto breaches = subject_gate(results, fail);
  ASSERT_EQ(breaches.size(), 1u);
  EXPECT_THAT(breaches[0], HasSubstr("eval/off/* at case bent"));
  EXPECT_THAT(breaches[0], HasSubstr("> allowed 1"));
  // "other" is no subject of these results and no method of the vocabulary.
  EXPECT_THROW((void)subject_gate(results, unknown), invalid_input);
  EXPECT_THROW((void)subject_gate(results, (dir / "missing.json").string()), invalid_input);
}

TEST(Subject, MeasureCaseFindsTheCaseAndMergeListsItOnce) {
  const auto dir = std::filesystem::temp_directory_path() / "curvebench_test_subject_cases";
  std::filesystem::create_directories(dir);
  nlohmann::json c = bent;
  c["reason"] = "test";
  std::ofstream((dir / "bent.json").string()) << c.dump();
  const auto a = measure_case(dir.string(), "bent", exact_subject(), quick);
  EXPECT_EQ(a["cases"][0]["reason"], "test");
  subject<2> other = exact_subject();
  other.name = "other";
  const auto merged = merge_results(a, measure_case(dir.string(), "bent", other, quick));
  EXPECT_EQ(merged["records"].size(), 8u);
  EXPECT_EQ(merged["cases"].size(), 1u);
  try {
    (void)measure_case(dir.string(), "nope", exact_subject());
    FAIL() << "no error for an unknown case";
  } catch (const invalid_input& e) {
    EXPECT_THAT(e.what(), HasSubstr("case nope"));
  }
}

TEST(Subject, BadSubjectsAreNamed) {
  subject<2> nameless = exact_subject();
  nameless.name = "";
  EXPECT_THROW((void)measure_spec(bent, nameless), invalid_input);
  subject<2> empty;
  empty.name = "empty";
  try {
    (void)measure_spec(bent, empty);
    FAIL();
  } catch (const invalid_input& e) {
    EXPECT_THAT(e.what(), HasSubstr("subject empty: has no function"));
  }
  subject<3> flat;
  flat.name = "flat";
  flat.eval = [](double) { return point<double, 3>(0, 0, 0); };
  try {
    (void)measure_spec(bent, flat);
    FAIL();
  } catch (const invalid_input& e) {
    EXPECT_THAT(e.what(), HasSubstr("the subject flat is 3D"));
  }
  subject<2> throws = exact_subject();
  throws.name = "throws";
  throws.eval = [](double u) -> point<double, 2> {
    if (u > 1.5) throw std::domain_error("past my table");
    return bent_at(u);
  };
  try {
    (void)measure_spec(bent, throws);
    FAIL();
  } catch (const invalid_input& e) {
    EXPECT_THAT(e.what(), HasSubstr("subject throws: eval(u = "));
    EXPECT_THAT(e.what(), HasSubstr("past my table"));
  }
  // A NaN answer must not drop out of the max and pass the gate: it is an error naming it.
  subject<2> nan_eval = exact_subject();
  nan_eval.name = "nan_eval";
  nan_eval.eval = [](double u) -> point<double, 2> {
    return u > 1.5 ? point<double, 2>(std::numeric_limits<double>::quiet_NaN(), 0.0) : bent_at(u);
  };
  try {
    (void)measure_spec(bent, nan_eval);
    FAIL();
  } catch (const invalid_input& e) {
    EXPECT_THAT(e.what(), HasSubstr("subject nan_eval eval"));
    EXPECT_THAT(e.what(), HasSubstr("column x"));
    EXPECT_THAT(e.what(), HasSubstr("is not finite"));
  }
}

// An inverse answer outside the domain is the subject's error, measured and recorded with a
// finding naming it (one float ulp past the end aborted the whole measurement and
// recorded nothing). Beyond the end u = 2 by d the row is measured as (|s(2) - s| + 6 d) / L, the
// polyline's last segment having speed 6 and L = 11.
TEST(Subject, InverseOutsideTheDomainIsAFindingNotAnAbort) {
  subject<2> ulp = exact_subject();
  ulp.name = "one_ulp_past";
  ulp.inverse = [](double s) { return s >= 11 ? std::nextafter(2.0, 3.0) : bent_u(s); };
  const auto r = measure_spec(bent, ulp, quick);
  const double beyond = std::nextafter(2.0, 3.0) - 2.0;
  EXPECT_LE(record(r, "u_of_s")["error"].get<double>(), 6 * beyond / 11 + 2 * eps);
  EXPECT_GT(record(r, "u_of_s")["error"].get<double>(), 0.0);
  ASSERT_EQ(r["findings"].size(), 1u);
  EXPECT_THAT(r["findings"][0].get<std::string>(), HasSubstr("subject one_ulp_past: "));
  EXPECT_THAT(r["findings"][0].get<std::string>(), HasSubstr("is outside the domain [0, 2]"));
  subject<2> outside = exact_subject();
  outside.name = "outside";
  outside.inverse = [](double) { return 2.5; };
  const auto o = measure_spec(bent, outside, quick);
  // The target s = 0 answered with 2.5: |s(2) - 0| / L + 0.5 x 6 / L = 1 + 3 / 11.
  EXPECT_NEAR(record(o, "u_of_s")["error"].get<double>(), 1 + 3.0 / 11, 1e-12);
  EXPECT_GE(o["findings"].size(), 9u);  // every target of the quick sweep
}

}  // namespace

// A channel subject: a keyframe channel checked by time through the subject API. The
// channel is linear from (0, 0) to (10, 5), held constant outside, so its value is
// clamp(t, 0, 10) / 2 in closed form; halving in double is exact, so the exact subject's records
// are 0 and a subject off by 2^-30 past t = 5 (and one slope off by 1/4) is reported at exactly
// that, in ulps of double of the value range 5.
TEST(Subject, ChannelSubjectIsCheckedByTime) {
  const nlohmann::json ramp = nlohmann::json::parse(R"({"name": "ramp", "type": "channel", "tool": "exact",
    "keys": [{"time": 0, "value": 0, "interpolation": "linear"}, {"time": 10, "value": 5}]})");
  const auto value = [](double t) { return std::clamp(t, 0.0, 10.0) / 2; };
  channel_subject s;
  s.name = "my_ramp";
  s.value = value;
  // At a key time the slope is the segment's (the first key starts it, the last ends it).
  s.slope = [](double t) { return t >= 0 && t <= 10 ? 0.5 : 0.0; };
  const auto exact = measure_spec(ramp, s, quick);
  ASSERT_EQ(exact["records"].size(), 2u);  // value, slope
  for (const auto& r : exact["records"]) {
    EXPECT_EQ(r["method"], "my_ramp");
    EXPECT_EQ(r["case"], "ramp");
    EXPECT_EQ(r["quantity"], "eval");
    EXPECT_EQ(r["error"].get<double>(), 0.0) << r;
  }
  EXPECT_EQ(exact["cases"][0]["value_range"].get<double>(), 5.0);
  const double off = std::ldexp(1.0, -30);
  channel_subject late = s;
  late.name = "late";
  late.value = [&](double t) { return value(t) + (t > 5 ? off : 0.0); };
  late.slope = [](double t) { return t >= 0 && t <= 10 ? 0.75 : 0.0; };
  const auto r = measure_spec(ramp, late, quick);
  EXPECT_DOUBLE_EQ(record(r, "eval")["error"].get<double>(), off / (eps * 5));
  EXPECT_DOUBLE_EQ(r["records"][1]["error"].get<double>(), 0.25 / (eps * 0.5));
  // The gate reads the records by the subject's name.
  const auto dir = std::filesystem::temp_directory_path() / "curvebench_channel_subject";
  std::filesystem::create_directories(dir);
  const auto rules = (dir / "rules.json").string();
  std::ofstream(rules) << R"({"rules": [{"quantity": "eval", "method": "late", "max_error": 1e6}]})";
  EXPECT_EQ(subject_gate(r, rules).size(), 1u);  // the slope's record is over, the value's is not
  // A curve case is not a channel; a channel subject needs a value function.
  channel_subject none;
  none.name = "none";
  EXPECT_THROW((void)measure_spec(ramp, none, quick), invalid_input);
  try {
    (void)measure_spec(bent, s, quick);
    FAIL();
  } catch (const invalid_input& e) {
    EXPECT_THAT(e.what(), HasSubstr("not a channel"));
  }
}
