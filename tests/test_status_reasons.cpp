// Every result of the arc-length length methods that is not converged names why
// (arclength/result.hpp's status_reason: the failed bound or the cap, the segment and interval where
// the method knows them, the quantity against its bound), and the nested Gauss rule keeps its bound
// on many-segment splines by halving a piece that fails its order test (arclength/length.hpp).
// Each status of each method is produced here on a curve built for it, and its reason checked: the
// text, the segment (against the curve's breakpoints) and the numbers.
#include "curvebench/arclength/adaptive_subdivision.hpp"
#include "curvebench/arclength/forward_difference.hpp"
#include "curvebench/arclength/gauss_kronrod.hpp"
#include "curvebench/arclength/length.hpp"
#include "curvebench/arclength/result.hpp"
#include "curvebench/curves/bezier.hpp"
#include "curvebench/curves/cardinal_spline.hpp"
#include "curvebench/curves/composite_bezier.hpp"
#include "curvebench/curves/lagrange.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstddef>
#include <random>
#include <span>
#include <string>
#include <vector>

namespace cb = curvebench;
namespace al = curvebench::arclength;

namespace {

using pt2 = cb::point<double, 2>;
using reason_t = al::status_reason<double>;
constexpr std::size_t npos = reason_t::npos;

// bench/cases/near_cusp_cubic.json's family: [[0,0],[1,1],[dip,1],[1,0]].
cb::bezier<double, 2> cusp_family(double dip) {
  const std::vector<pt2> p{pt2(0, 0), pt2(1, 1), pt2(dip, 1), pt2(1, 0)};
  return cb::bezier<double, 2>(std::span<const pt2>(p));
}

// Three cubic segments on knots 0, 1, 2, 3: a straight line at constant speed (its control points
// equally spaced), then `middle`, then the line again, so a method that fails on the middle only
// must name segment 1.
cb::composite_bezier<double, 2> line_middle_line(const cb::point_list<double, 2>& middle) {
  const pt2 a = middle.front(), d = middle.back();
  const cb::point_list<double, 2> first{a - pt2(3, 0), a - pt2(2, 0), a - pt2(1, 0), a};
  const cb::point_list<double, 2> last{d, d + pt2(1, 0), d + pt2(2, 0), d + pt2(3, 0)};
  const std::vector<cb::point_list<double, 2>> segs{first, middle, last};
  const std::vector<double> knots{0, 1, 2, 3};
  return cb::composite_bezier<double, 2>(std::span<const cb::point_list<double, 2>>(segs),
                                         std::span<const double>(knots));
}

// A hairpin: the middle segment turns back on itself (used for the turn of the tables' chords).
cb::composite_bezier<double, 2> hairpin() { return line_middle_line({pt2(0, 0), pt2(3, 1), pt2(3, -1), pt2(0.5, 0)}); }

// A bend: a smooth middle segment whose speed varies (every fixed rule's order test applies).
cb::composite_bezier<double, 2> bend() { return line_middle_line({pt2(0, 0), pt2(1, 0), pt2(1.5, 1), pt2(2, 3)}); }

// A centripetal Catmull-Rom through `count` points of a random walk (fixed seed): heading turned by
// up to 1 radian per point, steps from 0.3 to 3 long (as /tmp/i32/road1000.json's road: uneven
// knot intervals, curvature varying on the scale of a segment).
cb::cardinal_spline<double, 2> road(int count, unsigned seed) {
  std::mt19937 g(seed);
  std::uniform_real_distribution<double> turn(-1.0, 1.0), step(0.3, 3.0);
  cb::point_list<double, 2> p;
  double x = 0, y = 0, h = 0;
  for (int i = 0; i < count; ++i) {
    p.emplace_back(x, y);
    h += turn(g);
    const double d = step(g);
    x += d * std::cos(h);
    y += d * std::sin(h);
  }
  cb::cardinal_spline<double, 2>::options o;
  o.alpha = 0.5;
  return cb::cardinal_spline<double, 2>(p, o);
}

// The degree-20 Lagrange through Runge's function at 21 equispaced points
// (bench/cases/runge_lagrange_equispaced.json); monomial: its rounding has no bound (+inf).
cb::lagrange<double, 2> runge_lagrange(cb::lagrange_algorithm alg) {
  std::vector<pt2> p;
  for (int i = 0; i < 21; ++i) {
    const double x = -1 + 2 * static_cast<double>(i) / 20;
    p.emplace_back(x, 1 / (1 + 25 * x * x));
  }
  const std::vector<double> u = cb::equispaced_parameters<double>(21);
  return cb::lagrange<double, 2>(std::span<const pt2>(p), std::span<const double>(u), alg);
}
cb::lagrange<double, 2> unbounded_lagrange() { return runge_lagrange(cb::lagrange_algorithm::monomial); }

// A reason is well formed for a result on a curve with breakpoints bp: non-empty when the status is
// not converged (empty when it is), and a segment it names holds the interval it names.
template <class C>
::testing::AssertionResult well_formed(const al::quadrature_result<double>& r, const C& c) {
  if (r.status == al::result_status::converged) {
    if (!r.reason.empty()) return ::testing::AssertionFailure() << "converged with a reason: " << to_text(r.reason);
    return ::testing::AssertionSuccess();
  }
  if (r.reason.empty()) return ::testing::AssertionFailure() << al::to_string(r.status) << " without a reason";
  if (to_text(r.reason).empty()) return ::testing::AssertionFailure() << "a reason worded as \"\"";
  const std::span<const double> bp = c.breakpoints();
  if (r.reason.segment != npos) {
    const std::size_t i = r.reason.segment;
    if (i + 1 >= bp.size()) return ::testing::AssertionFailure() << "segment " << i << " of " << bp.size() - 1;
    if (r.reason.a != r.reason.b && !(bp[i] <= r.reason.a && r.reason.b <= bp[i + 1]))
      return ::testing::AssertionFailure()
             << to_text(r.reason) << ": not inside [" << bp[i] << ", " << bp[i + 1] << "]";
  }
  return ::testing::AssertionSuccess();
}

}  // namespace

