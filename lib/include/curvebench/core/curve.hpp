// The parametric-curve concept every family satisfies, and the domain type.
//
// A curve is a function P(u) on a closed domain [u0, u1] with exact derivatives:
//   - `c.domain()`                -> interval<Real> {lo = u0, hi = u1}
//   - `c(u)`                      -> point<Real, Dim>, the value
//   - `c.derivative(u, order)`    -> point<Real, Dim>, d^order P / du^order (order 0 is the value),
//                                    exact (analytic), never finite differences
//   - `c.breakpoints()`           -> sorted parameters where smoothness may drop, first u0, last u1
//                                    (segment boundaries); integrators split there
// and exposes `real_type`, `point_type` and `static constexpr int dimension`.
// Evaluating outside [u0, u1] throws std::domain_error (see `check_parameter`).
// Optionally, `c.rounding_bound(order)` (order 0 or 1) -> Real: an upper bound, over the whole
// domain, on |fl(P^(order)(u)) - P^(order)(u)| (Euclidean norm) for the curve's own evaluation in
// Real, a constant computed once at construction (+infinity: no bound known), relative to the
// curve's data. `declared_rounding_bound(c, order)` returns it, or 0 for a curve that declares none:
// its evaluation is then taken to be as well conditioned as the rounding floors of the arc-length
// methods assume (a few eps of |P'|); `rounding_bound(c, order)`, what the methods use, adds to a
// declared bound the absolute rounding of underflow (underflow_floor: results in the subnormal range).
// Optionally, `c.second_derivative_bound(a, b)` (a <= b in the domain) -> Real: an upper bound on
// |P''(u)| over [a, b] such that the speed |P'| is Lipschitz with it there (+infinity: none, e.g.
// across a knot where P' may jump); `second_derivative_bound(c, a, b)` returns it, or +infinity for
// a curve that declares none. Newton inversion uses it to bound a step without integrating it.
// Optionally, `c.value_from_left(u)` -> point: the limit of P from the left at an interior
// breakpoint u (the segment that ends there). A curve whose position may jump at a breakpoint
// (composite_bezier: segments need not meet) must declare it; `value_from_left(c, u)` returns it,
// or c(u) for a curve that declares none, which is then continuous. Methods that measure chords
// across a segment (subdivision, forward differences) end each segment there, so that a jump is
// not counted as length: L is the integral of |P'| over the segments, as the quadratures take it.
// Arc length, inversion and motion (arclength/, motion/) are written against this concept only.
#pragma once

#include "curvebench/core/point.hpp"
#include "curvebench/core/real.hpp"

#include <concepts>
#include <cstddef>
#include <limits>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>

