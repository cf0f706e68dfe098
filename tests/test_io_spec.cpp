// JSON specs -> curves: each type builds the same curve as the family's constructor, the real50
// twin holds exactly the same control data, and malformed specs get errors naming the field.
#include "support/accuracy.hpp"

#include "curvebench/io/spec.hpp"

#include <gmock/gmock.h>

#include <cmath>
#include <numbers>

namespace cb = curvebench;
namespace io = curvebench::io;
namespace cbt = curvebench::testing;
using ::testing::HasSubstr;

namespace {

template <int Dim>
cb::any_curve<double, Dim> make(const std::string& text) {
  const auto j = io::parse(text);
  return io::curve_from_spec<double, Dim>(io::root(j));
}

std::string error_of(const std::string& text) {
  try {
    const auto j = io::parse(text);
    const auto spec = io::root(j);
    if (io::spec_dimension(spec) == 3)
      (void)io::curve_from_spec<double, 3>(spec);
    else
      (void)io::curve_from_spec<double, 2>(spec);
  } catch (const io::spec_error& e) {
    return e.what();
  }
  return "(no error)";
}

// The same curve twice (spec and constructor) must agree bit for bit: one code path.
template <class A, class B>
void expect_same_curve(const A& a, const B& b) {
  ASSERT_EQ(a.domain().lo, b.domain().lo);
  ASSERT_EQ(a.domain().hi, b.domain().hi);
  for (int k = 0; k <= 16; ++k) {
    const double u = a.domain().lo + (a.domain().hi - a.domain().lo) * k / 16.0;
    ASSERT_EQ(a(u), b(u)) << u;
    ASSERT_EQ(a.derivative(u, 1), b.derivative(u, 1)) << u;
  }
}

}  // namespace

