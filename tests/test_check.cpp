// The check core (harness/check.hpp) and its CSV reader (harness/csv.hpp) against references that
// do not go through case_reference: a cubic Bezier's closed form (exact in double at dyadic
// parameters, long double elsewhere) and a straight polyline, whose s(u) and u(s) are exact.
#include "harness/check.hpp"
#include "harness/gate.hpp"
#include "harness/reference.hpp"

#include "support/fixtures.hpp"

#include "curvebench/core/error.hpp"
#include "curvebench/io/json_fields.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <array>
#include <chrono>
#include <cmath>
#include <functional>
#include <limits>
#include <sstream>
#include <string>

using namespace curvebench::harness;
using curvebench::invalid_input;
using curvebench::testing::invalid_input_of;
using ::testing::HasSubstr;

namespace {

constexpr double eps = std::numeric_limits<double>::epsilon();

// The arch of bench/cases/arch_cubic_bezier.json: P0 (0,0), P1 (1,2), P2 (3,2), P3 (4,0), u in [0, 1].
// Its size (largest coordinate magnitude over the domain) is 4 (x at u = 1); of the first
// derivative 6 (dy at u = 0 and 1), of the second 12 (d2y, constant).
const char* const arch = R"({"type": "bezier", "points": [[0,0],[1,2],[3,2],[4,0]]})";

// A straight polyline (0,0) -> (3,4) -> (3,10) with params 0, 1, 2: s(u) = 5u on [0, 1] and
// 5 + 6 (u - 1) on [1, 2]; L = 11.
const char* const bent = R"({"type": "polyline", "points": [[0,0],[3,4],[3,10]]})";

struct spec_doc {
  nlohmann::json j;
  curvebench::io::field f;
  explicit spec_doc(const char* text)
      : j(curvebench::io::parse(text, "test spec")), f(curvebench::io::root(j, "test spec")) {}
};

/// The arch's k-th derivative at u in long double (closed form of the Bernstein polynomial).
std::array<long double, 2> arch_at(long double u, int k) {
  const long double px[] = {0, 1, 3, 4}, py[] = {0, 2, 2, 0};
  std::array<long double, 2> out{};
  for (int c = 0; c < 2; ++c) {
    const long double* p = c == 0 ? px : py;
    const long double v = 1 - u;
    switch (k) {
      case 0: out[c] = v * v * v * p[0] + 3 * v * v * u * p[1] + 3 * v * u * u * p[2] + u * u * u * p[3]; break;
      case 1: out[c] = 3 * (v * v * (p[1] - p[0]) + 2 * v * u * (p[2] - p[1]) + u * u * (p[3] - p[2])); break;
      case 2: out[c] = 6 * (v * (p[2] - 2 * p[1] + p[0]) + u * (p[3] - 2 * p[2] + p[1])); break;
      default: out[c] = 6 * (p[3] - 3 * p[2] + 3 * p[1] - p[0]); break;
    }
  }
  return out;
}

/// A values CSV of the arch at us, rounded from long double, with derivatives up to order K.
std::string arch_csv(const std::vector<double>& us, int K) {
  std::ostringstream os;
  os.precision(17);
  os << "u,x,y";
  for (int k = 1; k <= K; ++k)
    os << ",d" << (k == 1 ? "" : std::to_string(k)) << "x,d" << (k == 1 ? "" : std::to_string(k)) << "y";
  os << "\n";
  for (double u : us) {
    os << u;
    for (int k = 0; k <= K; ++k)
      for (long double c : arch_at(u, k)) os << "," << static_cast<double>(c);
    os << "\n";
  }
  return os.str();
}

/// x with 17 significant digits: reads back as the same double.
std::string num(double x) {
  std::ostringstream os;
  os.precision(17);
  os << x;
  return os.str();
}

}  // namespace

// ---- the CSV reader ------------------------------------------------------------------------------

