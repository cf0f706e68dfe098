// The Maya animCurve tool model: the rules that turn a Maya animation curve's description (keys
// with in and out tangent types, fixed tangents, a weighted flag, pre and post infinity) into what
// Maya evaluates, built on the keyframe channel (channel/channel.hpp), so that the same keys can be
// evaluated as Maya does (double, the isolate_brent time solver) and exactly (real50, the exact
// solver) and the two compared.
//
// Keys: maya_key { time, value, in_type, out_type, in_x, in_y, out_x, out_y }. Times are in one
// unit throughout (frames or seconds, whichever the caller uses; Maya stores key times in the
// scene's time unit, its API's tangents in seconds: convert before building). A fixed tangent is
// the vector (x, y), x > 0, in (time, value) units, pointing forwards in time on both sides (as
// Maya stores kix/kiy and kox/koy): its slope is y / x. On a weighted curve the vector is also the
// handle: the Bezier control point is key + (x, y) / 3 (out) or key - (x, y) / 3 (in), so a vector
// of x = the segment's duration puts the handle at a third. tangent_from_angle(angle, weight) makes
// (x, y) = 3 weight (cos angle, sin angle) from Maya's angle (radians) and weight (the handle's
// length in the (time, value) plane).
// Tangent rules (slopes dv/dt; Maya Help, "Graph Editor Tangents menu" and "Graph Editor Curves
// menu", and Autodesk AnimX (Apache-2.0), src/animx.cpp, Maya's own animation-curve evaluator,
// docs/references.md; facts only, no code or text taken). AnimX evaluates the tangents Maya
// stores with each key; of the computed types it derives only flat and the auto family, so the
// spline, linear, clamped and plateau slopes below rest on the Help alone. n = the number of keys,
// d_l and d_r = the chord slopes to the previous and the next key, (v_i - v_{i-1}) / (t_i - t_{i-1})
// and (v_{i+1} - v_i) / (t_{i+1} - t_i):
// - fixed: y / x of the given vector.
// - linear: the tangent lies along the straight line to the neighbouring key: in = d_l, out = d_r;
//   an end key's missing side takes the other side's chord. A segment linear on both sides is the
//   straight line (AnimX interpolates such a span linearly; the Hermite / Bezier with chord slopes
//   at thirds is that line).
// - flat: 0 (AnimX: value offset 0, time offset the adjacent segment's duration, so a weighted
//   handle sits at a third; an end key uses its only segment).
// - step (out side): the key's value holds until the next key (channel constant); step_next (out
//   side): the next key's value from just after the key (channel step_next). Only the segment's
//   start key's out type makes a segment stepped (AnimX decides a span's method from its start
//   key's out tangent); a step or step_next in tangent has slope 0 (AnimX leaves it to the stored
//   tangent: not settled).
// - spline: a smooth pass from the previous key to the next, both tangents co-linear: the slope
//   of the chord through the two neighbours, (v_{i+1} - v_{i-1}) / (t_{i+1} - t_{i-1})
//   (Catmull-Rom-like); an end key takes the chord to its only neighbour.
// - clamped: spline, except where two neighbouring keys have (nearly) the same value, where the
//   tangents between them become linear (the Help describes it so): per side, when
//   |v_i - v_j| <= clamp_tolerance * max(1, |v_i|, |v_j|) for the neighbour j on that side, that
//   side's slope is the chord to j (0 for equal values), else the spline slope. Maya does not
//   publish its tolerance and AnimX does not compute clamped tangents; maya_curve::clamp_tolerance
//   (default 0: equal values only) makes it an explicit input.
// - auto (spelled auto_ in C++, "auto" in to_string): Maya's legacy auto tangent as AnimX computes
//   it (src/animx.cpp): flat at the first and last key; at an interior key the spline slope above
//   is the target, and it is bounded by three times each chord: 0 when the two chords d_l and d_r
//   do not have the same strict sign (a local extremum, or an equal neighbour), else the target
//   with its magnitude cut to 3 min(|d_l|, |d_r|) (so the Bezier control values stay within the
//   neighbours' values, AnimX's stated aim). Both sides of the key take that slope; on a weighted
//   curve the handle is at a third of the adjacent segment (AnimX's tangent x is the segment's
//   duration). AnimX's Auto Mix and Auto Ease (other targets, same bound) are not modelled.
// - plateau: described as keeping the curve from going beyond its keys' values, so that its
//   maxima and minima do not overshoot the keys (the Plateau entry of the Tangents menu; its
//   official wording was not retrieved). Maya does not publish its limiter and AnimX does not
//   compute plateau tangents (it only names the type); this model uses the auto rule above, whose
//   bound 3 min(|d_l|, |d_r|) is also Fritsch and Carlson's monotonicity condition, so each
//   segment between two such keys is monotone and the curve never overshoots its keys.
// Segments: a non-weighted curve's segment is the cubic Hermite polynomial in time with the two
// slopes (the handles' lengths ignored; channel hermite, handles at thirds). A weighted curve's
// segment is the cubic Bezier with the handles above (computed tangent types put their handles at
// thirds of the adjacent segment, so only fixed tangents carry a weight). Regressive handles
// (Maya's rule as AnimX applies it when it evaluates a weighted segment: src/animx.cpp calls the
// Bezier evaluation of src/internal/Tbezier.h, which corrects the handles first): with h
// the duration, a = out handle time / h and c = in handle time / h (both > 0), time along the
// segment is monotone exactly when a + c <= 1 or (a, c) lies in the ellipse
// E(a, c) = a^2 + a c + c^2 - 2 a - 2 c + 1 <= 0. Nothing changes unless a > 1 or c > 1 (a handle
// reaching past the other key) and E(a, c) > -m, with AnimX's margin m = 1e-10 (in every Real;
// in float it is below rounding, and the channel accepts the result as monotone). Then the start
// key's out handle is kept and only c moves, when a < 4/3 - m: to the upper edge of E at this a,
// c = (2 - a + sqrt(a (4 - 3 a))) / 2, less m, if c lies above it, else to the lower edge (the
// same with -sqrt), plus m, if c lies below that; when a >= 4/3 - m (past E's widest point
// a = 4/3, c = 1/3) both go to that point: a = 4/3 - m, c = 1/3 - m. A moved handle keeps its
// direction (its value offset is scaled by new / old reach), except one whose old reach was within
// m of 0, whose value offset is kept. Segments whose handles overlap in time but stay monotone
// (a + c > 1 inside E) are not touched.
// Infinity (pre before the first key, post after the last; Maya Help "Pre and Post Infinity"):
// constant (the end key's value), linear (the end key's tangent facing out of the keyed range: the
// first key's in tangent, the last key's out tangent: the Help says linear infinity continues
// along the end key's tangent, and AnimX extends the line at the first key's in tangent's and the
// last key's out tangent's angle; a step type there is slope 0, not settled by AnimX), cycle,
// cycle_relative (Cycle with Offset: each period shifted by v_last - v_first) and oscillate (the
// period next to the keyed range mirrored), wrapped as AnimX wraps them (measured against AnimX's
// values, tests/data/animx_curves.json): with T = t_last - t_first and r = (t - t_end) / T
// computed in Real (t_end the first key before the keys, the last after), N = |trunc(r)| + 1 and
// the fraction f = T |r - trunc(r)|, the time evaluated is t_last - f before the keys and
// t_first + f after them (cycle, cycle_relative), for oscillate t_first + f before and t_last - f
// after when N is odd (the mirrored repeats; dv/dt changes sign), else as for cycle;
// cycle_relative adds -N (v_last - v_first) before and +N (v_last - v_first) after. So at exactly
// k >= 1 whole periods before the first key cycle gives the last key's value (f = 0 maps to the
// end of the previous repeat) and after the last key the first key's. Whether a time is such a
// boundary is decided by r's rounding in Real, as AnimX decides it in double: with times in seconds
// on frames (n / 24, inexact), t - t_end = k T in exact arithmetic may round to a fraction just
// under 1 (then the other side's key) or just over 0. AnimX then rounds the wrapped time to Maya's
// ticks (1/141120000 s, in 64-bit time), which lands a time within rounding of a key on the key;
// times here have no unit, so the wrapped time is snapped to a key within the wrap's own rounding,
// 4 eps (|t| + 2 max(|t_first|, |t_last|) + T), instead (the same key on tick-aligned times; a
// wrapped time off the ticks, which Maya's times never are, is not rounded). The channel keeps its
// own cycle / cycle_offset / oscillate (its curve view), which differ from these only within
// rounding of the period boundaries. Linear infinity is evaluated here from the end key's own
// tangent. A one-key curve is constant under every
// mode (the channel's rule; AnimX's code returns 0 outside a one-key curve's key under any
// non-constant infinity, which this model does not follow: not settled).
// Evaluation: maya_model(curve) builds the evaluator in double with the isolate_brent time solver
// (the zeros of x'(u) isolate monotone pieces, Brent on the bracketing piece: AnimX's approach,
// which isolates the roots of x(u) - t between the zeros of its derivative and refines with
// Brent-Dekker). Not modelled from AnimX's evaluator: its shortcuts (a weighted segment whose
// handles lie within 1e-6 of the thirds in time is solved as u = (t - t0) / h; a non-weighted
// segment whose two slopes are within 2e-7 relative of the chord is the chord), AnimX's key
// snapping (a time within 1e-10 of a key is the key), and, in builds without 64-bit time, the
// float storage of tangents and the rounding of Bezier span times to float. Measured against
// AnimX (tests/test_maya_animx.cpp: fixed, auto, flat, linear, step and step_next tangents,
// weighted and not, regressive handles, every infinity on both sides): every recorded value
// within 8 eps(double) of V + |dv/dt| (|t| + H).
// maya_exact<High>(curve) builds the same keys converted exactly to High (real50) with the exact
// solver; the tangent rules are then applied in High too.
// Validation (invalid_input naming the key index and field with the value): no keys, non-finite
// numbers, unknown enum values, fixed tangents with x <= 0, a non-finite slope y / x, negative
// clamp_tolerance; the channel's own checks (time order, duplicate times) follow.
// Cost: O(n) to build; evaluation as the channel (O(log n) search plus the solver on weighted
// segments). Accuracy: the channel's plus the slopes' rounding (a few eps relative);
// tests/test_maya.cpp measures the double model against the real50 truth.
// Sources: Autodesk Maya Help (Graph Editor Tangents menu, Graph Editor Curves menu); Autodesk
// AnimX (Apache-2.0), src/animx.cpp (the auto tangent, the flat tangent's handle, step / step
// next / linear spans, the infinity modes) and src/internal/Tbezier.h (the regression correction
// and its margin); Fritsch and Carlson (1980). Facts only, no code.
#pragma once