TEST(io_spec, each_type_builds_the_family) {
  using p2 = cb::point<double, 2>;
  const cb::point_list<double, 2> pts{{0, 0}, {1, 2}, {3, 3}, {4, 0}, {6, 1}};
  expect_same_curve(make<2>(R"({"type": "polyline", "points": [[0,0],[1,2],[3,3],[4,0],[6,1]]})"),
                    cb::polyline<double, 2>(std::span<const p2>(pts)));
  expect_same_curve(make<2>(R"({"type": "bezier", "points": [[0,0],[1,2],[3,3],[4,0],[6,1]]})"),
                    cb::bezier<double, 2>(std::span<const p2>(pts)));
  const std::vector<double> w{1, 2, 0.5, 1, 3};
  expect_same_curve(make<2>(R"({"type": "rational_bezier", "points": [[0,0],[1,2],[3,3],[4,0],[6,1]],
                                "weights": [1, 2, 0.5, 1, 3]})"),
                    cb::rational_bezier<double, 2>(std::span<const p2>(pts), std::span<const double>(w)));
  cb::cardinal_options<double, 2> co;
  co.alpha = 0.5;
  expect_same_curve(make<2>(R"({"type": "catmull_rom", "alpha": 0.5, "points": [[0,0],[1,2],[3,3],[4,0],[6,1]]})"),
                    cb::cardinal_spline<double, 2>(pts, co));
  co.s = (1 - 0.2) / 2;
  expect_same_curve(
      make<2>(R"({"type": "cardinal", "tension": 0.2, "alpha": 0.5, "points": [[0,0],[1,2],[3,3],[4,0],[6,1]]})"),
      cb::cardinal_spline<double, 2>(pts, co));
  const std::vector<double> knots{0, 1, 2, 3, 4};
  expect_same_curve(
      make<2>(R"({"type": "natural_cubic", "end": "not_a_knot", "points": [[0,0],[1,2],[3,3],[4,0],[6,1]]})"),
      cb::natural_cubic_spline<double, 2>(knots, pts, cb::spline_end::not_a_knot));
  std::vector<cb::tcb<double>> keys(5, cb::tcb<double>{0.5, -0.25, 0.1});
  expect_same_curve(make<2>(R"({"type": "kochanek_bartels", "tension": 0.5, "continuity": -0.25, "bias": 0.1,
                                "points": [[0,0],[1,2],[3,3],[4,0],[6,1]]})"),
                    cb::kochanek_bartels<double, 2>(pts, keys, {}));
  expect_same_curve(make<2>(R"({"type": "bspline", "degree": 3, "points": [[0,0],[1,2],[3,3],[4,0],[6,1]]})"),
                    cb::bspline<double, 2>(4, cb::bspline_clamped_knots<double>(5, 4), pts));
  expect_same_curve(make<2>(R"({"type": "nurbs", "degree": 2, "weights": [1, 2, 0.5, 1, 3],
                                "points": [[0,0],[1,2],[3,3],[4,0],[6,1]]})"),
                    cb::nurbs<double, 2>(3, cb::bspline_clamped_knots<double>(5, 3), pts, w));
  expect_same_curve(make<2>(R"({"type": "circle", "center": [1, 2], "radius": 3})"),
                    cb::nurbs_circle_9<double>(p2(1, 2), 3.0));
  expect_same_curve(make<2>(R"({"type": "arc", "center": [0, 0], "radius": 2, "start": 0.5, "sweep": 2})"),
                    cb::circular_arc<double>(p2(0, 0), 2.0, 0.5, 2.0));
  const cb::point_list<double, 2> slopes{{1, 0}, {1, 1}, {0, 1}, {-1, 0}, {1, 1}};
  expect_same_curve(
      make<2>(R"({"type": "hermite", "knots": [0, 0.5, 2, 3, 7], "points": [[0,0],[1,2],[3,3],[4,0],[6,1]],
                                "slopes": [[1,0],[1,1],[0,1],[-1,0],[1,1]]})"),
      cb::hermite_spline<double, 2>({0, 0.5, 2, 3, 7}, pts, slopes));
  const std::vector<double> cheb = cb::chebyshev_parameters<double>(5);
  expect_same_curve(make<2>(R"({"type": "lagrange", "nodes": "chebyshev", "points": [[0,0],[1,2],[3,3],[4,0],[6,1]]})"),
                    cb::lagrange<double, 2>(std::span<const p2>(pts), std::span<const double>(cheb)));
  expect_same_curve(
      make<2>(R"({"type": "lagrange", "algorithm": "monomial", "points": [[0,0],[1,2],[3,3],[4,0],[6,1]]})"),
      cb::lagrange<double, 2>(std::span<const p2>(pts), cb::lagrange_algorithm::monomial));
  const std::vector<cb::point_list<double, 2>> segs{{{0, 0}, {1, 1}, {2, 0}}, {{2, 0}, {3, -1}, {3, 2}, {4, 0}}};
  const std::vector<double> seg_knots{0, 1, 3};
  expect_same_curve(make<2>(R"({"type": "composite_bezier", "knots": [0, 1, 3],
                                "segments": [[[0,0],[1,1],[2,0]], [[2,0],[3,-1],[3,2],[4,0]]]})"),
                    cb::composite_bezier<double, 2>(std::span<const cb::point_list<double, 2>>(segs),
                                                    std::span<const double>(seg_knots)));
  expect_same_curve(make<2>(R"({"type": "conic", "points": [[0,0],[1,1],[2,0]], "w": 0.5})"),
                    cb::conic<double, 2>(p2(0, 0), p2(1, 1), p2(2, 0), 0.5));
  expect_same_curve(make<2>(R"({"type": "circle", "center": [1, 2], "radius": 3, "control": 7})"),
                    cb::nurbs_circle_7<double>(p2(1, 2), 3.0));
  expect_same_curve(make<2>(R"({"type": "bspline", "degree": 3, "knot_vector": "periodic",
                                "points": [[0,0],[1,2],[3,3],[4,0],[6,1]]})"),
                    cb::periodic_bspline<double, 2>(4, std::span<const p2>(pts)));
  expect_same_curve(make<2>(R"({"type": "bezier", "domain": [2, 5], "points": [[0,0],[1,2],[3,3],[4,0],[6,1]]})"),
                    cb::bezier<double, 2>(std::span<const p2>(pts), cb::interval<double>{2, 5}));
  // 3D, and the metadata fields of a case file
  const auto helix = make<3>(R"({"type": "catmull_rom", "name": "h", "group": "smooth", "reason": "r",
                                 "points": [[1,0,0],[0,1,0.5],[-1,0,1],[0,-1,1.5],[1,0,2]]})");
  EXPECT_EQ(helix.family(), "catmull_rom");
  EXPECT_EQ(helix(0.0), (cb::point<double, 3>(1, 0, 0)));
}

