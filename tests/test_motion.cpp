// Motion along a path, P(U(L S(t))): position, speed, velocity and acceleration against closed
// forms on a circular arc with an exact arc-length map (all four Real types), frames, a curve with a
// stationary point, and the error messages.
#include "support/accuracy.hpp"

#include "curvebench/arclength/length.hpp"
#include "curvebench/arclength/parameterization.hpp"
#include "curvebench/curves/cardinal_spline.hpp"
#include "curvebench/motion/distance_time.hpp"
#include "curvebench/motion/motion_path.hpp"

#include <gmock/gmock.h>

#include <array>
#include <cstdio>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

namespace cb = curvebench;
namespace cbm = curvebench::motion;
namespace cbt = curvebench::testing;
using cb::real50;
using ::testing::HasSubstr;

namespace {

// Tolerances, in eps(Real) times a scale (observed maxima are ~3 eps for the position and ~7 eps
// for the acceleration of the smootherstep motion; the bounds below are the derivations):
// - position_ulps (scale r): the angle sigma / r carries the errors of S (a few eps), of L S and
//   of the division (relative, times |angle| <= 3), then cos/sin and r *: 16 eps;
// - velocity_ulps (scale: the maximum speed): speed = L S' / T (S' within a few eps of its scale)
//   times a unit tangent with ~4 eps per coordinate (norm, division): 16 eps;
// - acceleration_ulps (scale: max |r''| over the motion): the tangential part as the speed, the
//   normal part sigma'^2 / |P'|^2 times P'' minus its tangential projection (~8 roundings): 32 eps;
// - frame_ulps: a frame's x = (f - f0) / (f1 - f0) rounds once, t = f / fps and (t - t0) / T
//   three times: the two routes to the same frame differ by a few eps of x, times the speed: 16 eps
//   of scale L.
constexpr double position_ulps = 16;
constexpr double velocity_ulps = 16;
constexpr double acceleration_ulps = 32;
constexpr double frame_ulps = 16;

template <class Real>
class motion_test : public ::testing::Test {};
TYPED_TEST_SUITE(motion_test, cbt::all_reals);

// A circular arc of radius r centred at the origin, u = angle in [0, theta]: |P'| = r, so the
// exact arc-length map is u(s) = s / r and L = r theta.
template <class Real>
struct circular_arc {
  using real_type = Real;
  static constexpr int dimension = 2;
  using point_type = cb::point<Real, 2>;
  Real r, theta;
  std::array<Real, 2> breaks{Real(0), theta};
  circular_arc(const Real& radius, const Real& angle) : r(radius), theta(angle), breaks{Real(0), angle} {}
  [[nodiscard]] cb::interval<Real> domain() const { return {Real(0), theta}; }
  [[nodiscard]] point_type operator()(const Real& u) const { return derivative(u, 0); }
  [[nodiscard]] point_type derivative(const Real& u, int order) const {
    cb::check_parameter(u, domain());
    using std::cos;
    using std::sin;
    point_type p(r * cos(u), r * sin(u));
    for (int k = 0; k < order % 4; ++k) p = point_type(-p[1], p[0]);
    return p;
  }
  [[nodiscard]] std::span<const Real> breakpoints() const { return breaks; }
};

template <class Real>
struct exact_arc_map {
  using real_type = Real;
  circular_arc<Real> c;
  [[nodiscard]] Real length() const { return c.r * c.theta; }
  [[nodiscard]] Real u(const Real& s) const { return s / c.r; }
  [[nodiscard]] const circular_arc<Real>& curve() const { return c; }
};

static_assert(cb::curve<circular_arc<double>>);
static_assert(cbm::arc_length_map<exact_arc_map<double>>);
static_assert(cbm::arc_length_map<exact_arc_map<real50>>);

// A curve with a stationary point at u = 0 and an exactly invertible arc length.
template <class Real>
struct cusp_curve {
  using real_type = Real;
  static constexpr int dimension = 2;
  using point_type = cb::point<Real, 2>;
  std::array<Real, 2> breaks{Real(0), Real(1)};
  [[nodiscard]] cb::interval<Real> domain() const { return {Real(0), Real(1)}; }
  [[nodiscard]] point_type operator()(const Real& u) const { return derivative(u, 0); }
  // P(u) = (u^2 / 2, u^3 / 3): P'(0) = 0, P''(0) = (1, 0); |P'| = u sqrt(1 + u^2), so
  // s(u) = ((1 + u^2)^(3/2) - 1) / 3 and u(s) = sqrt((3 s + 1)^(2/3) - 1).
  [[nodiscard]] point_type derivative(const Real& u, int order) const {
    switch (order) {
      case 0: return point_type(u * u / Real(2), u * u * u / Real(3));
      case 1: return point_type(u, u * u);
      case 2: return point_type(Real(1), Real(2) * u);
      case 3: return point_type(Real(0), Real(2));
      default: return point_type::Zero();
    }
  }
  [[nodiscard]] std::span<const Real> breakpoints() const { return breaks; }
};

template <class Real>
struct cusp_map {
  using real_type = Real;
  cusp_curve<Real> c;
  [[nodiscard]] Real length() const {
    using std::sqrt;
    return (Real(2) * sqrt(Real(2)) - Real(1)) / Real(3);
  }
  [[nodiscard]] Real u(const Real& s) const {
    using std::cbrt;
    using std::sqrt;
    const Real a = cbrt(Real(3) * s + Real(1));
    const Real v = a * a - Real(1);
    return v > Real(0) ? sqrt(v) : Real(0);
  }
  [[nodiscard]] const cusp_curve<Real>& curve() const { return c; }
};

// The closed-form motion on the arc in real50: sigma = L S(x), angle sigma / r.
template <class F50>
struct arc_reference {
  real50 r, theta, t0, t1;
  F50 ease;
  [[nodiscard]] real50 T() const { return t1 - t0; }
  [[nodiscard]] real50 L() const { return r * theta; }
  [[nodiscard]] real50 x(const real50& t) const { return (t - t0) / T(); }
  [[nodiscard]] cb::point<real50, 2> position(const real50& t) const {
    const real50 a = L() * ease(x(t)) / r;
    return {r * cos(a), r * sin(a)};
  }
  [[nodiscard]] real50 speed(const real50& t) const { return L() * ease.velocity(x(t)) / T(); }
  [[nodiscard]] real50 tangential(const real50& t) const { return L() * ease.acceleration(x(t)) / (T() * T()); }
  [[nodiscard]] cb::point<real50, 2> velocity(const real50& t) const {
    const real50 a = L() * ease(x(t)) / r;
    return speed(t) * cb::point<real50, 2>(-sin(a), cos(a));
  }
  [[nodiscard]] cb::point<real50, 2> acceleration(const real50& t) const {
    const real50 a = L() * ease(x(t)) / r;
    const real50 v = speed(t);
    return tangential(t) * cb::point<real50, 2>(-sin(a), cos(a)) - (v * v / r) * cb::point<real50, 2>(cos(a), sin(a));
  }
};

template <class Real, class F, class F50>
void check_arc_motion(const F& ease, const F50& ease50, const char* name) {
  // radius 2, angle 3 (L = 6), over t in [1, 4] (T = 3): every number exact in every type.
  const exact_arc_map<Real> map{circular_arc<Real>(Real(2), Real(3))};
  const cbm::motion_path motion(map, ease, cb::interval<Real>{Real(1), Real(4)});
  const arc_reference<F50> ref{real50(2), real50(3), real50(1), real50(4), ease50};
  // scales: max speed and max acceleration over a fine grid of the reference
  real50 vmax(0), amax(0);
  for (int k = 0; k <= 512; ++k) {
    const real50 t = 1 + real50(3 * k) / 512;
    using std::abs;
    vmax = std::max(vmax, real50(abs(ref.speed(t))));
    amax = std::max(amax, real50(ref.acceleration(t).norm()));
  }
  for (int k = 0; k <= 96; ++k) {
    const Real t = Real(1) + Real(3 * k) / Real(96);
    const real50 t50(t);
    const auto s = motion.sample(t);
    ASSERT_TRUE(cbt::point_within(s.position, ref.position(t50), real50(2), position_ulps)) << name << " k=" << k;
    ASSERT_TRUE(cbt::point_within(motion.position(t), ref.position(t50), real50(2), position_ulps)) << name;
    ASSERT_TRUE(cbt::within_scaled_ulps(s.speed, ref.speed(t50), vmax, velocity_ulps)) << name << " k=" << k;
    ASSERT_TRUE(cbt::point_within(s.velocity, ref.velocity(t50), vmax, velocity_ulps)) << name << " k=" << k;
    ASSERT_TRUE(cbt::point_within(motion.velocity(t), ref.velocity(t50), vmax, velocity_ulps)) << name;
    ASSERT_TRUE(cbt::within_scaled_ulps(s.tangential_acceleration, ref.tangential(t50), amax, acceleration_ulps))
        << name;
    ASSERT_TRUE(cbt::point_within(s.acceleration, ref.acceleration(t50), amax, acceleration_ulps))
        << name << " k=" << k;
    // the velocity is the derivative of the position: |v| = speed, v tangent to the circle
    ASSERT_TRUE(cbt::within_scaled_ulps(Real(s.velocity.dot(s.position)), real50(0), 2 * vmax, velocity_ulps));
  }
  // the ends are exact: P(0) and P(theta)
  EXPECT_EQ(motion.distance(Real(1)), Real(0));
  EXPECT_EQ(motion.distance(Real(4)), Real(6));
  EXPECT_EQ(motion.parameter(Real(4)), Real(3));
}

}  // namespace

