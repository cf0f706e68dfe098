// CSS easing functions (channel/css_easing.hpp): the keywords' definitions, Chromium's published
// cubic-bezier tables at their tolerance, the spec's extrapolation outside [0, 1], steps() and
// linear() by the spec's algorithms and examples, cubic-bezier against the real50 exact solver,
// and the parser's errors.
#include "support/accuracy.hpp"
#include "support/fixtures.hpp"

#include "curvebench/channel/css_easing.hpp"
#include "curvebench/reference/multiprecision.hpp"

#include <gmock/gmock.h>

#include <cmath>
#include <string>
#include <utility>
#include <vector>

namespace cb = curvebench;
namespace ch = curvebench::channel;
namespace cbt = curvebench::testing;
using cb::real50;
using ::testing::HasSubstr;

namespace {

template <class Real>
class css_easing_test : public ::testing::Test {};
using float_double = ::testing::Types<float, double>;
TYPED_TEST_SUITE(css_easing_test, float_double);

// Chromium's published values (ui/gfx/geometry/cubic_bezier_unittest.cc, tests Basic and
// UnclampedYValues), 5 decimals, checked there at 1.5e-4: pairs (input, output).
const std::vector<std::pair<double, double>> chromium_basic{
    {0, 0},          {0.05, 0.01136}, {0.1, 0.03978},  {0.15, 0.079780}, {0.2, 0.12803},
    {0.25, 0.18235}, {0.3, 0.24115},  {0.35, 0.30323}, {0.4, 0.36761},   {0.45, 0.43345},
    {0.5, 0.5},      {0.6, 0.63238},  {0.65, 0.69676}, {0.7, 0.75884},   {0.75, 0.81764},
    {0.8, 0.87196},  {0.85, 0.92021}, {0.9, 0.96021},  {0.95, 0.98863},  {1, 1}};
const std::vector<std::pair<double, double>> chromium_unclamped{
    {0.0, 0.0},      {0.05, -0.08954}, {0.1, -0.15613}, {0.15, -0.19641}, {0.2, -0.20651}, {0.25, -0.18232},
    {0.3, -0.11992}, {0.35, -0.01672}, {0.4, 0.12660},  {0.45, 0.30349},  {0.5, 0.50000},  {0.55, 0.69651},
    {0.6, 0.87340},  {0.65, 1.01672},  {0.7, 1.11992},  {0.75, 1.18232},  {0.8, 1.20651},  {0.85, 1.19641},
    {0.9, 1.15613},  {0.95, 1.08954},  {1.0, 1.0}};
constexpr double chromium_tolerance = 1.5e-4;

}  // namespace

// Every solver but bisection12 meets Chromium's tolerance: bisection12 leaves u within 2^-13, so
// the output within 3 * 2^-13 * (value range 3 for y in [-1, 2]) = 1.1e-3 > 1.5e-4 (derived), and
// it is checked at that bound instead.
TYPED_TEST(css_easing_test, chromium_tables) {
  using Real = TypeParam;
  for (ch::time_solver solver : ch::all_time_solvers) {
    const auto basic = ch::css_easing<Real>::cubic_bezier(Real(0.25), Real(0), Real(0.75), Real(1), solver);
    const auto unclamped = ch::css_easing<Real>::cubic_bezier(Real(0.5), Real(-1), Real(0.5), Real(2), solver);
    const double tol_basic = solver == ch::time_solver::bisection12 ? 3 * 0x1p-13 : chromium_tolerance;
    const double tol_unclamped = solver == ch::time_solver::bisection12 ? 9 * 0x1p-13 : chromium_tolerance;
    for (const auto& [x, y] : chromium_basic)
      EXPECT_NEAR(static_cast<double>(basic(Real(x))), y, tol_basic) << ch::to_string(solver) << " x=" << x;
    for (const auto& [x, y] : chromium_unclamped)
      EXPECT_NEAR(static_cast<double>(unclamped(Real(x))), y, tol_unclamped) << ch::to_string(solver) << " x=" << x;
  }
}

