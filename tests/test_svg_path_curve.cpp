// The "svg_path" family (io/families/svg_path.hpp): a path's curve has the closed-form lengths of
// its arcs (a circle 2 pi r; an ellipse 4 a E(k), Boost's complete elliptic integral of the second
// kind at 50 digits), the same length as the Bezier spec of its lines and Beziers (S and T
// reflected), subpaths add their lengths, the methods bound their error on a path of every
// command, and bad path data is refused naming the field and the offset.
//
// Tolerances: an arc's pieces are computed at 50 digits from the arc as written, so the 50-digit
// curve is the ellipse itself: its length is the closed form to 1e-40 relative (the reference's own
// bound is below 1e-40 L). A path of the same double data as a Bezier spec has the same 50-digit
// length: 1e-40. (An ellipse turned by 30 degrees through ends written to 16 digits is not this
// ellipse: its ends are 1e-16 inside it, Lambda = 1 - 1e-16 moves the centre by sqrt(1e-16) of the
// radii, and the arc written is 6e-9 longer. Computed in double, Lambda rounded to 1 and hid it.)
#include "support/fixtures.hpp"
#include "support/source_dir.hpp"

#include "curvebench/arclength/length.hpp"
#include "curvebench/core/any_curve.hpp"
#include "curvebench/io/spec.hpp"
#include "curvebench/reference/arc_length.hpp"
#include "curvebench/reference/multiprecision.hpp"

#include <boost/math/constants/constants.hpp>
#include <boost/math/special_functions/ellint_2.hpp>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>

namespace cb = curvebench;
namespace cbt = curvebench::testing;
using R = cb::real50;
using ::testing::HasSubstr;

namespace {

R length_of(const std::string& spec_text) {
  const auto j = cb::io::parse(spec_text);
  const cb::reference::reference_arc_length<cb::any_curve<R, 2>> ref(cb::io::curve_from_spec<R, 2>(cb::io::root(j)));
  EXPECT_LT(ref.length_error(), R("1e-40") * ref.length()) << spec_text;
  return ref.length();
}

std::string path(const std::string& d) { return R"({"type": "svg_path", "d": ")" + d + R"("})"; }

void expect_relative(const R& got, const R& want, const R& tol, const std::string& what) {
  EXPECT_LT(abs(got - want), tol * abs(want)) << what << ": got " << cb::to_text(got) << ", want " << cb::to_text(want);
}

}  // namespace

TEST(svg_path_curve, arcs_have_their_closed_form_lengths) {
  const R pi = boost::math::constants::pi<R>();
  expect_relative(length_of(path("M10 0 A10 10 0 0 1 -10 0 A10 10 0 0 1 10 0")), 20 * pi, R("1e-40"), "circle");
  expect_relative(length_of(path("M1 0 A1 1 0 0 1 0 1")), pi / 2, R("1e-40"), "quarter circle");
  expect_relative(length_of(path("M1 0 A1 1 0 1 0 0 1")), 3 * pi / 2, R("1e-40"), "three quarters");
  // Radii too small: scaled to half the circle through both ends.
  expect_relative(length_of(path("M0 0 A1 1 0 0 1 10 0")), 5 * pi, R("1e-40"), "corrected radius");
  const R ellipse = 4 * 5 * boost::math::ellint_2(R("0.8"));  // a = 5, b = 3: k = sqrt(1 - 9 / 25)
  expect_relative(length_of(path("M5 0 A5 3 0 0 1 -5 0 A5 3 0 0 1 5 0")), ellipse, R("1e-40"), "ellipse");
  // The same ellipse turned by 90 degrees: its ends (0, 5) and (0, -5) are exact.
  expect_relative(length_of(path("M0 5 A5 3 90 1 1 0 -5 A5 3 90 1 1 0 5")), ellipse, R("1e-40"), "rotated ellipse");
}

