// Blender's F-curve as a tool model: the rules that turn an F-curve description (keys with
// absolute handle coordinates, handle types, per-segment interpolation and easing, extrapolation,
// auto-handle smoothing and a Cycles modifier) into the values Blender evaluates, on top of the
// keyframe channel (channel/channel.hpp) and Penner's easing (channel/penner.hpp).
//
// Description: blender_key { time, value, handle_left, handle_right (absolute (frame, value), as
// Blender stores them), handle_left_type, handle_right_type (free, aligned, vector, auto,
// auto_clamped; `automatic` in C++, "auto" as text), interpolation of the segment starting at the
// key (constant, linear, bezier, or a Penner family sine .. elastic), easing (penner.hpp's
// ease_mode) and back / amplitude / period }; blender_fcurve { keys (sorted by time),
// extrapolation (constant, linear), smoothing (none, cont_accel: Blender's "Auto Handle
// Smoothing"; new F-curves get cont_accel), cycles (the Cycles modifier: mode_before, mode_after in
// none, repeat, repeat_offset, mirror; cycles_before, cycles_after >= 0, 0 = infinite) }.
//
// Handle rules (blender_handles), found by experiment with Blender 3.4.1 through
// scripts/peers/blender_fcurves.py (tests/data/blender_fcurves.json; Blender's source was not
// read for these; it was for the smoothing of mixed curves, below). h_l, h_r are the key's intervals to its neighbours
// (at an end key both are the one interval it has); s_l, s_r the chord slopes to the neighbours.
// - auto and auto_clamped (both sides the same type, or one side beside a vector handle; auto
//   beside a free handle, whose side stays as given):
//   handles of time length f h_l (left) and f h_r (right) along one slope m. smoothing none:
//   f = 1 / 2.5614, each length limited to 5 times the other side's, m = (s_l + s_r) / 2 at
//   interior keys. smoothing cont_accel: f = 1/3 (the
//   segment between two such keys is a cubic polynomial in time) and the slopes make the curve C2
//   at interior keys: h_r m_{i-1} + 2 (h_l + h_r) m_i + h_l m_{i+1} = 3 (h_r s_l + h_l s_r), a
//   cubic spline. End keys: m = 0 under constant extrapolation; under linear, m = s (none) or the
//   natural end 2 m_0 + m_1 = 3 s (cont_accel).
//   auto_clamped then clamps interior keys: m = 0 at a local extremum (value >= both neighbours'
//   or <= both) or where m has the sign opposite to v_next - v_prev; else m is reduced until
//   neither handle's value offset exceeds the value change to its neighbour key. Under
//   cont_accel a clamped slope is fixed and the spline solved again for the rest until no slope
//   needs clamping (the end slopes measured with linear extrapolation show the re-solve): the
//   extrema are flat from the start, then an active set clamps keys whose solved slope breaks the
//   bound and releases clamped keys whose own equation falls back inside it, until stable (checked
//   on pseudo-random layouts). End keys are not clamped.
// - vector: time length h/3 of its side's interval, pointing at the neighbour key (an end key's
//   missing side mirrors the other), so vector handles sit at thirds of the chords.
// - aligned (both sides): the left handle is kept, the right keeps its length (in (frame, value)
//   units) and takes the opposite direction (what Blender's update() does with both handles set).
// - free: as given.
// Cyclic curves: a Cycles modifier repeating without a count on both sides (repeat or
// repeat_offset) makes key 0 and key n-1 one interior key for the rules above, its neighbours key
// n-2 moved back and key 1 moved on by the period T and by v_last - v_first (under repeat too), and
// cont_accel solves the periodic spline, with the end keys' handle lengths their own interval's;
// auto_clamped bounds the joint's slope with the wrapped neighbours' intervals, and a flat
// extremum at the joint takes those as its handle lengths (measured on tests/data/blender_fcurves.json
// and tests/data/blender_export).
// cont_accel on a curve mixing auto keys with vector, aligned or free ones: the keys'
// own rules first (auto slopes as under none, with the lengths f h of cont_accel; an auto_clamped
// side keeps from passing its own neighbour only; an end key flat under constant extrapolation
// only when both its sides are auto), then each run of auto keys between the others is smoothed
// on its own, held at the other keys' handles (blender_smooth_run: Blender's rules, read in its
// curve code for this case, and measured on tests/data/recorded/blender_mixed.json). On a cyclic
// curve the handles are cyclic only when both end keys are auto on both sides, and the runs wrap
// past the joint only when both end keys are free auto keys.
// Sources: Blender's manual and API reference name the options (docs/references.md); the rules are
// measured, as above.
// Evaluation (blender_evaluator, built by blender_model): the keys with the handles above become a
// channel<Real>: bezier segments with each handle's time length first limited to the segment's
// duration, scaled along its direction (Blender's correction: measured per handle, not on the sum,
// and this keeps time monotone); linear and constant as such; an eased segment is the chord in the
// channel (the view's placeholder) and penner_ease(family, easing, params) inside. Extrapolation
// constant, or linear by the end key's own interpolation (not its segment's: the last key's
// interpolation is the one no segment uses):
// constant, flat; linear, the chord to the neighbour key (flat for a single key); bezier and every
// eased family, the outer handle's slope (the first key's left handle before the keys, the last
// key's right handle after them; flat for a handle of zero time length; the handles of eased and
// other keys are computed by the rules above all the same). Measured on the held-out recording
// tests/data/recorded/blender_heldout.json (end_key/*, single_key/*, easing/*): before it the model took
// the end segment's interpolation and the chord at an eased end, off by up to 20 times the value
// range on those channels.
// Cycles modifier: outside [t_first, t_last] the time is wrapped into the keyed range for the first
// N repeats on that side (repeat: as channel's cycle; repeat_offset: shifted by k (v_last -
// v_first); mirror: every odd repeat mirrored, as channel's oscillate); t_last + N T and t_first -
// N T still belong to the repeats; beyond them (or with mode none) the curve's own extrapolation.
// Precision: Blender stores keys and handles in float32 and its values are float32.
// blender_model<float>(fcurve) forms a Bezier segment's value as Blender does: the handles
// corrected in float, the root of the time cubic of the absolute float control times found as
// Blender finds it (blender_root: float coefficients, Cardano's formula in double) and rounded to
// float, then the value cubic in float power form, each operation rounded (no FMA contraction).
// With the stored handles (stored_handles) it gives Blender's values bit for bit on the Bezier,
// constant and linear segments (tests/test_blender.cpp on tests/data/blender_fcurves.json,
// tests/data/blender_export); Penner eases within 0.46 float ulps; with the handles recomputed by
// their rules, to float rounding of the value scale. A named time solver replaces Blender's root
// (tests/test_blender.cpp measures each against the recorded values). blender_model<real50>(fcurve)
// is the 50-digit truth of the same description (solver exact).
// Validation (invalid_input naming the key index and field, with the value): no keys; non-finite
// numbers; keys not in increasing time order; handle_left after or handle_right before its key;
// enum values outside their lists; aligned on one side only, auto / auto_clamped on one side beside
// free or aligned; cont_accel mixing auto keys with others;
// negative cycle counts; amplitude < 0.
// Cost: O(n) handles for none; cont_accel solves a (cyclic) tridiagonal system in O(n), again after
// each round of newly clamped keys (at most n rounds, O(n^2) worst); evaluation as channel.hpp and
// penner.hpp, plus one fmod for the cycles. No allocation when evaluating.
#pragma once

#include "curvebench/channel/channel.hpp"
#include "curvebench/channel/penner.hpp"
#include "curvebench/channel/time_solver.hpp"
#include "curvebench/core/detail/segment_lookup.hpp"
#include "curvebench/core/error.hpp"
#include "curvebench/core/real.hpp"
#include "curvebench/curves/detail/tridiagonal.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <vector>

