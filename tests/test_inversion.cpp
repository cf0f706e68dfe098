// Arc-length inversion and reparameterization: Newton inversion in a bracket, the
// parameterization object's s(u), u(s) by table + linear, table + cubic Hermite (with and without
// the Newton polish) and Newton, constant-speed sampling, monotonicity, degenerate curves and bad
// input. Curves with closed-form s(u) (circle, helix, lines with non-uniform parameterization)
// give exact references; the others are checked by round trips.
#include "support/accuracy.hpp"

#include "curvebench/arclength/newton_inversion.hpp"
#include "curvebench/arclength/parameterization.hpp"
#include "curvebench/curves/bezier.hpp"
#include "curvebench/curves/cardinal_spline.hpp"
#include "curvebench/curves/piecewise_cubic.hpp"
#include "curvebench/curves/rational_bezier.hpp"
#include "curvebench/reference/analytic_curves.hpp"
#include "curvebench/reference/arc_length.hpp"

#include <gmock/gmock.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <vector>

namespace cb = curvebench;
namespace al = curvebench::arclength;
namespace ref = curvebench::reference;
namespace cbt = curvebench::testing;
using ::testing::HasSubstr;

namespace {

// Tolerances, in eps(Real) relative to the total length L:
// - Newton converges when |s(u) - s*| + bound <= 400 eps L (its default), so 400 is the honest
//   limit a test may assert (it stops as soon as the bound is met: float lands at ~300 eps);
// - the Hermite table is built until the measured midpoint error of the coarser table is
//   <= max(32 eps, 1e-15) L; the kept table is finer. Queries are checked against 64 eps L, and
//   for float (where 32 eps is reached with a small table) against the same number of eps;
// - linear table: O(ds^2) with ds = L / M; checked against the measured-size bound
//   |u''| ds^2 / 8 * |P'| (per curve below) rather than in eps.
constexpr double newton_tolerance_eps = 400;
constexpr double hermite_tolerance_eps = 64;
// - suite round trips against the 50-digit reference: Newton within its tolerance (400 eps L);
//   the auto-sized Hermite table within max(measured table error, its target) + the Newton
//   tolerance of its nodes (the same bound the motion layer uses); a linear table of M intervals
//   within ds^2 max|u''| max|P'| / 8, which is below 1e-5 L for M = 4096 on the one-segment smooth
//   curves; at cusps and corners u'' is unbounded and on the long spline ds spans many segments,
//   so there only monotonicity is asserted.
constexpr double linear_4096_rel = 1e-5;

template <class Real>
class inversion_test : public ::testing::Test {};
TYPED_TEST_SUITE(inversion_test, cbt::ieee_reals);

// A line traversed with non-uniform speed: P(u) = d (u + u^2) on [0, 1], s(u) = |d| (u + u^2).
template <class Real>
ref::piecewise_polynomial<Real, 2> accelerating_line() {
  return {Real(0), Real(1), {cb::point<Real, 2>(0, 0), cb::point<Real, 2>(3, 4), cb::point<Real, 2>(3, 4)}};
}

using R = cb::real50;
template <class Real>
using pt2 = cb::point<Real, 2>;
template <class Real>
using poly2 = ref::piecewise_polynomial<Real, 2>;

// Suite curves (dyadic data, the same in double and real50): see tests/test_arclength.cpp.
template <class Real>
poly2<Real> smooth_cubic() {
  return {Real(0), Real(1), {pt2<Real>(0, 0), pt2<Real>(1, 2), pt2<Real>(3, Real(-1)), pt2<Real>(Real(-2), Real(0.5))}};
}
template <class Real>
poly2<Real> cusp_cubic(double eps) {  // (x^2 + eps x, x^3), x = u - 3/4, on [0, 2]
  const Real e(eps);
  return {Real(0),
          Real(2),
          {pt2<Real>(Real(0.5625) - Real(0.75) * e, Real(-0.421875)), pt2<Real>(e - Real(1.5), Real(1.6875)),
           pt2<Real>(1, Real(-2.25)), pt2<Real>(0, 1)}};
}
template <class Real>
poly2<Real> with_zero_segment() {  // the middle segment [1, 1.5] is a point: speed 0 on an interval
  return {std::vector<Real>{Real(0), Real(1), Real(1.5), Real(2.5)},
          {{pt2<Real>(0, 0), pt2<Real>(1, 1), pt2<Real>(Real(0.5), Real(-0.5))},
           {pt2<Real>(Real(1.5), Real(0.5))},
           {pt2<Real>(Real(1.5), Real(0.5)), pt2<Real>(1, 0), pt2<Real>(0, Real(0.25))}}};
}
template <class Real>
cb::bezier<Real, 2> looping_bezier() {
  const std::vector<pt2<Real>> cps{pt2<Real>(0, 0), pt2<Real>(3, 3), pt2<Real>(-1, 3), pt2<Real>(2, 0)};
  return cb::bezier<Real, 2>(std::span<const pt2<Real>>(cps));
}
template <class Real>
cb::piecewise_cubic<Real, 2> long_spline() {  // 100 Hermite segments, Catmull-Rom slopes
  const std::size_t n = 100;
  std::vector<Real> knots(n + 1);
  std::vector<pt2<Real>> v(n + 1), slope(n + 1);
  for (std::size_t i = 0; i <= n; ++i) {
    knots[i] = Real(static_cast<long long>(i));
    v[i] = pt2<Real>(Real(static_cast<long long>(i)) / Real(4), Real(static_cast<long long>((i * 37) % 16)) / Real(8));
  }
  for (std::size_t i = 0; i <= n; ++i) {
    const std::size_t a = i == 0 ? 0 : i - 1, b = i == n ? n : i + 1;
    slope[i] = (v[b] - v[a]) / Real(static_cast<long long>(b - a));
  }
  return cb::piecewise_cubic<Real, 2>::from_hermite(knots, v, slope, slope);
}

// Round trips of every method against the reference on one curve.
template <class C, class C50>
void check_round_trips(const char* name, const C& c, const C50& c50, bool cusp, bool smooth) {
  SCOPED_TRACE(name);
  const ref::reference_arc_length<C50> r(c50);
  const double L = static_cast<double>(r.length());
  const al::parameterization<C> newton(c, [] {
    al::parameterization_options<double> o;
    o.method = al::inversion_method::newton;
    return o;
  }());
  const al::parameterization<C> hermite(c);
  const al::parameterization<C> linear(c, [] {
    al::parameterization_options<double> o;
    o.method = al::inversion_method::linear_table;
    o.table_intervals = 4096;
    return o;
  }());
  EXPECT_TRUE(cbt::within_relative(newton.length(), r.length(), 200 * cb::epsilon<double>()));
  EXPECT_EQ(linear.table_status(), al::result_status::not_guaranteed);  // size given: not measured
  EXPECT_EQ(linear.table_reason().what, al::reasons::table_size_given);
  const double newton_bound = newton.options().newton.relative_tolerance * L;
  const double hermite_bound = std::max(hermite.table_error(), hermite.options().table_tolerance * L) + newton_bound;
  double prev_h = -1, prev_l = -1;
  for (int k = 0; k <= 32; ++k) {  // 33 targets: each costs three 50-digit reference integrals
    const double s = k == 32 ? newton.length() : L * (k + 0.3183) / 32.5;
    const al::inversion_result<double> rn = newton.invert(s, al::inversion_method::newton);
    // At an exact cusp s(u) - s* ~ (u - u_c)^2: the bracket may collapse in double before the bound
    // is met; the method then says rounding_limited (honest), and its estimate still bounds the error.
    if (cusp) {
      EXPECT_TRUE(rn.converged() || rn.status == al::result_status::rounding_limited) << "k=" << k;
      EXPECT_LE(abs(r.s(R(rn.u)) - R(s)), R(rn.s_error_estimate) + R(newton_bound)) << "newton k=" << k;
    } else {
      EXPECT_TRUE(rn.converged()) << "k=" << k << " " << al::to_string(rn.status);
      EXPECT_LE(abs(r.s(R(rn.u)) - R(s)), R(newton_bound)) << "newton k=" << k;
    }
    const double uh = hermite.u(s);
    EXPECT_LE(abs(r.s(R(uh)) - R(s)), R(hermite_bound)) << "hermite k=" << k;
    const double ul = linear.u(s);
    if (smooth) {
      EXPECT_LE(abs(r.s(R(ul)) - R(s)), R(linear_4096_rel * L)) << "linear k=" << k;
    }
    EXPECT_GE(uh, prev_h);  // monotone u(s)
    EXPECT_GE(ul, prev_l);
    prev_h = uh;
    prev_l = ul;
  }
  // u(s(u)) = u where the speed is not small (elsewhere u is ill-conditioned in s)
  const auto dom = c.domain();
  for (int k = 1; k < 32; ++k) {
    const double u = dom.lo + (dom.hi - dom.lo) * k / 32.0;
    const double sp = al::speed(c, u);
    if (sp < 1e-3 * L / (dom.hi - dom.lo)) continue;
    const double back = newton.u(newton.s(u));
    EXPECT_LE(std::abs(back - u), 4 * newton_bound / sp) << "u=" << u;
  }
  // Constant-speed samples are equally spaced in true arc length.
  const std::vector<double> us = hermite.constant_speed_parameters(17);
  for (std::size_t i = 0; i < us.size(); ++i)
    EXPECT_LE(abs(r.s(R(us[i])) - R(hermite.length()) * R(static_cast<double>(i)) / 16),
              R(hermite_bound) + R(L) * R(1e-15))
        << "sample " << i;
}

}  // namespace

