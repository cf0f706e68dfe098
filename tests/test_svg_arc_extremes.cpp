// SVG elliptical arcs at the extremes of double (io/svg_path.hpp's centre form, io/families/svg_path.hpp's
// pieces): on a logarithmic grid of radii from 1e-300 to 1e300, over short and long chords, every
// length method of the length table (harness/length_methods.hpp, the quick sweep's settings) either
// bounds its error from the arc's closed form by its estimate or says its estimate is not finite,
// and the 50-digit reference built from the same spec is the arc itself. The closed forms are
// computed here at 50 digits, independently of the centre form: a circular arc of radius r over a
// chord c is 2 r asin(c / 2r) (its complement to 2 pi r with the large-arc flag), half the circle
// of diameter c when r < c / 2 (SVG scales the radii up); a quarter of an ellipse of semi-axes
// a >= b is a E(k), k^2 = 1 - b^2 / a^2 (Boost's complete elliptic integral of the second kind),
// and an ellipse scaled up to reach its end is half of that ellipse's perimeter.
//
// Tolerances: the methods are held to their own estimates (no tolerance of ours); adaptive_gk at
// 1e-10 must also be right to 1e-9 relative (its tolerance, with room for the rounding it adds).
// The reference must be within 1e-40 of the closed form relative (its own bound is below 1e-40 L,
// and the pieces are computed at 50 digits from the arc as written).
#include "support/fixtures.hpp"

#include "harness/length_methods.hpp"
#include "harness/sweep.hpp"

#include "curvebench/core/any_curve.hpp"
#include "curvebench/io/spec.hpp"
#include "curvebench/reference/arc_length.hpp"
#include "curvebench/reference/multiprecision.hpp"

#include <boost/math/constants/constants.hpp>
#include <boost/math/special_functions/ellint_2.hpp>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace cb = curvebench;
namespace cbt = curvebench::testing;
namespace h = curvebench::harness;
using R = cb::real50;
using ::testing::HasSubstr;

namespace {

struct arc_case {
  std::string d;  ///< the path data
  R length;       ///< its closed form
};

// Exactly the decimal text of x (17 significant digits round-trip a double).
std::string num(double x) {
  char b[40];
  std::snprintf(b, sizeof b, "%.17g", x);
  return b;
}

// A circular arc of radius r over the chord from (x0, y0) to (x0 + c, y0), both flags given.
arc_case circle(double r, double x0, double y0, double c, bool large, bool sweep) {
  const R pi = boost::math::constants::pi<R>();
  const R rr(r), half = R(c) / 2;
  R len;
  if (rr <= half) {
    len = pi * half;  // radii scaled up: half the circle through both ends, whatever the flags
  } else {
    const R minor = 2 * rr * asin(half / rr);
    len = large ? R(2 * pi * rr - minor) : minor;
  }
  // The end point as a double: x0 + c must be exact for the closed form to be the arc written.
  const double x1 = x0 + c;
  EXPECT_EQ(R(x1) - R(x0), R(c)) << "the grid's end point is not exact";
  return {"M" + num(x0) + " " + num(y0) + " A" + num(r) + " " + num(r) + " 0 " + (large ? "1" : "0") + " " +
              (sweep ? "1" : "0") + " " + num(x1) + " " + num(y0),
          len};
}

std::vector<arc_case> grid() {
  std::vector<arc_case> out;
  // Circles from 1e-300 to 1e300 over a chord of 10 at the origin and far from it, every flag.
  for (int e = -300; e <= 300; e += 20)
    for (int flags = 0; flags < 4; ++flags) {
      const double r = std::pow(10.0, e);
      out.push_back(circle(r, 0, 0, 10, flags & 1, flags & 2));
      if (flags == 1) out.push_back(circle(r, 1048576, -3e5, 10, true, false));
    }
  // A chord of 1e-10 under radii to 1e290, one of 2^1000 under radii around it (Lambda = 1 exactly
  // at r = 2^999: half the circle with its centre at the midpoint).
  for (int e = -10; e <= 290; e += 50) out.push_back(circle(std::pow(10.0, e), 0, 0, 1e-10, false, true));
  for (const double r : {std::ldexp(1.0, 999), std::ldexp(1.0, 999) * 1.5, std::ldexp(1.0, 1003)})
    out.push_back(circle(r, -std::ldexp(1.0, 999), 0, std::ldexp(1.0, 1000), false, true));
  // Quarter ellipses of semi-axes a and b = q a, from (a, 0) to (0, b) counter-clockwise, on the
  // same grid of sizes, and their mirror (large arc: the other three quarters).
  for (int e = -300; e <= 300; e += 30)
    for (const double q : {1.0, 0.25, 1e-3}) {
      const double a = std::pow(10.0, e), b = a * q;
      const R k = sqrt(R(1) - (R(b) / R(a)) * (R(b) / R(a)));
      const R quarter = R(a) * boost::math::ellint_2(k);
      const std::string head = "M" + num(a) + " 0 A" + num(a) + " " + num(b) + " 0 ";
      out.push_back({head + "0 1 0 " + num(b), quarter});
      out.push_back({head + "1 0 0 " + num(b), 3 * quarter});
    }
  // Radii far too small: rx = 1e-300 s and ry = 2e-300 s over the chord 10 are scaled up to 5 and 10:
  // half the perimeter of that ellipse, 2 * 10 * E(sqrt(3) / 2).
  for (const double s : {1.0, 1e100, 1e290}) {
    const R half = 20 * boost::math::ellint_2(sqrt(R(3)) / 2);
    out.push_back({"M0 0 A" + num(1e-300 * s) + " " + num(2e-300 * s) + " 0 0 1 10 0", half});
  }
  return out;
}

std::string spec_of(const std::string& d) { return R"({"type": "svg_path", "d": ")" + d + R"("})"; }

}  // namespace