#include "curvebench/channel/channel.hpp"
#include "curvebench/channel/time_solver.hpp"
#include "curvebench/core/error.hpp"
#include "curvebench/core/real.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <iterator>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace curvebench::channel {

/// Maya's tangent types (auto_ is Maya's "auto").
enum class maya_tangent : std::uint8_t { fixed, linear, flat, step, step_next, spline, clamped, plateau, auto_ };
/// Maya's pre / post infinity modes.
enum class maya_infinity : std::uint8_t { constant, linear, cycle, cycle_relative, oscillate };

inline constexpr std::array<maya_tangent, 9> all_maya_tangents{
    maya_tangent::fixed,  maya_tangent::linear,  maya_tangent::flat,    maya_tangent::step, maya_tangent::step_next,
    maya_tangent::spline, maya_tangent::clamped, maya_tangent::plateau, maya_tangent::auto_};
inline constexpr std::array<maya_infinity, 5> all_maya_infinities{maya_infinity::constant, maya_infinity::linear,
                                                                  maya_infinity::cycle, maya_infinity::cycle_relative,
                                                                  maya_infinity::oscillate};

[[nodiscard]] inline const char* to_string(maya_tangent t) {
  switch (t) {
    case maya_tangent::fixed: return "fixed";
    case maya_tangent::linear: return "linear";
    case maya_tangent::flat: return "flat";
    case maya_tangent::step: return "step";
    case maya_tangent::step_next: return "step_next";
    case maya_tangent::spline: return "spline";
    case maya_tangent::clamped: return "clamped";
    case maya_tangent::plateau: return "plateau";
    case maya_tangent::auto_: return "auto";
  }
  return "unknown";
}