TEST(csv, reads_a_header_and_rows_with_their_lines) {
  const csv_table t = parse_csv("u, x ,y\n0,1,2\n\n +0.5 ,-1e-3, 2.5E2\r\n", "in.csv");
  ASSERT_EQ(t.columns, (std::vector<std::string>{"u", "x", "y"}));
  ASSERT_EQ(t.rows.size(), 2u);
  EXPECT_EQ(t.lines, (std::vector<std::size_t>{2, 4}));  // the blank line 3 is skipped, lines count it
  EXPECT_EQ(t.rows[1], (std::vector<double>{0.5, -1e-3, 250}));
  EXPECT_EQ(t.column("y"), 2u);
  EXPECT_EQ(t.column("z"), csv_table::npos);
  EXPECT_EQ(t.where(1, 2), "in.csv: row 4, column y");
}

TEST(csv, names_file_row_column_and_text_of_every_bad_cell) {
  const auto msg = [](const char* text) { return invalid_input_of([&] { (void)parse_csv(text, "in.csv"); }); };
  EXPECT_EQ(msg(""), "in.csv: empty file (expected a header row, then one row per value)");
  EXPECT_EQ(msg("u,x\n"), "in.csv: the header row has no rows after it");
  EXPECT_EQ(msg("u,x\n0,1.5x\n"), "in.csv: row 2, column x: \"1.5x\" is not a finite number");
  EXPECT_EQ(msg("u,x\n0,1\n0,nan\n"), "in.csv: row 3, column x: \"nan\" is not a finite number");
  EXPECT_EQ(msg("u,x\ninf,1\n"), "in.csv: row 2, column u: \"inf\" is not a finite number");
  EXPECT_EQ(msg("u,x\n0,\n"), "in.csv: row 2, column x: \"\" is not a finite number");
  EXPECT_EQ(msg("u,x\n0,+-1\n"), "in.csv: row 2, column x: \"+-1\" is not a finite number");
  EXPECT_THAT(msg("u,x,y\n0,1\n"),
              HasSubstr("in.csv: row 2, column y: missing value (2 values, but the header names 3"));
  EXPECT_THAT(msg("u,x\n0,1,7\n"), HasSubstr("in.csv: row 2, column 3: \"7\" has no column (3 values"));
  EXPECT_THAT(msg("u,,x\n"), HasSubstr("in.csv: row 1 (the header), column 2: empty column name"));
  EXPECT_THAT(msg("u,x,x\n0,1,2\n"), HasSubstr("column \"x\" appears twice"));
  EXPECT_THAT(msg("0,1\n0,1\n"), HasSubstr("row 1 (the header), column 1: \"0\" is a number, not a column name"));
  // A long cell is cut to 40 characters in the message.
  const std::string long_cell(60, '7');
  EXPECT_THAT(msg(("u\n" + long_cell + "z\n").c_str()), HasSubstr("\"" + std::string(40, '7') + "...\""));
  // So is a long column name (fuzz finding: a 10 kB name came back whole in "missing value").
  const std::string long_name(5000, 'a');
  const std::string missing = msg(("u," + long_name + "\n1\n").c_str());
  EXPECT_THAT(missing, HasSubstr("in.csv: row 2, column " + std::string(40, 'a') + "...: missing value"));
  EXPECT_LT(missing.size(), 300u);
}

