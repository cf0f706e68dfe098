// Robert Penner's easing equations as Blender's F-curves apply them between two keys (keyframe
// interpolation SINE, QUAD, CUBIC, QUART, QUINT, EXPO, CIRC, BACK, BOUNCE, ELASTIC with the easing
// EASE_IN, EASE_OUT, EASE_IN_OUT or AUTO): the value at time t in [0, d] of a segment that starts
// at value b and changes by c over the duration d, and its exact first and second time derivatives.
//
// Each family is an "in" offset E(t) with E(0) = 0 and E(d) = c (Penner's easeIn minus b); the
// modes are built from it the way Penner's easeOut and easeInOut are:
//   in      b + E(t)
//   out     b + c - E(d - t)                      (the point reflection of in)
//   in_out  b + E2(2t) / 2 for t < d/2, else b + c - E2(2d - 2t) / 2, where E2 is E with back
//           multiplied by 1.525 and elastic's default period 0.45 d (Penner's easeInOut constants)
//   automatic  out for back, bounce and elastic, in for the others (Blender's AUTO easing, which its
//           API reference describes as ease-in for the transition families and ease-out for the
//           dynamic ones).
// With x = t / d the in offsets are E = c G(x):
//   sine 1 - cos(pi x / 2); quad .. quint x^2 .. x^5; circ 1 - sqrt(1 - x^2);
//   back x^2 ((s + 1) x - s), s = back (any finite value; 0 gives x^3; Blender's keys inserted
//        from the UI carry 1.70158, Penner's 10% overshoot);
//   bounce 1 - B(1 - x), B Penner's easeOutBounce: four parabolas 121/16 (y - m)^2 + h joined at
//        y = 4/11, 8/11, 10/11 (m = 0, 6/11, 9/11, 21/22; h = 0, 3/4, 15/16, 63/64);
//   expo (2^(10 x) - 1) / (2^10 - 1): Penner's 2^(10 (x - 1)) moved and scaled so that it starts at
//        0 instead of jumping from 0 to 2^-10 just after x = 0 (Blender's normalisation, measured:
//        its values next to the ends are within float rounding of this and 2^-10 c away from
//        Penner's).
//   elastic, with amplitude a >= 0 and period p (in the time unit of t; p = 0 means 0.3 d, 0.45 d
//        for in_out; negative p is used as given) and u = t - d <= 0, w = 2 pi / p:
//          E(t) = -F f(u) 2^(10 u / d) sin((u - s) w)
//        a >= |c| and a > 0: Penner's: F = a, s = asin(c / a) / w, f = 1;
//        otherwise (a < |c|, or a = 0): F = c, s = p / 4 and, where Penner raises a to |c|, Blender
//        scales the wave by a / |c| instead (0 for a = 0: no wave), and over the last quarter
//        period |u| < |s| blends the scale linearly up to 1 at u = 0 so that E(d) = c still holds:
//        f(u) = a/|c| + (1 - a/|c|)(1 - |u| / |s|) there, a/|c| elsewhere (1 if c = 0, where the
//        wave is 0 anyway).
//        The wave does not reach 0 at t = 0: E(0) = -F f 2^-10 sin((-d - s) w), and Penner's (and
//        Blender's) value is b there by a special case; the value at t = 0 and t = d is therefore
//        b and b + c exactly for every family, and the derivatives there are the one-sided
//        limits of the formulas from inside the segment.
//        Blender's ease-out is the exact reflection of its ease-in also for a >= |c|, where
//        Penner's published easeOutElastic starts the wave with the other phase (measured: the
//        recorded Blender values follow the reflection, 2.7 c away from Penner's easeOut).
// Pieces: bounce's parabolas (a point exactly at a join takes the later piece, as Penner's `<`
// tests do), elastic's blend zone |u| = |s| (first derivative jumps), in_out's midpoint (t = d/2
// takes the second half; the second derivative jumps there). Where the first derivative is
// infinite (circ's vertical tangent at the end of in, the start of out, the middle of in_out) the
// derivative throws std::domain_error.
// Sources: R. Penner, "Robert Penner's Programming Macromedia Flash MX" ch. 7 and his easing
// equations (BSD licence); Blender's manual and Python API reference (defaults, AUTO); the
// normalisations above were decided by Blender 3.4.1's own values (tests/data/blender_easing.json,
// scripts/peers/blender_fcurves.py). See docs/references.md. Blender's (GPL) source was not used.
// Validation: invalid_input naming the argument and value: t, begin, change, back, amplitude and
// period must be finite, duration finite and > 0, amplitude >= 0 (Blender's property range), order
// 0, 1 or 2; names that are not a family or mode. t outside [0, duration] -> std::domain_error.
// Cost: O(1): one or two elementary functions (cos, sqrt, expm1, exp and sin, asin for elastic).
// Accuracy: within a few eps of |b| + |c| (+ a for elastic) plus the rounding of t amplified by
// the slope, measured against real50 in tests/test_penner.cpp; expo uses expm1 and sine
// 2 sin^2(pi x / 4), circ x^2 / (1 + sqrt((1 - x)(1 + x))), so small offsets keep their digits.
#pragma once

