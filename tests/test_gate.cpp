// The CI gate names every breach, passes clean results, and fails on an injected regression.
#include "harness/gate.hpp"
#include "harness/record.hpp"
#include "support/source_dir.hpp"

#include "curvebench/core/error.hpp"
#include "curvebench/io/registry.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <limits>
#include <optional>
#include <string>
#include <vector>

using curvebench::harness::check_gate;
using nlohmann::json;
using ::testing::HasSubstr;

namespace {
json thresholds() {
  return json::parse(R"J({"rules": [
    {"quantity": "length", "method": "adaptive_gk", "group": "*", "max_error": 1e-13, "honest": true,
     "why": "test rule"},
    {"quantity": "length", "method": "forward_difference", "group": "smooth", "min_order": 1.8, "why": "O(h^2)"},
    {"quantity": "length", "method": "forward_difference", "setting": "steps=64", "max_error": 1e-4, "why": "one setting"}
  ]})J");
}
json clean_results() {
  return json::parse(R"J({
    "records": [
      {"case": "helix", "group": "smooth", "quantity": "length", "method": "adaptive_gk", "setting": "tol=1e-14",
       "error": 2e-16, "estimate": 1e-15, "bounded": true, "evaluations": 30, "status": "converged"},
      {"case": "loop", "group": "loop", "quantity": "length", "method": "adaptive_gk", "setting": "tol=1e-14",
       "error": 4e-15, "estimate": 9e-15, "bounded": true, "evaluations": 90, "status": "converged"},
      {"case": "helix", "group": "smooth", "quantity": "length", "method": "forward_difference", "setting": "steps=64",
       "error": 1e-5, "estimate": null, "bounded": null, "evaluations": 65, "status": "not_guaranteed"}
    ],
    "orders": [
      {"case": "helix", "group": "smooth", "quantity": "length", "method": "forward_difference", "observed": 2.01, "theory": 2}
    ]})J");
}
}  // namespace

TEST(gate, passes_clean_results) { EXPECT_TRUE(check_gate(clean_results(), thresholds()).empty()); }

// A record's "reason" (why a status is not converged) is read by no rule: results with it,
// text or null, or without it, or with a value of another type, are judged the same.
TEST(gate, ignores_the_reason_of_a_record) {
  for (const json& reason : {json("table: chord sums' ratio outside [3, 6]"), json(), json(3), json::array()}) {
    json r = clean_results();
    for (auto& rec : r["records"]) rec["reason"] = reason;
    EXPECT_TRUE(check_gate(r, thresholds()).empty()) << reason;
    r["records"][1]["error"] = 3e-10;
    r["records"][1]["estimate"] = 1e-9;
    const auto breaches = check_gate(r, thresholds());
    ASSERT_EQ(breaches.size(), 1u) << reason;
    EXPECT_EQ(breaches[0].message, "error 3e-10 > allowed 1e-13");
  }
}

TEST(gate, names_each_breach_with_measured_and_allowed) {
  json r = clean_results();
  r["records"][1]["error"] = 3e-10;    // injected accuracy regression...
  r["records"][1]["estimate"] = 1e-9;  // ...whose estimate still bounds it (else a second breach)
  r["records"][0]["bounded"] = false;  // a dishonest estimate
  r["orders"][0]["observed"] = 1.0;    // a deliberately coarse table: order dropped
  const auto breaches = check_gate(r, thresholds());
  ASSERT_EQ(breaches.size(), 3u);
  EXPECT_EQ(breaches[0].rule, "length/adaptive_gk/*");
  EXPECT_EQ(breaches[0].where, "case helix setting tol=1e-14");
  EXPECT_THAT(breaches[0].message, HasSubstr("not honest"));
  EXPECT_EQ(breaches[1].where, "case loop setting tol=1e-14");
  EXPECT_EQ(breaches[1].message, "error 3e-10 > allowed 1e-13");
  EXPECT_EQ(breaches[2].message, "observed order 1 < allowed 1.8");
}

TEST(gate, a_rule_may_name_one_setting) {
  json r = clean_results();
  r["records"][2]["error"] = 2e-4;  // the steps=64 table got worse
  const auto breaches = check_gate(r, thresholds());
  ASSERT_EQ(breaches.size(), 1u);
  EXPECT_EQ(breaches[0].rule, "length/forward_difference/*/steps=64");
  EXPECT_EQ(breaches[0].message, "error 0.0002 > allowed 0.0001");
  r["records"][2]["setting"] = "steps=32";  // the named setting vanished
  EXPECT_EQ(check_gate(r, thresholds()).back().message,
            "rule matched no result record: none has setting \"steps=64\"");  // the field that matches nothing
  json long_setting = thresholds();
  long_setting["rules"][0]["setting"] = std::string(9000, 's');
  const auto cut = check_gate(r, long_setting);
  EXPECT_LT(cut.back().rule.size() + cut.back().message.size(), 400u);  // both shown cut, as every message
}