TEST(io_spec, real50_twin_holds_the_same_control_data) {
  // 0.1 is not a binary fraction: the 50-digit curve must interpolate the double 0.1, not the decimal 0.1.
  const auto j = io::parse(R"({"type": "natural_cubic", "points": [[0.1, 0.3], [1.7, 2.9], [3.3, 0.7]]})");
  const auto c50 = io::curve_from_spec<cb::real50, 2>(io::root(j));
  EXPECT_EQ(c50(cb::real50(0))[0], cb::real50(0.1));
  EXPECT_EQ(c50(cb::real50(2))[1], cb::real50(0.7));
  EXPECT_NE(c50(cb::real50(0))[0], cb::real50("0.1"));
}

TEST(io_spec, real50_twin_of_derived_data_is_exact) {
  // Knots from |dP|^alpha, Chebyshev parameters, clamped knot fractions, s from tension and the
  // circle's sqrt(2)/2 weights are computed once in double; the 50-digit curve gets those doubles,
  // so its breakpoints (and domain) are exactly the double curve's.
  for (const char* text :
       {R"({"type": "catmull_rom", "alpha": 0.5, "points": [[0,0],[1,2],[3,3],[4,0],[6,1]]})",
        R"({"type": "cardinal", "tension": 0.3, "alpha": 1, "end": "closed", "points": [[0,0],[1,2],[3,3],[4,0]]})",
        R"({"type": "catmull_rom", "alpha": 0.3, "end": "control_points", "points": [[0,0],[1,2],[3,3],[4,0],[6,1]]})",
        R"({"type": "lagrange", "nodes": "chebyshev", "points": [[0,0],[1,2],[3,3],[4,0],[6,1]]})",
        R"({"type": "bspline", "degree": 3, "points": [[0,0],[1,2],[3,3],[4,0],[6,1],[7,0],[8,2]]})",
        R"({"type": "circle", "center": [1, 2], "radius": 3})",
        R"({"type": "arc", "center": [0, 0], "radius": 2, "start": 0.5, "sweep": 2})"}) {
    const auto j = io::parse(text);
    const auto c = io::curve_from_spec<double, 2>(io::root(j));
    const auto c50 = io::curve_from_spec<cb::real50, 2>(io::root(j));
    const auto b = c.breakpoints();
    const auto b50 = c50.breakpoints();
    ASSERT_EQ(b.size(), b50.size()) << text;
    for (std::size_t i = 0; i < b.size(); ++i) {
      EXPECT_EQ(b50[i], cb::real50(b[i])) << text << " breakpoint " << i;
      // Same data: the double value is the 50-digit value rounded, up to double's evaluation error
      // (a few ulps of the curve's size, here <= 8).
      const auto p = c(b[i]);
      const auto p50 = c50(cb::real50(b[i]));
      EXPECT_TRUE((cbt::point_within<double, 2>(p, p50, cb::real50(8), 8))) << text << " at " << b[i];
    }
    EXPECT_EQ(c50.family(), c.family());
  }
}

