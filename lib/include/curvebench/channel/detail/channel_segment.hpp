// Private helpers of channel/channel.hpp: one segment of a keyframe channel in Bernstein form, its
// evaluation at a local parameter w in [0, 1] (the curve view) and at a time t (the channel), and
// the limit of dv/dt where x'(w) vanishes. Not part of the public interface.
#pragma once

#include "curvebench/basis/detail/cubic_bernstein.hpp"
#include "curvebench/channel/detail/cubic_time.hpp"
#include "curvebench/channel/time_solver.hpp"
#include "curvebench/core/real.hpp"

#include <algorithm>
#include <array>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <string>

namespace curvebench::channel {

/// How the segment that starts at a key interpolates (see channel.hpp).
enum class interpolation : std::uint8_t { constant, step_next, linear, bezier, hermite };

}  // namespace curvebench::channel

namespace curvebench::channel::detail {

/// The order-th derivative in w of the cubic with Bernstein coefficients b (any order >= 0; above 3
/// zero): the shared kernel (basis/detail/cubic_bernstein.hpp), affine form.
template <class Real>
[[nodiscard]] Real bernstein3_any(const std::array<Real, 4>& b, const Real& w, int order) {
  if (order > 3) return Real(0);
  return basis::detail::cubic_derivative<basis::detail::cubic_form::affine>(b, w, order);
}

/// One segment [t[0], t[3]]: for bezier the control times and values of the cubic Bezier; for
/// hermite t[0], t[3], the Bernstein values v0, v0 + m0 h / 3, v3 - m1 h / 3, v3 (t[1], t[2]
/// unused: time is linear) and the slopes m0, m1 themselves (dv/dt at the keys, exactly); for linear, constant and
/// step_next t[0], t[3] and v[0], v[3].
/// For bezier, rel holds the control times relative to the segment's start, {0, out.dt, (t3 - t0)
/// + in.dt, t3 - t0}: the time inversion and the time derivatives work on them, so that keys far
/// from time 0 (frame 1e5) lose nothing to the rounding of absolute control times (which would
/// shift u by ulp(t) / h: about 1e-11 of the interval at frame 1e5 in double).
template <class Real>
struct segment {
  interpolation kind;
  std::array<Real, 4> t;
  std::array<Real, 4> v;
  Real m0{0}, m1{0};          // hermite: the end slopes as given (exact at the keys, not via v1, v2)
  std::array<Real, 4> rel{};  // bezier: control times relative to t[0] (see above)

  [[nodiscard]] Real span() const { return t[3] - t[0]; }

  /// The time coordinate's order-th derivative at local parameter w (order 0 absolute, exact at
  /// both ends; the derivatives from the relative control times).
  [[nodiscard]] Real time_at(const Real& w, int order) const {
    if (kind == interpolation::bezier) return order == 0 ? bernstein3_any(t, w, 0) : bernstein3_any(rel, w, order);
    if (order == 0) return (Real(1) - w) * t[0] + w * t[3];  // exact at both ends
    return order == 1 ? span() : Real(0);
  }

  /// The value coordinate's order-th derivative at local parameter w; constant and step_next are
  /// horizontal with their jump at the segment's end (constant) or start (step_next).
  [[nodiscard]] Real value_at(const Real& w, int order) const {
    switch (kind) {
      case interpolation::bezier:
      case interpolation::hermite: return bernstein3_any(v, w, order);
      case interpolation::linear:
        if (order == 0) return (Real(1) - w) * v[0] + w * v[3];
        return order == 1 ? v[3] - v[0] : Real(0);
      case interpolation::constant:
        if (order > 0) return Real(0);
        return w < Real(1) ? v[0] : v[3];
      case interpolation::step_next:
        if (order > 0) return Real(0);
        return w > Real(0) ? v[3] : v[0];
    }
    return Real(0);
  }

  /// The local parameter at time t in [t[0], t[3]]: the solver's root for bezier, else linear.
  [[nodiscard]] Real local(const Real& time, time_solver solver) const {
    if (kind == interpolation::bezier)
      return solve_time(solver, time_cubic<Real>{rel[0], rel[1], rel[2], rel[3]}, Real(time - t[0])).u;
    if (time == t[3]) return Real(1);
    return std::clamp((time - t[0]) / span(), Real(0), Real(1));
  }

  /// dv/dt at local parameter w. Where x'(w) > 0 it is v'(w) / x'(w). Where x'(w) <= 0 (a vertical
  /// tangent, a zero-length time handle at an end, or a dip by rounding at a regression limit) it
  /// is the limit along the segment: +-infinity with the sign of v'(w) when v'(w) != 0, else the
  /// ratio of the first derivatives of order 2 or 3 that do not both vanish (l'Hopital).
  [[nodiscard]] Real slope_at(const Real& w) const {
    if (kind == interpolation::hermite && w == Real(0)) return m0;
    if (kind == interpolation::hermite && w == Real(1)) return m1;
    const Real xp = time_at(w, 1), vp = value_at(w, 1);
    if (xp > Real(0)) return vp / xp;
    const Real inf = std::numeric_limits<Real>::infinity();
    if (vp != Real(0)) return vp > Real(0) ? inf : Real(-inf);
    for (int order = 2; order <= 3; ++order) {
      const Real xk = time_at(w, order), vk = value_at(w, order);
      if (xk != Real(0)) return vk / xk;
      if (vk != Real(0)) return vk > Real(0) ? inf : Real(-inf);
    }
    return Real(0);  // not reached for a segment with t[0] < t[3]: x''' or x'' or x' is nonzero
  }

  /// d^2 v / dt^2 at local parameter w: (v'' x' - v' x'') / x'^3. Where x'(w) <= 0 it is unbounded
  /// (std::domain_error) except in one alignment, which gives 0: x'(w) = v'(w) = 0 (zero-length
  /// handles) and x'' v''' = x''' v'' at w. x - x(w) and v - v(w) are then c h^2 + d h^3 and
  /// k (c h^2 + d h^3) in h = u - w (the segment is cubic), so v is affine in t on the whole segment
  /// (a zero-length handle on the line v = t). The test is exact: no value is made up from rounding.
  [[nodiscard]] Real curvature_at(const Real& w, const Real& time) const {
    const Real xp = time_at(w, 1);
    if (xp == Real(0) && value_at(w, 1) == Real(0) && time_at(w, 2) * value_at(w, 3) == time_at(w, 3) * value_at(w, 2))
      return Real(0);
    if (!(xp > Real(0)))
      throw std::domain_error("d2v/dt2 at t = " + to_text(time) +
                              ": the segment's time derivative x'(u) vanishes there (vertical tangent or "
                              "zero-length time handle), so the second derivative is unbounded");
    const Real vp = value_at(w, 1), xpp = time_at(w, 2), vpp = value_at(w, 2);
    return (vpp * xp - vp * xpp) / (xp * xp * xp);
  }
};

}  // namespace curvebench::channel::detail
