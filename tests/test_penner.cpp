// Penner's easing equations as Blender applies them (channel/penner.hpp): names, Blender's AUTO
// choice, exact endpoint values, closed forms, the out/in reflection and the in_out halves in
// real50, float / double / long double against real50, the derivatives against real50 central
// differences, Blender 3.4.1's recorded values (tests/data/blender_easing.json) at float32
// tolerance, and the validation messages.
#include "support/accuracy.hpp"
#include "support/fixtures.hpp"
#include "support/source_dir.hpp"

#include "curvebench/channel/penner.hpp"
#include "curvebench/reference/multiprecision.hpp"

#include <gmock/gmock.h>
#include <nlohmann/json.hpp>

#include <boost/math/constants/constants.hpp>

#include <cmath>
#include <fstream>
#include <map>
#include <string>
#include <vector>

namespace cb = curvebench;
namespace ch = curvebench::channel;
namespace cbt = curvebench::testing;
using cb::real50;
using ch::ease_mode;
using ch::penner_family;
using ::testing::HasSubstr;

namespace {

// Tolerances, in eps(Real) of the scale |b| + |c| + |v - b| + (|t| + d) |v'| (+ a for elastic):
// the data's magnitudes plus the rounding of t and d carried by the slope.
//  - own_precision: Real against its real50 twin from the same inputs. A handful of roundings of
//    half an ulp each (normalizing t, the elementary function, the product by c, the sum with b;
//    elastic adds the sine's argument and the amplitude blend), which mostly do not add up:
//    measured at most 0.60 (float), 0.40 (double), 0.39 (long double) over the grid below; 2
//    leaves a factor 3 for other libm versions.
constexpr double own_precision = 2;
//  - slope_precision: the first derivative against its real50 twin, in eps of
//    |v'| + |c| / d + (|t| + d) |v''| (+ a (2 pi / |p| + 10 ln 2 / d) for elastic, the size of its
//    wave's slope): the same roundings one derivative deeper. Measured at most 0.61 (float), 0.58
//    (double), 0.57 (long double); 2 leaves a factor 3.
constexpr double slope_precision = 2;
//  - blender_vs_double: Blender evaluates in float32 (keys, parameters and times are float32,
//    so the double formula on the recorded inputs is Blender's exact answer up to Blender's own
//    float32 rounding). In eps_float of the scale above with |t| + |t0| + d in place of |t| + d
//    (the absolute frame t, the key's frame t0 and the duration are each rounded to float32 by
//    Blender, and the slope carries each rounding into the value): measured 0.29; the bound
//    allows 2: Blender's evaluation is a handful of float operations, each at most half an ulp.
constexpr double blender_vs_double = 2;
//  - blender_vs_float: our float result against Blender's: both roundings, 2 + own_precision
//    (measured 0.54).
constexpr double blender_vs_float = blender_vs_double + own_precision;
//  - derivative_rel: real50 derivative formulas against real50 central differences with
//    h = 1e-20 d: truncation h^2 |v^(3)| / 6 and rounding 1e-50 |v| / h are both below 1e-28 of
//    the scale |v^(order)| + |c| / d^order + 1, and the bound is 1e-25 of it.
constexpr double derivative_rel = 1e-25;

struct segment {
  float b, c, d;
};
// A rising, a falling and short, a change below the default elastic amplitude, and no change.
const std::vector<segment> segments{{2, 5, 20}, {4, -3, 5.5f}, {0, 0.5f, 10}, {1, 0, 8}};

struct param_set {
  float back, amplitude, period;
};
// Blender's key defaults, keyframe_points.add()'s zeros, a large overshoot, amplitude above the
// change, a long period, a negative period.
const std::vector<param_set> param_sets{{1.70158f, 0.8f, 4.1f}, {0, 0, 0},     {3, 10, 3},
                                        {-0.5f, 2, 7},          {1, 0.25f, 0}, {2, 4, -2}};

const std::vector<ease_mode> modes{ease_mode::in, ease_mode::out, ease_mode::in_out};

template <class Real>
ch::penner_params<Real> params_of(const param_set& p) {
  return {Real(p.back), Real(p.amplitude), Real(p.period)};
}

// Times in [0, d]: a grid avoiding the pieces' joins (bounce's 4/11.., in_out's 1/2) plus the ends.
std::vector<float> times_of(float d) {
  std::vector<float> ts{0, d};
  for (int k = 0; k < 50; ++k) ts.push_back(d * (static_cast<float>(k) + 0.37f) / 50);
  return ts;
}

template <class Real>
Real ease(penner_family f, ease_mode m, const param_set& p, float t, const segment& s, int order = 0) {
  return ch::penner_ease<Real>(f, m, params_of<Real>(p), Real(t), Real(s.b), Real(s.c), Real(s.d), order);
}

real50 scale_of(penner_family f, const param_set& p, float t, const segment& s, const real50& v, const real50& v1) {
  using std::abs;
  real50 sc = abs(real50(s.b)) + abs(real50(s.c)) + abs(v - real50(s.b)) + (real50(t) + real50(s.d)) * abs(v1);
  if (f == penner_family::elastic) sc += real50(p.amplitude);
  return sc;
}

template <class Real>
class penner_test : public ::testing::Test {};
TYPED_TEST_SUITE(penner_test, cbt::ieee_reals);

}  // namespace

