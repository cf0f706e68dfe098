// The whole vocabulary (harness/vocabulary.hpp) as JSON, for `curvebench list vocabulary --json`
// (scripts/bench.sh writes it to reports/vocabulary.json for scripts/report.py):
//   {"quantities": [{"id", "doc"}],
//    "methods":    [{"id", "quantities": [ids], "settings": [keys], "theory" (0: none fitted), "doc"}],
//    "peers":      [{"id", "library", "doc"}],
//    "operations": [{"id", "doc"}],
//    "counters":   [{"name", "kind", "doc"}]}
#pragma once

#include <nlohmann/json.hpp>

namespace curvebench::harness {

nlohmann::json vocabulary_json();

}  // namespace curvebench::harness
