// CSS easing functions (CSS Easing Functions Level 1 and the linear() function of Level 2): the
// map from an input progress to an output progress that CSS transitions and animations apply.
// - cubic-bezier(x1, y1, x2, y2): the Bezier curve from (0, 0) to (1, 1) with handles (x1, y1) and
//   (x2, y2), x1 and x2 in [0, 1] (so time is monotone, see time_solver.hpp), y1 and y2 any
//   finite numbers. The output at x in (0, 1) is y(u) with x(u) = x solved by any time_solver
//   (curvebench's own by default). Outside [0, 1] the spec extends the curve by a tangent line:
//   below 0 through P0 and P1 if x1 > 0, else through P0 and P2 if x2 > 0, else the output is 0;
//   above 1 through P2 and P3 if x2 < 1, else through P1 and P3 if x1 < 1, else 1. (Chromium
//   differs where handles coincide with the ends, e.g. cubic-bezier(0, 0, 0, 0) below 0 gives -1
//   there and 0 here; w3c/csswg-drafts issue 4046 discusses it. This header follows the spec.)
// - steps(n, position): n >= 1 jumps placed by jump-start (alias start), jump-end (alias end, the
//   default), jump-none (n >= 2) or jump-both; the spec's algorithm (current step = floor(x n),
//   +1 for jump-start and jump-both, clamped to [0, jumps] for x in [0, 1], divided by jumps).
//   The spec's "before flag" (which makes a jump at x = 0 reached from the before phase of an
//   animation keep the step below) is not modelled: this is the plain function of x.
// - the keywords: linear (= linear(0, 1), the identity), ease = cubic-bezier(0.25, 0.1, 0.25, 1),
//   ease-in = (0.42, 0, 1, 1), ease-out = (0, 0, 0.58, 1), ease-in-out = (0.42, 0, 0.58, 1),
//   step-start = steps(1, jump-start), step-end = steps(1, jump-end).
// - linear(stops): two or more stops, each an output with zero, one or two input positions (a
//   percentage in CSS; a fraction here). The spec's rules: a stop's position is raised to the
//   largest position before it; a first stop without one is at 0, a last one at max(1, largest);
//   two positions make two points with the same output; runs of stops without a position are
//   spread evenly between their neighbours. The output is the linear interpolation between the
//   last point at or before x and the next one, and outside the points' span the line of the first
//   two (or last two) points extends it; where two points share an input the later one's output
//   is taken.
// parse_css_easing(text) reads any of these from its CSS text (keywords and function names are
// ASCII case-insensitive; whitespace around tokens; nothing may follow the easing).
// Errors: invalid_input naming the function, the argument index and value ("cubic-bezier argument
// 1 (x1) = 1.5: must be in [0, 1]"), and for text the offset and what was expected; an input
// progress that is not finite -> std::domain_error.
// Source: W3C, CSS Easing Functions Level 1 and Level 2 (docs/references.md).
// Cost: cubic-bezier one solve_time (about 4 cubic evaluations with the curvebench solver) plus
// one evaluation of y; steps O(1); linear() O(log points) (binary search). Parsing is linear in
// the text.
// Accuracy: cubic-bezier inherits the solver's (curvebench: within a few ulps of the output range
// [min(0, y1, y2), max(1, y1, y2)]); steps and linear() are exact up to one division and one
// multiply-add.
#pragma once

#include "curvebench/channel/detail/cubic_time.hpp"
#include "curvebench/channel/time_solver.hpp"
#include "curvebench/core/detail/segment_lookup.hpp"
#include "curvebench/core/error.hpp"
#include "curvebench/core/real.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstddef>
#include <limits>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

