// Converting a curve to another Real (typically its double control data to real50), exactly.
//
// Every family has its own control data (points, weights, knots, tangents, tension...), and the
// families are not ours to edit, so the conversion is generic in one place and family-specific in
// a callable the caller supplies:
//     auto c50 = reference::convert_curve<real50>(c, [](const auto& c, auto to) {
//       using To = typename decltype(to)::type;
//       return bezier<To, 2>(reference::exact_points<To>(c.control_points()));
//     });
// The callable rebuilds the curve in To from the source's data (the helpers `exact_value`,
// `exact_values`, `exact_points` convert and CHECK exactness: a value that does not round-trip
// is rejected with invalid_input naming it). convert_curve then checks that the result is a curve
// of the same dimension with real_type To, that its breakpoints are exactly the source's, and that
// it agrees with the source at every breakpoint to the source's rounding (a rebuild from the wrong
// data is caught). A widening conversion (float/double/long double -> real50) is always exact.
// Cost: O(size of the control data) + one evaluation per breakpoint.
#pragma once

#include "curvebench/core/curve.hpp"
#include "curvebench/core/error.hpp"
#include "curvebench/core/point.hpp"
#include "curvebench/core/real.hpp"

#include <cstddef>
#include <span>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

namespace curvebench::reference {

/// To(x), checked to convert back to x exactly (NaN is rejected).
template <class To, class From>
[[nodiscard]] To exact_value(const From& x, std::string_view name = "value", std::size_t index = std::string::npos) {
  const To y = static_cast<To>(x);
  if (!(static_cast<From>(y) == x))
    validate::fail(validate::indexed(name, index) + " = " + to_text(x) +
                   ": does not convert exactly to the target Real");
  return y;
}

/// Every value converted exactly.
template <class To, class From>
[[nodiscard]] std::vector<To> exact_values(std::span<const From> xs, std::string_view name = "values") {
  std::vector<To> out;
  out.reserve(xs.size());
  for (std::size_t i = 0; i < xs.size(); ++i) out.push_back(exact_value<To>(xs[i], name, i));
  return out;
}

/// Every coordinate of every point converted exactly.
template <class To, class From, int Dim>
[[nodiscard]] point_list<To, Dim> exact_points(std::span<const point<From, Dim>> ps, std::string_view name = "points") {
  point_list<To, Dim> out;
  out.reserve(ps.size());
  for (std::size_t i = 0; i < ps.size(); ++i) {
    point<To, Dim> q;
    for (int d = 0; d < Dim; ++d)
      q[d] = exact_value<To>(ps[i][d], validate::indexed(name, i) + "[" + std::to_string(d) + "]");
    out.push_back(q);
  }
  return out;
}

/// Overload for a std::vector of points (deduces Dim).
template <class To, class From, int Dim>
[[nodiscard]] point_list<To, Dim> exact_points(const point_list<From, Dim>& ps, std::string_view name = "points") {
  return exact_points<To, From, Dim>(std::span<const point<From, Dim>>(ps), name);
}

/// The curve rebuilt in To by rebuild(c, std::type_identity<To>{}), checked (see the header).
template <class To, curve C, class Rebuild>
[[nodiscard]] auto convert_curve(const C& c, Rebuild&& rebuild) {
  using From = typename C::real_type;
  using Out = std::remove_cvref_t<decltype(rebuild(c, std::type_identity<To>{}))>;
  static_assert(curve<Out>, "the rebuild callable must return a curve");
  static_assert(std::is_same_v<typename Out::real_type, To>, "the rebuilt curve must have real_type To");
  static_assert(Out::dimension == C::dimension, "the rebuilt curve must have the same dimension");
  Out out = rebuild(c, std::type_identity<To>{});
  const std::span<const From> b0 = c.breakpoints();
  const std::span<const To> b1 = out.breakpoints();
  validate::same_count("converted breakpoints", b1.size(), "breakpoints", b0.size());
  using std::abs;
  using std::max;
  From scale(0);
  for (std::size_t i = 0; i < b0.size(); ++i) scale = max(scale, From(c(b0[i]).cwiseAbs().maxCoeff()));
  if (!(scale > From(0))) scale = From(1);
  for (std::size_t i = 0; i < b0.size(); ++i) {
    if (!(b1[i] == static_cast<To>(b0[i])))
      validate::fail("converted breakpoints[" + std::to_string(i) + "] = " + to_text(b1[i]) + ": must equal " +
                     to_text(b0[i]));
    const point<From, C::dimension> p0 = c(b0[i]);
    const point<To, C::dimension> p1 = out(b1[i]);
    for (int d = 0; d < C::dimension; ++d) {
      const To diff = abs(p1[d] - static_cast<To>(p0[d]));
      if (diff > static_cast<To>(From(1024) * epsilon<From>() * scale))
        validate::fail("converted curve differs at breakpoints[" + std::to_string(i) + "][" + std::to_string(d) +
                       "]: " + to_text(p1[d]) + " vs " + to_text(p0[d]) + ": the rebuild used other data");
    }
  }
  return out;
}

}  // namespace curvebench::reference
