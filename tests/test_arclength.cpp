// Arc-length methods against the 50-digit reference on the curve suite: smooth, looping,
// near-cusp and exact-cusp cubics, a straight line with non-uniform speed, a curve with a
// zero-length segment, a circle (rational quadratic), a helix and a 200-segment Hermite spline.
// Each method's value is compared with the reference, and its error estimate with the true error:
// the estimate must be >= the true error whenever the status is converged (the headline
// property). Observed convergence orders: forward differencing 2, Richardson 4, composite
// Gauss-Legendre 2n, fixed Gauss-Legendre per segment geometric. Parent's false positive and its
// guards. Bad input.
#include "support/accuracy.hpp"

#include "curvebench/arclength/adaptive_subdivision.hpp"
#include "curvebench/arclength/forward_difference.hpp"
#include "curvebench/arclength/length.hpp"
#include "curvebench/curves/bezier.hpp"
#include "curvebench/curves/piecewise_cubic.hpp"
#include "curvebench/reference/analytic_curves.hpp"
#include "curvebench/reference/arc_length.hpp"
#include "curvebench/reference/convert.hpp"

#include <gmock/gmock.h>

#include <cmath>
#include <string>
#include <vector>

namespace cb = curvebench;
namespace al = curvebench::arclength;
namespace ref = curvebench::reference;
namespace cbt = curvebench::testing;
using R = cb::real50;
using ::testing::HasSubstr;