namespace curvebench::channel {

/// Where steps() puts its jumps.
enum class step_position { jump_start, jump_end, jump_none, jump_both };

[[nodiscard]] inline const char* to_string(step_position p) {
  switch (p) {
    case step_position::jump_start: return "jump-start";
    case step_position::jump_end: return "jump-end";
    case step_position::jump_none: return "jump-none";
    case step_position::jump_both: return "jump-both";
  }
  return "unknown";
}

/// A stop of linear(): an output and up to two input positions (fractions: 50% is 0.5).
template <class Real>
struct linear_stop {
  Real output;
  std::optional<Real> at;
  std::optional<Real> until;
};

/// A point of a linear() function after the spec's position rules.
template <class Real>
struct linear_point {
  Real input;
  Real output;
};

/// A CSS easing function: cubic-bezier(), steps() or linear(). Copyable value type.
template <class Real>
class css_easing {
 public:
  enum class kind { cubic_bezier, steps, linear };

  /// cubic-bezier(x1, y1, x2, y2) evaluated with `solver`.
  [[nodiscard]] static css_easing cubic_bezier(const Real& x1, const Real& y1, const Real& x2, const Real& y2,
                                               time_solver solver = time_solver::curvebench) {
    const auto arg = [](int index, const char* name, const Real& v, bool unit) {
      const std::string what = "cubic-bezier argument " + std::to_string(index) + " (" + name + ") = " + to_text(v);
      if (!is_finite(v)) validate::fail(what + ": must be finite");
      if (unit && !(Real(0) <= v && v <= Real(1))) validate::fail(what + ": must be in [0, 1] (time must not go back)");
    };
    arg(1, "x1", x1, true);
    arg(2, "y1", y1, false);
    arg(3, "x2", x2, true);
    arg(4, "y2", y2, false);
    css_easing e(kind::cubic_bezier);
    e.p_ = {x1, y1, x2, y2};
    e.solver_ = solver;
    return e;
  }

  /// The largest n of steps(n), 2^53.
  static constexpr long long max_steps = 1LL << 53;
  /// steps(n, position).
  [[nodiscard]] static css_easing steps(long long n, step_position position = step_position::jump_end) {
    if (n < 1) validate::fail("steps argument 1 (n) = " + std::to_string(n) + ": must be >= 1");
    // Above 2^53 the steps' times k / n are no longer distinct doubles (and n + 1 jumps overflow at
    // the largest long long).
    if (n > max_steps)
      validate::fail("steps argument 1 (n) = " + std::to_string(n) + ": at most 2^53 = " + std::to_string(max_steps) +
                     " (past it a double cannot tell the steps apart)");
    if (position == step_position::jump_none && n < 2)
      validate::fail("steps argument 1 (n) = " + std::to_string(n) + ": jump-none needs n >= 2");
    css_easing e(kind::steps);
    e.steps_ = n;
    e.position_ = position;
    return e;
  }

  /// linear(stops...) with the spec's rules for missing positions.
  [[nodiscard]] static css_easing linear(std::span<const linear_stop<Real>> stops) {
    validate::count_at_least("linear() stops", stops.size(), 2, "an output at two inputs at least");
    css_easing e(kind::linear);
    Real largest = -std::numeric_limits<Real>::infinity();
    std::vector<std::optional<Real>> inputs;
    for (std::size_t i = 0; i < stops.size(); ++i) {
      const linear_stop<Real>& s = stops[i];
      const std::string where = "linear argument " + std::to_string(i + 1);
      if (!is_finite(s.output)) validate::fail(where + " output = " + to_text(s.output) + ": must be finite");
      if (s.at && !is_finite(*s.at)) validate::fail(where + " first position = " + to_text(*s.at) + ": must be finite");
      if (s.until && !s.at) validate::fail(where + ": a second position needs a first");
      if (s.until && !is_finite(*s.until))
        validate::fail(where + " second position = " + to_text(*s.until) + ": must be finite");
      e.points_.push_back({Real(0), s.output});
      if (s.at) {
        largest = std::max(*s.at, largest);
        inputs.emplace_back(largest);
        if (s.until) {
          e.points_.push_back({Real(0), s.output});
          largest = std::max(*s.until, largest);
          inputs.emplace_back(largest);
        }
      } else if (i == 0) {
        largest = Real(0);
        inputs.emplace_back(Real(0));
      } else if (i + 1 == stops.size()) {
        largest = std::max(Real(1), largest);
        inputs.emplace_back(largest);
      } else {
        inputs.emplace_back(std::nullopt);
      }
    }
    // Runs without a position: evenly spaced between the known neighbours (the first and last
    // points always have one).
    for (std::size_t i = 0; i < inputs.size();) {
      if (inputs[i]) {
        e.points_[i].input = *inputs[i];
        ++i;
        continue;
      }
      std::size_t j = i;
      while (!inputs[j]) ++j;
      const Real a = *inputs[i - 1], b = *inputs[j];
      const Real count = Real(static_cast<long long>(j - i + 1));
      for (std::size_t k = i; k < j; ++k)
        e.points_[k].input = a + (b - a) * Real(static_cast<long long>(k - i + 1)) / count;
      i = j;
    }
    return e;
  }

