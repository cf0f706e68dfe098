// Quadrature: Gauss-Legendre rules computed in Real (closed forms for small n, exactness for
// degree <= 2n - 1, agreement of every Real with the real50 rule), our Gauss-Kronrod rules
// against Boost.Math's independently stored constants and by exactness to degree 3n + 1, the
// observed order of the composite rule, and the adaptive integrators: converged results whose
// estimate bounds the true error, caps and rounding limits reported in the status, bad input.
#include "support/accuracy.hpp"
#include "support/fixtures.hpp"

#include "curvebench/arclength/gauss_kronrod.hpp"
#include "curvebench/arclength/gauss_legendre.hpp"
#include "curvebench/basis/bernstein.hpp"

#include <gmock/gmock.h>
#include <boost/math/quadrature/gauss_kronrod.hpp>

#include <cmath>
#include <thread>
#include <vector>

namespace cb = curvebench;
namespace al = curvebench::arclength;
namespace cbt = curvebench::testing;
using ::testing::HasSubstr;

namespace {

// Tolerances:
// - a rule's node/weight vs the real50 rule of the same n: each node is a converged Newton root
//   (error ~1 ulp), each weight 2/((1-x^2)P'^2) carries ~2n roundings of the recurrence; 4n + 8
//   ulps relative covers n <= 64;
// - exactness sum w_i x_i^k vs 2/(k+1): n products and sums of terms <= 1: 4n + 8 ulps of scale 2;
// - real50 Kronrod rule vs Boost's 50-digit constants: 1e-45 absolute (Boost stores more digits
//   than real50 has; our construction loses a few digits in the linear solves);
// - IEEE Kronrod rules vs Boost's: 16 ulps of scale 1 (solve of a 15x15 system in Real);
// - composite order: the observed order log2(e_h / e_{h/2}) within 0.25 of 2n.
double rule_ulps(int n) { return 4.0 * n + 8; }
constexpr double kronrod_ieee_ulps = 16;
constexpr double composite_order_slack = 0.25;

template <class Real>
class quadrature_test : public ::testing::Test {};
TYPED_TEST_SUITE(quadrature_test, cbt::all_reals);

}  // namespace

TEST(quadrature, gauss_legendre_small_n_match_closed_forms) {
  using R = cb::real50;
  using std::sqrt;
  const auto& r1 = al::gauss_legendre<R>(1);
  EXPECT_EQ(r1.nodes[0], R(0));
  EXPECT_EQ(r1.weights[0], R(2));
  const auto& r2 = al::gauss_legendre<R>(2);
  EXPECT_TRUE(cbt::within_ulps(r2.nodes[1], 1 / sqrt(R(3)), 4));
  EXPECT_TRUE(cbt::within_ulps(r2.weights[0], R(1), 4));
  const auto& r3 = al::gauss_legendre<R>(3);
  EXPECT_EQ(r3.nodes[1], R(0));
  EXPECT_TRUE(cbt::within_ulps(r3.nodes[2], sqrt(R(3) / 5), 4));
  EXPECT_TRUE(cbt::within_ulps(r3.weights[1], R(8) / 9, 4));
  EXPECT_TRUE(cbt::within_ulps(r3.weights[2], R(5) / 9, 4));
  // n = 4: x = sqrt(3/7 -+ 2/7 sqrt(6/5)), w = (18 +- sqrt(30)) / 36
  const auto& r4 = al::gauss_legendre<R>(4);
  EXPECT_TRUE(cbt::within_ulps(r4.nodes[2], sqrt(R(3) / 7 - R(2) / 7 * sqrt(R(6) / 5)), 8));
  EXPECT_TRUE(cbt::within_ulps(r4.nodes[3], sqrt(R(3) / 7 + R(2) / 7 * sqrt(R(6) / 5)), 8));
  EXPECT_TRUE(cbt::within_ulps(r4.weights[2], (18 + sqrt(R(30))) / 36, 8));
  EXPECT_TRUE(cbt::within_ulps(r4.weights[3], (18 - sqrt(R(30))) / 36, 8));
  // n = 5: x = (1/3) sqrt(5 -+ 2 sqrt(10/7)), w = (322 +- 13 sqrt(70)) / 900, middle 128/225
  const auto& r5 = al::gauss_legendre<R>(5);
  EXPECT_TRUE(cbt::within_ulps(r5.nodes[3], sqrt(5 - 2 * sqrt(R(10) / 7)) / 3, 8));
  EXPECT_TRUE(cbt::within_ulps(r5.nodes[4], sqrt(5 + 2 * sqrt(R(10) / 7)) / 3, 8));
  EXPECT_TRUE(cbt::within_ulps(r5.weights[2], R(128) / 225, 8));
  EXPECT_TRUE(cbt::within_ulps(r5.weights[3], (322 + 13 * sqrt(R(70))) / 900, 8));
  EXPECT_TRUE(cbt::within_ulps(r5.weights[4], (322 - 13 * sqrt(R(70))) / 900, 8));
}

