// The "usd" tool: an OpenUSD Ts spline (channel/usd.hpp: usd_spline, anti-regression, inner
// loops, extrapolation, usd_model) as USD evaluates it, solver closed_form (USD's). The view is the
// channel over the resolved knots (usd_channel_keys: each segment's keys from usd_segment_keys); a
// dual-valued knot after a linear or curve segment (a jump at the knot) has no view: the model
// evaluates such a spline and view() refuses it (usd_view_refusal says why).
// from_keys: bezier knots with widths and slopes (the handle's time length and dv / dt), held,
// linear or curve after each knot, anti-regression keep_ratio; a vertical handle (zero time
// length, nonzero value) is refused (it has no slope).
#pragma once

#include "curvebench/channel/channel.hpp"
#include "curvebench/channel/tool_model.hpp"
#include "curvebench/channel/usd.hpp"

#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace curvebench::channel {

/// Why the resolved spline has no channel view (a dual-valued knot after a linear or curve
/// segment), or nothing.
template <class Real>
[[nodiscard]] std::optional<std::string> usd_view_refusal(const usd_spline<Real>& r) {
  for (std::size_t i = 1; i < r.knots.size(); ++i)
    if (r.knots[i].dual_valued && r.knots[i - 1].next_interp != usd_interpolation::held)
      return "knots[" + std::to_string(i) +
             "] is dual-valued: a jump at a knot has no curve view (sample --at, "
             "check --values and fidelity evaluate it)";
  return std::nullopt;
}

/// The keys of a resolved spline as one channel (the curve view over the knots); invalid_input
/// when usd_view_refusal gives a reason.
template <class Real>
[[nodiscard]] std::vector<key<Real>> usd_channel_keys(const usd_spline<Real>& r) {
  if (const auto why = usd_view_refusal(r)) validate::fail(*why);
  std::vector<key<Real>> keys;
  for (const auto& k : r.knots) keys.push_back({k.time, k.value, {}, {}, interpolation::linear});
  for (std::size_t i = 0; i + 1 < r.knots.size(); ++i) {
    const std::vector<key<Real>> seg = usd_segment_keys(r, i);
    keys[i].interp = seg[0].interp;
    keys[i].out = seg[0].out;
    keys[i + 1].in = seg[1].in;
  }
  return keys;
}

namespace tools {

struct usd {
  static constexpr std::string_view name = "usd";
  static constexpr std::string_view summary =
      "an OpenUSD Ts spline: knots with held / linear / curve segments, tangent widths and slopes, "
      "anti-regression, extrapolation, inner loops";
  static constexpr std::string_view rules =
      "bezier knots (width, slope), keep_ratio anti-regression, closed-form solver";
  /// What the model is verified against (recorded values of the real tool) and what is not.
  static constexpr std::string_view verification =
      "against OpenUSD's Ts 24.11 (tests/data/recorded/usd_ts_splines.json, curvebench fidelity): held, linear "
      "and curve segments, anti-regression, dual values (a jump after a linear or curve segment has no curve "
      "view: length and accuracy refuse it), extrapolation and loops; not modelled: Ts's padding of limited "
      "regressive tangents (1e-5 of the interval inside the ellipse), two Ts 24.11 defects (a looping "
      "post-extrapolation taking the pre-extrapolation's mode, a knot shadowed by inner loops still setting the "
      "extrapolation); Hermite segments unverified (Ts 24.11 does not evaluate them)";
  using storage_type = double;
  static constexpr time_solver default_solver = time_solver::closed_form;

  template <class Real>
  class model : public curvebench::channel::detail::optional_view<Real> {
   public:
    using real_type = Real;
    using tool_type = usd;
    static constexpr std::string_view name = usd::name;
    static constexpr int storage_bits = storage_bits_of<usd::storage_type>;

    /// The view is refused (view_refusal) for a dual-valued knot after a linear or curve segment.
    explicit model(const usd_model<Real>& m) : model_(m) {
      if (auto why = usd_view_refusal(m.resolved()))
        this->refuse_view(std::move(*why));
      else
        this->build_view(usd_channel_keys(m.resolved()), m.solver());
    }
    explicit model(const usd_spline<Real>& s, time_solver solver = default_solver)
        : model(usd_model<Real>(s, solver)) {}

    [[nodiscard]] Real value(const Real& t) const { return model_.value(t); }
    [[nodiscard]] Real derivative(const Real& t, int order) const { return model_.derivative(t, order); }
    /// The knot times of the resolved spline (the keys' times, with or without a view).
    [[nodiscard]] std::vector<Real> key_times() const {
      std::vector<Real> out;
      for (const auto& k : model_.resolved().knots) out.push_back(k.time);
      return out;
    }
    [[nodiscard]] const usd_model<Real>& evaluator() const { return model_; }

   private:
    usd_model<Real> model_;
  };

  /// The spline USD holds for the keys (see the header).
  [[nodiscard]] static usd_spline<double> spline_of_keys(std::span<const key<double>> keys) {
    curvebench::channel::detail::require_constant_linear_bezier(keys);
    usd_spline<double> s;
    for (const auto& k : keys) {
      usd_knot<double> u;
      u.time = k.time;
      u.value = k.value;
      u.next_interp = k.interp == interpolation::bezier   ? usd_interpolation::curve
                      : k.interp == interpolation::linear ? usd_interpolation::linear
                                                          : usd_interpolation::held;
      if ((k.in.dt == 0 && k.in.dv != 0) || (k.out.dt == 0 && k.out.dv != 0))
        validate::fail("a vertical handle (zero time length, nonzero value) has no slope in USD");
      u.pre_width = -k.in.dt, u.pre_slope = k.in.dt != 0 ? k.in.dv / k.in.dt : 0;
      u.post_width = k.out.dt, u.post_slope = k.out.dt != 0 ? k.out.dv / k.out.dt : 0;
      s.knots.push_back(u);
    }
    return s;
  }

  template <class Real>
  [[nodiscard]] static model<Real> from_keys(std::span<const key<double>> keys) {
    return model<Real>(usd_convert<Real>(spline_of_keys(keys)));
  }
};

}  // namespace tools

}  // namespace curvebench::channel