  /// The `linear` keyword: linear(0, 1), the identity everywhere.
  [[nodiscard]] static css_easing identity() {
    const linear_stop<Real> stops[2] = {{Real(0), std::nullopt, std::nullopt}, {Real(1), std::nullopt, std::nullopt}};
    return linear(stops);
  }

  [[nodiscard]] kind type() const { return kind_; }
  [[nodiscard]] time_solver solver() const { return solver_; }
  /// cubic-bezier's (x1, y1, x2, y2).
  [[nodiscard]] const std::array<Real, 4>& control() const { return p_; }
  [[nodiscard]] long long step_count() const { return steps_; }
  [[nodiscard]] step_position position() const { return position_; }
  [[nodiscard]] std::span<const linear_point<Real>> points() const { return points_; }

  /// The output progress at input progress x (any finite x). Throws std::domain_error otherwise.
  [[nodiscard]] Real operator()(const Real& x) const {
    if (!is_finite(x)) throw std::domain_error("input progress = " + to_text(x) + ": must be finite");
    switch (kind_) {
      case kind::cubic_bezier: return bezier(x);
      case kind::steps: return stepped(x);
      case kind::linear: return piecewise(x);
    }
    throw std::domain_error("css_easing: unknown kind");
  }

 private:
  explicit css_easing(kind k) : kind_(k) {}

  Real bezier(const Real& x) const {
    const Real x1 = p_[0], y1 = p_[1], x2 = p_[2], y2 = p_[3];
    if (x < Real(0)) {
      if (x1 > Real(0)) return y1 / x1 * x;
      if (x2 > Real(0)) return y2 / x2 * x;
      return Real(0);
    }
    if (x > Real(1)) {
      if (x2 < Real(1)) return Real(1) + (Real(1) - y2) / (Real(1) - x2) * (x - Real(1));
      if (x1 < Real(1)) return Real(1) + (Real(1) - y1) / (Real(1) - x1) * (x - Real(1));
      return Real(1);
    }
    if (x == Real(0)) return Real(0);
    if (x == Real(1)) return Real(1);
    const Real u = solve_time(solver_, time_cubic<Real>{Real(0), x1, x2, Real(1)}, x).u;
    return detail::bernstein3(Real(0), y1, y2, Real(1), u);
  }

  Real stepped(const Real& x) const {
    using std::floor;
    const Real n = Real(steps_);
    Real current = floor(x * n);
    if (position_ == step_position::jump_start || position_ == step_position::jump_both) current += Real(1);
    if (x >= Real(0) && current < Real(0)) current = Real(0);
    const long long jumps = position_ == step_position::jump_both   ? steps_ + 1
                            : position_ == step_position::jump_none ? steps_ - 1
                                                                    : steps_;
    const Real j = Real(jumps);
    if (x <= Real(1) && current > j) current = j;
    return current / j;
  }