TYPED_TEST(quadrature_test, gauss_legendre_is_exact_to_degree_2n_minus_1) {
  using Real = TypeParam;
  for (int n : {1, 2, 3, 6, 11, 20, 33}) {
    const al::gauss_legendre_rule<Real>& r = al::gauss_legendre<Real>(n);
    ASSERT_EQ(r.nodes.size(), static_cast<std::size_t>(n));
    for (int k = 0; k <= 2 * n - 1; ++k) {
      Real sum(0);
      for (std::size_t i = 0; i < r.nodes.size(); ++i) sum += r.weights[i] * cb::basis::pow_int(r.nodes[i], k);
      const cb::real50 exact = k % 2 == 1 ? cb::real50(0) : cb::real50(2) / (k + 1);
      ASSERT_TRUE(cbt::within_scaled_ulps(sum, exact, cb::real50(2), rule_ulps(n))) << "n=" << n << " k=" << k;
    }
    for (std::size_t i = 0; i < r.nodes.size(); ++i) {  // ascending, symmetric, inside (-1, 1)
      EXPECT_EQ(r.nodes[i], -r.nodes[r.nodes.size() - 1 - i]);
      EXPECT_EQ(r.weights[i], r.weights[r.nodes.size() - 1 - i]);
      if (i > 0) {
        EXPECT_LT(r.nodes[i - 1], r.nodes[i]);
      }
      EXPECT_GT(r.weights[i], Real(0));
    }
  }
}

TYPED_TEST(quadrature_test, every_real_matches_the_real50_rule) {
  using Real = TypeParam;
  for (int n : {4, 16, 64}) {
    const auto& r = al::gauss_legendre<Real>(n);
    const auto& ref = al::gauss_legendre<cb::real50>(n);
    for (std::size_t i = 0; i < r.nodes.size(); ++i) {
      ASSERT_TRUE(cbt::within_scaled_ulps(r.nodes[i], ref.nodes[i], cb::real50(1), rule_ulps(n))) << n << " " << i;
      // A weight is sensitive to its node's rounding: d ln w / dx ~ -x / (1 - x^2), so half an ulp
      // of x moves w by ~0.5 / (1 - x^2) ulps near the ends; allowed on top of the rule's own error.
      const double sensitivity = 1.0 / static_cast<double>(1 - ref.nodes[i] * ref.nodes[i]);
      ASSERT_TRUE(cbt::within_ulps(r.weights[i], ref.weights[i], rule_ulps(n) + sensitivity)) << n << " " << i;
    }
  }
}

