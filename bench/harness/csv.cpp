#include "harness/csv.hpp"

#include "harness/files.hpp"

#include "curvebench/core/error.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <limits>
#include <sstream>
#include <unordered_map>

namespace curvebench::harness {

namespace {

std::string_view trim(std::string_view s) {
  const auto first = s.find_first_not_of(" \t\r");
  if (first == std::string_view::npos) return {};
  const auto last = s.find_last_not_of(" \t\r");
  return s.substr(first, last - first + 1);
}

std::vector<std::string_view> split(std::string_view line) {
  std::vector<std::string_view> cells;
  std::size_t start = 0;
  while (true) {
    const auto comma = line.find(',', start);
    cells.push_back(trim(line.substr(start, comma == std::string_view::npos ? std::string_view::npos : comma - start)));
    if (comma == std::string_view::npos) break;
    start = comma + 1;
  }
  return cells;
}

/// A column name as messages show it: as written, cut to 40 characters ("..." appended), so that a
/// megabyte-long name does not become a megabyte-long message.
std::string shown_column(std::string_view name) {
  constexpr std::size_t max = 40;
  if (name.size() <= max) return std::string(name);
  return std::string(name.substr(0, max)) + "...";
}

/// The significant digits of a number's text: those of its mantissa from the first non-zero one.
int significant_digits(std::string_view text) {
  int n = 0;
  bool started = false;
  for (char ch : text) {
    if (ch == 'e' || ch == 'E') break;
    if (ch < '0' || ch > '9') continue;
    if (ch != '0') started = true;
    if (started) ++n;
  }
  return n;
}

}  // namespace

// Appended, not `"\"" + ...`: an insert at the front of a temporary, where GCC 12 at -O3 warns a false
// -Wrestrict in libstdc++'s _M_replace (the documented Release build printed it).
std::string quote_cell(std::string_view text) {
  std::string cell(1, '"');
  cell += validate::visible(text, 40);
  cell += '"';
  return cell;
}

bool parse_finite(std::string_view text, double& out) {
  text = trim(text);
  if (text.empty()) return false;
  if (text.front() == '+') {  // from_chars takes no '+'; "+-1" and "++1" are junk
    text.remove_prefix(1);
    if (text.empty() || text.front() == '-' || text.front() == '+') return false;
  }
  const char* end = text.data() + text.size();
  const auto [ptr, ec] = std::from_chars(text.data(), end, out);
  if (ec == std::errc::result_out_of_range && ptr == end) {
    // Below the least subnormal (1e-400) rounds to a signed zero, as a JSON spec's 1e-400 reads and
    // as IEEE rounding gives; past the largest double (1e400) is not finite, refused below.
    const std::string copy(text);
    out = std::strtod(copy.c_str(), nullptr);
    return std::isfinite(out);
  }
  return ec == std::errc() && ptr == end && std::isfinite(out);
}

std::size_t csv_table::column(std::string_view name) const {
  for (std::size_t i = 0; i < columns.size(); ++i)
    if (columns[i] == name) return i;
  return npos;
}

std::string csv_table::where(std::size_t r, std::size_t c) const {
  std::string w = file + ": row " + std::to_string(lines.at(r));
  if (c != npos) w += ", column " + shown_column(columns.at(c));
  return w;
}

csv_table parse_csv(std::string_view text, const std::string& file, bool empty_as_nan) {
  csv_table t;
  t.file = file;
  std::size_t line_no = 0, pos = 0;
  bool header = false;
  std::unordered_map<std::string_view, std::size_t> seen;  // header name -> column index (the text outlives it)
  while (pos < text.size()) {
    const auto nl = text.find('\n', pos);
    const std::string_view line = text.substr(pos, nl == std::string_view::npos ? std::string_view::npos : nl - pos);
    pos = nl == std::string_view::npos ? text.size() : nl + 1;
    ++line_no;
    if (trim(line).empty() || trim(line).front() == '#') continue;
    const std::vector<std::string_view> cells = split(line);
    const std::string row_name = file + ": row " + std::to_string(line_no);
    if (!header) {
      for (std::size_t c = 0; c < cells.size(); ++c) {
        if (cells[c].empty())
          throw invalid_input(row_name + " (the header), column " + std::to_string(c + 1) + ": empty column name");
        double ignored = 0;
        if (parse_finite(cells[c], ignored))
          throw invalid_input(row_name + " (the header), column " + std::to_string(c + 1) + ": " +
                              quote_cell(cells[c]) +
                              " is a number, not a column name: the first row names the columns");
        // A hash of the names seen, not a scan of the earlier ones: a header of 1e5 columns took
        // minutes when each name was compared with every one before it.
        if (!seen.emplace(cells[c], c).second)
          throw invalid_input(row_name + " (the header), column " + std::to_string(c + 1) + ": column " +
                              quote_cell(cells[c]) + " appears twice");
        t.columns.emplace_back(cells[c]);
      }
      t.digits.assign(t.columns.size(), 0);
      header = true;
      continue;
    }
    if (cells.size() < t.columns.size())
      throw invalid_input(row_name + ", column " + shown_column(t.columns[cells.size()]) + ": missing value (" +
                          std::to_string(cells.size()) + " values, but the header names " +
                          std::to_string(t.columns.size()) + " columns: " + quote_cell(trim(line)) + ")");
    if (cells.size() > t.columns.size())
      throw invalid_input(row_name + ", column " + std::to_string(t.columns.size() + 1) + ": " +
                          quote_cell(cells[t.columns.size()]) + " has no column (" + std::to_string(cells.size()) +
                          " values, but the header names " + std::to_string(t.columns.size()) + " columns)");
    if (t.rows.size() == max_csv_rows)
      throw invalid_input(row_name + ": more than " + std::to_string(max_csv_rows) +
                          " rows, the most a file may hold (split it into several checks)");
    std::vector<double> row(cells.size());
    for (std::size_t c = 0; c < cells.size(); ++c) {
      if (empty_as_nan && cells[c].empty()) {
        row[c] = std::numeric_limits<double>::quiet_NaN();
        continue;
      }
      if (!parse_finite(cells[c], row[c]))
        throw invalid_input(row_name + ", column " + shown_column(t.columns[c]) + ": " + quote_cell(cells[c]) +
                            " is not a finite number");
      t.digits[c] = std::max(t.digits[c], significant_digits(cells[c]));
    }
    t.rows.push_back(std::move(row));
    t.lines.push_back(line_no);
  }
  if (!header) throw invalid_input(file + ": empty file (expected a header row, then one row per value)");
  if (t.rows.empty()) throw invalid_input(file + ": the header row has no rows after it");
  return t;
}

csv_table read_csv(const std::string& path, bool empty_as_nan) {
  return parse_csv(read_input_file(path), path, empty_as_nan);
}

}  // namespace curvebench::harness