namespace curvebench::channel {

/// Blender's handle types (Python: FREE, ALIGNED, VECTOR, AUTO, AUTO_CLAMPED); to_string gives
/// "free", "aligned", "vector", "auto", "auto_clamped".
enum class handle_type : std::uint8_t { free, aligned, vector, automatic, auto_clamped };
/// Blender's keyframe interpolation (the segment starting at the key).
enum class blender_interpolation : std::uint8_t {
  constant,
  linear,
  bezier,
  sine,
  quad,
  cubic,
  quart,
  quint,
  expo,
  circ,
  back,
  bounce,
  elastic
};
enum class blender_extrapolation : std::uint8_t { constant, linear };
/// Blender's F-curve auto_smoothing (NONE, CONT_ACCEL).
enum class auto_smoothing : std::uint8_t { none, cont_accel };
/// The Cycles modifier's modes (NONE, REPEAT, REPEAT_OFFSET, MIRROR).
enum class cycles_mode : std::uint8_t { none, repeat, repeat_offset, mirror };

[[nodiscard]] inline const char* to_string(handle_type h) {
  switch (h) {
    case handle_type::free: return "free";
    case handle_type::aligned: return "aligned";
    case handle_type::vector: return "vector";
    case handle_type::automatic: return "auto";
    case handle_type::auto_clamped: return "auto_clamped";
  }
  return "unknown";
}

[[nodiscard]] inline const char* to_string(blender_interpolation i) {
  static constexpr std::array<const char*, 13> names{"constant", "linear", "bezier", "sine", "quad",
                                                     "cubic",    "quart",  "quint",  "expo", "circ",
                                                     "back",     "bounce", "elastic"};
  const auto k = static_cast<std::size_t>(i);
  return k < names.size() ? names[k] : "unknown";
}

[[nodiscard]] inline const char* to_string(blender_extrapolation e) {
  switch (e) {
    case blender_extrapolation::constant: return "constant";
    case blender_extrapolation::linear: return "linear";
  }
  return "unknown";
}

[[nodiscard]] inline const char* to_string(auto_smoothing s) {
  switch (s) {
    case auto_smoothing::none: return "none";
    case auto_smoothing::cont_accel: return "cont_accel";
  }
  return "unknown";
}

[[nodiscard]] inline const char* to_string(cycles_mode m) {
  switch (m) {
    case cycles_mode::none: return "none";
    case cycles_mode::repeat: return "repeat";
    case cycles_mode::repeat_offset: return "repeat_offset";
    case cycles_mode::mirror: return "mirror";
  }
  return "unknown";
}

/// The Penner family of an eased interpolation (sine .. elastic).
[[nodiscard]] inline bool is_eased(blender_interpolation i) {
  return i >= blender_interpolation::sine && i <= blender_interpolation::elastic;
}

[[nodiscard]] inline penner_family penner_family_of(blender_interpolation i) {
  if (!is_eased(i)) validate::fail(std::string("interpolation = ") + to_string(i) + ": not a Penner family");
  return static_cast<penner_family>(static_cast<int>(i) - static_cast<int>(blender_interpolation::sine));
}

/// A point in Blender's (frame, value) plane.
template <class Real>
struct blender_point {
  Real time{0};
  Real value{0};
};

/// A Blender keyframe (see the header). Handles are absolute coordinates.
template <class Real>
struct blender_key {
  Real time{0};
  Real value{0};
  blender_point<Real> handle_left{};
  blender_point<Real> handle_right{};
  handle_type handle_left_type = handle_type::auto_clamped;
  handle_type handle_right_type = handle_type::auto_clamped;
  blender_interpolation interpolation = blender_interpolation::bezier;
  ease_mode easing = ease_mode::automatic;
  penner_params<Real> params{};
};

/// The Cycles modifier; enabled = false means no modifier.
struct blender_cycles {
  bool enabled = false;
  cycles_mode mode_before = cycles_mode::repeat;
  cycles_mode mode_after = cycles_mode::repeat;
  int cycles_before = 0;  ///< 0 = infinite
  int cycles_after = 0;   ///< 0 = infinite
};

/// A Blender F-curve description (see the header).
template <class Real>
struct blender_fcurve {
  std::vector<blender_key<Real>> keys;
  blender_extrapolation extrapolation = blender_extrapolation::constant;
  auto_smoothing smoothing = auto_smoothing::cont_accel;
  blender_cycles cycles{};
  /// The handles are the ones Blender stored (an F-curve exported from a .blend): they are evaluated
  /// as they are, whatever their types, as Blender evaluates an F-curve; Blender applies the handle
  /// rules when keys are edited, in its own float order of operations, which the rules here
  /// reproduce to a few float roundings only (tests/test_blender.cpp, handle_tol).
  bool stored_handles = false;
};

namespace detail {

[[nodiscard]] inline std::string bkey_field(std::size_t i, std::string_view field) {
  return validate::indexed("keys", i) + "." + std::string(field);
}

[[nodiscard]] inline bool is_auto(handle_type h) {
  return h == handle_type::automatic || h == handle_type::auto_clamped;
}

template <class Real>
[[nodiscard]] bool blender_cyclic(const blender_fcurve<Real>& c);

template <class Real>
void validate_fcurve(const blender_fcurve<Real>& c) {
  validate::count_at_least("keys", c.keys.size(), 1, "an F-curve needs a key");
  if (c.extrapolation != blender_extrapolation::constant && c.extrapolation != blender_extrapolation::linear)
    validate::fail("extrapolation = " + std::to_string(static_cast<int>(c.extrapolation)) +
                   ": not an extrapolation (constant, linear)");
  if (c.smoothing != auto_smoothing::none && c.smoothing != auto_smoothing::cont_accel)
    validate::fail("smoothing = " + std::to_string(static_cast<int>(c.smoothing)) +
                   ": not an auto_smoothing (none, cont_accel)");
  if (c.cycles.enabled) {
    for (auto [name, m] :
         {std::pair{"cycles.mode_before", c.cycles.mode_before}, std::pair{"cycles.mode_after", c.cycles.mode_after}})
      if (std::string_view(to_string(m)) == "unknown")
        validate::fail(std::string(name) + " = " + std::to_string(static_cast<int>(m)) +
                       ": not a cycles mode (none, repeat, repeat_offset, mirror)");
    if (c.cycles.cycles_before < 0)
      validate::fail("cycles.cycles_before = " + std::to_string(c.cycles.cycles_before) +
                     ": must be >= 0 (0 = infinite)");
    if (c.cycles.cycles_after < 0)
      validate::fail("cycles.cycles_after = " + std::to_string(c.cycles.cycles_after) +
                     ": must be >= 0 (0 = infinite)");
  }
  for (std::size_t i = 0; i < c.keys.size(); ++i) {
    const blender_key<Real>& k = c.keys[i];
    validate::finite(bkey_field(i, "time"), k.time);
    validate::finite(bkey_field(i, "value"), k.value);
    validate::finite(bkey_field(i, "handle_left.time"), k.handle_left.time);
    validate::finite(bkey_field(i, "handle_left.value"), k.handle_left.value);
    validate::finite(bkey_field(i, "handle_right.time"), k.handle_right.time);
    validate::finite(bkey_field(i, "handle_right.value"), k.handle_right.value);
    for (auto [name, h] :
         {std::pair{"handle_left_type", k.handle_left_type}, std::pair{"handle_right_type", k.handle_right_type}})
      if (std::string_view(to_string(h)) == "unknown")
        validate::fail(bkey_field(i, name) + " = " + std::to_string(static_cast<int>(h)) +
                       ": not a handle type (free, aligned, vector, auto, auto_clamped)");
    if (std::string_view(to_string(k.interpolation)) == "unknown")
      validate::fail(bkey_field(i, "interpolation") + " = " + std::to_string(static_cast<int>(k.interpolation)) +
                     ": not an interpolation");
    if (std::string_view(to_string(k.easing)) == "unknown")
      validate::fail(bkey_field(i, "easing") + " = " + std::to_string(static_cast<int>(k.easing)) +
                     ": not an easing (in, out, in_out, automatic)");
    validate::finite(bkey_field(i, "back"), k.params.back);
    validate::finite(bkey_field(i, "amplitude"), k.params.amplitude);
    validate::finite(bkey_field(i, "period"), k.params.period);
    if (k.params.amplitude < Real(0))
      validate::fail(bkey_field(i, "amplitude") + " = " + to_text(k.params.amplitude) + ": must be >= 0");
    const handle_type l = k.handle_left_type, r = k.handle_right_type;
    // auto beside free: the auto side placed by the rule, the free side as given (measured). Not
    // auto_clamped beside free: Blender re-aligns the other side where the clamp bites.
    const auto auto_free = [](handle_type a, handle_type b) {
      return a == handle_type::automatic && b == handle_type::free;
    };
    const bool auto_ok = !(is_auto(l) || is_auto(r)) || l == r || l == handle_type::vector ||
                         r == handle_type::vector || auto_free(l, r) || auto_free(r, l);
    const bool aligned_ok = (l == handle_type::aligned) == (r == handle_type::aligned);
    if (!auto_ok || !aligned_ok)
      validate::fail(bkey_field(i, "handle_right_type") + " = " + to_string(r) + " with " +
                     bkey_field(i, "handle_left_type") + " = " + to_string(l) +
                     ": aligned is modelled on both sides of a key, auto and auto_clamped on both sides or "
                     "beside a vector handle, auto beside a free handle");
    if (i > 0 && !(k.time > c.keys[i - 1].time))
      validate::fail("keys must be in increasing time order: " + bkey_field(i, "time") + " = " + to_text(k.time) +
                     " <= " + bkey_field(i - 1, "time") + " = " + to_text(c.keys[i - 1].time));
  }
}

/// Whether the Cycles modifier makes the curve cyclic for the handle rules: an infinite repeat
/// (repeat or repeat_offset) on both sides makes key 0 and key n-1 one key (see the header).
template <class Real>
[[nodiscard]] bool blender_cyclic(const blender_fcurve<Real>& c) {
  const auto repeats = [](cycles_mode m) { return m == cycles_mode::repeat || m == cycles_mode::repeat_offset; };
  return c.cycles.enabled && repeats(c.cycles.mode_before) && repeats(c.cycles.mode_after) &&
         c.cycles.cycles_before == 0 && c.cycles.cycles_after == 0;
}

/// Whether both of the key's handles are auto or auto_clamped.
template <class Real>
[[nodiscard]] bool blender_auto_key(const blender_key<Real>& x) {
  return is_auto(x.handle_left_type) && is_auto(x.handle_right_type);
}

/// Whether a curve has both keys with an auto side and keys that are not auto on both sides.
template <class Real>
[[nodiscard]] bool blender_mixes_auto(const std::vector<blender_key<Real>>& k) {
  const auto any = [](const blender_key<Real>& x) {
    return is_auto(x.handle_left_type) || is_auto(x.handle_right_type);
  };
  return std::any_of(k.begin(), k.end(), any) && !std::all_of(k.begin(), k.end(), blender_auto_key<Real>);
}

template <class Real>
[[nodiscard]] bool blender_clamped(const blender_key<Real>& x) {
  return x.handle_left_type == handle_type::auto_clamped || x.handle_right_type == handle_type::auto_clamped;
}

/// What the handle rules read around each key of a curve with n >= 2 keys: its neighbours (on a
/// cyclic curve key n-2 moved back and key 1 moved on by the period T and the offset v_last -
/// v_first, also under repeat; measured), its intervals, the auto handles' time lengths and
/// auto_clamped's bound on a slope. The keys' times and values only are read.
template <class Real>
struct blender_neighbours {
  const std::vector<blender_key<Real>>& k;
  bool cyclic, accel;
  Real period, offset;
  Real f;  ///< the auto handles' length as a fraction of the interval

