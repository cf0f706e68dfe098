// Motion along a path: the cost of one frame, position(t) = P(U(L S(x))), with each u(s) method
// of the arc-length parameterization (linear table, Hermite table, Newton), on a Catmull-Rom path
// through five keys (uniform knots, so |P'| varies and u(s) is not linear) eased by a sine plateau
// over 240 frames; and the cost of the distance-time functions themselves (value + velocity).
// Each motion benchmark reports, measured once outside the timed loop, the largest error of the
// arc length reached at a frame, |s(u_f) - L S(x_f)| over the 240 frames, against a 50-digit
// adaptive Gauss-Kronrod arc length of the same spline, relative to the path length L (counter
// max_rel_s_err): the speed/accuracy trade-off of the u(s) methods at the motion level.
// Names: motion/position_at_frame/method:<0 linear_table | 1 hermite_table | 2 newton>,
//        motion/ease/<name>.
#include "curvebench/arclength/length.hpp"
#include "curvebench/arclength/parameterization.hpp"
#include "curvebench/curves/cardinal_spline.hpp"
#include "curvebench/motion/distance_time.hpp"
#include "curvebench/motion/motion_path.hpp"
#include "curvebench/reference/multiprecision.hpp"

#include <benchmark/benchmark.h>

#include <algorithm>
#include <vector>

namespace {

namespace cb = curvebench;
namespace cbm = curvebench::motion;
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

void position_at_frame(benchmark::State& state) {
  const auto method = static_cast<cb::arclength::inversion_method>(state.range(0));
  cb::arclength::parameterization_options<double> opt;
  opt.method = method;
  if (method == cb::arclength::inversion_method::linear_table) opt.table_intervals = 1024;
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
  state.counters["frames"] = benchmark::Counter(1.0, benchmark::Counter::kIsIterationInvariantRate);
  state.counters["max_rel_s_err"] =
      max_relative_s_error(motion, cbm::sine_plateau_ease<cb::real50>(cb::real50(0.25), cb::real50(0.75)));
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

}  // namespace

BENCHMARK(position_at_frame)->Name("motion/position_at_frame")->ArgName("method")->Arg(0)->Arg(1)->Arg(2);
BENCHMARK(ease_linear)->Name("motion/ease/linear");
BENCHMARK(ease_sine)->Name("motion/ease/sine");
BENCHMARK(ease_sine_plateau)->Name("motion/ease/sine_plateau");
BENCHMARK(ease_parabolic)->Name("motion/ease/parabolic");
BENCHMARK(ease_smootherstep)->Name("motion/ease/smootherstep");
BENCHMARK(ease_distance_keys)->Name("motion/ease/distance_keys");
BENCHMARK(ease_speed_cubic)->Name("motion/ease/speed_monotone_cubic");
