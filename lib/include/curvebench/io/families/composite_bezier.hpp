// Registry entry "composite_bezier" (see io/family.hpp): Bezier segments of any degrees, joined;
// rational ones when the spec gives weights.
#pragma once

#include "curvebench/curves/composite_bezier.hpp"
#include "curvebench/io/family.hpp"

namespace curvebench::io {

struct composite_bezier_family : family_defaults {
  static constexpr std::string_view name = "composite_bezier";
  static constexpr std::string_view summary = "Bezier segments of any degrees, each starting where the last ends";
  static constexpr field_doc fields[] = {
      {"segments", "one control point list per segment", presence::required},
      {"knots", "the segment boundaries, increasing, one more than the segments (default 0, 1, 2, ...)"},
      {"weights",
       "one weight list per segment, one weight > 0 per control point: rational segments (an SVG "
       "path's elliptical arcs, svg_path)"},
  };
  static constexpr std::string_view examples[] = {
      R"({"type": "composite_bezier", "knots": [0, 1, 2.5], "segments": [[[0,0],[1,2],[2,2]], [[2,2],[4,2],[5,0],[6,1]]]})",
  };

  /// The dimension of the first segment's points.
  static int dimension(const field& spec) {
    const field segs = spec.member("segments", "a composite Bezier curve is a list of segments");
    if (segs.array_size() == 0) segs.fail("expected at least one segment, got []");
    return segs.element(0).point_dimension();
  }

  template <class Real, int Dim>
  static any_curve<Real, Dim> build(const field& spec) {
    using pl = point_list<Real, Dim>;
    const field segs = spec.member("segments");
    std::vector<pl> segments(segs.array_size());
    for (std::size_t i = 0; i < segments.size(); ++i) segments[i] = segs.element(i).points<Real, Dim>();
    const std::vector<Real> k = detail::knots_or_uniform<Real>(spec, segments.size() + 1);
    if (!spec.has("weights"))
      return composite_bezier<Real, Dim>(std::span<const pl>(segments), std::span<const Real>(k));
    const field ws = spec.member("weights");
    if (ws.array_size() != segments.size())
      ws.fail("expected one weight list per segment (" + std::to_string(segments.size()) + "), got " +
              std::to_string(ws.array_size()));
    std::vector<std::vector<Real>> w(segments.size());
    for (std::size_t i = 0; i < w.size(); ++i) w[i] = ws.element(i).template reals<Real>();
    return composite_rational_bezier<Real, Dim>(std::span<const pl>(segments), std::span<const std::vector<Real>>(w),
                                                std::span<const Real>(k));
  }
};

}  // namespace curvebench::io