  Real piecewise(const Real& x) const {
    // The last point with input <= x (or the first), kept one before the end.
    std::size_t a =
        curvebench::detail::breakpoint_at_or_below(std::span<const linear_point<Real>>(points_), x,
                                                   [](const linear_point<Real>& p) -> const Real& { return p.input; });
    if (a == points_.size() - 1) --a;
    const linear_point<Real>& pa = points_[a];
    const linear_point<Real>& pb = points_[a + 1];
    if (pa.input == pb.input) return pb.output;
    return pa.output + (x - pa.input) / (pb.input - pa.input) * (pb.output - pa.output);
  }

  kind kind_;
  std::array<Real, 4> p_{};
  time_solver solver_ = time_solver::curvebench;
  long long steps_ = 1;
  step_position position_ = step_position::jump_end;
  std::vector<linear_point<Real>> points_;
};

/// The easing a CSS keyword names (linear, ease, ease-in, ease-out, ease-in-out, step-start,
/// step-end; ASCII case-insensitive), cubic-bezier ones evaluated with `solver`.
template <class Real>
[[nodiscard]] css_easing<Real> named_css_easing(std::string_view name, time_solver solver = time_solver::curvebench);

/// Parses a CSS <easing-function>: a keyword, cubic-bezier(...), steps(...) or linear(...).
template <class Real>
[[nodiscard]] css_easing<Real> parse_css_easing(std::string_view text, time_solver solver = time_solver::curvebench);

namespace detail {

inline bool iequal(std::string_view a, std::string_view b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i)
    if (std::tolower(static_cast<unsigned char>(a[i])) != std::tolower(static_cast<unsigned char>(b[i]))) return false;
  return true;
}

/// A strict reader of one CSS easing: tokens are identifiers, numbers (with an optional % after
/// them), '(' ')' ','; errors quote the text and the offset.
class css_reader {
 public:
  explicit css_reader(std::string_view text) : text_(text) {}

  [[noreturn]] void fail(const std::string& what) const {
    validate::fail("css easing \"" + validate::visible(text_) + "\": " + what + " at offset " + std::to_string(pos_));
  }
  void skip_space() {
    while (pos_ < text_.size() && (text_[pos_] == ' ' || text_[pos_] == '\t' || text_[pos_] == '\n' ||
                                   text_[pos_] == '\r' || text_[pos_] == '\f'))
      ++pos_;
  }
  bool at_end() {
    skip_space();
    return pos_ == text_.size();
  }
  std::string_view identifier() {
    skip_space();
    const std::size_t start = pos_;
    while (pos_ < text_.size() &&
           (std::isalnum(static_cast<unsigned char>(text_[pos_])) || text_[pos_] == '-' || text_[pos_] == '_'))
      ++pos_;
    return text_.substr(start, pos_ - start);
  }
  bool peek(char c) {
    skip_space();
    return pos_ < text_.size() && text_[pos_] == c;
  }
  void expect(char c, const std::string& context) {
    skip_space();
    if (pos_ < text_.size() && text_[pos_] == c) {
      ++pos_;
      return;
    }
    fail("expected '" + std::string(1, c) + "' " + context + ", got " + rest());
  }
  /// The text of a CSS <number> at the cursor (sign, digits, fraction, exponent), or empty.
  std::string_view number_token(bool* integer) {
    skip_space();
    const std::size_t start = pos_;
    std::size_t p = pos_;
    const auto digits = [&] {
      const std::size_t s = p;
      while (p < text_.size() && std::isdigit(static_cast<unsigned char>(text_[p]))) ++p;
      return p - s;
    };
    if (p < text_.size() && (text_[p] == '+' || text_[p] == '-')) ++p;
    const std::size_t whole = digits();
    std::size_t fraction = 0;
    bool has_point = false;
    if (p < text_.size() && text_[p] == '.') {
      ++p;
      has_point = true;
      fraction = digits();
      if (fraction == 0) return {};
    }
    if (whole == 0 && fraction == 0) return {};
    bool has_exponent = false;
    if (p < text_.size() && (text_[p] == 'e' || text_[p] == 'E')) {
      std::size_t q = p + 1;
      if (q < text_.size() && (text_[q] == '+' || text_[q] == '-')) ++q;
      if (q < text_.size() && std::isdigit(static_cast<unsigned char>(text_[q]))) {
        p = q;
        digits();
        has_exponent = true;
      }
    }
    if (integer) *integer = !has_point && !has_exponent;
    pos_ = p;
    return text_.substr(start, p - start);
  }
  /// What follows the cursor, for messages: 'abc' (up to 20 characters) or "the end".
  std::string rest() {
    skip_space();
    if (pos_ >= text_.size()) return "the end";
    std::size_t end = pos_;
    while (end < text_.size() && end - pos_ < 20 && text_[end] != ',' && text_[end] != ')') ++end;
    if (end == pos_) ++end;
    return "'" + validate::visible(text_.substr(pos_, end - pos_)) + "'";
  }
  bool percent() {
    if (pos_ < text_.size() && text_[pos_] == '%') {
      ++pos_;
      return true;
    }
    return false;
  }

