// The whole vocabulary (harness/vocabulary.hpp) as JSON, for `curvebench list vocabulary --json`
// (scripts/bench.sh writes it to reports/vocabulary.json for scripts/report.py):
//   {"quantities": [{"id", "doc"}],
//    "methods":    [{"id", "quantities": [ids], "settings": [keys], "theory" (0: none fitted), "doc"}],
//    "peers":      [{"id", "library", "doc"}],
//    "operations": [{"id", "doc"}],
//    "counters":   [{"name", "kind", "doc"}],
//    "algorithms": [{"id", "settings", "doc"}],
//    "variant_keys": [{"id", "values", "doc"}],
//    "tools":      [{"id", "storage_bits", "default_solver", "settings", "doc", "rules"}]}
// The tools are io::all_tools (io/tools/all.hpp): a channel spec's "tool", the algorithm of the
// tool model's benchmarks (bench_channel) and the report's columns.
#pragma once

#include <nlohmann/json.hpp>

namespace curvebench::harness {

nlohmann::json vocabulary_json();

}  // namespace curvebench::harness
