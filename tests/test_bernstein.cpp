// Bernstein basis: closed form and recursion against exact rational values computed in real50,
// partition of unity, symmetry, non-negativity and the derivative formula.
#include "support/accuracy.hpp"

#include "curvebench/basis/bernstein.hpp"

#include <array>
#include <vector>

namespace cb = curvebench;
namespace cbt = curvebench::testing;

namespace {

// Tolerances, in eps(Real) (ulps relative to 1, since every B_i^n(t) <= 1 on [0, 1]):
// - the recursion is n levels of convex combinations: each value carries at most ~n roundings
//   of magnitude <= its own size, so 2n ulps of scale 1 is a safe bound up to n = 30;
// - the closed form multiplies C(n,i), t^i and (1-t)^(n-i): ~2 log2(n) + 3 roundings, each
//   relative, plus 1 - t rounded once (relative error of (1-t)^(n-i) grows as (n-i) ulps);
//   so n + 8 ulps relative to the value;
// - partition of unity: a sum of n + 1 values each within 2n ulps: (n + 1) * 2n.
constexpr int max_degree = 30;
double recursion_ulps(int n) { return 2.0 * n + 2; }
double closed_form_ulps(int n) { return n + 8.0; }

template <class Real>
class bernstein_test : public ::testing::Test {};
TYPED_TEST_SUITE(bernstein_test, cbt::all_reals);

// Parameters exactly representable in every type, so the real50 closed form is the exact value
// of B_i^n at the same t (up to 50-digit rounding).
const std::array<double, 7> exact_ts{0.0, 0.125, 0.25, 0.3125, 0.5, 0.71875, 1.0};

}  // namespace

TYPED_TEST(bernstein_test, closed_form_and_recursion_match_reference) {
  using Real = TypeParam;
  for (int n = 0; n <= max_degree; ++n) {
    std::vector<Real> all(static_cast<std::size_t>(n) + 1);
    for (double td : exact_ts) {
      const auto t = static_cast<Real>(td);
      cb::basis::bernstein_all(n, t, std::span<Real>(all));
      for (int i = 0; i <= n; ++i) {
        const cb::real50 ref = cb::basis::bernstein(n, i, cb::real50(td));
        const Real closed = cb::basis::bernstein(n, i, t);
        ASSERT_TRUE(cbt::within_ulps(closed, ref, closed_form_ulps(n))) << "n=" << n << " i=" << i << " t=" << td;
        ASSERT_TRUE(cbt::within_scaled_ulps(all[static_cast<std::size_t>(i)], ref, cb::real50(1), recursion_ulps(n)))
            << "n=" << n << " i=" << i << " t=" << td;
      }
    }
  }
}

TYPED_TEST(bernstein_test, partition_of_unity_symmetry_nonnegativity) {
  using Real = TypeParam;
  for (int n = 1; n <= max_degree; ++n) {
    std::vector<Real> all(static_cast<std::size_t>(n) + 1);
    for (int k = 0; k <= 64; ++k) {
      const Real t = Real(k) / Real(64);
      cb::basis::bernstein_all(n, t, std::span<Real>(all));
      Real sum(0);
      for (const Real& b : all) {
        ASSERT_GE(b, Real(0));  // non-negative on [0, 1]
        sum += b;
      }
      ASSERT_TRUE(cbt::within_ulps(sum, cb::real50(1), (n + 1) * recursion_ulps(n))) << "n=" << n;
      // Reversal symmetry B_i^n(t) = B_{n-i}^n(1-t). With 1 - t exact (k/64 is), both sides multiply
      // the same three rounded factors C, t^i, (1-t)^(n-i) in another order: <= 2 roundings each,
      // so they agree to 4 ulps relative (products are not associative, so not bit for bit).
      for (int i = 0; i <= n; ++i)
        ASSERT_TRUE(cbt::within_ulps(cb::basis::bernstein(n, i, t),
                                     cb::real50(cb::basis::bernstein(n, n - i, Real(1) - t)), 4));
    }
  }
}

TYPED_TEST(bernstein_test, derivative_matches_reference_difference_formula) {
  using Real = TypeParam;
  // d/dt B_i^n = n (B_{i-1}^{n-1} - B_i^{n-1}): an independent expression of the first derivative
  // in 50 digits. The general-order code sums order+1 closed forms with binomial weights; its
  // error relative to the largest term is ~ 2^order (n + 8) ulps.
  for (int n = 1; n <= 12; ++n)
    for (double td : exact_ts)
      for (int i = 0; i <= n; ++i) {
        const cb::real50 t50(td);
        const cb::real50 ref =
            cb::real50(n) * (cb::basis::bernstein(n - 1, i - 1, t50) - cb::basis::bernstein(n - 1, i, t50));
        const Real got = cb::basis::bernstein_derivative(n, i, Real(td), 1);
        ASSERT_TRUE(cbt::within_scaled_ulps(got, ref, cb::real50(2 * n), 2.0 * (n + 8))) << n << " " << i << " " << td;
      }
  // Order > n vanishes; order n is the constant n! (-1)^(n-i) C(n, i).
  EXPECT_EQ(cb::basis::bernstein_derivative(3, 1, Real(0.4), 4), Real(0));
  EXPECT_EQ(cb::basis::bernstein_derivative(3, 1, Real(0.4), 3), Real(18));  // 3! * (+1) * C(3,1)
}

TEST(bernstein, bad_input) {
  std::vector<double> out(3);
  EXPECT_THROW(cb::basis::bernstein_all(3, 0.5, std::span<double>(out)), cb::invalid_input);
  EXPECT_THROW((void)cb::basis::bernstein(-1, 0, 0.5), cb::invalid_input);
  EXPECT_THROW((void)cb::basis::bernstein_derivative(3, 0, 0.5, -1), cb::invalid_input);
}