namespace {

// Tolerances (relative to the reference length unless said otherwise):
// - adaptive Gauss-Kronrod at its default 128 eps: true error within its estimate (asserted for
//   every curve), and so within 128 eps L + the 4 eps summation term: 132 eps;
// - fixed Gauss-Legendre, 16 points per segment, on the smooth cubic: the speed is analytic in a
//   wide ellipse, the error is at rounding level: 16 eps;
// - orders: observed log2(e_h / e_{h/2}) within 0.15 of the theoretical order.
constexpr double adaptive_eps = 132;
constexpr double fixed16_eps = 16;
constexpr double order_slack = 0.15;

// ---- the curve suite, built from the same dyadic (exact in every Real) data in double and real50 ----

template <class Real>
using poly2 = ref::piecewise_polynomial<Real, 2>;
template <class Real>
using pt2 = cb::point<Real, 2>;

template <class Real>
poly2<Real> smooth_cubic() {
  return {Real(0), Real(1), {pt2<Real>(0, 0), pt2<Real>(1, 2), pt2<Real>(3, Real(-1)), pt2<Real>(Real(-2), Real(0.5))}};
}
// (x^2 + eps x, x^3) with x = u - 3/4 on [0, 2]: a cusp at u = 3/4 for eps = 0 (away from every
// panel midpoint a method might split at first), speed down to ~3 eps^2 / 4 near it otherwise.
// Power form in u: x^2 + eps x = u^2 + (eps - 3/2) u + (9/16 - 3 eps / 4), x^3 = u^3 - 9/4 u^2 + 27/16 u - 27/64.
template <class Real>
poly2<Real> cusp_cubic(double eps) {
  const Real e(eps);
  return {Real(0),
          Real(2),
          {pt2<Real>(Real(0.5625) - Real(0.75) * e, Real(-0.421875)), pt2<Real>(e - Real(1.5), Real(1.6875)),
           pt2<Real>(1, Real(-2.25)), pt2<Real>(0, 1)}};
}
// A line along (3, 4)/5 with x(u) = u + u^3: non-uniform speed.
template <class Real>
poly2<Real> straight_line() {
  return {Real(0),
          Real(1),
          {pt2<Real>(1, 1), pt2<Real>(Real(0.6), Real(0.8)), pt2<Real>(0, 0), pt2<Real>(Real(0.6), Real(0.8))}};
}
// Three segments, the middle one of zero length (constant), C0.
template <class Real>
poly2<Real> with_zero_segment() {
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
ref::rational_quadratic<Real, 2> quarter_circle() {  // weights (1, sqrt(2)/2 rounded to double, 1): a conic
  return {pt2<Real>(1, 0), pt2<Real>(1, 1), pt2<Real>(0, 1), Real(0.70710678118654757)};
}
// 200 Hermite segments through dyadic points with Catmull-Rom slopes (dyadic too), unit knots.
template <class Real>
cb::piecewise_cubic<Real, 2> long_spline() {
  const std::size_t n = 200;
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

struct method_outcome {
  std::string name;
  R error;  // |value - reference|
  al::quadrature_result<double> r;
};

// Runs every length method on a double curve and returns the outcomes against the reference L.
template <class C>
std::vector<method_outcome> run_methods(const C& c, const R& length) {
  std::vector<method_outcome> out;
  auto add = [&](std::string name, const al::quadrature_result<double>& r) {
    out.push_back({std::move(name), abs(R(r.value) - length), r});
  };
  add("adaptive_gk15", al::adaptive_length(c));
  al::adaptive_options<double> loose;
  loose.relative_tolerance = 1e-8;
  add("adaptive_gk15_1e-8", al::adaptive_length(c, loose));
  al::adaptive_options<double> qp = loose;
  qp.model = al::error_model::quadpack;
  add("adaptive_gk15_quadpack_1e-8", al::adaptive_length(c, qp));
  add("gauss8_nested", al::gauss_length(c, 8, al::fixed_estimate::nested));
  add("gauss4_nested", al::gauss_length(c, 4, al::fixed_estimate::nested));
  add("gauss8_none", al::gauss_length(c, 8));
  const al::forward_difference_table<double> fd(c, 64);
  add("forward_difference_64", fd.length());
  add("richardson_64", fd.richardson_length());
  add("forward_difference_63", al::forward_difference_table<double>(c, 63).length());
  al::subdivision_options<double> so;
  so.tolerance = 1e-6 * static_cast<double>(length);
  so.relative_tolerance = 0;
  add("subdivision_1e-6", al::subdivision_length(c, so));
  return out;
}

template <class C50>
R reference_length(const C50& c) {
  const ref::reference_arc_length<C50> r(c);
  EXPECT_LT(r.length_error(), R("1e-40") * r.length());
  return r.length();
}

template <class C, class C50>
void check_suite_curve(const char* name, const C& c, const C50& c50) {
  SCOPED_TRACE(name);
  const R length = reference_length(c50);
  for (const method_outcome& m : run_methods(c, length)) {
    SCOPED_TRACE(m.name);
    EXPECT_GT(m.r.evaluations, 0u);
    // Honesty: a converged result's estimate bounds its true error; otherwise the method said so.
    if (m.r.status == al::result_status::converged) {
      EXPECT_LE(m.error, R(m.r.error_estimate)) << "value " << m.r.value << " estimate " << m.r.error_estimate;
    } else {
      EXPECT_TRUE(m.r.status == al::result_status::not_guaranteed || m.r.status == al::result_status::cap_hit ||
                  m.r.status == al::result_status::rounding_limited);
    }
    if (m.name == "adaptive_gk15") {
      // The 200-segment spline's power-form evaluation may round by ~100 eps of L (its rounding_bound,
      // the coefficients' sizes times the Horner and t roundings), which with the panels' own floor
      // passes the default 128 eps: its status is then rounding_limited, and its value still as close.
      EXPECT_TRUE(m.r.converged() ||
                  (std::string(name) == "200-segment spline" && m.r.status == al::result_status::rounding_limited))
          << al::to_string(m.r.status);
      EXPECT_TRUE(cbt::within_ulps(m.r.value, length, adaptive_eps));
    }
    if (m.name == "gauss8_none") {
      EXPECT_EQ(m.r.status, al::result_status::not_guaranteed);
      EXPECT_TRUE(std::isinf(m.r.error_estimate));
    }
    if (m.name == "forward_difference_63") {
      EXPECT_EQ(m.r.status, al::result_status::not_guaranteed);  // odd N: no coarse table, no bound
    }
    if (m.name == "subdivision_1e-6") {
      EXPECT_LE(m.error, R(1e-6) * length);
    }
  }
}

template <class Real>
class arclength_test : public ::testing::Test {};
TYPED_TEST_SUITE(arclength_test, cbt::ieee_reals);

}  // namespace

TEST(arclength, suite_estimates_bound_true_errors) {
  check_suite_curve("smooth cubic", smooth_cubic<double>(), smooth_cubic<R>());
  check_suite_curve("near cusp", cusp_cubic<double>(1.0 / 1024), cusp_cubic<R>(1.0 / 1024));
  check_suite_curve("exact cusp", cusp_cubic<double>(0), cusp_cubic<R>(0));
  check_suite_curve("straight line", straight_line<double>(), straight_line<R>());
  check_suite_curve("zero-length segment", with_zero_segment<double>(), with_zero_segment<R>());
  check_suite_curve("loop", looping_bezier<double>(), looping_bezier<R>());
  check_suite_curve("conic quarter circle", quarter_circle<double>(), quarter_circle<R>());
  check_suite_curve("helix", ref::helix<double>(1.5, 3, 0.25, 0, 2), ref::helix<R>(R(1.5), R(3), R(0.25), R(0), R(2)));
  check_suite_curve("200-segment spline", long_spline<double>(), long_spline<R>());
}

TEST(arclength, straight_line_and_zero_segment_closed_forms) {
  // Line: |P(1) - P(0)| = 2 exactly (x goes from 0 to 2 monotonically along a unit direction).
  EXPECT_TRUE(cbt::within_ulps(al::adaptive_length(straight_line<double>()).value, R(2), 8));
  // The zero-length segment contributes exactly 0 to every method.
  const auto z = with_zero_segment<double>();
  const auto middle = al::adaptive_length(z, 1.0, 1.5);
  EXPECT_EQ(middle.value, 0.0);
  EXPECT_TRUE(middle.converged());
  EXPECT_EQ(al::gauss_length(z, 1.0, 1.5, al::gauss_legendre<double>(5)).value, 0.0);
}

TEST(arclength, partial_lengths_are_signed_and_additive) {
  const auto c = long_spline<double>();
  const auto ab = al::adaptive_length(c, 3.25, 120.5);
  const auto ba = al::adaptive_length(c, 120.5, 3.25);
  EXPECT_EQ(ab.value, -ba.value);
  const auto a0 = al::adaptive_length(c, 0.0, 3.25), b0 = al::adaptive_length(c, 0.0, 120.5);
  EXPECT_NEAR(b0.value - a0.value, ab.value, ab.error_estimate + a0.error_estimate + b0.error_estimate);
  EXPECT_THROW((void)al::adaptive_length(c, -1.0, 2.0), std::domain_error);
}

TEST(arclength, fixed_gauss_legendre_converges_geometrically_on_a_smooth_segment) {
  const auto c = smooth_cubic<double>();
  const R length = reference_length(smooth_cubic<R>());
  R previous(1);
  for (int n : {2, 4, 8, 12}) {  // each step reduces the error by a large factor until rounding
    const R e = abs(R(al::gauss_length(c, n).value) - length);
    EXPECT_LT(e, previous / 10) << "n=" << n;
    previous = e;
  }
  EXPECT_TRUE(cbt::within_ulps(al::gauss_length(c, 16).value, length, fixed16_eps));
}

TEST(arclength, observed_orders) {
  const auto c = smooth_cubic<double>();
  const R length = reference_length(smooth_cubic<R>());
  auto order = [](const R& coarse, const R& fine) { return static_cast<double>(log2(coarse / fine)); };
  {  // forward differencing: chord sum error c h^2
    const R e1 = length - R(al::forward_difference_table<double>(c, 64).length().value);
    const R e2 = length - R(al::forward_difference_table<double>(c, 128).length().value);
    EXPECT_GT(e1, R(0));  // chord sums never exceed the arc length
    EXPECT_NEAR(order(e1, e2), 2.0, order_slack);
  }
  {  // Richardson of N and N/2 cancels h^2: measured 4
    const R e1 = abs(length - R(al::forward_difference_table<double>(c, 32).richardson_length().value));
    const R e2 = abs(length - R(al::forward_difference_table<double>(c, 64).richardson_length().value));
    EXPECT_NEAR(order(e1, e2), 4.0, order_slack);
  }
  for (int n : {1, 2, 3, 4}) {  // composite Gauss-Legendre with n points per panel: 2n (in real50: no rounding floor)
    const auto& rule = al::gauss_legendre<R>(n);
    const auto c50 = smooth_cubic<R>();
    const R e1 = abs(length - al::composite_gauss_length(c50, 32, rule).value);
    const R e2 = abs(length - al::composite_gauss_length(c50, 64, rule).value);
    EXPECT_NEAR(order(e1, e2), 2.0 * n, order_slack) << "n=" << n;
  }
  {  // the table's s(u) and u(s): O(h^2) too (linear interpolation and chords)
    const ref::reference_arc_length<poly2<R>> r(smooth_cubic<R>());
    R e[2];
    for (int k = 0; k < 2; ++k) {
      const al::forward_difference_table<double> t(c, 64u << k);
      e[k] = R(0);
      for (int j = 1; j < 40; ++j) {
        const double u = (j + 0.37) / 41.0;
        e[k] = std::max(e[k], R(abs(R(t.s(u)) - r.s(R(u)))));
      }
    }
    EXPECT_NEAR(order(e[0], e[1]), 2.0, order_slack);
  }
}

TYPED_TEST(arclength_test, every_real_meets_its_precision_on_the_smooth_cubic) {
  using Real = TypeParam;
  const R length = reference_length(smooth_cubic<R>());
  const auto c = smooth_cubic<Real>();
  const al::quadrature_result<Real> r = al::adaptive_length(c);
  EXPECT_TRUE(r.converged());
  EXPECT_LE(abs(R(r.value) - length), R(r.error_estimate));
  EXPECT_TRUE(cbt::within_ulps(r.value, length, adaptive_eps));
  const al::quadrature_result<Real> h = al::gauss_length(c, 10, al::fixed_estimate::nested);
  EXPECT_LE(abs(R(h.value) - length), R(h.error_estimate));
  const al::forward_difference_table<Real> t(c, 256);
  EXPECT_LE(abs(R(t.length().value) - length), R(t.length().error_estimate));
  EXPECT_LE(abs(R(t.richardson_length().value) - length), R(t.richardson_length().error_estimate));
}

// The speed-minimum screen of adaptive_length runs on the first panel's own 31 node speeds: a
// smooth segment (the smooth cubic, no speed minimum below half its top) costs that one G15-K31
// panel and no sample, and meets 1e-13 relative with it; the near-cusp cubic (speed down to
// 3 eps^2 / 4 at u = 3/4) is flagged, examined and split at its minimum, and still bounds its error
// (the screen may only decide where to look, never to trust less). screen_flags on hand-made node
// speeds: a dip to half the top inside, or a low end with the speed falling towards it, is
// flagged; a monotone speed that stays above half its top is not.
TEST(arclength, speed_minimum_screen_uses_the_first_panel_and_flags_low_minima) {
  al::adaptive_options<double> o;
  o.relative_tolerance = 1e-13;
  const auto smooth = smooth_cubic<double>();
  const al::quadrature_result<double> r = al::adaptive_length(smooth, o);
  EXPECT_TRUE(r.converged());
  EXPECT_EQ(r.evaluations, al::gauss_kronrod<double>(15).nodes.size());
  EXPECT_LE(abs(R(r.value) - reference_length(smooth_cubic<R>())), R(r.error_estimate));

  const auto cusp = cusp_cubic<double>(1e-3);
  const R cusp_length = reference_length(cusp_cubic<R>(1e-3));
  const al::quadrature_result<double> c = al::adaptive_length(cusp, o);
  EXPECT_LE(abs(R(c.value) - cusp_length), R(c.error_estimate));
  // Flagged on its own first panel's node speeds, and so examined: more than that panel and the samples.
  const auto& screen = al::gauss_kronrod<double>(15);
  std::vector<double> nodes(screen.nodes.size());
  (void)screen.apply([&](double u) { return al::speed(cusp, u); }, 0.0, 2.0, al::error_model::gauss_difference,
                     nodes.data());
  EXPECT_TRUE(al::detail::screen_flags<double>(nodes));
  EXPECT_GT(c.evaluations, screen.nodes.size() + o.speed_minimum_samples + 1);
  std::vector<double> smooth_nodes(screen.nodes.size());
  (void)screen.apply([&](double u) { return al::speed(smooth, u); }, 0.0, 1.0, al::error_model::gauss_difference,
                     smooth_nodes.data());
  EXPECT_FALSE(al::detail::screen_flags<double>(smooth_nodes));

  using v = std::vector<double>;
  EXPECT_TRUE(al::detail::screen_flags<double>(v{2, 1.5, 0.9, 1.2, 2.5}));   // dip to 0.36 of the top
  EXPECT_FALSE(al::detail::screen_flags<double>(v{2, 1.8, 1.4, 1.6, 2.5}));  // dip to 0.56 of the top
  EXPECT_TRUE(al::detail::screen_flags<double>(v{0.5, 0.9, 1.5, 2, 2.5}));   // low end, falling towards it
  EXPECT_FALSE(al::detail::screen_flags<double>(v{1.3, 1.5, 1.8, 2, 2.5}));  // monotone, above half the top
  EXPECT_TRUE(al::detail::screen_flags<double>(v{0, 0, 0}));                 // no speed at all
}

TEST(arclength, parent_false_positive_and_its_guards) {
  // S-curve (u, u^3 - u) on [-1, 1]: P(-1), P(0), P(1) are collinear and evenly spaced on the x axis.
  const poly2<double> s_curve(-1.0, 1.0,
                              {pt2<double>(-1, 0), pt2<double>(1, 2), pt2<double>(0, -3), pt2<double>(0, 1)});
  // (local t = u + 1: u^3 - u = t^3 - 3t^2 + 2t)
  ASSERT_EQ(s_curve(0.0), pt2<double>(0, 0));
  const poly2<R> s50(R(-1), R(1), {pt2<R>(-1, 0), pt2<R>(1, 2), pt2<R>(0, -3), pt2<R>(0, 1)});
  const R length = reference_length(s50);
  // Parent's chord test alone (the whole chord against its halves', here 2 = 1 + 1) accepted the
  // chord 2.0 of the whole interval, true length ~2.62. The chord / control-polygon bracket does
  // not: P'(-1) = P'(1) = (1, 2) put the polygon far from the chord, so even unguarded (no forced
  // levels, no look-ahead) the pieces are halved until the bracket is within the tolerance.
  al::subdivision_options<double> naive;
  naive.tolerance = 1e-6;
  naive.relative_tolerance = 0;
  naive.min_depth = 0;
  naive.look_ahead = false;
  const auto unguarded = al::subdivision_length(s_curve, naive);
  EXPECT_GT(length - R(2.0), R(0.5));
  EXPECT_TRUE(unguarded.converged()) << al::to_string(unguarded.status);
  EXPECT_LE(abs(R(unguarded.value) - length), R(unguarded.error_estimate));
  EXPECT_LE(unguarded.error_estimate, 1e-6);
  al::subdivision_options<double> guarded = naive;
  guarded.min_depth = 2;  // Parent's remedy: force a few levels
  guarded.look_ahead = true;
  const auto looked = al::subdivision_length(s_curve, guarded);
  EXPECT_LE(abs(R(looked.value) - length), R(1e-6));
  EXPECT_LE(abs(R(looked.value) - length), R(looked.error_estimate));
}

// Bounded work: subdivision's default tolerance is relative to the curve's size (it was
// 1e-6 absolute: a curve of size 1e10 asked for 1e-16 relative and ran to depth 40, 2^40 leaves).
// Scaling a curve by 2^33 (exact in binary) leaves the work unchanged; the result scales.
TEST(arclength, subdivision_default_tolerance_is_relative_to_the_size) {
  const auto c = smooth_cubic<double>();
  const double k = std::ldexp(1.0, 33);
  auto scaled = [](double f) {
    return poly2<double>(
        0.0, 1.0, {pt2<double>(0, 0) * f, pt2<double>(1, 2) * f, pt2<double>(3, -1) * f, pt2<double>(-2, 0.5) * f});
  };
  const R length = reference_length(smooth_cubic<R>());
  const auto one = al::subdivision_length(c, {});
  const auto big = al::subdivision_length(scaled(k), {});
  const auto small = al::subdivision_length(scaled(1 / k), {});
  EXPECT_TRUE(one.converged()) << al::to_string(one.status);
  EXPECT_EQ(big.evaluations, one.evaluations);
  EXPECT_EQ(small.evaluations, one.evaluations);
  EXPECT_EQ(big.value, one.value * k);
  EXPECT_LE(abs(R(one.value) - length), R(one.error_estimate));
  EXPECT_LE(abs(R(one.value) - length), R(1e-6) * length);  // the default 1e-6 of the size (<= L)
}

// The evaluation budget: a tolerance of 1e-13 relative needs ~10^6 pieces; 2000 evaluations stop it
// with cap_hit, never past the budget. The pieces with the largest bounds are halved first, so the
// capped result keeps a finite bound (it was +inf when the recursion was depth first: the pieces
// the budget stopped could be coarse anywhere). A tolerance below the rounding floor (1e-18) ends
// rounding_limited within the default budget instead of running to depth 40.
TEST(arclength, subdivision_budget_ends_in_cap_hit_with_an_honest_estimate) {
  const auto c = smooth_cubic<double>();
  const R length = reference_length(smooth_cubic<R>());
  al::subdivision_options<double> o;
  o.relative_tolerance = 1e-13;
  o.max_evaluations = 2000;
  const auto capped = al::subdivision_length(c, o);
  EXPECT_EQ(capped.status, al::result_status::cap_hit);
  EXPECT_LE(capped.evaluations, o.max_evaluations);
  EXPECT_GE(capped.evaluations + 1, o.max_evaluations);  // 2 per halving: at most 1 left unspent
  EXPECT_TRUE(std::isfinite(capped.error_estimate));
  EXPECT_LE(abs(R(capped.value) - length), R(capped.error_estimate));
  // ~1000 pieces of a smooth cubic at order 2 bound its error to ~1e-7 of L or below; 1e-6 of L
  // fails if the budget were spent on a few pieces while the rest stayed coarse.
  EXPECT_LE(R(capped.error_estimate), R(1e-6) * length);
  o.relative_tolerance = 1e-18;
  o.max_evaluations = al::subdivision_options<double>{}.max_evaluations;
  const auto below = al::subdivision_length(c, o);
  EXPECT_TRUE(below.status == al::result_status::rounding_limited || below.status == al::result_status::cap_hit)
      << al::to_string(below.status);
  EXPECT_LE(below.evaluations, o.max_evaluations);
  EXPECT_LE(abs(R(below.value) - length), R(below.error_estimate));
}

TEST(arclength, bad_input_is_rejected_with_clear_messages) {
  const auto c = smooth_cubic<double>();
  al::subdivision_options<double> so;
  so.tolerance = 0;
  so.relative_tolerance = 0;
  try {
    (void)al::subdivision_length(c, so);
    FAIL();
  } catch (const cb::invalid_input& e) {
    EXPECT_STREQ(e.what(), "tolerance = 0 and relative_tolerance = 0: at least one must be > 0");
  }
  al::adaptive_options<double> ao;
  ao.relative_tolerance = std::nan("");
  try {
    (void)al::adaptive_length(c, ao);
    FAIL();
  } catch (const cb::invalid_input& e) {
    EXPECT_STREQ(e.what(), "relative_tolerance = nan: must be finite");
  }
  try {
    (void)al::forward_difference_table<double>(c, 0);
    FAIL();
  } catch (const cb::invalid_input& e) {
    EXPECT_STREQ(e.what(), "steps_per_segment = 0: must be >= 1");
  }
  const al::forward_difference_table<double> t(c, 8);
  EXPECT_THROW((void)t.u(-1.0), std::domain_error);
  EXPECT_THROW((void)t.u(std::nan("")), std::domain_error);
  EXPECT_THROW((void)t.s(1.5), std::domain_error);
  EXPECT_THROW((void)al::composite_gauss_length(c, 0, al::gauss_legendre<double>(3)), cb::invalid_input);
}

namespace {

// The curve c with every coordinate multiplied by 2^k: exact in binary arithmetic, so a method
// whose arithmetic neither overflows nor underflows returns 2^k times its unscaled result, bit for bit.
template <class C>
struct scaled_by_power_of_two {
  using real_type = typename C::real_type;
  using point_type = typename C::point_type;
  static constexpr int dimension = C::dimension;
  C c;
  int k;
  [[nodiscard]] cb::interval<real_type> domain() const { return c.domain(); }
  [[nodiscard]] point_type operator()(const real_type& u) const { return derivative(u, 0); }
  [[nodiscard]] point_type derivative(const real_type& u, int order) const {
    point_type p = c.derivative(u, order);
    for (int d = 0; d < dimension; ++d) p[d] = std::ldexp(p[d], k);
    return p;
  }
  [[nodiscard]] std::span<const real_type> breakpoints() const { return c.breakpoints(); }
};

}  // namespace

// With coordinates near 1e200 the squared speed overflowed (length null, status
// rounding_limited), near 1e-170 it underflowed (length 0, converged). Every length method must
// scale exactly: 2^664 ~ 1e200 and 2^-565 ~ 1e-170 make the squares of speeds and chords leave
// double's range, while the lengths themselves are far inside it.
template <class C, class C50>
void check_exact_scaling(const char* name, const C& plain, const C50& c50) {
  const R length = reference_length(c50);
  const std::vector<method_outcome> base = run_methods(plain, length);
  for (const int k : {664, -565}) {
    SCOPED_TRACE(std::string(name) + " scaled by 2^" + std::to_string(k));
    const scaled_by_power_of_two<C> big{plain, k};
    const std::vector<method_outcome> scaled = run_methods(big, R(ldexp(length, k)));
    ASSERT_EQ(scaled.size(), base.size());
    for (std::size_t i = 0; i < base.size(); ++i) {
      SCOPED_TRACE(base[i].name);
      EXPECT_EQ(scaled[i].r.value, std::ldexp(base[i].r.value, k));
      EXPECT_EQ(scaled[i].r.status, base[i].r.status);
      EXPECT_EQ(scaled[i].r.evaluations, base[i].r.evaluations);
    }
  }
}

TEST(arclength, lengths_scale_exactly_from_1e_minus_170_to_1e200) {
  check_exact_scaling("smooth cubic", smooth_cubic<double>(), smooth_cubic<R>());
  check_exact_scaling("near cusp", cusp_cubic<double>(1.0 / 1024), cusp_cubic<R>(1.0 / 1024));
  check_exact_scaling("loop", looping_bezier<double>(), looping_bezier<R>());
}