static_assert(cb::curve<ref::piecewise_polynomial<double, 2>>);
static_assert(cb::curve<ref::circle<cb::real50>>);

TYPED_TEST(inversion_test, newton_inverts_closed_form_s) {
  using Real = TypeParam;
  const auto line = accelerating_line<Real>();
  const al::segment_lengths<Real> seg(line);
  EXPECT_TRUE(cbt::within_ulps(seg.length(), cb::real50(10), 64));
  for (int k = 0; k <= 20; ++k) {
    const Real s = seg.length() * Real(k) / Real(20);
    const al::inversion_result<Real> r = al::newton_invert(line, seg, s);
    ASSERT_TRUE(r.converged()) << al::to_string(r.status);
    // exact: 5 (u + u^2) = s  =>  u = (-1 + sqrt(1 + 4 s / 5)) / 2
    const cb::real50 s50(s);
    const cb::real50 exact_u = (sqrt(cb::real50(1) + 4 * s50 / 5) - 1) / 2;
    const cb::real50 s_of_u = 5 * (cb::real50(r.u) + cb::real50(r.u) * cb::real50(r.u));
    EXPECT_TRUE(cbt::within_scaled_ulps(Real(s_of_u), s50, cb::real50(10), newton_tolerance_eps)) << "k=" << k;
    EXPECT_LE(cb::real50(r.s_error_estimate), cb::real50(newton_tolerance_eps) * 10 * cb::real50(cb::epsilon<Real>()));
    (void)exact_u;
  }
}

TYPED_TEST(inversion_test, parameterization_round_trips_every_method) {
  using Real = TypeParam;
  const ref::circle<Real> c(Real(2), Real(3), Real(1) / Real(5), Real(0), Real(1));
  const al::parameterization<ref::circle<Real>> p(c);
  const Real len = p.length();  // 6 = r w (u1 - u0), within the tolerance checked next
  EXPECT_TRUE(cbt::within_ulps(p.length(), cb::real50(6), 64));
  for (auto m : {al::inversion_method::hermite_table, al::inversion_method::newton}) {
    for (int k = 0; k <= 50; ++k) {
      const Real s = len * Real(k) / Real(50);
      const Real u = p.u(s, m);
      // s(u) = 6 u exactly for this circle
      EXPECT_TRUE(cbt::within_scaled_ulps(Real(6) * u, cb::real50(s), cb::real50(6), hermite_tolerance_eps))
          << "k=" << k << " method=" << static_cast<int>(m);
      EXPECT_TRUE(cbt::within_scaled_ulps(p.s(u), cb::real50(6) * cb::real50(u), cb::real50(6), 64));
    }
  }
}

