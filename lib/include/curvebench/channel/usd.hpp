// The OpenUSD Ts spline (USD Anim) as a tool model over curvebench's keyframe channel: a Ts spline
// description (knots, curve type, anti-regression mode, extrapolation) turned into the function of
// time that USD evaluates, so that the same knots can be measured against their 50-digit truth.
// The rules are read from OpenUSD's public documentation of Ts (the Ts overview and "Regressive
// Splines in USD" pages, the documentation comments of TsKnot, TsSpline and types.h, and the
// USD Anim proposal; docs/references.md); no OpenUSD code is used. It is checked against values
// recorded from OpenUSD's Ts library itself (24.11, commit 899c19e; tests/test_usd_ts.cpp,
// tests/data/recorded/usd_ts_splines.json): where they differed, the rule was read in Ts's source (facts
// only) and is marked "(Ts 24.11)" below. Not modelled (tests/test_usd_ts.cpp lists each): Ts sets
// a limited tangent 1e-5 of the interval short of the ellipse, not on it (a difference of up to
// about 2 % of a segment's rise next to its vertical); and two Ts defects (a looping
// post-extrapolation takes repeat or oscillate from the pre-extrapolation's mode; next to inner
// loops, a knot they shadow still gives the pre-value and linear slope of the knot after them).
//
// Knots: usd_knot { time, value, next_interp, pre/post tangent as width (a time length >= 0) and
// slope (dv/dt), dual_valued, pre_value }. next_interp is the interpolation of the segment that
// follows the knot: held (the knot's value until the next knot, the step at the next knot), linear,
// curve (Bezier or Hermite, the spline's curve_type). A dual-valued knot has a pre-value: the
// value an instant before the knot time; at the knot time and after it the ordinary value holds.
// So a linear or curve segment ends at its end knot's pre-value; after a held segment the pre-value
// is ignored (the held value applies). Tangents of knots not adjacent to a curve segment, and the
// outward tangents of the end knots, have no effect.
// Curve segments: bezier: control points (t0, v0), (t0 + w0, v0 + s0 w0), (t1 - w1, v1 - s1 w1),
// (t1, v1) with w0 the start knot's post width, s0 its post slope, w1 and s1 the end knot's pre
// width and slope (as a channel::key's out and in handles). hermite: the widths are fixed at 1/3
// of the interval (the given widths are ignored): the cubic Hermite polynomial with the two slopes.
// Anti-regression (a segment of duration h, normalized widths a = w0 / h, c = w1 / h; time runs
// monotonically exactly when a + c <= 1 or (a + c - 1)^2 <= a c; the boundary of the second, an
// ellipse through (1, 0), (1, 1), (0, 1), (4/3, 1/3) and (1/3, 4/3), is the single vertical):
// - none: the widths are kept (authoring); evaluation then applies keep_ratio ("None ... will
//   result in Keep Ratio behavior at evaluation time");
// - contain: every curve tangent is clamped to the interval, a, c <= 1, regressive or not (bold
//   tangents are shortened too);
// - keep_ratio: a regressive (a, c) is scaled by k = 1 / (a + c - sqrt(a c)) onto the outer edge of
//   the ellipse (the intersection of the ray from the origin through (a, c) with the ellipse,
//   solved in closed form), keeping a : c;
// - keep_start (Maya): a regressive segment keeps a and moves c to the nearest point of the ellipse
//   on the line a = const, c = (2 - a +- sqrt(a (4 - 3 a))) / 2 (+ when c is beyond the upper edge,
//   - on the fringe a in (1, 4/3], where a short c lies below the lower edge); for a > 4/3 both
//   become (4/3, 1/3).
// usd_limit_widths applies one mode to one segment's (a, c); usd_apply_anti_regression to a whole
// spline (bezier curve segments only; hermite widths are fixed, held and linear have none);
// usd_is_regressive is the exact test. A limited segment lies on the ellipse up to rounding; its
// widths are then moved inside by 2 eps relative steps until the rounded control times pass the
// channel's monotonicity check (a few ulps; see detail::usd_settle). The model applies the
// spline's mode to the authored knots, bakes the inner loops, and then applies keep_ratio (USD's
// runtime limiting) to what still regresses (Ts 24.11: the authoring mode acts on the authored
// knots only; segments made by inner loops get the runtime keep_ratio alone).
// Extrapolation, before the first and after the last knot (usd_extrapolation { mode, slope }):
// - held: the end knot's value; linear: the line through the end knot whose slope is 0 after a held
//   end segment, the segment's slope for a linear one, and for a curve end segment the knot's
//   tangent on the segment's side (the first knot's post slope, the last knot's pre slope); sloped:
//   the line through the end knot with the given slope. Before the first knot the line starts from
//   its pre-value when it is dual-valued (the value an instant before the knot), after the last knot
//   from its ordinary value; linear extrapolation from a dual-valued end knot is flat (Ts 24.11);
// - loop_repeat: the knot range [t_first, t_last] repeated, iteration k (k whole periods
//   T = t_last - t_first away, negative before) offset by k (v_last - v_first) so that the ends
//   meet, v_first the first knot's pre-value when it is dual-valued (Ts 24.11); loop_reset:
//   repeated exactly (a jump at each join when v_last != v_first); loop_oscillate: every other
//   iteration reversed in time (t_last - r instead of t_first + r), dv/dt negated there, showing the
//   left side of each knot (after a held segment the previous knot's value, else the pre-value;
//   Ts 24.11). A looping extrapolation after the knots starts its iteration 1 at t_last itself
//   (reset: v_first there, oscillate: the last knot's left side; Ts 24.11).
// Inner loops (usd_loops, TsLoopParams; "Continue" mode): the prototype [proto_start, proto_end)
// is repeated num_pre_loops times before and num_post_loops times after itself by copying its knots
// whole (tangents kept), iteration j shifted by j P in time (P = proto_end - proto_start) and by
// j value_offset in value (and pre-value); a copy of the start knot (offset by num_post_loops + 1)
// closes the last iteration at proto_end + num_post_loops P. Authored knots inside the looped
// interval [proto_start - num_pre_loops P, proto_end + num_post_loops P] other than the
// prototype's are shadowed (ignored); a knot exactly at proto_end is not part of the prototype.
// The loop parameters are ignored unless proto_end > proto_start, a count is positive (negative
// counts are 0) and a knot sits exactly at proto_start. usd_bake_inner_loops does this; inner
// loops are resolved before anti-regression and before the extrapolating loops, which then repeat
// the whole baked knot range.
// A one-knot spline is constant, except sloped extrapolation, which keeps its line.
// Side convention: at a knot time the segment that starts there applies (the ordinary value; its
// derivatives from the right); the last knot's time gives its ordinary value and the left
// derivatives of the last segment, unless the extrapolation after it loops; a loop join
// t_first + k T starts iteration k. Whether t is at a join is decided as Ts decides it (Ts 24.11):
// the distance to the knots over T, rounded in Real, is a whole number (recorded random/08, 21, 24:
// t computed as t_first + 4 T, where an exact remainder put it at the end of iteration 3).
// Evaluation: usd_model<Real>(spline, solver) resolves the rules above into one two-key
// channel<Real> per segment (channel/channel.hpp) and evaluates value(t) and derivative(t, order)
// (order 0, 1, 2, exact) by locating the segment (binary search) and mapping times for the
// extrapolation; USD solves the Bezier time cubic in closed form (time_solver::closed_form, the
// default), and the exact twin is the same spline in real50 with time_solver::exact
// (usd_convert<real50>).
// Left out: value blocks (TsInterpValueBlock, TsExtrapValueBlock: no value), automatic tangents,
// half-precision values, the interactive anti-regression modes (limit_active, limit_opposite) and
// the [1/4, 4] ratio clamp mentioned for the keep-ratio prototype in the USD Anim proposal (the
// released documentation does not state it).
// Validation (invalid_input naming the knot index and field, with the value): no knots; non-finite
// time, value, widths, slopes or pre-value; non-finite loop parameters; negative widths; knot
// times not increasing or too close to be resolved (also after baking the inner loops); enum
// values outside their lists; a non-finite extrapolation slope. Evaluating at a non-finite time
// throws std::domain_error.
// Cost: O(n) construction (one channel per segment); per evaluation O(log n) search, a fmod for
// loops and the channel's cost (one closed-form cubic solve on a Bezier segment).
// Accuracy: the channel's on each segment with the chosen solver; with closed_form the Cardano /
// trigonometric solution cancels near multiple roots (and near the single vertical the limiting
// modes produce), measured against the exact twin in tests/test_usd.cpp as mixed errors of tens
// of ulps of the value range in float and double.
#pragma once