TYPED_TEST(motion_test, circular_arc_matches_closed_form) {
  using Real = TypeParam;
  check_arc_motion<Real>(cbm::linear_ease<Real>{}, cbm::linear_ease<real50>{}, "linear");
  check_arc_motion<Real>(cbm::sine_ease<Real>{}, cbm::sine_ease<real50>{}, "sine");
  const Real t1 = Real(1) / Real(4), t2 = Real(5) / Real(8);
  check_arc_motion<Real>(cbm::parabolic_ease<Real>(t1, t2), cbm::parabolic_ease<real50>(real50(t1), real50(t2)),
                         "parabolic");
  check_arc_motion<Real>(cbm::sine_plateau_ease<Real>(t1, t2), cbm::sine_plateau_ease<real50>(real50(t1), real50(t2)),
                         "sine_plateau");
  check_arc_motion<Real>(cbm::smootherstep_ease<Real>{}, cbm::smootherstep_ease<real50>{}, "smootherstep");
}

TYPED_TEST(motion_test, frames_map_to_normalized_time) {
  // Frames 10..40 at 24 fps: frame f is time f / 24, x = (f - 10) / 30; the first and last frames
  // sit exactly on the ends; distance per frame is L (S(x_{f+1}) - S(x_f)); the frame and time
  // routes agree.
  using Real = TypeParam;
  const exact_arc_map<Real> map{circular_arc<Real>(Real(2), Real(3))};
  const cbm::smoothstep_ease<Real> ease;
  const cbm::motion_path motion(map, ease, cbm::frame_range<Real>{10, 40, Real(24)});
  const cbm::smoothstep_ease<real50> e50;
  EXPECT_EQ(motion.frames().count(), 31);
  EXPECT_EQ(motion.distance_at_frame(10), Real(0));
  EXPECT_EQ(motion.distance_at_frame(40), Real(6));
  EXPECT_TRUE(cbt::within_ulps(motion.time_domain().lo, real50(10) / 24, 1));
  EXPECT_TRUE(cbt::within_ulps(motion.duration(), real50(30) / 24, 4));
  const auto samples = motion.sample_frames();
  ASSERT_EQ(samples.size(), 31u);
  for (long long f = 10; f < 40; ++f) {
    const real50 x0 = real50(f - 10) / 30, x1 = real50(f + 1 - 10) / 30;
    const real50 per_frame = 6 * (e50(x1) - e50(x0));
    EXPECT_TRUE(cbt::within_scaled_ulps(Real(motion.distance_at_frame(f + 1) - motion.distance_at_frame(f)), per_frame,
                                        real50(6), frame_ulps))
        << f;
    EXPECT_TRUE(cbt::point_within(motion.position_at_frame(f), cb::point_cast<real50>(samples[std::size_t(f - 10)]),
                                  real50(2), 0));
    EXPECT_TRUE(cbt::point_within(motion.position(motion.frame_time(f)),
                                  cb::point_cast<real50>(motion.position_at_frame(f)), real50(6), frame_ulps))
        << f;
    // speed in length per unit time: L S'(x) / T with T = 30 / 24
    EXPECT_TRUE(cbt::within_scaled_ulps(motion.speed_at_frame(f), 6 * e50.velocity(x0) * 24 / 30,
                                        real50(6) * 24 / 30 * real50(3) / 2, velocity_ulps))
        << f;
    const auto s = motion.sample_at_frame(f);
    EXPECT_EQ(s.position, motion.position_at_frame(f));
    EXPECT_EQ(s.time, motion.frame_time(f));
  }
}