// Chromium's exact checks at x = 0.5 of symmetric curves: u = 1/2 there and y = 3/4 y1 + 1/8
// (y1 = y2), exact in binary: 0.875, 1.625, -0.625. The solvers that converge to rounding level
// land on u = 1/2 within an ulp, so y within 4 ulps (|y'| <= 3 max|y_i|).
TYPED_TEST(css_easing_test, chromium_symmetric_values) {
  using Real = TypeParam;
  for (ch::time_solver solver : {ch::time_solver::curvebench, ch::time_solver::exact, ch::time_solver::isolate_brent,
                                 ch::time_solver::closed_form}) {
    EXPECT_TRUE(
        cbt::within_ulps(ch::css_easing<Real>::cubic_bezier(Real(0.5), Real(1), Real(0.5), Real(1), solver)(Real(0.5)),
                         real50(0.875), 4));
    EXPECT_TRUE(
        cbt::within_ulps(ch::css_easing<Real>::cubic_bezier(Real(0.5), Real(2), Real(0.5), Real(2), solver)(Real(0.5)),
                         real50(1.625), 4));
    EXPECT_TRUE(cbt::within_ulps(
        ch::css_easing<Real>::cubic_bezier(Real(0.5), Real(-1), Real(0.5), Real(-1), solver)(Real(0.5)), real50(-0.625),
        4));
  }
}

// Outside [0, 1], the spec's tangent lines. Values that Chromium's InputOutOfRange test publishes
// and the spec agrees with, then the three where Chromium departs from the spec text (it treats
// handles coinciding with an end as the chord P0P3, per w3c/csswg-drafts issue 4046).
TYPED_TEST(css_easing_test, extrapolation_by_the_spec) {
  using Real = TypeParam;
  const auto e = [](double x1, double y1, double x2, double y2) {
    return ch::css_easing<Real>::cubic_bezier(Real(x1), Real(y1), Real(x2), Real(y2));
  };
  EXPECT_EQ(e(0.5, 1, 0.5, 1)(Real(-1)), Real(-2));
  EXPECT_EQ(e(0.5, 1, 0.5, 1)(Real(2)), Real(1));
  EXPECT_EQ(e(0, 0, 1, 1)(Real(-1)), Real(-1));
  EXPECT_EQ(e(0, 0, 1, 1)(Real(2)), Real(2));
  EXPECT_EQ(e(0, 1, 1, 0)(Real(-1)), Real(0));
  EXPECT_EQ(e(0, 1, 1, 0)(Real(2)), Real(1));
  EXPECT_EQ(e(0.5, 0, 1, 0.5)(Real(-1)), Real(0));
  EXPECT_NEAR(static_cast<double>(e(0.1, 0.2, 0.8, 0.8)(Real(-1))), -2.0, 4 * std::numeric_limits<Real>::epsilon());
  EXPECT_NEAR(static_cast<double>(e(0.1, 0.2, 0.8, 0.8)(Real(2))), 2.0, 4 * std::numeric_limits<Real>::epsilon());
  EXPECT_EQ(e(0, 0, 0.5, 1)(Real(-1)), Real(-2));
  EXPECT_EQ(e(0, 0, 0.5, 1)(Real(2)), Real(1));
  EXPECT_EQ(e(1, 0.5, 1, 1)(Real(-1)), Real(-0.5));
  EXPECT_EQ(e(1, 0.5, 1, 1)(Real(2)), Real(1));
  EXPECT_EQ(e(0, 0, 0, 0)(Real(2)), Real(2));
  EXPECT_EQ(e(1, 1, 1, 1)(Real(-1)), Real(-1));
  // Spec text, not Chromium: both handles at P0 -> output 0 below 0 (Chromium: -1); both at P3 ->
  // 1 above 1 (Chromium: 2); x2 = 1 but x1 < 1 -> the line P1P3, slope (1 - 0) / (1 - 0.5) = 2
  // (Chromium: 1).
  EXPECT_EQ(e(0, 0, 0, 0)(Real(-1)), Real(0));
  EXPECT_EQ(e(1, 1, 1, 1)(Real(2)), Real(1));
  EXPECT_EQ(e(0.5, 0, 1, 0.5)(Real(2)), Real(3));
}

