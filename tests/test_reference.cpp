// The 50-digit references: Boost.Math integration of the speed, split at breakpoints and at the
// interior zeros/minima of the speed, agrees with every closed form to 1e-40 (lines in power and
// Bezier form, traversed monotonically and back and forth; circular arcs as rational quadratics;
// parabolas as quadratic Beziers, including the collinear back-tracking case; helices; the
// semicubical cusp); u(s) round trips; exact conversion of double control data and its checks.
#include "support/accuracy.hpp"
#include "support/fixtures.hpp"

#include "curvebench/curves/bezier.hpp"
#include "curvebench/curves/hermite_spline.hpp"
#include "curvebench/curves/lagrange.hpp"
#include "curvebench/curves/nurbs.hpp"
#include "curvebench/curves/rational_bezier.hpp"
#include "curvebench/reference/analytic_curves.hpp"
#include "curvebench/reference/arc_length.hpp"
#include "curvebench/reference/closed_forms.hpp"
#include "curvebench/reference/convert.hpp"

#include <gmock/gmock.h>

#include <boost/multiprecision/cpp_bin_float.hpp>

#include <array>
#include <memory>
#include <tuple>
#include <vector>

namespace cb = curvebench;
namespace ref = curvebench::reference;
namespace cbt = curvebench::testing;
using R = cb::real50;
using ::testing::HasSubstr;

namespace {

// Tolerances: the 1e-40 relative agreement between the 50-digit reference and each closed
// form (both are good to ~1e-45; the margin absorbs the closed forms' own cancellation, e.g. the
// asinh form of the parabola). The cusp location by Brent + Newton on P'.P'' is good to ~1e-48.
const R agreement("1e-40");
const R cusp_location("1e-40");

using p2 = cb::point<R, 2>;
using p3 = cb::point<R, 3>;

template <class C>
void expect_length(const ref::reference_arc_length<C>& r, const R& exact, const char* what) {
  EXPECT_TRUE(cbt::within_relative(r.length(), exact, static_cast<double>(agreement))) << what;
  EXPECT_LE(r.length_error(), agreement * exact) << what;
}

// A curve that counts its derivative evaluations (the whole cost of a reference) and can scale P'
// by 1 + noise * h(u), h a deterministic hash of u in [-1, 1): a stand-in for the rounding of an
// ill-conditioned evaluation, which no quadrature tolerance below it can get through.
template <class C>
struct counted_curve {
  using real_type = typename C::real_type;
  using point_type = typename C::point_type;
  static constexpr int dimension = C::dimension;
  C c;
  real_type noise{0};
  std::shared_ptr<std::size_t> calls = std::make_shared<std::size_t>(0);  // shared by the reference's copy

  [[nodiscard]] cb::interval<real_type> domain() const { return c.domain(); }
  [[nodiscard]] point_type operator()(const real_type& u) const { return c(u); }
  [[nodiscard]] std::span<const real_type> breakpoints() const { return c.breakpoints(); }
  [[nodiscard]] point_type derivative(const real_type& u, int order) const {
    ++*calls;
    point_type d = c.derivative(u, order);
    if (order == 1 && noise != 0) d *= real_type(1 + noise * hash(u));
    return d;
  }
  static real_type hash(const real_type& u) {
    const auto hi = static_cast<double>(u);  // both halves of u, so nearby real50 nodes differ
    return real_type(cbt::unit_hash(hi + 0x1p-20 * cbt::unit_hash(static_cast<double>(u - hi))));
  }
};

}  // namespace

static_assert(cb::curve<counted_curve<cb::bezier<R, 2>>>);
static_assert(cb::curve<ref::rational_quadratic<R, 2>>);
static_assert(cb::curve<ref::helix<R>>);

