// Reading curve specs from JSON (nlohmann/json): typed field access whose errors name the field
// by its path and say what was expected, e.g.
//   "spec.points[2]: expected an array of 3 numbers, got [1,"a",3]"
//   "spec.weights: missing (required for type \"nurbs\")"
//   "spec.alpha = 2: must be in [0, 1]"
// Numbers are read as double (JSON's own precision) and converted exactly to Real; a 50-digit
// reference built from a spec therefore holds exactly the same control data as the double one.
// Unknown fields are rejected, so a typo ("tenson") never passes silently.
#pragma once

#include "curvebench/core/error.hpp"
#include "curvebench/core/point.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <initializer_list>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace curvebench::io {

using json = nlohmann::json;

/// A malformed spec. Derives from invalid_input, so the library's error policy covers it.
class spec_error : public invalid_input {
 public:
  using invalid_input::invalid_input;
};

/// A JSON value with its path from the root ("spec", "spec.points[2]", ...).
struct field {
  const json& value;
  std::string path;

  [[noreturn]] void fail(const std::string& what) const { throw spec_error(path + ": " + what); }

  /// A short rendering of the offending value for messages (cut at 60 characters).
  [[nodiscard]] std::string shown() const {
    std::string s = value.dump();
    if (s.size() > 60) s = s.substr(0, 57) + "...";
    return s;
  }

  [[nodiscard]] bool has(std::string_view key) const { return value.is_object() && value.contains(std::string(key)); }

  /// The member `key` of this object; a missing member fails with `why_required` in the message.
  [[nodiscard]] field member(std::string_view key, std::string_view why_required = {}) const {
    if (!value.is_object()) fail("expected an object, got " + shown());
    const auto it = value.find(std::string(key));
    if (it == value.end()) {
      std::string m = std::string(key) + " is missing";
      if (!why_required.empty()) m += " (" + std::string(why_required) + ")";
      fail(m);
    }
    return {*it, path + "." + std::string(key)};
  }

  /// Element i of this array.
  [[nodiscard]] field element(std::size_t i) const { return {value.at(i), path + "[" + std::to_string(i) + "]"}; }

  [[nodiscard]] std::size_t array_size() const {
    if (!value.is_array()) fail("expected an array, got " + shown());
    return value.size();
  }

  [[nodiscard]] double number() const {
    if (!value.is_number()) fail("expected a number, got " + shown());
    const double x = value.get<double>();
    if (!is_finite(x)) fail("expected a finite number, got " + shown());
    return x;
  }

  [[nodiscard]] long long integer() const {
    if (!value.is_number_integer()) fail("expected an integer, got " + shown());
    return value.get<long long>();
  }

  [[nodiscard]] bool boolean() const {
    if (!value.is_boolean()) fail("expected true or false, got " + shown());
    return value.get<bool>();
  }

  [[nodiscard]] std::string string() const {
    if (!value.is_string()) fail("expected a string, got " + shown());
    return value.get<std::string>();
  }

  /// A string that must be one of `allowed`.
  [[nodiscard]] std::string one_of(std::initializer_list<std::string_view> allowed) const {
    const std::string s = string();
    if (std::find(allowed.begin(), allowed.end(), s) != allowed.end()) return s;
    std::string list;
    for (auto a : allowed) list += (list.empty() ? "" : ", ") + std::string(a);
    fail("\"" + s + "\" is not one of: " + list);
  }

  /// Fails on any member not in `allowed` (catches misspelled options); `context` is added to the
  /// message after the field's name, e.g. ` for type "cardinal"`.
  void only_members(std::span<const std::string_view> allowed, std::string_view context = {}) const {
    if (!value.is_object()) fail("expected an object, got " + shown());
    for (const auto& [key, v] : value.items())
      if (std::find(allowed.begin(), allowed.end(), key) == allowed.end()) {
        std::string list;
        for (auto a : allowed) list += (list.empty() ? "" : ", ") + std::string(a);
        fail("unknown field \"" + key + "\"" + std::string(context) + " (allowed: " + list + ")");
      }
  }
  void only_members(std::initializer_list<std::string_view> allowed) const {
    only_members(std::span<const std::string_view>(allowed.begin(), allowed.size()));
  }

  /// An array of finite numbers converted to Real.
  template <class Real>
  [[nodiscard]] std::vector<Real> reals() const {
    std::vector<Real> out(array_size());
    for (std::size_t i = 0; i < out.size(); ++i) out[i] = Real(element(i).number());
    return out;
  }

  /// An array of points, each an array of exactly Dim finite numbers.
  template <class Real, int Dim>
  [[nodiscard]] point_list<Real, Dim> points() const {
    point_list<Real, Dim> out(array_size());
    for (std::size_t i = 0; i < out.size(); ++i) {
      const field p = element(i);
      if (!p.value.is_array() || p.value.size() != static_cast<std::size_t>(Dim))
        p.fail("expected an array of " + std::to_string(Dim) + " numbers, got " + p.shown());
      for (int d = 0; d < Dim; ++d) out[i][d] = Real(p.element(static_cast<std::size_t>(d)).number());
    }
    return out;
  }

  /// The dimension of a points array: the length of its first point (all must agree; 1..4).
  [[nodiscard]] int point_dimension() const {
    const std::size_t n = array_size();
    if (n == 0) fail("expected at least one point, got []");
    const field first = element(0);
    if (!first.value.is_array() || first.value.empty() || first.value.size() > static_cast<std::size_t>(max_dimension))
      first.fail("expected a point: an array of 1 to " + std::to_string(max_dimension) + " numbers, got " +
                 first.shown());
    return static_cast<int>(first.value.size());
  }
};

/// The root of a spec document.
[[nodiscard]] inline field root(const json& j, std::string name = "spec") { return {j, std::move(name)}; }

/// Parses JSON text; a syntax error becomes a spec_error naming the source and the position.
[[nodiscard]] inline json parse(std::string_view text, std::string_view source = "spec") {
  try {
    return json::parse(text);
  } catch (const json::exception& e) {  // syntax errors and out-of-range numbers alike
    throw spec_error(std::string(source) + ": not valid JSON: " + e.what());
  }
}

}  // namespace curvebench::io
