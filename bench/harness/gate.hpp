// The CI gate: compares accuracy results against checked-in thresholds and names every breach.
//
// Results (written by the accuracy runner, reports/accuracy.json) hold "records", one per
// case x quantity x method x setting:
//   {"case", "group", "quantity", "method", "setting", "error", "estimate", "bounded", "evaluations", "status"}
// ("estimate"/"bounded" are null where a method gives no estimate; "status" is a result_status
// name, "not_guaranteed" for eval records) and "orders", one per case x quantity x method:
// {"case", "group", "quantity", "method", "observed", "theory"}. Quantity and method ids are those of
// harness/vocabulary.hpp (eval records name evaluation algorithms), settings "key=value[,key=value]".
// Thresholds (reports/thresholds.json) hold "rules":
//   {"quantity", "method", "group", "setting"  (each may be "*" or left out: any),
//    "max_error"  (optional: every matching record's error must be <= it),
//    "min_order"  (optional: every matching observed order must be >= it),
//    "honest"     (optional: every matching record with an estimate must have bounded = true),
//    "why"        (the reason for the number: measured figure and margin)}
// A rule that matches no record is itself a breach: a gate must not pass because a method or a
// case group disappeared. A rule naming a quantity or method that is not in the vocabulary is an
// error (invalid_input naming the rule's index and the value): a misspelt or renamed id must not
// silently turn into a rule that matches nothing. For quantity "eval" the methods are "default" and
// the evaluation algorithms the families offer in the family registry (io/registry.hpp).
// Records of a user's own implementation (a "subject": `curvebench check`, harness/check.hpp) carry
// "subject": true and the subject's name as "method"; a rule may name such a method when the
// results hold a subject record of that name (the quantity must still be in the vocabulary).
#pragma once

#include "harness/vocabulary.hpp"

#include "curvebench/core/error.hpp"
#include "curvebench/io/registry.hpp"

#include <nlohmann/json.hpp>

#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace curvebench::harness {

struct breach {
  std::string rule;     // "length/gauss_kronrod/smooth"
  std::string where;    // "case helix_3d setting tol=1e-12"
  std::string message;  // "error 3.1e-10 > allowed 1e-13"
};

namespace detail {
inline bool matches(const nlohmann::json& rule, const nlohmann::json& record) {
  for (const char* key : {"quantity", "method", "group", "setting"}) {
    const std::string want = rule.value(key, std::string("*"));
    if (want != "*" && record.value(key, std::string()) != want) return false;
  }
  return true;
}
inline std::string rule_name(const nlohmann::json& rule) {
  std::string name = rule.value("quantity", std::string("*")) + "/" + rule.value("method", std::string("*")) + "/" +
                     rule.value("group", std::string("*"));
  if (rule.contains("setting")) name += "/" + rule["setting"].get<std::string>();
  return name;
}
/// The methods of the subject records ("subject": true) among `records`.
inline std::set<std::string> subject_methods(const nlohmann::json& records) {
  std::set<std::string> out;
  for (const auto& r : records)
    if (r.is_object() && r.value("subject", false) && r.contains("method") && r["method"].is_string())
      out.insert(r["method"].get<std::string>());
  return out;
}
/// Throws invalid_input when rule `index` names a quantity outside the vocabulary, or a method that
/// is neither in the vocabulary nor one of `subjects` (the results' subject methods).
inline void check_rule_ids(const nlohmann::json& rule, std::size_t index, const std::set<std::string>& subjects = {}) {
  const std::string where = "thresholds rule " + std::to_string(index) + ": ";
  for (const char* key : {"quantity", "method", "group", "setting"})
    if (rule.contains(key) && !rule[key].is_string())
      throw invalid_input(where + key + " " + rule[key].dump() + " is not a string");
  const std::string quantity = rule.value("quantity", std::string("*"));
  const std::string method = rule.value("method", std::string("*"));
  if (quantity != "*" && !vocab::find_quantity(quantity))
    throw invalid_input(where + "quantity \"" + quantity + "\" is not a quantity of the vocabulary");
  if (method == "*" || subjects.count(method)) return;
  if (quantity == vocab::quantities::eval.id) {
    if (method == vocab::methods::eval_default.id) return;
    std::string known;
    for (const io::family_descriptor& f : io::families())
      for (std::string_view a : f.algorithms) {
        if (a == method) return;
        if (known.find(std::string(a) + ",") == std::string::npos) known += std::string(a) + ",";
      }
    known.pop_back();
    throw invalid_input(where + "method \"" + method + "\" is not an evaluation algorithm of any family (default, " +
                        known + ")");
  }
  const vocab::method* m = vocab::find_method(method);
  if (!m)
    throw invalid_input(where + "method \"" + method + "\" is not a method of the vocabulary (curvebench list methods)");
  if (quantity != "*" && !vocab::lists(m->quantities, quantity))
    throw invalid_input(where + "method \"" + method + "\" has no " + quantity + " records (its quantities: " +
                        std::string(m->quantities) + ")");
}
inline std::string number(double x) {
  std::ostringstream os;
  os.precision(3);
  os << x;
  return os.str();
}
}  // namespace detail

