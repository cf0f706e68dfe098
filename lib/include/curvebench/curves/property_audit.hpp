// Property audit: measures, for any curve family built from control data, the properties of seed
// 001's table ("There is no single best representation of cubic spline": Interpolate? Local?
// Continuity, Affine?, Convex?, VD?) instead of asserting them from memory.
//
// Source: seed 001 (the table and the definitions of affine invariance and the convex hull
// property), seed 000 (properties of Bezier curves: end point interpolation, affine invariance,
// convex hull, variation diminishing "no straight line cuts the curve more times than it cuts the
// control polygon"; C^k continuity at knots).
//
// Usage: `audit_properties(build, items, roles, options)` where `build` maps a span of control items
// (points, or points and tangents) to a curve satisfying `curvebench::curve`, `items` is the control
// data and `roles` says which items are tangents (default: all points). The family is rebuilt from
// perturbed / transformed copies of the items; nothing about the family is assumed.
// What is measured, and how (all distances relative to `scale`, the bounding-box diagonal of the
// point items; parameters sampled on a grid of `samples_per_segment` cells per breakpoint segment):
//   - interpolation: for each point item, the distance to the curve (best grid sample, then a
//     safeguarded Newton iteration on (C(u) - P) . C'(u) = 0); interpolated when <= tolerance.
//     Summary: all / all but the end items / end items only / none / partial.
//   - local control: each item in turn is moved by scale/8 in a random direction and the family
//     rebuilt; a grid sample "moved" when the curve changed there by more than move_threshold times
//     the perturbation. Per item: the moved parameter range and the fraction of grid cells that
//     moved. Local when every item leaves some whole grid cell unmoved (so a global family whose
//     influence merely vanishes at isolated parameters, like a Bezier curve at its ends, is not local).
//   - continuity at every interior breakpoint b: one-sided limits of derivative(u, k), k = 0..max,
//     extrapolated from u = b -/+ h, b -/+ 2h, b -/+ 3h (quadratic extrapolation, exact for the
//     derivatives of a cubic; h = eps^(1/4) times the shorter neighbouring segment); the jump is
//     compared with the largest |derivative(u, k)| on the grid. C^k when jumps 0..k are all below
//     continuity_tolerance. The curve's continuity is the minimum over breakpoints (C^max means "at
//     least"); a curve with no interior breakpoint is reported as one polynomial/rational piece.
//   - affine invariance: a random well-conditioned affine map x -> A x + b is applied to the point
//     items (A v to tangent items) and the family rebuilt; the rebuilt curve is compared with the
//     mapped curve at the same normalized parameter (the domain may depend on the data, e.g.
//     chord-length knots).
//   - convex hull (Dim = 2, all items points): every grid sample within the convex hull of the items
//     (exact 2D hull, Andrew's monotone chain); otherwise not applicable.
//   - variation diminishing (Dim = 2, all items points): for random lines and for lines just inside
//     every local extremum of n . C(u) over 72 directions n, the number of sign changes of the signed
//     distance along the sampled curve vs along the control polygon. Sampling can only miss curve
//     crossings, so a reported violation is real; "yes" means none was found.
// Cost: (items + 2) rebuilds and O(items * samples) evaluations, plus O(lines * samples) for VD.
// The audit is a measurement: it reports; the tests decide what the answer should be.
#pragma once

#include "curvebench/core/curve.hpp"
#include "curvebench/core/error.hpp"
#include "curvebench/core/point.hpp"
#include "curvebench/core/real.hpp"

#include <boost/math/constants/constants.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <random>
#include <span>
#include <string>
#include <type_traits>
#include <vector>