// Fuzz finding: the header's repeated-name check compared each name with every earlier one, so a
// header of 30000 columns took 65 s (under ASan). 2e5 distinct names take about 0.1 s when found by
// hashing and minutes by the quadratic scan; 5 s leaves a wide margin for a loaded machine.
TEST(csv, a_wide_header_is_read_in_linear_time) {
  constexpr std::size_t n = 200000;
  std::string text;
  for (std::size_t c = 0; c < n; ++c) text += (c ? ",c" : "c") + std::to_string(c);
  text += "\n";
  for (std::size_t c = 0; c < n; ++c) text += c ? ",1" : "1";
  text += "\n";
  const auto start = std::chrono::steady_clock::now();
  const csv_table t = parse_csv(text, "wide.csv");
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_EQ(t.columns.size(), n);
  EXPECT_LT(seconds, 5.0);
  // One row past max_csv_rows is refused naming its line (the header is line 1); the cap itself passes.
  std::string rows = "u\n";
  for (std::size_t r = 0; r < max_csv_rows; ++r) rows += "0\n";
  EXPECT_EQ(parse_csv(rows, "in.csv").rows.size(), max_csv_rows);
  EXPECT_THAT(invalid_input_of([&] { (void)parse_csv(rows + "0\n", "in.csv"); }),
              HasSubstr("in.csv: row 1000002: more than 1000000 rows"));
  // A repeat far from its first use is still found.
  EXPECT_THAT(invalid_input_of([&] { (void)parse_csv("c0,c1,c2,c1\n1,2,3,4\n", "in.csv"); }),
              HasSubstr("column 4: column \"c1\" appears twice"));
}

// ---- values --------------------------------------------------------------------------------------

// At dyadic parameters the arch's points and derivatives are exact in double: every error is 0.
TEST(check, exact_rows_have_no_error) {
  const spec_doc s(arch);
  const check_result r =
      run_check(s.f, check_kind::values, parse_csv(arch_csv({0, 0.125, 0.25, 0.5, 0.75, 1}, 3), "arch.csv"));
  EXPECT_DOUBLE_EQ(r.size, 4);
  ASSERT_EQ(r.derivative_sizes.size(), 3u);
  EXPECT_DOUBLE_EQ(r.derivative_sizes[0], 6);
  EXPECT_DOUBLE_EQ(r.derivative_sizes[1], 12);
  EXPECT_DOUBLE_EQ(r.derivative_sizes[2], 12);  // constant: d3x = 6 (4 - 9 + 3 - 0) = -12, d3y = 0
  EXPECT_EQ(r.summary.rows, 6u);
  EXPECT_EQ(r.summary.max, 0);
  for (const check_row& row : r.rows) EXPECT_EQ(row.derivative_ulps, (std::vector<double>{0, 0, 0}));
  EXPECT_TRUE(rows_over(r, 0).empty());
}

// Rounded from long double at non-dyadic parameters: a correctly rounded value is within half an ulp
// of itself, and its ulp is at most eps x |value| <= eps x size, so <= 0.5 ulps of size (plus the
// long double evaluation's ~1e-19 relative error: 0.51).
TEST(check, correctly_rounded_rows_are_within_half_an_ulp_of_size) {
  const spec_doc s(arch);
  const check_result r =
      run_check(s.f, check_kind::values, parse_csv(arch_csv({0.1, 0.3, 0.7, 0.9, 1.0 / 3}, 2), "a.csv"));
  EXPECT_LE(r.summary.max, 0.51);
  EXPECT_LE(r.summary.rms, r.summary.max);
  EXPECT_GT(r.summary.max, 0);  // 0.1 etc. are not exact: something rounds
  EXPECT_NEAR(r.summary.max_relative, r.summary.max * eps, 1e-30);
}

