// Core types: the curve concept, domain checks, validation messages and Real utilities.
#include "support/accuracy.hpp"
#include "support/fixtures.hpp"

#include "curvebench/core/any_curve.hpp"
#include "curvebench/core/curve.hpp"
#include "curvebench/core/error.hpp"

#include <gmock/gmock.h>

#include <array>
#include <cfloat>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

namespace cb = curvebench;
using ::testing::HasSubstr;

namespace {

// A minimal curve (the unit circle, trigonometric) to check the concept is satisfiable and usable.
template <class Real>
struct circle {
  using real_type = Real;
  static constexpr int dimension = 2;
  using point_type = cb::point<Real, 2>;
  std::array<Real, 2> breaks{Real(0), Real(1)};
  [[nodiscard]] cb::interval<Real> domain() const { return {Real(0), Real(1)}; }
  [[nodiscard]] point_type operator()(const Real& u) const { return derivative(u, 0); }
  [[nodiscard]] point_type derivative(const Real& u, int order) const {
    cb::check_parameter(u, domain());
    using std::cos;
    using std::sin;
    const Real w = Real(2) * boost::math::constants::pi<Real>();
    Real a = w * u;
    Real scale(1);
    for (int k = 0; k < order; ++k) scale *= w;
    const int phase = order % 4;  // derivatives of (cos, sin) rotate by 90 degrees
    point_type p;
    p << cos(a), sin(a);
    for (int k = 0; k < phase; ++k) p = point_type(-p[1], p[0]);
    return scale * p;
  }
  [[nodiscard]] std::span<const Real> breakpoints() const { return breaks; }
};

static_assert(cb::curve<circle<double>>);
static_assert(cb::curve<circle<cb::real50>>);
static_assert(!cb::curve<int>);

}  // namespace

TEST(core, domain_error_names_value_and_domain) {
  circle<double> c;
  EXPECT_NO_THROW((void)c(1.0));
  try {
    (void)c(1.5);
    FAIL() << "expected std::domain_error";
  } catch (const std::domain_error& e) {
    EXPECT_THAT(e.what(), HasSubstr("u = 1.5"));
    EXPECT_THAT(e.what(), HasSubstr("[0, 1]"));
  }
}

TEST(core, validation_messages_name_argument_index_value) {
  std::vector<double> knots{0.0, 0.2, 0.7, 0.5};
  try {
    cb::validate::non_decreasing<double>("knots", knots);
    FAIL();
  } catch (const cb::invalid_input& e) {
    EXPECT_STREQ(e.what(), "knots must be non-decreasing: knots[3] = 0.5 < knots[2] = 0.69999999999999996");
  }
  EXPECT_THROW(cb::validate::positive("weights", -1.0, 2), cb::invalid_input);
  try {
    cb::validate::positive("weights", -1.0, 2);
  } catch (const std::invalid_argument& e) {  // invalid_input is-a std::invalid_argument
    EXPECT_STREQ(e.what(), "weights[2] = -1: must be > 0");
  }
  cb::point_list<double, 3> pts{{0, 0, 0}, {1, std::numeric_limits<double>::quiet_NaN(), 0}};
  try {
    cb::validate::finite_points<double, 3>("points", pts);
    FAIL();
  } catch (const cb::invalid_input& e) {
    EXPECT_STREQ(e.what(), "points[1][1] = nan: coordinates must be finite");
  }
  try {
    cb::validate::count_at_least("points", 1, 2, "a polyline needs two vertices");
    FAIL();
  } catch (const cb::invalid_input& e) {
    EXPECT_STREQ(e.what(), "points: 1 given, at least 2 required (a polyline needs two vertices)");
  }
  EXPECT_THROW(cb::validate::increasing<double>("knots", std::vector<double>{0, 1, 1}), cb::invalid_input);
  EXPECT_THROW(cb::validate::same_count("weights", 3, "points", 4), cb::invalid_input);
  EXPECT_THROW(cb::validate::derivative_order(-1), cb::invalid_input);
  EXPECT_THROW(cb::validate::finite("tension", std::numeric_limits<cb::real50>::infinity()), cb::invalid_input);
}

// point<Real, Dim> (and so every family built on it) takes only floating Real types: with an
// integer Real the generic code's Real(1) / Real(2) would be 0, silently.
template <class R>
concept has_point2 = requires {
  typename cb::point<R, 2>;
};

TEST(core, point_accepts_only_real_numbers) {
  EXPECT_TRUE(has_point2<float>);
  EXPECT_TRUE(has_point2<double>);
  EXPECT_TRUE(has_point2<long double>);
  EXPECT_TRUE(has_point2<cb::real50>);
  EXPECT_FALSE(has_point2<int>);
  EXPECT_FALSE(has_point2<long long>);
  EXPECT_FALSE(has_point2<bool>);
}