[[nodiscard]] inline const char* to_string(maya_infinity m) {
  switch (m) {
    case maya_infinity::constant: return "constant";
    case maya_infinity::linear: return "linear";
    case maya_infinity::cycle: return "cycle";
    case maya_infinity::cycle_relative: return "cycle_relative";
    case maya_infinity::oscillate: return "oscillate";
  }
  return "unknown";
}

template <>
[[nodiscard]] inline maya_tangent from_string<maya_tangent>(std::string_view name) {
  return detail::enum_from_string("maya tangent", name, all_maya_tangents);
}

template <>
[[nodiscard]] inline maya_infinity from_string<maya_infinity>(std::string_view name) {
  return detail::enum_from_string("maya infinity", name, all_maya_infinities);
}

/// A Maya key: time, value, tangent types, and the fixed tangent vectors (x > 0, both pointing
/// forwards in time; used by fixed tangents, and on weighted curves also their handle length).
template <class Real>
struct maya_key {
  Real time{0};
  Real value{0};
  maya_tangent in_type = maya_tangent::spline;
  maya_tangent out_type = maya_tangent::spline;
  Real in_x{1}, in_y{0};
  Real out_x{1}, out_y{0};
};

/// A Maya animation curve: keys in time order, weighted or not, pre and post infinity.
template <class Real>
struct maya_curve {
  std::vector<maya_key<Real>> keys;
  bool weighted = false;
  maya_infinity pre = maya_infinity::constant;
  maya_infinity post = maya_infinity::constant;
  Real clamp_tolerance{0};  // clamped: neighbours this close (relative to max(1, |v|)) count as equal
};

