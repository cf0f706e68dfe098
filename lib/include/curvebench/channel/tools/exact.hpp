// The "exact" tool: the keys as given (channel/channel.hpp), every segment type, the extrapolation
// asked for and any time solver (default exact: the inversion solved to the precision of the
// evaluation). It is the reference the other tools' models of the same keys are compared with.
// from_keys: always holds the keys (constant extrapolation on both sides).
#pragma once

#include "curvebench/channel/channel.hpp"
#include "curvebench/channel/tool_model.hpp"

#include <span>
#include <string_view>

namespace curvebench::channel::tools {

struct exact {
  static constexpr std::string_view name = "exact";
  static constexpr std::string_view summary =
      "the keys as given: per-side handles, each segment's interpolation, extrapolation, any time solver";
  static constexpr std::string_view rules = "the keys as given";
  /// What the model is verified against (recorded values of the real tool) and what is not.
  static constexpr std::string_view verification =
      "nothing to reproduce: the keys' own mathematical channel, the truth the other tools are measured "
      "against";
  using storage_type = double;
  static constexpr time_solver default_solver = time_solver::exact;

  template <class Real>
  using model = curvebench::channel::detail::channel_tool_model<exact, Real>;

  template <class Real>
  [[nodiscard]] static model<Real> from_keys(std::span<const key<double>> keys) {
    return model<Real>(channel<Real>(curvebench::channel::detail::keys_as<Real>(keys), extrapolation::constant,
                                     extrapolation::constant, default_solver));
  }
};

}  // namespace curvebench::channel::tools
