// Keyframes: (frame, value) keys for any animated channel (position, scale, an angle or a color
// channel; scalars are Dim = 1 points) turned into a curve of the chosen family with the key
// frames as knots, so value(f) = P(f) and derivative(f, 1) is the rate per frame. Families: linear
// (polyline, C0), catmull_rom and cardinal (cardinal_spline.hpp, C1), natural_cubic (C2),
// hermite (the user's slopes per frame, C1) and monotone (Fritsch-Carlson slopes per coordinate,
// monotone_cubic.hpp: no overshoot, for colors and scales that must stay in range). Angles are
// plain numbers (no wrap-around). For motion at a controlled speed use motion_path.hpp instead.
// Errors: too few keys for the family, frames not strictly increasing, non-finite values or
// slopes, a slope count mismatch -> invalid_input naming the key; a frame outside the keys ->
// std::domain_error.
// Source: seed 002 (Maya keyframe interpolation of position, orientation, scale, color).
// Cost: the family's (O(n) construction, O(log n) evaluation on non-uniform frame knots) plus one
// virtual call through any_curve for keyframe_track. Accuracy: the family's.
#pragma once

#include "curvebench/core/any_curve.hpp"
#include "curvebench/core/curve.hpp"
#include "curvebench/core/error.hpp"
#include "curvebench/core/point.hpp"
#include "curvebench/curves/cardinal_spline.hpp"
#include "curvebench/curves/hermite_spline.hpp"
#include "curvebench/curves/natural_cubic_spline.hpp"
#include "curvebench/curves/polyline.hpp"
#include "curvebench/motion/monotone_cubic.hpp"

#include <cstddef>
#include <span>
#include <string>
#include <utility>
#include <vector>

