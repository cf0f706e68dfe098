// Each property function of curvebench/analysis/property_audit.hpp used alone, on curves whose
// answer is a closed fact: the Bernstein basis is non-negative and sums to 1 (hull, VD), a Lagrange
// parabola through four points overshoots them by a known amount, a cubic B-spline's third
// derivative jumps by the fourth difference of its control points, Catmull-Rom's second derivative
// by 2 (P_{i+1} - P_{i-1}) - P_{i+2} + P_{i-2}, a polyline vertex moves exactly its two segments.
// Also: audit_properties equals the functions it composes, and the functions' errors.
#include "tools/property_families.hpp"

#include "curvebench/analysis/property_audit.hpp"
#include "curvebench/curves/bezier.hpp"
#include "curvebench/curves/bspline.hpp"
#include "curvebench/curves/cardinal_spline.hpp"
#include "curvebench/curves/hermite_spline.hpp"
#include "curvebench/curves/lagrange.hpp"
#include "curvebench/curves/polyline.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

namespace cb = curvebench;
namespace an = curvebench::analysis;
namespace pf = curvebench::property_families;
using pf::list2;
using pf::P2;
using pf::span2;

namespace {

constexpr double eps = std::numeric_limits<double>::epsilon();

// Tolerances, each a margin over the rounding of what is compared (quantities are O(1)):
// a closed-form distance divided by the rounded scale sqrt(8): two roundings, 4 eps leaves 2x.
constexpr double tol_distance = 4 * eps;
// a ratio of third-derivative jumps: each derivative is rounded to ~10 eps of its size, and the
// one-sided extrapolation 3 d1 - 3 d2 + d3 amplifies by 7 per side; 1e-12 leaves a margin of ~100.
constexpr double tol_jump_ratio = 1e-12;
// a distance outside the hull from a barycentric Lagrange evaluation (a few eps of the values,
// which are <= 3): 1e-14 is ~20 eps of them.
constexpr double tol_hull = 1e-14;

// Four points (0,0) (1,1) (2,1) (3,0): the Bezier curve on them stays in their hull (x = 3u,
// y = 3u(1 - u), apex 0.75); the Lagrange curve through them at u = 0, 1/3, 2/3, 1 is the parabola
// x = 3u, y = x (3 - x) / 2, apex (1.5, 1.125): 0.125 above the hull's top edge y = 1.
const list2 arch{{0, 0}, {1, 1}, {2, 1}, {3, 0}};
cb::bezier<double, 2> bezier_of(span2 p) { return cb::bezier<double, 2>(p); }
cb::lagrange<double, 2> lagrange_of(span2 p) { return cb::lagrange<double, 2>(p); }

// Seed 001's Hermite chain: points alternating with tangents.
struct chain_items {
  list2 items;
  std::vector<an::control_role> roles;
};
chain_items hermite_items() {
  chain_items c;
  for (std::size_t i = 0; i < 4; ++i) {
    c.items.push_back(pf::data()[i]);
    c.items.push_back(P2(1.0, (i % 2 == 0) ? 0.75 : -0.5));
    c.roles.push_back(an::control_role::point);
    c.roles.push_back(an::control_role::tangent);
  }
  return c;
}
cb::hermite_spline<double, 2> hermite_of(span2 items) { return cb::hermite_spline<double, 2>::chain(items); }

}  // namespace

// ---- interpolation ----

TEST(measure_interpolation, all_ends_only_none) {
  const list2& d = pf::data();
  EXPECT_EQ(an::measure_interpolation(lagrange_of(d), d).kind, an::interpolation_kind::all);
  EXPECT_EQ(an::measure_interpolation(bezier_of(d), d).kind, an::interpolation_kind::ends_only);
  EXPECT_EQ(an::measure_interpolation(pf::uniform_cubic_bspline(d), d).kind, an::interpolation_kind::none);
  EXPECT_EQ(an::measure_interpolation(pf::seed_cardinal_spline(d), d).kind, an::interpolation_kind::all_but_ends);
}

// The quadratic Bezier on (0,0) (1,2) (2,0) is the parabola y = x (2 - x): it passes through its
// end points exactly, and the nearest point to (1,2) is the apex (1,1), at distance 1 = 1/sqrt(8)
// of the data's diagonal.
TEST(measure_interpolation, distance_to_the_middle_control_point) {
  const list2 p{{0, 0}, {1, 2}, {2, 0}};
  const auto r = an::measure_interpolation(bezier_of(p), p);
  EXPECT_EQ(r.kind, an::interpolation_kind::ends_only);
  ASSERT_EQ(r.distance.size(), 3u);
  EXPECT_EQ(r.distance[0], 0.0);
  EXPECT_EQ(r.distance[2], 0.0);
  EXPECT_NEAR(r.distance[1], 1 / std::sqrt(8.0), tol_distance);
}

