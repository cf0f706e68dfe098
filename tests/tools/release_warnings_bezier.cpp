// Compiled at -O3 (CMake's Release default, the documented install's flags) with the tests' warning
// flags, where scripts/test.sh builds everything else at -O2: GCC 12 warns at -O3 where it does not
// at -O2. Each function of these two files (one context per file: together in one file, GCC inlined
// differently and did not warn) is a context in which GCC 12.2 warned about the library's headers
// before they were changed (the message builders of check_parameter and of the JSON reader's paths:
// a false -Wrestrict / -Wstringop-overflow in libstdc++'s string insert); with CURVEBENCH_WERROR
// the test build fails if one comes back. Nothing here runs.
#include "curvebench/curves/bezier.hpp"

#include <span>

namespace curvebench::release_warnings {

// check_parameter's "us[i] = ..." message, inlined into a batch evaluation.
void batch(const bezier<double, 2>& c, std::span<const double> us, std::span<point<double, 2>> out) {
  c.evaluate(us, out, bezier_algorithm::de_casteljau, 1);
}

}  // namespace curvebench::release_warnings