#include "curvebench/channel/channel.hpp"
#include "curvebench/channel/time_solver.hpp"
#include "curvebench/core/detail/segment_lookup.hpp"
#include "curvebench/core/error.hpp"
#include "curvebench/core/real.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace curvebench::channel {

/// The interpolation of the segment after a knot (TsInterpHeld, TsInterpLinear, TsInterpCurve).
enum class usd_interpolation : std::uint8_t { held, linear, curve };
/// The spline's curve type (TsCurveTypeBezier, TsCurveTypeHermite).
enum class usd_curve_type : std::uint8_t { bezier, hermite };
/// The anti-regression mode (TsAntiRegressionNone, ...Contain, ...KeepRatio, ...KeepStart).
enum class usd_anti_regression : std::uint8_t { none, contain, keep_ratio, keep_start };
/// The extrapolation mode (TsExtrapHeld, ...Linear, ...Sloped, ...LoopRepeat, ...LoopReset,
/// ...LoopOscillate).
enum class usd_extrapolation_mode : std::uint8_t { held, linear, sloped, loop_repeat, loop_reset, loop_oscillate };

inline constexpr std::array<usd_interpolation, 3> all_usd_interpolations{
    usd_interpolation::held, usd_interpolation::linear, usd_interpolation::curve};