TEST(motion, stationary_point_uses_the_forward_tangent) {
  // P(u) = (u^2 / 2, u^3 / 3) has P'(0) = 0. With a constant-speed ease the motion leaves u = 0 with
  // speed L / T along P''(0) / |P''(0)| = (1, 0); the curvature term is undefined there: throws.
  // With an ease that starts at rest (smoothstep) the velocity is 0 and the acceleration is
  // sigma''(0) (1, 0).
  const cusp_map<double> map{};
  const double L = map.length();
  const cbm::motion_path lin(map, cbm::linear_ease<double>{}, cb::interval<double>{0.0, 2.0});
  const auto v = lin.velocity(0.0);
  EXPECT_DOUBLE_EQ(v[0], L / 2);
  EXPECT_EQ(v[1], 0.0);
  try {
    (void)lin.acceleration(0.0);
    FAIL() << "expected std::domain_error";
  } catch (const std::domain_error& e) {
    EXPECT_THAT(e.what(), HasSubstr("P'(u) = 0 at u = 0 while moving"));
  }
  const cbm::motion_path rest(map, cbm::smoothstep_ease<double>{}, cb::interval<double>{0.0, 2.0});
  const auto s = rest.sample(0.0);
  EXPECT_EQ(s.velocity, (cb::point<double, 2>::Zero()));
  EXPECT_DOUBLE_EQ(s.acceleration[0], L * 6 / 4);  // L S''(0) / T^2
  EXPECT_EQ(s.acceleration[1], 0.0);
  // away from the cusp the velocity is tangent and the speed exact: check against |P'| du/dt
  const double t = 0.75;
  const auto m = lin.sample(t);
  const auto d1 = map.curve().derivative(m.parameter, 1);
  EXPECT_NEAR(m.velocity[0] * d1[1] - m.velocity[1] * d1[0], 0.0, 1e-15);
  EXPECT_DOUBLE_EQ(m.velocity.norm(), L / 2);
}

