// io::curve_from_spec<double, Dim> compiled once for the in-tree builds (see the end of io/spec.hpp and
// the curvebench_spec_instances target in CMakeLists.txt).
#include "curvebench/io/spec.hpp"

namespace curvebench::io {
template any_curve<double, 1> curve_from_spec<double, 1>(const field&);
template any_curve<double, 2> curve_from_spec<double, 2>(const field&);
template any_curve<double, 3> curve_from_spec<double, 3>(const field&);
template any_curve<double, 4> curve_from_spec<double, 4>(const field&);
}  // namespace curvebench::io