inline constexpr std::array<usd_curve_type, 2> all_usd_curve_types{usd_curve_type::bezier, usd_curve_type::hermite};
inline constexpr std::array<usd_anti_regression, 4> all_usd_anti_regressions{
    usd_anti_regression::none, usd_anti_regression::contain, usd_anti_regression::keep_ratio,
    usd_anti_regression::keep_start};
inline constexpr std::array<usd_extrapolation_mode, 6> all_usd_extrapolation_modes{
    usd_extrapolation_mode::held,        usd_extrapolation_mode::linear,     usd_extrapolation_mode::sloped,
    usd_extrapolation_mode::loop_repeat, usd_extrapolation_mode::loop_reset, usd_extrapolation_mode::loop_oscillate};

[[nodiscard]] inline const char* to_string(usd_interpolation i) {
  switch (i) {
    case usd_interpolation::held: return "held";
    case usd_interpolation::linear: return "linear";
    case usd_interpolation::curve: return "curve";
  }
  return "unknown";
}
[[nodiscard]] inline const char* to_string(usd_curve_type c) {
  switch (c) {
    case usd_curve_type::bezier: return "bezier";
    case usd_curve_type::hermite: return "hermite";
  }
  return "unknown";
}
[[nodiscard]] inline const char* to_string(usd_anti_regression a) {
  switch (a) {
    case usd_anti_regression::none: return "none";
    case usd_anti_regression::contain: return "contain";
    case usd_anti_regression::keep_ratio: return "keep_ratio";
    case usd_anti_regression::keep_start: return "keep_start";
  }
  return "unknown";
}
[[nodiscard]] inline const char* to_string(usd_extrapolation_mode e) {
  switch (e) {
    case usd_extrapolation_mode::held: return "held";
    case usd_extrapolation_mode::linear: return "linear";
    case usd_extrapolation_mode::sloped: return "sloped";
    case usd_extrapolation_mode::loop_repeat: return "loop_repeat";
    case usd_extrapolation_mode::loop_reset: return "loop_reset";
    case usd_extrapolation_mode::loop_oscillate: return "loop_oscillate";
  }
  return "unknown";
}

template <>
[[nodiscard]] inline usd_interpolation from_string<usd_interpolation>(std::string_view name) {
  return detail::enum_from_string("usd interpolation", name, all_usd_interpolations);
}
template <>
[[nodiscard]] inline usd_curve_type from_string<usd_curve_type>(std::string_view name) {
  return detail::enum_from_string("usd curve type", name, all_usd_curve_types);
}
template <>
[[nodiscard]] inline usd_anti_regression from_string<usd_anti_regression>(std::string_view name) {
  return detail::enum_from_string("usd anti-regression", name, all_usd_anti_regressions);
}
template <>
[[nodiscard]] inline usd_extrapolation_mode from_string<usd_extrapolation_mode>(std::string_view name) {
  return detail::enum_from_string("usd extrapolation", name, all_usd_extrapolation_modes);
}

/// A Ts knot: time, value, the interpolation of the following segment, the pre and post tangents
/// (width >= 0 in time, slope dv/dt) and, when dual_valued, the pre-value.
template <class Real>
struct usd_knot {
  Real time{0};
  Real value{0};
  usd_interpolation next_interp = usd_interpolation::curve;
  Real pre_width{0};
  Real pre_slope{0};
  Real post_width{0};
  Real post_slope{0};
  bool dual_valued = false;
  Real pre_value{0};
};

/// Extrapolation on one side: the mode and, for sloped, the slope.
template <class Real>
struct usd_extrapolation {
  usd_extrapolation_mode mode = usd_extrapolation_mode::held;
  Real slope{0};
};

/// Inner-loop parameters (TsLoopParams): the prototype [proto_start, proto_end) repeated
/// num_pre_loops times before and num_post_loops times after it, each iteration offset in value by
/// value_offset from the previous one. Ignored unless proto_end > proto_start, a count is > 0 and a
/// knot sits at proto_start (negative counts count as 0).
template <class Real>
struct usd_loops {
  Real proto_start{0};
  Real proto_end{0};
  int num_pre_loops = 0;
  int num_post_loops = 0;
  Real value_offset{0};
};

