// Observed convergence orders: least-squares slope of log error against log cost, fitted only where
// the error still decreases (above the rounding floor).
#pragma once

#include <cstddef>
#include <utility>
#include <vector>

namespace curvebench::harness {

// Orders are fitted where the error is above the rounding floor of double (~1e-13 relative once
// summed over many panels) and below 1e-2 (pre-asymptotic region).
inline constexpr double order_floor = 1e-12;
inline constexpr double order_ceiling = 1e-2;
// A point whose error is not at least this factor below the best error at a lower cost is on a
// plateau (the rounding level of the case, or a cap): it and every costlier point are left out.
inline constexpr double order_plateau_drop = 0.9;
// The fit needs this many points spanning at least this factor in cost.
inline constexpr std::size_t order_min_points = 3;
inline constexpr double order_min_cost_span = 4.0;

struct order_fit {
  double order;          ///< -d log(error) / d log(cost); NaN when too few points are left
  std::size_t used;      ///< points in the fit
  std::size_t excluded;  ///< points left out as at the rounding floor (error <= floor or plateau)
};

/// The convergence order of a series of (cost, error) points (any order; sorted by cost here).
/// Points with a non-positive cost or a non-finite error are ignored. Walking by increasing cost,
/// points whose error is at or above `ceiling` before the first one below it are pre-asymptotic
/// and ignored; from there on, the first cost whose smallest error is <= floor or not at least
/// order_plateau_drop times the best error of the lower costs starts the plateau, and it and every
/// costlier point are excluded. The slope is a least-squares fit of log error on log cost over the
/// points left (at one cost, every point); NaN unless there are at least order_min_points of them
/// spanning order_min_cost_span in cost.
order_fit fit_order(const std::vector<std::pair<double, double>>& cost_error, double floor, double ceiling);

}  // namespace curvebench::harness
