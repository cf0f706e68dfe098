// glTF 2.0 animation samplers (channel/gltf.hpp): the closed forms of the spec's Appendix C (step,
// lerp, the Hermite with tangents per second, slerp), the end rules (clamping, key values as
// stored at key times), exact derivatives, float/double/long double against the same sampler in
// real50, rotations against closed-form rotations about a fixed axis, the short path, nlerp's
// deviation from slerp against its derived maximum, and every validation message.
#include "support/accuracy.hpp"
#include "support/fixtures.hpp"

#include "curvebench/channel/gltf.hpp"

#include <gmock/gmock.h>

#include <boost/math/constants/constants.hpp>
#include <boost/math/special_functions/next.hpp>

#include <array>
#include <cmath>
#include <limits>
#include <vector>

namespace cb = curvebench;
namespace cbt = curvebench::testing;
namespace gltf = curvebench::channel::gltf;
using cb::real50;
using ::testing::HasSubstr;

namespace {

// Tolerances, in eps(Real) of the stated scale. u = eps / 2 is the unit roundoff.
// - lerp_ulps (scale: data 4; slopes, at most 9 on these data: 16): s = (t - t_k) / h rounds once
//   (t - t_k is exact on these dyadic times), and u s times |v_{k+1} - v_k| <= 8 is <= 1 eps of the
//   scale; 1 - s, the two products and the sum add 4 u of values <= the scale: 3 eps in all; 4.
//   The slope is a difference and a division: 2 u of the slope scale.
// - hermite_ulps (scale: data 4, times 4^order for order >= 1, h >= 1/4): each basis function is
//   4 roundings of terms up to 3 (<= 8 eps absolute) and moves by <= 1.5 u through the rounding
//   of s; four of them weigh values and h * tangents up to 1.5 * 4: 4 * 9.5 eps * 1.5 plus the
//   3 roundings of the sum: ~60 eps of the scale in the worst case; 64.
// - rotation_ulps (absolute, components <= 1): slerp's angle (two norms and atan2, ~4 u relative),
//   its sines (1 u each, and an a-relative error moves sin(a s)/sin(a) by <= 2 x that), the two
//   products and the sum: <= 12 eps; nlerp and the normalization: a sum, a norm (3 u) and a
//   division: <= 6 eps. 16 for both. Derivatives scale by (a / h)^m, which the scale carries.
// - cubic_rotation_ulps: the Hermite on 4 components (hermite_ulps, data scale 2 instead of 4) then
//   the normalization (6 eps), the Hermite's error divided by |p|, taken >= 1/2 for these random
//   keys (keys near v_{k+1} = -v_k would need more): 2 * (64 / 2 + 6); 80.
// - angle_ulps (in eps of the reference angle theta(tau) >= 0.3): the keys round to Real
//   (|dq| <= 2 u, angle error <= 4 u), slerp's own 12 eps (times 2: a rotation angle is twice
//   the 4-vector angle): <= 28 eps absolute (angle_abs_ulps: 32), / 0.3 rad = 93; 96.
// - segment_angle_ulps (absolute): two rounded keys (4 u each in the 4-vector angle) and the
//   norms and atan2 (~4 u), doubled for the rotation angle: 12 eps; 16.
// - unit_ulps: | |q| - 1 | after normalization: a norm (3 u) and a division (u) then the norm of
//   the result measured in real50: 2 eps; 4.
// - fd_relative: central differences in real50 with step h = 1e-12: truncation h^2 |f'''| / 6 and
//   h^2 |f''''| / 12 (~1e-24 of the scale), rounding 1e-49 / h^2 = 1e-25 for the second
//   difference; 1e-18 leaves a margin of 1e6 and still fails for any wrong formula.
constexpr double lerp_ulps = 4;
constexpr double hermite_ulps = 64;
constexpr double rotation_ulps = 16;
constexpr double cubic_rotation_ulps = 80;
constexpr double angle_ulps = 96;
constexpr double angle_abs_ulps = 32;
constexpr double segment_angle_ulps = 16;
constexpr double unit_ulps = 4;
constexpr double fd_relative = 1e-18;
const double data_scale = 4.0;  // max |value| and |tangent| of the vector data

template <class Real>
class gltf_test : public ::testing::Test {};
TYPED_TEST_SUITE(gltf_test, cbt::all_reals);

template <class Real>
class gltf_ieee_test : public ::testing::Test {};
TYPED_TEST_SUITE(gltf_ieee_test, cbt::ieee_reals);

// Non-uniform dyadic key times and values, exact in every type.
const std::vector<double> td{0.0, 0.25, 1.0, 1.5, 3.0};
const std::vector<std::array<double, 3>> vd{{0, 1, -2}, {1.5, -0.5, 0.25}, {2, 2.25, -1}, {-1, 0.5, 3}, {3, 0, 1.75}};
// cubicspline output: in-tangent, value, out-tangent per key; broken tangents (a_k != b_k).
const std::vector<std::array<double, 3>> cd{{0, 0, 0},        {0, 1, -2},        {1, 0, -0.5},     // key 0 (a_0 unused)
                                            {2, -1, 0.5},     {1.5, -0.5, 0.25}, {-1.5, 2, 1},     // key 1
                                            {0.5, 0.5, -3},   {2, 2.25, -1},     {0.25, -2, 4},    // key 2
                                            {-2, 1, 1},       {-1, 0.5, 3},      {1, 1.5, -0.75},  // key 3
                                            {0.75, -1.25, 2}, {3, 0, 1.75},      {0, 0, 0}};       // key 4 (b_4 unused)

template <class Real>
std::vector<Real> times() {
  return std::vector<Real>(td.begin(), td.end());
}

template <class Real>
gltf::sampler<Real, 3> make_sampler(gltf::interpolation mode) {
  const auto out = cbt::points_from<Real>(mode == gltf::interpolation::cubicspline ? cd : vd);
  return gltf::sampler<Real, 3>(times<Real>(), std::span<const cb::point<Real, 3>>(out), mode);
}

// Times to sample: every key, points inside each segment (dyadic where possible), outside both ends.
std::vector<double> sample_times() {
  std::vector<double> ts{-1.0, -0.125, 3.25, 10.0};
  for (std::size_t k = 0; k + 1 < td.size(); ++k)
    for (int j = 0; j < 16; ++j) ts.push_back(td[k] + (td[k + 1] - td[k]) * j / 16.0);
  ts.push_back(td.back());
  ts.push_back(0.3);
  ts.push_back(2.718281828459045);
  return ts;
}

// A rotation about the unit axis n by angle theta: (sin(theta/2) n, cos(theta/2)), x y z w.
cb::point<real50, 4> axis_angle(const cb::point<real50, 3>& n, const real50& theta) {
  using std::cos;
  using std::sin;
  const real50 h = theta / 2;
  return {sin(h) * n[0], sin(h) * n[1], sin(h) * n[2], cos(h)};
}

cb::point<real50, 3> unit_axis() {
  cb::point<real50, 3> n(real50(2), real50(-3), real50(6));
  return n / real50(7);
}

template <class Real>
cb::point<Real, 4> to_real(const cb::point<real50, 4>& q) {
  cb::point<Real, 4> r;
  for (int d = 0; d < 4; ++d) r[d] = static_cast<Real>(q[d]);
  return r;
}

// Unit quaternions rounded to float (so exact in every type): random directions in double.
std::vector<cb::point<float, 4>> float_unit_quaternions(int count, unsigned seed) {
  const auto p = cbt::random_points<double, 4>(count, seed);
  std::vector<cb::point<float, 4>> q;
  for (const auto& x : p) {
    const cb::point<double, 4> u = x / x.norm();
    q.push_back(u.cast<float>());
  }
  return q;
}

template <class Real, int Dim>
cb::point<real50, Dim> to50(const cb::point<Real, Dim>& p) {
  return cb::point_cast<real50>(p);
}

}  // namespace

