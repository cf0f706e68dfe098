// The curves' bounds on the rounding of their own evaluation (core/curve.hpp, rounding_bound):
// barycentric Lagrange and de Casteljau Bezier, P and P', in double against the real50 twin of the
// same data (converted exactly) at many parameters, on well- and ill-conditioned cases; and what
// the arc-length methods do with a curve that has no bound (the monomial Lagrange).
//
// Also the bounds of the other families (polyline, the cubic engine with its families' slope errors,
// de Boor for B-splines and NURBS, rational and composite Bezier), on data near the origin and far
// from it (where the coordinates' rounding dominates), on uniform and uneven knots.
//
// Tolerances (one table):
//   - the bound must hold: max error <= bound, no margin (it is a bound, not an estimate);
//   - for the other families, looseness only where their rounding is visible (data shifted far from
//     the origin): bound <= 1000 x the largest error seen (see each test's measured ratios);
//   - looseness: bound <= 1000 x the largest error seen, on the ill-conditioned cases (Runge through
//     equispaced nodes, a degree-20 Bezier), which suffices: a bound a thousand times the
//     error still adds only ~1e3 eps of the curve's size to an estimate. Measured (this machine):
//     see each test's comment.
#include "support/accuracy.hpp"

#include "curvebench/arclength/adaptive_subdivision.hpp"
#include "curvebench/arclength/forward_difference.hpp"
#include "curvebench/arclength/length.hpp"
#include "curvebench/arclength/parameterization.hpp"
#include "curvebench/core/any_curve.hpp"
#include "curvebench/curves/bezier.hpp"
#include "curvebench/curves/bspline.hpp"
#include "curvebench/curves/cardinal_spline.hpp"
#include "curvebench/curves/composite_bezier.hpp"
#include "curvebench/curves/hermite_spline.hpp"
#include "curvebench/curves/kochanek_bartels.hpp"
#include "curvebench/curves/lagrange.hpp"
#include "curvebench/curves/natural_cubic_spline.hpp"
#include "curvebench/curves/nurbs.hpp"
#include "curvebench/curves/polyline.hpp"
#include "curvebench/curves/rational_bezier.hpp"
#include "curvebench/reference/multiprecision.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <concepts>
#include <string>
#include <vector>

namespace cb = curvebench;
namespace al = curvebench::arclength;
using R = cb::real50;