TEST(motion, errors_are_reported) {
  const exact_arc_map<double> map{circular_arc<double>(2.0, 3.0)};
  const cbm::linear_ease<double> ease;
  const auto message = [](auto&& fn) -> std::string {
    try {
      fn();
    } catch (const cb::invalid_input& e) {
      return e.what();
    }
    return "(no invalid_input)";
  };
  EXPECT_EQ(message([&] {
              cbm::motion_path(map, ease, cb::interval<double>{2.0, 1.0});
            }),
            "time = [2, 1]: the motion needs an interval with time.lo < time.hi");
  EXPECT_EQ(message([&] {
              cbm::motion_path(map, ease, cbm::frame_range<double>{67, 22, 24.0});
            }),
            "frames = [67, 22]: the last frame must come after the first");
  EXPECT_EQ(message([&] {
              cbm::motion_path(map, ease, cbm::frame_range<double>{22, 67, 0.0});
            }),
            "fps = 0: must be > 0");
  const cbm::motion_path timed(map, ease, cb::interval<double>{1.0, 4.0});
  EXPECT_THROW((void)timed.frames(), std::logic_error);
  EXPECT_THROW((void)timed.position_at_frame(1), std::logic_error);
  try {
    (void)timed.position(4.5);
    FAIL();
  } catch (const std::domain_error& e) {
    EXPECT_STREQ(e.what(), "t = 4.5 is outside the motion's time interval [1, 4]");
  }
  const cbm::motion_path framed(map, ease, cbm::frame_range<double>{22, 67, 24.0});
  try {
    (void)framed.position_at_frame(68);
    FAIL();
  } catch (const std::domain_error& e) {
    EXPECT_STREQ(e.what(), "frame = 68 is outside the frame range [22, 67]");
  }
  std::vector<cb::point<double, 2>> out(10);
  EXPECT_EQ(message([&] { framed.sample_frames(std::span<cb::point<double, 2>>(out)); }),
            "sample_frames output: 10 given, must match frames: 46");
}

