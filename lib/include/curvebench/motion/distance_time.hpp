// Distance-time (speed-control) functions: s = S(t) on [0, 1], S(0) = 0, S(1) = 1, with exact
// velocity S' and acceleration S''; the motion P(U(L S(t))) of motion_path.hpp follows S'.
// Families: linear, sine (sin^2(pi t / 2)), sine_plateau and parabolic (accelerate, cruise,
// decelerate), smoothstep, smootherstep, distance_keys_ease (user (t, s) keys through a monotone
// cubic, monotone_cubic.hpp) and speed_curve_ease (user speed keys integrated exactly, normalized).
// Each formula is derived in its class comment. Interface (the distance_time concept): f(t),
// velocity, acceleration, derivative(t, order, side), breakpoints(), continuity() at the joints,
// rest_continuity() at t = 0 and 1 against rest (capped at 2). t outside [0, 1] throws
// std::domain_error; bad parameters throw invalid_input at construction.
// Sources: seed 002 ("Speed Control Function", "Ease-in/Ease-out"); Parent, Computer Animation
// (2012), 3.2. Cost: O(1) per evaluation, O(log n) for the key-based ones.
// Accuracy: closed forms to a few ulps, written without cancellation near both ends.
#pragma once

#include "curvebench/core/curve.hpp"
#include "curvebench/core/error.hpp"
#include "curvebench/core/real.hpp"
#include "curvebench/motion/monotone_cubic.hpp"

#include <boost/math/constants/constants.hpp>

#include <array>
#include <concepts>
#include <cstddef>
#include <limits>
#include <span>
#include <string>
#include <vector>

namespace curvebench::motion {

/// continuity() of a function without interior joints.
inline constexpr int infinitely_smooth = std::numeric_limits<int>::max();

template <class F>
concept distance_time = requires(const F& f, const typename F::real_type& t, int order, side s) {
  typename F::real_type;
  { f(t) } -> std::convertible_to<typename F::real_type>;
  { f.velocity(t) } -> std::convertible_to<typename F::real_type>;
  { f.acceleration(t) } -> std::convertible_to<typename F::real_type>;
  { f.derivative(t, order, s) } -> std::convertible_to<typename F::real_type>;
  { f.breakpoints() } -> std::convertible_to<std::span<const typename F::real_type>>;
  { f.continuity() } -> std::convertible_to<int>;
  { f.rest_continuity() } -> std::convertible_to<int>;
};

namespace detail {

/// The shared surface of the distance-time functions: domain check, order check, the named
/// accessors. Derived implements `Real evaluate(const Real& t, int order, side s) const` for
/// order 0..2 with t already in [0, 1].
template <class Derived, class Real>
class distance_time_base {
 public:
  using real_type = Real;

  [[nodiscard]] static interval<Real> domain() { return {Real(0), Real(1)}; }

