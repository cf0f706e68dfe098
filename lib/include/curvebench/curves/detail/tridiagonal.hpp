// O(n) solvers for tridiagonal and cyclic tridiagonal systems, for any Real and for right-hand
// sides that are scalars or points (one solve for every coordinate at once).
//
// System: a[i] x[i-1] + b[i] x[i] + c[i] x[i+1] = r[i], i = 0..n-1. For the plain solver a[0] and
// c[n-1] are not used; for the cyclic one they are the corner coefficients (a[0] multiplies
// x[n-1], c[n-1] multiplies x[0]).
// Algorithms: Thomas elimination without pivoting (stable for the diagonally dominant systems of
// spline slopes; see e.g. Golub & Van Loan 4.3), and Sherman-Morrison for the cyclic system
// (Press et al., Numerical Recipes 2.7: a rank-one correction of a tridiagonal solve).
// Cost O(n), one scratch vector; a zero or non-finite pivot throws invalid_input.
#pragma once

#include "curvebench/core/error.hpp"
#include "curvebench/core/real.hpp"

#include <cstddef>
#include <span>
#include <string>
#include <vector>

namespace curvebench::detail {

/// Solves the tridiagonal system in place: r becomes x.
template <class Real, class V>
void solve_tridiagonal(std::span<const Real> a, std::span<const Real> b, std::span<const Real> c, std::span<V> r) {
  const std::size_t n = b.size();
  if (a.size() != n || c.size() != n || r.size() != n)
    validate::fail("tridiagonal system: a, b, c, r must all have " + std::to_string(n) + " entries");
  if (n == 0) return;
  std::vector<Real> cp(n);
  auto pivot_ok = [](const Real& p, std::size_t i) {
    if (!(p != Real(0)) || !is_finite(p))
      validate::fail("tridiagonal system: pivot " + std::to_string(i) + " = " + to_text(p) + " (system is singular)");
  };
  Real beta = b[0];
  pivot_ok(beta, 0);
  r[0] = V(r[0] / beta);
  for (std::size_t i = 1; i < n; ++i) {
    cp[i - 1] = c[i - 1] / beta;
    beta = b[i] - a[i] * cp[i - 1];
    pivot_ok(beta, i);
    r[i] = V((r[i] - a[i] * r[i - 1]) / beta);
  }
  for (std::size_t i = n - 1; i-- > 0;) r[i] = V(r[i] - cp[i] * r[i + 1]);
}

/// Solves the cyclic tridiagonal system in place (n >= 1): r becomes x.
template <class Real, class V>
void solve_cyclic_tridiagonal(std::span<const Real> a, std::span<const Real> b, std::span<const Real> c,
                              std::span<V> r) {
  const std::size_t n = b.size();
  if (a.size() != n || c.size() != n || r.size() != n)
    validate::fail("cyclic tridiagonal system: a, b, c, r must all have " + std::to_string(n) + " entries");
  if (n == 0) return;
  if (n == 1) {  // a x + b x + c x = r
    const Real d = a[0] + b[0] + c[0];
    if (!(d != Real(0))) validate::fail("cyclic tridiagonal system: singular 1 x 1 system");
    r[0] = V(r[0] / d);
    return;
  }
  if (n == 2) {  // both neighbours of x0 are x1 and vice versa: a 2 x 2 system, by Cramer's rule
    const Real p = b[0], q = a[0] + c[0], s = a[1] + c[1], t = b[1];
    const Real det = p * t - q * s;
    if (!(det != Real(0))) validate::fail("cyclic tridiagonal system: singular 2 x 2 system");
    const V r0 = r[0];
    r[0] = V((t * r0 - q * r[1]) / det);
    r[1] = V((p * r[1] - s * r0) / det);
    return;
  }
  // Sherman-Morrison: A = T + u v^T with u = (gamma, 0, ..., 0, c[n-1]), v = (1, 0, ..., 0, a[0]/gamma),
  // T tridiagonal with the two corner-adjusted diagonal entries. u is scalar, so T z = u is one
  // scalar solve shared by every coordinate of V; then x = y - z (v·y) / (1 + v·z).
  const Real gamma = -b[0];
  std::vector<Real> bb(b.begin(), b.end());
  bb[0] = b[0] - gamma;
  bb[n - 1] = b[n - 1] - a[0] * c[n - 1] / gamma;
  std::vector<Real> z(n, Real(0));
  z[0] = gamma;
  z[n - 1] = c[n - 1];
  solve_tridiagonal<Real, V>(a, bb, c, r);
  solve_tridiagonal<Real, Real>(a, bb, c, std::span<Real>(z));
  const Real ratio = a[0] / gamma;
  const Real den = Real(1) + z[0] + ratio * z[n - 1];
  if (!(den != Real(0)) || !is_finite(den))
    validate::fail("cyclic tridiagonal system: Sherman-Morrison denominator " + to_text(den) + " (system is singular)");
  const V fact = V((r[0] + ratio * r[n - 1]) / den);
  for (std::size_t i = 0; i < n; ++i) r[i] = V(r[i] - z[i] * fact);
}

}  // namespace curvebench::detail
