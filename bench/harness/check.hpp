// The check core of `curvebench check`: a user's own values (points and derivatives at chosen
// parameters, arc lengths between parameters, inverse parameters at arc lengths) against the
// 50-digit reference of a spec (harness/reference.hpp), per row and in summary, as rows and as
// records of the accuracy.json format (harness/gate.hpp) so that the gate's rules apply to them.
//
// Tables (harness/csv.hpp; column names as `curvebench sample` writes them):
//   values   u, then the coordinates x[,y[,z]] (by the spec's dimension), optionally s (the arc
//            length from the domain's start) and derivative columns: dx,dy,... (first), d2x,...
//            (second), d3x,... (third); a derivative order present needs every coordinate.
//   times    a channel spec's values by time (any tool but glTF rotations): t, value, optionally
//            dvalue and d2value (the columns `curvebench sample` writes for a channel); the
//            values kind of a channel spec whose table has a t column.
//   lengths  u0, u1, length (the user's arc length from u0 to u1)
//   inverse  s, u (the user's parameter at arc length s from the domain's start)
//   at_length x[,y[,z]] and optionally s: the user's point at arc length s (getPointAtLength(s)), or
//            points with no s (a path's equally spaced points); with s optionally L, the total
//            length on the scale of s (a tool's own getTotalLength(): its s runs over [0, L], and the
//            row asks for the point at the fraction s / L of the curve's true length). At most
//            max_at_length_rows rows.
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
//   inverse  error = relative = |s(u_user) - s| / L (the u_of_s measure of the accuracy runner);
//            with outside_is_finding (the subject API) a u beyond an end by d is measured as
//            (|s(end) - s| + d |P'(end)|) / L, at least the error of the curve extended along its
//            end tangent, and listed in findings.
//   at_length error = relative = |q - P(u(s))| / L, the distance of the user's point q from the exact
//            point at arc length s; s_error = |s(u*) - s| / L, where u* is the point of the curve
//            nearest q (case_reference::nearest: how far along the curve the point is off);
//            s_true = s(u*), off_curve = |q - P(u*)| / L. Without an s column: error = off_curve.
//            With an L column (L_tool), s is rescaled to s L / L_tool and tool_length_error =
//            |L_tool - L| / L (a length record of its own).
//   times    abs = |value - V(t)|, V the channel at 50 digits at the user's t (exactly as read): the
//            truth (the spec's tool rules, the time solver "exact"), or with against = tool the
//            tool's own evaluation (its default or the spec's solver, in its storage precision:
//            float for Blender, at float(t)); error = abs in the unit of the row's scale: range =
//            the value range of the truth over the rows' times and 65 times across the keys (max
//            |V| when the range is 0, 1 when that is 0 too); the row's scale is max(|V(t)|, range)
//            in the ulp units (a stored value is rounded to an ulp of itself, so an ulp of the
//            value is the least a float engine can miss by) and in the records, range in rel and
//            abs (the motion's size); dvalue, d2value in the unit of their own scale (a cell
//            where the truth's derivative is unbounded is not checked: NaN in derivative_errors,
//            counted in unchecked). time_error = abs / |V'(t)|: how late or early the user's value
//            is, to first order (infinite where V' = 0 or is unbounded).
// Units of the values kinds (value_unit): ulp-double (eps(double) x scale), ulp-float
// (eps(float) x scale), rel (x scale), abs; by default ulp-double unless every value cell of the
// table carries at most 9 significant digits (a float's %.9g), then ulp-float (csv_table::digits;
// tables built in memory: ulp-double). The records stay in ulps of double whatever the unit; the
// values and times records also carry "unit" and "error_in_unit", their error as the check printed it.
// Every difference is taken in 50 digits. Parameters outside the domain, s outside [0, L], unknown
// or missing columns, a row whose error overflows double: invalid_input naming the file, row,
// column and value.
//
// Records: {"case", "group", "quantity", "method": <the subject's name>, "setting", "error",
// "estimate": null, "bounded": null, "evaluations": <rows>, "status": "not_guaranteed",
// "subject": true}; quantity eval (setting "" for points, "derivative=K" for the K-th derivative,
// error in ulps), s_of_u (an s column), length, u_of_s (inverse; at_length with an s column: the
// largest s_error); error the largest over the rows.
#pragma once

#include "harness/csv.hpp"

#include "curvebench/io/json_fields.hpp"

#include <nlohmann/json.hpp>

#include <cstddef>
#include <functional>
#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace curvebench::harness {

enum class check_kind { values, lengths, inverse, times, at_length };

/// "values", "lengths", "inverse", "times", "at_length".
[[nodiscard]] std::string_view to_string(check_kind k);

/// The unit of a values or times check's errors (see the top of this file).
enum class value_unit { ulp_double, ulp_float, rel, abs };
/// "ulp-double", "ulp-float", "rel", "abs".
[[nodiscard]] std::string_view to_string(value_unit u);
/// The unit of a name above; invalid_input naming the argument otherwise.
[[nodiscard]] value_unit value_unit_of(std::string_view name, const std::string& argument);
/// An absolute error in unit u for a quantity of size `scale`.
[[nodiscard]] double in_unit(double absolute, double scale, value_unit u);

/// What a times check compares with: the channel's truth, or the tool's own evaluation.
enum class check_against { truth, tool };

/// The most rows an --at-length table may have: each row costs a 50-digit u(s) and nearest point.
inline constexpr std::size_t max_at_length_rows = 20000;

