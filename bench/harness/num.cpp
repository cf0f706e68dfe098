// detail::num (check_detail.hpp), in a file of its own: compare's reader formats its messages with
// it, and the compare fuzz target links that reader without the 50-digit check code.
#include "harness/check_detail.hpp"

#include <cstdio>
#include <string>

namespace curvebench::harness::detail {

std::string num(double x, int digits) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*g", digits, x);
  return buf;
}

}  // namespace curvebench::harness::detail