/// A Ts spline description.
template <class Real>
struct usd_spline {
  std::vector<usd_knot<Real>> knots;
  usd_curve_type curve_type = usd_curve_type::bezier;
  usd_anti_regression anti_regression = usd_anti_regression::keep_ratio;
  usd_extrapolation<Real> pre{};
  usd_extrapolation<Real> post{};
  usd_loops<Real> inner_loops{};
};

/// One segment's tangent widths as fractions of its interval: a the start knot's post width, c the
/// end knot's pre width.
template <class Real>
struct usd_widths {
  Real start{0};
  Real end{0};
};

namespace detail {
/// sqrt(a c) for widths a, c >= 0: as USD computes it, and without the overflow of a c past 1e308
/// (widths of 1e155 and more) by sqrt(a) sqrt(c) there.
template <class Real>
[[nodiscard]] Real usd_sqrt_product(const Real& a, const Real& c) {
  using std::sqrt;
  const Real p = a * c;
  return is_finite(p) ? Real(sqrt(p)) : Real(sqrt(a) * sqrt(c));
}
}  // namespace detail

/// True when widths (a, c) (fractions of the interval, >= 0) make time run backwards somewhere
/// inside the segment: a + c > 1 and (a + c - 1)^2 > a c. The ellipse edge itself is not regressive.
/// Past the squares' overflow (widths of 1e155 and more), a + c - 1 > sqrt(a c), the same test.
template <class Real>
[[nodiscard]] bool usd_is_regressive(const Real& a, const Real& c) {
  const Real excess = a + c - Real(1);
  const Real square = excess * excess, product = a * c;
  if (is_finite(square) && is_finite(product)) return excess > Real(0) && square > product;
  return excess > Real(0) && excess > detail::usd_sqrt_product(a, c);
}

namespace detail {
// The mode's exact rule on (a, c) (see the header), unrounded intent; which_end says how the result
// was reached: 0 untouched, 1 scaled (keep_ratio, or keep_start's (4/3, 1/3)), 2 the end moved to
// the upper edge, 3 the end moved to the lower edge (keep_start's fringe).
template <class Real>
[[nodiscard]] std::pair<usd_widths<Real>, int> usd_rule(usd_anti_regression mode, const Real& a, const Real& c) {
  using std::sqrt;
  switch (mode) {
    case usd_anti_regression::none: return {{a, c}, 0};
    case usd_anti_regression::contain: return {{std::min(a, Real(1)), std::min(c, Real(1))}, 0};
    case usd_anti_regression::keep_ratio: {
      if (!usd_is_regressive(a, c)) return {{a, c}, 0};
      const Real k = Real(1) / (a + c - detail::usd_sqrt_product(a, c));
      return {{Real(a * k), Real(c * k)}, 1};
    }
    case usd_anti_regression::keep_start: {
      if (!usd_is_regressive(a, c)) return {{a, c}, 0};
      if (a >= Real(4) / Real(3)) return {{Real(4) / Real(3), Real(1) / Real(3)}, 1};
      const Real root = sqrt(a * (Real(4) - Real(3) * a));
      const Real upper = (Real(2) - a + root) / Real(2);
      const Real lower = (Real(2) - a - root) / Real(2);
      return c > upper ? std::pair<usd_widths<Real>, int>{{a, upper}, 2}
                       : std::pair<usd_widths<Real>, int>{{a, lower}, 3};
    }
  }
  validate::fail("anti-regression mode = " + std::to_string(static_cast<int>(mode)) + ": not a usd_anti_regression");
}

// A limited segment lies on the ellipse up to rounding, and its rounded control times relative
// to the segment's start (0, w0, h - w1, h), h = t1 - t0, which the channel checks, may then fail
// the channel's monotonicity check by a few ulps. Settle
// moves the widths inside by 2 eps relative per step (scaled widths shrink, an end moved to the
// upper edge shrinks, one moved to the lower edge grows) until the check passes; a few steps.
template <class Real>
void usd_settle(int how, Real& w0, Real& w1, const Real& t0, const Real& t1) {
  const Real step = Real(2) * epsilon<Real>();
  const Real h = t1 - t0;
  for (int i = 0; i < 64 && how != 0 && time_handles_regress(Real(0), w0, Real(h + Real(-w1)), h); ++i) {
    if (how == 1) w0 *= Real(1) - step;
    if (how == 1 || how == 2) w1 *= Real(1) - step;
    if (how == 3) w1 *= Real(1) + step;
  }
}
}  // namespace detail

