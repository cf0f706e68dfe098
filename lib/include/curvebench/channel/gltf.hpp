// glTF 2.0 animation samplers as a tool model: the rules by which a glTF player turns a sampler's
// input (key times) and output (key values) into a value at any time, for vector and scalar
// channels (translation, scale, morph weights: point<Real, Dim>, Dim = 1 for a scalar) and for
// rotation channels (unit quaternions stored x y z w).
//
// Rules (glTF 2.0 specification, "Animations" and Appendix C "Interpolation"; see references.md):
//   - input: key times in seconds, finite, strictly increasing, time[0] >= 0 (the schema's rule,
//     which glTF-Validator reports as ACCESSOR_ANIMATION_INPUT_NEGATIVE); at least 1 key (n > 0),
//     at least 2 for cubicspline.
//   - output: one value per key (step, linear), or per key an in-tangent a_k, a value v_k and an
//     out-tangent b_k in that order (cubicspline: 3 n elements). Morph weights with m targets are
//     Dim = m points per key (the spec's a_1..a_m, v_1..v_m, b_1..b_m grouping within a key).
//   - before the first and after the last key the output is clamped to the end value; at a key
//     time the key's value is returned as stored, without interpolation; a one-key sampler is
//     constant.
//   - on t_k < t_c < t_{k+1}, with t_d = t_{k+1} - t_k and s = (t_c - t_k) / t_d:
//       step         v_k (the key at or before t_c holds until the next key);
//       linear       (1 - s) v_k + s v_{k+1};
//       cubicspline  (2s^3 - 3s^2 + 1) v_k + t_d (s^3 - 2s^2 + s) b_k + (-2s^3 + 3s^2) v_{k+1}
//                    + t_d (s^3 - s^2) a_{k+1}: the tangents are per second, so dv/dt_c = b_k at
//                    t_k and a_{k+1} at t_{k+1}; a_1 and b_n are never used.
//   - rotation, linear: slerp on the short path, sin(a (1 - s)) / sin(a) v_k + sin(a s) / sin(a)
//     w with w = sign(v_k . v_{k+1}) v_{k+1} (sign +1 when the dot product is 0) and a the angle
//     between v_k and w as 4-vectors; or, as a variant players use, nlerp: normalize((1 - s) v_k
//     + s w). Rotation, cubicspline: the Hermite above on the 4 components (no sign flip, as the
//     spec states), then normalized (the spec's MUST). Rotation, step: v_k.
// Derivatives: derivative(t, order, side) is the exact derivative in time (per second^order) of
// the piece that holds just after t (side::right, the default) or just before t (side::left; at
// order 0 the left limit of the value):
// the segment polynomial, the slerp closed form, or the derivative of the normalization q = p / |p|
// (orders 0..2 for nlerp and cubicspline rotations). Clamped ends and step channels are piecewise
// constant, so their derivatives are 0 (a step's jumps have no classical derivative); at a key
// the two sides differ wherever the channel is only C0.
// Algorithm: binary search of the key times, then the formulas above. The slerp angle is computed
// as 2 atan2(| |w| v_k - |v_k| w |, | |w| v_k + |v_k| w |) (Kahan's angle between vectors), which
// is accurate for small angles where the spec's arccos(|v_k . v_{k+1}|) loses half the digits;
// at a = 0 slerp is the lerp it tends to. Both are the spec's formula computed differently, which
// the spec allows (it lets implementations approximate its equations).
// Validation: invalid_input naming the field and index (input[i], output[i] with the key and its
// role) for too few keys, non-finite numbers, negative or out-of-order or duplicate times, spans
// too narrow to resolve (validate::resolvable), output counts that do not match, and rotation
// values (not tangents) whose length differs from 1 by more than 0.00769: glTF-Validator's
// threshold for animation output quaternions, slightly above the largest error of signed 8-bit
// normalized storage, so any key a valid glTF file can hold is accepted. Keys are used as stored
// (a key 0.5% off unit gives results that far off unit for step and slerp). Sampling at a
// non-finite time throws std::domain_error, as does a cubicspline rotation whose Hermite
// quaternion vanishes (keys v_{k+1} = -v_k, which the spec tells exporters to avoid).
// Cost: O(n) construction (one atan2 per rotation segment), O(log n) per evaluation, no
// allocation when evaluating. Accuracy: a few eps of the data's scale per value; slerp within a
// few eps absolute in angle (tests/test_gltf.cpp measures both against real50).
#pragma once