 private:
  std::string_view text_;
  std::size_t pos_ = 0;
};

template <class Real>
Real parse_real(std::string_view token) {
  if constexpr (std::is_floating_point_v<Real>) {
    if (!token.empty() && token.front() == '+') token.remove_prefix(1);
    Real v{};
    const auto r = std::from_chars(token.data(), token.data() + token.size(), v);
    if (r.ec == std::errc::result_out_of_range)
      return token.front() == '-' ? -std::numeric_limits<Real>::infinity() : std::numeric_limits<Real>::infinity();
    return v;
  } else {
    return Real(std::string(token));
  }
}

template <class Real>
Real read_number(css_reader& in, const std::string& where) {
  bool integer = false;
  const std::string_view t = in.number_token(&integer);
  if (t.empty()) in.fail(where + ": expected a number, got " + in.rest());
  const Real v = parse_real<Real>(t);
  if (!is_finite(v)) in.fail(where + " = " + validate::visible(t) + ": not representable");
  return v;
}

}  // namespace detail

template <class Real>
css_easing<Real> named_css_easing(std::string_view name, time_solver solver) {
  using detail::iequal;
  const auto bez = [&](std::string_view x1, std::string_view y1, std::string_view x2, std::string_view y2) {
    // The keywords' constants are decimal fractions, read from their text so that each is the
    // nearest Real (0.1 in real50 is not double's 0.1).
    return css_easing<Real>::cubic_bezier(detail::parse_real<Real>(x1), detail::parse_real<Real>(y1),
                                          detail::parse_real<Real>(x2), detail::parse_real<Real>(y2), solver);
  };
  if (iequal(name, "linear")) return css_easing<Real>::identity();
  if (iequal(name, "ease")) return bez("0.25", "0.1", "0.25", "1");
  if (iequal(name, "ease-in")) return bez("0.42", "0", "1", "1");
  if (iequal(name, "ease-out")) return bez("0", "0", "0.58", "1");
  if (iequal(name, "ease-in-out")) return bez("0.42", "0", "0.58", "1");
  if (iequal(name, "step-start")) return css_easing<Real>::steps(1, step_position::jump_start);
  if (iequal(name, "step-end")) return css_easing<Real>::steps(1, step_position::jump_end);
  validate::fail("css easing keyword \"" + validate::visible(name) +
                 "\": unknown, expected linear, ease, ease-in, ease-out, ease-in-out, step-start or step-end");
}