TEST(status_reasons, worded_as_one_line) {
  EXPECT_EQ(to_text(reason_t{}), "");
  const reason_t r = al::segment_reason(al::reasons::order_test, 8, 10.124, 11.649, 3.0e-7, 6.2e-7);
  EXPECT_EQ(to_text(r),
            "segment 8 (u 10.124 to 11.649): order test failed: |Q1 - Q2| < 16 |Q2 - Q4| (measured 3e-07, bound "
            "6.2e-07)");
  EXPECT_EQ(to_text(al::global_reason<double>(al::reasons::budget, 1e-9, 1e-12)),
            "evaluation budget reached (measured 1e-09, bound 1e-12)");
  EXPECT_EQ(to_text(al::global_reason<double>(al::reasons::no_rounding_bound)), "the curve knows no rounding bound");
  EXPECT_EQ(to_text(reason_t{al::reasons::near_cusp, npos, 0.25, 0.5}),
            "u 0.25 to 0.5: near-cusp branch point within 1/8 of the piece");
}

TEST(status_reasons, a_sum_keeps_the_reason_of_the_worse_status) {
  using q = al::quadrature_result<double>;
  q total;
  total += q{1, 0, 1, al::result_status::converged};
  EXPECT_TRUE(total.reason.empty());
  total += q{1, 0, 1, al::result_status::rounding_limited, al::global_reason<double>(al::reasons::panels_at_floor)};
  EXPECT_EQ(total.reason.what, al::reasons::panels_at_floor);
  // A tie keeps the first; a worse status brings its own; a better one changes nothing.
  total += q{1, 0, 1, al::result_status::rounding_limited, al::global_reason<double>(al::reasons::pieces_at_floor)};
  EXPECT_EQ(total.reason.what, al::reasons::panels_at_floor);
  total += q{1, 0, 1, al::result_status::not_guaranteed, al::segment_reason(al::reasons::order_test, 3, 0.0, 1.0)};
  EXPECT_EQ(total.status, al::result_status::not_guaranteed);
  EXPECT_EQ(total.reason.segment, 3u);
  total += q{1, 0, 1, al::result_status::cap_hit, al::global_reason<double>(al::reasons::budget)};
  EXPECT_EQ(total.reason.what, al::reasons::order_test);
  EXPECT_EQ(total.value, 5);
  EXPECT_EQ(total.evaluations, 5u);
  // The inversion result carries one too (newton_inversion.hpp fills its own statuses).
  al::inversion_result<double> inv;
  EXPECT_TRUE(inv.reason.empty());
}

