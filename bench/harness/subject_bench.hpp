// Google Benchmark registration of a subject (harness/subject.hpp), named and counted as
// curvebench's own evaluation benchmarks (bench/bench_piecewise_cubic.cpp; harness/bench_support.hpp):
//   <family>/<subject name>/calls:single   one evaluation at a random parameter per iteration
//   <family>/<subject name>/calls:sorted   a sorted batch of 1024 random parameters per iteration
// each declaring the operation "evaluation" with its items processed per evaluation, so that a
// benchmark JSON of yours reads like curvebench's (time per evaluation). With a length function:
//   <family>/<subject name>/calls:single   under the operation "query": one length(lo, u) per
//                                          iteration at a random u (registered as <family>_length).
// Header-only: include it in your benchmark program and link benchmark::benchmark_main.
//
//   const auto s = my_subject();                              // a curvebench::harness::subject<2>
//   curvebench::bench::register_subject_benchmarks("catmull_rom", s, 0.0, 5.0);
#pragma once

#include "harness/bench_support.hpp"
#include "harness/subject.hpp"

#include <benchmark/benchmark.h>

#include <algorithm>
#include <cstddef>
#include <random>
#include <string>
#include <vector>

namespace curvebench::bench {

/// count parameters drawn uniformly from [lo, hi] with a fixed seed (the same in every run).
inline std::vector<double> subject_parameters(double lo, double hi, std::size_t count, bool sorted) {
  std::mt19937_64 rng(987);
  std::uniform_real_distribution<double> dist(lo, hi);
  std::vector<double> us(count);
  for (double& u : us) u = dist(rng);
  if (sorted) std::sort(us.begin(), us.end());
  return us;
}

/// Registers the subject's benchmarks (see the top of this file) on the domain [lo, hi].
template <int Dim>
void register_subject_benchmarks(const std::string& family, const harness::subject<Dim>& s, double lo, double hi) {
  constexpr std::size_t batch = 1024;
  // The names are built from a vocabulary algorithm whose id is the subject's name (benchmark_name
  // copies it, and Google Benchmark copies the name).
  const vocab::algorithm id{s.name, "", "a user's implementation (subject)"};
  if (s.eval) {
    const auto eval = s.eval;
    register_benchmark(benchmark_name(family, id).variant(vocab::variant_keys::calls, "single"),
                       [eval, lo, hi](benchmark::State& state) {
                         const std::vector<double> us = subject_parameters(lo, hi, batch, false);
                         std::size_t k = 0;
                         for (auto _ : state) {
                           auto p = eval(us[k]);
                           benchmark::DoNotOptimize(p);
                           k = (k + 1) % batch;
                         }
                         per_operation(state, vocab::operations::evaluation, 1.0);
                       });
    register_benchmark(benchmark_name(family, id).variant(vocab::variant_keys::calls, "sorted"),
                       [eval, lo, hi](benchmark::State& state) {
                         const std::vector<double> us = subject_parameters(lo, hi, batch, true);
                         std::vector<point<double, Dim>> out(batch);
                         for (auto _ : state) {
                           for (std::size_t j = 0; j < batch; ++j) out[j] = eval(us[j]);
                           benchmark::DoNotOptimize(out.data());
                           benchmark::ClobberMemory();
                         }
                         per_operation(state, vocab::operations::evaluation, static_cast<double>(batch));
                       });
  }
  if (s.length) {
    const auto length = s.length;
    register_benchmark(benchmark_name(family + "_length", id).variant(vocab::variant_keys::calls, "single"),
                       [length, lo, hi](benchmark::State& state) {
                         const std::vector<double> us = subject_parameters(lo, hi, batch, false);
                         std::size_t k = 0;
                         for (auto _ : state) {
                           double v = length(lo, us[k]);
                           benchmark::DoNotOptimize(v);
                           k = (k + 1) % batch;
                         }
                         per_operation(state, vocab::operations::query, 1.0);
                       });
  }
}

}  // namespace curvebench::bench