TEST(reference, straight_lines_in_power_and_bezier_form) {
  // p0 + x(t) d with d = (3, 4, 0)/5, monotone x(t) = t + t^3 and back-tracking x(t) = t + 2t^2 - 2.5t^3
  // (x' = 1 + 4t - 7.5t^2 vanishes at t = (4 + sqrt(46)) / 15 inside: the speed is zero there).
  const p3 d(R(3) / 5, R(4) / 5, R(0));
  const p3 p0(1, -2, R("0.5"));
  const std::array<std::array<R, 4>, 2> xs{{{R(0), R(1), R(0), R(1)}, {R(0), R(1), R(2), R("-2.5")}}};
  for (const auto& x : xs) {
    const ref::piecewise_polynomial<R, 3> line(R(0), R(1),
                                               {p3(p0 + x[0] * d), p3(x[1] * d), p3(x[2] * d), p3(x[3] * d)});
    const ref::reference_arc_length<ref::piecewise_polynomial<R, 3>> r(line);
    expect_length(r, ref::straight_polynomial_length<R>(x, R(0), R(1)), "straight power form");
  }
  // The back-tracking line has an interior zero of the speed: it must be found and split at.
  const ref::piecewise_polynomial<R, 3> back(R(0), R(1), {p0, p3(d), p3(2 * d), p3(R("-2.5") * d)});
  const ref::reference_arc_length<ref::piecewise_polynomial<R, 3>> rb(back);
  ASSERT_EQ(rb.speed_minima().size(), 1u);
  EXPECT_LT(abs(rb.speed_minima()[0] - (4 + sqrt(R(46))) / 15), cusp_location);
  // A cubic Bezier with collinear control points, non-uniform but monotone: length |P3 - P0|.
  const std::vector<p2> cps{p2(0, 0), p2(R("0.1"), R("0.2")), p2(R("2.5"), R(5)), p2(3, 6)};
  const cb::bezier<R, 2> bz(cps);
  const ref::reference_arc_length<cb::bezier<R, 2>> rz(bz);
  expect_length(rz, ref::segment_length<R, 2>(cps.front(), cps.back()), "straight Bezier");
}

TEST(reference, circular_arcs_as_rational_quadratics) {
  const R pi = boost::math::constants::pi<R>();
  for (const R& theta : {pi / 3, 2 * pi / 3, 9 * pi / 10}) {
    const R radius("1.75");
    const auto arc = ref::circular_arc_rational<R>(p2(R("0.5"), R(-1)), radius, R("0.3"), theta);
    const ref::rational_quadratic<R, 2> c(arc.p0, arc.p1, arc.p2, arc.weight);
    // the construction is on the circle: every point at distance r from the center
    for (int k = 0; k <= 8; ++k) {
      const p2 q = c(R(k) / 8) - p2(R("0.5"), R(-1));
      EXPECT_LT(abs(sqrt(q.squaredNorm()) - radius), R("1e-45"));
    }
    const ref::reference_arc_length<ref::rational_quadratic<R, 2>> r(c);
    expect_length(r, ref::circular_arc_length(radius, theta), "circle");
    for (int k = 1; k < 8; ++k) {
      const R u = R(k) / 8;
      EXPECT_TRUE(
          cbt::within_relative(r.s(u), ref::circular_arc_rational_s(radius, theta, u), static_cast<double>(agreement)))
          << "u=" << k << "/8";
    }
  }
}

TEST(reference, circles_of_the_rational_families) {
  // The families' own circles (rational_bezier's circular_arc, NURBS 9- and 7-point circles):
  // length 2 pi r (theta r for the arc) and, for the symmetric arcs, s(u) by the closed form.
  const R pi = boost::math::constants::pi<R>();
  const R radius("1.25");
  const p2 center(R("0.5"), R(-2));
  const R sweep = 3 * pi / 5;
  const auto arc = cb::circular_arc<R>(center, radius, R("0.2"), sweep);
  const ref::reference_arc_length<cb::rational_bezier<R, 2>> ra(arc);
  expect_length(ra, ref::circular_arc_length(radius, sweep), "rational_bezier circular_arc");
  for (int k = 1; k < 8; ++k)
    EXPECT_TRUE(cbt::within_relative(ra.s(R(k) / 8), ref::circular_arc_rational_s(radius, sweep, R(k) / 8),
                                     static_cast<double>(agreement)));
  const ref::reference_arc_length<cb::nurbs<R, 2>> r9(cb::nurbs_circle_9<R>(center, radius));
  expect_length(r9, 2 * pi * radius, "nurbs circle 9");
  for (int q = 0; q < 4; ++q) {  // each quarter is a symmetric rational quadratic arc of pi/2
    const R u = (R(q) + R("0.3")) / 4;
    EXPECT_TRUE(cbt::within_relative(r9.s(u),
                                     q * pi / 2 * radius + ref::circular_arc_rational_s(radius, pi / 2, R("0.3")),
                                     static_cast<double>(agreement)));
  }
  const ref::reference_arc_length<cb::nurbs<R, 2>> r7(cb::nurbs_circle_7<R>(center, radius));
  expect_length(r7, 2 * pi * radius, "nurbs circle 7");
}

