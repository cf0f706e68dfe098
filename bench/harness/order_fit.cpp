#include "harness/order_fit.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace curvebench::harness {

order_fit fit_order(const std::vector<std::pair<double, double>>& cost_error, double floor, double ceiling) {
  std::vector<std::pair<double, double>> pts;
  for (const auto& [cost, err] : cost_error)
    if (cost > 0 && std::isfinite(cost) && std::isfinite(err)) pts.emplace_back(cost, err);
  std::sort(pts.begin(), pts.end());
  std::size_t i = 0;
  while (i < pts.size() && !(pts[i].second < ceiling)) ++i;  // pre-asymptotic
  std::vector<std::pair<double, double>> used;
  double best = std::numeric_limits<double>::infinity();
  while (i < pts.size()) {
    std::size_t j = i;  // [i, j): the points of one cost
    double smallest = std::numeric_limits<double>::infinity();
    for (; j < pts.size() && pts[j].first == pts[i].first; ++j) smallest = std::min(smallest, pts[j].second);
    if (!(smallest > floor) || !(smallest <= order_plateau_drop * best)) break;  // the plateau starts here
    for (std::size_t k = i; k < j; ++k)
      if (pts[k].second > floor && pts[k].second < ceiling) used.push_back(pts[k]);
    best = smallest;
    i = j;
  }
  order_fit out{std::numeric_limits<double>::quiet_NaN(), used.size(), pts.size() - i};
  if (used.size() < order_min_points || !(used.back().first >= order_min_cost_span * used.front().first)) return out;
  double mx = 0, my = 0;  // centred sums: the slope of a clean power law to rounding
  for (const auto& [cost, err] : used) {
    mx += std::log(cost);
    my += std::log(err);
  }
  const double n = static_cast<double>(used.size());
  mx /= n;
  my /= n;
  double sxx = 0, sxy = 0;
  for (const auto& [cost, err] : used) {
    const double x = std::log(cost) - mx;
    sxx += x * x;
    sxy += x * (std::log(err) - my);
  }
  if (sxx > 0) out.order = -sxy / sxx;
  return out;
}

}  // namespace curvebench::harness
