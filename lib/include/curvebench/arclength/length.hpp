// Gaussian arc length of any curve: s = integral |P'(u)| du, split at every breakpoint.
//
// - `speed(c, u)`: |P'(u)| from the curve's exact first derivative (one derivative evaluation).
// - `gauss_length`: the fixed n-point Gauss-Legendre rule on each segment (seed 002, "Gaussian
//   quadrature"). With estimate::none the cost is n evaluations per segment and no error bound
//   (status not_guaranteed, estimate +inf). With fixed_estimate::nested each segment is also
//   integrated as 2 and 4 panels (7n evaluations per segment); the 4-panel value Q4 is reported
//   with estimate |Q2 - Q4| + rounding floor (the error of Q2, which exceeds Q4's by ~2^(2n) on
//   smooth segments), trusted (converged) only when |Q1 - Q2| >= 16 |Q2 - Q4| (the observed order
//   is >= 4, as for n >= 2 on a speed the panels resolve; not at a cusp, whose kink gives order 2
//   with an erratic constant), else not_guaranteed.
// - `composite_gauss_length`: m equal panels per segment, n points each; error O(h^(2n)) for a
//   speed in C^(2n) (measured in tests), no error bound (not_guaranteed).
// - `adaptive_length`: globally adaptive Gauss-Kronrod (G7-K15 by default) to a tolerance, with the
//   honest |G - K| estimate and a status (see gauss_kronrod.hpp). Each segment is first split at
//   the interior minima of the speed (16 samples of |P'|^2, Newton on P'.P''): a near-cusp dip
//   narrower than the first panels would otherwise be missed by G and K alike, and |G - K| would
//   not see it (tests/test_arclength.cpp shows it on the near-cusp curve).
// Partial lengths between a and b (any order: the result is signed, the estimate is not) split
// at the breakpoints strictly between them. Accuracy: Gauss-Legendre with n points per segment
// converges geometrically in n on segments whose speed is analytic near the segment (polynomial
// and rational segments away from cusps); near a cusp the speed has a kink and convergence is only
// algebraic: use adaptive_length there. Sources: seed 002; Guenter & Parent, "Computing the arc
// length of parametric curves", IEEE CG&A 10(3), 1990.
#pragma once

#include "curvebench/arclength/gauss_kronrod.hpp"
#include "curvebench/arclength/gauss_legendre.hpp"
#include "curvebench/arclength/detail/speed_minima.hpp"
#include "curvebench/arclength/result.hpp"
#include "curvebench/core/curve.hpp"
#include "curvebench/core/error.hpp"

#include <cstddef>
#include <span>
#include <vector>