#include "curvebench/core/detail/segment_lookup.hpp"
#include "curvebench/core/error.hpp"
#include "curvebench/core/point.hpp"
#include "curvebench/core/real.hpp"

#include <algorithm>
#include <array>
#include <cstddef>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace curvebench::channel::gltf {

/// A sampler's interpolation; the names are the spec's (STEP, LINEAR, CUBICSPLINE) in lowercase.
enum class interpolation { step, linear, cubicspline };

/// How a rotation channel interpolates linearly: slerp (the spec's SHOULD) or nlerp.
enum class rotation_blend { slerp, nlerp };

/// Which piece a derivative is taken from at a time where two pieces meet.
enum class side { right, left };

[[nodiscard]] inline const char* to_string(interpolation i) {
  switch (i) {
    case interpolation::step: return "step";
    case interpolation::linear: return "linear";
    case interpolation::cubicspline: return "cubicspline";
  }
  return "unknown";
}

[[nodiscard]] inline const char* to_string(rotation_blend b) {
  switch (b) {
    case rotation_blend::slerp: return "slerp";
    case rotation_blend::nlerp: return "nlerp";
  }
  return "unknown";
}

/// from_string<interpolation>("linear"), from_string<rotation_blend>("nlerp"): the exact lowercase
/// names; anything else is an invalid_input listing them.
template <class Enum>
[[nodiscard]] Enum from_string(std::string_view name);

template <>
[[nodiscard]] inline interpolation from_string<interpolation>(std::string_view name) {
  for (interpolation i : {interpolation::step, interpolation::linear, interpolation::cubicspline})
    if (name == to_string(i)) return i;
  validate::fail("interpolation = \"" + std::string(name) +
                 "\": must be one of step, linear, cubicspline (the glTF names in lowercase)");
}

template <>
[[nodiscard]] inline rotation_blend from_string<rotation_blend>(std::string_view name) {
  for (rotation_blend b : {rotation_blend::slerp, rotation_blend::nlerp})
    if (name == to_string(b)) return b;
  validate::fail("rotation blend = \"" + std::string(name) + "\": must be one of slerp, nlerp");
}

/// The cubic Hermite basis of Appendix C and its derivatives in s: {h00, h10, h01, h11}^(order)(s)
/// with h00 = 2s^3 - 3s^2 + 1 (weight of v_k), h10 = s^3 - 2s^2 + s (of t_d b_k), h01 = -2s^3 + 3s^2
/// (of v_{k+1}), h11 = s^3 - s^2 (of t_d a_{k+1}). Orders above 3 are 0.
template <class Real>
[[nodiscard]] std::array<Real, 4> hermite_basis(const Real& s, int order = 0) {
  validate::derivative_order(order);
  const Real s2 = s * s, s3 = s2 * s;
  const Real two(2), three(3), four(4), six(6), twelve(12);
  switch (order) {
    case 0: return {two * s3 - three * s2 + Real(1), s3 - two * s2 + s, three * s2 - two * s3, s3 - s2};
    case 1: return {six * s2 - six * s, three * s2 - four * s + Real(1), six * s - six * s2, three * s2 - two * s};
    case 2: return {twelve * s - six, six * s - four, six - twelve * s, six * s - two};
    case 3: return {twelve, six, -twelve, six};
    default: return {Real(0), Real(0), Real(0), Real(0)};
  }
}

