// The data of a curve spec as the families read it, public: for code that hands the same data to
// another library (the harness's peers: GSL, Boost and Eigen splines on the spec's own points and
// knots) or routes a spec by its kind (a glTF rotation channel, which has no scalar curve).
// Reading through these keeps such code on the families' rules (generated points, the uniform
// default knots, a point field's errors) without reaching into io::detail.
#pragma once

#include "curvebench/io/families/channel.hpp"
#include "curvebench/io/family.hpp"

#include <cstddef>
#include <vector>

namespace curvebench::io {

/// The spec's points: its "points" array, or the points its generator object makes.
template <class Real, int Dim>
[[nodiscard]] point_list<Real, Dim> points_of(const field& spec) {
  return detail::spec_points<Real, Dim>(spec);
}

/// The spec's "knots", or 0, 1, ..., count - 1 when it has none (the families' default).
template <class Real>
[[nodiscard]] std::vector<Real> knots_of(const field& spec, std::size_t count) {
  return detail::knots_or_uniform<Real>(spec, count);
}

/// One point field (e.g. "start_slope": [1, 0]) read as a point of Dim coordinates; errors name it.
template <class Real, int Dim>
[[nodiscard]] point<Real, Dim> point_of(const field& f) {
  return detail::one_point<Real, Dim>(f);
}

/// Whether the spec is a glTF rotation channel ("tool": "gltf", "path": "rotation"): a sampler of
/// quaternions, not a scalar channel or curve.
[[nodiscard]] inline bool is_gltf_rotation(const field& spec) { return detail::is_gltf_rotation(spec); }

}  // namespace curvebench::io
