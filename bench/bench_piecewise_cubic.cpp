// piecewise_cubic engine: speed of the three evaluation algorithms (power-coefficient Horner,
// matrix form T·M·G per call, Bezier form by de Casteljau) for single random parameters and for
// batches of 1024 (unsorted: one lookup each; sorted: the segment-walking fast path), on uniform
// knots (O(1) lookup) and non-uniform knots (binary search). Operation evaluation: one per
// iteration for single calls, 1024 for a batch; the parameters are fixed in advance, so the
// evaluations are independent (throughput), and the report's time per evaluation compares single
// calls and batches directly. Each benchmark also reports, as counter max_err_eps, the algorithm's
// maximum error against the real50 engine built from the same data (in units of eps(double) times
// the data scale), measured once outside the timed loop.
// Names: piecewise_cubic/<algorithm>/calls:<single|batch|sorted>/segments:<n>/knots:<uniform|nonuniform>.
#include "curvebench/curves/piecewise_cubic.hpp"
#include "curvebench/reference/multiprecision.hpp"

#include "harness/bench_support.hpp"

#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

namespace {

namespace cb = curvebench;
namespace vocab = curvebench::harness::vocab;

template <class Real>
struct test_data {
  std::vector<Real> knots;
  cb::point_list<Real, 3> values, slopes;
};

// Random Hermite data (values and slopes in [-1, 1]) on n segments; non-uniform knots have
// intervals in [0.25, 1.75]. Doubles converted exactly to real50 for the reference.
test_data<double> make_data(std::size_t n, bool uniform) {
  std::mt19937_64 rng(12345);
  std::uniform_real_distribution<double> coord(-1.0, 1.0), step(0.25, 1.75);
  test_data<double> d;
  d.knots = uniform ? cb::uniform_knots<double>(n) : std::vector<double>{0.0};
  for (std::size_t i = 0; i <= n; ++i) {
    if (!uniform && i > 0) d.knots.push_back(d.knots.back() + step(rng));
    d.values.emplace_back(coord(rng), coord(rng), coord(rng));
    d.slopes.emplace_back(coord(rng), coord(rng), coord(rng));
  }
  return d;
}

std::vector<double> random_parameters(const cb::interval<double>& dom, std::size_t count, bool sorted) {
  std::mt19937_64 rng(987);
  std::uniform_real_distribution<double> u(dom.lo, dom.hi);
  std::vector<double> us(count);
  for (auto& x : us) x = u(rng);
  if (sorted) std::sort(us.begin(), us.end());
  return us;
}

// Max |double - real50| over the parameters, in eps(double) units of the data scale (values and
// slopes <= 1, intervals <= 1.75, so the geometry items are <= 1.75).
double max_error(const cb::piecewise_cubic<double, 3>& c, const cb::piecewise_cubic<cb::real50, 3>& ref,
                 const std::vector<double>& us, cb::cubic_algorithm alg) {
  cb::real50 worst(0);
  for (double u : us) {
    const auto got = c.evaluate(u, 0, alg);
    const auto r = ref.evaluate(cb::real50(u), 0, cb::cubic_algorithm::power);
    for (int k = 0; k < 3; ++k) {
      using std::abs;
      worst = std::max(worst, cb::real50(abs(cb::real50(got[k]) - r[k])));
    }
  }
  return static_cast<double>(worst / (cb::real50(std::numeric_limits<double>::epsilon()) * cb::real50(1.75)));
}

struct fixture {
  cb::piecewise_cubic<double, 3> curve;
  cb::piecewise_cubic<cb::real50, 3> reference;
};

fixture make_fixture(std::size_t n, bool uniform) {
  const auto d = make_data(n, uniform);
  std::vector<cb::real50> k50(d.knots.begin(), d.knots.end());
  return {cb::piecewise_cubic<double, 3>::from_hermite(d.knots, d.values, d.slopes, d.slopes),
          cb::piecewise_cubic<cb::real50, 3>::from_hermite(k50, cb::points_cast<cb::real50, double, 3>(d.values),
                                                           cb::points_cast<cb::real50, double, 3>(d.slopes),
                                                           cb::points_cast<cb::real50, double, 3>(d.slopes))};
}

enum class mode { single, batch, sorted };

template <cb::cubic_algorithm Alg, mode Mode>
void evaluate(benchmark::State& state, std::size_t n, bool uniform) {
  const auto f = make_fixture(n, uniform);
  constexpr std::size_t batch = 1024;
  const auto us = random_parameters(f.curve.domain(), batch, Mode == mode::sorted);
  std::vector<cb::point<double, 3>> out(batch);
  std::size_t k = 0;
  for (auto _ : state) {
    if constexpr (Mode == mode::single) {
      auto p = f.curve.evaluate(us[k], 0, Alg);
      benchmark::DoNotOptimize(p);
      k = (k + 1) % batch;
    } else if constexpr (Mode == mode::batch) {
      f.curve.evaluate_batch(us, out, 0, Alg);
      benchmark::DoNotOptimize(out.data());
    } else {
      f.curve.evaluate_sorted(us, out, 0, Alg);
      benchmark::DoNotOptimize(out.data());
    }
    benchmark::ClobberMemory();
  }
  const double per_iteration = Mode == mode::single ? 1.0 : static_cast<double>(batch);
  curvebench::bench::per_operation(state, vocab::operations::evaluation, per_iteration);
  curvebench::bench::set_counter(state, vocab::counters::max_err_eps, max_error(f.curve, f.reference, us, Alg));
}

using cb::cubic_algorithm;

template <cubic_algorithm Alg, mode Mode>
void add(const vocab::algorithm& id, std::string_view calls) {
  for (std::size_t n : {8, 64, 4096})
    for (bool uniform : {true, false})
      curvebench::bench::register_benchmark(curvebench::bench::benchmark_name("piecewise_cubic", id)
                                                .variant(vocab::variant_keys::calls, calls)
                                                .arg("segments", n)
                                                .arg("knots", uniform ? "uniform" : "nonuniform"),
                                            [n, uniform](benchmark::State& s) { evaluate<Alg, Mode>(s, n, uniform); });
}

const bool registered = [] {
  namespace a = vocab::algorithms;
  add<cubic_algorithm::power, mode::single>(a::power, "single");
  add<cubic_algorithm::matrix, mode::single>(a::matrix, "single");
  add<cubic_algorithm::bezier, mode::single>(a::bezier, "single");
  add<cubic_algorithm::power, mode::batch>(a::power, "batch");
  add<cubic_algorithm::matrix, mode::batch>(a::matrix, "batch");
  add<cubic_algorithm::bezier, mode::batch>(a::bezier, "batch");
  add<cubic_algorithm::power, mode::sorted>(a::power, "sorted");
  add<cubic_algorithm::matrix, mode::sorted>(a::matrix, "sorted");
  add<cubic_algorithm::bezier, mode::sorted>(a::bezier, "sorted");
  return true;
}();

}  // namespace