TEST(penner, names_round_trip) {
  for (penner_family f : ch::all_penner_families) EXPECT_EQ(ch::penner_family_from_string(ch::to_string(f)), f);
  for (ease_mode m : ch::all_ease_modes) EXPECT_EQ(ch::ease_mode_from_string(ch::to_string(m)), m);
  EXPECT_STREQ(ch::to_string(penner_family::elastic), "elastic");
  EXPECT_STREQ(ch::to_string(ease_mode::in_out), "in_out");
  EXPECT_THAT(cbt::message_of([] { (void)ch::penner_family_from_string("Quad"); }),
              HasSubstr("penner family = \"Quad\": unknown"));
  EXPECT_THAT(cbt::message_of([] { (void)ch::ease_mode_from_string("inout"); }),
              HasSubstr("ease mode = \"inout\": unknown (expected in, out, in_out or automatic)"));
}

// Blender's API reference: AUTO is "Ease In for transitional types, and Ease Out for dynamic
// effects" (back, bounce, elastic); the fixture's AUTO channels confirm it numerically below.
TEST(penner, automatic_is_blenders_choice) {
  for (penner_family f : ch::all_penner_families) {
    const bool dynamic = f == penner_family::back || f == penner_family::bounce || f == penner_family::elastic;
    EXPECT_EQ(ch::resolve(f, ease_mode::automatic), dynamic ? ease_mode::out : ease_mode::in) << ch::to_string(f);
    for (ease_mode m : modes) EXPECT_EQ(ch::resolve(f, m), m);
  }
}

// value(0) = begin and value(d) = begin + change exactly, every family, mode and parameter set.
TYPED_TEST(penner_test, endpoints_exact) {
  using Real = TypeParam;
  for (penner_family f : ch::all_penner_families)
    for (ease_mode m : ch::all_ease_modes)
      for (const segment& s : segments)
        for (const param_set& p : param_sets) {
          EXPECT_EQ(ease<Real>(f, m, p, 0, s), Real(s.b)) << ch::to_string(f) << " " << ch::to_string(m);
          EXPECT_EQ(ease<Real>(f, m, p, s.d, s), Real(s.b) + Real(s.c)) << ch::to_string(f) << " " << ch::to_string(m);
        }
}