/// Maya's (angle in radians, weight) as the tangent vector (x, y) = 3 weight (cos, sin).
template <class Real>
[[nodiscard]] std::pair<Real, Real> tangent_from_angle(const Real& angle, const Real& weight) {
  using std::cos;
  using std::sin;
  validate::finite("angle", angle);
  validate::finite("weight", weight);
  if (!(weight > Real(0))) validate::fail("weight = " + to_text(weight) + ": must be > 0");
  return {Real(3) * weight * cos(angle), Real(3) * weight * sin(angle)};
}

/// The curve with every number converted to To (exactly when To is wider).
template <class To, class From>
[[nodiscard]] maya_curve<To> convert(const maya_curve<From>& c) {
  maya_curve<To> r;
  r.weighted = c.weighted;
  r.pre = c.pre;
  r.post = c.post;
  r.clamp_tolerance = To(c.clamp_tolerance);
  for (const auto& k : c.keys)
    r.keys.push_back(
        {To(k.time), To(k.value), k.in_type, k.out_type, To(k.in_x), To(k.in_y), To(k.out_x), To(k.out_y)});
  return r;
}

namespace detail {

[[nodiscard]] inline std::string maya_field(std::size_t i, std::string_view field) {
  return validate::indexed("keys", i) + "." + std::string(field);
}

template <class Real>
void validate_maya(const maya_curve<Real>& c) {
  validate::count_at_least("keys", c.keys.size(), 1, "a Maya curve needs a key");
  validate::finite("clamp_tolerance", c.clamp_tolerance);
  if (c.clamp_tolerance < Real(0)) validate::fail("clamp_tolerance = " + to_text(c.clamp_tolerance) + ": must be >= 0");
  const auto known_infinity = [](maya_infinity m) {
    return std::find(all_maya_infinities.begin(), all_maya_infinities.end(), m) != all_maya_infinities.end();
  };
  if (!known_infinity(c.pre))
    validate::fail("pre = " + std::to_string(static_cast<int>(c.pre)) + ": not a maya_infinity");
  if (!known_infinity(c.post))
    validate::fail("post = " + std::to_string(static_cast<int>(c.post)) + ": not a maya_infinity");
  for (std::size_t i = 0; i < c.keys.size(); ++i) {
    const auto& k = c.keys[i];
    validate::finite(maya_field(i, "time"), k.time);
    validate::finite(maya_field(i, "value"), k.value);
    const std::array<std::pair<const char*, maya_tangent>, 2> types{{{"in_type", k.in_type}, {"out_type", k.out_type}}};
    for (const auto& [name, type] : types)
      if (std::find(all_maya_tangents.begin(), all_maya_tangents.end(), type) == all_maya_tangents.end())
        validate::fail(maya_field(i, name) + " = " + std::to_string(static_cast<int>(type)) + ": not a maya_tangent");
    const bool in_used = k.in_type == maya_tangent::fixed, out_used = k.out_type == maya_tangent::fixed;
    const std::array<std::pair<const char*, const Real*>, 4> fields{
        {{"in_x", &k.in_x}, {"in_y", &k.in_y}, {"out_x", &k.out_x}, {"out_y", &k.out_y}}};
    for (const auto& [name, value] : fields) validate::finite(maya_field(i, name), *value);
    if (in_used && !(k.in_x > Real(0)))
      validate::fail(maya_field(i, "in_x") + " = " + to_text(k.in_x) +
                     ": a fixed tangent's x must be > 0 (the vector points forwards in time)");
    if (out_used && !(k.out_x > Real(0)))
      validate::fail(maya_field(i, "out_x") + " = " + to_text(k.out_x) +
                     ": a fixed tangent's x must be > 0 (the vector points forwards in time)");
    if (in_used) validate::finite(maya_field(i, "in_y / in_x"), Real(k.in_y / k.in_x));
    if (out_used) validate::finite(maya_field(i, "out_y / out_x"), Real(k.out_y / k.out_x));
    if (i > 0 && !(k.time > c.keys[i - 1].time))
      validate::fail("keys must be in increasing time order: " + maya_field(i, "time") + " = " + to_text(k.time) +
                     " <= " + maya_field(i - 1, "time") + " = " + to_text(c.keys[i - 1].time));
  }
}

template <class Real>
Real maya_chord(const maya_key<Real>& a, const maya_key<Real>& b) {
  return (b.value - a.value) / (b.time - a.time);
}

/// The slope of key i's tangent on one side (in: toward i - 1, out: toward i + 1).
template <class Real>
Real maya_slope(const maya_curve<Real>& c, std::size_t i, bool out) {
  using std::abs;
  using std::max;
  using std::min;
  const auto& keys = c.keys;
  const std::size_t n = keys.size();
  const maya_key<Real>& k = keys[i];
  const maya_tangent type = out ? k.out_type : k.in_type;
  if (n == 1) return type == maya_tangent::fixed ? (out ? k.out_y / k.out_x : k.in_y / k.in_x) : Real(0);
  const bool has_prev = i > 0, has_next = i + 1 < n;
  const Real d_l = has_prev ? maya_chord(keys[i - 1], k) : maya_chord(k, keys[i + 1]);
  const Real d_r = has_next ? maya_chord(k, keys[i + 1]) : d_l;
  const Real spline = has_prev && has_next
                          ? (keys[i + 1].value - keys[i - 1].value) / (keys[i + 1].time - keys[i - 1].time)
                          : (has_prev ? d_l : d_r);
  switch (type) {
    case maya_tangent::fixed: return out ? k.out_y / k.out_x : k.in_y / k.in_x;
    case maya_tangent::linear: return out ? d_r : d_l;
    case maya_tangent::flat:
    case maya_tangent::step:
    case maya_tangent::step_next: return Real(0);
    case maya_tangent::spline: return spline;
    case maya_tangent::clamped: {
      const bool side_exists = out ? has_next : has_prev;
      if (side_exists) {
        const maya_key<Real>& j = keys[out ? i + 1 : i - 1];
        const Real scale = max(Real(1), max(abs(k.value), abs(j.value)));
        if (abs(k.value - j.value) <= c.clamp_tolerance * scale) return out ? d_r : d_l;
      }
      return spline;
    }
    case maya_tangent::plateau:  // the stand-in: the auto rule (the header comment)
    case maya_tangent::auto_: {
      if (!has_prev || !has_next) return Real(0);  // flat at the ends
      const bool rising = d_l > Real(0) && d_r > Real(0), falling = d_l < Real(0) && d_r < Real(0);
      if (!rising && !falling) return Real(0);  // an extremum or an equal neighbour
      const Real bound = Real(3) * min(abs(d_l), abs(d_r));
      return std::clamp(spline, -bound, bound);
    }
  }
  return Real(0);
}

/// AnimX's margin for the regression correction, an absolute amount of the normalized handle
/// reaches a and c: 1e-10 in every Real (in float it is below the rounding of a and c, and the
/// corrected handles lie on the ellipse to rounding, which the channel accepts as monotone).
template <class Real>
Real maya_regression_margin() {
  return static_cast<Real>(1e-10);
}

/// Maya's correction of a weighted segment's handles (out: the start key's, dt > 0; in: the end
/// key's, dt < 0) over a duration h, in place. See the header comment, "Regressive handles".
template <class Real>
void maya_correct_regression(const Real& h, handle<Real>& out, handle<Real>& in) {
  using std::abs;
  using std::sqrt;
  const Real m = maya_regression_margin<Real>();
  const Real a = out.dt / h, c = -in.dt / h;  // the handles' time reach as fractions of h
  if (!(a > Real(1) || c > Real(1))) return;  // neither handle passes the other key: monotone
  // Outside the ellipse E(a, c) = a^2 + a c + c^2 - 2 a - 2 c + 1 <= 0, x'(u) changes sign.
  const Real e = a * a + a * c + c * c - Real(2) * a - Real(2) * c + Real(1);
  if (!(e > -m)) return;
  Real a_new = a, c_new = c;
  const Real four_thirds = Real(4) / Real(3);
  if (a < four_thirds - m) {
    // Keep the out handle; the in handle's reach c moves to the nearer edge of E at this a:
    // c = (2 - a -/+ sqrt(a (4 - 3 a))) / 2, pulled inside by the margin.
    const Real root = sqrt(a * (Real(4) - Real(3) * a));
    const Real c_hi = (Real(2) - a + root) / Real(2), c_lo = (Real(2) - a - root) / Real(2);
    if (c > c_hi - m) {
      c_new = c_hi - m;
    } else if (c < c_lo + m) {
      c_new = c_lo + m;
    }
  } else {
    // Past E's widest a (4/3, where c = 1/3): both go to that tip, less the margin.
    a_new = four_thirds - m;
    c_new = Real(1) / Real(3) - m;
  }
  // A moved handle keeps its direction (its value offset scales with its time), unless its old
  // reach was within the margin of 0, where the value offset is kept as it was.
  if (a_new != a) {
    if (abs(a) > m) out.dv = out.dv * (a_new / a);
    out.dt = a_new * h;
  }
  if (c_new != c) {
    if (abs(c) > m) in.dv = in.dv * (c_new / c);
    in.dt = -c_new * h;
  }
}

}  // namespace detail

