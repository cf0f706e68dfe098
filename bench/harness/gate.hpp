// The CI gate: compares accuracy results against checked-in thresholds and names every breach.
//
// Results (written by the accuracy runner, reports/accuracy.json) hold "records", one per
// case x quantity x method x setting:
//   {"case", "group", "quantity", "method", "setting", "error", "estimate", "bounded", "evaluations", "status",
//    "reason"}
// ("estimate"/"bounded" are null where a method gives no estimate; "reason" says why a status is not
// converged, text or null, and no rule reads it; "status" is a result_status
// name, "not_guaranteed" for eval records) and "orders", one per case x quantity x method:
// {"case", "group", "quantity", "method", "observed", "theory", "points", "excluded"}. Quantity and method ids are
// those of harness/vocabulary.hpp (eval records name evaluation algorithms), settings "key=value[,key=value]".
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
// the evaluation algorithms the families offer (vocab::eval_algorithms, the family registry's).
// Records of a user's own implementation (a "subject": `curvebench check`, harness/check.hpp) carry
// "subject": true and the subject's name as "method"; a rule may name such a method when the
// results hold a subject record of that name (the quantity must still be in the vocabulary).
// Both files' structure is checked first, so that no typo switches the gate off: the thresholds
// must hold "rules", a non-empty array of objects with no key but those above, each with at least
// one check (max_error, min_order or honest: true) and values of the right type; the results must
// hold a "records" array (and "orders", when present, an array) of objects whose fields read here
// have the types written by the accuracy runner (records are read by harness/record.hpp's reader).
// Anything else is invalid_input naming the file (the names given to check_gate), the rule or
// record and the key.
#pragma once

#include "harness/record.hpp"
#include "harness/vocabulary.hpp"

#include "curvebench/core/error.hpp"
#include "curvebench/io/json_fields.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <set>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

