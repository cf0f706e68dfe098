// The spec of tool "gltf" (channel/tools/gltf.hpp): a glTF 2.0 sampler ("interpolation": step,
// linear or cubicspline, "times" and "values" as glTF stores them: one value per key, or
// in-tangent, value, out-tangent per key for cubicspline), clamped outside the keys.
// "path": "weights" (the default: a scalar channel, one morph weight) or "rotation": the values are
// unit quaternions x y z w, four numbers each, interpolated by "blend": slerp (the default, the
// spec's) or nlerp for linear, normalized Hermite for cubicspline. A rotation's value is a
// quaternion, not a number over time: rotation_of_spec gives the sampler, `curvebench sample SPEC
// --at` prints t, x, y, z, w, and the scalar model and the curve view refuse it naming the path
// (a rotation spec is 4D, so that the runners that take 2D and 3D curves pass it by).
#pragma once

#include "curvebench/channel/gltf.hpp"
#include "curvebench/channel/tools/gltf.hpp"
#include "curvebench/core/point.hpp"
#include "curvebench/io/family.hpp"
#include "curvebench/io/tools/common.hpp"

#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace curvebench::io {

namespace detail {

// A gltf spec's "path": weights (scalar, the default) or rotation.
inline bool is_gltf_rotation(const field& spec) {
  if (!spec.has("tool") || spec.member("tool").string() != "gltf" || !spec.has("path")) return false;
  return spec.member("path").one_of({"weights", "rotation"}) == "rotation";
}

// The refusal of a scalar view (the channel, its curve) of a rotation spec.
[[noreturn]] inline void refuse_rotation(const field& spec, std::string_view what) {
  spec.member("path").fail("a rotation channel's value is a unit quaternion, so it has no " + std::string(what) +
                           "; `curvebench sample SPEC --at T1,T2` evaluates it (t, x, y, z, w)");
}

/// What sampler errors call the spec's data: its "times" and its flat "values".
inline constexpr channel::gltf::accessor_names spec_names{"times", "values", true};

/// make(), its sampler's invalid_input (which names times[i] or values[i]) as the spec's error:
/// rotation_of_spec's (the scalar channel's go through channel_model_of_spec, which does the same).
template <class F>
auto sampler_of_spec(const field& spec, F&& make) {
  try {
    return make();
  } catch (const invalid_input& x) {
    spec.fail(x.what());
  }
}

}  // namespace detail

/// The rotation sampler of a gltf spec with "path": "rotation" (see the header): its times, its
/// quaternions (x y z w; in-tangent, value, out-tangent per key for cubicspline) and its blend.
/// The sampler validates them as glTF does, naming the spec's file, values[i] (its place in the flat
/// list) and the key's role (unit values, | |q| - 1 | <= 0.00769). invalid_input for another tool
/// or path.
template <class Real>
channel::gltf::rotation_sampler<Real> rotation_of_spec(const field& spec) {
  if (!detail::is_gltf_rotation(spec))
    spec.fail("a rotation sampler needs \"tool\": \"gltf\" and \"path\": \"rotation\"");
  namespace g = channel::gltf;
  const g::interpolation mode = g::from_string<g::interpolation>(
      spec.member("interpolation", "tool \"gltf\" takes an interpolation").one_of({"step", "linear", "cubicspline"}));
  const g::rotation_blend blend =
      spec.has("blend") ? g::from_string<g::rotation_blend>(spec.member("blend").one_of({"slerp", "nlerp"}))
                        : g::rotation_blend::slerp;
  if (spec.has("blend") && mode != g::interpolation::linear)
    spec.member("blend").fail("blend chooses how linear interpolation turns between two rotations; interpolation \"" +
                              std::string(g::to_string(mode)) +
                              "\" would ignore it (step holds each key, cubicspline interpolates the components)");
  std::vector<Real> t = spec.member("times", "tool \"gltf\" takes times").reals<Real>();
  const field vf = spec.member("values", "tool \"gltf\" takes values");
  const std::vector<Real> v = vf.reals<Real>();
  if (v.size() % 4 != 0)
    vf.fail(std::to_string(v.size()) + " numbers given: a rotation's values are quaternions, 4 numbers (x y z w) each");
  std::vector<point<Real, 4>> q(v.size() / 4);
  for (std::size_t i = 0; i < q.size(); ++i) q[i] = point<Real, 4>(v[4 * i], v[4 * i + 1], v[4 * i + 2], v[4 * i + 3]);
  return detail::sampler_of_spec(spec, [&] {
    return g::rotation_sampler<Real>(std::move(t), std::span<const point<Real, 4>>(q), mode, blend, detail::spec_names);
  });
}

template <>
struct tool_spec<channel::tools::gltf> {
  static constexpr field_doc fields[] = {
      {"interpolation", "step, linear or cubicspline"},
      {"times", "the key times (the sampler's input)"},
      {"values",
       "the sampler's output (cubicspline: in-tangent, value, out-tangent per key; rotation: "
       "4 numbers x y z w per quaternion)"},
      {"path", "weights (a scalar channel, the default) or rotation (unit quaternion keys)"},
      {"blend", "rotation: slerp (the default) or nlerp for linear interpolation"},
  };
  static constexpr std::string_view example =
      R"({"type": "channel", "tool": "gltf", "interpolation": "cubicspline", "times": [0, 1, 3], "values": [0, 0, 1, 1, 2, 0, 0, 1, 0]})";

  /// The scalar sampler's model (a rotation spec is refused, naming the path).
  template <class Real>
  static channel::tools::gltf::model<Real> parse(const field& spec) {
    if (detail::is_gltf_rotation(spec)) detail::refuse_rotation(spec, "scalar value v(t)");
    if (spec.has("blend"))
      spec.member("blend").fail(
          "blend chooses how rotations interpolate; this channel's path is weights (a scalar "
          "channel), which would ignore it");
    namespace g = channel::gltf;
    const std::string mode =
        spec.member("interpolation", "tool \"gltf\" takes an interpolation").one_of({"step", "linear", "cubicspline"});
    std::vector<Real> t = spec.member("times", "tool \"gltf\" takes times").reals<Real>();
    const field vf = spec.member("values", "tool \"gltf\" takes values");
    const std::vector<Real> v = vf.reals<Real>();
    // The sampler validates the counts, times and values as glTF does (in double, as glTF's
    // floats widened, so that every precision refuses the same specs).
    const std::vector<double> td = spec.member("times").reals<double>(), vd = vf.reals<double>();
    const g::interpolation im = g::from_string<g::interpolation>(mode);
    // The samplers' invalid_input (naming times[i] or values[i]) becomes the spec's error in
    // channel_model_of_spec, which names the file.
    (void)g::sampler<double, 1>(td, std::span<const double>(vd), im, detail::spec_names);
    return channel::tools::gltf::model<Real>(
        g::sampler<Real, 1>(std::move(t), std::span<const Real>(v), im, detail::spec_names),
        detail::solver_of(spec, channel::tools::gltf::default_solver));
  }

  static int dimension(const field& spec) { return detail::is_gltf_rotation(spec) ? 4 : 2; }

  static void check_curve_view(const field& spec, int) {
    if (detail::is_gltf_rotation(spec)) detail::refuse_rotation(spec, "planar curve view (t(u), v(u))");
  }
};

}  // namespace curvebench::io
