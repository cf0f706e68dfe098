// The one record of accuracy.json (its format: harness/gate.hpp), with its one JSON writer and its
// one reader. The sweeps write it (harness/records.hpp, record_sink), `curvebench check` writes its
// subject records with it (harness/check.hpp), the peers theirs (harness/peer_record.hpp), and the
// gate reads results through read_record (harness/gate.hpp). Header-only: the gate, and with it the
// fuzz target that replays it, links no harness library.
//
// Fields: case, group, quantity, method, setting, error and estimate (numbers, null when not
// finite: no estimate, or nothing measured), bounded (estimate >= error; null unless both are
// finite), evaluations, status (a result_status name), reason (why the status is not converged, one
// line of text, arclength/result.hpp's to_text; null when the method gave none: converged, or a
// method that names no reason); "subject": true on a subject's record;
// a peer's record adds "peer": true, library, peer_status, ns_per_op, counterpart {method, setting},
// counterpart_ns_per_op and, when measured, counterpart_error; a quantity's extra figures (named
// in its vocabulary doc) are further fields, numbers null when not finite.
#pragma once

#include "curvebench/core/error.hpp"
#include "curvebench/io/json_fields.hpp"

#include <nlohmann/json.hpp>

#include <cmath>
#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <utility>

namespace curvebench::harness {

/// x as JSON: null when it is not finite (JSON has no NaN or infinity).
inline nlohmann::json finite_or_null(double x) { return std::isfinite(x) ? nlohmann::json(x) : nlohmann::json(); }

/// Whether an estimate bounds the error: nullopt (null) unless both are finite.
inline std::optional<bool> bounded_of(double estimate, double error) {
  if (!std::isfinite(estimate) || !std::isfinite(error)) return std::nullopt;
  return estimate >= error;
}

/// The fields of a peer's record (a library measured beside curvebench on the same data).
struct peer_fields {
  std::string library;      ///< "<library> <version>"
  std::string peer_status;  ///< the library's own words for its status
  double ns_per_op = std::numeric_limits<double>::quiet_NaN();
  std::string counterpart_method;  ///< eval: the family's algorithm; otherwise the curvebench method id
  std::string counterpart_setting;
  double counterpart_ns_per_op = std::numeric_limits<double>::quiet_NaN();
  /// curvebench's error measured beside the peer's where its own sweeps keep no record of the same
  /// quantity; NaN: none, left out.
  double counterpart_error = std::numeric_limits<double>::quiet_NaN();
};

struct record {
  std::string case_name;
  std::string group;
  std::string quantity;
  std::string method;
  std::string setting;
  double error = std::numeric_limits<double>::quiet_NaN();     ///< NaN: nothing measured
  double estimate = std::numeric_limits<double>::quiet_NaN();  ///< NaN (or infinite): no estimate
  std::optional<bool> bounded;  ///< as measured() sets it (bounded_of), or as a results file says
  double evaluations = 0;
  std::string status;    ///< a result_status name
  std::string reason;    ///< why the status is not converged; "" (null in JSON): none given
  bool subject = false;  ///< a user's implementation (`curvebench check`)
  std::optional<peer_fields> peer;
  nlohmann::json extra = nlohmann::json::object();  ///< a quantity's extra figures