namespace curvebench::motion {

/// A key: the channel's value at a frame (frames may be fractional).
template <class Real, int Dim>
struct key {
  Real frame;
  point<Real, Dim> value;
};

/// A scalar key (scale, angle, one color channel).
template <class Real>
struct scalar_key {
  Real frame;
  Real value;
};

/// The curve family a track is built with.
enum class key_interpolation { linear, catmull_rom, cardinal, natural_cubic, hermite, monotone };

[[nodiscard]] inline const char* to_string(key_interpolation k) {
  switch (k) {
    case key_interpolation::linear: return "linear";
    case key_interpolation::catmull_rom: return "catmull_rom";
    case key_interpolation::cardinal: return "cardinal";
    case key_interpolation::natural_cubic: return "natural_cubic";
    case key_interpolation::hermite: return "hermite";
    case key_interpolation::monotone: return "monotone";
  }
  return "unknown";
}

namespace detail {

/// Validates the keys (>= 2, frames finite and strictly increasing, values finite) and splits them
/// into frames and values.
template <class Real, int Dim>
void split_keys(std::span<const key<Real, Dim>> keys, std::vector<Real>& frames, point_list<Real, Dim>& values) {
  validate::count_at_least("keys", keys.size(), 2, "a track interpolates between two keys at least");
  frames.clear();
  values.clear();
  for (std::size_t i = 0; i < keys.size(); ++i) {
    validate::finite("keys[" + std::to_string(i) + "].frame", keys[i].frame);
    for (int d = 0; d < Dim; ++d)
      if (!is_finite(keys[i].value[d]))
        validate::fail("keys[" + std::to_string(i) + "].value[" + std::to_string(d) +
                       "] = " + to_text(keys[i].value[d]) + ": must be finite");
    if (i > 0 && !(keys[i].frame > keys[i - 1].frame))
      validate::fail("keys[" + std::to_string(i) + "].frame = " + to_text(keys[i].frame) + " <= keys[" +
                     std::to_string(i - 1) + "].frame = " + to_text(keys[i - 1].frame) +
                     ": key frames must be strictly increasing");
    frames.push_back(keys[i].frame);
    values.push_back(keys[i].value);
  }
}

}  // namespace detail

/// Scalar keys as Dim = 1 keys.
template <class Real>
[[nodiscard]] std::vector<key<Real, 1>> scalar_keys(std::span<const scalar_key<Real>> keys) {
  std::vector<key<Real, 1>> out;
  out.reserve(keys.size());
  for (const auto& k : keys) out.push_back({k.frame, point<Real, 1>(k.value)});
  return out;
}

/// Polyline through the keys, parameter = frame.
template <class Real, int Dim>
[[nodiscard]] polyline<Real, Dim> linear_track(std::span<const key<Real, Dim>> keys) {
  std::vector<Real> frames;
  point_list<Real, Dim> values;
  detail::split_keys(keys, frames, values);
  return polyline<Real, Dim>(std::span<const point<Real, Dim>>(values), std::span<const Real>(frames));
}

/// Cardinal spline with tangent scale s through the keys on the frame knots (s = 1/2: Catmull-Rom).
template <class Real, int Dim>
[[nodiscard]] cardinal_spline<Real, Dim> cardinal_track(std::span<const key<Real, Dim>> keys, const Real& s,
                                                        cardinal_end ends = cardinal_end::phantom) {
  std::vector<Real> frames;
  point_list<Real, Dim> values;
  detail::split_keys(keys, frames, values);
  if (ends == cardinal_end::closed || ends == cardinal_end::given_tangents)
    validate::fail(std::string("ends = ") + to_string(ends) +
                   ": keyframe tracks use phantom or one_sided ends (a closed loop needs an extra key "
                   "frame; for given end tangents use hermite_track)");
  if (ends == cardinal_end::control_points)
    validate::fail(
        "ends = control_points: a keyframe track passes through every key, and control_points would "
        "leave the first and last keys off the track");
  cardinal_options<Real, Dim> opt;
  opt.s = s;
  opt.end = ends;
  return cardinal_spline<Real, Dim>(frames, values, opt);
}

/// Catmull-Rom (cardinal with s = 1/2) through the keys on the frame knots.
template <class Real, int Dim>
[[nodiscard]] cardinal_spline<Real, Dim> catmull_rom_track(std::span<const key<Real, Dim>> keys,
                                                           cardinal_end ends = cardinal_end::phantom) {
  return cardinal_track(keys, Real(1) / Real(2), ends);
}

/// The C2 cubic spline through the keys on the frame knots (natural, not_a_knot or periodic ends).
template <class Real, int Dim>
[[nodiscard]] natural_cubic_spline<Real, Dim> natural_track(std::span<const key<Real, Dim>> keys,
                                                            spline_end ends = spline_end::natural) {
  std::vector<Real> frames;
  point_list<Real, Dim> values;
  detail::split_keys(keys, frames, values);
  return natural_cubic_spline<Real, Dim>(frames, values, ends);
}

/// Cubic Hermite through the keys with the given slopes (value units per frame), one per key.
template <class Real, int Dim>
[[nodiscard]] hermite_spline<Real, Dim> hermite_track(std::span<const key<Real, Dim>> keys,
                                                      std::span<const point<Real, Dim>> slopes) {
  std::vector<Real> frames;
  point_list<Real, Dim> values;
  detail::split_keys(keys, frames, values);
  validate::same_count("slopes", slopes.size(), "keys", keys.size());
  validate::finite_points<Real, Dim>("slopes", slopes);
  return hermite_spline<Real, Dim>(std::move(frames), std::move(values),
                                   point_list<Real, Dim>(slopes.begin(), slopes.end()));
}

/// The Fritsch-Carlson slopes of each coordinate (monotone_cubic.hpp) for the keys.
template <class Real, int Dim>
[[nodiscard]] point_list<Real, Dim> monotone_key_slopes(std::span<const key<Real, Dim>> keys) {
  std::vector<Real> frames;
  point_list<Real, Dim> values;
  detail::split_keys(keys, frames, values);
  point_list<Real, Dim> slopes(keys.size(), point<Real, Dim>::Zero());
  std::vector<Real> coordinate(keys.size());
  for (int d = 0; d < Dim; ++d) {
    for (std::size_t i = 0; i < keys.size(); ++i) coordinate[i] = values[i][d];
    const std::vector<Real> m = monotone_slopes<Real>(frames, coordinate);
    for (std::size_t i = 0; i < keys.size(); ++i) slopes[i][d] = m[i];
  }
  return slopes;
}

/// Cubic Hermite with per-coordinate monotone (Fritsch-Carlson) slopes: no overshoot.
template <class Real, int Dim>
[[nodiscard]] hermite_spline<Real, Dim> monotone_track(std::span<const key<Real, Dim>> keys) {
  const point_list<Real, Dim> slopes = monotone_key_slopes(keys);
  return hermite_track(keys, std::span<const point<Real, Dim>>(slopes));
}

/// Options of a keyframe_track built by name.
template <class Real>
struct track_options {
  key_interpolation interpolation = key_interpolation::catmull_rom;
  Real tension_s = Real(1) / Real(2);                  ///< cardinal: tangent scale s
  cardinal_end cardinal_ends = cardinal_end::phantom;  ///< catmull_rom, cardinal
  spline_end natural_ends = spline_end::natural;       ///< natural_cubic
};

/// An animated channel: keys and the curve through them (family chosen at run time), evaluated
/// at frames. Satisfies the curve concept with the frame as parameter.
template <class Real, int Dim>
class keyframe_track {
 public:
  using real_type = Real;
  using point_type = point<Real, Dim>;
  static constexpr int dimension = Dim;
  using key_type = key<Real, Dim>;