TEST(gltf_names, interpolation_and_blend_names_round_trip_in_lowercase) {
  for (auto i : {gltf::interpolation::step, gltf::interpolation::linear, gltf::interpolation::cubicspline})
    EXPECT_EQ(gltf::from_string<gltf::interpolation>(gltf::to_string(i)), i);
  EXPECT_STREQ(gltf::to_string(gltf::interpolation::cubicspline), "cubicspline");
  EXPECT_STREQ(gltf::to_string(gltf::interpolation::step), "step");
  EXPECT_STREQ(gltf::to_string(gltf::interpolation::linear), "linear");
  for (auto b : {gltf::rotation_blend::slerp, gltf::rotation_blend::nlerp})
    EXPECT_EQ(gltf::from_string<gltf::rotation_blend>(gltf::to_string(b)), b);
  EXPECT_STREQ(gltf::to_string(gltf::rotation_blend::nlerp), "nlerp");
  EXPECT_EQ(cbt::message_of([] { (void)gltf::from_string<gltf::interpolation>("LINEAR"); }),
            "interpolation = \"LINEAR\": must be one of step, linear, cubicspline (the glTF names in lowercase)");
  EXPECT_EQ(cbt::message_of([] { (void)gltf::from_string<gltf::rotation_blend>("squad"); }),
            "rotation blend = \"squad\": must be one of slerp, nlerp");
}

TYPED_TEST(gltf_test, hermite_basis_is_the_spec_cubic_and_a_partition_of_unity) {
  using Real = TypeParam;
  for (int j = 0; j <= 16; ++j) {
    const Real s = Real(j) / Real(16);  // s, s^2, s^3 exact in every type: every basis value is exact
    const real50 x = real50(j) / 16;
    const auto h = gltf::hermite_basis(s);
    EXPECT_EQ(real50(h[0]), 2 * x * x * x - 3 * x * x + 1) << j;
    EXPECT_EQ(real50(h[1]), x * x * x - 2 * x * x + x) << j;
    EXPECT_EQ(real50(h[2]), -2 * x * x * x + 3 * x * x) << j;
    EXPECT_EQ(real50(h[3]), x * x * x - x * x) << j;
    EXPECT_EQ(h[0] + h[2], Real(1)) << j;  // the value weights sum to 1: constants are reproduced
    for (int order = 1; order <= 4; ++order) {
      const auto d = gltf::hermite_basis(s, order);
      EXPECT_EQ(d[0] + d[2], Real(0)) << j << " order " << order;
    }
  }
  // Derivatives are those of the polynomials (checked at s = 1/4 against differentiation by hand).
  const auto d1 = gltf::hermite_basis(Real(1) / Real(4), 1);
  EXPECT_EQ(d1[1], Real(3) / Real(16) - Real(1) + Real(1));  // 3 s^2 - 4 s + 1
  EXPECT_EQ(d1[3], Real(3) / Real(16) - Real(1) / Real(2));  // 3 s^2 - 2 s
}

