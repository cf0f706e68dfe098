// Private: interior local minima of a curve's speed on [a, b], where the adaptive length methods
// split so that a near-cusp (a dip of |P'| narrower than the first panels) cannot hide between
// quadrature nodes. |P'|^2 is sampled at `samples` + 1 points; each interior sample that is a
// local minimum below (1/4 max speed)^2 is refined by Newton on h = P'.P'' (the derivative of
// |P'|^2 / 2) with h' = |P''|^2 + P'.P''', kept inside its sampling bracket (a failed step keeps the
// best point so far). Cost: samples + 1 + 3 per Newton step derivative evaluations (counted).
#pragma once

#include "curvebench/core/curve.hpp"
#include "curvebench/core/real.hpp"

#include <cstddef>
#include <vector>

namespace curvebench::arclength::detail {

template <curve C>
void append_speed_minima(const C& c, const typename C::real_type& a, const typename C::real_type& b,
                         std::size_t samples, std::vector<typename C::real_type>& out, std::size_t& evaluations) {
  using Real = typename C::real_type;
  using std::abs;
  if (samples < 2 || !(b > a)) return;
  std::vector<Real> us(samples + 1), g(samples + 1);
  Real gmax(0);
  for (std::size_t k = 0; k <= samples; ++k) {
    us[k] = k == samples ? b : a + (b - a) * Real(static_cast<long long>(k)) / Real(static_cast<long long>(samples));
    g[k] = c.derivative(us[k], 1).squaredNorm();
    gmax = g[k] > gmax ? g[k] : gmax;
  }
  evaluations += samples + 1;
  if (!(gmax > Real(0))) return;
  const Real threshold = gmax / Real(16);
  for (std::size_t k = 1; k < samples; ++k) {
    if (!(g[k] <= g[k - 1] && g[k] <= g[k + 1]) || g[k] > threshold) continue;
    if (g[k] == Real(0) && g[k - 1] == Real(0)) continue;  // inside a zero-speed stretch
    Real x = us[k];
    for (int it = 0; it < 30; ++it) {
      const typename C::point_type d1 = c.derivative(x, 1);
      const typename C::point_type d2 = c.derivative(x, 2);
      const typename C::point_type d3 = c.derivative(x, 3);
      evaluations += 3;
      const Real h = d1.dot(d2);
      const Real dh = d2.squaredNorm() + d1.dot(d3);
      if (!(dh > Real(0))) break;
      const Real next = x - h / dh;
      if (!(next > us[k - 1] && next < us[k + 1])) break;
      const bool done = abs(next - x) <= Real(4) * epsilon<Real>() * (abs(x) + (b - a));
      x = next;
      if (done) break;
    }
    if (x > a && x < b && (out.empty() || x > out.back())) out.push_back(x);
  }
}

}  // namespace curvebench::arclength::detail