TEST(reference, parabolas_as_quadratic_beziers) {
  // Generic 2D parabola (h2's bezier), a 3D one in power form, and the collinear back-tracking one
  // (P1 beyond P2: the speed vanishes inside, the closed form's D = 0 branch).
  const std::vector<p2> cps{p2(0, 0), p2(R("1.25"), R(2)), p2(R(3), R("-0.5"))};
  const cb::bezier<R, 2> bz(cps);
  const ref::reference_arc_length<cb::bezier<R, 2>> r(bz);
  expect_length(r, ref::quadratic_bezier_length(cps[0], cps[1], cps[2]), "parabola");
  for (int k = 1; k < 10; ++k) {
    const R t = R(k) / 10;
    EXPECT_TRUE(cbt::within_relative(r.s(t), ref::quadratic_bezier_length(cps[0], cps[1], cps[2], t),
                                     static_cast<double>(agreement)));
    // u(s) round trip against the closed form
    const R s = ref::quadratic_bezier_length(cps[0], cps[1], cps[2], t);
    EXPECT_LT(abs(r.u(s) - t), R("1e-38")) << "k=" << k;
  }
  const p3 q0(1, 2, 3), q1(R(-1), R("0.5"), R(4)), q2(R(2), R(2), R(-1));
  // power form of the quadratic Bezier: q0 + 2 (q1 - q0) t + (q0 - 2 q1 + q2) t^2
  const ref::piecewise_polynomial<R, 3> p3d(R(0), R(1), {q0, p3(2 * (q1 - q0)), p3(q0 - 2 * q1 + q2)});
  const ref::reference_arc_length<ref::piecewise_polynomial<R, 3>> r3(p3d);
  expect_length(r3, ref::quadratic_bezier_length(q0, q1, q2), "3D parabola");
  const std::vector<p2> back{p2(0, 0), p2(2, 1), p2(1, R("0.5"))};
  const cb::bezier<R, 2> bb(back);
  const ref::reference_arc_length<cb::bezier<R, 2>> rb(bb);
  ASSERT_EQ(rb.speed_minima().size(), 1u);
  EXPECT_LT(abs(rb.speed_minima()[0] - R(2) / 3), cusp_location);  // P' = 2 (a + t b) = 0 at t = 2/3
  expect_length(rb, ref::quadratic_bezier_length(back[0], back[1], back[2]), "back-tracking parabola");
}

