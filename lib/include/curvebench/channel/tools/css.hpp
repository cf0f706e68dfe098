// The "css" tool: one CSS easing function (channel/css_easing.hpp) on progress [0, 1] as a
// channel, evaluated as browsers do (time solver table_newton, the WebKit / Chromium scheme),
// the value held outside [0, 1] (constant extrapolation).
// css_keys(easing): cubic-bezier(x1, y1, x2, y2) is one bezier segment from (0, 0) to (1, 1) with
// handles (x1, y1) and (x2 - 1, y2 - 1); steps(n, position) are n + 1 keys at k / n joined by
// constant segments whose values follow the specification's step algorithm; linear(...) is one
// linear segment between consecutive stops (two stops at one input, a jump, is an invalid_input: a
// channel has one value per time).
// The model of steps(n) evaluates in closed form (css_steps: the key below t found from floor(n t),
// O(1) for any n up to 2^53); its curve view holds the n + 1 keys and is built for n <= 2^16 only
// (css_max_step_keys): above, view() refuses with the reason, as a USD jump's does, and values
// and derivatives still evaluate.
// from_keys: a single bezier segment from (0, 0) to (1, 1) (handle times in [0, 1], as
// cubic-bezier requires), or linear segments from time 0 to time 1 (linear() with the key times as
// stop positions); constant segments are refused (steps() are equal steps, not arbitrary ones).
#pragma once

#include "curvebench/channel/channel.hpp"
#include "curvebench/channel/css_easing.hpp"
#include "curvebench/channel/tool_model.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace curvebench::channel {

/// steps(n)'s curve view holds n + 1 keys: built for n at most this (2^16); above it the model
/// evaluates without a view.
inline constexpr long long css_max_step_keys = 1LL << 16;

/// steps(n, position) as the constant segments of css_keys, in closed form: the value at time t is
/// key k's for the last key time k / n <= t (rounded as css_keys rounds it), key 0's before time
/// 0 and key n's after time 1 (constant extrapolation), so it equals the channel of the n + 1
/// keys at every t, with no keys made. n <= 2^53 (css_easing::steps), so k and k / n are exact.
template <class Real>
class css_steps {
 public:
  explicit css_steps(const css_easing<double>& f)
      : n_(f.step_count()),
        start_(f.position() == step_position::jump_start || f.position() == step_position::jump_both),
        jumps_(f.position() == step_position::jump_none   ? n_ - 1
               : f.position() == step_position::jump_both ? n_ + 1
                                                          : n_) {}

  /// Key k's time, k / n.
  [[nodiscard]] Real time_of(long long k) const { return Real(k) / Real(n_); }
  /// Key k's value: the step algorithm's output at k / n (see css_keys).
  [[nodiscard]] Real value_of(long long k) const { return Real(std::min(k + (start_ ? 1 : 0), jumps_)) / Real(jumps_); }
  /// The key whose constant segment holds t (t finite).
  [[nodiscard]] long long key_at(const Real& t) const {
    using std::floor;
    if (!(t > Real(0))) return 0;
    if (!(t < Real(1))) return n_;
    // floor(n t) is within one of the key: n t rounds, and so does k / n; the two loops settle it
    // on css_keys' key times.
    long long k = static_cast<long long>(floor(t * Real(n_)));
    k = std::clamp(k, 0LL, n_);
    while (k < n_ && time_of(k + 1) <= t) ++k;
    while (k > 0 && time_of(k) > t) --k;
    return k;
  }
  [[nodiscard]] Real value(const Real& t) const { return value_of(key_at(t)); }
  [[nodiscard]] long long count() const { return n_; }

 private:
  long long n_;
  bool start_;
  long long jumps_;
};

/// The keys of a CSS easing (see the header).
template <class Real>
[[nodiscard]] std::vector<key<Real>> css_keys(const css_easing<double>& f) {
  std::vector<key<Real>> keys;
  using K = css_easing<double>::kind;
  if (f.type() == K::cubic_bezier) {
    const auto& p = f.control();  // x1, y1, x2, y2
    keys.push_back({Real(0), Real(0), {}, {Real(p[0]), Real(p[1])}, interpolation::bezier});
    keys.push_back({Real(1), Real(1), {Real(p[2]) - Real(1), Real(p[3]) - Real(1)}, {}, interpolation::bezier});
  } else if (f.type() == K::steps) {
    // CSS Easing 1, the step algorithm at x = k / n: floor(n x) = k steps, one more with a jump at
    // the start, the output that over the jumps (n, n - 1 without jumps at the ends, n + 1 with both),
    // at most 1. The value holds until the next step: constant segments, right-continuous like CSS.
    const long long n = f.step_count();
    // n + 1 keys, materialised: capped before any is made (steps(1e7) took 63 s and 2.5 GB); the
    // model evaluates larger n without keys (css_steps).
    if (n > css_max_step_keys)
      validate::fail("steps argument 1 (n) = " + std::to_string(n) +
                     ": the curve view holds steps() as n + 1 keys, n at most " + std::to_string(css_max_step_keys) +
                     " (sample --at and check --values evaluate any n)");
    const css_steps<Real> st(f);
    keys.reserve(static_cast<std::size_t>(n) + 1);
    for (long long k = 0; k <= n; ++k) keys.push_back({st.time_of(k), st.value_of(k), {}, {}, interpolation::constant});
  } else {
    const auto pts = f.points();
    for (std::size_t i = 0; i < pts.size(); ++i) {
      if (i > 0 && !(pts[i].input > pts[i - 1].input))
        validate::fail("linear() has two points at the input " + to_text(pts[i].input) + " (its points " +
                       std::to_string(i) + " and " + std::to_string(i + 1) +
                       ", counted from 1; a stop with two positions is two points): a jump, which a channel (one "
                       "value per time) does not hold");
      keys.push_back({Real(pts[i].input), Real(pts[i].output), {}, {}, interpolation::linear});
    }
  }
  return keys;
}

