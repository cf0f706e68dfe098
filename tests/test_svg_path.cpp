// SVG path data (io/svg_path.hpp): every command, absolute and relative, implicit repeats, every
// number form, the reflections of S and T, closepath and the subpath after it, arcs converted to
// their centre form (against hand-worked centres and the ellipse's equation), and errors naming the
// offset, the character and what was expected.
//
// Tolerances: coordinates parsed from text and summed once (relative commands) are exact or within
// an ulp of numbers of order 10: 1e-14 absolute. An arc's endpoints recomputed from its centre form
// go through sqrt, atan2, cos and sin of a chain of a dozen operations on numbers of order 10:
// 1e-12 absolute (about 50 ulps, measured below 1e-14).
#include "support/fixtures.hpp"

#include "curvebench/io/svg_path.hpp"
#include "curvebench/reference/multiprecision.hpp"

#include <boost/math/constants/constants.hpp>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>
#include <vector>

namespace svg = curvebench::io::svg;
namespace cbt = curvebench::testing;
using ::testing::HasSubstr;

namespace {

constexpr double exact_tol = 1e-14;
constexpr double arc_tol = 1e-12;

void expect_at(const svg::xy& p, double x, double y, double tol = exact_tol) {
  EXPECT_NEAR(p.x, x, tol);
  EXPECT_NEAR(p.y, y, tol);
}
void expect_at(const std::array<double, 2>& p, double x, double y, double tol) {
  EXPECT_NEAR(p[0], x, tol);
  EXPECT_NEAR(p[1], y, tol);
}

std::vector<svg::segment> segments_of(std::string_view d) {
  std::vector<svg::segment> out;
  for (const auto& sp : svg::parse_path(d)) out.insert(out.end(), sp.segments.begin(), sp.segments.end());
  return out;
}

std::string error_of(std::string_view d) {
  return cbt::message_of([&] { (void)svg::parse_path(d); });
}

}  // namespace

TEST(svg_path, numbers_in_every_form) {
  expect_at(svg::parse_path("M0.5.5").at(0).start, 0.5, 0.5);  // a second '.' starts the next number
  expect_at(svg::parse_path("M1-2").at(0).start, 1, -2);       // a sign ends a number
  expect_at(svg::parse_path("M1e2-3E-1").at(0).start, 100, -0.3);
  expect_at(svg::parse_path("M+.5,-.5").at(0).start, 0.5, -0.5);
  expect_at(svg::parse_path("M1.,2.").at(0).start, 1, 2);  // "1." is digits and a point
  expect_at(svg::parse_path(" \t\r\n\fM 1e+1 , 2 ").at(0).start, 10, 2);
  const svg::xy tiny = svg::parse_path("M1e-400 0.0000001e-330").at(0).start;  // below double's range: 0
  EXPECT_EQ(tiny.x, 0.0);
  EXPECT_EQ(tiny.y, 0.0);
}

TEST(svg_path, moveto_repeats_are_linetos_and_relative_ones_accumulate) {
  const auto a = svg::parse_path("M 10,20 30,40 50 60");
  ASSERT_EQ(a.size(), 1u);
  expect_at(a[0].start, 10, 20);
  ASSERT_EQ(a[0].segments.size(), 2u);
  EXPECT_EQ(a[0].segments[0].kind, svg::segment_kind::line);
  expect_at(a[0].segments[0].start(), 10, 20);
  expect_at(a[0].segments[1].end(), 50, 60);
  const auto r = segments_of("m 1 1 2 2 l 1 0");
  ASSERT_EQ(r.size(), 2u);
  expect_at(r[0].end(), 3, 3);
  expect_at(r[1].end(), 4, 3);
  // A comma may separate argument groups.
  EXPECT_EQ(segments_of("M0 0 L1 1, 2 2").size(), 2u);
}

TEST(svg_path, horizontal_and_vertical_lines) {
  const auto s = segments_of("M1 1 H5 v3 h-2 V0");
  ASSERT_EQ(s.size(), 4u);
  expect_at(s[0].end(), 5, 1);
  expect_at(s[1].end(), 5, 4);
  expect_at(s[2].end(), 3, 4);
  expect_at(s[3].end(), 3, 0);
}

