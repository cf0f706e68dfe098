// Motion along a path: position(t) = P(U(L S((t - t0) / (t1 - t0)))), with velocity, speed and
// acceleration, over a time interval or a range of integer frames at a frame rate.
// A motion binds an arc-length parameterization of a curve (the arc_length_map concept:
// arclength/parameterization.hpp with any inversion method) and a distance-time function S
// (distance_time.hpp) to a time interval [t0, t1] or frames [f0, f1] at fps (formulas above the
// class). Speed and tangential acceleration are exact; position, velocity direction and normal
// acceleration carry the inversion's error in u. Where P' = 0 while moving, acceleration() (and,
// if P'' = 0 too, velocity()) throws std::domain_error. Frame f maps to x = (f - f0) / (f1 - f0)
// from integers, so the first and last frames are exactly S(0) = 0 and S(1) = 1.
// Sources: seed 002 ("Distance Time Function and Speed Control": p = P(U(S(t)))); Parent (2012),
// 3.2. Cost: one S evaluation, one u(s), one to three curve evaluations; no allocation except the
// vector-returning sampler. Accuracy: position error = |P'| times the inversion's u error; speed
// exact to a few ulps.
#pragma once

#include "curvebench/core/curve.hpp"
#include "curvebench/core/error.hpp"
#include "curvebench/core/point.hpp"
#include "curvebench/core/real.hpp"
#include "curvebench/motion/distance_time.hpp"

#include <concepts>
#include <cstddef>
#include <span>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

namespace curvebench::motion {

/// An arc-length parameterization of a curve: total length, u(s) for s in [0, L], and the curve.
template <class A>
concept arc_length_map = requires(const A& a, const typename A::real_type& s) {
  typename A::real_type;
  { a.length() } -> std::convertible_to<typename A::real_type>;
  { a.u(s) } -> std::convertible_to<typename A::real_type>;
  requires curve<std::remove_cvref_t<decltype(a.curve())>>;
  requires std::same_as < typename std::remove_cvref_t<decltype(a.curve())>::real_type,
  typename A::real_type > ;
};

/// Integer frames [first, last] at `fps` frames per unit of time (time of frame f = f / fps).
template <class Real>
struct frame_range {
  long long first;
  long long last;
  Real fps = Real(24);
  [[nodiscard]] long long count() const { return last - first + 1; }
};

/// Everything about the motion at one instant.
template <class Real, int Dim>
struct motion_sample {
  Real time;                      ///< t
  Real normalized_time;           ///< x = (t - t0) / T in [0, 1]
  Real distance;                  ///< sigma = L S(x), arc length travelled
  Real parameter;                 ///< u = U(sigma)
  point<Real, Dim> position;      ///< P(u)
  Real speed;                     ///< sigma' = L S'(x) / T
  Real tangential_acceleration;   ///< sigma'' = L S''(x) / T^2
  point<Real, Dim> velocity;      ///< sigma' T_hat
  point<Real, Dim> acceleration;  ///< sigma'' T_hat + sigma'^2 k N
};

// to a time interval [t0, t1] of duration T (or frames [f0, f1] at fps frames per unit time,
// t = f / fps). At time t, with x = (t - t0) / T the normalized time:
// distance   sigma(t) = L S(x)                       (arc length travelled, seed 002's s = S(t))
// parameter  u(t) = U(sigma(t))                       (the arc-length inversion)
// position   r(t) = P(u(t))
// speed      sigma'(t) = L S'(x) / T                  (chain rule, dx/dt = 1 / T)
// velocity   r'(t) = sigma'(t) T_hat, T_hat = P'(u) / |P'(u)|   (since dsigma/du = |P'(u)|)
// tangential acceleration sigma''(t) = L S''(x) / T^2
// acceleration r''(t) = sigma'' T_hat + sigma'^2 k N,  k N = dT_hat/dsigma
//              = (P''(u) - T_hat (T_hat . P''(u))) / |P'(u)|^2   (curvature vector).
// The speed and the tangential acceleration are exact (they do not depend on the inversion); the
// position, velocity direction and normal acceleration carry the inversion's error in u. At a
// stationary point of the curve (P'(u) = 0) the forward unit tangent is the limit P''/|P''|; the
// curvature term is undefined there, so acceleration() throws std::domain_error if the motion is
// moving at that instant (at rest it is sigma'' T_hat); where P' = P'' = 0 and the motion is not at
// rest, velocity() throws too.
template <arc_length_map A, distance_time F>
requires std::same_as<typename A::real_type, typename F::real_type>
class motion_path {
 public:
  using real_type = typename A::real_type;
  using Real = real_type;
  using curve_type = std::remove_cvref_t<decltype(std::declval<const A&>().curve())>;
  static constexpr int dimension = curve_type::dimension;
  using point_type = point<Real, dimension>;
  using sample_type = motion_sample<Real, dimension>;

