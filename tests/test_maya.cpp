// The Maya animCurve tool model (channel/maya.hpp): each tangent type's defining property, the
// non-weighted segments against the Hermite closed form in real50, weighted handles at thirds
// against the non-weighted curve, the regressive-handle correction, the infinity modes against
// their closed forms, the double model (isolate_brent) against the real50 truth (exact solver),
// float / double / real50 instantiation, and the validation messages.
#include "support/accuracy.hpp"

#include "curvebench/channel/maya.hpp"
#include "curvebench/reference/multiprecision.hpp"

#include <gmock/gmock.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace cb = curvebench;
namespace ch = curvebench::channel;
namespace cbt = curvebench::testing;
using cb::real50;
using ch::maya_infinity;
using ch::maya_tangent;
using ::testing::HasSubstr;

namespace {

// Tolerances, in eps(Real) of the scale V + S (T + H): V the largest |key value|, S the largest
// |dv/dt| at the keys (the slopes), T the largest |t| evaluated, H the longest segment.
//  - model_vs_exact: the double model against the real50 truth of the same keys. Roundings: the
//    slope of each tangent rule (a chord: two differences and a quotient, 3 eps relative of S; the
//    plateau limit and the spline's wider chord likewise), the handle m h / 3 (2 more), the
//    segment's de Casteljau in the value (3 levels, about 3 eps of V + S H), the time inversion
//    (isolate_brent to full precision, the channel's bound: a few eps of the range) and t's own
//    rounding in the wrapped / normalized time (eps T times the slope). Summed without
//    cancellation that is about 12; the bound is 16. Measured over stress_curves(): 0.41 (double),
//    0.27 (float); the test prints them. Within the wrap's rounding of a cyclic infinity's
//    period boundary, where the model jumps, the truth taken is the nearer one-sided value.
constexpr double model_vs_exact = 16;
//  - float_vs_exact: the same roundings in float, on the float keys converted exactly.
constexpr double float_vs_exact = 16;
//  - same_curve: two evaluations of the same polynomial by different exact-in-theory routes in
//    double (Bezier handles at thirds through the time solver vs the Hermite form): the solver's
//    u is exact to a few eps of the span, times the slope; 8.
constexpr double same_curve = 8;

using curve_d = ch::maya_curve<double>;

ch::maya_key<double> key(double t, double v, maya_tangent in, maya_tangent out) {
  ch::maya_key<double> k;
  k.time = t;
  k.value = v;
  k.in_type = in;
  k.out_type = out;
  return k;
}

ch::maya_key<double> key(double t, double v, maya_tangent both) { return key(t, v, both, both); }

curve_d curve_of(std::vector<ch::maya_key<double>> keys, bool weighted = false) {
  curve_d c;
  c.keys = std::move(keys);
  c.weighted = weighted;
  return c;
}

// The out slope of key i (segment i's slope at its start) and the in slope of key i (segment
// i - 1's slope at its end) from the channel keys the rules produced.
double out_slope(const std::vector<ch::key<double>>& k, std::size_t i) { return k[i].out.dv / k[i].out.dt; }
double in_slope(const std::vector<ch::key<double>>& k, std::size_t i) { return k[i].in.dv / k[i].in.dt; }

const std::vector<double> times_uneven{0, 1, 3, 3.5, 6};
const std::vector<double> values_mixed{0, 2, 1, 1, 4};

curve_d uniform_type(maya_tangent type, bool weighted = false) {
  std::vector<ch::maya_key<double>> keys;
  for (std::size_t i = 0; i < times_uneven.size(); ++i) keys.push_back(key(times_uneven[i], values_mixed[i], type));
  return curve_of(keys, weighted);
}

TEST(Maya, NamesRoundTripAndAutoIsSpelledAuto) {
  for (auto t : ch::all_maya_tangents) EXPECT_EQ(ch::from_string<maya_tangent>(ch::to_string(t)), t);
  for (auto m : ch::all_maya_infinities) EXPECT_EQ(ch::from_string<maya_infinity>(ch::to_string(m)), m);
  EXPECT_STREQ(ch::to_string(maya_tangent::auto_), "auto");
  EXPECT_STREQ(ch::to_string(maya_infinity::cycle_relative), "cycle_relative");
  EXPECT_THAT([] { (void)ch::from_string<maya_tangent>("smooth"); },
              ::testing::ThrowsMessage<cb::invalid_input>(HasSubstr("expected one of fixed, linear, flat")));
}

TEST(Maya, FlatTangentsHaveZeroSlope) {
  const auto keys = ch::maya_channel_keys(uniform_type(maya_tangent::flat));
  const auto eval = ch::maya_model(uniform_type(maya_tangent::flat));
  for (std::size_t i = 0; i + 1 < keys.size(); ++i) {
    EXPECT_EQ(out_slope(keys, i), 0.0) << i;
    EXPECT_EQ(in_slope(keys, i + 1), 0.0) << i;
    EXPECT_EQ(eval.derivative(times_uneven[i], 1), 0.0) << i;
  }
}

TEST(Maya, LinearTangentsPointAtTheNeighbourAndMakeStraightSegments) {
  const curve_d c = uniform_type(maya_tangent::linear);
  const auto keys = ch::maya_channel_keys(c);
  const auto eval = ch::maya_model(c);
  for (std::size_t i = 0; i + 1 < keys.size(); ++i) {
    const double chord = (values_mixed[i + 1] - values_mixed[i]) / (times_uneven[i + 1] - times_uneven[i]);
    EXPECT_DOUBLE_EQ(out_slope(keys, i), chord) << i;
    EXPECT_DOUBLE_EQ(in_slope(keys, i + 1), chord) << i;
    // Linear on both sides: the segment is the chord, its midpoint the mean of the values.
    const double mid = (times_uneven[i] + times_uneven[i + 1]) / 2;
    EXPECT_NEAR(eval.value(mid), (values_mixed[i] + values_mixed[i + 1]) / 2, 1e-14) << i;
  }
}

TEST(Maya, SplineSlopeIsTheChordThroughTheNeighbours) {
  const curve_d c = uniform_type(maya_tangent::spline);
  const auto keys = ch::maya_channel_keys(c);
  const std::size_t n = keys.size();
  for (std::size_t i = 1; i + 1 < n; ++i) {
    const double m = (values_mixed[i + 1] - values_mixed[i - 1]) / (times_uneven[i + 1] - times_uneven[i - 1]);
    EXPECT_DOUBLE_EQ(out_slope(keys, i), m) << i;
    EXPECT_DOUBLE_EQ(in_slope(keys, i), m) << i;  // co-linear tangents
  }
  // The ends take the chord to their only neighbour.
  EXPECT_DOUBLE_EQ(out_slope(keys, 0), (values_mixed[1] - values_mixed[0]) / (times_uneven[1] - times_uneven[0]));
  EXPECT_DOUBLE_EQ(in_slope(keys, n - 1),
                   (values_mixed[n - 1] - values_mixed[n - 2]) / (times_uneven[n - 1] - times_uneven[n - 2]));
  // On evenly spaced samples of a parabola the chord slope is the parabola's derivative at the
  // middle key, so the interior slopes are 2 t exactly.
  std::vector<ch::maya_key<double>> parabola;
  for (int i = 0; i < 5; ++i) parabola.push_back(key(i, i * i, maya_tangent::spline));
  const auto pk = ch::maya_channel_keys(curve_of(parabola));
  for (std::size_t i = 1; i < 4; ++i) EXPECT_EQ(out_slope(pk, i), 2.0 * static_cast<double>(i));
}

TEST(Maya, ClampedDoesNotOvershootBetweenEqualNeighboursAndIsSplineOtherwise) {
  const std::vector<double> t{0, 1, 2, 3, 4}, v{0, 1, 1, 0, 2};
  std::vector<ch::maya_key<double>> sk, ck;
  for (std::size_t i = 0; i < t.size(); ++i) {
    sk.push_back(key(t[i], v[i], maya_tangent::spline));
    ck.push_back(key(t[i], v[i], maya_tangent::clamped));
  }
  const auto spline = ch::maya_model(curve_of(sk));
  const auto clamped = ch::maya_model(curve_of(ck));
  // Spline overshoots the equal keys 1 and 2; clamped stays on them.
  double spline_max = 0, clamped_max = -1;
  for (int j = 0; j <= 100; ++j) {
    const double tt = 1 + j / 100.0;
    spline_max = std::max(spline_max, spline.value(tt));
    clamped_max = std::max(clamped_max, clamped.value(tt));
  }
  EXPECT_GT(spline_max, 1.05);
  EXPECT_EQ(clamped_max, 1.0);
  // Where the neighbours differ, clamped is spline: key 3's in and out, key 1's in.
  const auto s = ch::maya_channel_keys(curve_of(sk));
  const auto c = ch::maya_channel_keys(curve_of(ck));
  EXPECT_EQ(in_slope(c, 1), in_slope(s, 1));
  EXPECT_EQ(in_slope(c, 3), in_slope(s, 3));
  EXPECT_EQ(out_slope(c, 3), out_slope(s, 3));
  EXPECT_EQ(out_slope(c, 1), 0.0);
  EXPECT_EQ(in_slope(c, 2), 0.0);
  // A tolerance makes close values count as equal: the linear slope toward the neighbour.
  curve_d close = curve_of(ck);
  close.keys[2].value = 1.001;
  close.clamp_tolerance = 0.01;
  const auto cc = ch::maya_channel_keys(close);
  EXPECT_EQ(out_slope(cc, 1), 1.001 - 1.0);  // the chord over a duration of 1
  EXPECT_EQ(in_slope(cc, 2), 1.001 - 1.0);
}

TEST(Maya, PlateauAndAutoAreFlatAtExtremaAndNeverOvershoot) {
  for (maya_tangent type : {maya_tangent::plateau, maya_tangent::auto_}) {
    // Steep and shallow chords side by side, extrema, a plateau of equal values.
    const std::vector<double> t{0, 0.5, 1, 4, 4.2, 7, 8, 9}, v{0, 5, 5.2, 6, 2, 2, 3, 10};
    std::vector<ch::maya_key<double>> keys;
    for (std::size_t i = 0; i < t.size(); ++i) keys.push_back(key(t[i], v[i], type));
    const auto k = ch::maya_channel_keys(curve_of(keys));
    const auto eval = ch::maya_model(curve_of(keys));
    EXPECT_EQ(out_slope(k, 0), 0.0);
    EXPECT_EQ(in_slope(k, t.size() - 1), 0.0);
    EXPECT_EQ(out_slope(k, 3), 0.0);  // local maximum
    EXPECT_EQ(in_slope(k, 3), 0.0);
    EXPECT_EQ(out_slope(k, 4), 0.0);  // equal to a neighbour: an extremum by the rule
    EXPECT_GT(out_slope(k, 1), 0.0);  // a transitional key keeps a slope
    for (std::size_t i = 0; i + 1 < t.size(); ++i) {
      const double lo = std::min(v[i], v[i + 1]), hi = std::max(v[i], v[i + 1]);
      for (int j = 0; j <= 200; ++j) {
        const double tt = t[i] + (t[i + 1] - t[i]) * j / 200.0;
        const double value = eval.value(tt);
        EXPECT_GE(value, lo - 1e-14 * (1 + hi)) << ch::to_string(type) << " segment " << i << " t " << tt;
        EXPECT_LE(value, hi + 1e-14 * (1 + hi)) << ch::to_string(type) << " segment " << i << " t " << tt;
      }
    }
  }
  // Spline on the same keys does overshoot (so the test above can fail).
  const std::vector<double> t{0, 0.5, 1, 4}, v{0, 5, 5.2, 6};
  std::vector<ch::maya_key<double>> keys;
  for (std::size_t i = 0; i < t.size(); ++i) keys.push_back(key(t[i], v[i], maya_tangent::spline));
  EXPECT_GT(ch::maya_model(curve_of(keys)).value(0.75), 5.2);
}

TEST(Maya, StepHoldsTheKeyAndStepNextTheNextKey) {
  std::vector<ch::maya_key<double>> keys{key(0, 1, maya_tangent::spline, maya_tangent::step),
                                         key(2, 3, maya_tangent::spline, maya_tangent::step_next),
                                         key(4, -1, maya_tangent::spline)};
  const auto eval = ch::maya_model(curve_of(keys));
  EXPECT_EQ(eval.value(0), 1.0);
  EXPECT_EQ(eval.value(1.999), 1.0);
  EXPECT_EQ(eval.value(2), 3.0);
  EXPECT_EQ(eval.value(2.001), -1.0);
  EXPECT_EQ(eval.value(4), -1.0);
  EXPECT_EQ(eval.derivative(1, 1), 0.0);
}

// Hermite in real50: h00 v0 + h10 h m0 + h01 v1 + h11 h m1 with s = (t - t0) / h.
real50 hermite(real50 t0, real50 t1, real50 v0, real50 v1, real50 m0, real50 m1, real50 t) {
  const real50 h = t1 - t0, s = (t - t0) / h;
  const real50 s2 = s * s, s3 = s2 * s;
  return (2 * s3 - 3 * s2 + 1) * v0 + (s3 - 2 * s2 + s) * h * m0 + (-2 * s3 + 3 * s2) * v1 + (s3 - s2) * h * m1;
}

TEST(Maya, NonWeightedSegmentsAreCubicHermite) {
  // Fixed tangents with long and short vectors: only the direction counts.
  std::vector<ch::maya_key<double>> keys{key(0, 1, maya_tangent::fixed), key(2, 3, maya_tangent::fixed),
                                         key(5, -1, maya_tangent::fixed)};
  keys[0].out_x = 10, keys[0].out_y = 5;    // slope 0.5
  keys[1].in_x = 0.1, keys[1].in_y = -0.2;  // slope -2
  keys[1].out_x = 3, keys[1].out_y = 3;     // slope 1
  keys[2].in_x = 1, keys[2].in_y = 4;       // slope 4
  const auto eval = ch::maya_exact<real50>(curve_of(keys));
  const auto model = ch::maya_model(curve_of(keys));
  for (int j = 0; j <= 50; ++j) {
    const real50 t = real50(5) * j / 50;
    const real50 ref = t <= 2 ? hermite(0, 2, 1, 3, real50(0.5), -2, t) : hermite(2, 5, 3, -1, 1, 4, t);
    EXPECT_LT(abs(eval.value(t) - ref), real50(1e-45)) << j;
    EXPECT_TRUE(cbt::within_scaled_ulps(model.value(static_cast<double>(t)), ref, real50(20), 8)) << j;
  }
}

// The auto tangent as Autodesk AnimX (Apache-2.0), src/animx.cpp, computes it (plateau uses the
// same rule in this model), against hand-derived slopes: the spline slope (v_n - v_p) / (t_n - t_p)
// unless the chords differ in sign (then 0) or it exceeds 3 x the smaller chord (then that bound).
// Tolerance: the slope is one chord and at most one product, 2 roundings: 2 eps of its magnitude.
constexpr double auto_slope_ulps = 2;

TEST(Maya, AutoSlopeClosedFormsAtAndBesideAnExtremum) {
  for (maya_tangent type : {maya_tangent::auto_, maya_tangent::plateau}) {
    const auto slopes = [&](const std::vector<double>& t, const std::vector<double>& v, bool weighted = false) {
      std::vector<ch::maya_key<double>> keys;
      for (std::size_t i = 0; i < t.size(); ++i) keys.push_back(key(t[i], v[i], type));
      return ch::maya_channel_keys(curve_of(keys, weighted));
    };
    // Rising, the spline slope inside the bound: (0,0), (1,1), (3,4): chords 1 and 3/2, spline 4/3.
    const auto rising = slopes({0, 1, 3}, {0, 1, 4});
    EXPECT_TRUE(cbt::within_scaled_ulps(out_slope(rising, 1), real50(4) / 3, real50(4) / 3, auto_slope_ulps));
    EXPECT_EQ(in_slope(rising, 1), out_slope(rising, 1));  // one slope on both sides
    EXPECT_EQ(out_slope(rising, 0), 0.0);                  // flat at the ends
    EXPECT_EQ(in_slope(rising, 2), 0.0);
    // Beside a maximum: (0,0), (1,3), (1.5,3.1), (2.5,0). Key 2 is the maximum: 0. Key 1: chords 3
    // and 0.2, spline 3.1 / 1.5 ~ 2.07 > 3 x 0.2, so the bound 3 (3.1 - 3) / 0.5 (3.1 as a double).
    const auto beside = slopes({0, 1, 1.5, 2.5}, {0, 3, 3.1, 0});
    const real50 bound = 3 * (real50(3.1) - 3) / real50(0.5);
    EXPECT_TRUE(cbt::within_scaled_ulps(out_slope(beside, 1), bound, bound, auto_slope_ulps)) << ch::to_string(type);
    EXPECT_EQ(out_slope(beside, 2), 0.0);
    EXPECT_EQ(in_slope(beside, 2), 0.0);
    // Mirrored in value: falling, the bound with its sign.
    const auto falling = slopes({0, 1, 1.5, 2.5}, {0, -3, -3.1, 0});
    EXPECT_TRUE(cbt::within_scaled_ulps(out_slope(falling, 1), -bound, bound, auto_slope_ulps));
    // An equal neighbour counts as an extremum: (0,0), (1,1), (2,1): key 1 is flat.
    const auto equal = slopes({0, 1, 2}, {0, 1, 1});
    EXPECT_EQ(out_slope(equal, 1), 0.0);
    EXPECT_EQ(in_slope(equal, 1), 0.0);
    // Weighted: the handle at a third of the adjacent segment (AnimX's tangent x is its duration).
    const auto w = slopes({0, 1, 3}, {0, 1, 4}, true);
    EXPECT_EQ(w[1].in.dt, -1.0 / 3);
    EXPECT_EQ(w[1].out.dt, 2.0 / 3);
  }
}

TEST(Maya, ClampedThreeKeysClosedForm) {
  // (0,0), (1,2), (3,2), clamped: key 0's only chord, 2; key 1's in side the spline slope
  // (2 - 0) / (3 - 0) = 2/3 (its previous neighbour differs), its out side the chord to the equal
  // neighbour, 0; key 2's in side 0. The first segment is then the Hermite with slopes 2 and 2/3.
  std::vector<ch::maya_key<double>> keys{key(0, 0, maya_tangent::clamped), key(1, 2, maya_tangent::clamped),
                                         key(3, 2, maya_tangent::clamped)};
  const auto k = ch::maya_channel_keys(curve_of(keys));
  EXPECT_EQ(out_slope(k, 0), 2.0);
  EXPECT_TRUE(cbt::within_scaled_ulps(in_slope(k, 1), real50(2) / 3, real50(2) / 3, auto_slope_ulps));
  EXPECT_EQ(out_slope(k, 1), 0.0);
  EXPECT_EQ(in_slope(k, 2), 0.0);
  // Values against the real50 Hermite: the segment's de Casteljau in double, a few eps of
  // V + S H = 2 + 2: 8 (as same_curve).
  const auto model = ch::maya_model(curve_of(keys));
  const auto exact = ch::maya_exact<real50>(curve_of(keys));
  for (int j = 0; j <= 30; ++j) {
    const real50 t = real50(3) * j / 30;
    const real50 ref = t <= 1 ? hermite(0, 1, 0, 2, 2, real50(2) / 3, t) : hermite(1, 3, 2, 2, 0, 0, t);
    EXPECT_LT(abs(exact.value(t) - ref), real50(1e-45)) << j;
    EXPECT_TRUE(cbt::within_scaled_ulps(model.value(static_cast<double>(t)), ref, real50(4), same_curve)) << j;
  }
}

TEST(Maya, WeightedHandlesAtThirdsEqualTheNonWeightedCurve) {
  const std::vector<double> t{0, 1.5, 2, 5}, v{0, 2, -1, 3}, m{1, -2, 0.5, 3};
  std::vector<ch::maya_key<double>> keys;
  for (std::size_t i = 0; i < t.size(); ++i) {
    auto k = key(t[i], v[i], maya_tangent::fixed);
    const double h_in = i > 0 ? t[i] - t[i - 1] : 1, h_out = i + 1 < t.size() ? t[i + 1] - t[i] : 1;
    k.in_x = h_in, k.in_y = m[i] * h_in;
    k.out_x = h_out, k.out_y = m[i] * h_out;
    keys.push_back(k);
  }
  const auto weighted = ch::maya_model(curve_of(keys, true));
  const auto plain = ch::maya_model(curve_of(keys, false));
  EXPECT_EQ(weighted.underlying().keys()[0].interp, ch::interpolation::bezier);
  EXPECT_EQ(plain.underlying().keys()[0].interp, ch::interpolation::hermite);
  for (int j = 0; j <= 100; ++j) {
    const double tt = 5.0 * j / 100;
    EXPECT_TRUE(cbt::within_scaled_ulps(weighted.value(tt), real50(plain.value(tt)), real50(3 + 3 * 5), same_curve))
        << tt;
  }
  // Computed tangent types on a weighted curve put their handles at thirds too.
  const auto w2 = ch::maya_model(uniform_type(maya_tangent::spline, true));
  const auto p2 = ch::maya_model(uniform_type(maya_tangent::spline, false));
  for (int j = 0; j <= 60; ++j) {
    const double tt = 6.0 * j / 60;
    EXPECT_TRUE(cbt::within_scaled_ulps(w2.value(tt), real50(p2.value(tt)), real50(4 + 2 * 6), same_curve)) << tt;
  }
}

TEST(Maya, WeightedFixedTangentsAreBezierHandlesAtAThirdOfTheVector) {
  // Handles (0.4, 1.2) and (-0.9, 0.3) on [0, 2]: the vectors are three times the handles.
  std::vector<ch::maya_key<double>> keys{key(0, 1, maya_tangent::fixed), key(2, 0, maya_tangent::fixed)};
  keys[0].out_x = 1.2, keys[0].out_y = 3.6;
  keys[1].in_x = 2.7, keys[1].in_y = -0.9;
  const auto exact = ch::maya_exact<real50>(curve_of(keys, true));
  // The Bezier at u = 1/2: time (t0 + 3 t1 + 3 t2 + t3) / 8, value (v0 + 3 v1 + 3 v2 + v3) / 8.
  // (The keys are the doubles nearest 1.2, 3.6, 2.7, 0.9, converted exactly.)
  const real50 t1 = real50(1.2) / 3, t2 = 2 - real50(2.7) / 3, v1 = 1 + real50(3.6) / 3, v2 = real50(0.9) / 3;
  const real50 t_mid = (0 + 3 * t1 + 3 * t2 + 2) / 8, v_mid = (1 + 3 * v1 + 3 * v2 + 0) / 8;
  EXPECT_LT(abs(exact.value(t_mid) - v_mid), real50(1e-45));
  // The non-weighted curve with the same slopes is a different curve (the weight matters).
  const auto plain = ch::maya_exact<real50>(curve_of(keys, false));
  EXPECT_GT(abs(plain.value(t_mid) - v_mid), real50(1e-3));
  // Maya's (angle, weight) gives the same vector.
  const auto [x, y] = ch::tangent_from_angle(std::atan2(1.2, 0.4), std::hypot(0.4, 1.2));
  EXPECT_NEAR(x, 1.2, 1e-15);
  EXPECT_NEAR(y, 3.6, 1e-15);
}

// The regression correction (maya.hpp, from Autodesk AnimX (Apache-2.0), src/animx.cpp), checked
// against hand-derived closed forms. With a = out handle time / h, c = in handle time / h, time is
// monotone iff a + c <= 1 or E(a, c) = a^2 + a c + c^2 - 2a - 2c + 1 <= 0. Solving E = 0 for c at a
// given a: c = (2 - a +- sqrt(a (4 - 3 a))) / 2. m = AnimX's margin, 1e-10 as a double.
const real50 animx_margin = real50(1e-10);

real50 ellipse(const real50& a, const real50& c) { return a * a + a * c + c * c - 2 * a - 2 * c + 1; }

// A two-key weighted segment [0, h] with fixed handles given as (dt, dv) (vectors 3 x the handle).
curve_d weighted_segment(double h, double out_dt, double out_dv, double in_dt, double in_dv) {
  std::vector<ch::maya_key<double>> keys{key(0, 0, maya_tangent::fixed), key(h, 1, maya_tangent::fixed)};
  keys[0].out_x = 3 * out_dt, keys[0].out_y = 3 * out_dv;
  keys[1].in_x = -3 * in_dt, keys[1].in_y = -3 * in_dv;  // in_dt < 0: the vector points forwards
  return curve_of(keys, true);
}

// Time along the double model's corrected segment never runs backwards.
void expect_time_monotone(const curve_d& c) {
  const auto eval = ch::maya_model(c);  // the channel itself refuses regressive handles
  const auto curve = eval.underlying().curve();
  double previous = -1;
  for (int j = 0; j <= 1000; ++j) {
    const double time = curve(j / 1000.0)[0];
    EXPECT_GE(time, previous) << j;
    previous = time;
  }
}

// Tolerances for the corrected handles of the double model against the closed forms, in eps of
// the reference's magnitude: the corrected reach takes a square root, a sum, a halving and the
// margin (about 2 eps), times h (exact here: h a power of 2 or 3 with exact reaches), and the value
// offset its ratio new / old (2 more): 4. Where the lower edge is taken, 2 - a - sqrt(.) cancels
// (0.75 - 0.56 here, a factor 4 on the sum's roundings): 8.
constexpr double handle_ulps = 4;
constexpr double handle_ulps_cancelling = 8;

TEST(Maya, RegressionPastTheEllipseTipMovesBothHandlesToTheTip) {
  // a = c = 1.5 on [0, 2]: E = 1.75 > 0 and a >= 4/3, so a -> 4/3 - m, c -> 1/3 - m, directions kept.
  const curve_d c = weighted_segment(2, 3, 1, -3, 2);
  std::vector<ch::key<double>> raw(2);  // as they are, the channel refuses them
  raw[0] = {0, 0, {}, {3, 1}, ch::interpolation::bezier};
  raw[1] = {2, 1, {-3, 2}, {}, ch::interpolation::bezier};
  EXPECT_THROW((void)ch::channel<double>(raw), cb::invalid_input);
  const real50 a = real50(4) / 3 - animx_margin, cc = real50(1) / 3 - animx_margin;
  const real50 out_dt = 2 * a, out_dv = a / real50(1.5), in_dt = -2 * cc, in_dv = 2 * cc / real50(1.5);
  const auto k = ch::maya_channel_keys(c);
  EXPECT_TRUE(cbt::within_scaled_ulps(k[0].out.dt, out_dt, abs(out_dt), handle_ulps));
  EXPECT_TRUE(cbt::within_scaled_ulps(k[0].out.dv, out_dv, abs(out_dv), handle_ulps));
  EXPECT_TRUE(cbt::within_scaled_ulps(k[1].in.dt, in_dt, abs(in_dt), handle_ulps));
  EXPECT_TRUE(cbt::within_scaled_ulps(k[1].in.dv, in_dv, abs(in_dv), handle_ulps));
  // The rule in real50 lands on the same closed form (the same arithmetic, 50 digits).
  const auto k50 = ch::maya_channel_keys(ch::convert<real50>(c));
  EXPECT_LT(abs(k50[0].out.dv - out_dv) + abs(k50[1].in.dt - in_dt), real50(1e-45));
  // Just inside the monotone region: E(a, c) < 0 by about the margin.
  EXPECT_LT(ellipse(a, cc), 0);
  EXPECT_GT(ellipse(a, cc), -10 * animx_margin);
  expect_time_monotone(c);
}

TEST(Maya, RegressionKeepsTheOutHandleAndPullsTheInHandleToTheEllipse) {
  // h = 3, out handle (1.5, 0.5): a = 1/2; in handle (-4.5, 3): c = 3/2 > 1. E = 1/4 > 0. At a = 1/2
  // the upper edge is c = (3/2 + sqrt(5/4)) / 2 = (3 + sqrt 5) / 4 ~ 1.309 < c: c -> that - m.
  const curve_d c = weighted_segment(3, 1.5, 0.5, -4.5, 3);
  const real50 cc = (3 + sqrt(real50(5))) / 4 - animx_margin;
  const real50 in_dt = -3 * cc, in_dv = 3 * cc / real50(1.5);
  const auto k = ch::maya_channel_keys(c);
  EXPECT_EQ(k[0].out.dt, 1.5);  // the out handle is kept as it is
  EXPECT_EQ(k[0].out.dv, 0.5);
  EXPECT_TRUE(cbt::within_scaled_ulps(k[1].in.dt, in_dt, abs(in_dt), handle_ulps));
  EXPECT_TRUE(cbt::within_scaled_ulps(k[1].in.dv, in_dv, abs(in_dv), handle_ulps));
  EXPECT_LT(ellipse(real50(0.5), cc), 0);
  EXPECT_GT(ellipse(real50(0.5), cc), -10 * animx_margin);
  // The evaluated curve is the Bezier of the corrected handles: at u = 1/2, time
  // (t0 + 3 t1 + 3 t2 + t3) / 8 and value (v0 + 3 v1 + 3 v2 + v3) / 8. real50 within 1e-40 (the
  // exact solver); the double model within the channel's bound, 16 eps of V + S (T + H) (slope S
  // <= 2 here, V = 1, T = H = 3: 16 eps x 13).
  const real50 t_mid = (0 + 3 * real50(1.5) + 3 * (3 + in_dt) + 3) / 8;
  const real50 v_mid = (0 + 3 * real50(0.5) + 3 * (1 + in_dv) + 1) / 8;
  EXPECT_LT(abs(ch::maya_exact<real50>(c).value(t_mid) - v_mid), real50(1e-40));
  EXPECT_TRUE(
      cbt::within_scaled_ulps(ch::maya_model(c).value(static_cast<double>(t_mid)), v_mid, real50(13), model_vs_exact));
  expect_time_monotone(c);
}

TEST(Maya, RegressionBelowTheEllipseLengthensTheInHandle) {
  // h = 4, out handle (5, 1): a = 5/4 > 1; in handle (-0.25, 0.5): c = 1/16. E = 0.01953125 > 0. At
  // a = 5/4 the lower edge is c = (3/4 - sqrt(5/16)) / 2 = (3 - sqrt 5) / 8 ~ 0.0955 > c: c -> that + m.
  const curve_d c = weighted_segment(4, 5, 1, -0.25, 0.5);
  const real50 cc = (3 - sqrt(real50(5))) / 8 + animx_margin;
  const real50 in_dt = -4 * cc, in_dv = real50(0.5) * cc * 16;
  const auto k = ch::maya_channel_keys(c);
  EXPECT_EQ(k[0].out.dt, 5.0);
  EXPECT_EQ(k[0].out.dv, 1.0);
  EXPECT_TRUE(cbt::within_scaled_ulps(k[1].in.dt, in_dt, abs(in_dt), handle_ulps_cancelling));
  EXPECT_TRUE(cbt::within_scaled_ulps(k[1].in.dv, in_dv, abs(in_dv), handle_ulps_cancelling));
  EXPECT_LT(ellipse(real50(1.25), cc), 0);
  EXPECT_GT(ellipse(real50(1.25), cc), -10 * animx_margin);
  expect_time_monotone(c);
}

TEST(Maya, OverlappingButMonotoneHandlesAreLeftAlone) {
  // a = 1.1, c = 0.3 (h = 2): a + c > 1 but E = -0.17 < 0, time is monotone; a = c = 0.9: neither
  // handle passes the other key. (A rule scaling by 1 / (a + c) would shorten both.)
  for (const auto& [a, cc] : {std::pair{1.1, 0.3}, std::pair{0.9, 0.9}, std::pair{0.75, 0.25}}) {
    const curve_d c = weighted_segment(2, 2 * a, 0.5, -2 * cc, -0.25);
    const auto k = ch::maya_channel_keys(c);
    EXPECT_EQ(k[0].out.dt, c.keys[0].out_x / 3) << a;
    EXPECT_EQ(k[0].out.dv, c.keys[0].out_y / 3) << a;
    EXPECT_EQ(k[1].in.dt, -c.keys[1].in_x / 3) << a;
    EXPECT_EQ(k[1].in.dv, -c.keys[1].in_y / 3) << a;
    expect_time_monotone(c);
  }
}

TEST(Maya, InfinityModesMatchTheirClosedForms) {
  std::vector<ch::maya_key<double>> keys{key(1, 2, maya_tangent::fixed), key(2, 5, maya_tangent::spline),
                                         key(4, 3, maya_tangent::fixed)};
  keys[0].in_x = 1, keys[0].in_y = -3;  // broken tangents: in slope -3, out slope 2
  keys[0].out_x = 1, keys[0].out_y = 2;
  keys[2].in_x = 1, keys[2].in_y = 0.5;
  keys[2].out_x = 2, keys[2].out_y = 1;  // out slope 0.5... distinct from in below
  keys[2].out_y = -1;                    // out slope -0.5
  curve_d c = curve_of(keys);
  const double period = 3;
  for (maya_infinity mode : ch::all_maya_infinities) {
    c.pre = c.post = mode;
    const auto e = ch::maya_model(c);
    for (double r : {0.25, 1.0, 2.5}) {
      const double before = 1 - r, after = 4 + r;
      switch (mode) {
        case maya_infinity::constant:
          EXPECT_EQ(e.value(before), 2.0);
          EXPECT_EQ(e.value(after), 3.0);
          break;
        case maya_infinity::linear:  // the end key's own outward tangent, not the segment's
          EXPECT_DOUBLE_EQ(e.value(before), 2 + 3 * r);
          EXPECT_DOUBLE_EQ(e.value(after), 3 - 0.5 * r);
          EXPECT_EQ(e.derivative(before, 1), -3.0);
          break;
        case maya_infinity::cycle:
          EXPECT_NEAR(e.value(after), e.value(1 + r), 1e-14);
          EXPECT_NEAR(e.value(before), e.value(before + period), 1e-14);
          break;
        case maya_infinity::cycle_relative:  // each repeat offset by v_last - v_first = 1
          EXPECT_NEAR(e.value(after), e.value(1 + r) + 1, 1e-14);
          EXPECT_NEAR(e.value(before), e.value(before + period) - 1, 1e-14);
          break;
        case maya_infinity::oscillate:  // mirrored in time about each end
          EXPECT_NEAR(e.value(after), e.value(4 - r), 1e-14);
          EXPECT_NEAR(e.value(before), e.value(1 + r), 1e-14);
          break;
      }
    }
  }
}

// Mixed curves for the model against the truth: every tangent type, weighted and not, regressive
// handles, all infinity modes.
std::vector<curve_d> stress_curves() {
  std::vector<curve_d> out;
  const std::vector<maya_tangent> types{maya_tangent::spline, maya_tangent::clamped, maya_tangent::plateau,
                                        maya_tangent::auto_,  maya_tangent::linear,  maya_tangent::flat,
                                        maya_tangent::fixed};
  const std::vector<double> t{-3.7, -1.1, 0.3, 2.9, 3.05, 7.5, 11}, v{0.5, 4.25, -2, -1.9, 6, 6, -3.3};
  for (bool weighted : {false, true})
    for (std::size_t shift = 0; shift < types.size(); ++shift) {
      curve_d c;
      c.weighted = weighted;
      for (std::size_t i = 0; i < t.size(); ++i) {
        auto k = key(t[i], v[i], types[(i + shift) % types.size()], types[(i + 2 * shift + 1) % types.size()]);
        k.in_x = 0.7 + 0.9 * static_cast<double>(i % 3), k.in_y = 1.3 - 0.6 * static_cast<double>(i);
        k.out_x = 2.6 - 0.4 * static_cast<double>(i % 4), k.out_y = -0.8 + 0.5 * static_cast<double>(i);
        c.keys.push_back(k);
      }
      c.pre = ch::all_maya_infinities[shift % 5];
      c.post = ch::all_maya_infinities[(shift + 2) % 5];
      out.push_back(c);
    }
  // The three branches of the regression correction (the closed-form tests above), with every
  // infinity mode, so that the model and the truth apply it alike.
  const std::vector<curve_d> corrected{weighted_segment(2, 3, 1, -3, 2), weighted_segment(3, 1.5, 0.5, -4.5, 3),
                                       weighted_segment(4, 5, 1, -0.25, 0.5)};
  for (std::size_t i = 0; i < corrected.size(); ++i) {
    curve_d c = corrected[i];
    c.pre = ch::all_maya_infinities[(i + 2) % 5];
    c.post = ch::all_maya_infinities[(i + 4) % 5];
    out.push_back(c);
  }
  return out;
}

// The whole-period boundary t_end + k T (k != 0) of a cyclic infinity (cycle, cycle_relative,
// oscillate) that t lies within the wrap's rounding of (16 eps(Real) of |t| + |t_end| + T, the
// error of Real's ratio (t - t_end) / T times T), or none.
template <class Real>
std::optional<real50> wrap_boundary(const ch::maya_curve<Real>& c, const real50& t, double eps) {
  const real50 t_first(c.keys.front().time), t_last(c.keys.back().time), period = t_last - t_first;
  const bool before = t < t_first;
  if (!before && !(t > t_last)) return std::nullopt;
  const maya_infinity mode = before ? c.pre : c.post;
  if (mode == maya_infinity::constant || mode == maya_infinity::linear || c.keys.size() < 2) return std::nullopt;
  const real50 end = before ? t_first : t_last;
  const real50 k = round((t - end) / period);
  if (k == 0) return std::nullopt;
  const real50 b = end + k * period;
  if (abs(t - b) > real50(16 * eps) * (abs(t) + abs(end) + period)) return std::nullopt;
  return b;
}

// The largest error of the model (Real, the given solver) against the truth over stress_curves(),
// in eps(Real) of V + S (|t| + H); each sample asserted within `bound` when `check`.
template <class Real>
double worst_against_truth(ch::time_solver solver, double bound, bool check, const char* label) {
  double worst = 0;
  std::size_t boundary_samples = 0;
  for (const curve_d& cd : stress_curves()) {
    const ch::maya_curve<Real> c = ch::convert<Real>(cd);
    const ch::maya_evaluator<Real> model(c, solver);
    // The truth of the keys the model saw (exact conversion of the Real keys).
    const ch::maya_evaluator<real50> truth(ch::convert<real50>(c), ch::time_solver::exact);
    real50 v_max = 0, s_max = 0, h_max = 0;
    for (std::size_t i = 0; i < c.keys.size(); ++i) {
      v_max = std::max(v_max, real50(abs(real50(c.keys[i].value))));
      s_max = std::max(s_max, real50(abs(truth.derivative(real50(c.keys[i].time), 1))));
      if (i > 0) h_max = std::max(h_max, real50(c.keys[i].time) - real50(c.keys[i - 1].time));
    }
    for (const auto& k : truth.underlying().keys()) {  // the handle slopes too
      if (k.out.dt > 0) s_max = std::max(s_max, real50(abs(k.out.dv / k.out.dt)));
      if (k.in.dt < 0) s_max = std::max(s_max, real50(abs(k.in.dv / k.in.dt)));
    }
    for (int j = 0; j <= 600; ++j) {
      const Real tt = Real(-40 + 80 * static_cast<double>(j) / 600);
      const real50 t50(tt);
      // Sample the curve densely too for the largest slope between keys.
      s_max = std::max(s_max, real50(abs(truth.derivative(t50, 1))));
    }
    for (int j = 0; j <= 600; ++j) {
      const Real tt = Real(-40 + 80 * static_cast<double>(j) / 600);
      const real50 t50(tt);
      const real50 scale = v_max + s_max * (abs(t50) + h_max);
      real50 ref = truth.value(t50);
      const Real got = model.value(tt);
      // Within the wrap's rounding of a whole period outside the keys, a cyclic infinity's jump
      // (last key to first) falls on the side Real's own arithmetic gives, as in AnimX: the model
      // then matches the truth at the exact boundary or just past it, whichever is nearer.
      if (const auto b = wrap_boundary(c, t50, static_cast<double>(cb::epsilon<Real>()))) {
        const real50 nudge = real50(1e-30) * (real50(c.keys.back().time) - real50(c.keys.front().time));
        for (const real50& alt : {truth.value(*b), truth.value(*b + nudge), truth.value(*b - nudge)})
          if (cbt::scaled_ulps(got, alt, scale) < cbt::scaled_ulps(got, ref, scale)) ref = alt;
        ++boundary_samples;
      }
      worst = std::max(worst, static_cast<double>(cbt::scaled_ulps(got, ref, scale)));
      if (check) {
        EXPECT_TRUE(cbt::within_scaled_ulps(got, ref, scale, bound)) << label << " t = " << static_cast<double>(tt);
      }
    }
  }
  std::cout << "[maya] " << label << " model (" << ch::to_string(solver) << ") vs real50 exact: max " << worst
            << " eps * (V + S (|t| + H)), bound " << bound << " (" << boundary_samples
            << " samples within rounding of a cyclic infinity's period boundary)\n";
  return worst;
}

// Cycle pre-infinity at whole periods before the first key (measured with Autodesk
// AnimX built with 64-bit time on curves keyed on whole frames): Maya takes the last key's value
// there, the end of the previous repeat; just after that time the repeat's start, the first
// key's. Post-infinity and cycle_relative (continuous there) agree with the channel's rule. The
// boundary is decided in double as AnimX decides it: (t - t_first) / T rounding to a whole number
// is the boundary (the next double after -2 here: -2 - 1 rounds to -3), and a wrapped time within
// rounding of a key is that key (tests/test_maya_animx.cpp checks it on AnimX's values).
TEST(Maya, CyclePreInfinityAtWholePeriodsTakesTheLastKey) {
  curve_d c =
      curve_of({key(1, 2, maya_tangent::linear), key(2, 5, maya_tangent::linear), key(4, 3, maya_tangent::linear)});
  c.pre = c.post = maya_infinity::cycle;
  const auto e = ch::maya_model(c);
  const double period = 3;
  for (int k = 1; k <= 4; ++k) {
    const double t = 1 - k * period;
    EXPECT_EQ(e.value(t), 3.0) << "k = " << k;                         // the last key
    EXPECT_DOUBLE_EQ(e.derivative(t, 1), -1.0) << "k = " << k;         // the last segment's slope
    EXPECT_NEAR(e.value(t + 1e-9), 2.0 + 3e-9, 1e-12) << "k = " << k;  // the next repeat starts
    EXPECT_EQ(e.value(4 + k * period), 2.0) << "k = " << k;            // post: the first key
  }
  EXPECT_EQ(e.value(std::nextafter(-2.0, 0.0)), 3.0);  // (t - 1) / 3 rounds to -1: the boundary
  EXPECT_EQ(e.value(std::nextafter(-5.0, 0.0)), 2.0);  // (t - 1) / 3 just above -2: past it, snapped to the first key
  c.pre = maya_infinity::cycle_relative;               // each repeat offset by v_last - v_first = 1: continuous
  EXPECT_DOUBLE_EQ(ch::maya_model(c).value(1 - 2 * period), 2.0 - 2.0);
}

TEST(Maya, DoubleModelAgainstTheExactTruth) {
  (void)worst_against_truth<double>(ch::time_solver::isolate_brent, model_vs_exact, true, "double");
}
TEST(Maya, FloatModelAgainstTheExactTruth) {
  (void)worst_against_truth<float>(ch::time_solver::isolate_brent, float_vs_exact, true, "float");
}
// The measurement can tell solvers apart: 12 halvings leave u within 2^-13, far above the bound
// on the weighted stress curves, so the comparison above would catch a coarse solver.
TEST(Maya, TheTruthComparisonCatchesACoarseSolver) {
  EXPECT_GT(worst_against_truth<double>(ch::time_solver::bisection12, model_vs_exact, false, "double"),
            100 * model_vs_exact);
}

TEST(Maya, NonFiniteTimesAreDomainErrorsUnderLinearInfinity) {
  curve_d c = uniform_type(maya_tangent::spline);
  c.pre = c.post = maya_infinity::linear;
  const auto e = ch::maya_model(c);
  EXPECT_THROW((void)e.value(-std::numeric_limits<double>::infinity()), std::domain_error);
  EXPECT_THROW((void)e.value(std::numeric_limits<double>::infinity()), std::domain_error);
  EXPECT_THROW((void)e.value(std::nan("")), std::domain_error);
}

TEST(Maya, InstantiatesOnFloatDoubleAndReal50) {
  const curve_d c = uniform_type(maya_tangent::spline, true);
  const auto f = ch::maya_evaluator<float>(ch::convert<float>(c), ch::time_solver::isolate_brent);
  const auto d = ch::maya_model(c);
  const auto r = ch::maya_exact<real50>(c);
  EXPECT_EQ(f.value(3.0f), 1.0f);
  EXPECT_EQ(d.value(3.0), 1.0);
  EXPECT_EQ(r.value(real50(3)), real50(1));
  EXPECT_NEAR(static_cast<double>(r.value(real50(2))), d.value(2.0), 1e-14);
}

TEST(Maya, TangentFromAngleAndWeight) {
  const auto [x, y] = ch::tangent_from_angle(std::atan(0.5), std::sqrt(1.25));
  EXPECT_NEAR(x, 3.0, 1e-15);
  EXPECT_NEAR(y, 1.5, 1e-15);
  EXPECT_THAT([] { (void)ch::tangent_from_angle(0.1, 0.0); },
              ::testing::ThrowsMessage<cb::invalid_input>(HasSubstr("weight = 0")));
}

TEST(Maya, ValidationNamesTheKeyAndField) {
  const auto message = [](curve_d c) {
    try {
      (void)ch::maya_model(c);
    } catch (const cb::invalid_input& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_THAT(message(curve_d{}), HasSubstr("keys"));
  curve_d c = uniform_type(maya_tangent::spline);
  c.keys[2].value = std::nan("");
  EXPECT_THAT(message(c), HasSubstr("keys[2].value"));
  c = uniform_type(maya_tangent::fixed);
  c.keys[3].out_x = -1;
  EXPECT_THAT(message(c), HasSubstr("keys[3].out_x = -1: a fixed tangent's x must be > 0"));
  c = uniform_type(maya_tangent::fixed);
  c.keys[1].in_x = 0;
  EXPECT_THAT(message(c), HasSubstr("keys[1].in_x = 0"));
  c = uniform_type(maya_tangent::spline);
  c.keys[3].time = 1;
  EXPECT_THAT(message(c), HasSubstr("keys must be in increasing time order: keys[3].time = 1 <= keys[2].time = 3"));
  c = uniform_type(maya_tangent::spline);
  c.keys[0].in_type = static_cast<maya_tangent>(42);
  EXPECT_THAT(message(c), HasSubstr("keys[0].in_type = 42: not a maya_tangent"));
  c = uniform_type(maya_tangent::spline);
  c.post = static_cast<maya_infinity>(9);
  EXPECT_THAT(message(c), HasSubstr("post = 9: not a maya_infinity"));
  c = uniform_type(maya_tangent::spline);
  c.clamp_tolerance = -0.5;
  EXPECT_THAT(message(c), HasSubstr("clamp_tolerance = -0.5: must be >= 0"));
}

}  // namespace
