// Registry entry "channel" (see io/family.hpp): a keyframe channel, a value over time, as one
// animation tool evaluates it (channel/tool_model.hpp). The "tool" field names the tool whose rules
// apply to the keys (one of io/tools/all.hpp's all_tools: exact, css, gltf, maya, blender, usd) and
// the tool's own fields follow; each tool's parser, its fields and their docs are in
// io/tools/<tool>.hpp, and the field docs below are assembled from them at compile time (a field
// several tools share lists each tool's meaning). "solver" chooses the time solver of bezier
// segments for every tool (each has its default, channel/tools/<tool>.hpp).
// The spec's curve is the channel's planar curve P(u) = (t(u), v(u)) (2D; segment i on [i, i + 1]),
// the view of the tool's model, so arc length and the accuracy sweep apply; `curvebench sample SPEC
// --at T1,T2` and `--frames A:B:STEP` evaluate the value at times through channel_model_of_spec.
// A tool may refuse the curve view of some specs (glTF rotations, Blender's eased segments) or
// give another dimension (a glTF rotation is 4D, so that the runners of 2D and 3D curves pass it by).
#pragma once

#include "curvebench/channel/channel.hpp"
#include "curvebench/channel/tool_model.hpp"
#include "curvebench/io/family.hpp"
#include "curvebench/io/tools/all.hpp"

