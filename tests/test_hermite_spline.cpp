// Hermite spline on non-uniform knots: seed 000's coefficient formulas (erratum fixed) as the
// closed-form reference, the slope convention (dP/du of the global parameter), interpolation of
// values and slopes, C1 (one slope per knot) versus broken tangents, seed 001's Hermite chain,
// cubic reproduction, and bad input.
#include "support/accuracy.hpp"
#include "support/fixtures.hpp"

#include "curvebench/curves/hermite_spline.hpp"

#include <gmock/gmock.h>

#include <cmath>
#include <vector>

namespace cb = curvebench;
namespace cbt = curvebench::testing;
using ::testing::HasSubstr;

namespace {

// Tolerances (eps(Real) times the scale of the data, values ~ 3 and slopes ~ 4 on h >= 0.25):
// - knot_value_ulps: at the start of a segment the value is the stored a0 = P_i itself (0 ulps);
//   at the end of the last segment Horner adds 4 coefficients of size <= scale: 4 roundings.
// - slope_ulps: a1 / h = (h m) / h: 2 roundings of the slope; left limits add 3 products: 8.
// - seed_formula_ulps: engine (Hermite -> power coefficients, ~4 roundings of items of size
//   scale, Horner 3) against the seed's closed form in real50; derivatives divide by h^k with
//   h >= 1/4, which the scale carries (x 4^k). 24 = 2x the count.
// - continuity_ulps: a jump at a knot, two evaluations of ~8 roundings each, relative to the scale.
constexpr double knot_value_ulps = 4;
constexpr double slope_ulps = 8;
constexpr double seed_formula_ulps = 24;
constexpr double continuity_ulps = 16;

template <class Real>
class hermite_test : public ::testing::Test {};
TYPED_TEST_SUITE(hermite_test, cbt::all_reals);

// Non-uniform dyadic data, exact in every type.
const std::vector<double> kd{-1.0, -0.25, 0.5, 0.75, 2.0};
const std::vector<std::array<double, 2>> vd{{0.0, 1.0}, {1.5, -0.5}, {2.0, 2.25}, {-1.0, 0.5}, {3.0, 0.0}};
const std::vector<std::array<double, 2>> sd{{1.0, 0.0}, {-2.0, 3.5}, {0.5, -1.0}, {4.0, 2.0}, {-1.0, 1.0}};
const std::vector<std::array<double, 2>> in_d{{0.0, 0.0}, {1.0, -1.0}, {-3.0, 0.25}, {0.0, 4.0}, {2.0, -2.0}};

template <class Real>
cb::point_list<Real, 2> pts(const std::vector<std::array<double, 2>>& a) {
  return cbt::points_from<Real>(a);
}
template <class Real>
std::vector<Real> knots() {
  return std::vector<Real>(kd.begin(), kd.end());
}
const double data_scale = 4.0;  // max |value| and max |slope| of the data

// Seed 000, "Cubic Hermite Splines": on [t_i, t_{i+1}], x = t - t_i,
//   q = a x^3 + b x^2 + c x + d,  a = -2Δy/h^3 + (s_i + s_{i+1})/h^2,  b = 3Δy/h^2 - (2 s_i + s_{i+1})/h,
//   c = s_i, d = y_i, with slopes s per unit of t (the global parameter). Derivatives by hand.
cb::real50 seed_coefficient_form(double y0, double y1, double s0, double s1, double t0, double t1, const cb::real50& t,
                                 int order) {
  const cb::real50 h = cb::real50(t1) - cb::real50(t0), dy = cb::real50(y1) - cb::real50(y0), x = t - cb::real50(t0);
  const cb::real50 a = -2 * dy / (h * h * h) + (cb::real50(s0) + cb::real50(s1)) / (h * h);
  const cb::real50 b = 3 * dy / (h * h) - (2 * cb::real50(s0) + cb::real50(s1)) / h;
  const cb::real50 c(s0), d(y0);
  switch (order) {
    case 0: return ((a * x + b) * x + c) * x + d;
    case 1: return (3 * a * x + 2 * b) * x + c;
    case 2: return 6 * a * x + 2 * b;
    default: return 6 * a;
  }
}

// Seed 000, "Hermite Basis", with the DESIGN.md erratum fixed (the y_{i+1} term is
// -2x^3/h^3 + 3x^2/h^2): the same polynomial written as a blend; values only.
cb::real50 seed_basis_form(double y0, double y1, double s0, double s1, double t0, double t1, const cb::real50& t) {
  const cb::real50 h = cb::real50(t1) - cb::real50(t0), x = t - cb::real50(t0);
  const cb::real50 x2 = x * x / (h * h), x3 = x * x * x / (h * h * h);
  return cb::real50(y0) * (2 * x3 - 3 * x2 + 1) + cb::real50(y1) * (-2 * x3 + 3 * x2) +
         cb::real50(s0) * (x * x * x / (h * h) - 2 * x * x / h + x) +
         cb::real50(s1) * (x * x * x / (h * h) - x * x / h);
}

}  // namespace