/// The rotation angle, in radians in [0, pi], of the rotation that takes r to q (unit quaternions,
/// x y z w; q and -q are the same rotation). Computed as 2 phi, phi = 2 atan2(| |r| q - |q| r |,
/// | |r| q + |q| r |) the angle between q and r as 4-vectors after flipping r when q . r < 0 (a unit
/// quaternion rotates by twice its half-angle), so it is accurate for small angles (no arccos of
/// a dot product near 1) and does not depend on the lengths. A zero or non-finite argument is an
/// invalid_input.
template <class Real>
[[nodiscard]] Real angular_distance(const point<Real, 4>& q, point<Real, 4> r) {
  using std::atan2;
  validate::finite_point<Real, 4>("q", std::string::npos, q);
  validate::finite_point<Real, 4>("r", std::string::npos, r);
  const Real nq = safe_norm<Real, 4>(q), nr = safe_norm<Real, 4>(r);
  if (!(nq > Real(0))) validate::fail("q = 0: the angle needs a nonzero quaternion");
  if (!(nr > Real(0))) validate::fail("r = 0: the angle needs a nonzero quaternion");
  if (q.dot(r) < Real(0)) r = -r;
  const point<Real, 4> a = nr * q, b = nq * r;
  return Real(4) * atan2(safe_norm<Real, 4>(point<Real, 4>(a - b)), safe_norm<Real, 4>(point<Real, 4>(a + b)));
}

/// The largest | |q| - 1 | a rotation key may have: glTF-Validator's unitLengthThresholdVec4.
template <class Real>
[[nodiscard]] Real unit_quaternion_tolerance() {
  return Real(769) / Real(100000);
}

/// The names that validation errors give the sampler's data: glTF's accessor names by default;
/// a reader of another format passes its own (the spec's "times" and "values", whose values are
/// one flat list: flat names element i's component d by its place in that list, i x Dim + d).
struct accessor_names {
  std::string_view input = "input";
  std::string_view output = "output";
  bool flat = false;
};

