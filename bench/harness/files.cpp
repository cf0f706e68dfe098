#include "harness/files.hpp"

#include "curvebench/core/error.hpp"

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <vector>

namespace curvebench::harness {

namespace fs = std::filesystem;

namespace {
std::string mib(std::size_t bytes) { return std::to_string(bytes >> 20) + " MiB"; }
}  // namespace

std::string read_input_file(const std::string& path, std::string_view prefix, std::size_t limit) {
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
      throw invalid_input(who + ": larger than " + mib(limit) + " (" + std::to_string(limit) +
                          " bytes), the limit for this input; nothing past it was read");
    text.append(chunk.data(), got);
  }
  if (in.bad()) throw invalid_input(who + ": reading failed after " + std::to_string(text.size()) + " bytes");
  return text;
}

}  // namespace curvebench::harness