TEST(svg_path, cubics_and_the_reflection_of_s) {
  for (const char* d :
       {"M0 0 C1 2 3 2 4 0 S7 -2 8 0", "M0 0 c1 2 3 2 4 0 s3 -2 4 0", "M0 0 C1 2 3 2 4 0 7 -2 7 -2 8 0"}) {
    SCOPED_TRACE(d);
    const auto s = segments_of(d);
    ASSERT_EQ(s.size(), 2u);
    EXPECT_EQ(s[1].kind, svg::segment_kind::cubic);
    EXPECT_EQ(s[1].points, 4);
    expect_at(s[1].p[0], 4, 0);
    if (std::string_view(d).find_first_of("Ss") != std::string_view::npos) expect_at(s[1].p[1], 5, -2);
    expect_at(s[1].p[2], 7, -2);
    expect_at(s[1].p[3], 8, 0);
  }
  // S after a command that is not a cubic: its first control point is the current point.
  const auto l = segments_of("M0 0 L1 1 S2 2 3 3");
  expect_at(l[1].p[1], 1, 1);
  // The reflection follows S after S.
  const auto ss = segments_of("M0 0 S1 1 2 0 S3 -1 4 0");
  expect_at(ss[1].p[1], 3, -1);
}

TEST(svg_path, quadratics_and_the_reflection_of_t) {
  const auto s = segments_of("M0 0 Q1 2 2 0 T4 0 t2 0");
  ASSERT_EQ(s.size(), 3u);
  EXPECT_EQ(s[1].kind, svg::segment_kind::quadratic);
  expect_at(s[1].p[1], 3, -2);
  expect_at(s[1].p[2], 4, 0);
  expect_at(s[2].p[1], 5, 2);  // reflected again about (4, 0)
  expect_at(s[2].p[2], 6, 0);
  // T after a line: the control point is the current point (a straight quadratic).
  const auto l = segments_of("M0 0 L1 0 T3 0");
  expect_at(l[1].p[1], 1, 0);
  // After a cubic, T does not reflect the cubic's control point.
  const auto c = segments_of("M0 0 C0 1 1 1 1 0 T2 0");
  expect_at(c[1].p[1], 1, 0);
}

TEST(svg_path, closepath_adds_the_closing_line_and_the_next_subpath_starts_at_the_start) {
  const auto a = svg::parse_path("M0 0 L1 0 L1 1 Z");
  ASSERT_EQ(a.size(), 1u);
  EXPECT_TRUE(a[0].closed);
  ASSERT_EQ(a[0].segments.size(), 3u);
  expect_at(a[0].segments[2].end(), 0, 0);
  // Already at the start: no closing segment of zero length.
  EXPECT_EQ(svg::parse_path("M0 0 L1 0 L0 0 z").at(0).segments.size(), 2u);
  // A drawing command after Z starts a subpath at the closed one's start; relative to it.
  const auto b = svg::parse_path("M5 5 L6 5 Z l0 1");
  ASSERT_EQ(b.size(), 2u);
  expect_at(b[1].start, 5, 5);
  expect_at(b[1].segments.at(0).end(), 5, 6);
  const auto m = svg::parse_path("M5 5 L6 5 Z m 2 2 h1");
  ASSERT_EQ(m.size(), 2u);
  expect_at(m[1].start, 7, 7);
  expect_at(m[1].segments.at(0).end(), 8, 7);
}

TEST(svg_path, arcs_to_their_centre_form) {
  // A half circle of radius 5 from (0, 0) to (10, 0), positive-angle direction (clockwise on screen,
  // through y = -5): centre (5, 0), theta from pi to 2 pi.
  for (const char* d :
       {"M0 0 A5 5 0 0 1 10 0", "M0 0 A1 1 0 0 1 10 0", "M0 0 A-5 -5 0 0 1 10 0", "M0 0 a5 5 0 0110 0"}) {
    SCOPED_TRACE(d);
    const auto s = segments_of(d);
    ASSERT_EQ(s.size(), 1u);
    ASSERT_EQ(s[0].kind, svg::segment_kind::arc);
    const auto a = svg::center_form<double>(s[0]);
    EXPECT_NEAR(a.cx, 5, arc_tol);
    EXPECT_NEAR(a.cy, 0, arc_tol);
    EXPECT_NEAR(a.rx, 5, arc_tol);  // "A1 1": scaled up by sqrt(Lambda) = 5
    EXPECT_NEAR(a.ry, 5, arc_tol);
    EXPECT_NEAR(std::abs(a.dtheta), std::numbers::pi, arc_tol);
    EXPECT_GT(a.dtheta, 0);
    expect_at(svg::arc_point(a, a.theta1 + a.dtheta / 2), 5, -5, arc_tol);
  }
  // Sweep flag 0: the other half, through y = +5.
  const auto s0 = segments_of("M0 0 A5 5 0 0 0 10 0");
  const auto a0 = svg::center_form<double>(s0.at(0));
  EXPECT_LT(a0.dtheta, 0);
  expect_at(svg::arc_point(a0, a0.theta1 + a0.dtheta / 2), 5, 5, arc_tol);
}