  blender_neighbours(const std::vector<blender_key<Real>>& keys, bool is_cyclic, bool cont_accel)
      : k(keys),
        cyclic(is_cyclic),
        accel(cont_accel),
        period(keys.back().time - keys.front().time),
        offset(keys.back().value - keys.front().value),
        f(cont_accel ? Real(1) / Real(3) : Real(10000) / Real(25614)) {}

  [[nodiscard]] std::size_t size() const { return k.size(); }

  /// The neighbour before key i; false at the start of a non-cyclic curve.
  bool prev(std::size_t i, blender_point<Real>& p) const {
    const std::size_t n = k.size();
    if (i > 0)
      p = {k[i - 1].time, k[i - 1].value};
    else if (cyclic)
      p = {Real(k[n - 2].time - period), Real(k[n - 2].value - offset)};
    else
      return false;
    return true;
  }
  /// The neighbour after key i; false at the end of a non-cyclic curve.
  bool next(std::size_t i, blender_point<Real>& p) const {
    const std::size_t n = k.size();
    if (i + 1 < n)
      p = {k[i + 1].time, k[i + 1].value};
    else if (cyclic)
      p = {Real(k[1].time + period), Real(k[1].value + offset)};
    else
      return false;
    return true;
  }
  /// The key's own interval on one side (an end key's missing side: its only interval).
  [[nodiscard]] Real interval(std::size_t i, bool left) const {
    const std::size_t n = k.size();
    if (left) return i > 0 ? k[i].time - k[i - 1].time : k[1].time - k[0].time;
    return i + 1 < n ? k[i + 1].time - k[i].time : k[n - 1].time - k[n - 2].time;
  }
  /// The chord slope of segment i.
  [[nodiscard]] Real chord(std::size_t i) const { return (k[i + 1].value - k[i].value) / (k[i + 1].time - k[i].time); }
  /// The time lengths (left, right) of key i's auto handles: under smoothing none its neighbour
  /// lengths; under cont_accel f times its own intervals (an end key's only interval on both
  /// sides, even on a cyclic curve: measured).
  [[nodiscard]] std::pair<Real, Real> auto_lengths(std::size_t i) const {
    if (!accel) return neighbour_lengths(i);
    return {Real(f * interval(i, true)), Real(f * interval(i, false))};
  }
  /// The time lengths (left, right) of an interior key's auto handles: f times the intervals to
  /// its neighbours (on a cyclic curve key 0 and key n-1 have the wrapped ones), each limited to 5
  /// times the other under smoothing none. auto_clamped bounds every slope with these, and a
  /// flat extremum at the cyclic joint takes them under cont_accel too (measured, where its
  /// solved slope keeps the end key's own interval: auto_lengths).
  [[nodiscard]] std::pair<Real, Real> neighbour_lengths(std::size_t i) const {
    using std::min;
    blender_point<Real> p, q;
    Real l = prev(i, p) ? Real(k[i].time - p.time) : interval(i, true);
    Real r = next(i, q) ? Real(q.time - k[i].time) : interval(i, false);
    if (!accel) {
      const Real l5 = Real(5) * l, r5 = Real(5) * r;
      l = min(l, r5);
      r = min(r, l5);
    }
    return {Real(f * l), Real(f * r)};
  }
  /// Whether key i has both neighbours and a value at or beyond both (auto_clamped makes it flat).
  [[nodiscard]] bool extremum(std::size_t i) const {
    blender_point<Real> p, q;
    if (!prev(i, p) || !next(i, q)) return false;
    const Real v = k[i].value;
    return (v >= p.value && v >= q.value) || (v <= p.value && v <= q.value);
  }
  /// auto_clamped's rule on the slope m of interior key i: 0 at a local extremum or against the
  /// neighbours' direction, else reduced until neither handle (of the neighbour lengths) passes
  /// its neighbour's value.
  [[nodiscard]] Real clamp(std::size_t i, Real m) const {
    using std::abs;
    blender_point<Real> p, q;
    if (!prev(i, p) || !next(i, q)) return m;
    const Real vp = p.value, v = k[i].value, vn = q.value;
    if (extremum(i)) return Real(0);
    if (m * (vn - vp) < Real(0)) return Real(0);
    // Only an auto_clamped side is kept from passing its neighbour's value (a vector side beside
    // it is placed by its own rule).
    const auto [dl, dr] = neighbour_lengths(i);
    if (k[i].handle_right_type == handle_type::auto_clamped && abs(m * dr) > abs(vn - v)) m = (vn - v) / dr;
    if (k[i].handle_left_type == handle_type::auto_clamped && abs(m * dl) > abs(v - vp)) m = (v - vp) / dl;
    return m;
  }
};

/// The auto slopes under smoothing none: the mean of the chord slopes at interior keys, the end
/// chord (linear extrapolation) or 0 (constant) at the ends; auto_clamped keys clamped.
template <class Real>
[[nodiscard]] std::vector<Real> blender_slopes_none(const blender_neighbours<Real>& nb, bool linear) {
  const auto& k = nb.k;
  const std::size_t n = k.size();
  std::vector<Real> slope(n, Real(0));
  for (std::size_t i = 0; i < n; ++i) {
    blender_point<Real> p, q;
    const bool hp = nb.prev(i, p), hn = nb.next(i, q);
    Real mi;
    if (hp && hn)
      mi = ((k[i].value - p.value) / (k[i].time - p.time) + (q.value - k[i].value) / (q.time - k[i].time)) / Real(2);
    // An end key: the chord, flat under constant extrapolation when both its sides are auto
    // (Blender flattens only those).
    else if (!hp)
      mi = linear || !blender_auto_key(k[i]) ? nb.chord(0) : Real(0);
    else
      mi = linear || !blender_auto_key(k[i]) ? nb.chord(n - 2) : Real(0);
    slope[i] = blender_clamped(k[i]) ? nb.clamp(i, mi) : mi;
  }
  return slope;
}

/// The rows of cont_accel's C2 conditions on the unknown slopes m_0 .. m_{u-1} (u = n, or n - 1 on
/// a cyclic curve where m_{n-1} = m_0): ra m_{i-1} + rb m_i + rc m_{i+1} = rd with cyclic indices;
/// an end row is the natural end 2 m_end + m_neighbour = 3 s (linear extrapolation) or m = 0.
template <class Real>
struct blender_c2_rows {
  std::vector<Real> ra, rb, rc, rd;
};

template <class Real>
[[nodiscard]] blender_c2_rows<Real> blender_c2_system(const blender_neighbours<Real>& nb, std::size_t u, bool linear) {
  const auto& k = nb.k;
  const std::size_t n = k.size();
  blender_c2_rows<Real> r{std::vector<Real>(u, Real(0)), std::vector<Real>(u, Real(1)), std::vector<Real>(u, Real(0)),
                          std::vector<Real>(u, Real(0))};
  for (std::size_t i = 0; i < u; ++i) {
    blender_point<Real> p, q;
    if (nb.prev(i, p) && nb.next(i, q)) {
      const Real hl = k[i].time - p.time, hr = q.time - k[i].time;
      r.ra[i] = hr;
      r.rb[i] = Real(2) * (hl + hr);
      r.rc[i] = hl;
      r.rd[i] = Real(3) * (hr * (k[i].value - p.value) / hl + hl * (q.value - k[i].value) / hr);
    } else if (linear) {
      r.rb[i] = Real(2);
      (i == 0 ? r.rc[i] : r.ra[i]) = Real(1);
      r.rd[i] = Real(3) * nb.chord(i == 0 ? 0 : n - 2);
    }  // else constant extrapolation: m = 0
  }
  return r;
}

/// The auto slopes under smoothing cont_accel: the C2 spline of blender_c2_system, with
/// auto_clamped keys fixed by an active set (see the header).
template <class Real>
[[nodiscard]] std::vector<Real> blender_slopes_cont_accel(const blender_neighbours<Real>& nb, bool linear) {
  const auto& k = nb.k;
  const std::size_t n = k.size();
  const std::size_t u = nb.cyclic ? n - 1 : n;
  // auto_clamped extrema are flat before anything is solved; other clamped keys are fixed round
  // by round (measured: the extrema never take part in the solve).
  std::vector<bool> fixed(u, false);
  std::vector<Real> m(u, Real(0));
  for (std::size_t i = 0; i < u; ++i) fixed[i] = blender_clamped(k[i]) && nb.extremum(i);
  const blender_c2_rows<Real> rows = blender_c2_system(nb, u, linear);
  const std::vector<bool> extremum = fixed;
  // Active set: clamp the keys whose solved slope breaks their bound, release a clamped key whose
  // own equation, given its neighbours, is back inside the bound; until nothing changes.
  for (std::size_t round = 0; round <= 4 * u + 4; ++round) {
    std::vector<Real> a = rows.ra, bb = rows.rb, cc = rows.rc;
    for (std::size_t i = 0; i < u; ++i)
      if (fixed[i]) {
        a[i] = cc[i] = Real(0);
        bb[i] = Real(1);
      } else {
        m[i] = rows.rd[i];
      }
    // m holds the right-hand side (the fixed slopes stay as they are) and becomes the solution.
    if (nb.cyclic)
      curvebench::detail::solve_cyclic_tridiagonal<Real, Real>(a, bb, cc, std::span<Real>(m));
    else
      curvebench::detail::solve_tridiagonal<Real, Real>(a, bb, cc, std::span<Real>(m));
    bool changed = false;
    for (std::size_t i = 0; i < u; ++i) {
      if (extremum[i] || !blender_clamped(k[i])) continue;
      if (!fixed[i]) {
        const Real mc = nb.clamp(i, m[i]);
        if (mc != m[i]) {
          m[i] = mc;
          fixed[i] = true;
          changed = true;
        }
      } else {
        const Real ml = m[i > 0 ? i - 1 : u - 1], mr = m[i + 1 < u ? i + 1 : 0];
        const Real free_m = (rows.rd[i] - rows.ra[i] * ml - rows.rc[i] * mr) / rows.rb[i];
        if (nb.clamp(i, free_m) == free_m) {
          fixed[i] = false;
          changed = true;
        }
      }
    }
    if (!changed) break;
  }
  std::vector<Real> slope(n);
  for (std::size_t i = 0; i < n; ++i) slope[i] = m[i < u ? i : 0];
  return slope;
}

/// auto and auto_clamped: the handles along the key's slope, of the auto time lengths.
template <class Real>
void blender_place_auto(blender_key<Real>& key, const Real& slope, const std::pair<Real, Real>& lengths) {
  const auto [dl, dr] = lengths;
  if (is_auto(key.handle_left_type)) key.handle_left = {Real(key.time - dl), Real(key.value - slope * dl)};
  if (is_auto(key.handle_right_type)) key.handle_right = {Real(key.time + dr), Real(key.value + slope * dr)};
}

/// aligned: the left handle kept, the right one keeps its length and takes the opposite direction.
template <class Real>
void blender_align(blender_key<Real>& key) {
  using std::sqrt;
  const Real lx = key.time - key.handle_left.time, ly = key.value - key.handle_left.value;
  const Real rx = key.handle_right.time - key.time, ry = key.handle_right.value - key.value;
  const Real ll = sqrt(lx * lx + ly * ly), lr = sqrt(rx * rx + ry * ry);
  if (ll > Real(0)) key.handle_right = {Real(key.time + lx * lr / ll), Real(key.value + ly * lr / ll)};
}

/// vector: a third of its side's interval along the chord to the neighbour key (an end key's
/// missing side mirrors the other, pointing away from it).
template <class Real>
void blender_vector_handles(std::vector<blender_key<Real>>& k, const blender_neighbours<Real>& nb) {
  const std::size_t n = k.size();
  for (std::size_t i = 0; i < n; ++i) {
    for (bool left : {true, false}) {
      blender_key<Real>& key = k[i];
      if ((left ? key.handle_left_type : key.handle_right_type) != handle_type::vector) continue;
      const bool to_left = (left && i > 0) || (!left && i + 1 == n);
      const blender_key<Real>& target = k[to_left ? i - 1 : i + 1];
      const Real s = (target.value - key.value) / (target.time - key.time);
      const Real out_dt = left ? Real(-nb.interval(i, left) / Real(3)) : Real(nb.interval(i, left) / Real(3));
      const Real out_dv = s * out_dt;
      const blender_point<Real> p{Real(key.time + out_dt), Real(key.value + out_dv)};
      if (left)
        key.handle_left = p;
      else
        key.handle_right = p;
    }
  }
}

/// Whether key i's handles are fixed before cont_accel smooths (Blender's locked auto keys): an
/// auto / auto_clamped key made flat as an auto_clamped extremum, or at an end of a curve whose
/// extrapolation is constant.
template <class Real>
[[nodiscard]] bool blender_locked(const blender_neighbours<Real>& nb, std::size_t i, bool linear) {
  if (!blender_auto_key(nb.k[i])) return false;
  if (blender_clamped(nb.k[i]) && nb.extremum(i)) return true;
  return !linear && !nb.cyclic && (i == 0 || i + 1 == nb.size());
}

/// A point of a run of blender_smooth_run: the key whose left side and the key whose right side it
/// is (the same key but at a cyclic curve's joint, key n-1 and key 0).
struct blender_run_point {
  std::size_t left, right;
};

/// cont_accel on a curve that mixes auto keys with vector, aligned or free ones (see the header):
/// the keys whose handles are both auto and not locked (blender_locked) form runs
/// between the other keys, and each run, with the key before and after it, is smoothed on its own.
/// The unknowns are the handles' value offsets h_j (right side; the left side is -h_j / l_j,
/// l_j = dx_{j+1} / dx_j, handles of time length dx / 3), the rows C2 continuity
///   l_j^2 h_{j-1} + 2 (l_j + 1) h_j + h_{j+1} / l_{j+1} = dy_j l_j^2 + dy_{j+1}.
/// An end of the run whose facing handle is vector, or auto at an end of the curve, takes the
/// zero-acceleration row (2 h_0 + h_1 / l_1 = dy_1, or l^2 h_{n-2} + 2 l h_{n-1} = dy l^2) and
/// its handle is set; any other end is held at its handle's offset, the handle first scaled to at
/// most 2/3 of the interval, and its time length x enters its neighbour's row as
/// (1 - 3 x / dx) (times l_1 at the start). auto_clamped keys bound their h by the adjacent value
/// changes (no reversal, no overshoot), by an active set: an h past its bound is held at it
/// (those pulled towards a nonzero bound first), a held one is released, at most twice, when its
/// own row would move it back inside. A run of two keys with both ends held, or both solved, is
/// left as it is. This is Blender's smoothing (BKE_nurb_handle_smooth_fcurve in Blender's curve
/// code, read for the rules; measured on tests/data/recorded/blender_mixed.json).
template <class Real>
void blender_smooth_run(std::vector<blender_key<Real>>& k, std::span<const blender_run_point> run,
                        const std::vector<bool>& locked, bool cyclic) {
  using std::abs;
  const std::size_t n = k.size(), count = run.size();
  blender_key<Real>& first_key = k[run.front().right];
  blender_key<Real>& last_key = k[run.back().left];
  const bool solve_first =
      first_key.handle_right_type == handle_type::vector ||
      (!cyclic && run.front().right == 0 && is_auto(first_key.handle_right_type) && !locked[run.front().right]);
  const bool solve_last =
      last_key.handle_left_type == handle_type::vector ||
      (!cyclic && run.back().left + 1 == n && is_auto(last_key.handle_left_type) && !locked[run.back().left]);
  if (count < 2 || (count == 2 && solve_first == solve_last)) return;
  std::vector<Real> dx(count, Real(0)), dy(count, Real(0)), l(count, Real(1));
  for (std::size_t i = 1; i < count; ++i) {
    dx[i] = k[run[i].left].time - k[run[i - 1].right].time;
    dy[i] = k[run[i].left].value - k[run[i - 1].right].value;
  }
  for (std::size_t i = 1; i + 1 < count; ++i) l[i] = dx[i + 1] / dx[i];
  // Bounds of auto_clamped keys: no reversal against, no overshoot of, the adjacent value change.
  const Real big = std::numeric_limits<Real>::max();
  std::vector<Real> hmin(count, -big), hmax(count, big);
  const auto bound = [&](std::size_t i, const Real& d, bool on) {
    if (!on) return;
    if (d > Real(0)) {
      hmax[i] = std::min(hmax[i], d);
      hmin[i] = Real(0);
    } else if (d < Real(0)) {
      hmax[i] = Real(0);
      hmin[i] = std::max(hmin[i], d);
    } else {
      hmax[i] = hmin[i] = Real(0);
    }
  };
  const auto clamped = [&](const blender_run_point& q) {
    return blender_clamped(k[q.left]) || blender_clamped(k[q.right]);
  };
  for (std::size_t i = 1; i < count; ++i) {
    bound(i - 1, dy[i], clamped(run[i - 1]));
    bound(i, Real(dy[i] * l[i]), clamped(run[i]));
  }
  std::vector<Real> a(count, Real(0)), b(count, Real(1)), c(count, Real(0)), d(count, Real(0));
  // A held end: its handle (scaled to at most 2/3 of the interval) and the time-length correction.
  const auto held = [](Real hx, Real hy, const Real& span, Real& adj) {
    const Real fac = span / (hx + span / Real(3));
    if (fac < Real(1)) hx *= fac, hy *= fac;
    adj = Real(1) - Real(3) * hx / span;
    return hy;
  };
  Real adj_first = 0, adj_last = 0;
  if (solve_first) {
    b[0] = Real(2), c[0] = Real(1) / l[1], d[0] = dy[1];
  } else {
    d[0] = held(first_key.handle_right.time - first_key.time, first_key.handle_right.value - first_key.value, dx[1],
                adj_first);
  }
  if (solve_last) {
    const Real ll = l[count - 1];
    a[count - 1] = ll * ll, b[count - 1] = Real(2) * ll, c[count - 1] = Real(0), d[count - 1] = dy[count - 1] * ll * ll;
  } else {
    d[count - 1] = held(last_key.time - last_key.handle_left.time, last_key.value - last_key.handle_left.value,
                        dx[count - 1], adj_last);
  }
  for (std::size_t i = 1; i + 1 < count; ++i) {
    a[i] = l[i] * l[i];
    b[i] = Real(2) * (l[i] + Real(1));
    c[i] = Real(1) / l[i + 1];
    d[i] = dy[i] * l[i] * l[i] + dy[i + 1];
  }
  if (count > 2 || solve_last) b[1] += l[1] * adj_first;
  if (count > 2 || solve_first) b[count - 2] += adj_last;
  // The active set on the bounds (see above).
  const std::vector<Real> a0 = a, b0 = b, c0 = c, d0 = d;
  std::vector<bool> is_held(count, false);
  std::vector<int> releases(count, 0);
  std::vector<Real> h(count);
  for (std::size_t round = 0; round < 8 * count + 8; ++round) {
    h = d;
    curvebench::detail::solve_tridiagonal<Real, Real>(a, b, c, std::span<Real>(h));
    bool over = false, locked_one = false, released = false;
    for (bool all : {false, true}) {
      for (std::size_t i = 0; i < count; ++i) {
        if (h[i] >= hmin[i] && h[i] <= hmax[i]) continue;
        over = true;
        const Real target = h[i] > hmax[i] ? hmax[i] : hmin[i];
        if (target != Real(0) || all) {
          is_held[i] = true;
          a[i] = c[i] = Real(0), b[i] = Real(1), d[i] = target;
          locked_one = true;
        }
      }
      if (!over || locked_one) break;
    }
    if (!locked_one)
      for (std::size_t i = 0; i < count; ++i) {
        if (!is_held[i] || releases[i] >= 2) continue;
        const Real state =
            a0[i] * (i > 0 ? h[i - 1] : Real(0)) + b0[i] * h[i] + c0[i] * (i + 1 < count ? h[i + 1] : Real(0)) - d0[i];
        const Real relax = -state * b0[i];
        if ((relax > Real(0) && h[i] < hmax[i]) || (relax < Real(0) && h[i] > hmin[i])) {
          a[i] = a0[i], b[i] = b0[i], c[i] = c0[i], d[i] = d0[i];
          is_held[i] = false;
          ++releases[i];
          released = true;
        }
      }
    if (!over && !released) break;
  }
  // Output: only auto and vector handles take the result; at an end of the curve the key's other
  // auto or vector handle mirrors it.
  const auto output = [&](std::size_t j, bool right, const Real& dv) {
    blender_key<Real>& key = k[j];
    const handle_type mine = right ? key.handle_right_type : key.handle_left_type;
    const handle_type other = right ? key.handle_left_type : key.handle_right_type;
    if (!is_auto(mine) && mine != handle_type::vector) return;
    blender_point<Real>& p = right ? key.handle_right : key.handle_left;
    p.value = Real(key.value + dv);
    const bool endpoint = j == 0 || j + 1 == n;
    if (endpoint && (is_auto(other) || other == handle_type::vector)) {
      blender_point<Real>& o = right ? key.handle_left : key.handle_right;
      o = {Real(key.time + (key.time - p.time)), Real(key.value + (key.value - p.value))};
    }
  };
  for (std::size_t i = 1; i + 1 < count; ++i) {
    output(run[i].left, false, Real(-h[i] / l[i]));
    output(run[i].right, true, h[i]);
  }
  if (solve_first) output(run.front().right, true, h[0]);
  if (solve_last) output(run.back().left, false, Real(-h[count - 1] / l[count - 1]));
}

/// cont_accel on a mixed curve (see blender_smooth_run): the runs of free auto keys. On a cyclic
/// curve whose end keys are free auto keys, key n-1 and key 0 are one point (its left side key
/// n-1's, its right side key 0's), the runs start at the first other key and may pass the joint.
template <class Real>
void blender_smooth_mixed(std::vector<blender_key<Real>>& k, const blender_neighbours<Real>& nb, bool linear) {
  const std::size_t n = k.size();
  std::vector<bool> locked(n);
  for (std::size_t i = 0; i < n; ++i) locked[i] = blender_locked(nb, i, linear);
  const auto free_auto = [&](std::size_t i) { return blender_auto_key(k[i]) && !locked[i]; };
  const bool cyclic = nb.cyclic && free_auto(0) && free_auto(n - 1);
  std::size_t start = 0;
  if (cyclic)
    for (std::size_t i = 1; i + 1 < n; ++i)
      if (!free_auto(i)) {
        start = i;
        break;
      }
  std::vector<blender_run_point> run{{start, start}};
  for (std::size_t i = 1, j = start + 1; i < n; ++i, ++j) {
    blender_run_point q{j, j};
    if (cyclic && j == n - 1) q = {n - 1, 0}, j = 0;
    run.push_back(q);
    if (!free_auto(q.right)) {
      blender_smooth_run(k, std::span<const blender_run_point>(run), locked, cyclic);
      run.assign(1, q);
    }
  }
  if (run.size() > 1) blender_smooth_run(k, std::span<const blender_run_point>(run), locked, cyclic);
}

}  // namespace detail

/// The keys with Blender's handle rules applied (see the header): auto, auto_clamped, vector and
/// aligned handles recomputed, free handles as given; every handle as given when the F-curve's
/// handles are the stored ones (stored_handles). Validates the description.
template <class Real>
[[nodiscard]] std::vector<blender_key<Real>> blender_handles(const blender_fcurve<Real>& c) {
  detail::validate_fcurve(c);
  std::vector<blender_key<Real>> k = c.keys;
  if (k.size() < 2 || c.stored_handles) return k;
  const bool accel = c.smoothing == auto_smoothing::cont_accel;
  const bool linear = c.extrapolation == blender_extrapolation::linear;
  // Blender takes the handles as cyclic only when both end keys are auto on both sides.
  const bool cyclic =
      detail::blender_cyclic(c) && detail::blender_auto_key(k.front()) && detail::blender_auto_key(k.back());
  // The rules read only times and values, which the handles below leave unchanged.
  const detail::blender_neighbours<Real> nb(k, cyclic, accel);
  // cont_accel on a curve mixing auto keys with others smooths runs of auto keys after the keys'
  // own rules (blender_smooth_mixed); a curve of auto keys only is one C2 spline.
  const bool mixed = accel && detail::blender_mixes_auto(k);
  const std::vector<Real> slope =
      accel && !mixed ? detail::blender_slopes_cont_accel(nb, linear) : detail::blender_slopes_none(nb, linear);
  for (std::size_t i = 0; i < k.size(); ++i) {
    // A flat auto_clamped extremum at the cyclic joint has its neighbours' lengths (measured).
    const bool joint_extremum =
        cyclic && accel && (i == 0 || i + 1 == k.size()) && detail::blender_clamped(k[i]) && nb.extremum(i);
    if (detail::is_auto(k[i].handle_left_type) || detail::is_auto(k[i].handle_right_type))
      detail::blender_place_auto(k[i], slope[i], joint_extremum ? nb.neighbour_lengths(i) : nb.auto_lengths(i));
    else if (k[i].handle_left_type == handle_type::aligned)
      detail::blender_align(k[i]);
  }
  detail::blender_vector_handles(k, nb);
  if (mixed) detail::blender_smooth_mixed(k, nb, linear);
  return k;
}

/// Blender's evaluation of an F-curve (see the header): value(t) and derivative(t, order) at any
/// finite t, from the keys with Blender's handle rules.
template <class Real>
class blender_evaluator {
 public:
  using real_type = Real;