// The keywords are their definitions (the same control points, hence the same outputs).
TYPED_TEST(css_easing_test, keywords_are_their_definitions) {
  using Real = TypeParam;
  const std::vector<std::pair<std::string, std::string>> defs{{"ease", "cubic-bezier(0.25, 0.1, 0.25, 1)"},
                                                              {"ease-in", "cubic-bezier(0.42, 0, 1, 1)"},
                                                              {"ease-out", "cubic-bezier(0, 0, 0.58, 1)"},
                                                              {"ease-in-out", "cubic-bezier(0.42, 0, 0.58, 1)"},
                                                              {"step-start", "steps(1, jump-start)"},
                                                              {"step-end", "steps(1, jump-end)"},
                                                              {"linear", "linear(0, 1)"},
                                                              {"EASE-IN", "Cubic-Bezier(0.42,0,1,1)"}};
  for (const auto& [keyword, definition] : defs) {
    const auto k = ch::parse_css_easing<Real>(keyword);
    const auto d = ch::parse_css_easing<Real>(definition);
    EXPECT_EQ(k.type(), d.type()) << keyword;
    for (int i = -4; i <= 24; ++i) {
      const Real x = Real(i) / Real(20);
      EXPECT_EQ(k(x), d(x)) << keyword << " x=" << x;
    }
  }
  EXPECT_EQ(ch::parse_css_easing<Real>("ease").control()[1], Real(0.1));
  EXPECT_EQ(ch::parse_css_easing<Real>("linear")(Real(-3.5)), Real(-3.5));  // the identity everywhere
  EXPECT_EQ(ch::parse_css_easing<Real>("linear")(Real(7)), Real(7));
}

// steps() by the spec's algorithm: floor(x n), +1 for jump-start / jump-both, clamped to
// [0, jumps] inside [0, 1], divided by jumps (n, n, n - 1, n + 1).
TYPED_TEST(css_easing_test, steps_by_the_spec) {
  using Real = TypeParam;
  const auto s = [](long long n, ch::step_position p, double x) {
    return static_cast<double>(ch::css_easing<Real>::steps(n, p)(Real(x)));
  };
  using P = ch::step_position;
  EXPECT_EQ(s(4, P::jump_end, 0), 0);
  EXPECT_EQ(s(4, P::jump_end, 0.24), 0);
  EXPECT_EQ(s(4, P::jump_end, 0.25), 0.25);
  EXPECT_EQ(s(4, P::jump_end, 0.99), 0.75);
  EXPECT_EQ(s(4, P::jump_end, 1), 1);
  EXPECT_EQ(s(4, P::jump_start, 0), 0.25);
  EXPECT_EQ(s(4, P::jump_start, 0.75), 1);
  EXPECT_EQ(s(4, P::jump_start, 1), 1);  // floor(4) + 1 = 5, clamped to 4 jumps
  EXPECT_EQ(s(4, P::jump_none, 0), 0);
  EXPECT_EQ(s(4, P::jump_none, 0.25), static_cast<double>(Real(1) / Real(3)));
  EXPECT_EQ(s(4, P::jump_none, 0.8), 1);
  EXPECT_EQ(s(4, P::jump_none, 1), 1);
  EXPECT_EQ(s(4, P::jump_both, 0), static_cast<double>(Real(1) / Real(5)));
  EXPECT_EQ(s(4, P::jump_both, 0.99), static_cast<double>(Real(4) / Real(5)));
  EXPECT_EQ(s(4, P::jump_both, 1), 1);
  // Outside [0, 1] the steps continue (no clamping there): floor(-0.4) = -1 -> -1/4.
  EXPECT_EQ(s(4, P::jump_end, -0.1), -0.25);
  EXPECT_EQ(s(4, P::jump_end, 1.5), 1.5);
  // step-start and step-end; the before flag is not modelled, so step-start(0) = 1.
  EXPECT_EQ(static_cast<double>(ch::parse_css_easing<Real>("step-start")(Real(0))), 1);
  EXPECT_EQ(static_cast<double>(ch::parse_css_easing<Real>("step-end")(Real(0.999))), 0);
  EXPECT_EQ(ch::parse_css_easing<Real>("steps(3, start)")(Real(0.5)), Real(2) / Real(3));  // floor(1.5) + 1 = 2
  EXPECT_EQ(ch::parse_css_easing<Real>("steps(3, end)").position(), P::jump_end);
  EXPECT_EQ(ch::parse_css_easing<Real>("steps(3)").position(), P::jump_end);
}

