// A strict reader of the numeric CSV files `curvebench check` takes: a header row of column names,
// then rows of finite numbers, comma-separated (spaces around a cell are ignored). Every problem
// throws invalid_input naming the file, the row (its 1-based line number, as an editor shows it),
// the column and the cell's text: a non-numeric cell ("1.5x", "", nan, inf), a row with too few or
// too many values, a repeated or empty column name, an empty file, a file with a header only, more
// than max_csv_rows rows.
// Messages show column names and cells cut to 40 characters, so their size does not grow with the
// input's. Cost: linear in the text (repeated names are found by hashing).
// Blank lines and lines starting with '#' (a comment, as `curvebench sample` writes one first) are
// skipped. Which columns a check needs is the check's business (harness/check.hpp).
#pragma once

#include <cstddef>
#include <iosfwd>
#include <string>
#include <string_view>
#include <vector>

namespace curvebench::harness {

struct csv_table {
  std::string file;                       ///< the name errors use (a path, or "<stdin>")
  std::vector<std::string> columns;       ///< the header's names, in order
  std::vector<std::vector<double>> rows;  ///< each row has columns.size() values
  std::vector<std::size_t> lines;         ///< the 1-based line of each row in the file
  /// Per column, the most significant digits a cell of it is written with ("0.0632506": 6,
  /// "1.5e-3": 2, trailing zeros count); empty for a table built in memory.
  std::vector<int> digits;

  static constexpr std::size_t npos = static_cast<std::size_t>(-1);
  /// The index of column `name`, or npos.
  [[nodiscard]] std::size_t column(std::string_view name) const;
  /// "FILE: row N, column C" for row index r and column index c (c = npos: no column part).
  [[nodiscard]] std::string where(std::size_t r, std::size_t c = npos) const;
};

/// The most data rows a file may hold (as `curvebench sample` writes at most): a larger file is
/// refused at the first row past it, before it is all parsed. check's 50-digit reference costs
/// about 0.2 ms per row (docs/checking.md), so the cap bounds a check at minutes.
inline constexpr std::size_t max_csv_rows = 1000000;

/// Parses CSV text; `file` names it in errors. With empty_as_nan an empty cell is read as NaN
/// (a value not given: `curvebench sample` leaves a derivative cell empty where the derivative is
/// unbounded), which the reader of the table must refuse where it needs a value.
[[nodiscard]] csv_table parse_csv(std::string_view text, const std::string& file, bool empty_as_nan = false);
/// Reads and parses the file at `path` (invalid_input when it cannot be read).
[[nodiscard]] csv_table read_csv(const std::string& path, bool empty_as_nan = false);

/// The text of a cell for an error message: quoted, cut to 40 characters ("..." appended).
[[nodiscard]] std::string quote_cell(std::string_view text);
/// Parses a whole string as a finite double: no leading or trailing junk (spaces around are
/// allowed), no nan or inf. Returns false when it is not one.
[[nodiscard]] bool parse_finite(std::string_view text, double& out);

}  // namespace curvebench::harness
