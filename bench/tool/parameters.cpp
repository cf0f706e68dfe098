// The parameters of `curvebench sample` given on the command line (tool/parameters.hpp).
#include "tool/parameters.hpp"

#include "harness/csv.hpp"

#include "curvebench/core/error.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <limits>
#include <string_view>

namespace curvebench::tool {

using harness::parse_finite;
using harness::quote_cell;

namespace {

/// A number written as a plain decimal (digits, at most one point, no exponent, at most 17
/// digits): digits / 10^scale; nullopt otherwise.
struct decimal {
  long long digits;
  int scale;
};
std::optional<decimal> decimal_of(std::string_view text) {
  std::size_t k = 0;
  const bool negative = !text.empty() && text[0] == '-';
  if (!text.empty() && (text[0] == '-' || text[0] == '+')) k = 1;
  long long digits = 0;
  int scale = 0, count = 0;
  bool point = false;
  for (; k < text.size(); ++k) {
    const char c = text[k];
    if (c == '.' && !point) {
      point = true;
    } else if (c >= '0' && c <= '9') {
      if (++count > 17) return std::nullopt;
      digits = digits * 10 + (c - '0');
      if (point) ++scale;
    } else {
      return std::nullopt;
    }
  }
  if (count == 0) return std::nullopt;
  return decimal{negative ? -digits : digits, scale};
}

/// The grid value A + i STEP: from its exact decimal value, correctly rounded, when A and STEP are
/// plain decimals (steps of 0.1 give 0.3, not 0.30000000000000004); a + i step in double otherwise.
double grid_value(const std::optional<decimal>& da, const std::optional<decimal>& ds, double a, double step,
                  std::size_t i) {
  if (da && ds) {
    const int scale = std::max(da->scale, ds->scale);
    __int128 pa = da->digits, ps = ds->digits;  // each below 10^17, scaled by at most 10^17: < 10^34
    for (int k = da->scale; k < scale; ++k) pa *= 10;
    for (int k = ds->scale; k < scale; ++k) ps *= 10;
    // i <= max_sample_values (10^6): with |pa|, |ps| <= 10^30 the sum stays below 10^37 < 2^127;
    // larger scaled values (17 digits on one side, 17 decimals on the other) take the double path.
    const __int128 limit = static_cast<__int128>(1000000000000000LL) * 1000000000000000LL;  // 10^30
    if (pa > limit || pa < -limit || ps > limit || ps < -limit) return a + static_cast<double>(i) * step;
    const __int128 v = pa + static_cast<__int128>(i) * ps;
    __int128 m = v < 0 ? -v : v;
    std::string text;
    do {
      text.insert(text.begin(), static_cast<char>('0' + static_cast<int>(m % 10)));
      m /= 10;
    } while (m > 0);
    text = (v < 0 ? "-" : "") + text + "e-" + std::to_string(scale);
    double out = 0;
    const auto r = std::from_chars(text.data(), text.data() + text.size(), out);
    if (r.ec == std::errc()) return out;
  }
  return a + static_cast<double>(i) * step;
}

}  // namespace

std::vector<std::string> split(const std::string& text, char sep) {
  std::vector<std::string> out;
  std::size_t start = 0;
  while (true) {
    const auto p = text.find(sep, start);
    out.push_back(text.substr(start, p == std::string::npos ? std::string::npos : p - start));
    if (p == std::string::npos) return out;
    start = p + 1;
  }
}

void check_count(std::size_t n, const std::string& option) {
  if (n > max_sample_values)
    throw invalid_input(option + ": " + std::to_string(n) + " values, more than the maximum " +
                        std::to_string(max_sample_values));
}

std::vector<parameter> parse_at(const std::string& text) {
  const std::vector<std::string> items = split(text, ',');
  check_count(items.size(), "--at");
  std::vector<parameter> out;
  for (std::size_t i = 0; i < items.size(); ++i) {
    const std::string where = "--at: item " + std::to_string(i + 1);
    double u = 0;
    if (items[i].find_first_not_of(" \t") == std::string::npos) throw invalid_input(where + " is empty");
    if (!parse_finite(items[i], u)) throw invalid_input(where + " " + quote_cell(items[i]) + " is not a finite number");
    out.push_back({u, where});
  }
  return out;
}

std::vector<parameter> parse_range(const std::string& text, const std::string& option,
                                   std::optional<double> default_step) {
  std::vector<std::string> items = split(text, ':');
  if (items.size() == 2 && default_step) items.push_back(to_text(*default_step));
  if (items.size() != 3)
    throw invalid_input(option + " " + quote_cell(text) + ": expected A:B" + (default_step ? "[:STEP]" : ":STEP") +
                        " (" + (default_step ? "two or three" : "three") + " numbers), got " +
                        std::to_string(items.size()) + " items");
  const char* names[] = {"A", "B", "STEP"};
  double v[3];
  for (std::size_t i = 0; i < 3; ++i)
    if (!parse_finite(items[i], v[i]))
      throw invalid_input(option + ": item " + std::to_string(i + 1) + " (" + names[i] + ") " + quote_cell(items[i]) +
                          " is not a finite number");
  const double a = v[0], b = v[1], step = v[2];
  if (!(step > 0)) throw invalid_input(option + ": item 3 (STEP) " + quote_cell(items[2]) + " is not positive");
  if (b < a) throw invalid_input(option + ": B = " + items[1] + " is below A = " + items[0]);
  const double steps = (b - a) / step;
  if (steps + 1 > static_cast<double>(max_sample_values))
    throw invalid_input(option + " " + quote_cell(text) + ": more than the maximum " +
                        std::to_string(max_sample_values) + " values");
  const auto n = static_cast<std::size_t>(std::floor(steps + 1e-9));
  const std::optional<decimal> da = decimal_of(items[0]), ds = decimal_of(items[2]);
  std::vector<parameter> out;
  for (std::size_t i = 0; i <= n; ++i) {
    double u = grid_value(da, ds, a, step, i);
    // The last value is B when B lies on the grid up to the rounding of the grid's arithmetic (a
    // few ulps of its magnitudes), not up to a fraction of the step: with a step past B - A (0:1:1e9)
    // the grid is {A}, and B, one billionth of a step away, is not on it.
    const double rounding = 16 * std::numeric_limits<double>::epsilon() * std::max({std::abs(a), std::abs(b), step});
    if (i == n && std::abs(u - b) <= rounding) u = b;
    out.push_back({u, option + ": grid point " + std::to_string(i + 1)});  // not "value": a channel has values
  }
  return out;
}

}  // namespace curvebench::tool
