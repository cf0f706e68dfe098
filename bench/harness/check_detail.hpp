// What the check core's two units share (harness/check.cpp: curves by u; harness/check_channel.cpp:
// channels by time): column roles, the unit chosen for a table, the summary.
#pragma once

#include "harness/check.hpp"

#include <cstddef>
#include <string>
#include <vector>

namespace curvebench::harness::detail {

/// "%.*g" of x.
[[nodiscard]] std::string num(double x, int digits = 17);
/// The index of a required column; errors name the file, the column and the columns there are.
std::size_t need(const csv_table& t, const std::string& name, const std::string& role);
/// Every column of t must be in `allowed`.
void only(const csv_table& t, const std::vector<std::string>& allowed, const std::string& kind);
/// The unit of a values or times check (harness/check.hpp): options.unit, or chosen from the most
/// significant digits of the value columns; sets res.unit and res.unit_reason.
void choose_unit(check_result& res, const csv_table& t, const std::vector<std::size_t>& value_columns,
                 const check_options& o);
/// res.digits_warning when the table's digits cannot carry the unit's precision and its errors are
/// as large as that rounding could make them (call after the rows).
void warn_digits(check_result& res, const csv_table& t, const std::vector<std::size_t>& value_columns);
/// Whether u is an ulp unit (ulp-double, ulp-float): the units whose times rows are scaled by
/// max(|V(t)|, range) rather than the range, and said so.
[[nodiscard]] inline bool is_ulp(value_unit u) { return u == value_unit::ulp_double || u == value_unit::ulp_float; }
/// A values or times record that also says what the check printed: "unit" (the check's unit,
/// "ulp-float") and "error_in_unit" (the largest row error of the record's quantity in it), so that
/// `compare` can show a check's figures as the check did. "error" stays in ulps of double.
[[nodiscard]] nlohmann::json with_unit(nlohmann::json record, value_unit u, double error_in_unit);
/// The summary and the worst rows of res.
void summarize(check_result& res, std::size_t worst);

/// Whether the spec is a channel ("type": "channel").
[[nodiscard]] bool is_channel_spec(const io::field& spec);
/// The times check of a channel spec (harness/check_channel.cpp).
[[nodiscard]] check_result check_times(const io::field& spec, const csv_table& t, const check_options& o);

}  // namespace curvebench::harness::detail