namespace tools {

struct css {
  static constexpr std::string_view name = "css";
  static constexpr std::string_view summary =
      "a CSS easing function (cubic-bezier, steps, linear() or a keyword) on progress [0, 1], as browsers "
      "evaluate it";
  static constexpr std::string_view rules =
      "cubic-bezier from one bezier segment (0, 0) to (1, 1), or linear() through linear keys on [0, 1]; "
      "table_newton solver";
  /// What the model is verified against (recorded values of the real tool) and what is not.
  static constexpr std::string_view verification =
      "against Chromium (Blink, through the Web Animations API; scripts/peers.sh, the report's Peers "
      "section): cubic-bezier() and steps() progress; Firefox and WebKit not recorded";
  using storage_type = double;
  static constexpr time_solver default_solver = time_solver::table_newton;

  /// The channel of the easing's keys, evaluated by it; steps() evaluated in closed form, its view
  /// built for n <= css_max_step_keys (see the header).
  template <class Real>
  class model : public curvebench::channel::detail::optional_view<Real> {
   public:
    using real_type = Real;
    using tool_type = css;
    static constexpr std::string_view name = css::name;
    static constexpr int storage_bits = storage_bits_of<css::storage_type>;

    model(const css_easing<double>& f, time_solver solver) {
      if (f.type() == css_easing<double>::kind::steps) {
        steps_.emplace(f);
        if (f.step_count() > css_max_step_keys) {
          this->refuse_view("steps(" + std::to_string(f.step_count()) +
                            ") has no curve view: it would hold n + 1 keys, n at most " +
                            std::to_string(css_max_step_keys) + " (sample --at and check --values evaluate it)");
          return;
        }
      }
      this->build_view(css_keys<Real>(f), solver);
    }

    [[nodiscard]] Real value(const Real& t) const { return derivative(t, 0); }
    [[nodiscard]] Real derivative(const Real& t, int order) const {
      if (!steps_) return this->view().derivative(t, order);
      channel<Real>::check_derivative(t, order);
      return order == 0 ? steps_->value(t) : Real(0);  // constant segments and extrapolation
    }
    /// The key times; without a view (steps() above css_max_step_keys) the first and last only, 0
    /// and 1.
    [[nodiscard]] std::vector<Real> key_times() const {
      if (!this->has_view()) return {Real(0), Real(1)};
      std::vector<Real> out;
      for (const auto& k : this->view().keys()) out.push_back(k.time);
      return out;
    }

   private:
    std::optional<css_steps<Real>> steps_;
  };

  /// The model of an easing, solved by `solver`.
  template <class Real>
  [[nodiscard]] static model<Real> of_easing(const css_easing<double>& f, time_solver solver = default_solver) {
    return model<Real>(f, solver);
  }

  /// The easing that the keys are (see the header).
  [[nodiscard]] static css_easing<double> easing_of_keys(std::span<const key<double>> keys) {
    curvebench::channel::detail::require_constant_linear_bezier(keys);
    if (keys.size() < 2 || keys.front().time != 0 || keys.back().time != 1)
      validate::fail("a CSS easing is a function of progress: its keys run from time 0 to time 1");
    const bool all_linear = std::all_of(keys.begin(), keys.end() - 1,
                                        [](const key<double>& k) { return k.interp == interpolation::linear; });
    if (all_linear) {
      std::vector<linear_stop<double>> stops;
      for (const auto& k : keys) stops.push_back({k.value, k.time, std::nullopt});
      return css_easing<double>::linear(stops);
    }
    if (keys.size() != 2 || keys[0].interp != interpolation::bezier)
      validate::fail("a CSS easing holds one cubic-bezier segment or linear segments only (steps() are equal steps)");
    if (keys[0].value != 0 || keys[1].value != 1)
      validate::fail("a CSS cubic-bezier runs from the value 0 to the value 1");
    return css_easing<double>::cubic_bezier(keys[0].out.dt, keys[0].out.dv, 1 + keys[1].in.dt, 1 + keys[1].in.dv);
  }

  template <class Real>
  [[nodiscard]] static model<Real> from_keys(std::span<const key<double>> keys) {
    return of_easing<Real>(easing_of_keys(keys));
  }
};

}  // namespace tools

}  // namespace curvebench::channel