TEST(status_reasons, fixed_rules_without_an_estimate_say_so) {
  const auto c = bend();
  const auto none = al::gauss_length(c, 5, al::fixed_estimate::none);
  EXPECT_EQ(none.status, al::result_status::not_guaranteed);
  EXPECT_EQ(none.reason.what, al::reasons::no_estimate);
  EXPECT_EQ(none.reason.segment, npos);  // the rule's, not a segment's
  const auto part = al::gauss_length(c, 0.5, 2.5, al::gauss_legendre<double>(5), al::fixed_estimate::none);
  EXPECT_EQ(part.reason.what, al::reasons::no_estimate);
  const auto composite = al::composite_gauss_length(c, 4, al::gauss_legendre<double>(5));
  EXPECT_EQ(composite.status, al::result_status::not_guaranteed);
  EXPECT_EQ(composite.reason.what, al::reasons::composite_no_estimate);
  EXPECT_TRUE(well_formed(none, c) && well_formed(part, c) && well_formed(composite, c));
}

// The midpoint rule (n = 1) converges at order 2, so its nested differences never show the order 4
// the test asks for (|Q1 - Q2| ~ 4 |Q2 - Q4|): on the bend only the middle segment's speed varies
// (the lines' is constant: both differences are rounding), so the reason is segment 1's, after
// every halving was tried.
TEST(status_reasons, gauss_nested_names_the_segment_failing_its_order_test) {
  const auto c = bend();
  const auto r = al::gauss_length(c, 1, al::fixed_estimate::nested);
  EXPECT_EQ(r.status, al::result_status::not_guaranteed);
  EXPECT_EQ(r.reason.what, al::reasons::order_test);
  EXPECT_EQ(r.reason.segment, 1u);
  EXPECT_TRUE(well_formed(r, c));
  // The order test's quantities: |Q1 - Q2| below 16 |Q2 - Q4|.
  EXPECT_GT(r.reason.measured, 0);
  EXPECT_LT(r.reason.measured, r.reason.limit);
  // The part reported is the first failing one at the last level: 1/16 of the segment.
  EXPECT_DOUBLE_EQ(r.reason.b - r.reason.a, 1.0 / 16);
  // The same on a part of the curve from inside segment 0 to inside segment 2.
  const auto part = al::gauss_length(c, 0.5, 2.5, al::gauss_legendre<double>(1), al::fixed_estimate::nested);
  EXPECT_EQ(part.reason.segment, 1u);
  EXPECT_TRUE(well_formed(part, c));
}

TEST(status_reasons, gauss_nested_names_a_near_cusp) {
  // Two segments: a line, then bench/cases/near_cusp_cubic.json's curve (branch points at
  // 1/2 +- 1.2e-4 i, far closer than 1/8 of a piece).
  const auto c = line_middle_line({pt2(0, 0), pt2(1, 1), pt2(0.001, 1), pt2(1, 0)});  // segments 0 and 2 are lines
  const auto r = al::gauss_length(c, 8, al::fixed_estimate::nested);
  EXPECT_EQ(r.status, al::result_status::not_guaranteed);
  EXPECT_EQ(r.reason.what, al::reasons::near_cusp);
  EXPECT_EQ(r.reason.segment, 1u);
  EXPECT_LT(r.reason.measured, r.reason.limit);  // the branch point's distance against 1/8 of the piece
  EXPECT_TRUE(well_formed(r, c));
}