namespace {

constexpr double max_looseness = 1000;

template <class Real>
using pt2 = cb::point<Real, 2>;

// The data of bench/cases/runge_lagrange_*.json's generator (io/family.hpp), in double, shifted by
// `shift` in x (a curve far from the origin rounds relative to its coordinates, not its size).
struct lagrange_data {
  std::vector<pt2<double>> points;
  std::vector<double> params;
};

lagrange_data runge(int count, bool chebyshev, double shift = 0, double a = 25) {
  lagrange_data d;
  for (int i = 0; i < count; ++i) {
    const double f = static_cast<double>(i) / static_cast<double>(count - 1);
    const double x = chebyshev ? -std::cos(3.141592653589793 * f) : -1 + 2 * f;
    d.points.emplace_back(x + shift, 1 / (1 + a * x * x));
  }
  d.params = chebyshev ? cb::chebyshev_parameters<double>(static_cast<std::size_t>(count))
                       : cb::equispaced_parameters<double>(static_cast<std::size_t>(count));
  return d;
}

template <class Real>
cb::lagrange<Real, 2> build(const lagrange_data& d, cb::lagrange_algorithm alg = cb::lagrange_algorithm::barycentric) {
  std::vector<pt2<Real>> p;
  for (const auto& q : d.points) p.emplace_back(Real(q[0]), Real(q[1]));
  const std::vector<Real> u(d.params.begin(), d.params.end());
  return cb::lagrange<Real, 2>(std::span<const pt2<Real>>(p), std::span<const Real>(u), alg);
}

template <class Real>
cb::bezier<Real, 2> bezier_of(const std::vector<pt2<double>>& pts, double lo = 0, double hi = 1) {
  std::vector<pt2<Real>> p;
  for (const auto& q : pts) p.emplace_back(Real(q[0]), Real(q[1]));
  return cb::bezier<Real, 2>(std::span<const pt2<Real>>(p), cb::interval<Real>{Real(lo), Real(hi)});
}

// bench/cases/bezier_degree_20.json: 21 points of a spiral (the generator of io/family.hpp), shifted.
std::vector<pt2<double>> spiral(int count, double turns, double shift) {
  std::vector<pt2<double>> p;
  for (int i = 0; i < count; ++i) {
    const double f = static_cast<double>(i) / static_cast<double>(count - 1);
    const double th = 2 * 3.141592653589793 * turns * f;
    p.emplace_back(f * std::cos(th) + shift, f * std::sin(th));
  }
  return p;
}

// The largest |fl(P^(k)(u)) - P^(k)(u)| over 4001 parameters: a uniform grid, every node and its two
// neighbours one ulp away (where the barycentric formulas switch branches).
template <class C, class C50>
double max_error(const C& c, const C50& c50, int order) {
  const cb::interval<double> d = c.domain();
  std::vector<double> us;
  for (int k = 0; k <= 4000; ++k) us.push_back(k == 4000 ? d.hi : d.lo + (d.hi - d.lo) * k / 4000.0);
  for (double b : c.breakpoints()) {
    us.push_back(std::nextafter(b, d.lo));
    us.push_back(std::nextafter(b, d.hi));
  }
  if constexpr (requires {
                  { c.parameters()[0] } -> std::convertible_to<double>;
                })
    for (double u : c.parameters()) {
      us.push_back(u);
      us.push_back(std::nextafter(u, d.lo));
      us.push_back(std::nextafter(u, d.hi));
    }
  double worst = 0;
  for (double u : us) {
    if (!(u >= d.lo && u <= d.hi)) continue;
    const pt2<double> v = c.derivative(u, order);
    const pt2<R> v50 = c50.derivative(R(u), order);
    const R e = sqrt((R(v[0]) - v50[0]) * (R(v[0]) - v50[0]) + (R(v[1]) - v50[1]) * (R(v[1]) - v50[1]));
    worst = std::max(worst, static_cast<double>(e));
  }
  return worst;
}

// ill_conditioned: the bound must also be within `looseness` x the largest error seen.
template <class C, class C50>
void check_bound(const C& c, const C50& c50, bool ill_conditioned, double looseness = max_looseness) {
  for (int order : {0, 1}) {
    SCOPED_TRACE("order " + std::to_string(order));
    const double bound = c.rounding_bound(order);
    const double err = max_error(c, c50, order);
    EXPECT_TRUE(std::isfinite(bound));
    EXPECT_LE(err, bound) << "the bound does not bound";
    if (ill_conditioned) {
      EXPECT_GT(err, 0.0);
      EXPECT_LE(bound, looseness * err) << "bound " << bound << " vs error " << err;
    }
    std::printf("  order %d: max error %.3g, bound %.3g (%.0fx)\n", order, err, bound, bound / err);
  }
}

// Data of the other families: count points on a wavy arc, shifted by `shift` in x, at knots whose
// intervals alternate 1 and `ratio` (1: uniform).
struct family_data {
  std::vector<pt2<double>> points;
  std::vector<double> knots;
};

family_data wavy(int count, double shift, double ratio = 1) {
  family_data d;
  double u = 0;
  for (int i = 0; i < count; ++i) {
    const double f = static_cast<double>(i) / static_cast<double>(count - 1);
    d.points.emplace_back(3 * std::cos(2.5 * f) + shift + 0.1 * i, 2 * std::sin(4 * f) + 0.3 * std::sin(17.0 * f));
    d.knots.push_back(u);
    u += (i % 2 == 0) ? 1.0 : ratio;
  }
  return d;
}

template <class Real>
cb::point_list<Real, 2> points_of(const family_data& d) {
  cb::point_list<Real, 2> p;
  for (const auto& q : d.points) p.emplace_back(Real(q[0]), Real(q[1]));
  return p;
}

template <class Real>
std::vector<Real> knots_of(const family_data& d) {
  return std::vector<Real>(d.knots.begin(), d.knots.end());
}

// Each family's double curve and its real50 twin from the same data, checked by check_bound; a
// looseness limit applies when given (data far from the origin, where the rounding is visible).
// The limits, from the ratios measured on this machine (largest bound / error seen):
//   - polyline 42, B-splines 2.3e3 (order 1 of a degree-1 B-spline: the bound takes the largest
//     |Q^1| of a span's control data, the error is that of the slope where it is sampled);
//   - the cubic engine's families 3.3e3 (order 0, not-a-knot) and 2.2e3 (order 1): the bound holds
//     the worst case of M G's rounding on coordinates 1e4 (|M||G| with M's 3s), which the samples
//     seldom reach;
//   - rational Bezier 6e3 and NURBS 3.6e4 (weights 0.2 to 5): the quotient's bound divides by the
//     smallest weight twice where W is 1 to 5 at most samples (detail/quotient_rounding.hpp).
constexpr double family_looseness = 5000, rational_looseness = 50000;

template <class Make>
void check_family(const Make& make, double looseness) {
  check_bound(make(double{}), make(R{}), looseness > 0, looseness);
}

// A curve of the concept without rounding_bound.
struct plain_line {
  using real_type = double;
  using point_type = pt2<double>;
  static constexpr int dimension = 2;
  std::vector<double> b{0, 1};
  [[nodiscard]] cb::interval<double> domain() const { return {0, 1}; }
  [[nodiscard]] point_type operator()(double u) const { return {u, 2 * u}; }
  [[nodiscard]] point_type derivative(double u, int order) const {
    return order == 0 ? (*this)(u) : order == 1 ? point_type(1, 2) : point_type(0, 0);
  }
  [[nodiscard]] std::span<const double> breakpoints() const { return b; }
};
static_assert(!cb::declares_rounding_bound<plain_line>);
static_assert(cb::declares_rounding_bound<cb::lagrange<double, 2>>);

}  // namespace