/// The channel keys Maya's rules make of the curve: slopes by tangent type, Hermite (non-weighted)
/// or Bezier (weighted, regressive handles shortened) segments, step / step_next segments.
template <class Real>
[[nodiscard]] std::vector<key<Real>> maya_channel_keys(const maya_curve<Real>& c) {
  detail::validate_maya(c);
  const auto& mk = c.keys;
  const std::size_t n = mk.size();
  std::vector<key<Real>> keys(n);
  for (std::size_t i = 0; i < n; ++i) {
    keys[i].time = mk[i].time;
    keys[i].value = mk[i].value;
  }
  for (std::size_t i = 0; i + 1 < n; ++i) {
    const Real h = mk[i + 1].time - mk[i].time;
    key<Real>& k0 = keys[i];
    key<Real>& k1 = keys[i + 1];
    if (mk[i].out_type == maya_tangent::step) {
      k0.interp = interpolation::constant;
      continue;
    }
    if (mk[i].out_type == maya_tangent::step_next) {
      k0.interp = interpolation::step_next;
      continue;
    }
    const Real m0 = detail::maya_slope(c, i, true), m1 = detail::maya_slope(c, i + 1, false);
    if (!c.weighted) {
      k0.interp = interpolation::hermite;
      k0.out = {h / Real(3), m0 * h / Real(3)};
      k1.in = {-h / Real(3), -m1 * h / Real(3)};
      continue;
    }
    k0.interp = interpolation::bezier;
    handle<Real> out{h / Real(3), m0 * h / Real(3)}, in{-h / Real(3), -m1 * h / Real(3)};
    if (mk[i].out_type == maya_tangent::fixed) out = {mk[i].out_x / Real(3), mk[i].out_y / Real(3)};
    if (mk[i + 1].in_type == maya_tangent::fixed) in = {-mk[i + 1].in_x / Real(3), -mk[i + 1].in_y / Real(3)};
    detail::maya_correct_regression(h, out, in);
    k0.out = out;
    k1.in = in;
  }
  return keys;
}