TEST(svg_arc_extremes, every_length_estimate_bounds_the_error_from_the_closed_form) {
  const h::sweep w = h::settings(true);
  int measured = 0, bounded_runs = 0;
  for (const arc_case& a : grid()) {
    const auto doc = cb::io::parse(spec_of(a.d));
    const cb::any_curve<double, 2> c = cb::io::curve_from_spec<double, 2>(cb::io::root(doc));
    const double L = static_cast<double>(a.length);
    h::for_each_length_method(c, w, L, [&](const auto& method, const std::string& setting, const auto& run) {
      const auto r = run();
      ++measured;
      const R error = abs(R(r.value) - a.length);
      if (!std::isfinite(r.error_estimate)) {
        EXPECT_NE(r.status, cb::arclength::result_status::converged)
            << a.d << " " << method.id << " " << setting << ": converged without a finite estimate";
        return;
      }
      ++bounded_runs;
      EXPECT_LE(error, R(r.error_estimate))
          << a.d << ": " << method.id << " " << setting << " gives " << cb::to_text(r.value) << " ("
          << cb::arclength::to_string(r.status) << ", estimate " << r.error_estimate << "), the arc is "
          << cb::to_text(a.length);
      if (std::string(method.id) == "adaptive_gk" && setting == "tol=1e-10") {
        EXPECT_LT(error, R("1e-9") * a.length) << a.d << ": adaptive_gk tol=1e-10 gives " << cb::to_text(r.value);
      }
    });
  }
  // Most runs carry an estimate: a grid where every estimate was infinite would prove nothing.
  EXPECT_GT(bounded_runs, measured / 2);
}

TEST(svg_arc_extremes, the_50_digit_reference_is_the_arc_itself) {
  const std::vector<arc_case> all = grid();
  for (std::size_t i = 0; i < all.size(); i += 3) {  // a third of the grid: each reference takes ~0.1 s
    const arc_case& a = all[i];
    const auto doc = cb::io::parse(spec_of(a.d));
    const cb::reference::reference_arc_length<cb::any_curve<R, 2>> ref(
        cb::io::curve_from_spec<R, 2>(cb::io::root(doc)));
    EXPECT_LT(abs(ref.length() - a.length), R("1e-40") * a.length)
        << a.d << ": reference " << cb::to_text(ref.length()) << ", closed form " << cb::to_text(a.length);
  }
}

TEST(svg_arc_extremes, arcs_past_the_range_are_refused_with_the_reason) {
  const auto error = [](const std::string& d) {
    return cbt::message_of([&] { (void)cb::io::curve_from_spec<double, 2>(cb::io::root(cb::io::parse(spec_of(d)))); });
  };
  // The circle through these ends has radius 1e308 and its far side at 2e308: past double.
  EXPECT_THAT(error("M0 0 A1e308 1e308 0 1 0 10 0"), HasSubstr("past the range"));
  EXPECT_THAT(error("M0 0 A1e308 1e308 0 1 0 10 0"), HasSubstr("the arc at offset 5"));
  // Radii of ratio 1e600, scaled up to reach the end: the ellipse reaches 1e900.
  EXPECT_THAT(error("M0 0 A1e-300 1e300 30 0 1 1e300 1e300"), HasSubstr("past the range"));
  // Relative coordinates that overflow are refused where they were written.
  EXPECT_THAT(error("M0 0 l1e308 0 l1e308 0"), HasSubstr("at offset 15"));
  EXPECT_THAT(error("M0 0 l1e308 0 l1e308 0"), HasSubstr("overflows"));
}
