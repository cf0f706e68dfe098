// The error policy of curvebench and the validation helpers every family uses.
//
// Policy (DESIGN.md): bad input is rejected at construction with `curvebench::invalid_input`
// (derived from std::invalid_argument). The message names the argument, the index and the
// offending value, and says what is allowed, e.g.
//   "knots must be non-decreasing: knots[3] = 0.5 < knots[2] = 0.7".
// Evaluation outside a curve's domain throws std::domain_error with the value and the domain.
// No silent clamping, no "return something".
#pragma once

#include "curvebench/core/point.hpp"
#include "curvebench/core/real.hpp"

#include <cstddef>
#include <limits>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>

namespace curvebench {

/// Thrown for invalid construction data or arguments. The message says what, where and why.
class invalid_input : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};

namespace validate {

/// A user's text as a message shows it: every byte outside printable ASCII written \xNN (a NUL
/// would cut the message, a control or an invisible character hide or garble it, and a name or
/// number in a spec is ASCII), cut after `max` characters with "..." (an echo never grows with the
/// input).
[[nodiscard]] inline std::string visible(std::string_view text, std::size_t max = 80) {
  static constexpr char hex[] = "0123456789abcdef";
  std::string out;
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (out.size() >= max) return out + "...";
    const auto c = static_cast<unsigned char>(text[i]);
    if (c >= 0x20 && c < 0x7f) {
      out.push_back(static_cast<char>(c));
    } else {
      out += "\\x";
      out.push_back(hex[c >> 4]);
      out.push_back(hex[c & 15]);
    }
  }
  return out;
}

/// "name[i]" (or "name" when index is npos).
[[nodiscard]] inline std::string indexed(std::string_view name, std::size_t index = std::string::npos) {
  std::string s(name);
  if (index != std::string::npos) {
    // Appended piece by piece: GCC 12 at -O3 reports a false -Wrestrict on "[" + to_string(i) + "]".
    s.push_back('[');
    s.append(std::to_string(index));
    s.push_back(']');
  }
  return s;
}

[[noreturn]] inline void fail(const std::string& message) { throw invalid_input(message); }

/// At least `minimum` items: "points: 1 given, at least 2 required (what needs them)".
inline void count_at_least(std::string_view name, std::size_t count, std::size_t minimum, std::string_view why = {}) {
  if (count >= minimum) return;
  std::string m =
      std::string(name) + ": " + std::to_string(count) + " given, at least " + std::to_string(minimum) + " required";
  if (!why.empty()) m += " (" + std::string(why) + ")";
  fail(m);
}

/// Two sequences of matching length: "weights: 3 given, must match points: 4".
inline void same_count(std::string_view name, std::size_t count, std::string_view other, std::size_t other_count) {
  if (count == other_count) return;
  fail(std::string(name) + ": " + std::to_string(count) + " given, must match " + std::string(other) + ": " +
       std::to_string(other_count));
}

/// A finite scalar: "tension = nan: must be finite".
template <class Real>
void finite(std::string_view name, const Real& value, std::size_t index = std::string::npos) {
  if (is_finite(value)) return;
  fail(indexed(name, index) + " = " + to_text(value) + ": must be finite");
}

/// Every coordinate finite: "points[3][1] = inf: coordinates must be finite".
template <class Real, int Dim>
void finite_point(std::string_view name, std::size_t index, const point<Real, Dim>& p) {
  for (int d = 0; d < Dim; ++d)
    if (!is_finite(p[d]))
      fail(indexed(name, index) + "[" + std::to_string(d) + "] = " + to_text(p[d]) + ": coordinates must be finite");
}

/// Every point of a list finite.
template <class Real, int Dim>
void finite_points(std::string_view name, std::span<const point<Real, Dim>> ps) {
  for (std::size_t i = 0; i < ps.size(); ++i) finite_point<Real, Dim>(name, i, ps[i]);
}

/// A strictly positive finite scalar: "weights[2] = -1: must be > 0".
template <class Real>
void positive(std::string_view name, const Real& value, std::size_t index = std::string::npos) {
  finite(name, value, index);
  if (value > Real(0)) return;
  fail(indexed(name, index) + " = " + to_text(value) + ": must be > 0");
}

/// A finite scalar in [lo, hi]: "alpha = 2: must be in [0, 1]".
template <class Real>
void in_range(std::string_view name, const Real& value, const Real& lo, const Real& hi,
              std::size_t index = std::string::npos) {
  finite(name, value, index);
  if (lo <= value && value <= hi) return;
  fail(indexed(name, index) + " = " + to_text(value) + ": must be in [" + to_text(lo) + ", " + to_text(hi) + "]");
}

/// The fewest representable parameters a parameter span [lo, hi] must hold: 2^(digits / 3), a
/// third of the precision's bits (2^17 in double, 2^8 in float): then the local parameter
/// t = (u - lo) / (hi - lo) keeps that many bits and every method can place distinct nodes in it.
/// A narrower span (a domain one ulp wide, [1e15, 1e15 + 1] in double) cannot be sampled: its nodes
/// collapse onto its ends and any length or inverse computed there is garbage.
template <class Real>
[[nodiscard]] constexpr int min_span_bits() {
  return std::numeric_limits<Real>::digits / 3;
}