/// The widths after one anti-regression mode (see the header); none returns them unchanged. A
/// limited result lies on the ellipse within a few ulps, on the side the channel accepts.
template <class Real>
[[nodiscard]] usd_widths<Real> usd_limit_widths(usd_anti_regression mode, const Real& a, const Real& c) {
  validate::finite("a", a);
  validate::finite("c", c);
  if (a < Real(0)) validate::fail("a = " + to_text(a) + ": a tangent width must be >= 0");
  if (c < Real(0)) validate::fail("c = " + to_text(c) + ": a tangent width must be >= 0");
  auto [w, how] = detail::usd_rule(mode, a, c);
  detail::usd_settle(how, w.start, w.end, Real(0), Real(1));
  return w;
}

namespace detail {
[[nodiscard]] inline std::string usd_field(std::size_t i, std::string_view field) {
  return validate::indexed("knots", i) + "." + std::string(field);
}

template <class Enum, std::size_t N>
[[nodiscard]] bool usd_known(Enum e, const std::array<Enum, N>& all) {
  return std::find(all.begin(), all.end(), e) != all.end();
}

template <class Real>
void usd_validate(const usd_spline<Real>& s) {
  validate::count_at_least("knots", s.knots.size(), 1, "a spline needs a knot; one knot makes a constant spline");
  if (!usd_known(s.curve_type, all_usd_curve_types))
    validate::fail("curve_type = " + std::to_string(static_cast<int>(s.curve_type)) + ": not a usd_curve_type");
  if (!usd_known(s.anti_regression, all_usd_anti_regressions))
    validate::fail("anti_regression = " + std::to_string(static_cast<int>(s.anti_regression)) +
                   ": not a usd_anti_regression");
  for (const auto& [name, e] : {std::pair<const char*, const usd_extrapolation<Real>*>{"pre", &s.pre},
                                std::pair<const char*, const usd_extrapolation<Real>*>{"post", &s.post}}) {
    if (!usd_known(e->mode, all_usd_extrapolation_modes))
      validate::fail(std::string(name) + ".mode = " + std::to_string(static_cast<int>(e->mode)) +
                     ": not a usd_extrapolation_mode");
    validate::finite(std::string(name) + ".slope", e->slope);
  }
  for (std::size_t i = 0; i < s.knots.size(); ++i) {
    const usd_knot<Real>& k = s.knots[i];
    validate::finite(usd_field(i, "time"), k.time);
    validate::finite(usd_field(i, "value"), k.value);
    validate::finite(usd_field(i, "pre_width"), k.pre_width);
    validate::finite(usd_field(i, "pre_slope"), k.pre_slope);
    validate::finite(usd_field(i, "post_width"), k.post_width);
    validate::finite(usd_field(i, "post_slope"), k.post_slope);
    if (k.dual_valued) validate::finite(usd_field(i, "pre_value"), k.pre_value);
    if (k.pre_width < Real(0))
      validate::fail(usd_field(i, "pre_width") + " = " + to_text(k.pre_width) + ": a tangent width must be >= 0");
    if (k.post_width < Real(0))
      validate::fail(usd_field(i, "post_width") + " = " + to_text(k.post_width) + ": a tangent width must be >= 0");
    if (!usd_known(k.next_interp, all_usd_interpolations))
      validate::fail(usd_field(i, "next_interp") + " = " + std::to_string(static_cast<int>(k.next_interp)) +
                     ": not a usd_interpolation");
    if (i > 0) {
      const Real& prev = s.knots[i - 1].time;
      if (!(k.time > prev))
        validate::fail("knot times must be increasing: " + usd_field(i, "time") + " = " + to_text(k.time) +
                       " <= " + usd_field(i - 1, "time") + " = " + to_text(prev));
      validate::resolvable(usd_field(i, "time") + " - " + usd_field(i - 1, "time"), prev, k.time);
    }
  }
}
}  // namespace detail

/// The spline with one anti-regression mode applied to its bezier curve segments (widths changed,
/// nothing else); a hermite spline is returned unchanged. Validates the spline first.
template <class Real>
[[nodiscard]] usd_spline<Real> usd_apply_anti_regression(usd_spline<Real> s, usd_anti_regression mode) {
  detail::usd_validate(s);
  if (!detail::usd_known(mode, all_usd_anti_regressions))
    validate::fail("anti-regression mode = " + std::to_string(static_cast<int>(mode)) + ": not a usd_anti_regression");
  if (s.curve_type == usd_curve_type::hermite || mode == usd_anti_regression::none) return s;
  for (std::size_t i = 0; i + 1 < s.knots.size(); ++i) {
    usd_knot<Real>& k0 = s.knots[i];
    usd_knot<Real>& k1 = s.knots[i + 1];
    if (k0.next_interp != usd_interpolation::curve) continue;
    const Real h = k1.time - k0.time;
    if (mode == usd_anti_regression::contain) {  // in absolute widths: no rounding of untouched widths
      k0.post_width = std::min(k0.post_width, h);
      k1.pre_width = std::min(k1.pre_width, h);
      continue;
    }
    const Real a = k0.post_width / h, c = k1.pre_width / h;
    if (!usd_is_regressive(a, c)) continue;
    const auto [w, how] = detail::usd_rule(mode, a, c);
    if (how == 1 && mode == usd_anti_regression::keep_ratio) {  // scaled in absolute widths
      const Real k = Real(1) / (a + c - detail::usd_sqrt_product(a, c));
      k0.post_width *= k;
      k1.pre_width *= k;
    } else {
      if (w.start != a) k0.post_width = w.start * h;  // keep_start keeps the start width as given
      k1.pre_width = w.end * h;
    }
    detail::usd_settle(how, k0.post_width, k1.pre_width, k0.time, k1.time);
  }
  return s;
}

