// Registry entries "bspline" and "nurbs" (see io/family.hpp): B-spline curves of any degree, and
// their rational (weighted) form.
#pragma once

#include "curvebench/curves/bspline.hpp"
#include "curvebench/curves/nurbs.hpp"
#include "curvebench/io/family.hpp"

namespace curvebench::io {

namespace detail {

inline constexpr std::array<std::string_view, 2> bspline_algorithms{"de_boor", "basis_sum"};

/// The order (degree + 1) of a bspline or nurbs spec.
inline int spline_order(const field& spec) {
  const long long degree = spec.member("degree", "the polynomial degree of the pieces").integer();
  if (degree < 0 || degree >= bspline_max_order)
    spec.member("degree").fail(std::to_string(degree) + " is not allowed (0 to " +
                               std::to_string(bspline_max_order - 1) + ")");
  return static_cast<int>(degree) + 1;
}

/// The knot vector a spec gives or names (clamped by default).
template <class Real>
std::vector<Real> spline_knots(const field& spec, const std::string& kind, std::size_t count, int order) {
  if (spec.has("knots")) return spec.member("knots").reals<Real>();
  return kind == "uniform" ? bspline_uniform_knots<Real>(count, order) : bspline_clamped_knots<Real>(count, order);
}

/// Clamped or uniform knot vectors computed once in double (a periodic one is left to the builder).
template <int Dim>
json resolve_spline_knots(const field& spec) {
  json r = spec.value;
  if (!spec.has("knots") && spec.has("degree") && spec.member("degree").value.is_number_integer()) {
    const std::string kind = spec.has("knot_vector") ? spec.member("knot_vector").string() : "clamped";
    const long long degree = spec.member("degree").integer();
    if ((kind == "clamped" || kind == "uniform") && degree >= 0 && degree < bspline_max_order) {
      const std::size_t n = spec.member("points").array_size();
      const int order = static_cast<int>(degree) + 1;
      r["knots"] =
          kind == "uniform" ? bspline_uniform_knots<double>(n, order) : bspline_clamped_knots<double>(n, order);
      r.erase("knot_vector");
    }
  }
  return r;
}

template <class C, int Dim>
evaluator_fn<Dim> spline_evaluator(const any_curve<double, Dim>& c, std::string_view type, std::string_view algorithm) {
  const bspline_evaluation a = named(type, algorithm, {bspline_evaluation::de_boor, bspline_evaluation::basis_sum});
  return on_target<C>(c, type, [a](const C& f, double u) { return f.evaluate(u, 0, a); });
}

}  // namespace detail

struct bspline_family : audited_by_points {
  static constexpr std::string_view name = "bspline";
  static constexpr std::string_view summary = "a B-spline curve of any degree on a knot vector";
  static constexpr field_doc fields[] = {
      {"points", "the control points", presence::required},
      {"degree", "the degree of the pieces, an integer 0 to 15 (order = degree + 1)", presence::required},
      {"knots", "the knot vector, non-decreasing, points + degree + 1 knots (not with knot_vector)"},
      {"knot_vector", "clamped (default), uniform, or periodic (closed: the points are a control loop)"},
  };
  static constexpr std::string_view examples[] = {
      R"({"type": "bspline", "points": [[0,0],[1,2],[3,3],[4,0],[6,1]], "degree": 3, "knot_vector": "clamped"})",
  };
  static constexpr std::array<std::string_view, 2> algorithms = detail::bspline_algorithms;

  template <class Real, int Dim>
  static any_curve<Real, Dim> build(const field& spec) {
    const point_list<Real, Dim> p = detail::spec_points<Real, Dim>(spec);
    const int order = detail::spline_order(spec);
    if (spec.has("knots") && spec.has("knot_vector")) spec.member("knots").fail("give either knots or knot_vector");
    const std::string kind =
        spec.has("knot_vector") ? spec.member("knot_vector").one_of({"clamped", "uniform", "periodic"}) : "clamped";
    if (kind == "periodic") return periodic_bspline<Real, Dim>(order, std::span<const point<Real, Dim>>(p));
    return bspline<Real, Dim>(order, detail::spline_knots<Real>(spec, kind, p.size(), order), p);
  }

  template <int Dim>
  static json resolve(const field& spec) {
    return detail::resolve_spline_knots<Dim>(spec);
  }

  template <int Dim>
  static evaluator_fn<Dim> evaluator(const any_curve<double, Dim>& c, const json&, std::string_view algorithm) {
    return detail::spline_evaluator<bspline<double, Dim>>(c, name, algorithm);
  }
};

struct nurbs_family : audited_by_points {
  static constexpr std::string_view name = "nurbs";
  static constexpr std::string_view summary = "a rational B-spline: control points with positive weights";
  static constexpr field_doc fields[] = {
      {"points", "the control points", presence::required},
      {"weights", "one weight > 0 per point", presence::required},
      {"degree", "the degree of the pieces, an integer 0 to 15 (order = degree + 1)", presence::required},
      {"knots", "the knot vector, non-decreasing, points + degree + 1 knots (not with knot_vector)"},
      {"knot_vector", "clamped (default) or uniform"},
  };
  static constexpr std::string_view examples[] = {
      R"({"type": "nurbs", "points": [[0,0],[1,2],[2,0],[3,2]], "weights": [1,3,0.5,1], "degree": 2, "knots": [0,0,0,0.5,1,1,1]})",
  };
  static constexpr std::array<std::string_view, 2> algorithms = detail::bspline_algorithms;

  template <class Real, int Dim>
  static any_curve<Real, Dim> build(const field& spec) {
    const point_list<Real, Dim> p = detail::spec_points<Real, Dim>(spec);
    const int order = detail::spline_order(spec);
    if (spec.has("knots") && spec.has("knot_vector")) spec.member("knots").fail("give either knots or knot_vector");
    const std::string kind =
        spec.has("knot_vector") ? spec.member("knot_vector").one_of({"clamped", "uniform"}) : "clamped";
    std::vector<Real> k = detail::spline_knots<Real>(spec, kind, p.size(), order);
    return nurbs<Real, Dim>(order, std::move(k), p,
                            spec.member("weights", "a NURBS curve has one weight per point").reals<Real>());
  }

  template <int Dim>
  static json resolve(const field& spec) {
    return detail::resolve_spline_knots<Dim>(spec);
  }

  template <int Dim>
  static evaluator_fn<Dim> evaluator(const any_curve<double, Dim>& c, const json&, std::string_view algorithm) {
    return detail::spline_evaluator<nurbs<double, Dim>>(c, name, algorithm);
  }
};

}  // namespace curvebench::io