  /// d^order S / dt^order, order 0 (distance), 1 (velocity) or 2 (acceleration).
  [[nodiscard]] Real derivative(const Real& t, int order, side s = side::right) const {
    validate::derivative_order(order);
    if (order > 2)
      validate::fail("order = " + std::to_string(order) +
                     ": distance-time functions provide orders 0 (distance), 1 (velocity) and 2 (acceleration)");
    check_parameter(t, domain());
    return static_cast<const Derived&>(*this).evaluate(t, order, s);
  }
  [[nodiscard]] Real operator()(const Real& t) const { return derivative(t, 0); }
  [[nodiscard]] Real velocity(const Real& t) const { return derivative(t, 1); }
  [[nodiscard]] Real acceleration(const Real& t) const { return derivative(t, 2); }
};

/// Validates 0 <= t1 <= t2 <= 1 for the three-phase eases.
template <class Real>
void check_phases(const Real& t1, const Real& t2) {
  validate::in_range("t1", t1, Real(0), Real(1));
  validate::in_range("t2", t2, Real(0), Real(1));
  if (t2 < t1)
    validate::fail("t2 = " + to_text(t2) + " < t1 = " + to_text(t1) +
                   ": the constant-speed phase [t1, t2] must not end before it starts (0 <= t1 <= t2 <= 1)");
}

/// Normalized phase boundaries from frames: t1 = (f1 - f0) / (f3 - f0), t2 = (f2 - f0) / (f3 - f0).
template <class Real>
std::array<Real, 2> phases_from_frames(long long start, long long end_accel, long long start_decel, long long stop) {
  if (!(start < stop))
    validate::fail("stop = " + std::to_string(stop) + " <= start = " + std::to_string(start) +
                   ": the move must end after it starts");
  if (end_accel < start || end_accel > stop)
    validate::fail("end_accel = " + std::to_string(end_accel) + ": must be in [start, stop] = [" +
                   std::to_string(start) + ", " + std::to_string(stop) + "]");
  if (start_decel < end_accel || start_decel > stop)
    validate::fail("start_decel = " + std::to_string(start_decel) + ": must be in [end_accel, stop] = [" +
                   std::to_string(end_accel) + ", " + std::to_string(stop) + "]");
  const Real span = Real(stop - start);
  return {Real(end_accel - start) / span, Real(start_decel - start) / span};
}

/// The joints 0, t1, t2, 1 of a three-phase ease without repeats; returns their number.
template <class Real>
std::size_t phase_breaks(const Real& t1, const Real& t2, std::array<Real, 4>& out) {
  std::size_t n = 0;
  for (const Real& b : {Real(0), t1, t2, Real(1)})
    if (n == 0 || b > out[n - 1]) out[n++] = b;
  return n;
}

/// Checks one key list for the key-based eases: >= 2 keys, times strictly increasing from exactly
/// 0 to exactly 1.
template <class Real>
void check_key_times(std::span<const Real> times) {
  validate::count_at_least("times", times.size(), 2, "keys at t = 0 and t = 1 at least");
  for (std::size_t i = 0; i < times.size(); ++i) validate::in_range("times", times[i], Real(0), Real(1), i);
  validate::increasing<Real>("times", times);
  if (times.front() != Real(0))
    validate::fail("times[0] = " + to_text(times.front()) + ": the first key must be at t = 0");
  if (times.back() != Real(1))
    validate::fail(validate::indexed("times", times.size() - 1) + " = " + to_text(times.back()) +
                   ": the last key must be at t = 1");
}

}  // namespace detail

/// S(t) = t: constant speed 1. C-infinity inside; at rest it is only C0 (the speed jumps to 1).
template <class Real>
class linear_ease : public detail::distance_time_base<linear_ease<Real>, Real> {
 public:
  [[nodiscard]] std::span<const Real> breakpoints() const { return breaks_; }
  [[nodiscard]] static int continuity() { return infinitely_smooth; }
  [[nodiscard]] static int rest_continuity() { return 0; }

 private:
  friend class detail::distance_time_base<linear_ease<Real>, Real>;
  [[nodiscard]] Real evaluate(const Real& t, int order, side) const {
    return order == 0 ? t : (order == 1 ? Real(1) : Real(0));
  }

  std::array<Real, 2> breaks_{Real(0), Real(1)};
};

/// Sinusoidal ease-in/ease-out (seed 002): S = (sin(pi t - pi/2) + 1) / 2 = (1 - cos(pi t)) / 2
/// = sin^2(pi t / 2); S' = (pi / 2) sin(pi t); S'' = (pi^2 / 2) cos(pi t). Maximum speed pi/2 at
/// t = 1/2. C-infinity inside; at rest C1 (S'(0) = 0 but S''(0) = pi^2 / 2).
template <class Real>
class sine_ease : public detail::distance_time_base<sine_ease<Real>, Real> {
 public:
  [[nodiscard]] std::span<const Real> breakpoints() const { return breaks_; }
  [[nodiscard]] static int continuity() { return infinitely_smooth; }
  [[nodiscard]] static int rest_continuity() { return 1; }

