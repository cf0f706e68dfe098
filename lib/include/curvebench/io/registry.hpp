// The family registry: every spec type, in one list. Each entry (io/families/<type>.hpp, built
// from io/family.hpp) holds the type's name, summary, documented fields, examples, builder,
// resolver of derived data, dimension rule, evaluation algorithms and property-audit hooks. The
// spec parser (io/spec.hpp), `curvebench list`, the accuracy runner and docs/specs.md's spec section
// (families_markdown(), checked by tests/test_registry.cpp) all read it.
//
// Adding a spec type: its entry file, its #include below and its name in `all_families`.
//
// Compile-time access: for_each_family_type(f) calls f(std::type_identity<Entry>{}) per entry.
// Runtime access: families() / for_each_family(f) / find_family(type) give family_descriptor's;
// evaluation_algorithms(curve, spec), audit_items_of(spec) and with_items(spec, items) dispatch
// on the spec's "type". Cost: a linear scan of the names per dispatch.
#pragma once

#include "curvebench/io/families/bezier.hpp"
#include "curvebench/io/families/bspline.hpp"
#include "curvebench/io/families/cardinal.hpp"
#include "curvebench/io/families/channel.hpp"
#include "curvebench/io/families/composite_bezier.hpp"
#include "curvebench/io/families/conic.hpp"
#include "curvebench/io/families/hermite.hpp"
#include "curvebench/io/families/kochanek_bartels.hpp"
#include "curvebench/io/families/lagrange.hpp"
#include "curvebench/io/families/natural_cubic.hpp"
#include "curvebench/io/families/polyline.hpp"
#include "curvebench/io/families/svg_path.hpp"
#include "curvebench/io/family.hpp"

#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <vector>

namespace curvebench::io {

template <class... Entries>
struct family_list {};

/// Every spec type, in the order `curvebench list` and docs/specs.md show them.
using all_families = family_list<polyline_family, lagrange_family, bezier_family, rational_bezier_family,
                                 composite_bezier_family, conic_family, arc_family, circle_family, svg_path_family,
                                 hermite_family, cardinal_family, catmull_rom_family, kochanek_bartels_family,
                                 natural_cubic_family, bspline_family, nurbs_family, channel_family>;

namespace detail {
template <class F, class... Entries>
void for_each_in(family_list<Entries...>, F& f) {
  (f(std::type_identity<Entries>{}), ...);
}
}  // namespace detail

/// Calls f(std::type_identity<Entry>{}) for every entry of all_families, in order.
template <class F>
void for_each_family_type(F&& f) {
  detail::for_each_in(all_families{}, f);
}

/// Calls f(std::type_identity<Entry>{}) for the entry named `type`; false when there is none.
template <class F>
bool visit_family(std::string_view type, F&& f) {
  bool found = false;
  for_each_family_type([&](auto entry) {
    if (!found && decltype(entry)::type::name == type) {
      found = true;
      f(entry);
    }
  });
  return found;
}

/// What the registry says about one spec type, without its templates.
struct family_descriptor {
  std::string_view type;                         ///< the spec's "type"
  std::string_view summary;                      ///< one line
  std::span<const field_doc> fields;             ///< in the order the docs list them
  std::span<const std::string_view> examples;    ///< spec texts that parse and build (at least one)
  std::span<const std::string_view> algorithms;  ///< evaluation algorithms besides the default
  std::string_view audit;                        ///< what the property audit moves; empty: not audited

