// Keyframe channels: a value over time given by keys, the interpolation of the segment that
// starts at each key, and the extrapolation before the first and after the last key; evaluated
// at any finite time, with exact first and second time derivatives, and viewed as the planar
// curve P(u) = (t(u), v(u)) so that arc length, s(u) and the property audit apply.
//
// Keys: key { time, value, in, out, interp }. in and out are handle offsets (dt, dv) from the key
// in the (time, value) plane: in.dt <= 0, out.dt >= 0. interp says how the segment from this key
// to the next one interpolates (the last key's interp is unused):
// - constant: the key's value holds until the next key (the jump is at the next key's time);
// - step_next: the next key's value right after the key (the jump is just after the key's time);
// - linear: the straight line between the two keys;
// - bezier: the cubic Bezier with control points key0, key0 + key0.out, key1 + key1.in, key1 in
//   the (time, value) plane (free, weighted handles). Time is x(u), a cubic in u; the value at a
//   time needs u with x(u) = t first (channel/time_solver.hpp, the chosen time_solver). The handles
//   may reach beyond the segment as long as time stays monotone (validate_time_cubic's condition);
// - hermite: slopes only, unweighted: the cubic Hermite polynomial in t with the slopes
//   m0 = key0.out.dv / key0.out.dt and m1 = key1.in.dv / key1.in.dt (only each handle's direction
//   counts, its length does not; dt must be nonzero). Time is linear in u, no inversion. The
//   hermite segment equals the bezier segment whose handles sit at thirds of the interval along
//   the same directions (Bernstein values v0 + m0 h / 3 and v1 - m1 h / 3).
// out_handle(slope, weight, span) and in_handle(...) make a handle from a slope and a weight, the
// handle's time length as a fraction of the interval (as animation tools store it; 1/3 is the
// unweighted default).
// Extrapolation, separately before the first and after the last key:
// - constant: the end key's value;
// - linear: the line through the end key with the end segment's slope at that key: dv/dt of the
//   segment there (for bezier the handle's direction, or where the handle has zero length the
//   limit of dv/dt, the direction of the first control point off the key); constant and step_next
//   ends extrapolate flat. A vertical end tangent with linear extrapolation is an invalid_input;
// - cycle: the keyed range [t_first, t_last] repeated, wrapped time t_first + (t - t_first) mod T,
//   T = t_last - t_first;
// - cycle_offset: as cycle, each repeat shifted by k (v_last - v_first), k the number of periods;
// - oscillate: back and forth, every other repeat mirrored in time (t_first + r forwards, then
//   t_last - r), so dv/dt changes sign on the mirrored repeats.
// A one-key channel is constant (its value everywhere, derivatives 0) under every extrapolation.
// Side convention: at a key's time the segment starting at the key applies (a constant segment
// gives its key's value, step_next its key's value too, the jump comes after); the last key's time
// belongs to the keyed range (value v_last, derivatives the left limits of the last segment), and
// in a cycle its repeats t_last + k T are the first key of the next repeat.
// Derivatives: derivative(t, order) with order 0, 1, 2, exact (no differences): dv/dt = v'(u) /
// x'(u), d2v/dt2 = (v''(u) x'(u) - v'(u) x''(u)) / x'(u)^3 through the inversion (for hermite and
// linear x' = h, x'' = 0). Where x'(u) = 0 (a vertical tangent: a zero-length time handle at an end
// or the double root at a regression limit), order 1 returns the limit of dv/dt along the segment:
// +-infinity (the sign of v'(u)) when v'(u) != 0, else the finite ratio of the first higher
// derivatives (a zero-length handle gives the direction to the next control point); order 2 throws
// std::domain_error there (unbounded), except on a segment that is a line in (t, v) (zero-length
// handles on v = a t + b), where it is 0. Steps and constant pieces have derivative 0; the jumps have
// none.
// Curve view: curve() is P(u) on [0, segments], segment i on [i, i+1] with local w = u - i, the
// breakpoints the integers; derivative(u, order) exact for every order. P(i) is always key i. A
// constant or step_next segment is the graph with its jump drawn in, so that the curve stays
// continuous and every arc-length method (chords and polygons as well as quadrature) measures the
// same length, the jump's height included: constant runs horizontally at v_i on [i, i + 1/2] and
// climbs at t_{i+1} to v_{i+1} on [i + 1/2, i + 1]; step_next climbs at t_i first, then runs at
// v_{i+1}; i + 1/2 is a breakpoint. A one-key channel's curve is the single point P(0) on [0, 0].
// Validation (invalid_input naming the key index and field, with the value): no keys; non-finite
// numbers (keys[i].time, .value, .in.dt, .in.dv, .out.dt, .out.dv); keys out of time order or with
// duplicate times, or too close to be resolved; handles pointing backwards in time (in.dt > 0,
// out.dt < 0); regressive bezier segments; zero-length handle times on a hermite segment; enum
// values outside their lists; a vertical end tangent under linear extrapolation. to_string and
// from_string<interpolation> / from_string<extrapolation> use lowercase snake_case names.
// Evaluating at a non-finite time throws std::domain_error.
// Algorithm and sources: binary search of the key times; Bezier and Hermite segments in Bernstein
// form by de Casteljau (Farin, Curves and Surfaces for CAGD); the inversion by the chosen solver on
// the control times relative to the segment's start (segment_time_cubic), so keys at frame 1e5
// keep the accuracy they have near 0;
// extrapolation by fmod of the time. Derived from the definitions above, no tool's code.
// Cost: O(n) construction, O(log n) search plus the solver's cost (bezier only) per evaluation; no
// allocation when evaluating (evaluate() writes into the caller's span).
// Accuracy: hermite, linear and constant segments within a few eps of the value range; bezier
// segments within the time solver's bound (tests/test_time_solvers.cpp; 4 ulps of the range for
// the curvebench and exact solvers) plus t's own rounding times |dv/dt|; cycle modes add the
// rounding of the wrapped time (one ulp of the time's magnitude) times |dv/dt|
// (tests/test_channel.cpp measures all of these against real50).
#pragma once