// Closed forms at chosen points in real50 (b = 0, c = 1, d = 1), typed from Penner's equations
// independently of the header's forms (expo's normalisation, 2 sin^2 for sine, x^2 / (1 + r) for
// circ, the reflection for out are the header's; these are the textbook forms).
TEST(penner, closed_forms) {
  using std::cos;
  using std::pow;
  using std::sin;
  using std::sqrt;
  const real50 pi = boost::math::constants::pi<real50>();
  const ch::penner_params<real50> p{real50(2), real50(3), real50(real50(2) / 7)};
  const auto at = [&](penner_family f, ease_mode m, const real50& x) {
    return ch::penner_ease<real50>(f, m, p, x, real50(0), real50(1), real50(1));
  };
  const real50 x("0.3");
  const real50 y = x - 1;
  const std::vector<std::pair<real50, real50>> cases{
      {at(penner_family::sine, ease_mode::in, x), 1 - cos(x * pi / 2)},
      {at(penner_family::sine, ease_mode::out, x), sin(x * pi / 2)},
      {at(penner_family::sine, ease_mode::in_out, x), -(cos(pi * x) - 1) / 2},
      {at(penner_family::quad, ease_mode::out, x), -x * (x - 2)},
      {at(penner_family::cubic, ease_mode::out, x), y * y * y + 1},
      {at(penner_family::quart, ease_mode::out, x), -(y * y * y * y - 1)},
      {at(penner_family::quint, ease_mode::in_out, x), 16 * x * x * x * x * x},
      {at(penner_family::circ, ease_mode::in, x), -(sqrt(1 - x * x) - 1)},
      {at(penner_family::circ, ease_mode::out, x), sqrt(1 - y * y)},
      {at(penner_family::expo, ease_mode::in, x),
       (pow(real50(2), 10 * y) - pow(real50(2), -10)) / (1 - pow(real50(2), -10))},
      {at(penner_family::back, ease_mode::in, x), x * x * (3 * x - 2)},
      {at(penner_family::back, ease_mode::out, x), y * y * (3 * y + 2) + 1},
      {at(penner_family::bounce, ease_mode::out, real50("0.2")), real50(121) / 16 * real50("0.04")},
      {at(penner_family::bounce, ease_mode::out, real50("0.5")),
       real50(121) / 16 * (real50("0.5") - real50(6) / 11) * (real50("0.5") - real50(6) / 11) + real50("0.75")},
      // Penner's easeInElastic with a = 3 >= |c| = 1, p = 2/7: s = p / (2 pi) asin(c / a).
      {at(penner_family::elastic, ease_mode::in, x),
       -(3 * pow(real50(2), 10 * y) * sin((y - p.period / (2 * pi) * asin(real50(1) / 3)) * (2 * pi) / p.period))},
  };
  for (std::size_t i = 0; i < cases.size(); ++i)
    EXPECT_TRUE(cbt::within_scaled_ulps(cases[i].first, cases[i].second, real50(1), 16)) << "case " << i;
}

// out(t) = b + c - (in(d - t) - b), and in_out's halves are in and out on half the time with the
// in_out constants (back * 1.525; elastic's default period 0.45 d given explicitly), in real50.
TEST(penner, reflection_and_halves) {
  for (penner_family f : ch::all_penner_families)
    for (const segment& s : segments)
      for (const param_set& ps : param_sets)
        for (float t : times_of(s.d)) {
          const auto v = [&](ease_mode m, const ch::penner_params<real50>& p, const real50& at) {
            return ch::penner_ease<real50>(f, m, p, at, real50(s.b), real50(s.c), real50(s.d));
          };
          ch::penner_params<real50> p = params_of<real50>(ps);
          const real50 tt(t), d(s.d), b(s.b), c(s.c);
          const real50 scale = abs(b) + abs(c) + real50(ps.amplitude) + 1;
          if (t != 0 && t != s.d) {  // elastic's wave is b, b + c at the ends only by the special case
            EXPECT_TRUE(
                cbt::within_scaled_ulps(v(ease_mode::out, p, tt), b + c - (v(ease_mode::in, p, d - tt) - b), scale, 64))
                << ch::to_string(f) << " t=" << t;
          }
          ch::penner_params<real50> h = p;
          h.back = p.back * real50("1.525");
          if (h.period == 0) h.period = real50("0.45") * d;
          const real50 half = tt < d / 2 ? b + (v(ease_mode::in, h, 2 * tt) - b) / 2
                                         : b + c / 2 + (v(ease_mode::out, h, 2 * tt - d) - b) / 2;
          if (t != 0 && t != s.d && 2 * t != s.d) {
            EXPECT_TRUE(cbt::within_scaled_ulps(v(ease_mode::in_out, p, tt), half, scale, 64))
                << ch::to_string(f) << " t=" << t;
          }
        }
}