TEST(reference, helix_and_semicubical_cusp) {
  const ref::helix<R> h(R("1.5"), R(3), R("0.4"), R(0), R(2));
  const ref::reference_arc_length<ref::helix<R>> rh(h);
  expect_length(rh, ref::helix_length(R("1.5"), R(3), R("0.4"), R(0), R(2)), "helix");
  EXPECT_TRUE(cbt::within_relative(rh.s(R("0.7")), ref::helix_length(R("1.5"), R(3), R("0.4"), R(0), R("0.7")),
                                   static_cast<double>(agreement)));
  // (t^2, t^3) on [-1, 1.5]: exact cusp at t = 0, an asymmetric interval so 0 is not a sample point's midpoint.
  // In the local variable t = u + 1 of piecewise_polynomial: u^2 = t^2 - 2t + 1, u^3 = t^3 - 3t^2 + 3t - 1.
  const ref::piecewise_polynomial<R, 2> cusp(R(-1), R("1.5"), {p2(1, -1), p2(-2, 3), p2(1, -3), p2(0, 1)});
  for (auto integrator : {ref::reference_integrator::gauss_kronrod, ref::reference_integrator::tanh_sinh}) {
    ref::reference_options<R> opt;
    opt.integrator = integrator;
    const ref::reference_arc_length<ref::piecewise_polynomial<R, 2>> rc(cusp, opt);
    ASSERT_EQ(rc.speed_minima().size(), 1u);
    EXPECT_LT(abs(rc.speed_minima()[0]), cusp_location);
    expect_length(rc, ref::semicubical_length(R(-1), R("1.5")), "cusp");
    EXPECT_TRUE(cbt::within_relative(rc.s(R("0.25")), ref::semicubical_length(R(-1), R("0.25")),
                                     static_cast<double>(agreement)));
  }
}

TEST(reference, closed_forms_are_consistent) {
  // Uniform straight quadratic (A = 0) and the D = 0 branch against the segment length; the cusp
  // form is additive across the cusp.
  EXPECT_EQ(ref::quadratic_bezier_length(p2(0, 0), p2(R("1.5"), 2), p2(3, 4)), R(5));
  EXPECT_TRUE(cbt::within_relative(ref::quadratic_bezier_length(p2(0, 0), p2(1, 0), p2(3, 0)), R(3), 1e-48));
  EXPECT_TRUE(cbt::within_relative(ref::semicubical_length(R(-1), R(2)),
                                   ref::semicubical_length(R(-1), R(0)) + ref::semicubical_length(R(0), R(2)), 1e-48));
  EXPECT_TRUE(cbt::within_relative(ref::semicubical_length(R(-1), R(0)), ref::semicubical_length(R(0), R(1)), 1e-48));
  const std::array<R, 4> x{R(0), R(1), R(0), R(-1)};  // x = t - t^3 on [0, 2]: up to 2/(3 sqrt 3), down to -6
  const R peak = 2 / (3 * sqrt(R(3)));
  EXPECT_TRUE(cbt::within_relative(ref::straight_polynomial_length<R>(x, R(0), R(2)), peak + (peak + 6), 1e-48));
  EXPECT_THROW((void)ref::circular_arc_rational<R>(p2(0, 0), R(1), R(0), R(4)), cb::invalid_input);
}

TEST(reference, double_curves_convert_exactly_and_conversion_is_checked) {
  const std::vector<cb::point<double, 2>> cps{{0.1, 0.2}, {1.3, 2.7}, {2.9, -0.4}, {4.1, 1.1}};
  const cb::bezier<double, 2> bd(cps);
  auto rebuild = [](const cb::bezier<double, 2>& c, auto to) {
    using To = typename decltype(to)::type;
    return cb::bezier<To, 2>(ref::exact_points<To>(c.control_points()));
  };
  const cb::bezier<R, 2> b50 = ref::convert_curve<R>(bd, rebuild);
  for (std::size_t i = 0; i < cps.size(); ++i)
    for (int d = 0; d < 2; ++d) EXPECT_EQ(b50.control_points()[i][d], R(cps[i][d]));  // exact: 0.1 stays the double 0.1
  EXPECT_NE(b50.control_points()[0][0], R("0.1"));
  // A rebuild from other data is caught at the breakpoints.
  auto wrong = [](const cb::bezier<double, 2>& c, auto to) {
    using To = typename decltype(to)::type;
    auto p = ref::exact_points<To>(c.control_points());
    p[0][0] += To(1) / 1000;
    return cb::bezier<To, 2>(p);
  };
  try {
    (void)ref::convert_curve<R>(bd, wrong);
    FAIL();
  } catch (const cb::invalid_input& e) {
    EXPECT_THAT(e.what(), HasSubstr("converted curve differs at breakpoints[0][0]"));
  }
  // A narrowing conversion that is not exact is rejected with the value named.
  try {
    (void)ref::exact_value<float>(0.1, "control_points", 3);
    FAIL();
  } catch (const cb::invalid_input& e) {
    EXPECT_STREQ(e.what(), "control_points[3] = 0.10000000000000001: does not convert exactly to the target Real");
  }
  EXPECT_EQ(ref::exact_value<float>(0.5), 0.5f);
}