static_assert(cb::curve<cb::hermite_spline<double, 2>>);
static_assert(cb::curve<cb::hermite_spline<cb::real50, 3>>);

TYPED_TEST(hermite_test, matches_seed_000_coefficient_formulas_on_nonuniform_knots) {
  using Real = TypeParam;
  const cb::hermite_spline<Real, 2> c(knots<Real>(), pts<Real>(vd), pts<Real>(sd));
  for (std::size_t i = 0; i + 1 < kd.size(); ++i)
    for (int k = 0; k < 16; ++k) {
      const double u = kd[i] + (kd[i + 1] - kd[i]) * k / 16.0;  // dyadic, exact
      for (int order = 0; order <= 3; ++order) {
        cb::point<cb::real50, 2> ref;
        for (int d = 0; d < 2; ++d) {
          ref[d] = seed_coefficient_form(vd[i][d], vd[i + 1][d], sd[i][d], sd[i + 1][d], kd[i], kd[i + 1],
                                         cb::real50(u), order);
          if (order == 0) {
            // The two seed forms are the same polynomial (checks the erratum fix), to 50 digits.
            const cb::real50 basis =
                seed_basis_form(vd[i][d], vd[i + 1][d], sd[i][d], sd[i + 1][d], kd[i], kd[i + 1], cb::real50(u));
            ASSERT_TRUE(cbt::within_scaled_ulps(basis, ref[d], cb::real50(data_scale), 64));
          }
        }
        const cb::real50 scale = cb::real50(data_scale) * cb::real50(std::pow(4.0, order));
        ASSERT_TRUE(cbt::point_within(c.derivative(Real(u), order), ref, scale, seed_formula_ulps))
            << "u=" << u << " order=" << order;
      }
    }
}

TYPED_TEST(hermite_test, interpolates_values_and_global_slopes_and_is_c1) {
  using Real = TypeParam;
  const auto v = pts<Real>(vd);
  const auto s = pts<Real>(sd);
  const cb::hermite_spline<Real, 2> c(knots<Real>(), v, s);
  const auto& e = c.engine();
  const cb::real50 scale(data_scale);
  for (std::size_t i = 0; i < kd.size(); ++i) {
    const Real u = Real(kd[i]);
    ASSERT_TRUE(cbt::point_within(c(u), cb::point_cast<cb::real50>(v[i]), scale, knot_value_ulps)) << i;
    // Slopes are dP/du of the GLOBAL parameter (not dP/dt of the segment): on knots with h != 1
    // the two differ by the factor h, so this fails for the other convention.
    ASSERT_TRUE(cbt::point_within(c.derivative(u, 1), cb::point_cast<cb::real50>(s[i]), scale, slope_ulps)) << i;
    if (i > 0 && i + 1 < kd.size()) {
      for (int order = 0; order <= 1; ++order) {
        const auto left = e.evaluate_segment(i - 1, Real(1), order);
        const auto right = e.evaluate_segment(i, Real(0), order);
        ASSERT_TRUE(cbt::point_within(left, cb::point_cast<cb::real50>(right), scale * 4, continuity_ulps))
            << "C" << order << " at knot " << i;
      }
      // Not C2: generic Hermite data have a second-derivative jump (relative size >> rounding).
      const auto l2 = e.evaluate_segment(i - 1, Real(1), 2);
      const auto r2 = e.evaluate_segment(i, Real(0), 2);
      EXPECT_GT(static_cast<double>((l2 - r2).norm()), 1e-2) << "knot " << i;
    }
  }
}