#include "curvebench/channel/detail/channel_segment.hpp"
#include "curvebench/channel/detail/cubic_time.hpp"
#include "curvebench/channel/time_solver.hpp"
#include "curvebench/core/curve.hpp"
#include "curvebench/core/detail/segment_lookup.hpp"
#include "curvebench/core/error.hpp"
#include "curvebench/core/point.hpp"
#include "curvebench/core/real.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <memory>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace curvebench::channel {

/// What a channel does before its first or after its last key (see the header).
enum class extrapolation : std::uint8_t { constant, linear, cycle, cycle_offset, oscillate };

inline constexpr std::array<interpolation, 5> all_interpolations{interpolation::constant, interpolation::step_next,
                                                                 interpolation::linear, interpolation::bezier,
                                                                 interpolation::hermite};
inline constexpr std::array<extrapolation, 5> all_extrapolations{extrapolation::constant, extrapolation::linear,
                                                                 extrapolation::cycle, extrapolation::cycle_offset,
                                                                 extrapolation::oscillate};

[[nodiscard]] inline const char* to_string(interpolation i) {
  switch (i) {
    case interpolation::constant: return "constant";
    case interpolation::step_next: return "step_next";
    case interpolation::linear: return "linear";
    case interpolation::bezier: return "bezier";
    case interpolation::hermite: return "hermite";
  }
  return "unknown";
}

[[nodiscard]] inline const char* to_string(extrapolation e) {
  switch (e) {
    case extrapolation::constant: return "constant";
    case extrapolation::linear: return "linear";
    case extrapolation::cycle: return "cycle";
    case extrapolation::cycle_offset: return "cycle_offset";
    case extrapolation::oscillate: return "oscillate";
  }
  return "unknown";
}

/// from_string<interpolation>("bezier"), from_string<extrapolation>("cycle_offset"): the exact
/// lowercase names; anything else is an invalid_input listing them.
template <class Enum>
[[nodiscard]] Enum from_string(std::string_view name);