  /// solver: the time solver of the Bezier segments; none (the default) is Blender's own in the
  /// float model (blender_root) and exact in every other precision.
  blender_evaluator(const blender_fcurve<Real>& curve, std::optional<time_solver> solver)
      : keys_(blender_handles(curve)),
        solver_(solver),
        cycles_(curve.cycles),
        linear_(curve.extrapolation == blender_extrapolation::linear),
        channel_(make_channel(keys_, curve, solver.value_or(time_solver::exact))) {}

  [[nodiscard]] Real value(const Real& t) const { return eval(t, 0); }
  /// d^order v / dt^order, order 0, 1 or 2 (channel.hpp's and penner.hpp's rules).
  [[nodiscard]] Real derivative(const Real& t, int order) const {
    validate::derivative_order(order);
    if (order > 2) validate::fail("order = " + std::to_string(order) + ": the time derivatives go to order 2");
    return eval(t, order);
  }
  /// The keys after the handle rules.
  [[nodiscard]] const std::vector<blender_key<Real>>& keys() const { return keys_; }
  /// The channel behind the evaluation (eased segments appear there as their chords).
  [[nodiscard]] const channel<Real>& underlying() const { return channel_; }

 private:
  std::vector<blender_key<Real>> keys_;
  std::optional<time_solver> solver_;
  blender_cycles cycles_;
  bool linear_;
  channel<Real> channel_;