TYPED_TEST(gltf_test, linear_is_lerp_with_constant_slope) {
  using Real = TypeParam;
  const auto s = make_sampler<Real>(gltf::interpolation::linear);
  for (std::size_t k = 0; k + 1 < td.size(); ++k)
    for (int j = 1; j < 16; ++j) {
      const double t = td[k] + (td[k + 1] - td[k]) * j / 16.0;
      const real50 u = (real50(t) - real50(td[k])) / (real50(td[k + 1]) - real50(td[k]));
      cb::point<real50, 3> ref, slope;
      for (int d = 0; d < 3; ++d) {
        ref[d] = (1 - u) * real50(vd[k][d]) + u * real50(vd[k + 1][d]);
        slope[d] = (real50(vd[k + 1][d]) - real50(vd[k][d])) / (real50(td[k + 1]) - real50(td[k]));
      }
      ASSERT_TRUE(cbt::point_within(s(Real(t)), ref, real50(data_scale), lerp_ulps)) << "t=" << t;
      ASSERT_TRUE(cbt::point_within(s.derivative(Real(t), 1), slope, real50(data_scale) * 4, lerp_ulps)) << t;
      EXPECT_EQ(s.derivative(Real(t), 2), (cb::point<Real, 3>::Zero())) << t;
    }
}

TYPED_TEST(gltf_test, cubicspline_ends_are_the_keys_and_slopes_are_the_tangents_per_second) {
  using Real = TypeParam;
  const auto s = make_sampler<Real>(gltf::interpolation::cubicspline);
  const auto out = cbt::points_from<Real>(cd);
  for (std::size_t k = 0; k + 1 < td.size(); ++k) {
    const Real t0 = Real(td[k]), t1 = Real(td[k + 1]);
    // The Hermite at s = 0 and s = 1 is the key value (the spec's basis weights are 1 and 0 there).
    EXPECT_EQ(s.derivative(t0, 0, gltf::side::right), out[3 * k + 1]) << k;
    EXPECT_EQ(s.derivative(t1, 0, gltf::side::left), out[3 * k + 4]) << k;
    // dv/dt = t_d b_k / t_d = b_k leaving key k and a_{k+1} arriving at key k + 1: exact, since
    // the slope is computed without multiplying the tangent by t_d first.
    EXPECT_EQ(s.derivative(t0, 1, gltf::side::right), out[3 * k + 2]) << k;
    EXPECT_EQ(s.derivative(t1, 1, gltf::side::left), out[3 * k + 3]) << k;
  }
  // With broken tangents the two one-sided slopes at an interior key differ (a_2 != b_2).
  EXPECT_NE(s.derivative(Real(1), 1, gltf::side::left), s.derivative(Real(1), 1, gltf::side::right));
}

TYPED_TEST(gltf_test, cubicspline_reproduces_a_cubic_sampled_with_exact_tangents) {
  using Real = TypeParam;
  // P(t) = (1 - 2t + t^2/2 + t^3/4, -3 + t/2 - t^2 + t^3/8): values and slopes at the dyadic key
  // times are exact in float, so every Real holds the same data.
  const std::array<std::array<double, 4>, 2> c{{{1, -2, 0.5, 0.25}, {-3, 0.5, -1, 0.125}}};
  const auto poly = [&](const real50& t, int d, int order) {
    const real50 a0(c[d][0]), a1(c[d][1]), a2(c[d][2]), a3(c[d][3]);
    switch (order) {
      case 0: return ((a3 * t + a2) * t + a1) * t + a0;
      case 1: return (3 * a3 * t + 2 * a2) * t + a1;
      case 2: return 6 * a3 * t + 2 * a2;
      case 3: return 6 * a3;
      default: return real50(0);
    }
  };
  std::vector<cb::point<Real, 2>> out;
  for (double t : td) {
    cb::point<Real, 2> v, m;
    for (int d = 0; d < 2; ++d) {
      v[d] = static_cast<Real>(poly(real50(t), d, 0));
      m[d] = static_cast<Real>(poly(real50(t), d, 1));
    }
    out.insert(out.end(), {m, v, m});
  }
  const gltf::sampler<Real, 2> s(times<Real>(), std::span<const cb::point<Real, 2>>(out),
                                 gltf::interpolation::cubicspline);
  const real50 scale(16);  // |P| <= 7, |P'| <= 8 on [0, 3], h * |P'| <= 12
  for (double t : sample_times()) {
    if (t < 0 || t > 3) continue;
    for (int order = 0; order <= 3; ++order) {
      cb::point<real50, 2> ref;
      for (int d = 0; d < 2; ++d) ref[d] = poly(real50(t), d, order);
      const auto side = t == 3.0 ? gltf::side::left : gltf::side::right;
      ASSERT_TRUE(
          cbt::point_within(s.derivative(Real(t), order, side), ref, scale * std::pow(4.0, order), hermite_ulps))
          << "t=" << t << " order=" << order;
    }
    EXPECT_EQ(s.derivative(Real(t), 4, gltf::side::left), (cb::point<Real, 2>::Zero()));
  }
}

TYPED_TEST(gltf_test, cubicspline_with_secant_tangents_is_linear) {
  using Real = TypeParam;
  // b_k = a_{k+1} = (v_{k+1} - v_k) / t_d on every segment makes the Hermite the straight line,
  // because the tangents are per second and the formula multiplies them by t_d. On these
  // non-uniform keys (t_d = 1/4, 3/4, 1/2, 3/2) a formula without that factor is off by O(1).
  // a_0 and b_4 hold the end values, which the spec never uses. Tolerance: both samplers' own.
  const auto v = cbt::points_from<Real>(vd);
  const std::vector<Real> t = times<Real>();
  std::vector<cb::point<Real, 3>> out;
  for (std::size_t k = 0; k < v.size(); ++k) {
    const cb::point<Real, 3> in = k > 0 ? cb::point<Real, 3>((v[k] - v[k - 1]) / (t[k] - t[k - 1])) : v[k];
    const cb::point<Real, 3> leave =
        k + 1 < v.size() ? cb::point<Real, 3>((v[k + 1] - v[k]) / (t[k + 1] - t[k])) : v[k];
    out.insert(out.end(), {in, v[k], leave});
  }
  const gltf::sampler<Real, 3> cubic(t, std::span<const cb::point<Real, 3>>(out), gltf::interpolation::cubicspline);
  const auto line = make_sampler<Real>(gltf::interpolation::linear);
  for (double x : sample_times())
    for (int order = 0; order <= 2; ++order)
      ASSERT_TRUE(cbt::point_within(cubic.derivative(Real(x), order), to50(line.derivative(Real(x), order)),
                                    real50(data_scale) * real50(std::pow(4.0, order)), hermite_ulps + lerp_ulps))
          << "t=" << x << " order=" << order;
}

