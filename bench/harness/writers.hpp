// The accuracy runner's output files: the results JSON and the records CSV beside it.
#pragma once

#include <nlohmann/json.hpp>

#include <string>
#include <string_view>

namespace curvebench::harness {

/// Refuses (invalid_input naming option and path) a path that exists and is not a regular file: a
/// directory, a symbolic link, a FIFO, a device (as root, /dev/null or /dev/full would otherwise be
/// replaced by a regular file), a socket. A new path or a regular file passes.
void check_output_path(const std::string& path, std::string_view option = "--out");

/// Writes text to path through a new temporary file beside it (created exclusively, never through a
/// link), renamed over it: readers never see half a file, and only a regular file or a new path is
/// ever replaced (check_output_path, before writing and again before the rename). Throws
/// invalid_input naming option and path when it cannot be written.
void write_atomic(const std::string& path, const std::string& text, std::string_view option = "--out");

/// The records as CSV: case,group,quantity,method,setting,error,estimate,bounded,evaluations,status
/// (null cells empty; settings hold commas, so the setting cell is quoted when it has one).
std::string records_csv(const nlohmann::json& records);

/// The path of the CSV beside a results JSON: FILE.json -> FILE.csv, any other name + ".csv".
std::string csv_path(const std::string& json_path);
/// Where a run with a failed case writes its results: FILE.json -> FILE.partial.json beside it.
std::string partial_path(const std::string& json_path);

/// Checks before any work that write_results(…, path) can succeed: path and its CSV are each a
/// regular file or a new path (check_output_path), and a file can be created beside them (the directory is created as
/// write_results would). Throws invalid_input naming the option and the path; leaves no file behind.
void check_results_path(const std::string& path);

/// Writes the results JSON to path (creating its directory) and records_csv of its records to csv_path(path).
void write_results(const nlohmann::json& results, const std::string& path);

}  // namespace curvebench::harness