[[nodiscard]] inline extrapolation to_extrapolation(maya_infinity m) {
  switch (m) {
    case maya_infinity::constant: return extrapolation::constant;
    case maya_infinity::linear: return extrapolation::linear;
    case maya_infinity::cycle: return extrapolation::cycle;
    case maya_infinity::cycle_relative: return extrapolation::cycle_offset;
    case maya_infinity::oscillate: return extrapolation::oscillate;
  }
  validate::fail("maya infinity = " + std::to_string(static_cast<int>(m)) + ": not a maya_infinity");
}

/// What Maya evaluates: the channel of maya_channel_keys with the curve's infinity, linear
/// infinity along the end key's own outward tangent.
template <class Real>
class maya_evaluator {
 public:
  using real_type = Real;

  maya_evaluator(const maya_curve<Real>& c, time_solver solver)
      : channel_(make_channel(c, solver)),
        pre_(c.pre),
        post_(c.post),
        slope_pre_(detail::maya_slope(c, 0, false)),
        slope_post_(detail::maya_slope(c, c.keys.size() - 1, true)) {
    // Maya's end tangents are never vertical (x > 0), but a weighted end key's slope can overflow.
    validate::finite("keys[0] in slope (linear pre infinity)", slope_pre_);
    validate::finite(validate::indexed("keys", c.keys.size() - 1) + " out slope (linear post infinity)", slope_post_);
  }