TEST(svg_path, rotated_arcs_meet_their_endpoints_with_each_pair_of_flags) {
  for (const char* rotation : {"30", "390", "-330"}) {  // taken modulo 360 degrees
    for (int large = 0; large < 2; ++large) {
      for (int sweep = 0; sweep < 2; ++sweep) {
        const std::string d =
            std::string("M0 0 A10 5 ") + rotation + " " + std::to_string(large) + " " + std::to_string(sweep) + " 5 5";
        SCOPED_TRACE(d);
        const auto s = segments_of(d);
        ASSERT_EQ(s.size(), 1u);
        const auto a = svg::center_form<double>(s[0]);
        EXPECT_NEAR(a.rx, 10, exact_tol);  // (5, 5) is reachable: no correction
        EXPECT_NEAR(a.ry, 5, exact_tol);
        EXPECT_NEAR(a.phi, std::numbers::pi / 6, 1e-15);
        expect_at(svg::arc_point(a, a.theta1), 0, 0, arc_tol);
        expect_at(svg::arc_point(a, a.theta1 + a.dtheta), 5, 5, arc_tol);
        EXPECT_EQ(std::abs(a.dtheta) > std::numbers::pi, large == 1);
        EXPECT_EQ(a.dtheta > 0, sweep == 1);
        // Every point of the arc is on the ellipse: ((x' / rx)^2 + (y' / ry)^2 = 1 in its frame).
        for (int k = 0; k <= 8; ++k) {
          const auto p = svg::arc_point(a, a.theta1 + a.dtheta * k / 8);
          const double dx = p[0] - a.cx, dy = p[1] - a.cy;
          const double xr = std::cos(a.phi) * dx + std::sin(a.phi) * dy;
          const double yr = -std::sin(a.phi) * dx + std::cos(a.phi) * dy;
          EXPECT_NEAR(xr * xr / 100 + yr * yr / 25, 1, arc_tol);
        }
      }
    }
  }
}

// The centre form computed at 50 digits from the same data: its ends meet the written end points
// to 1e-45 (the 50-digit chain of a dozen operations, about 100 ulps of 1e-49 at coordinates of 5),
// and the double conversion agrees with it to arc_tol.
TEST(svg_path, centre_form_at_50_digits) {
  using R = curvebench::real50;
  for (const char* d : {"M0 0 A10 5 30 1 0 5 5", "M0 0 A1 1 0 0 1 10 0", "M-3 2 a7 2 -80 1 1 4 -1"}) {
    SCOPED_TRACE(d);
    const auto s = segments_of(d);
    ASSERT_EQ(s.size(), 1u);
    const auto a = svg::center_form<R>(s[0]);
    const auto start = svg::arc_point(a, a.theta1), end = svg::arc_point(a, R(a.theta1 + a.dtheta));
    EXPECT_LT(abs(start[0] - R(s[0].p[0].x)) + abs(start[1] - R(s[0].p[0].y)), R(1e-45));
    EXPECT_LT(abs(end[0] - R(s[0].p[1].x)) + abs(end[1] - R(s[0].p[1].y)), R(1e-45));
    const auto ad = svg::center_form<double>(s[0]);
    EXPECT_NEAR(ad.cx, static_cast<double>(a.cx), arc_tol);
    EXPECT_NEAR(ad.cy, static_cast<double>(a.cy), arc_tol);
    EXPECT_NEAR(ad.dtheta, static_cast<double>(a.dtheta), arc_tol);
  }
}

// Radii too small, rotated: after the sqrt(Lambda) scaling the arc is exactly half the ellipse and
// its centre exactly the chord's midpoint, in double and at 50 digits (F.6.6's radicand is 0 there;
// computed it is rounding noise, whose square root moved the centre by ~1e-8 before). The arc of
// svg_every_command: from (12, 0), radii (2, 1) rotated 30 degrees, to (16, 0): Lambda = 3/4 + 1.
TEST(svg_path, an_arc_with_scaled_radii_is_centred_on_its_chord) {
  using R = curvebench::real50;
  const auto s = segments_of("M12 0 A2 1 30 0 1 16 0");
  ASSERT_EQ(s.size(), 1u);
  const auto a = svg::center_form<double>(s[0]);
  EXPECT_EQ(a.cx, 14.0);
  EXPECT_EQ(a.cy, 0.0);
  EXPECT_NEAR(a.rx, 2 * std::sqrt(1.75), 4e-15);  // sqrt of a rounded Lambda: a few ulps
  EXPECT_NEAR(a.ry, std::sqrt(1.75), 2e-15);
  EXPECT_NEAR(std::abs(a.dtheta), std::numbers::pi, 1e-15);
  const auto a50 = svg::center_form<R>(s[0]);
  EXPECT_EQ(a50.cx, R(14));
  EXPECT_EQ(a50.cy, R(0));
  const auto end = svg::arc_point(a50, R(a50.theta1 + a50.dtheta));
  EXPECT_LT(abs(end[0] - R(16)) + abs(end[1]), R(1e-45));
}