TYPED_TEST(hermite_test, broken_tangents_give_the_two_one_sided_slopes) {
  using Real = TypeParam;
  const auto v = pts<Real>(vd);
  const auto out = pts<Real>(sd);
  const auto in = pts<Real>(in_d);
  const cb::hermite_spline<Real, 2> c(knots<Real>(), v, in, out);
  const auto& e = c.engine();
  for (std::size_t i = 1; i + 1 < kd.size(); ++i) {
    // C0 holds, the slope jumps from incoming[i] to outgoing[i].
    ASSERT_TRUE(cbt::point_within(e.evaluate_segment(i - 1, Real(1), 0), cb::point_cast<cb::real50>(v[i]),
                                  cb::real50(data_scale), knot_value_ulps));
    ASSERT_TRUE(cbt::point_within(e.evaluate_segment(i - 1, Real(1), 1), cb::point_cast<cb::real50>(in[i]),
                                  cb::real50(data_scale), slope_ulps));
    ASSERT_TRUE(cbt::point_within(e.evaluate_segment(i, Real(0), 1), cb::point_cast<cb::real50>(out[i]),
                                  cb::real50(data_scale), slope_ulps));
  }
  EXPECT_EQ(c.incoming_slopes().size(), kd.size());
}

TYPED_TEST(hermite_test, reproduces_a_cubic_from_its_hermite_data) {
  using Real = TypeParam;
  // q(u) = 1 - 2u + u^2/2 + u^3/4: dyadic values and slopes at dyadic knots; q''' = 3/2 exactly.
  auto q = [](double u, int order) {
    switch (order) {
      case 0: return 1 - 2 * u + u * u / 2 + u * u * u / 4;
      case 1: return -2 + u + 3 * u * u / 4;
      case 2: return 1 + 3 * u / 2;
      default: return 1.5;
    }
  };
  std::vector<Real> k = knots<Real>();
  cb::point_list<Real, 1> v, s;
  for (double u : kd) {
    v.push_back(cb::point<Real, 1>(Real(q(u, 0))));
    s.push_back(cb::point<Real, 1>(Real(q(u, 1))));
  }
  const cb::hermite_spline<Real, 1> c(k, v, s);
  for (int j = 0; j <= 48; ++j) {
    const double u = -1.0 + 3.0 * j / 48.0;  // dyadic multiples of 1/16
    for (int order = 0; order <= 3; ++order)
      ASSERT_TRUE(cbt::within_scaled_ulps(c.derivative(Real(u), order)[0], cb::real50(q(u, order)),
                                          cb::real50(4) * cb::real50(std::pow(4.0, order)), seed_formula_ulps))
          << u << " " << order;
  }
}

