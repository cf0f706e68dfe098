// The "maya" tool: a Maya animCurve (channel/maya.hpp: maya_curve, the tangent rules and
// maya_evaluator) as Maya evaluates it: solver isolate_brent, linear infinity along the end keys'
// own tangents. The view is the channel of the keys after the tangent rules.
// from_keys: a weighted curve with fixed tangents, the tangent vector 3 x the handle on the sides
// of bezier segments, linear tangents beside linear segments and a step out tangent on constant
// ones; a handle of zero time length is refused (a Maya tangent's x must be > 0); a handle that
// passes the other key on a segment whose time regresses is pulled back (AnimX's rule, maya.hpp).
#pragma once

#include "curvebench/channel/channel.hpp"
#include "curvebench/channel/maya.hpp"
#include "curvebench/channel/tool_model.hpp"

#include <span>
#include <string_view>
#include <utility>

namespace curvebench::channel::tools {

struct maya {
  static constexpr std::string_view name = "maya";
  static constexpr std::string_view summary =
      "a Maya animCurve: tangent types per side, fixed tangent vectors, weighted or not, pre and post infinity";
  static constexpr std::string_view rules =
      "weighted fixed tangents; regressive handles past the other key pulled back (AnimX)";
  /// What the model is verified against (recorded values of the real tool) and what is not.
  static constexpr std::string_view verification =
      "against Autodesk AnimX (Maya's evaluator, 64-bit time; tests/data/recorded/animx_curves.json, curvebench "
      "fidelity): fixed, auto, flat, linear, step and step_next tangents, weights, regressive handles, every "
      "infinity; spline, clamped and plateau tangents follow Maya's documentation and are not verified (AnimX "
      "evaluates stored tangents and does not compute them)";
  using storage_type = double;
  static constexpr time_solver default_solver = time_solver::isolate_brent;

  template <class Real>
  class model {
   public:
    using real_type = Real;
    using tool_type = maya;
    static constexpr std::string_view name = maya::name;
    static constexpr int storage_bits = storage_bits_of<maya::storage_type>;

    explicit model(const maya_curve<Real>& c, time_solver solver = default_solver) : evaluator_(c, solver) {}

    [[nodiscard]] Real value(const Real& t) const { return evaluator_.value(t); }
    [[nodiscard]] Real derivative(const Real& t, int order) const { return evaluator_.derivative(t, order); }
    [[nodiscard]] const channel<Real>& view() const { return evaluator_.underlying(); }

   private:
    maya_evaluator<Real> evaluator_;
  };

  /// The curve Maya holds for the keys (see the header).
  [[nodiscard]] static maya_curve<double> curve_of_keys(std::span<const key<double>> keys) {
    curvebench::channel::detail::require_constant_linear_bezier(keys);
    maya_curve<double> c;
    c.weighted = true;
    for (std::size_t i = 0; i < keys.size(); ++i) {
      const auto& k = keys[i];
      maya_key<double> m;
      m.time = k.time;
      m.value = k.value;
      // Only the sides of bezier segments carry a handle; the others keep Maya's default type.
      const bool bez_in = i > 0 && keys[i - 1].interp == interpolation::bezier;
      const bool bez_out = i + 1 < keys.size() && k.interp == interpolation::bezier;
      if ((bez_in && k.in.dt == 0) || (bez_out && k.out.dt == 0))
        validate::fail(validate::indexed("keys", i) +
                       ": a handle of zero time length has no Maya tangent (its x must be > 0)");
      if (bez_in) m.in_type = maya_tangent::fixed, m.in_x = -3 * k.in.dt, m.in_y = -3 * k.in.dv;
      if (bez_out) m.out_type = maya_tangent::fixed, m.out_x = 3 * k.out.dt, m.out_y = 3 * k.out.dv;
      if (k.interp == interpolation::linear) m.out_type = maya_tangent::linear;
      if (i > 0 && keys[i - 1].interp == interpolation::linear) m.in_type = maya_tangent::linear;
      if (k.interp == interpolation::constant) m.out_type = maya_tangent::step;
      c.keys.push_back(m);
    }
    return c;
  }

  template <class Real>
  [[nodiscard]] static model<Real> from_keys(std::span<const key<double>> keys) {
    return model<Real>(convert<Real>(curve_of_keys(keys)));
  }
};

}  // namespace curvebench::channel::tools