// Tangent items are not points: no distance, and the Hermite chain passes through every point.
TEST(measure_interpolation, tangent_items_are_skipped) {
  const chain_items c = hermite_items();
  const auto r = an::measure_interpolation(hermite_of(c.items), c.items, c.roles);
  EXPECT_EQ(r.kind, an::interpolation_kind::all);
  for (std::size_t i = 0; i < c.items.size(); ++i) EXPECT_EQ(std::isnan(r.distance[i]), i % 2 == 1) << i;
}

// ---- local control ----

// A polyline vertex moves exactly the two segments it ends (one at the ends): 2/9 and 1/9 of the
// nine segments' grid cells, and its moved range is (u_{i-1}, u_{i+1}) less one grid cell per side.
TEST(measure_local_control, polyline_vertex_moves_two_segments) {
  const list2& d = pf::data();
  const auto r = an::measure_local_control<double, 2>([](span2 p) { return cb::polyline<double, 2>(p); }, d);
  EXPECT_TRUE(r.local);
  const double cell = 1.0 / 48;
  for (std::size_t i = 0; i < d.size(); ++i) {
    const bool end = i == 0 || i + 1 == d.size();
    EXPECT_EQ(r.moved_fraction[i], end ? 1.0 / 9 : 2.0 / 9) << i;
    const double u = static_cast<double>(i);
    EXPECT_DOUBLE_EQ(r.moved_range[i].lo, i == 0 ? 0.0 : u - 1 + cell) << i;
    EXPECT_DOUBLE_EQ(r.moved_range[i].hi, i + 1 == d.size() ? 9.0 : u + 1 - cell) << i;
  }
  EXPECT_EQ(r.max_moved_fraction, 2.0 / 9);
}

// Every Bernstein polynomial of degree 9 is non-zero on (0, 1), and a sample moves when the item's
// weight B_i(u) exceeds move_threshold = eps^(3/4) ~ 1.8e-12 (the change is B_i(u) times the
// perturbation). On the 48-cell grid: P_2..P_7 move every cell; B_1 = 9u(1 - u)^8 is 3.2e-13 at
// u = 47/48 (and 7.8e-11 at 46/48), so P_1 leaves the last cell unmoved: 47/48; B_0 = (1 - u)^9 is
// 3.8e-13 at 46/48 (and 6.9e-12 at 45/48): 46/48. Symmetrically for P_8 and P_9.
TEST(measure_local_control, bezier_is_global) {
  const list2& d = pf::data();
  const auto r = an::measure_local_control<double, 2>(bezier_of, d);
  EXPECT_FALSE(r.local);
  const double expected[10] = {46.0 / 48, 47.0 / 48, 1, 1, 1, 1, 1, 1, 47.0 / 48, 46.0 / 48};
  for (std::size_t i = 0; i < d.size(); ++i) EXPECT_EQ(r.moved_fraction[i], expected[i]) << i;
  EXPECT_EQ(r.max_moved_fraction, 1.0);
}

// ---- continuity ----

// Uniform cubic B-spline: C2 at every knot, and the third derivative, constant Delta^3 P_j / h^3 on
// segment j, jumps by Delta^4 P_j: relative to the largest |Delta^3 P_k| that is the measured jump.
TEST(measure_continuity, cubic_bspline_is_c2_and_its_third_derivative_jumps_by_the_fourth_difference) {
  const list2& d = pf::data();
  const auto r = an::measure_continuity(pf::uniform_cubic_bspline(d));
  EXPECT_FALSE(r.one_piece);
  EXPECT_EQ(r.order, 2);
  EXPECT_EQ(r.max_order, 3);
  std::vector<P2> d3;
  for (std::size_t j = 0; j + 3 < d.size(); ++j) d3.push_back(d[j + 3] - 3.0 * d[j + 2] + 3.0 * d[j + 1] - d[j]);
  double d3max = 0;
  for (const P2& v : d3) d3max = std::max(d3max, v.norm());
  ASSERT_EQ(r.knots.size(), d3.size() - 1);  // ten points: seven segments, six interior knots
  for (std::size_t b = 0; b < r.knots.size(); ++b) {
    EXPECT_EQ(r.knots[b].order, 2) << b;
    EXPECT_NEAR(static_cast<double>(r.knots[b].relative_jump[3]), (d3[b + 1] - d3[b]).norm() / d3max, tol_jump_ratio)
        << b;
  }
}