// Degree-20 Runge through equispaced nodes (the case runge_lagrange_equispaced): errors of ~2e5 eps
// (value) and ~3e7 eps (P'), measured bound/error ratios 273 and 752. Shifted 1000 along x the
// errors grow 7x to 12x, the bound 16x to 32x (it counts the coordinates twice, in
// sum_j |P_j| max|l_j'| and in Lambda' max|P|): measured 721 and 1801, limited at 3000.
TEST(rounding_bound, lagrange_equispaced_runge) {
  const lagrange_data d = runge(21, false);
  check_bound(build<double>(d), build<R>(d), true);
  const lagrange_data far = runge(21, false, 1000);
  check_bound(build<double>(far), build<R>(far), true, 3000);
}

// Other degrees and Chebyshev nodes (well conditioned): the bound must still hold.
TEST(rounding_bound, lagrange_other_degrees_and_nodes) {
  for (int count : {2, 3, 6, 11, 31, 41}) {
    for (bool cheb : {false, true}) {
      SCOPED_TRACE(std::to_string(count) + (cheb ? " chebyshev" : " equispaced"));
      const lagrange_data d = runge(count, cheb);
      check_bound(build<double>(d), build<R>(d), false);
    }
  }
  const lagrange_data d = runge(81, true, 100);
  check_bound(build<double>(d), build<R>(d), false);
}

// Degree-20 Bezier (the case bezier_degree_20) near and far from the origin: measured ratios
// (bound / error) 5 to 26 on [0, 1], where t = u is exact; on [0.3, 1.7] t rounds and the bound
// adds its term (2L c, c = 3).
TEST(rounding_bound, bezier_degree_20) {
  for (double shift : {0.0, 1000.0}) {
    SCOPED_TRACE("shift " + std::to_string(shift));
    const auto p = spiral(21, 1.5, shift);
    check_bound(bezier_of<double>(p), bezier_of<R>(p), true);
  }
  for (int count : {2, 4, 9, 40, 61}) {
    SCOPED_TRACE(std::to_string(count) + " points");
    const auto p = spiral(count, 2, 0);
    check_bound(bezier_of<double>(p), bezier_of<R>(p), false);
    check_bound(bezier_of<double>(p, 0.3, 1.7), bezier_of<R>(p, 0.3, 1.7), false);
  }
}

