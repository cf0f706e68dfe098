// Two runs compared (`curvebench compare BASE NEW`): did an error grow, did an estimate stop bounding
// its error, did a benchmark get slower, and is the slowdown real or noise?
//
// A run is a results file or a directory of them: accuracy.json, the JSON of `curvebench check
// --json`, a subject's results (each holding "records", harness/record.hpp) and Google Benchmark
// JSON files (holding "benchmarks"; a directory's bench_*.json). Both kinds may sit in one file.
//
// Only runs of one suite are compared: errors measured on other cases, other samples or fields of
// another meaning would pass or fail by accident. When both runs hold records, every records file
// of one must agree with every records file of the other on
//   - its kind: accuracy results (accuracy.json: "schema" and "suite"), subject results (the same
//     with context.subject), check --json output ("checks"), or a file of bare "records";
//   - "schema" (this build compares schema 1 only);
//   - suite.name and suite.version (harness/cases.hpp: the version changes when a case does, so a
//     key of another version may measure another curve);
//   - context.quick (a quick run samples fewer times and parameters: the same key's error is a
//     maximum over other samples).
// Benchmark files must agree on Google Benchmark's context.json_schema_version where both write
// one. Anything else may differ, and is what a comparison is for: the curvebench revision, the
// compiler, the flags, the machine, the date (context.revision, compiler, flags; Google Benchmark's
// host and executable). A run of records against a run of benchmarks only is compared as it is
// (nothing matches: the records are removed or added). A difference is invalid_input naming both
// files, the field and both values.
//
// Records are matched by case, group, quantity, method, setting, subject and peer library (the k-th
// record of a key in one run with the k-th in the other). A matched record regresses when
//   - its error grew: new > base x (1 + max_error_growth) + floor, where floor is the rounding level
//     of the quantity's unit (ulps_floor for errors in eps units: eval, channel values, keys, time
//     residuals, rotations; relative_floor for errors relative to the length: length, s_of_u,
//     u_of_s; 0 for counts: channel_monotone), so that rounding-level wobble between compilers is
//     not a regression;
//   - it is no longer measured (a finite error became null);
//   - its estimate stopped bounding its error (bounded true became false).
// Errors are deterministic for one build, so these need no statistics. Each change carries its
// error's unit (error_unit below), in which both errors are written.
//
// Benchmarks are matched by run name. Their times (cpu_time per iteration, in ns) are the
// repetitions of the run (entries of run_type "iteration"; an aggregate-only file gives its median
// as one sample). A benchmark regresses when the median time grew by more than max_time_growth AND
// the two-sided Mann-Whitney U test of the two samples gives p < alpha after Holm's correction over
// every tested benchmark (a full run has hundreds: at alpha each, some would fail by chance). With
// too few repetitions for any p below alpha (3 against 3 cannot go under 0.1), the change is
// reported as not confident, with a warning naming the repetitions needed; it never fails.
// Repetitions see the noise within one run only. Between two runs of one build the medians move
// further on a shared machine (measured here, a 2-core VM, 4 kernels of 10-45 ns, repetitions
// interleaved: up to 46 %, tests/data/compare/README.md), so the default margin is 50 %: a doubled
// time fails, this machine's drift does not. On a quiet machine a smaller margin holds; measure
// yours by comparing two runs of one build. The report gives the median change over all benchmarks
// (the run's drift) beside each change.
#pragma once

#include "harness/record.hpp"

#include <nlohmann/json.hpp>

#include <cstddef>
#include <limits>
#include <span>
#include <string>
#include <vector>