namespace detail {
template <class Enum, std::size_t N>
[[nodiscard]] Enum enum_from_string(std::string_view what, std::string_view name, const std::array<Enum, N>& all) {
  std::string names;
  for (Enum e : all) {
    if (name == to_string(e)) return e;
    names += names.empty() ? "" : ", ";
    names += to_string(e);
  }
  validate::fail(std::string(what) + " = \"" + std::string(name) + "\": unknown, expected one of " + names);
}
}  // namespace detail

template <>
[[nodiscard]] inline interpolation from_string<interpolation>(std::string_view name) {
  return detail::enum_from_string("interpolation", name, all_interpolations);
}

template <>
[[nodiscard]] inline extrapolation from_string<extrapolation>(std::string_view name) {
  return detail::enum_from_string("extrapolation", name, all_extrapolations);
}

/// A handle as an offset from its key in the (time, value) plane.
template <class Real>
struct handle {
  Real dt{0};
  Real dv{0};
};

/// A key: its time and value, its in and out handles (offsets; in.dt <= 0 <= out.dt), and the
/// interpolation of the segment that starts at it.
template <class Real>
struct key {
  Real time{0};
  Real value{0};
  handle<Real> in{};
  handle<Real> out{};
  interpolation interp = interpolation::linear;
};

/// The out handle with slope dv/dt = slope and time length weight * span (weight >= 0: the
/// fraction of the interval to the next key; 1/3 is the unweighted default).
template <class Real>
[[nodiscard]] handle<Real> out_handle(const Real& slope, const Real& weight, const Real& span) {
  validate::finite("slope", slope);
  validate::finite("weight", weight);
  validate::finite("span", span);
  if (weight < Real(0)) validate::fail("weight = " + to_text(weight) + ": must be >= 0");
  if (!(span > Real(0))) validate::fail("span = " + to_text(span) + ": must be > 0");
  const Real dt = weight * span;
  return {dt, slope * dt};
}

/// The in handle with slope dv/dt = slope and time length weight * span (pointing back in time).
template <class Real>
[[nodiscard]] handle<Real> in_handle(const Real& slope, const Real& weight, const Real& span) {
  const handle<Real> h = out_handle(slope, weight, span);
  return {Real(-h.dt), Real(-h.dv)};
}

template <class Real>
class channel_curve;

namespace detail {
template <class Real>
struct channel_data {
  std::vector<key<Real>> keys;
  std::vector<Real> times;  // keys[i].time
  std::vector<segment<Real>> segments;
  std::vector<Real> breaks;  // 0, 1, ..., segments
  extrapolation before = extrapolation::constant;
  extrapolation after = extrapolation::constant;
  time_solver solver = time_solver::curvebench;
  Real slope_first{0}, slope_last{0};  // dv/dt at the first key (right) and at the last (left)
};

[[nodiscard]] inline std::string key_field(std::size_t i, std::string_view field) {
  return validate::indexed("keys", i) + "." + std::string(field);
}
}  // namespace detail

/// A keyframe channel over Real (float, double, long double, real50); see the header.
template <class Real>
class channel {
 public:
  using real_type = Real;

  explicit channel(std::vector<key<Real>> keys, extrapolation before = extrapolation::constant,
                   extrapolation after = extrapolation::constant, time_solver solver = time_solver::curvebench);

  /// The value at time t (any finite t).
  [[nodiscard]] Real value(const Real& t) const { return eval(t, 0); }
  /// d^order v / dt^order at time t, order 0, 1 or 2 (see the header for vertical tangents).
  [[nodiscard]] Real derivative(const Real& t, int order) const {
    check_derivative(t, order);
    return eval(t, order);
  }
  /// derivative()'s refusals: invalid_input for an order outside 0..2, std::domain_error for a
  /// non-finite t (a model that evaluates without a channel, CSS steps(), refuses as a channel does).
  static void check_derivative(const Real& t, int order) {
    validate::derivative_order(order);
    if (order > 2) validate::fail("order = " + std::to_string(order) + ": a channel's time derivatives go to order 2");
    if (!is_finite(t)) throw std::domain_error("t = " + to_text(t) + ": a channel is evaluated at finite times only");
  }
  /// out[i] = value(times[i]); no allocation. Spans of different sizes are an invalid_input.
  void evaluate(std::span<const Real> times, std::span<Real> out) const {
    validate::same_count("out", out.size(), "times", times.size());
    for (std::size_t i = 0; i < times.size(); ++i) {
      if (!is_finite(times[i]))
        throw std::domain_error(validate::indexed("times", i) + " = " + to_text(times[i]) +
                                ": a channel is evaluated at finite times only");
      out[i] = eval(times[i], 0);
    }
  }