// any_curve forwards the bound; a curve that declares none gets 0 (core/curve.hpp).
TEST(rounding_bound, any_curve_forwards_it) {
  const lagrange_data d = runge(21, false);
  const auto c = build<double>(d);
  const cb::any_curve<double, 2> a(c, "lagrange");
  EXPECT_EQ(a.rounding_bound(1), c.rounding_bound(1));
  EXPECT_EQ(a.rounding_bound(0), c.rounding_bound(0));
  const cb::any_curve<double, 2> plain{plain_line{}};
  EXPECT_EQ(plain.rounding_bound(1), 0.0);
}

// The monomial Lagrange has no bound (+inf): every length method then says not_guaranteed with an
// infinite estimate rather than a number its own rounding may exceed.
TEST(rounding_bound, no_bound_means_not_guaranteed) {
  const lagrange_data d = runge(21, false);
  const auto c = build<double>(d, cb::lagrange_algorithm::monomial);
  EXPECT_TRUE(std::isinf(c.rounding_bound(1)));
  const auto expect_none = [](const al::quadrature_result<double>& r, const char* what) {
    EXPECT_EQ(r.status, al::result_status::not_guaranteed) << what;
    EXPECT_TRUE(std::isinf(r.error_estimate)) << what;
  };
  expect_none(al::gauss_length(c, 16, al::fixed_estimate::nested), "gauss");
  expect_none(al::adaptive_length(c), "adaptive");
  al::subdivision_options<double> so;
  so.tolerance = 1e-3;
  so.max_depth = 12;  // the wiggles' noise keeps the chord test failing to depth 40 otherwise
  expect_none(al::subdivision_length(c, so), "subdivision");
  expect_none(al::forward_difference_table<double>(c, 64).length(), "forward difference");
  al::parameterization_options<double> o;
  o.table_intervals = 64;              // not sized automatically: on this noisy curve that doubles to the cap
  o.newton.relative_tolerance = 1e-6;  // at 400 eps its integrals bisect the monomial's noise to depth
  const al::parameterization<cb::lagrange<double, 2>> p(c, o);
  expect_none(p.s_result(0.3), "s(u)");
  EXPECT_EQ(p.invert(0.5 * p.length(), al::inversion_method::newton).status, al::result_status::not_guaranteed);
  EXPECT_EQ(p.invert(0.5 * p.length(), al::inversion_method::hermite_table).status, al::result_status::not_guaranteed);
}

// Polyline: the weights' and the slope's roundings. Measured ratios near 10 far from the origin.
TEST(rounding_bound, polyline) {
  for (double shift : {0.0, 1e4}) {
    SCOPED_TRACE("shift " + std::to_string(shift));
    const family_data d = wavy(12, shift, 3.7);
    check_family(
        [&](auto z) {
          using Real = decltype(z);
          const auto p = points_of<Real>(d);
          const auto k = knots_of<Real>(d);
          return cb::polyline<Real, 2>(std::span<const pt2<Real>>(p), std::span<const Real>(k));
        },
        shift != 0 ? family_looseness : 0);
  }
}

