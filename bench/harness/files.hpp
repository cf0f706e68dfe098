// The tool's input files (specs, cases, results, thresholds, CSVs) read through one bounded reader.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

namespace curvebench::harness {

/// The largest spec, case, thresholds or CSV file read (64 MiB: a spec of about two million keys, a
/// CSV of about a million rows; `check` at 50 digits takes ~1 ms a row, so more would not finish).
inline constexpr std::size_t max_input_bytes = std::size_t(64) << 20;
/// The largest results file read (`gate --results`, merged runs): 256 MiB, about ten times a full
/// `accuracy` run's records.
inline constexpr std::size_t max_results_bytes = std::size_t(256) << 20;

/// The whole of a file, read in chunks and never more than limit bytes: a larger file (or an endless
/// one, /dev/zero) is refused with its size named; a directory or a path that cannot be opened is
/// refused too. Messages start with prefix + path ("thresholds x.json: ...", prefix "thresholds ").
/// Throws invalid_input.
std::string read_input_file(const std::string& path, std::string_view prefix = "", std::size_t limit = max_input_bytes);

}  // namespace curvebench::harness