TEST(svg_path, degenerate_arcs) {
  const auto line = segments_of("M0 0 A0 5 0 0 1 10 0");  // a zero radius: a straight line
  ASSERT_EQ(line.size(), 1u);
  EXPECT_EQ(line[0].kind, svg::segment_kind::line);
  expect_at(line[0].end(), 10, 0);
  EXPECT_TRUE(segments_of("M1 1 A5 5 0 0 1 1 1").empty());  // coincident endpoints: omitted
  const auto compact = segments_of("M0 0a1 1 0 00.5.5");    // flags without separators
  ASSERT_EQ(compact.size(), 1u);
  expect_at(compact[0].end(), 0.5, 0.5);
}

TEST(svg_path, errors_name_the_offset_the_character_and_what_was_expected) {
  EXPECT_THAT(error_of(""), HasSubstr("at offset 0 (the end of the data): expected a moveto command"));
  EXPECT_THAT(error_of("L1 2"), HasSubstr("at offset 0 ('L'): expected a moveto command (M or m) first"));
  EXPECT_THAT(error_of("M 1"), HasSubstr("at offset 3 (the end of the data): expected a number (the y coordinate)"));
  EXPECT_THAT(error_of("M1 2 L"), HasSubstr("at offset 6 (the end of the data): expected a number (the x coordinate)"));
  EXPECT_THAT(error_of("M1 2 X3"), HasSubstr("at offset 5 ('X'): expected a path command"));
  EXPECT_THAT(error_of("M0 0 A1 1 0 2 0 1 1"), HasSubstr("at offset 12 ('2'): expected an arc flag, 0 or 1"));
  EXPECT_THAT(error_of("M1e 2"), HasSubstr("at offset 3 (' '): expected the exponent's digits of a number"));
  EXPECT_THAT(error_of("M1e999 0"), HasSubstr("at offset 1 ('1'): expected a number within double's range"));
  EXPECT_THAT(error_of("M0 0 Z 1 1"), HasSubstr("at offset 7 ('1'): expected a command after closepath"));
  EXPECT_THAT(error_of("M1 2,Z"), HasSubstr("at offset 5 ('Z'): expected a number (the x coordinate)"));
  EXPECT_THAT(error_of("M."), HasSubstr("at offset 1 ('.'): expected a number (the x coordinate)"));
  EXPECT_THAT(error_of("M0 0 L1 1 L2"), HasSubstr("at offset 12 (the end of the data)"));  // never shortened
}

// Radii from 1e-300 to 1e300 over a chord of 10: the centre form is finite, its start angle's unit
// vector is a unit vector, and the sweep is the closed form 2 asin(5 / r) (pi when r < 5, where SVG
// scales the radii up) to 1e-15 relative, where squaring the radii twice overflowed past 1e77 and
// lost the sweep of a radius of 1e20 to the rounding of its centre (1e-16 of 1e20 against 5).
TEST(svg_path, centre_form_from_the_smallest_to_the_largest_radii) {
  using R = curvebench::real50;
  for (int e = -300; e <= 300; e += 25) {
    const double r = std::pow(10.0, e);
    char text[80];
    std::snprintf(text, sizeof text, "M0 0 A%.17g %.17g 0 0 1 10 0", r, r);
    SCOPED_TRACE(text);
    const auto s = segments_of(text);
    ASSERT_EQ(s.size(), 1u);
    const auto a = svg::center_form<double>(s[0]);
    EXPECT_TRUE(std::isfinite(a.cx) && std::isfinite(a.cy) && std::isfinite(a.rx) && std::isfinite(a.ry));
    EXPECT_NEAR(std::hypot(a.ux, a.uy), 1.0, 4e-16);
    const R rr(r);
    const R want = rr <= 5 ? boost::math::constants::pi<R>() : R(2 * asin(R(5) / rr));
    EXPECT_LT(abs(R(a.dtheta) - want), R("1e-15") * want) << "dtheta " << a.dtheta;
    const auto a50 = svg::center_form<R>(s[0]);
    EXPECT_LT(abs(a50.dtheta - want), R("1e-45") * want);
  }
}

// A path's segments are bounded before they are built: one more than max_segments is refused,
// naming the limit and where the data passed it.
TEST(svg_path, at_most_max_segments_per_path) {
  std::string d = "M0 0";
  d.reserve(6 * (svg::max_segments + 2));
  for (std::size_t i = 0; i <= svg::max_segments; ++i) d += "l1 1 ";
  const std::string message = curvebench::testing::message_of([&] { (void)svg::parse_path(d); });
  EXPECT_THAT(message, ::testing::HasSubstr("at most 1000000 segments"));
  EXPECT_THAT(message, ::testing::HasSubstr("at offset " + std::to_string(4 + 5 * svg::max_segments)));
  d.resize(d.size() - 5);  // exactly the limit: accepted
  EXPECT_EQ(svg::parse_path(d).at(0).segments.size(), svg::max_segments);
}