// The cubic engine through hermite_spline (slopes as data: only h * slope, M G and Horner round),
// cardinal / Catmull-Rom with every end (the parabola slopes' rounding), Kochanek-Bartels (the TCB
// weights), and the natural spline with every end condition (the a posteriori slope bound), on
// uniform knots and on knots alternating 1 and 37 (the not-a-knot end rows then amplify the
// residual by (h0 + h1) / h1).
TEST(rounding_bound, cubic_engine_families) {
  for (double shift : {0.0, 1e4}) {
    for (double ratio : {1.0, 37.0}) {
      SCOPED_TRACE("shift " + std::to_string(shift) + ", ratio " + std::to_string(ratio));
      const double visible = shift != 0 ? family_looseness : 0;
      const family_data d = wavy(9, shift, ratio);
      {
        SCOPED_TRACE("hermite");
        check_family(
            [&](auto z) {
              using Real = decltype(z);
              cb::point_list<Real, 2> slopes;
              for (std::size_t i = 0; i < d.points.size(); ++i)
                slopes.emplace_back(Real(std::sin(1.0 * static_cast<double>(i))), Real(0.5));
              return cb::hermite_spline<Real, 2>(knots_of<Real>(d), points_of<Real>(d), slopes);
            },
            visible);
      }
      for (cb::cardinal_end end : {cb::cardinal_end::phantom, cb::cardinal_end::one_sided,
                                   cb::cardinal_end::control_points, cb::cardinal_end::given_tangents}) {
        SCOPED_TRACE(std::string("cardinal ") + cb::to_string(end));
        check_family(
            [&](auto z) {
              using Real = decltype(z);
              typename cb::cardinal_spline<Real, 2>::options o;
              o.s = Real(0.3);
              o.end = end;
              o.start_tangent = pt2<Real>(Real(1), Real(-2));
              return cb::cardinal_spline<Real, 2>(knots_of<Real>(d), points_of<Real>(d), o);
            },
            visible);
      }
      for (bool adjust : {true, false}) {
        SCOPED_TRACE(adjust ? "kochanek_bartels time-adjusted" : "kochanek_bartels");
        check_family(
            [&](auto z) {
              using Real = decltype(z);
              std::vector<cb::tcb<Real>> params;
              for (std::size_t i = 0; i < d.points.size(); ++i)
                params.push_back({Real(0.1 * static_cast<double>(i % 3)), Real(-0.3), Real(0.45)});
              return cb::kochanek_bartels<Real, 2>(knots_of<Real>(d), points_of<Real>(d), params, {false, adjust});
            },
            visible);
      }
      for (cb::spline_end end : {cb::spline_end::natural, cb::spline_end::not_a_knot, cb::spline_end::clamped}) {
        SCOPED_TRACE(std::string("natural_cubic ") + cb::to_string(end));
        check_family(
            [&](auto z) {
              using Real = decltype(z);
              if (end == cb::spline_end::clamped)
                return cb::natural_cubic_spline<Real, 2>(knots_of<Real>(d), points_of<Real>(d),
                                                         pt2<Real>(Real(1), Real(0)), pt2<Real>(Real(0), Real(1)));
              return cb::natural_cubic_spline<Real, 2>(knots_of<Real>(d), points_of<Real>(d), end);
            },
            visible);
      }
    }
  }
  // Closed loops: cardinal and natural periodic.
  family_data loop = wavy(8, 1e4, 2.5);
  loop.points.push_back(loop.points.front());
  loop.knots.push_back(loop.knots.back() + 1.5);
  check_family(
      [&](auto z) {
        using Real = decltype(z);
        return cb::natural_cubic_spline<Real, 2>(knots_of<Real>(loop), points_of<Real>(loop), cb::spline_end::periodic);
      },
      family_looseness);
  family_data open = loop;
  open.points.pop_back();
  check_family(
      [&](auto z) {
        using Real = decltype(z);
        typename cb::cardinal_spline<Real, 2>::options o;
        o.end = cb::cardinal_end::closed;
        return cb::cardinal_spline<Real, 2>(knots_of<Real>(open), points_of<Real>(open), o);
      },
      family_looseness);
}