// Real against the real50 twin (same inputs, exact in every type), value and both derivatives.
TYPED_TEST(penner_test, accuracy_against_real50) {
  using Real = TypeParam;
  double worst = 0, worst_slope = 0;
  for (penner_family f : ch::all_penner_families)
    for (ease_mode m : modes)
      for (const segment& s : segments)
        for (const param_set& p : param_sets)
          for (float t : times_of(s.d)) {
            if (f == penner_family::circ && t == s.d) continue;  // circ in: vertical tangent at the end
            const real50 r = ease<real50>(f, m, p, t, s);
            const bool smooth = !(f == penner_family::circ && ((m == ease_mode::out && t == 0)));
            const real50 r1 = smooth ? ease<real50>(f, m, p, t, s, 1) : real50(0);
            const real50 sc = scale_of(f, p, t, s, r, r1);
            const Real v = ease<Real>(f, m, p, t, s);
            const double e = static_cast<double>(cbt::scaled_ulps(v, r, sc));
            worst = std::max(worst, e);
            EXPECT_LE(e, own_precision) << ch::to_string(f) << " " << ch::to_string(m) << " t=" << t << " b=" << s.b
                                        << " c=" << s.c << " d=" << s.d << "\n"
                                        << cbt::exact_text(v) << " vs " << r;
            // The slope, except where circ's is unbounded or its second derivative is (t = 0 of
            // out and in_out's midpoint, where the scale below would be infinite).
            if (!smooth || (f == penner_family::circ && (t == 0 || 2 * t == s.d))) continue;
            using std::abs;
            const real50 r2 = ease<real50>(f, m, p, t, s, 2);
            real50 sc1 = abs(r1) + abs(real50(s.c)) / real50(s.d) + (real50(t) + real50(s.d)) * abs(r2);
            if (f == penner_family::elastic) {
              const real50 period = p.period != 0 ? abs(real50(p.period)) : real50("0.3") * real50(s.d);
              sc1 += real50(p.amplitude) * (2 * boost::math::constants::pi<real50>() / period +
                                            10 * boost::math::constants::ln_two<real50>() / real50(s.d));
            }
            const Real v1 = ease<Real>(f, m, p, t, s, 1);
            if (sc1 == 0) {  // no change and no wave: the slope is exactly 0
              EXPECT_EQ(v1, Real(0)) << ch::to_string(f) << " " << ch::to_string(m) << " t=" << t;
              continue;
            }
            const double e1 = static_cast<double>(cbt::scaled_ulps(v1, r1, sc1));
            worst_slope = std::max(worst_slope, e1);
            EXPECT_LE(e1, slope_precision) << ch::to_string(f) << " " << ch::to_string(m) << " slope t=" << t
                                           << " b=" << s.b << " c=" << s.c << " d=" << s.d << "\n"
                                           << cbt::exact_text(v1) << " vs " << r1;
          }
  std::cout << "worst value error " << worst << ", slope error " << worst_slope << " eps of the scale\n";
}

// The derivative formulas (real50) against central differences of the real50 value and of the
// first derivative, away from the pieces' joins (the grid avoids them) and the ends.
TEST(penner, derivatives_against_central_differences) {
  using std::abs;
  for (penner_family f : ch::all_penner_families)
    for (ease_mode m : modes)
      for (const segment& s : segments)
        for (const param_set& p : param_sets) {
          const real50 d(s.d), h = real50("1e-20") * d;
          const ch::penner_params<real50> pr = params_of<real50>(p);
          const auto v = [&](const real50& t, int order) {
            return ch::penner_ease<real50>(f, m, pr, t, real50(s.b), real50(s.c), d, order);
          };
          for (float tf : times_of(s.d)) {
            if (tf == 0 || tf == s.d) continue;
            const real50 t(tf);
            for (int order = 1; order <= 2; ++order) {
              const real50 fd = (v(t + h, order - 1) - v(t - h, order - 1)) / (2 * h);
              const real50 exact = v(t, order);
              const real50 sc = abs(exact) + abs(real50(s.c)) / pow(d, order) + 1;
              EXPECT_LE(abs(exact - fd) / sc, real50(derivative_rel))
                  << ch::to_string(f) << " " << ch::to_string(m) << " order " << order << " t=" << tf << "\n"
                  << exact << "\n"
                  << fd;
            }
          }
        }
}