  /// The value at time t (any finite t).
  [[nodiscard]] Real value(const Real& t) const { return derivative(t, 0); }
  /// d^order v / dt^order, order 0, 1 or 2 (the channel's conventions).
  [[nodiscard]] Real derivative(const Real& t, int order) const {
    const auto keys = channel_.keys();
    if (keys.size() > 1 && is_finite(t)) {  // non-finite t: the channel's domain_error
      if (pre_ == maya_infinity::linear && t < keys.front().time) return line(keys.front(), slope_pre_, t, order);
      if (post_ == maya_infinity::linear && t > keys.back().time) return line(keys.back(), slope_post_, t, order);
      const bool before = (t < keys.front().time);
      const bool after = (t > keys.back().time);
      const maya_infinity mode = before ? pre_ : post_;
      if ((before || after) && mode != maya_infinity::constant) return wrapped(t, before, mode, order);
    }
    return channel_.derivative(t, order);
  }
  [[nodiscard]] const channel<Real>& underlying() const { return channel_; }

 private:
  channel<Real> channel_;
  maya_infinity pre_, post_;
  Real slope_pre_, slope_post_;

  // The keys first (they validate the whole curve), then the channel with the infinity modes.
  static channel<Real> make_channel(const maya_curve<Real>& c, time_solver solver) {
    std::vector<key<Real>> keys = maya_channel_keys(c);
    return channel<Real>(std::move(keys),
                         c.pre == maya_infinity::linear ? extrapolation::constant : to_extrapolation(c.pre),
                         c.post == maya_infinity::linear ? extrapolation::constant : to_extrapolation(c.post), solver);
  }