TEST(reference, s_between_matches_the_closed_forms_near_and_across_splits) {
  // s_between(a, b) = s(b) - s(a): one panel when no split lies between a and b (the runner's case:
  // many answers u near one target), s(b) - s(a) when one does. Both against closed forms, in both
  // orders, with a gap from 1e-15 (a double's answer near u*) to a whole piece.
  const ref::helix<R> h(R("1.5"), R(3), R("0.4"), R(0), R(2));
  const ref::reference_arc_length<ref::helix<R>> rh(h);
  const auto helix_s = [](const R& u) { return ref::helix_length(R("1.5"), R(3), R("0.4"), R(0), u); };
  for (const char* gap : {"1e-15", "3e-9", "0.25", "1.1"}) {
    const R a("0.7"), b = a + R(gap);
    const R exact = helix_s(b) - helix_s(a);
    // Absolute 1e-40 (relative to the unit scale of the curve): the closed forms' difference is
    // itself only that accurate for the 1e-15 gap, and the runner needs ~1e-20 L.
    EXPECT_TRUE(cbt::within_relative(rh.s_between(a, b), exact, static_cast<double>(agreement), 1)) << gap;
    EXPECT_TRUE(cbt::within_relative(rh.s_between(b, a), R(-exact), static_cast<double>(agreement), 1)) << gap;
  }
  EXPECT_EQ(rh.s_between(R("0.7"), R("0.7")), R(0));
  // The back-tracking parabola has a split at its speed minimum t = 2/3: pairs on both sides of it.
  const std::vector<p2> back{p2(0, 0), p2(2, 1), p2(1, R("0.5"))};
  const cb::bezier<R, 2> bb(back);
  const ref::reference_arc_length<cb::bezier<R, 2>> rb(bb);
  const auto parabola_s = [&](const R& t) { return ref::quadratic_bezier_length(back[0], back[1], back[2], t); };
  // Across the split the partial pieces are integrated at relative tolerance 1e-30 (see s_between).
  for (const auto& [a, b, tol] :
       {std::tuple<R, R, double>(R("0.6"), R("0.7"), 1e-30), std::tuple<R, R, double>(R("0.1"), R(1), 1e-30),
        std::tuple<R, R, double>(R("0.5"), R("0.6"), 1e-40),
        std::tuple<R, R, double>(R("0.7"), R("0.7000000000000001"), 1e-40)}) {
    const R exact = parabola_s(b) - parabola_s(a);
    EXPECT_TRUE(cbt::within_relative(rb.s_between(a, b), exact, tol, 1)) << a << " " << b;
    EXPECT_TRUE(cbt::within_relative(rb.s_between(b, a), R(-exact), tol, 1)) << a << " " << b;
  }
  // A chain of 1000 short steps (check's sorted rows, each one G7-K15 panel when its estimate meets
  // the tolerance) up to 0.66, next to the speed minimum at 2/3 where the speed changes fastest:
  // 1e-40 relative, as one panel (the steps' estimates add up to far less).
  R chain(0);
  for (int k = 0; k < 1000; ++k) chain += rb.s_between(R("0.00066") * k, R("0.00066") * (k + 1));
  EXPECT_TRUE(cbt::within_relative(chain, parabola_s(R("0.66")), 1e-40, 1));
  EXPECT_THROW((void)rh.s_between(R(-1), R("0.5")), std::domain_error);
}

