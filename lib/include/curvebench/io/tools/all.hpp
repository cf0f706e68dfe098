// Every animation tool, in one list: all_tools. Each entry is a channel tool
// (channel/tools/<tool>.hpp: its name, storage precision, model and construction from keys) with
// its spec parser (io/tools/<tool>.hpp: tool_spec<Tool>, its fields and their docs). The spec
// parser (the "tool" of a channel spec and its dispatch, io/families/channel.hpp), `curvebench
// list`, the vocabulary, the channel sweep and bench_channel all iterate it.
//
// Adding a tool: channel/tools/<tool>.hpp, io/tools/<tool>.hpp, its #include below and its entry
// in all_tools (plus its test and its case).
#pragma once

#include "curvebench/channel/tool_model.hpp"
#include "curvebench/io/tools/blender.hpp"
#include "curvebench/io/tools/common.hpp"
#include "curvebench/io/tools/css.hpp"
#include "curvebench/io/tools/exact.hpp"
#include "curvebench/io/tools/gltf.hpp"
#include "curvebench/io/tools/maya.hpp"
#include "curvebench/io/tools/usd.hpp"

#include <concepts>
#include <string_view>
#include <type_traits>

namespace curvebench::io {

/// Every tool, in the order `curvebench list`, the docs and the report show them.
using all_tools = channel::tool_list<channel::tools::exact, channel::tools::css, channel::tools::gltf,
                                     channel::tools::maya, channel::tools::blender, channel::tools::usd>;

/// A tool with its spec parser.
template <class Tool>
concept parsable_tool = channel::tool<Tool> && requires(const field& spec) {
  { tool_spec<Tool>::fields[0] } -> std::convertible_to<field_doc>;
  { tool_spec<Tool>::example } -> std::convertible_to<std::string_view>;
  { tool_spec<Tool>::template parse<double>(spec) } -> std::same_as<typename Tool::template model<double>>;
};

namespace detail {
template <class... Tools>
constexpr bool all_parsable(channel::tool_list<Tools...>) {
  return (parsable_tool<Tools> && ...);
}
}  // namespace detail
static_assert(detail::all_parsable(all_tools{}), "every tool of all_tools has a tool_spec (io/tools/<tool>.hpp)");

/// The tools' names, in the order of all_tools.
inline constexpr auto all_tool_names = channel::tool_names(all_tools{});

/// Calls f(std::type_identity<Tool>{}) for every tool of all_tools, in order.
template <class F>
void for_each_tool(F&& f) {
  channel::for_each_tool(all_tools{}, f);
}

/// Calls f(std::type_identity<Tool>{}) for the tool named `name`; false when there is none.
template <class F>
bool visit_tool(std::string_view name, F&& f) {
  bool found = false;
  for_each_tool([&](auto t) {
    if (!found && decltype(t)::type::name == name) {
      found = true;
      f(t);
    }
  });
  return found;
}

}  // namespace curvebench::io