TEST(svg_path_curve, lines_and_beziers_are_the_segments_as_written) {
  expect_relative(length_of(path("M0 0 L3 4 M10 10 l0 5")), R(10), R("1e-40"), "two subpaths: 5 + 5");
  expect_relative(length_of(path("M0 0 H3 V4 Z")), R(12), R("1e-40"), "a closed 3-4-5 triangle");
  const R s_path = length_of(path("M0 0 C1 2 3 2 4 0 S7 -2 8 0 Q9 1 10 0 T12 0"));
  const R spelled =
      length_of(R"({"type": "composite_bezier", "segments": [[[0,0],[1,2],[3,2],[4,0]], [[4,0],[5,-2],[7,-2],[8,0]],)"
                R"( [[8,0],[9,1],[10,0]], [[10,0],[11,-1],[12,0]]]})");
  expect_relative(s_path, spelled, R("1e-40"), "S and T reflected");
}

TEST(svg_path_curve, every_method_bounds_its_error_on_a_path_of_every_command) {
  const std::string spec = path("M0 0 C1 2 3 2 4 0 S7 -2 8 0 Q9 1 10 0 T12 0 A2 1 30 0 1 16 0 L16 -2 H10 V-3 Z");
  const R truth = length_of(spec);
  const auto j = cb::io::parse(spec);
  const auto c = cb::io::curve_from_spec<double, 2>(cb::io::root(j));
  cb::arclength::adaptive_options<double> o;
  o.relative_tolerance = 1e-12;
  const auto r = cb::arclength::adaptive_length(c, o);
  EXPECT_TRUE(r.converged());
  EXPECT_LE(abs(R(r.value) - truth), R(r.error_estimate));
  EXPECT_LT(abs(R(r.value) - truth), R("1e-12") * truth);
}

TEST(svg_path_curve, bad_path_data_is_refused_naming_the_field_and_the_offset) {
  const auto error = [](const std::string& d) {
    return cbt::message_of([&] { (void)cb::io::curve_from_spec<double, 2>(cb::io::root(cb::io::parse(path(d)))); });
  };
  EXPECT_THAT(error("M0 0 L1"), HasSubstr("at offset 7 (the end of the data): expected a number (the y coordinate)"));
  EXPECT_THAT(error("M0 0 L1"), HasSubstr(".d"));
  EXPECT_THAT(error("M1 1"), HasSubstr("draws no segment"));
  EXPECT_THAT(error("M0 0 A1 1 0 2 0 1 1"), HasSubstr("expected an arc flag, 0 or 1"));
}

namespace {

std::string shape(const std::string& fields) { return R"({"type": "svg_path", "shape": {)" + fields + "}}"; }

R case_length(const std::string& name) {
  const std::string file = cbt::source_dir() + "/bench/cases/" + name + ".json";
  std::ifstream in(file);
  std::stringstream text;
  text << in.rdbuf();
  return length_of(text.str());
}

}  // namespace

// SVG 2's equivalent paths of the basic shapes, against their closed forms.
TEST(svg_path_curve, shapes_are_measured_as_the_paths_svg_defines_for_them) {
  const R pi = boost::math::constants::pi<R>();
  expect_relative(length_of(shape(R"("element": "circle", "cx": 3, "cy": -2, "r": 5)")), 10 * pi, R("1e-40"), "circle");
  // rx absent: SVG 2's auto takes ry's value.
  expect_relative(length_of(shape(R"("element": "ellipse", "ry": 2)")), 4 * pi, R("1e-40"), "ellipse, rx auto");
  expect_relative(length_of(shape(R"("element": "ellipse", "rx": 5, "ry": 3)")),
                  4 * 5 * boost::math::ellint_2(R("0.8")), R("1e-40"), "ellipse");
  expect_relative(length_of(shape(R"("element": "rect", "x": 1, "y": 2, "width": 10, "height": 4)")), R(28), R("1e-40"),
                  "square corners");
  // rx and ry are limited separately, rx to width / 2 and ry to height / 2: ry = 5 becomes 2, so the
  // corners are quarters of the 3 x 2 ellipse and the vertical edges have length 0.
  const R corner = boost::math::ellint_2(sqrt(R(1) - R(4) / R(9))) * 3;  // a quarter of the 3 x 2 ellipse
  expect_relative(length_of(shape(R"("element": "rect", "width": 10, "height": 4, "rx": 3, "ry": 5)")),
                  2 * (10 - 6) + 0 + 4 * corner, R("1e-40"), "rounded corners, ry limited to height / 2");
  expect_relative(length_of(shape(R"("element": "rect", "width": 10, "height": 4, "rx": 2)")), 2 * 6 + 0 + 2 * pi * 2,
                  R("1e-40"), "rx = ry = height / 2: no vertical edge");
  expect_relative(length_of(shape(R"("element": "line", "x1": 1, "y1": 1, "x2": 4, "y2": 5)")), R(5), R("1e-40"),
                  "line");
  expect_relative(length_of(shape(R"("element": "polygon", "points": [[0, 0], [3, 0], [3, 4]])")), R(12), R("1e-40"),
                  "polygon, closed");
  expect_relative(length_of(shape(R"("element": "polyline", "points": [[0, 0], [3, 0], [3, 4]])")), R(7), R("1e-40"),
                  "polyline, open");
}

