// The CI gate names every breach, passes clean results, and fails on an injected regression.
#include "harness/gate.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

using nlohmann::json;
using curvebench::harness::check_gate;
using ::testing::HasSubstr;

namespace {
json thresholds() {
  return json::parse(R"J({"rules": [
    {"quantity": "length", "method": "gauss_kronrod", "group": "*", "max_error": 1e-13, "honest": true,
     "why": "test rule"},
    {"quantity": "length", "method": "forward_difference", "group": "smooth", "min_order": 1.8, "why": "O(h^2)"},
    {"quantity": "length", "method": "forward_difference", "setting": "N=64", "max_error": 1e-4, "why": "one setting"}
  ]})J");
}
json clean_results() {
  return json::parse(R"J({
    "records": [
      {"case": "helix", "group": "smooth", "quantity": "length", "method": "gauss_kronrod", "setting": "tol=1e-14",
       "error": 2e-16, "estimate": 1e-15, "bounded": true, "evaluations": 30, "status": "converged"},
      {"case": "loop", "group": "loop", "quantity": "length", "method": "gauss_kronrod", "setting": "tol=1e-14",
       "error": 4e-15, "estimate": 9e-15, "bounded": true, "evaluations": 90, "status": "converged"},
      {"case": "helix", "group": "smooth", "quantity": "length", "method": "forward_difference", "setting": "N=64",
       "error": 1e-5, "estimate": null, "bounded": null, "evaluations": 65, "status": "ok"}
    ],
    "orders": [
      {"case": "helix", "group": "smooth", "quantity": "length", "method": "forward_difference", "observed": 2.01, "theory": 2}
    ]})J");
}
}  // namespace

TEST(gate, passes_clean_results) { EXPECT_TRUE(check_gate(clean_results(), thresholds()).empty()); }

TEST(gate, names_each_breach_with_measured_and_allowed) {
  json r = clean_results();
  r["records"][1]["error"] = 3e-10;     // injected accuracy regression
  r["records"][0]["bounded"] = false;   // a dishonest estimate
  r["orders"][0]["observed"] = 1.0;     // a deliberately coarse table: order dropped
  const auto breaches = check_gate(r, thresholds());
  ASSERT_EQ(breaches.size(), 3u);
  EXPECT_EQ(breaches[0].rule, "length/gauss_kronrod/*");
  EXPECT_EQ(breaches[0].where, "case helix setting tol=1e-14");
  EXPECT_THAT(breaches[0].message, HasSubstr("not honest"));
  EXPECT_EQ(breaches[1].where, "case loop setting tol=1e-14");
  EXPECT_EQ(breaches[1].message, "error 3e-10 > allowed 1e-13");
  EXPECT_EQ(breaches[2].message, "observed order 1 < allowed 1.8");
}

TEST(gate, a_rule_may_name_one_setting) {
  json r = clean_results();
  r["records"][2]["error"] = 2e-4;  // the N=64 table got worse
  const auto breaches = check_gate(r, thresholds());
  ASSERT_EQ(breaches.size(), 1u);
  EXPECT_EQ(breaches[0].rule, "length/forward_difference/*/N=64");
  EXPECT_EQ(breaches[0].message, "error 0.0002 > allowed 0.0001");
  r["records"][2]["setting"] = "N=32";  // the named setting vanished
  EXPECT_EQ(check_gate(r, thresholds()).back().message,
            "rule matched no result record (method or case group missing)");
}

TEST(gate, missing_method_or_nan_error_is_a_breach) {
  json r = clean_results();
  r["orders"] = json::array();
  r["records"][0]["error"] = nullptr;  // e.g. NaN written as null
  const auto breaches = check_gate(r, thresholds());
  ASSERT_EQ(breaches.size(), 2u);
  EXPECT_THAT(breaches[0].message, HasSubstr("no error measured"));
  EXPECT_THAT(breaches[1].message, HasSubstr("matched no observed order"));
}
