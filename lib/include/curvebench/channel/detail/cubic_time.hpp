// Private helpers of channel/time_solver.hpp: the cubic Bernstein polynomial of a segment's times
// and its derivative (the channel's names for the shared kernels of basis/detail/cubic_bernstein.hpp),
// the regression test of the time handles, and Brent's root finder. Not part of the public interface.
#pragma once

#include "curvebench/basis/detail/cubic_bernstein.hpp"
#include "curvebench/core/real.hpp"
#include "curvebench/core/result_status.hpp"

#include <cmath>
#include <limits>

namespace curvebench::channel::detail {

/// The value at u in [0, 1] of the cubic with Bernstein coefficients b0..b3: the shared kernel
/// (basis/detail/cubic_bernstein.hpp) in the affine form the channel's recorded values use.
template <class Real>
[[nodiscard]] Real bernstein3(const Real& b0, const Real& b1, const Real& b2, const Real& b3, const Real& u) {
  return basis::detail::cubic_value<basis::detail::cubic_form::affine>(b0, b1, b2, b3, u);
}

/// d/du of the cubic with Bernstein coefficients b0..b3: 3 times the quadratic of the differences
/// (the shared kernel, affine form).
template <class Real>
[[nodiscard]] Real bernstein3_derivative(const Real& b0, const Real& b1, const Real& b2, const Real& b3,
                                         const Real& u) {
  return basis::detail::cubic_first_derivative<basis::detail::cubic_form::affine>(b0, b1, b2, b3, u);
}

/// Whether the time handles of a segment with t0 < t3, t1 >= t0 and t2 <= t3 let x(u) decrease
/// somewhere in [0, 1]. x'(u) / 3 = a (1-u)^2 + 2 b u (1-u) + c u^2 with a = t1 - t0 >= 0,
/// c = t3 - t2 >= 0 and b = t2 - t1, and such a quadratic is >= 0 on [0, 1] exactly when b >= 0 or
/// b^2 <= a c. b >= 0 is decided exactly (t2 >= t1). Otherwise a, b, c are rounded differences
/// (relative error eps/2 each), scaled exactly by a power of two so that the squares neither
/// overflow nor underflow, and b^2 <= a c is tested with a margin of 8 eps relative: it covers the
/// rounding of the differences and products (at most about 3 eps on each side), so every segment
/// with exactly non-decreasing time passes, the double-root limits (a, c) = (1/3, 4/3) h and
/// (4/3, 1/3) h included; what passes beyond the exact condition has b^2 > a c by at most 8 eps
/// relative, so x' dips below 0 by at most 8 eps a c / (a - 2 b + c) <= 8 eps h, and x regresses
/// by at most that times the width of the dip, a few eps of h (rounding level, not a regression).
template <class Real>
[[nodiscard]] bool time_handles_regress(const Real& t0, const Real& t1, const Real& t2, const Real& t3) {
  using std::abs;
  using std::frexp;
  using std::ldexp;
  if (t2 >= t1) return false;
  Real a = t1 - t0, b = t1 - t2, c = t3 - t2;  // b here is -(t2 - t1) > 0
  const Real big = a > b ? (a > c ? a : c) : (b > c ? b : c);
  int exponent = 0;
  (void)frexp(big, &exponent);
  a = ldexp(a, -exponent);
  b = ldexp(b, -exponent);
  c = ldexp(c, -exponent);
  return b * b > a * c * (Real(1) + Real(8) * epsilon<Real>());
}

/// The result of brent_root: the root estimate, iterations and function evaluations spent, and
/// converged when the tolerance was met before the iteration cap (cap_hit otherwise).
template <class Real>
struct brent_result {
  Real root;
  int iterations;
  int evaluations;
  result_status status;
};

/// Brent's method (R. P. Brent, Algorithms for Minimization without Derivatives, 1973, chapter 4:
/// bisection, secant and inverse quadratic interpolation, with the step kept inside the bracket
/// and bisection whenever interpolation does not shrink the bracket fast enough) for f on [a, b]
/// with f(a) = fa and f(b) = fb of opposite signs (or one of them zero). Stops when the bracket is
/// narrower than 4 eps |b| + tol, or f(b) = 0; at most max_iterations steps.
template <class Real, class F>
[[nodiscard]] brent_result<Real> brent_root(F&& f, Real a, Real b, Real fa, Real fb, const Real& tol,
                                            int max_iterations) {
  using std::abs;
  const Real eps = epsilon<Real>();
  int evaluations = 0;
  if (fa == Real(0)) return {a, 0, 0, result_status::converged};
  if (fb == Real(0)) return {b, 0, 0, result_status::converged};
  Real c = a, fc = fa, d = b - a, e = d;
  for (int it = 1; it <= max_iterations; ++it) {
    if ((fb > Real(0)) == (fc > Real(0))) {  // keep the root between b and c
      c = a;
      fc = fa;
      d = b - a;
      e = d;
    }
    if (abs(fc) < abs(fb)) {  // b is the best estimate
      a = b;
      b = c;
      c = a;
      fa = fb;
      fb = fc;
      fc = fa;
    }
    const Real tol1 = Real(2) * eps * abs(b) + tol / Real(2);
    const Real m = (c - b) / Real(2);
    if (abs(m) <= tol1 || fb == Real(0)) return {b, it - 1, evaluations, result_status::converged};
    if (abs(e) >= tol1 && abs(fa) > abs(fb)) {
      Real p, q;
      const Real s = fb / fa;
      if (a == c) {  // secant
        p = Real(2) * m * s;
        q = Real(1) - s;
      } else {  // inverse quadratic interpolation
        const Real qq = fa / fc, r = fb / fc;
        p = s * (Real(2) * m * qq * (qq - r) - (b - a) * (r - Real(1)));
        q = (qq - Real(1)) * (r - Real(1)) * (s - Real(1));
      }
      if (p > Real(0))
        q = -q;
      else
        p = -p;
      if (Real(2) * p < Real(3) * m * q - abs(tol1 * q) && p < abs(e * q / Real(2))) {
        e = d;
        d = p / q;
      } else {
        d = m;
        e = m;
      }
    } else {
      d = m;
      e = m;
    }
    a = b;
    fa = fb;
    b += abs(d) > tol1 ? d : (m > Real(0) ? tol1 : Real(-tol1));
    fb = f(b);
    ++evaluations;
  }
  return {b, max_iterations, evaluations, result_status::cap_hit};
}

}  // namespace curvebench::channel::detail