  /// A measured record: bounded from the estimate and the error.
  static record measured(std::string case_name, std::string group, std::string_view quantity, std::string_view method,
                         std::string setting, double error, double estimate, double evaluations,
                         std::string_view status) {
    record r;
    r.case_name = std::move(case_name);
    r.group = std::move(group);
    r.quantity = std::string(quantity);
    r.method = std::string(method);
    r.setting = std::move(setting);
    r.error = error;
    r.estimate = estimate;
    r.bounded = bounded_of(estimate, error);
    r.evaluations = evaluations;
    r.status = std::string(status);
    return r;
  }
};

/// The record as accuracy.json holds it.
inline nlohmann::json to_json(const record& r) {
  nlohmann::json j{{"case", r.case_name},
                   {"group", r.group},
                   {"quantity", r.quantity},
                   {"method", r.method},
                   {"setting", r.setting},
                   {"error", finite_or_null(r.error)},
                   {"estimate", finite_or_null(r.estimate)},
                   {"bounded", r.bounded ? nlohmann::json(*r.bounded) : nlohmann::json()},
                   {"evaluations", r.evaluations},
                   {"status", r.status},
                   {"reason", r.reason.empty() ? nlohmann::json() : nlohmann::json(r.reason)}};
  if (r.subject) j["subject"] = true;
  if (r.peer) {
    const peer_fields& p = *r.peer;
    j["peer"] = true;
    j["library"] = p.library;
    j["peer_status"] = p.peer_status;
    j["ns_per_op"] = finite_or_null(p.ns_per_op);
    j["counterpart"] = {{"method", p.counterpart_method}, {"setting", p.counterpart_setting}};
    j["counterpart_ns_per_op"] = finite_or_null(p.counterpart_ns_per_op);
    if (std::isfinite(p.counterpart_error)) j["counterpart_error"] = p.counterpart_error;
  }
  for (const auto& [key, value] : r.extra.items())
    j[key] = value.is_number() ? finite_or_null(value.get<double>()) : value;
  return j;
}

/// Throws invalid_input "WHERE.KEY: expected ..., got ..." unless each field of `row` that the
/// gate reads has the type the runner writes (strings; numbers or null; true, false or null).
inline void check_field_types(const nlohmann::json& row, const std::string& where) {
  if (!row.is_object()) throw invalid_input(where + ": expected an object, got " + io::field::shown_value(row));
  const auto expect = [&](const char* key, bool ok, const char* what) {
    if (row.contains(key) && !ok)
      throw invalid_input(where + "." + key + ": expected " + what + ", got " + io::field::shown_value(row[key]));
  };
  for (const char* key : {"case", "group", "quantity", "method", "setting"})
    expect(key, row.contains(key) && row[key].is_string(), "a string");
  for (const char* key : {"error", "estimate", "observed"})
    expect(key, row.contains(key) && (row[key].is_number() || row[key].is_null()), "a number or null");
  expect("bounded", row.contains("bounded") && (row["bounded"].is_boolean() || row["bounded"].is_null()),
         "true, false or null");
  expect("subject", row.contains("subject") && row["subject"].is_boolean(), "true or false");
}

/// The record `j` of a results file (`where` names it in errors, "res.json: records[3]"): fields
/// checked by check_field_types; a missing string is "", a missing or null number NaN, a missing
/// bounded null. The peer fields are read when "peer" is true; fields it does not know go to extra.
inline record read_record(const nlohmann::json& j, const std::string& where) {
  check_field_types(j, where);
  constexpr double nan = std::numeric_limits<double>::quiet_NaN();
  const auto text = [&](const char* key) {
    return j.contains(key) && j[key].is_string() ? j[key].get<std::string>() : "";
  };
  const auto number = [&](const char* key) {
    return j.contains(key) && j[key].is_number() ? j[key].get<double>() : nan;
  };
  record r;
  r.case_name = text("case");
  r.group = text("group");
  r.quantity = text("quantity");
  r.method = text("method");
  r.setting = text("setting");
  r.error = number("error");
  r.estimate = number("estimate");
  // An error or estimate is a size: negative is no measurement (null is how a record says none).
  for (const auto& [name, v] : {std::pair{"error", r.error}, std::pair{"estimate", r.estimate}})
    if (std::isfinite(v) && v < 0)
      throw invalid_input(where + "." + name + ": " + io::field::shown_value(j[name]) +
                          " is negative (an error is >= 0, or null)");
  // Whether the estimate bounds the error is measured from the two numbers when the record has both
  // (a file's "bounded": true beside an estimate below its error passed the gate's honest rule);
  // a file's false is kept (it can only make the gate stricter), and where the numbers cannot say
  // (no error measured) the field is read as written.
  r.bounded = bounded_of(r.estimate, r.error);
  if (j.contains("bounded") && j["bounded"].is_boolean() && (!r.bounded || !j["bounded"].get<bool>()))
    r.bounded = j["bounded"].get<bool>();
  r.evaluations = j.contains("evaluations") && j["evaluations"].is_number() ? j["evaluations"].get<double>() : 0;
  r.status = text("status");
  r.reason = text("reason");  // read and written back; the gate's rules do not look at it
  r.subject = j.contains("subject") && j["subject"].get<bool>();
  const bool peer = j.contains("peer") && j["peer"].is_boolean() && j["peer"].get<bool>();
  if (peer) {
    peer_fields p;
    p.library = text("library");
    p.peer_status = text("peer_status");
    p.ns_per_op = number("ns_per_op");
    if (j.contains("counterpart") && j["counterpart"].is_object()) {
      const nlohmann::json& c = j["counterpart"];
      p.counterpart_method = c.contains("method") && c["method"].is_string() ? c["method"].get<std::string>() : "";
      p.counterpart_setting = c.contains("setting") && c["setting"].is_string() ? c["setting"].get<std::string>() : "";
    }
    p.counterpart_ns_per_op = number("counterpart_ns_per_op");
    p.counterpart_error = number("counterpart_error");
    r.peer = std::move(p);
  }
  static constexpr std::string_view known[] = {"case",     "group",   "quantity",    "method", "setting", "error",
                                               "estimate", "bounded", "evaluations", "status", "reason",  "subject"};
  static constexpr std::string_view peer_known[] = {
      "peer", "library", "peer_status", "ns_per_op", "counterpart", "counterpart_error", "counterpart_ns_per_op"};
  for (const auto& [key, value] : j.items()) {
    bool is_known = false;
    for (std::string_view k : known) is_known = is_known || k == key;
    for (std::string_view k : peer_known) is_known = is_known || (peer && k == key);
    if (!is_known) r.extra[key] = value;
  }
  return r;
}

}  // namespace curvebench::harness