// Catmull-Rom (uniform, phantom ends): C1 at every knot. With m_i = (P_{i+1} - P_{i-1}) / 2 the
// second derivative jumps at u_i by 2 (P_{i+1} - P_{i-1}) - P_{i+2} + P_{i-2} (times 1/h^2); the
// measured jumps, all divided by the same scale, keep the ratios of these.
TEST(measure_continuity, catmull_rom_is_c1_with_the_closed_form_second_derivative_jumps) {
  const list2& d = pf::data();
  const auto r = an::measure_continuity(pf::catmull_rom(d));
  EXPECT_EQ(r.order, 1);
  ASSERT_EQ(r.knots.size(), d.size() - 2);  // knots u_1 .. u_{n-2}
  auto jump = [&](std::size_t i) { return (2.0 * (d[i + 1] - d[i - 1]) - d[i + 2] + d[i - 2]).norm(); };
  for (std::size_t i = 2; i + 2 < d.size(); ++i) {
    EXPECT_EQ(r.knots[i - 1].order, 1) << i;
    EXPECT_NEAR(static_cast<double>(r.knots[i - 1].relative_jump[2] / r.knots[1].relative_jump[2]), jump(i) / jump(2),
                tol_jump_ratio)
        << i;
  }
}

// One polynomial piece has no interior knot; a lower max_continuity_order caps the answer ("at least").
TEST(measure_continuity, one_piece_and_the_order_cap) {
  const list2& d = pf::data();
  const auto lag = an::measure_continuity(lagrange_of(d));
  EXPECT_TRUE(lag.one_piece);
  EXPECT_TRUE(lag.knots.empty());
  EXPECT_EQ(lag.order, lag.max_order);
  auto opt = an::audit_options<double>::defaults();
  opt.max_continuity_order = 1;
  const auto capped = an::measure_continuity(pf::uniform_cubic_bspline(d), opt);
  EXPECT_EQ(capped.order, 1);
  EXPECT_EQ(capped.max_order, 1);
  for (const auto& k : capped.knots) EXPECT_EQ(k.relative_jump.size(), 2u);
}

// ---- affine invariance ----

// The B-spline basis sums to 1: invariant to rounding. Centripetal knots depend on distances, which
// a shear changes: not invariant. Hermite tangent items are mapped by the linear part only.
TEST(measure_affine_invariance, bspline_yes_centripetal_no_hermite_tangents_linear) {
  const list2& d = pf::data();
  const auto opt = an::audit_options<double>::defaults();
  const auto b = an::measure_affine_invariance<double, 2>(pf::clamped_cubic_bspline, d);
  EXPECT_TRUE(b.invariant);
  EXPECT_LE(b.deviation, opt.affine_tolerance);
  const auto c = an::measure_affine_invariance<double, 2>(pf::centripetal_catmull_rom, d);
  EXPECT_FALSE(c.invariant);
  EXPECT_GT(c.deviation, 1e-3);
  const chain_items h = hermite_items();
  const auto ht = an::measure_affine_invariance<double, 2>(hermite_of, h.items, h.roles);
  EXPECT_TRUE(ht.invariant);
}

// ---- convex hull ----

TEST(measure_convex_hull, bezier_inside_lagrange_outside_by_the_closed_form) {
  const auto b = an::measure_convex_hull(bezier_of(arch), arch);
  EXPECT_EQ(b.verdict, an::audit_verdict::yes);
  EXPECT_EQ(b.violation, 0.0);
  // The grid (48 cells) has u = 1/2, the apex: 0.125 outside, over the diagonal sqrt(10).
  const auto l = an::measure_convex_hull(lagrange_of(arch), arch);
  EXPECT_EQ(l.verdict, an::audit_verdict::no);
  EXPECT_NEAR(l.violation, 0.125 / std::sqrt(10.0), tol_hull);
}

TEST(measure_convex_hull, not_applicable_to_tangents_or_3d) {
  const chain_items h = hermite_items();
  EXPECT_EQ(an::measure_convex_hull(hermite_of(h.items), h.items, h.roles).verdict, an::audit_verdict::not_applicable);
  const cb::point_list<double, 3> p3{{0, 0, 0}, {1, 1, 0}, {2, 0, 1}};
  EXPECT_EQ(an::measure_convex_hull(cb::polyline<double, 3>(p3), p3).verdict, an::audit_verdict::not_applicable);
}

// ---- variation diminishing ----