  static channel<Real> make_channel(const std::vector<blender_key<Real>>& ks, const blender_fcurve<Real>& c,
                                    time_solver solver) {
    using std::abs;
    std::vector<key<Real>> out;
    for (std::size_t i = 0; i < ks.size(); ++i) {
      const blender_key<Real>& b = ks[i];
      if (b.handle_left.time > b.time)
        validate::fail(detail::bkey_field(i, "handle_left.time") + " = " + to_text(b.handle_left.time) +
                       ": after the key's time " + to_text(b.time) + " (a left handle points back in time)");
      if (b.handle_right.time < b.time)
        validate::fail(detail::bkey_field(i, "handle_right.time") + " = " + to_text(b.handle_right.time) +
                       ": before the key's time " + to_text(b.time) + " (a right handle points forward in time)");
      key<Real> k;
      k.time = b.time;
      k.value = b.value;
      k.interp = b.interpolation == blender_interpolation::constant ? interpolation::constant
                 : b.interpolation == blender_interpolation::bezier ? interpolation::bezier
                                                                    : interpolation::linear;
      handle<Real> in{Real(b.handle_left.time - b.time), Real(b.handle_left.value - b.value)};
      handle<Real> outh{Real(b.handle_right.time - b.time), Real(b.handle_right.value - b.value)};
      // Blender's correction: each handle's time length at most its segment's duration.
      if (i > 0) {
        const Real h = b.time - ks[i - 1].time;
        if (-in.dt > h) {
          in.dv = in.dv * (h / -in.dt);
          in.dt = -h;
        }
      }
      if (i + 1 < ks.size()) {
        const Real h = ks[i + 1].time - b.time;
        if (outh.dt > h) {
          outh.dv = outh.dv * (h / outh.dt);
          outh.dt = h;
        }
      }
      k.in = in;
      k.out = outh;
      out.push_back(k);
    }
    const extrapolation e =
        c.extrapolation == blender_extrapolation::linear ? extrapolation::linear : extrapolation::constant;
    return channel<Real>(std::move(out), e, e, solver);
  }

