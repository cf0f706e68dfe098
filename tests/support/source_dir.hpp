// The source tree's root, read at run time: ctest gives every test CURVEBENCH_SOURCE_DIR in its
// environment (tests/CMakeLists.txt, curvebench_add_test). It is not compiled in, so that it is not
// in every test's command line, which ccache keys on; the precompiled header the tests reuse still
// holds the path, so a checkout at another path does not yet build its tests from the cache.
#pragma once

#include <cstdlib>
#include <stdexcept>
#include <string>

namespace curvebench::testing {

/// The checkout's root (recorded data, cases, thresholds, docs). Throws std::runtime_error saying
/// what to do when the test runs outside ctest without the variable.
inline std::string source_dir() {
  const char* dir = std::getenv("CURVEBENCH_SOURCE_DIR");
  if (dir == nullptr || *dir == '\0')
    throw std::runtime_error(
        "CURVEBENCH_SOURCE_DIR is not set: run the test through ctest, or set it to the checkout's root");
  return dir;
}

}  // namespace curvebench::testing