/// The two channel keys of segment i (0 <= i < knots - 1) of a spline whose widths are already
/// final: held -> constant, linear -> linear, curve -> bezier (widths as given) or hermite (widths
/// h / 3); the end key carries the end knot's pre-value when it is dual-valued.
template <class Real>
[[nodiscard]] std::vector<key<Real>> usd_segment_keys(const usd_spline<Real>& s, std::size_t i) {
  if (i + 1 >= s.knots.size())
    validate::fail("segment = " + std::to_string(i) + ": a spline with " + std::to_string(s.knots.size()) +
                   " knots has segments 0 to " + std::to_string(s.knots.size()) + " - 2");
  const usd_knot<Real>& k0 = s.knots[i];
  const usd_knot<Real>& k1 = s.knots[i + 1];
  const Real h = k1.time - k0.time;
  key<Real> a{k0.time, k0.value, {}, {}, interpolation::linear};
  key<Real> b{k1.time, k1.dual_valued ? k1.pre_value : k1.value, {}, {}, interpolation::linear};
  switch (k0.next_interp) {
    case usd_interpolation::held: a.interp = interpolation::constant; break;
    case usd_interpolation::linear: a.interp = interpolation::linear; break;
    case usd_interpolation::curve: {
      const bool hermite = s.curve_type == usd_curve_type::hermite;
      const Real w0 = hermite ? Real(h / Real(3)) : k0.post_width;
      const Real w1 = hermite ? Real(h / Real(3)) : k1.pre_width;
      a.interp = hermite ? interpolation::hermite : interpolation::bezier;
      a.out = {w0, Real(k0.post_slope * w0)};
      b.in = {Real(-w1), Real(-(k1.pre_slope * w1))};
      break;
    }
  }
  return {a, b};
}

/// The most knots a spline's inner loops may bake into (2^21, about what a 64 MiB spec can hold).
inline constexpr std::size_t usd_max_baked_knots = std::size_t(1) << 21;

/// The spline with its inner loops baked into knots (and the loop parameters cleared), as the Ts
/// documentation describes them (see the header); a spline without valid loops is returned as is.
template <class Real>
[[nodiscard]] usd_spline<Real> usd_bake_inner_loops(usd_spline<Real> s) {
  const usd_loops<Real> p = s.inner_loops;
  s.inner_loops = {};
  validate::finite("inner_loops.proto_start", p.proto_start);
  validate::finite("inner_loops.proto_end", p.proto_end);
  validate::finite("inner_loops.value_offset", p.value_offset);
  const int pre = std::max(p.num_pre_loops, 0), post = std::max(p.num_post_loops, 0);
  const auto start =
      std::find_if(s.knots.begin(), s.knots.end(), [&](const usd_knot<Real>& k) { return k.time == p.proto_start; });
  if (!(p.proto_end > p.proto_start) || (pre == 0 && post == 0) || start == s.knots.end()) return s;
  const Real period = p.proto_end - p.proto_start;
  const Real lo = p.proto_start - Real(pre) * period, hi = p.proto_end + Real(post) * period;
  std::vector<usd_knot<Real>> proto, baked;
  for (const auto& k : s.knots)
    if (k.time >= p.proto_start && k.time < p.proto_end) proto.push_back(k);
  // Each count is capped on its own; their product with the prototype is capped here, before any
  // knot is copied (200 prototype knots looped 1e5 times were 2e7 knots and 2.3 GB).
  // Divided first, so that the product is formed only when it cannot overflow.
  const unsigned long long iterations =
      static_cast<unsigned long long>(pre) + static_cast<unsigned long long>(post) + 1;
  const bool over = proto.size() > usd_max_baked_knots / iterations ||
                    iterations * proto.size() + s.knots.size() + 1 > usd_max_baked_knots;
  if (over)
    validate::fail("inner_loops: (pre_loops = " + std::to_string(pre) + " + post_loops = " + std::to_string(post) +
                   " + 1) x " + std::to_string(proto.size()) + " prototype knots: more than the " +
                   std::to_string(usd_max_baked_knots) + " knots a spline may bake");
  const auto echo = [&](usd_knot<Real> k, int j) {
    k.time += Real(j) * period;
    k.value += Real(j) * p.value_offset;
    if (k.dual_valued) k.pre_value += Real(j) * p.value_offset;
    return k;
  };
  for (const auto& k : s.knots)
    if (k.time < lo) baked.push_back(k);
  for (int j = -pre; j <= post; ++j)
    for (const auto& k : proto) baked.push_back(echo(k, j));
  baked.push_back(echo(*start, post + 1));  // the start knot's copy closes the last iteration
  for (const auto& k : s.knots)
    if (k.time > hi) baked.push_back(k);
  s.knots = std::move(baked);
  return s;
}