TYPED_TEST(inversion_test, bad_input_is_rejected_with_clear_messages) {
  using Real = TypeParam;
  const auto line = accelerating_line<Real>();
  const al::parameterization<ref::piecewise_polynomial<Real, 2>> p(line);
  try {
    (void)p.u(Real(11));
    FAIL();
  } catch (const std::domain_error& e) {
    EXPECT_THAT(e.what(), HasSubstr("is outside the arc-length range [0, "));
  }
  EXPECT_THROW((void)p.u(std::numeric_limits<Real>::quiet_NaN()), std::domain_error);
  EXPECT_THROW((void)p.s(Real(2)), std::domain_error);
  const ref::piecewise_polynomial<Real, 2> point_curve(Real(0), Real(1), {cb::point<Real, 2>(1, 1)});
  try {
    al::parameterization<ref::piecewise_polynomial<Real, 2>> bad(point_curve);
    FAIL();
  } catch (const cb::invalid_input& e) {
    EXPECT_THAT(e.what(),
                HasSubstr("curve length = 0: an arc-length parameterization needs a curve of positive length"));
  }
  al::parameterization_options<Real> opt;
  opt.newton.relative_tolerance = Real(0);
  try {
    al::parameterization<ref::piecewise_polynomial<Real, 2>> bad(line, opt);
    FAIL();
  } catch (const cb::invalid_input& e) {
    EXPECT_STREQ(e.what(), "relative_tolerance = 0: must be > 0");
  }
}

TEST(inversion, suite_round_trips_against_the_reference) {
  check_round_trips("smooth cubic", smooth_cubic<double>(), smooth_cubic<R>(), false, true);
  check_round_trips("loop", looping_bezier<double>(), looping_bezier<R>(), false, true);
  check_round_trips("near cusp", cusp_cubic<double>(1.0 / 1024), cusp_cubic<R>(1.0 / 1024), true, false);
  check_round_trips("exact cusp", cusp_cubic<double>(0), cusp_cubic<R>(0), true, false);
  check_round_trips("zero-length segment", with_zero_segment<double>(), with_zero_segment<R>(), false, false);
  check_round_trips("100-segment spline", long_spline<double>(), long_spline<R>(), false, false);
}

TEST(inversion, speed_zero_on_an_interval_inverts_by_bisection) {
  // The middle segment [1, 1.5] is a single point: s is constant there. Any u in it is a correct
  // answer for that s; nearby targets must converge (the bisection path handles |P'| = 0).
  const auto c = with_zero_segment<double>();
  const al::segment_lengths<double> seg(c);
  const double plateau = seg.cumulative()[1];
  EXPECT_EQ(seg.cumulative()[2], plateau);
  for (double ds : {-1e-9, 0.0, 1e-9}) {
    const auto r = al::newton_invert(c, seg, plateau + ds);
    EXPECT_TRUE(r.converged()) << ds;
    if (ds < 0) {
      EXPECT_LT(r.u, 1.0);
    } else if (ds > 0) {
      EXPECT_GT(r.u, 1.5);
    } else {
      EXPECT_TRUE(r.u >= 1.0 && r.u <= 1.5);
    }
  }
  // A target inside a segment whose speed is zero at an interior point (exact cusp): bracket +
  // bisection converge on both sides of the cusp.
  const auto cusp = cusp_cubic<double>(0);
  const al::segment_lengths<double> cs(cusp);
  const double s_cusp = al::adaptive_length(cusp, 0.0, 0.75).value;
  for (double ds : {-1e-12, 0.0, 1e-12}) {
    const auto r = al::newton_invert(cusp, cs, s_cusp + ds);
    EXPECT_TRUE(r.converged()) << ds;
    EXPECT_NEAR(r.u, 0.75, 1e-5);  // s - s_cusp ~ |u - 3/4|^2: u is only determined to ~sqrt(tolerance)
  }
}

TEST(inversion, table_methods_need_a_table_and_report_status) {
  const auto c = smooth_cubic<double>();
  al::parameterization_options<double> o;
  o.method = al::inversion_method::newton;
  const al::parameterization<poly2<double>> p(c, o);
  EXPECT_EQ(p.table_intervals(), 0u);
  EXPECT_THROW((void)p.u(0.5, al::inversion_method::hermite_table), std::logic_error);
  const al::parameterization<poly2<double>> h(c);
  // Grown by doubling: converged (measured error <= target) or stopped at the size cap, never unmeasured.
  EXPECT_NE(h.table_status(), al::result_status::not_guaranteed);
  EXPECT_TRUE(std::isfinite(h.table_error()));
  if (h.table_status() == al::result_status::converged) {
    EXPECT_LE(h.table_error(), h.options().table_tolerance * h.length());
  }
  const auto r = h.invert(1.0, al::inversion_method::hermite_table);
  EXPECT_TRUE(r.converged());
  EXPECT_GT(r.evaluations, 0u);
  al::parameterization_options<double> capped;
  capped.max_table_intervals = 32;
  const al::parameterization<poly2<double>> small(c, capped);
  EXPECT_EQ(small.table_status(), al::result_status::cap_hit);
  EXPECT_LE(small.table_intervals(), 32u);
  EXPECT_THROW((void)h.constant_speed_parameters(1), cb::invalid_input);
}