 private:
  friend class detail::distance_time_base<sine_ease<Real>, Real>;
  [[nodiscard]] Real evaluate(const Real& t, int order, side) const {
    using std::cos;
    using std::sin;
    const Real pi = boost::math::constants::pi<Real>();
    switch (order) {
      case 0: {
        const Real h = sin(pi * t / Real(2));
        return h * h;
      }
      case 1: return pi / Real(2) * sin(pi * t);
      default: return pi * pi / Real(2) * cos(pi * t);
    }
  }

  std::array<Real, 2> breaks_{Real(0), Real(1)};
};

/// Sine acceleration on [0, t1], constant speed on [t1, t2], sine deceleration on [t2, 1]
/// (Parent's "sine interpolation with a constant-speed middle").
/// Derivation: take the unnormalized speed w(t) = sin(pi t / (2 t1)) on [0, t1] (0 -> 1 with zero
/// slope at t1), w = 1 on [t1, t2], w = sin(pi (1 - t) / (2 (1 - t2))) on [t2, 1] (1 -> 0). Its
/// integral is f = 2 t1 / pi + (t2 - t1) + 2 (1 - t2) / pi; dividing by f gives S(1) = 1 and the
/// maximum speed v = 1 / f. Integrating, with 1 - cos x = 2 sin^2(x / 2):
///   [0, t1]:  S = v (4 t1 / pi) sin^2(pi t / (4 t1)),
///             S' = v sin(pi t / (2 t1)),  S'' = v (pi / (2 t1)) cos(pi t / (2 t1));
///   [t1, t2]: S = v (2 t1 / pi + t - t1),  S' = v,  S'' = 0;
///   [t2, 1]:  S = 1 - v (4 (1 - t2) / pi) sin^2(pi (1 - t) / (4 (1 - t2))),
///             S' = v sin(pi (1 - t) / (2 (1 - t2))),  S'' = -v (pi / (2 (1 - t2))) cos(...).
/// S'' is 0 at t1 and t2 from both sides: C2 at the joints (the jerk jumps). At rest C1 when
/// t1 > 0 and t2 < 1 (S'(0) = 0, S''(0) = v pi / (2 t1) != 0), C0 otherwise. Empty phases
/// (t1 = 0, t2 = 1, t1 = t2) are allowed; t1 = 0, t2 = 1 is the linear ease.
template <class Real>
class sine_plateau_ease : public detail::distance_time_base<sine_plateau_ease<Real>, Real> {
 public:
  /// 0 <= t1 <= t2 <= 1, else invalid_input.
  sine_plateau_ease(const Real& t1, const Real& t2) : t1_(t1), t2_(t2) {
    detail::check_phases(t1, t2);
    const Real pi = boost::math::constants::pi<Real>();
    v_ = Real(1) / (Real(2) * t1_ / pi + (t2_ - t1_) + Real(2) * (Real(1) - t2_) / pi);
    count_ = detail::phase_breaks(t1_, t2_, breaks_);
  }
  /// The phases from frame numbers: accelerate from `start` to `end_accel`, decelerate from
  /// `start_decel` to `stop` (start < stop, start <= end_accel <= start_decel <= stop).
  [[nodiscard]] static sine_plateau_ease from_frames(long long start, long long end_accel, long long start_decel,
                                                     long long stop) {
    const auto p = detail::phases_from_frames<Real>(start, end_accel, start_decel, stop);
    return sine_plateau_ease(p[0], p[1]);
  }

  /// The constant speed of the middle phase, 1 / (2 t1 / pi + t2 - t1 + 2 (1 - t2) / pi).
  [[nodiscard]] Real max_velocity() const { return v_; }
  [[nodiscard]] Real t1() const { return t1_; }
  [[nodiscard]] Real t2() const { return t2_; }
  /// 0, t1, t2, 1 without repeats (empty phases drop out).
  [[nodiscard]] std::span<const Real> breakpoints() const { return {breaks_.data(), count_}; }
  [[nodiscard]] static int continuity() { return 2; }
  [[nodiscard]] int rest_continuity() const { return (t1_ > Real(0) && t2_ < Real(1)) ? 1 : 0; }

