// Bezier curves: speed of the three evaluation algorithms (de Casteljau O(L^2), direct Bernstein
// sum O(L), Horner on power-basis coefficients converted once O(L)) at degrees 3, 7 and 20, for
// single random parameters (calls:single, one evaluation per iteration) and for a sorted batch of
// 1024 parameters (calls:sorted, the batch API, 1024 evaluations per iteration). Operation
// evaluation; the parameters are fixed in advance, so the evaluations are independent (throughput).
// Each benchmark also reports, as counter max_err_eps measured once outside the timed loop, the
// algorithm's maximum error over its parameters against the real50 de Casteljau of the same
// control points, in units of eps(double) times the control-point scale (max |coordinate| = 1):
// the speed/accuracy trade-off in one table (Horner is fastest and, at degree 20, ~1e8 times less
// accurate).
// Names: bezier/<algorithm>/calls:<single|sorted>/degree:<n>.
#include "curvebench/curves/bezier.hpp"
#include "curvebench/reference/multiprecision.hpp"

#include "harness/bench_support.hpp"

#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

namespace {

namespace cb = curvebench;
namespace vocab = curvebench::harness::vocab;

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
void evaluate(benchmark::State& state, int degree) {
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
  curvebench::bench::per_operation(state, vocab::operations::evaluation, per_iteration);
  curvebench::bench::set_counter(state, vocab::counters::max_err_eps, max_error(curve, reference, us, Alg));
}

using cb::bezier_algorithm;
using curvebench::bench::benchmark_name;

template <bezier_algorithm Alg, mode Mode>
void add(const vocab::algorithm& id) {
  for (int degree : {3, 7, 20})
    curvebench::bench::register_benchmark(
        benchmark_name("bezier", id)
            .variant(vocab::variant_keys::calls, Mode == mode::single ? "single" : "sorted")
            .arg("degree", degree),
        [degree](benchmark::State& s) { evaluate<Alg, Mode>(s, degree); });
}

const bool registered = [] {
  namespace a = vocab::algorithms;
  add<bezier_algorithm::de_casteljau, mode::single>(a::de_casteljau);
  add<bezier_algorithm::bernstein_sum, mode::single>(a::bernstein_sum);
  add<bezier_algorithm::horner, mode::single>(a::horner);
  add<bezier_algorithm::de_casteljau, mode::sorted>(a::de_casteljau);
  add<bezier_algorithm::bernstein_sum, mode::sorted>(a::bernstein_sum);
  add<bezier_algorithm::horner, mode::sorted>(a::horner);
  return true;
}();

}  // namespace