// A winding road through 1001 points (turning at random by up to 0.6 rad per key, steps of 0.5 to
// 3): the many-segment centripetal Catmull-Rom, in Real.
template <class Real>
cb::cardinal_spline<Real, 2> road(int keys) {
  cb::point_list<Real, 2> pts;
  double x = 0, y = 0, heading = 0;
  std::uint64_t state = 32;
  auto uniform = [&state](double lo, double hi) {  // a fixed LCG: the same road on every platform
    state = state * 6364136223846793005ULL + 1442695040888963407ULL;
    return lo + (hi - lo) * static_cast<double>(state >> 11) / 9007199254740992.0;
  };
  for (int k = 0; k < keys; ++k) {
    pts.push_back(pt2<Real>(x, y));
    heading += uniform(-0.6, 0.6);
    const double step = uniform(0.5, 3.0);
    x += step * std::cos(heading);
    y += step * std::sin(heading);
  }
  typename cb::cardinal_spline<Real, 2>::options o;
  o.alpha = Real(0.5);
  return cb::cardinal_spline<Real, 2>(pts, o);
}

// The sized tables of the many-segment tests: Hermite to 1e-12 L, linear to 1e-8 L.
al::parameterization<cb::cardinal_spline<double, 2>> sized_table(const cb::cardinal_spline<double, 2>& c,
                                                                 al::inversion_method method) {
  al::parameterization_options<double> o;
  o.method = method;
  o.table_tolerance = method == al::inversion_method::hermite_table ? 1e-12 : 1e-8;
  return al::parameterization<cb::cardinal_spline<double, 2>>(c, o);
}

// On 1000 segments a table whose size was global stalled (M = 16 to 256: 7e-7 L; the
// automatic size stopped at its cap of 65536 cells, 2.2e-10 L). Sized per segment, best first, the
// Hermite table reaches the target of 1e-12 L, its measured error bounds the 50-digit error at 400
// targets (a quarter of them next to knots), and the linear table reaches 1e-8 L the same way.
// Tolerances: the table's own bound plus its nodes' Newton tolerance (newton_tolerance_eps eps L),
// as the round-trip tests take it.
TEST(inversion, many_segment_tables_are_sized_per_segment) {
  const auto c = road<double>(1001);
  const ref::reference_arc_length<cb::cardinal_spline<R, 2>> r(road<R>(1001));
  const auto cum_segments = al::segment_lengths<double>(c);
  for (const auto method : {al::inversion_method::hermite_table, al::inversion_method::linear_table}) {
    const bool hermite = method == al::inversion_method::hermite_table;
    SCOPED_TRACE(hermite ? "hermite_table" : "linear_table");
    const auto p = sized_table(c, method);
    const auto& o = p.options();
    EXPECT_EQ(p.table_status(), al::result_status::converged);
    EXPECT_TRUE(p.table_reason().empty());
    EXPECT_LE(p.table_error(), o.table_tolerance * p.length());
    EXPECT_GE(p.table_intervals(), 1000u);  // at least one cell per segment
    const auto cum = cum_segments.cumulative();
    R worst(0);
    for (int k = 0; k < 400; ++k) {
      double s = p.length() * std::fmod(k * 0.6180339887498949, 1.0);
      if (k % 4 == 0) s = std::min(p.length(), cum[static_cast<std::size_t>(k / 4 * 2 + 1)] + (k % 8 ? 1e-9 : -1e-9));
      worst = std::max(worst, R(abs(r.s(R(p.u(s, method))) - R(s))));
    }
    const R bound = R(p.table_error()) + R(newton_tolerance_eps * std::numeric_limits<double>::epsilon()) * r.length();
    EXPECT_LE(worst, bound) << "the table's bound does not cover its error";
    EXPECT_LE(worst / r.length(), R(o.table_tolerance));
    std::printf("[%s] 1000 segments: %zu cells, measured %.3g L, 50-digit %.3g L, %zu evaluations\n",
                hermite ? "hermite" : "linear", p.table_intervals(), p.table_error() / p.length(),
                static_cast<double>(worst / r.length()), p.construction_evaluations());
  }
}

// On a table of many segments the query reads two copies of cells chosen by the
// bucket of s and checks that the one it takes holds s, falling back to bisection where a bucket
// meets more than two cells. A road of 300 unit steps with one step of 1e-3 and a bump: its cells
// range from 3e-2 to 8e-6 wide (the segments next to the short step are refined far more than the
// others, so most buckets there meet many cells). At 5000 table nodes (a cell's end is the next
// cell's start), the doubles on either side of each and the middle of the cell after it, u(s) must
// have s(u) within the table's bound of s, and u must not decrease with s. A wrong cell is off by
// up to a cell's width (2.6e-8 L at the narrowest), far beyond the bound (1e-12 L); s(u) is
// integrated from the nearest table node, not read from the table.
TEST(inversion, table_lookup_finds_the_cell_of_every_s_on_unequal_cells) {
  cb::point_list<double, 2> pts;
  double x = 0;
  for (int k = 0; k < 301; ++k) {
    pts.push_back(pt2<double>(x, k == 200 ? 0.8 : 0.0));
    x += k == 100 ? 1e-3 : 1.0;
  }
  cb::cardinal_spline<double, 2>::options co;
  co.alpha = 0.5;
  const cb::cardinal_spline<double, 2> c(pts, co);
  for (const auto method : {al::inversion_method::hermite_table, al::inversion_method::linear_table}) {
    const bool hermite = method == al::inversion_method::hermite_table;
    SCOPED_TRACE(hermite ? "hermite_table" : "linear_table");
    const auto p = sized_table(c, method);
    ASSERT_EQ(p.table_status(), al::result_status::converged);
    const double L = p.length();
    const auto nodes = p.table_parameters();
    std::vector<double> s;
    const std::size_t stride = nodes.size() / 5000 + 1;
    for (std::size_t j = 0; j < nodes.size(); j += stride) {
      const double sj = p.s(nodes[j]);
      s.insert(s.end(), {sj, std::nextafter(sj, -1.0), std::nextafter(sj, 2 * L)});
      if (j + 1 < nodes.size()) s.push_back((sj + p.s(nodes[j + 1])) / 2);
    }
    for (double& v : s) v = std::clamp(v, 0.0, L);
    std::sort(s.begin(), s.end());
    double worst = 0, previous = -1;
    std::size_t decreasing = 0;
    for (const double v : s) {
      const double u = p.u(v, method);
      const auto back = p.s_result(u);
      worst = std::max(worst, std::abs(back.value - v) - back.error_estimate);
      decreasing += u < previous;
      previous = u;
    }
    EXPECT_EQ(decreasing, 0u);
    const double bound = p.table_error() + newton_tolerance_eps * std::numeric_limits<double>::epsilon() * L;
    EXPECT_LE(worst, bound) << s.size() << " targets on " << p.table_intervals() << " cells";
  }
}

