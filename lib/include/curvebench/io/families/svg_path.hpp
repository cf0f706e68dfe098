// Registry entry "svg_path" (see io/family.hpp): SVG path data (io/svg_path.hpp) as a composite
// curve of its segments, each on a parameter interval of length 1 in the path's order: lines,
// quadratic and cubic Beziers as they are written, and each elliptical arc exactly as rational
// quadratics of at most 90 degrees each (the ellipse is an affine image of the circle, whose arc
// of sweep alpha from theta_a is the rational quadratic with end points on it, middle point
// (cos theta_m, sin theta_m) / cos(alpha / 2) and middle weight cos(alpha / 2), theta_m the middle
// angle). Subpaths follow one another; a jump between them adds no length (the segments need not
// meet, composite_bezier.hpp), so the length is the sum of the subpaths' lengths, as SVG's
// getTotalLength() gives it.
// Each arc's pieces are computed at 50 digits from the arc as written (io/svg_path.hpp's centre
// form, overflow-free) and converted to the Real built: a 50-digit build is the arc itself, so a
// reference built from it does not share a double build's rounding, and a double build's pieces
// are the 50-digit ones rounded, at most 2 ulps from them (the curve's rounding bound includes that
// distance, rational_bezier.hpp's control_data_error, so every estimate bounds the error from the
// arc written). Each piece starts at the written start point or at P_0 + A (u_k - u_0), A the
// ellipse's linear map, and its middle control point is its start plus tan(alpha / 2) times the
// tangent A perp(u_k): nothing is measured from the centre, which may be 1e300 away from an arc of
// length 10. How many pieces an arc has is decided once, in double, so every Real has the same
// parameterization. A path of lines and Beziers only is a polynomial composite, exact as written.
// The curve is built directly from the parsed segments (no intermediate JSON). At most
// svg::max_segments segments per path (svg_path.hpp) and max_arcs arcs, each of which costs about
// 0.1 ms at 50 digits.
// A path that draws no segment (only movetos) is refused, naming the field.
// Instead of "d", a spec may give "shape": one of SVG's basic shapes (circle, ellipse, rect, line,
// polyline, polygon) with its attributes as numbers ("points" for polyline and polygon: an array of
// [x, y]), measured as the path data SVG 2 defines for it (io/svg_shapes.hpp).
#pragma once

#include "curvebench/curves/composite_bezier.hpp"
#include "curvebench/io/family.hpp"
#include "curvebench/io/svg_path.hpp"
#include "curvebench/io/svg_shapes.hpp"
#include "curvebench/reference/multiprecision.hpp"

#include <boost/math/special_functions/pow.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <string>
#include <vector>