TEST(reference, stops_at_the_rounding_floor_of_a_noisy_speed) {
  // The segment (0, 0)-(3, 4), length 5, with P' perturbed by 1e-40 relative: the requested
  // 4096 eps (2e-47) is out of reach. Rules see |K - G| ~ 1e-41 L and their halves no better; the
  // bisection stops at the second such stagnation in a row. With depth 10 allowed, a recursion
  // that only knows the tolerance (Boost's) costs 65 samples + 2047 rules of 61 = 124932.
  using line = counted_curve<cb::bezier<R, 2>>;
  const std::vector<p2> ends{p2(0, 0), p2(3, 4)};
  line noisy{cb::bezier<R, 2>(ends), R("1e-40")};
  ref::reference_options<R> deep;
  deep.max_depth = 10;
  const ref::reference_arc_length<line> r(noisy, deep);
  EXPECT_LE(*noisy.calls, 5000u) << "evaluations";  // measured 1956: 2.5x margin, 25x below
  // The noise averages over the nodes: the length is good to the noise level, 1e-40.
  EXPECT_TRUE(cbt::within_relative(r.length(), R(5), 1e-40));
  // Honest: the estimate says the tolerance was not met (it is the noise, ~1e-41 L).
  EXPECT_GT(r.length_error(), ref::reference_options<R>{}.tolerance * 5);
  // Control: without the noise one rule meets the tolerance and the length is exact to ~eps.
  line clean{cb::bezier<R, 2>(ends)};
  const ref::reference_arc_length<line> rc(clean);
  EXPECT_LE(*clean.calls, 200u);  // measured 126: the samples and one rule
  EXPECT_TRUE(cbt::within_relative(rc.length(), R(5), 1e-47));
}

TEST(reference, ill_conditioned_runge_interpolant_costs_thousands_not_millions_of_evaluations) {
  // Degree-20 Lagrange through 1/(1 + 25 x^2) at 21 equispaced x (the runge_lagrange_equispaced
  // case): a Lebesgue constant near 1e4 puts ~1e-46 relative rounding on its 50-digit speed near
  // the ends, above the 2e-47 tolerance, and its 13 speed minima (speed 2 between wiggles of speed
  // 1e4) are graded. Measured: 24339 evaluations; before the rounding-floor stop and the
  // delta-based grading, 2423136 (130 s). The bound 1e5 keeps a 4x margin.
  // The data, parameters j/20 included, in double: the 50- and 100-digit curves are exact twins.
  const cb::point_list<double, 2> pd = cbt::runge_samples();
  std::vector<double> ud;
  for (int j = 0; j <= 20; ++j) ud.push_back(j / 20.0);
  const std::span<const cb::point<double, 2>> pts(pd);
  const std::span<const double> us(ud);
  using C50 = counted_curve<cb::lagrange<R, 2>>;
  const std::vector<R> u50 = ref::exact_values<R>(us);
  const C50 c{cb::lagrange<R, 2>(ref::exact_points<R>(pts), u50)};
  const ref::reference_arc_length<C50> r(c);
  EXPECT_LE(*c.calls, 100000u) << "evaluations";
  EXPECT_EQ(r.speed_minima().size(), 13u);
  // Against the same data at 100 digits (tolerance 1e-60: its own rounding floor is ~1e-96):
  // measured 4e-47 relative, the 50-digit speed's rounding; 1e-44 allows 250x.
  using R100 = boost::multiprecision::cpp_bin_float_100;
  const std::vector<R100> u100 = ref::exact_values<R100>(us);
  const cb::lagrange<R100, 2> c100(ref::exact_points<R100>(pts), u100);
  ref::reference_options<R100> o100;
  o100.tolerance = R100("1e-60");
  const ref::reference_arc_length<cb::lagrange<R100, 2>> r100(c100, o100);
  const R l100(r100.length());
  EXPECT_TRUE(cbt::within_relative(r.length(), l100, 1e-44));
  for (const char* u : {"0.03", "0.5", "0.97"})
    EXPECT_TRUE(cbt::within_relative(r.s(R(u)), R(r100.s(R100(u))), 1e-44, static_cast<double>(l100))) << u;
}

