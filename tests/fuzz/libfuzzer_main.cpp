// The libFuzzer entry point of one target (CURVEBENCH_FUZZ_TARGET: spec_target, gate_target,
// csv_target, times_target or svg_target; targets.hpp), built with -fsanitize=fuzzer by tests/fuzz/CMakeLists.txt.
#include "targets.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return curvebench::fuzz::CURVEBENCH_FUZZ_TARGET(data, size);
}