TEST(hermite, chain_of_alternating_points_and_tangents_is_seed_001s) {
  // P0, T0, P1, T1, P2, T2: 6 items -> (6 - 2)/2 = 2 segments on knots 0, 1, 2 (dP/du = dP/dt).
  using P = cb::point<double, 2>;
  const std::vector<P> items{P(0, 0), P(1, 1), P(2, 0), P(0, -1), P(3, 2), P(1, 0)};
  const auto c = cb::hermite_spline<double, 2>::chain(items);
  EXPECT_EQ(c.engine().segment_count(), 2u);
  EXPECT_EQ(c.domain().hi, 2.0);
  const cb::hermite_spline<double, 2> ref({0.0, 1.0, 2.0}, {items[0], items[2], items[4]},
                                          {items[1], items[3], items[5]});
  for (int k = 0; k <= 20; ++k) {
    const double u = k / 10.0;
    EXPECT_EQ(c(u), ref(u));
    EXPECT_EQ(c.derivative(u, 1), ref.derivative(u, 1));
  }
  // Segment 0 is the textbook Hermite cubic with G = [P0, P1, T0, T1] (seed 001's blending functions).
  const double t = 0.375;
  const P expect = (2 * t * t * t - 3 * t * t + 1) * items[0] + (t * t * t - 2 * t * t + t) * items[1] +
                   (-2 * t * t * t + 3 * t * t) * items[2] + (t * t * t - t * t) * items[3];
  EXPECT_NEAR((c(t) - expect).norm(), 0.0, 8 * 3 * std::numeric_limits<double>::epsilon());
  // Given knots: tangents stay dP/du.
  const auto c2 = cb::hermite_spline<double, 2>::chain(items, {0.0, 0.5, 2.0});
  EXPECT_NEAR((c2.derivative(0.5, 1) - items[3]).norm(), 0.0, 8 * 4 * std::numeric_limits<double>::epsilon());
}

TEST(hermite, bad_input_names_what_and_where) {
  using P = cb::point<double, 2>;
  auto msg = [](auto&& f) -> std::string {
    try {
      f();
    } catch (const cb::invalid_input& e) {
      return e.what();
    }
    return "no exception";
  };
  const cb::point_list<double, 2> v3(3, P(0, 0));
  const cb::point_list<double, 2> v2(2, P(0, 0));
  EXPECT_THAT(msg([&] {
                cb::hermite_spline<double, 2>({0.0, 1.0, 2.0}, v3, v2);
              }),
              HasSubstr("slopes: 2 given, must match knots: 3"));
  EXPECT_THAT(msg([&] {
                cb::hermite_spline<double, 2>({0.0, 2.0, 1.0}, v3, v3);
              }),
              HasSubstr("knots must be increasing: knots[2] = 1 <= knots[1] = 2"));
  EXPECT_THAT(msg([&] { cb::hermite_spline<double, 2>({0.0}, {P(0, 0)}, {P(0, 0)}); }),
              HasSubstr("knots: 1 given, at least 2 required"));
  auto bad = v3;
  bad[2][1] = std::nan("");
  EXPECT_THAT(msg([&] {
                cb::hermite_spline<double, 2>({0.0, 1.0, 2.0}, bad, v3);
              }),
              HasSubstr("values[2][1] = nan: coordinates must be finite"));
  EXPECT_THAT(msg([&] {
                cb::hermite_spline<double, 2>({0.0, 1.0, 2.0}, v3, v3, bad);
              }),
              HasSubstr("outgoing slopes[2][1] = nan"));
  const std::vector<P> odd(5, P(0, 0));
  EXPECT_THAT(msg([&] { (void)cb::hermite_spline<double, 2>::chain(odd); }),
              HasSubstr("chain items: 5 given, must be even"));
  const std::vector<P> two(2, P(0, 0));
  EXPECT_THAT(msg([&] { (void)cb::hermite_spline<double, 2>::chain(two); }),
              HasSubstr("chain items: 2 given, at least 4"));
  const std::vector<P> four(4, P(0, 0));
  EXPECT_THAT(msg([&] {
                (void)cb::hermite_spline<double, 2>::chain(four, {0.0, 1.0, 2.0});
              }),
              HasSubstr("knots: 3 given, must match chain points (items / 2): 2"));
  const cb::hermite_spline<double, 2> c({0.0, 1.0, 2.0}, v3, v3);
  EXPECT_THROW((void)c(2.5), std::domain_error);
}