namespace curvebench {

/// What a control item is: a point the curve may pass through, or a tangent (a vector).
enum class control_role { point, tangent };

/// Which point items the curve passes through.
enum class interpolation_kind { all, all_but_ends, ends_only, none, partial };

/// A property that holds, fails, or does not apply (tangent items, or Dim != 2).
enum class audit_verdict { yes, no, not_applicable };

[[nodiscard]] inline const char* to_string(interpolation_kind k) {
  switch (k) {
    case interpolation_kind::all:
      return "all";
    case interpolation_kind::all_but_ends:
      return "all but ends";
    case interpolation_kind::ends_only:
      return "ends only";
    case interpolation_kind::none:
      return "none";
    case interpolation_kind::partial:
      return "partial";
  }
  return "unknown";
}

[[nodiscard]] inline const char* to_string(audit_verdict v) {
  switch (v) {
    case audit_verdict::yes:
      return "yes";
    case audit_verdict::no:
      return "no";
    case audit_verdict::not_applicable:
      return "n/a";
  }
  return "unknown";
}

/// Tuning of the audit; `audit_options<Real>::defaults()` scales the tolerances with eps(Real).
template <class Real>
struct audit_options {
  int samples_per_segment = 48;
  int max_continuity_order = 3;
  int random_lines = 400;
  int directions = 72;
  std::uint64_t seed = 1;
  Real interpolation_tolerance;  ///< distance / scale at or below which a point is interpolated
  Real move_threshold;           ///< change / perturbation above which a sample "moved"
  Real continuity_tolerance;     ///< jump / derivative scale above which a derivative is discontinuous
  Real affine_tolerance;         ///< deviation / scale above which affine invariance fails
  Real hull_tolerance;           ///< distance outside the hull / scale above which the hull is left

