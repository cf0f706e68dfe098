// The "css" tool: one CSS easing function (channel/css_easing.hpp) on progress [0, 1] as a
// channel, evaluated as browsers do (time solver table_newton, the WebKit / Chromium scheme),
// the value held outside [0, 1] (constant extrapolation).
// css_keys(easing): cubic-bezier(x1, y1, x2, y2) is one bezier segment from (0, 0) to (1, 1) with
// handles (x1, y1) and (x2 - 1, y2 - 1); steps(n, position) are n + 1 keys at k / n joined by
// constant segments whose values follow the specification's step algorithm (n <= 2^20); linear(...)
// is one linear segment between consecutive stops (two stops at one input, a jump, is an
// invalid_input: a channel has one value per time).
// from_keys: a single bezier segment from (0, 0) to (1, 1) (handle times in [0, 1], as
// cubic-bezier requires), or linear segments from time 0 to time 1 (linear() with the key times as
// stop positions); constant segments are refused (steps() are equal steps, not arbitrary ones).
#pragma once

#include "curvebench/channel/channel.hpp"
#include "curvebench/channel/css_easing.hpp"
#include "curvebench/channel/tool_model.hpp"

#include <algorithm>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace curvebench::channel {

/// steps(n) becomes n + 1 keys in a channel: n at most this (2^20, about what a 64 MiB spec holds).
inline constexpr long long css_max_step_keys = 1LL << 20;

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
    // n + 1 keys, materialised: capped before any is made (steps(1e7) took 63 s and 2.5 GB, and
    // n + 1 overflows at the largest long long). css_easing evaluates steps() in closed form.
    if (n > css_max_step_keys)
      validate::fail("steps argument 1 (n) = " + std::to_string(n) +
                     ": a channel holds steps() as n + 1 keys, n at most " + std::to_string(css_max_step_keys));
    const step_position pos = f.position();
    const bool start = pos == step_position::jump_start || pos == step_position::jump_both;
    const long long jumps = pos == step_position::jump_none ? n - 1 : pos == step_position::jump_both ? n + 1 : n;
    for (long long k = 0; k <= n; ++k) {
      const long long step = std::min(k + (start ? 1 : 0), jumps);
      keys.push_back({Real(k) / Real(n), Real(step) / Real(jumps), {}, {}, interpolation::constant});
    }
  } else {
    const auto pts = f.points();
    for (std::size_t i = 0; i < pts.size(); ++i) {
      if (i > 0 && !(pts[i].input > pts[i - 1].input))
        validate::fail("stops " + std::to_string(i - 1) + " and " + std::to_string(i) + " share the input " +
                       to_text(pts[i].input) + ": a jump, which a channel (one value per time) does not hold");
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

  template <class Real>
  using model = curvebench::channel::detail::channel_tool_model<css, Real>;

  /// The model of an easing, solved by `solver`.
  template <class Real>
  [[nodiscard]] static model<Real> of_easing(const css_easing<double>& f, time_solver solver = default_solver) {
    return model<Real>(channel<Real>(css_keys<Real>(f), extrapolation::constant, extrapolation::constant, solver));
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