  /// Linear extrapolation beyond the end key k (the first key before the keys, the last after
  /// them), by k's own interpolation, not its segment's (the last key's is the one no segment
  /// uses): constant, flat; linear, the chord to its neighbour key (flat for a single key);
  /// bezier or eased, the line along its outer handle (the left one before the keys, the right
  /// one after; flat for a handle of zero time length). Measured on
  /// tests/data/recorded/blender_heldout.json (end_key/*, single_key/*, easing/* past their ends). The
  /// slope and value are formed as s = (v_k - v_h) / (t_k - t_h), v_k - s (t_k - t), Blender's
  /// float rounding (the same on the recorded values to the last bit).
  [[nodiscard]] Real extrapolate(const Real& t, int order) const {
    const bool before = t < keys_.front().time;
    const blender_key<Real>& k = before ? keys_.front() : keys_.back();
    Real dt{0}, dv{0};
    if (k.interpolation == blender_interpolation::linear) {
      if (keys_.size() > 1) {
        const blender_key<Real>& nb = before ? keys_[1] : keys_[keys_.size() - 2];
        dt = k.time - nb.time;
        dv = k.value - nb.value;
      }
    } else if (k.interpolation != blender_interpolation::constant) {
      const blender_point<Real>& h = before ? k.handle_left : k.handle_right;
      dt = k.time - h.time;
      dv = k.value - h.value;
    }
    if (dt == Real(0)) return order == 0 ? k.value : Real(0);
    const Real slope = dv / dt;
    if (order == 0) return k.value - slope * Real(k.time - t);
    return order == 1 ? slope : Real(0);
  }

