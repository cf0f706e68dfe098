// The high-precision type of curvebench's references: boost::multiprecision::cpp_bin_float_50
// (50 decimal digits, 166-bit significand, expression templates off), with Eigen support.
//
// Every numerical template is instantiated on `real50` to produce reference values: one code
// path, two precisions (DESIGN.md). Include this header (and only this one) to use real50 with
// Eigen; keep 50-digit instantiations in few translation units, they are slow to compile.
#pragma once

#include <boost/multiprecision/cpp_bin_float.hpp>
#include <boost/multiprecision/eigen.hpp>

namespace curvebench {

using real50 = boost::multiprecision::cpp_bin_float_50;

}  // namespace curvebench
