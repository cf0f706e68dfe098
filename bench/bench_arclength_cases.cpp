// Arc-length speed per case: every length method x setting of the length table
// (harness/length_methods.hpp) over the harness sweep (harness/sweep.hpp, the quick settings, a
// subset of the full ones) timed on every case of the suite. The benchmark
// arclength_case/<case>/<method>/<setting> computes exactly what the accuracy runner's record
// (case, "length", method, setting) measured, so report.py joins the two into error-vs-time Pareto
// plots per case. Curves are the type-erased any_curve<double, Dim> the runner uses: every method
// pays the same dispatch per evaluation, so ratios between methods on a case are fair; the family
// benchmarks (bench_arclength.cpp) time concrete types.
//
// Own flags (removed before Google Benchmark sees the rest):
//   --cases=DIR     the case directory (default: the source tree's bench/cases)
//   --quick-suite   only the cases of the quick suite (scripts/bench.sh --quick)
// Operation: vocab::operations::length (one arc length of the whole curve, set-up included), one
// per iteration. Counters: vocab::counters::evaluations (curve-derivative evaluations per length).
// u(s) on many segments, on the cases of at least many_segments segments and on the
// one-segment baseline_case: the Hermite table sized per segment to 1e-12 L, its build
// (u_of_s_build_case/hermite_table_sized/case:<case>/tol:1e-12, one table per iteration, operation
// table_build; counters table_intervals and evaluations) and its queries (u_of_s_case/..., operation
// query, one per iteration cycling through 1024 random targets in [0, L]), so that the per-query
// time on 1000 segments is compared with one segment's in the same run.
#include "harness/cases.hpp"
#include "harness/length_methods.hpp"
#include "harness/sweep.hpp"
#include "harness/vocabulary.hpp"

#include "curvebench/io/spec.hpp"

#include <benchmark/benchmark.h>

#include <cstdio>
#include <cstring>
#include <exception>
#include <memory>
#include <random>
#include <string>
#include <vector>

namespace {

namespace cb = curvebench;
namespace al = curvebench::arclength;
using cb::harness::case_info;
namespace vocab = cb::harness::vocab;

/// The sized Hermite table's target in the per-case u(s) benchmarks: 1e-12 L.
constexpr double table_target = 1e-12;
/// The cases whose u(s) table is timed: at least this many segments, and the one-segment baseline.
constexpr std::size_t many_segments = 100;
constexpr const char* baseline_case = "arch_cubic_bezier";

template <class Curve>
void register_table(const case_info& info, const std::shared_ptr<const Curve>& c) {
  al::parameterization_options<double> o;
  o.table_tolerance = table_target;
  const std::string name = std::string(vocab::methods::hermite_table_sized.id) + "/case:" + info.name +
                           "/tol:" + cb::harness::fmt(table_target);
  const auto build = [c, o](benchmark::State& st) {
    std::size_t cells = 0, evaluations = 0;
    for (auto _ : st) {
      const al::parameterization<Curve> p(*c, o);
      cells = p.table_intervals();
      evaluations = p.construction_evaluations();
      benchmark::DoNotOptimize(cells);
    }
    st.SetItemsProcessed(st.iterations());
    st.SetLabel(std::string(vocab::operations::table_build.id));
    st.counters[std::string(vocab::counters::table_intervals.name)] = static_cast<double>(cells);
    st.counters[std::string(vocab::counters::evaluations.name)] = static_cast<double>(evaluations);
  };
  benchmark::RegisterBenchmark(("u_of_s_build_case/" + name).c_str(), build)->Unit(benchmark::kMillisecond);
  const auto query = [c, o](benchmark::State& st) {
    const al::parameterization<Curve> p(*c, o);  // built once, outside the timed loop
    std::mt19937_64 rng(2024);
    std::uniform_real_distribution<double> d(0.0, p.length());
    std::vector<double> q(1024);
    for (double& x : q) x = d(rng);
    std::size_t i = 0;
    for (auto _ : st) {
      double u = p.u(q[i]);
      benchmark::DoNotOptimize(u);
      i = (i + 1) & 1023;
    }
    st.SetItemsProcessed(st.iterations());
    st.SetLabel(std::string(vocab::operations::query.id));
    st.counters[std::string(vocab::counters::table_intervals.name)] = static_cast<double>(p.table_intervals());
  };
  benchmark::RegisterBenchmark(("u_of_s_case/" + name).c_str(), query);
}

template <int Dim>
void register_case(const case_info& info, const cb::harness::sweep& w) {
  using curve = cb::any_curve<double, Dim>;
  const auto c =
      std::make_shared<const curve>(cb::io::curve_from_spec<double, Dim>(cb::io::root(info.spec, info.name)));
  // The subdivision tolerance is tol * L; any accurate L names the same setting.
  const double length = al::adaptive_length(*c).value;
  cb::harness::for_each_length_method(
      *c, w, length, [&](const vocab::method& method, const std::string& setting, auto run) {
        const std::string name = "arclength_case/" + info.name + "/" + std::string(method.id) + "/" + setting;
        // run refers to *c, which the shared pointer keeps alive for the benchmark's lifetime.
        benchmark::RegisterBenchmark(name.c_str(), [c, run](benchmark::State& st) {
          std::size_t evaluations = 0;
          for (auto _ : st) {
            const auto r = run();
            benchmark::DoNotOptimize(r.value);
            evaluations = r.evaluations;
          }
          st.SetItemsProcessed(st.iterations());
          st.SetLabel(std::string(vocab::operations::length.id));
          st.counters[std::string(vocab::counters::evaluations.name)] = static_cast<double>(evaluations);
        });
      });
  if (c->breakpoints().size() - 1 >= many_segments || info.name == baseline_case) register_table(info, c);
}

}  // namespace

int main(int argc, char** argv) {
  std::string dir = CURVEBENCH_CASES_DIR;
  bool quick_suite = false;
  std::vector<char*> rest;
  for (int i = 0; i < argc; ++i) {
    if (std::strncmp(argv[i], "--cases=", 8) == 0)
      dir = argv[i] + 8;
    else if (std::strcmp(argv[i], "--quick-suite") == 0)
      quick_suite = true;
    else
      rest.push_back(argv[i]);
  }
  int n = static_cast<int>(rest.size());
  try {
    const cb::harness::sweep w = cb::harness::settings(true);
    for (const case_info& info : cb::harness::load_cases(dir)) {
      if (quick_suite && !info.quick) continue;
      if (info.dimension == 2)
        register_case<2>(info, w);
      else if (info.dimension == 3)
        register_case<3>(info, w);
      else  // as the accuracy runner, which has no errors to join for other dimensions
        std::fprintf(stderr, "bench_arclength_cases: %s is %dD, skipped (2D and 3D cases only)\n", info.name.c_str(),
                     info.dimension);
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "bench_arclength_cases: %s\n", e.what());
    return 2;
  }
  benchmark::Initialize(&n, rest.data());
  if (benchmark::ReportUnrecognizedArguments(n, rest.data())) return 2;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
