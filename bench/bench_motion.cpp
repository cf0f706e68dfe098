// Motion along a path: the cost of one frame, position(t) = P(U(L S(x))), with each u(s) method
// of the arc-length parameterization (linear table, Hermite table, Newton), on a Catmull-Rom path
// through five keys (uniform knots, so |P'| varies and u(s) is not linear) eased by a sine plateau
// over 240 frames (operation frame, one per iteration); and the cost of the distance-time functions
// themselves (operation ease: value + velocity, one per iteration). Frames and ease parameters are
// fixed in advance, so consecutive iterations are independent (throughput).
// Each motion benchmark reports, measured once outside the timed loop, the largest error of the
// arc length reached at a frame, |s(u_f) - L S(x_f)| over the 240 frames, against a 50-digit
// adaptive Gauss-Kronrod arc length of the same spline, relative to the path length L (counter
// max_ds_rel): the speed/accuracy trade-off of the u(s) methods at the motion level.
// Names: motion/<linear_table/M:1024 | hermite_table | newton>, ease/<ease>.
#include "curvebench/arclength/length.hpp"
#include "curvebench/arclength/parameterization.hpp"
#include "curvebench/curves/cardinal_spline.hpp"
#include "curvebench/motion/distance_time.hpp"
#include "curvebench/motion/motion_path.hpp"
#include "curvebench/reference/multiprecision.hpp"

#include "harness/bench_support.hpp"
#include "harness/length_methods.hpp"  // the vocabulary entries of the length and u(s) methods

#include <benchmark/benchmark.h>

#include <algorithm>
#include <vector>

namespace {

namespace cb = curvebench;
namespace cbm = curvebench::motion;
namespace cbb = curvebench::bench;
namespace vocab = curvebench::harness::vocab;
using point2 = cb::point<double, 2>;

const cb::point_list<double, 2>& keys() {
  static const cb::point_list<double, 2> k{point2(0, 0), point2(1, 2), point2(3, 3), point2(4, 0), point2(6, 1)};
  return k;
}

constexpr long long last_frame = 240;

template <class Motion>
double max_relative_s_error(const Motion& motion, const cbm::sine_plateau_ease<cb::real50>& ease50) {
  const cb::cardinal_spline<cb::real50, 2> path50(cb::points_cast<cb::real50, double, 2>(keys()));
  cb::arclength::adaptive_options<cb::real50> opt;
  opt.relative_tolerance = cb::real50("1e-30");
  const cb::real50 L = cb::arclength::adaptive_length(path50, opt).value;
  cb::real50 s(0), worst(0);
  double u_prev = 0;
  for (long long f = 1; f <= last_frame; ++f) {
    const double u = motion.sample_at_frame(f).parameter;
    s += cb::arclength::adaptive_length(path50, cb::real50(u_prev), cb::real50(u), opt).value;
    u_prev = u;
    using std::abs;
    worst = std::max(worst, cb::real50(abs(s - L * ease50(cb::real50(f) / last_frame))));
  }
  return static_cast<double>(worst / L);
}

void position_at_frame(benchmark::State& state, const cb::arclength::parameterization_options<double>& opt) {
  const cb::cardinal_spline<double, 2> path(keys());
  const cb::arclength::parameterization arc(path, opt);
  const cbm::sine_plateau_ease<double> ease(0.25, 0.75);
  const cbm::motion_path motion(arc, ease, cbm::frame_range<double>{0, last_frame, 24.0});
  long long f = 0;
  for (auto _ : state) {
    const point2 p = motion.position_at_frame(f);
    benchmark::DoNotOptimize(p);
    f = f == last_frame ? 0 : f + 1;
  }
  cbb::per_operation(state, vocab::operations::frame, 1);
  cbb::set_counter(
      state, vocab::counters::max_ds_rel,
      max_relative_s_error(motion, cbm::sine_plateau_ease<cb::real50>(cb::real50(0.25), cb::real50(0.75))));
}

template <class F>
void ease_cost(benchmark::State& state, const F& ease) {
  std::vector<double> ts(1024);
  for (std::size_t i = 0; i < ts.size(); ++i) ts[i] = static_cast<double>(i) / 1023.0;
  std::size_t k = 0;
  for (auto _ : state) {
    const double s = ease(ts[k]) + ease.velocity(ts[k]);
    benchmark::DoNotOptimize(s);
    k = (k + 1) & 1023;
  }
  cbb::per_operation(state, vocab::operations::ease, 1);
}

void ease_linear(benchmark::State& s) { ease_cost(s, cbm::linear_ease<double>{}); }
void ease_sine(benchmark::State& s) { ease_cost(s, cbm::sine_ease<double>{}); }
void ease_sine_plateau(benchmark::State& s) { ease_cost(s, cbm::sine_plateau_ease<double>(0.25, 0.75)); }
void ease_parabolic(benchmark::State& s) { ease_cost(s, cbm::parabolic_ease<double>(0.25, 0.75)); }
void ease_smootherstep(benchmark::State& s) { ease_cost(s, cbm::smootherstep_ease<double>{}); }
void ease_distance_keys(benchmark::State& s) {
  const std::vector<double> t{0, 0.1, 0.3, 0.5, 0.6, 0.8, 0.9, 1}, d{0, 0.02, 0.2, 0.5, 0.55, 0.8, 0.97, 1};
  ease_cost(s, cbm::distance_keys_ease<double>(t, d));
}
void ease_speed_cubic(benchmark::State& s) {
  const std::vector<double> t{0, 0.25, 0.5, 0.75, 1}, v{0, 1, 3, 1, 0};
  ease_cost(s, cbm::speed_curve_ease<double>(t, v, cbm::speed_interpolation::monotone_cubic));
}

const bool registered = [] {
  using cbb::benchmark_name;
  using cbb::register_benchmark;
  namespace al = cb::arclength;
  al::parameterization_options<double> linear;
  linear.method = al::inversion_method::linear_table;
  linear.table_intervals = 1024;
  register_benchmark(benchmark_name("motion", vocab::methods::linear_table).arg("M", linear.table_intervals),
                     [linear](benchmark::State& s) { position_at_frame(s, linear); });
  al::parameterization_options<double> hermite;
  hermite.method = al::inversion_method::hermite_table;
  register_benchmark(benchmark_name("motion", vocab::methods::hermite_table),
                     [hermite](benchmark::State& s) { position_at_frame(s, hermite); });
  al::parameterization_options<double> newton;
  newton.method = al::inversion_method::newton;
  register_benchmark(benchmark_name("motion", vocab::methods::newton),
                     [newton](benchmark::State& s) { position_at_frame(s, newton); });

  namespace a = vocab::algorithms;
  register_benchmark(benchmark_name("ease", a::ease_linear), ease_linear);
  register_benchmark(benchmark_name("ease", a::ease_sine), ease_sine);
  register_benchmark(benchmark_name("ease", a::ease_sine_plateau).arg("t1", 0.25).arg("t2", 0.75), ease_sine_plateau);
  register_benchmark(benchmark_name("ease", a::ease_parabolic).arg("t1", 0.25).arg("t2", 0.75), ease_parabolic);
  register_benchmark(benchmark_name("ease", a::ease_smootherstep), ease_smootherstep);
  register_benchmark(benchmark_name("ease", a::ease_distance_keys), ease_distance_keys);
  register_benchmark(benchmark_name("ease", a::ease_speed_curve).arg("interpolation", "monotone_cubic"),
                     ease_speed_cubic);
  return true;
}();

}  // namespace
