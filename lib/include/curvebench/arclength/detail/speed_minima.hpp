// Private: interior local minima of a curve's speed on [a, b], where the length methods split so
// that a near-cusp (a dip of |P'| narrower than the first panels) cannot hide between quadrature
// nodes, and the distance of the speed's branch point from the real axis there, which decides how
// far a Gauss rule next to the minimum can be trusted.
//
// Detection: |P'|^2 is sampled at `samples` + 1 points; each interior sample that is a local
// minimum below (1/4 max speed)^2 is refined by Newton on h = P'.P'' (the derivative of |P'|^2 / 2)
// with h' = |P''|^2 + P'.P''', kept inside its sampling bracket (a failed step keeps the best point
// so far). Cost: samples + 1 + 3 per Newton step derivative evaluations (counted).
//
// Branch point: the speed is sqrt(g) with g(t) = P'(t).P'(t), analytic wherever g != 0. Near a
// minimum m, g(t) ~ g0 + g2 (t - m)^2 with g0 = |P'(m)|^2 and g2 = |P''(m)|^2 + P'(m).P'''(m), so
// the speed has square-root branch points at t = m +- i delta, delta = sqrt(g0 / g2). An exact cusp
// (g0 = 0) has delta = 0: the speed is then |linear| and analytic on each side of m. A near-cusp
// has a small delta > 0: a Gauss rule on a panel that ends at m (or contains it) sees a
// singularity at distance delta from the panel, and its error estimate is meaningless until the
// panel is not much wider than delta (length.hpp). delta is taken from the last Newton iterate's
// derivatives (within a few ulps of m; the quadratic model's delta changes by O(eps (b - a)) only).
// A minimum where the model fails (g2 <= 0: a flatter than quadratic minimum) reports
// delta = b - a, i.e. "as far as the segment is wide": no grading, and the fixed-rule guard treats
// it as a near-cusp of unknown depth.
#pragma once

#include "curvebench/core/curve.hpp"
#include "curvebench/core/real.hpp"

#include <cstddef>
#include <vector>

namespace curvebench::arclength::detail {

/// A deep interior speed minimum at u, with the branch-point distance delta (see above).
template <class Real>
struct speed_minimum {
  Real u;
  Real delta;
};

/// Appends the deep interior speed minima of [a, b] (ascending, each > out.back() if any).
template <curve C>
void find_speed_minima(const C& c, const typename C::real_type& a, const typename C::real_type& b,
                       std::size_t samples, std::vector<speed_minimum<typename C::real_type>>& out,
                       std::size_t& evaluations) {
  using Real = typename C::real_type;
  using std::abs;
  using std::sqrt;
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
    Real g0 = g[k], g2(-1);
    for (int it = 0; it < 30; ++it) {
      const typename C::point_type d1 = c.derivative(x, 1);
      const typename C::point_type d2 = c.derivative(x, 2);
      const typename C::point_type d3 = c.derivative(x, 3);
      evaluations += 3;
      const Real h = d1.dot(d2);
      const Real dh = d2.squaredNorm() + d1.dot(d3);
      g0 = d1.squaredNorm();
      g2 = dh;
      if (!(dh > Real(0))) break;
      const Real next = x - h / dh;
      if (!(next > us[k - 1] && next < us[k + 1])) break;
      const bool done = abs(next - x) <= Real(4) * epsilon<Real>() * (abs(x) + (b - a));
      x = next;
      if (done) break;
    }
    const Real delta = g2 > Real(0) ? sqrt(g0 / g2) : b - a;
    if (x > a && x < b && (out.empty() || x > out.back().u)) out.push_back({x, delta});
  }
}

/// The minima's parameters only, appended to out (each > out.back() if any).
template <curve C>
void append_speed_minima(const C& c, const typename C::real_type& a, const typename C::real_type& b,
                         std::size_t samples, std::vector<typename C::real_type>& out, std::size_t& evaluations) {
  std::vector<speed_minimum<typename C::real_type>> m;
  find_speed_minima(c, a, b, samples, m, evaluations);
  for (const auto& x : m)
    if (out.empty() || x.u > out.back()) out.push_back(x.u);
}

/// Whether a branch point at distance delta from a minimum matters for a piece of width `width`
/// that ends there: for delta <= sqrt(eps) / 16 * width the speed differs from the kink |linear|
/// (exactly analytic on the piece) by an integral of relative size about
/// (delta/width)^2 ln(width/delta) = eps/256 ln(16/sqrt(eps)) < eps/4 (the log is 11, 21 and 59
/// for float, double and real50): below every rounding floor.
template <class Real>
[[nodiscard]] bool branch_point_matters(const Real& delta, const Real& width) {
  using std::sqrt;
  return delta > sqrt(epsilon<Real>()) / Real(16) * width;
}

}  // namespace curvebench::arclength::detail