// ---- seed 002: (-5, 0, 0) at frame 22 to (5, 0, 0) at frame 67 --------------------------------
//
// Closed forms (derived in distance_time.hpp, parabolic_ease): T = 45 frames, t1 = 12/45,
// t2 = 28/45, v = 2 / (1 + t2 - t1) = 90/61 (normalized). With L = 10:
//   cruise speed  L v / T = 20/61 units per frame (480/61 per second at 24 fps);
//   frame 34: S(t1) = v t1 / 2 = 12/61, x = -5 + 120/61 = -185/61;
//   frame 50: S(t2) = 1 - v (1 - t2) / 2 = 44/61, x = -5 + 440/61 = 135/61;
//   distance from frame 22 + k to 23 + k (k < 12): a (2k + 1) / 2 with a = (20/61) / 12 per frame^2;
//   from 50 + k to 51 + k (k < 17): 20/61 - (20/61) (2k + 1) / 34.

namespace {

template <class Real>
class seed_002_test : public ::testing::Test {};
// float and double (long double adds compile time, not coverage: the contract is the same).
using seed_reals = ::testing::Types<float, double>;
TYPED_TEST_SUITE(seed_002_test, seed_reals);

// The expected distance covered between frame f and f + 1 (a closed form of the seed example).
real50 seed_002_step(long long f) {
  const real50 vmax = real50(20) / 61;  // per frame
  if (f < 34) return vmax / 12 * (2 * (f - 22) + 1) / 2;
  if (f < 50) return vmax;
  return vmax - vmax * (2 * (f - 50) + 1) / 34;
}

}  // namespace

TYPED_TEST(seed_002_test, positions_speeds_and_distance_per_frame) {
  using Real = TypeParam;
  using point3 = cb::point<Real, 3>;
  const cb::cardinal_spline<Real, 3> path(cb::point_list<Real, 3>{point3(-5, 0, 0), point3(5, 0, 0)});
  const cb::arclength::parameterization arc(path);
  const auto ease = cbm::parabolic_ease<Real>::from_frames(22, 34, 50, 67);
  const cbm::motion_path motion(arc, ease, cbm::frame_range<Real>{22, 67, Real(24)});
  // The inversion's contract (its table tolerance and the Newton tolerance of the nodes) plus a
  // few roundings of L S(x), measured in eps(Real) of the extent 5:
  const real50 L50(10);
  const real50 eps(cb::epsilon<Real>());
  const real50 inv_err =
      (real50(arc.options().table_tolerance) + real50(arc.options().newton.relative_tolerance)) * L50;
  const double tol = static_cast<double>((inv_err + 32 * eps * L50) / (eps * 5));

  EXPECT_TRUE(cbt::within_ulps(arc.length(), L50, 4));
  // positions at the key frames
  const std::array<std::pair<long long, real50>, 4> keys{
      {{22, real50(-5)}, {34, real50(-185) / 61}, {50, real50(135) / 61}, {67, real50(5)}}};
  for (const auto& [f, x] : keys) {
    const point3 p = motion.position_at_frame(f);
    EXPECT_TRUE(cbt::within_scaled_ulps(p[0], x, real50(5), tol)) << "frame " << f;
    EXPECT_EQ(p[1], Real(0));
    EXPECT_EQ(p[2], Real(0));
  }
  // stopped at both ends, exactly
  EXPECT_EQ(motion.speed_at_frame(22), Real(0));
  EXPECT_EQ(motion.speed_at_frame(67), Real(0));
  EXPECT_EQ(motion.sample_at_frame(67).velocity, point3::Zero());
  // constant speed 20/61 per frame (x 24 fps) on [34, 50], below it elsewhere
  const real50 cruise = real50(20) / 61 * 24;
  for (long long f = 22; f <= 67; ++f) {
    const Real v = motion.speed_at_frame(f);
    if (f >= 34 && f <= 50) {
      EXPECT_TRUE(cbt::within_ulps(v, cruise, 8)) << "frame " << f;
      EXPECT_TRUE(cbt::within_ulps(motion.sample_at_frame(f).velocity[0], cruise, 16)) << "frame " << f;
    } else {
      EXPECT_LT(real50(v), cruise) << "frame " << f;
    }
  }
  // distance covered per frame
  const auto xs = motion.sample_frames();
  for (long long f = 22; f < 67; ++f) {
    const Real step = xs[std::size_t(f - 22) + 1][0] - xs[std::size_t(f - 22)][0];
    EXPECT_TRUE(cbt::within_scaled_ulps(step, seed_002_step(f), real50(5), 2 * tol)) << "frame " << f;
  }
}

