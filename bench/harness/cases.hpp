// The curve case suite: one JSON spec per file in bench/cases/ (or a user's directory), each with
// "name" (= the file's stem), "group" (the threshold group), "reason" (why the case is there),
// optionally "quick": false (left out of the quick suite that CI runs, for cases too slow for it),
// and the spec fields of io/spec.hpp. Users add a case by dropping a file there.
#pragma once

#include "harness/files.hpp"

#include "curvebench/io/spec.hpp"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace curvebench::harness {

/// The suite's name and version: bump the version when a case changes, so reports are comparable.
inline constexpr const char* suite_name = "curvebench-cases";
inline constexpr int suite_version = 4;  // 2: conic_ellipse_arc and rational_cubic_weighted added;
                                         // 3: catmull_rom_centripetal_end_controls_2d added;
                                         // 4: the svg_* corpus added

struct case_info {
  std::string name;
  std::string group;
  std::string reason;
  std::string file;
  nlohmann::json spec;
  int dimension = 0;
  bool quick = true;  ///< part of the quick suite (CI's); "quick": false keeps slow cases for full runs
};

/// All *.json cases of a directory, sorted by name. Each must be a valid spec with name (equal to
/// the file's stem), group and reason; errors name the file and field. A file named index.json is
/// the directory's index, not a case (scripts/blender_export.py writes one beside its specs, which
/// are cases), so no case is named "index".
inline std::vector<case_info> load_cases(const std::string& dir) {
  namespace fs = std::filesystem;
  if (!fs::is_directory(dir)) throw invalid_input("cases: " + dir + " is not a directory");
  std::vector<case_info> out;
  for (const auto& entry : fs::directory_iterator(dir)) {
    if (entry.path().extension() != ".json" || entry.path().filename() == "index.json") continue;
    const std::string file = entry.path().string();
    // A case is a file: a FIFO named *.json blocked the whole run at its open (no writer), and a
    // directory or device is no case either. A symbolic link to a regular file is one.
    std::error_code ec;
    if (!fs::is_regular_file(entry.path(), ec))
      throw invalid_input("cases: " + file + " is not a regular file (a case is a *.json file)");
    case_info c;
    c.spec = io::parse(read_input_file(file), file);
    const io::field root = io::root(c.spec, entry.path().filename().string());
    c.name = root.member("name", "every case has a name").string();
    if (c.name != entry.path().stem().string())
      root.member("name").fail("\"" + c.name + "\" must equal the file name's stem \"" + entry.path().stem().string() +
                               "\"");
    c.group = root.member("group", "every case has a threshold group").string();
    c.reason = root.member("reason", "every case says why it is there").string();
    c.file = file;
    if (root.has("quick")) c.quick = root.member("quick").boolean();
    c.dimension = io::spec_dimension(root);
    out.push_back(std::move(c));
  }
  std::sort(out.begin(), out.end(), [](const case_info& a, const case_info& b) { return a.name < b.name; });
  if (out.empty()) throw invalid_input("cases: no *.json case in " + dir);
  return out;
}

}  // namespace curvebench::harness
