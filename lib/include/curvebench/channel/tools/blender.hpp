// The "blender" tool: a Blender F-curve (channel/blender.hpp: blender_fcurve, the handle rules,
// Penner easing, the Cycles modifier and blender_evaluator) as Blender evaluates it; Blender
// stores and evaluates in float32 (storage_bits 32), with its own root finding of a Bezier
// segment's time cubic (blender_root; default_solver, exact, is the truth's). The view is the channel of the
// keys after the handle rules, each handle limited to its segment's duration; an eased segment
// appears there as its chord (its values are Penner's, not the view's).
// from_keys: free handles at the absolute positions key + handle (computed in double, then
// rounded to Real), the segments' interpolations, smoothing none; Blender limits each handle to
// its segment's duration when it evaluates.
#pragma once

#include "curvebench/channel/blender.hpp"
#include "curvebench/channel/channel.hpp"
#include "curvebench/channel/tool_model.hpp"

#include <cmath>
#include <cstddef>
#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace curvebench::channel::tools {

struct blender {
  static constexpr std::string_view name = "blender";
  static constexpr std::string_view summary =
      "a Blender F-curve: absolute handles and handle types, constant / linear / bezier / Penner "
      "interpolation, extrapolation, auto-handle smoothing, the Cycles modifier; float32";
  static constexpr std::string_view rules = "free handles in float32; each handle limited to its segment's duration";
  /// What the model is verified against (recorded values of the real tool) and what is not.
  static constexpr std::string_view verification =
      "against Blender 3.4.1 (tests/data/blender_fcurves.json, recorded/blender_heldout.json, curvebench "
      "fidelity): every handle type, interpolation and easing, extrapolation, smoothing and the Cycles "
      "modifier, curves mixing auto keys with vector, aligned and free ones (recorded/blender_mixed.json); near "
      "frame 1e4 and beyond to float rounding of the absolute frames, not bit for bit; refused (not "
      "modelled): auto_clamped beside a free handle on one key";
  using storage_type = float;
  static constexpr time_solver default_solver = time_solver::exact;
  /// What solves a Bezier segment's time in the float model when the spec names no solver (the
  /// 50-digit truth: default_solver).
  static constexpr std::string_view own_solver = "Blender's own";

  /// The words for a number Blender cannot hold (its F-curves are float32), after the field's name:
  /// "1e+300 is past float's range (3.4e38): ...". The spec parser and fcurve_of_keys say the same.
  [[nodiscard]] static std::string past_float(double x) {
    return to_text(x) + " is past float's range (3.4e38): Blender stores F-curves in float32";
  }

  template <class Real>
  class model {
   public:
    using real_type = Real;
    using tool_type = blender;
    static constexpr std::string_view name = blender::name;
    static constexpr int storage_bits = storage_bits_of<blender::storage_type>;

    /// solver: none (the default) is Blender's own root finding in float and exact at other
    /// precisions (blender_evaluator); a solver named in the spec replaces both.
    explicit model(const blender_fcurve<Real>& c, std::optional<time_solver> solver = std::nullopt)
        : evaluator_(c, solver) {}

    [[nodiscard]] Real value(const Real& t) const { return evaluator_.value(t); }
    [[nodiscard]] Real derivative(const Real& t, int order) const { return evaluator_.derivative(t, order); }
    [[nodiscard]] const channel<Real>& view() const { return evaluator_.underlying(); }
    /// The keys after the handle rules.
    [[nodiscard]] const std::vector<blender_key<Real>>& keys() const { return evaluator_.keys(); }

   private:
    blender_evaluator<Real> evaluator_;
  };

  /// The F-curve Blender holds for the keys, in Real (see the header).
  template <class Real>
  [[nodiscard]] static blender_fcurve<Real> fcurve_of_keys(std::span<const key<double>> keys) {
    curvebench::channel::detail::require_constant_linear_bezier(keys);
    blender_fcurve<Real> f;
    f.smoothing = auto_smoothing::none;
    // A finite double beyond Real's range (1e300 in float32) is refused naming the key's field and
    // the storage, not passed on as an infinity that the evaluator would call "not finite".
    const auto stored = [](std::size_t i, const char* field, double x) {
      const Real r = static_cast<Real>(x);
      if (std::isfinite(x) && !is_finite(r))
        validate::fail(validate::indexed("keys", i) + "." + field + " = " + past_float(x));
      return r;
    };
    for (std::size_t i = 0; i < keys.size(); ++i) {
      const auto& k = keys[i];
      blender_key<Real> b;
      b.time = stored(i, "time", k.time);
      b.value = stored(i, "value", k.value);
      b.handle_left = {stored(i, "time + in.dt", k.time + k.in.dt), stored(i, "value + in.dv", k.value + k.in.dv)};
      b.handle_right = {stored(i, "time + out.dt", k.time + k.out.dt), stored(i, "value + out.dv", k.value + k.out.dv)};
      b.handle_left_type = b.handle_right_type = handle_type::free;
      b.interpolation = k.interp == interpolation::bezier   ? blender_interpolation::bezier
                        : k.interp == interpolation::linear ? blender_interpolation::linear
                                                            : blender_interpolation::constant;
      f.keys.push_back(b);
    }
    return f;
  }

  template <class Real>
  [[nodiscard]] static model<Real> from_keys(std::span<const key<double>> keys) {
    return model<Real>(fcurve_of_keys<Real>(keys));
  }
};

}  // namespace curvebench::channel::tools
