// One interface for every animation tool's model of a keyframe channel (channel/tools/<tool>.hpp).
//
// A tool model (concept tool_model) is what one tool evaluates for a channel, in one Real:
//   value(t), derivative(t, order)  the value and its time derivatives, orders 0 to 2, at any
//                                   finite t under the tool's rules (extrapolation included);
//   view()                          the channel<Real> whose curve() is the channel's planar curve
//                                   (t(u), v(u)) over the keys as the tool holds them (an eased
//                                   Blender segment appears there as its chord);
//   name                            the tool's one name ("maya", "blender", ...): the spec's
//                                   "tool", the benchmark's algorithm, the vocabulary's and the
//                                   report's id;
//   storage_bits                    the precision the tool itself stores and evaluates in (32 for
//                                   Blender's float32, 64 for the others).
// A tool (concept tool) is the struct that names it and makes its models:
//   name, summary (one line), rules (what from_keys applies, for the report), verification (what
//   the model is verified against, recorded from the real tool, and what is not), storage_type (float
//   or double: storage_bits of its models), default_solver (the time solver of its bezier
//   segments), model<Real> (a tool_model), and from_keys<Real>(keys): the model of a channel's
//   generic keys (time, value, per-side handles, constant / linear / bezier segments) as the tool
//   would hold them, or invalid_input saying why the tool cannot hold them (the reason the channel
//   sweep reports as `skipped`).
// tool_list<T...> is a compile-time list of tools; io/tools/all.hpp holds the list of them all.
#pragma once

#include "curvebench/channel/channel.hpp"
#include "curvebench/channel/time_solver.hpp"
#include "curvebench/core/error.hpp"

#include <array>
#include <concepts>
#include <cstddef>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

namespace curvebench::channel {

template <class M>
concept tool_model = requires(const M& m, const typename M::real_type& t, int order) {
  { M::name } -> std::convertible_to<std::string_view>;
  { M::storage_bits } -> std::convertible_to<int>;
  { m.value(t) } -> std::same_as<typename M::real_type>;
  { m.derivative(t, order) } -> std::same_as<typename M::real_type>;
  { m.view() } -> std::same_as<const channel<typename M::real_type>&>;
};

template <class T>
concept tool = requires(std::span<const key<double>> keys) {
  { T::name } -> std::convertible_to<std::string_view>;
  { T::summary } -> std::convertible_to<std::string_view>;
  { T::rules } -> std::convertible_to<std::string_view>;
  { T::verification } -> std::convertible_to<std::string_view>;
  { T::default_solver } -> std::convertible_to<time_solver>;
  typename T::storage_type;
  { T::template from_keys<double>(keys) } -> std::same_as<typename T::template model<double>>;
  { T::template from_keys<float>(keys) } -> std::same_as<typename T::template model<float>>;
}
&&tool_model<typename T::template model<double>>&& tool_model<typename T::template model<float>>;

/// A compile-time list of tools.
template <tool... Tools>
struct tool_list {
  static constexpr std::size_t size = sizeof...(Tools);
};

/// Calls f(std::type_identity<Tool>{}) for every tool of the list, in order.
template <tool... Tools, class F>
void for_each_tool(tool_list<Tools...>, F&& f) {
  (f(std::type_identity<Tools>{}), ...);
}

/// The names of the list's tools, in order.
template <tool... Tools>
[[nodiscard]] constexpr std::array<std::string_view, sizeof...(Tools)> tool_names(tool_list<Tools...>) {
  return {std::string_view(Tools::name)...};
}

/// The bits of a storage type (float 32, double 64).
template <class Storage>
inline constexpr int storage_bits_of = static_cast<int>(sizeof(Storage) * 8);

namespace detail {

/// invalid_input naming the first key whose segment is neither constant, linear nor bezier (the
/// segments the tools' from_keys translate).
inline void require_constant_linear_bezier(std::span<const key<double>> keys) {
  for (std::size_t i = 0; i + 1 < keys.size(); ++i) {
    const auto p = keys[i].interp;
    if (p == interpolation::step_next || p == interpolation::hermite)
      validate::fail("keys[" + std::to_string(i) + "] is " + to_string(p));
  }
}

/// The keys converted to Real.
template <class Real>
[[nodiscard]] std::vector<key<Real>> keys_as(std::span<const key<double>> keys) {
  std::vector<key<Real>> out;
  out.reserve(keys.size());
  for (const auto& k : keys)
    out.push_back(
        {Real(k.time), Real(k.value), {Real(k.in.dt), Real(k.in.dv)}, {Real(k.out.dt), Real(k.out.dv)}, k.interp});
  return out;
}

/// A model that is its channel (the exact tool): the channel evaluates, the channel is the view.
template <class Tool, class Real>
class channel_tool_model {
 public:
  using real_type = Real;
  using tool_type = Tool;
  static constexpr std::string_view name = Tool::name;
  static constexpr int storage_bits = storage_bits_of<typename Tool::storage_type>;

  explicit channel_tool_model(channel<Real> c) : channel_(std::move(c)) {}

  [[nodiscard]] Real value(const Real& t) const { return channel_.value(t); }
  [[nodiscard]] Real derivative(const Real& t, int order) const { return channel_.derivative(t, order); }
  [[nodiscard]] const channel<Real>& view() const { return channel_; }

 private:
  channel<Real> channel_;
};

/// The curve view of a model that may have none (USD's dual values, CSS steps() past
/// css_max_step_keys): a model derives from it, builds the view or says why there is none, and
/// inherits view() and view_refusal(), which io::channel_model_of_spec asks before view().
template <class Real>
class optional_view {
 public:
  /// The curve view; invalid_input saying why when there is none (view_refusal).
  [[nodiscard]] const channel<Real>& view() const {
    if (!view_) validate::fail(*refusal_);
    return *view_;
  }
  /// Why the model has no curve view, or nothing. value() and derivative() do not need the view.
  [[nodiscard]] const std::optional<std::string>& view_refusal() const { return refusal_; }

 protected:
  optional_view() = default;
  /// The view of `keys` under `solver`, constant extrapolation on both sides.
  void build_view(std::vector<key<Real>> keys, time_solver solver) {
    view_.emplace(std::move(keys), extrapolation::constant, extrapolation::constant, solver);
  }
  void refuse_view(std::string why) { refusal_ = std::move(why); }
  [[nodiscard]] bool has_view() const { return view_.has_value(); }

 private:
  std::optional<channel<Real>> view_;
  std::optional<std::string> refusal_;
};

}  // namespace detail

}  // namespace curvebench::channel
