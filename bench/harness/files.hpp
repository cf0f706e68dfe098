// The tool's input files (specs, cases, results, thresholds, CSVs) read through one bounded reader
// (header-only: the fuzz targets and the per-case benchmark read cases without the harness library).
#pragma once

#include "curvebench/core/error.hpp"

#include <cerrno>
#include <cstddef>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <string_view>
#include <vector>

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
inline std::string read_input_file(const std::string& path, std::string_view prefix = "",
                                   std::size_t limit = max_input_bytes) {
  namespace fs = std::filesystem;
  const std::string who = std::string(prefix) + path;
  std::error_code ec;
  const fs::file_status st = fs::status(path, ec);  // through links: a link to a file is that file
  if (ec && ec != std::errc::no_such_file_or_directory)
    throw invalid_input(who + ": cannot be read (" + ec.message() + ")");
  if (fs::is_directory(st)) throw invalid_input(who + ": is a directory, not a file");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw invalid_input(who + ": cannot be read (" + std::strerror(errno) + ")");
  std::string text;
  std::vector<char> chunk(std::size_t(1) << 20);
  while (in) {
    in.read(chunk.data(), static_cast<std::streamsize>(chunk.size()));
    const auto got = static_cast<std::size_t>(in.gcount());
    if (text.size() + got > limit)
      throw invalid_input(who + ": larger than " + std::to_string(limit >> 20) + " MiB (" + std::to_string(limit) +
                          " bytes), the limit for this input; nothing past it was read");
    text.append(chunk.data(), got);
  }
  if (in.bad()) throw invalid_input(who + ": reading failed after " + std::to_string(text.size()) + " bytes");
  return text;
}

}  // namespace curvebench::harness
