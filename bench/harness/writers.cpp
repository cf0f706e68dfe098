#include "harness/writers.hpp"

#include "curvebench/core/error.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <iomanip>
#include <sstream>
#include <string_view>
#include <utility>

namespace curvebench::harness {

namespace fs = std::filesystem;

namespace {

// What a path is, in the words of the refusal ("a FIFO"), for anything but a regular file.
std::string kind_of(fs::file_type t) {
  switch (t) {
    case fs::file_type::directory: return "a directory";
    case fs::file_type::symlink: return "a symbolic link";
    case fs::file_type::block: return "a block device";
    case fs::file_type::character: return "a character device";
    case fs::file_type::fifo: return "a FIFO";
    case fs::file_type::socket: return "a socket";
    default: return "not a regular file";
  }
}

std::string directory_of(const std::string& path) {
  const fs::path parent = fs::path(path).parent_path();
  return parent.empty() ? std::string(".") : parent.string();
}

// A new file beside path, created exclusively (O_EXCL: never an existing name, never through a
// link): its descriptor and name. Throws invalid_input naming option and path.
std::pair<int, std::string> create_temporary(const std::string& path, std::string_view option) {
  std::string name = path + ".tmp.XXXXXX";
  const int fd = ::mkstemp(name.data());
  if (fd < 0)
    throw invalid_input(std::string(option) + " " + path + ": cannot be written (no file can be created in " +
                        directory_of(path) + ": " + std::strerror(errno) + ")");
  return {fd, name};
}

}  // namespace

void check_output_path(const std::string& path, std::string_view option) {
  if (path.empty()) throw invalid_input(std::string(option) + ": an empty path");
  std::error_code ec;
  const fs::file_status st = fs::symlink_status(path, ec);
  if (ec && ec != std::errc::no_such_file_or_directory)
    throw invalid_input(std::string(option) + " " + path + ": cannot be inspected (" + ec.message() + ")");
  if (fs::exists(st) && !fs::is_regular_file(st))
    throw invalid_input(std::string(option) + " " + path + ": is " + kind_of(st.type()) +
                        "; results are written only to a regular file or a new path");
}

void write_atomic(const std::string& path, const std::string& text, std::string_view option) {
  check_output_path(path, option);
  auto [fd, tmp] = create_temporary(path, option);
  const char* p = text.data();
  std::size_t left = text.size();
  int failure = 0;
  while (left > 0) {
    const ssize_t n = ::write(fd, p, left);
    if (n < 0) {
      if (errno == EINTR) continue;
      failure = errno;
      break;
    }
    p += n;
    left -= static_cast<std::size_t>(n);
  }
  if (::close(fd) != 0 && failure == 0) failure = errno;
  std::error_code ec;
  if (failure != 0) {
    fs::remove(tmp, ec);
    throw invalid_input(std::string(option) + " " + path + ": writing failed (" + std::strerror(failure) + ")");
  }
  // mkstemp creates 0600; a result file gets what the user's umask gives a new file.
  const ::mode_t mask = ::umask(0);
  ::umask(mask);
  fs::permissions(tmp, static_cast<fs::perms>(0666 & ~mask), ec);
  // Checked again just before the rename: the path may have been replaced during the work.
  try {
    check_output_path(path, option);
  } catch (...) {
    fs::remove(tmp, ec);
    throw;
  }
  fs::rename(tmp, path, ec);
  if (ec) {
    std::error_code ignored;
    fs::remove(tmp, ignored);
    throw invalid_input(std::string(option) + " " + path + ": cannot be written (" + ec.message() + ")");
  }
}

void check_results_path(const std::string& path) {
  if (path.empty()) throw invalid_input("--out: an empty path");
  std::error_code ec;
  fs::create_directories(directory_of(path), ec);
  if (ec) throw invalid_input("--out " + path + ": its directory cannot be created (" + ec.message() + ")");
  for (const std::string& p : {path, csv_path(path)}) {
    check_output_path(p, "--out");
    // A file can be created beside it (removed at once; the target itself is never opened).
    const auto [fd, tmp] = create_temporary(p, "--out");
    ::close(fd);
    fs::remove(tmp, ec);
  }
}

std::string records_csv(const nlohmann::json& records) {
  std::ostringstream os;
  os << std::setprecision(17)
     << "case,group,quantity,method,setting,error,estimate,bounded,evaluations,status,reason\n";
  const auto cell = [](const nlohmann::json& v) -> std::string {
    if (v.is_null()) return "";
    if (!v.is_string()) return v.dump();
    const std::string s = v.get<std::string>();
    if (s.find_first_of(",\"") == std::string::npos) return s;
    std::string quoted = "\"";
    for (char ch : s) quoted += ch == '"' ? std::string("\"\"") : std::string(1, ch);
    return quoted + "\"";
  };
  for (const auto& r : records)
    os << cell(r["case"]) << "," << cell(r["group"]) << "," << cell(r["quantity"]) << "," << cell(r["method"]) << ","
       << cell(r["setting"]) << "," << cell(r["error"]) << "," << cell(r["estimate"]) << "," << cell(r["bounded"])
       << "," << cell(r["evaluations"]) << "," << cell(r["status"]) << ","
       << cell(r.contains("reason") ? r["reason"] : nlohmann::json()) << "\n";
  return os.str();
}

namespace {
/// FILE.json -> FILE; any other name as it is.
std::string without_json(std::string p) {
  if (p.size() > 5 && p.ends_with(".json")) p.resize(p.size() - 5);
  return p;
}
}  // namespace

std::string csv_path(const std::string& json_path) { return without_json(json_path) + ".csv"; }

std::string partial_path(const std::string& json_path) { return without_json(json_path) + ".partial.json"; }

void write_results(const nlohmann::json& results, const std::string& path) {
  const std::filesystem::path parent = std::filesystem::path(path).parent_path();
  std::filesystem::create_directories(parent.empty() ? std::filesystem::path(".") : parent);
  write_atomic(path, results.dump(1) + "\n");
  write_atomic(csv_path(path), records_csv(results["records"]));
}

}  // namespace curvebench::harness