  // A cyclic infinity (cycle, cycle_relative, oscillate) as AnimX computes it (the header comment,
  // "Infinity"): the ratio of t's distance from the end key to the period, its whole part and the
  // fraction, the fraction times the period from the end the mode maps it to; then the wrapped time
  // within the wrap's rounding of a key is that key (AnimX rounds it to Maya's ticks).
  Real wrapped(const Real& t, bool before, maya_infinity mode, int order) const {
    using std::abs;
    using std::fmod;
    using std::max;
    using std::trunc;
    const auto keys = channel_.keys();
    const Real t_first = keys.front().time, t_last = keys.back().time;
    const Real period = t_last - t_first;
    const Real ratio = (t - (before ? t_first : t_last)) / period;
    const Real whole = trunc(ratio);
    const Real offset = period * abs(ratio - whole);  // ratio - whole: exact (the fraction)
    const Real cycles = abs(whole) + Real(1);
    const bool odd = fmod(cycles, Real(2)) != Real(0);
    const bool mirrored = mode == maya_infinity::oscillate && odd;
    const bool from_first = before ? mirrored : !(mode == maya_infinity::oscillate && odd);
    Real at = std::clamp(from_first ? Real(t_first + offset) : Real(t_last - offset), t_first, t_last);
    // Snap to a key: the wrap's rounding is a few eps of |t|, the key times and the period.
    const Real snap = Real(4) * epsilon<Real>() * (abs(t) + Real(2) * max(abs(t_first), abs(t_last)) + period);
    const auto next =
        std::lower_bound(keys.begin(), keys.end(), at, [](const key<Real>& k, const Real& x) { return k.time < x; });
    if (next != keys.end() && next->time - at <= snap) {
      at = next->time;
    } else if (next != keys.begin() && at - std::prev(next)->time <= snap) {
      at = std::prev(next)->time;
    }
    Real result = channel_.derivative(at, order);
    if (mirrored && order == 1) result = -result;
    if (mode == maya_infinity::cycle_relative && order == 0) {
      const Real shift = cycles * (keys.back().value - keys.front().value);
      result = before ? Real(result - shift) : Real(result + shift);
    }
    return result;
  }

  static Real line(const key<Real>& k, const Real& slope, const Real& t, int order) {
    validate::derivative_order(order);
    if (order > 2) validate::fail("order = " + std::to_string(order) + ": a channel's time derivatives go to order 2");
    if (order == 0) return k.value + (t - k.time) * slope;
    return order == 1 ? slope : Real(0);
  }
};

/// Maya's evaluation of the curve: double, the isolate_brent time solver.
[[nodiscard]] inline maya_evaluator<double> maya_model(const maya_curve<double>& c) {
  return maya_evaluator<double>(c, time_solver::isolate_brent);
}

/// The truth of the same keys: converted exactly to High (real50), the rules applied in High, the
/// exact time solver.
template <class High>
[[nodiscard]] maya_evaluator<High> maya_exact(const maya_curve<double>& c) {
  return maya_evaluator<High>(convert<High>(c), time_solver::exact);
}

}  // namespace curvebench::channel