// Without random lines and with four directions (0, 90, 180, 270 degrees), only the arch's one
// maximum of y is cut, by three lines just below it. Bezier: the polygon (up to y = 1) is cut twice
// like the curve (up to 0.75). Lagrange: the parabola above y = 1 is cut twice, the polygon never;
// a parabola meets a line at most twice, so 2 is also the worst excess of the full default set.
TEST(measure_variation_diminishing, bezier_yes_lagrange_no) {
  auto opt = an::audit_options<double>::defaults();
  opt.random_lines = 0;
  opt.directions = 4;
  const auto b = an::measure_variation_diminishing(bezier_of(arch), arch, {}, opt);
  EXPECT_EQ(b.verdict, an::audit_verdict::yes);
  EXPECT_EQ(b.lines_tested, 3);
  EXPECT_EQ(b.worst_excess, 0);
  const auto l = an::measure_variation_diminishing(lagrange_of(arch), arch, {}, opt);
  EXPECT_EQ(l.verdict, an::audit_verdict::no);
  EXPECT_EQ(l.lines_tested, 3);
  EXPECT_EQ(l.worst_excess, 2);
  const auto full = an::measure_variation_diminishing(lagrange_of(arch), arch);
  EXPECT_EQ(full.worst_excess, 2);
  EXPECT_EQ(an::measure_variation_diminishing(bezier_of(arch), arch).verdict, an::audit_verdict::yes);
}

TEST(measure_variation_diminishing, not_applicable_to_tangents) {
  const chain_items h = hermite_items();
  const auto r = an::measure_variation_diminishing(hermite_of(h.items), h.items, h.roles);
  EXPECT_EQ(r.verdict, an::audit_verdict::not_applicable);
  EXPECT_EQ(r.lines_tested, 0);
}

// ---- composition and errors ----

// audit_properties is the six functions on one grid: identical results for those that draw nothing
// at random, for local control (the first to draw from the seed), and for VD without random lines.
TEST(audit_properties, composes_the_property_functions) {
  const list2& d = pf::data();
  auto opt = an::audit_options<double>::defaults();
  opt.random_lines = 0;
  const auto all = an::audit_properties<double, 2>(pf::uniform_cubic_bspline, d, {}, opt);
  const auto c = pf::uniform_cubic_bspline(d);
  EXPECT_EQ(all.items, d.size());
  const auto i = an::measure_interpolation(c, d, {}, opt);
  EXPECT_EQ(i.kind, all.interpolation.kind);
  EXPECT_EQ(i.distance, all.interpolation.distance);
  const auto l = an::measure_local_control<double, 2>(pf::uniform_cubic_bspline, d, {}, opt);
  EXPECT_EQ(l.moved_fraction, all.local_control.moved_fraction);
  for (std::size_t k = 0; k < d.size(); ++k) {
    EXPECT_EQ(l.moved_range[k].lo, all.local_control.moved_range[k].lo);
    EXPECT_EQ(l.moved_range[k].hi, all.local_control.moved_range[k].hi);
  }
  const auto co = an::measure_continuity(c, opt);
  ASSERT_EQ(co.knots.size(), all.continuity.knots.size());
  for (std::size_t k = 0; k < co.knots.size(); ++k)
    EXPECT_EQ(co.knots[k].relative_jump, all.continuity.knots[k].relative_jump);
  EXPECT_EQ(an::measure_convex_hull(c, d, {}, opt).violation, all.convex_hull.violation);
  const auto v = an::measure_variation_diminishing(c, d, {}, opt);
  EXPECT_EQ(v.lines_tested, all.variation_diminishing.lines_tested);
  EXPECT_EQ(v.worst_excess, all.variation_diminishing.worst_excess);
  const auto a = an::measure_affine_invariance<double, 2>(pf::uniform_cubic_bspline, d, {}, opt);
  EXPECT_EQ(a.invariant, all.affine.invariant);
}

template <class F>
void expect_invalid(F&& f, const std::string& message) {
  try {
    f();
    ADD_FAILURE() << "accepted; expected: " << message;
  } catch (const cb::invalid_input& e) {
    EXPECT_EQ(std::string(e.what()), message);
  }
}

TEST(audit_properties, errors_name_the_argument_and_value) {
  const list2& d = pf::data();
  const auto c = pf::uniform_cubic_bspline(d);
  expect_invalid([&] { (void)an::measure_interpolation(c, list2{}); }, "items: 0 given, at least 1 required");
  expect_invalid([&] { (void)an::measure_convex_hull(c, d, std::vector<an::control_role>(2)); },
                 "roles: 2 given, must match items: 10");
  auto opt = an::audit_options<double>::defaults();
  opt.max_continuity_order = -1;
  expect_invalid([&] { (void)an::measure_continuity(c, opt); }, "max_continuity_order = -1: must be >= 0");
  opt = an::audit_options<double>::defaults();
  opt.random_lines = -1;
  expect_invalid([&] { (void)an::measure_variation_diminishing(c, d, {}, opt); }, "random_lines = -1: must be >= 0");
  opt = an::audit_options<double>::defaults();
  opt.directions = -2;
  expect_invalid([&] { (void)an::audit_properties<double, 2>(pf::uniform_cubic_bspline, d, {}, opt); },
                 "directions = -2: must be >= 0");
}
