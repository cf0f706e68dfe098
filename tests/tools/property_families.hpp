// The families of docs/properties.md's measured table: each built from the same ten planar points,
// audited once in double. Compiled once (tools/property_families.cpp) and shared by the tests
// (test_analysis.cpp pins every row and checks the document) and by the writer of the document
// (tools/write_properties.cpp).
#pragma once

#include "curvebench/analysis/property_audit.hpp"
#include "curvebench/curves/bspline.hpp"
#include "curvebench/curves/cardinal_spline.hpp"

#include <span>
#include <string>
#include <vector>

namespace curvebench::property_families {

using P2 = point<double, 2>;
using list2 = point_list<double, 2>;
using span2 = std::span<const P2>;

/// The control polygon of every point-based family: ten points with a flat run, a step and a sharp
/// turn, so that an overshooting family leaves the hull of its points (a dip below y = 0 after the
/// flat run) and a line just below y = 0 cuts the curve twice but the polygon never. The flat run
/// is unevenly spaced on purpose (evenly spaced collinear points are interpolated by a uniform
/// cubic B-spline, see test_analysis.cpp).
[[nodiscard]] const list2& data();

/// One row of the table: the family's label and its measured report.
struct family_row {
  std::string label;
  analysis::property_report<double> report;
};

/// Every family of the table audited on data(), in the table's order (measured at each call).
[[nodiscard]] std::vector<family_row> measure_all();

/// The markdown table (header and rows, harness/audit_table.hpp) of the given rows.
[[nodiscard]] std::string markdown_table(const std::vector<family_row>& rows);

/// The lines that enclose the generated table in docs/properties.md.
inline constexpr const char* table_begin =
    "<!-- measured table: begin (written by tests/tools/write_properties.cpp; do not edit by hand) -->\n";
inline constexpr const char* table_end = "<!-- measured table: end -->\n";

/// The path of docs/properties.md in the source tree.
[[nodiscard]] std::string document_path();

/// The text between the markers of `document` (throws std::runtime_error naming the missing marker).
[[nodiscard]] std::string table_in(const std::string& document);

/// `document` with the text between its markers replaced by `table`.
[[nodiscard]] std::string with_table(const std::string& document, const std::string& table);

/// The command that rewrites the document's table, for messages.
inline constexpr const char* regenerate_command =
    "cmake --build build --target write_properties && build/tests/write_properties";

// The builders the table uses that the tests also audit on other data.
[[nodiscard]] bspline<double, 2> uniform_cubic_bspline(span2 p);
[[nodiscard]] bspline<double, 2> clamped_cubic_bspline(span2 p);
[[nodiscard]] cardinal_spline<double, 2> catmull_rom(span2 p);
[[nodiscard]] cardinal_spline<double, 2> seed_cardinal_spline(span2 p);
[[nodiscard]] cardinal_spline<double, 2> centripetal_catmull_rom(span2 p);

}  // namespace curvebench::property_families
