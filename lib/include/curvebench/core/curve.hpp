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
// Arc length, inversion and motion (arclength/, motion/) are written against this concept only.
#pragma once

#include "curvebench/core/point.hpp"
#include "curvebench/core/real.hpp"

#include <concepts>
#include <cstddef>
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

/// Throws std::domain_error unless u lies in the closed domain (NaN fails too):
/// "u = 1.5 is outside the domain [0, 1]"; batch evaluators pass the span's name and the index:
/// "us[5] = nan is outside the domain [0, 1]".
template <class Real>
void check_parameter(const Real& u, const interval<Real>& domain, std::string_view name = "u",
                     std::size_t index = std::string::npos) {
  if (domain.contains(u)) return;
  std::string what(name);
  if (index != std::string::npos) what += "[" + std::to_string(index) + "]";
  throw std::domain_error(what + " = " + to_text(u) + " is outside the domain [" + to_text(domain.lo) + ", " +
                          to_text(domain.hi) + "]");
}

}  // namespace curvebench