#include <algorithm>
#include <array>
#include <cstddef>
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace curvebench::io {

/// A channel spec under its tool's rules: the value and time derivatives (orders 0 to 2) at a time
/// as the tool evaluates them (the tool model's derivative), the keys' times, and the channel whose
/// curve() is the spec's curve (the tool model's view). A model may have no view (a USD
/// dual-valued knot after a linear or curve segment: a jump; CSS steps(n) above 2^16, whose key
/// times are then given as 0 and 1 only); source() then fails with the reason, naming the spec,
/// and `at` still evaluates.
template <class Real>
struct channel_model {
  std::optional<channel::channel<Real>> view;
  std::string no_view;  // why view is empty, with the spec's path
  std::vector<Real> key_times;
  std::function<Real(const Real&, int)> at;

  [[nodiscard]] const channel::channel<Real>& source() const {
    if (!view) throw spec_error(no_view);
    return *view;
  }
};

namespace detail {

/// Fails on a member of a channel spec that belongs to another tool than the spec's (T), naming the
/// tools it belongs to: the family accepts every tool's fields, so `"easing"` on an exact channel,
/// `"keys"` on a CSS one or Maya's `"post"` on an exact one were silently dropped. The metadata,
/// "tool" and "solver" are every tool's; a name no tool has is refused as unknown, listing T's
/// fields (the family's only_members reports it on the curve path, but `sample --at` and `check
/// --values` build the model alone: a misspelt "extrapolation" was read past there).
template <class T, class... Tools>
void check_tool_fields(const field& spec, channel::tool_list<Tools...>) {
  if (!spec.value.is_object()) return;
  for (const auto& item : spec.value.items()) {
    const std::string& key = item.key();
    if (key == "tool" || key == "solver" ||
        std::find(std::begin(metadata), std::end(metadata), key) != std::end(metadata))
      continue;
    const auto has = [&](std::span<const field_doc> fields) {
      return std::any_of(fields.begin(), fields.end(), [&](const field_doc& f) { return f.name == key; });
    };
    if (has(tool_spec<T>::fields)) continue;
    std::string owners;
    const auto add = [&](std::string_view tool, std::span<const field_doc> fields) {
      if (has(fields)) owners += (owners.empty() ? "\"" : ", \"") + std::string(tool) + "\"";
    };
    (add(Tools::name, tool_spec<Tools>::fields), ...);
    if (owners.empty()) {  // no tool's: a misspelling, refused on every path (sample --at read past it)
      std::vector<std::string_view> allowed(std::begin(metadata), std::end(metadata));
      allowed.insert(allowed.end(), {"tool", "solver"});
      for (const field_doc& f : tool_spec<T>::fields) allowed.push_back(f.name);
      spec.only_members(allowed, " for a channel of tool \"" + std::string(T::name) + "\"");
    }
    spec.member(key).fail("a field of tool " + owners + ", not of tool \"" + std::string(T::name) +
                          "\" (this spec's \"tool\"), which would ignore it");
  }
}

}  // namespace detail

/// The model of a "channel" spec under its tool (see the header), type-erased.
template <class Real>
channel_model<Real> channel_model_of_spec(const field& spec) {
  const field tool = spec.member("tool", "a channel names the tool whose rules evaluate it");
  const std::string name = tool.string();
  std::optional<channel_model<Real>> out;
  const bool known = visit_tool(name, [&](auto t) {
    using T = typename decltype(t)::type;
    detail::check_tool_fields<T>(spec, all_tools{});
    // The model's own refusals (keys out of order, a backwards handle) name the spec's file too.
    const auto m = [&] {
      try {
        return tool_spec<T>::template parse<Real>(spec);
      } catch (const spec_error&) {
        throw;
      } catch (const invalid_input& x) {
        spec.fail(x.what());
      }
    }();
    channel_model<Real> cm;
    cm.at = [m](const Real& x, int order) { return m.derivative(x, order); };
    if constexpr (requires { m.view_refusal(); }) {  // a model that may lack a view (usd, css)
      if (const auto& why = m.view_refusal()) {
        cm.no_view = spec.path + ": " + *why;
        cm.key_times = m.key_times();
        out = std::move(cm);
        return;
      }
    }
    cm.view = m.view();
    for (const auto& k : cm.view->keys()) cm.key_times.push_back(k.time);
    // One key: a constant value, and a curve view with no segment (its one breakpoint made `sample
    // --count` fail with "breakpoints: 1 given", `length --method richardson` divide by zero, and
    // `check --lengths` divide by L = 0). Refused as the other models without a view are.
    if (cm.key_times.size() < 2) {
      cm.no_view = spec.path + ": one key: the channel is the constant " + to_text(cm.at(cm.key_times.front(), 0)) +
                   " and has no curve view (no segment between keys; sample --at and check --values evaluate it)";
      cm.view.reset();
    }
    out = std::move(cm);
  });
  if (!known) {
    std::string list;
    for (std::string_view n : all_tool_names) list += (list.empty() ? "" : ", ") + std::string(n);
    tool.fail(field::shown_string(name) + " is not one of: " + list);
  }
  return std::move(*out);
}

/// The channel a "channel" spec describes, under its tool's rules, in Real (see the header).
template <class Real>
channel::channel<Real> channel_of_spec(const field& spec) {
  return channel_model_of_spec<Real>(spec).source();
}

namespace detail {

// The channel family's field docs, assembled at compile time from the tools' (see the header):
// "tool" (the tools' names), then each field name in the order the tools first give it, its doc
// "tool: doc" per tool that has it, joined by "; ", then "solver".
struct tool_field {
  std::string_view tool, name, doc;
};

template <class... Tools>
constexpr auto collect_tool_fields(channel::tool_list<Tools...>) {
  constexpr std::size_t n = (std::size(tool_spec<Tools>::fields) + ... + std::size_t(0));
  std::array<tool_field, n> out{};
  std::size_t i = 0;
  const auto add = [&](std::string_view tool, std::span<const field_doc> fields) {
    for (const field_doc& f : fields) out[i++] = {tool, f.name, f.doc};
  };
  (add(Tools::name, tool_spec<Tools>::fields), ...);
  return out;
}

// Writes the docs into `out`, or only measures them when out is null.
struct doc_writer {
  char* out = nullptr;
  std::size_t size = 0;
  constexpr void put(std::string_view s) {
    for (char c : s) {
      if (out) out[size] = c;
      ++size;
    }
  }
};

template <std::size_t N>
constexpr bool first_of_name(const std::array<tool_field, N>& f, std::size_t i) {
  for (std::size_t j = 0; j < i; ++j)
    if (f[j].name == f[i].name) return false;
  return true;
}

template <std::size_t N>
constexpr std::size_t distinct_names(const std::array<tool_field, N>& f) {
  std::size_t k = 0;
  for (std::size_t i = 0; i < N; ++i) k += first_of_name(f, i) ? 1 : 0;
  return k;
}

// The docs one after another: the tool list, then one per distinct field name; ends[k] (when
// given) is the end of doc k.
template <std::size_t N, std::size_t K>
constexpr void write_docs(doc_writer& w, const std::array<tool_field, N>& f, std::span<const std::string_view> tools,
                          std::array<std::size_t, K>* ends) {
  std::size_t k = 0;
  w.put("whose rules evaluate the keys: ");
  for (std::size_t i = 0; i < tools.size(); ++i) {
    if (i > 0) w.put(i + 1 == tools.size() ? " or " : ", ");
    w.put(tools[i]);
  }
  if (ends) (*ends)[k] = w.size;
  ++k;
  for (std::size_t i = 0; i < N; ++i) {
    if (!first_of_name(f, i)) continue;
    bool first = true;
    for (std::size_t j = i; j < N; ++j) {
      if (f[j].name != f[i].name) continue;
      if (!first) w.put("; ");
      first = false;
      w.put(f[j].tool);
      w.put(": ");
      w.put(f[j].doc);
    }
    if (ends) (*ends)[k] = w.size;
    ++k;
  }
}

inline constexpr auto channel_tool_fields = collect_tool_fields(all_tools{});
inline constexpr std::size_t channel_doc_count = 1 + distinct_names(channel_tool_fields);
inline constexpr std::size_t channel_doc_size = [] {
  doc_writer w;
  write_docs<channel_tool_fields.size(), channel_doc_count>(w, channel_tool_fields, all_tool_names, nullptr);
  return w.size;
}();
inline constexpr std::array<char, channel_doc_size> channel_doc_text = [] {
  std::array<char, channel_doc_size> text{};
  doc_writer w{text.data()};
  write_docs<channel_tool_fields.size(), channel_doc_count>(w, channel_tool_fields, all_tool_names, nullptr);
  return text;
}();
inline constexpr std::array<field_doc, channel_doc_count + 1> channel_fields = [] {
  std::array<std::size_t, channel_doc_count> ends{};
  doc_writer w;
  write_docs<channel_tool_fields.size(), channel_doc_count>(w, channel_tool_fields, all_tool_names, &ends);
  std::array<field_doc, channel_doc_count + 1> out{};
  const auto doc = [&](std::size_t k) {
    const std::size_t begin = k == 0 ? 0 : ends[k - 1];
    return std::string_view(channel_doc_text.data() + begin, ends[k] - begin);
  };
  out[0] = {"tool", doc(0), presence::required};
  std::size_t k = 1;
  for (std::size_t i = 0; i < channel_tool_fields.size(); ++i)
    if (first_of_name(channel_tool_fields, i)) {
      out[k] = {channel_tool_fields[i].name, doc(k)};
      ++k;
    }
  out[k] = {"solver",
            "the time solver of bezier segments (closed_form, table_newton, newton_bisection, bisection12, "
            "bisection30, isolate_brent, curvebench, exact)"};
  return out;
}();

template <class... Tools>
constexpr std::array<std::string_view, sizeof...(Tools)> tool_examples(channel::tool_list<Tools...>) {
  return {tool_spec<Tools>::example...};
}

}  // namespace detail

struct channel_family : family_defaults {
  static constexpr std::string_view name = "channel";
  static constexpr std::string_view summary =
      "a keyframe channel (value over time) under one tool's rules, as the planar curve (t(u), v(u))";
  static constexpr auto fields = detail::channel_fields;
  static constexpr auto examples = detail::tool_examples(all_tools{});

  // 2, or the tool's own dimension rule (a glTF rotation is 4D).
  static int dimension(const field& spec) {
    int dim = 2;
    if (spec.has("tool"))
      visit_tool(spec.member("tool").string(), [&](auto t) {
        using S = tool_spec<typename decltype(t)::type>;
        if constexpr (requires { S::dimension(spec); }) dim = S::dimension(spec);
      });
    return dim;
  }

  template <class Real, int Dim>
  static any_curve<Real, Dim> build(const field& spec) {
    if (spec.has("tool"))
      visit_tool(spec.member("tool").string(), [&](auto t) {
        using S = tool_spec<typename decltype(t)::type>;
        if constexpr (requires { S::check_curve_view(spec, Dim); }) S::check_curve_view(spec, Dim);
      });
    if constexpr (Dim == 2) {
      return any_curve<Real, 2>(channel_of_spec<Real>(spec).curve(), std::string(name));
    } else {
      spec.fail("a channel is the planar curve (t(u), v(u)), 2D; a " + std::to_string(Dim) + "D curve was asked for");
    }
  }
};

}  // namespace curvebench::io