// An error of k ulps of size injected in one cell is reported as exactly k: x + k eps 4 is exact
// (x = 0.90625 at u = 0.25 has ulp eps / 2, and k eps 4 is a multiple of it).
TEST(check, reports_an_injected_error_exactly_and_names_its_row) {
  const spec_doc s(arch);
  csv_table t = parse_csv(arch_csv({0, 0.25, 0.5, 1}, 1), "arch.csv");
  t.rows[1][1] += 3 * eps * 4;   // row 3 of the file: x off by 3 ulps of size 4
  t.rows[2][4] -= 40 * eps * 6;  // row 4: dy off by 40 ulps of the first derivative's size 6
  check_options o;
  o.name = "my_engine";
  o.case_name = "arch";
  o.worst = 2;
  o.unit = value_unit::ulp_double;  // the file's short exact values alone would choose float ulps
  const check_result r = run_check(s.f, check_kind::values, t, o);
  EXPECT_EQ(r.rows[1].point_ulps, 3);
  EXPECT_EQ(r.rows[1].error, 3);
  EXPECT_EQ(r.rows[2].point_ulps, 0);
  EXPECT_EQ(r.rows[2].derivative_ulps, (std::vector<double>{40}));
  EXPECT_EQ(r.rows[2].error, 40);
  EXPECT_EQ(r.summary.max, 40);
  EXPECT_DOUBLE_EQ(r.summary.rms, std::sqrt((9.0 + 1600.0) / 4));
  EXPECT_EQ(r.worst, (std::vector<std::size_t>{2, 1}));
  const auto over = rows_over(r, 4);
  ASSERT_EQ(over.size(), 1u);
  EXPECT_EQ(over[0], "arch.csv: row 4 (u = 0.5): error 40 > allowed 4 ulps of double x size");
  // The records: eval points and eval derivative=1, the subject's name as method.
  ASSERT_EQ(r.records.size(), 2u);
  EXPECT_EQ(r.records[0]["quantity"], "eval");
  EXPECT_EQ(r.records[0]["method"], "my_engine");
  EXPECT_EQ(r.records[0]["setting"], "");
  EXPECT_EQ(r.records[0]["error"], 3.0);
  EXPECT_EQ(r.records[0]["subject"], true);
  EXPECT_EQ(r.records[0]["case"], "arch");
  EXPECT_EQ(r.records[1]["setting"], "derivative=1");
  EXPECT_EQ(r.records[1]["error"], 40.0);
  // The gate's rules apply to them.
  const auto breaches = check_gate({{"records", r.records}}, nlohmann::json::parse(R"({"rules": [
      {"quantity": "eval", "method": "my_engine", "setting": "", "max_error": 4},
      {"quantity": "eval", "method": "my_engine", "setting": "derivative=1", "max_error": 8}]})"));
  ASSERT_EQ(breaches.size(), 1u);
  EXPECT_EQ(breaches[0].message, "error 40 > allowed 8");
  // The JSON form holds the summary, the worst rows and every row.
  const nlohmann::json j = to_json(r);
  EXPECT_EQ(j["summary"]["max"], 40.0);
  EXPECT_EQ(j["worst"].size(), 2u);
  EXPECT_EQ(j["worst"][0]["line"], 4);
  EXPECT_EQ(j["rows"].size(), 4u);
  EXPECT_EQ(j["records"], r.records);
}

// An s column is checked against s(u) (here the polyline's exact 5u) and gives an s_of_u record.
TEST(check, an_s_column_is_checked_against_the_arc_length) {
  const spec_doc s(bent);
  const double ds = 0.0009765625;  // 2^-10, exact
  const check_result r =
      run_check(s.f, check_kind::values, parse_csv("u,s,x,y\n0.5," + num(2.5 + ds) + ",1.5,2\n1.5,8,3,7\n", "p.csv"));
  EXPECT_NEAR(r.rows[0].s_error, ds / 11, 1e-18);
  EXPECT_LE(r.rows[1].s_error, 1e-30);
  EXPECT_EQ(r.summary.max, 0);  // s is reported, not part of the row's error
  ASSERT_EQ(r.records.size(), 2u);
  EXPECT_EQ(r.records[1]["quantity"], "s_of_u");
}

TEST(check, a_1d_spec_has_one_coordinate) {
  const spec_doc s(R"({"type": "polyline", "points": [[0],[2],[1]]})");
  const check_result r = run_check(s.f, check_kind::values, parse_csv("u,x,dx\n0.5,1,2\n1.5,1.5,-1\n", "one.csv"));
  EXPECT_EQ(r.summary.max, 0);
  EXPECT_DOUBLE_EQ(r.size, 2);
}

