// Registry entry "lagrange" (see io/family.hpp): the interpolating polynomial through the points.
#pragma once

#include "curvebench/curves/lagrange.hpp"
#include "curvebench/io/family.hpp"

namespace curvebench::io {

struct lagrange_family : audited_by_points {
  static constexpr std::string_view name = "lagrange";
  static constexpr std::string_view summary = "the polynomial of degree n through n + 1 points";
  static constexpr field_doc fields[] = {
      {"points", "the interpolated points", presence::required},
      {"params", "the parameter of each point, increasing (not with nodes)"},
      {"nodes",
       "the parameters when params are not given: equispaced on [0, 1] (default) or chebyshev "
       "(2nd kind, on [-1, 1])"},
      {"algorithm", "barycentric (default) or monomial (Vandermonde solve, then Horner)"},
  };
  static constexpr std::string_view examples[] = {
      R"({"type": "lagrange", "points": [[0,0],[1,2],[2,1]], "nodes": "chebyshev", "algorithm": "barycentric"})",
  };
  /// The algorithm is fixed at construction: each one is the curve rebuilt with "algorithm" set.
  static constexpr std::array<std::string_view, 2> algorithms{"barycentric", "monomial"};

  template <class Real, int Dim>
  static any_curve<Real, Dim> build(const field& spec) {
    const point_list<Real, Dim> p = detail::spec_points<Real, Dim>(spec);
    const lagrange_algorithm algorithm =
        spec.has("algorithm") && spec.member("algorithm").one_of({"barycentric", "monomial"}) == "monomial"
            ? lagrange_algorithm::monomial
            : lagrange_algorithm::barycentric;
    if (spec.has("params") && spec.has("nodes")) spec.member("params").fail("give either params or nodes");
    std::vector<Real> u;
    if (spec.has("params")) {
      u = spec.member("params").reals<Real>();
    } else if (spec.has("nodes") && spec.member("nodes").one_of({"equispaced", "chebyshev"}) == "chebyshev") {
      u = chebyshev_parameters<Real>(p.size());
    } else {
      u = equispaced_parameters<Real>(p.size());
    }
    return lagrange<Real, Dim>(std::span<const point<Real, Dim>>(p), std::span<const Real>(u), algorithm);
  }

  /// The parameters (equispaced or Chebyshev) computed once in double.
  template <int Dim>
  static json resolve(const field& spec) {
    json r = spec.value;
    if (!spec.has("params")) {
      const std::size_t n = spec.member("points").array_size();
      const bool cheb = spec.has("nodes") && spec.member("nodes").one_of({"equispaced", "chebyshev"}) == "chebyshev";
      r["params"] = cheb ? chebyshev_parameters<double>(n) : equispaced_parameters<double>(n);
      r.erase("nodes");
    }
    return r;
  }

  template <int Dim>
  static evaluator_fn<Dim> evaluator(const any_curve<double, Dim>&, const json& spec, std::string_view algorithm) {
    json twin = spec;
    twin["algorithm"] =
        to_string(detail::named(name, algorithm, {lagrange_algorithm::barycentric, lagrange_algorithm::monomial}));
    const any_curve<double, Dim> t = build<double, Dim>(field{twin, "spec"});
    return [t](double u) { return t(u); };
  }
};

}  // namespace curvebench::io
