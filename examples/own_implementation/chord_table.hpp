// An engine team's own arc-length table: the curve sampled at `steps` equal parameter steps
// over its domain, the cumulative chord lengths stored, and s(u) and u(s) read off the table by
// linear interpolation. Chords cut corners, so the table's lengths are short by O(h^2).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

namespace own {

class chord_table {
 public:
  /// `curve(u)` returns a point with .x and .y, on [start, end].
  template <class Curve>
  chord_table(const Curve& curve, double start, double end, std::size_t steps) {
    u_.push_back(start);
    s_.push_back(0.0);
    auto prev = curve(start);
    for (std::size_t j = 1; j <= steps; ++j) {
      const double u = j == steps ? end : start + (end - start) * static_cast<double>(j) / static_cast<double>(steps);
      const auto p = curve(u);
      s_.push_back(s_.back() + std::hypot(p.x - prev.x, p.y - prev.y));
      u_.push_back(u);
      prev = p;
    }
  }

  [[nodiscard]] double total() const { return s_.back(); }

  /// Arc length from the start to u.
  [[nodiscard]] double s(double u) const { return interpolate(u_, s_, u); }
  /// Arc length from u0 to u1.
  [[nodiscard]] double length(double u0, double u1) const { return s(u1) - s(u0); }
  /// The parameter at arc length s from the start (past the table's total: the end).
  [[nodiscard]] double u(double s) const { return std::min(interpolate(s_, u_, s), u_.back()); }

 private:
  static double interpolate(const std::vector<double>& from, const std::vector<double>& to, double x) {
    const auto it = std::upper_bound(from.begin(), from.end(), x);
    const std::size_t k = std::clamp<std::size_t>(static_cast<std::size_t>(it - from.begin()), 1, from.size() - 1) - 1;
    const double w = (x - from[k]) / (from[k + 1] - from[k]);
    return to[k] + w * (to[k + 1] - to[k]);
  }
  std::vector<double> u_;
  std::vector<double> s_;
};

}  // namespace own