namespace curvebench::arclength {

/// |P'(u)|, the speed of the curve at u (one derivative evaluation).
template <curve C>
[[nodiscard]] typename C::real_type speed(const C& c, const typename C::real_type& u) {
  using std::sqrt;
  const typename C::point_type d = c.derivative(u, 1);
  return sqrt(d.squaredNorm());
}

/// How a fixed Gauss-Legendre length estimates its error.
enum class fixed_estimate {
  none,   ///< n evaluations per segment, no bound (status not_guaranteed)
  nested  ///< 7n evaluations per segment: the rule on 1, 2 and 4 panels, see gauss_length
};

namespace detail {

/// a, the breakpoints strictly inside (min(a,b), max(a,b)), b (ascending; a <= b required).
template <curve C>
std::vector<typename C::real_type> split_points(const C& c, const typename C::real_type& a,
                                                const typename C::real_type& b) {
  std::vector<typename C::real_type> s;
  s.push_back(a);
  for (const auto& t : c.breakpoints())
    if (t > a && t < b) s.push_back(t);
  s.push_back(b);
  return s;
}

/// One panel by a fixed rule, with the optional nested estimate.
template <class Real, class F>
quadrature_result<Real> fixed_panel(F&& f, const Real& a, const Real& b, const gauss_legendre_rule<Real>& rule,
                                    fixed_estimate est) {
  using std::abs;
  quadrature_result<Real> r;
  const Real whole = rule.integrate(f, a, b);
  r.evaluations = rule.nodes.size();
  if (est == fixed_estimate::none) {
    r.value = whole;
    r.error_estimate = no_bound<Real>();
    r.status = result_status::not_guaranteed;
    return r;
  }
  const Real h = (b - a) / Real(4);
  const Real q1 = a + h, mid = (a + b) / Real(2), q3 = b - h;
  const Real l = rule.integrate(f, a, q1), ml = rule.integrate(f, q1, mid), mr = rule.integrate(f, mid, q3),
             r4 = rule.integrate(f, q3, b);
  const Real halves = rule.integrate(f, a, mid) + rule.integrate(f, mid, b);
  const Real quarters = (l + ml) + (mr + r4);
  r.evaluations += 6 * rule.nodes.size();
  r.value = quarters;
  // The speed is >= 0, so |integral| bounds integral |f|: the floor covers the rounding of f and the sums.
  const Real floor = Real(50) * epsilon<Real>() * abs(quarters);
  const Real d1 = abs(whole - halves), d2 = abs(halves - quarters);
  r.error_estimate = d2 + floor;
  // On a smooth speed the rule converges at order 2n >= 4 (n >= 2) once the panels resolve it:
  // d1 >= 16 d2. A kink (cusp) gives order 2 with a constant that depends on where the kink falls
  // in the panels, and a feature narrower than the panels gives anything: not trusted.
  r.status = (d1 >= Real(16) * d2 || (d1 <= floor && d2 <= floor)) ? result_status::converged
                                                                  : result_status::not_guaranteed;
  return r;
}

template <class Real>
void check_order(const Real& a, const Real& b, bool& flipped, Real& lo, Real& hi) {
  flipped = b < a;
  lo = flipped ? b : a;
  hi = flipped ? a : b;
}

}  // namespace detail

/// Length of the part from a to b (signed: negative when b < a) by the fixed n-point rule on each
/// piece between breakpoints. Throws std::domain_error when a or b is outside the domain.
template <curve C>
[[nodiscard]] quadrature_result<typename C::real_type> gauss_length(
    const C& c, const typename C::real_type& a, const typename C::real_type& b,
    const gauss_legendre_rule<typename C::real_type>& rule, fixed_estimate est = fixed_estimate::none) {
  using Real = typename C::real_type;
  check_parameter(a, interval<Real>(c.domain()));
  check_parameter(b, interval<Real>(c.domain()));
  bool flipped;
  Real lo, hi;
  detail::check_order(a, b, flipped, lo, hi);
  auto f = [&c](const Real& u) { return speed(c, u); };
  quadrature_result<Real> total;
  total.status = est == fixed_estimate::none ? result_status::not_guaranteed : result_status::converged;
  Real prev = lo;
  for (const Real& t : c.breakpoints()) {
    if (!(t > lo && t < hi)) continue;
    total += detail::fixed_panel(f, prev, t, rule, est);
    prev = t;
  }
  if (hi > prev) total += detail::fixed_panel(f, prev, hi, rule, est);
  if (est == fixed_estimate::none) total.error_estimate = no_bound<Real>();
  if (flipped) total.value = -total.value;
  return total;
}

/// Total length by the fixed rule on every segment (no allocation; the hot path of the
/// benchmarks: fetch the rule once with gauss_legendre<Real>(n)).
template <curve C>
[[nodiscard]] quadrature_result<typename C::real_type> gauss_length(
    const C& c, const gauss_legendre_rule<typename C::real_type>& rule, fixed_estimate est = fixed_estimate::none) {
  using Real = typename C::real_type;
  auto f = [&c](const Real& u) { return speed(c, u); };
  const std::span<const Real> bp = c.breakpoints();
  quadrature_result<Real> total;
  total.status = est == fixed_estimate::none ? result_status::not_guaranteed : result_status::converged;
  for (std::size_t i = 0; i + 1 < bp.size(); ++i)
    if (bp[i + 1] > bp[i]) total += detail::fixed_panel(f, bp[i], bp[i + 1], rule, est);
  if (est == fixed_estimate::none) total.error_estimate = no_bound<Real>();
  return total;
}

/// Total length by the fixed n-point rule per segment (cached rule).
template <curve C>
[[nodiscard]] quadrature_result<typename C::real_type> gauss_length(const C& c, int n,
                                                                    fixed_estimate est = fixed_estimate::none) {
  return gauss_length(c, gauss_legendre<typename C::real_type>(n), est);
}

/// Total length by the composite rule: `panels` equal panels per segment, the rule on each.
/// No error bound (status not_guaranteed); tests measure its order O(h^(2n)).
template <curve C>
[[nodiscard]] quadrature_result<typename C::real_type> composite_gauss_length(
    const C& c, int panels, const gauss_legendre_rule<typename C::real_type>& rule) {
  using Real = typename C::real_type;
  if (panels < 1) validate::fail("panels = " + std::to_string(panels) + ": must be >= 1");
  auto f = [&c](const Real& u) { return speed(c, u); };
  const std::span<const Real> bp = c.breakpoints();
  quadrature_result<Real> total;
  for (std::size_t i = 0; i + 1 < bp.size(); ++i) {
    if (!(bp[i + 1] > bp[i])) continue;
    total.value += integrate_composite(f, bp[i], bp[i + 1], panels, rule);
    total.evaluations += static_cast<std::size_t>(panels) * rule.nodes.size();
  }
  total.error_estimate = no_bound<Real>();
  total.status = result_status::not_guaranteed;
  return total;
}

namespace detail {

/// The split points with the interior speed minima of every piece inserted (when enabled).
template <curve C>
std::vector<typename C::real_type> with_speed_minima(const C& c, const std::vector<typename C::real_type>& s,
                                                     std::size_t samples, std::size_t& evaluations) {
  if (samples == 0) return s;
  std::vector<typename C::real_type> out;
  for (std::size_t i = 0; i + 1 < s.size(); ++i) {
    out.push_back(s[i]);
    append_speed_minima(c, s[i], s[i + 1], samples, out, evaluations);
  }
  out.push_back(s.back());
  return out;
}

}  // namespace detail

/// Length from a to b (signed) by adaptive Gauss-Kronrod, split at the breakpoints in between and
/// at the interior speed minima (opt.speed_minimum_samples). Throws std::domain_error for a or b
/// outside the domain, invalid_input for bad tolerances.
template <curve C>
[[nodiscard]] quadrature_result<typename C::real_type> adaptive_length(
    const C& c, const typename C::real_type& a, const typename C::real_type& b,
    const adaptive_options<typename C::real_type>& opt = {}) {
  using Real = typename C::real_type;
  check_parameter(a, interval<Real>(c.domain()));
  check_parameter(b, interval<Real>(c.domain()));
  bool flipped;
  Real lo, hi;
  detail::check_order(a, b, flipped, lo, hi);
  std::size_t extra = 0;
  const std::vector<Real> s = detail::with_speed_minima(c, detail::split_points(c, lo, hi), opt.speed_minimum_samples, extra);
  quadrature_result<Real> r = integrate_adaptive([&c](const Real& u) { return speed(c, u); },
                                                 std::span<const Real>(s), opt);
  r.evaluations += extra;
  if (flipped) r.value = -r.value;
  return r;
}

/// Total length by adaptive Gauss-Kronrod over all segments (split at breakpoints and speed minima).
template <curve C>
[[nodiscard]] quadrature_result<typename C::real_type> adaptive_length(
    const C& c, const adaptive_options<typename C::real_type>& opt = {}) {
  using Real = typename C::real_type;
  const std::span<const Real> bp = c.breakpoints();
  std::size_t extra = 0;
  const std::vector<Real> s =
      detail::with_speed_minima(c, std::vector<Real>(bp.begin(), bp.end()), opt.speed_minimum_samples, extra);
  quadrature_result<Real> r = integrate_adaptive([&c](const Real& u) { return speed(c, u); }, std::span<const Real>(s), opt);
  r.evaluations += extra;
  return r;
}

}  // namespace curvebench::arclength