TYPED_TEST(gltf_test, scalar_channels_and_constants) {
  using Real = TypeParam;
  // A scalar (Dim = 1) cubicspline with equal values and zero tangents is that constant exactly
  // (h00 + h01 = 1 is exact on dyadic s, and the tangent terms vanish).
  const std::vector<Real> out{Real(0), Real(2.5), Real(0), Real(0), Real(2.5), Real(0), Real(0), Real(2.5), Real(0)};
  const gltf::sampler<Real, 1> s(std::vector<Real>{Real(0), Real(0.5), Real(2.5)}, std::span<const Real>(out),
                                 gltf::interpolation::cubicspline);
  for (int j = -4; j <= 40; ++j) EXPECT_EQ(s.scalar(Real(j) / Real(16)), Real(2.5)) << j;
  EXPECT_EQ(s.key_count(), 3u);
  EXPECT_EQ(s.mode(), gltf::interpolation::cubicspline);
  ASSERT_EQ(s.in_tangents().size(), 3u);
}

TYPED_TEST(gltf_test, clamps_outside_the_keys_and_a_single_key_is_constant) {
  using Real = TypeParam;
  for (auto mode : {gltf::interpolation::step, gltf::interpolation::linear, gltf::interpolation::cubicspline}) {
    const auto s = make_sampler<Real>(mode);
    const auto first = s.values().front(), last = s.values().back();
    for (double t : {-1e30, -1.0, -0.125}) {
      EXPECT_EQ(s(Real(t)), first) << gltf::to_string(mode) << " t=" << t;
      EXPECT_EQ(s.derivative(Real(t), 1), (cb::point<Real, 3>::Zero())) << gltf::to_string(mode);
    }
    for (double t : {3.0, 3.25, 1e30}) {
      EXPECT_EQ(s(Real(t)), last) << gltf::to_string(mode) << " t=" << t;
      EXPECT_EQ(s.derivative(Real(t), 1), (cb::point<Real, 3>::Zero())) << gltf::to_string(mode);
      EXPECT_EQ(s.derivative(Real(t), 2), (cb::point<Real, 3>::Zero())) << gltf::to_string(mode);
    }
    // Time 0 is the first key: the right derivative is the first segment's, the left one 0.
    if (mode != gltf::interpolation::step) {
      EXPECT_NE(s.derivative(Real(0), 1), (cb::point<Real, 3>::Zero())) << gltf::to_string(mode);
    }
    EXPECT_EQ(s.derivative(Real(0), 1, gltf::side::left), (cb::point<Real, 3>::Zero())) << gltf::to_string(mode);
  }
  const std::vector<cb::point<Real, 3>> one{cb::point<Real, 3>(Real(1), Real(-2), Real(0.5))};
  for (auto mode : {gltf::interpolation::step, gltf::interpolation::linear}) {
    const gltf::sampler<Real, 3> s(std::vector<Real>{Real(2)}, std::span<const cb::point<Real, 3>>(one), mode);
    for (double t : {0.0, 2.0, 7.0}) {
      EXPECT_EQ(s(Real(t)), one[0]);
      EXPECT_EQ(s.derivative(Real(t), 1), (cb::point<Real, 3>::Zero()));
    }
  }
}

TYPED_TEST(gltf_test, step_holds_the_key_at_or_before_t) {
  using Real = TypeParam;
  const auto s = make_sampler<Real>(gltf::interpolation::step);
  const auto v = cbt::points_from<Real>(vd);
  for (std::size_t k = 0; k < td.size(); ++k) {
    const Real t = Real(td[k]);
    EXPECT_EQ(s(t), v[k]) << k;  // at a key time: that key, as stored
    if (k > 0) {
      const Real before = boost::math::float_prior(t);
      EXPECT_EQ(s(before), v[k - 1]) << k;                             // just before: the previous key
      EXPECT_EQ(s.derivative(t, 0, gltf::side::left), v[k - 1]) << k;  // the left limit at the jump
    }
    if (k + 1 < td.size()) {
      const Real mid = (Real(td[k]) + Real(td[k + 1])) / Real(2);
      EXPECT_EQ(s(mid), v[k]) << k;
      EXPECT_EQ(s.derivative(mid, 1), (cb::point<Real, 3>::Zero())) << k;  // piecewise constant
    }
  }
}

TYPED_TEST(gltf_test, key_times_return_the_stored_values_as_is) {
  using Real = TypeParam;
  for (auto mode : {gltf::interpolation::linear, gltf::interpolation::cubicspline}) {
    const auto s = make_sampler<Real>(mode);
    for (std::size_t k = 0; k < td.size(); ++k) EXPECT_EQ(s(Real(td[k])), s.values()[k]) << gltf::to_string(mode);
  }
  // A rotation key 0.5% off unit length (within the validator's tolerance) is returned as stored at
  // its time; between keys the cubicspline result is normalized.
  const cb::point<Real, 4> z = cb::point<Real, 4>::Zero();
  const cb::point<Real, 4> q0(Real(0), Real(0), Real(0), Real(1.005));
  const cb::point<Real, 4> q1(Real(0), Real(0.6), Real(0), Real(0.8));
  const std::vector<cb::point<Real, 4>> out{z, q0, z, z, q1, z};
  const gltf::rotation_sampler<Real> r(std::vector<Real>{Real(0), Real(1)}, std::span<const cb::point<Real, 4>>(out),
                                       gltf::interpolation::cubicspline);
  EXPECT_EQ(r(Real(0)), q0);
  EXPECT_EQ(r(Real(1)), q1);
  EXPECT_TRUE(cbt::within_scaled_ulps(cb::safe_norm<Real, 4>(r(Real(0.25))), real50(1), real50(1), unit_ulps));
}

