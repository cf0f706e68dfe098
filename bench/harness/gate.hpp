// The CI gate: compares accuracy results against checked-in thresholds and names every breach.
//
// Results (written by the accuracy runner, reports/accuracy.json) hold "records", one per
// case x quantity x method x setting:
//   {"case", "group", "quantity", "method", "setting", "error", "estimate", "bounded", "evaluations", "status"}
// ("estimate"/"bounded" are null where a method gives no estimate) and "orders", one per case x
// quantity x method: {"case", "group", "quantity", "method", "observed", "theory"}.
// Thresholds (reports/thresholds.json) hold "rules":
//   {"quantity", "method", "group", "setting"  (each may be "*" or left out: any),
//    "max_error"  (optional: every matching record's error must be <= it),
//    "min_order"  (optional: every matching observed order must be >= it),
//    "honest"     (optional: every matching record with an estimate must have bounded = true),
//    "why"        (the reason for the number: measured figure and margin)}
// A rule that matches no record is itself a breach: a gate must not pass because a method or a
// case group disappeared.
#pragma once

#include <nlohmann/json.hpp>

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
inline std::string number(double x) {
  std::ostringstream os;
  os.precision(3);
  os << x;
  return os.str();
}
}  // namespace detail

/// Every breach of `thresholds` by `results`; empty when the gate passes.
inline std::vector<breach> check_gate(const nlohmann::json& results, const nlohmann::json& thresholds) {
  std::vector<breach> out;
  const nlohmann::json empty = nlohmann::json::array();
  const nlohmann::json& records = results.contains("records") ? results["records"] : empty;
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
