// Registry entries "conic", "arc" and "circle" (see io/family.hpp): conic sections as rational
// quadratics. Arcs and circles are built once in double by the library's constructors and become
// plain rational_bezier / nurbs data (their resolver), so the 50-digit twin has the same weights.
#pragma once

#include "curvebench/curves/bspline.hpp"
#include "curvebench/curves/nurbs.hpp"
#include "curvebench/curves/rational_bezier.hpp"
#include "curvebench/io/family.hpp"

namespace curvebench::io {

namespace detail {

/// The spec of a double curve built by an arc or circle constructor: its control data as a
/// "nurbs" or "rational_bezier" spec.
inline json control_data_spec(const any_curve<double, 2>& c) {
  if (const auto* n = c.template target<nurbs<double, 2>>()) {
    return {{"type", "nurbs"},
            {"degree", n->degree()},
            {"points", points_json<2>(n->control_points())},
            {"weights", std::vector<double>(n->weights().begin(), n->weights().end())},
            {"knots", std::vector<double>(n->knots().begin(), n->knots().end())}};
  }
  const auto& b = *c.template target<rational_bezier<double, 2>>();
  return {{"type", "rational_bezier"},
          {"points", points_json<2>(b.control_points())},
          {"weights", std::vector<double>(b.weights().begin(), b.weights().end())}};
}

}  // namespace detail

struct conic_family : family_defaults {
  static constexpr std::string_view name = "conic";
  static constexpr std::string_view summary =
      "a rational quadratic conic arc: w < 1 ellipse, w = 1 parabola, w > 1 hyperbola";
  static constexpr field_doc fields[] = {
      {"points", "exactly 3 control points: start, shoulder, end", presence::required},
      {"w", "the middle weight (> 0; the end weights are 1)", presence::required},
  };
  static constexpr std::string_view examples[] = {
      R"({"type": "conic", "points": [[0,0],[1,1],[2,0]], "w": 0.5})",
  };

  template <class Real, int Dim>
  static any_curve<Real, Dim> build(const field& spec) {
    const point_list<Real, Dim> p = detail::spec_points<Real, Dim>(spec);
    if (p.size() != 3) spec.member("points").fail("a conic has exactly 3 points, got " + std::to_string(p.size()));
    return conic<Real, Dim>(p[0], p[1], p[2], spec.member("w").number_as<Real>());
  }
};

struct arc_family : family_defaults {
  static constexpr std::string_view name = "arc";
  static constexpr std::string_view summary = "a circular arc as one rational quadratic (2D, sweep in (0, pi))";
  static constexpr field_doc fields[] = {
      {"center", "[x, y]", presence::required},
      {"radius", "> 0", presence::required},
      {"start", "the start angle, radians", presence::required},
      {"sweep", "the swept angle, radians, in (0, pi)", presence::required},
  };
  static constexpr std::string_view examples[] = {
      R"({"type": "arc", "center": [0,0], "radius": 2, "start": 0.25, "sweep": 2.0943951023931957})",
  };

  static int dimension(const field&) { return 2; }

  template <class Real, int Dim>
  static any_curve<Real, Dim> build(const field& spec) {
    if constexpr (Dim == 2) {
      const point<Real, 2> c = detail::one_point<Real, 2>(spec.member("center"));
      const Real r(spec.member("radius").number());
      const Real start(spec.member("start").number());
      const Real sweep(spec.member("sweep").number());
      return circular_arc<Real>(c, r, start, sweep);
    } else {
      spec.fail("an arc is 2D, a " + std::to_string(Dim) + "D curve was asked for");
    }
  }

  /// The control points and weights, computed once in double: a "rational_bezier" spec.
  template <int Dim>
  static json resolve(const field& spec) {
    if constexpr (Dim == 2) return detail::control_data_spec(build<double, 2>(spec));
    return spec.value;
  }
};

struct circle_family : family_defaults {
  static constexpr std::string_view name = "circle";
  static constexpr std::string_view summary = "a full circle as a quadratic NURBS (2D)";
  static constexpr field_doc fields[] = {
      {"center", "[x, y]", presence::required},
      {"radius", "> 0", presence::required},
      {"control", "9 (four quarter arcs, default) or 7 (three 120-degree arcs) control points"},
  };
  static constexpr std::string_view examples[] = {
      R"({"type": "circle", "center": [1,-2], "radius": 3, "control": 9})",
  };
  /// A circle is a NURBS curve: its algorithms are the NURBS ones.
  static constexpr std::array<std::string_view, 2> algorithms{"de_boor", "basis_sum"};

  static int dimension(const field&) { return 2; }

  template <class Real, int Dim>
  static any_curve<Real, Dim> build(const field& spec) {
    if constexpr (Dim == 2) {
      const point<Real, 2> c = detail::one_point<Real, 2>(spec.member("center"));
      const Real r(spec.member("radius").number());
      const long long control = spec.has("control") ? spec.member("control").integer() : 9;
      if (control != 9 && control != 7)
        spec.member("control").fail(std::to_string(control) + " is not allowed (9 or 7 control points)");
      return control == 9 ? nurbs_circle_9<Real>(c, r) : nurbs_circle_7<Real>(c, r);
    } else {
      spec.fail("a circle is 2D, a " + std::to_string(Dim) + "D curve was asked for");
    }
  }

  /// The control points, weights and knots, computed once in double: a "nurbs" spec.
  template <int Dim>
  static json resolve(const field& spec) {
    if constexpr (Dim == 2) return detail::control_data_spec(build<double, 2>(spec));
    return spec.value;
  }

  template <int Dim>
  static evaluator_fn<Dim> evaluator(const any_curve<double, Dim>& c, const json&, std::string_view algorithm) {
    const bspline_evaluation a =
        detail::named(name, algorithm, {bspline_evaluation::de_boor, bspline_evaluation::basis_sum});
    return detail::on_target<nurbs<double, Dim>>(c, name, [a](const auto& n, double u) { return n.evaluate(u, 0, a); });
  }
};

}  // namespace curvebench::io