  [[nodiscard]] static audit_options defaults() {
    using std::sqrt;
    const Real e = epsilon<Real>();
    audit_options o;
    const Real e34 = sqrt(e) * sqrt(sqrt(e));  // eps^(3/4): 1.8e-12 in double
    o.interpolation_tolerance = Real(64) * e34;
    o.move_threshold = e34;
    o.continuity_tolerance = Real(64) * sqrt(e);
    o.affine_tolerance = Real(64) * e34;
    o.hull_tolerance = Real(64) * e34;
    return o;
  }
};

/// Continuity measured at one interior breakpoint.
template <class Real>
struct knot_continuity {
  Real u;
  int order;                       ///< highest k with jumps 0..k below tolerance; -1: the curve jumps
  std::vector<Real> relative_jump;  ///< |D_k(u+) - D_k(u-)| / max_grid |D_k|, k = 0..max
};

template <class Real>
struct property_report {
  std::size_t items = 0;
  // interpolation
  interpolation_kind interpolation = interpolation_kind::none;
  std::vector<Real> distance;  ///< per item: distance from the curve / scale (NaN for tangents)
  // local control
  bool local_control = false;
  std::vector<interval<Real>> moved_range;  ///< per item: first..last moved parameter (lo > hi: none)
  std::vector<Real> moved_fraction;         ///< per item: fraction of grid cells that moved
  Real max_moved_fraction = Real(0);
  // continuity
  bool one_piece = true;  ///< no interior breakpoint
  int continuity = 0;     ///< min over interior breakpoints (max_continuity_order means "at least")
  int max_continuity_order = 3;
  std::vector<knot_continuity<Real>> knots;
  // affine invariance
  bool affine_invariant = false;
  Real affine_deviation = Real(0);
  // convex hull
  audit_verdict convex_hull = audit_verdict::not_applicable;
  Real hull_violation = Real(0);  ///< largest distance outside the hull / scale
  // variation diminishing
  audit_verdict variation_diminishing = audit_verdict::not_applicable;
  int lines_tested = 0;
  int worst_excess = 0;  ///< max over lines of (curve crossings - polygon crossings)
};

namespace detail {

template <class Real, int Dim>
Real audit_scale(std::span<const point<Real, Dim>> items, std::span<const control_role> roles) {
  point<Real, Dim> lo, hi;
  bool first = true;
  for (std::size_t i = 0; i < items.size(); ++i) {
    if (!roles.empty() && roles[i] != control_role::point) continue;
    if (first) {
      lo = hi = items[i];
      first = false;
    }
    lo = lo.cwiseMin(items[i]);
    hi = hi.cwiseMax(items[i]);
  }
  if (first) return Real(1);
  const Real d = point<Real, Dim>(hi - lo).norm();
  return d > Real(0) ? d : Real(1);
}

/// The sampling grid: samples_per_segment cells per breakpoint segment.
template <class Curve>
std::vector<typename Curve::real_type> audit_grid(const Curve& c, int per_segment) {
  using Real = typename Curve::real_type;
  const auto br = c.breakpoints();
  std::vector<Real> g;
  for (std::size_t s = 0; s + 1 < br.size(); ++s)
    for (int j = 0; j < per_segment; ++j)
      g.push_back(br[s] + (br[s + 1] - br[s]) * Real(j) / Real(per_segment));
  g.push_back(br.back());
  return g;
}

/// u in a's domain mapped to the same normalized position in b's domain.
template <class Real>
Real audit_map(const Real& u, const interval<Real>& a, const interval<Real>& b) {
  if (a.lo == b.lo && a.hi == b.hi) return u;
  const Real v = b.lo + (u - a.lo) / (a.hi - a.lo) * (b.hi - b.lo);
  using std::max;
  using std::min;
  return min(max(v, b.lo), b.hi);
}

/// Distance from p to the curve, starting at the best grid sample and refining by a safeguarded
/// Newton iteration on g(u) = (C(u) - p) . C'(u) within the neighbouring cells.
template <class Curve, class Point>
typename Curve::real_type audit_distance(const Curve& c, const std::vector<typename Curve::real_type>& grid,
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
std::vector<point<Real, 2>> audit_hull(std::vector<point<Real, 2>> p) {
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
Real audit_outside(const std::vector<point<Real, 2>>& h, const point<Real, 2>& q) {
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
  Real out(0);
  bool inside = true;
  for (std::size_t i = 0; i < h.size(); ++i) {
    const point<Real, 2>& a = h[i];
    const point<Real, 2>& b = h[(i + 1) % h.size()];
    const point<Real, 2> e = b - a;
    const Real side = e[0] * (q[1] - a[1]) - e[1] * (q[0] - a[0]);  // > 0: left of the ccw edge (inside)
    if (side < Real(0)) inside = false;
  }
  if (inside) return out;
  Real best = std::numeric_limits<Real>::max();
  for (std::size_t i = 0; i < h.size(); ++i) best = min(best, seg(h[i], h[(i + 1) % h.size()], q));
  return best;
}

/// Sign changes of a sequence (zeros skipped).
template <class Real>
int audit_sign_changes(const std::vector<Real>& v) {
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

}  // namespace detail

/// Measures seed 001's properties for the family `build` on the control items (see the header).
template <class Real, int Dim, class Builder>
[[nodiscard]] property_report<Real> audit_properties(Builder&& build, std::span<const point<Real, Dim>> items,
                                                     std::span<const control_role> roles = {},
                                                     audit_options<Real> opt = audit_options<Real>::defaults()) {
  using Curve = std::decay_t<std::invoke_result_t<Builder&, std::span<const point<Real, Dim>>>>;
  static_assert(curve<Curve>, "the builder must return a curvebench::curve");
  static_assert(std::is_same_v<typename Curve::real_type, Real> && Curve::dimension == Dim,
                "the builder must return a curve of the items' Real and Dim");
  using pt = point<Real, Dim>;
  if (!roles.empty()) validate::same_count("roles", roles.size(), "items", items.size());
  if (opt.samples_per_segment < 2)
    validate::fail("samples_per_segment = " + std::to_string(opt.samples_per_segment) + ": must be >= 2");
  if (opt.max_continuity_order < 0)
    validate::fail("max_continuity_order = " + std::to_string(opt.max_continuity_order) + ": must be >= 0");
  auto is_point = [&](std::size_t i) { return roles.empty() || roles[i] == control_role::point; };
  bool all_points = true;
  for (std::size_t i = 0; i < items.size(); ++i) all_points = all_points && is_point(i);

  using std::abs;
  using std::max;
  using std::sqrt;
  property_report<Real> rep;
  rep.items = items.size();
  rep.max_continuity_order = opt.max_continuity_order;
  const Real scale = detail::audit_scale<Real, Dim>(items, roles);
  const Curve c = build(items);
  const interval<Real> dom = c.domain();
  const std::vector<Real> grid = detail::audit_grid(c, opt.samples_per_segment);
  std::vector<pt> base(grid.size());
  for (std::size_t j = 0; j < grid.size(); ++j) base[j] = c(grid[j]);
  std::mt19937_64 rng(opt.seed);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);

  // ---- interpolation ----
  rep.distance.assign(items.size(), std::numeric_limits<Real>::quiet_NaN());
  std::vector<std::size_t> point_index;
  for (std::size_t i = 0; i < items.size(); ++i)
    if (is_point(i)) {
      point_index.push_back(i);
      rep.distance[i] = detail::audit_distance(c, grid, items[i]) / scale;
    }
  {
    std::size_t hit = 0, hit_interior = 0;
    bool first = false, last = false;
    for (std::size_t k = 0; k < point_index.size(); ++k) {
      const bool on = rep.distance[point_index[k]] <= opt.interpolation_tolerance;
      if (!on) continue;
      ++hit;
      if (k == 0) first = true;
      if (k + 1 == point_index.size()) last = true;
      if (k != 0 && k + 1 != point_index.size()) ++hit_interior;
    }
    const std::size_t interior = point_index.size() >= 2 ? point_index.size() - 2 : 0;
    if (hit == point_index.size())
      rep.interpolation = interpolation_kind::all;
    else if (hit == 0)
      rep.interpolation = interpolation_kind::none;
    else if (first && last && hit == 2)
      rep.interpolation = interpolation_kind::ends_only;
    else if (!first && !last && hit_interior == interior)
      rep.interpolation = interpolation_kind::all_but_ends;
    else
      rep.interpolation = interpolation_kind::partial;
  }

  // ---- local control ----
  rep.moved_range.resize(items.size());
  rep.moved_fraction.assign(items.size(), Real(0));
  rep.local_control = true;
  std::vector<pt> work(items.begin(), items.end());
  for (std::size_t i = 0; i < items.size(); ++i) {
    pt dir;
    do {
      for (int d = 0; d < Dim; ++d) dir[d] = Real(unit(rng));
    } while (!(dir.norm() > Real(1) / Real(4)));
    const pt delta = dir * (scale / Real(8) / dir.norm());
    work[i] = items[i] + delta;
    const Curve moved = build(std::span<const pt>(work));
    work[i] = items[i];
    const interval<Real> md = moved.domain();
    const Real threshold = opt.move_threshold * delta.norm();
    std::vector<char> mv(grid.size());
    interval<Real> range{dom.hi, dom.lo};
    for (std::size_t j = 0; j < grid.size(); ++j) {
      mv[j] = pt(moved(detail::audit_map(grid[j], dom, md)) - base[j]).norm() > threshold ? 1 : 0;
      if (mv[j]) {
        range.lo = std::min(range.lo, grid[j]);
        range.hi = std::max(range.hi, grid[j]);
      }
    }
    std::size_t moved_cells = 0;
    for (std::size_t j = 0; j + 1 < grid.size(); ++j) moved_cells += (mv[j] || mv[j + 1]) ? 1 : 0;
    rep.moved_range[i] = range;
    rep.moved_fraction[i] = Real(static_cast<long long>(moved_cells)) / Real(static_cast<long long>(grid.size() - 1));
    rep.max_moved_fraction = max(rep.max_moved_fraction, rep.moved_fraction[i]);
    if (moved_cells == grid.size() - 1) rep.local_control = false;
  }

  // ---- continuity ----
  const int kmax = opt.max_continuity_order;
  std::vector<Real> dscale(static_cast<std::size_t>(kmax) + 1, Real(0));
  for (const Real& u : grid)
    for (int k = 0; k <= kmax; ++k)
      dscale[static_cast<std::size_t>(k)] = max(dscale[static_cast<std::size_t>(k)], Real(c.derivative(u, k).norm()));
  const auto br = c.breakpoints();
  rep.one_piece = br.size() <= 2;
  rep.continuity = kmax;
  {
    using std::sqrt;
    const Real e14 = sqrt(sqrt(epsilon<Real>()));
    for (std::size_t b = 1; b + 1 < br.size(); ++b) {
      const Real h = std::min(br[b] - br[b - 1], br[b + 1] - br[b]) * e14;
      knot_continuity<Real> kc{br[b], kmax, {}};
      for (int k = 0; k <= kmax; ++k) {
        auto lim = [&](const Real& sgn) {
          const pt d1 = c.derivative(br[b] + sgn * h, k);
          const pt d2 = c.derivative(br[b] + sgn * Real(2) * h, k);
          const pt d3 = c.derivative(br[b] + sgn * Real(3) * h, k);
          return pt(Real(3) * d1 - Real(3) * d2 + d3);
        };
        const Real jump = pt(lim(Real(1)) - lim(Real(-1))).norm();
        const Real s = dscale[static_cast<std::size_t>(k)];
        const Real rel = s > Real(0) ? Real(jump / s) : Real(0);
        kc.relative_jump.push_back(rel);
        if (kc.order == kmax && rel > opt.continuity_tolerance) kc.order = k - 1;
      }
      rep.continuity = std::min(rep.continuity, kc.order);
      rep.knots.push_back(kc);
    }
  }

  // ---- affine invariance ----
  {
    Eigen::Matrix<Real, Dim, Dim> a;
    do {
      for (int r = 0; r < Dim; ++r)
        for (int q = 0; q < Dim; ++q) a(r, q) = Real(unit(rng)) + (r == q ? Real(2) : Real(0));
      a(0, Dim - 1) += Real(1);  // a shear, so the map is not a similarity (when Dim > 1)
    } while (!(abs(Real(a.determinant())) > Real(1) / Real(2)));
    pt b;
    for (int d = 0; d < Dim; ++d) b[d] = Real(unit(rng)) * scale;
    std::vector<pt> mapped(items.size());
    for (std::size_t i = 0; i < items.size(); ++i) mapped[i] = is_point(i) ? pt(a * items[i] + b) : pt(a * items[i]);
    const Curve ca = build(std::span<const pt>(mapped));
    const interval<Real> ad = ca.domain();
    const Real mscale = detail::audit_scale<Real, Dim>(std::span<const pt>(mapped), roles);
    Real dev(0);
    for (std::size_t j = 0; j < grid.size(); ++j)
      dev = max(dev, Real(pt(ca(detail::audit_map(grid[j], dom, ad)) - (a * base[j] + b)).norm() / mscale));
    rep.affine_deviation = dev;
    rep.affine_invariant = dev <= opt.affine_tolerance;
  }

  // ---- convex hull and variation diminishing (planar point data) ----
  if constexpr (Dim == 2) {
    if (all_points) {
      const auto hull = detail::audit_hull<Real>(std::vector<pt>(items.begin(), items.end()));
      Real worst(0);
      for (const pt& q : base) worst = max(worst, Real(detail::audit_outside<Real>(hull, q) / scale));
      rep.hull_violation = worst;
      rep.convex_hull = worst <= opt.hull_tolerance ? audit_verdict::yes : audit_verdict::no;

      std::vector<Real> fc(base.size()), fp(items.size());
      int worst_excess = std::numeric_limits<int>::min();
      auto test_line = [&](const pt& n, const Real& offset) {
        for (std::size_t j = 0; j < base.size(); ++j) fc[j] = n.dot(base[j]) - offset;
        for (std::size_t i = 0; i < items.size(); ++i) fp[i] = n.dot(items[i]) - offset;
        worst_excess = std::max(worst_excess, detail::audit_sign_changes(fc) - detail::audit_sign_changes(fp));
        ++rep.lines_tested;
      };
      // Random lines through the bounding region.
      for (int l = 0; l < opt.random_lines; ++l) {
        const double th = boost::math::constants::pi<double>() * (unit(rng) + 1.0);
        const pt n(Real(std::cos(th)), Real(std::sin(th)));
        const pt q = items[static_cast<std::size_t>((unit(rng) + 1.0) / 2.0 * static_cast<double>(items.size() - 1) + 0.5)];
        test_line(n, n.dot(q) + Real(unit(rng)) * scale / Real(4));
      }
      // Lines just inside each local extremum of n . C(u), where a curve bulge is cut twice.
      const Real offsets[3] = {scale / Real(1000000), scale / Real(10000), scale / Real(100)};
      for (int dnum = 0; dnum < opt.directions; ++dnum) {
        const double th = boost::math::constants::two_pi<double>() * dnum / opt.directions;
        const pt n(Real(std::cos(th)), Real(std::sin(th)));
        for (std::size_t j = 0; j < base.size(); ++j) fc[j] = n.dot(base[j]);
        std::vector<Real> peaks;
        for (std::size_t j = 1; j + 1 < base.size(); ++j)
          if (fc[j] > fc[j - 1] && fc[j] >= fc[j + 1]) peaks.push_back(fc[j]);
        for (const Real& v : peaks)
          for (const Real& off : offsets) test_line(n, v - off);
      }
      rep.worst_excess = worst_excess;
      rep.variation_diminishing = worst_excess <= 0 ? audit_verdict::yes : audit_verdict::no;
    }
  }
  return rep;
}

/// The header of the markdown table written by `audit_markdown_row`.
[[nodiscard]] inline std::string audit_markdown_header() {
  return "| Family | Interpolates | Local control | Continuity | Affine invariant | Convex hull | Variation "
         "diminishing |\n|---|---|---|---|---|---|---|\n";
}

/// One row of the measured table: the verdicts and the numbers behind them.
template <class Real>
[[nodiscard]] std::string audit_markdown_row(const std::string& family, const property_report<Real>& r) {
  auto num = [](const Real& x) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.2g", static_cast<double>(x));
    return std::string(buf);
  };
  std::string row = "| " + family + " | " + to_string(r.interpolation) + " | ";
  row += std::string(r.local_control ? "yes" : "no") + " (max " +
         std::to_string(static_cast<int>(static_cast<double>(r.max_moved_fraction) * 100.0 + 0.5)) + "% moves) | ";
  if (r.one_piece)
    row += "one piece (no interior knot)";
  else if (r.continuity < 0)
    row += "discontinuous";
  else
    row += "C" + std::to_string(r.continuity) + (r.continuity == r.max_continuity_order ? "+" : "");
  row += " | " + std::string(r.affine_invariant ? "yes" : "no") + " (dev " + num(r.affine_deviation) + ") | ";
  row += to_string(r.convex_hull);
  if (r.convex_hull == audit_verdict::no) row += " (out by " + num(r.hull_violation) + ")";
  row += " | " + std::string(to_string(r.variation_diminishing));
  if (r.variation_diminishing != audit_verdict::not_applicable)
    row += " (" + std::to_string(r.lines_tested) + " lines, worst excess " + std::to_string(r.worst_excess) + ")";
  row += " |\n";
  return row;
}

}  // namespace curvebench