TEST(io_spec, generated_points) {
  const auto helix = make<3>(R"({"type": "catmull_rom", "points": {"generate": "helix", "count": 9, "radius": 2,
                                                                    "pitch": 0.5, "turns": 1}})");
  // Catmull-Rom interpolates: the knot values are the generated points (double trigonometry).
  EXPECT_EQ(helix(0.0), (cb::point<double, 3>(2, 0, 0)));
  EXPECT_EQ(helix(2.0),
            (cb::point<double, 3>(2 * std::cos(std::numbers::pi / 2), 2 * std::sin(std::numbers::pi / 2), 0.125)));
  EXPECT_EQ(helix.domain().hi, 8.0);
  const auto runge = make<2>(R"({"type": "polyline", "points": {"generate": "runge", "count": 5}})");
  EXPECT_EQ(runge(2.0), (cb::point<double, 2>(0, 1)));
  EXPECT_EQ(runge(4.0), (cb::point<double, 2>(1, 1.0 / 26)));
  EXPECT_THAT(error_of(R"({"type": "polyline", "points": {"generate": "runge", "count": 1}})"),
              HasSubstr("spec.points.count: 1 is not allowed (2 to 1000000 points"));
  // The limit is checked before any point is made (1e7 points took 44 s and 6.9 GB).
  EXPECT_THAT(error_of(R"({"type": "polyline", "points": {"generate": "runge", "count": 10000000}})"),
              HasSubstr("spec.points.count: 10000000 is not allowed (2 to 1000000 points"));
  EXPECT_THAT(error_of(R"({"type": "polyline", "points": {"generate": "koch", "count": 4}})"),
              HasSubstr("spec.points.generate: \"koch\" is not one of"));
}

TEST(io_spec, malformed_specs_name_the_field) {
  EXPECT_EQ(error_of(R"({"type": "bezir", "points": [[0,0],[1,1]]})").substr(0, 44),
            "spec.type: \"bezir\" is not a curve type (type");
  EXPECT_THAT(error_of(R"({"type": "bspline", "points": [[0,0],[1,1],[2,0]]})"), HasSubstr("spec: degree is missing"));
  EXPECT_THAT(error_of(R"({"type": "bspline", "degree": 2.5, "points": [[0,0],[1,1],[2,0]]})"),
              HasSubstr("spec.degree: expected an integer, got 2.5"));
  EXPECT_THAT(error_of(R"({"type": "cardinal", "tenson": 0.3, "points": [[0,0],[1,1],[2,0]]})"),
              HasSubstr("spec: unknown field \"tenson\" for type \"cardinal\""));
  EXPECT_THAT(error_of(R"({"type": "nurbs", "degree": 2, "points": [[0,0],[1,1],[2,0]], "weights": [1, -1, 1]})"),
              HasSubstr("spec (type \"nurbs\"): weights[1] = -1: must be > 0"));
  EXPECT_THAT(error_of(R"({"type": "catmull_rom", "alpha": 0.5, "points": [[0,0],[0,0],[2,0]]})"),
              HasSubstr("spec (type \"catmull_rom\"): points[1] repeats points[0]"));
  EXPECT_THAT(error_of(R"({"type": "natural_cubic", "end": "clamped", "points": [[0,0],[1,1]]})"),
              HasSubstr("spec: start_slope is missing (end is \"clamped\")"));
  EXPECT_THAT(error_of(R"({"type": "kochanek_bartels", "bias": [0, 1], "points": [[0,0],[1,1],[2,0]]})"),
              HasSubstr("spec.bias: expected a number or 3 numbers (one per key), got 2"));
  EXPECT_THAT(error_of(R"({"type": "polyline", "points": [[0,0],[1,1,1]]})"),
              HasSubstr("spec.points[1]: expected an array of 2 numbers, got [1,1,1]"));
  EXPECT_THAT(error_of(R"({"type": "circle", "center": [0, 0], "radius": 1, "control": 8})"),
              HasSubstr("spec.control: 8 is not allowed (9 or 7 control points)"));
  EXPECT_THAT(error_of(R"({"type": "conic", "points": [[0,0],[1,1]], "w": 1})"),
              HasSubstr("spec.points: a conic has exactly 3 points, got 2"));
  // Arcs and circles are resolved into rational data before they are built: a misspelled field
  // must be refused before that drops it.
  EXPECT_THAT(error_of(R"({"type": "arc", "center": [0, 0], "radius": 2, "start": 0, "sweep": 1, "swep": 2})"),
              HasSubstr("spec: unknown field \"swep\" for type \"arc\""));
  EXPECT_THAT(error_of(R"(["not", "an", "object"])"), HasSubstr("spec: expected an object"));
  // An unknown type without points: its dimension is asked of the points before the build names
  // the type, and that message quoted the whole type (a 9 kB type gave 6 kB: fuzz spec).
  // Cut to 80 characters as every quoted string is: the message stays under 200.
  const std::string long_type(9000, '[');
  const std::string e = error_of(R"({"type": "catmull_)" + long_type + R"("})");
  EXPECT_LT(e.size(), 200u) << e.substr(0, 300);
  EXPECT_THAT(e, HasSubstr("points is missing (every spec of type \"catmull_[[["));
}

