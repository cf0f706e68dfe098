// Registry entry "svg_path" (see io/family.hpp): SVG path data (io/svg_path.hpp) as a composite
// curve of its segments, each on a parameter interval of length 1 in the path's order: lines,
// quadratic and cubic Beziers as they are written, and each elliptical arc exactly as rational
// quadratics of at most 90 degrees each (the ellipse is an affine image of the circle, whose arc
// of sweep alpha from theta_a is the rational quadratic with end points on it, middle point
// (cos theta_m, sin theta_m) / cos(alpha / 2) and middle weight cos(alpha / 2), theta_m the middle
// angle). Subpaths follow one another; a jump between them adds no length (the segments need not
// meet, composite_bezier.hpp), so the length is the sum of the subpaths' lengths, as SVG's
// getTotalLength() gives it.
// The resolver converts the path once, in double, to a "composite_bezier" spec with weights (the
// first and last piece of an arc end exactly at the written points), so a 50-digit twin has the
// same control data, as for the "arc" family; a path of lines and Beziers only has no weights.
// A path that draws no segment (only movetos) is refused, naming the field.
// Instead of "d", a spec may give "shape": one of SVG's basic shapes (circle, ellipse, rect, line,
// polyline, polygon) with its attributes as numbers ("points" for polyline and polygon: an array of
// [x, y]), measured as the path data SVG 2 defines for it (io/svg_shapes.hpp).
#pragma once

#include "curvebench/curves/composite_bezier.hpp"
#include "curvebench/io/families/composite_bezier.hpp"
#include "curvebench/io/family.hpp"
#include "curvebench/io/svg_path.hpp"
#include "curvebench/io/svg_shapes.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <string>
#include <vector>

namespace curvebench::io {

namespace detail {

/// The rational quadratic pieces (points and weights) of arc segment s, in double.
inline void arc_pieces(const svg::segment& s, std::vector<std::vector<std::array<double, 2>>>& points,
                       std::vector<std::vector<double>>& weights) {
  const svg::arc_center<double> a = svg::center_form<double>(s);
  // Radii or coordinates near double's limits overflow the conversion; the cast below must not
  // see a NaN (undefined behaviour), and the curve's own validation would refuse an inf anyway.
  for (const double v : {a.cx, a.cy, a.rx, a.ry, a.theta1, a.dtheta})
    if (!std::isfinite(v))
      throw invalid_input("an elliptical arc's centre form overflows double (its radii or coordinates are too large)");
  const double quarter = std::acos(-1.0) / 2;
  const int n = std::max(1, static_cast<int>(std::ceil(std::abs(a.dtheta) / quarter - 1e-12)));
  const double alpha = a.dtheta / n, c = std::cos(alpha / 2);
  const double cp = std::cos(a.phi), sp = std::sin(a.phi);
  auto on = [&](double theta, double scale) {
    const double x = a.rx * std::cos(theta) / scale, y = a.ry * std::sin(theta) / scale;
    return std::array<double, 2>{a.cx + cp * x - sp * y, a.cy + sp * x + cp * y};
  };
  for (int k = 0; k < n; ++k) {
    const double ta = a.theta1 + alpha * k, tb = k + 1 == n ? a.theta1 + a.dtheta : ta + alpha;
    const std::array<double, 2> p0 = k == 0 ? std::array<double, 2>{s.p[0].x, s.p[0].y} : points.back().back();
    const std::array<double, 2> p2 = k + 1 == n ? std::array<double, 2>{s.p[1].x, s.p[1].y} : on(tb, 1);
    points.push_back({p0, on((ta + tb) / 2, c), p2});
    weights.push_back({1, c, 1});
  }
}

}  // namespace detail

struct svg_path_family : family_defaults {
  static constexpr std::string_view name = "svg_path";
  static constexpr std::string_view summary =
      "SVG path data (the d attribute): lines, quadratic and cubic Beziers, elliptical arcs (exact, as rational "
      "quadratics), every subpath";
  static constexpr field_doc fields[] = {
      {"d",
       "the path data, SVG 1.1 / SVG 2 grammar (M, L, H, V, C, S, Q, T, A, Z, absolute and relative); exactly one of d "
       "and shape",
       presence::optional},
      {"shape",
       "an SVG basic shape as {\"element\": circle | ellipse | rect | line | polyline | polygon, its attributes as "
       "numbers "
       "(cx, cy, r, rx, ry, x, y, width, height, x1, y1, x2, y2), \"points\": [[x, y], ...] for polyline and polygon}, "
       "measured as the path SVG 2 defines for it",
       presence::optional},
  };
  static constexpr std::string_view examples[] = {
      R"({"type": "svg_path", "d": "M0 0 C1 2 3 2 4 0 S7 -2 8 0 Q9 1 10 0 A2 1 30 0 1 14 0 L14 -2 Z"})",
      R"({"type": "svg_path", "shape": {"element": "rect", "x": 0, "y": 0, "width": 10, "height": 4, "rx": 1}})",
  };