namespace detail {

/// Time validation: count, finite, time[0] >= 0, strictly increasing, resolvable spans.
template <class Real>
void validate_input(std::span<const Real> input, interpolation mode, const accessor_names& names) {
  const std::string name(names.input);
  if (mode == interpolation::cubicspline)
    validate::count_at_least(name, input.size(), 2, "a cubicspline sampler needs 2 keys at least (glTF 2.0)");
  else
    validate::count_at_least(name, input.size(), 1, "a sampler needs 1 key at least (glTF 2.0: n > 0)");
  for (std::size_t i = 0; i < input.size(); ++i) {
    validate::finite(name, input[i], i);
    if (i == 0 && input[0] < Real(0))
      validate::fail(validate::indexed(name, 0) + " = " + to_text(input[0]) +
                     ": key times must be >= 0 (glTF 2.0: time[0] >= 0)");
    if (i == 0) continue;
    const std::string here = validate::indexed(name, i), before = validate::indexed(name, i - 1);
    if (input[i] == input[i - 1])
      validate::fail(here + " = " + to_text(input[i]) + " equals " + before +
                     ": duplicate key time, key times must be strictly increasing");
    if (input[i] < input[i - 1])
      validate::fail(here + " = " + to_text(input[i]) + " < " + before + " = " + to_text(input[i - 1]) +
                     ": key times out of order, they must be strictly increasing");
    validate::resolvable(here + " - " + before, input[i - 1], input[i]);
  }
}

/// Output count (elements of Dim numbers): n (step, linear) or 3 n (cubicspline).
inline void validate_output_count(std::size_t output, std::size_t keys, interpolation mode, const accessor_names& names,
                                  int dim) {
  const std::string what = std::string(names.output) + ": " + std::to_string(output) +
                           (names.flat && dim > 1 ? " elements of " + std::to_string(dim) + " numbers" : "") + " given";
  if (mode == interpolation::cubicspline) {
    if (output == 3 * keys) return;
    validate::fail(what + ", must be 3 x " + std::string(names.input) + " = " + std::to_string(3 * keys) +
                   " (cubicspline stores an in-tangent, a value and an out-tangent per key)");
  }
  if (output == keys) return;
  validate::fail(what + ", must match " + std::string(names.input) + ": " + std::to_string(keys) + " (" +
                 to_string(mode) + " stores one value per key)");
}

/// "output[4] (key 1 value)": output element i and its role; with flat names, component d's place
/// in the flat list ("values[9] (key 2 value, component 1)"), or the element's first number's.
inline std::string output_element(std::size_t i, interpolation mode, const accessor_names& names, int dim,
                                  int component = -1) {
  static constexpr const char* roles[3] = {"in-tangent", "value", "out-tangent"};
  const std::string name(names.output);
  const auto d = static_cast<std::size_t>(dim);
  const std::size_t index = names.flat ? i * d + static_cast<std::size_t>(component < 0 ? 0 : component) : i;
  const std::string key = mode != interpolation::cubicspline ? "key " + std::to_string(i) + " value"
                                                             : "key " + std::to_string(i / 3) + " " + roles[i % 3];
  if (!names.flat)
    return validate::indexed(name, index) + " (" + key + ")" +
           (component >= 0 ? "[" + std::to_string(component) + "]" : "");
  if (dim == 1) return validate::indexed(name, index) + " (" + key + ")";
  if (component < 0)
    return name + "[" + std::to_string(index) + ".." + std::to_string(index + d - 1) + "] (" + key + ")";
  return validate::indexed(name, index) + " (" + key + ", component " + std::to_string(component) + ")";
}

template <class Real, int Dim>
void validate_output_finite(std::span<const point<Real, Dim>> output, interpolation mode, const accessor_names& names) {
  for (std::size_t i = 0; i < output.size(); ++i)
    for (int d = 0; d < Dim; ++d)
      if (!is_finite(output[i][d]))
        validate::fail(output_element(i, mode, names, Dim, names.flat && Dim == 1 ? -1 : d) + " = " +
                       to_text(output[i][d]) + ": must be finite");
}

/// Where a time falls: on the constant piece before the first key or from the last key on
/// (clamped, key k = 0 or n - 1), at an interior key k (right side: segment k at s = 0), or in
/// segment k with local parameter s (the left side at t_{k+1} gives s = 1 exactly).
template <class Real>
struct location {
  enum kind_t { clamped_first, clamped_last, at_key, in_segment } kind;
  std::size_t k;
  Real s;
  Real h;
};

template <class Real>
void check_time(const Real& t) {
  if (!is_finite(t)) throw std::domain_error("t = " + to_text(t) + ": the sampling time must be finite");
}

/// The piece holding at t for values (side::right rules: a key time is that key).
template <class Real>
location<Real> locate(std::span<const Real> input, const Real& t, side from) {
  check_time(t);
  const std::size_t n = input.size();
  using L = location<Real>;
  if (from == side::right) {
    if (t < input[0]) return {L::clamped_first, 0, Real(0), Real(0)};
    if (t >= input[n - 1]) return {L::clamped_last, n - 1, Real(0), Real(0)};  // the last key as stored
    const std::size_t k = curvebench::detail::breakpoint_at_or_below<Real>(input, t);
    const Real h = input[k + 1] - input[k];
    return {t == input[k] ? L::at_key : L::in_segment, k, (t - input[k]) / h, h};
  }
  if (t <= input[0]) return {L::clamped_first, 0, Real(0), Real(0)};
  if (t > input[n - 1]) return {L::clamped_last, n - 1, Real(0), Real(0)};
  const std::size_t k = curvebench::detail::segment_of_from_left<Real>(input, t);
  const Real h = input[k + 1] - input[k];
  return {L::in_segment, k, t == input[k + 1] ? Real(1) : (t - input[k]) / h, h};
}

/// h^order, order >= 0.
template <class Real>
Real power(const Real& h, int order) {
  Real r(1);
  for (int i = 0; i < order; ++i) r *= h;
  return r;
}

/// The order-th time derivative of the Appendix C Hermite on a segment of length h at s:
/// (h00 v0 + h01 v1) / h^order + (h10 b0 + h11 a1) / h^(order - 1).
template <class Real, int Dim>
point<Real, Dim> hermite_segment(const point<Real, Dim>& v0, const point<Real, Dim>& b0, const point<Real, Dim>& v1,
                                 const point<Real, Dim>& a1, const Real& s, const Real& h, int order) {
  const std::array<Real, 4> w = hermite_basis(s, order);
  if (order == 0) return point<Real, Dim>(w[0] * v0 + w[2] * v1 + h * (w[1] * b0 + w[3] * a1));
  if (order == 1) return point<Real, Dim>((w[0] * v0 + w[2] * v1) / h + (w[1] * b0 + w[3] * a1));
  return point<Real, Dim>((w[0] * v0 + w[2] * v1) / power(h, order) + (w[1] * b0 + w[3] * a1) / power(h, order - 1));
}

/// Derivatives of q = p / |p| from p, p', p'' (orders 0..2): with r = |p|, r' = q . p',
/// q' = (p' - r' q) / r, r'' = q' . p' + q . p'', q'' = (p'' - r'' q - 2 r' q') / r.
template <class Real>
point<Real, 4> normalized(const point<Real, 4>& p, const point<Real, 4>& p1, const point<Real, 4>& p2, int order,
                          const Real& t) {
  const Real r = safe_norm<Real, 4>(p);
  if (!(r > Real(0)) || !is_finite(r))
    throw std::domain_error("t = " + to_text(t) + ": the interpolated quaternion has length " + to_text(r) +
                            " and cannot be normalized (keys v_{k+1} = -v_k, which glTF tells exporters to avoid)");
  const point<Real, 4> q = p / r;
  if (order == 0) return q;
  const Real r1 = q.dot(p1);
  const point<Real, 4> q1 = (p1 - r1 * q) / r;
  if (order == 1) return q1;
  const Real r2 = q1.dot(p1) + q.dot(p2);
  return point<Real, 4>((p2 - r2 * q - Real(2) * r1 * q1) / r);
}

}  // namespace detail

