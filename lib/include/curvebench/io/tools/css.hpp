// The spec of tool "css" (channel/tools/css.hpp): one CSS easing function ("easing":
// "cubic-bezier(x1, y1, x2, y2)", "steps(n, jump-end)", "linear(0, 0.25 75%, 1)", or a keyword) on
// progress [0, 1], as the keys of channel::css_keys: cubic-bezier one bezier segment from (0, 0) to
// (1, 1); steps() constant segments whose values follow the specification's step algorithm (the
// model evaluates them in closed form, without keys, and has a curve view for n <= 2^16);
// linear() linear segments through the stops (a jump, two stops at one input, is refused). Time
// solver default table_newton (the WebKit / Chromium scheme). Outside [0, 1] the value holds
// (constant extrapolation).
#pragma once

#include "curvebench/channel/css_easing.hpp"
#include "curvebench/channel/tools/css.hpp"
#include "curvebench/io/family.hpp"
#include "curvebench/io/tools/common.hpp"

#include <string_view>

namespace curvebench::io {

template <>
struct tool_spec<channel::tools::css> {
  static constexpr field_doc fields[] = {
      {"easing",
       "cubic-bezier(x1, y1, x2, y2), steps(n, jump-start|jump-end|jump-none|jump-both) (n at most 2^53, "
       "evaluated in closed form; a curve view for n at most 2^16), linear(...) or a keyword"},
  };
  static constexpr std::string_view example =
      R"j({"type": "channel", "tool": "css", "easing": "cubic-bezier(0.25, 0.1, 0.25, 1)"})j";

  template <class Real>
  static channel::tools::css::model<Real> parse(const field& spec) {
    const field e = spec.member("easing", "tool \"css\" takes an easing");
    try {
      return channel::tools::css::of_easing<Real>(channel::parse_css_easing<double>(e.string()),
                                                  detail::solver_of(spec, channel::tools::css::default_solver));
    } catch (const spec_error&) {
      throw;
    } catch (const invalid_input& x) {
      e.fail(x.what());
    }
  }
};

}  // namespace curvebench::io