#include "curvebench/core/error.hpp"
#include "curvebench/core/real.hpp"

#include <boost/math/constants/constants.hpp>
#include <boost/math/special_functions/expm1.hpp>

#include <array>
#include <cmath>
#include <stdexcept>
#include <string>
#include <string_view>

namespace curvebench::channel {

/// Penner's ten easing families (Blender's interpolation modes of the same names).
enum class penner_family { sine, quad, cubic, quart, quint, expo, circ, back, bounce, elastic };
/// Which end the easing is applied to; automatic is Blender's AUTO (out for back, bounce, elastic).
enum class ease_mode { in, out, in_out, automatic };

inline constexpr std::array<penner_family, 10> all_penner_families{
    penner_family::sine, penner_family::quad, penner_family::cubic, penner_family::quart,  penner_family::quint,
    penner_family::expo, penner_family::circ, penner_family::back,  penner_family::bounce, penner_family::elastic};
inline constexpr std::array<ease_mode, 4> all_ease_modes{ease_mode::in, ease_mode::out, ease_mode::in_out,
                                                         ease_mode::automatic};

[[nodiscard]] inline const char* to_string(penner_family f) {
  switch (f) {
    case penner_family::sine: return "sine";
    case penner_family::quad: return "quad";
    case penner_family::cubic: return "cubic";
    case penner_family::quart: return "quart";
    case penner_family::quint: return "quint";
    case penner_family::expo: return "expo";
    case penner_family::circ: return "circ";
    case penner_family::back: return "back";
    case penner_family::bounce: return "bounce";
    case penner_family::elastic: return "elastic";
  }
  return "unknown";
}

[[nodiscard]] inline const char* to_string(ease_mode m) {
  switch (m) {
    case ease_mode::in: return "in";
    case ease_mode::out: return "out";
    case ease_mode::in_out: return "in_out";
    case ease_mode::automatic: return "automatic";
  }
  return "unknown";
}

/// The family named `name` (lowercase, as to_string writes it).
[[nodiscard]] inline penner_family penner_family_from_string(std::string_view name) {
  for (penner_family f : all_penner_families)
    if (name == to_string(f)) return f;
  validate::fail("penner family = \"" + std::string(name) +
                 "\": unknown (expected sine, quad, cubic, quart, quint, expo, circ, back, bounce or elastic)");
}

/// The mode named `name` (lowercase, as to_string writes it).
[[nodiscard]] inline ease_mode ease_mode_from_string(std::string_view name) {
  for (ease_mode m : all_ease_modes)
    if (name == to_string(m)) return m;
  validate::fail("ease mode = \"" + std::string(name) + "\": unknown (expected in, out, in_out or automatic)");
}

/// The mode Blender uses: automatic resolved to out for back, bounce and elastic, in otherwise.
[[nodiscard]] inline ease_mode resolve(penner_family f, ease_mode m) {
  if (m != ease_mode::automatic) return m;
  const bool dynamic = f == penner_family::back || f == penner_family::bounce || f == penner_family::elastic;
  return dynamic ? ease_mode::out : ease_mode::in;
}

/// A key's easing parameters; the defaults are those of a key Blender inserts (back 1.70158,
/// amplitude 0.8, period 4.1; keyframe_points.add() in Python gives 0, 0, 0 instead).
template <class Real>
struct penner_params {
  Real back = Real(170158) / Real(100000);  ///< back's overshoot s (any finite value)
  Real amplitude = Real(4) / Real(5);       ///< elastic's amplitude a >= 0, in value units
  Real period = Real(41) / Real(10);        ///< elastic's period p in time units; 0 means 0.3 d (0.45 d in_out)
};

namespace detail {

/// A value with its first two derivatives.
template <class Real>
struct penner_jet {
  Real v, d1, d2;
};

/// The normalized in-function G(x) and its derivatives in x for the non-elastic families.
template <class Real>
penner_jet<Real> penner_in_normalized(penner_family f, const Real& x, const Real& back) {
  using std::cos;
  using std::exp;
  using std::sin;
  using std::sqrt;
  switch (f) {
    case penner_family::sine: {
      const Real h = boost::math::constants::half_pi<Real>();
      const Real q = sin(h * x / Real(2));
      return {Real(2) * q * q, h * sin(h * x), h * h * cos(h * x)};
    }
    case penner_family::quad: return {x * x, Real(2) * x, Real(2)};
    case penner_family::cubic: return {x * x * x, Real(3) * x * x, Real(6) * x};
    case penner_family::quart: return {x * x * x * x, Real(4) * x * x * x, Real(12) * x * x};
    case penner_family::quint: return {x * x * x * x * x, Real(5) * x * x * x * x, Real(20) * x * x * x};
    case penner_family::expo: {
      const Real k = Real(10) * boost::math::constants::ln_two<Real>();
      const Real n = Real(1023);  // 2^10 - 1
      const Real e = exp(k * x);
      return {boost::math::expm1(k * x) / n, k * e / n, k * k * e / n};
    }
    case penner_family::circ: {
      const Real w = (Real(1) - x) * (Real(1) + x);  // 1 - x^2 without cancellation
      const Real r = sqrt(w);
      return {x * x / (Real(1) + r), x / r, Real(1) / (w * r)};
    }
    case penner_family::back: {
      const Real s = back;
      return {x * x * ((s + Real(1)) * x - s), Real(3) * (s + Real(1)) * x * x - Real(2) * s * x,
              Real(6) * (s + Real(1)) * x - Real(2) * s};
    }
    case penner_family::bounce: {
      // G(x) = 1 - B(y), y = 1 - x, B = 121/16 (y - m)^2 + h on the piece holding y.
      const Real y = Real(1) - x;
      const Real e = Real(11);
      Real m, h;
      if (y < Real(4) / e) {
        m = Real(0);
        h = Real(0);
      } else if (y < Real(8) / e) {
        m = Real(6) / e;
        h = Real(3) / Real(4);
      } else if (y < Real(10) / e) {
        m = Real(9) / e;
        h = Real(15) / Real(16);
      } else {
        m = Real(21) / Real(22);
        h = Real(63) / Real(64);
      }
      const Real k = Real(121) / Real(16);
      const Real z = y - m;
      return {Real(1) - (k * z * z + h), Real(2) * k * z, -Real(2) * k};
    }
    case penner_family::elastic: break;
  }
  throw std::logic_error("penner_in_normalized: elastic has no normalized form");
}

/// Elastic's in offset E and its derivatives in t at u = t - d (see the header comment).
template <class Real>
penner_jet<Real> penner_elastic_in(const Real& u, const Real& c, const Real& d, const Real& a, const Real& p) {
  using std::abs;
  using std::asin;
  using std::cos;
  using std::exp;
  using std::sin;
  const Real w = boost::math::constants::two_pi<Real>() / p;
  Real big_f, s, f(1), df(0);
  if (a > Real(0) && a >= abs(c)) {
    big_f = a;
    s = asin(c / a) / w;
  } else {
    big_f = c;
    s = p / Real(4);
    const Real ratio = c == Real(0) ? Real(1) : a / abs(c);
    f = ratio;
    const Real as = abs(s);
    if (abs(u) < as) {  // u <= 0: |u| = -u
      f = ratio + (Real(1) - ratio) * (Real(1) + u / as);
      df = (Real(1) - ratio) / as;
    }
  }
  const Real k = Real(10) * boost::math::constants::ln_two<Real>() / d;
  const Real pw = exp(k * u);
  const Real sn = sin((u - s) * w);
  const Real cs = cos((u - s) * w);
  const Real g = f * pw * sn;
  const Real g1 = df * pw * sn + f * pw * (k * sn + w * cs);
  const Real g2 = Real(2) * df * pw * (k * sn + w * cs) + f * pw * ((k * k - w * w) * sn + Real(2) * k * w * cs);
  return {-big_f * g, -big_f * g1, -big_f * g2};
}

/// The in offset E(t) for t in [0, d] with the given parameters (period already defaulted).
template <class Real>
penner_jet<Real> penner_in_offset(penner_family f, const Real& t, const Real& c, const Real& d, const Real& back,
                                  const Real& a, const Real& p) {
  if (f == penner_family::elastic) return penner_elastic_in(Real(t - d), c, d, a, p);
  const penner_jet<Real> g = penner_in_normalized(f, Real(t / d), back);
  return {c * g.v, c * g.d1 / d, c * g.d2 / (d * d)};
}

}  // namespace detail

/// The value (order 0) or the order-th time derivative (1, 2) at t in [0, duration] of the segment
/// from `begin` changing by `change` over `duration`, eased by `family` in `mode` with `params`.
template <class Real>
[[nodiscard]] Real penner_ease(penner_family family, ease_mode mode, const penner_params<Real>& params, const Real& t,
                               const Real& begin, const Real& change, const Real& duration, int order = 0) {
  validate::finite("t", t);
  validate::finite("begin", begin);
  validate::finite("change", change);
  validate::positive("duration", duration);
  validate::finite("back", params.back);
  validate::finite("amplitude", params.amplitude);
  if (params.amplitude < Real(0))
    validate::fail("amplitude = " + to_text(params.amplitude) + ": must be >= 0 (Blender's range)");
  validate::finite("period", params.period);
  validate::derivative_order(order);
  if (order > 2) validate::fail("order = " + std::to_string(order) + ": penner_ease gives orders 0, 1 and 2");
  if (!(Real(0) <= t && t <= duration))
    throw std::domain_error("t = " + to_text(t) + ": outside the segment [0, duration = " + to_text(duration) + "]");

  const ease_mode m = resolve(family, mode);
  if (order == 0 && t == Real(0)) return begin;
  if (order == 0 && t == duration) return begin + change;

  const Real& d = duration;
  const Real& c = change;
  const bool halves = m == ease_mode::in_out;
  const Real back = halves ? params.back * (Real(1525) / Real(1000)) : params.back;
  const Real period =
      params.period != Real(0) ? params.period : (halves ? Real(45) / Real(100) : Real(3) / Real(10)) * d;
  const auto offset = [&](const Real& at) {
    return detail::penner_in_offset(family, at, c, d, back, params.amplitude, period);
  };

  Real v, d1, d2;
  if (m == ease_mode::in) {
    const auto e = offset(t);
    v = begin + e.v;
    d1 = e.d1;
    d2 = e.d2;
  } else if (m == ease_mode::out) {
    const auto e = offset(Real(d - t));
    v = begin + c - e.v;
    d1 = e.d1;
    d2 = -e.d2;
  } else if (t < d / Real(2)) {
    const auto e = offset(Real(Real(2) * t));
    v = begin + e.v / Real(2);
    d1 = e.d1;
    d2 = Real(2) * e.d2;
  } else {
    const auto e = offset(Real(Real(2) * (d - t)));
    v = begin + c - e.v / Real(2);
    d1 = e.d1;
    d2 = -Real(2) * e.d2;
  }
  const Real& r = order == 0 ? v : (order == 1 ? d1 : d2);
  if (!is_finite(r))
    throw std::domain_error(std::string("penner_ease: the ") + (order == 1 ? "first" : "second") + " derivative of " +
                            to_string(family) + " " + to_string(m) + " is unbounded at t = " + to_text(t));
  return r;
}

}  // namespace curvebench::channel