TEST(check, bad_columns_and_parameters_name_file_row_column_and_value) {
  const spec_doc s(arch);
  const auto msg = [&](const char* text) {
    return invalid_input_of([&] { (void)run_check(s.f, check_kind::values, parse_csv(text, "v.csv")); });
  };
  EXPECT_EQ(msg("u,x,y\n1.5,0,0\n"), "v.csv: row 2, column u: 1.5 is outside the curve's domain [0, 1]");
  EXPECT_EQ(msg("u,x\n0.5,1\n"),
            "v.csv: row 1 (the header): no column y (coordinate 2 of the point); the header names u,x");
  EXPECT_THAT(msg("u,x,y,z\n0,0,0,0\n"), HasSubstr("v.csv: row 1 (the header), column z: unknown column"));
  EXPECT_THAT(msg("u,x,y,d2x\n0,0,0,0\n"), HasSubstr("no column d2y (derivative 2 of coordinate y)"));
  EXPECT_THAT(msg("t,x,y\n0,0,0\n"), HasSubstr("column t: this spec is a curve, whose parameter is u"));
  EXPECT_THAT(msg("x,y\n0,0\n"), HasSubstr("no column u"));
}

// A fuzz finding: the check core echoed every column name of a header in full (a 100 kB
// name, or 20000 names, became a message of that size). Names are cut at 40 characters, lists at 12.
TEST(check, column_errors_are_bounded_however_long_the_header) {
  const spec_doc s(arch);
  const auto msg = [&](const std::string& text) {
    return invalid_input_of([&] { (void)run_check(s.f, check_kind::values, parse_csv(text, "v.csv")); });
  };
  const std::string long_name(100000, 'q');
  const std::string unknown = msg("u,x,y," + long_name + "\n0.5,1,1,1\n");
  EXPECT_THAT(unknown, HasSubstr("column qqqq"));
  EXPECT_THAT(unknown, HasSubstr("unknown column"));
  EXPECT_LT(unknown.size(), 400u);
  std::string many = "u,x";
  std::string row = "0.5,1";
  for (int i = 0; i < 20000; ++i) {
    many += ",c" + std::to_string(i);
    row += ",0";
  }
  const std::string missing = msg(many + "\n" + row + "\n");
  EXPECT_THAT(missing, HasSubstr("no column y"));
  EXPECT_THAT(missing, HasSubstr("(20002 columns)"));
  EXPECT_LT(missing.size(), 400u);
}

// ---- lengths and inverse -------------------------------------------------------------------------

TEST(check, lengths_against_the_polylines_exact_segments) {
  const spec_doc s(bent);
  const double d = 0.0009765625;  // 2^-10
  const check_result r =
      run_check(s.f, check_kind::lengths,
                parse_csv("u0,u1,length\n0,2,11\n0.5,1.5,5.5\n0.25,0.75," + num(2.5 + d) + "\n1,1,0\n", "len.csv"));
  EXPECT_DOUBLE_EQ(r.length, 11);
  EXPECT_LE(r.rows[0].error, 1e-30);
  EXPECT_LE(r.rows[1].error, 1e-30);                // 2.5 + 3 across the bend
  EXPECT_NEAR(r.rows[2].error, d / 11, 1e-18);      // relative to L
  EXPECT_NEAR(r.rows[2].relative, d / 2.5, 1e-18);  // relative to the segment
  EXPECT_EQ(r.rows[3].relative, 0);                 // an empty segment measured as empty
  // The absolute error beside them, in the curve's units: 2^-10 exactly (the lengths are exact).
  EXPECT_EQ(r.rows[2].absolute, d);
  EXPECT_EQ(r.summary.max_absolute, d);
  EXPECT_EQ(to_json(r)["rows"][2]["absolute"], d);
  EXPECT_EQ(to_json(r)["summary"]["max_absolute"], d);
  EXPECT_EQ(r.records[0]["quantity"], "length");
  const auto over = rows_over(r, 1e-6);
  ASSERT_EQ(over.size(), 1u);
  EXPECT_THAT(over[0],
              HasSubstr("len.csv: row 4 (u0 = 0.25, u1 = 0.75): error 8.88e-05 > allowed 1e-06 relative to L"));
  EXPECT_THAT(invalid_input_of(
                  [&] { (void)run_check(s.f, check_kind::lengths, parse_csv("u0,u1,length\n0,2.5,1\n", "l.csv")); }),
              HasSubstr("l.csv: row 2, column u1: 2.5 is outside the curve's domain [0, 2]"));
  EXPECT_THAT(invalid_input_of([&] { (void)run_check(s.f, check_kind::lengths, parse_csv("u0,u1\n0,2\n", "l.csv")); }),
              HasSubstr("no column length"));
}