TYPED_TEST(gltf_ieee_test, vector_channels_match_the_real50_sampler) {
  using Real = TypeParam;
  for (auto mode : {gltf::interpolation::step, gltf::interpolation::linear, gltf::interpolation::cubicspline}) {
    const auto s = make_sampler<Real>(mode);
    const auto r = make_sampler<real50>(mode);
    const double tol = mode == gltf::interpolation::cubicspline ? hermite_ulps : lerp_ulps;
    real50 worst(0);
    for (double t : sample_times())
      for (int order = 0; order <= 3; ++order)
        for (auto side : {gltf::side::right, gltf::side::left}) {
          const auto a = s.derivative(Real(t), order, side);
          const auto ref = r.derivative(real50(t), order, side);
          const real50 scale = real50(data_scale) * real50(std::pow(4.0, order));
          for (int d = 0; d < 3; ++d) worst = std::max(worst, cbt::scaled_ulps(a[d], ref[d], scale));
          ASSERT_TRUE(cbt::point_within(a, ref, scale, tol))
              << gltf::to_string(mode) << " t=" << t << " order=" << order;
        }
    this->RecordProperty(std::string("max_ulps_") + gltf::to_string(mode), std::to_string(static_cast<double>(worst)));
  }
}

TEST(gltf_real50, derivatives_match_finite_differences) {
  // Central differences of the real50 value (step 1e-12) inside segments, for every channel kind.
  const real50 h("1e-12");
  const auto check = [&](const auto& f, const char* what) {
    for (double t : {0.1, 0.3, 0.7, 1.2, 2.0, 2.9}) {
      const real50 x(t);
      const auto f0 = f.derivative(x, 0), fp = f.derivative(x + h, 0), fm = f.derivative(x - h, 0);
      const auto d1 = f.derivative(x, 1), d2 = f.derivative(x, 2);
      const auto fd1 = ((fp - fm) / (2 * h)).eval();
      const auto fd2 = ((fp - real50(2) * f0 + fm) / (h * h)).eval();
      const real50 s1 = 1 + d1.norm(), s2 = 1 + d2.norm();
      for (int d = 0; d < fd1.size(); ++d) {
        ASSERT_TRUE(cbt::within_relative(d1[d], fd1[d], fd_relative, static_cast<double>(s1)))
            << what << " t=" << t << " d/dt";
        ASSERT_TRUE(cbt::within_relative(d2[d], fd2[d], fd_relative, static_cast<double>(s2)))
            << what << " t=" << t << " d2/dt2";
      }
    }
  };
  for (auto mode : {gltf::interpolation::linear, gltf::interpolation::cubicspline})
    check(make_sampler<real50>(mode), gltf::to_string(mode));
  const auto qf = float_unit_quaternions(5, 7u);
  std::vector<cb::point<real50, 4>> q, q3;
  for (const auto& x : qf) q.push_back(cb::point_cast<real50>(x));
  const auto tan = cbt::random_points<float, 4>(10, 11u);
  for (std::size_t k = 0; k < q.size(); ++k)
    q3.insert(q3.end(), {cb::point_cast<real50>(tan[2 * k]), q[k], cb::point_cast<real50>(tan[2 * k + 1])});
  check(gltf::rotation_sampler<real50>(times<real50>(), q, gltf::interpolation::linear), "slerp");
  check(gltf::rotation_sampler<real50>(times<real50>(), q, gltf::interpolation::linear, gltf::rotation_blend::nlerp),
        "nlerp");
  check(gltf::rotation_sampler<real50>(times<real50>(), q3, gltf::interpolation::cubicspline), "cubic rotation");
}

TYPED_TEST(gltf_ieee_test, rotation_channels_match_the_real50_sampler) {
  using Real = TypeParam;
  const auto qf = float_unit_quaternions(5, 3u);
  const auto tan = cbt::random_points<float, 4>(10, 5u);
  std::vector<cb::point<Real, 4>> q, q3;
  for (std::size_t k = 0; k < qf.size(); ++k) {
    q.push_back(qf[k].cast<Real>());
    q3.insert(q3.end(), {tan[2 * k].cast<Real>(), qf[k].cast<Real>(), tan[2 * k + 1].cast<Real>()});
  }
  const auto q50 = cb::points_cast<real50, Real, 4>(q);
  const auto q350 = cb::points_cast<real50, Real, 4>(q3);
  struct kind {
    gltf::interpolation mode;
    gltf::rotation_blend blend;
    double ulps;
    int orders;
  };
  for (const kind& c : {kind{gltf::interpolation::linear, gltf::rotation_blend::slerp, rotation_ulps, 4},
                        kind{gltf::interpolation::linear, gltf::rotation_blend::nlerp, rotation_ulps, 2},
                        kind{gltf::interpolation::step, gltf::rotation_blend::slerp, 0, 2},
                        kind{gltf::interpolation::cubicspline, gltf::rotation_blend::slerp, cubic_rotation_ulps, 2}}) {
    const bool cubic = c.mode == gltf::interpolation::cubicspline;
    const gltf::rotation_sampler<Real> s(times<Real>(), cubic ? q3 : q, c.mode, c.blend);
    const gltf::rotation_sampler<real50> r(times<real50>(), cubic ? q350 : q50, c.mode, c.blend);
    real50 worst(0);
    for (double t : sample_times())
      for (int order = 0; order <= c.orders; ++order) {
        const auto a = s.derivative(Real(t), order);
        const auto ref = r.derivative(real50(t), order);
        const real50 scale = 1 + ref.norm();  // derivatives grow as (a / h)^m: the scale carries it
        for (int d = 0; d < 4; ++d) worst = std::max(worst, cbt::scaled_ulps(a[d], ref[d], scale));
        ASSERT_TRUE(cbt::point_within(a, ref, scale, c.ulps))
            << gltf::to_string(c.mode) << "/" << gltf::to_string(c.blend) << " t=" << t << " order=" << order;
      }
    this->RecordProperty(std::string("max_ulps_") + gltf::to_string(c.mode) + "_" + gltf::to_string(c.blend),
                         std::to_string(static_cast<double>(worst)));
  }
}