TYPED_TEST(quadrature_test, kronrod_is_exact_to_degree_3n_plus_1) {
  using Real = TypeParam;
  for (int n : {3, 7, 10, 15}) {
    const al::gauss_kronrod_rule<Real>& r = al::gauss_kronrod<Real>(n);
    ASSERT_EQ(r.nodes.size(), static_cast<std::size_t>(2 * n + 1));
    const int exact_degree = n % 2 == 1 ? 3 * n + 2 : 3 * n + 1;
    for (int k = 0; k <= exact_degree + 2; ++k) {
      Real sum(0), gsum(0);
      for (std::size_t i = 0; i < r.nodes.size(); ++i) {
        sum += r.kronrod_weights[i] * cb::basis::pow_int(r.nodes[i], k);
        gsum += r.gauss_weights[i] * cb::basis::pow_int(r.nodes[i], k);
      }
      const cb::real50 exact = k % 2 == 1 ? cb::real50(0) : cb::real50(2) / (k + 1);
      if (k <= exact_degree) {
        ASSERT_TRUE(cbt::within_scaled_ulps(sum, exact, cb::real50(2), rule_ulps(2 * n + 1)))
            << "n=" << n << " k=" << k;
      } else if (k % 2 == 0 && std::is_same_v<Real, cb::real50>) {
        // Not exact beyond: the rule is the Kronrod extension, not a higher Gauss rule (the defect
        // at degree 3n + 2 or 3n + 3 is far above 50-digit rounding for these n).
        EXPECT_GT(abs(cb::real50(sum) - exact), cb::real50("1e-40")) << "n=" << n << " k=" << k;
      }
      if (k <= 2 * n - 1) {
        ASSERT_TRUE(cbt::within_scaled_ulps(gsum, exact, cb::real50(2), rule_ulps(n))) << "gauss n=" << n << " k=" << k;
      }
    }
  }
}

TEST(quadrature, kronrod_15_matches_boost_stored_constants) {
  // Boost.Math stores the positive half (0 first) with ~100 digits, independent of our construction.
  {
    using R = cb::real50;
    const auto& r = al::gauss_kronrod<R>(7);
    const auto& bx = boost::math::quadrature::gauss_kronrod<R, 15>::abscissa();
    const auto& bw = boost::math::quadrature::gauss_kronrod<R, 15>::weights();
    for (std::size_t i = 0; i < bx.size(); ++i) {
      EXPECT_LT(abs(r.nodes[7 + i] - bx[i]), R("1e-45")) << i;
      EXPECT_LT(abs(r.kronrod_weights[7 + i] - bw[i]), R("1e-45")) << i;
    }
  }
  {
    const auto& r = al::gauss_kronrod<double>(7);
    const auto& bx = boost::math::quadrature::gauss_kronrod<double, 15>::abscissa();
    const auto& bw = boost::math::quadrature::gauss_kronrod<double, 15>::weights();
    for (std::size_t i = 0; i < bx.size(); ++i) {
      EXPECT_TRUE(cbt::within_scaled_ulps(r.nodes[7 + i], cb::real50(bx[i]), cb::real50(1), kronrod_ieee_ulps)) << i;
      EXPECT_TRUE(
          cbt::within_scaled_ulps(r.kronrod_weights[7 + i], cb::real50(bw[i]), cb::real50(1), kronrod_ieee_ulps));
    }
  }
  {  // G10-K21 as well
    using R = cb::real50;
    const auto& r = al::gauss_kronrod<R>(10);
    const auto& bx = boost::math::quadrature::gauss_kronrod<R, 21>::abscissa();
    const auto& bw = boost::math::quadrature::gauss_kronrod<R, 21>::weights();
    for (std::size_t i = 0; i < bx.size(); ++i) {
      EXPECT_LT(abs(r.nodes[10 + i] - bx[i]), R("1e-45")) << i;
      EXPECT_LT(abs(r.kronrod_weights[10 + i] - bw[i]), R("1e-45")) << i;
    }
  }
}

TEST(quadrature, composite_gauss_legendre_has_order_2n) {
  // f(x) = 1 / (1 + x^2) on [0, 2]: integral atan(2). In real50 so that rounding never hides the
  // truncation error; the observed order from m and 2m panels tends to 2n.
  using R = cb::real50;
  using std::log2;
  const R exact = atan(R(2));
  auto f = [](const R& x) { return 1 / (1 + x * x); };
  for (int n : {1, 2, 3, 4}) {
    const auto& rule = al::gauss_legendre<R>(n);
    const R e1 = abs(al::integrate_composite(f, R(0), R(2), 32, rule) - exact);
    const R e2 = abs(al::integrate_composite(f, R(0), R(2), 64, rule) - exact);
    const double order = static_cast<double>(log2(e1 / e2));
    EXPECT_NEAR(order, 2.0 * n, composite_order_slack) << "n=" << n;
  }
}