// A claimed length of 1e300 is an error of 9.1e298 of L: its RMS is a number, not an overflowed
// square (a sweep found `rms inf`, null in JSON, with exit 0).
TEST(check, the_rms_of_huge_errors_does_not_overflow) {
  const spec_doc s(bent);
  const check_result r = run_check(s.f, check_kind::lengths, parse_csv("u0,u1,length\n0,2,1e300\n0,2,11\n", "l.csv"));
  const double e = (1e300 - 11) / 11;
  EXPECT_DOUBLE_EQ(r.summary.max, e);
  EXPECT_NEAR(r.summary.rms, e / std::sqrt(2.0), 1e-12 * e);  // sqrt((e^2 + 0) / 2)
  EXPECT_TRUE(to_json(r)["summary"]["rms"].is_number());
}

TEST(check, inverse_against_the_polylines_exact_u_of_s) {
  const spec_doc s(bent);
  const double du = 0.0009765625;  // 2^-10: on the second segment s changes by 6 du
  const check_result r =
      run_check(s.f, check_kind::inverse, parse_csv("s,u\n0,0\n2.5,0.5\n8," + num(1.5 + du) + "\n11,2\n", "inv.csv"));
  EXPECT_LE(r.rows[0].error, 1e-30);
  EXPECT_LE(r.rows[1].error, 1e-30);
  EXPECT_NEAR(r.rows[2].error, 6 * du / 11, 1e-18);
  // Absolute: |s(u) - s| = 6 du in the curve's units, to the rounding of dividing by L and back (2 ulps).
  EXPECT_NEAR(r.rows[2].absolute, 6 * du, 2 * std::numeric_limits<double>::epsilon() * 6 * du);
  EXPECT_NEAR(r.summary.max_absolute, 6 * du, 2 * std::numeric_limits<double>::epsilon() * 6 * du);
  EXPECT_EQ(to_json(r)["rows"][2]["absolute"], r.rows[2].absolute);
  EXPECT_LE(r.rows[3].error, 1e-30);
  EXPECT_EQ(r.records[0]["quantity"], "u_of_s");
  EXPECT_THAT(invalid_input_of([&] { (void)run_check(s.f, check_kind::inverse, parse_csv("s,u\n12,2\n", "i.csv")); }),
              HasSubstr("i.csv: row 2, column s: 12 is outside [0, L]"));
}

// Several tables against one reference (built once).
TEST(check, run_checks_keeps_the_order_of_its_inputs) {
  const spec_doc s(bent);
  const auto r = run_checks(s.f, {{check_kind::inverse, parse_csv("s,u\n5,1\n", "i.csv")},
                                  {check_kind::lengths, parse_csv("u0,u1,length\n0,1,5\n", "l.csv")}});
  ASSERT_EQ(r.size(), 2u);
  EXPECT_EQ(r[0].kind, check_kind::inverse);
  EXPECT_EQ(r[1].file, "l.csv");
}

// ---- points at arc length (--at-length) ----------------------------------------------------------