// Blender's own values (recorded by scripts/peers/blender_fcurves.py, float32) against the
// formulas on Blender's float32 inputs, in double and in float.
TEST(penner, blender_recorded_values) {
  std::ifstream in(curvebench::testing::source_dir() + "/tests/data/blender_easing.json");
  ASSERT_TRUE(in) << "tests/data/blender_easing.json";
  const nlohmann::json doc = nlohmann::json::parse(in);
  EXPECT_EQ(doc.at("blender_version").get<std::string>(), "3.4.1");
  const std::map<std::string, ease_mode> easing{{"AUTO", ease_mode::automatic},
                                                {"EASE_IN", ease_mode::in},
                                                {"EASE_OUT", ease_mode::out},
                                                {"EASE_IN_OUT", ease_mode::in_out}};
  const double eps_f = std::numeric_limits<float>::epsilon();
  std::size_t checked = 0;
  double worst = 0, worst_float = 0;
  for (const auto& c : doc.at("channels")) {
    const auto& k0 = c.at("keys").at(0);
    const auto& k1 = c.at("keys").at(1);
    std::string fam = k0.at("interpolation").get<std::string>();
    for (char& x : fam) x = static_cast<char>(std::tolower(static_cast<unsigned char>(x)));
    const penner_family f = ch::penner_family_from_string(fam);
    const ease_mode m = easing.at(k0.at("easing").get<std::string>());
    const double t0 = k0.at("time"), v0 = k0.at("value"), t1 = k1.at("time"), v1 = k1.at("value");
    const ch::penner_params<double> pd{k0.at("back").get<double>(), k0.at("amplitude").get<double>(),
                                       k0.at("period").get<double>()};
    const ch::penner_params<float> pf{static_cast<float>(pd.back), static_cast<float>(pd.amplitude),
                                      static_cast<float>(pd.period)};
    const auto& ts = c.at("times");
    const auto& vs = c.at("values");
    ASSERT_EQ(ts.size(), vs.size());
    for (std::size_t i = 0; i < ts.size(); ++i) {
      const double t = ts[i], blender = vs[i];
      const double vd = ch::penner_ease(f, m, pd, t - t0, v0, v1 - v0, t1 - t0);
      const float vf = ch::penner_ease(f, m, pf, static_cast<float>(t - t0), static_cast<float>(v0),
                                       static_cast<float>(v1 - v0), static_cast<float>(t1 - t0));
      // The slope carries the rounding of t, t0 and d into the value. At circ's vertical tangents
      // (t exact in float there, so nothing to carry) and at the ends (the value is the key's) it
      // is left out.
      double slope = 0;
      try {
        if (t > t0 && t < t1) slope = std::abs(ch::penner_ease(f, m, pd, t - t0, v0, v1 - v0, t1 - t0, 1));
      } catch (const std::domain_error&) {
        EXPECT_EQ(f, penner_family::circ) << c.at("name").get<std::string>() << " t=" << t;
      }
      double scale =
          std::abs(v0) + std::abs(v1 - v0) + std::abs(vd - v0) + (std::abs(t) + std::abs(t0) + (t1 - t0)) * slope;
      if (f == penner_family::elastic) scale += pd.amplitude;
      const double ed = std::abs(vd - blender) / (eps_f * scale);
      const double ef = std::abs(static_cast<double>(vf) - blender) / (eps_f * scale);
      worst = std::max(worst, ed);
      worst_float = std::max(worst_float, ef);
      EXPECT_LE(ed, blender_vs_double) << c.at("name").get<std::string>() << " t=" << t << " blender " << blender
                                       << " double " << vd;
      EXPECT_LE(ef, blender_vs_float) << c.at("name").get<std::string>() << " t=" << t << " blender " << blender
                                      << " float " << vf;
      ++checked;
    }
  }
  EXPECT_GT(checked, 10000u);  // 288 channels x 39 times
  std::cout << "checked " << checked << " Blender values; worst " << worst << " (double), " << worst_float
            << " (float) eps_float of the scale\n";
}

