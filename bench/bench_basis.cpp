// Basis evaluation speed: all n + 1 Bernstein polynomials of degree n by the recursion versus
// n + 1 calls of the closed form. Names follow family/algorithm/arg:value.
#include "curvebench/basis/bernstein.hpp"

#include <benchmark/benchmark.h>

#include <vector>

namespace {

void bernstein_recursion(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  std::vector<double> out(static_cast<std::size_t>(n) + 1);
  double t = 0.3;
  for (auto _ : state) {
    curvebench::basis::bernstein_all(n, t, std::span<double>(out));
    benchmark::DoNotOptimize(out.data());
    t = t < 0.9 ? t + 0.001 : 0.1;
  }
  state.counters["basis_evals"] = benchmark::Counter(static_cast<double>(n + 1), benchmark::Counter::kIsIterationInvariantRate);
}

void bernstein_closed_form(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  std::vector<double> out(static_cast<std::size_t>(n) + 1);
  double t = 0.3;
  for (auto _ : state) {
    for (int i = 0; i <= n; ++i) out[static_cast<std::size_t>(i)] = curvebench::basis::bernstein(n, i, t);
    benchmark::DoNotOptimize(out.data());
    t = t < 0.9 ? t + 0.001 : 0.1;
  }
  state.counters["basis_evals"] = benchmark::Counter(static_cast<double>(n + 1), benchmark::Counter::kIsIterationInvariantRate);
}

}  // namespace

BENCHMARK(bernstein_recursion)->Name("bernstein/recursion")->ArgName("degree")->Arg(3)->Arg(7)->Arg(20);
BENCHMARK(bernstein_closed_form)->Name("bernstein/closed_form")->ArgName("degree")->Arg(3)->Arg(7)->Arg(20);
