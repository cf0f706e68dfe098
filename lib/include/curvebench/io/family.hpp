// What a family's registry entry (io/families/<type>.hpp) is made of, and the spec helpers the
// entries share.
//
// An entry is a struct deriving from `family_defaults` (or `audited_by_points`) with
//   name       the spec's "type"                      summary   one line: what the curve is
//   fields     its fields: name, one-line doc, required  examples  spec texts that parse and build
//   build<Real, Dim>(spec) -> any_curve<Real, Dim>     the builder, for any Real and Dim
// and, where the default does not fit, hides the default's
//   dimension(spec)          the curve's dimension (default: the points' dimension)
//   resolve<Dim>(spec)       derived data computed once in double and written into the spec, so a
//                            50-digit build is the exact twin of the double one (default: none)
//   algorithms, evaluator<Dim>(curve, spec, name)   the evaluation algorithms the accuracy runner
//                            compares with the default evaluation (default: none)
//   audit, audit_items_of(spec), with_items(spec, items)   the property audit's control items and
//                            how a perturbed set of items becomes a spec again (default: not audited)
// io/registry.hpp lists the entries; nothing else names them.
#pragma once

#include "curvebench/core/any_curve.hpp"
#include "curvebench/io/json_fields.hpp"

#include <boost/math/constants/constants.hpp>

#include <array>
#include <cmath>
#include <cstddef>
#include <functional>
#include <initializer_list>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace curvebench::io {

/// Whether every spec of a type must give a field.
enum class presence { required, optional };

/// One field of a spec type: its name, what it means (one line), whether every spec must give it.
struct field_doc {
  std::string_view name;
  std::string_view doc;
  presence need = presence::optional;

  [[nodiscard]] constexpr bool required() const { return need == presence::required; }
};

/// The role of a control item in the property audit: a point (moved as a point) or a tangent.
enum class audit_role { point, tangent };

/// The control items a family exposes to the property audit (2D, in double).
struct audit_items {
  point_list<double, 2> items;
  std::vector<audit_role> roles;  ///< one per item
};

/// The audit moves items one at a time and rebuilds the curve each time: specs with more points
/// are left out (the audit costs O(items^2) builds).
inline constexpr std::size_t audit_max_points = 40;

/// An evaluation algorithm applied to one double curve: u -> P(u).
template <int Dim>
using evaluator_fn = std::function<point<double, Dim>(double)>;

/// The most points a generator makes (its "count"): checked before any point is made.
inline constexpr std::size_t max_generated_points = 1000000;