  /// Over the time interval [time.lo, time.hi] (finite, lo < hi).
  motion_path(A arc, F ease, const interval<Real>& time) : arc_(std::move(arc)), ease_(std::move(ease)), time_(time) {
    validate::finite("time.lo", time.lo);
    validate::finite("time.hi", time.hi);
    if (!(time.lo < time.hi))
      validate::fail("time = [" + to_text(time.lo) + ", " + to_text(time.hi) +
                     "]: the motion needs an interval with time.lo < time.hi");
    init();
  }

  /// Over frames [frames.first, frames.last] (first < last) at frames.fps > 0.
  motion_path(A arc, F ease, const frame_range<Real>& frames)
      : arc_(std::move(arc)), ease_(std::move(ease)), frames_(frames), has_frames_(true) {
    if (!(frames.first < frames.last))
      validate::fail("frames = [" + std::to_string(frames.first) + ", " + std::to_string(frames.last) +
                     "]: the last frame must come after the first");
    validate::positive("fps", frames.fps);
    time_ = {Real(frames.first) / frames.fps, Real(frames.last) / frames.fps};
    init();
  }

  [[nodiscard]] const A& arc_length() const { return arc_; }
  [[nodiscard]] const F& ease() const { return ease_; }
  [[nodiscard]] const curve_type& curve() const { return arc_.curve(); }
  /// Path length L.
  [[nodiscard]] Real length() const { return length_; }
  [[nodiscard]] interval<Real> time_domain() const { return time_; }
  [[nodiscard]] Real duration() const { return time_.hi - time_.lo; }
  /// True when built over frames; frames() is then the range.
  [[nodiscard]] bool has_frames() const { return has_frames_; }
  [[nodiscard]] const frame_range<Real>& frames() const {
    require_frames();
    return frames_;
  }

  /// x = (t - t0) / T; std::domain_error outside [t0, t1].
  [[nodiscard]] Real normalized_time(const Real& t) const {
    check_time(t);
    if (t == time_.hi) return Real(1);
    return (t - time_.lo) / duration();
  }
  /// x of frame f = (f - f0) / (f1 - f0) (exact integers, one rounding); std::domain_error
  /// outside the frame range.
  [[nodiscard]] Real normalized_frame(long long f) const {
    require_frames();
    if (f < frames_.first || f > frames_.last)
      throw std::domain_error("frame = " + std::to_string(f) + " is outside the frame range [" +
                              std::to_string(frames_.first) + ", " + std::to_string(frames_.last) + "]");
    return Real(f - frames_.first) / Real(frames_.last - frames_.first);
  }
  /// Time of frame f: f / fps.
  [[nodiscard]] Real frame_time(long long f) const {
    require_frames();
    return Real(f) / frames_.fps;
  }

  [[nodiscard]] Real distance(const Real& t) const { return distance_at(normalized_time(t)); }
  [[nodiscard]] Real parameter(const Real& t) const { return arc_.u(distance(t)); }
  [[nodiscard]] point_type position(const Real& t) const { return curve()(parameter(t)); }
  [[nodiscard]] Real speed(const Real& t) const { return speed_at(normalized_time(t)); }
  [[nodiscard]] Real tangential_acceleration(const Real& t) const {
    return tangential_acceleration_at(normalized_time(t));
  }
  [[nodiscard]] point_type velocity(const Real& t) const { return velocity_at(normalized_time(t)); }
  [[nodiscard]] point_type acceleration(const Real& t) const { return sample(t).acceleration; }

  /// All quantities at time t.
  [[nodiscard]] sample_type sample(const Real& t) const { return sample_at(t, normalized_time(t)); }

  [[nodiscard]] Real distance_at_frame(long long f) const { return distance_at(normalized_frame(f)); }
  [[nodiscard]] point_type position_at_frame(long long f) const {
    return curve()(arc_.u(distance_at(normalized_frame(f))));
  }
  /// Speed at frame f in length per unit time (divide by fps for length per frame).
  [[nodiscard]] Real speed_at_frame(long long f) const { return speed_at(normalized_frame(f)); }
  [[nodiscard]] sample_type sample_at_frame(long long f) const {
    const Real x = normalized_frame(f);
    return sample_at(frame_time(f), x);
  }

