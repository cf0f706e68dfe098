// The subject API (harness/subject.hpp): the subject's functions sampled where the accuracy
// runner samples curvebench's methods, their values handed to the check core as tables, and the
// check core's records assembled into a results JSON.
#include "harness/subject.hpp"

#include "harness/accuracy.hpp"
#include "harness/cases.hpp"
#include "harness/check.hpp"
#include "harness/check_detail.hpp"
#include "harness/files.hpp"
#include "harness/gate.hpp"
#include "harness/sweeps.hpp"

#include "curvebench/core/error.hpp"
#include "curvebench/io/spec.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <exception>
#include <fstream>
#include <limits>
#include <optional>
#include <sstream>
#include <string_view>

namespace curvebench::harness {

namespace {

using json = nlohmann::json;

std::string num(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.17g", x);
  return buf;
}

/// Calls f(args...), turning an exception into invalid_input naming the subject and the call.
template <class F, class... A>
auto call(const std::string& subject, const std::string& what, const F& f, A... args) {
  try {
    return f(args...);
  } catch (const std::exception& e) {
    throw invalid_input("subject " + subject + ": " + what + " threw: " + e.what());
  }
}

/// A table of the check core whose rows are the subject's answers at the sampled arguments (its
/// "file" names the subject and function, its "lines" are the samples' 1-based indices).
csv_table table(const std::string& subject, const std::string& function, std::vector<std::string> columns) {
  csv_table t;
  t.file = "subject " + subject + " " + function + " (row = sample)";
  t.columns = std::move(columns);
  return t;
}
void add_row(csv_table& t, std::vector<double> row) {
  t.rows.push_back(std::move(row));
  t.lines.push_back(t.rows.size());
}

/// A subject's name is the records' method: letters, digits, '_' and '-'.
void check_name(const std::string& name) {
  const bool name_ok = !name.empty() && std::all_of(name.begin(), name.end(), [](char ch) {
    return (ch >= 'a' && ch <= 'z') || (ch >= 'A' && ch <= 'Z') || (ch >= '0' && ch <= '9') || ch == '_' || ch == '-';
  });
  if (!name_ok)
    throw invalid_input("subject name \"" + validate::visible(name) +
                        "\": must be letters, digits, '_' and '-' (the records' method)");
}

template <int Dim>
void check_subject(const subject<Dim>& s) {
  check_name(s.name);
  if (!s.eval && !s.length && !s.inverse)
    throw invalid_input("subject " + s.name + ": has no function to measure (eval, length or inverse)");
}

/// The results JSON of one case: its entry, the records and orders given (curvebench's own when
/// compared side by side), then every check result's records and findings, the context.
json results_of(json case_entry, json records, json orders, const std::vector<check_result>& results,
                const std::string& subject, bool quick) {
  json out{{"schema", 1},
           {"suite", {{"name", suite_name}, {"version", suite_version}, {"cases", 1}}},
           {"records", std::move(records)},
           {"orders", std::move(orders)},
           {"cases", json::array({std::move(case_entry)})}};
  for (const check_result& r : results) {
    for (const json& rec : r.records) out["records"].push_back(rec);
    for (const std::string& f : r.findings) out["findings"].push_back("subject " + subject + ": " + f);
  }
  out["context"] = {{"subject", subject}, {"compiler", compiler_id()}, {"quick", quick}};
  return out;
}

template <int Dim>
json measure(const case_info& info, const subject<Dim>& s, const subject_options& o) {
  check_subject(s);
  if (info.dimension != Dim)
    throw invalid_input(info.file + ": case " + info.name + " is " + std::to_string(info.dimension) +
                        "D, the subject " + s.name + " is " + std::to_string(Dim) + "D");
  const sweep w = settings(o.quick);
  const io::field spec = io::root(info.spec, info.file);
  const any_curve<double, Dim> c = io::curve_from_spec<double, Dim>(spec);
  const interval<double> d = c.domain();
  check_options co;
  co.name = s.name;
  co.case_name = info.name;
  co.group = o.group.empty() ? info.group : o.group;

  // The inputs of the first pass: points at the eval sweep's parameters, the whole length, and
  // s(u) at the s(u) sweep's parameters (a lengths table from the domain's start).
  std::vector<check_input> inputs;
  if (s.eval) {
    std::vector<std::string> columns{"u", "x", "y", "z"};
    columns.resize(Dim + 1);
    csv_table t = table(s.name, "eval", columns);
    for (double u : sample_parameters(d.lo, d.hi, w.eval_params)) {
      const point<double, Dim> p = call(s.name, "eval(u = " + num(u) + ")", s.eval, u);
      std::vector<double> row{u};
      for (int i = 0; i < Dim; ++i) row.push_back(p[i]);
      add_row(t, std::move(row));
    }
    inputs.push_back({check_kind::values, std::move(t)});
  }
  std::size_t s_of_u_input = inputs.size() + 1;  // the index of the s(u) table, when there is one
  if (s.length) {
    csv_table whole = table(s.name, "length", {"u0", "u1", "length"});
    add_row(whole, {d.lo, d.hi, call(s.name, "length(" + num(d.lo) + ", " + num(d.hi) + ")", s.length, d.lo, d.hi)});
    inputs.push_back({check_kind::lengths, std::move(whole)});
    csv_table partial = table(s.name, "length from the start", {"u0", "u1", "length"});
    for (double u : sample_parameters(d.lo, d.hi, w.params))
      add_row(partial, {d.lo, u, call(s.name, "length(" + num(d.lo) + ", " + num(u) + ")", s.length, d.lo, u)});
    s_of_u_input = inputs.size();
    inputs.push_back({check_kind::lengths, std::move(partial)});
  }
  std::vector<check_result> results;
  if (!inputs.empty()) results = run_checks(spec, inputs, co);
  // s(u) is the check core's lengths measure from the domain's start: the s_of_u quantity.
  if (s_of_u_input < results.size())
    for (json& r : results[s_of_u_input].records) r["quantity"] = vocab::quantities::s_of_u.id;

  // u(s) at the u(s) sweep's targets, fractions of L: a second pass once L is known (the first
  // pass's reference has it; without one, a pass of the whole-length table alone gets it).
  if (s.inverse) {
    double L = 0;
    if (!results.empty()) {
      L = results.front().length;
    } else {
      csv_table probe = table(s.name, "domain", {"u0", "u1", "length"});
      add_row(probe, {d.lo, d.hi, 0.0});
      L = run_check(spec, check_kind::lengths, probe, co).length;
    }
    csv_table t = table(s.name, "inverse", {"s", "u"});
    for (double f : sample_fractions(w.params)) {
      const double target = std::min(L * f, L);
      add_row(t, {target, call(s.name, "inverse(s = " + num(target) + ")", s.inverse, target)});
    }
    // A u outside the domain (one float ulp past the end, say) is the subject's error, measured
    // and recorded, not a reason to record nothing.
    check_options inverse_options = co;
    inverse_options.outside_is_finding = true;
    results.push_back(run_check(spec, check_kind::inverse, t, inverse_options));
  }

  if (o.with_methods) {
    json own = run_case(info, o.quick);
    return results_of(std::move(own["case"]), std::move(own["records"]), std::move(own["orders"]), results, s.name,
                      o.quick);
  }
  return results_of({{"name", info.name},
                     {"group", info.group},
                     {"reason", info.reason},
                     {"family", c.family()},
                     {"dimension", Dim},
                     {"segments", c.breakpoints().size() - 1},
                     {"reference_length", results.empty() ? std::string() : num(results.front().length)}},
                    json::array(), json::array(), results, s.name, o.quick);
}

json measure_channel(const case_info& info, const channel_subject& s, const subject_options& o) {
  check_name(s.name);
  if (!s.value) throw invalid_input("subject " + s.name + ": has no value function to measure");
  const io::field spec = io::root(info.spec, info.file);
  if (!detail::is_channel_spec(spec))
    throw invalid_input(info.file + ": case " + info.name +
                        " is not a channel (\"type\": \"channel\"): a "
                        "channel subject measures a keyframe channel by time");
  const channel_values ch = channel_values_of(spec, o.against);
  // The channel sweep's times: across the keys and a quarter of their span beyond each end, and
  // the key times themselves.
  const double first = ch.keys.empty() ? 0.0 : ch.keys.front(), last = ch.keys.empty() ? 1.0 : ch.keys.back();
  const double span = last - first;
  const double lo = span > 0 ? first - span / 4 : first - 1, hi = span > 0 ? last + span / 4 : last + 1;
  std::vector<double> ts = sample_parameters(lo, hi, settings(o.quick).eval_params);
  ts.insert(ts.end(), ch.keys.begin(), ch.keys.end());
  std::sort(ts.begin(), ts.end());
  ts.erase(std::unique(ts.begin(), ts.end()), ts.end());
  csv_table t =
      table(s.name, "value",
            s.slope ? std::vector<std::string>{"t", "value", "dvalue"} : std::vector<std::string>{"t", "value"});
  for (double x : ts) {
    std::vector<double> row{x, call(s.name, "value(t = " + num(x) + ")", s.value, x)};
    if (s.slope) {
      // Where the channel's slope is unbounded or infinite there is nothing to compare: not asked.
      const std::optional<double> d = ch.at(x, 1);
      row.push_back(d && std::isfinite(*d) ? call(s.name, "slope(t = " + num(x) + ")", s.slope, x)
                                           : std::numeric_limits<double>::quiet_NaN());
    }
    add_row(t, std::move(row));
  }
  check_options co;
  co.name = s.name;
  co.case_name = info.name;
  co.group = o.group.empty() ? info.group : o.group;
  co.against = o.against;
  co.unit = value_unit::ulp_double;
  const std::vector<check_result> results = run_checks(spec, {{check_kind::times, std::move(t)}}, co);
  return results_of({{"name", info.name},
                     {"group", info.group},
                     {"reason", info.reason},
                     {"family", "channel"},
                     {"dimension", 1},
                     {"against", results.front().against},
                     {"value_range", results.front().size}},
                    json::array(), json::array(), results, s.name, o.quick);
}

/// The case of a spec given in JSON (its name, group and reason when it has them).
case_info spec_case(const json& spec, const std::string& file) {
  case_info c;
  c.spec = spec;
  c.file = file;
  const io::field root = io::root(c.spec, file);
  c.name = root.has("name") ? root.member("name").string() : "spec";
  c.group = root.has("group") ? root.member("group").string() : "subject";
  c.reason = root.has("reason") ? root.member("reason").string() : "";
  c.dimension = io::spec_dimension(root);
  return c;
}

/// The case named case_name in cases_dir.
case_info find_case(const std::string& cases_dir, const std::string& case_name) {
  for (const case_info& c : load_cases(cases_dir))
    if (c.name == case_name) return c;
  throw invalid_input("case " + case_name + ": no such case in " + cases_dir + " (curvebench list cases)");
}

}  // namespace

json measure_case(const std::string& cases_dir, const std::string& case_name, const channel_subject& s,
                  const subject_options& options) {
  return measure_channel(find_case(cases_dir, case_name), s, options);
}

json measure_spec(const json& spec, const channel_subject& s, const subject_options& options, const std::string& file) {
  return measure_channel(spec_case(spec, file), s, options);
}

template <int Dim>
json measure_case(const std::string& cases_dir, const std::string& case_name, const subject<Dim>& s,
                  const subject_options& options) {
  return measure<Dim>(find_case(cases_dir, case_name), s, options);
}

template <int Dim>
json measure_spec(const json& spec, const subject<Dim>& s, const subject_options& options, const std::string& file) {
  return measure<Dim>(spec_case(spec, file), s, options);
}

std::vector<std::string> subject_gate(const json& results, const std::string& thresholds_path) {
  const json thresholds = io::parse(read_input_file(thresholds_path, "thresholds "), thresholds_path);
  if (!thresholds.is_object() || !thresholds.contains("rules") || !thresholds["rules"].is_array())
    throw invalid_input("thresholds " + thresholds_path + ": needs a \"rules\" array (harness/gate.hpp)");
  std::vector<std::string> out;
  for (const breach& b : check_gate(results, thresholds)) out.push_back(b.rule + " at " + b.where + ": " + b.message);
  return out;
}

json merge_results(json into, const json& more) {
  for (const char* key : {"records", "orders", "cases", "findings"}) {
    if (std::string_view(key) == "findings" && !more.contains(key)) continue;  // only when there are some
    if (!into.contains(key)) into[key] = json::array();
    if (!more.contains(key)) continue;
    for (const json& x : more[key]) {
      // A case measured in both (a subject beside accuracy.json's methods) is listed once.
      const bool listed = std::string(key) == "cases" &&
                          std::any_of(into[key].begin(), into[key].end(),
                                      [&](const json& c) { return c.value("name", "") == x.value("name", ""); });
      if (!listed) into[key].push_back(x);
    }
  }
  if (into.contains("suite") && into["suite"].is_object()) into["suite"]["cases"] = into["cases"].size();
  return into;
}

template json measure_case<2>(const std::string&, const std::string&, const subject<2>&, const subject_options&);
template json measure_case<3>(const std::string&, const std::string&, const subject<3>&, const subject_options&);
template json measure_spec<2>(const json&, const subject<2>&, const subject_options&, const std::string&);
template json measure_spec<3>(const json&, const subject<3>&, const subject_options&, const std::string&);

}  // namespace curvebench::harness