TEST(status_reasons, no_rounding_bound_is_named_by_every_method) {
  const auto c = unbounded_lagrange();
  const auto expect_named = [&](const al::quadrature_result<double>& r, const char* what) {
    EXPECT_EQ(r.status, al::result_status::not_guaranteed) << what;
    EXPECT_TRUE(well_formed(r, c)) << what;
  };
  // gauss and adaptive: the rounding is added last, unless a bound failed first.
  const auto a = al::adaptive_length(c);
  expect_named(a, "adaptive");
  EXPECT_EQ(a.reason.what, al::reasons::no_rounding_bound);
  al::subdivision_options<double> so;
  so.tolerance = 1e-3;
  so.max_depth = 12;
  const auto s = al::subdivision_length(c, so);
  expect_named(s, "subdivision");
  EXPECT_EQ(s.reason.what, al::reasons::no_rounding_bound);
  expect_named(al::gauss_length(c, 16, al::fixed_estimate::nested), "gauss");
  expect_named(al::forward_difference_table<double>(c, 64).length(), "forward difference");
}

TEST(status_reasons, adaptive_caps_and_floor) {
  const auto c = bend();
  // The evaluation budget: 3 first panels of 31, then no bisection affordable.
  al::adaptive_options<double> o;
  o.relative_tolerance = 1e-15;
  o.max_evaluations = 100;
  const auto budget = al::adaptive_length(c, o);
  EXPECT_EQ(budget.status, al::result_status::cap_hit);
  EXPECT_EQ(budget.reason.what, al::reasons::budget);
  EXPECT_EQ(budget.reason.segment, npos);
  // The estimate reached against the target (the curve's rounding is added to the estimate after).
  EXPECT_GT(budget.reason.measured, 0);
  EXPECT_LE(budget.reason.measured, budget.error_estimate);
  EXPECT_GT(budget.reason.measured, budget.reason.limit);
  EXPECT_TRUE(well_formed(budget, c));
  o.max_evaluations = std::size_t(1) << 24;
  o.max_intervals = 4;
  const auto intervals = al::adaptive_length(c, o);
  EXPECT_EQ(intervals.status, al::result_status::cap_hit);
  EXPECT_EQ(intervals.reason.what, al::reasons::interval_cap);
  // Below what double resolves: the panel at its floor with the largest estimate, in its segment.
  o.max_intervals = 4000;
  o.relative_tolerance = 1e-18;
  const auto floor = al::adaptive_length(c, o);
  EXPECT_EQ(floor.status, al::result_status::rounding_limited);
  EXPECT_EQ(floor.reason.what, al::reasons::panels_at_floor);
  EXPECT_NE(floor.reason.segment, npos);
  EXPECT_TRUE(well_formed(floor, c));
  // integrate_recursive (Newton's integrals): the depth cap and the budget.
  const auto f = [&c](double u) { return al::speed(c, u); };
  const auto& rule = al::gauss_kronrod<double>(7);
  const auto depth = al::integrate_recursive(f, 1.0, 2.0, 1e-20, rule, 0);
  EXPECT_EQ(depth.status, al::result_status::cap_hit);
  EXPECT_EQ(depth.reason.what, al::reasons::max_depth);
  EXPECT_EQ(depth.reason.a, 1.0);
  EXPECT_EQ(depth.reason.b, 2.0);
  const auto spent = al::integrate_recursive(f, 1.0, 2.0, 1e-20, rule, 20, 20);
  EXPECT_EQ(spent.status, al::result_status::cap_hit);
  EXPECT_EQ(spent.reason.what, al::reasons::budget);
}

