// The JSON reader's half of release_warnings_bezier.cpp (see there): built at -O3 with the tests'
// warning flags; before strict_builder::path() appended its pieces, GCC 12.2 warned here.
#include "curvebench/io/json_fields.hpp"

#include <string>

namespace curvebench::release_warnings {

// strict_builder::path(), inlined into the strict JSON reader.
io::json parse(const std::string& text) { return io::parse(text); }

}  // namespace curvebench::release_warnings
