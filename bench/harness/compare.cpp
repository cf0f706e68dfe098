#include "harness/compare.hpp"

#include "harness/check_detail.hpp"
#include "harness/files.hpp"
#include "harness/vocabulary.hpp"

#include "curvebench/core/error.hpp"
#include "curvebench/io/json_fields.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <initializer_list>
#include <limits>
#include <map>
#include <set>
#include <string>
#include <utility>

namespace curvebench::harness {

namespace {

constexpr double nan = std::numeric_limits<double>::quiet_NaN();
constexpr std::size_t exact_limit = 20;  // the exact U distribution up to 20 values a side

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 == 1 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

/// counts[u] = the number of orderings of n1 a's and n2 b's whose U (pairs a > b) is u; the
/// recurrence on the largest value: an a there beats all n2 b's, a b there beats none.
std::vector<double> u_counts(std::size_t n1, std::size_t n2) {
  // f[m][n] over u, built up in m and n; C(40, 20) ~ 1.4e11 fits a double exactly.
  std::vector<std::vector<std::vector<double>>> f(n1 + 1, std::vector<std::vector<double>>(n2 + 1));
  for (std::size_t m = 0; m <= n1; ++m)
    for (std::size_t n = 0; n <= n2; ++n) {
      std::vector<double>& c = f[m][n];
      c.assign(m * n + 1, 0.0);
      if (m == 0 || n == 0) {
        c[0] = 1;
        continue;
      }
      const std::vector<double>& a_last = f[m - 1][n];  // the largest is an a: U grows by n
      const std::vector<double>& b_last = f[m][n - 1];  // the largest is a b: U unchanged
      for (std::size_t u = 0; u < a_last.size(); ++u) c[u + n] += a_last[u];
      for (std::size_t u = 0; u < b_last.size(); ++u) c[u] += b_last[u];
    }
  return f[n1][n2];
}

double normal_two_sided(double z) { return std::erfc(z / std::sqrt(2.0)); }

/// The rounding level of a quantity's error unit (see the header).
double floor_of(const std::string& quantity, const compare_options& o) {
  namespace q = vocab::quantities;
  for (const vocab::quantity* relative : {&q::length, &q::s_of_u, &q::u_of_s})
    if (quantity == relative->id) return o.relative_floor;
  for (const vocab::quantity* ulps :
       {&q::eval, &q::channel_value, &q::channel_keys, &q::channel_time, &q::channel_rotation})
    if (quantity == ulps->id) return o.ulps_floor;
  return 0;  // counts (channel_monotone), and a quantity this build does not know
}

std::string key_of(const record& r) {
  std::string k = r.case_name + "/" + r.quantity + "/" + r.method;
  if (!r.setting.empty()) k += "/" + r.setting;
  if (!r.group.empty()) k += " [" + r.group + "]";
  if (r.subject) k += " (subject)";
  if (r.peer) k += " (peer " + r.peer->library + ")";
  return k;
}

void read_records(const nlohmann::json& j, const std::string& file, const char* key, run_results& out) {
  const nlohmann::json& records = j.at(key);
  if (!records.is_array()) throw invalid_input(file + ": \"" + key + "\" is not an array");
  for (std::size_t i = 0; i < records.size(); ++i) {
    const std::string where = file + ": " + key + "[" + std::to_string(i) + "]";
    out.records.push_back(read_record(records[i], where));  // negative errors refused there
    out.record_where.push_back(where);
  }
}

void read_benchmarks(const nlohmann::json& j, const std::string& file, run_results& out) {
  const nlohmann::json& list = j.at("benchmarks");
  if (!list.is_array()) throw invalid_input(file + ": \"benchmarks\" is not an array");
  // Repetitions (run_type "iteration") per run name; a run name with aggregates only (Google
  // Benchmark's --benchmark_report_aggregates_only) keeps its median.
  std::map<std::string, bench_times> iterations, medians;
  std::vector<std::string> order;
  for (std::size_t i = 0; i < list.size(); ++i) {
    const nlohmann::json& e = list[i];
    const std::string where = file + ": benchmarks[" + std::to_string(i) + "]";
    if (!e.is_object()) throw invalid_input(where + ": expected an object, got " + io::field::shown_value(e));
    const auto text = [&](const char* key) -> std::string {
      if (!e.contains(key)) return "";
      if (!e[key].is_string())
        throw invalid_input(where + "." + key + ": expected a string, got " + io::field::shown_value(e[key]));
      return e[key].get<std::string>();
    };
    std::string name = text("run_name");
    if (name.empty()) name = text("name");
    if (name.empty()) throw invalid_input(where + ": no \"name\" or \"run_name\"");
    if (e.contains("error_occurred") && e["error_occurred"].is_boolean() && e["error_occurred"].get<bool>())
      continue;  // a benchmark that failed has no time
    const std::string type = text("run_type");
    const std::string aggregate = text("aggregate_name");
    if (type == "aggregate" && aggregate != "median") continue;
    if (!e.contains("cpu_time") || !e["cpu_time"].is_number())
      throw invalid_input(where + ".cpu_time: expected a number, got " +
                          (e.contains("cpu_time") ? io::field::shown_value(e["cpu_time"]) : std::string("nothing")));
    const std::string unit = e.contains("time_unit") ? text("time_unit") : "ns";
    const double scale = unit == "ns" ? 1 : unit == "us" ? 1e3 : unit == "ms" ? 1e6 : unit == "s" ? 1e9 : nan;
    if (!std::isfinite(scale))
      throw invalid_input(where + ".time_unit: \"" + validate::visible(unit) + "\" is not ns, us, ms or s");
    const double ns = e["cpu_time"].get<double>() * scale;
    if (!std::isfinite(ns) || ns < 0)
      throw invalid_input(where + ".cpu_time: " + detail::num(ns, 3) + " ns is not a time");
    auto& table = type == "aggregate" ? medians : iterations;
    auto [it, fresh] = table.try_emplace(name);
    if (fresh) {
      it->second.name = name;
      it->second.file = file;
      if (!iterations.count(name) || !medians.count(name)) order.push_back(name);
    } else if (type == "aggregate") {
      throw invalid_input(where + ": the median of " + name + " is given twice");
    }
    it->second.ns.push_back(ns);
  }
  std::map<std::string, std::string> seen;  // name -> the file that gave it
  for (const auto& b : out.benchmarks) seen.emplace(b.name, b.file);
  for (const std::string& name : order) {
    if (const auto [it, fresh] = seen.emplace(name, file); !fresh)
      throw invalid_input(file + ": benchmark " + name + " is in " + it->second + " of this run too");
    out.benchmarks.push_back(iterations.count(name) ? iterations[name] : medians[name]);
  }
}

/// The member at a path of keys ("suite", "name"), or null when the file has none.
nlohmann::json member_at(const nlohmann::json& j, std::initializer_list<const char*> keys) {
  const nlohmann::json* at = &j;
  for (const char* k : keys) {
    if (!at->is_object() || !at->contains(k)) return nullptr;
    at = &(*at)[k];
  }
  return *at;
}

results_file records_file_of(const nlohmann::json& j, const std::string& file) {
  results_file f;
  f.path = file;
  f.schema = member_at(j, {"schema"});
  f.suite_name = member_at(j, {"suite", "name"});
  f.suite_version = member_at(j, {"suite", "version"});
  f.quick = member_at(j, {"context", "quick"});
  if (j.contains("checks"))
    f.kind = "check --json output";
  else if (j.contains("schema") || j.contains("suite"))
    f.kind = member_at(j, {"context", "subject"}).is_null() ? "accuracy results" : "subject results";
  else
    f.kind = "records";
  return f;
}

/// A field's value as the messages show it: its JSON (cut), or "none" when the file has none.
std::string shown(const nlohmann::json& v) { return v.is_null() ? "none" : io::field::shown_value(v); }

/// Refuses b and n unless they agree on every field compare checks (see the header).
void check_same_suite(const results_file& b, const results_file& n) {
  const auto refuse = [&](const std::string& field, const std::string& bv, const std::string& nv,
                          const std::string& why) {
    throw invalid_input(b.path + " and " + n.path + " are not runs of one suite: " + field + " is " + bv + " in " +
                        b.path + " and " + nv + " in " + n.path + " (" + why + ")");
  };
  if (b.kind != n.kind)
    refuse("the kind", b.kind, n.kind,
           "compare compares runs of one kind: accuracy results with accuracy results, subject results with subject "
           "results, check --json output with check --json output; benchmarks with benchmarks in either");
  if (b.schema != n.schema)
    refuse(b.kind == "Google Benchmark JSON" ? "context.json_schema_version" : "\"schema\"", shown(b.schema),
           shown(n.schema), "the files' fields may not mean the same");
  if (b.suite_name != n.suite_name)
    refuse("suite.name", shown(b.suite_name), shown(n.suite_name), "runs of different case suites");
  if (b.suite_version != n.suite_version)
    refuse("suite.version", shown(b.suite_version), shown(n.suite_version),
           "the suite's version changes when a case does, so one key may measure another curve: rerun the base with "
           "this suite");
  if (b.quick != n.quick)
    refuse("context.quick", shown(b.quick), shown(n.quick),
           "a quick run measures each key on fewer samples than a full run, so their errors differ without a "
           "change: compare two quick or two full runs");
}

void read_file_into(const std::string& path, run_results& out) {
  read_results(io::parse(read_input_file(path, "", max_results_bytes), path), path, out);
}

}  // namespace

double mann_whitney_min_p(std::size_t n1, std::size_t n2) {
  if (n1 == 0 || n2 == 0) return 1;
  if (n1 <= exact_limit && n2 <= exact_limit) {
    const std::vector<double> c = u_counts(n1, n2);
    double total = 0;
    for (double x : c) total += x;
    return std::min(1.0, 2 * c[0] / total);
  }
  const double n1d = static_cast<double>(n1), n2d = static_cast<double>(n2);
  const double mu = n1d * n2d / 2, sigma = std::sqrt(n1d * n2d * (n1d + n2d + 1) / 12);
  return std::min(1.0, normal_two_sided((mu - 0.5) / sigma));
}

namespace {

struct ranked {
  double u = 0;        ///< pairs a > b plus half the ties between the samples
  double tie_sum = 0;  ///< sum of t^3 - t over the tie groups, for the variance
  bool ties = false;
};

ranked rank_u(std::span<const double> a, std::span<const double> b) {
  const std::size_t n1 = a.size(), n2 = b.size();
  // U from the ranks of one sort of both samples: each value's rank is the mean of the ranks its tie
  // group spans, so a tie between the samples gives each side half, as the pairwise count does.
  // Twice the ranks are integers (a group of ranks i + 1 .. j has mean (i + 1 + j) / 2), so the
  // rank sum and U are exact (2 x (n1 + n2)^2 fits 64 bits for any sample that fits memory).
  std::vector<std::pair<double, bool>> all;  // (value, from a)
  all.reserve(n1 + n2);
  for (double x : a) all.emplace_back(x, true);
  for (double y : b) all.emplace_back(y, false);
  for (const auto& [v, from_a] : all)
    if (std::isnan(v))
      throw invalid_input(std::string("the Mann-Whitney U test: sample ") + (from_a ? "a" : "b") +
                          " holds NaN, which has no rank");
  std::sort(all.begin(), all.end(), [](const auto& x, const auto& y) { return x.first < y.first; });
  ranked r;
  std::uint64_t twice_rank_sum = 0;  // of a's values
  for (std::size_t i = 0; i < all.size();) {
    std::size_t j = i;
    std::uint64_t in_a = 0;
    while (j < all.size() && all[j].first == all[i].first) in_a += all[j++].second ? 1 : 0;
    twice_rank_sum += in_a * (i + 1 + j);
    const double t = static_cast<double>(j - i);
    if (t > 1) r.ties = true, r.tie_sum += t * t * t - t;
    i = j;
  }
  r.u = static_cast<double>(twice_rank_sum - static_cast<std::uint64_t>(n1) * (n1 + 1)) / 2;
  return r;
}

}  // namespace

double mann_whitney_u(std::span<const double> a, std::span<const double> b) { return rank_u(a, b).u; }

double mann_whitney_p(std::span<const double> a, std::span<const double> b) {
  const std::size_t n1 = a.size(), n2 = b.size();
  if (n1 == 0 || n2 == 0) return 1;
  const auto [u, tie_sum, ties] = rank_u(a, b);
  if (!ties && n1 <= exact_limit && n2 <= exact_limit) {
    const std::vector<double> c = u_counts(n1, n2);
    double total = 0, below = 0, above = 0;
    const auto k = static_cast<std::size_t>(u);  // an integer without ties
    for (std::size_t i = 0; i < c.size(); ++i) {
      total += c[i];
      if (i <= k) below += c[i];
      if (i >= k) above += c[i];
    }
    return std::min(1.0, 2 * std::min(below, above) / total);
  }
  const double n1d = static_cast<double>(n1), n2d = static_cast<double>(n2), n = n1d + n2d;
  const double variance = n1d * n2d / 12 * ((n + 1) - tie_sum / (n * (n - 1)));
  if (!(variance > 0)) return 1;  // every value equal
  const double z = std::max(0.0, std::abs(u - n1d * n2d / 2) - 0.5) / std::sqrt(variance);
  return std::min(1.0, normal_two_sided(z));
}

void read_results(const nlohmann::json& j, const std::string& path, run_results& out) {
  if (!j.is_object() || (!j.contains("records") && !j.contains("benchmarks")))
    throw invalid_input(path +
                        ": holds neither \"records\" (accuracy.json, check --json) nor \"benchmarks\" (Google "
                        "Benchmark JSON)");
  if (j.contains("records")) {
    read_records(j, path, "records", out);
    out.record_files.push_back(records_file_of(j, path));
  }
  // accuracy.json's records of the peer libraries (GSL, Boost, ...): their errors compared too.
  if (j.contains("peer_records")) read_records(j, path, "peer_records", out);
  if (j.contains("benchmarks")) {
    read_benchmarks(j, path, out);
    results_file f;
    f.path = path;
    f.kind = "Google Benchmark JSON";
    f.schema = member_at(j, {"context", "json_schema_version"});
    out.benchmark_files.push_back(std::move(f));
  }
}

std::string error_unit(const record& r) {
  namespace q = vocab::quantities;
  for (const vocab::quantity* relative : {&q::length, &q::s_of_u, &q::u_of_s})
    if (r.quantity == relative->id) return "rel-L";
  if (r.quantity == q::eval.id) return "ulp-double";  // points and channel values alike (check.hpp)
  if (r.quantity == q::channel_monotone.id) return "count";
  // The channel quantities are in eps of the model's precision, which the setting's bits names.
  bool float_bits = false;
  for (std::size_t at = 0; at <= r.setting.size();) {
    const std::size_t comma = std::min(r.setting.find(',', at), r.setting.size());
    float_bits = float_bits || r.setting.substr(at, comma - at) == "bits=32";
    at = comma + 1;
  }
  const std::string eps = float_bits ? "ulp-float" : "ulp-double";
  for (const vocab::quantity* ulps : {&q::channel_value, &q::channel_keys, &q::channel_time})
    if (r.quantity == ulps->id) return eps;
  if (r.quantity == q::channel_rotation.id) return eps + "-rad";
  return "";
}

run_results read_run(const std::string& path) {
  namespace fs = std::filesystem;
  run_results out;
  out.path = path;
  std::error_code ec;
  if (fs::is_directory(path, ec)) {
    // A result directory (reports/): accuracy.json and the benchmarks' bench_*.json, in name order.
    std::vector<std::string> files;
    for (const auto& entry : fs::directory_iterator(path, ec)) {
      const std::string name = entry.path().filename().string();
      if (name == "accuracy.json" || (name.starts_with("bench_") && name.ends_with(".json")))
        files.push_back(entry.path().string());
    }
    if (ec) throw invalid_input(path + ": cannot be listed (" + ec.message() + ")");
    std::sort(files.begin(), files.end());
    if (files.empty())
      throw invalid_input(path +
                          ": a directory with no accuracy.json and no bench_*.json (the results of "
                          "scripts/bench.sh are in reports/)");
    for (const std::string& f : files) read_file_into(f, out);
    return out;
  }
  read_file_into(path, out);
  return out;
}

std::size_t comparison::regressions() const {
  std::size_t n = 0;
  for (const record_change& r : records) n += r.regression() ? 1 : 0;
  for (const time_change& t : times) n += t.slower ? 1 : 0;
  return n;
}

comparison compare_runs(const run_results& base, const run_results& now, const compare_options& o) {
  // One suite, or nothing is compared (see the header): every records file of one run against
  // every one of the other, then the benchmark files; then the schema this build reads.
  for (const results_file& b : base.record_files)
    for (const results_file& n : now.record_files) check_same_suite(b, n);
  for (const results_file& b : base.benchmark_files)
    for (const results_file& n : now.benchmark_files)
      if (!b.schema.is_null() && !n.schema.is_null()) check_same_suite(b, n);
  for (const run_results* run : {&base, &now})
    for (const results_file& f : run->record_files)
      if (!f.schema.is_null() && f.schema != 1)
        throw invalid_input(f.path + ": \"schema\" " + shown(f.schema) +
                            ": this curvebench compares results of schema 1, whose fields it knows");
  comparison c;
  c.base = base.path;
  c.now = now.path;
  c.options = o;
  // Records by their key, which is unique in a run (a key written twice would leave the match to
  // the order of the file: refused).
  const auto keys_of = [](const run_results& r) {
    std::map<std::string, std::size_t> keys;
    for (std::size_t i = 0; i < r.records.size(); ++i) {
      const auto [it, fresh] = keys.try_emplace(key_of(r.records[i]), i);
      if (!fresh)
        throw invalid_input(r.record_where[i] + ": the same record as " + r.record_where[it->second] + " (" +
                            it->first + "): a run holds each record once, so compare cannot tell which to match");
    }
    return keys;
  };
  const std::map<std::string, std::size_t> base_keys = keys_of(base), now_keys = keys_of(now);
  for (std::size_t i = 0; i < now.records.size(); ++i) {
    const record& n = now.records[i];
    const std::string key = key_of(n);
    const auto it = base_keys.find(key);
    if (it == base_keys.end()) {
      c.records_added.push_back(key);
      continue;
    }
    const record& b = base.records[it->second];
    ++c.records_matched;
    record_change ch;
    ch.key = key;
    ch.where = now.record_where[i];
    ch.unit = error_unit(n);
    ch.base_error = b.error;
    ch.new_error = n.error;
    const auto check_unit = [](const record& r) {
      const auto u = r.extra.find("unit");
      return u != r.extra.end() && u->is_string() && r.extra.contains("error_in_unit") ? u->get<std::string>() : "";
    };
    const auto in_unit = [](const record& r) {
      const auto e = r.extra.find("error_in_unit");
      return e->is_number() ? e->get<double>() : std::numeric_limits<double>::quiet_NaN();
    };
    if (const std::string u = check_unit(n); !u.empty() && u == check_unit(b)) {
      ch.check_unit = u;
      ch.base_in_unit = in_unit(b);
      ch.new_in_unit = in_unit(n);
    }
    ch.base_status = b.status;
    ch.new_status = n.status;
    const double margin = floor_of(n.quantity, o);
    if (std::isfinite(b.error) && std::isfinite(n.error)) {
      ch.error_grew = n.error > b.error * (1 + o.max_error_growth) + margin;
      ch.improved = n.error * (1 + o.max_error_growth) + margin < b.error;
    }
    ch.unmeasured = std::isfinite(b.error) && !std::isfinite(n.error);
    ch.bound_lost = b.bounded == true && n.bounded == false;
    if (ch.regression() || ch.improved) c.records.push_back(std::move(ch));
  }
  for (const auto& [key, index] : base_keys)
    if (!now_keys.count(key)) c.records_removed.push_back(key);
  // Benchmarks by run name.
  std::map<std::string, const bench_times*> base_bench;
  for (const bench_times& b : base.benchmarks) base_bench[b.name] = &b;
  std::set<std::string> matched;
  std::size_t untestable = 0;
  for (const bench_times& n : now.benchmarks) {
    const auto it = base_bench.find(n.name);
    if (it == base_bench.end()) {
      c.benchmarks_added.push_back(n.name);
      continue;
    }
    matched.insert(n.name);
    const bench_times& b = *it->second;
    time_change t;
    t.name = n.name;
    t.base_n = b.ns.size();
    t.new_n = n.ns.size();
    t.base_ns = median(b.ns);
    t.new_ns = median(n.ns);
    t.change = t.base_ns > 0 ? t.new_ns / t.base_ns - 1 : (t.new_ns > 0 ? std::numeric_limits<double>::infinity() : 0);
    t.p = mann_whitney_p(b.ns, n.ns);
    t.testable = mann_whitney_min_p(t.base_n, t.new_n) < o.alpha;
    if (!t.testable) ++untestable;
    c.times.push_back(std::move(t));
  }
  // Holm's step-down correction over the testable benchmarks: the k-th smallest p times (m - k + 1),
  // kept monotone. The family-wise chance of a false regression stays below alpha.
  std::vector<time_change*> tested;
  for (time_change& t : c.times)
    if (t.testable) tested.push_back(&t);
  std::sort(tested.begin(), tested.end(), [](const time_change* x, const time_change* y) { return x->p < y->p; });
  double running = 0;
  for (std::size_t k = 0; k < tested.size(); ++k) {
    running = std::max(running, std::min(1.0, tested[k]->p * static_cast<double>(tested.size() - k)));
    tested[k]->p_holm = running;
  }
  std::vector<double> changes;
  for (time_change& t : c.times) {
    t.significant = t.testable && t.p_holm < o.alpha;
    t.slower = t.significant && t.change > o.max_time_growth;
    t.faster = t.significant && t.change < -o.max_time_growth;
    changes.push_back(t.change);
  }
  if (!changes.empty()) c.drift = median(changes);
  // The largest changes first: the tables open with what matters.
  std::stable_sort(c.times.begin(), c.times.end(),
                   [](const time_change& x, const time_change& y) { return x.change > y.change; });
  const auto growth = [](const record_change& r) {
    return std::isfinite(r.new_error) && std::isfinite(r.base_error) && r.base_error > 0 ? r.new_error / r.base_error
                                                                                         : 0.0;
  };
  std::stable_sort(c.records.begin(), c.records.end(), [&](const record_change& x, const record_change& y) {
    if (x.regression() != y.regression()) return x.regression();
    if (x.bound_lost != y.bound_lost) return x.bound_lost;
    return growth(x) > growth(y);
  });
  for (const bench_times& b : base.benchmarks)
    if (!matched.count(b.name)) c.benchmarks_removed.push_back(b.name);
  if (untestable > 0) {
    // The fewest equal repetitions a side whose complete separation reaches p < alpha.
    std::size_t need = 2;
    while (need < 1000 && mann_whitney_min_p(need, need) >= o.alpha) ++need;
    c.warnings.push_back(std::to_string(untestable) + " of " + std::to_string(c.times.size()) +
                         " benchmarks have too few repetitions for the U test to reach p < " + detail::num(o.alpha, 3) +
                         " (at least " + std::to_string(need) +
                         " a side: --benchmark_repetitions); their changes are shown, never counted as regressions");
  }
  if (c.records_matched == 0 && c.times.empty())
    throw invalid_input(base.path + " and " + now.path +
                        " share no record and no benchmark: nothing was compared (two runs of the same kind of "
                        "results are needed: accuracy or check results, or benchmark JSON)");
  return c;
}

nlohmann::json to_json(const comparison& c) {
  const auto num = [](double x) { return finite_or_null(x); };
  nlohmann::json records = nlohmann::json::array();
  for (const record_change& r : c.records) {
    nlohmann::json j{{"key", r.key},
                     {"where", r.where},
                     {"unit", r.unit.empty() ? nlohmann::json() : nlohmann::json(r.unit)},
                     {"base_error", num(r.base_error)},
                     {"new_error", num(r.new_error)},
                     {"check_unit", r.check_unit.empty() ? nlohmann::json() : nlohmann::json(r.check_unit)},
                     {"base_in_unit", num(r.base_in_unit)},
                     {"new_in_unit", num(r.new_in_unit)},
                     {"base_status", r.base_status},
                     {"new_status", r.new_status},
                     {"error_grew", r.error_grew},
                     {"unmeasured", r.unmeasured},
                     {"bound_lost", r.bound_lost},
                     {"improved", r.improved},
                     {"regression", r.regression()}};
    records.push_back(std::move(j));
  }
  nlohmann::json times = nlohmann::json::array();
  for (const time_change& t : c.times)
    times.push_back({{"name", t.name},
                     {"base_repetitions", t.base_n},
                     {"new_repetitions", t.new_n},
                     {"base_ns", num(t.base_ns)},
                     {"new_ns", num(t.new_ns)},
                     {"change", num(t.change)},
                     {"p", num(t.p)},
                     {"p_holm", num(t.p_holm)},
                     {"significant", t.significant},
                     {"testable", t.testable},
                     {"slower", t.slower},
                     {"faster", t.faster}});
  return {{"base", c.base},
          {"new", c.now},
          {"options",
           {{"max_error_growth", c.options.max_error_growth},
            {"ulps_floor", c.options.ulps_floor},
            {"relative_floor", c.options.relative_floor},
            {"max_time_growth", c.options.max_time_growth},
            {"alpha", c.options.alpha}}},
          {"records_matched", c.records_matched},
          {"records", records},
          {"records_removed", c.records_removed},
          {"records_added", c.records_added},
          {"benchmarks", times},
          {"drift", num(c.drift)},
          {"benchmarks_removed", c.benchmarks_removed},
          {"benchmarks_added", c.benchmarks_added},
          {"warnings", c.warnings},
          {"regressions", c.regressions()}};
}

}  // namespace curvebench::harness