struct check_options {
  std::string name = "values";                   ///< the subject's name: the records' "method"
  std::string case_name = "check";               ///< the records' "case" (the tool uses the spec file's stem)
  std::string group = "subject";                 ///< the records' "group"
  std::size_t worst = 5;                         ///< how many worst rows check_result::worst lists
  std::optional<value_unit> unit;                ///< values and times: the unit (none: chosen from the digits)
  check_against against = check_against::truth;  ///< times: what the user's values are compared with
  /// `against` was chosen (check --against): a table checked by u, where it has no effect, is refused.
  bool against_given = false;
  /// inverse: a u outside the domain is a finding, not an error (the subject API): its row is
  /// measured at the nearest end with the distance beyond it along the end tangent added, and the
  /// result's findings say so.
  bool outside_is_finding = false;
  /// Called after each row with (rows done, rows in the file, the file): the tool's progress line.
  std::function<void(std::size_t, std::size_t, const std::string&)> on_row;
};

/// The errors of one row (see the top of this file for the units).
struct check_row {
  std::size_t line = 0;                   ///< the row's 1-based line in its file
  double u = 0;                           ///< values, inverse: the row's (user's) u; lengths: u0
  double u1 = 0;                          ///< lengths: u1 (0 otherwise)
  double s = 0;                           ///< inverse: the target s; values: the user's s (when given)
  double error = 0;                       ///< values: ulps of size (largest over point and derivatives); else / L
  double relative = 0;                    ///< values: error x eps(double); lengths: per segment; inverse: = error
  double point_ulps = 0;                  ///< values: the point's error in ulps of size
  std::vector<double> derivative_ulps;    ///< values: order k = 1..K at index k - 1 (empty without)
  double s_error = -1;                    ///< values with an s column: |s_user - s(u)| / L; -1 without
  double t = 0;                           ///< times: the row's time
  double absolute = 0;                    ///< values: |p - P|_inf; times: |value - V(t)|; lengths: |l - L(u0, u1)|;
                                          ///< inverse: |s(u) - s| (in the curve's units)
  std::vector<double> derivative_errors;  ///< times: dvalue, d2value in the unit (NaN: not checked)
  double time_error = 0;                  ///< times: abs / |V'(t)| (infinite where V' is 0 or unbounded)
  double scale = 0;                       ///< times: the value's scale in the unit (max(|V(t)|, range) or range)
  double s_true = 0;                      ///< at_length: s(u*) at the curve's point u* nearest the user's
  double off_curve = 0;                   ///< at_length: |q - P(u*)| / L
};

struct check_summary {
  std::size_t rows = 0;
  double max = 0, rms = 0;                    ///< of the rows' error
  double max_relative = 0, rms_relative = 0;  ///< of the rows' relative
  double max_absolute = 0;                    ///< of the rows' absolute (NaN when a row's is)
};

struct check_result {
  check_kind kind = check_kind::values;
  std::string file;             ///< the table's file
  std::vector<check_row> rows;  ///< in the file's order
  check_summary summary;
  std::vector<std::size_t> worst;            ///< indices into rows, worst error first (at most options.worst)
  double size = 0;                           ///< values: the points' size
  std::vector<double> derivative_sizes;      ///< values: the size of derivative k at index k - 1
  double length = 0;                         ///< the curve's total length L (rounded)
  value_unit unit = value_unit::ulp_double;  ///< values, times: the unit of error
  std::string unit_reason;                   ///< values, times: why that unit ("--unit", "17 digits")
  std::string digits_warning;                ///< values, times: the CSV cannot carry the unit's precision
  std::string against;                       ///< times: what was compared with, in words
  std::size_t unchecked = 0;                 ///< times: derivative cells not checked (unbounded)
  std::vector<std::string> findings;         ///< inverse with outside_is_finding: rows outside the domain
  double tool_length = std::numeric_limits<double>::quiet_NaN();        ///< at_length with an L column: that L
  double tool_length_error = std::numeric_limits<double>::quiet_NaN();  ///< |L_column - L| / L
  nlohmann::json records = nlohmann::json::array();                     ///< accuracy.json records (see above)
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

/// A channel spec's values at times, in double: the truth (the channel at 50 digits, rounded to
/// double) or the tool's own evaluation (its solver, its storage precision; a float tool's values
/// are floats). `curvebench sample` prints them; check_times compares with the same at 50 digits.
struct channel_values {
  /// The value (order 0) or time derivative (orders 1, 2) at t; std::nullopt where it is unbounded
  /// or not representable (a circ ease's slope at its key), +-inf for a vertical tangent's slope.
  std::function<std::optional<double>(double, int)> at;
  std::string what;          ///< in words, for the output's header
  int bits = 64;             ///< 32: the values are floats (a float tool's own evaluation)
  std::vector<double> keys;  ///< the channel's key times, in order (0 and 1 only for CSS steps() past 2^16)
};
/// Throws spec_error for a glTF rotation channel (quaternion values) and for bad specs.
[[nodiscard]] channel_values channel_values_of(const io::field& spec, check_against against);

/// One record of a subject (a user's implementation) in the accuracy.json format, "subject": true.
[[nodiscard]] nlohmann::json subject_record(const std::string& case_name, const std::string& group,
                                            std::string_view quantity, const std::string& method,
                                            const std::string& setting, double error, double evaluations);

/// The result as JSON: {"kind", "file", "length", "size", "summary": {...}, "worst": [rows],
/// "rows": [{"line", "u", ..., "error", "relative", ...}], "records": [...]}.
[[nodiscard]] nlohmann::json to_json(const check_result& r);

/// The unit of r's errors in words: "ulps of double x size", "relative to L", ...
[[nodiscard]] std::string unit_text(const check_result& r);

/// One message per row whose error exceeds max_error ("FILE: row N (u = ...): error E > allowed A
/// ulps of double x size" or "... relative to L"); empty when none does.
[[nodiscard]] std::vector<std::string> rows_over(const check_result& r, double max_error);

}  // namespace curvebench::harness