TYPED_TEST(quadrature_test, adaptive_estimate_bounds_true_error) {
  using Real = TypeParam;
  using std::sqrt;
  struct problem {
    const char* name;
    Real (*f)(const Real&);
    Real a, b;
    cb::real50 exact;
  };
  const std::vector<problem> problems{
      {"sqrt",
       [](const Real& x) {
         using std::sqrt;
         return sqrt(x);
       },
       Real(0), Real(1), cb::real50(2) / 3},
      {"kink",
       [](const Real& x) {
         using std::abs;
         return abs(x - Real(1) / Real(3));
       },
       Real(0), Real(1), cb::real50(5) / 18},
      {"runge", [](const Real& x) { return Real(1) / (Real(1) + Real(25) * x * x); }, Real(-1), Real(1),
       cb::real50(2) / 5 * atan(cb::real50(5))},
  };
  for (const auto& p : problems) {
    // 1e-3, and 1000 eps but not below 1e-24 (an endpoint singularity at 50 digits would need
    // bisection to 1e-94 in the recursive variant).
    using std::max;
    const Real tight = max(Real(1000) * cb::epsilon<Real>(), Real(1) / Real(1000000000000LL) / Real(1000000000000LL));
    for (const Real& tol : {Real(1) / Real(1000), tight}) {
      al::adaptive_options<Real> opt;
      opt.relative_tolerance = tol;
      const Real ends[2] = {p.a, p.b};
      const al::quadrature_result<Real> r = al::integrate_adaptive(p.f, std::span<const Real>(ends, 2), opt);
      EXPECT_TRUE(r.converged()) << p.name << " " << al::to_string(r.status);
      EXPECT_LE(abs(cb::real50(r.value) - p.exact), cb::real50(r.error_estimate)) << p.name;
      EXPECT_LE(r.error_estimate, tol * abs(r.value)) << p.name;
      EXPECT_GT(r.evaluations, 0u);
      const al::quadrature_result<Real> q =
          al::integrate_recursive(p.f, p.a, p.b, tol * abs(r.value), al::gauss_kronrod<Real>(7), 200);
      EXPECT_TRUE(q.converged()) << p.name;
      EXPECT_LE(abs(cb::real50(q.value) - p.exact), cb::real50(q.error_estimate)) << p.name;
    }
  }
}

TEST(quadrature, adaptive_reports_caps_rounding_limits_and_bad_input) {
  auto f = [](const double& x) { return std::sqrt(x); };
  const double ends[2] = {0.0, 1.0};
  al::adaptive_options<double> opt;
  opt.max_intervals = 3;
  const auto capped = al::integrate_adaptive(f, std::span<const double>(ends, 2), opt);
  EXPECT_EQ(capped.status, al::result_status::cap_hit);
  EXPECT_LE(std::abs(capped.value - 2.0 / 3.0), capped.error_estimate);  // still an honest bound
  opt = {};
  opt.relative_tolerance = 1e-20;  // below double's resolution
  const auto limited = al::integrate_adaptive(f, std::span<const double>(ends, 2), opt);
  EXPECT_EQ(limited.status, al::result_status::rounding_limited);
  EXPECT_LE(std::abs(limited.value - 2.0 / 3.0), limited.error_estimate);
  opt.relative_tolerance = 0;
  try {
    (void)al::integrate_adaptive(f, std::span<const double>(ends, 2), opt);
    FAIL();
  } catch (const cb::invalid_input& e) {
    EXPECT_STREQ(e.what(), "tolerance: absolute_tolerance = 0 and relative_tolerance = 0: at least one must be > 0");
  }
  opt.relative_tolerance = -1;
  EXPECT_THROW((void)al::integrate_adaptive(f, std::span<const double>(ends, 2), opt), cb::invalid_input);
  try {
    (void)al::gauss_legendre<double>(0);
    FAIL();
  } catch (const cb::invalid_input& e) {
    EXPECT_STREQ(e.what(), "n = 0: number of Gauss-Legendre points must be in [1, 100000]");
  }
  EXPECT_THROW((void)al::gauss_kronrod<double>(61), cb::invalid_input);
  const double rev[2] = {1.0, 0.0};
  EXPECT_THROW((void)al::integrate_adaptive(f, std::span<const double>(rev, 2), al::adaptive_options<double>{}),
               cb::invalid_input);
}

