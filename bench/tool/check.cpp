// curvebench check: a user's own values (points and derivatives, lengths, inverse parameters) against
// the 50-digit reference of a spec (harness/check.hpp), as a table or JSON, gated by --max-error or
// by thresholds in the gate's rule format.
#include "tool/tool.hpp"

#include "harness/check.hpp"
#include "harness/gate.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <memory>
#include <sstream>
#include <utility>

namespace curvebench::tool {

namespace {

using harness::check_kind;
using harness::check_result;

std::string g(double x, int digits = 3) {
  std::ostringstream os;
  os << std::setprecision(digits) << x;
  return os.str();
}

void print_table(const check_result& r, const std::string& spec) {
  const bool values = r.kind == check_kind::values, times = r.kind == check_kind::times;
  std::cout << "check " << r.file << " (" << harness::to_string(r.kind) << ", " << r.summary.rows << " rows) against ";
  if (times) {
    std::cout << r.against << " of " << spec << ": value range " << g(r.size, 6);
    for (std::size_t k = 0; k < r.derivative_sizes.size(); ++k)
      if (std::isfinite(r.derivative_sizes[k]))
        std::cout << ", " << (k == 0 ? "dvalue" : "d2value") << " size " << g(r.derivative_sizes[k], 6);
  } else {
    std::cout << spec << ": L = " << g(r.length, 17);
    if (std::isfinite(r.tool_length))
      std::cout << "; the L column (s on its scale, asked at s / L of the way): " << g(r.tool_length, 17)
                << ", relative error " << g(r.tool_length_error);
  }
  if (values) {
    std::cout << ", size " << g(r.size, 6);
    for (std::size_t k = 0; k < r.derivative_sizes.size(); ++k)
      if (std::isfinite(r.derivative_sizes[k]))
        std::cout << ", derivative " << k + 1 << " size " << g(r.derivative_sizes[k], 6);
  }
  std::cout << "\n  error (" << harness::unit_text(r);
  if (values || times) std::cout << "; " << r.unit_reason << ", --unit to choose";
  std::cout << "): max " << g(r.summary.max) << ", rms " << g(r.summary.rms);
  std::cout << "; absolute" << (values || times ? "" : " (in the curve's length units)") << ": max "
            << g(r.summary.max_absolute);
  if (r.kind != check_kind::inverse && r.kind != check_kind::times && r.kind != check_kind::at_length)
    std::cout << "; relative" << (values ? " to size" : " to the segment") << ": max " << g(r.summary.max_relative)
              << ", rms " << g(r.summary.rms_relative);
  if (times) {  // a row where the value is flat has no time error (its column shows "-"): not a max of inf
    double late = 0;
    std::size_t flat = 0;
    for (const auto& row : r.rows)
      if (std::isfinite(row.time_error))
        late = std::max(late, row.time_error);
      else
        ++flat;
    if (flat == r.rows.size())
      std::cout << "; time error: none (every row is where the value is flat)";
    else
      std::cout << "; time error: max " << g(late)
                << (flat > 0 ? " (" + std::to_string(flat) + (flat == 1 ? " row" : " rows") +
                                   " where the value is flat: none)"
                             : "");
  }
  std::cout << "\n";
  if (!r.digits_warning.empty()) std::cout << "  warning: " << r.digits_warning << "\n";
  if (r.unchecked > 0)
    std::cout << "  note: " << r.unchecked
              << " derivative cells not checked (empty, or the channel's derivative is unbounded there)\n";
  std::cout << "  worst rows:\n    " << std::left << std::setw(7) << "row";
  switch (r.kind) {
    case check_kind::values: std::cout << std::setw(24) << "u"; break;
    case check_kind::lengths: std::cout << std::setw(24) << "u0" << std::setw(24) << "u1"; break;
    case check_kind::inverse: std::cout << std::setw(24) << "s" << std::setw(24) << "u"; break;
    case check_kind::times: std::cout << std::setw(24) << "t"; break;
    case check_kind::at_length: std::cout << std::setw(24) << "s" << std::setw(24) << "nearest s"; break;
  }
  std::cout << std::setw(11) << "error";
  if (values) {
    std::cout << std::setw(11) << "point";
    for (std::size_t k = 0; k < r.derivative_sizes.size(); ++k)
      if (std::isfinite(r.derivative_sizes[k])) std::cout << std::setw(11) << ("d" + std::to_string(k + 1));
    if (!r.rows.empty() && r.rows.front().s_error >= 0) std::cout << std::setw(11) << "s_error/L";
  } else if (r.kind == check_kind::lengths) {
    std::cout << std::setw(11) << "/segment" << std::setw(11) << "absolute";
  } else if (r.kind == check_kind::inverse) {
    std::cout << std::setw(11) << "absolute";
  } else if (r.kind == check_kind::at_length) {
    std::cout << std::setw(11) << "s_error/L" << std::setw(11) << "off/L";
  } else if (times) {
    std::cout << std::setw(11) << "absolute";
    for (std::size_t k = 0; k < r.derivative_sizes.size(); ++k)
      if (std::isfinite(r.derivative_sizes[k])) std::cout << std::setw(11) << (k == 0 ? "dvalue" : "d2value");
    std::cout << std::setw(11) << "time";
  }
  std::cout << "\n";
  for (std::size_t i : r.worst) {
    const harness::check_row& row = r.rows[i];
    std::cout << "    " << std::setw(7) << row.line;
    switch (r.kind) {
      case check_kind::values: std::cout << std::setw(24) << g(row.u, 17); break;
      case check_kind::lengths: std::cout << std::setw(24) << g(row.u, 17) << std::setw(24) << g(row.u1, 17); break;
      case check_kind::inverse: std::cout << std::setw(24) << g(row.s, 17) << std::setw(24) << g(row.u, 17); break;
      case check_kind::times: std::cout << std::setw(24) << g(row.t, 17); break;
      case check_kind::at_length:
        std::cout << std::setw(24) << (row.s_error >= 0 ? g(row.s, 17) : std::string("-")) << std::setw(24)
                  << g(row.s_true, 17);
        break;
    }
    std::cout << std::setw(11) << g(row.error);
    if (values) {
      std::cout << std::setw(11) << g(row.point_ulps);
      for (std::size_t k = 0; k < row.derivative_ulps.size(); ++k)
        if (std::isfinite(r.derivative_sizes[k])) std::cout << std::setw(11) << g(row.derivative_ulps[k]);
      if (row.s_error >= 0) std::cout << std::setw(11) << g(row.s_error);
    } else if (r.kind == check_kind::lengths) {
      std::cout << std::setw(11) << g(row.relative) << std::setw(11) << g(row.absolute);
    } else if (r.kind == check_kind::inverse) {
      std::cout << std::setw(11) << g(row.absolute);
    } else if (r.kind == check_kind::at_length) {
      std::cout << std::setw(11) << (row.s_error >= 0 ? g(row.s_error) : std::string("-")) << std::setw(11)
                << g(row.off_curve);
    } else if (times) {
      std::cout << std::setw(11) << g(row.absolute);
      for (std::size_t k = 0; k < row.derivative_errors.size(); ++k)
        if (std::isfinite(r.derivative_sizes[k]))
          std::cout << std::setw(11) << (std::isnan(row.derivative_errors[k]) ? "-" : g(row.derivative_errors[k]));
      std::cout << std::setw(11) << (std::isinf(row.time_error) ? "-" : g(row.time_error));
    }
    std::cout << "\n";
  }
  std::cout << std::right;
}

/// The limit of a check kind: its own option, else --max-error (< 0: none).
double limit_of(const check_args& a, check_kind k) {
  const double own = k == check_kind::lengths     ? a.max_length_error
                     : k == check_kind::inverse   ? a.max_inverse_error
                     : k == check_kind::at_length ? a.max_at_length_error
                                                  : a.max_value_error;
  return own >= 0 ? own : a.max_error;
}

/// An option that would change nothing is refused: a user who gives it expects it to act.
void refuse_without_effect(const check_args& a) {
  if (!a.unit.empty() && a.values.empty())
    throw invalid_input("check: --unit " + a.unit +
                        " sets the unit of --values errors, and no --values file is given (--lengths, --inverse and "
                        "--at-length errors are relative to the total length L)");
  struct own_limit {
    double limit;
    const char* option;
    const char* files;
    const std::string& file;
  };
  const own_limit own[] = {{a.max_value_error, "--max-value-error", "--values", a.values},
                           {a.max_length_error, "--max-length-error", "--lengths", a.lengths},
                           {a.max_inverse_error, "--max-inverse-error", "--inverse", a.inverse},
                           {a.max_at_length_error, "--max-at-length-error", "--at-length", a.at_length}};
  bool some_without_own = false;
  for (const own_limit& o : own) {
    if (o.limit >= 0 && o.file.empty())
      throw invalid_input(std::string("check: ") + o.option + " limits the rows of the " + o.files + " file, and no " +
                          o.files + " file is given");
    if (o.limit < 0 && !o.file.empty()) some_without_own = true;
  }
  if (a.max_error >= 0 && !some_without_own)
    throw invalid_input(
        "check: --max-error applies to the files without a limit of their own, and every file given "
        "has one (--max-value-error, --max-length-error, --max-inverse-error, --max-at-length-error)");
}

/// Failure lines printed to the terminal: the first few, then a count (--json lists them all).
constexpr std::size_t failures_shown = 20;

void print_failures(std::ostream& os, const std::vector<std::string>& failures) {
  for (std::size_t i = 0; i < failures.size() && i < failures_shown; ++i) os << failures[i] << "\n";
  if (failures.size() > failures_shown)
    os << "check: ... and " << failures.size() - failures_shown << " more (--json lists them all)\n";
}

}  // namespace

CLI::App* add_check(CLI::App& app, check_args& a) {
  auto* chk = app.add_subcommand(
      "check",
      "check your own implementation's values against the 50-digit reference of a spec; exit 1 naming every row "
      "over --max-error (or every breached rule of --thresholds)");
  chk->add_option("spec", a.spec, "JSON curve spec (1D to 3D), or a channel spec (\"type\": \"channel\")")
      ->required()
      ->check(CLI::ExistingFile);
  chk->add_option("--values", a.values,
                  "CSV of points: u, then x[,y[,z]]; optional s (arc length from the domain's start, "
                  "reported, not part of --max-error) and derivatives dx,dy,.. d2x,.. d3x,.. "
                  "(the columns `curvebench sample` writes). For a channel spec: t,value[,dvalue[,d2value]], "
                  "your channel's value and time derivatives at time t (a u column checks its planar curve instead)")
      ->check(CLI::ExistingFile);
  chk->add_option("--lengths", a.lengths, "CSV of arc lengths: u0,u1,length")->check(CLI::ExistingFile);
  chk->add_option("--inverse", a.inverse, "CSV of inverse parameters: s,u (your u at arc length s)")
      ->check(CLI::ExistingFile);
  chk->add_option(
         "--at-length", a.at_length,
         "CSV of points at arc length: s,x[,y[,z]] (your point at arc length s from the domain's start, e.g. "
         "SVG's getPointAtLength(s)): error |q - P(s)| / L, and s_error, how far along the curve your point "
         "is from s (measured at the curve's point nearest yours); without s (x[,y[,z]] only: equally spaced "
         "points) each point's nearest arc length s_true and its distance from the curve. An L column (with s) "
         "is the total length on the scale of s, a tool's own (SVG's getTotalLength()): each row is then "
         "asked at the fraction s / L of the way, and the L column's own error is reported. At most " +
             std::to_string(harness::max_at_length_rows) + " rows")
      ->check(CLI::ExistingFile);
  chk->add_option("--name", a.name, "your implementation's name: the method of the records (default values)");
  chk->add_flag("--json", a.json, "JSON on stdout: per check the summary, the worst rows, every row, the records");
  chk->add_option("--max-error", a.max_error,
                  "largest allowed row error of every kind without a limit of its own: in --unit for --values "
                  "(points and derivatives, each against its own size), relative to the total length L for "
                  "--lengths, --inverse and --at-length")
      ->check(non_negative_finite());
  chk->add_option("--max-value-error", a.max_value_error, "largest allowed --values row error, in --unit")
      ->check(non_negative_finite());
  chk->add_option("--max-length-error", a.max_length_error,
                  "largest allowed --lengths row error, relative to the total length L")
      ->check(non_negative_finite());
  chk->add_option("--max-inverse-error", a.max_inverse_error,
                  "largest allowed --inverse row error: |s(u) - s| relative to the total length L")
      ->check(non_negative_finite());
  chk->add_option("--max-at-length-error", a.max_at_length_error,
                  "largest allowed --at-length row error: |q - P(s)| relative to the total length L")
      ->check(non_negative_finite());
  chk->add_option("--unit", a.unit,
                  "unit of --values errors: ulp-double (eps(double) x the size; a channel's: x its value range), "
                  "ulp-float (eps(float) x the same), rel (relative to it) or abs (absolute). Default: ulp-double "
                  "when the values carry more than 9 significant digits, else ulp-float (the output says which)")
      ->check(CLI::IsMember({"ulp-double", "ulp-float", "rel", "abs"}));
  chk->add_option("--against", a.against,
                  "channel specs: compare with the channel's truth (default: the tool's rules at 50 digits, exact "
                  "time inversion) or with the tool's own evaluation (tool: its time solver, in its precision, "
                  "e.g. WebKit's table and Newton for css, float32 for blender)")
      ->check(CLI::IsMember({"truth", "tool"}));
  chk->add_option("--thresholds", a.thresholds,
                  "gate rules (the format of `curvebench gate`) applied to the check's records, e.g. "
                  "{\"rules\": [{\"quantity\": \"eval\", \"method\": \"values\", \"max_error\": 4}]}")
      ->check(CLI::ExistingFile);
  chk->add_option("--worst", a.worst, "how many worst rows to show (default 5)")->check(CLI::Range(0, 1000000));
  chk->add_flag("--quiet", a.quiet, "no progress lines on stderr (printed once a run takes over a second)");
  chk->footer(
      "\nCSV files: a header row naming the columns (those above, any order), then one row of finite numbers per "
      "line; blank lines and lines starting with # are skipped. Unknown or "
      "missing columns, non-numeric cells (1.5x, nan, inf, empty), rows with too few or too many values, "
      "parameters outside the domain, empty or header-only files are errors naming the file, the row (its line), "
      "the column and the cell.\n" +
      example("curvebench check bench/cases/arch_cubic_bezier.json --values values.csv --max-error 4") +
      example("curvebench check bench/cases/css_overshoot.json --values easing.csv --against tool"));
  return chk;
}

int run_check(const check_args& a) {
  std::vector<harness::check_input> inputs;
  // Empty cells read as NaN: a channel's empty derivative cells (`sample` leaves one empty where the
  // derivative is unbounded) are not given there; every other empty cell is refused by run_checks.
  if (!a.values.empty()) inputs.push_back({check_kind::values, harness::read_csv(a.values, true)});
  if (!a.lengths.empty()) inputs.push_back({check_kind::lengths, harness::read_csv(a.lengths)});
  if (!a.inverse.empty()) inputs.push_back({check_kind::inverse, harness::read_csv(a.inverse)});
  if (!a.at_length.empty()) inputs.push_back({check_kind::at_length, harness::read_csv(a.at_length)});
  if (inputs.empty())
    throw invalid_input("check: nothing to check: give --values, --lengths, --inverse or --at-length FILE");
  refuse_without_effect(a);
  const nlohmann::json j = read_spec(a.spec);
  const io::field spec = io::root(j, a.spec);
  harness::check_options o;
  o.name = a.name;
  o.case_name = std::filesystem::path(a.spec).stem().string();
  o.group = spec.has("group") && spec.member("group").value.is_string() ? spec.member("group").string() : "subject";
  o.worst = a.worst;
  if (!a.unit.empty()) o.unit = harness::value_unit_of(a.unit, "--unit");
  o.against = a.against == "tool" ? harness::check_against::tool : harness::check_against::truth;
  o.against_given = !a.against.empty();
  // One progress line a second once a file's rows take over a second (the 50-digit reference per row).
  std::unique_ptr<progress> shown;
  std::string shown_file;
  o.on_row = [&](std::size_t done, std::size_t total, const std::string& file) {
    if (!shown || file != shown_file) {
      shown = std::make_unique<progress>("check " + file + ": rows", total, a.quiet);
      shown_file = file;
    }
    shown->update(done);
  };
  const std::vector<check_result> results = harness::run_checks(spec, inputs, o);

  std::vector<std::string> failures;
  nlohmann::json records = nlohmann::json::array();
  for (const check_result& r : results) {
    for (const auto& rec : r.records) records.push_back(rec);
    if (const double limit = limit_of(a, r.kind); limit >= 0)
      for (std::string& m : harness::rows_over(r, limit)) failures.push_back("check: OVER " + m);
  }
  if (!a.thresholds.empty()) {
    const nlohmann::json t = io::parse(read_file(a.thresholds), a.thresholds);
    for (const auto& b : harness::check_gate({{"records", records}}, t, "check records", a.thresholds))
      failures.push_back("check: BREACH " + b.rule + " " + b.where + ": " + b.message);
  }
  if (a.json) {
    nlohmann::json out{{"spec", a.spec}, {"name", a.name}, {"checks", nlohmann::json::array()}, {"records", records}};
    for (const check_result& r : results) out["checks"].push_back(harness::to_json(r));
    if (a.max_error >= 0) out["max_error"] = a.max_error;
    for (const auto& [key, v] :
         {std::pair{"max_value_error", a.max_value_error}, std::pair{"max_length_error", a.max_length_error},
          std::pair{"max_inverse_error", a.max_inverse_error}, std::pair{"max_at_length_error", a.max_at_length_error}})
      if (v >= 0) out[key] = v;
    out["failures"] = failures;
    out["passed"] = failures.empty();
    std::cout << std::setw(1) << out << "\n";
    print_failures(std::cerr, failures);
  } else {
    for (const check_result& r : results) print_table(r, a.spec);
    print_failures(std::cout, failures);
    if (a.max_error >= 0 || a.max_value_error >= 0 || a.max_length_error >= 0 || a.max_inverse_error >= 0 ||
        a.max_at_length_error >= 0 || !a.thresholds.empty())
      std::cout << "check: " << (failures.empty() ? "passed" : std::to_string(failures.size()) + " failures") << "\n";
  }
  if (!failures.empty()) say_verdict("check", failures.size(), "failure", "failures");
  return failures.empty() ? 0 : 1;
}

}  // namespace curvebench::tool