// end "duplicate" (game engines clamp the index, so P_-1 = P_0 and P_n+1 = P_n): the uniform
// Catmull-Rom through every point, from the first to the last on [0, n-1] with u = i at point i (the
// engine's own parameter), whose slope at a point is half the chord between its neighbours: at the
// ends half the end chord.
TEST(io_spec, catmull_rom_end_duplicate_is_the_engines_clamped_index) {
  const cb::point_list<double, 2> pts{{0, 0}, {1, 2}, {3, 3}, {4, 0}};
  const auto j = io::parse(R"({"type": "catmull_rom", "points": [[0,0],[1,2],[3,3],[4,0]], "end": "duplicate"})");
  const auto c = io::curve_from_spec<double, 2>(io::root(j));
  EXPECT_EQ(c.domain().lo, 0.0);
  EXPECT_EQ(c.domain().hi, 3.0);
  for (int i = 0; i < 4; ++i) EXPECT_EQ(c(static_cast<double>(i)), pts[static_cast<std::size_t>(i)]) << i;
  // Slopes in u (unit knot spacing): (P_1 - P_0) / 2 = (0.5, 1) at the start, (P_3 - P_2) / 2 =
  // (0.5, -1.5) at the end, (P_2 - P_0) / 2 = (1.5, 1.5) at P_1: exact in double.
  EXPECT_EQ(c.derivative(0.0, 1), (cb::point<double, 2>{0.5, 1}));
  EXPECT_EQ(c.derivative(3.0, 1), (cb::point<double, 2>{0.5, -1.5}));
  EXPECT_EQ(c.derivative(1.0, 1), (cb::point<double, 2>{1.5, 1.5}));
  // Between points, the uniform Catmull-Rom segment of P_-1 = P_0, P_0, P_1, P_2 at its middle:
  // (-P_-1 + 9 P_0 + 9 P_1 - P_2) / 16 = (8 P_0 + 9 P_1 - P_2) / 16 = (6, 15) / 16, exact in double.
  EXPECT_EQ(c(0.5), (cb::point<double, 2>{6.0 / 16, 15.0 / 16}));
  // The same at 50 digits, and the refusals name the field.
  const auto c50 = io::curve_from_spec<cb::real50, 2>(io::root(j));
  EXPECT_EQ(c50(cb::real50(2.5)), (cb::point<cb::real50, 2>(c(2.5))));
  EXPECT_THAT(error_of(R"({"type": "catmull_rom", "points": [[0,0],[1,2],[3,3]], "end": "duplicate", "alpha": 0.5})"),
              HasSubstr("spec.alpha"));
  EXPECT_THAT(
      error_of(R"({"type": "catmull_rom", "points": [[0,0],[1,2],[3,3]], "end": "duplicate", "knots": [0,1,2]})"),
      HasSubstr("spec.knots"));
}

