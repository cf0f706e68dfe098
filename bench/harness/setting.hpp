// A record's setting, "key=value[,key=value]" (vocabulary.hpp), formatted from a method of the
// vocabulary and its values: the keys are checked against the method's declared `settings`, so a
// record or a benchmark name cannot carry a key its method does not have.
#pragma once

#include "harness/vocabulary.hpp"

#include "curvebench/core/error.hpp"

#include <concepts>
#include <initializer_list>
#include <sstream>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace curvebench::harness {

/// A setting's number as it appears in records and benchmark names ("1e-06", "0.5", "256").
inline std::string fmt(double x) {
  std::ostringstream os;
  os << x;
  return os.str();
}

/// One key=value of a setting; integers print as integers, doubles through fmt.
struct setting_value {
  std::string_view key;
  std::string value;
  setting_value(std::string_view k, std::integral auto v) : key(k), value(std::to_string(v)) {}
  setting_value(std::string_view k, double v) : key(k), value(fmt(v)) {}
};

/// The setting of method m: every key of m.settings, each once, in the declared order; "" for a
/// method without settings. Throws invalid_input naming the method, the position and the key otherwise.
inline std::string setting(const vocab::method& m, std::initializer_list<setting_value> values) {
  std::string out;
  std::string_view expected = m.settings;  // the declared keys not yet given
  std::size_t index = 0;
  for (const setting_value& v : values) {
    const auto space = expected.find(' ');
    const std::string_view next = expected.substr(0, space);
    if (next.empty() || v.key != next)
      throw invalid_input("setting of method " + std::string(m.id) + ": key " + std::to_string(index) + " \"" +
                          std::string(v.key) + "\" is not " +
                          (next.empty() ? std::string("expected (all keys given)")
                                        : "the next declared key \"" + std::string(next) + "\"") +
                          " (declared: \"" + std::string(m.settings) + "\")");
    expected = space == std::string_view::npos ? std::string_view() : expected.substr(space + 1);
    if (!out.empty()) out += ',';
    out += std::string(v.key) + "=" + v.value;
    ++index;
  }
  if (!expected.empty())
    throw invalid_input("setting of method " + std::string(m.id) + ": key \"" +
                        std::string(expected.substr(0, expected.find(' '))) + "\" missing (declared: \"" +
                        std::string(m.settings) + "\")");
  return out;
}

/// The (key, value) pairs of a setting string; throws invalid_input on an item without '='.
inline std::vector<std::pair<std::string, std::string>> parse_setting(std::string_view s) {
  std::vector<std::pair<std::string, std::string>> out;
  if (s.empty()) return out;
  std::size_t index = 0;
  while (true) {
    const auto comma = s.find(',');
    const std::string_view item = s.substr(0, comma);
    const auto eq = item.find('=');
    if (eq == std::string_view::npos || eq == 0)
      throw invalid_input("setting item " + std::to_string(index) + " \"" + validate::visible(item) +
                          "\": not key=value");
    out.emplace_back(std::string(item.substr(0, eq)), std::string(item.substr(eq + 1)));
    if (comma == std::string_view::npos) break;
    s.remove_prefix(comma + 1);
    ++index;
  }
  return out;
}

}  // namespace curvebench::harness