  [[nodiscard]] Real inside(const Real& t, int order) const {
    const Real t_first = keys_.front().time, t_last = keys_.back().time;
    if (linear_ && (t < t_first || t > t_last)) return extrapolate(t, order);
    if (keys_.size() > 1 && t >= t_first && t < t_last) {
      const std::size_t i =
          curvebench::detail::breakpoint_at_or_below(std::span<const blender_key<Real>>(keys_), t,
                                                     [](const blender_key<Real>& k) -> const Real& { return k.time; });
      const blender_key<Real>& k0 = keys_[i];
      if (is_eased(k0.interpolation)) {
        const blender_key<Real>& k1 = keys_[i + 1];
        return penner_ease(penner_family_of(k0.interpolation), k0.easing, k0.params, Real(t - k0.time), k0.value,
                           Real(k1.value - k0.value), Real(k1.time - k0.time), order);
      }
      if constexpr (std::is_same_v<Real, float>)
        if (order == 0 && k0.interpolation == blender_interpolation::bezier && t > k0.time) return bezier_value(i, t);
    }
    return order == 0 ? channel_.value(t) : channel_.derivative(t, order);
  }

  /// A float or double that is the rounded result of the operation that made it: stored through a
  /// volatile, so that no compiler fuses a product into the next sum (an FMA rounds once where
  /// Blender's arithmetic rounds twice, and the emulation must not depend on the target's contraction).
  template <class F>
  static F rounded(F x) {
    volatile F r = x;
    return r;
  }

  /// The power-form coefficients c1, c2, c3 of the cubic Bezier p0..p3 (c0 = p0) as Blender forms
  /// them in float, for its time and its value cubic alike: c1 = 3 (p1 - p0), c2 = 3 ((p0 - 2 p1) +
  /// p2), c3 = (p3 - p0) + 3 (p1 - p2).
  static std::array<float, 3> power_coefficients(float p0, float p1, float p2, float p3) {
    return {rounded(3.0f * rounded(p1 - p0)), rounded(3.0f * rounded(rounded(p0 - rounded(2.0f * p1)) + p2)),
            rounded(rounded(p3 - p0) + rounded(3.0f * rounded(p1 - p2)))};
  }
  /// A cube root as Blender takes it: exp(log(|d|) / 3) with d's sign, 0 at 0 (not std::cbrt,
  /// whose last bits differ).
  static double blender_cube_root(double d) {
    if (d == 0.0) return 0.0;
    return d < 0.0 ? -std::exp(rounded(std::log(-d) / 3.0)) : std::exp(rounded(std::log(d) / 3.0));
  }

  /// Blender's root u of the time cubic with float control times q0..q3 at frame x: the power
  /// coefficients formed in float (c0 = q0 - x, the others power_coefficients'), then solved in double by Cardano's
  /// formula (one real root) or the trigonometric one (three), a quadratic or a linear equation where the leading
  /// coefficients are exactly 0, each root rounded to float and the first in [-1e-10, 1.000001]
  /// taken; none when no root lies there. Measured: with the stored handles it gives Blender
  /// 3.4.1's recorded values bit for bit (tests/test_blender.cpp), where the exact root of the
  /// same cubic rounded to float differs from Blender's root by a float ulp on 3 % of them.
  [[nodiscard]] static std::optional<float> blender_root(float x, float q0, float q1, float q2, float q3) {
    const double c0 = rounded(q0 - x);
    const auto [f1, f2, f3] = power_coefficients(q0, q1, q2, q3);
    const double c1 = f1, c2 = f2, c3 = f3;
    const auto in_segment = [](float r) { return r >= static_cast<float>(-1.0e-10) && r <= 1.000001f; };
    std::array<double, 3> roots{};
    std::size_t n = 0;
    if (c3 != 0.0) {
      const double a = rounded(rounded(c2 / c3) / 3.0), b = rounded(c1 / c3), c = rounded(c0 / c3);
      const double aa = rounded(a * a);
      const double p = rounded(rounded(b / 3.0) - aa);
      const double q = rounded(rounded(rounded(rounded(2.0 * aa) * a) - rounded(a * b)) + c) / 2.0;
      const double ppp = rounded(rounded(p * p) * p);
      const double d = rounded(rounded(q * q) + ppp);
      if (d > 0.0) {
        const double r = std::sqrt(d);
        roots[n++] = rounded(rounded(blender_cube_root(rounded(-q + r)) + blender_cube_root(rounded(-q - r))) - a);
        // Blender tests only this root: a cubic with one real root has no other.
      } else if (d == 0.0) {
        const double r = blender_cube_root(-q);
        roots[n++] = rounded(rounded(2.0 * r) - a);
        roots[n++] = rounded(-r - a);
      } else {
        const double phi = std::acos(rounded(-q / std::sqrt(-ppp)));
        const double r = std::sqrt(-p);
        const double cp = std::cos(phi / 3.0);
        const double sq = std::sqrt(rounded(3.0 - rounded(rounded(3.0 * cp) * cp)));
        roots[n++] = rounded(rounded(rounded(2.0 * r) * cp) - a);
        roots[n++] = rounded(rounded(-r * rounded(cp + sq)) - a);
        roots[n++] = rounded(rounded(-r * rounded(cp - sq)) - a);
      }
    } else if (c2 != 0.0) {
      const double disc = rounded(rounded(c1 * c1) - rounded(rounded(4.0 * c2) * c0));
      if (disc > 0.0) {
        const double r = std::sqrt(disc);
        roots[n++] = rounded(-c1 - r) / rounded(2.0 * c2);
        roots[n++] = rounded(-c1 + r) / rounded(2.0 * c2);
      } else if (disc == 0.0) {
        roots[n++] = -c1 / rounded(2.0 * c2);
      }
    } else if (c1 != 0.0) {
      roots[n++] = -c0 / c1;
    } else if (c0 == 0.0) {
      roots[n++] = 0.0;
    }
    for (std::size_t k = 0; k < n; ++k) {
      const auto r = static_cast<float>(roots[k]);
      if (in_segment(r)) return r;
    }
    return std::nullopt;
  }