// On the bent polyline P(s) is exact: s <= 5 is (3s/5, 4s/5), beyond it (3, 4 + (s - 5)). A point
// asked at s and given exactly has no error but the rounding of the 50-digit distance (0 here: the
// points are exact doubles); one 0.5 off along the curve is 0.5 / 11 of L off, its s_error too.
TEST(check, at_length_against_the_polylines_exact_points) {
  const spec_doc s(bent);
  const check_result r =
      run_check(s.f, check_kind::at_length, parse_csv("s,x,y\n0,0,0\n2.5,1.5,2\n8,3,7\n11,3,10\n6,3,5.5\n", "p.csv"));
  for (std::size_t i = 0; i < 4; ++i) EXPECT_LE(r.rows[i].error, 1e-30) << "row " << r.rows[i].line;
  EXPECT_NEAR(r.rows[4].error, 0.5 / 11, 1e-17);
  EXPECT_NEAR(r.rows[4].s_error, 0.5 / 11, 1e-17);
  EXPECT_NEAR(r.rows[4].off_curve, 0, 1e-30);
  EXPECT_TRUE(std::isnan(r.tool_length));
}

// A tool's own s runs over its own total length (getTotalLength()): with an L column the row is
// asked at s / L of the way. A tool whose L is twice the true 11 and whose s is doubled with it
// gives the true points: no error, and its length's own error |22 - 11| / 11 = 1 exactly.
TEST(check, an_l_column_puts_s_on_the_tools_own_scale) {
  const spec_doc s(bent);
  const check_result r = run_check(s.f, check_kind::at_length,
                                   parse_csv("s,L,x,y\n0,22,0,0\n5,22,1.5,2\n16,22,3,7\n22,22,3,10\n", "tool.csv"));
  for (const check_row& row : r.rows) EXPECT_LE(row.error, 1e-30) << "row " << row.line;
  EXPECT_EQ(r.tool_length, 22);
  EXPECT_EQ(r.tool_length_error, 1);
  ASSERT_EQ(r.records.size(), 2u);
  EXPECT_EQ(r.records[1]["quantity"], "length");
  EXPECT_EQ(r.records[1]["error"], 1.0);
  EXPECT_EQ(to_json(r)["tool_length"], 22.0);
  // Past the tool's own length, rows that disagree on L, an L without s: each refused by row and column.
  const auto refused = [&](const std::string& text) {
    return invalid_input_of([&] { (void)run_check(s.f, check_kind::at_length, parse_csv(text, "t.csv")); });
  };
  EXPECT_THAT(refused("s,L,x,y\n23,22,3,10\n"), HasSubstr("t.csv: row 2, column s: 23 is outside [0, L] = [0, 22]"));
  EXPECT_THAT(refused("s,L,x,y\n1,22,0,0\n2,21,0,0\n"),
              HasSubstr("t.csv: row 3, column L: 21 differs from row 2's 22"));
  EXPECT_THAT(refused("s,L,x,y\n1,0,0,0\n"), HasSubstr("t.csv: row 2, column L: 0 is not a positive length"));
  EXPECT_THAT(refused("L,x,y\n22,0,0\n"), HasSubstr("column L: L is the total length on the scale of the s column"));
  // Without L, s past the curve's own length says how to give a tool's scale.
  EXPECT_THAT(refused("s,x,y\n12,3,10\n"), HasSubstr("give that length as an L column"));
}

// A point whose distance from the curve is past double's range cannot be reported or gated.
TEST(check, an_error_past_doubles_range_is_refused_by_row) {
  const spec_doc s(bent);
  EXPECT_THAT(invalid_input_of([&] {
                (void)run_check(s.f, check_kind::at_length, parse_csv("x,y\n0,0\n1.7e308,-1.7e308\n", "far.csv"));
              }),
              HasSubstr("far.csv: row 3: the error overflows double"));
  // 1e308 away is far, but finite: measured (a gate fails it).
  const check_result r = run_check(s.f, check_kind::at_length, parse_csv("s,x,y\n0,1e308,0\n", "f.csv"));
  EXPECT_NEAR(r.rows[0].error, 1e308 / 11, 1e308 / 11 * 1e-15);
}