TYPED_TEST(gltf_test, slerp_is_the_rotation_about_a_fixed_axis_at_the_interpolated_angle) {
  using Real = TypeParam;
  // Keys about one axis; consecutive angles differ by less than pi, so the short path is the
  // direct one and slerp is the rotation by theta_k + s (theta_{k+1} - theta_k).
  const std::vector<double> theta{0.3, 1.1, 2.9, 2.0, 0.7};
  const auto n = unit_axis();
  std::vector<cb::point<Real, 4>> q;
  for (double a : theta) q.push_back(to_real<Real>(axis_angle(n, real50(a))));
  const gltf::rotation_sampler<Real> s(times<Real>(), q, gltf::interpolation::linear);
  real50 worst(0);
  for (std::size_t k = 0; k + 1 < td.size(); ++k)
    for (int j = 0; j <= 16; ++j) {
      const double t = td[k] + (td[k + 1] - td[k]) * j / 16.0;
      const real50 u = (real50(t) - real50(td[k])) / (real50(td[k + 1]) - real50(td[k]));
      const real50 angle = real50(theta[k]) + u * (real50(theta[k + 1]) - real50(theta[k]));
      const real50 err = gltf::angular_distance<real50>(to50(s(Real(t))), axis_angle(n, angle));
      const real50 in_ulps = err / (real50(cb::epsilon<Real>()) * angle);
      worst = std::max(worst, in_ulps);
      ASSERT_LE(in_ulps, real50(angle_ulps)) << "t=" << t << " error " << static_cast<double>(err) << " rad";
    }
  this->RecordProperty("max_angle_ulps", std::to_string(static_cast<double>(worst)));
  // The segment angle is the rotation between keys (theta_{k+1} - theta_k), to the key rounding.
  for (std::size_t k = 0; k + 1 < td.size(); ++k)
    EXPECT_TRUE(cbt::within_scaled_ulps(s.segment_angle(k), abs(real50(theta[k + 1]) - real50(theta[k])), real50(1),
                                        segment_angle_ulps))
        << k;
}

TYPED_TEST(gltf_test, slerp_takes_the_short_path_whatever_the_sign_of_the_stored_key) {
  using Real = TypeParam;
  using boost::math::constants::two_pi;
  const auto n = unit_axis();
  // 0.2 rad to 6.0 rad about n: the rotations are 2 pi - 5.8 = 0.48 rad apart the short way round,
  // so slerp turns by -0.48 rad, not +5.8 rad. The dot product of the stored keys is cos(2.9) < 0.
  const real50 a0("0.2"), a1("6.0"), short_end = a1 - two_pi<real50>();
  for (int sign : {1, -1}) {
    const std::vector<cb::point<Real, 4>> q{to_real<Real>(axis_angle(n, a0)),
                                            to_real<Real>(cb::point<real50, 4>(real50(sign) * axis_angle(n, a1)))};
    const gltf::rotation_sampler<Real> s(std::vector<Real>{Real(0), Real(1)}, q, gltf::interpolation::linear);
    for (int j = 0; j <= 8; ++j) {
      const real50 u = real50(j) / 8;
      const real50 err =
          gltf::angular_distance<real50>(to50(s(Real(j) / Real(8))), axis_angle(n, a0 + u * (short_end - a0)));
      ASSERT_LE(err, real50(angle_abs_ulps) * real50(cb::epsilon<Real>())) << "sign " << sign << " j=" << j;
    }
    EXPECT_TRUE(cbt::within_scaled_ulps(s.segment_angle(0), real50(a0 - short_end), real50(1), segment_angle_ulps));
    // The path does not pass through the long way's midpoint (rotation by 3.1 rad).
    EXPECT_GT(gltf::angular_distance<real50>(to50(s(Real(0.5))), axis_angle(n, (a0 + a1) / 2)), real50(3));
  }
}