TEST(io_spec, catmull_rom_and_cardinal_with_end_control_points) {
  // The textbook Catmull-Rom: the first and last of the eight points only shape the end segments.
  const std::string points = "[[0,0],[1,2],[3,3],[4,0],[6,1],[7,4],[9,3],[10,0]]";
  const cb::point_list<double, 2> pts{{0, 0}, {1, 2}, {3, 3}, {4, 0}, {6, 1}, {7, 4}, {9, 3}, {10, 0}};
  const auto j =
      io::parse(R"({"type": "catmull_rom", "points": )" + points + R"(, "alpha": 0.5, "end": "control_points"})");
  cb::cardinal_options<double, 2> co;
  co.alpha = 0.5;
  co.end = cb::cardinal_end::control_points;
  const cb::cardinal_spline<double, 2> lib(pts, co);
  const auto c = io::curve_from_spec<double, 2>(io::root(j));
  expect_same_curve(c, lib);
  // The curve runs from P_1 to P_6 on [u_1, u_6] of the centripetal knots of all eight points.
  const auto knots = cb::alpha_knots<double, 2>(std::span<const cb::point<double, 2>>(pts), 0.5);
  EXPECT_EQ(c.domain().lo, knots[1]);
  EXPECT_EQ(c.domain().hi, knots[6]);
  EXPECT_EQ(c(c.domain().lo), pts[1]);
  // real50: the spec's knots are resolved once in double; the 50-digit twin is the library's
  // 50-digit spline on those knots and the same points, bit for bit.
  const auto c50 = io::curve_from_spec<cb::real50, 2>(io::root(j));
  cb::cardinal_options<cb::real50, 2> co50;
  co50.end = cb::cardinal_end::control_points;
  const cb::cardinal_spline<cb::real50, 2> lib50(std::vector<cb::real50>(knots.begin(), knots.end()),
                                                 cb::points_cast<cb::real50, double, 2>(pts), co50);
  ASSERT_EQ(c50.domain().lo, lib50.domain().lo);
  ASSERT_EQ(c50.domain().hi, lib50.domain().hi);
  for (int k = 0; k <= 16; ++k) {
    const cb::real50 u = lib50.domain().lo + (lib50.domain().hi - lib50.domain().lo) * k / 16;
    ASSERT_EQ(c50(u), lib50(u)) << k;
    ASSERT_EQ(c50.derivative(u, 1), lib50.derivative(u, 1)) << k;
    // And the double curve is its rounding (a few ulps of the size 10, here <= 8).
    const double ud = static_cast<double>(u);
    ASSERT_TRUE((cbt::point_within<double, 2>(c(ud), c50(cb::real50(ud)), cb::real50(10), 8))) << k;
  }
  // The cardinal type takes the same end, with its tension, and given knots.
  co.s = (1 - 0.4) / 2.0;
  expect_same_curve(
      make<2>(R"({"type": "cardinal", "tension": 0.4, "alpha": 0.5, "end": "control_points", "points": )" + points +
              "}"),
      cb::cardinal_spline<double, 2>(pts, co));
  co.alpha = 0;
  const std::vector<double> given{0, 1, 1.5, 3, 4, 4.25, 6, 7};
  expect_same_curve(
      make<2>(
          R"({"type": "cardinal", "tension": 0.4, "end": "control_points", "knots": [0, 1, 1.5, 3, 4, 4.25, 6, 7], "points": )" +
          points + "}"),
      cb::cardinal_spline<double, 2>(given, pts, co));
  // Too few points: the error names the field, the count and the end mode; a repeated point with
  // alpha > 0 is still refused.
  for (const char* type : {"catmull_rom", "cardinal"})
    for (const char* alpha : {"0", "0.5"})
      EXPECT_THAT(error_of(std::string(R"({"type": ")") + type + R"(", "alpha": )" + alpha +
                           R"(, "end": "control_points", "points": [[0,0],[1,1],[2,0]]})"),
                  HasSubstr("points: 3 given, at least 4 required (end = control_points"))
          << type << " alpha " << alpha;
  EXPECT_THAT(
      error_of(
          R"({"type": "catmull_rom", "alpha": 0.5, "end": "control_points", "points": [[0,0],[1,1],[1,1],[2,0]]})"),
      HasSubstr("points[2] repeats points[1]"));
  EXPECT_THAT(error_of(R"({"type": "catmull_rom", "end": "control", "points": [[0,0],[1,1],[2,0],[3,1]]})"),
              HasSubstr("spec.end: \"control\" is not one of"));
}
