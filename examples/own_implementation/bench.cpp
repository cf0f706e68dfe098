// Google Benchmark timings of the hand-written Catmull-Rom and chord table, named and counted as
// curvebench's own benchmarks (harness/subject_bench.hpp): catmull_rom/own_catmull_rom/calls:...
#include "keys.hpp"

#include <harness/subject_bench.hpp>

namespace {
const bool registered = [] {
  const own::catmull_rom c(own::keys(), 0.5);
  curvebench::bench::register_subject_benchmarks("catmull_rom", own::spline_subject(0.5), c.start(), c.end());
  curvebench::bench::register_subject_benchmarks("catmull_rom", own::table_subject(0.5), c.start(), c.end());
  return true;
}();
}  // namespace
