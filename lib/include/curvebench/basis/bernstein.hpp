// Bernstein polynomials B_i^n(t) = C(n, i) t^i (1 - t)^(n - i), the basis of Bezier curves.
//
// Source: seed 000 (CS 174C week 3), seed 002; Farin, "Curves and Surfaces for CAGD", ch. 5.
// Two evaluations, kept side by side so the test-bench can compare them:
//   - `bernstein(n, i, t)`: the closed form, O(n) multiplications for one function;
//   - `bernstein_all(n, t, out)`: all n + 1 values by the recursion
//       B_i^n = (1 - t) B_i^{n-1} + t B_{i-1}^{n-1},  B_0^0 = 1,
//     O(n^2), every step a convex combination for t in [0, 1], hence backward stable; no allocation.
// Both sum to 1 (partition of unity); the recursion does so to within a few ulps for any n.
// Derivative: d/dt B_i^n = n (B_{i-1}^{n-1} - B_i^{n-1}).
#pragma once

#include "curvebench/core/error.hpp"
#include "curvebench/core/real.hpp"

#include <cstddef>
#include <span>
#include <string>

namespace curvebench::basis {

/// x^k for a non-negative integer k by repeated squaring (exact for the small integer cases).
template <class Real>
[[nodiscard]] Real pow_int(const Real& x, int k) {
  Real result(1);
  Real base = x;
  while (k > 0) {
    if (k & 1) result *= base;
    base *= base;
    k >>= 1;
  }
  return result;
}

/// The closed form C(n, i) t^i (1 - t)^(n - i); zero for i outside [0, n].
template <class Real>
[[nodiscard]] Real bernstein(int n, int i, const Real& t) {
  if (n < 0) validate::fail("n = " + std::to_string(n) + ": degree must be >= 0");
  if (i < 0 || i > n) return Real(0);
  return binomial<Real>(n, i) * pow_int(t, i) * pow_int(Real(1) - t, n - i);
}

/// All B_0^n .. B_n^n at t by the recursion, written into out (size n + 1).
template <class Real>
void bernstein_all(int n, const Real& t, std::span<Real> out) {
  if (n < 0) validate::fail("n = " + std::to_string(n) + ": degree must be >= 0");
  if (out.size() != static_cast<std::size_t>(n) + 1)
    validate::fail("out: size " + std::to_string(out.size()) + ", must be n + 1 = " + std::to_string(n + 1));
  const Real s = Real(1) - t;
  out[0] = Real(1);
  for (int k = 1; k <= n; ++k) {
    const auto uk = static_cast<std::size_t>(k);
    out[uk] = t * out[uk - 1];
    for (std::size_t i = uk - 1; i >= 1; --i) out[i] = s * out[i] + t * out[i - 1];
    out[0] = s * out[0];
  }
}

/// d^order/dt^order B_i^n(t) by the closed form of the derivative of the basis:
/// n!/(n-order)! * sum_j (-1)^(order-j) C(order, j) B_{i-j}^{n-order}(t).
template <class Real>
[[nodiscard]] Real bernstein_derivative(int n, int i, const Real& t, int order) {
  validate::derivative_order(order);
  if (order > n) return Real(0);
  Real falling(1);
  for (int j = 0; j < order; ++j) falling *= Real(n - j);
  Real sum(0);
  for (int j = 0; j <= order; ++j) {
    const Real term = binomial<Real>(order, j) * bernstein(n - order, i - j, t);
    sum += ((order - j) % 2 == 0) ? term : Real(-term);
  }
  return falling * sum;
}

}  // namespace curvebench::basis
