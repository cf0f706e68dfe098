// The measured property table in markdown: one row per audited family, written from an
// analysis::property_report (curvebench/analysis/property_audit.hpp). The accuracy runner writes
// these rows into its records (report.py prints them in REPORT.md), and docs/properties.md holds
// the table of tests/tools/property_families.hpp written by tests/tools/write_properties.cpp.
// The library measures; this file only formats: the verdict of each column and the number behind
// it (largest share of the grid one item moves, the affine deviation, how far the hull is left,
// the lines tested and the worst excess of crossings).
#pragma once

#include "curvebench/analysis/property_audit.hpp"

#include <cstdio>
#include <string>

namespace curvebench::harness {

/// The header of the markdown table whose rows `audit_markdown_row` writes (two lines).
[[nodiscard]] inline std::string audit_markdown_header() {
  return "| Family | Interpolates | Local control | Continuity | Affine invariant | Convex hull | Variation "
         "diminishing |\n|---|---|---|---|---|---|---|\n";
}

/// One row of the measured table, ending in a newline: the verdicts and the numbers behind them.
[[nodiscard]] inline std::string audit_markdown_row(const std::string& label,
                                                    const analysis::property_report<double>& r) {
  using analysis::audit_verdict;
  auto num = [](double x) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.2g", x);
    return std::string(buf);
  };
  const auto& lc = r.local_control;
  const auto& co = r.continuity;
  const auto& hull = r.convex_hull;
  const auto& vd = r.variation_diminishing;
  std::string row = "| " + label + " | " + analysis::to_string(r.interpolation.kind) + " | ";
  row += std::string(lc.local ? "yes" : "no") + " (max " +
         std::to_string(static_cast<int>(lc.max_moved_fraction * 100.0 + 0.5)) + "% moves) | ";
  if (co.one_piece)
    row += "one piece (no interior knot)";
  else if (co.order < 0)
    row += "discontinuous";
  else
    row += "C" + std::to_string(co.order) + (co.order == co.max_order ? "+" : "");
  row += " | " + std::string(r.affine.invariant ? "yes" : "no") + " (dev " + num(r.affine.deviation) + ") | ";
  row += analysis::to_string(hull.verdict);
  if (hull.verdict == audit_verdict::no) row += " (out by " + num(hull.violation) + ")";
  row += " | " + std::string(analysis::to_string(vd.verdict));
  if (vd.verdict != audit_verdict::not_applicable)
    row += " (" + std::to_string(vd.lines_tested) + " lines, worst excess " + std::to_string(vd.worst_excess) + ")";
  row += " |\n";
  return row;
}

}  // namespace curvebench::harness