// A conic of weight w moves its whole length within about 1/w of the parameter's ends: at w = 1e6
// every node of a G30-K61 panel on [0, 1/2] misses the burst, both rules agree on almost nothing,
// and the estimate said converged (the reference gave L = 1.41 for 2.83). The
// chord check (arc >= chord) sends such panels on bisecting. Independent truth: the inscribed
// polygon through P(m(i / N)), m(v) = 10 v^3 - 15 v^4 + 6 v^5 clustering the nodes at both ends
// (the burst at w = 1e6 is ~5e-3 wide in v), Richardson-extrapolated from N = 4096 and 8192 (the
// polygon's deficit is O(1 / N^2) on a smooth P o m). Measured: 1.2e-18, 1.2e-19 and 1.2e-21
// relative at w = 1e3, 1e4 and 1e6 (the extrapolated polygon's own error); 1e-14 allows 1e4x and is
// far below what the missed burst cost (1.2e-6 at w = 1e4, half the length at w = 1e6).
TEST(reference, a_burst_of_speed_narrower_than_the_nodes_is_found_by_the_chord) {
  const auto polygon = [](const ref::rational_quadratic<R, 2>& c, int n) {
    R sum(0);
    p2 prev = c(R(0));
    for (int i = 1; i <= n; ++i) {
      const R v = R(i) / n;
      const R u = v * v * v * (R(10) - R(15) * v + R(6) * v * v);
      const p2 q = c(u);
      sum += sqrt((q - prev).squaredNorm());
      prev = q;
    }
    return sum;
  };
  for (const char* w : {"1e3", "1e4", "1e6"}) {
    const ref::rational_quadratic<R, 2> c(p2(R(0), R(0)), p2(R(1), R(1)), p2(R(2), R(0)), R(w));
    const R coarse = polygon(c, 4096), fine = polygon(c, 8192);
    const R truth = fine + (fine - coarse) / 3;
    const ref::reference_arc_length<ref::rational_quadratic<R, 2>> r(c);
    EXPECT_TRUE(cbt::within_relative(r.length(), truth, 1e-14))
        << "w = " << w << ": " << static_cast<double>(r.length()) << " against " << static_cast<double>(truth)
        << ", relative " << static_cast<double>(abs(r.length() - truth) / truth);
    EXPECT_GE(r.length(), fine * (1 - R("1e-40"))) << "w = " << w << ": below the inscribed polygon";
  }
}

// A 1D curve's length is its total variation: the sum of |x(r_j+1) - x(r_j)| between the zeros r_j
// of x' (closed form: x' is a quadratic per segment). This 1D Hermite spline (found by a sweep)
// has end slopes 1e-6 of its chords, so x' vanishes about 1e-7 of a segment from each knot: inside
// the first and last sampling intervals, where no sampled minimum brackets it, and at the middle
// knot the next segment's P' was sampled. The reference missed those cusps: 27.010441700892218
// (4e-14 relative short) claiming 2.9e-49; mpmath's total variation at 30 digits is
// 27.01044170089323038. Both tolerances are the file's 1e-40 (the cusps are located to ~1e-48).
TEST(reference, cusps_within_the_end_sampling_intervals_of_a_segment) {
  using p1 = cb::point<R, 1>;
  const std::vector<double> x{-4.3956121485829, 8.347203569851503, -5.920422412606312};
  const std::vector<double> m{-8.616913516939592e-06, -1.7714687517724158e-06, -5.018719425729576e-06};
  cb::point_list<R, 1> values, slopes;
  for (std::size_t i = 0; i < x.size(); ++i) {
    values.push_back(p1(R(x[i])));
    slopes.push_back(p1(R(m[i])));
  }
  const cb::hermite_spline<R, 1> c({R(0), R(1), R(2)}, values, slopes);
  // The closed form, segment by segment: x(t) = a t^3 + b t^2 + c t + d on t in [0, 1].
  R exact(0);
  for (std::size_t i = 0; i + 1 < x.size(); ++i) {
    const R p0(x[i]), p1v(x[i + 1]), m0(m[i]), m1(m[i + 1]);
    const R a = R(2) * (p0 - p1v) + m0 + m1, b = R(3) * (p1v - p0) - R(2) * m0 - m1, cc = m0;
    const auto at = [&](const R& t) { return ((a * t + b) * t + cc) * t + p0; };
    // x' = 3a t^2 + 2b t + c: the stable quadratic formula (no cancellation between b and the root).
    const R A = R(3) * a, B = R(2) * b, disc = B * B - R(4) * A * cc;
    std::vector<R> ts{R(0)};
    if (disc > 0) {
      const R q = -(B + (B < 0 ? -sqrt(disc) : sqrt(disc))) / 2;
      std::vector<R> roots{q / A, cc / q};
      std::sort(roots.begin(), roots.end());
      for (const R& r : roots)
        if (r > 0 && r < 1) ts.push_back(r);
    }
    ts.push_back(R(1));
    for (std::size_t j = 0; j + 1 < ts.size(); ++j) exact += abs(at(ts[j + 1]) - at(ts[j]));
  }
  EXPECT_TRUE(cbt::within_relative(exact, R("27.01044170089323038"), 1e-18)) << "the closed form against mpmath";
  const ref::reference_arc_length<cb::hermite_spline<R, 1>> r(c);
  expect_length(r, exact, "1D Hermite with end cusps");
  // x' changes sign near both ends of the first segment; the second, falling with falling end
  // slopes, has none.
  EXPECT_EQ(r.speed_minima().size(), 2u);
}