/// The spline's numbers converted to another Real (enums and flags copied).
template <class To, class From>
[[nodiscard]] usd_spline<To> usd_convert(const usd_spline<From>& s) {
  usd_spline<To> r;
  r.curve_type = s.curve_type;
  r.anti_regression = s.anti_regression;
  r.pre = {s.pre.mode, To(s.pre.slope)};
  r.post = {s.post.mode, To(s.post.slope)};
  r.inner_loops = {To(s.inner_loops.proto_start), To(s.inner_loops.proto_end), s.inner_loops.num_pre_loops,
                   s.inner_loops.num_post_loops, To(s.inner_loops.value_offset)};
  for (const auto& k : s.knots)
    r.knots.push_back({To(k.time), To(k.value), k.next_interp, To(k.pre_width), To(k.pre_slope), To(k.post_width),
                       To(k.post_slope), k.dual_valued, To(k.pre_value)});
  return r;
}

/// What USD evaluates for a spline (see the header): the authoring mode, then keep_ratio, then one
/// channel per segment solved by `solver` (closed_form is USD's; exact gives the truth in real50).
template <class Real>
class usd_model {
 public:
  using real_type = Real;

  explicit usd_model(const usd_spline<Real>& spline, time_solver solver = time_solver::closed_form)
      : resolved_(usd_apply_anti_regression(
            usd_bake_inner_loops(usd_apply_anti_regression(validated(spline), spline.anti_regression)),
            usd_anti_regression::keep_ratio)),
        solver_(solver) {
    if (std::string_view(to_string(solver)) == "unknown")
      validate::fail("time solver = " + std::to_string(static_cast<int>(solver)) + ": not a time_solver");
    const auto& k = resolved_.knots;
    for (const auto& knot : k) times_.push_back(knot.time);
    for (std::size_t i = 0; i + 1 < k.size(); ++i)
      segments_.emplace_back(usd_segment_keys(resolved_, i), extrapolation::constant, extrapolation::constant, solver);
    const std::size_t n = k.size();
    if (n > 1) {
      slope_first_ = end_slope(0, true);
      slope_last_ = end_slope(n - 2, false);
    }
  }

  /// The value at time t (any finite t).
  [[nodiscard]] Real value(const Real& t) const { return eval(t, 0); }
  /// d^order v / dt^order at t, order 0, 1 or 2 (the channel's rules at vertical tangents).
  [[nodiscard]] Real derivative(const Real& t, int order) const {
    validate::derivative_order(order);
    if (order > 2)
      validate::fail("order = " + std::to_string(order) + ": a USD spline's time derivatives go to order 2");
    return eval(t, order);
  }

  /// The spline as evaluated: the authoring mode and the runtime keep_ratio applied.
  [[nodiscard]] const usd_spline<Real>& resolved() const { return resolved_; }
  [[nodiscard]] time_solver solver() const { return solver_; }
  /// The linear extrapolation slopes at the first and last knot (0 for one knot).
  [[nodiscard]] Real linear_slope_before() const { return slope_first_; }
  [[nodiscard]] Real linear_slope_after() const { return slope_last_; }

 private:
  static const usd_spline<Real>& validated(const usd_spline<Real>& s) {
    detail::usd_validate(s);
    return s;
  }
  usd_spline<Real> resolved_;
  time_solver solver_;
  std::vector<Real> times_;
  std::vector<channel<Real>> segments_;
  Real slope_first_{0}, slope_last_{0};

  [[nodiscard]] Real end_slope(std::size_t seg, bool first) const {
    const auto& k0 = resolved_.knots[seg];
    const auto& k1 = resolved_.knots[seg + 1];
    if (first ? k0.dual_valued : k1.dual_valued) return Real(0);  // a dual-valued end knot: flat
    switch (k0.next_interp) {
      case usd_interpolation::held: return Real(0);
      case usd_interpolation::linear:
        return ((k1.dual_valued ? k1.pre_value : k1.value) - k0.value) / (k1.time - k0.time);
      case usd_interpolation::curve: return first ? k0.post_slope : k1.pre_slope;
    }
    return Real(0);
  }

