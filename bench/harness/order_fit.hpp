// Observed convergence orders: least-squares slope of log error against log cost.
#pragma once

#include <utility>
#include <vector>

namespace curvebench::harness {

// Orders are fitted where the error is above the rounding floor of double (~1e-13 relative once
// summed over many panels) and below 1e-2 (pre-asymptotic region).
inline constexpr double order_floor = 1e-12;
inline constexpr double order_ceiling = 1e-2;

/// The convergence order -d log(error) / d log(cost) by least squares over the points whose error
/// lies in (floor, ceiling) and whose cost is positive; NaN when fewer than 3 points qualify.
double fit_order(const std::vector<std::pair<double, double>>& cost_error, double floor, double ceiling);

}  // namespace curvebench::harness