/// A glTF animation sampler for a vector (or, Dim = 1, scalar) channel.
template <class Real, int Dim>
class sampler {
 public:
  using real_type = Real;
  using point_type = point<Real, Dim>;
  static constexpr int dimension = Dim;

  /// input: key times; output: the output accessor's elements, n (step, linear) or 3 n
  /// (cubicspline: in-tangent, value, out-tangent per key). names: what errors call them.
  sampler(std::vector<Real> input, std::span<const point_type> output, interpolation mode,
          const accessor_names& names = {})
      : input_(std::move(input)), mode_(mode) {
    detail::validate_input<Real>(input_, mode_, names);
    detail::validate_output_count(output.size(), input_.size(), mode_, names, Dim);
    detail::validate_output_finite<Real, Dim>(output, mode_, names);
    if (mode_ != interpolation::cubicspline) {
      values_.assign(output.begin(), output.end());
      return;
    }
    for (std::size_t k = 0; k < input_.size(); ++k) {
      in_.push_back(output[3 * k]);
      values_.push_back(output[3 * k + 1]);
      out_.push_back(output[3 * k + 2]);
    }
  }

  /// A scalar channel (Dim = 1) from scalar outputs.
  sampler(std::vector<Real> input, std::span<const Real> output, interpolation mode,
          const accessor_names& names = {}) requires(Dim == 1)
      : sampler(std::move(input), std::span<const point_type>(to_points(output)), mode, names) {}

  /// The channel's value at time t (clamped to the end values outside the keys).
  [[nodiscard]] point_type operator()(const Real& t) const { return derivative(t, 0); }

  /// The value of a scalar channel.
  [[nodiscard]] Real scalar(const Real& t) const requires(Dim == 1) { return derivative(t, 0)[0]; }

  /// d^order value / dt^order (per second^order) of the piece on the given side of t. Order 0 on
  /// side::left is the left limit of the value (at a key time: the previous segment's end, which
  /// for step is the previous key; the value the spec prescribes there is operator()).
  [[nodiscard]] point_type derivative(const Real& t, int order, side from = side::right) const {
    validate::derivative_order(order);
    const auto at = detail::locate<Real>(input_, t, from);
    using L = detail::location<Real>;
    if (order == 0) {
      if (at.kind != L::in_segment) return values_[at.k];
    } else if (at.kind == L::clamped_first || at.kind == L::clamped_last || mode_ == interpolation::step) {
      return point_type::Zero();
    }
    const std::size_t k = at.k;
    switch (mode_) {
      case interpolation::step: return values_[k];
      case interpolation::linear:
        if (order == 0) return point_type((Real(1) - at.s) * values_[k] + at.s * values_[k + 1]);
        if (order == 1) return point_type((values_[k + 1] - values_[k]) / at.h);
        return point_type::Zero();
      case interpolation::cubicspline:
        return detail::hermite_segment<Real, Dim>(values_[k], out_[k], values_[k + 1], in_[k + 1], at.s, at.h, order);
    }
    return point_type::Zero();
  }