 private:
  friend class detail::distance_time_base<sine_plateau_ease<Real>, Real>;
  [[nodiscard]] Real evaluate(const Real& t, int order, side s) const {
    using std::cos;
    using std::sin;
    const Real pi = boost::math::constants::pi<Real>();
    const bool in_first = s == side::right ? t < t1_ : t <= t1_ && t1_ > Real(0);
    const bool in_last = s == side::right ? t >= t2_ && t2_ < Real(1) : t > t2_;
    if (in_first) {
      const Real a = pi * t / (Real(2) * t1_);
      switch (order) {
        case 0: {
          const Real h = sin(a / Real(2));
          return v_ * (Real(4) * t1_ / pi) * h * h;
        }
        case 1: return v_ * sin(a);
        default: return v_ * (pi / (Real(2) * t1_)) * cos(a);
      }
    }
    if (in_last) {
      const Real w = Real(1) - t2_;
      const Real a = pi * (Real(1) - t) / (Real(2) * w);
      switch (order) {
        case 0: {
          const Real h = sin(a / Real(2));
          return Real(1) - v_ * (Real(4) * w / pi) * h * h;
        }
        case 1: return v_ * sin(a);
        default: return -v_ * (pi / (Real(2) * w)) * cos(a);
      }
    }
    switch (order) {
      case 0: return v_ * (Real(2) * t1_ / pi + (t - t1_));
      case 1: return v_;
      default: return Real(0);
    }
  }

  Real t1_, t2_, v_;
  std::array<Real, 4> breaks_;
  std::size_t count_ = 0;
};

/// Constant acceleration on [0, t1], constant speed v on [t1, t2], constant deceleration on [t2, 1]
/// (Parent's parabolic ease-in/ease-out; the seed 002 example frame 22 -> 34 -> 50 -> 67).
/// Derivation: the speed is the trapezoid 0 -> v (linear) -> v -> 0 (linear). Its area is the
/// distance: v t1 / 2 + v (t2 - t1) + v (1 - t2) / 2 = v (1 + t2 - t1) / 2 = 1, so
///   v = 2 / (1 + t2 - t1)   (the maximum speed, in units of the average speed 1).
///   [0, t1]:  S = v t^2 / (2 t1),           S' = v t / t1,            S'' = v / t1;
///   [t1, t2]: S = v (t - t1 / 2),            S' = v,                   S'' = 0;
///   [t2, 1]:  S = 1 - v (1 - t)^2 / (2 (1 - t2)),  S' = v (1 - t) / (1 - t2),  S'' = -v / (1 - t2).
/// The pieces meet with equal S and S' (v t1 / 2 both sides at t1; v (t2 - t1/2) = 1 - v (1 - t2) / 2
/// at t2 by the area equation): C1 at the joints, the acceleration jumps. At rest C1 when t1 > 0
/// and t2 < 1, C0 otherwise. t1 = t2 (no cruise) and empty phases are allowed.
template <class Real>
class parabolic_ease : public detail::distance_time_base<parabolic_ease<Real>, Real> {
 public:
  /// 0 <= t1 <= t2 <= 1, else invalid_input.
  parabolic_ease(const Real& t1, const Real& t2) : t1_(t1), t2_(t2) {
    detail::check_phases(t1, t2);
    v_ = Real(2) / (Real(1) + t2_ - t1_);
    count_ = detail::phase_breaks(t1_, t2_, breaks_);
  }
  /// The phases from frame numbers (see sine_plateau_ease::from_frames).
  [[nodiscard]] static parabolic_ease from_frames(long long start, long long end_accel, long long start_decel,
                                                  long long stop) {
    const auto p = detail::phases_from_frames<Real>(start, end_accel, start_decel, stop);
    return parabolic_ease(p[0], p[1]);
  }