namespace curvebench::harness {

struct compare_options {
  double max_error_growth = 0.10;  ///< relative growth of an error beyond which it regresses
  double ulps_floor = 4;           ///< growth in eps units below this is rounding (eval, channels)
  double relative_floor = 1e-15;   ///< growth of a relative error (length, s(u), u(s)) below this is rounding
  double max_time_growth = 0.5;    ///< relative growth of a median time beyond which it may regress
  double alpha = 0.05;             ///< the U test's p must be below this for a confident change
};

/// One benchmark's times in one run.
struct bench_times {
  std::string name;        ///< the run name (without the aggregate suffix)
  std::string file;        ///< the file it came from
  std::vector<double> ns;  ///< cpu time per iteration of each repetition (aggregates only: the median), ns
};

/// What a results file says it is, the fields compare checks before matching anything (see the
/// header); a field the file does not have is null.
struct results_file {
  std::string path;
  std::string kind;              ///< "accuracy results", "subject results", "check --json output", "records",
                                 ///< "Google Benchmark JSON"
  nlohmann::json schema;         ///< "schema"; for benchmarks context.json_schema_version
  nlohmann::json suite_name;     ///< suite.name
  nlohmann::json suite_version;  ///< suite.version
  nlohmann::json quick;          ///< context.quick
};

/// A run: its records and its benchmarks, and the files they came from.
struct run_results {
  std::string path;
  std::vector<record> records;
  std::vector<std::string> record_where;  ///< "accuracy.json: records[3]" per record
  std::vector<bench_times> benchmarks;
  std::vector<results_file> record_files;     ///< the files that gave records
  std::vector<results_file> benchmark_files;  ///< the files that gave benchmarks
};

/// Reads a results file or directory (see the header). invalid_input naming the file and the entry
/// for a file that is neither, a malformed record or benchmark, a benchmark named twice in a run, or a
/// directory with no results file.
[[nodiscard]] run_results read_run(const std::string& path);

/// Adds the records and benchmarks of one results file already parsed (`file` names it in
/// messages) to `out`, as read_run does for each file: the same errors.
void read_results(const nlohmann::json& j, const std::string& file, run_results& out);

/// The unit of a record's error, from its quantity and setting (vocabulary.hpp's docs say how each
/// is measured): "rel-L" (relative to the curve's length: length, s_of_u, u_of_s), "ulp-double"
/// (eps(double) times the curve's size or the channel's value range: eval, and the channel
/// quantities at bits=64 or without bits), "ulp-float" (eps(float) times the same: the channel
/// quantities at bits=32), "ulp-double-rad" / "ulp-float-rad" (a rotation angle in eps radians:
/// channel_rotation), "count" (channel_monotone); "" for a quantity this build does not know.
[[nodiscard]] std::string error_unit(const record& r);

struct record_change {
  std::string key;                       ///< "case/quantity/method/setting" (and subject, peer) as the table shows it
  std::string where;                     ///< the new record's place
  std::string unit;                      ///< the errors' unit (error_unit); "": unknown
  double base_error = 0, new_error = 0;  ///< NaN: not measured
  /// A check's record ("unit" and "error_in_unit" on both sides, the same unit): the errors as the
  /// check printed them, in check_unit ("ulp-float", "rel", ...); "" and NaN otherwise.
  std::string check_unit;
  double base_in_unit = std::numeric_limits<double>::quiet_NaN(), new_in_unit = base_in_unit;
  std::string base_status, new_status;
  bool bound_lost = false;
  bool error_grew = false;
  bool unmeasured = false;  ///< a finite error became null
  bool improved = false;    ///< the error shrank beyond the same margin
  [[nodiscard]] bool regression() const { return bound_lost || error_grew || unmeasured; }
};

struct time_change {
  std::string name;
  std::size_t base_n = 0, new_n = 0;
  double base_ns = 0, new_ns = 0;       ///< the medians
  double change = 0;                    ///< new_ns / base_ns - 1
  double p = 1;                         ///< two-sided U test
  double p_holm = 1;                    ///< p after Holm's correction over the tested benchmarks
  bool testable = false;                ///< enough repetitions for p < alpha
  bool slower = false, faster = false;  ///< confident: beyond the margin and p_holm < alpha
  bool significant = false;             ///< p_holm < alpha, whatever the size of the change
};

struct comparison {
  std::string base, now;
  compare_options options;
  std::size_t records_matched = 0;
  std::vector<record_change> records;  ///< regressions and improvements only
  std::vector<std::string> records_removed, records_added;
  std::vector<time_change> times;  ///< every matched benchmark
  double drift = 0;                ///< the median change over the matched benchmarks
  std::vector<std::string> benchmarks_removed, benchmarks_added;
  std::vector<std::string> warnings;
  [[nodiscard]] std::size_t regressions() const;
};

/// Compares two runs read by read_run. invalid_input naming both files, the field and both values
/// when they are not runs of one suite (see the header), naming the file for a schema other than 1,
/// and when the runs share no record and no benchmark (nothing would be compared).
[[nodiscard]] comparison compare_runs(const run_results& base, const run_results& now,
                                      const compare_options& options = {});

/// The comparison as JSON (the options, counts, every change with its error unit, warnings,
/// "regressions").
[[nodiscard]] nlohmann::json to_json(const comparison& c);

/// The two-sided p-value of the Mann-Whitney U test of samples a and b: exact (the distribution of U
/// counted over all orderings) when neither has more than 20 values and there are no ties, else
/// the normal approximation with the tie correction and a continuity correction of 1/2. U is the
/// rank sum of a (average ranks over ties) less n1 (n1 + 1) / 2, which is the count of pairs a > b
/// plus half the ties: one sort, O(n log n) (1e5 repetitions a side counted pair by pair took
/// 18 s). invalid_input for a NaN, which has no rank.
[[nodiscard]] double mann_whitney_p(std::span<const double> a, std::span<const double> b);
/// The U statistic of a against b that mann_whitney_p tests: from the ranks, as above.
[[nodiscard]] double mann_whitney_u(std::span<const double> a, std::span<const double> b);
/// The smallest two-sided p the test can give for sizes n1 and n2 (complete separation, no ties).
[[nodiscard]] double mann_whitney_min_p(std::size_t n1, std::size_t n2);

}  // namespace curvebench::harness