TEST(core, binomial_is_exact) {
  // C(62, 31) = 465428353255261088 needs 59 bits: exact through the split multiplicative formula.
  EXPECT_EQ(cb::binomial<cb::real50>(62, 31), cb::real50("465428353255261088"));
  EXPECT_EQ(cb::binomial<double>(20, 10), 184756.0);
  EXPECT_EQ(cb::binomial<double>(5, 7), 0.0);
  for (int n = 0; n <= 40; ++n)
    for (int k = 1; k < n; ++k)  // Pascal's rule, exact in 50 digits
      ASSERT_EQ(cb::binomial<cb::real50>(n, k),
                cb::binomial<cb::real50>(n - 1, k - 1) + cb::binomial<cb::real50>(n - 1, k));
}

// Messages show a 50-digit value that is a double exactly (a number the user wrote) as the
// double's shortest text; any other 50-digit value keeps its own digits, and doubles theirs.
TEST(core, to_text_of_a_double_held_in_50_digits_is_the_double) {
  EXPECT_EQ(cb::to_text(cb::real50(1e300)), "1e+300");
  EXPECT_EQ(cb::to_text(cb::real50(0.1)), "0.1");
  EXPECT_EQ(cb::to_text(cb::real50(-2.5)), "-2.5");
  EXPECT_EQ(cb::to_text(cb::real50(0)), "0");
  const std::string third = cb::to_text(cb::real50(1) / 3);
  EXPECT_GE(third.size(), 50u) << third;                    // not a double: all its digits
  EXPECT_EQ(cb::real50(third.c_str()), cb::real50(1) / 3);  // and they read back to it
  EXPECT_EQ(cb::to_text(0.1), "0.10000000000000001");       // a double keeps its 17 digits
}

TEST(core, circle_derivatives_are_exact) {
  // The concept's derivative contract, checked on the test curve against its closed form at 50 digits.
  circle<cb::real50> c;
  const cb::real50 u("0.3");
  const cb::real50 w = 2 * boost::math::constants::pi<cb::real50>();
  const auto d2 = c.derivative(u, 2);
  const auto p = c(u);
  EXPECT_TRUE(cb::testing::within_ulps<cb::real50>(d2[0], -w * w * p[0], 8));
  EXPECT_TRUE(cb::testing::within_ulps<cb::real50>(d2[1], -w * w * p[1], 8));
}

TEST(core, any_curve_wraps_and_satisfies_the_concept) {
  static_assert(cb::curve<cb::any_curve<double, 2>>);
  static_assert(cb::curve<cb::any_curve<cb::real50, 2>>);
  const cb::any_curve<double, 2> a(circle<double>{}, "circle");
  const circle<double> c;
  EXPECT_EQ(a.family(), "circle");
  for (double u : {0.0, 0.25, 0.7, 1.0}) {
    EXPECT_EQ(a(u), c(u));  // the same code runs: bit-identical
    for (int k = 1; k <= 3; ++k) EXPECT_EQ(a.derivative(u, k), c.derivative(u, k));
  }
  EXPECT_EQ(a.breakpoints().size(), 2u);
  EXPECT_EQ(a.domain().hi, 1.0);
  EXPECT_NE(a.target<circle<double>>(), nullptr);
  EXPECT_THROW((void)a(-0.5), std::domain_error);
  const cb::any_curve<double, 2> copy = a;  // copies share the wrapped curve
  EXPECT_EQ(copy(0.3), a(0.3));
  const cb::any_curve<double, 2> named = a.renamed("unit circle");
  EXPECT_EQ(named.family(), "unit circle");
  EXPECT_EQ(a.family(), "circle");
  EXPECT_EQ(named(0.3), a(0.3));
}

// safe_norm (core/point.hpp): |v| for coordinates whose squares overflow or underflow, against the
// closed form sqrt(61) 2^e in real50 (correctly rounded to within half an ulp of real50 itself).
// Each coordinate is a power of two times a small integer, exact in every Real, so only safe_norm's
// own rounding is measured: the sum of Dim scaled squares and one root, within (Dim / 2 + 1) eps
// relative; 3 ulps covers Dim = 3 with room for the reference's own rounding when Real is real50.
template <class Real>
class safe_norm_test : public ::testing::Test {};
TYPED_TEST_SUITE(safe_norm_test, cb::testing::all_reals);

TYPED_TEST(safe_norm_test, matches_real50_from_underflow_to_overflow) {
  using Real = TypeParam;
  using std::ldexp;
  const int emax = std::numeric_limits<Real>::max_exponent, emin = std::numeric_limits<Real>::min_exponent;
  // Exponents from just above the smallest normal to just below the largest finite value: the
  // plain sqrt(v . v) is 0, subnormal or inf at both ends for the IEEE types.
  for (const int e : {emin + 2, emin / 2 - 3, emin / 2, -20, 0, 20, emax / 2, emax / 2 + 3, emax - 3}) {
    // (3, -4, 6) 2^e, exact in every Real: |v| = sqrt(61) 2^e.
    cb::point<Real, 3> v(ldexp(Real(3), e), ldexp(Real(-4), e), ldexp(Real(12), e - 1));
    using std::sqrt;
    // Compared as got / 2^e (exact) with sqrt(61): the distance in ulps of a value near real50's own
    // range limits would itself underflow.
    const cb::real50 ref = sqrt(cb::real50(61));
    const Real got = cb::safe_norm(v);
    EXPECT_TRUE(cb::is_finite(got)) << "exponent " << e;
    EXPECT_TRUE(cb::testing::within_ulps(Real(ldexp(got, -e)), ref, 3.0)) << "exponent " << e;
  }
  EXPECT_EQ(cb::safe_norm(cb::point<Real, 2>(Real(0), Real(0))), Real(0));
  const Real inf = std::numeric_limits<Real>::infinity();
  EXPECT_FALSE(cb::is_finite(cb::safe_norm(cb::point<Real, 2>(inf, Real(1)))));
  const Real nan = std::numeric_limits<Real>::quiet_NaN();
  EXPECT_FALSE(cb::is_finite(cb::safe_norm(cb::point<Real, 2>(Real(1), nan))));
}