TEST(gate, missing_method_or_nan_error_is_a_breach) {
  json r = clean_results();
  r["orders"] = json::array();
  r["records"][0]["error"] = nullptr;  // e.g. NaN written as null
  const auto breaches = check_gate(r, thresholds());
  ASSERT_EQ(breaches.size(), 3u);
  EXPECT_THAT(breaches[0].message, HasSubstr("no error measured (allowed"));
  // Its estimate 1e-15 has no error beside it: honesty cannot be shown, whatever "bounded" says.
  EXPECT_THAT(breaches[1].message, HasSubstr("estimate 1e-15 with no error measured: its honesty cannot be checked"));
  EXPECT_THAT(breaches[2].message, HasSubstr("matched no observed order"));
}

TEST(gate, rejects_a_rule_naming_an_id_outside_the_vocabulary) {
  const auto message = [](const char* rules) {
    try {
      (void)check_gate(clean_results(), json::parse(rules));
    } catch (const curvebench::invalid_input& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  // composite_gauss3 was the records' name before the vocabulary: a stale threshold must not pass silently.
  EXPECT_EQ(
      message(R"({"rules": [{"quantity": "*", "honest": true},
                                   {"quantity": "length", "method": "composite_gauss3", "min_order": 3}]})"),
      "thresholds rule 1: method \"composite_gauss3\" is not a method of the vocabulary (curvebench list methods)");
  EXPECT_EQ(message(R"({"version": 2, "rules": [{"quantity": "*", "honest": true}]})"),
            "thresholds: \"version\" 2: this curvebench reads thresholds of version 1");
  EXPECT_EQ(message(R"({"version": 1, "rules": [{"quantity": "*", "honest": true}]})"), "accepted");
  EXPECT_EQ(message(R"({"rules": [{"quantity": "lenght", "method": "*", "max_error": 1}]})"),
            "thresholds rule 0: quantity \"lenght\" is not a quantity of the vocabulary");
  EXPECT_THAT(message(R"({"rules": [{"quantity": "length", "method": "newton", "max_error": 1}]})"),
              HasSubstr("thresholds rule 0: method \"newton\" has no length records"));
  EXPECT_THAT(message(R"({"rules": [{"method": "de_casteljau", "max_error": 1}]})"),
              HasSubstr("rule 0: method \"de_casteljau\" is not a method"));
  // For eval the methods are "default" and the algorithms of the family registry; "*" always.
  EXPECT_EQ(message(R"({"rules": [{"quantity": "eval", "method": "de_casteljau", "max_error": 8},
                                   {"quantity": "eval", "method": "default", "max_error": 8},
                                   {"quantity": "*", "method": "*", "honest": true}]})"),
            "accepted");
  EXPECT_THAT(message(R"({"rules": [{"quantity": "eval", "method": "de_casteljeau", "max_error": 8}]})"),
              HasSubstr("thresholds rule 0: method \"de_casteljeau\" is not an evaluation algorithm of any family"));
  // A name of 9 kB is shown cut, not whole (the gate fuzz target's bounded-message property: a rule
  // quoting a 9 kB quantity made an 8.8 kB message in CI's smoke run).
  for (const char* key : {"quantity", "method"}) {
    const json rule = {{"rules", json::array({{{key, std::string(9000, '[')}, {"max_error", 1}}})}};
    const std::string m = message(rule.dump().c_str());
    EXPECT_LT(m.size(), 400u) << key;
    EXPECT_THAT(m, HasSubstr(std::string("thresholds rule 0: ") + key + " \"[[[")) << key;
  }
}

TEST(gate, the_checked_in_thresholds_name_vocabulary_ids_only) {
  std::ifstream in(curvebench::testing::source_dir() + "/reports/thresholds.json");
  ASSERT_TRUE(in) << "reports/thresholds.json not found";
  const json t = json::parse(in);
  ASSERT_GT(t["rules"].size(), 10u);
  EXPECT_NO_THROW((void)check_gate(json{{"records", json::array()}}, t, "results", "reports/thresholds.json"));
}

