// The mechanics of the property audit: the functions declared in analysis/property_audit.hpp, each
// a thin wrapper that validates its input, samples the curve once and calls the measurement below.
// The measurements take the sampled curve and the random stream from the caller, so that
// audit_properties shares both among them.
#pragma once

#include "curvebench/analysis/detail/geometry.hpp"
#include "curvebench/analysis/property_audit.hpp"
#include "curvebench/core/curve.hpp"
#include "curvebench/core/error.hpp"
#include "curvebench/core/point.hpp"
#include "curvebench/core/real.hpp"

#include <Eigen/Core>
#include <Eigen/LU>
#include <boost/math/constants/constants.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <random>
#include <span>
#include <string>
#include <type_traits>
#include <vector>

namespace curvebench::analysis {
namespace detail {

/// The curve type a builder returns for items of Real and Dim, checked against the contract.
template <class Real, int Dim, class Builder>
struct built_curve {
  using type = std::decay_t<std::invoke_result_t<Builder&, std::span<const point<Real, Dim>>>>;
  static_assert(curve<type>, "the builder must return a curvebench::curve");
  static_assert(std::is_same_v<typename type::real_type, Real> && type::dimension == Dim,
                "the builder must return a curve of the items' Real and Dim");
};

/// The random stream of the audit: uniform doubles in [-1, 1).
struct random_stream {
  std::mt19937_64 engine;
  std::uniform_real_distribution<double> unit{-1.0, 1.0};
  explicit random_stream(std::uint64_t seed) : engine(seed) {}
  double operator()() { return unit(engine); }
};

inline void check_options(int samples_per_segment, int max_continuity_order, int random_lines, int directions) {
  if (samples_per_segment < 2)
    validate::fail("samples_per_segment = " + std::to_string(samples_per_segment) + ": must be >= 2");
  if (max_continuity_order < 0)
    validate::fail("max_continuity_order = " + std::to_string(max_continuity_order) + ": must be >= 0");
  if (random_lines < 0) validate::fail("random_lines = " + std::to_string(random_lines) + ": must be >= 0");
  if (directions < 0) validate::fail("directions = " + std::to_string(directions) + ": must be >= 0");
}

template <class Real, int Dim>
void check_input(std::span<const point<Real, Dim>> items, std::span<const control_role> roles,
                 const audit_options<Real>& opt) {
  validate::count_at_least("items", items.size(), 1);
  if (!roles.empty()) validate::same_count("roles", roles.size(), "items", items.size());
  check_options(opt.samples_per_segment, opt.max_continuity_order, opt.random_lines, opt.directions);
}

inline bool is_point(std::span<const control_role> roles, std::size_t i) {
  return roles.empty() || roles[i] == control_role::point;
}

inline bool all_points(std::span<const control_role> roles) {
  return std::all_of(roles.begin(), roles.end(), [](control_role r) { return r == control_role::point; });
}

/// The bounding-box diagonal of the point items (1 when there are none or it is 0).
template <class Real, int Dim>
Real data_scale(std::span<const point<Real, Dim>> items, std::span<const control_role> roles) {
  point<Real, Dim> lo, hi;
  bool first = true;
  for (std::size_t i = 0; i < items.size(); ++i) {
    if (!is_point(roles, i)) continue;
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

/// A curve with its domain, sampling grid, samples on the grid and the scale of its items.
template <class Curve>
struct sampled_curve {
  using real_type = typename Curve::real_type;
  using point_type = typename Curve::point_type;
  const Curve& c;
  interval<real_type> domain;
  std::vector<real_type> grid;
  std::vector<point_type> base;
  real_type scale;
};

template <class Curve>
sampled_curve<Curve> sample(const Curve& c, std::span<const point<typename Curve::real_type, Curve::dimension>> items,
                            std::span<const control_role> roles, int per_segment) {
  sampled_curve<Curve> s{c,
                         c.domain(),
                         parameter_grid(c, per_segment),
                         {},
                         data_scale<typename Curve::real_type, Curve::dimension>(items, roles)};
  s.base.resize(s.grid.size());
  for (std::size_t j = 0; j < s.grid.size(); ++j) s.base[j] = c(s.grid[j]);
  return s;
}

template <class Curve>
interpolation_result<typename Curve::real_type> interpolation(
    const sampled_curve<Curve>& s, std::span<const point<typename Curve::real_type, Curve::dimension>> items,
    std::span<const control_role> roles, const audit_options<typename Curve::real_type>& opt) {
  using Real = typename Curve::real_type;
  interpolation_result<Real> r;
  r.distance.assign(items.size(), std::numeric_limits<Real>::quiet_NaN());
  std::vector<std::size_t> point_index;
  for (std::size_t i = 0; i < items.size(); ++i)
    if (is_point(roles, i)) {
      point_index.push_back(i);
      r.distance[i] = distance_to_curve(s.c, s.grid, items[i]) / s.scale;
    }
  std::size_t hit = 0, hit_interior = 0;
  bool first = false, last = false;
  for (std::size_t k = 0; k < point_index.size(); ++k) {
    if (!(r.distance[point_index[k]] <= opt.interpolation_tolerance)) continue;
    ++hit;
    if (k == 0) first = true;
    if (k + 1 == point_index.size()) last = true;
    if (k != 0 && k + 1 != point_index.size()) ++hit_interior;
  }
  const std::size_t interior = point_index.size() >= 2 ? point_index.size() - 2 : 0;
  if (hit == point_index.size())
    r.kind = interpolation_kind::all;
  else if (hit == 0)
    r.kind = interpolation_kind::none;
  else if (first && last && hit == 2)
    r.kind = interpolation_kind::ends_only;
  else if (!first && !last && hit_interior == interior)
    r.kind = interpolation_kind::all_but_ends;
  else
    r.kind = interpolation_kind::partial;
  return r;
}

template <class Curve, class Builder>
local_control_result<typename Curve::real_type> local_control(
    Builder& build, const sampled_curve<Curve>& s,
    std::span<const point<typename Curve::real_type, Curve::dimension>> items,
    const audit_options<typename Curve::real_type>& opt, random_stream& unit) {
  using Real = typename Curve::real_type;
  using pt = typename Curve::point_type;
  constexpr int Dim = Curve::dimension;
  local_control_result<Real> r;
  r.moved_range.resize(items.size());
  r.moved_fraction.assign(items.size(), Real(0));
  r.local = true;
  const std::size_t cells = s.grid.size() - 1;
  std::vector<pt> work(items.begin(), items.end());
  for (std::size_t i = 0; i < items.size(); ++i) {
    pt dir;
    do {
      for (int d = 0; d < Dim; ++d) dir[d] = Real(unit());
    } while (!(dir.norm() > Real(1) / Real(4)));
    const pt delta = dir * (s.scale / Real(8) / dir.norm());
    work[i] = items[i] + delta;
    const auto moved = build(std::span<const pt>(work));
    work[i] = items[i];
    const interval<Real> md = moved.domain();
    const Real threshold = opt.move_threshold * delta.norm();
    std::vector<char> mv(s.grid.size());
    interval<Real> range{s.domain.hi, s.domain.lo};
    for (std::size_t j = 0; j < s.grid.size(); ++j) {
      mv[j] = pt(moved(map_parameter(s.grid[j], s.domain, md)) - s.base[j]).norm() > threshold ? 1 : 0;
      if (mv[j]) {
        range.lo = std::min(range.lo, s.grid[j]);
        range.hi = std::max(range.hi, s.grid[j]);
      }
    }
    std::size_t moved_cells = 0;
    for (std::size_t j = 0; j < cells; ++j) moved_cells += (mv[j] || mv[j + 1]) ? 1 : 0;
    r.moved_range[i] = range;
    r.moved_fraction[i] = Real(static_cast<long long>(moved_cells)) / Real(static_cast<long long>(cells));
    using std::max;
    r.max_moved_fraction = max(r.max_moved_fraction, r.moved_fraction[i]);
    if (moved_cells == cells) r.local = false;
  }
  return r;
}

template <class Curve>
continuity_result<typename Curve::real_type> continuity(const sampled_curve<Curve>& s,
                                                        const audit_options<typename Curve::real_type>& opt) {
  using Real = typename Curve::real_type;
  using pt = typename Curve::point_type;
  using std::max;
  using std::sqrt;
  const Curve& c = s.c;
  const int kmax = opt.max_continuity_order;
  continuity_result<Real> r;
  r.max_order = kmax;
  std::vector<Real> dscale(static_cast<std::size_t>(kmax) + 1, Real(0));
  for (const Real& u : s.grid)
    for (int k = 0; k <= kmax; ++k)
      dscale[static_cast<std::size_t>(k)] = max(dscale[static_cast<std::size_t>(k)], Real(c.derivative(u, k).norm()));
  const auto br = c.breakpoints();
  r.one_piece = br.size() <= 2;
  r.order = kmax;
  const Real e14 = sqrt(sqrt(epsilon<Real>()));
  for (std::size_t b = 1; b + 1 < br.size(); ++b) {
    const Real h = std::min(br[b] - br[b - 1], br[b + 1] - br[b]) * e14;
    knot_continuity<Real> kc{br[b], kmax, {}};
    for (int k = 0; k <= kmax; ++k) {
      // The one-sided limit at br[b] of the quadratic through the samples at sgn h, 2 sgn h, 3 sgn h.
      auto lim = [&](const Real& sgn) {
        const pt d1 = c.derivative(br[b] + sgn * h, k);
        const pt d2 = c.derivative(br[b] + sgn * Real(2) * h, k);
        const pt d3 = c.derivative(br[b] + sgn * Real(3) * h, k);
        return pt(Real(3) * d1 - Real(3) * d2 + d3);
      };
      const Real jump = pt(lim(Real(1)) - lim(Real(-1))).norm();
      const Real scale = dscale[static_cast<std::size_t>(k)];
      const Real rel = scale > Real(0) ? Real(jump / scale) : Real(0);
      kc.relative_jump.push_back(rel);
      if (kc.order == kmax && rel > opt.continuity_tolerance) kc.order = k - 1;
    }
    r.order = std::min(r.order, kc.order);
    r.knots.push_back(kc);
  }
  return r;
}

template <class Curve, class Builder>
affine_result<typename Curve::real_type> affine_invariance(
    Builder& build, const sampled_curve<Curve>& s,
    std::span<const point<typename Curve::real_type, Curve::dimension>> items, std::span<const control_role> roles,
    const audit_options<typename Curve::real_type>& opt, random_stream& unit) {
  using Real = typename Curve::real_type;
  using pt = typename Curve::point_type;
  constexpr int Dim = Curve::dimension;
  using std::abs;
  using std::max;
  Eigen::Matrix<Real, Dim, Dim> a;
  do {
    for (int r = 0; r < Dim; ++r)
      for (int q = 0; q < Dim; ++q) a(r, q) = Real(unit()) + (r == q ? Real(2) : Real(0));
    a(0, Dim - 1) += Real(1);  // a shear, so the map is not a similarity (when Dim > 1)
  } while (!(abs(Real(a.determinant())) > Real(1) / Real(2)));
  pt b;
  for (int d = 0; d < Dim; ++d) b[d] = Real(unit()) * s.scale;
  std::vector<pt> mapped(items.size());
  for (std::size_t i = 0; i < items.size(); ++i)
    mapped[i] = is_point(roles, i) ? pt(a * items[i] + b) : pt(a * items[i]);
  const auto ca = build(std::span<const pt>(mapped));
  const interval<Real> ad = ca.domain();
  const Real mscale = data_scale<Real, Dim>(std::span<const pt>(mapped), roles);
  affine_result<Real> r;
  Real dev(0);
  for (std::size_t j = 0; j < s.grid.size(); ++j)
    dev = max(dev, Real(pt(ca(map_parameter(s.grid[j], s.domain, ad)) - (a * s.base[j] + b)).norm() / mscale));
  r.deviation = dev;
  r.invariant = dev <= opt.affine_tolerance;
  return r;
}

template <class Curve>
convex_hull_result<typename Curve::real_type> convex_hull(
    const sampled_curve<Curve>& s, std::span<const point<typename Curve::real_type, Curve::dimension>> items,
    std::span<const control_role> roles, const audit_options<typename Curve::real_type>& opt) {
  using Real = typename Curve::real_type;
  using pt = typename Curve::point_type;
  convex_hull_result<Real> r;
  if constexpr (Curve::dimension == 2) {
    if (all_points(roles)) {
      using std::max;
      const auto hull = convex_hull_2d<Real>(std::vector<pt>(items.begin(), items.end()));
      Real worst(0);
      for (const pt& q : s.base) worst = max(worst, Real(distance_outside<Real>(hull, q) / s.scale));
      r.violation = worst;
      r.verdict = worst <= opt.hull_tolerance ? audit_verdict::yes : audit_verdict::no;
    }
  }
  return r;
}

template <class Curve>
variation_diminishing_result variation_diminishing(
    const sampled_curve<Curve>& s, std::span<const point<typename Curve::real_type, Curve::dimension>> items,
    std::span<const control_role> roles, const audit_options<typename Curve::real_type>& opt, random_stream& unit) {
  using Real = typename Curve::real_type;
  using pt = typename Curve::point_type;
  variation_diminishing_result r;
  if constexpr (Curve::dimension == 2) {
    if (all_points(roles)) {
      const std::vector<pt>& base = s.base;
      std::vector<Real> fc(base.size()), fp(items.size());
      int worst_excess = std::numeric_limits<int>::min();
      auto test_line = [&](const pt& n, const Real& offset) {
        for (std::size_t j = 0; j < base.size(); ++j) fc[j] = n.dot(base[j]) - offset;
        for (std::size_t i = 0; i < items.size(); ++i) fp[i] = n.dot(items[i]) - offset;
        worst_excess = std::max(worst_excess, sign_changes(fc) - sign_changes(fp));
        ++r.lines_tested;
      };
      // Random lines through the bounding region.
      for (int l = 0; l < opt.random_lines; ++l) {
        const double th = boost::math::constants::pi<double>() * (unit() + 1.0);
        const pt n(Real(std::cos(th)), Real(std::sin(th)));
        const pt q =
            items[static_cast<std::size_t>((unit() + 1.0) / 2.0 * static_cast<double>(items.size() - 1) + 0.5)];
        test_line(n, n.dot(q) + Real(unit()) * s.scale / Real(4));
      }
      // Lines just inside each local extremum of n . C(u), where a curve bulge is cut twice.
      const Real offsets[3] = {s.scale / Real(1000000), s.scale / Real(10000), s.scale / Real(100)};
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
      r.worst_excess = worst_excess;
      r.verdict = worst_excess <= 0 ? audit_verdict::yes : audit_verdict::no;
    }
  }
  return r;
}

}  // namespace detail

template <curve Curve>
interpolation_result<typename Curve::real_type> measure_interpolation(
    const Curve& c, std::span<const point<typename Curve::real_type, Curve::dimension>> items,
    std::span<const control_role> roles, const audit_options<typename Curve::real_type>& opt) {
  detail::check_input(items, roles, opt);
  return detail::interpolation(detail::sample(c, items, roles, opt.samples_per_segment), items, roles, opt);
}

template <class Real, int Dim, class Builder>
local_control_result<Real> measure_local_control(Builder&& build, std::span<const point<Real, Dim>> items,
                                                 std::span<const control_role> roles, const audit_options<Real>& opt) {
  using Curve = typename detail::built_curve<Real, Dim, Builder>::type;
  detail::check_input(items, roles, opt);
  const Curve c = build(items);
  detail::random_stream unit(opt.seed);
  return detail::local_control(build, detail::sample(c, items, roles, opt.samples_per_segment), items, opt, unit);
}

template <curve Curve>
continuity_result<typename Curve::real_type> measure_continuity(const Curve& c,
                                                                const audit_options<typename Curve::real_type>& opt) {
  detail::check_options(opt.samples_per_segment, opt.max_continuity_order, opt.random_lines, opt.directions);
  return detail::continuity(detail::sample(c, {}, {}, opt.samples_per_segment), opt);
}

template <class Real, int Dim, class Builder>
affine_result<Real> measure_affine_invariance(Builder&& build, std::span<const point<Real, Dim>> items,
                                              std::span<const control_role> roles, const audit_options<Real>& opt) {
  using Curve = typename detail::built_curve<Real, Dim, Builder>::type;
  detail::check_input(items, roles, opt);
  const Curve c = build(items);
  detail::random_stream unit(opt.seed);
  return detail::affine_invariance(build, detail::sample(c, items, roles, opt.samples_per_segment), items, roles, opt,
                                   unit);
}

template <curve Curve>
convex_hull_result<typename Curve::real_type> measure_convex_hull(
    const Curve& c, std::span<const point<typename Curve::real_type, Curve::dimension>> items,
    std::span<const control_role> roles, const audit_options<typename Curve::real_type>& opt) {
  detail::check_input(items, roles, opt);
  return detail::convex_hull(detail::sample(c, items, roles, opt.samples_per_segment), items, roles, opt);
}

template <curve Curve>
variation_diminishing_result measure_variation_diminishing(
    const Curve& c, std::span<const point<typename Curve::real_type, Curve::dimension>> items,
    std::span<const control_role> roles, const audit_options<typename Curve::real_type>& opt) {
  detail::check_input(items, roles, opt);
  detail::random_stream unit(opt.seed);
  return detail::variation_diminishing(detail::sample(c, items, roles, opt.samples_per_segment), items, roles, opt,
                                       unit);
}

template <class Real, int Dim, class Builder>
property_report<Real> audit_properties(Builder&& build, std::span<const point<Real, Dim>> items,
                                       std::span<const control_role> roles, const audit_options<Real>& opt) {
  using Curve = typename detail::built_curve<Real, Dim, Builder>::type;
  detail::check_input(items, roles, opt);
  const Curve c = build(items);
  const detail::sampled_curve<Curve> s = detail::sample(c, items, roles, opt.samples_per_segment);
  detail::random_stream unit(opt.seed);
  property_report<Real> r;
  r.items = items.size();
  r.interpolation = detail::interpolation(s, items, roles, opt);
  r.local_control = detail::local_control(build, s, items, opt, unit);
  r.continuity = detail::continuity(s, opt);
  r.affine = detail::affine_invariance(build, s, items, roles, opt, unit);
  r.convex_hull = detail::convex_hull(s, items, roles, opt);
  r.variation_diminishing = detail::variation_diminishing(s, items, roles, opt, unit);
  return r;
}

}  // namespace curvebench::analysis
