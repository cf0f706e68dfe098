// The tool's shared helpers (tool/tool.hpp): files, the default directories, the version line.
#include "tool/tool.hpp"

#include "harness/csv.hpp"
#include "harness/files.hpp"

#include "curvebench_version.hpp"  // generated at build time by cmake/version_header.cmake

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <system_error>
#include <utility>

namespace curvebench::tool {

namespace fs = std::filesystem;

std::string read_file(const std::string& path) { return harness::read_input_file(path); }

nlohmann::json read_spec(const std::string& path) { return io::parse(read_file(path), path); }

std::string installed_data_dir() {
  std::error_code ec;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);  // Linux: the running binary
  if (ec) return {};
  const fs::path dir = (exe.parent_path() / ".." / "share" / "curvebench").lexically_normal();
  return fs::is_directory(dir, ec) ? dir.string() : std::string();
}

std::string default_cases_dir() {
  const std::string data = installed_data_dir();
  std::error_code ec;
  if (!data.empty() && fs::is_directory(fs::path(data) / "cases", ec)) return (fs::path(data) / "cases").string();
  return CURVEBENCH_CASES_DIR;
}

std::string default_thresholds() {
  const std::string local = "reports/thresholds.json";
  std::error_code ec;
  if (fs::is_regular_file(local, ec)) return local;
  const std::string data = installed_data_dir();
  if (!data.empty() && fs::is_regular_file(fs::path(data) / "thresholds.json", ec))
    return (fs::path(data) / "thresholds.json").string();
  return local;
}

std::string version_line() {
  return std::string("curvebench ") + CURVEBENCH_VERSION + " (" + CURVEBENCH_REVISION + ")";
}

CLI::Validator positive_finite() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        double v = 0;
        if (harness::parse_finite(text, v) && v > 0) return {};
        return harness::quote_cell(text) + " is not a finite number > 0";
      },
      "POSITIVE");
}

CLI::Validator non_negative_finite() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        double v = 0;
        if (harness::parse_finite(text, v) && v >= 0) return {};
        return harness::quote_cell(text) + " is not a finite number >= 0";
      },
      "NONNEGATIVE");
}

CLI::Validator non_empty() {
  return CLI::Validator(
      [](std::string& text) -> std::string { return text.empty() ? "an empty value (give at least one)" : ""; },
      "TEXT");
}

std::string non_finite_cause(std::span<const double> breakpoints, double largest_coordinate) {
  std::string why = "domain [" + to_text(breakpoints.front()) + ", " + to_text(breakpoints.back()) + "]";
  std::size_t narrow = 0;
  for (std::size_t i = 1; i + 1 < breakpoints.size(); ++i)
    if (breakpoints[i + 1] - breakpoints[i] < breakpoints[narrow + 1] - breakpoints[narrow]) narrow = i;
  if (breakpoints.size() > 2)
    why += ", narrowest segment [" + to_text(breakpoints[narrow]) + ", " + to_text(breakpoints[narrow + 1]) +
           "] (breakpoints " + std::to_string(narrow) + " and " + std::to_string(narrow + 1) + ")";
  if (std::isnan(largest_coordinate))
    why += ", a point at a breakpoint is not a number (its evaluation overflows double)";
  else
    why += ", largest |coordinate| at the breakpoints " + to_text(largest_coordinate);
  why +=
      ": coordinates, their differences or the derivatives (which grow like 1/h^k on a span of width h) "
      "exceed double's range of about 1.8e308";
  return why;
}

std::string example(const std::string& command) { return "\nExample:\n  " + command + "\n"; }

void say_verdict(const std::string& command, std::size_t count, const std::string& one, const std::string& many) {
  std::cerr << "curvebench: " << command << ": " << count << " " << (count == 1 ? one : many) << " (exit 1)\n";
}

progress::progress(std::string what, std::size_t total, bool quiet, bool planned)
    : what_(std::move(what)),
      total_(total),
      quiet_(quiet),
      planned_(planned),
      start_(std::chrono::steady_clock::now()),
      next_(start_ + std::chrono::seconds(1)) {}

void progress::update(std::size_t done) {
  if (quiet_) return;
  const auto now = std::chrono::steady_clock::now();
  if (now < next_) return;
  next_ = now + std::chrono::seconds(1);
  const double elapsed = std::chrono::duration<double>(now - start_).count();
  const double percent = total_ == 0 ? 100.0 : 100.0 * static_cast<double>(done) / static_cast<double>(total_);
  std::ostringstream line;
  if (planned_ && done > total_)
    line << what_ << ": " << done << ", past the " << total_ << " planned (speed minima split segments), " << std::fixed
         << std::setprecision(1) << elapsed << " s elapsed\n";
  else
    line << what_ << ": " << done << " of " << total_ << " (" << std::fixed << std::setprecision(1) << percent << "%), "
         << elapsed << " s elapsed\n";
  std::cerr << line.str() << std::flush;
}

}  // namespace curvebench::tool