// linear(): the spec's examples and its position rules.
TYPED_TEST(css_easing_test, linear_by_the_spec) {
  using Real = TypeParam;
  const auto f = [](const char* text, double x) {
    return static_cast<double>(ch::parse_css_easing<Real>(text)(Real(x)));
  };
  // linear(0, 0.25, 1): 0.25 at 50%.
  EXPECT_EQ(f("linear(0, 0.25, 1)", 0.5), 0.25);
  EXPECT_EQ(f("linear(0, 0.25, 1)", 0.25), 0.125);
  EXPECT_EQ(f("linear(0, 0.25, 1)", 0.75), 0.625);
  // linear(0, 0.25 75%, 1): 0.25 at 75%.
  EXPECT_EQ(f("linear(0, 0.25 75%, 1)", 0.75), 0.25);
  EXPECT_NEAR(f("linear(0, 0.25 75%, 1)", 0.375), 0.125, 1e-7);
  // linear(0, 0.5 25% 75%, 1): held at 0.5 from 25% to 75%.
  EXPECT_EQ(f("linear(0, 0.5 25% 75%, 1)", 0.25), 0.5);
  EXPECT_EQ(f("linear(0, 0.5 25% 75%, 1)", 0.6), 0.5);
  EXPECT_EQ(f("linear(0, 0.5 25% 75%, 1)", 0.875), 0.75);
  // Runs without positions are spread evenly: 0.1 at 25%, 0.6 at 75%.
  const auto run = ch::parse_css_easing<Real>("linear(0, 0.1, 0.2 50%, 0.6, 1)");
  ASSERT_EQ(run.points().size(), 5u);
  EXPECT_EQ(run.points()[1].input, Real(0.25));
  EXPECT_EQ(run.points()[3].input, Real(0.75));
  // A position below an earlier one is raised to it; at the shared input the later point wins.
  const auto raised = ch::parse_css_easing<Real>("linear(0, 1 80%, 0.5 20%, 1)");
  EXPECT_EQ(raised.points()[2].input, raised.points()[1].input);
  EXPECT_EQ(static_cast<double>(raised(Real(0.8))), 0.5);
  // The last stop without a position sits at max(1, the largest so far).
  EXPECT_NEAR(static_cast<double>(ch::parse_css_easing<Real>("linear(0, 0.5 120%, 1)").points()[2].input), 1.2, 1e-7);
  // Extrapolation by the first two and the last two points.
  EXPECT_EQ(f("linear(0, 0.25, 1)", -1), -0.5);
  EXPECT_EQ(f("linear(0, 0.25, 1)", 2), 2.5);
  EXPECT_EQ(f("linear(0.5, 0.5)", 3), 0.5);
}

// cubic-bezier with the curvebench solver against the same easing at real50 with the exact
// solver: within 4 ulps of the output range (the time solver's goal; y's range here is [0, 1]).
TYPED_TEST(css_easing_test, cubic_bezier_against_real50) {
  using Real = TypeParam;
  for (const char* text : {"ease", "ease-in-out", "cubic-bezier(0, 4, 1, -3)", "cubic-bezier(0.3, 1.5, 0.7, -0.5)"}) {
    const auto e = ch::parse_css_easing<Real>(text);
    const auto c = e.control();
    const auto r = ch::css_easing<real50>::cubic_bezier(real50(c[0]), real50(c[1]), real50(c[2]), real50(c[3]),
                                                        ch::time_solver::exact);
    using std::max;
    using std::min;
    const real50 range = max({real50(1), real50(c[1]), real50(c[3])}) - min({real50(0), real50(c[1]), real50(c[3])});
    for (int i = 0; i <= 200; ++i) {
      const Real x = Real(i) / Real(200);
      EXPECT_TRUE(cbt::within_scaled_ulps(e(x), r(real50(x)), range, 4)) << text << " x=" << x;
    }
  }
}

TEST(css_easing, solver_is_chosen_by_the_caller) {
  const auto e = ch::parse_css_easing<double>("cubic-bezier(0.25, 0.1, 0.25, 1)", ch::time_solver::table_newton);
  EXPECT_EQ(e.solver(), ch::time_solver::table_newton);
  EXPECT_EQ(ch::parse_css_easing<double>("ease", ch::time_solver::bisection30).solver(), ch::time_solver::bisection30);
  // Different schemes give (slightly) different outputs: table_newton stops at a 1e-7 residual.
  const auto exact = ch::parse_css_easing<double>("cubic-bezier(0.25, 0.1, 0.25, 1)", ch::time_solver::exact);
  EXPECT_NEAR(e(0.3), exact(0.3), 1e-6);
}

TEST(css_easing, real50_keywords_are_exact_decimals) {
  // "0.1" read as real50 text, not as double's 0.1.
  EXPECT_EQ(ch::parse_css_easing<real50>("ease").control()[1], real50("0.1"));
}

// ---------------------------------------------------------------------------------------------
// Errors name the function, the argument and the value.