  /// The value of Bezier segment i at time t (inside it) in float as Blender forms it: the handles
  /// as stored, corrected in Blender's order of operations (make_channel's correction of the same
  /// rule is in relative handles, rounded otherwise), the root u of the time cubic of those absolute
  /// control times (Blender's own, blender_root, unless a solver was chosen: then that solver's in
  /// double, where float times are exact) rounded to float, then the value cubic in power form,
  /// y0 + u c1 + u^2 c2 + u^3 c3 (power_coefficients), summed left to right.
  /// de Casteljau's rounding of the same cubic at the root of the float-relative control times was
  /// up to 2 float ulps from Blender's values (tests/data/blender_export, stepsAction.rotation_euler.2
  /// at t = 6.5 to 7.5).
  [[nodiscard]] float bezier_value(std::size_t i, float t) const {
    const blender_key<float>& k0 = keys_[i];
    const blender_key<float>& k1 = keys_[i + 1];
    // Blender returns the first key's value where the four values lie within FLT_EPSILON of each
    // other (absolute: |y0 - y3|, |y1 - y2| and |y2 - y3|, on the handles before correction).
    const float eps = std::numeric_limits<float>::epsilon();
    if (std::abs(k0.value - k1.value) < eps && std::abs(k0.handle_right.value - k1.handle_left.value) < eps &&
        std::abs(k1.handle_left.value - k1.value) < eps)
      return k0.value;
    const float h = k1.time - k0.time;
    // Blender's handle correction: a handle longer in time than the segment is shortened along
    // itself to the segment's duration.
    const auto corrected = [h](const blender_key<float>& k, blender_point<float> p) {
      const float dt = std::abs(k.time - p.time);
      if (dt > h) {
        const float fac = h / dt;
        p.time = rounded(k.time - rounded(fac * rounded(k.time - p.time)));
        p.value = rounded(k.value - rounded(fac * rounded(k.value - p.value)));
      }
      return p;
    };
    const blender_point<float> p1 = corrected(k0, k0.handle_right), p2 = corrected(k1, k1.handle_left);
    float u = 0;
    if (solver_) {
      const double t0 = k0.time;
      const time_cubic<double> x{0.0, double(p1.time) - t0, double(p2.time) - t0, double(k1.time) - t0};
      u = static_cast<float>(solve_time(*solver_, x, double(t) - t0).u);
    } else {
      const std::optional<float> r = blender_root(t, k0.time, p1.time, p2.time, k1.time);
      if (!r) return 0.0f;  // Blender's value where its solver finds no root in the segment
      u = *r;
    }
    const float y0 = k0.value;
    const auto [c1, c2, c3] = power_coefficients(y0, p1.value, p2.value, k1.value);
    const float uu = rounded(u * u);
    return rounded(rounded(rounded(y0 + rounded(u * c1)) + rounded(uu * c2)) + rounded(rounded(uu * u) * c3));
  }

  [[nodiscard]] Real eval(const Real& t, int order) const {
    using std::floor;
    using std::fmod;
    if (!is_finite(t)) throw std::domain_error("t = " + to_text(t) + ": an F-curve is evaluated at finite times only");
    const Real t_first = keys_.front().time, t_last = keys_.back().time;
    // One key, linear extrapolation: extrapolate's rule (along the handle on that side for a
    // bezier or eased key, flat for constant and linear ones).
    if (keys_.size() == 1 && linear_ && t != t_first) return extrapolate(t, order);
    if (!cycles_.enabled || keys_.size() < 2 || (t >= t_first && t <= t_last)) return inside(t, order);
    const bool before = t < t_first;
    const cycles_mode mode = before ? cycles_.mode_before : cycles_.mode_after;
    const int count = before ? cycles_.cycles_before : cycles_.cycles_after;
    const Real period = t_last - t_first;
    if (mode == cycles_mode::none) return inside(t, order);
    // Repeat number k >= 1 on this side and the position r in [0, period] inside it.
    const Real dist = before ? t_first - t : t - t_last;
    Real k = floor(dist / period);
    Real r = dist - k * period;
    if (r > Real(0))
      k += Real(1);
    else
      r = period;  // exactly at a repeat's far end
    if (count > 0 && k > Real(count)) return inside(t, order);
    // Forward repeats: after the range the wrapped time is t_first + r, before it t_last - r.
    bool mirrored = mode == cycles_mode::mirror && fmod(k, Real(2)) == Real(1);
    Real wrapped = before ? t_last - r : t_first + r;
    if (mirrored) wrapped = before ? t_first + r : t_last - r;
    Real v = inside(std::clamp(wrapped, t_first, t_last), order);
    if (mirrored && order == 1) v = -v;
    if (mode == cycles_mode::repeat_offset && order == 0) {
      const Real shift = keys_.back().value - keys_.front().value;
      v += before ? Real(-k * shift) : Real(k * shift);
    }
    return v;
  }
};

/// The evaluator of an F-curve as Blender computes it (Real = float) or its truth (Real = real50);
/// no solver (the default) is Blender's own root finding in float and exact at other precisions
/// (see the header).
template <class Real>
[[nodiscard]] blender_evaluator<Real> blender_model(const blender_fcurve<Real>& curve,
                                                    std::optional<time_solver> solver = std::nullopt) {
  return blender_evaluator<Real>(curve, solver);
}

/// The same description in another Real (for the 50-digit truth of a float description).
template <class To, class From>
[[nodiscard]] blender_fcurve<To> convert_fcurve(const blender_fcurve<From>& c) {
  blender_fcurve<To> out;
  out.extrapolation = c.extrapolation;
  out.smoothing = c.smoothing;
  out.cycles = c.cycles;
  out.stored_handles = c.stored_handles;
  for (const auto& k : c.keys) {
    blender_key<To> b;
    b.time = To(k.time);
    b.value = To(k.value);
    b.handle_left = {To(k.handle_left.time), To(k.handle_left.value)};
    b.handle_right = {To(k.handle_right.time), To(k.handle_right.value)};
    b.handle_left_type = k.handle_left_type;
    b.handle_right_type = k.handle_right_type;
    b.interpolation = k.interpolation;
    b.easing = k.easing;
    b.params = {To(k.params.back), To(k.params.amplitude), To(k.params.period)};
    out.keys.push_back(b);
  }
  return out;
}

}  // namespace curvebench::channel