  [[nodiscard]] Real eval(const Real& t, int order) const {
    if (!is_finite(t)) throw std::domain_error("t = " + to_text(t) + ": a spline is evaluated at finite times only");
    const auto& k = resolved_.knots;
    const Real t_first = times_.front(), t_last = times_.back();
    if (t < t_first) return extrapolate(resolved_.pre, true, t, order);
    if (t > t_last || k.size() == 1 || (t == t_last && looping(resolved_.post.mode)))
      return extrapolate(resolved_.post, false, t, order);
    return inside(t, order);
  }

  [[nodiscard]] static bool looping(usd_extrapolation_mode m) {
    return m == usd_extrapolation_mode::loop_repeat || m == usd_extrapolation_mode::loop_reset ||
           m == usd_extrapolation_mode::loop_oscillate;
  }

  // The value an instant before t inside [t_first, t_last] (the side a reversed loop iteration
  // shows): at a knot after a held segment the previous knot's value, at another knot its pre-value
  // (its value when not dual-valued), between knots the value; derivatives from the left at knots.
  [[nodiscard]] Real inside_left(const Real& t, int order) const {
    const auto it = std::lower_bound(times_.begin(), times_.end(), t);
    if (it == times_.end() || *it != t) return inside(t, order);
    const std::size_t i = static_cast<std::size_t>(it - times_.begin());
    const auto& k = resolved_.knots;
    if (order > 0) return i == 0 ? inside(t, order) : segments_[i - 1].derivative(t, order);
    if (i > 0 && k[i - 1].next_interp == usd_interpolation::held) return k[i - 1].value;
    return k[i].dual_valued ? k[i].pre_value : k[i].value;
  }

  [[nodiscard]] Real inside(const Real& t, int order) const {
    std::size_t i = curvebench::detail::breakpoint_at_or_below<Real>(times_, t);
    if (i >= segments_.size()) {  // the last knot's time: its ordinary value, the left derivatives
      if (order == 0) return resolved_.knots.back().value;
      i = segments_.size() - 1;
    }
    return order == 0 ? segments_[i].value(t) : segments_[i].derivative(t, order);
  }

  [[nodiscard]] Real extrapolate(const usd_extrapolation<Real>& e, bool before, const Real& t, int order) const {
    const auto& k = resolved_.knots;
    const usd_knot<Real>& end = before ? k.front() : k.back();
    const Real v0 = before && end.dual_valued ? end.pre_value : end.value;
    const Real dt = t - end.time;
    const bool single = k.size() == 1;
    switch (e.mode) {
      case usd_extrapolation_mode::held: return order == 0 ? v0 : Real(0);
      case usd_extrapolation_mode::linear:
      case usd_extrapolation_mode::sloped: {
        const Real slope = e.mode == usd_extrapolation_mode::sloped ? e.slope
                           : single                                 ? Real(0)
                           : before                                 ? slope_first_
                                                                    : slope_last_;
        if (order == 0) return v0 + slope * dt;
        return order == 1 ? slope : Real(0);
      }
      case usd_extrapolation_mode::loop_repeat:
      case usd_extrapolation_mode::loop_reset:
      case usd_extrapolation_mode::loop_oscillate: {
        if (single) return order == 0 ? v0 : Real(0);
        using std::abs;
        using std::floor;
        using std::fmod;
        using std::round;
        const Real t_first = times_.front(), t_last = times_.back();
        const Real period = t_last - t_first;
        // The whole iterations between t and the knots, as Ts counts them (Ts 24.11): the
        // distance to the nearer end of the knots over the period, rounded in Real, truncated; one
        // hop more, except before the knots at an exact boundary (the value there starts an
        // iteration). t hops by whole periods (one rounding of n T, one of the sum).
        const Real offset = before ? Real(t_first - t) : Real(t - t_last);
        const Real frac = offset / period;
        const Real whole = floor(frac);
        const Real hops = before && whole == frac ? whole : Real(whole + Real(1));
        const Real iteration = before ? Real(-hops) : hops;
        const Real hopped = Real(t - Real(iteration * period));
        const bool mirrored =
            e.mode == usd_extrapolation_mode::loop_oscillate && fmod(abs(iteration), Real(2)) == Real(1);
        const Real local =
            std::clamp(mirrored ? Real(t_first + Real(period - Real(hopped - t_first))) : hopped, t_first, t_last);
        Real result = mirrored ? inside_left(local, order) : inside(local, order);
        if (mirrored && order == 1) result = -result;
        if (e.mode == usd_extrapolation_mode::loop_repeat && order == 0) {
          const usd_knot<Real>& first = k.front();
          result += iteration * (k.back().value - (first.dual_valued ? first.pre_value : first.value));
        }
        return result;
      }
    }
    return Real(0);
  }
};

}  // namespace curvebench::channel