namespace curvebench {

/// A closed parameter interval [lo, hi].
template <class Real>
struct interval {
  Real lo;
  Real hi;
  [[nodiscard]] Real length() const { return hi - lo; }
  [[nodiscard]] bool contains(const Real& u) const { return lo <= u && u <= hi; }
};

template <class C>
concept curve = requires(const C& c, const typename C::real_type& u, int order) {
  typename C::real_type;
  typename C::point_type;
  { C::dimension } -> std::convertible_to<int>;
  requires std::same_as<typename C::point_type, point<typename C::real_type, C::dimension>>;
  { c.domain() } -> std::convertible_to<interval<typename C::real_type>>;
  { c(u) } -> std::convertible_to<typename C::point_type>;
  { c.derivative(u, order) } -> std::convertible_to<typename C::point_type>;
  { c.breakpoints() } -> std::convertible_to<std::span<const typename C::real_type>>;
};

/// A curve that declares the rounding of its own evaluation (see the header).
template <class C>
concept declares_rounding_bound = curve<C> && requires(const C& c, int order) {
  { c.rounding_bound(order) } -> std::convertible_to<typename C::real_type>;
};

/// The absolute rounding that underflow adds to one evaluation: 2^20 x denorm_min (5e-318 in
/// double). The curves' bounds are relative to their data (eps x size), which holds only while the
/// results stay normal numbers; a derivative in the subnormal range (coordinates of 1e-21 over a
/// domain of width 1e294: |P'| ~ 1e-315) is rounded to an absolute denorm_min / 2 per operation,
/// and an evaluation of up to 2^20 such operations (de Casteljau of degree 60 takes about 2^12)
/// stays within this. Negligible elsewhere; a sweep found adaptive_gk converged with an
/// estimate 2.4x below the error on such a curve.
template <class Real>
[[nodiscard]] Real underflow_floor() {
  using std::ldexp;
  return ldexp(std::numeric_limits<Real>::denorm_min(), 20);
}

/// c.rounding_bound(order) when c declares one, else 0 (see the header). order is 0 or 1.
template <curve C>
[[nodiscard]] typename C::real_type declared_rounding_bound(const C& c, int order) {
  if constexpr (declares_rounding_bound<C>)
    return c.rounding_bound(order);
  else
    return typename C::real_type(0);
}

/// The bound the methods use: a declared bound plus underflow_floor, or 0 for a curve that
/// declares none (taken to be well conditioned, as the header says: a zero-length piece of such a
/// curve stays exactly 0, converged).
template <curve C>
[[nodiscard]] typename C::real_type rounding_bound(const C& c, int order) {
  using Real = typename C::real_type;
  if constexpr (declares_rounding_bound<C>)
    return Real(c.rounding_bound(order)) + underflow_floor<Real>();
  else
    return Real(0);
}

/// A curve that gives the limit of P from the left at its breakpoints (see the header).
template <class C>
concept declares_value_from_left = curve<C> && requires(const C& c, const typename C::real_type& u) {
  { c.value_from_left(u) } -> std::convertible_to<typename C::point_type>;
};

/// P(u-): c.value_from_left(u) when c declares it, else c(u) (a continuous curve; see the header).
template <curve C>
[[nodiscard]] typename C::point_type value_from_left(const C& c, const typename C::real_type& u) {
  if constexpr (declares_value_from_left<C>)
    return c.value_from_left(u);
  else
    return c(u);
}

/// A curve that bounds its second derivative over an interval (see the header).
template <class C>
concept declares_second_derivative_bound = curve<C> && requires(const C& c, const typename C::real_type& u) {
  { c.second_derivative_bound(u, u) } -> std::convertible_to<typename C::real_type>;
};

/// c.second_derivative_bound(a, b) when c declares one, else +infinity (no bound known).
template <curve C>
[[nodiscard]] typename C::real_type second_derivative_bound(const C& c, const typename C::real_type& a,
                                                            const typename C::real_type& b) {
  if constexpr (declares_second_derivative_bound<C>)
    return c.second_derivative_bound(a, b);
  else
    return std::numeric_limits<typename C::real_type>::infinity();
}

/// Throws std::domain_error unless u lies in the closed domain (NaN fails too):
/// "u = 1.5 is outside the domain [0, 1]"; batch evaluators pass the span's name and the index:
/// "us[5] = nan is outside the domain [0, 1]".
template <class Real>
void check_parameter(const Real& u, const interval<Real>& domain, std::string_view name = "u",
                     std::size_t index = std::string::npos) {
  if (domain.contains(u)) return;
  // Appended piece by piece: `"[" + std::to_string(index)` inserts at the front of a temporary, where
  // GCC 12 at -O3 warns a false -Wrestrict / -Wstringop-overflow in libstdc++'s _M_replace.
  std::string what(name);
  if (index != std::string::npos) {
    what += '[';
    what += std::to_string(index);
    what += ']';
  }
  what += " = ";
  what += to_text(u);
  what += " is outside the domain [";
  what += to_text(domain.lo);
  what += ", ";
  what += to_text(domain.hi);
  what += ']';
  throw std::domain_error(what);
}

}  // namespace curvebench
