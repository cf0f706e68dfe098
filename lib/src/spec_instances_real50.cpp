// io::curve_from_spec<real50, Dim> compiled once for the in-tree builds (see the end of io/spec.hpp and
// the curvebench_spec_instances target in CMakeLists.txt).
#include "curvebench/io/spec.hpp"

namespace curvebench::io {
template any_curve<real50, 1> curve_from_spec<real50, 1>(const field&);
template any_curve<real50, 2> curve_from_spec<real50, 2>(const field&);
template any_curve<real50, 3> curve_from_spec<real50, 3>(const field&);
}  // namespace curvebench::io