// Each row costs a 50-digit u(s) and nearest point: the table's size is capped, and refused before
// the reference is built.
TEST(check, at_length_tables_are_capped_in_rows) {
  const spec_doc s(bent);
  std::string text = "s,x,y\n";
  for (std::size_t i = 0; i <= max_at_length_rows; ++i) text += "0,0,0\n";
  EXPECT_THAT(invalid_input_of([&] { (void)run_check(s.f, check_kind::at_length, parse_csv(text, "many.csv")); }),
              HasSubstr("many.csv: row " + std::to_string(max_at_length_rows + 2) + ": more than " +
                        std::to_string(max_at_length_rows) + " rows"));
}

// The nearest point searches a tree of the segments' boxes, nearest first: on a path of many
// segments a point near one branch samples a few segments, whatever their number. A straight line
// of 1024 unit segments along x: the point (x, h) is nearest (x, 0), at distance h and s = x; the
// candidates lie within 2h + the slack, so at most the three segments x - 2h .. x + 2h touch.
TEST(check, the_nearest_point_on_a_long_path_samples_a_few_segments) {
  constexpr int n = 1024;
  nlohmann::json points = nlohmann::json::array();
  for (int i = 0; i <= n; ++i) points.push_back({i, 0});
  const nlohmann::json j{{"type", "polyline"}, {"points", points}};
  const curvebench::io::field f = curvebench::io::root(j, "line");
  case_reference<2> ref(f);
  for (const double x : {0.3, 17.5, 512.0, 1000.01, 1023.9}) {
    const auto near = ref.nearest({x, 0.25}, std::numeric_limits<double>::quiet_NaN());
    EXPECT_DOUBLE_EQ(near.distance, 0.25) << x;
    EXPECT_NEAR(near.s, x, 1e-12 * n) << x;
    EXPECT_LE(near.scanned, 3u) << x;
  }
  // A point equally near every segment (above the middle, far away) needs them all: the tree
  // prunes by distance, never by a guess.
  const auto far = ref.nearest({n / 2.0, 1e9}, std::numeric_limits<double>::quiet_NaN());
  EXPECT_NEAR(far.distance, 1e9, 1e-6);
  EXPECT_EQ(far.s, n / 2.0);
}

// A circle of radius 10 drawn as 360 one-degree SVG arcs: the point at radius 10 (1 + d) and angle
// a is nearest the circle's point at that angle, at distance 10 d, s = 10 a. The arcs' end points
// are doubles, so each arc's centre is off the circle's by ~1e-15 of the radius: the tolerances.
TEST(check, the_nearest_point_on_a_circle_of_many_arcs) {
  std::ostringstream d;
  d.precision(17);
  d << "M10 0";
  for (int k = 1; k <= 360; ++k)
    d << " A10 10 0 0 1 " << 10 * std::cos(k * M_PI / 180) << " " << 10 * std::sin(k * M_PI / 180);
  const nlohmann::json j{{"type", "svg_path"}, {"d", d.str()}};
  const curvebench::io::field f = curvebench::io::root(j, "circle");
  case_reference<2> ref(f);
  for (const double a : {0.01, 1.0, 3.0, 5.5}) {
    for (const double dr : {0.01, -0.01}) {
      const double r = 10 * (1 + dr);
      const auto near = ref.nearest({r * std::cos(a), r * std::sin(a)}, std::numeric_limits<double>::quiet_NaN());
      EXPECT_NEAR(near.distance, 10 * std::abs(dr), 1e-13) << a << " " << dr;
      EXPECT_NEAR(near.s, 10 * a, 1e-12) << a << " " << dr;
      EXPECT_LE(near.scanned, 4u) << a << " " << dr;
    }
  }
}