template <class Real>
css_easing<Real> parse_css_easing(std::string_view text, time_solver solver) {
  using detail::iequal;
  detail::css_reader in(text);
  const std::string_view name = in.identifier();
  if (name.empty()) in.fail("expected an easing keyword or function, got " + in.rest());
  if (!in.peek('(')) {
    if (iequal(name, "cubic-bezier") || iequal(name, "steps"))
      in.fail(std::string(name) + " needs its arguments in parentheses");
    auto e = named_css_easing<Real>(name, solver);
    if (!in.at_end()) in.fail("unexpected text after the easing: " + in.rest());
    return e;
  }
  in.expect('(', "after " + std::string(name));
  std::optional<css_easing<Real>> result;
  if (iequal(name, "cubic-bezier")) {
    std::array<Real, 4> a{};
    for (int i = 0; i < 4; ++i) {
      if (i > 0) in.expect(',', "after cubic-bezier argument " + std::to_string(i));
      a[static_cast<std::size_t>(i)] = detail::read_number<Real>(in, "cubic-bezier argument " + std::to_string(i + 1));
    }
    in.expect(')', "after cubic-bezier's 4 arguments");
    result = css_easing<Real>::cubic_bezier(a[0], a[1], a[2], a[3], solver);
  } else if (iequal(name, "steps")) {
    bool integer = false;
    const std::string_view t = in.number_token(&integer);
    if (t.empty() || !integer)
      in.fail("steps argument 1: expected an integer, got " +
              (t.empty() ? in.rest() : "'" + validate::visible(t) + "'"));
    long long n = 0;
    std::string_view digits = t;
    if (digits.front() == '+') digits.remove_prefix(1);
    const auto r = std::from_chars(digits.data(), digits.data() + digits.size(), n);
    if (r.ec != std::errc()) in.fail("steps argument 1 = " + validate::visible(t) + ": out of range");
    step_position position = step_position::jump_end;
    if (in.peek(',')) {
      in.expect(',', "after steps argument 1");
      const std::string_view p = in.identifier();
      if (iequal(p, "jump-start") || iequal(p, "start"))
        position = step_position::jump_start;
      else if (iequal(p, "jump-end") || iequal(p, "end"))
        position = step_position::jump_end;
      else if (iequal(p, "jump-none"))
        position = step_position::jump_none;
      else if (iequal(p, "jump-both"))
        position = step_position::jump_both;
      else
        in.fail("steps argument 2: expected jump-start, jump-end, jump-none, jump-both, start or end, got " +
                (p.empty() ? in.rest() : "'" + validate::visible(p) + "'"));
    }
    in.expect(')', "after steps' arguments");
    result = css_easing<Real>::steps(n, position);
  } else if (iequal(name, "linear")) {
    std::vector<linear_stop<Real>> stops;
    do {
      if (!stops.empty()) in.expect(',', "between linear() stops");
      const std::string where = "linear argument " + std::to_string(stops.size() + 1);
      linear_stop<Real> s{detail::read_number<Real>(in, where), std::nullopt, std::nullopt};
      for (int k = 0; k < 2; ++k) {
        bool integer = false;
        const std::string_view t = in.number_token(&integer);
        if (t.empty()) break;
        if (!in.percent()) in.fail(where + ": a position must be a percentage, got '" + validate::visible(t) + "'");
        const Real v = detail::parse_real<Real>(t) / Real(100);
        if (!is_finite(v)) in.fail(where + " position " + validate::visible(t) + "%: not representable");
        (k == 0 ? s.at : s.until) = v;
      }
      stops.push_back(s);
    } while (in.peek(','));
    in.expect(')', "after linear() stops");
    result = css_easing<Real>::linear(stops);
  } else {
    in.fail("unknown easing function '" + validate::visible(name) + "', expected cubic-bezier, steps or linear");
  }
  if (!in.at_end()) in.fail("unexpected text after the easing: " + in.rest());
  return *result;
}

}  // namespace curvebench::channel