  [[nodiscard]] std::span<const Real> input() const { return input_; }
  /// The key values v_k (for cubicspline, the middle element of each key's triple).
  [[nodiscard]] std::span<const point_type> values() const { return values_; }
  /// cubicspline only (empty otherwise): a_k and b_k, per second.
  [[nodiscard]] std::span<const point_type> in_tangents() const { return in_; }
  [[nodiscard]] std::span<const point_type> out_tangents() const { return out_; }
  [[nodiscard]] interpolation mode() const { return mode_; }
  [[nodiscard]] std::size_t key_count() const { return input_.size(); }

 private:
  static point_list<Real, 1> to_points(std::span<const Real> xs) {
    point_list<Real, 1> p;
    p.reserve(xs.size());
    for (const Real& x : xs) p.push_back(point<Real, 1>(x));
    return p;
  }

  std::vector<Real> input_;
  interpolation mode_;
  point_list<Real, Dim> values_, in_, out_;
};

/// A glTF animation sampler for a rotation channel: unit quaternions x y z w.
template <class Real>
class rotation_sampler {
 public:
  using real_type = Real;
  using quaternion = point<Real, 4>;

  /// input: key times; output: n quaternions (step, linear) or 3 n (cubicspline: in-tangent,
  /// value, out-tangent per key; only the values must be unit). blend: slerp or nlerp for linear.
  rotation_sampler(std::vector<Real> input, std::span<const quaternion> output, interpolation mode,
                   rotation_blend blend = rotation_blend::slerp, const accessor_names& names = {})
      : input_(std::move(input)), mode_(mode), blend_(blend) {
    detail::validate_input<Real>(input_, mode_, names);
    detail::validate_output_count(output.size(), input_.size(), mode_, names, 4);
    detail::validate_output_finite<Real, 4>(output, mode_, names);
    const std::size_t stride = mode_ == interpolation::cubicspline ? 3 : 1;
    const std::size_t offset = mode_ == interpolation::cubicspline ? 1 : 0;
    for (std::size_t k = 0; k < input_.size(); ++k) {
      const std::size_t i = stride * k + offset;
      using std::abs;
      const Real length = safe_norm<Real, 4>(output[i]);
      if (!(abs(length - Real(1)) <= unit_quaternion_tolerance<Real>()))
        validate::fail(detail::output_element(i, mode_, names, 4) + " = (" + to_text(output[i][0]) + ", " +
                       to_text(output[i][1]) + ", " + to_text(output[i][2]) + ", " + to_text(output[i][3]) +
                       ") has length " + to_text(length) +
                       ": rotation values must be unit quaternions, | |q| - 1 | <= 0.00769 (glTF-Validator's "
                       "threshold, slightly above the error of signed 8-bit storage)");
      values_.push_back(output[i]);
      if (mode_ == interpolation::cubicspline) {
        in_.push_back(output[i - 1]);
        out_.push_back(output[i + 1]);
      }
    }
    // Per segment: the next key on the short path (w = +-v_{k+1}) and the angle a between v_k and w.
    using std::atan2;
    for (std::size_t k = 0; k + 1 < values_.size(); ++k) {
      const quaternion& v = values_[k];
      const quaternion w = v.dot(values_[k + 1]) < Real(0) ? quaternion(-values_[k + 1]) : values_[k + 1];
      const Real nv = safe_norm<Real, 4>(v), nw = safe_norm<Real, 4>(w);
      const quaternion x = nw * v, y = nv * w;
      next_.push_back(w);
      angle_.push_back(Real(2) * atan2(safe_norm<Real, 4>(quaternion(x - y)), safe_norm<Real, 4>(quaternion(x + y))));
    }
  }

  /// The rotation at time t (clamped to the end keys outside them).
  [[nodiscard]] quaternion operator()(const Real& t) const { return derivative(t, 0); }

