// The CSV target (targets.hpp): harness::parse_csv, the reader of `curvebench check --values,
// --lengths, --inverse`, on any bytes.
//
// Properties:
//   documented exceptions only   a refusal is invalid_input with a non-empty message of bounded size
//   a table as documented        at least one column, names non-empty, unique and not numbers; at
//                                least one row; every row as wide as the header and every cell
//                                finite; lines 1-based and increasing, after the header's
//   round trip                   the table written back as CSV (%.17g) reads as the same table
//   bounded work                 parsing takes at most 2 s (a quadratic step on a long header or
//                                row shows here, not as a libFuzzer timeout)
#include "guard.hpp"
#include "targets.hpp"

#include "harness/csv.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <string>
#include <unordered_set>

namespace curvebench::fuzz {

namespace {

constexpr std::string_view name = "csv";

void check_table(const harness::csv_table& t, std::string_view text) {
  if (t.columns.empty()) violation(name, "a table as documented", "no columns");
  if (t.rows.empty()) violation(name, "a table as documented", "no rows");
  if (t.rows.size() != t.lines.size())
    violation(name, "a table as documented",
              std::to_string(t.rows.size()) + " rows but " + std::to_string(t.lines.size()) + " line numbers");
  std::unordered_set<std::string_view> names;
  for (std::size_t c = 0; c < t.columns.size(); ++c) {
    double x = 0;
    if (t.columns[c].empty())
      violation(name, "a table as documented", "column " + std::to_string(c + 1) + " has no name");
    if (harness::parse_finite(t.columns[c], x))
      violation(name, "a table as documented", "column " + std::to_string(c + 1) + " is named by a number");
    if (!names.insert(t.columns[c]).second)
      violation(name, "a table as documented", "column " + std::to_string(c + 1) + " repeats an earlier name");
  }
  std::size_t newlines = 0;
  for (char ch : text) newlines += ch == '\n';
  for (std::size_t r = 0; r < t.rows.size(); ++r) {
    if (t.rows[r].size() != t.columns.size())
      violation(name, "a table as documented",
                "row index " + std::to_string(r) + " has " + std::to_string(t.rows[r].size()) + " values for " +
                    std::to_string(t.columns.size()) + " columns");
    for (double x : t.rows[r])
      if (!std::isfinite(x))
        violation(name, "a table as documented", "a non-finite cell in row index " + std::to_string(r));
    if (t.lines[r] < 2 || (r > 0 && t.lines[r] <= t.lines[r - 1]) || t.lines[r] > newlines + 1)
      violation(name, "a table as documented",
                "row index " + std::to_string(r) + " at line " + std::to_string(t.lines[r]));
  }
}

std::string written(const harness::csv_table& t) {
  std::string out;
  for (std::size_t c = 0; c < t.columns.size(); ++c) out += (c ? "," : "") + t.columns[c];
  out += "\n";
  char buf[40];
  for (const auto& row : t.rows) {
    for (std::size_t c = 0; c < row.size(); ++c) {
      std::snprintf(buf, sizeof buf, "%.17g", row[c]);
      out += (c ? "," : "") + std::string(buf);
    }
    out += "\n";
  }
  return out;
}

}  // namespace

int csv_target(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  harness::csv_table t;
  const auto start = std::chrono::steady_clock::now();
  const bool parsed =
      run_step(name, "parse_csv", domain_errors::violation, [&] { t = harness::parse_csv(text, "fuzz.csv"); });
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (seconds > 2)
    violation(name, "bounded work",
              "parse_csv took " + std::to_string(seconds) + " s on " + std::to_string(size) + " bytes");
  if (!parsed) return 0;
  check_table(t, text);
  const std::string again = written(t);
  harness::csv_table u;
  if (!run_step(name, "parse_csv (round trip)", domain_errors::violation,
                [&] { u = harness::parse_csv(again, "again.csv"); }))
    violation(name, "round trip", "the table written back was refused");
  if (u.columns != t.columns || u.rows != t.rows)
    violation(name, "round trip", "the table written back reads differently");
  return 0;
}

}  // namespace curvebench::fuzz