  /// The cruise speed v = 2 / (1 + t2 - t1).
  [[nodiscard]] Real max_velocity() const { return v_; }
  [[nodiscard]] Real t1() const { return t1_; }
  [[nodiscard]] Real t2() const { return t2_; }
  /// 0, t1, t2, 1 without repeats (empty phases drop out).
  [[nodiscard]] std::span<const Real> breakpoints() const { return {breaks_.data(), count_}; }
  [[nodiscard]] static int continuity() { return 1; }
  [[nodiscard]] int rest_continuity() const { return (t1_ > Real(0) && t2_ < Real(1)) ? 1 : 0; }

 private:
  friend class detail::distance_time_base<parabolic_ease<Real>, Real>;
  [[nodiscard]] Real evaluate(const Real& t, int order, side s) const {
    const bool in_first = s == side::right ? t < t1_ : t <= t1_ && t1_ > Real(0);
    const bool in_last = s == side::right ? t >= t2_ && t2_ < Real(1) : t > t2_;
    if (in_first) {
      switch (order) {
        case 0: return v_ * t * t / (Real(2) * t1_);
        case 1: return v_ * t / t1_;
        default: return v_ / t1_;
      }
    }
    if (in_last) {
      const Real w = Real(1) - t2_;
      const Real r = Real(1) - t;
      switch (order) {
        case 0: return Real(1) - v_ * r * r / (Real(2) * w);
        case 1: return v_ * r / w;
        default: return -v_ / w;
      }
    }
    switch (order) {
      case 0: return v_ * (t - t1_ / Real(2));
      case 1: return v_;
      default: return Real(0);
    }
  }

  Real t1_, t2_, v_;
  std::array<Real, 4> breaks_;
  std::size_t count_ = 0;
};

/// Cubic smoothstep S = 3 t^2 - 2 t^3 = t^2 (3 - 2 t); S' = 6 t (1 - t); S'' = 6 (1 - 2 t).
/// The cubic with S(0) = 0, S(1) = 1, S'(0) = S'(1) = 0. Maximum speed 3/2 at t = 1/2.
/// C-infinity inside; at rest C1 (S''(0) = 6).
template <class Real>
class smoothstep_ease : public detail::distance_time_base<smoothstep_ease<Real>, Real> {
 public:
  [[nodiscard]] std::span<const Real> breakpoints() const { return breaks_; }
  [[nodiscard]] static int continuity() { return infinitely_smooth; }
  [[nodiscard]] static int rest_continuity() { return 1; }

 private:
  friend class detail::distance_time_base<smoothstep_ease<Real>, Real>;
  [[nodiscard]] Real evaluate(const Real& t, int order, side) const {
    switch (order) {
      case 0: return t * t * (Real(3) - Real(2) * t);
      case 1: return Real(6) * t * (Real(1) - t);
      default: return Real(6) * (Real(1) - Real(2) * t);
    }
  }

  std::array<Real, 2> breaks_{Real(0), Real(1)};
};

/// Quintic smootherstep S = 6 t^5 - 15 t^4 + 10 t^3 = t^3 (10 + t (6 t - 15));
/// S' = 30 t^2 (1 - t)^2; S'' = 60 t (1 - t)(1 - 2 t). The quintic with S' = S'' = 0 at both ends:
/// starts and stops with zero acceleration. Maximum speed 15/8 at t = 1/2. C-infinity inside;
/// at rest C2 (S'''(0) = 60).
template <class Real>
class smootherstep_ease : public detail::distance_time_base<smootherstep_ease<Real>, Real> {
 public:
  [[nodiscard]] std::span<const Real> breakpoints() const { return breaks_; }
  [[nodiscard]] static int continuity() { return infinitely_smooth; }
  [[nodiscard]] static int rest_continuity() { return 2; }