  [[nodiscard]] bool audited() const { return !audit.empty(); }
  [[nodiscard]] const field_doc* find_field(std::string_view name) const {
    for (const auto& f : fields)
      if (f.name == name) return &f;
    return nullptr;
  }
};

/// The descriptors of all_families, in order.
[[nodiscard]] inline std::span<const family_descriptor> families() {
  static const std::vector<family_descriptor> all = [] {
    std::vector<family_descriptor> v;
    for_each_family_type([&](auto entry) {
      using E = typename decltype(entry)::type;
      v.push_back({E::name, E::summary, std::span<const field_doc>(E::fields),
                   std::span<const std::string_view>(E::examples), std::span<const std::string_view>(E::algorithms),
                   E::audit});
    });
    return v;
  }();
  return all;
}

/// Calls f(const family_descriptor&) for every spec type, in order.
template <class F>
void for_each_family(F&& f) {
  for (const auto& d : families()) f(d);
}

/// The descriptor of `type`, or nullptr when no family has that name.
[[nodiscard]] inline const family_descriptor* find_family(std::string_view type) {
  for (const auto& d : families())
    if (d.type == type) return &d;
  return nullptr;
}

namespace detail {

/// The names of all types, comma separated (for error messages).
inline std::string type_names() {
  std::string list;
  for (const auto& d : families()) list += (list.empty() ? "" : ", ") + std::string(d.type);
  return list;
}

/// The entry of spec's "type" applied to f; an unknown type is a spec_error listing the types.
template <class F>
void visit_spec_family(const field& spec, F&& f) {
  const std::string type = spec.member("type").string();
  if (!visit_family(type, f))
    spec.member("type").fail(field::shown_string(type) + " is not a curve type (types: " + type_names() + ")");
}

}  // namespace detail

/// The evaluation algorithms the spec's family offers besides its default evaluation c(u): each
/// name with u -> P(u) evaluated by that algorithm. c is the double curve built from spec
/// (curve_from_spec<double, Dim>(root(spec))). Empty when the family offers none.
template <int Dim>
[[nodiscard]] std::vector<std::pair<std::string, evaluator_fn<Dim>>> evaluation_algorithms(
    const any_curve<double, Dim>& c, const json& spec) {
  std::vector<std::pair<std::string, evaluator_fn<Dim>>> out;
  detail::visit_spec_family(root(spec), [&](auto entry) {
    using E = typename decltype(entry)::type;
    for (std::string_view a : E::algorithms) out.emplace_back(std::string(a), E::template evaluator<Dim>(c, spec, a));
  });
  return out;
}

/// The control items the property audit moves for this spec (points, then tangents), or nullopt
/// when the audit does not apply (family not audited, not 2D, points generated or more than
/// audit_max_points).
[[nodiscard]] inline std::optional<audit_items> audit_items_of(const json& spec) {
  std::optional<audit_items> out;
  detail::visit_spec_family(root(spec), [&](auto entry) { out = decltype(entry)::type::audit_items_of(root(spec)); });
  return out;
}

/// The spec with its audit items replaced by `items` (same count and order as audit_items_of's).
[[nodiscard]] inline json with_items(const json& spec, std::span<const point<double, 2>> items) {
  json out;
  detail::visit_spec_family(root(spec), [&](auto entry) { out = decltype(entry)::type::with_items(spec, items); });
  return out;
}

/// One family's fields in one line: required names first, then [optional] ones.
[[nodiscard]] inline std::string fields_line(const family_descriptor& d) {
  std::string line;
  for (const auto& f : d.fields)
    if (f.required()) line += (line.empty() ? "" : " ") + std::string(f.name);
  for (const auto& f : d.fields)
    if (!f.required()) line += (line.empty() ? "[" : " [") + std::string(f.name) + "]";
  return line;
}

/// docs/specs.md's spec reference: every example, then each type's summary and field docs, then the
/// algorithms and audit of each. docs/specs.md holds this text between the markers
/// `<!-- families:begin -->` and `<!-- families:end -->` (tests/test_registry.cpp checks it).
[[nodiscard]] inline std::string families_markdown() {
  std::string md = "```json\n";
  for (const auto& d : families())
    for (auto e : d.examples) md += std::string(e) + "\n";
  md += "```\n\n";
  for (const auto& d : families()) {
    md += "- **`" + std::string(d.type) + "`**: " + std::string(d.summary) + ".";
    if (!d.algorithms.empty()) {
      md += " Evaluation algorithms:";
      for (std::size_t i = 0; i < d.algorithms.size(); ++i)
        md += std::string(i == 0 ? " `" : ", `") + std::string(d.algorithms[i]) + "`";
      md += ".";
    }
    if (d.audited()) md += " Property audit: " + std::string(d.audit) + ".";
    md += "\n";
    for (const auto& f : d.fields)
      md +=
          "  - `" + std::string(f.name) + "`" + (f.required() ? " (required)" : "") + ": " + std::string(f.doc) + "\n";
  }
  return md;
}

}  // namespace curvebench::io
