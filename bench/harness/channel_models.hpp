// The tools' models of the same keys: a channel's keys (time, value, per-side handles, constant /
// linear / bezier segments) imported into each tool of io::all_tools as that tool would hold them
// (channel/tools/<tool>.hpp: Tool::from_keys, in the tool's storage precision), so that the
// accuracy runner can measure where the tools disagree on the same keys (harness/sweep_channel.cpp)
// and the benchmarks can time each tool's evaluator on the same data (bench/bench_channel.cpp).
// Keyed range only: the extrapolation is each tool's default. The exact tool is the keys
// themselves, the reference the others are compared with, so it is not among the models.
// Keys a tool cannot hold (step_next or hermite segments, zero-length or vertical handles where
// the tool needs a direction, mixed interpolations for glTF, anything but one easing on [0, 1] for
// CSS) leave that tool out: `skipped` gets the tool's name and the reason (from_keys's
// invalid_input).
#pragma once

#include "curvebench/channel/channel.hpp"
#include "curvebench/channel/tool_model.hpp"
#include "curvebench/core/error.hpp"
#include "curvebench/io/tools/all.hpp"

#include <nlohmann/json.hpp>

#include <functional>
#include <span>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

namespace curvebench::harness {

using channel_evaluator = std::function<double(double)>;

/// One tool's model of the keys, evaluated in its storage precision at a double time.
struct keys_model {
  std::string_view name;
  std::string_view rules;  ///< what was applied, for the report
  int storage_bits = 64;
  channel_evaluator at;
};

/// The models of the tools of io::all_tools (but exact) that can hold `keys` (see the header); the
/// others are named in `skipped` with the reason.
inline std::vector<keys_model> tool_models(const std::vector<channel::key<double>>& keys, nlohmann::json& skipped) {
  std::vector<keys_model> out;
  io::for_each_tool([&](auto t) {
    using T = typename decltype(t)::type;
    if constexpr (!std::is_same_v<T, channel::tools::exact>) {
      using S = typename T::storage_type;
      try {
        const auto m = T::template from_keys<S>(std::span<const channel::key<double>>(keys));
        out.push_back({T::name, T::rules, channel::storage_bits_of<S>,
                       [m](double x) { return static_cast<double>(m.value(static_cast<S>(x))); }});
      } catch (const invalid_input& x) {
        skipped[std::string(T::name)] = x.what();
      }
    }
  });
  return out;
}

}  // namespace curvebench::harness
