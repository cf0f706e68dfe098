// violation() of the fuzz targets (targets.hpp).
#include "targets.hpp"

#include <cstdio>
#include <cstdlib>

namespace curvebench::fuzz {

void violation(std::string_view target, std::string_view property, const std::string& details) {
  std::fprintf(stderr, "fuzz %.*s: property violated: %.*s: %s\n", static_cast<int>(target.size()), target.data(),
               static_cast<int>(property.size()), property.data(), details.c_str());
  std::fflush(stderr);
  std::abort();
}

}  // namespace curvebench::fuzz