// B-splines (de Boor) of orders 2 to 6 on clamped uneven knots, and NURBS with weights from 0.2 to 5.
TEST(rounding_bound, bspline_and_nurbs) {
  for (double shift : {0.0, 1e4}) {
    const family_data d = wavy(10, shift);
    for (int order : {2, 3, 4, 6}) {
      SCOPED_TRACE("shift " + std::to_string(shift) + ", order " + std::to_string(order));
      std::vector<double> knots(static_cast<std::size_t>(order), 0.0);
      const int inner = static_cast<int>(d.points.size()) - order;
      for (int i = 1; i <= inner; ++i) knots.push_back(i + 0.6 * ((i % 2) ? 1 : -0.5));
      for (int i = 0; i < order; ++i) knots.push_back(inner + 1);
      check_family(
          [&](auto z) {
            using Real = decltype(z);
            return cb::bspline<Real, 2>(order, std::vector<Real>(knots.begin(), knots.end()), points_of<Real>(d));
          },
          shift != 0 ? family_looseness : 0);
      check_family(
          [&](auto z) {
            using Real = decltype(z);
            std::vector<Real> w;
            for (std::size_t i = 0; i < d.points.size(); ++i)
              w.push_back(Real(i % 3 == 0 ? 5.0 : (i % 3 == 1 ? 0.2 : 1.3)));
            return cb::nurbs<Real, 2>(order, std::vector<Real>(knots.begin(), knots.end()), points_of<Real>(d), w);
          },
          shift != 0 ? rational_looseness : 0);
    }
  }
}

// Rational Bezier (degree 2 to 7, weights 0.25 to 5) and composite Bezier chains.
TEST(rounding_bound, rational_and_composite_bezier) {
  for (double shift : {0.0, 1e4}) {
    for (int count : {3, 5, 8}) {
      SCOPED_TRACE("shift " + std::to_string(shift) + ", points " + std::to_string(count));
      const family_data d = wavy(count, shift);
      check_family(
          [&](auto z) {
            using Real = decltype(z);
            const auto p = points_of<Real>(d);
            std::vector<Real> w;
            for (int i = 0; i < count; ++i) w.push_back(Real(i % 2 == 0 ? 1.0 : (i % 4 == 1 ? 5.0 : 0.25)));
            return cb::rational_bezier<Real, 2>(std::span<const pt2<Real>>(p), std::span<const Real>(w),
                                                cb::interval<Real>{Real(0.25), Real(1.5)});
          },
          shift != 0 ? rational_looseness : 0);
    }
    const family_data d = wavy(10, shift);
    check_family(
        [&](auto z) {
          using Real = decltype(z);
          const auto p = points_of<Real>(d);
          std::vector<cb::point_list<Real, 2>> segs{
              {p[0], p[1], p[2], p[3]}, {p[3], p[4], p[5]}, {p[5], p[6], p[7], p[8], p[9]}};
          const std::vector<Real> k{Real(0), Real(0.7), Real(2), Real(2.3)};
          return cb::composite_bezier<Real, 2>(std::span<const cb::point_list<Real, 2>>(segs),
                                               std::span<const Real>(k));
        },
        shift != 0 ? family_looseness : 0);
  }
}

// A conic whose three points coincide (length 0; the case the fuzz target found): the bound on P'
// still holds where P' is rounding noise.
TEST(rounding_bound, zero_length_conic) {
  const family_data d{{{1.5, -2}, {1.5, -2}, {1.5, -2}}, {}};
  check_family(
      [&](auto z) {
        using Real = decltype(z);
        const auto p = points_of<Real>(d);
        const std::vector<Real> w{Real(1), Real(5), Real(1)};
        return cb::rational_bezier<Real, 2>(std::span<const pt2<Real>>(p), std::span<const Real>(w));
      },
      0);
}

