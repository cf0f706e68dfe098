// Private: interior local minima of a curve's speed on [a, b], where the length methods split so
// that a near-cusp (a dip of |P'| narrower than the first panels) cannot hide between quadrature
// nodes, and the distance of the speed's branch point from the real axis there, which decides how
// far a Gauss rule next to the minimum can be trusted.
//
// Detection: |P'|^2 is sampled at `samples` + 1 points; each interior sample that is a local
// minimum below (1/4 max speed)^2 is refined by Newton on h = P'.P'' (the derivative of |P'|^2 / 2)
// with h' = |P''|^2 + P'.P''', kept inside its sampling bracket (a failed step keeps the best point
// so far); an end sample below that level with the speed falling towards it is examined too (see
// speed_features), and so is every sampling interval across which P' turns back by more than 90
// degrees (P'(u_k).P'(u_k+1) < 0: a minimum of the speed lies between, whatever the samples' speeds). Cost: samples + 1
// + 3 per Newton step derivative evaluations (counted). The branch-point distance delta is explained above speed_model.
#pragma once

#include "curvebench/core/curve.hpp"
#include "curvebench/core/real.hpp"

#include <cstddef>
#include <vector>

namespace curvebench::arclength::detail {

/// A point of a piece (an end or a deep interior speed minimum) and delta, the distance from it
/// to the nearest branch point of the speed (0 when there is none nearby or it does not matter).
template <class Real>
struct speed_minimum {
  Real u;
  Real delta;
};

// Branch point: the speed is sqrt(g) with g(t) = P'(t).P'(t), analytic wherever g != 0. Near a
// minimum m, g(t) ~ g0 + g2 (t - m)^2 with g0 = |P'(m)|^2 and g2 = |P''(m)|^2 + P'(m).P'''(m), so
// the speed has square-root branch points at t = m +- i delta, delta = sqrt(g0 / g2). An exact cusp
// (g0 = 0) has delta = 0: the speed is then |linear| and analytic on each side of m. A near-cusp
// has a small delta > 0: a Gauss rule on a panel that ends at m (or contains it) sees a
// singularity at distance delta from the panel, and its error estimate is meaningless until the
// panel is not much wider than delta (length.hpp). delta is taken from the model at the last
// Newton iterate (g0 - h^2/g2 is the model's minimum whichever iterate it is taken at). A minimum
// where the model fails (g2 <= 0: a flatter than quadratic minimum) reports delta = b - a, i.e.
// "as far as the piece is wide": no grading, and the fixed rule leaves it to its order test.
/// The quadratic model of g = |P'|^2 at x: g0 = g(x), h = g'(x)/2 = P'.P'', dh = g''(x)/2.
template <class Real>
struct speed_model {
  Real x, g0, h, dh;
  /// The branch points' distance from the real axis above the model's minimum:
  /// sqrt((g0 - h^2/dh) / dh) (dh > 0 required; 0 when the model's minimum is <= 0).
  [[nodiscard]] Real delta() const {
    using std::sqrt;
    const Real gmin = g0 - h * h / dh;
    return gmin > Real(0) ? sqrt(gmin / dh) : Real(0);
  }
};

/// The ends and the deep interior speed minima of [a, b], ascending: front().u = a, back().u = b.
/// An interior minimum's delta is its branch points' distance from the real axis (b - a when the
/// quadratic model fails, g'' <= 0). An end's delta is nonzero when the speed there is small and
/// still falls outwards: the model extrapolated from the end then puts a minimum at distance e
/// outside the piece, with branch points at distance sqrt(e^2 + delta_min^2) from the end (a
/// partial length that stops just short of a near-cusp sees it about as close as an interior
/// one). A minimum inside the sampling interval next to an end (invisible to the interior test)
/// is found by Newton from that end. With `shallow`, the interior sample minima above the depth
/// threshold are appended there too, each with the delta of the quadratic model at the sample
/// (3 more evaluations each; not refined, not split at): a shallow dip can still have its branch
/// points close to the real axis (the graph of a steep bump, |P'| = sqrt(1 + y'^2)).
template <curve C>
std::vector<speed_minimum<typename C::real_type>> speed_features(
    const C& c, const typename C::real_type& a, const typename C::real_type& b, std::size_t samples,
    std::size_t& evaluations, std::vector<speed_minimum<typename C::real_type>>* shallow = nullptr) {
  using Real = typename C::real_type;
  using std::abs;
  using std::frexp;
  using std::ldexp;
  using std::max;
  using std::sqrt;
  std::vector<speed_minimum<Real>> out{{a, Real(0)}};
  speed_minimum<Real> end_b{b, Real(0)};
  if (samples < 2 || !(b > a)) {
    out.push_back(end_b);
    return out;
  }
  std::vector<Real> us(samples + 1), g(samples + 1);
  std::vector<typename C::point_type> d1s(samples + 1);
  // |P'|^2 and its derivatives are compared only with each other, so every derivative is scaled by
  // one power of two near 1 / max|P'|: exact, and the squares neither overflow (|P'| > 1e154 in
  // double) nor underflow (|P'| < 1e-154).
  // The last sample is taken a few ulps inside b: at an interior breakpoint c.derivative(b) is the
  // next segment's (breakpoints belong to the segment on their right), whose velocity made a
  // Kochanek-Bartels segment ending at a near-cusp look like one that turns back at its end, and hid
  // the near-cusp just past its end (an error 47x the estimate).
  const Real resolution = Real(4) * epsilon<Real>() * (abs(a) + abs(b) + (b - a));
  Real dmax(0);
  for (std::size_t k = 0; k <= samples; ++k) {
    us[k] = k == samples ? Real(b - resolution)
                         : a + (b - a) * Real(static_cast<long long>(k)) / Real(static_cast<long long>(samples));
    d1s[k] = c.derivative(us[k], 1);
    dmax = max(dmax, Real(d1s[k].cwiseAbs().maxCoeff()));
  }
  evaluations += samples + 1;
  int scale_exp = 0;
  if (dmax > Real(0) && is_finite(dmax)) (void)frexp(dmax, &scale_exp);
  auto scaled = [&](const typename C::point_type& d) -> typename C::point_type {
    typename C::point_type s;
    for (int i = 0; i < s.size(); ++i) s[i] = ldexp(d[i], -scale_exp);
    return s;
  };
  Real gmax(0);
  for (std::size_t k = 0; k <= samples; ++k) {
    g[k] = scaled(d1s[k]).squaredNorm();
    gmax = g[k] > gmax ? g[k] : gmax;
  }
  if (!(gmax > Real(0))) {
    out.push_back(end_b);
    return out;
  }
  const Real threshold = gmax / Real(16);
  // Newton on h from x inside (lo, hi); returns the model at the last point evaluated, with x the
  // final iterate (within `resolution` of it when converged; a step leaving the bracket keeps the
  // best point so far).
  auto refine = [&](Real x, const Real& lo, const Real& hi) {
    speed_model<Real> m{x, Real(0), Real(0), Real(-1)};
    for (int it = 0; it < 30; ++it) {
      const typename C::point_type d1 = scaled(c.derivative(x, 1));
      const typename C::point_type d2 = scaled(c.derivative(x, 2));
      const typename C::point_type d3 = scaled(c.derivative(x, 3));
      evaluations += 3;
      m = {x, d1.squaredNorm(), d1.dot(d2), d2.squaredNorm() + d1.dot(d3)};
      if (!(m.dh > Real(0))) break;
      const Real next = x - m.h / m.dh;
      if (!(next > lo && next < hi)) break;
      const bool done = abs(next - x) <= resolution;
      x = next;
      if (done) break;
    }
    m.x = x;
    return m;
  };
  auto add_interior = [&](const speed_model<Real>& m) {
    if (m.x > a && m.x < b && m.x > out.back().u + resolution) out.push_back({m.x, m.dh > Real(0) ? m.delta() : b - a});
  };
  // An end whose small speed falls towards it: a minimum just inside, or just outside the piece.
  auto end_feature = [&](std::size_t k, std::size_t inner, Real& delta) {
    if (!(g[k] <= g[inner]) || g[k] > threshold || (g[k] == Real(0) && g[inner] == Real(0))) return;
    const Real lo = k == 0 ? a : us[inner], hi = k == 0 ? us[inner] : b;
    const speed_model<Real> m = refine(us[k], lo, hi);
    if (m.x != us[k]) {
      add_interior(m);
      return;
    }
    if (!(m.dh > Real(0))) return;
    const Real e = abs(m.h / m.dh), dm = m.delta();
    delta = sqrt(e * e + dm * dm);
  };
  // A velocity that turns back by more than 90 degrees between two samples passes a minimum of the
  // speed in between, however high the speed at both samples: a 1D curve's x' changing sign at
  // 0.98 between samples at 0.9375 and 1 (speeds 1.25 and 1.42) is an exact cusp of |x'| that the
  // sample test above cannot see, and adaptive Gauss-Kronrod then reported 4.2e-7 for an error of
  // 9.7e-7. Refined by Newton from the slower sample, else from the middle.
  // Searched unless a feature was already found inside (us[k], us[k + 1]): a sampled minimum whose
  // Newton left its bracket is kept at the sample itself, us[k], and must not hide a zero just
  // after it (a 1D Lagrange curve lost its zero at 0.718 behind the sample at 0.6875: 0.127
  // reported for an error of 0.604).
  auto reversal = [&](std::size_t k) {
    if (!(scaled(d1s[k]).dot(scaled(d1s[k + 1])) < Real(0)) || out.back().u > us[k]) return;
    speed_model<Real> m = refine(g[k] <= g[k + 1] ? us[k] : us[k + 1], us[k], us[k + 1]);
    if (!(m.x > us[k] && m.x < us[k + 1])) m = refine((us[k] + us[k + 1]) / Real(2), us[k], us[k + 1]);
    add_interior(m);
  };
  end_feature(0, 1, out.front().delta);
  for (std::size_t k = 1; k < samples; ++k) {
    reversal(k - 1);
    if (shallow && g[k] <= g[k - 1] && g[k] <= g[k + 1] && g[k] > threshold) {
      const typename C::point_type d1 = c.derivative(us[k], 1), d2 = c.derivative(us[k], 2),
                                   d3 = c.derivative(us[k], 3);
      evaluations += 3;
      const speed_model<Real> m{us[k], d1.squaredNorm(), d1.dot(d2), d2.squaredNorm() + d1.dot(d3)};
      if (m.dh > Real(0)) shallow->push_back({us[k], m.delta()});
    }
    if (!(g[k] <= g[k - 1] && g[k] <= g[k + 1]) || g[k] > threshold) continue;
    if (g[k] == Real(0) && g[k - 1] == Real(0)) continue;  // inside a zero-speed stretch
    add_interior(refine(us[k], us[k - 1], us[k + 1]));
  }
  reversal(samples - 1);
  end_feature(samples, samples - 1, end_b.delta);
  out.push_back(end_b);
  return out;
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