/// Every breach of `thresholds` by `results`; empty when the gate passes. Throws invalid_input for
/// a rule naming a quantity or method outside the vocabulary and the results' subjects (see above).
inline std::vector<breach> check_gate(const nlohmann::json& results, const nlohmann::json& thresholds) {
  std::vector<breach> out;
  const nlohmann::json empty = nlohmann::json::array();
  const nlohmann::json& records = results.contains("records") ? results["records"] : empty;
  const std::set<std::string> subjects = detail::subject_methods(records);
  std::size_t index = 0;
  for (const auto& rule : thresholds.at("rules")) detail::check_rule_ids(rule, index++, subjects);
  const nlohmann::json& orders = results.contains("orders") ? results["orders"] : empty;
  for (const auto& rule : thresholds.at("rules")) {
    const std::string name = detail::rule_name(rule);
    const bool checks_records = rule.contains("max_error") || rule.value("honest", false);
    std::size_t matched_records = 0;
    std::size_t matched_orders = 0;
    if (checks_records) {
      for (const auto& r : records) {
        if (!detail::matches(rule, r)) continue;
        ++matched_records;
        const std::string where = "case " + r.value("case", std::string("?")) + " setting " +
                                  r.value("setting", std::string("?"));
        if (rule.contains("max_error")) {
          const double allowed = rule["max_error"].get<double>();
          const bool has_error = r.contains("error") && r["error"].is_number();
          const double err = has_error ? r["error"].get<double>() : 0.0;
          if (!has_error || !(err <= allowed))  // NaN or missing error is a breach too
            out.push_back({name, where,
                           has_error ? "error " + detail::number(err) + " > allowed " + detail::number(allowed)
                                     : "no error measured (allowed " + detail::number(allowed) + ")"});
        }
        if (rule.value("honest", false) && r.contains("bounded") && r["bounded"].is_boolean() &&
            !r["bounded"].get<bool>())
          out.push_back({name, where,
                         "estimate " + detail::number(r.value("estimate", 0.0)) + " < true error " +
                             detail::number(r.value("error", 0.0)) + " (estimate not honest)"});
      }
      if (matched_records == 0)
        out.push_back({name, "-", "rule matched no result record (method or case group missing)"});
    }
    if (rule.contains("min_order")) {
      const double allowed = rule["min_order"].get<double>();
      for (const auto& o : orders) {
        if (!detail::matches(rule, o)) continue;
        ++matched_orders;
        const double observed = o.value("observed", 0.0);
        if (!(observed >= allowed))
          out.push_back({name, "case " + o.value("case", std::string("?")),
                         "observed order " + detail::number(observed) + " < allowed " + detail::number(allowed)});
      }
      if (matched_orders == 0)
        out.push_back({name, "-", "rule matched no observed order (method or case group missing)"});
    }
  }
  return out;
}

}  // namespace curvebench::harness