TEST(quadrature, adaptive_stops_at_the_rounding_of_a_noisy_integrand) {
  // f = 1 + 1e-9 h(x), h a deterministic hash in [-1, 1): rounding noise 1e-9 relative, as an
  // ill-conditioned evaluation produces (degree-20 Lagrange on equispaced nodes rounds its speed
  // to ~1e-12), far above the 50 eps floor the rules assume. At relative tolerance 1e-14 both
  // integrators stop with rounding_limited where bisection stagnates twice in a row (measured: 51
  // G7-K15 rules = 765 evaluations each). Before roundoff detection the recursive one bisected to
  // its depth cap (about 2^21 rules at depth 20: 31451445 evaluations, measured) and the global one
  // to max_intervals (119985); 2500 keeps a 3x margin and admits neither.
  auto f = [](const double& x) { return 1 + 1e-9 * cbt::unit_hash(x); };
  const double ends[2] = {0.0, 1.0};
  al::adaptive_options<double> opt;
  opt.relative_tolerance = 1e-14;
  const auto global = al::integrate_adaptive(f, std::span<const double>(ends, 2), opt);
  EXPECT_EQ(global.status, al::result_status::rounding_limited);
  EXPECT_LE(global.evaluations, 2500u) << "evaluations";
  EXPECT_NEAR(global.value, 1.0, 1e-9);     // the noise averages: good to its own level
  EXPECT_GT(global.error_estimate, 1e-14);  // and the estimate does not claim the tolerance
  const auto recursive = al::integrate_recursive(f, 0.0, 1.0, 1e-14, al::gauss_kronrod<double>(7), 20);
  EXPECT_EQ(recursive.status, al::result_status::rounding_limited);
  EXPECT_LE(recursive.evaluations, 2500u) << "evaluations";
  EXPECT_NEAR(recursive.value, 1.0, 1e-9);
  // A smooth integrand at 1e-13 (above its 50 eps floor) still converges: the detection needs
  // stagnation, which a resolved panel never shows.
  auto smooth = [](const double& x) { return std::exp(x); };
  const auto clean = al::integrate_recursive(smooth, 0.0, 4.0, 1e-13 * std::exp(4.0), al::gauss_kronrod<double>(7), 20);
  EXPECT_TRUE(clean.converged()) << al::to_string(clean.status);
}

TEST(quadrature, quadpack_model_is_sharper_but_still_bounds_smooth_integrands) {
  auto f = [](const double& x) { return std::exp(x) * std::cos(3 * x); };
  const double exact = (std::exp(2.0) * (std::cos(6.0) + 3 * std::sin(6.0)) - 1) / 10;  // integral on [0, 2]
  const auto& rule = al::gauss_kronrod<double>(7);
  const auto diff = rule.apply(f, 0.0, 2.0, al::error_model::gauss_difference);
  const auto qp = rule.apply(f, 0.0, 2.0, al::error_model::quadpack);
  EXPECT_EQ(diff.kronrod, qp.kronrod);
  EXPECT_LE(qp.error_estimate, diff.error_estimate);
  EXPECT_LE(std::abs(qp.kronrod - exact), qp.error_estimate);
}

TEST(quadrature, rule_cache_is_shared_and_thread_safe) {
  std::vector<const al::gauss_kronrod_rule<double>*> seen(8, nullptr);
  std::vector<std::thread> threads;
  for (std::size_t t = 0; t < seen.size(); ++t)
    threads.emplace_back([&seen, t] { seen[t] = &al::gauss_kronrod<double>(12); });
  for (auto& th : threads) th.join();
  for (const auto* p : seen) EXPECT_EQ(p, seen[0]);
  EXPECT_EQ(&al::gauss_legendre<double>(200), &al::gauss_legendre<double>(200));  // beyond the lock-free range
}