// reports/thresholds_full.json, which scripts/bench.sh gates every run on (quick and full) without
// `|| true`: an honesty rule over every quantity, method and group, and nothing a full sweep's
// errors could breach otherwise. One dishonest record anywhere must fail it; clean results pass.
TEST(gate, the_full_sweep_gate_is_honesty_on_every_record) {
  std::ifstream in(curvebench::testing::source_dir() + "/reports/thresholds_full.json");
  ASSERT_TRUE(in) << "reports/thresholds_full.json not found";
  const json t = json::parse(in);
  ASSERT_FALSE(t["rules"].empty());
  for (const json& rule : t["rules"]) {
    EXPECT_TRUE(rule.value("honest", false));
    EXPECT_FALSE(rule.contains("max_error") || rule.contains("min_order")) << rule.dump();
  }
  EXPECT_TRUE(check_gate(clean_results(), t, "results", "reports/thresholds_full.json").empty());
  for (std::size_t i : {0u, 1u}) {
    json r = clean_results();
    r["records"][i]["error"] = 1e-3;  // errors alone are not this gate's business, when bounded
    r["records"][i]["estimate"] = 2e-3;
    EXPECT_TRUE(check_gate(r, t, "results", "reports/thresholds_full.json").empty());
    r["records"][i]["bounded"] = false;  // a file's false is kept
    auto breaches = check_gate(r, t, "results", "reports/thresholds_full.json");
    ASSERT_EQ(breaches.size(), 1u);
    EXPECT_THAT(breaches[0].message, HasSubstr("not honest"));
    // An estimate below its error breaches whatever the file's "bounded" says (formerly a
    // record claiming true beside an estimate 1e-30 and an error 1 passed).
    r["records"][i]["bounded"] = true;
    r["records"][i]["estimate"] = 1e-4;
    breaches = check_gate(r, t, "results", "reports/thresholds_full.json");
    ASSERT_EQ(breaches.size(), 1u);
    EXPECT_THAT(breaches[0].message, HasSubstr("estimate 0.0001 < true error 0.001 (estimate not honest)"));
  }
}

// ---- malformed files: a typo must not switch the gate off ------------------------------------

namespace {
/// The message of the invalid_input check_gate throws for these files, or "accepted".
std::string gate_error(const json& results, const char* thresholds_text) {
  try {
    (void)check_gate(results, json::parse(thresholds_text), "res.json", "thr.json");
  } catch (const curvebench::invalid_input& e) {
    return e.what();
  }
  return "accepted";
}
}  // namespace

// These three passed with exit 0: the misspelt rule checked nothing, the others had no rule at all.
TEST(gate, a_misspelt_key_in_a_rule_is_an_error_naming_the_file_rule_and_key) {
  EXPECT_EQ(gate_error(clean_results(), R"({"rules": [{"quantity": "length", "max_error": 1},
                                                      {"quantity": "length", "max_eror": 1e-13}]})"),
            "thr.json rule 1: unknown key \"max_eror\" (known keys: quantity, method, group, setting, max_error, "
            "min_order, honest, why)");
}

TEST(gate, rules_must_be_a_non_empty_array_of_objects) {
  EXPECT_EQ(gate_error(clean_results(), R"({"rules": []})"),
            "thr.json: \"rules\" is empty: a gate without rules checks nothing");
  EXPECT_EQ(gate_error(clean_results(), R"({"rules": {"quantity": "length", "max_error": 1}})"),
            "thr.json: \"rules\" must be an array, got {\"max_error\":1,\"quantity\":\"length\"}");
  EXPECT_EQ(gate_error(clean_results(), R"({"rule": [{"max_error": 1}]})"),
            "thr.json: expected an object holding a \"rules\" array, got {\"rule\":[{\"max_error\":1}]}");
  EXPECT_EQ(gate_error(clean_results(), R"([{"max_error": 1}])"),
            "thr.json: expected an object holding a \"rules\" array, got [{\"max_error\":1}]");
  EXPECT_EQ(gate_error(clean_results(), R"({"rules": [{"max_error": 1}, "length"]})"),
            "thr.json rule 1: expected an object, got \"length\"");
}

