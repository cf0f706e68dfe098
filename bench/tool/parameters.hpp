// The parameters a user lists on `curvebench sample`'s command line, read as the tool reads them:
//   parse_at("V1,V2,...")                          --at: finite numbers, none empty;
//   parse_range("A:B:STEP"), "A:B[:STEP]" with a default STEP (--frames: 1)
//                                                 --range, --frames: A, A + STEP, ... up to B, both
//                                                 inclusive (B when it lies on the grid within
//                                                 1e-9 steps), STEP > 0, B >= A; plain decimals
//                                                 give the grid's exact decimal values (steps of 0.1
//                                                 give 0.3, not 0.30000000000000004).
// At most max_sample_values parameters; every refusal is an invalid_input naming the option, the
// item and its text (cut to 80 characters). The fuzz target `times` (tests/fuzz) reads its
// inputs through these functions too.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace curvebench::tool {

/// The most samples --count asks for and parameters --at, --at-file and --range may give.
inline constexpr std::size_t max_sample_values = 1000000;

/// One parameter with the words an error about it needs ("--at: item 3").
struct parameter {
  double u;
  std::string where;
};

/// text cut at every `sep` (n separators give n + 1 pieces, empty ones included).
[[nodiscard]] std::vector<std::string> split(const std::string& text, char sep);

/// invalid_input when n exceeds max_sample_values, naming the option.
void check_count(std::size_t n, const std::string& option);

/// --at's list (see the header).
[[nodiscard]] std::vector<parameter> parse_at(const std::string& text);

/// --range's A:B:STEP, or with default_step A:B[:STEP] under the name `option` (see the header).
[[nodiscard]] std::vector<parameter> parse_range(const std::string& text, const std::string& option = "--range",
                                                 std::optional<double> default_step = std::nullopt);

}  // namespace curvebench::tool
