// Bezier curves: speed of the three evaluation algorithms (de Casteljau O(L^2), direct Bernstein
// sum O(L), Horner on power-basis coefficients converted once O(L)) at degrees 3, 7 and 20, for
// single random parameters and for a sorted batch of 1024 parameters (the batch API). Each
// benchmark also reports, as a counter measured once outside the timed loop, the algorithm's
// maximum error over its parameters against the real50 de Casteljau of the same control points, in
// units of eps(double) times the control-point scale (max |coordinate| = 1): the speed/accuracy
// trade-off in one table (Horner is fastest and, at degree 20, ~1e8 times less accurate).
// Names: bezier/<algorithm>_<single|sorted>/degree:<n>.
#include "curvebench/curves/bezier.hpp"
#include "curvebench/reference/multiprecision.hpp"

#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

namespace {

namespace cb = curvebench;

// Random control points in [-1, 1]^3, scaled so that the largest |coordinate| is exactly 1.
cb::point_list<double, 3> make_points(int degree) {
  std::mt19937_64 rng(2024 + static_cast<unsigned>(degree));
  std::uniform_real_distribution<double> coord(-1.0, 1.0);
  cb::point_list<double, 3> p(static_cast<std::size_t>(degree) + 1);
  double m = 0;
  for (auto& q : p) {
    q = cb::point<double, 3>(coord(rng), coord(rng), coord(rng));
    m = std::max(m, q.cwiseAbs().maxCoeff());
  }
  for (auto& q : p) q /= m;
  return p;
}

std::vector<double> random_parameters(std::size_t count, bool sorted) {
  std::mt19937_64 rng(987);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<double> us(count);
  for (auto& x : us) x = u(rng);
  if (sorted) std::sort(us.begin(), us.end());
  return us;
}

double max_error(const cb::bezier<double, 3>& c, const cb::bezier<cb::real50, 3>& ref, const std::vector<double>& us,
                 cb::bezier_algorithm alg) {
  cb::real50 worst(0);
  for (double u : us) {
    const cb::point<double, 3> got = c.evaluate(u, alg);
    const cb::point<cb::real50, 3> r = ref(cb::real50(u));
    for (int k = 0; k < 3; ++k) {
      using std::abs;
      worst = std::max(worst, cb::real50(abs(cb::real50(got[k]) - r[k])));
    }
  }
  return static_cast<double>(worst / cb::real50(std::numeric_limits<double>::epsilon()));
}

enum class mode { single, sorted };

template <cb::bezier_algorithm Alg, mode Mode>
void evaluate(benchmark::State& state) {
  const int degree = static_cast<int>(state.range(0));
  const auto p = make_points(degree);
  const cb::bezier<double, 3> curve(p);
  const cb::bezier<cb::real50, 3> reference(cb::points_cast<cb::real50, double, 3>(p));
  constexpr std::size_t batch = 1024;
  const auto us = random_parameters(batch, Mode == mode::sorted);
  std::vector<cb::point<double, 3>> out(batch);
  std::size_t k = 0;
  for (auto _ : state) {
    if constexpr (Mode == mode::single) {
      auto v = curve.evaluate(us[k], Alg);
      benchmark::DoNotOptimize(v);
      k = (k + 1) % batch;
    } else {
      curve.evaluate(std::span<const double>(us), std::span<cb::point<double, 3>>(out), Alg);
      benchmark::DoNotOptimize(out.data());
    }
    benchmark::ClobberMemory();
  }
  const double per_iteration = Mode == mode::single ? 1.0 : static_cast<double>(batch);
  state.counters["evals"] = benchmark::Counter(per_iteration, benchmark::Counter::kIsIterationInvariantRate);
  state.counters["max_err_eps"] = max_error(curve, reference, us, Alg);
}

void degrees(benchmark::internal::Benchmark* b) { b->ArgName("degree")->Arg(3)->Arg(7)->Arg(20); }

using cb::bezier_algorithm;

}  // namespace

BENCHMARK(evaluate<bezier_algorithm::de_casteljau, mode::single>)->Name("bezier/de_casteljau_single")->Apply(degrees);
BENCHMARK(evaluate<bezier_algorithm::bernstein_sum, mode::single>)->Name("bezier/bernstein_sum_single")->Apply(degrees);
BENCHMARK(evaluate<bezier_algorithm::horner, mode::single>)->Name("bezier/horner_single")->Apply(degrees);
BENCHMARK(evaluate<bezier_algorithm::de_casteljau, mode::sorted>)->Name("bezier/de_casteljau_sorted")->Apply(degrees);
BENCHMARK(evaluate<bezier_algorithm::bernstein_sum, mode::sorted>)->Name("bezier/bernstein_sum_sorted")->Apply(degrees);
BENCHMARK(evaluate<bezier_algorithm::horner, mode::sorted>)->Name("bezier/horner_sorted")->Apply(degrees);