 private:
  friend class detail::distance_time_base<smootherstep_ease<Real>, Real>;
  [[nodiscard]] Real evaluate(const Real& t, int order, side) const {
    const Real r = Real(1) - t;
    switch (order) {
      case 0: return t * t * t * (Real(10) + t * (Real(6) * t - Real(15)));
      case 1: return Real(30) * t * t * r * r;
      default: return Real(60) * t * r * (Real(1) - Real(2) * t);
    }
  }

  std::array<Real, 2> breaks_{Real(0), Real(1)};
};

namespace detail {
/// Rest continuity of a key-based ease from its exact end values (capped at 2, the orders provided).
template <class F>
int rest_order(const F& f) {
  using Real = typename F::real_type;
  if (f.velocity(Real(0)) != Real(0) || f.velocity(Real(1)) != Real(0)) return 0;
  if (f.acceleration(Real(0)) != Real(0) || f.derivative(Real(1), 2, side::left) != Real(0)) return 1;
  return 2;
}
}  // namespace detail

/// A user distance-time curve from keys (t_i, s_i), interpolated by the monotone cubic of
/// monotone_cubic.hpp. Keys: t strictly increasing from exactly 0 to exactly 1, s non-decreasing
/// from exactly 0 to exactly 1 (S(0) = 0, S(1) = 1), all in [0, 1]. Decreasing s (the object
/// would run backwards, seed 002) and keys outside [0, 1] are rejected with invalid_input; there is
/// no silent clamping. Equal neighbouring s values give a pause (S constant on that interval).
/// The interpolant is monotone (derivation in monotone_cubic.hpp), C1 at the keys (S'' jumps).
/// At rest: C0 in general, C1 when the limiter makes the end slopes 0 (e.g. flat end keys).
template <class Real>
class distance_keys_ease : public detail::distance_time_base<distance_keys_ease<Real>, Real> {
 public:
  distance_keys_ease(std::span<const Real> times, std::span<const Real> distances)
      : cubic_(checked(times, distances), distances) {
    rest_ = detail::rest_order(*this);
  }

  [[nodiscard]] std::span<const Real> breakpoints() const { return cubic_.breakpoints(); }
  [[nodiscard]] static int continuity() { return 1; }
  [[nodiscard]] int rest_continuity() const { return rest_; }
  /// The interpolant (knot slopes, pieces).
  [[nodiscard]] const monotone_cubic<Real>& interpolant() const { return cubic_; }

 private:
  friend class detail::distance_time_base<distance_keys_ease<Real>, Real>;
  [[nodiscard]] Real evaluate(const Real& t, int order, side s) const { return cubic_.derivative(t, order, s); }

  static std::span<const Real> checked(std::span<const Real> times, std::span<const Real> distances) {
    detail::check_key_times(times);
    validate::same_count("distances", distances.size(), "times", times.size());
    for (std::size_t i = 0; i < distances.size(); ++i)
      validate::in_range("distances", distances[i], Real(0), Real(1), i);
    for (std::size_t i = 1; i < distances.size(); ++i)
      if (distances[i] < distances[i - 1])
        validate::fail("distances must be non-decreasing: " + validate::indexed("distances", i) + " = " +
                       to_text(distances[i]) + " < " + validate::indexed("distances", i - 1) + " = " +
                       to_text(distances[i - 1]) + " (a distance-time function must not run backwards)");
    if (distances.front() != Real(0))
      validate::fail("distances[0] = " + to_text(distances.front()) + ": S(0) must be 0");
    if (distances.back() != Real(1))
      validate::fail(validate::indexed("distances", distances.size() - 1) + " = " + to_text(distances.back()) +
                     ": S(1) must be 1");
    return times;
  }

