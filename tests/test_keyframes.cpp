// Keyframe tracks: (frame, value) keys through every family with the frames as knots. Interpolation
// of the keys in all four Real types, polynomial reproduction on irregular frames (Catmull-Rom with
// one-sided ends: quadratics; not-a-knot: cubics; Hermite with exact slopes: cubics), slopes per
// frame, no overshoot for the monotone tracks (where Catmull-Rom overshoots), the seed 002
// channels (position, scale, angle, color) and agreement of a Hermite position track with the
// seed 002 motion, and the error messages.
#include "support/accuracy.hpp"

#include "curvebench/motion/distance_time.hpp"
#include "curvebench/motion/keyframes.hpp"

#include <gmock/gmock.h>

#include <array>
#include <string>
#include <vector>

namespace cb = curvebench;
namespace cbm = curvebench::motion;
namespace cbt = curvebench::testing;
using cb::real50;
using ::testing::HasSubstr;

namespace {

// Tolerances, in eps(Real) times the largest |value| of the track's keys (or of the reproduced
// polynomial / its derivative over the frame range); observed maxima are <= 2 eps:
// - key_ulps: at a key frame the engine evaluates a segment end (c0 plus terms multiplied by a
//   rounded local parameter 0 or 1): a few roundings: 4 eps;
// - reproduction_ulps: inside a segment the engine's cubic in the local parameter carries ~10
//   roundings on terms no larger than the scale, the slopes (parabola derivatives from frame
//   differences) a few more: 16 eps;
// - slope_ulps: derivative per frame = local derivative / h, the same roundings relative to the
//   derivative's scale: 16 eps.
constexpr double key_ulps = 4;
constexpr double reproduction_ulps = 16;
constexpr double slope_ulps = 16;

template <class Real>
class keyframes_test : public ::testing::Test {};
TYPED_TEST_SUITE(keyframes_test, cbt::all_reals);

static_assert(cb::curve<cbm::keyframe_track<double, 1>>);
static_assert(cb::curve<cbm::keyframe_track<cb::real50, 3>>);

template <class Real>
std::vector<cbm::scalar_key<Real>> scale_keys() {  // seed 002 frames, a scale channel
  return {
      {Real(22), Real(1)}, {Real(34), Real(5) / Real(2)}, {Real(50), Real(5) / Real(2)}, {Real(67), Real(1) / Real(2)}};
}

// q(f) = (f - 40)^2 / 64 + 1 on irregular frames (exact in every type at integer frames).
template <class Real>
Real quadratic(const Real& f) {
  return (f - Real(40)) * (f - Real(40)) / Real(64) + Real(1);
}
// c(f) = ((f - 40) / 16)^3 - (f - 40) / 8 + 2
template <class Real>
Real cubic(const Real& f) {
  const Real x = (f - Real(40)) / Real(16);
  return x * x * x - Real(2) * x + Real(2);
}
template <class Real>
Real cubic_slope(const Real& f) {
  const Real x = (f - Real(40)) / Real(16);
  return (Real(3) * x * x - Real(2)) / Real(16);
}
const std::array<int, 7> irregular_frames{22, 30, 34, 41, 50, 58, 67};

template <class Real, class Fn>
std::vector<cbm::key<Real, 1>> sampled_keys(Fn&& fn) {
  std::vector<cbm::key<Real, 1>> k;
  for (int f : irregular_frames) k.push_back({Real(f), cb::point<Real, 1>(fn(Real(f)))});
  return k;
}

}  // namespace

TYPED_TEST(keyframes_test, every_family_interpolates_the_keys) {
  using Real = TypeParam;
  const auto keys = scale_keys<Real>();
  const std::vector<cb::point<Real, 1>> slopes(keys.size(), cb::point<Real, 1>(Real(1) / Real(8)));
  std::vector<cbm::keyframe_track<Real, 1>> tracks;
  for (auto how :
       {cbm::key_interpolation::linear, cbm::key_interpolation::catmull_rom, cbm::key_interpolation::cardinal,
        cbm::key_interpolation::natural_cubic, cbm::key_interpolation::monotone}) {
    cbm::track_options<Real> opt;
    opt.interpolation = how;
    opt.tension_s = Real(3) / Real(10);
    tracks.emplace_back(std::span<const cbm::scalar_key<Real>>(keys), opt);
  }
  const auto k1 = cbm::scalar_keys<Real>(keys);
  tracks.emplace_back(std::span<const cbm::key<Real, 1>>(k1), std::span<const cb::point<Real, 1>>(slopes));
  for (const auto& t : tracks) {
    EXPECT_EQ(t.domain().lo, Real(22));
    EXPECT_EQ(t.domain().hi, Real(67));
    for (const auto& k : keys)
      EXPECT_TRUE(cbt::within_scaled_ulps(t.scalar(k.frame), real50(k.value), real50(5) / 2, key_ulps))
          << cbm::to_string(t.interpolation()) << " frame " << k.frame;
  }
  // the Hermite track has the given slopes (per frame) at the keys
  const auto& h = tracks.back();
  for (const auto& k : keys)
    EXPECT_TRUE(cbt::within_scaled_ulps(h.derivative(k.frame, 1)[0], real50(1) / 8, real50(1) / 8, slope_ulps));
  // linear: halfway between keys is the average
  EXPECT_TRUE(cbt::within_ulps(tracks[0].scalar(Real(28)), real50(7) / 4, key_ulps));
}

