// The compare target (targets.hpp): what `curvebench compare BASE NEW` does with two results files.
// The input is the base's text, a NUL byte, then the new run's text; without a NUL byte the same
// text is both (a run compared with itself, which keeps seeds and mutations simple).
//
// Properties:
//   documented exceptions only   io::parse, read_results and compare_runs refuse with invalid_input
//                                only, with a non-empty message of bounded size
//   no vacuous pass              a comparison that returns has matched a record or a benchmark
//   one suite                    a comparison that returns is of records files of one kind, schema,
//                                suite name and version and context.quick (compare.hpp)
//   a run against itself         the base compared with itself has no regression and no change
//   sound statistics             every p and Holm p is in [0, 1], Holm's is not below the raw p, and a
//                                benchmark counted slower or faster is significant and past the margin
//   units                        every record change carries its record's unit (error_unit)
//   JSON output                  to_json of the comparison dumps (no NaN, no invalid UTF-8)
#include "guard.hpp"
#include "targets.hpp"

#include "harness/compare.hpp"

#include "curvebench/io/json_fields.hpp"

#include <map>
#include <string>

namespace curvebench::fuzz {

namespace {

constexpr std::string_view name = "compare";

void check_comparison(const harness::comparison& c, const harness::compare_options& o) {
  if (c.records_matched == 0 && c.times.empty())
    violation(name, "no vacuous pass", "a comparison with no record matched and no benchmark");
  for (const harness::time_change& t : c.times) {
    if (!(t.p >= 0 && t.p <= 1) || !(t.p_holm >= 0 && t.p_holm <= 1) || t.p_holm < t.p)
      violation(name, "sound statistics", t.name + ": p " + std::to_string(t.p) + ", Holm " + std::to_string(t.p_holm));
    if ((t.slower || t.faster) && !t.significant)
      violation(name, "sound statistics", t.name + ": counted slower or faster without significance");
    if ((t.slower && !(t.change > o.max_time_growth)) || (t.faster && !(t.change < -o.max_time_growth)))
      violation(name, "sound statistics", t.name + ": counted past the margin with change " + std::to_string(t.change));
  }
  std::string text;
  if (!run_step(name, "to_json", domain_errors::violation, [&] { text = harness::to_json(c).dump(); }))
    violation(name, "JSON output", "to_json refused a comparison it had made");
}

void check_one_suite(const harness::run_results& base, const harness::run_results& now) {
  for (const harness::results_file& b : base.record_files)
    for (const harness::results_file& n : now.record_files)
      if (b.kind != n.kind || b.schema != n.schema || b.suite_name != n.suite_name ||
          b.suite_version != n.suite_version || b.quick != n.quick)
        violation(name, "one suite", b.path + " (" + b.kind + ") compared with " + n.path + " (" + n.kind + ")");
}

}  // namespace

int compare_target(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  const auto nul = text.find('\0');
  const std::string_view base_text = nul == std::string_view::npos ? text : text.substr(0, nul);
  const std::string_view new_text = nul == std::string_view::npos ? text : text.substr(nul + 1);
  harness::run_results base, now;
  base.path = "base.json";
  now.path = "new.json";
  io::json base_json, new_json;
  if (!run_step(name, "parse base", domain_errors::violation, [&] { base_json = io::parse(base_text, "base.json"); }))
    return 0;
  if (!run_step(name, "parse new", domain_errors::violation, [&] { new_json = io::parse(new_text, "new.json"); }))
    return 0;
  if (!run_step(name, "read base", domain_errors::violation,
                [&] { harness::read_results(base_json, "base.json", base); }))
    return 0;
  // The base against itself: whatever it holds, nothing regressed and nothing changed.
  harness::comparison self;
  if (run_step(name, "compare base with itself", domain_errors::violation,
               [&] { self = harness::compare_runs(base, base); })) {
    check_comparison(self, {});
    if (self.regressions() != 0 || !self.records.empty() || !self.records_added.empty() ||
        !self.records_removed.empty() || !self.benchmarks_added.empty() || !self.benchmarks_removed.empty())
      violation(name, "a run against itself",
                std::to_string(self.regressions()) + " regressions, " + std::to_string(self.records.size()) +
                    " record changes");
  }
  if (!run_step(name, "read new", domain_errors::violation, [&] { harness::read_results(new_json, "new.json", now); }))
    return 0;
  const harness::compare_options o;
  harness::comparison c;
  if (!run_step(name, "compare", domain_errors::violation, [&] { c = harness::compare_runs(base, now, o); })) return 0;
  check_one_suite(base, now);
  check_comparison(c, o);
  std::map<std::string, std::size_t> at;  // a new record's place -> its index
  for (std::size_t i = 0; i < now.record_where.size(); ++i) at.emplace(now.record_where[i], i);
  for (const harness::record_change& r : c.records) {
    const auto it = at.find(r.where);
    if (it == at.end() || harness::error_unit(now.records[it->second]) != r.unit)
      violation(name, "units", r.key + ": unit \"" + r.unit + "\" is not its record's (" + r.where + ")");
  }
  return 0;
}

}  // namespace curvebench::fuzz