TYPED_TEST(gltf_test, nlerp_deviates_from_slerp_by_at_most_the_derived_bound) {
  using Real = TypeParam;
  // Derivation. Unit keys v, w (after the sign flip) at 4-vector angle a in (0, pi/2]. slerp is at
  // angle a s from v; nlerp's p = (1 - s) v + s w is at phi(s) = atan2(s sin a, 1 - s + s cos a),
  // with phi' = sin a / |p|^2 and |p|^2 = 1 - 2 s (1 - s)(1 - cos a). f = phi - a s vanishes at
  // s = 0, 1/2, 1 and is extreme where phi' = a, i.e. s (1 - s) = (1 - sin a / a) / (2 (1 - cos a)),
  // at s* the root below 1/2. The rotation angle between the two is 2 |f(s*)|.
  using std::abs;
  using std::atan2;
  using std::cos;
  using std::sin;
  using std::sqrt;
  const auto n = unit_axis();
  for (double rotation : {0.5, 1.5, 3.0}) {
    const real50 a = real50(rotation) / 2;
    const real50 c = (1 - sin(a) / a) / (2 * (1 - cos(a)));
    const real50 s_star = (1 - sqrt(1 - 4 * c)) / 2;
    const real50 bound = 2 * abs(atan2(s_star * sin(a), 1 - s_star + s_star * cos(a)) - a * s_star);
    const std::vector<cb::point<Real, 4>> q{to_real<Real>(axis_angle(n, real50(0))),
                                            to_real<Real>(axis_angle(n, real50(rotation)))};
    const gltf::rotation_sampler<Real> slerp(std::vector<Real>{Real(0), Real(1)}, q, gltf::interpolation::linear);
    const gltf::rotation_sampler<Real> nlerp(std::vector<Real>{Real(0), Real(1)}, q, gltf::interpolation::linear,
                                             gltf::rotation_blend::nlerp);
    real50 worst(0);
    for (int j = 0; j <= 1024; ++j) {
      const Real t = Real(j) / Real(1024);
      worst = std::max(worst, gltf::angular_distance<real50>(to50(nlerp(t)), to50(slerp(t))));
    }
    // Both evaluations round (rotation_ulps each, doubled as rotation angles).
    const real50 rounding = 4 * real50(rotation_ulps) * real50(cb::epsilon<Real>());
    EXPECT_LE(worst, bound + rounding) << "rotation " << rotation;
    // The grid (step 1/1024) comes within (1/2048)^2 x |f''| of the maximum: the bound is attained.
    EXPECT_GE(worst, real50("0.99") * bound - rounding) << "rotation " << rotation;
  }
}

TYPED_TEST(gltf_test, cubicspline_rotation_is_unit_and_its_derivative_is_tangent) {
  using Real = TypeParam;
  const auto qf = float_unit_quaternions(5, 13u);
  const auto tan = cbt::random_points<float, 4>(10, 17u);
  std::vector<cb::point<Real, 4>> q3;
  for (std::size_t k = 0; k < qf.size(); ++k)
    q3.insert(q3.end(), {tan[2 * k].cast<Real>(), qf[k].cast<Real>(), tan[2 * k + 1].cast<Real>()});
  const gltf::rotation_sampler<Real> s(times<Real>(), q3, gltf::interpolation::cubicspline);
  for (double t : sample_times()) {
    const cb::point<Real, 4> v = s(Real(t));
    const bool at_key = std::find(td.begin(), td.end(), t) != td.end() || t < 0 || t > 3;
    // Keys are stored as given: float-rounded unit quaternions, whose 4 components carry 2^-24
    // relative each, so |q| is within 2 x 2^-24 ~ 1.2e-7 of 1. Elsewhere the result is normalized.
    if (at_key)
      EXPECT_TRUE(cbt::within_relative(cb::safe_norm<Real, 4>(v), real50(1), 1.2e-7)) << "t=" << t;
    else
      EXPECT_TRUE(cbt::within_scaled_ulps(cb::safe_norm<Real, 4>(v), real50(1), real50(1), unit_ulps)) << "t=" << t;
    // |q| = 1 makes q . q' = 0.
    const auto d1 = s.derivative(Real(t), 1);
    EXPECT_TRUE(cbt::within_scaled_ulps(v.dot(d1), real50(0), 1 + to50(d1).norm(), 4 * rotation_ulps)) << t;
  }
}

TYPED_TEST(gltf_test, angular_distance_is_accurate_for_small_angles_and_sign_blind) {
  using Real = TypeParam;
  const auto n = unit_axis();
  for (const char* angle : {"1e-6", "0.001", "0.75", "3.1"}) {
    const real50 a(angle);
    const cb::point<Real, 4> q = to_real<Real>(axis_angle(n, real50(0.25)));
    const cb::point<real50, 4> r50 = axis_angle(n, real50(0.25) + a);
    // In real50 the distance is within 16 eps of the angle, absolute, even for 1e-6 rad: the inputs'
    // rounding (u per component, 4u in the 4-vector angle, doubled in the rotation angle) and the
    // formula's few roundings. arccos(q . r) would lose a factor 1 / sin(angle / 2) ~ 2e6 there.
    EXPECT_TRUE(
        cbt::within_scaled_ulps(gltf::angular_distance<real50>(axis_angle(n, real50(0.25)), r50), a, real50(1), 16))
        << angle;
    EXPECT_EQ(gltf::angular_distance<Real>(q, q), Real(0));
    EXPECT_EQ(gltf::angular_distance<Real>(q, to_real<Real>(r50)),
              gltf::angular_distance<Real>(q, cb::point<Real, 4>(-to_real<Real>(r50))));
  }
}