// Bounded work: the table's construction budget. At 4000 evaluations the smooth cubic
// (16 nodes ~ 700 evaluations, 32 nodes ~ 1300) affords one doubling but not the next: the table
// stops measured, cap_hit, its error bound finite, and every u(s) is within that bound plus the
// Newton tolerance of its nodes (the bound the round-trip suite uses), checked against 50 digits.
// With a cap of one cell no finer table measures the first: not_guaranteed, no bound.
TEST(inversion, table_construction_budget_ends_in_cap_hit_with_an_honest_bound) {
  const auto c = smooth_cubic<double>();
  const ref::reference_arc_length<poly2<R>> r(smooth_cubic<R>());
  const al::parameterization<poly2<double>> full(c);
  al::parameterization_options<double> o;
  o.max_evaluations = 4000;
  const al::parameterization<poly2<double>> capped(c, o);
  EXPECT_EQ(capped.table_status(), al::result_status::cap_hit);
  // The reason names the cap and the segment with the worst measured error (the only one).
  EXPECT_EQ(capped.table_reason().what, al::reasons::table_cap);
  EXPECT_EQ(capped.table_reason().segment, 0u);
  EXPECT_LT(capped.table_intervals(), full.table_intervals());
  // Each node gets at least min_node_evaluations, so the budget is passed by at most that per node.
  EXPECT_LE(capped.construction_evaluations(), o.max_evaluations + al::min_node_evaluations * capped.table_intervals());
  ASSERT_TRUE(std::isfinite(capped.table_error()));
  const R bound =
      R(capped.table_error()) + R(newton_tolerance_eps * std::numeric_limits<double>::epsilon()) * r.length();
  R worst(0);
  for (int k = 0; k <= 200; ++k) {
    const double s = capped.length() * k / 200;
    worst = std::max(worst, R(abs(r.s(R(capped.u(s))) - R(s))));
  }
  EXPECT_LE(worst, bound) << "the table's bound does not cover its error";
  EXPECT_GT(worst, R(full.table_error()));  // the capped table is coarser than the full one
  // Smaller budgets: each table is measured (a finite bound that covers its error) or says it has
  // no bound. (The size is per segment: even at 60 evaluations one cell, halved once
  // with a node given min_node_evaluations, is measured.)
  for (std::size_t budget : {60u, 100u, 150u, 200u, 300u}) {
    o.max_evaluations = budget;
    const al::parameterization<poly2<double>> starved(c, o);
    SCOPED_TRACE(budget);
    if (starved.table_status() == al::result_status::not_guaranteed) {
      EXPECT_FALSE(std::isfinite(starved.table_error()));
      continue;
    }
    ASSERT_TRUE(std::isfinite(starved.table_error()));
    R err(0);
    for (int k = 0; k <= 200; ++k) {
      const double s = starved.length() * k / 200;
      err = std::max(err, R(abs(r.s(R(starved.u(s))) - R(s))));
    }
    EXPECT_LE(err,
              R(starved.table_error()) + R(newton_tolerance_eps * std::numeric_limits<double>::epsilon()) * r.length());
  }
  // A cap of one cell: the segment's one cell cannot be halved to measure it, no bound.
  o.max_evaluations = al::parameterization_options<double>{}.max_evaluations;
  o.max_table_intervals = 1;
  const al::parameterization<poly2<double>> unmeasured(c, o);
  EXPECT_EQ(unmeasured.table_intervals(), 1u);
  EXPECT_EQ(unmeasured.table_status(), al::result_status::not_guaranteed);
  EXPECT_EQ(unmeasured.table_reason().what, al::reasons::table_unmeasured);
  EXPECT_EQ(unmeasured.table_reason().segment, 0u);
  EXPECT_FALSE(std::isfinite(unmeasured.table_error()));
}

// Newton's budget: 40 evaluations allow one long step (31 + 1 speed) and one panel more; the solve
// ends in cap_hit with the best iterate, and its bound still covers the true |s(u) - s|.
TEST(inversion, newton_budget_ends_in_cap_hit_with_an_honest_bound) {
  const auto c = looping_bezier<double>();
  const al::segment_lengths<double> seg(c);
  const ref::reference_arc_length<cb::bezier<R, 2>> r(looping_bezier<R>());
  al::newton_options<double> opt;
  opt.max_evaluations = 40;
  for (int k = 1; k < 8; ++k) {
    const double s = seg.length() * k / 8;
    const auto inv = al::newton_invert(c, seg, s, opt);
    EXPECT_EQ(inv.status, al::result_status::cap_hit) << "s = " << s;
    EXPECT_EQ(inv.reason.what, al::reasons::newton_cap) << "s = " << s;  // it says why
    EXPECT_LE(inv.evaluations, opt.max_evaluations + 31u);               // the first panel of a call is always computed
    ASSERT_TRUE(std::isfinite(inv.s_error_estimate));
    EXPECT_LE(abs(r.s(R(inv.u)) - R(s)), R(inv.s_error_estimate)) << "s = " << s;
  }
  const auto free = al::newton_invert(c, seg, seg.length() / 3, {});
  EXPECT_TRUE(free.converged());
  EXPECT_GT(free.evaluations, 40u);  // the default solve needs more than the capped one got
}