namespace detail {

inline constexpr std::string_view generators[] = {"helix", "lissajous", "spiral", "runge"};

/// Generated point sets, so that a case with 1e5 points stays a few lines of JSON:
///   {"generate": "helix", "count": n, "radius": r, "pitch": c, "turns": k}      3D
///   {"generate": "lissajous", "count": n, "a": 3, "b": 2, "turns": 1}           2D
///   {"generate": "spiral", "count": n, "turns": k}                               2D
///   {"generate": "runge", "count": n, "nodes": "equispaced" | "chebyshev"}      2D graph of 1/(1+25x^2)
/// Computed in double (std::sin/cos of the double angle) and converted exactly to Real, so every
/// precision sees the same data.
inline std::vector<std::vector<double>> generate_points(const field& g) {
  g.only_members({"generate", "count", "radius", "pitch", "turns", "a", "b", "nodes"});
  const std::string kind = g.member("generate").one_of({"helix", "lissajous", "spiral", "runge"});
  const long long count = g.member("count").integer();
  if (count < 2 || count > static_cast<long long>(max_generated_points))
    g.member("count").fail(std::to_string(count) + " is not allowed (2 to " + std::to_string(max_generated_points) +
                           " points: the generated set is built in memory, about 1 KB a point, before the curve)");
  const auto n = static_cast<std::size_t>(count);
  const double two_pi = 2 * boost::math::constants::pi<double>();
  const auto num = [&](std::string_view key, double fallback) {
    return g.has(key) ? g.member(key).number() : fallback;
  };
  std::vector<std::vector<double>> out(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double f = static_cast<double>(i) / static_cast<double>(n - 1);
    if (kind == "helix") {
      const double th = two_pi * num("turns", 1) * f;
      out[i] = {num("radius", 1) * std::cos(th), num("radius", 1) * std::sin(th), num("pitch", 1) * th / two_pi};
    } else if (kind == "lissajous") {
      const double th = two_pi * num("turns", 1) * f;
      out[i] = {std::sin(num("a", 3) * th + two_pi / 4), std::sin(num("b", 2) * th)};
    } else if (kind == "spiral") {
      const double th = two_pi * num("turns", 1) * f;
      out[i] = {f * std::cos(th), f * std::sin(th)};
    } else {
      const std::string nodes = g.has("nodes") ? g.member("nodes").one_of({"equispaced", "chebyshev"}) : "equispaced";
      const double x = nodes == "equispaced" ? -1 + 2 * f : -std::cos(boost::math::constants::pi<double>() * f);
      out[i] = {x, 1 / (1 + 25 * x * x)};
    }
  }
  return out;
}

/// The points of a spec: an array of points, or a generator object.
template <class Real, int Dim>
point_list<Real, Dim> spec_points(const field& spec) {
  const field f = spec.member("points");
  if (!f.value.is_object()) return f.points<Real, Dim>();
  const json generated(generate_points(f));
  return field{generated, f.path}.points<Real, Dim>();
}

/// The dimension of a spec's points (a generator's: helix 3, the others 2).
inline int points_dimension(const field& spec) {
  // The type quoted as the messages quote a user's string (cut to 80 characters): an unknown type
  // reaches here before the build names it (a 9 kB type made a 6 kB message, fuzz spec).
  const std::string type = field::shown_string(spec.member("type").string());
  const field pts = spec.member("points", "every spec of type " + type + " has points");
  if (pts.value.is_object()) {
    const std::string kind = pts.member("generate").one_of({"helix", "lissajous", "spiral", "runge"});
    return kind == "helix" ? 3 : 2;
  }
  return pts.point_dimension();
}

inline constexpr std::string_view metadata[] = {"type", "name", "group", "reason", "quick"};

/// only_members with the metadata fields added: `fields` are the names of the type's fields.
inline void allow(const field& spec, std::span<const field_doc> fields) {
  std::vector<std::string_view> all(std::begin(metadata), std::end(metadata));
  for (const auto& f : fields) all.push_back(f.name);
  spec.only_members(all, " for type \"" + spec.member("type").string() + "\"");
}

template <class Real>
std::vector<Real> knots_or_uniform(const field& spec, std::size_t count) {
  if (spec.has("knots")) return spec.member("knots").reals<Real>();
  std::vector<Real> k(count);
  for (std::size_t i = 0; i < count; ++i) k[i] = Real(static_cast<long long>(i));
  return k;
}

template <class Real>
Real real_or(const field& spec, std::string_view key, const Real& fallback) {
  return spec.has(key) ? spec.member(key).number_as<Real>() : fallback;
}

template <class Real, int Dim>
point<Real, Dim> one_point(const field& f) {
  const json wrapped = json::array({f.value});
  const field list{wrapped, f.path};
  const point_list<Real, Dim> p = list.points<Real, Dim>();
  return p[0];
}

/// tension/continuity/bias: absent (0), one number for every key, or one per key.
template <class Real>
std::vector<Real> per_key(const field& spec, std::string_view key, std::size_t keys) {
  if (!spec.has(key)) return std::vector<Real>(keys, Real(0));
  const field f = spec.member(key);
  if (f.value.is_number()) return std::vector<Real>(keys, f.number_as<Real>());
  std::vector<Real> v = f.reals<Real>();
  if (v.size() != keys)
    f.fail("expected a number or " + std::to_string(keys) + " numbers (one per key), got " + std::to_string(v.size()));
  return v;
}

template <int Dim>
json points_json(std::span<const point<double, Dim>> ps) {
  json a = json::array();
  for (const auto& p : ps) {
    json q = json::array();
    for (int d = 0; d < Dim; ++d) q.push_back(p[d]);
    a.push_back(std::move(q));
  }
  return a;
}

/// u -> f(t, u) where t is the curve of type C wrapped by c, or an invalid_input naming the family
/// when c wraps something else. The function holds a copy of c, which keeps t alive.
template <class C, int Dim, class F>
evaluator_fn<Dim> on_target(const any_curve<double, Dim>& c, std::string_view type, F f) {
  const C* t = c.template target<C>();
  if (!t)
    throw invalid_input("evaluation algorithms of \"" + std::string(type) + "\": curve \"" + c.family() +
                        "\" was not built by this family");
  return [c, t, f](double u) {
    static_cast<void>(c);  // held for t's lifetime
    return f(*t, u);
  };
}

/// The enumerator of `all` whose to_string is `name`, or an invalid_input listing the names.
template <class Enum>
Enum named(std::string_view type, std::string_view name, std::initializer_list<Enum> all) {
  std::string list;
  for (Enum e : all) {
    if (to_string(e) == name) return e;
    list += (list.empty() ? "" : ", ") + std::string(to_string(e));
  }
  throw invalid_input("algorithm \"" + std::string(name) + "\" of type \"" + std::string(type) + "\": not one of " +
                      list);
}

}  // namespace detail

/// The defaults of a registry entry: dimension of the points, no derived data, no evaluation
/// algorithms besides the default, not audited. An entry hides what it does differently.
struct family_defaults {
  static constexpr std::array<std::string_view, 0> algorithms{};
  static constexpr std::string_view audit{};  ///< what the audit moves; empty: not audited

  static int dimension(const field& spec) { return detail::points_dimension(spec); }

  template <int Dim>
  static json resolve(const field& spec) {
    return spec.value;
  }

  template <int Dim>
  static evaluator_fn<Dim> evaluator(const any_curve<double, Dim>& c, const json&, std::string_view algorithm) {
    throw invalid_input("algorithm \"" + std::string(algorithm) + "\": type \"" + c.family() +
                        "\" offers no evaluation algorithm besides its default");
  }

  static std::optional<audit_items> audit_items_of(const field&) { return std::nullopt; }

  static json with_items(const json& spec, std::span<const point<double, 2>>) {
    throw invalid_input("with_items: type " + spec.value("type", std::string("?")) + " is not audited");
  }
};

/// An entry whose audit moves its control points: 2D specs whose points are an array of at most
/// audit_max_points points (generated point sets are not audited).
struct audited_by_points : family_defaults {
  static constexpr std::string_view audit = "the points (2D, an array of at most 40)";

  static std::optional<audit_items> audit_items_of(const field& spec) {
    if (!spec.has("points")) return std::nullopt;
    const field p = spec.member("points");
    if (!p.value.is_array() || p.value.empty() || p.value.size() > audit_max_points) return std::nullopt;
    if (!p.value[0].is_array() || p.value[0].size() != 2) return std::nullopt;
    audit_items a;
    a.items = p.points<double, 2>();
    a.roles.assign(a.items.size(), audit_role::point);
    return a;
  }

  static json with_items(const json& spec, std::span<const point<double, 2>> items) {
    json s = spec;
    s["points"] = detail::points_json<2>(items);
    return s;
  }
};

}  // namespace curvebench::io