TEST(status_reasons, subdivision_caps_and_floor) {
  const auto c = bend();
  al::subdivision_options<double> o;
  // 7 evaluations for segment 0 (its right end is interior), then 7 more are not affordable.
  o.max_evaluations = 10;
  const auto unmeasured = al::subdivision_length(c, o);
  EXPECT_EQ(unmeasured.status, al::result_status::cap_hit);
  EXPECT_EQ(unmeasured.reason.what, al::reasons::budget_unmeasured);
  EXPECT_EQ(unmeasured.reason.segment, 1u);
  EXPECT_EQ(unmeasured.reason.a, 1.0);
  EXPECT_EQ(unmeasured.reason.b, 2.0);
  EXPECT_TRUE(well_formed(unmeasured, c));
  o.max_evaluations = 200;
  o.relative_tolerance = 1e-12;
  const auto budget = al::subdivision_length(c, o);
  EXPECT_EQ(budget.status, al::result_status::cap_hit);
  EXPECT_EQ(budget.reason.what, al::reasons::budget);
  EXPECT_EQ(budget.reason.measured, budget.error_estimate);
  o.max_evaluations = std::size_t(1) << 22;
  o.max_depth = 3;
  const auto depth = al::subdivision_length(c, o);
  EXPECT_EQ(depth.status, al::result_status::cap_hit);
  EXPECT_EQ(depth.reason.what, al::reasons::max_depth);
  EXPECT_EQ(depth.reason.segment, 1u);  // the lines' brackets are exact: only the bend is halved
  EXPECT_EQ(depth.reason.b - depth.reason.a, 1.0 / 8);
  EXPECT_TRUE(well_formed(depth, c));
  o.max_depth = 40;
  o.relative_tolerance = 1e-19;
  const auto floor = al::subdivision_length(c, o);
  EXPECT_EQ(floor.status, al::result_status::rounding_limited);
  EXPECT_EQ(floor.reason.what, al::reasons::pieces_at_floor);
  EXPECT_TRUE(well_formed(floor, c));
}

TEST(status_reasons, tables_name_the_check_that_failed) {
  const auto c = hairpin();
  // Steps not a multiple of 4: no coarser sums.
  const al::forward_difference_table<double> odd(c, 10);
  EXPECT_EQ(odd.length().reason.what, al::reasons::table_steps);
  EXPECT_EQ(odd.richardson_length().reason.what, al::reasons::table_steps);
  EXPECT_EQ(odd.length().reason.measured, 10);
  // The hairpin's 4h chords turn back: the turn, on segment 1.
  const al::forward_difference_table<double> coarse(c, 16);
  const auto turn = coarse.length();
  EXPECT_EQ(turn.status, al::result_status::not_guaranteed);
  EXPECT_EQ(turn.reason.what, al::reasons::table_turn);
  EXPECT_EQ(turn.reason.segment, 1u);
  EXPECT_LT(turn.reason.measured, 0.5);
  EXPECT_TRUE(well_formed(turn, c));
  EXPECT_EQ(coarse.richardson_length().reason.segment, 1u);
  // Runge's polynomial at N = 20: its 4h chords turn by less than 60 degrees, but the sums creep
  // (test_arclength_honesty's trap): measured (L_2h - L_4h) / (L_h - L_2h) = 63, against the end 6.
  const auto runge = runge_lagrange(cb::lagrange_algorithm::barycentric);
  const al::forward_difference_table<double> t(runge, 20);
  EXPECT_EQ(t.length().status, al::result_status::not_guaranteed);
  EXPECT_EQ(t.length().reason.what, al::reasons::table_ratio);
  EXPECT_GT(t.length().reason.measured, 6);
  EXPECT_EQ(t.length().reason.limit, 6);
  EXPECT_EQ(t.length().reason.segment, npos);  // the sums are the whole curve's
  EXPECT_TRUE(well_formed(t.length(), runge));
}

