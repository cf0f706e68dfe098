// Reading curve specs from JSON (nlohmann/json): typed field access whose errors name the field
// by its path and say what was expected, e.g.
//   "spec.points[2]: expected an array of 3 numbers, got [1,"a",3]"
//   "spec.weights: missing (required for type \"nurbs\")"
//   "spec.alpha = 2: must be in [0, 1]"
// Numbers are read as double (JSON's own precision) and converted exactly to Real; a 50-digit
// reference built from a spec therefore holds exactly the same control data as the double one.
// Unknown fields are rejected, so a typo ("tenson") never passes silently.
//
// Hostile input: parse() rejects documents nested deeper than max_nesting_depth (64) levels and
// objects with a repeated key, before anything walks the value recursively; shown() echoes at
// most a bounded prefix of a value however large or deep it is.
#pragma once

#include "curvebench/core/error.hpp"
#include "curvebench/core/point.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <initializer_list>
#include <limits>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

namespace curvebench::io {

using json = nlohmann::json;

/// The deepest nesting of arrays and objects parse() accepts: the document's root array or object
/// is level 1. The deepest spec (a case file's items holding points) needs 4; 64 leaves room for
/// any future format while keeping every recursive walk of a parsed value (copies, dumps,
/// destruction) far from the stack's limit.
inline constexpr std::size_t max_nesting_depth = 64;

namespace detail {

/// Messages echo at most this many characters of a value.
inline constexpr std::size_t shown_limit = 60;

/// Appends the JSON text of the string `s` to `out` (invalid UTF-8 replaced), serialising only the
/// prefix that can still show: once `out` holds more than `limit` characters the rest is cut.
inline void render_string_prefix(std::string_view s, std::string& out, std::size_t limit) {
  const std::size_t room = limit + 1 - std::min(out.size(), limit + 1);
  out += json(std::string(s.substr(0, room))).dump(-1, ' ', false, json::error_handler_t::replace);
}

/// Appends compact JSON text of `v` to `out` until `out` holds more than `limit` characters. Each
/// level of nesting writes at least one character, so the recursion is at most limit + 1 deep
/// however deep `v` is, and no more than about `limit` characters of it are ever serialised.
inline void render_prefix(const json& v, std::string& out, std::size_t limit) {
  if (out.size() > limit) return;
  if (v.is_string()) {
    render_string_prefix(v.get_ref<const json::string_t&>(), out, limit);
  } else if (v.is_array()) {
    out += '[';
    for (std::size_t i = 0; i < v.size() && out.size() <= limit; ++i) {
      if (i > 0) out += ',';
      render_prefix(v[i], out, limit);
    }
    out += ']';
  } else if (v.is_object()) {
    out += '{';
    bool first = true;
    for (const auto& [key, member] : v.get_ref<const json::object_t&>()) {
      if (out.size() > limit) break;
      if (!first) out += ',';
      first = false;
      render_string_prefix(key, out, limit);
      out += ':';
      render_prefix(member, out, limit);
    }
    out += '}';
  } else if (v.is_binary()) {
    out += "<binary>";  // never produced by JSON text
  } else {
    out += v.dump();  // null, boolean, number: a few characters
  }
}

/// `text` cut to at most `limit` bytes with "..." (not inside a UTF-8 sequence).
inline std::string cut(std::string text, std::size_t limit) {
  if (text.size() <= limit) return text;
  text.resize(limit - 3);
  while (!text.empty() && (static_cast<unsigned char>(text.back()) & 0xC0U) == 0x80U) text.pop_back();
  if (!text.empty() && static_cast<unsigned char>(text.back()) >= 0xC0U) text.pop_back();
  return text + "...";
}

}  // namespace detail

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

  /// A short rendering of the offending value for messages (cut at 60 characters). Only a bounded
  /// prefix is ever serialised, so a 10 MB string or a deeply nested value costs no more than a
  /// small one (see detail::render_prefix).
  [[nodiscard]] std::string shown() const { return shown_value(value); }

  /// shown() for any JSON value.
  [[nodiscard]] static std::string shown_value(const json& v) {
    std::string out;
    detail::render_prefix(v, out, detail::shown_limit);
    return detail::cut(std::move(out), detail::shown_limit);
  }