TEST(svg_path_curve, shapes_svg_does_not_render_or_misspelled_are_refused_by_name) {
  const auto error = [](const std::string& spec) {
    return cbt::message_of([&] { (void)cb::io::curve_from_spec<double, 2>(cb::io::root(cb::io::parse(spec))); });
  };
  EXPECT_THAT(error(shape(R"("element": "circle", "r": 0)")), HasSubstr("renders nothing"));
  EXPECT_THAT(error(shape(R"("element": "circle", "r": -1)")), HasSubstr("r = -1 is negative"));
  EXPECT_THAT(error(shape(R"("element": "rect", "width": 1)")), HasSubstr("width or height is 0"));
  EXPECT_THAT(error(shape(R"("element": "circle", "radius": 1)")), HasSubstr("spec.shape.radius"));
  EXPECT_THAT(error(shape(R"("element": "square", "r": 1)")), HasSubstr("spec.shape.element"));
  EXPECT_THAT(error(shape(R"("element": "polyline", "points": [[0, 0]])")), HasSubstr("at least 2"));
  EXPECT_THAT(error(R"({"type": "svg_path", "d": "M0 0 L1 1", "shape": {"element": "circle", "r": 1}})"),
              HasSubstr("gives both d and shape"));
  EXPECT_THAT(error(R"({"type": "svg_path"})"), HasSubstr("needs d (path data) or shape"));
}

// The corpus cases whose lengths have closed forms: its cases are the curves they claim.
TEST(svg_path_curve, corpus_cases_have_their_closed_form_lengths) {
  const R pi = boost::math::constants::pi<R>();
  // fontTools' cusp: x(t) = 150 t - 200 t^3 runs to 50 and back to -50.
  expect_relative(case_length("svg_cusp_fonttools"), R(150), R("1e-40"), "fontTools' cusp");
  expect_relative(case_length("svg_quarter_circle_arc"), 50 * pi, R("1e-40"), "quarter circle as an arc");
  expect_relative(case_length("svg_circle"), 100 * pi, R("1e-40"), "circle shape");
  expect_relative(case_length("svg_rounded_rect"), 200 + 20 * pi, R("1e-40"), "rounded rect");
  expect_relative(case_length("svg_thin_ellipse"), 40 * boost::math::ellint_2(sqrt(R("0.99"))), R("1e-40"),
                  "thin ellipse 10 x 1");
  // The quadratic (-100, 0) (0, 4) (100, 0) is y = 2 - x^2 / 5000 over [-100, 100]: with a = 1 / 2500
  // (|y'| = a |x|), length = 2 int_0^100 sqrt(1 + a^2 x^2) = x sqrt(1 + a^2 x^2) + asinh(a x) / a at 100.
  const R a = R(1) / 2500, x = 100;
  expect_relative(case_length("svg_wide_parabola"), x * sqrt(1 + a * a * x * x) + asinh(a * x) / a, R("1e-40"),
                  "wide parabola");
}