TEST(gate, each_rule_needs_a_check_and_values_of_the_right_type) {
  EXPECT_EQ(gate_error(clean_results(), R"({"rules": [{"quantity": "length", "why": "no number"}]})"),
            "thr.json rule 0: no check (give max_error, min_order or \"honest\": true)");
  EXPECT_EQ(gate_error(clean_results(), R"({"rules": [{"quantity": "length", "honest": false}]})"),
            "thr.json rule 0: no check (give max_error, min_order or \"honest\": true)");
  EXPECT_EQ(gate_error(clean_results(), R"({"rules": [{"max_error": "1e-13"}]})"),
            "thr.json rule 0: max_error \"1e-13\" is not a number");
  EXPECT_EQ(gate_error(clean_results(), R"({"rules": [{"honest": "yes"}]})"),
            "thr.json rule 0: honest \"yes\" is not true or false");
  EXPECT_EQ(gate_error(clean_results(), R"({"rules": [{"method": 3, "max_error": 1}]})"),
            "thr.json rule 0: method 3 is not a string");
  // A negative max_error breaches on every record, a min_order <= 0 checks nothing: refused.
  EXPECT_EQ(gate_error(clean_results(), R"({"rules": [{"max_error": -1}]})"),
            "thr.json rule 0: max_error -1 is negative (an error is >= 0)");
  EXPECT_EQ(gate_error(clean_results(), R"({"rules": [{"min_order": -5}]})"),
            "thr.json rule 0: min_order -5 is not positive (an observed order of convergence is > 0)");
  // The vocabulary checks name the file too.
  EXPECT_EQ(gate_error(clean_results(), R"({"rules": [{"quantity": "lenght", "max_error": 1}]})"),
            "thr.json rule 0: quantity \"lenght\" is not a quantity of the vocabulary");
}

TEST(gate, results_must_hold_a_records_array_of_objects) {
  const char* rules = R"({"rules": [{"quantity": "length", "max_error": 1}]})";
  EXPECT_EQ(gate_error(json::object(), rules), "res.json: expected an object holding a \"records\" array, got {}");
  EXPECT_EQ(gate_error(json{{"records", json::object()}}, rules), "res.json: \"records\" must be an array, got {}");
  json r = clean_results();
  r["records"][1] = 7;
  EXPECT_EQ(gate_error(r, rules), "res.json: records[1]: expected an object, got 7");
  r = clean_results();
  r["records"][2]["error"] = "small";
  EXPECT_EQ(gate_error(r, rules), "res.json: records[2].error: expected a number or null, got \"small\"");
  r = clean_results();
  r["records"][0]["case"] = 12;
  EXPECT_EQ(gate_error(r, rules), "res.json: records[0].case: expected a string, got 12");
  r = clean_results();
  r["orders"] = json::object();
  EXPECT_EQ(gate_error(r, rules), "res.json: \"orders\" must be an array, got {}");
  r = clean_results();
  r["orders"][0]["observed"] = true;
  EXPECT_EQ(gate_error(r, rules), "res.json: orders[0].observed: expected a number or null, got true");
  // Null where the runner writes null is fine: a null order is a breach, not an exception.
  r = clean_results();
  r["orders"][0]["observed"] = nullptr;
  const auto breaches = check_gate(r, thresholds());
  ASSERT_EQ(breaches.size(), 1u);
  EXPECT_EQ(breaches[0].message, "observed order nan < allowed 1.8");
}

// A user's implementation (curvebench check, harness/check.hpp) writes records with "subject": true
// and its own name as the method: rules may name it when the results hold it, and only then.
TEST(gate, a_rule_may_name_a_subject_of_the_results) {
  json r = clean_results();
  r["records"].push_back(json::parse(R"({"case": "arch", "group": "subject", "quantity": "eval", "method": "my_engine",
      "setting": "", "error": 3.5, "estimate": null, "bounded": null, "evaluations": 11,
      "status": "not_guaranteed", "subject": true})"));
  r["records"].push_back(json::parse(R"({"case": "arch", "group": "subject", "quantity": "eval", "method": "my_engine",
      "setting": "derivative=1", "error": 40, "estimate": null, "bounded": null, "evaluations": 11,
      "status": "not_guaranteed", "subject": true})"));
  const json rules = json::parse(R"({"rules": [
      {"quantity": "eval", "method": "my_engine", "setting": "", "max_error": 4, "why": "test"},
      {"quantity": "eval", "method": "my_engine", "setting": "derivative=1", "max_error": 8, "why": "test"}]})");
  const auto breaches = check_gate(r, rules);
  ASSERT_EQ(breaches.size(), 1u);  // the point passes at 3.5 <= 4, the derivative breaches at 40 > 8
  EXPECT_EQ(breaches[0].rule, "eval/my_engine/*/derivative=1");
  EXPECT_EQ(breaches[0].where, "case arch setting derivative=1");
  EXPECT_EQ(breaches[0].message, "error 40 > allowed 8");
  // The same name without a subject record is still a misspelt method, and the quantity is still checked.
  EXPECT_THROW((void)check_gate(clean_results(), rules), curvebench::invalid_input);
  r["records"][3]["subject"] = false;
  r["records"][4].erase("subject");
  EXPECT_THROW((void)check_gate(r, rules), curvebench::invalid_input);
  r["records"][3]["subject"] = true;
  EXPECT_THROW((void)check_gate(r, json::parse(R"({"rules": [{"quantity": "evals", "method": "my_engine",
      "max_error": 4}]})")),
               curvebench::invalid_input);
}