// A domain far from 0: each quadrature node u is placed within eps |u| of where its rule puts it,
// which on [1e15, 1e15 + 1e5] is 1e-6 of the curve. The Gauss and Kronrod values share those nodes,
// so their difference does not show it; adaptive_length returned an estimate of 8.3e-8 for an error
// of 6.4e-7 here (found by a hostile sweep). Every bounded estimate of every length method must
// cover its error against the 50-digit length of the same curve (no margin: it is a bound).
TEST(rounding_bound, far_domain_length_estimates_hold) {
  const std::vector<pt2<double>> cps{{0, 0}, {1, 2}, {3, 2}, {4, 0}};
  const std::vector<pt2<R>> cps50{{R(0), R(0)}, {R(1), R(2)}, {R(3), R(2)}, {R(4), R(0)}};
  const cb::bezier<R, 2> exact50{std::span<const pt2<R>>(cps50)};
  const double exact = static_cast<double>(al::adaptive_length(exact50).value);
  for (const auto& [lo, hi] : {std::pair{-1e15, -0.9999999999e15}, std::pair{1e20, 1e20 + 1e10},
                               std::pair{1e8, 1e8 + 1}, std::pair{0.0, 1.0}}) {
    SCOPED_TRACE("domain [" + cb::to_text(lo) + ", " + cb::to_text(hi) + "]");
    const cb::bezier<double, 2> c(std::span<const pt2<double>>(cps), {lo, hi});
    const auto expect_bound = [&](const al::quadrature_result<double>& r, const std::string& what) {
      if (r.status == al::result_status::not_guaranteed) return;
      EXPECT_LE(std::abs(r.value - exact), r.error_estimate)
          << what << ": " << cb::to_text(r.value) << " status " << al::to_string(r.status);
    };
    for (double tol : {1e-6, 1e-10, 1e-14}) {
      al::adaptive_options<double> o;
      o.relative_tolerance = tol;
      expect_bound(al::adaptive_length(c, o), "adaptive tol " + cb::to_text(tol));
      o.model = al::error_model::quadpack;
      expect_bound(al::adaptive_length(c, o), "adaptive quadpack tol " + cb::to_text(tol));
      al::subdivision_options<double> so;
      so.tolerance = tol;
      expect_bound(al::subdivision_length(c, so), "subdivision tol " + cb::to_text(tol));
    }
    for (int n : {5, 12, 24})
      expect_bound(al::gauss_length(c, n, al::fixed_estimate::nested), "gauss " + std::to_string(n));
    const auto rec = al::integrate_recursive([&](double u) { return al::speed(c, u); }, lo, hi, 1e-12 * exact,
                                             al::gauss_kronrod<double>(7));
    expect_bound(rec, "recursive Gauss-Kronrod");
  }
}

// Speeds in the subnormal range: coordinates of 1e-21 over a domain of width 1e294 give |P'| ~
// 1e-315, rounded to an absolute denorm_min / 2 per operation, which the curves' relative bounds
// do not hold. Found by a sweep: adaptive_gk at tol 1e-6 said converged with 5.6e-28 for an error
// of 1.3e-27. underflow_floor (core/curve.hpp) makes every bounded estimate cover it.
TEST(rounding_bound, subnormal_speeds_are_bounded) {
  const std::vector<double> x{2.813333840141927e-21, 8.195890247332922e-21, -8.219377760162278e-21,
                              2.4438919018548067e-21};
  std::vector<cb::point<double, 1>> p;
  std::vector<cb::point<R, 1>> p50;
  for (double v : x) {
    p.emplace_back(v);
    p50.emplace_back(R(v));
  }
  const cb::bezier<double, 1> c{std::span<const cb::point<double, 1>>(p), {1e300, 1.000001e300}};
  const cb::bezier<R, 1> c50{std::span<const cb::point<R, 1>>(p50)};
  const double exact = static_cast<double>(al::adaptive_length(c50).value);
  for (double tol : {1e-4, 1e-6, 1e-10}) {
    al::adaptive_options<double> o;
    o.relative_tolerance = tol;
    const al::quadrature_result<double> r = al::adaptive_length(c, o);
    EXPECT_NE(r.status, al::result_status::not_guaranteed);
    EXPECT_LE(std::abs(r.value - exact), r.error_estimate) << tol;
  }
  EXPECT_EQ(cb::declared_rounding_bound(c, 1), c.rounding_bound(1));
  EXPECT_GT(cb::rounding_bound(c, 1), c.rounding_bound(1));  // the floor added on top
}