  monotone_cubic<Real> cubic_;
  int rest_ = 0;
};

/// How speed keys are joined.
enum class speed_interpolation {
  linear,          ///< piecewise-linear v(t): S piecewise quadratic, C1 (S'' jumps at the keys)
  monotone_cubic,  ///< monotone cubic v(t): S piecewise quartic, C2; v >= 0 is preserved
};

/// A user speed curve: keys (t_i, v_i) with t strictly increasing from 0 to 1 and v_i >= 0, not
/// all 0. The speed v(t) is interpolated (linearly or by the monotone cubic, which cannot dip below
/// 0 between non-negative keys - see monotone_cubic.hpp) and integrated exactly piece by piece
/// (piecewise polynomial antiderivative, no quadrature error), then normalized:
///   S(t) = A(t) / A(1), A(t) = int_0^t v,  S' = v / A(1),  S'' = v' / A(1).
/// Negative speeds (the object would run backwards) are rejected with invalid_input.
/// Continuity: C1 (linear) or C2 (monotone cubic) at the keys; at rest C0 unless v = 0 at both
/// ends (then C1, or C2 if v' = 0 there too).
template <class Real>
class speed_curve_ease : public detail::distance_time_base<speed_curve_ease<Real>, Real> {
 public:
  speed_curve_ease(std::span<const Real> times, std::span<const Real> speeds,
                   speed_interpolation how = speed_interpolation::linear)
      : how_(how) {
    detail::check_key_times(times);
    validate::same_count("speeds", speeds.size(), "times", times.size());
    bool any_positive = false;
    for (std::size_t i = 0; i < speeds.size(); ++i) {
      validate::finite("speeds", speeds[i], i);
      if (speeds[i] < Real(0))
        validate::fail(validate::indexed("speeds", i) + " = " + to_text(speeds[i]) +
                       ": must be >= 0 (a negative speed would run the motion backwards)");
      any_positive = any_positive || speeds[i] > Real(0);
    }
    if (!any_positive) validate::fail("speeds: all zero, at least one must be > 0 (the motion must cover the path)");
    const std::size_t n = times.size();
    std::vector<std::array<Real, 4>> pieces(n - 1);
    std::vector<Real> m;
    if (how == speed_interpolation::monotone_cubic) m = monotone_slopes<Real>(times, speeds);
    for (std::size_t k = 0; k + 1 < n; ++k) {
      const Real h = times[k + 1] - times[k];
      if (how == speed_interpolation::monotone_cubic)
        pieces[k] = hermite_piece(speeds[k], speeds[k + 1], m[k], m[k + 1], h);
      else
        pieces[k] = {speeds[k], (speeds[k + 1] - speeds[k]) / h, Real(0), Real(0)};
    }
    speed_ = scalar_piecewise_cubic<Real>(std::vector<Real>(times.begin(), times.end()), std::move(pieces));
    area_ = speed_.total_integral();
    rest_ = detail::rest_order(*this);
  }

  [[nodiscard]] std::span<const Real> breakpoints() const { return speed_.breakpoints(); }
  [[nodiscard]] int continuity() const { return how_ == speed_interpolation::linear ? 1 : 2; }
  [[nodiscard]] int rest_continuity() const { return rest_; }
  /// int_0^1 v(t) dt of the interpolated user speed (the normalization).
  [[nodiscard]] Real area() const { return area_; }
  /// The interpolated user speed v(t) (before normalization).
  [[nodiscard]] const scalar_piecewise_cubic<Real>& speed() const { return speed_; }

 private:
  friend class detail::distance_time_base<speed_curve_ease<Real>, Real>;
  [[nodiscard]] Real evaluate(const Real& t, int order, side s) const {
    if (order == 0) {
      // The last knot is exact: S(1) = A(1) / A(1) = 1.
      return t == Real(1) ? Real(1) : speed_.integral(t) / area_;
    }
    return speed_.derivative(t, order - 1, s) / area_;
  }

  speed_interpolation how_;
  scalar_piecewise_cubic<Real> speed_;
  Real area_{};
  int rest_ = 0;
};

}  // namespace curvebench::motion