namespace curvebench::harness {

struct breach {
  std::string rule;     // "length/gauss_kronrod/smooth"
  std::string where;    // "case helix_3d setting tol=1e-12"
  std::string message;  // "error 3.1e-10 > allowed 1e-13"
};

namespace detail {
/// A row's field `key` (quantity, method, group, setting) as a rule matches it: a record's, or an
/// observed order's (a JSON row, its fields type-checked by read_results; missing is "").
inline const std::string& field_of(const record& r, std::string_view key) {
  return key == "quantity" ? r.quantity : key == "method" ? r.method : key == "group" ? r.group : r.setting;
}
inline const std::string& field_of(const nlohmann::json& row, std::string_view key) {
  static const std::string none;
  const auto it = row.find(std::string(key));
  return it != row.end() && it->is_string() ? it->template get_ref<const std::string&>() : none;
}
/// Whether a row (a record or an observed order) has every field the rule names ("*" or left out:
/// any).
template <class Row>
bool matches(const nlohmann::json& rule, const Row& row) {
  for (const char* key : {"quantity", "method", "group", "setting"}) {
    const std::string want = rule.value(key, std::string("*"));
    if (want != "*" && field_of(row, key) != want) return false;
  }
  return true;
}
/// Why a rule matched none of `rows` (`what`: "result record", "observed order"): the first of its
/// fields that no row has, else that no row has them all together.
template <class Rows>
std::string unmatched(const nlohmann::json& rule, const Rows& rows, const std::string& what) {
  for (const char* key : {"quantity", "method", "group", "setting"}) {
    const std::string want = rule.value(key, std::string("*"));
    if (want == "*") continue;
    bool any = false;
    for (const auto& row : rows) any = any || field_of(row, key) == want;
    if (!any)
      return "rule matched no " + what + ": none has " + key + " " + io::field::shown_string(want) +
             (what == "observed order" && std::string_view(key) != "group"
                  ? " (orders are fitted per case, quantity and method, for methods with a theory order; they have "
                    "no setting)"
                  : "");
  }
  return "rule matched no " + what + ": none has its quantity, method, group and setting together";
}
inline std::string rule_name(const nlohmann::json& rule) {
  // Each field as the user wrote it, cut to 80 characters with control characters escaped.
  const auto field = [&](const char* key) { return validate::visible(rule.value(key, std::string("*"))); };
  std::string name = field("quantity") + "/" + field("method") + "/" + field("group");
  if (rule.contains("setting")) name += "/" + field("setting");
  return name;
}
/// The methods of the subject records ("subject": true) among `records`.
inline std::set<std::string> subject_methods(const std::vector<record>& records) {
  std::set<std::string> out;
  for (const record& r : records)
    if (r.subject) out.insert(r.method);
  return out;
}
inline constexpr std::array<std::string_view, 8> rule_keys{"quantity",  "method",    "group",  "setting",
                                                           "max_error", "min_order", "honest", "why"};

/// Fails unless `j` is an object holding `key` as an array; returns that array.
inline const nlohmann::json& array_member(const nlohmann::json& j, const char* key, const std::string& file) {
  if (!j.is_object() || !j.contains(key))
    throw invalid_input(file + ": expected an object holding a \"" + key + "\" array, got " +
                        io::field::shown_value(j));
  if (!j[key].is_array())
    throw invalid_input(file + ": \"" + key + "\" must be an array, got " + io::field::shown_value(j[key]));
  return j[key];
}

/// Throws invalid_input naming `file` unless `thresholds` holds a non-empty "rules" array of rule
/// objects with known keys of the right types, each with at least one check.
inline void check_thresholds_structure(const nlohmann::json& thresholds, const std::string& file) {
  const nlohmann::json& rules = array_member(thresholds, "rules", file);
  // The format's version (optional): a file of another version may mean its rules differently.
  if (thresholds.contains("version") && thresholds["version"] != 1)
    throw invalid_input(file + ": \"version\" " + io::field::shown_value(thresholds["version"]) +
                        ": this curvebench reads thresholds of version 1");
  if (rules.empty()) throw invalid_input(file + ": \"rules\" is empty: a gate without rules checks nothing");
  for (std::size_t i = 0; i < rules.size(); ++i) {
    const std::string where = file + " rule " + std::to_string(i) + ": ";
    const nlohmann::json& rule = rules[i];
    if (!rule.is_object()) throw invalid_input(where + "expected an object, got " + io::field::shown_value(rule));
    for (const auto& [key, value] : rule.items()) {
      if (std::find(rule_keys.begin(), rule_keys.end(), key) == rule_keys.end()) {
        std::string known;
        for (std::string_view k : rule_keys) known += (known.empty() ? "" : ", ") + std::string(k);
        throw invalid_input(where + "unknown key " + io::field::shown_string(key) + " (known keys: " + known + ")");
      }
      const bool number = key == "max_error" || key == "min_order";
      const bool ok = number ? value.is_number() : key == "honest" ? value.is_boolean() : value.is_string();
      if (!ok)
        throw invalid_input(where + key + " " + io::field::shown_value(value) + " is not " +
                            (number            ? "a number"
                             : key == "honest" ? "true or false"
                                               : "a string"));
      // An error is >= 0 and an order > 0: a rule below that breaches on every record (max_error
      // < 0) or checks nothing (min_order <= 0), and says the thresholds file is wrong.
      if (key == "max_error" && !(value.get<double>() >= 0))
        throw invalid_input(where + "max_error " + io::field::shown_value(value) + " is negative (an error is >= 0)");
      if (key == "min_order" && !(value.get<double>() > 0))
        throw invalid_input(where + "min_order " + io::field::shown_value(value) +
                            " is not positive (an observed order of convergence is > 0)");
    }
    if (!rule.contains("max_error") && !rule.contains("min_order") && !rule.value("honest", false))
      throw invalid_input(where + "no check (give max_error, min_order or \"honest\": true)");
  }
}

/// The records of `results`, read by read_record (harness/record.hpp). Throws invalid_input naming
/// `file` unless `results` holds a "records" array (and "orders", when present, an array) of
/// objects whose fields read by the gate have the types the runner writes.
inline std::vector<record> read_results(const nlohmann::json& results, const std::string& file) {
  std::vector<record> out;
  for (const char* list : {"records", "orders"}) {
    if (std::string_view(list) == "orders" && !results.contains(list)) continue;
    const nlohmann::json& rows = array_member(results, list, file);
    for (std::size_t i = 0; i < rows.size(); ++i) {
      const std::string where = file + ": " + list + "[" + std::to_string(i) + "]";
      if (std::string_view(list) == "records")
        out.push_back(read_record(rows[i], where));
      else
        check_field_types(rows[i], where);
    }
  }
  return out;
}

/// Throws invalid_input when rule `index` names a quantity outside the vocabulary, or a method that
/// is neither in the vocabulary nor one of `subjects` (the results' subject methods).
inline void check_rule_ids(const nlohmann::json& rule, std::size_t index, const std::set<std::string>& subjects = {},
                           const std::string& file = "thresholds") {
  const std::string where = file + " rule " + std::to_string(index) + ": ";
  const std::string quantity = rule.value("quantity", std::string("*"));
  const std::string method = rule.value("method", std::string("*"));
  if (quantity != "*" && !vocab::find_quantity(quantity))
    throw invalid_input(where + "quantity " + io::field::shown_string(quantity) +
                        " is not a quantity of the vocabulary");
  if (method == "*" || subjects.count(method)) return;
  if (quantity == vocab::quantities::eval.id) {
    if (method == vocab::methods::eval_default.id) return;
    std::string known;
    for (const vocab::algorithm* a : vocab::eval_algorithms) {
      if (a->id == method) return;
      known += std::string(a->id) + ",";
    }
    known.pop_back();
    throw invalid_input(where + "method " + io::field::shown_string(method) +
                        " is not an evaluation algorithm of any family (default, " + known + ")");
  }
  const vocab::method* m = vocab::find_method(method);
  if (!m)
    throw invalid_input(where + "method " + io::field::shown_string(method) +
                        " is not a method of the vocabulary (curvebench list methods)");
  if (quantity != "*" && !vocab::lists(m->quantities, quantity))
    throw invalid_input(where + "method " + io::field::shown_string(method) + " has no " + quantity +
                        " records (its quantities: " + std::string(m->quantities) + ")");
}
/// The number `key` of a record, NaN when it is null or missing (the structure is checked first).
inline double number_or_nan(const nlohmann::json& row, const char* key) {
  return row.contains(key) && row[key].is_number() ? row[key].get<double>() : std::numeric_limits<double>::quiet_NaN();
}
inline std::string number(double x) {
  std::ostringstream os;
  os.precision(3);
  os << x;
  return os.str();
}
}  // namespace detail

/// Every breach of `thresholds` by `results`; empty when the gate passes. Throws invalid_input,
/// naming the file (`results_file`, `thresholds_file`), for a malformed file and for a rule naming
/// a quantity or method outside the vocabulary and the results' subjects (see above).
inline std::vector<breach> check_gate(const nlohmann::json& results, const nlohmann::json& thresholds,
                                      const std::string& results_file = "results",
                                      const std::string& thresholds_file = "thresholds") {
  detail::check_thresholds_structure(thresholds, thresholds_file);
  const std::vector<record> records = detail::read_results(results, results_file);
  std::vector<breach> out;
  const nlohmann::json empty = nlohmann::json::array();
  const std::set<std::string> subjects = detail::subject_methods(records);
  std::size_t index = 0;
  for (const auto& rule : thresholds.at("rules")) detail::check_rule_ids(rule, index++, subjects, thresholds_file);
  const nlohmann::json& orders = results.contains("orders") ? results["orders"] : empty;
  for (const auto& rule : thresholds.at("rules")) {
    const std::string name = detail::rule_name(rule);
    const bool checks_records = rule.contains("max_error") || rule.value("honest", false);
    std::size_t matched_records = 0;
    std::size_t matched_orders = 0;
    if (checks_records) {
      for (const record& r : records) {
        if (!detail::matches(rule, r)) continue;
        ++matched_records;
        const std::string where = "case " + r.case_name + " setting " + r.setting;
        if (rule.contains("max_error")) {
          const double allowed = rule["max_error"].get<double>();
          const bool has_error = !std::isnan(r.error);  // null or missing: NaN
          if (!has_error || !(r.error <= allowed))      // NaN or missing error is a breach too
            out.push_back({name, where,
                           has_error ? "error " + detail::number(r.error) + " > allowed " + detail::number(allowed)
                                     : "no error measured (allowed " + detail::number(allowed) + ")"});
        }
        // An estimate with no error measured beside it cannot be shown honest: a breach, whatever
        // the file's "bounded" says (read_record measures bounded where both numbers are there).
        if (rule.value("honest", false) && std::isfinite(r.estimate) && std::isnan(r.error))
          out.push_back({name, where,
                         "estimate " + detail::number(r.estimate) +
                             " with no error measured: its honesty cannot "
                             "be checked"});
        else if (rule.value("honest", false) && r.bounded && !*r.bounded)
          out.push_back({name, where,
                         "estimate " + detail::number(r.estimate) + " < true error " + detail::number(r.error) +
                             " (estimate not honest)"});
      }
      if (matched_records == 0) out.push_back({name, "-", detail::unmatched(rule, records, "result record")});
    }
    if (rule.contains("min_order")) {
      const double allowed = rule["min_order"].get<double>();
      for (const auto& o : orders) {
        if (!detail::matches(rule, o)) continue;
        ++matched_orders;
        const double observed = detail::number_or_nan(o, "observed");
        if (!(observed >= allowed))
          out.push_back({name, "case " + o.value("case", std::string("?")),
                         "observed order " + detail::number(observed) + " < allowed " + detail::number(allowed)});
      }
      if (matched_orders == 0) out.push_back({name, "-", detail::unmatched(rule, orders, "observed order")});
    }
  }
  return out;
}

}  // namespace curvebench::harness
