// The check core of `curvebench check`: a user's own values (points and derivatives at chosen
// parameters, arc lengths between parameters, inverse parameters at arc lengths) against the
// 50-digit reference of a spec (harness/reference.hpp), per row and in summary, as rows and as
// records of the accuracy.json format (harness/gate.hpp) so that the gate's rules apply to them.
//
// Tables (harness/csv.hpp; column names as `curvebench sample` writes them):
//   values   u, then the coordinates x[,y[,z]] (by the spec's dimension), optionally s (the arc
//            length from the domain's start) and derivative columns: dx,dy,... (first), d2x,...
//            (second), d3x,... (third); a derivative order present needs every coordinate.
//            (`t` instead of `u` is for time-based specs, none of which exist yet: an error.)
//   lengths  u0, u1, length (the user's arc length from u0 to u1)
//   inverse  s, u (the user's parameter at arc length s from the domain's start)
// Errors per row ("error" is the unit --max-error uses):
//   values   error = |p - P|_inf / (eps(double) x size), ulps of the curve's size, where size is
//            the largest coordinate magnitude of the exact points at the rows' parameters and at 65
//            equally spaced parameters across the domain (1 when all are 0): the eval records'
//            definition, over a fixed grid too so that a file of one row is measured against the
//            whole curve. Derivative order k likewise in ulps of its own size (the same
//            parameters, the k-th derivative), in `derivative_ulps`; the row's error is the
//            largest of the point's and the derivatives', relative = error x eps(double). An s column gives
//            s_error = |s_user - s(u)| / L.
//   lengths  error = |length - (s(u1) - s(u0))| / L (L: the curve's total length);
//            relative = the same over the segment's own length (infinite for an empty segment
//            with a non-zero length).
//   inverse  error = relative = |s(u_user) - s| / L (the u_of_s measure of the accuracy runner).
// Every difference is taken in 50 digits. Parameters outside the domain, s outside [0, L], unknown
// or missing columns: invalid_input naming the file, row, column and value.
//
// Records: {"case", "group", "quantity", "method": <the subject's name>, "setting", "error",
// "estimate": null, "bounded": null, "evaluations": <rows>, "status": "not_guaranteed",
// "subject": true}; quantity eval (setting "" for points, "derivative=K" for the K-th derivative,
// error in ulps), s_of_u (an s column), length, u_of_s; error the largest over the rows.
#pragma once

#include "harness/csv.hpp"

#include "curvebench/io/json_fields.hpp"

#include <nlohmann/json.hpp>

#include <cstddef>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

namespace curvebench::harness {

enum class check_kind { values, lengths, inverse };

/// "values", "lengths", "inverse".
[[nodiscard]] std::string_view to_string(check_kind k);

struct check_options {
  std::string name = "values";      ///< the subject's name: the records' "method"
  std::string case_name = "check";  ///< the records' "case" (the tool uses the spec file's stem)
  std::string group = "subject";    ///< the records' "group"
  std::size_t worst = 5;            ///< how many worst rows check_result::worst lists
  /// Called after each row with (rows done, rows in the file, the file): the tool's progress line.
  std::function<void(std::size_t, std::size_t, const std::string&)> on_row;
};

/// The errors of one row (see the top of this file for the units).
struct check_row {
  std::size_t line = 0;                 ///< the row's 1-based line in its file
  double u = 0;                         ///< values, inverse: the row's (user's) u; lengths: u0
  double u1 = 0;                        ///< lengths: u1 (0 otherwise)
  double s = 0;                         ///< inverse: the target s; values: the user's s (when given)
  double error = 0;                     ///< values: ulps of size (largest over point and derivatives); else / L
  double relative = 0;                  ///< values: error x eps(double); lengths: per segment; inverse: = error
  double point_ulps = 0;                ///< values: the point's error in ulps of size
  std::vector<double> derivative_ulps;  ///< values: order k = 1..K at index k - 1 (empty without)
  double s_error = -1;                  ///< values with an s column: |s_user - s(u)| / L; -1 without
};

struct check_summary {
  std::size_t rows = 0;
  double max = 0, rms = 0;                    ///< of the rows' error
  double max_relative = 0, rms_relative = 0;  ///< of the rows' relative
};

struct check_result {
  check_kind kind = check_kind::values;
  std::string file;             ///< the table's file
  std::vector<check_row> rows;  ///< in the file's order
  check_summary summary;
  std::vector<std::size_t> worst;                    ///< indices into rows, worst error first (at most options.worst)
  double size = 0;                                   ///< values: the points' size
  std::vector<double> derivative_sizes;              ///< values: the size of derivative k at index k - 1
  double length = 0;                                 ///< the curve's total length L (rounded)
  nlohmann::json records = nlohmann::json::array();  ///< accuracy.json records (see above)
};

/// One input of run_checks.
struct check_input {
  check_kind kind;
  csv_table table;
};

/// Checks every table against the spec's 50-digit reference (built once: seconds on hard curves).
/// Throws invalid_input for a spec of a dimension other than 1..3, and for bad tables (above).
[[nodiscard]] std::vector<check_result> run_checks(const io::field& spec, const std::vector<check_input>& inputs,
                                                   const check_options& options = {});
/// One table.
[[nodiscard]] check_result run_check(const io::field& spec, check_kind kind, const csv_table& table,
                                     const check_options& options = {});

/// One record of a subject (a user's implementation) in the accuracy.json format, "subject": true.
[[nodiscard]] nlohmann::json subject_record(const std::string& case_name, const std::string& group,
                                            std::string_view quantity, const std::string& method,
                                            const std::string& setting, double error, double evaluations);

/// The result as JSON: {"kind", "file", "length", "size", "summary": {...}, "worst": [rows],
/// "rows": [{"line", "u", ..., "error", "relative", ...}], "records": [...]}.
[[nodiscard]] nlohmann::json to_json(const check_result& r);

/// One message per row whose error exceeds max_error ("FILE: row N (u = ...): error E > allowed A
/// ulps of size" or "... relative to L"); empty when none does.
[[nodiscard]] std::vector<std::string> rows_over(const check_result& r, double max_error);

}  // namespace curvebench::harness