// The length prefix (segment_lengths with prefix panels, what parameterization's newton method
// builds): every prefix point's bound covers its true arc length (50-digit reference), the brackets
// it gives hold s, and Newton from them converges with a bound that covers the true |s(u) - s| on
// the suite curves, in fewer evaluations than from the whole segment on the smooth ones.
template <class C, class C50>
void check_prefix(const char* name, const C& c, const C50& c50, bool cusp) {
  SCOPED_TRACE(name);
  const ref::reference_arc_length<C50> r(c50);
  const auto opt = al::segment_lengths<double>::default_options();
  const al::segment_lengths<double> plain(c);
  const al::segment_lengths<double> seg(c, opt, al::segment_lengths<double>::newton_prefix_panels);
  EXPECT_EQ(seg.prefix_panels(), al::segment_lengths<double>::newton_prefix_panels);
  EXPECT_GT(seg.prefix_evaluations(), 0u);
  // The prefix leaves the segments' own lengths alone.
  for (std::size_t i = 0; i < seg.cumulative().size(); ++i) EXPECT_EQ(seg.cumulative()[i], plain.cumulative()[i]);
  std::size_t points = 0;
  for (std::size_t i = 0; i < seg.segment_count(); ++i) {
    const auto us = seg.prefix_parameters(i), ss = seg.prefix_lengths(i), es = seg.prefix_errors(i);
    ASSERT_EQ(us.size(), ss.size());
    ASSERT_EQ(us.size(), es.size());
    for (std::size_t k = 0; k < us.size(); ++k) {
      ++points;
      EXPECT_TRUE(us[k] > seg.parameters()[i] && us[k] < seg.parameters()[i + 1]);
      EXPECT_TRUE(ss[k] > seg.cumulative()[i] && ss[k] < seg.cumulative()[i + 1]);
      if (k > 0) {
        EXPECT_GT(ss[k], ss[k - 1]);
      }
      EXPECT_LE(abs(r.s(R(us[k])) - R(ss[k])), R(es[k])) << "segment " << i << " point " << k;
    }
  }
  EXPECT_GT(points, 0u);
  const double L = seg.length();
  const double tol = al::newton_options<double>{}.relative_tolerance * L;
  std::size_t with = 0, without = 0;
  for (int k = 0; k <= 24; ++k) {
    const double s = k == 24 ? L : L * (k + 0.3183) / 24.5;
    const auto br = seg.bracket(s);
    EXPECT_TRUE(br.s_lo <= s && s <= br.s_hi) << "k=" << k;
    EXPECT_TRUE(br.u_lo <= br.u_hi);
    const auto rn = al::newton_invert(c, seg, s);
    const auto rp = al::newton_invert(c, plain, s);
    with += rn.evaluations;
    without += rp.evaluations;
    if (cusp) {
      EXPECT_TRUE(rn.converged() || rn.status == al::result_status::rounding_limited) << "k=" << k;
    } else {
      EXPECT_TRUE(rn.converged()) << "k=" << k << " " << al::to_string(rn.status);
      EXPECT_LE(rn.s_error_estimate, tol);
    }
    EXPECT_LE(abs(r.s(R(rn.u)) - R(s)), R(rn.s_error_estimate)) << "k=" << k;
  }
  if (!cusp) {
    EXPECT_LT(with, without);
  }
}

TEST(inversion, length_prefix_bounds_hold_and_newton_from_it_converges) {
  check_prefix("smooth cubic", smooth_cubic<double>(), smooth_cubic<R>(), false);
  check_prefix("loop", looping_bezier<double>(), looping_bezier<R>(), false);
  check_prefix("near cusp", cusp_cubic<double>(1.0 / 1024), cusp_cubic<R>(1.0 / 1024), true);
  check_prefix("exact cusp", cusp_cubic<double>(0), cusp_cubic<R>(0), true);
  check_prefix("zero-length segment", with_zero_segment<double>(), with_zero_segment<R>(), false);
  check_prefix("100-segment spline", long_spline<double>(), long_spline<R>(), false);
  // Smooth one-segment curve: the guess from the sub-panel is close enough that at most two Newton
  // steps and the check (three G7-K15 panels and two speeds, 47 evaluations) converge for every
  // target at the default 400 eps L (without the prefix: one G15-K31 panel and more steps).
  const auto c = smooth_cubic<double>();
  const al::segment_lengths<double> seg(c, al::segment_lengths<double>::default_options(),
                                        al::segment_lengths<double>::newton_prefix_panels);
  for (int k = 1; k < 64; ++k) {
    const auto rn = al::newton_invert(c, seg, seg.length() * k / 64);
    EXPECT_TRUE(rn.converged());
    EXPECT_LE(rn.evaluations, 47u) << "k=" << k;
  }
  // A budget below one step still ends in cap_hit with an honest bound.
  const ref::reference_arc_length<poly2<R>> r(smooth_cubic<R>());
  al::newton_options<double> starved;
  starved.max_evaluations = 10;
  for (int k = 1; k < 8; ++k) {
    const double s = seg.length() * k / 8;
    const auto inv = al::newton_invert(c, seg, s, starved);
    EXPECT_EQ(inv.status, al::result_status::cap_hit) << "s = " << s;
    EXPECT_EQ(inv.reason.what, al::reasons::newton_cap) << "s = " << s;  // it says why
    ASSERT_TRUE(std::isfinite(inv.s_error_estimate));
    EXPECT_LE(abs(r.s(R(inv.u)) - R(s)), R(inv.s_error_estimate)) << "s = " << s;
  }
  EXPECT_THROW(al::segment_lengths<double>(c, al::segment_lengths<double>::default_options(), 4096), cb::invalid_input);
}