  /// Any family but hermite (which needs slopes: use the constructor with slopes).
  keyframe_track(std::span<const key_type> keys, const track_options<Real>& opt = {})
      : keys_(keys.begin(), keys.end()), how_(opt.interpolation), curve_(build(keys, opt)) {}

  /// Hermite with the given slopes per key (value units per frame).
  keyframe_track(std::span<const key_type> keys, std::span<const point_type> slopes)
      : keys_(keys.begin(), keys.end()),
        how_(key_interpolation::hermite),
        curve_(any_curve<Real, Dim>(hermite_track(keys, slopes), "hermite")) {}

  /// Scalar channel (Dim = 1) from (frame, value) keys.
  keyframe_track(std::span<const scalar_key<Real>> keys, const track_options<Real>& opt = {}) requires(Dim == 1)
      : keyframe_track(std::span<const key_type>(scalar_keys(keys)), opt) {}

  [[nodiscard]] interval<Real> domain() const { return curve_.domain(); }
  [[nodiscard]] std::span<const Real> breakpoints() const { return curve_.breakpoints(); }
  /// The value at frame f (std::domain_error outside [first, last] key frame).
  [[nodiscard]] point_type operator()(const Real& frame) const { return curve_(frame); }
  /// d^order value / dframe^order (per frame; multiply by fps^order for per unit time).
  [[nodiscard]] point_type derivative(const Real& frame, int order) const { return curve_.derivative(frame, order); }
  /// The value of a scalar channel at frame f.
  [[nodiscard]] Real scalar(const Real& frame) const requires(Dim == 1) { return curve_(frame)[0]; }

  /// Values at the integer frames first..last, written to out (size last - first + 1).
  void sample_frames(long long first, long long last, std::span<point_type> out) const {
    if (last < first)
      validate::fail("frames [" + std::to_string(first) + ", " + std::to_string(last) +
                     "]: last must not be before first");
    validate::same_count("sample_frames output", out.size(), "frames", static_cast<std::size_t>(last - first + 1));
    for (long long f = first; f <= last; ++f) out[static_cast<std::size_t>(f - first)] = curve_(Real(f));
  }

  [[nodiscard]] std::span<const key_type> keys() const { return keys_; }
  [[nodiscard]] key_interpolation interpolation() const { return how_; }
  /// The curve through the keys (any_curve::target<F>() gives the concrete family).
  [[nodiscard]] const any_curve<Real, Dim>& curve() const { return curve_; }

 private:
  static any_curve<Real, Dim> build(std::span<const key_type> keys, const track_options<Real>& opt) {
    switch (opt.interpolation) {
      case key_interpolation::linear: return {linear_track(keys), "polyline"};
      case key_interpolation::catmull_rom: return {catmull_rom_track(keys, opt.cardinal_ends), "catmull_rom"};
      case key_interpolation::cardinal: return {cardinal_track(keys, opt.tension_s, opt.cardinal_ends), "cardinal"};
      case key_interpolation::natural_cubic: return {natural_track(keys, opt.natural_ends), "natural_cubic"};
      case key_interpolation::monotone: return {monotone_track(keys), "monotone"};
      case key_interpolation::hermite: break;
    }
    validate::fail("interpolation = hermite needs slopes: use the keyframe_track constructor with slopes");
  }

  std::vector<key_type> keys_;
  key_interpolation how_;
  any_curve<Real, Dim> curve_;
};

}  // namespace curvebench::motion
