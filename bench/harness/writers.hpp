// The accuracy runner's output files: the results JSON and the records CSV beside it.
#pragma once

#include <nlohmann/json.hpp>

#include <string>

namespace curvebench::harness {

/// Writes text to path through a temporary file renamed over it (readers never see half a file);
/// throws invalid_input naming the path when it cannot be written.
void write_atomic(const std::string& path, const std::string& text);

/// The records as CSV: case,group,quantity,method,setting,error,estimate,bounded,evaluations,status
/// (null cells empty; settings hold commas, so the setting cell is quoted when it has one).
std::string records_csv(const nlohmann::json& records);

/// The path of the CSV beside a results JSON: FILE.json -> FILE.csv, any other name + ".csv".
std::string csv_path(const std::string& json_path);

/// Checks before any work that write_results(…, path) can succeed: neither path nor its CSV is a
/// directory, and a file can be created beside them (the directory is created as write_results
/// would). Throws invalid_input naming the option and the path; leaves no file behind.
void check_results_path(const std::string& path);

/// Writes the results JSON to path (creating its directory) and records_csv of its records to csv_path(path).
void write_results(const nlohmann::json& results, const std::string& path);

}  // namespace curvebench::harness