namespace curvebench::io {

namespace detail {

/// The rational quadratic pieces of arc segment s (see the header): control points, weights and the
/// distance of each piece's stored data from the 50-digit pieces (control_data_error).
template <class Real>
void arc_pieces(const svg::segment& s, std::vector<point_list<Real, 2>>& points,
                std::vector<std::vector<Real>>& weights, std::vector<control_data_error<Real>>& errors) {
  using W = real50;
  using std::abs, std::cos, std::sin, std::tan;
  const svg::arc_center<W> a = svg::center_form<W>(s);
  const double quarter = std::acos(-1.0) / 2;
  const int n = std::max(1, static_cast<int>(std::ceil(std::abs(static_cast<double>(a.dtheta)) / quarter - 1e-12)));
  const W alpha = a.dtheta / n, t = tan(alpha / 2), c = cos(alpha / 2);
  const W cp = cos(a.phi), sp = sin(a.phi);
  auto map = [&](const W& x, const W& y) {  // A (x, y), A = R(phi) diag(rx, ry)
    const W ax = a.rx * x, ay = a.ry * y;
    return std::array<W, 2>{cp * ax - sp * ay, sp * ax + cp * ay};
  };
  auto unit = [&](int k) {  // u_k = R(k alpha) u_0
    const W ck = cos(alpha * k), sk = sin(alpha * k);
    return std::array<W, 2>{ck * a.ux - sk * a.uy, sk * a.ux + ck * a.uy};
  };
  const std::array<W, 2> p0{W(s.p[0].x), W(s.p[0].y)}, pn{W(s.p[1].x), W(s.p[1].y)};
  auto at = [&](int k) {  // P_k: the written ends, else P_0 + A (u_k - u_0)
    if (k == 0) return p0;
    if (k == n) return pn;
    const std::array<W, 2> uk = unit(k);
    const std::array<W, 2> d = map(uk[0] - a.ux, uk[1] - a.uy);
    return std::array<W, 2>{p0[0] + d[0], p0[1] + d[1]};
  };
  // The 50-digit pieces' own rounding: relative to the points and to the tangents they are built from
  // (|t| (rx + ry) for one piece, rx + ry for several), with a factor 2^26 to spare over real50's
  // 2^-166 for the few operations each takes.
  const W own_scale = (n == 1 ? W(abs(t)) : W(1)) * (a.rx + a.ry);
  const W own = boost::math::pow<140>(W(0.5));
  const Real eps = epsilon<Real>();
  for (int k = 0; k < n; ++k) {
    const std::array<W, 2> pk = at(k), pk1 = at(k + 1), uk = unit(k);
    const std::array<W, 2> tangent = map(-uk[1], uk[0]);
    const std::array<W, 2> mid{pk[0] + t * tangent[0], pk[1] + t * tangent[1]};
    point_list<Real, 2> piece;
    W largest(0);
    for (const std::array<W, 2>& q : {pk, mid, pk1}) {
      piece.push_back(point<Real, 2>(static_cast<Real>(q[0]), static_cast<Real>(q[1])));
      if (!is_finite(piece.back()[0]) || !is_finite(piece.back()[1]))
        throw invalid_input("its pieces reach (" + to_text(q[0]) + ", " + to_text(q[1]) +
                            "), past the range of the arithmetic (radii " + to_text(a.rx) + ", " + to_text(a.ry) + ")");
      largest = std::max(largest, W(std::max(abs(q[0]), abs(q[1]))));
    }
    const Real wc = static_cast<Real>(c);
    points.push_back(std::move(piece));
    weights.push_back({Real(1), wc, Real(1)});
    // A conversion to Real is within 1 ulp per coordinate (2 eps |P| in norm, with room), the
    // weight's within 1 ulp; the written end points are exact but share the bound.
    const Real point_error =
        Real(2) * eps * static_cast<Real>(largest) + static_cast<Real>(own * (largest + own_scale));
    const Real weight_error = Real(2) * eps * wc + static_cast<Real>(own);
    errors.push_back({point_error, weight_error});
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

  /// The arcs a path may hold: each costs about 0.1 ms at 50 digits (see the header).
  static constexpr std::size_t max_arcs = 100000;

  template <class Real, int Dim>
  static any_curve<Real, Dim> build(const field& spec) {
    if constexpr (Dim == 2) {
      const std::string data = path_data(spec);
      const field d = spec.has("d") ? spec.member("d") : spec.member("shape");
      std::vector<svg::subpath> paths;
      try {
        paths = svg::parse_path(data);
      } catch (const invalid_input& e) {
        d.fail(e.what());
      }
      std::size_t arcs = 0;
      for (const svg::subpath& sp : paths)
        for (const svg::segment& s : sp.segments) arcs += s.kind == svg::segment_kind::arc ? 1 : 0;
      if (arcs > max_arcs)
        d.fail("the path data has " + std::to_string(arcs) + " elliptical arcs, more than the " +
               std::to_string(max_arcs) + " a path may hold (each costs about 0.1 ms at 50 digits)");
      std::vector<point_list<Real, 2>> points;
      std::vector<std::vector<Real>> weights;
      std::vector<control_data_error<Real>> errors;
      for (const svg::subpath& sp : paths) {
        for (const svg::segment& s : sp.segments) {
          if (s.kind == svg::segment_kind::arc) {
            try {
              detail::arc_pieces<Real>(s, points, weights, errors);
            } catch (const invalid_input& e) {
              d.fail("the arc at offset " + std::to_string(s.offset) + ": " + e.what());
            }
            continue;
          }
          point_list<Real, 2> p;
          for (int k = 0; k < s.points; ++k)
            p.push_back(
                point<Real, 2>(Real(s.p[static_cast<std::size_t>(k)].x), Real(s.p[static_cast<std::size_t>(k)].y)));
          points.push_back(std::move(p));
          weights.emplace_back(static_cast<std::size_t>(s.points), Real(1));
          errors.push_back({});
        }
      }
      if (points.empty()) d.fail("the path data draws no segment (only movetos or zero-length arcs)");
      std::vector<Real> knots(points.size() + 1);
      for (std::size_t i = 0; i < knots.size(); ++i) knots[i] = Real(static_cast<long long>(i));
      if (arcs == 0)
        return composite_bezier<Real, 2>(std::span<const point_list<Real, 2>>(points), std::span<const Real>(knots));
      return composite_rational_bezier<Real, 2>(
          std::span<const point_list<Real, 2>>(points), std::span<const std::vector<Real>>(weights),
          std::span<const Real>(knots), std::span<const control_data_error<Real>>(errors));
    } else {
      spec.fail("an svg_path is 2D, a " + std::to_string(Dim) + "D curve was asked for");
    }
  }
};

}  // namespace curvebench::io
