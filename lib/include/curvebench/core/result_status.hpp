// How sure a numerical result is: the status every result of curvebench carries (arc-length
// quadrature, lengths and inversion in arclength/result.hpp, the time solvers of a keyframe
// segment in channel/time_solver.hpp).
//
// DESIGN.md: "Results of numerical methods carry what they cost and how sure they are." Iterative
// methods have caps and say when they hit them. The vocabulary:
//   converged       the method stopped by its own criterion: for the arc-length methods the error
//                   estimate is <= the requested tolerance (and, for the adaptive methods, the
//                   estimate is an upper bound on every test curve of the suite); for the time
//                   solvers the residual test or the full-precision stop of the scheme was met;
//   cap_hit         an iteration / interval / depth / table-size cap stopped the method first;
//                   the estimate (or the best iterate) is still reported and still meant as a bound;
//   rounding_limited the answer is dominated by the rounding floor of Real: the tolerance asked
//                   for is below what Real resolves; an estimate includes that floor;
//   not_guaranteed  the method has no error bound for this result (a fixed rule asked for no
//                   comparison, a table without a coarser table, a step that could not be checked,
//                   a closed form or a fixed number of bisections with no residual test); an error
//                   estimate is then +infinity, never a made-up number.
// Names: to_string gives the snake_case name ("converged", "cap_hit", "rounding_limited",
// "not_guaranteed"), the one written in records; result_status_from_string reads it back
// (invalid_input naming the text and the four names otherwise). worst orders the statuses by
// certainty. Cost: O(1), no allocation except the message of a failed from_string.
#pragma once

#include "curvebench/core/error.hpp"

#include <array>
#include <string>
#include <string_view>

namespace curvebench {

enum class result_status { converged, cap_hit, rounding_limited, not_guaranteed };

inline constexpr std::array<result_status, 4> all_result_statuses{
    result_status::converged, result_status::cap_hit, result_status::rounding_limited, result_status::not_guaranteed};

/// "converged", "cap_hit", "rounding_limited", "not_guaranteed".
[[nodiscard]] constexpr std::string_view to_string(result_status s) {
  switch (s) {
    case result_status::converged: return "converged";
    case result_status::cap_hit: return "cap_hit";
    case result_status::rounding_limited: return "rounding_limited";
    case result_status::not_guaranteed: return "not_guaranteed";
  }
  return "unknown";
}

/// The status named by its snake_case name (to_string's); invalid_input listing the names otherwise:
/// "result status = \"done\": unknown, expected one of converged, cap_hit, rounding_limited, not_guaranteed".
[[nodiscard]] inline result_status result_status_from_string(std::string_view name) {
  std::string names;
  for (result_status s : all_result_statuses) {
    if (name == to_string(s)) return s;
    if (!names.empty()) names += ", ";
    names += to_string(s);
  }
  validate::fail("result status = \"" + std::string(name) + "\": unknown, expected one of " + names);
}

/// The less certain of two statuses (converged < rounding_limited < cap_hit < not_guaranteed).
[[nodiscard]] constexpr result_status worst(result_status a, result_status b) {
  auto rank = [](result_status s) {
    switch (s) {
      case result_status::converged: return 0;
      case result_status::rounding_limited: return 1;
      case result_status::cap_hit: return 2;
      case result_status::not_guaranteed: return 3;
    }
    return 3;
  };
  return rank(a) >= rank(b) ? a : b;
}

}  // namespace curvebench