// The example of docs/motion.md (the lead copies this block there; keep them identical).
namespace readme {
void seed_002_example() {
  // ---- docs/motion.md snippet begins ----
  namespace cb = curvebench;
  using point3 = cb::point<double, 3>;

  // The path through the keys: a Catmull-Rom spline (a straight line for two keys),
  // parameterized by arc length (u(s) from a cubic Hermite table).
  const cb::cardinal_spline<double, 3> path(cb::point_list<double, 3>{point3(-5, 0, 0), point3(5, 0, 0)});
  const cb::arclength::parameterization arc(path);

  // The speed: at rest at frame 22, accelerate until frame 34, cruise until 50, stop at 67.
  const auto ease = cb::motion::parabolic_ease<double>::from_frames(22, 34, 50, 67);
  const cb::motion::motion_path motion(arc, ease, cb::motion::frame_range<double>{22, 67, 24.0});

  for (long long f = 22; f <= 67; ++f) {
    const point3 p = motion.position_at_frame(f);              // P(U(L S((f - 22) / 45)))
    const double per_frame = motion.speed_at_frame(f) / 24.0;  // 20/61 while cruising
    std::printf("frame %2lld  x = %9.5f  speed = %.5f per frame\n", f, p.x(), per_frame);
  }
  // ---- docs/motion.md snippet ends ----
}
}  // namespace readme

TEST(readme, seed_002_example_runs_and_prints_the_key_frames) {
  ::testing::internal::CaptureStdout();
  readme::seed_002_example();
  const std::string out = ::testing::internal::GetCapturedStdout();
  EXPECT_THAT(out, HasSubstr("frame 22  x =  -5.00000  speed = 0.00000 per frame"));
  EXPECT_THAT(out, HasSubstr("frame 34  x =  -3.03279  speed = 0.32787 per frame"));  // -185/61, 20/61
  EXPECT_THAT(out, HasSubstr("frame 50  x =   2.21311  speed = 0.32787 per frame"));  // 135/61
  EXPECT_THAT(out, HasSubstr("frame 67  x =   5.00000  speed = 0.00000 per frame"));
  EXPECT_EQ(std::count(out.begin(), out.end(), '\n'), 46);
}

// ---- a curved path: Catmull-Rom through five keys, every inversion method ---------------------