TEST(penner, validation_messages) {
  const ch::penner_params<double> p;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  const auto msg = [&](auto&& f) { return cbt::message_of(f); };
  using F = penner_family;
  using M = ease_mode;
  EXPECT_THAT(msg([&] { (void)ch::penner_ease(F::quad, M::in, p, 0.5, 0.0, 1.0, 0.0); }),
              HasSubstr("duration = 0: must be > 0"));
  EXPECT_THAT(msg([&] { (void)ch::penner_ease(F::quad, M::in, p, 0.5, 0.0, 1.0, -2.0); }),
              HasSubstr("duration = -2: must be > 0"));
  EXPECT_THAT(msg([&] { (void)ch::penner_ease(F::quad, M::in, p, nan, 0.0, 1.0, 1.0); }),
              HasSubstr("t = nan: must be finite"));
  EXPECT_THAT(msg([&] { (void)ch::penner_ease(F::quad, M::in, p, 0.5, inf, 1.0, 1.0); }),
              HasSubstr("begin = inf: must be finite"));
  EXPECT_THAT(msg([&] { (void)ch::penner_ease(F::quad, M::in, p, 0.5, 0.0, -inf, 1.0); }),
              HasSubstr("change = -inf: must be finite"));
  EXPECT_THAT(msg([&] {
                (void)ch::penner_ease(F::elastic, M::in, ch::penner_params<double>{1, -1, 1}, 0.5, 0.0, 1.0, 1.0);
              }),
              HasSubstr("amplitude = -1: must be >= 0"));
  EXPECT_THAT(msg([&] {
                (void)ch::penner_ease(F::elastic, M::in, ch::penner_params<double>{1, 1, nan}, 0.5, 0.0, 1.0, 1.0);
              }),
              HasSubstr("period = nan: must be finite"));
  EXPECT_THAT(msg([&] {
                (void)ch::penner_ease(F::back, M::in, ch::penner_params<double>{inf, 1, 1}, 0.5, 0.0, 1.0, 1.0);
              }),
              HasSubstr("back = inf: must be finite"));
  EXPECT_THAT(msg([&] { (void)ch::penner_ease(F::quad, M::in, p, 0.5, 0.0, 1.0, 1.0, 3); }),
              HasSubstr("order = 3: penner_ease gives orders 0, 1 and 2"));
  EXPECT_THAT(msg([&] { (void)ch::penner_ease(F::quad, M::in, p, 0.5, 0.0, 1.0, 1.0, -1); }),
              HasSubstr("order = -1: derivative order must be >= 0"));
  EXPECT_THROW((void)ch::penner_ease(F::quad, M::in, p, 0.5, 0.0, 1.0, 1.0, -1), cb::invalid_input);
  // Outside the segment: domain_error with the value and the segment.
  EXPECT_THROW((void)ch::penner_ease(F::quad, M::in, p, 1.5, 0.0, 1.0, 1.0), std::domain_error);
  EXPECT_THAT(msg([&] { (void)ch::penner_ease(F::quad, M::in, p, -0.25, 0.0, 1.0, 1.0); }),
              HasSubstr("t = -0.25: outside the segment [0, duration = 1]"));
  // circ's vertical tangent: the derivative is unbounded there, not a number to return.
  EXPECT_THAT(msg([&] { (void)ch::penner_ease(F::circ, M::in, p, 1.0, 0.0, 1.0, 1.0, 1); }),
              HasSubstr("first derivative of circ in is unbounded at t = 1"));
  EXPECT_THAT(msg([&] { (void)ch::penner_ease(F::circ, M::in_out, p, 0.5, 0.0, 1.0, 1.0, 2); }),
              HasSubstr("second derivative of circ in_out is unbounded"));
  EXPECT_NO_THROW((void)ch::penner_ease(F::circ, M::in, p, 1.0, 0.0, 1.0, 1.0));
}