/// The width a span [lo, hi] must have to be resolvable: 2^bits ulps of max(|lo|, |hi|). Below the
/// smallest normal number the spacing stops shrinking (it is denorm_min, 4.9e-324 in double), so
/// the width is at least 2^bits of that: a span of one subnormal ulp is as unresolvable as any.
template <class Real>
[[nodiscard]] Real resolvable_width(const Real& lo, const Real& hi, int bits = min_span_bits<Real>()) {
  using std::abs;
  using std::ldexp;
  const Real big = abs(lo) > abs(hi) ? abs(lo) : abs(hi);
  const Real spacing = big * epsilon<Real>();
  const Real smallest = std::numeric_limits<Real>::denorm_min();
  return ldexp(spacing > smallest ? spacing : smallest, bits);
}

/// Whether [lo, hi] passes `resolvable` (no throw): for optional work that is skipped on a span too
/// narrow for it (an arc-length prefix's sub-panels on a far domain).
template <class Real>
[[nodiscard]] bool is_resolvable(const Real& lo, const Real& hi, int bits = min_span_bits<Real>()) {
  return hi - lo >= resolvable_width(lo, hi, bits);
}

/// hi - lo >= 2^min_span_bits ulps of max(|lo|, |hi|) (lo < hi finite assumed): "knots[1] - knots[0]
/// = 2.2e-16 is too narrow to be resolved around 1: at least 2.9e-11 (2^17 ulps) is needed"; and
/// hi - lo finite (a width that overflows is refused too).
/// `bits` may be smaller where fewer interior values serve (channel_min_span_bits).
template <class Real>
void resolvable(const std::string& span, const Real& lo, const Real& hi, int bits = min_span_bits<Real>()) {
  using std::abs;
  const Real big = abs(lo) > abs(hi) ? abs(lo) : abs(hi);
  const Real need = resolvable_width(lo, hi, bits);
  if (!is_finite(Real(hi - lo)))  // [-1.7e308, 1.7e308]: no Real holds the width, t = (u - lo) / width is NaN
    fail(span + " = " + to_text(hi) + " - (" + to_text(lo) + ") overflows: it must be at most " +
         to_text(std::numeric_limits<Real>::max()));
  if (hi - lo >= need) return;
  fail(span + " = " + to_text(Real(hi - lo)) + " is too narrow to be resolved around " + to_text(big) + ": at least " +
       to_text(need) + " (2^" + std::to_string(bits) +
       " units in the last place) is needed, so that the parameter can be sampled inside it");
}

/// The key interval of a keyframe channel holds at least 2^4 = 16 representable times: a channel
/// is a value over time, evaluated at the times the tool can represent, and animation tools store
/// times in their own precision at any magnitude (Blender's float32 frames near 1e5 are 1/128 apart,
/// so keys 1.125 frames apart, which Blender evaluates, hold 144 of them). The curve families'
/// 2^(digits/3) would refuse such keys; 16 leaves every segment an interior to sample.
inline constexpr int channel_min_span_bits = 4;

/// Finite and strictly increasing: "knots must be increasing: knots[3] = 0.5 <= knots[2] = 0.7".
template <class Real>
void increasing(std::string_view name, std::span<const Real> values) {
  for (std::size_t i = 0; i < values.size(); ++i) {
    finite(name, values[i], i);
    if (i > 0 && !(values[i] > values[i - 1]))
      fail(std::string(name) + " must be increasing: " + indexed(name, i) + " = " + to_text(values[i]) +
           " <= " + indexed(name, i - 1) + " = " + to_text(values[i - 1]));
    if (i > 0) resolvable(indexed(name, i) + " - " + indexed(name, i - 1), values[i - 1], values[i]);
  }
}

/// Finite and non-decreasing: "knots must be non-decreasing: knots[3] = 0.5 < knots[2] = 0.7".
template <class Real>
void non_decreasing(std::string_view name, std::span<const Real> values) {
  for (std::size_t i = 0; i < values.size(); ++i) {
    finite(name, values[i], i);
    if (i > 0 && values[i] < values[i - 1])
      fail(std::string(name) + " must be non-decreasing: " + indexed(name, i) + " = " + to_text(values[i]) + " < " +
           indexed(name, i - 1) + " = " + to_text(values[i - 1]));
    if (i > 0 && values[i] > values[i - 1])
      resolvable(indexed(name, i) + " - " + indexed(name, i - 1), values[i - 1], values[i]);
  }
}

/// A derivative order: 0 is the value, negative orders are rejected.
inline void derivative_order(int order) {
  if (order < 0) fail("order = " + std::to_string(order) + ": derivative order must be >= 0");
}

}  // namespace validate
}  // namespace curvebench
