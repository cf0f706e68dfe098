// Gauss-Legendre quadrature: nodes and weights for any n, computed in Real, cached; the fixed
// n-point rule on [a, b] and the composite rule over equal panels.
// Nodes: roots of P_n by Newton on the three-term recurrence from Tricomi's initial guesses,
// iterated in Real until the step is below eps(Real) and once more (a real50 rule is exact to 50
// digits); weights 2 / ((1 - x^2) P_n'(x)^2); nodes mirrored so the rule is exactly symmetric.
// gauss_legendre<Real>(n) returns a process-wide rule computed once under a mutex (lock-free look
// up for n <= 128); hot paths keep the reference.
// Sources: seed 002 (Gaussian quadrature for arc length); Davis & Rabinowitz (1984), 2.7;
// Abramowitz & Stegun 25.4.29, 22.16.6.
// Cost: the rule O(n^2) per Newton sweep, once; n evaluations per application.
// Accuracy: exact for degree <= 2n - 1; O(rho^-2n) for f analytic in the Bernstein ellipse rho;
// composite with panels h: O(h^2n) for f in C^2n.
#pragma once

#include "curvebench/arclength/detail/rule_cache.hpp"
#include "curvebench/core/error.hpp"
#include "curvebench/core/real.hpp"

#include <boost/math/constants/constants.hpp>

#include <cstddef>
#include <string>
#include <utility>
#include <vector>

namespace curvebench::arclength {

/// An n-point Gauss-Legendre rule on [-1, 1]: nodes ascending, weights summing to 2.
template <class Real>
struct gauss_legendre_rule {
  int n{0};
  std::vector<Real> nodes;
  std::vector<Real> weights;

  /// sum_i w_i f(x_i) mapped to [a, b]: the n-point rule, exact for degree <= 2n - 1.
  template <class F>
  [[nodiscard]] Real integrate(F&& f, const Real& a, const Real& b) const {
    const Real half = (b - a) / Real(2);
    const Real mid = (a + b) / Real(2);
    Real sum(0);
    for (std::size_t i = 0; i < nodes.size(); ++i) sum += weights[i] * f(mid + half * nodes[i]);
    return sum * half;
  }
};

namespace detail {

/// P_n(x) and P_{n-1}(x) by the three-term recurrence (n >= 1).
template <class Real>
std::pair<Real, Real> legendre_pair(int n, const Real& x) {
  Real p_prev(1);
  Real p = x;
  for (int k = 1; k < n; ++k) {
    Real p_next = (Real(2 * k + 1) * x * p - Real(k) * p_prev) / Real(k + 1);
    p_prev = p;
    p = p_next;
  }
  return {p, p_prev};
}

}  // namespace detail

/// Computes the n-point rule in Real (uncached). Throws invalid_input unless 1 <= n <= 100000.
template <class Real>
[[nodiscard]] gauss_legendre_rule<Real> make_gauss_legendre(int n) {
  if (n < 1 || n > 100000)
    validate::fail("n = " + std::to_string(n) + ": number of Gauss-Legendre points must be in [1, 100000]");
  using std::abs;
  using std::cos;
  gauss_legendre_rule<Real> r;
  r.n = n;
  r.nodes.assign(static_cast<std::size_t>(n), Real(0));
  r.weights.assign(static_cast<std::size_t>(n), Real(0));
  const Real pi = boost::math::constants::pi<Real>();
  const Real nr = static_cast<Real>(n);
  const Real tricomi = Real(1) - (nr - Real(1)) / (Real(8) * nr * nr * nr);
  const int half = (n + 1) / 2;
  for (int i = 1; i <= half; ++i) {
    // Root i counted from the right end (x near 1 for i = 1).
    Real x = tricomi * cos(pi * (Real(4 * i - 1)) / (Real(4) * nr + Real(2)));
    Real dp(1);
    bool last_pass = false;
    for (int iter = 0; iter < 100; ++iter) {
      const auto [p, p1] = detail::legendre_pair(n, x);
      dp = Real(n) * (x * p - p1) / (x * x - Real(1));
      const Real step = p / dp;
      x -= step;
      if (last_pass) break;
      if (abs(step) <= epsilon<Real>()) last_pass = true;  // one more step after reaching eps
    }
    if (2 * i - 1 == n) x = Real(0);  // the middle node of an odd rule is exactly 0
    {
      const auto [p, p1] = detail::legendre_pair(n, x);
      dp = Real(n) * (x * p - p1) / (x * x - Real(1));
    }
    const Real w = Real(2) / ((Real(1) - x * x) * dp * dp);
    const auto right = static_cast<std::size_t>(n - i);
    const auto left = static_cast<std::size_t>(i - 1);
    r.nodes[right] = x;
    r.weights[right] = w;
    r.nodes[left] = -x;
    r.weights[left] = w;
  }
  return r;
}

/// The cached n-point rule (thread-safe; the reference stays valid until exit).
template <class Real>
[[nodiscard]] const gauss_legendre_rule<Real>& gauss_legendre(int n) {
  return detail::rule_cache<gauss_legendre_rule<Real>>::get(n, &make_gauss_legendre<Real>);
}

/// The composite rule: [a, b] cut into `panels` equal panels, the rule on each. Throws
/// invalid_input when panels < 1.
template <class Real, class F>
[[nodiscard]] Real integrate_composite(F&& f, const Real& a, const Real& b, int panels,
                                       const gauss_legendre_rule<Real>& rule) {
  if (panels < 1) validate::fail("panels = " + std::to_string(panels) + ": must be >= 1");
  const Real h = (b - a) / Real(panels);
  Real sum(0);
  for (int k = 0; k < panels; ++k) {
    const Real lo = a + Real(k) * h;
    const Real hi = k + 1 == panels ? b : a + Real(k + 1) * h;
    sum += rule.integrate(f, lo, hi);
  }
  return sum;
}

}  // namespace curvebench::arclength