TEST(gltf_validation, every_error_names_the_field_the_index_and_the_value) {
  using P3 = cb::point<double, 3>;
  using Q = cb::point<double, 4>;
  const auto lin = gltf::interpolation::linear;
  const auto cub = gltf::interpolation::cubicspline;
  const auto vec = [](std::vector<double> in, std::vector<P3> out, gltf::interpolation m) {
    return cbt::message_of([&] { gltf::sampler<double, 3> s(std::move(in), std::span<const P3>(out), m); });
  };
  const auto rot = [](std::vector<double> in, std::vector<Q> out, gltf::interpolation m) {
    return cbt::message_of([&] { gltf::rotation_sampler<double> s(std::move(in), std::span<const Q>(out), m); });
  };
  const P3 o = P3::Zero();
  const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
  EXPECT_EQ(vec({}, {}, lin), "input: 0 given, at least 1 required (a sampler needs 1 key at least (glTF 2.0: n > 0))");
  EXPECT_EQ(vec({1}, {o, o, o}, cub),
            "input: 1 given, at least 2 required (a cubicspline sampler needs 2 keys at least (glTF 2.0))");
  EXPECT_EQ(vec({0, 1, nan}, {o, o, o}, lin), "input[2] = nan: must be finite");
  EXPECT_EQ(vec({-0.5, 1}, {o, o}, lin), "input[0] = -0.5: key times must be >= 0 (glTF 2.0: time[0] >= 0)");
  EXPECT_EQ(vec({0, 1, 1}, {o, o, o}, lin),
            "input[2] = 1 equals input[1]: duplicate key time, key times must be strictly increasing");
  EXPECT_EQ(vec({0, 1, 0.5}, {o, o, o}, lin),
            "input[2] = 0.5 < input[1] = 1: key times out of order, they must be strictly increasing");
  EXPECT_THAT(vec({0, 1e6, 1e6 + 1e-9}, {o, o, o}, lin), HasSubstr("input[2] - input[1] = "));
  EXPECT_THAT(vec({0, 1e6, 1e6 + 1e-9}, {o, o, o}, lin), HasSubstr("is too narrow to be resolved around 1000000"));
  EXPECT_EQ(vec({0, 1, 2}, {o, o}, lin), "output: 2 given, must match input: 3 (linear stores one value per key)");
  EXPECT_EQ(vec({0, 1}, {o}, gltf::interpolation::step),
            "output: 1 given, must match input: 2 (step stores one value per key)");
  EXPECT_EQ(vec({0, 1, 2}, {o, o, o, o, o, o, o}, cub),
            "output: 7 given, must be 3 x input = 9 (cubicspline stores an in-tangent, a value and an "
            "out-tangent per key)");
  EXPECT_EQ(vec({0, 1}, {o, P3(0, inf, 0)}, lin), "output[1] (key 1 value)[1] = inf: must be finite");
  EXPECT_EQ(vec({0, 1}, {o, o, o, o, o, P3(nan, 0, 0)}, cub), "output[5] (key 1 out-tangent)[0] = nan: must be finite");
  EXPECT_EQ(vec({0, 1}, {o, o, o, P3(0, 0, -inf), o, o}, cub),
            "output[3] (key 1 in-tangent)[2] = -inf: must be finite");
  // Rotations: the values must be unit within glTF-Validator's 0.00769; tangents need not be.
  const Q id(0, 0, 0, 1), z = Q::Zero();
  EXPECT_EQ(rot({0, 1}, {id, Q(0, 0, 0, 1.5)}, lin),
            "output[1] (key 1 value) = (0, 0, 0, 1.5) has length 1.5: rotation values must be unit quaternions, "
            "| |q| - 1 | <= 0.00769 (glTF-Validator's threshold, slightly above the error of signed 8-bit storage)");
  EXPECT_THAT(rot({0, 1}, {z, id, z, z, Q(0, 0, 0, 0.99), z}, cub),
              HasSubstr("output[4] (key 1 value) = (0, 0, 0, 0.98999999999999999) has length 0.98999999999999999"));
  EXPECT_THAT(rot({0, 1}, {id, z}, lin), HasSubstr("output[1] (key 1 value) = (0, 0, 0, 0) has length 0"));
  EXPECT_EQ(rot({0, 1}, {id, Q(0, 0, 0, 1.0075)}, lin), "(no exception)");  // inside the tolerance
  EXPECT_THAT(rot({0, 1}, {id, Q(0, 0, 0, 1.0077)}, lin), HasSubstr("output[1] (key 1 value) = (0, 0, 0, 1.00"));
  EXPECT_EQ(rot({0, 1}, {Q(5, 5, 5, 5), id, z, z, id, Q(0, 9, 0, 0)}, cub), "(no exception)");
  EXPECT_EQ(rot({0, 1}, {id, Q(0, nan, 0, 1)}, lin), "output[1] (key 1 value)[1] = nan: must be finite");
  // Evaluation.
  const std::vector<Q> qs{id, Q(0, 1, 0, 0)};
  const gltf::rotation_sampler<double> nl({0, 1}, qs, lin, gltf::rotation_blend::nlerp);
  EXPECT_EQ(cbt::message_of([&] { (void)nl.derivative(0.5, 3); }),
            "order = 3: nlerp rotations give derivatives up to order 2");
  EXPECT_EQ(cbt::message_of([&] { (void)nl.derivative(0.5, -1); }), "order = -1: derivative order must be >= 0");
  EXPECT_EQ(cbt::message_of([&] { (void)nl(nan); }), "t = nan: the sampling time must be finite");
  EXPECT_THROW((void)nl(inf), std::domain_error);
  const std::vector<Q> opposite{z, id, z, z, Q(0, 0, 0, -1), z};
  const gltf::rotation_sampler<double> cu({0, 1}, opposite, cub);
  EXPECT_EQ(cbt::message_of([&] { (void)cu(0.5); }),
            "t = 0.5: the interpolated quaternion has length 0 and cannot be normalized (keys v_{k+1} = -v_k, "
            "which glTF tells exporters to avoid)");
  EXPECT_THROW((void)cu(0.5), std::domain_error);
  EXPECT_EQ(cbt::message_of([&] { (void)cu.derivative(0.5, 3); }),
            "order = 3: cubicspline rotations give derivatives up to order 2");
  EXPECT_EQ(cbt::message_of([&] { (void)gltf::angular_distance<double>(z, id); }),
            "q = 0: the angle needs a nonzero quaternion");
  EXPECT_EQ(cbt::message_of([&] { (void)gltf::angular_distance<double>(id, Q(inf, 0, 0, 0)); }),
            "r[0] = inf: coordinates must be finite");
  EXPECT_THROW((gltf::sampler<double, 3>({0, -1}, std::vector<P3>{o, o}, lin)), cb::invalid_input);
}