  /// d^order q / dt^order (per second^order) of the piece on the given side of t (order 0 on
  /// side::left: the left limit, as for sampler::derivative). Orders: any
  /// for slerp (closed form), 0..2 for nlerp and cubicspline (normalization), any for step (0).
  [[nodiscard]] quaternion derivative(const Real& t, int order, side from = side::right) const {
    validate::derivative_order(order);
    const bool normalizes =
        mode_ == interpolation::cubicspline || (mode_ == interpolation::linear && blend_ == rotation_blend::nlerp);
    if (normalizes && order > 2)
      validate::fail("order = " + std::to_string(order) + ": " +
                     (mode_ == interpolation::cubicspline ? std::string("cubicspline") : std::string("nlerp")) +
                     " rotations give derivatives up to order 2");
    const auto at = detail::locate<Real>(input_, t, from);
    using L = detail::location<Real>;
    if (order == 0) {
      if (at.kind != L::in_segment) return values_[at.k];
    } else if (at.kind == L::clamped_first || at.kind == L::clamped_last || mode_ == interpolation::step) {
      return quaternion::Zero();
    }
    const std::size_t k = at.k;
    if (mode_ == interpolation::step) return values_[k];
    if (mode_ == interpolation::cubicspline) {
      std::array<quaternion, 3> p;
      for (int o = 0; o <= order; ++o)
        p[static_cast<std::size_t>(o)] =
            detail::hermite_segment<Real, 4>(values_[k], out_[k], values_[k + 1], in_[k + 1], at.s, at.h, o);
      return detail::normalized<Real>(p[0], order >= 1 ? p[1] : quaternion::Zero().eval(),
                                      order >= 2 ? p[2] : quaternion::Zero().eval(), order, t);
    }
    const quaternion& v = values_[k];
    const quaternion& w = next_[k];
    if (blend_ == rotation_blend::nlerp) {
      const quaternion p = (Real(1) - at.s) * v + at.s * w;
      return detail::normalized<Real>(p, quaternion((w - v) / at.h), quaternion::Zero().eval(), order, t);
    }
    return slerp(v, w, angle_[k], at.s, at.h, order);
  }

  /// The angle, in radians, of the rotation from key k to key k + 1 on the short path (twice the
  /// 4-vector angle a of the slerp formula).
  [[nodiscard]] Real segment_angle(std::size_t k) const { return Real(2) * angle_.at(k); }

  [[nodiscard]] std::span<const Real> input() const { return input_; }
  [[nodiscard]] std::span<const quaternion> values() const { return values_; }
  [[nodiscard]] std::span<const quaternion> in_tangents() const { return in_; }
  [[nodiscard]] std::span<const quaternion> out_tangents() const { return out_; }
  [[nodiscard]] interpolation mode() const { return mode_; }
  [[nodiscard]] rotation_blend blend() const { return blend_; }
  [[nodiscard]] std::size_t key_count() const { return input_.size(); }

 private:
  /// d^m/dt^m of (sin(a (1 - s)) v + sin(a s) w) / sin(a), s = (t - t_k) / h:
  /// (a / h)^m ((-1)^m sin^(m)(a (1 - s)) v + sin^(m)(a s) w) / sin(a), sin^(m)(x) = sin(x + m pi/2).
  /// At a = 0 it is the lerp (1 - s) v + s w.
  static quaternion slerp(const quaternion& v, const quaternion& w, const Real& a, const Real& s, const Real& h,
                          int m) {
    if (a == Real(0)) {
      if (m == 0) return quaternion((Real(1) - s) * v + s * w);
      if (m == 1) return quaternion((w - v) / h);
      return quaternion::Zero();
    }
    using std::cos;
    using std::sin;
    const auto sin_m = [m](const Real& x) -> Real {
      switch (m % 4) {
        case 0: return sin(x);
        case 1: return cos(x);
        case 2: return -sin(x);
        default: return -cos(x);
      }
    };
    const Real c0 = sin_m(a * (Real(1) - s)) * (m % 2 == 0 ? Real(1) : Real(-1));
    const Real c1 = sin_m(a * s);
    const Real scale = detail::power(Real(a / h), m) / sin(a);
    return quaternion(scale * (c0 * v + c1 * w));
  }

  std::vector<Real> input_;
  interpolation mode_;
  rotation_blend blend_;
  point_list<Real, 4> values_, in_, out_, next_;
  std::vector<Real> angle_;
};

}  // namespace curvebench::channel::gltf
