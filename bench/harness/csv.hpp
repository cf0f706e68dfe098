// A strict reader of the numeric CSV files `curvebench check` takes: a header row of column names,
// then rows of finite numbers, comma-separated (spaces around a cell are ignored). Every problem
// throws invalid_input naming the file, the row (its 1-based line number, as an editor shows it),
// the column and the cell's text: a non-numeric cell ("1.5x", "", nan, inf), a row with too few or
// too many values, a repeated or empty column name, an empty file, a file with a header only.
// Messages show column names and cells cut to 40 characters, so their size does not grow with the
// input's. Cost: linear in the text (repeated names are found by hashing).
// Blank lines are skipped. Which columns a check needs is the check's business (harness/check.hpp).
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

  static constexpr std::size_t npos = static_cast<std::size_t>(-1);
  /// The index of column `name`, or npos.
  [[nodiscard]] std::size_t column(std::string_view name) const;
  /// "FILE: row N, column C" for row index r and column index c (c = npos: no column part).
  [[nodiscard]] std::string where(std::size_t r, std::size_t c = npos) const;
};

/// Parses CSV text; `file` names it in errors.
[[nodiscard]] csv_table parse_csv(std::string_view text, const std::string& file);
/// Reads and parses the file at `path` (invalid_input when it cannot be read).
[[nodiscard]] csv_table read_csv(const std::string& path);

/// The text of a cell for an error message: quoted, cut to 40 characters ("..." appended).
[[nodiscard]] std::string quote_cell(std::string_view text);
/// Parses a whole string as a finite double: no leading or trailing junk (spaces around are
/// allowed), no nan or inf. Returns false when it is not one.
[[nodiscard]] bool parse_finite(std::string_view text, double& out);

}  // namespace curvebench::harness