  [[nodiscard]] std::span<const key<Real>> keys() const { return data_->keys; }
  [[nodiscard]] extrapolation before() const { return data_->before; }
  [[nodiscard]] extrapolation after() const { return data_->after; }
  [[nodiscard]] time_solver solver() const { return data_->solver; }
  [[nodiscard]] std::size_t segment_count() const { return data_->segments.size(); }
  /// The segment that evaluates time t in [keys().front().time, keys().back().time]: the one starting
  /// at the last key time <= t (the last key's time belongs to the last segment). Binary search,
  /// O(log n). invalid_input for a channel of one key (no segment) or t outside the keys or not
  /// finite (extrapolation, not a segment, answers there).
  [[nodiscard]] std::size_t segment_at(const Real& t) const {
    const auto& d = *data_;
    if (d.segments.empty()) validate::fail("segment_at: the channel has one key and no segment");
    if (!(t >= d.times.front() && t <= d.times.back()))
      validate::fail("t = " + to_text(t) + ": outside the keys [" + to_text(d.times.front()) + ", " +
                     to_text(d.times.back()) + "], where no segment holds it");
    return locate(t);
  }
  /// The time cubic that segment i (a bezier segment) inverts: its control times relative to
  /// keys()[i].time, {0, out.dt, (t_{i+1} - t_i) + in.dt, t_{i+1} - t_i}; a time t in the segment is
  /// solved as t - keys()[i].time. invalid_input for an index out of range or another interpolation.
  [[nodiscard]] time_cubic<Real> segment_time_cubic(std::size_t i) const {
    if (i >= data_->segments.size())
      validate::fail("segment = " + std::to_string(i) + ": the channel has " + std::to_string(data_->segments.size()) +
                     " segments");
    const auto& s = data_->segments[i];
    if (s.kind != interpolation::bezier)
      validate::fail("segment = " + std::to_string(i) + ": is " + to_string(s.kind) + ", not bezier (no time cubic)");
    return {s.rel[0], s.rel[1], s.rel[2], s.rel[3]};
  }
  /// The planar-curve view P(u) = (t(u), v(u)) (shares the channel's data).
  [[nodiscard]] channel_curve<Real> curve() const { return channel_curve<Real>(data_); }

 private:
  std::shared_ptr<const detail::channel_data<Real>> data_;

  [[nodiscard]] Real eval(const Real& t, int order) const;
  [[nodiscard]] Real inside(const Real& t, int order) const;
  // segment_at without the checks (t within the keys, at least one segment).
  [[nodiscard]] std::size_t locate(const Real& t) const {
    const auto& d = *data_;
    return curvebench::detail::segment_of<Real>(d.times, t);  // times has segments + 1 entries
  }
  [[nodiscard]] Real extrapolate(extrapolation mode, bool before, const Real& t, int order) const;
};

/// The curve view of a channel: P(u) = (t(u), v(u)) on [0, segments] (see the header); satisfies
/// curvebench::curve.
template <class Real>
class channel_curve {
 public:
  using real_type = Real;
  static constexpr int dimension = 2;
  using point_type = point<Real, 2>;

