#include "harness/order_fit.hpp"

#include <cmath>
#include <limits>

namespace curvebench::harness {

double fit_order(const std::vector<std::pair<double, double>>& cost_error, double floor, double ceiling) {
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  int n = 0;
  for (const auto& [cost, err] : cost_error) {
    if (!(err > floor && err < ceiling && cost > 0)) continue;
    const double x = std::log(cost), y = std::log(err);
    sx += x;
    sy += y;
    sxx += x * x;
    sxy += x * y;
    ++n;
  }
  constexpr double none = std::numeric_limits<double>::quiet_NaN();
  if (n < 3) return none;
  const double denom = n * sxx - sx * sx;
  if (!(denom > 0)) return none;
  return -(n * sxy - sx * sy) / denom;
}

}  // namespace curvebench::harness
