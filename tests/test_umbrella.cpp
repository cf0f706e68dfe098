// The umbrella header curvebench/curvebench.hpp compiles on its own (it is the only curvebench
// include of this file, and comes first) and its layers work together in one translation unit:
// a curve family, the arc-length methods, the 50-digit reference and the motion layer.
#include "curvebench/curvebench.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <limits>
#include <utility>

namespace cb = curvebench;

namespace {

// Tolerances (the motion's is computed in the test from the parameterization's options):
//   length_tolerance  relative, asked of adaptive_length; its |G - K| estimate must bound the true
//                     error, which must then be below the tolerance as well;
//   motion position   the parameterization's contract, (table_tolerance + Newton tolerance) L, plus
//                     32 roundings of L S(x) (as in tests/test_motion.cpp), L = 10 the path's length;
//   cruise speed      S' is a closed form: 16 eps of the speed 20/61 per frame covers the divisions.
constexpr double length_tolerance = 1e-12;
constexpr double speed_ulps = 16;

}  // namespace

// A parabola (quadratic Bezier) measured by adaptive Gauss-Kronrod in double against its closed
// form evaluated at 50 digits (reference/closed_forms.hpp).
TEST(umbrella, adaptive_length_of_a_parabola_matches_the_closed_form) {
  using p2 = cb::point<double, 2>;
  const cb::point_list<double, 2> pts{p2(0, 0), p2(1, 2), p2(3, -1)};
  const cb::bezier<double, 2> c{std::span<const p2>(pts)};
  cb::arclength::adaptive_options<double> opt;
  opt.relative_tolerance = length_tolerance;
  const auto r = cb::arclength::adaptive_length(c, opt);
  ASSERT_TRUE(r.converged());

  const cb::real50 exact = cb::reference::quadratic_bezier_length(
      cb::point_cast<cb::real50>(pts[0]), cb::point_cast<cb::real50>(pts[1]), cb::point_cast<cb::real50>(pts[2]));
  const double error = std::abs(static_cast<double>(cb::real50(r.value) - exact));
  const double length = static_cast<double>(exact);
  EXPECT_LE(error, r.error_estimate) << "the estimate must bound the error";
  EXPECT_LE(error, length_tolerance * length);
  EXPECT_GT(r.evaluations, 0u);
}

// Seed 002's example through the umbrella: from (-5, 0, 0) at frame 22 to (5, 0, 0) at frame 67,
// constant acceleration until frame 34, cruise until 50, constant deceleration to 67. With the
// parabolic ease the key frames land at x = -185/61 (frame 34) and 135/61 (frame 50), and the cruise
// speed is 20/61 units per frame (derivation in tests/test_motion.cpp).
TEST(umbrella, seed_002_motion_lands_on_its_key_frames) {
  using p3 = cb::point<double, 3>;
  const cb::cardinal_spline<double, 3> path(cb::point_list<double, 3>{p3(-5, 0, 0), p3(5, 0, 0)});
  const cb::arclength::parameterization arc(path);
  const auto ease = cb::motion::parabolic_ease<double>::from_frames(22, 34, 50, 67);
  const cb::motion::motion_path motion(arc, ease, cb::motion::frame_range<double>{22, 67, 24.0});
  const double eps = std::numeric_limits<double>::epsilon();
  const double length = 10;
  const double position_tolerance =
      (arc.options().table_tolerance + arc.options().newton.relative_tolerance) * length + 32 * eps * length;
  const std::array<std::pair<long long, double>, 4> keys{{{22, -5.0}, {34, -185.0 / 61}, {50, 135.0 / 61}, {67, 5.0}}};
  for (const auto& [frame, x] : keys) {
    const p3 p = motion.position_at_frame(frame);
    EXPECT_NEAR(p.x(), x, position_tolerance) << "frame " << frame;
    EXPECT_EQ(p.y(), 0.0);
    EXPECT_EQ(p.z(), 0.0);
  }
  EXPECT_NEAR(motion.speed_at_frame(40) / 24.0, 20.0 / 61, speed_ulps * eps * (20.0 / 61));
  EXPECT_EQ(motion.speed_at_frame(22), 0.0);
}