  /// The path data of a spec: its "d", or the path of its "shape" (exactly one of them).
  static std::string path_data(const field& spec) {
    if (spec.has("d") == spec.has("shape"))
      spec.fail(spec.has("d") ? "gives both d and shape; an svg_path is one of them"
                              : "needs d (path data) or shape (an SVG basic shape)");
    if (spec.has("d")) return spec.member("d").string();
    const field f = spec.member("shape");
    svg::shape s;
    s.element = f.member("element", "a shape names its SVG element")
                    .one_of({"circle", "ellipse", "rect", "line", "polyline", "polygon"});
    const bool listed = s.element == "polyline" || s.element == "polygon";
    static constexpr std::string_view numeric[] = {"cx",    "cy",     "r",  "rx", "ry", "x", "y",
                                                   "width", "height", "x1", "y1", "x2", "y2"};
    for (const auto& [key, value] : f.value.items()) {
      if (key == "element") continue;
      if (key == "points" && listed) {
        const point_list<double, 2> pts = f.member("points").points<double, 2>();
        for (const auto& p : pts) s.points.push_back({p[0], p[1]});
        continue;
      }
      if (std::find(std::begin(numeric), std::end(numeric), key) == std::end(numeric))
        f.member(key).fail(
            "is not an attribute of a <" + s.element + "> curvebench reads (" +
            (listed ? std::string("points") : std::string("cx, cy, r, rx, ry, x, y, width, height, x1, y1, x2, y2")) +
            ")");
      s.numbers[key] = f.member(key).number();
    }
    try {
      return svg::shape_path_data(s);
    } catch (const invalid_input& e) {
      f.fail(e.what());
    }
  }

  static int dimension(const field&) { return 2; }

  /// The path as a "composite_bezier" spec (see the header).
  template <int Dim>
  static json resolve(const field& spec) {
    const std::string data = path_data(spec);
    const field d = spec.has("d") ? spec.member("d") : spec.member("shape");
    std::vector<svg::subpath> paths;
    try {
      paths = svg::parse_path(data);
    } catch (const invalid_input& e) {
      d.fail(e.what());
    }
    std::vector<std::vector<std::array<double, 2>>> points;
    std::vector<std::vector<double>> weights;
    bool rational = false;
    for (const svg::subpath& sp : paths) {
      for (const svg::segment& s : sp.segments) {
        if (s.kind == svg::segment_kind::arc) {
          detail::arc_pieces(s, points, weights);
          rational = true;
          continue;
        }
        std::vector<std::array<double, 2>> p;
        for (int k = 0; k < s.points; ++k)
          p.push_back({s.p[static_cast<std::size_t>(k)].x, s.p[static_cast<std::size_t>(k)].y});
        points.push_back(std::move(p));
        weights.emplace_back(static_cast<std::size_t>(s.points), 1.0);
      }
    }
    if (points.empty()) d.fail("the path data draws no segment (only movetos or zero-length arcs)");
    json out{{"type", "composite_bezier"}, {"segments", points}};
    if (rational) out["weights"] = weights;
    return out;
  }

  template <class Real, int Dim>
  static any_curve<Real, Dim> build(const field& spec) {
    if constexpr (Dim == 2) {
      const json r = resolve<2>(spec);
      return composite_bezier_family::build<Real, Dim>(field{r, spec.path});
    } else {
      spec.fail("an svg_path is 2D, a " + std::to_string(Dim) + "D curve was asked for");
    }
  }
};

}  // namespace curvebench::io
