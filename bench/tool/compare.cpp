// curvebench compare BASE NEW: two runs (result files or directories) compared record by record and
// benchmark by benchmark (harness/compare.hpp); exit 1 only on a confident regression.
#include "tool/tool.hpp"

#include "harness/check_detail.hpp"
#include "harness/compare.hpp"
#include "harness/csv.hpp"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <sstream>

namespace curvebench::tool {

namespace {

/// x to `digits` significant digits ("null" when not finite: an error not measured, as in JSON).
std::string g(double x, int digits = 3) { return std::isfinite(x) ? harness::detail::num(x, digits) : "null"; }

/// A change as a percentage, or as a factor once it passes 100x ("x2.1e+03", not 200000.0%).
std::string percent(double change) {
  std::ostringstream os;
  if (std::isfinite(change) && change >= 99)
    os << "x" << std::setprecision(3) << change + 1;
  else
    os << std::showpos << std::fixed << std::setprecision(1) << 100 * change << "%";
  return os.str();
}

std::string time_line(const harness::time_change& t) {
  return t.name + ": " + g(t.base_ns, 4) + " ns -> " + g(t.new_ns, 4) + " ns (" + percent(t.change) +
         ", p = " + g(t.p, 2) + ", Holm " + g(t.p_holm, 2) + ", " + std::to_string(t.base_n) + " vs " +
         std::to_string(t.new_n) + " repetitions)";
}

std::string record_line(const harness::record_change& r) {
  std::string why;  // a regression's kind; an improvement's table label says it
  if (r.error_grew) why = "error grew";
  if (r.unmeasured) why = "no longer measured";
  if (r.bound_lost) why += std::string(why.empty() ? "" : ", ") + "estimate no longer bounds the error";
  // Each error with its unit (harness::error_unit): "9.92e+09 ulp-double" says what "9.92e+09" cannot.
  const std::string unit = r.unit.empty() ? "" : " " + r.unit;
  std::string line = (why.empty() ? "" : why + ": ") + r.key + ": error ";
  // A check's figures in the unit the check printed them (its --unit), the records' beside them.
  if (!r.check_unit.empty())
    line += g(r.base_in_unit) + " " + r.check_unit + " -> " + g(r.new_in_unit) + " " + r.check_unit + " (records: ";
  line += g(r.base_error) + unit + " -> " + g(r.new_error) + unit;
  if (!r.check_unit.empty()) line += ")";
  if (r.unit.empty()) line += " (a quantity of no unit this build knows)";
  if (r.base_status != r.new_status) line += ", status " + r.base_status + " -> " + r.new_status;
  return line + " (" + r.where + ")";
}

template <class T, class Keep, class Line>
void print_some(const std::vector<T>& rows, Keep keep, const std::string& label, Line line, std::size_t show) {
  std::size_t shown = 0, total = 0;
  for (const T& r : rows) {
    if (!keep(r)) continue;
    if (shown < show) {
      std::cout << label << " " << line(r) << "\n";
      ++shown;
    }
    ++total;
  }
  if (total > shown) std::cout << label << " ... and " << total - shown << " more (--json lists them all)\n";
}

}  // namespace

CLI::App* add_compare(CLI::App& app, compare_args& a) {
  auto* cmp = app.add_subcommand(
      "compare",
      "compare two runs (accuracy/check results, Google Benchmark JSON, or result directories such as reports/): "
      "errors that grew (each in its unit), estimates that stopped bounding, benchmarks slower with a Mann-Whitney U "
      "test; exit 1 only on a confident regression. Runs of different suites are refused: another kind of file, "
      "schema, suite name or version, or a quick run against a full one (the curvebench revision may differ)");
  cmp->add_option("base", a.base, "the baseline run: a results file or a directory (accuracy.json, bench_*.json)")
      ->required()
      ->check(CLI::ExistingPath);
  cmp->add_option("new", a.now, "the new run, the same kinds of files")->required()->check(CLI::ExistingPath);
  cmp->add_flag("--json", a.json, "JSON on stdout: the options, every change, the warnings, the regressions");
  cmp->add_option("--max-error-growth", a.options.max_error_growth,
                  "an error regresses when new > base x (1 + X) + the unit's rounding floor (default 0.1)")
      ->check(non_negative_finite());
  cmp->add_option("--ulps-floor", a.options.ulps_floor,
                  "the rounding floor of errors in eps units (eval, channel values): default 4")
      ->check(non_negative_finite());
  cmp->add_option("--relative-floor", a.options.relative_floor,
                  "the rounding floor of errors relative to the length (length, s_of_u, u_of_s): default 1e-15")
      ->check(non_negative_finite());
  cmp->add_option(
         "--max-time-growth", a.options.max_time_growth,
         "a benchmark regresses when its median time grew by more than X (default 0.5: a shared machine drifts "
         "tens of percent between runs) with p < --alpha after Holm's correction")
      ->check(non_negative_finite());
  cmp->add_option("--alpha", a.options.alpha, "the U test's significance level, in [1e-12, 1] (default 0.05)")
      ->check(CLI::Validator(
          [](std::string& text) -> std::string {
            double v = 0;
            return harness::parse_finite(text, v) && v >= 1e-12 && v <= 1
                       ? ""
                       : "\"" + text + "\" is not a level in [1e-12, 1]";
          },
          "LEVEL"));
  cmp->add_option("--show", a.show, "rows shown per table (default 20; --json has them all)")
      ->check(CLI::Range(std::size_t(0), std::size_t(1000000)));
  cmp->footer(example("cp -r reports /tmp/base && scripts/bench.sh && curvebench compare /tmp/base reports") +
              example("curvebench compare base/accuracy.json reports/accuracy.json --max-error-growth 0"));
  return cmp;
}

int run_compare(const compare_args& a) {
  const harness::run_results base = harness::read_run(a.base);
  const harness::run_results now = harness::read_run(a.now);
  const harness::comparison c = harness::compare_runs(base, now, a.options);
  const std::size_t regressions = c.regressions();
  if (a.json) {
    std::cout << std::setw(1) << harness::to_json(c) << "\n";
    for (const std::string& w : c.warnings) std::cerr << "curvebench: compare: warning: " << w << "\n";
    if (regressions > 0) say_verdict("compare", regressions, "confident regression", "confident regressions");
    return regressions > 0 ? 1 : 0;
  }
  const auto count = [](const auto& rows, auto keep) {
    return static_cast<std::size_t>(std::count_if(rows.begin(), rows.end(), keep));
  };
  const auto& o = c.options;
  std::cout << "compare " << c.base << " -> " << c.now << "\n";
  std::cout << "records: " << c.records_matched << " matched; "
            << count(c.records, [](const auto& r) { return r.error_grew; }) << " errors grew by more than "
            << g(100 * o.max_error_growth + 0.0) << "% plus the rounding floor, "
            << count(c.records, [](const auto& r) { return r.bound_lost; }) << " estimates stopped bounding, "
            << count(c.records, [](const auto& r) { return r.unmeasured; }) << " no longer measured, "
            << count(c.records, [](const auto& r) { return r.improved; }) << " improved; " << c.records_removed.size()
            << " removed, " << c.records_added.size() << " added\n";
  std::cout << "benchmarks: " << c.times.size() << " matched; "
            << count(c.times, [](const auto& t) { return t.slower; }) << " slower and "
            << count(c.times, [](const auto& t) { return t.faster; }) << " faster by more than "
            << g(100 * o.max_time_growth + 0.0) << "% with p < " << g(o.alpha) << " (Holm); "
            << count(c.times, [](const auto& t) { return !t.testable; }) << " with too few repetitions to test; "
            << c.benchmarks_removed.size() << " removed, " << c.benchmarks_added.size() << " added\n";
  if (!c.times.empty())
    std::cout << "median change over the matched benchmarks: " << percent(c.drift)
              << " (a shared machine moves every benchmark between runs; a change of code moves those it touches)\n";
  print_some(
      c.records, [](const auto& r) { return r.regression(); }, "REGRESSION", record_line, a.show);
  print_some(
      c.times, [](const auto& t) { return t.slower; }, "SLOWER", time_line, a.show);
  print_some(
      c.records, [](const auto& r) { return !r.regression(); }, "improved", record_line, a.show);
  print_some(
      c.times, [](const auto& t) { return t.faster; }, "faster", time_line, a.show);
  // Changes the test confirms within the margin, and changes past it that it cannot confirm:
  // shown, never counted.
  print_some(
      c.times, [&](const auto& t) { return t.significant && !t.slower && !t.faster; }, "within the margin", time_line,
      a.show);
  print_some(
      c.times, [&](const auto& t) { return !t.significant && std::abs(t.change) > o.max_time_growth; }, "not confident",
      time_line, a.show);
  print_some(
      c.records_removed, [](const auto&) { return true; }, "removed record", [](const auto& k) { return k; }, a.show);
  print_some(
      c.benchmarks_removed, [](const auto&) { return true; }, "removed benchmark", [](const auto& k) { return k; },
      a.show);
  for (const std::string& w : c.warnings) std::cout << "warning: " << w << "\n";
  std::cout << "compare: "
            << (regressions == 0 ? std::string("no confident regression")
                                 : std::to_string(regressions) + (regressions == 1 ? " regression" : " regressions"))
            << "\n";
  if (regressions > 0) say_verdict("compare", regressions, "confident regression", "confident regressions");
  return regressions > 0 ? 1 : 0;
}

}  // namespace curvebench::tool