// The gate reads the families' evaluation algorithms from the vocabulary, not the registry: the
// two lists must be the same, in the registry's order (each algorithm once), or a rule naming a
// family's algorithm would be refused (or a removed one accepted).
TEST(gate, the_vocabulary_lists_the_registrys_evaluation_algorithms) {
  std::vector<std::string> registry;
  for (const curvebench::io::family_descriptor& f : curvebench::io::families())
    for (std::string_view a : f.algorithms)
      if (std::find(registry.begin(), registry.end(), a) == registry.end()) registry.emplace_back(a);
  std::vector<std::string> vocabulary;
  for (const curvebench::harness::vocab::algorithm* a : curvebench::harness::vocab::eval_algorithms)
    vocabulary.emplace_back(a->id);
  EXPECT_EQ(vocabulary, registry);
  for (const std::string& a : registry) EXPECT_NE(curvebench::harness::vocab::find_algorithm(a), nullptr) << a;
}

// One record type (harness/record.hpp): what the writer writes the reader reads back, field by
// field, for a measured record, a subject's and a peer's; bounded is computed once, from the
// numbers, and read as written (the gate judges a results file's own "bounded").
TEST(record, the_reader_reads_what_the_writer_writes) {
  namespace h = curvebench::harness;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  h::record m = h::record::measured("helix", "smooth", "length", "gauss", "n=4", 1e-9, 2e-9, 28, "cap_hit");
  m.reason = "evaluation budget reached (measured 2e-09, bound 1e-12)";
  ASSERT_TRUE(m.bounded.has_value());
  EXPECT_TRUE(*m.bounded);
  m.extra["rms"] = 0.5;
  m.extra["not_a_number"] = nan;  // written as null, as every number that is not finite
  const json mj = h::to_json(m);
  EXPECT_EQ(mj["bounded"], true);
  EXPECT_EQ(mj["reason"], "evaluation budget reached (measured 2e-09, bound 1e-12)");
  EXPECT_TRUE(mj["not_a_number"].is_null());
  EXPECT_FALSE(mj.contains("subject") || mj.contains("peer"));
  EXPECT_EQ(h::to_json(h::read_record(mj, "m")), mj);

  h::record s = h::record::measured("arch", "subject", "eval", "mine", "", 3.5, nan, 11, "not_guaranteed");
  s.subject = true;
  const json sj = h::to_json(s);
  EXPECT_TRUE(sj["estimate"].is_null());
  EXPECT_TRUE(sj["bounded"].is_null());
  EXPECT_TRUE(sj["reason"].is_null());  // none given
  EXPECT_EQ(sj["subject"], true);
  EXPECT_EQ(h::to_json(h::read_record(sj, "s")), sj);

  // An estimate below the error: bounded false (the gate's honesty breach).
  h::record p =
      h::record::measured("arch", "smooth", "length", "peer_gsl_qag", "tol=1e-10", 2e-10, 1e-10, 45, "converged");
  p.peer = h::peer_fields{"GSL 2.7.1", "success", 120, "adaptive_gk", "tol=1e-10", 80, nan};
  const json pj = h::to_json(p);
  EXPECT_EQ(pj["bounded"], false);
  EXPECT_EQ(pj["peer"], true);
  EXPECT_EQ(pj["counterpart"], json({{"method", "adaptive_gk"}, {"setting", "tol=1e-10"}}));
  EXPECT_FALSE(pj.contains("counterpart_error"));
  EXPECT_EQ(h::to_json(h::read_record(pj, "p")), pj);

  // A results file's false is kept; its true is measured from the estimate and the error.
  json dishonest = mj;
  dishonest["bounded"] = false;
  EXPECT_EQ(h::read_record(dishonest, "d").bounded, std::optional<bool>(false));
  json lying = mj;
  lying["estimate"] = 0.5 * lying["error"].get<double>();
  lying["bounded"] = true;
  EXPECT_EQ(h::read_record(lying, "l").bounded, std::optional<bool>(false));
  EXPECT_THROW((void)h::read_record(json{{"case", 3}}, "r"), curvebench::invalid_input);
}
