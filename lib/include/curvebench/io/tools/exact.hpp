// The spec of tool "exact" (channel/tools/exact.hpp): keys with per-side handles and the
// interpolation of each segment, extrapolation before and after, and the time solver (default
// exact: the inversion solved to the precision of the evaluation). Keys in a spec:
//   {"time": 0, "value": 1, "interpolation": "bezier", "in": [-0.5, 0], "out": [0.5, 0.2]}
// with in/out the handle offsets (dt, dv) from the key (default [0, 0]), interpolation one of
// constant, step_next, linear, bezier, hermite (default bezier; the last key's is unused).
// Generated keys, so that a channel of 1e5 keys stays a few lines of JSON:
//   {"generate": "wave", "count": n, "start": t0, "step": h}
// n keys at t0 + i h (defaults 0 and 1) with values sin(0.37 i) + sin(1.91 i) / 2 (a bounded,
// never periodic wiggle), bezier segments whose handles follow the Catmull-Rom slope
// (v_{i+1} - v_{i-1}) / 2h (one-sided at the ends) with time lengths 0.25 h and 0.45 h alternating
// per key (a + c <= 0.9: every segment monotone in time). Computed in double and converted exactly
// to Real, so every precision sees the same keys.
#pragma once

#include "curvebench/channel/tools/exact.hpp"
#include "curvebench/io/family.hpp"
#include "curvebench/io/tools/common.hpp"

#include <cmath>
#include <string>
#include <string_view>
#include <vector>

namespace curvebench::io {

namespace detail {

inline nlohmann::json generate_keys(const field& g) {
  static constexpr std::string_view fields[] = {"generate", "count", "start", "step"};
  g.only_members(fields, " in a key generator");
  (void)g.member("generate").one_of({"wave"});
  const long long count = g.member("count").integer();
  if (count < 2 || count > static_cast<long long>(max_generated_points))
    g.member("count").fail(std::to_string(count) + " is not allowed (2 to " + std::to_string(max_generated_points) +
                           " keys)");
  const double t0 = g.has("start") ? g.member("start").number() : 0, h = g.has("step") ? g.member("step").number() : 1;
  if (!std::isfinite(t0)) g.member("start").fail("must be finite");
  if (!(h > 0) || !std::isfinite(h)) g.member("step").fail("must be finite and > 0");
  const auto n = static_cast<std::size_t>(count);
  std::vector<double> v(n);
  for (std::size_t i = 0; i < n; ++i)
    v[i] = std::sin(0.37 * static_cast<double>(i)) + std::sin(1.91 * static_cast<double>(i)) / 2;
  nlohmann::json keys = nlohmann::json::array();
  // The keys are the generator's, not the user's: what goes wrong with them is said of the
  // generator's fields (a time past double's range, times too close to tell apart, a slope that
  // overflows), not of keys[i] the user never wrote.
  const std::string given = "start " + to_text(t0) + ", step " + to_text(h) + ", count " + std::to_string(count);
  double previous = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const double m = i == 0 ? (v[1] - v[0]) / h : i + 1 == n ? (v[i] - v[i - 1]) / h : (v[i + 1] - v[i - 1]) / (2 * h);
    const double a = (i % 2 == 0 ? 0.25 : 0.45) * h, c = (i % 2 == 0 ? 0.45 : 0.25) * h;
    const double t = t0 + static_cast<double>(i) * h;
    if (!std::isfinite(t))
      g.fail("generated key " + std::to_string(i) + "'s time start + " + std::to_string(i) +
             " x step is past double's range (" + given + ")");
    if (i > 0 && !(t > previous))
      g.member("step").fail("generated keys " + std::to_string(i - 1) + " and " + std::to_string(i) +
                            " share the time " + to_text(t) + ": the step is below the spacing of doubles there (" +
                            given + ")");
    if (!std::isfinite(a * m) || !std::isfinite(c * m))
      g.member("step").fail("generated key " + std::to_string(i) + "'s slope overflows double (" + given + ")");
    previous = t;
    keys.push_back(
        {{"time", t}, {"value", v[i]}, {"interpolation", "bezier"}, {"in", {-c, -c * m}}, {"out", {a, a * m}}});
  }
  return keys;
}

template <class Real>
std::vector<channel::key<Real>> channel_keys(const field& spec) {
  const field given = spec.member("keys", "tool \"exact\" takes keys");
  const nlohmann::json generated = given.value.is_object() ? generate_keys(given) : nlohmann::json();
  const field keys = given.value.is_object() ? field{generated, given.path} : given;
  const std::size_t n = keys.array_size();
  std::vector<channel::key<Real>> out;
  out.reserve(n);
  for (std::size_t i = 0; i < n; ++i) {
    const field k = keys.element(i);
    static constexpr std::string_view key_fields[] = {"time", "value", "interpolation", "in", "out"};
    k.only_members(key_fields, " in a channel key");
    channel::key<Real> key;
    key.time = k.member("time").number_as<Real>();
    key.value = k.member("value").number_as<Real>();
    key.in = handle_of<Real>(k, "in");
    key.out = handle_of<Real>(k, "out");
    key.interp = k.has("interpolation")
                     ? channel::from_string<channel::interpolation>(
                           k.member("interpolation").one_of({"constant", "step_next", "linear", "bezier", "hermite"}))
                     : channel::interpolation::bezier;
    out.push_back(key);
  }
  return out;
}

}  // namespace detail

template <>
struct tool_spec<channel::tools::exact> {
  static constexpr field_doc fields[] = {
      {"keys",
       "[{time, value, interpolation, in: [dt, dv], out: [dt, dv]}, ...] in time order, or "
       "{generate: wave, count, start, step} (generated bezier keys)"},
      {"before", "extrapolation before the first key: constant, linear, cycle, cycle_offset, oscillate"},
      {"after", "extrapolation after the last key (the same names)"},
  };
  static constexpr std::string_view example =
      R"({"type": "channel", "tool": "exact", "keys": [{"time": 0, "value": 0, "out": [0.5, 0]}, {"time": 2, "value": 1, "in": [-0.5, 0.4]}], "after": "cycle_offset"})";

  template <class Real>
  static channel::tools::exact::model<Real> parse(const field& spec) {
    return channel::tools::exact::model<Real>(channel::channel<Real>(
        detail::channel_keys<Real>(spec), detail::extrapolation_of(spec, "before"),
        detail::extrapolation_of(spec, "after"), detail::solver_of(spec, channel::tools::exact::default_solver)));
  }
};

}  // namespace curvebench::io