TYPED_TEST(keyframes_test, polynomial_reproduction_on_irregular_frames) {
  // Catmull-Rom with one-sided ends reproduces quadratics (its slopes are parabola derivatives);
  // not-a-knot natural splines and Hermite with exact slopes reproduce cubics.
  using Real = TypeParam;
  const auto qk = sampled_keys<Real>(quadratic<Real>);
  const auto ck = sampled_keys<Real>(cubic<Real>);
  cbm::track_options<Real> cr;
  cr.cardinal_ends = cb::cardinal_end::one_sided;
  const cbm::keyframe_track<Real, 1> catmull(std::span<const cbm::key<Real, 1>>(qk), cr);
  cbm::track_options<Real> nak;
  nak.interpolation = cbm::key_interpolation::natural_cubic;
  nak.natural_ends = cb::spline_end::not_a_knot;
  const cbm::keyframe_track<Real, 1> natural(std::span<const cbm::key<Real, 1>>(ck), nak);
  std::vector<cb::point<Real, 1>> exact_slopes;
  for (int f : irregular_frames) exact_slopes.emplace_back(cubic_slope(Real(f)));
  const auto hermite = cbm::hermite_track<Real, 1>(ck, exact_slopes);
  const real50 qscale = quadratic(real50(67)), cscale(4), dscale(1);
  for (int f8 = 22 * 8; f8 <= 67 * 8; ++f8) {
    const Real f = Real(f8) / Real(8);
    const real50 f50(f);
    ASSERT_TRUE(cbt::within_scaled_ulps(catmull.scalar(f), quadratic(f50), qscale, reproduction_ulps)) << f8;
    ASSERT_TRUE(cbt::within_scaled_ulps(catmull.derivative(f, 1)[0], (f50 - 40) / 32, dscale, slope_ulps)) << f8;
    ASSERT_TRUE(cbt::within_scaled_ulps(natural.scalar(f), cubic(f50), cscale, reproduction_ulps)) << f8;
    ASSERT_TRUE(cbt::within_scaled_ulps(hermite(f)[0], cubic(f50), cscale, reproduction_ulps)) << f8;
    ASSERT_TRUE(cbt::within_scaled_ulps(natural.derivative(f, 1)[0], cubic_slope(f50), dscale, slope_ulps)) << f8;
  }
}

TEST(keyframes, monotone_tracks_do_not_overshoot) {
  // A color channel that ramps up, holds at 1 and drops: the monotone track stays in [0, 1] and is
  // flat on the holds; Catmull-Rom on the same keys overshoots (the reason monotone exists).
  const std::vector<cbm::scalar_key<double>> keys{{0, 0}, {10, 0}, {14, 1}, {30, 1}, {33, 0.2}, {40, 0.2}};
  cbm::track_options<double> mono;
  mono.interpolation = cbm::key_interpolation::monotone;
  const cbm::keyframe_track<double, 1> m(keys, mono);
  const cbm::keyframe_track<double, 1> c(keys);
  double cmin = 0, cmax = 1;
  for (int k = 0; k <= 40 * 16; ++k) {
    const double f = k / 16.0;
    const double v = m.scalar(f);
    ASSERT_GE(v, 0.0) << f;
    ASSERT_LE(v, 1.0) << f;
    if ((f >= 0 && f <= 10) || (f >= 33 && f <= 40)) {
      ASSERT_EQ(v, f <= 10 ? 0.0 : 0.2) << f;
    }
    if (f >= 14 && f <= 30) {
      ASSERT_EQ(v, 1.0) << f;
    }
    cmin = std::min(cmin, c.scalar(f));
    cmax = std::max(cmax, c.scalar(f));
  }
  EXPECT_LT(cmin, -0.01);
  EXPECT_GT(cmax, 1.01);
}

