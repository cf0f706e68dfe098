// Private mechanics of the Bezier family (bezier.hpp, rational_bezier.hpp, composite_bezier.hpp):
// the three evaluation kernels over a span of control values, written once for points and for
// scalars (the weights of a rational curve), and the conversion to the power basis.
//
// No kernel allocates: the de Casteljau triangle and the powers of (1 - t) live in a stack buffer
// of bezier_max_degree + 1 entries, which is why the family rejects degrees above that bound.
#pragma once

#include "curvebench/core/real.hpp"

#include <array>
#include <cstddef>
#include <span>
#include <vector>

namespace curvebench {

/// Largest degree a Bezier curve of curvebench accepts. Evaluation uses a stack buffer of this
/// many + 1 entries (no allocation, thread-safe), and binomial coefficients up to this order are
/// exact 64-bit integers. In floating point a single segment of higher degree is of no practical
/// use (its power-basis form has lost every digit long before, see tests/test_bezier.cpp).
inline constexpr int bezier_max_degree = 60;

namespace detail::bezier_kernels {

/// de Casteljau's algorithm: n levels of convex combinations (1 - t) b_i + t b_{i+1}.
/// O(n^2) operations, backward stable for t in [0, 1]. `p` holds n + 1 values, n <= bezier_max_degree.
template <class Vec, class Real>
[[nodiscard]] Vec de_casteljau(std::span<const Vec> p, const Real& t) {
  const std::size_t n = p.size() - 1;
  if (n == 0) return p[0];
  const Real s = Real(1) - t;
  std::array<Vec, bezier_max_degree> b;
  for (std::size_t i = 0; i < n; ++i) b[i] = s * p[i] + t * p[i + 1];
  for (std::size_t m = n - 1; m >= 1; --m)
    for (std::size_t i = 0; i < m; ++i) b[i] = s * b[i] + t * b[i + 1];
  return b[0];
}

/// The direct Bernstein sum sum_i C(n, i) t^i (1 - t)^(n - i) p_i, with the binomials given
/// (`binom` holds C(n, 0..n)) and the powers of t and 1 - t built incrementally: O(n) operations.
/// Every weight is non-negative for t in [0, 1], so the error is ~ n ulps of the control scale.
template <class Vec, class Real>
[[nodiscard]] Vec bernstein_sum(std::span<const Vec> p, std::span<const Real> binom, const Real& t) {
  const std::size_t n = p.size() - 1;
  const Real s = Real(1) - t;
  std::array<Real, bezier_max_degree + 1> s_pow;
  s_pow[0] = Real(1);
  for (std::size_t j = 1; j <= n; ++j) s_pow[j] = s_pow[j - 1] * s;
  Vec acc = (binom[0] * s_pow[n]) * p[0];
  Real t_pow(1);
  for (std::size_t i = 1; i <= n; ++i) {
    t_pow *= t;
    acc += (binom[i] * t_pow * s_pow[n - i]) * p[i];
  }
  return acc;
}

/// Horner's rule on power-basis coefficients a_0 .. a_n (value = sum a_j t^j), differentiated
/// `order` times: sum_{j >= order} j! / (j - order)! a_j t^(j - order). O(n * order) operations.
template <class Vec, class Real>
[[nodiscard]] Vec horner(std::span<const Vec> a, const Real& t, int order) {
  const int n = static_cast<int>(a.size()) - 1;
  const auto falling = [order](int j) {
    Real f(1);
    for (int m = 0; m < order; ++m) f *= Real(j - m);
    return f;
  };
  Vec acc = falling(n) * a[static_cast<std::size_t>(n)];
  for (int j = n - 1; j >= order; --j) acc = acc * t + falling(j) * a[static_cast<std::size_t>(j)];
  return acc;
}

/// Power-basis coefficients of a Bezier polynomial: a_j = C(n, j) sum_{i <= j} (-1)^(j-i) C(j, i) p_i.
/// The alternating sums with binomial weights up to C(n, n/2) cancel catastrophically at high
/// degree: this conversion is where the power basis loses its accuracy (kept deliberately so, it
/// is what the test-bench measures).
template <class Vec, class Real>
[[nodiscard]] std::vector<Vec> to_power_basis(std::span<const Vec> p) {
  const int n = static_cast<int>(p.size()) - 1;
  std::vector<Vec> a;
  a.reserve(p.size());
  for (int j = 0; j <= n; ++j) {
    Vec sum = binomial<Real>(j, 0) * p[0];
    if (j % 2 == 1) sum = -sum;
    for (int i = 1; i <= j; ++i) {
      const Real c = ((j - i) % 2 == 0) ? binomial<Real>(j, i) : Real(-binomial<Real>(j, i));
      sum += c * p[static_cast<std::size_t>(i)];
    }
    a.push_back(binomial<Real>(n, j) * sum);
  }
  return a;
}

}  // namespace detail::bezier_kernels
}  // namespace curvebench