// Every method and setting on curves that produce each status: every result not converged names a
// reason, and a segment it names holds its interval.
TEST(status_reasons, every_method_names_every_status) {
  int named = 0;
  const auto walk = [&](const auto& c, const char* name) {
    SCOPED_TRACE(name);
    std::vector<al::quadrature_result<double>> rs;
    for (int n : {1, 2, 5, 8})
      for (auto e : {al::fixed_estimate::none, al::fixed_estimate::nested}) rs.push_back(al::gauss_length(c, n, e));
    rs.push_back(al::composite_gauss_length(c, 3, al::gauss_legendre<double>(4)));
    for (double tol : {1e-6, 1e-12, 1e-18})
      for (std::size_t budget : {std::size_t(64), std::size_t(1) << 16}) {
        al::adaptive_options<double> o;
        o.relative_tolerance = tol;
        o.max_evaluations = budget;
        rs.push_back(al::adaptive_length(c, o));
        al::subdivision_options<double> so;
        so.relative_tolerance = tol;
        so.max_evaluations = budget;
        so.max_depth = 20;
        rs.push_back(al::subdivision_length(c, so));
      }
    for (std::size_t steps : {6, 16, 64, 256}) {
      const al::forward_difference_table<double> t(c, steps);
      rs.push_back(t.length());
      if (steps % 2 == 0) rs.push_back(t.richardson_length());
    }
    for (const auto& r : rs) {
      EXPECT_TRUE(well_formed(r, c));
      named += r.status == al::result_status::converged ? 0 : 1;
    }
  };
  walk(bend(), "bend");
  walk(hairpin(), "hairpin");
  walk(cusp_family(0.001), "near cusp");
  walk(road(40, 7), "road of 40 points");
  walk(unbounded_lagrange(), "monomial Lagrange");
  walk(runge_lagrange(cb::lagrange_algorithm::barycentric), "barycentric Lagrange");
  EXPECT_GT(named, 100);  // the walk does reach the statuses it checks
}

// The nested rule on many segments: on the road, pieces fail the order test by being
// pre-asymptotic (observed ratios 8 to 13 where 16 is asked), and one such piece left the whole
// length without a bound. Each is now halved and tried again, so the result is converged, and its
// estimate must bound the error. The reference is adaptive Gauss-Kronrod (a different rule: G7-K15
// panels refined globally) at 1e-14, its own estimate added (below 1e-12 L, while the nested
// estimate is about 1e-8 L): the inequality allows both estimates, nothing else.
TEST(status_reasons, nested_gauss_keeps_its_bound_on_many_segments) {
  const auto c = road(300, 32);
  const std::span<const double> bp = c.breakpoints();
  // The road exercises the halving: some segments fail the order test as one piece.
  const auto f = [&c](double u) { return al::speed(c, u); };
  const auto& rule = al::gauss_legendre<double>(5);
  int failing = 0;
  for (std::size_t i = 0; i + 1 < bp.size(); ++i)
    failing += al::detail::fixed_panel(f, bp[i], bp[i + 1], rule, al::fixed_estimate::nested).converged() ? 0 : 1;
  EXPECT_GE(failing, 3);  // measured: 9 of 299
  const auto r = al::gauss_length(c, 5, al::fixed_estimate::nested);
  EXPECT_EQ(r.status, al::result_status::converged) << to_text(r.reason);
  EXPECT_TRUE(r.reason.empty());
  al::adaptive_options<double> o;
  o.relative_tolerance = 1e-14;
  const auto reference = al::adaptive_length(c, o);
  // 1e-14 over 300 segments is at double's floor: rounding_limited, whose estimate includes it.
  ASSERT_TRUE(reference.status == al::result_status::converged ||
              reference.status == al::result_status::rounding_limited)
      << to_text(reference.reason);
  EXPECT_LT(reference.error_estimate, 1e-12 * reference.value);
  EXPECT_LE(std::abs(r.value - reference.value), r.error_estimate + reference.error_estimate);
  // The partial length over most of the road, across the same segments.
  const auto part = al::gauss_length(c, bp[3] + 0.25, bp[290] - 0.25, rule, al::fixed_estimate::nested);
  EXPECT_EQ(part.status, al::result_status::converged) << to_text(part.reason);
  const auto part_ref = al::adaptive_length(c, bp[3] + 0.25, bp[290] - 0.25, o);
  EXPECT_LE(std::abs(part.value - part_ref.value), part.error_estimate + part_ref.error_estimate);
  // Other seeds and rules: converged or named, and bounded whenever converged.
  for (unsigned seed : {1u, 2u, 3u})
    for (int n : {4, 5, 6, 8}) {
      SCOPED_TRACE("seed " + std::to_string(seed) + ", n = " + std::to_string(n));
      const auto other = road(200, seed);
      const auto q = al::gauss_length(other, n, al::fixed_estimate::nested);
      EXPECT_TRUE(well_formed(q, other));
      if (!q.converged()) continue;
      const auto qr = al::adaptive_length(other, o);
      EXPECT_LE(std::abs(q.value - qr.value), q.error_estimate + qr.error_estimate);
    }
}