TEST(keyframes, seed_002_channels) {
  // Position, scale, orientation angle and color keyed at frames 22, 34, 50, 67 and sampled at
  // every frame. The Hermite position track with the motion's speeds as slopes (0, 20/61, 20/61,
  // 0 per frame) reproduces the seed 002 motion exactly: the motion is quadratic, linear and
  // quadratic in the frame on the three intervals, and Hermite cubics with exact end slopes
  // reproduce those. Its frame samples are compared with the closed form of the motion.
  using point3 = cb::point<double, 3>;
  const double v = 20.0 / 61;
  const std::vector<cbm::key<double, 3>> position{
      {22, point3(-5, 0, 0)}, {34, point3(-185.0 / 61, 0, 0)}, {50, point3(135.0 / 61, 0, 0)}, {67, point3(5, 0, 0)}};
  const std::vector<point3> speeds{point3::Zero(), point3(v, 0, 0), point3(v, 0, 0), point3::Zero()};
  const cbm::keyframe_track<double, 3> pos(position, speeds);
  std::vector<point3> xs(46);
  pos.sample_frames(22, 67, std::span<point3>(xs));
  const auto ease = cbm::parabolic_ease<real50>::from_frames(22, 34, 50, 67);
  for (long long f = 22; f <= 67; ++f) {
    const real50 x = -5 + 10 * ease(real50(f - 22) / 45);
    EXPECT_TRUE(cbt::within_scaled_ulps(xs[std::size_t(f - 22)][0], x, real50(5), 16)) << "frame " << f;
  }
  // scale (monotone: stays within [0.5, 2.5]), angle (Catmull-Rom, radians), color (monotone, RGB)
  const auto sk = scale_keys<double>();
  cbm::track_options<double> mono;
  mono.interpolation = cbm::key_interpolation::monotone;
  const cbm::keyframe_track<double, 1> scale(sk, mono);
  const std::vector<cbm::scalar_key<double>> ak{{22, 0}, {34, 0.5}, {50, 1.5}, {67, 3.14159}};
  const cbm::keyframe_track<double, 1> angle(ak);
  const std::vector<cbm::key<double, 3>> ck{
      {22, point3(1, 0, 0)}, {34, point3(1, 1, 0)}, {50, point3(0, 1, 0)}, {67, point3(0, 0, 1)}};
  const cbm::keyframe_track<double, 3> color(ck, mono);
  for (long long f = 22; f <= 67; ++f) {
    const double fr = static_cast<double>(f);
    EXPECT_GE(scale.scalar(fr), 0.5);
    EXPECT_LE(scale.scalar(fr), 2.5);
    const point3 c = color(fr);
    EXPECT_GE(c.minCoeff(), 0.0) << f;
    EXPECT_LE(c.maxCoeff(), 1.0) << f;
  }
  EXPECT_EQ(scale.scalar(42), 2.5);  // flat between the equal keys 34 and 50
  EXPECT_DOUBLE_EQ(angle.scalar(50), 1.5);
  EXPECT_EQ(color(34.0), point3(1, 1, 0));
  const auto* hermite_color = color.curve().target<cb::hermite_spline<double, 3>>();
  EXPECT_TRUE(hermite_color != nullptr);
  EXPECT_EQ(angle.curve().family(), "catmull_rom");
}

TEST(keyframes, errors_name_the_key) {
  using K = cbm::scalar_key<double>;
  const auto message = [](auto&& fn) -> std::string {
    try {
      fn();
    } catch (const cb::invalid_input& e) {
      return e.what();
    }
    return "(no invalid_input)";
  };
  const std::vector<K> unordered{{0, 1}, {10, 2}, {10, 3}};
  EXPECT_EQ(message([&] { cbm::keyframe_track<double, 1>(std::span<const K>(unordered)); }),
            "keys[2].frame = 10 <= keys[1].frame = 10: key frames must be strictly increasing");
  const std::vector<K> one{{0, 1}};
  EXPECT_EQ(message([&] { cbm::keyframe_track<double, 1>(std::span<const K>(one)); }),
            "keys: 1 given, at least 2 required (a track interpolates between two keys at least)");
  const std::vector<K> nan_value{{0, 1}, {10, std::numeric_limits<double>::quiet_NaN()}};
  EXPECT_EQ(message([&] { cbm::keyframe_track<double, 1>(std::span<const K>(nan_value)); }),
            "keys[1].value[0] = nan: must be finite");
  const std::vector<K> ok{{0, 1}, {10, 2}, {20, 0}};
  cbm::track_options<double> h;
  h.interpolation = cbm::key_interpolation::hermite;
  EXPECT_EQ(message([&] { cbm::keyframe_track<double, 1>(std::span<const K>(ok), h); }),
            "interpolation = hermite needs slopes: use the keyframe_track constructor with slopes");
  const auto k1 = cbm::scalar_keys<double>(ok);
  const std::vector<cb::point<double, 1>> two_slopes(2, cb::point<double, 1>(0.0));
  EXPECT_EQ(message([&] { (void)cbm::hermite_track<double, 1>(k1, two_slopes); }),
            "slopes: 2 given, must match keys: 3");
  EXPECT_EQ(message([&] { (void)cbm::catmull_rom_track<double, 1>(k1, cb::cardinal_end::closed); }),
            "ends = closed: keyframe tracks use phantom or one_sided ends (a closed loop needs an extra key frame; "
            "for given end tangents use hermite_track)");
  const cbm::keyframe_track<double, 1> t(ok);
  EXPECT_THROW((void)t.scalar(20.5), std::domain_error);
  std::vector<cb::point<double, 1>> out(3);
  EXPECT_EQ(message([&] { t.sample_frames(0, 20, std::span<cb::point<double, 1>>(out)); }),
            "sample_frames output: 3 given, must match frames: 21");
}
