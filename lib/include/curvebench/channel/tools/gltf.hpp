// The "gltf" tool: a scalar glTF 2.0 animation sampler (channel/gltf.hpp; one morph weight), as a
// glTF player evaluates it: the sampler's own step, linear or cubicspline formula, clamped outside
// the keys. The view is the channel of the same keys: cubicspline keys become hermite segments
// with the in and out tangents as slopes per unit time (gltf_channel_keys), step constant and
// linear linear segments. Rotation samplers (quaternions) have no scalar model: io/tools/gltf.hpp
// reads them as gltf::rotation_sampler.
// from_keys: a cubicspline sampler whose tangents are the handles' slopes (the handle lengths are
// lost: the Hermite puts them at 1/3 of the interval); all segments must be bezier (a sampler has
// one interpolation) and no handle vertical (a slope must be finite); times >= 0 (glTF's rule).
#pragma once

#include "curvebench/channel/channel.hpp"
#include "curvebench/channel/gltf.hpp"
#include "curvebench/channel/tool_model.hpp"

#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace curvebench::channel {

/// The channel keys of a scalar sampler (see the header).
template <class Real>
[[nodiscard]] std::vector<key<Real>> gltf_channel_keys(const gltf::sampler<Real, 1>& s) {
  const auto t = s.input();
  const auto v = s.values();
  std::vector<key<Real>> keys;
  for (std::size_t k = 0; k < t.size(); ++k) {
    key<Real> key;
    key.time = t[k];
    key.value = v[k][0];
    if (s.mode() == gltf::interpolation::cubicspline) {
      // glTF's tangents are slopes per unit time (the spec multiplies them by the key interval).
      key.in = {Real(-1), Real(-s.in_tangents()[k][0])};
      key.out = {Real(1), s.out_tangents()[k][0]};
      key.interp = interpolation::hermite;
    } else {
      key.interp = s.mode() == gltf::interpolation::step ? interpolation::constant : interpolation::linear;
    }
    keys.push_back(key);
  }
  return keys;
}

namespace tools {

struct gltf {
  static constexpr std::string_view name = "gltf";
  static constexpr std::string_view summary =
      "a glTF 2.0 animation sampler (step, linear or cubicspline; scalar weights or rotation quaternions)";
  static constexpr std::string_view rules = "cubicspline: the handles' slopes, lengths dropped (1/3 of the interval)";
  /// What the model is verified against (recorded values of the real tool) and what is not.
  static constexpr std::string_view verification =
      "against three.js's GLTFLoader interpolants (scripts/peers.sh, the Peers section) as the glTF 2.0 "
      "specification: step, linear and cubicspline scalars and rotations";
  using storage_type = double;
  static constexpr time_solver default_solver = time_solver::exact;

  template <class Real>
  class model {
   public:
    using real_type = Real;
    using tool_type = gltf;
    static constexpr std::string_view name = gltf::name;
    static constexpr int storage_bits = storage_bits_of<gltf::storage_type>;

    /// The sampler, and the solver of the view's channel (its hermite segments need none).
    explicit model(curvebench::channel::gltf::sampler<Real, 1> s, time_solver solver = default_solver)
        : sampler_(std::move(s)),
          view_(gltf_channel_keys(sampler_), extrapolation::constant, extrapolation::constant, solver) {}

    [[nodiscard]] Real value(const Real& t) const { return sampler_(t)[0]; }
    /// d^order v / dt^order, order 0 to 2 (the sampler's right-side derivative).
    [[nodiscard]] Real derivative(const Real& t, int order) const {
      validate::derivative_order(order);
      if (order > 2)
        validate::fail("order = " + std::to_string(order) + ": a channel's time derivatives go to order 2");
      return sampler_.derivative(t, order)[0];
    }
    [[nodiscard]] const channel<Real>& view() const { return view_; }
    [[nodiscard]] const curvebench::channel::gltf::sampler<Real, 1>& sampler() const { return sampler_; }

   private:
    curvebench::channel::gltf::sampler<Real, 1> sampler_;
    channel<Real> view_;
  };

  template <class Real>
  [[nodiscard]] static model<Real> from_keys(std::span<const key<double>> keys) {
    curvebench::channel::detail::require_constant_linear_bezier(keys);
    for (std::size_t i = 0; i + 1 < keys.size(); ++i)
      if (keys[i].interp != interpolation::bezier)
        validate::fail("a glTF sampler has one interpolation for all keys; these mix them");
    std::vector<Real> times, values;
    for (const auto& k : keys) {
      if ((k.in.dt == 0 && k.in.dv != 0) || (k.out.dt == 0 && k.out.dv != 0))
        validate::fail("a vertical handle has no finite glTF tangent");
      times.push_back(Real(k.time));
      values.push_back(Real(k.in.dt != 0 ? k.in.dv / k.in.dt : 0));
      values.push_back(Real(k.value));
      values.push_back(Real(k.out.dt != 0 ? k.out.dv / k.out.dt : 0));
    }
    return model<Real>(curvebench::channel::gltf::sampler<Real, 1>(
        std::move(times), std::span<const Real>(values), curvebench::channel::gltf::interpolation::cubicspline));
  }
};

}  // namespace tools

}  // namespace curvebench::channel