  /// shown() for a string, e.g. an object key, quoted as JSON.
  [[nodiscard]] static std::string shown_string(std::string_view s) {
    std::string out;
    detail::render_string_prefix(s, out, detail::shown_limit);
    return detail::cut(std::move(out), detail::shown_limit);
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

  /// number() held in Real: a finite double past Real's range (1e300 in float) is an error naming
  /// the field and the value as written, never an infinity passed on.
  template <class Real>
  [[nodiscard]] Real number_as() const {
    const double x = number();
    const Real r = static_cast<Real>(x);
    if (!is_finite(r))
      fail(shown() + " is past " +
           (std::is_same_v<Real, float> ? "float's range (3.4e38)" : "the working precision's range") +
           ", in which this data is held");
    return r;
  }

  /// An integer in the range of long long. One written beyond it (nlohmann keeps 2^63 to 2^64-1 as
  /// unsigned) is an error quoting the digits written, never wrapped round to a negative value.
  [[nodiscard]] long long integer() const {
    if (!value.is_number_integer()) fail("expected an integer, got " + shown());
    if (value.is_number_unsigned() &&
        value.get<json::number_unsigned_t>() > static_cast<unsigned long long>(std::numeric_limits<long long>::max()))
      fail(shown() + " is too large (at most " + std::to_string(std::numeric_limits<long long>::max()) + ")");
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
    fail(shown_string(s) + " is not one of: " + list);
  }

  /// Fails on any member not in `allowed` (catches misspelled options); `context` is added to the
  /// message after the field's name, e.g. ` for type "cardinal"`.
  void only_members(std::span<const std::string_view> allowed, std::string_view context = {}) const {
    if (!value.is_object()) fail("expected an object, got " + shown());
    for (const auto& [key, v] : value.items())
      if (std::find(allowed.begin(), allowed.end(), key) == allowed.end()) {
        std::string list;
        for (auto a : allowed) list += (list.empty() ? "" : ", ") + std::string(a);
        fail("unknown field " + shown_string(key) + std::string(context) + " (allowed: " + list + ")");
      }
  }
  void only_members(std::initializer_list<std::string_view> allowed) const {
    only_members(std::span<const std::string_view>(allowed.begin(), allowed.size()));
  }

  /// An array of finite numbers converted to Real.
  template <class Real>
  [[nodiscard]] std::vector<Real> reals() const {
    std::vector<Real> out(array_size());
    for (std::size_t i = 0; i < out.size(); ++i) out[i] = element(i).number_as<Real>();
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
      for (int d = 0; d < Dim; ++d) out[i][d] = p.element(static_cast<std::size_t>(d)).number_as<Real>();
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

namespace detail {

/// nlohmann's SAX interface building the value the way json::parse does, but refusing, before the
/// value grows any deeper, nesting beyond max_nesting_depth, and refusing a key repeated in one
/// object (json::parse keeps the last, so {"type":"bezier","type":"polyline"} would silently
/// measure a polyline). Errors name the path from `source`, e.g. "case.json.items[3]".
class strict_builder {
 public:
  strict_builder(json& root, std::string_view source) : root_(root), source_(source) {}

  bool null() { return (void)put(nullptr), true; }
  bool boolean(bool b) { return (void)put(b), true; }
  bool number_integer(json::number_integer_t x) { return (void)put(x), true; }
  bool number_unsigned(json::number_unsigned_t x) { return (void)put(x), true; }
  bool number_float(json::number_float_t x, const json::string_t& /*text*/) { return (void)put(x), true; }
  bool string(json::string_t& s) { return (void)put(std::move(s)), true; }
  bool binary(json::binary_t& b) { return (void)put(json::binary(std::move(b))), true; }
  bool start_object(std::size_t /*elements*/) { return open(json::object()); }
  bool start_array(std::size_t /*elements*/) { return open(json::array()); }
  bool end_object() { return open_.pop_back(), true; }
  bool end_array() { return open_.pop_back(), true; }

  bool key(json::string_t& k) {
    frame& top = open_.back();
    if (top.value->contains(k))
      throw spec_error(path() + ": key " + field::shown_string(k) +
                       " appears twice in this object (JSON keeps only one of them)");
    top.key = std::move(k);
    return true;
  }

  bool parse_error(std::size_t /*position*/, const std::string& last_token, const json::exception& e) {
    // 406: a number beyond double's range (1e400); named by its path and as written, not as a
    // syntax error of the whole file.
    if (e.id == 406)
      throw spec_error(value_path() + ": the number " + cut(last_token, 40) +
                       " is beyond double's range (magnitudes up to about 1.8e308)");
    // e.what() holds the line, column and the last token read, which can be a whole 10 MB string,
    // after the library's tag ("[json.exception.parse_error.101] "), which is dropped; an invalid
    // byte of the text (0xff) is shown as U+FFFD and a control character escaped, as in every value
    // a message quotes.
    std::string what = e.what();
    if (const std::size_t close = what.find("] "); what.starts_with("[json.exception.") && close != std::string::npos)
      what.erase(0, close + 2);
    std::string shown = json(what).dump(-1, ' ', false, json::error_handler_t::replace);
    shown = shown.substr(1, shown.size() - 2);
    for (const auto& [escaped, plain] : {std::pair{"\\\"", "\""}, std::pair{"\\\\", "\\"}})  // \" and \\ as read
      for (std::size_t at = shown.find(escaped); at != std::string::npos; at = shown.find(escaped, at + 1))
        shown.replace(at, 2, plain);
    throw spec_error(std::string(source_) + ": not valid JSON: " + cut(std::move(shown), 300));
  }

 private:
  struct frame {
    json* value;      // an array or object being filled
    std::string key;  // for an object, the key of the member being read
  };

  /// Stores `v` where the text has reached and returns it. Pointers to open containers stay valid:
  /// a container only grows at its end while nothing in it is open.
  json* put(json v) {
    if (open_.empty()) {
      root_ = std::move(v);
      return &root_;
    }
    frame& top = open_.back();
    if (top.value->is_array()) {
      top.value->push_back(std::move(v));
      return &top.value->back();
    }
    auto& members = top.value->get_ref<json::object_t&>();
    return &members.insert_or_assign(top.key, std::move(v)).first->second;  // the key stays for path()
  }

  bool open(json container) {
    open_.push_back({put(std::move(container)), {}});
    if (open_.size() > max_nesting_depth)
      throw spec_error(path() + ": JSON nested more than " + std::to_string(max_nesting_depth) +
                       " levels deep (the limit; no spec needs more than a few)");
    return true;
  }

  /// The path of the value about to be stored: the innermost open container's path and the value's
  /// index or key in it.
  [[nodiscard]] std::string value_path() const {
    if (open_.empty()) return std::string(source_);
    const frame& top = open_.back();
    if (top.value->is_array()) return path() + "[" + std::to_string(top.value->size()) + "]";
    return path() + "." + cut(top.key, 40);
  }

  /// The path of the innermost open container.
  [[nodiscard]] std::string path() const {
    std::string p(source_);
    for (std::size_t i = 0; i + 1 < open_.size(); ++i) {
      const json& v = *open_[i].value;
      // Appended piece by piece (not `"[" + std::to_string(...)`, an insert at the front of a
      // temporary, where GCC 12 at -O3 warns a false -Wstringop-overflow in libstdc++'s _M_replace).
      if (v.is_array()) {
        p += '[';
        p += std::to_string(v.size() - 1);
        p += ']';
      } else {
        p += '.';
        p += cut(open_[i].key, 40);
      }
    }
    return p;
  }

  json& root_;
  std::string_view source_;
  std::vector<frame> open_;
};

}  // namespace detail

/// Parses JSON text. A syntax error becomes a spec_error naming the source and the position;
/// nesting deeper than max_nesting_depth and a key repeated in an object are errors naming the
/// path. The parser itself does not recurse, so no input overflows the stack here. A UTF-8 byte
/// order mark at the start is skipped (RFC 8259 lets a parser ignore it; editors on Windows write
/// one, and refusing it showed an invisible character in the message).
[[nodiscard]] inline json parse(std::string_view text, std::string_view source = "spec") {
  if (text.starts_with("\xEF\xBB\xBF")) text.remove_prefix(3);
  json result;
  detail::strict_builder builder(result, source);
  (void)json::sax_parse(text, &builder);  // strict: trailing text is an error too
  return result;
}

}  // namespace curvebench::io