TEST(css_easing, bad_arguments) {
  const auto msg = [](const char* text) { return cbt::message_of([&] { (void)ch::parse_css_easing<double>(text); }); };
  EXPECT_THAT(msg("cubic-bezier(1.5, 0, 0.5, 1)"), HasSubstr("cubic-bezier argument 1 (x1) = 1.5: must be in [0, 1]"));
  EXPECT_THAT(msg("cubic-bezier(0.5, 0, -0.25, 1)"),
              HasSubstr("cubic-bezier argument 3 (x2) = -0.25: must be in [0, 1]"));
  EXPECT_THAT(msg("cubic-bezier(0.25, 0.1, abc, 1)"),
              HasSubstr("cubic-bezier argument 3: expected a number, got 'abc'"));
  EXPECT_THAT(msg("cubic-bezier(0.25, 1e999, 0.25, 1)"),
              HasSubstr("cubic-bezier argument 2 = 1e999: not representable"));
  EXPECT_THAT(msg("cubic-bezier(0, 0, 1)"), HasSubstr("expected ','"));
  EXPECT_THAT(msg("cubic-bezier(0, 0, 1, 1"), HasSubstr("expected ')'"));
  EXPECT_THAT(msg("cubic-bezier(0, 0, 1, 1, 1)"), HasSubstr("expected ')'"));
  EXPECT_THAT(msg("cubic-bezier"), HasSubstr("needs its arguments in parentheses"));
  EXPECT_THAT(msg("steps(0)"), HasSubstr("steps argument 1 (n) = 0: must be >= 1"));
  EXPECT_THAT(msg("steps(1, jump-none)"), HasSubstr("steps argument 1 (n) = 1: jump-none needs n >= 2"));
  EXPECT_THAT(msg("steps(2.5)"), HasSubstr("steps argument 1: expected an integer, got '2.5'"));
  EXPECT_THAT(msg("steps(2, middle)"), HasSubstr("steps argument 2: expected jump-start"));
  EXPECT_THAT(msg("steps(2, middle)"), HasSubstr("got 'middle'"));
  EXPECT_THAT(msg("linear(0)"), HasSubstr("linear() stops: 1 given, at least 2 required"));
  EXPECT_THAT(msg("linear(0, 0.5 50, 1)"), HasSubstr("linear argument 2: a position must be a percentage, got '50'"));
  EXPECT_THAT(msg("linear(0, x, 1)"), HasSubstr("linear argument 2: expected a number, got 'x'"));
  EXPECT_THAT(msg("bounce(1)"), HasSubstr("unknown easing function 'bounce'"));
  EXPECT_THAT(msg("ease-sideways"), HasSubstr("css easing keyword \"ease-sideways\": unknown"));
  EXPECT_THAT(msg("ease junk"), HasSubstr("unexpected text after the easing: 'junk'"));
  EXPECT_THAT(msg("steps(2) x"), HasSubstr("unexpected text after the easing: 'x' at offset 9"));
  EXPECT_THAT(msg(""), HasSubstr("expected an easing keyword or function, got the end"));
  // The user's text is echoed visible and bounded: a NUL cut the message short, an invisible
  // character hid the cause, and a long text was echoed whole.
  EXPECT_THAT(cbt::message_of([] { (void)ch::parse_css_easing<double>(std::string("ease\0junk", 9)); }),
              HasSubstr("ease\\x00junk"));
  EXPECT_THAT(msg("ease\xe2\x80\x8b"), HasSubstr("\\xe2\\x80\\x8b"));
  EXPECT_LT(msg(("linear(0, " + std::string(100000, '5') + " x, 1)").c_str()).size(), 400u);
  EXPECT_THROW((void)ch::parse_css_easing<double>("steps(0)"), cb::invalid_input);
}

TEST(css_easing, bad_values_through_the_api) {
  const auto msg = [](auto f) { return cbt::message_of(f); };
  EXPECT_THAT(msg([] { (void)ch::css_easing<double>::cubic_bezier(0.5, std::nan(""), 0.5, 1); }),
              HasSubstr("cubic-bezier argument 2 (y1) = nan: must be finite"));
  EXPECT_THAT(msg([] { (void)ch::css_easing<double>::steps(-3); }),
              HasSubstr("steps argument 1 (n) = -3: must be >= 1"));
  const std::vector<ch::linear_stop<double>> stops{{0, std::nullopt, std::nullopt}, {1, std::nullopt, 0.5}};
  EXPECT_THAT(msg([&] { (void)ch::css_easing<double>::linear(stops); }),
              HasSubstr("linear argument 2: a second position needs a first"));
  const auto e = ch::css_easing<double>::identity();
  EXPECT_THROW((void)e(std::nan("")), std::domain_error);
  EXPECT_THAT(msg([&] { (void)e(INFINITY); }), HasSubstr("input progress = inf: must be finite"));
}