// Capped subdivision on many segments: with a tolerance it cannot reach within its budget
// it refines the piece with the largest bound first, so the capped result still carries a finite
// bound, and that bound holds against adaptive Gauss-Kronrod at 1e-14 (its own estimate added).
TEST(status_reasons, capped_subdivision_on_many_segments_is_within_its_bound) {
  const auto c = road(300, 32);
  al::subdivision_options<double> s;
  s.relative_tolerance = 1e-14;
  s.max_evaluations = std::size_t(1) << 18;
  const auto r = al::subdivision_length(c, s);
  EXPECT_EQ(r.status, al::result_status::cap_hit);
  EXPECT_EQ(r.reason.what, al::reasons::budget);
  EXPECT_LE(r.evaluations, s.max_evaluations);
  ASSERT_TRUE(std::isfinite(r.error_estimate));
  al::adaptive_options<double> o;
  o.relative_tolerance = 1e-14;
  const auto reference = al::adaptive_length(c, o);
  EXPECT_LT(reference.error_estimate, 1e-12 * reference.value);
  EXPECT_LE(std::abs(r.value - reference.value), r.error_estimate + reference.error_estimate);
  EXPECT_LT(r.error_estimate, 1e-6 * reference.value);  // best first: the budget buys a useful bound
}

// The halving is bounded: a piece that keeps failing is halved nested_split_levels (4) times, 31
// tries of 7n evaluations, and then keeps not_guaranteed with its reason. On a parabola's single
// segment (speed analytic, no speed minimum inside: one piece) the midpoint rule fails at every
// level; the count is the search for speed minima (speed_features, as fixed_segment calls it) and
// exactly the 31 tries.
TEST(status_reasons, nested_gauss_halving_is_bounded) {
  const std::vector<pt2> p{pt2(0, 0), pt2(1, 2), pt2(3, 0)};
  const cb::bezier<double, 2> c{std::span<const pt2>(p)};
  std::size_t search = 0;
  std::vector<al::detail::speed_minimum<double>> shallow;
  const auto pieces = al::detail::speed_features(c, 0.0, 1.0, al::detail::fixed_minimum_samples, search, &shallow);
  ASSERT_EQ(pieces.size(), 2u);  // one piece: no deep minimum to split at
  const auto one = al::gauss_length(c, 1, al::fixed_estimate::nested);
  EXPECT_EQ(one.status, al::result_status::not_guaranteed);
  EXPECT_EQ(one.reason.what, al::reasons::order_test);
  EXPECT_EQ(one.reason.segment, 0u);
  EXPECT_EQ(al::detail::nested_split_levels, 4);
  EXPECT_EQ(one.evaluations, search + 31u * 7u);
  EXPECT_DOUBLE_EQ(one.reason.b - one.reason.a, 1.0 / 16);  // the first part of the last level
}
