// Replays saved inputs through a fuzz target without libFuzzer (targets.hpp), so the normal test
// build checks every regression input and seed on every run:
//   curvebench_fuzz_replay TARGET PATH...     TARGET: spec, gate, csv, times, svg, compare or fidelity (the
//                                             last two where the harness is built); PATH: a file or a directory
//                                             (its regular files, sorted, not recursively)
// Prints each file before running it, so a violation (which aborts) is preceded by its file's name.
// Exits 2 on a usage error or an unreadable path, 0 when every file passed.
#include "targets.hpp"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

namespace fs = std::filesystem;

namespace {
struct target {
  std::string_view name;
  int (*run)(const std::uint8_t*, std::size_t);
};
constexpr target all_targets[] = {
    {"spec", curvebench::fuzz::spec_target},       {"gate", curvebench::fuzz::gate_target},
    {"csv", curvebench::fuzz::csv_target},         {"times", curvebench::fuzz::times_target},
    {"svg", curvebench::fuzz::svg_target},
#ifdef CURVEBENCH_FUZZ_HARNESS_TARGETS  // their readers are the harness library's (bench/)
    {"compare", curvebench::fuzz::compare_target}, {"fidelity", curvebench::fuzz::fidelity_target},
#endif
};
}  // namespace

int main(int argc, char** argv) {
  if (argc < 3) {
    std::fprintf(stderr, "usage: %s spec|gate|csv|times|svg|compare|fidelity PATH...\n", argv[0]);
    return 2;
  }
  const target* t = nullptr;
  for (const auto& candidate : all_targets)
    if (candidate.name == argv[1]) t = &candidate;
  if (!t) {
    std::fprintf(stderr, "replay: unknown target '%s' (spec, gate, csv, times, svg, compare, fidelity)\n", argv[1]);
    return 2;
  }
  std::vector<fs::path> files;
  for (int i = 2; i < argc; ++i) {
    std::error_code ec;
    const fs::path p(argv[i]);
    if (fs::is_directory(p, ec)) {
      std::vector<fs::path> in_dir;
      for (const auto& e : fs::directory_iterator(p, ec))
        if (e.is_regular_file()) in_dir.push_back(e.path());
      std::sort(in_dir.begin(), in_dir.end());
      files.insert(files.end(), in_dir.begin(), in_dir.end());
    } else if (fs::is_regular_file(p, ec)) {
      files.push_back(p);
    } else {
      std::fprintf(stderr, "replay: %s is neither a file nor a directory\n", argv[i]);
      return 2;
    }
  }
  for (const fs::path& f : files) {
    std::ifstream in(f, std::ios::binary);
    if (!in) {
      std::fprintf(stderr, "replay: %s cannot be read\n", f.c_str());
      return 2;
    }
    const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    std::fprintf(stderr, "replay %s: %s (%zu bytes)\n", argv[1], f.c_str(), bytes.size());
    t->run(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size());
  }
  std::printf("replay %s: %zu inputs, no violation\n", argv[1], files.size());
  return 0;
}
