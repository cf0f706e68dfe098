// docs/specs.md's generated spec section: the text between `<!-- families:begin -->` and
// `<!-- families:end -->` is io::families_markdown(). Shared by curvebench_docs (which rewrites
// it) and tests/test_registry.cpp (which checks it).
#pragma once

#include "curvebench/io/registry.hpp"

#include <string>
#include <string_view>
#include <utility>

namespace curvebench::docs {

inline constexpr std::string_view families_begin = "<!-- families:begin -->";
inline constexpr std::string_view families_end = "<!-- families:end -->";

/// The command that regenerates the section (printed by the test when it is stale).
inline constexpr std::string_view regenerate_command =
    "cmake --build build --target curvebench_docs && build/tests/curvebench_docs docs/specs.md";

/// Where the section's text starts and ends in `readme`; an invalid_input when a marker is missing.
inline std::pair<std::size_t, std::size_t> families_span(const std::string& readme) {
  const std::size_t b = readme.find(std::string(families_begin) + "\n");
  if (b == std::string::npos)
    throw invalid_input("docs/specs.md: the line " + std::string(families_begin) + " is missing");
  const std::size_t from = b + families_begin.size() + 1;
  const std::size_t to = readme.find(families_end, from);
  if (to == std::string::npos)
    throw invalid_input("docs/specs.md: " + std::string(families_end) + " is missing after " +
                        std::string(families_begin));
  return {from, to};
}

/// The section as docs/specs.md holds it.
inline std::string families_section(const std::string& readme) {
  const auto [from, to] = families_span(readme);
  return readme.substr(from, to - from);
}

/// docs/specs.md with the section replaced by io::families_markdown().
inline std::string with_families_section(const std::string& readme) {
  const auto [from, to] = families_span(readme);
  return readme.substr(0, from) + io::families_markdown() + readme.substr(to);
}

}  // namespace curvebench::docs