TEST(core, plain_norm_fails_where_safe_norm_does_not) {
  // The reason safe_norm exists: in double the squares of 1e200 overflow and those of 1e-170 vanish.
  const cb::point<double, 2> big(3e200, 4e200), tiny(3e-170, 4e-170);
  EXPECT_FALSE(std::isfinite(big.norm()));
  EXPECT_EQ(tiny.norm(), 0.0);
  EXPECT_TRUE(cb::testing::within_ulps(cb::safe_norm(big), cb::real50("5e200"), 2.0));
  EXPECT_TRUE(cb::testing::within_ulps(cb::safe_norm(tiny), cb::real50("5e-170"), 2.0));
}

// validate::resolvable: a span must hold 2^(digits / 3) representable values around its ends.
TEST(core, unresolvable_spans_are_refused_with_their_values) {
  static_assert(cb::validate::min_span_bits<double>() == 17 && cb::validate::min_span_bits<float>() == 8);
  const double one_ulp = std::nextafter(1.0, 2.0);
  try {
    cb::validate::increasing<double>("knots", std::vector<double>{0.0, 1.0, one_ulp});
    FAIL() << "a span of one ulp was accepted";
  } catch (const cb::invalid_input& e) {
    EXPECT_THAT(e.what(), HasSubstr("knots[2] - knots[1] = 2.2204460492503131e-16"));
    EXPECT_THAT(e.what(), HasSubstr("too narrow"));
  }
  // 2^17 ulps of 1 is the smallest span accepted there; half of it is refused.
  const double need = std::ldexp(std::numeric_limits<double>::epsilon(), 17);
  EXPECT_NO_THROW(cb::validate::increasing<double>("knots", std::vector<double>{1.0 - need, 1.0}));
  EXPECT_THROW(cb::validate::increasing<double>("knots", std::vector<double>{1.0, 1.0 + need / 2}), cb::invalid_input);
  // float asks for 2^8 ulps: 400 equispaced nodes on [0, 1] (spacing 0.0025) are fine there.
  EXPECT_NO_THROW(cb::validate::increasing<float>("knots", std::vector<float>{0.3175f, 0.32f}));
  EXPECT_THROW(cb::validate::increasing<float>("knots", std::vector<float>{1.0f, 1.0f + 64 * FLT_EPSILON}),
               cb::invalid_input);
  // Far from 0 the same width is narrower in ulps: [1e9, 1e9 + 1] holds 2^23 doubles, [1e15, 1e15 + 1] only 8.
  EXPECT_NO_THROW(cb::validate::increasing<double>("knots", std::vector<double>{1e9, 1e9 + 1}));
  EXPECT_THROW(cb::validate::increasing<double>("knots", std::vector<double>{1e15, 1e15 + 1}), cb::invalid_input);
  // Tiny spans near 0 are resolvable (1e-300 holds many doubles); multiplicity (zero spans) is allowed.
  EXPECT_NO_THROW(cb::validate::increasing<double>("knots", std::vector<double>{0.0, 1e-300, 1.0}));
  EXPECT_NO_THROW(cb::validate::non_decreasing<double>("knots", std::vector<double>{0.0, 0.0, 1.0, 1.0}));
  EXPECT_THROW(cb::validate::non_decreasing<double>("knots", std::vector<double>{0.0, 1.0, one_ulp}),
               cb::invalid_input);
  // Below the smallest normal double the spacing is denorm_min: one subnormal ulp (or 2^16 of them)
  // is refused, 2^17 accepted, and the width needed is named.
  const double sub = std::numeric_limits<double>::denorm_min();
  EXPECT_THAT(cb::testing::message_of([&] {
                cb::validate::increasing<double>("knots", std::vector<double>{1e-310, 1e-310 + sub});
              }),
              HasSubstr("knots[1] - knots[0] = 4.9406564584124654e-324 is too narrow"));
  EXPECT_THROW(cb::validate::increasing<double>("knots", std::vector<double>{0.0, std::ldexp(sub, 16)}),
               cb::invalid_input);
  EXPECT_NO_THROW(cb::validate::increasing<double>("knots", std::vector<double>{0.0, std::ldexp(sub, 17)}));
  // real50 resolves the double data that double cannot: the check is per precision.
  EXPECT_NO_THROW(cb::validate::increasing<cb::real50>("knots", std::vector<cb::real50>{1, cb::real50(one_ulp)}));
}