  [[nodiscard]] interval<Real> domain() const { return {Real(0), data_->breaks.back()}; }
  [[nodiscard]] point_type operator()(const Real& u) const { return derivative(u, 0); }
  [[nodiscard]] point_type derivative(const Real& u, int order) const {
    validate::derivative_order(order);
    check_parameter(u, domain());
    const auto& d = *data_;
    if (d.segments.empty())
      return order == 0 ? point_type(d.keys[0].time, d.keys[0].value) : point_type(Real(0), Real(0));
    using std::floor;
    const std::size_t n = d.segments.size();
    std::size_t i = static_cast<std::size_t>(static_cast<long long>(floor(u)));
    if (i >= n) i = n - 1;
    const Real w = u - Real(static_cast<long long>(i));
    const auto& s = d.segments[i];
    if (s.kind == interpolation::constant || s.kind == interpolation::step_next) {
      // Two straight pieces that keep the curve continuous (see the header): constant runs
      // horizontally on [0, 1/2] and climbs to the next key on [1/2, 1]; step_next climbs first.
      const bool horizontal = (s.kind == interpolation::constant) == (w < Real(1) / Real(2));
      const Real f = s.kind == interpolation::constant ? Real(2) * w : Real(2) * w - Real(1);  // along the horizontal
      const Real g = s.kind == interpolation::constant ? Real(2) * w - Real(1) : Real(2) * w;  // along the vertical
      if (horizontal) {
        const Real level = s.kind == interpolation::constant ? s.v[0] : s.v[3];
        if (order == 0) return point_type(f >= Real(1) ? s.t[3] : s.t[0] + f * s.span(), level);
        return order == 1 ? point_type(Real(2) * s.span(), Real(0)) : point_type(Real(0), Real(0));
      }
      const Real at = s.kind == interpolation::constant ? s.t[3] : s.t[0];
      if (order == 0) return point_type(at, g >= Real(1) ? s.v[3] : s.v[0] + g * (s.v[3] - s.v[0]));
      return order == 1 ? point_type(Real(0), Real(2) * (s.v[3] - s.v[0])) : point_type(Real(0), Real(0));
    }
    return point_type(s.time_at(w, order), s.value_at(w, order));
  }
  [[nodiscard]] std::span<const Real> breakpoints() const { return data_->breaks; }

 private:
  friend class channel<Real>;
  explicit channel_curve(std::shared_ptr<const detail::channel_data<Real>> data) : data_(std::move(data)) {}
  std::shared_ptr<const detail::channel_data<Real>> data_;
};

// ---------------------------------------------------------------------------------------------