namespace {

// Arc-length error bound of each inversion method, in length units, for the curve c with the
// parameterization a (derivations in the comments; the test asserts per-frame distances within
// twice the bound, one per frame end).
template <class C>
double inversion_bound(const cb::arclength::parameterization<C>& a, cb::arclength::inversion_method m) {
  const double L = a.length();
  const double newton = a.options().newton.relative_tolerance * L;
  switch (m) {
    case cb::arclength::inversion_method::newton: return newton;  // the Newton stopping rule |s(u) - s| <= tol L
    case cb::arclength::inversion_method::hermite_table:
      // the measured table error (of the coarser table; the kept one is finer), its target, and
      // the Newton error of the nodes it interpolates
      return std::max(a.table_error(), a.options().table_tolerance * L) + newton;
    case cb::arclength::inversion_method::linear_table: {
      // |u - u_lin| <= ds^2 / 8 max |u''(s)|, u'' = -(P'.P'') / |P'|^4, and the arc error is |P'| |du|:
      // bound ds^2 / 8 * max|P'| * max|P'.P''| / |P'|^4 sampled densely (x2 for the sampling).
      const auto& c = a.curve();
      double vmax = 0, umax = 0;
      const auto dom = c.domain();
      for (int k = 0; k <= 4000; ++k) {
        const double u = dom.lo + (dom.hi - dom.lo) * k / 4000;
        const auto d1 = c.derivative(u, 1);
        const auto d2 = c.derivative(u, 2);
        const double n = d1.norm();
        vmax = std::max(vmax, n);
        umax = std::max(umax, std::abs(d1.dot(d2)) / (n * n * n * n));
      }
      const double ds = L / static_cast<double>(a.table_intervals());
      return 2 * ds * ds / 8 * vmax * umax + newton;
    }
  }
  return 0;
}

// The Catmull-Rom path (uniform knots: its speed |P'| varies a lot) and its 50-digit twin.
struct curved_case {
  using point2 = cb::point<double, 2>;
  cb::point_list<double, 2> keys{point2(0, 0), point2(1, 2), point2(3, 3), point2(4, 0), point2(6, 1)};
  cb::cardinal_spline<double, 2> path{keys};
  cb::cardinal_spline<real50, 2> path50{cb::points_cast<real50, double, 2>(keys)};
  // 50-digit reference lengths to 1e-30 relative: far below any double error, and cheap.
  cb::arclength::adaptive_options<real50> ref_opt = [] {
    cb::arclength::adaptive_options<real50> o;
    o.relative_tolerance = real50("1e-30");
    return o;
  }();
  real50 L50 = cb::arclength::adaptive_length(path50, ref_opt).value;
};

template <class A, class F, class F50>
void check_curved_motion(const curved_case& c, const A& arc, cb::arclength::inversion_method m, const F& ease,
                         const F50& ease50, const char* name) {
  const double bound = inversion_bound(arc, m) + 64 * cb::epsilon<double>() * static_cast<double>(c.L50);
  const cbm::motion_path motion(arc, ease, cbm::frame_range<double>{0, 48, 24.0});
  real50 s_prev(0), worst(0);
  double u_prev = 0;
  for (long long f = 1; f <= 48; ++f) {
    const double u = motion.sample_at_frame(f).parameter;
    // the true arc length covered during the frame, in 50 digits
    const real50 step = cb::arclength::adaptive_length(c.path50, real50(u_prev), real50(u), c.ref_opt).value;
    const real50 s_now = s_prev + step;
    const real50 x0 = real50(f - 1) / 48, x1 = real50(f) / 48;
    const real50 expected_step = c.L50 * (ease50(x1) - ease50(x0));
    using std::abs;
    worst = std::max(worst, real50(abs(step - expected_step)));
    ASSERT_LE(abs(step - expected_step), real50(2 * bound)) << name << " method " << int(m) << " frame " << f;
    ASSERT_LE(abs(s_now - c.L50 * ease50(x1)), real50(bound)) << name << " method " << int(m) << " frame " << f;
    s_prev = s_now;
    u_prev = u;
  }
  std::printf("[curved path, %s] u(s) method %d: max |frame distance - L dS| = %.3g (bound %.3g, L = %.6f)\n", name,
              int(m), static_cast<double>(worst), 2 * bound, static_cast<double>(c.L50));
}

}  // namespace

TEST(motion, curved_path_frame_distances_follow_the_ease) {
  // Constant speed and two eases, for each u(s) method: the true arc length covered between
  // consecutive frames equals L (S(x_{f+1}) - S(x_f)) within the method's error bound.
  const curved_case c;
  using cb::arclength::inversion_method;
  for (auto m : {inversion_method::linear_table, inversion_method::hermite_table, inversion_method::newton}) {
    cb::arclength::parameterization_options<double> opt;
    opt.method = m;
    if (m == inversion_method::linear_table) opt.table_intervals = 256;
    const cb::arclength::parameterization arc(c.path, opt);
    check_curved_motion(c, arc, m, cbm::linear_ease<double>{}, cbm::linear_ease<real50>{}, "constant speed");
    check_curved_motion(c, arc, m, cbm::sine_plateau_ease<double>(0.25, 0.75),
                        cbm::sine_plateau_ease<real50>(0.25, 0.75), "sine plateau");
    check_curved_motion(c, arc, m, cbm::smootherstep_ease<double>{}, cbm::smootherstep_ease<real50>{}, "smootherstep");
  }
}