// A curve whose length is rounding noise (a rational quadratic with three equal points: the speed
// is the rounding of N'w - N w') hung the table build (minutes: Newton on noise at a tolerance of
// 400 eps times the noise). Now: s(u) by Newton's method within its noise, cheaply; u(s) and the
// tables refuse it with a message that says why.
TEST(inversion, a_rounding_noise_length_has_s_of_u_but_no_u_of_s) {
  const std::vector<pt2<double>> same(3, pt2<double>(1.1, -2.3));
  const std::vector<double> w{1, 0.3, 2};
  const cb::rational_bezier<double, 2> c{std::span<const pt2<double>>(same), std::span<const double>(w)};
  al::parameterization_options<double> o;
  o.method = al::inversion_method::newton;
  const al::parameterization<cb::rational_bezier<double, 2>> p(c, o);
  EXPECT_TRUE(p.degenerate());
  EXPECT_LE(p.length(), al::degenerate_length_eps * std::numeric_limits<double>::epsilon() * p.size());
  const auto q = p.s_result(0.5);
  EXPECT_TRUE(std::isfinite(q.value));
  EXPECT_LE(q.evaluations, 31u * 3);  // one panel meets the noise-level tolerance
  try {
    (void)p.u(0.0);
    FAIL();
  } catch (const cb::invalid_input& e) {
    EXPECT_THAT(e.what(), HasSubstr("is rounding noise (at most 64 eps of the curve's size 2.2999999999999998)"));
    EXPECT_THAT(e.what(), HasSubstr("needs a curve of positive length"));
  }
  EXPECT_THROW((al::parameterization<cb::rational_bezier<double, 2>>(c)), cb::invalid_input);
  const al::parameterization<poly2<double>> fine(smooth_cubic<double>(), o);
  EXPECT_FALSE(fine.degenerate());
}

// A domain far from 0: [1e8, 1e8 + 1] took 13 s (the table doubled to its cap chasing 32 eps L
// while u itself resolves only 1.5e-8). Now the table stops at the resolution of u
// (rounding_limited) within a small budget, and its u(s) are within that resolution plus the
// Newton tolerance, against 50 digits.
TEST(inversion, a_domain_far_from_zero_stops_at_the_resolution_of_u) {
  const std::vector<pt2<double>> cps{pt2<double>(0, 0), pt2<double>(1, 2), pt2<double>(3, 2), pt2<double>(4, 0)};
  const std::vector<pt2<R>> cps50{pt2<R>(0, 0), pt2<R>(1, 2), pt2<R>(3, 2), pt2<R>(4, 0)};
  const cb::bezier<double, 2> c(std::span<const pt2<double>>(cps), {1e8, 1e8 + 1});
  const cb::bezier<R, 2> c50(std::span<const pt2<R>>(cps50), {R(1e8), R(1e8 + 1)});
  const ref::reference_arc_length<cb::bezier<R, 2>> r(c50);
  const al::parameterization<cb::bezier<double, 2>> p(c);
  EXPECT_EQ(p.table_status(), al::result_status::rounding_limited);
  EXPECT_LT(p.construction_evaluations(), 200000u);
  ASSERT_TRUE(std::isfinite(p.table_error()));
  R worst(0);
  for (int k = 0; k <= 100; ++k) {
    const double s = p.length() * k / 100;
    worst = std::max(worst, R(abs(r.s(R(p.u(s))) - R(s))));
  }
  // u rounds to ulp(1e8) = 1.5e-8: s(u) can be off by |P'| ulp(u) / 2 ~ 4e-8 whatever the method
  // (|P'| <= 3 |P1 - P0| = 6.7); 4e-7 allows ten such roundings in the table's interpolation.
  EXPECT_LE(worst, R(p.table_error()) + R(4e-7));
}

TEST(inversion, polish_improves_a_coarse_hermite_table) {
  const auto c = smooth_cubic<double>();
  const ref::reference_arc_length<poly2<R>> r(smooth_cubic<R>());
  al::parameterization_options<double> o;
  o.table_intervals = 16;
  const al::parameterization<poly2<double>> coarse(c, o);
  o.newton_polish = true;
  const al::parameterization<poly2<double>> polished(c, o);
  R e_coarse(0), e_polished(0);
  for (int k = 1; k < 40; ++k) {
    const double s = coarse.length() * (k + 0.5) / 40.5;
    e_coarse = std::max(e_coarse, R(abs(r.s(R(coarse.u(s))) - R(s))));
    e_polished = std::max(e_polished, R(abs(r.s(R(polished.u(s))) - R(s))));
  }
  EXPECT_LT(e_polished, e_coarse / 1000);  // one Newton step roughly squares the relative error
}

TEST(inversion, real50_newton_reaches_50_digits) {
  const auto c = smooth_cubic<R>();
  const al::segment_lengths<R> seg(c);
  const ref::reference_arc_length<poly2<R>> r(c);
  EXPECT_LT(abs(seg.length() - r.length()), R("1e-45"));
  al::newton_options<R> opt;
  opt.relative_tolerance = R("1e-40");
  for (int k = 1; k < 4; ++k) {
    const R s = r.length() * k / 4;
    const auto inv = al::newton_invert(c, seg, s, opt);
    EXPECT_TRUE(inv.converged()) << al::to_string(inv.status);
    EXPECT_LT(abs(r.s(inv.u) - s), R("1e-40") * r.length());
  }
}

// ---- Newton steps bounded without integrating them ------------------------------------------

// The smooth and near-cusp suite cubics as piecewise_cubic engines (which bound their second
// derivative): the same polynomials in t = u / w, a_k = c_k w^k (exact: w is a power of two).
template <class Real>
cb::piecewise_cubic<Real, 2> engine_of(const poly2<Real>& p, const Real& lo, const Real& hi) {
  typename cb::piecewise_cubic<Real, 2>::geometry_type a;
  Real scale(1);
  for (int k = 0; k < 4; ++k) {
    a.row(k) = (p.coefficients()[0][static_cast<std::size_t>(k)] * scale).transpose();
    scale *= hi - lo;
  }
  return cb::piecewise_cubic<Real, 2>::from_power({lo, hi}, {a});
}

