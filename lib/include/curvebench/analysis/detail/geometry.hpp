// Geometric helpers of the property audit (analysis/property_audit.hpp): the sampling grid, the
// parameter map between two domains, the distance from a point to a curve, the exact 2D convex
// hull and the distance outside it, and sign changes of a sequence.
#pragma once

#include "curvebench/core/curve.hpp"
#include "curvebench/core/point.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <span>
#include <vector>

namespace curvebench::analysis::detail {

/// The sampling grid: per_segment equal cells per breakpoint segment, both ends included.
template <class Curve>
std::vector<typename Curve::real_type> parameter_grid(const Curve& c, int per_segment) {
  using Real = typename Curve::real_type;
  const auto br = c.breakpoints();
  std::vector<Real> g;
  for (std::size_t s = 0; s + 1 < br.size(); ++s)
    for (int j = 0; j < per_segment; ++j) g.push_back(br[s] + (br[s + 1] - br[s]) * Real(j) / Real(per_segment));
  g.push_back(br.back());
  return g;
}

/// u in a's domain mapped to the same normalized position in b's domain.
template <class Real>
Real map_parameter(const Real& u, const interval<Real>& a, const interval<Real>& b) {
  if (a.lo == b.lo && a.hi == b.hi) return u;
  const Real v = b.lo + (u - a.lo) / (a.hi - a.lo) * (b.hi - b.lo);
  using std::max;
  using std::min;
  return min(max(v, b.lo), b.hi);
}

/// Distance from p to the curve, starting at the best grid sample and refining by a safeguarded
/// Newton iteration on g(u) = (C(u) - p) . C'(u) within the neighbouring cells.
template <class Curve, class Point>
typename Curve::real_type distance_to_curve(const Curve& c, const std::vector<typename Curve::real_type>& grid,
                                            const Point& p) {
  using Real = typename Curve::real_type;
  std::size_t best = 0;
  Real bd = std::numeric_limits<Real>::max();
  for (std::size_t j = 0; j < grid.size(); ++j) {
    const Real d = Point(c(grid[j]) - p).squaredNorm();
    if (d < bd) {
      bd = d;
      best = j;
    }
  }
  Real lo = grid[best == 0 ? 0 : best - 1];
  Real hi = grid[best + 1 < grid.size() ? best + 1 : best];
  Real u = grid[best];
  for (int it = 0; it < 60 && bd > Real(0); ++it) {
    const Point r = c(u) - p;
    const Point d1 = c.derivative(u, 1);
    const Point d2 = c.derivative(u, 2);
    const Real g = r.dot(d1);
    const Real gp = d1.dot(d1) + r.dot(d2);
    Real next = gp > Real(0) ? Real(u - g / gp) : (g > Real(0) ? lo : hi);
    if (!(next > lo && next < hi)) next = (g > Real(0) ? (lo + u) : (u + hi)) / Real(2);
    if (g > Real(0))
      hi = u;
    else
      lo = u;
    const Real dn = Point(c(next) - p).squaredNorm();
    if (dn < bd) bd = dn;
    if (next == u) break;
    u = next;
  }
  using std::sqrt;
  return sqrt(bd);
}

/// 2D convex hull (counter-clockwise, Andrew's monotone chain); collinear points dropped.
template <class Real>
std::vector<point<Real, 2>> convex_hull_2d(std::vector<point<Real, 2>> p) {
  std::sort(p.begin(), p.end(), [](const point<Real, 2>& a, const point<Real, 2>& b) {
    return a[0] < b[0] || (a[0] == b[0] && a[1] < b[1]);
  });
  p.erase(std::unique(p.begin(), p.end()), p.end());
  if (p.size() < 3) return p;
  auto cross = [](const point<Real, 2>& o, const point<Real, 2>& a, const point<Real, 2>& b) {
    return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0]);
  };
  std::vector<point<Real, 2>> h(2 * p.size());
  std::size_t k = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    while (k >= 2 && !(cross(h[k - 2], h[k - 1], p[i]) > Real(0))) --k;
    h[k++] = p[i];
  }
  for (std::size_t i = p.size() - 1, t = k + 1; i-- > 0;) {
    while (k >= t && !(cross(h[k - 2], h[k - 1], p[i]) > Real(0))) --k;
    h[k++] = p[i];
  }
  h.resize(k - 1);
  return h;
}

/// Distance of q outside the convex polygon / segment / point h (0 inside).
template <class Real>
Real distance_outside(const std::vector<point<Real, 2>>& h, const point<Real, 2>& q) {
  using std::max;
  using std::min;
  auto seg = [](const point<Real, 2>& a, const point<Real, 2>& b, const point<Real, 2>& x) {
    const point<Real, 2> ab = b - a;
    const Real l2 = ab.squaredNorm();
    Real t = l2 > Real(0) ? Real(point<Real, 2>(x - a).dot(ab) / l2) : Real(0);
    t = min(max(t, Real(0)), Real(1));
    return point<Real, 2>(x - (a + t * ab)).norm();
  };
  if (h.size() == 1) return point<Real, 2>(q - h[0]).norm();
  if (h.size() == 2) return seg(h[0], h[1], q);
  bool inside = true;
  for (std::size_t i = 0; i < h.size(); ++i) {
    const point<Real, 2>& a = h[i];
    const point<Real, 2>& b = h[(i + 1) % h.size()];
    const point<Real, 2> e = b - a;
    const Real side = e[0] * (q[1] - a[1]) - e[1] * (q[0] - a[0]);  // > 0: left of the ccw edge (inside)
    if (side < Real(0)) inside = false;
  }
  if (inside) return Real(0);
  Real best = std::numeric_limits<Real>::max();
  for (std::size_t i = 0; i < h.size(); ++i) best = min(best, seg(h[i], h[(i + 1) % h.size()], q));
  return best;
}

/// Sign changes of a sequence (zeros skipped).
template <class Real>
int sign_changes(const std::vector<Real>& v) {
  int changes = 0;
  int last = 0;
  for (const Real& x : v) {
    const int s = x > Real(0) ? 1 : (x < Real(0) ? -1 : 0);
    if (s == 0) continue;
    if (last != 0 && s != last) ++changes;
    last = s;
  }
  return changes;
}

}  // namespace curvebench::analysis::detail