template <class Real>
channel<Real>::channel(std::vector<key<Real>> keys, extrapolation before, extrapolation after, time_solver solver) {
  using detail::key_field;
  auto d = std::make_shared<detail::channel_data<Real>>();
  validate::count_at_least("keys", keys.size(), 1, "a channel needs a key; one key makes a constant channel");
  const auto known_extrapolation = [](extrapolation e) {
    return std::find(all_extrapolations.begin(), all_extrapolations.end(), e) != all_extrapolations.end();
  };
  if (!known_extrapolation(before))
    validate::fail("extrapolation before = " + std::to_string(static_cast<int>(before)) + ": not an extrapolation");
  if (!known_extrapolation(after))
    validate::fail("extrapolation after = " + std::to_string(static_cast<int>(after)) + ": not an extrapolation");
  if (std::string_view(to_string(solver)) == "unknown")
    validate::fail("time solver = " + std::to_string(static_cast<int>(solver)) + ": not a time_solver");
  for (std::size_t i = 0; i < keys.size(); ++i) {
    const key<Real>& k = keys[i];
    validate::finite(key_field(i, "time"), k.time);
    validate::finite(key_field(i, "value"), k.value);
    validate::finite(key_field(i, "in.dt"), k.in.dt);
    validate::finite(key_field(i, "in.dv"), k.in.dv);
    validate::finite(key_field(i, "out.dt"), k.out.dt);
    validate::finite(key_field(i, "out.dv"), k.out.dv);
    if (std::find(all_interpolations.begin(), all_interpolations.end(), k.interp) == all_interpolations.end())
      validate::fail(key_field(i, "interp") + " = " + std::to_string(static_cast<int>(k.interp)) +
                     ": not an interpolation");
    if (k.in.dt > Real(0))
      validate::fail(key_field(i, "in.dt") + " = " + to_text(k.in.dt) +
                     ": the in handle points forwards in time (must be <= 0)");
    if (k.out.dt < Real(0))
      validate::fail(key_field(i, "out.dt") + " = " + to_text(k.out.dt) +
                     ": the out handle points backwards in time (must be >= 0)");
    if (i > 0) {
      const Real& prev = keys[i - 1].time;
      if (k.time == prev)
        validate::fail(key_field(i, "time") + " = " + to_text(k.time) + " duplicates " + key_field(i - 1, "time") +
                       ": key times must be distinct");
      if (k.time < prev)
        validate::fail("keys must be in increasing time order: " + key_field(i, "time") + " = " + to_text(k.time) +
                       " < " + key_field(i - 1, "time") + " = " + to_text(prev));
      validate::resolvable(key_field(i, "time") + " - " + key_field(i - 1, "time"), prev, k.time,
                           validate::channel_min_span_bits);
    }
  }
  for (std::size_t i = 0; i + 1 < keys.size(); ++i) {
    const key<Real>& k0 = keys[i];
    const key<Real>& k1 = keys[i + 1];
    detail::segment<Real> s{
        k0.interp, {k0.time, k0.time, k1.time, k1.time}, {k0.value, k0.value, k1.value, k1.value}, Real(0), Real(0)};
    const Real h = k1.time - k0.time;
    if (k0.interp == interpolation::bezier) {
      s.t = {k0.time, k0.time + k0.out.dt, k1.time + k1.in.dt, k1.time};
      s.rel = {Real(0), k0.out.dt, Real(h + k1.in.dt), h};
      s.v = {k0.value, k0.value + k0.out.dv, k1.value + k1.in.dv, k1.value};
      validate::finite(key_field(i, "time + out.dt"), s.t[1]);
      validate::finite(key_field(i + 1, "time + in.dt"), s.t[2]);
      validate::finite(key_field(i, "value + out.dv"), s.v[1]);
      validate::finite(key_field(i + 1, "value + in.dv"), s.v[2]);
      if (detail::time_handles_regress(s.rel[0], s.rel[1], s.rel[2], s.rel[3]))
        validate::fail(key_field(i, "out") + " = (" + to_text(k0.out.dt) + ", " + to_text(k0.out.dv) + ") and " +
                       key_field(i + 1, "in") + " = (" + to_text(k1.in.dt) + ", " + to_text(k1.in.dv) +
                       "): the handles of segment " + std::to_string(i) + " [" + to_text(k0.time) + ", " +
                       to_text(k1.time) +
                       "] regress (time runs backwards inside the segment); with h = the segment's duration, "
                       "a = out.dt / h and c = -in.dt / h, time is monotone only when 1 - a - c >= 0 or "
                       "(1 - a - c)^2 <= a c");
    } else if (k0.interp == interpolation::hermite) {
      if (!(k0.out.dt > Real(0)))
        validate::fail(key_field(i, "out.dt") + " = " + to_text(k0.out.dt) +
                       ": a hermite segment takes its slope dv/dt from the handle, which needs dt > 0");
      if (!(k1.in.dt < Real(0)))
        validate::fail(key_field(i + 1, "in.dt") + " = " + to_text(k1.in.dt) +
                       ": a hermite segment takes its slope dv/dt from the handle, which needs dt < 0");
      const Real m0 = k0.out.dv / k0.out.dt, m1 = k1.in.dv / k1.in.dt;
      validate::finite(key_field(i, "out slope"), m0);
      validate::finite(key_field(i + 1, "in slope"), m1);
      s.v = {k0.value, k0.value + m0 * h / Real(3), k1.value - m1 * h / Real(3), k1.value};
      s.m0 = m0;
      s.m1 = m1;
      validate::finite(key_field(i, "hermite control value"), s.v[1]);
      validate::finite(key_field(i + 1, "hermite control value"), s.v[2]);
    }
    d->segments.push_back(s);
  }
  for (const auto& k : keys) d->times.push_back(k.time);
  for (std::size_t i = 0; i <= d->segments.size(); ++i) {
    d->breaks.push_back(Real(static_cast<long long>(i)));
    // A constant or step_next segment's curve turns a corner at its middle (see the header).
    if (i < d->segments.size() &&
        (d->segments[i].kind == interpolation::constant || d->segments[i].kind == interpolation::step_next))
      d->breaks.push_back(Real(static_cast<long long>(i)) + Real(1) / Real(2));
  }
  d->before = before;
  d->after = after;
  d->solver = solver;
  if (!d->segments.empty()) {
    d->slope_first = d->segments.front().slope_at(Real(0));
    d->slope_last = d->segments.back().slope_at(Real(1));
    if (before == extrapolation::linear && !is_finite(d->slope_first))
      validate::fail(
          "extrapolation before = linear needs a finite slope at keys[0]: the first segment's tangent "
          "there is vertical (" +
          key_field(0, "out") + " = (" + to_text(keys[0].out.dt) + ", " + to_text(keys[0].out.dv) + "))");
    if (after == extrapolation::linear && !is_finite(d->slope_last))
      validate::fail("extrapolation after = linear needs a finite slope at " +
                     validate::indexed("keys", keys.size() - 1) + ": the last segment's tangent there is vertical (" +
                     key_field(keys.size() - 1, "in") + " = (" + to_text(keys.back().in.dt) + ", " +
                     to_text(keys.back().in.dv) + "))");
  }
  d->keys = std::move(keys);
  data_ = std::move(d);
}

