// An engine team's own Catmull-Rom spline, written the way such code usually is: knots from the
// chord lengths raised to alpha (0 uniform, 0.5 centripetal), Hermite segments whose interior
// tangents are the non-uniform Catmull-Rom (Barry-Goldman) ones, and end tangents from a phantom
// point mirrored through the end key. curvebench's spec {"type": "catmull_rom", "alpha": a} with
// the same points is the same curve, so curvebench can tell how far this code is from it.
// Built with -DOWN_BUG=ON the end tangents are halved: a slip the accuracy check must catch.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <stdexcept>
#include <vector>

namespace own {

struct vec2 {
  double x = 0, y = 0;
};
inline vec2 operator+(vec2 a, vec2 b) { return {a.x + b.x, a.y + b.y}; }
inline vec2 operator-(vec2 a, vec2 b) { return {a.x - b.x, a.y - b.y}; }
inline vec2 operator*(double s, vec2 a) { return {s * a.x, s * a.y}; }

class catmull_rom {
 public:
  catmull_rom(std::vector<vec2> keys, double alpha) : keys_(std::move(keys)) {
    if (keys_.size() < 2) throw std::invalid_argument("catmull_rom: needs two keys");
    knots_.push_back(0.0);
    for (std::size_t i = 0; i + 1 < keys_.size(); ++i) {
      const vec2 d = keys_[i + 1] - keys_[i];
      knots_.push_back(knots_.back() + std::pow(std::sqrt(d.x * d.x + d.y * d.y), alpha));
    }
    const std::size_t n = keys_.size() - 1;
    tangents_.resize(keys_.size());
    for (std::size_t i = 1; i < n; ++i) {
      const double h0 = knots_[i] - knots_[i - 1], h1 = knots_[i + 1] - knots_[i];
      const vec2 d0 = (1.0 / h0) * (keys_[i] - keys_[i - 1]);
      const vec2 d1 = (1.0 / h1) * (keys_[i + 1] - keys_[i]);
      tangents_[i] = (1.0 / (h0 + h1)) * (h1 * d0 + h0 * d1);
    }
    // Phantom keys 2 P0 - P1 and 2 Pn - Pn-1: the end tangent is the end chord's slope.
    double end_scale = 1.0;
#ifdef OWN_BUG
    end_scale = 0.5;
#endif
    tangents_[0] = (end_scale / (knots_[1] - knots_[0])) * (keys_[1] - keys_[0]);
    tangents_[n] = (end_scale / (knots_[n] - knots_[n - 1])) * (keys_[n] - keys_[n - 1]);
  }

  [[nodiscard]] double start() const { return knots_.front(); }
  [[nodiscard]] double end() const { return knots_.back(); }

  /// The point at parameter u in [start(), end()].
  [[nodiscard]] vec2 operator()(double u) const {
    const std::size_t n = keys_.size() - 1;
    std::size_t i = static_cast<std::size_t>(std::upper_bound(knots_.begin(), knots_.end(), u) - knots_.begin());
    i = std::clamp<std::size_t>(i, 1, n) - 1;
    const double h = knots_[i + 1] - knots_[i];
    const double t = (u - knots_[i]) / h, t2 = t * t, t3 = t2 * t;
    const double h00 = 2 * t3 - 3 * t2 + 1, h10 = t3 - 2 * t2 + t, h01 = -2 * t3 + 3 * t2, h11 = t3 - t2;
    return h00 * keys_[i] + (h10 * h) * tangents_[i] + h01 * keys_[i + 1] + (h11 * h) * tangents_[i + 1];
  }

 private:
  std::vector<vec2> keys_;
  std::vector<double> knots_;
  std::vector<vec2> tangents_;
};

}  // namespace own
