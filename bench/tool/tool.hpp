// The pieces of the curvebench tool (bench/tool/): main.cpp wires the subcommands; sample.cpp and
// check.cpp hold the two that take a user's parameters and values; this header the shared helpers.
#pragma once

#include "tool/parameters.hpp"
#include "tool/svg_file.hpp"

#include "harness/compare.hpp"

#include "curvebench/io/spec.hpp"

#include <CLI/CLI.hpp>

#include <chrono>
#include <cmath>
#include <cstddef>
#include <span>
#include <string>
#include <type_traits>
#include <vector>

namespace curvebench::tool {

/// The whole file at `path` (invalid_input naming it when it cannot be read).
std::string read_file(const std::string& path);

/// The spec file at `path`, parsed (errors name the file).
nlohmann::json read_spec(const std::string& path);

/// Calls f(std::integral_constant<int, Dim>) for the spec's dimension (1..4).
template <class F>
void with_dimension(const io::field& spec, F&& f) {
  switch (io::spec_dimension(spec)) {
    case 1: f(std::integral_constant<int, 1>{}); break;
    case 2: f(std::integral_constant<int, 2>{}); break;
    case 3: f(std::integral_constant<int, 3>{}); break;
    default: f(std::integral_constant<int, 4>{}); break;
  }
}

/// The installed data directory next to the running executable, <exe dir>/../share/curvebench (the
/// layout `cmake --install` makes), or "" when the executable has none (a build tree).
std::string installed_data_dir();
/// The default case directory: the installed one, else the source tree's bench/cases.
std::string default_cases_dir();
/// The default thresholds of `gate`: reports/thresholds.json when the working directory has one
/// (a checkout), else the installed one, else reports/thresholds.json (the error then names it).
std::string default_thresholds();

/// "curvebench 0.1.0 (abc1234)": the project version and the git revision the binary was built from.
std::string version_line();

/// A CLI11 check: a finite number > 0, subnormals included (CLI::PositiveNumber starts at the
/// smallest normal double, 2.2e-308, and prints that bound with all its digits).
CLI::Validator positive_finite();
/// A CLI11 validator: a finite number >= 0 (CLI::NonNegativeNumber takes "nan", which disabled a gate).
CLI::Validator non_negative_finite();
/// A CLI11 validator: a non-empty value (`--at ''` is refused, not taken for no --at).
CLI::Validator non_empty();
/// Progress of a long loop on stderr (never stdout): once the run has taken a second, at most one
/// line a second, "sample: 1200 of 100000 (1.2%), 2.0 s elapsed"; nothing when quiet.
class progress {
 public:
  /// planned: the total is the work planned, not a cap; past it the line says so instead of a
  /// percentage above 100.
  progress(std::string what, std::size_t total, bool quiet, bool planned = false);
  /// `done` items of the total are finished.
  void update(std::size_t done);

 private:
  std::string what_;
  std::size_t total_;
  bool quiet_;
  bool planned_;
  std::chrono::steady_clock::time_point start_, next_;
};

/// The footer of a subcommand's --help: one example.
std::string example(const std::string& command);

/// A negative verdict's line on stderr (docs/tool.md, exit codes), where a CI log shows it:
/// "curvebench: gate: 2 breaches (exit 1)"; `one` and `many` are the counted word's two forms.
void say_verdict(const std::string& command, std::size_t count, const std::string& one, const std::string& many);

/// Why a result of `curve` in double is not finite, in the user's terms: the curve's domain, its
/// narrowest breakpoint span and its largest |coordinate| on the breakpoints, which say whether the
/// data exceed double's range (coordinates or derivatives past ~1e308; knot spans so narrow that
/// 1/h^k overflows).
std::string non_finite_cause(std::span<const double> breakpoints, double largest_coordinate);

/// Throws invalid_input "WHAT = nan: not representable in double (CAUSE)" unless `value` is finite:
/// the tool never prints a non-finite number as a result with exit code 0.
template <class Curve>
void require_finite(double value, const std::string& what, const Curve& c) {
  if (std::isfinite(value)) return;
  double largest = 0;
  for (const double u : c.breakpoints()) {
    const auto p = c(u);
    for (int d = 0; d < p.size(); ++d)
      if (!(std::abs(p[d]) <= largest)) largest = std::abs(p[d]);  // NaN is kept
  }
  throw invalid_input(what + " = " + to_text(value) + ": the result is not representable in double (" +
                      non_finite_cause(c.breakpoints(), largest) + ")");
}

// ---- sample (sample.cpp) ------------------------------------------------------------------------

struct sample_args {
  std::string spec;
  std::size_t count = 11;
  std::string by = "u";
  std::string method;  ///< u(s) method for --by arclength; empty: not given (hermite_table)
  bool polish = false;
  double table_tol = 0;  ///< the u(s) table's target relative to L; 0: not given (the library's)
  std::string ease;      ///< distance-time function for --by arclength; empty: not given (linear)
  std::string at;        ///< --at V1,V2,...
  std::string at_file;   ///< --at-file FILE
  std::string range;     ///< --range A:B:STEP
  std::string frames;    ///< --frames A:B[:STEP] (STEP 1 by default)
  int derivatives = 1;   ///< derivative columns: orders 1..K
  bool quiet = false;    ///< no progress on stderr
  bool as_tool = false;  ///< channels: the tool's own evaluation instead of the truth
};
CLI::App* add_sample(CLI::App& app, sample_args& a);
void run_sample(const sample_args& a);

// ---- check (check.cpp) --------------------------------------------------------------------------

struct check_args {
  std::string spec;
  std::string values, lengths, inverse, at_length;
  std::string name = "values";
  bool json = false;
  double max_error = -1;  ///< < 0: none; every kind's limit unless its own is given
  double max_value_error = -1, max_length_error = -1, max_inverse_error = -1,
         max_at_length_error = -1;  ///< < 0: --max-error's
  std::string unit;                 ///< empty: from the digits
  std::string against;              ///< channels: truth or tool (empty: truth, not chosen)
  std::string thresholds;
  std::size_t worst = 5;
  bool quiet = false;  ///< no progress on stderr
};
CLI::App* add_check(CLI::App& app, check_args& a);
/// 0 when every row is within the limits (or none is given), 1 otherwise.
int run_check(const check_args& a);

// ---- fidelity (fidelity.cpp) ----------------------------------------------------------------------

struct fidelity_args {
  std::vector<std::string> recordings;
  bool json = false;
  bool require = false;  ///< exit 1 on a disagreeing channel or a refusal the recording does not mark
};
CLI::App* add_fidelity(CLI::App& app, fidelity_args& a);
/// 0 unless --require-agreement is given and a channel disagrees or is newly refused.
int run_fidelity(const fidelity_args& a);

// ---- compare (compare.cpp) ----------------------------------------------------------------------

struct compare_args {
  std::string base, now;
  bool json = false;
  std::size_t show = 20;  ///< rows of each table shown (the JSON has them all)
  harness::compare_options options;
};
CLI::App* add_compare(CLI::App& app, compare_args& a);
/// 1 when a regression is confident (harness/compare.hpp), else 0.
int run_compare(const compare_args& a);

}  // namespace curvebench::tool