template <class Real>
Real channel<Real>::eval(const Real& t, int order) const {
  if (!is_finite(t)) throw std::domain_error("t = " + to_text(t) + ": a channel is evaluated at finite times only");
  const auto& d = *data_;
  if (d.segments.empty()) return order == 0 ? d.keys[0].value : Real(0);
  if (t < d.times.front()) return extrapolate(d.before, true, t, order);
  if (t > d.times.back()) return extrapolate(d.after, false, t, order);
  return inside(t, order);
}

template <class Real>
Real channel<Real>::inside(const Real& t, int order) const {
  const auto& d = *data_;
  const auto& s = d.segments[locate(t)];
  const Real w = t >= s.t[3] ? Real(1) : s.local(t, d.solver);
  // At a key (w = 0 or 1) the value is the key's: value_at's polynomial form would meet 0 x inf
  // there when the handles are near double's range (keys at 1e308).
  if (order == 0) return t >= s.t[3] ? s.v[3] : w == Real(0) ? s.v[0] : s.value_at(w, 0);
  if (order == 1) return s.slope_at(w);
  return s.curvature_at(w, t);
}

template <class Real>
Real channel<Real>::extrapolate(extrapolation mode, bool before, const Real& t, int order) const {
  using std::fmod;
  using std::round;
  const auto& d = *data_;
  const Real t_first = d.times.front(), t_last = d.times.back();
  const Real v_first = d.keys.front().value, v_last = d.keys.back().value;
  switch (mode) {
    case extrapolation::constant: return order == 0 ? (before ? v_first : v_last) : Real(0);
    case extrapolation::linear: {
      const Real slope = before ? d.slope_first : d.slope_last;
      if (order == 0) return before ? v_first + (t - t_first) * slope : v_last + (t - t_last) * slope;
      return order == 1 ? slope : Real(0);
    }
    case extrapolation::cycle:
    case extrapolation::cycle_offset:
    case extrapolation::oscillate: {
      const Real period = t_last - t_first;
      const Real offset = t - t_first;
      Real r = fmod(offset, period);  // exact; the sign of offset
      if (r < Real(0)) r += period;
      if (r >= period) r = Real(0);                 // r + period rounded up to the period: the next repeat's start
      const Real k = round((offset - r) / period);  // whole periods; an integer up to rounding, rounded
      bool mirrored = false;
      if (mode == extrapolation::oscillate) {
        using std::abs;
        mirrored = fmod(abs(k), Real(2)) == Real(1);
      }
      const Real wrapped = mirrored ? t_last - r : t_first + r;
      Real result = inside(std::clamp(wrapped, t_first, t_last), order);
      if (mirrored && order == 1) result = -result;
      if (mode == extrapolation::cycle_offset && order == 0) result += k * (v_last - v_first);
      return result;
    }
  }
  return Real(0);
}

}  // namespace curvebench::channel
