// Basis evaluation speed: all n + 1 Bernstein polynomials of degree n by the triangular recursion
// versus n + 1 calls of the closed form. Operation basis (all n + 1 values at one parameter), one
// per iteration; the parameters step independently of the results, so consecutive iterations are
// independent evaluations (throughput).
// Names: bernstein/<algorithm>/degree:<n>.
#include "curvebench/basis/bernstein.hpp"

#include "harness/bench_support.hpp"

#include <benchmark/benchmark.h>

#include <vector>

namespace {

namespace vocab = curvebench::harness::vocab;
using curvebench::bench::benchmark_name;
using curvebench::bench::per_operation;
using curvebench::bench::register_benchmark;

void bernstein_recursion(benchmark::State& state, int n) {
  std::vector<double> out(static_cast<std::size_t>(n) + 1);
  double t = 0.3;
  for (auto _ : state) {
    curvebench::basis::bernstein_all(n, t, std::span<double>(out));
    benchmark::DoNotOptimize(out.data());
    t = t < 0.9 ? t + 0.001 : 0.1;
  }
  per_operation(state, vocab::operations::basis, 1);
}

void bernstein_closed_form(benchmark::State& state, int n) {
  std::vector<double> out(static_cast<std::size_t>(n) + 1);
  double t = 0.3;
  for (auto _ : state) {
    for (int i = 0; i <= n; ++i) out[static_cast<std::size_t>(i)] = curvebench::basis::bernstein(n, i, t);
    benchmark::DoNotOptimize(out.data());
    t = t < 0.9 ? t + 0.001 : 0.1;
  }
  per_operation(state, vocab::operations::basis, 1);
}

const bool registered = [] {
  for (int n : {3, 7, 20}) {
    register_benchmark(benchmark_name("bernstein", vocab::algorithms::recursion).arg("degree", n),
                       [n](benchmark::State& s) { bernstein_recursion(s, n); });
    register_benchmark(benchmark_name("bernstein", vocab::algorithms::closed_form).arg("degree", n),
                       [n](benchmark::State& s) { bernstein_closed_form(s, n); });
  }
  return true;
}();

}  // namespace