// A circle of radius 1e-150 centred at (1e10, 1e10): at 50 digits its control points all round to
// the centre, so its speed is the rounding of the quotient rule (~1e-40), noise with sampled minima
// everywhere. Each minimum was graded and each piece halved through the extra levels meant for
// truncation-sized estimates: 46 million evaluations (6 minutes) with a per-piece cap of 64 panels,
// and `check --lengths` on it never finished. Such a segment (whole sampled length below 2^10 eps
// of its points' size) is one rule now, and its error must cover the distance to the true length,
// 2 pi 1e-150 (~0 next to the noise).
TEST(reference, a_speed_of_pure_rounding_noise_is_one_rule_with_an_honest_error) {
  using circle = counted_curve<cb::nurbs<R, 2>>;
  const circle c{cb::nurbs_circle_9<R>(p2(R("1e10"), R("1e10")), R("1e-150"))};
  const ref::reference_arc_length<circle> r(c);
  // 4 quarter arcs: 65 samples, 3 points and one rule of 61 each; 2000 leaves room for a few
  // minimum searches, 4 orders of magnitude below the runaway.
  EXPECT_LE(*c.calls, 2000u) << "evaluations";
  EXPECT_TRUE(r.speed_minima().empty());
  const R truth = R(2) * boost::math::constants::pi<R>() * R("1e-150");
  EXPECT_GE(r.length_error(), abs(r.length() - truth))
      << "length " << static_cast<double>(r.length()) << ", estimate " << static_cast<double>(r.length_error());
  EXPECT_GE(r.s_result(R("0.3")).error_estimate, abs(r.s(R("0.3"))));
  // Control: radius 1e-30 is resolved, with no noise bound in its estimate. Its control points
  // 1e10 +- 1e-30 carry 50-digit rounding of ~1e-40, 1e-10 of the radius, so the curve is a circle
  // to 1e-10 only (measured 2.2e-12 from 2 pi 1e-30; 1e-9 allows 450x).
  const circle real{cb::nurbs_circle_9<R>(p2(R("1e10"), R("1e10")), R("1e-30"))};
  const ref::reference_arc_length<circle> rr(real);
  EXPECT_TRUE(cbt::within_relative(rr.length(), R(2) * boost::math::constants::pi<R>() * R("1e-30"), 1e-9));
  // Its estimate is the quadrature's at the speed's rounding floor (measured 1.2e-12 of L), not the
  // noise bound, which is at least the length itself.
  EXPECT_LT(rr.length_error(), R("1e-9") * rr.length());
}