  /// Positions at every frame first..last, written to out (size frames().count()). No allocation.
  void sample_frames(std::span<point_type> out) const {
    require_frames();
    validate::same_count("sample_frames output", out.size(), "frames", static_cast<std::size_t>(frames_.count()));
    for (long long f = frames_.first; f <= frames_.last; ++f)
      out[static_cast<std::size_t>(f - frames_.first)] = position_at_frame(f);
  }
  [[nodiscard]] std::vector<point_type> sample_frames() const {
    require_frames();
    std::vector<point_type> out(static_cast<std::size_t>(frames_.count()));
    sample_frames(std::span<point_type>(out));
    return out;
  }

 private:
  void init() {
    length_ = arc_.length();
    validate::positive("path length", length_);
  }
  void require_frames() const {
    if (!has_frames_) throw std::logic_error("motion_path: built over a time interval, not over frames");
  }
  void check_time(const Real& t) const {
    if (time_.contains(t)) return;
    throw std::domain_error("t = " + to_text(t) + " is outside the motion's time interval [" + to_text(time_.lo) +
                            ", " + to_text(time_.hi) + "]");
  }

  [[nodiscard]] Real distance_at(const Real& x) const {
    if (x == Real(1)) return length_;  // S(1) = 1 by definition: land exactly on the end
    // S(x) <= 1 mathematically; a closed form may round to 1 + eps, and u(s) rejects s > L, so the
    // product is limited to L (a rounding guard, not a clamp of user data).
    const Real s = length_ * ease_(x);
    return s > length_ ? length_ : s;
  }
  [[nodiscard]] Real speed_at(const Real& x) const { return length_ * ease_.velocity(x) / duration(); }
  [[nodiscard]] Real tangential_acceleration_at(const Real& x) const {
    const Real T = duration();
    return length_ * ease_.acceleration(x) / (T * T);
  }

  // The forward unit tangent at u: P'/|P'|, or P''/|P''| where P'(u) = 0 (the limit from the side
  // the motion goes to); sets |P'(u)| in n1. std::domain_error when both vanish.
  [[nodiscard]] point_type unit_tangent(const Real& u, const point_type& d1, const point_type& d2, Real& n1) const {
    n1 = d1.norm();
    if (n1 > Real(0)) return d1 / n1;
    const Real n2 = d2.norm();
    if (n2 > Real(0)) return d2 / n2;
    throw std::domain_error("motion_path: P'(u) = P''(u) = 0 at u = " + to_text(u) +
                            ": the direction of motion is undefined there");
  }

  [[nodiscard]] point_type velocity_at(const Real& x) const {
    const Real sp = speed_at(x);
    if (sp == Real(0)) return point_type::Zero();
    const Real u = arc_.u(distance_at(x));
    Real n1;
    return sp * unit_tangent(u, curve().derivative(u, 1), curve().derivative(u, 2), n1);
  }

  [[nodiscard]] sample_type sample_at(const Real& t, const Real& x) const {
    sample_type r;
    r.time = t;
    r.normalized_time = x;
    r.distance = distance_at(x);
    r.parameter = arc_.u(r.distance);
    r.position = curve()(r.parameter);
    r.speed = speed_at(x);
    r.tangential_acceleration = tangential_acceleration_at(x);
    r.velocity = point_type::Zero();
    r.acceleration = point_type::Zero();
    if (r.speed == Real(0) && r.tangential_acceleration == Real(0)) return r;  // at rest
    const point_type d1 = curve().derivative(r.parameter, 1);
    const point_type d2 = curve().derivative(r.parameter, 2);
    Real n1;
    const point_type tangent = unit_tangent(r.parameter, d1, d2, n1);
    r.velocity = r.speed * tangent;
    r.acceleration = r.tangential_acceleration * tangent;
    if (r.speed == Real(0)) return r;  // no centripetal term at rest
    if (!(n1 > Real(0)))
      throw std::domain_error("motion_path: P'(u) = 0 at u = " + to_text(r.parameter) +
                              " while moving: the curvature term of the acceleration is undefined there");
    const point_type normal_part = d2 - tangent * tangent.dot(d2);
    r.acceleration += (r.speed * r.speed / (n1 * n1)) * normal_part;
    return r;
  }

  A arc_;
  F ease_;
  interval<Real> time_{Real(0), Real(1)};
  frame_range<Real> frames_{0, 1, Real(1)};
  bool has_frames_ = false;
  Real length_{};
};

}  // namespace curvebench::motion
