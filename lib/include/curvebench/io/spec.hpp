// JSON curve specs -> curves: the format the `curvebench` tool and the case suite read.
//
// A spec is an object {"type": "...", "points": [[x, y(, z)], ...], <the family's own fields>}.
// Every spec may also carry the metadata fields "name", "group", "reason" and "quick" (the case
// suite uses them); any other unknown field is an error, so a misspelled option never passes silently.
// The types, their fields, dimension rules and derived data are the family registry's
// (io/registry.hpp, one entry per type in io/families/); docs/specs.md's spec section is generated
// from it.
//
// Numbers are JSON doubles converted exactly to Real, so a spec instantiated at real50 is the
// exact 50-digit twin of the double curve (the harness's reference). Errors: io::spec_error
// (an invalid_input) naming the field path; family constructors' own invalid_input messages
// are prefixed with the spec's path. Cost: one construction of the family.
#pragma once

#include "curvebench/core/any_curve.hpp"
#include "curvebench/io/json_fields.hpp"
#include "curvebench/io/registry.hpp"

#include <cmath>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace curvebench::io {

/// One line per spec type: its name and its fields (required first, [optional] after).
struct spec_type_info {
  std::string_view type;
  std::string_view fields;
};

[[nodiscard]] inline std::span<const spec_type_info> spec_types() {
  static const std::vector<std::string> lines = [] {
    std::vector<std::string> v;
    for (const auto& d : families()) v.push_back(fields_line(d));
    return v;
  }();
  static const std::vector<spec_type_info> types = [] {
    std::vector<spec_type_info> v;
    for (std::size_t i = 0; i < families().size(); ++i) v.push_back({families()[i].type, lines[i]});
    return v;
  }();
  return types;
}

/// The dimension of the curve a spec describes (1..4).
[[nodiscard]] inline int spec_dimension(const field& spec) {
  int dim = 0;
  const std::string type = spec.member("type").string();
  if (visit_family(type, [&](auto entry) { dim = decltype(entry)::type::dimension(spec); })) return dim;
  return detail::points_dimension(spec);  // an unknown type: its points say; the build names the type
}

namespace detail {

/// The curve of a (resolved) spec of type `type`, after checking its fields.
template <class Real, int Dim>
any_curve<Real, Dim> build(const field& spec, const std::string& type) {
  std::optional<any_curve<Real, Dim>> c;
  visit_spec_family(spec, [&](auto entry) {
    using E = typename decltype(entry)::type;
    allow(spec, E::fields);
    c = E::template build<Real, Dim>(spec).renamed(type);
  });
  return *c;
}

/// The spec with every derived quantity computed once, in double, and written out as data:
/// generated points here, then the family's own resolver (alpha knots, s from tension, Lagrange
/// parameters, clamped/uniform B-spline knots, the control data of circles and arcs). Building
/// any Real from the resolved spec then gives the exact twin of the double curve (same knots,
/// same control data), which is what a 50-digit reference must be: computing e.g. |dP|^(1/2)
/// again in 50 digits would give a different curve, with a different domain, by an ulp.
template <int Dim>
json resolve(const field& spec) {
  json r = spec.value;
  if (spec.has("points") && spec.member("points").value.is_object())
    r["points"] = points_json<Dim>(spec_points<double, Dim>(spec));
  const field rf{r, spec.path};
  json out = r;
  visit_spec_family(rf, [&](auto entry) {
    using E = typename decltype(entry)::type;
    allow(rf, E::fields);  // before resolving: a resolver may drop fields (circle, arc)
    out = E::template resolve<Dim>(rf);
  });
  return out;
}

}  // namespace detail

/// The curve a spec describes, in Real and Dim (Dim must equal spec_dimension(spec)).
namespace detail {

/// The path and |value| of the number of largest magnitude in a JSON value (0 and the path when it
/// holds none). JSON values here are at most max_nesting_depth deep, so the recursion is bounded.
inline std::pair<std::string, double> largest_number(const json& v, const std::string& path) {
  std::pair<std::string, double> best{path, 0.0};
  auto consider = [&](const std::pair<std::string, double>& p) {
    if (p.second > best.second) best = p;
  };
  if (v.is_number()) return {path, std::abs(v.get<double>())};
  if (v.is_array())
    for (std::size_t i = 0; i < v.size(); ++i) consider(largest_number(v[i], path + "[" + std::to_string(i) + "]"));
  if (v.is_object())
    for (const auto& [k, m] : v.items()) consider(largest_number(m, path + "." + cut(k, 40)));
  return best;
}

}  // namespace detail

template <class Real, int Dim>
[[nodiscard]] any_curve<Real, Dim> curve_from_spec(const field& spec) {
  const std::string type = spec.member("type").string();
  const int dim = spec_dimension(spec);
  if (dim != Dim)
    spec.fail("describes a " + std::to_string(dim) + "D curve, but a " + std::to_string(Dim) + "D one was asked for");
  try {
    // Derived data is computed once in double, then every precision builds from the same data.
    const json resolved = detail::resolve<Dim>(spec);
    const field r{resolved, spec.path};
    const std::string resolved_type = r.member("type").string();
    any_curve<Real, Dim> c = detail::build<Real, Dim>(r, resolved_type);
    if (resolved_type == type) return c;
    return c.renamed(type);  // keep the family name the user gave ("circle", "arc")
  } catch (const spec_error&) {
    throw;
  } catch (const invalid_input& e) {  // a family's own validation: say which spec it came from
    std::string what = e.what();
    // The spec's numbers are all finite (io::parse refuses others), so a non-finite value in the
    // message is one the family computed (a tangent, a slope, a weight): name the data it came from.
    if (what.find("= inf") != std::string::npos || what.find("= -inf") != std::string::npos ||
        what.find("= nan") != std::string::npos || what.find("= -nan") != std::string::npos) {
      const auto [where, value] = detail::largest_number(spec.value, spec.path);
      what += " (a value computed from the spec's data overflowed double; its largest number is " + to_text(value) +
              " at " + where + ")";
    }
    throw spec_error(spec.path + " (type \"" + type + "\"): " + what);
  }
}

// The in-tree builds (tests, harness, tool) compile curve_from_spec once per Real and Dim in
// lib/src/spec_instances_*.cpp rather than in every file that reads a spec: each instantiation builds
// every family through any_curve, 30-80 s of compilation per file. CMake's curvebench_spec_instances
// target defines the macro; the installed, header-only io layer never sees it.
#ifdef CURVEBENCH_IO_SPEC_INSTANCES
}  // namespace curvebench::io
#include "curvebench/reference/multiprecision.hpp"
namespace curvebench::io {
#define CURVEBENCH_IO_SPEC_INSTANCE(Real, Dim) \
  extern template any_curve<Real, Dim> curve_from_spec<Real, Dim>(const field&);
CURVEBENCH_IO_SPEC_INSTANCE(double, 1)
CURVEBENCH_IO_SPEC_INSTANCE(double, 2)
CURVEBENCH_IO_SPEC_INSTANCE(double, 3)
CURVEBENCH_IO_SPEC_INSTANCE(double, 4)
CURVEBENCH_IO_SPEC_INSTANCE(real50, 1)
CURVEBENCH_IO_SPEC_INSTANCE(real50, 2)
CURVEBENCH_IO_SPEC_INSTANCE(real50, 3)
#undef CURVEBENCH_IO_SPEC_INSTANCE
#endif

}  // namespace curvebench::io