// detail::bounded_step_error against the 50-digit arc length: from points u across every segment,
// toward targets s* = s(u + f w) for steps f of 1e-9 to 1e-1 of the segment width w either way
// (so that the step's quadratic term, M D^2, ranges from negligible to dominant), with s(u) given
// as the double nearest the reference and eu its exact error: |s(next) - s*| <= the bound, every
// time. And the bound is not vacuous: on the large steps it is within 30x of the true error
// somewhere (M is the largest |P''| of the segment, the true term uses |P''| near u).
template <class C, class C50>
void check_bounded_steps(const char* name, const C& c, const C50& c50) {
  SCOPED_TRACE(name);
  using Real = typename C::real_type;
  const ref::reference_arc_length<C50> r(c50);
  const auto bp = c.breakpoints();
  std::size_t checked = 0;
  double closest = 0;
  // Every segment of a short curve; of a long one every 9th and the last (12 of the 100-segment
  // spline's: the bound's code is the same on each, and each segment costs ~300 50-digit integrals,
  // which made this test 4 minutes in the -O2 build and over 10 under the sanitizers). The
  // sanitizer build takes every other point inside a segment too.
  const std::size_t segments = bp.size() - 1;
  std::vector<std::size_t> chosen;
  for (std::size_t i = 0; i<segments; i += segments> 8 ? 9 : 1) chosen.push_back(i);
  if (chosen.back() != segments - 1) chosen.push_back(segments - 1);
  const int point_stride = cbt::sanitizer_build ? 2 : 1;
  for (const std::size_t i : chosen) {
    const Real w = bp[i + 1] - bp[i];
    for (int j = 1; j < 16; j += point_stride) {
      const Real u = bp[i] + w * Real(j) / Real(16);
      const R s_u = r.s(R(u));
      const Real su = static_cast<Real>(s_u);
      const Real eu = std::nextafter(static_cast<Real>(abs(s_u - R(su))), std::numeric_limits<Real>::infinity());
      const Real sp = al::speed(c, u);
      if (!(sp > Real(0))) continue;
      for (const double f : {1e-9, -1e-9, 1e-6, -1e-6, 1e-4, -1e-4, 1e-2, -1e-2, 1e-1, -1e-1}) {
        const Real ut = u + Real(f) * w;
        if (!(ut > bp[i] && ut < bp[i + 1])) continue;
        const Real target = static_cast<Real>(r.s(R(ut)));
        const Real fu = su - target;
        const Real next = u - fu / sp;
        if (!(next > bp[i] && next < bp[i + 1])) continue;
        const Real b = al::detail::bounded_step_error(c, u, fu, eu, sp, next);
        ASSERT_TRUE(std::isfinite(b)) << "segment " << i << " u = " << u;
        const R truth = abs(r.s(R(next)) - R(target));
        ASSERT_LE(truth, R(b)) << "segment " << i << " u = " << u << " step " << f;
        ++checked;
        if (std::abs(f) >= 1e-2) closest = std::max(closest, static_cast<double>(truth / R(b)));
      }
    }
  }
  EXPECT_GT(checked, cbt::sanitizer_build ? 25u : 50u);
  EXPECT_GT(closest, 1.0 / 30);
}

TEST(inversion, a_newton_step_bounded_by_the_second_derivative_bounds_its_true_error) {
  check_bounded_steps("smooth cubic", engine_of(smooth_cubic<double>(), 0.0, 1.0),
                      engine_of(smooth_cubic<R>(), R(0), R(1)));
  check_bounded_steps("near cusp", engine_of(cusp_cubic<double>(1.0 / 1024), 0.0, 2.0),
                      engine_of(cusp_cubic<R>(1.0 / 1024), R(0), R(2)));
  check_bounded_steps("100-segment spline", long_spline<double>(), long_spline<R>());
  check_bounded_steps("100-segment spline, float", long_spline<float>(), long_spline<R>());
  // Across a knot the curve bounds nothing (P' may jump there): no bounded step.
  const auto c = long_spline<double>();
  EXPECT_EQ(al::detail::bounded_step_error(c, 4.9, 1e-3, 0.0, 1.0, 5.1), std::numeric_limits<double>::infinity());
  // A curve that declares no second-derivative bound: none either.
  EXPECT_EQ(al::detail::bounded_step_error(smooth_cubic<double>(), 0.4, 1e-3, 0.0, 1.0, 0.401),
            std::numeric_limits<double>::infinity());
}

// With the length prefix and a curve that bounds its second derivative, a smooth segment's query
// costs one short integral (G7-K15 from the nearer prefix point) and one speed: 16 evaluations,
// converged with a bound that covers the true |s(u) - s*| (50-digit reference).
TEST(inversion, newton_on_a_piecewise_cubic_settles_its_step_without_a_check_integral) {
  const auto c = engine_of(smooth_cubic<double>(), 0.0, 1.0);
  const ref::reference_arc_length<cb::piecewise_cubic<R, 2>> r(engine_of(smooth_cubic<R>(), R(0), R(1)));
  const al::segment_lengths<double> seg(c, al::segment_lengths<double>::default_options(),
                                        al::segment_lengths<double>::newton_prefix_panels);
  const double tol = al::newton_options<double>{}.relative_tolerance * seg.length();
  for (int k = 1; k < 64; ++k) {
    const double s = seg.length() * (k + 0.3183) / 64.5;
    const auto rn = al::newton_invert(c, seg, s);
    EXPECT_TRUE(rn.converged()) << "k=" << k;
    EXPECT_LE(rn.evaluations, 16u) << "k=" << k;
    EXPECT_LE(rn.s_error_estimate, tol) << "k=" << k;
    EXPECT_LE(abs(r.s(R(rn.u)) - R(s)), R(rn.s_error_estimate)) << "k=" << k;
  }
}
