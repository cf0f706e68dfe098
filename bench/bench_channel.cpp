// Keyframe channels: the cost of one value at one time (operation channel_value) with each time
// solver of channel/time_solver.hpp, in float and in double (bits:32, bits:64), on two channels:
// keys:64, 64 keys joined by bezier segments with random handles (time lengths 5% to 50% of the
// interval, so every segment is monotone in time), and keys:2, the CSS keyword `ease`
// (cubic-bezier(0.25, 0.1, 0.25, 1) on [0, 1]) as browsers evaluate it. calls:single evaluates
// 1024 random times one call each, calls:sorted the same times sorted through channel::evaluate;
// all evaluations are independent (throughput, not latency). Each benchmark reports, measured once
// before the timed loop, its largest error over the 1024 times in units of eps x the channel's
// value range (counter max_err_range_eps) against the same keys at 50 digits with the exact
// inversion (float keys are the double keys rounded, so the rounding of the data counts, as in a
// float runtime), and the solver's mean iterations per value (counter iterations).
// The tools' models of the 64 keys (harness/channel_models.hpp: every tool of io::all_tools that
// can hold them, each in its storage precision: glTF, Maya, Blender in float, USD) are timed with
// calls:single beside them, named by the tool (its vocabulary entry: the "tools" of
// `curvebench list vocabulary --json`).
// Names: channel_value/<solver | tool>/keys:N/bits:B/calls:<single | sorted>/timing:throughput.
#include "curvebench/channel/channel.hpp"
#include "curvebench/reference/multiprecision.hpp"

#include "harness/bench_support.hpp"
#include "harness/channel_models.hpp"

#include <benchmark/benchmark.h>

#include <algorithm>
#include <cstdint>
#include <limits>
#include <vector>

namespace {

namespace cb = curvebench;
namespace cbc = curvebench::channel;
namespace cbb = curvebench::bench;
namespace vocab = curvebench::harness::vocab;

constexpr std::size_t batch = 1024;
constexpr std::string_view family = "channel_value";

// A small deterministic generator (the data must be the same in every run).
struct lcg {
  std::uint64_t s = 0x9E3779B97F4A7C15ull;
  double next() {
    s = s * 6364136223846793005ull + 1442695040888963407ull;
    return static_cast<double>(s >> 11) * 0x1.0p-53;
  }
};

std::vector<cbc::key<double>> keys64() {
  lcg g;
  std::vector<cbc::key<double>> k(64);
  double t = 0;
  for (std::size_t i = 0; i < k.size(); ++i) {
    k[i].time = t;
    k[i].value = g.next();
    k[i].interp = cbc::interpolation::bezier;
    t += 0.5 + g.next();
  }
  for (std::size_t i = 0; i + 1 < k.size(); ++i) {
    const double h = k[i + 1].time - k[i].time;
    const double a = 0.05 + 0.45 * g.next(), c = 0.05 + 0.45 * g.next();  // a + c <= 1: monotone
    k[i].out = {a * h, (g.next() - 0.5) * 2 * a * h};
    k[i + 1].in = {-c * h, (g.next() - 0.5) * 2 * c * h};
  }
  return k;
}

std::vector<cbc::key<double>> css_ease() {
  return {{0, 0, {}, {0.25, 0.1}, cbc::interpolation::bezier}, {1, 1, {-0.75, 0}, {}, cbc::interpolation::bezier}};
}

template <class Real>
std::vector<cbc::key<Real>> keys_as(const std::vector<cbc::key<double>>& k) {
  std::vector<cbc::key<Real>> out;
  for (const auto& x : k)
    out.push_back(
        {Real(x.time), Real(x.value), {Real(x.in.dt), Real(x.in.dv)}, {Real(x.out.dt), Real(x.out.dv)}, x.interp});
  return out;
}

std::vector<double> random_times(const std::vector<cbc::key<double>>& k) {
  lcg g;
  g.s ^= 0xA5A5;
  std::vector<double> ts(batch);
  for (double& t : ts) t = k.front().time + (k.back().time - k.front().time) * g.next();
  return ts;
}

template <class Real>
void solver_benchmark(benchmark::State& state, const std::vector<cbc::key<double>>& kd, cbc::time_solver solver,
                      bool sorted) {
  const cbc::channel<Real> c(keys_as<Real>(kd), cbc::extrapolation::constant, cbc::extrapolation::constant, solver);
  std::vector<double> td = random_times(kd);
  if (sorted) std::sort(td.begin(), td.end());
  std::vector<Real> ts(td.begin(), td.end()), out(ts.size());
  {  // error and iterations, once, outside the timed loop
    const cbc::channel<cb::real50> exact(keys_as<cb::real50>(kd), cbc::extrapolation::constant,
                                         cbc::extrapolation::constant, cbc::time_solver::exact);
    double lo = 0, hi = 0, worst = 0, iterations = 0;
    for (std::size_t i = 0; i < kd.size(); ++i)
      lo = i == 0 ? kd[i].value : std::min(lo, kd[i].value), hi = i == 0 ? kd[i].value : std::max(hi, kd[i].value);
    std::vector<cb::real50> truth(ts.size());
    for (std::size_t j = 0; j < ts.size(); ++j) {
      truth[j] = exact.value(cb::real50(ts[j]));
      lo = std::min(lo, static_cast<double>(truth[j])), hi = std::max(hi, static_cast<double>(truth[j]));
    }
    const double unit = static_cast<double>(std::numeric_limits<Real>::epsilon()) * (hi - lo);
    for (std::size_t j = 0; j < ts.size(); ++j) {
      using std::abs;
      worst = std::max(worst, static_cast<double>(abs(cb::real50(c.value(ts[j])) - truth[j])) / unit);
      const std::size_t i = c.segment_at(ts[j]);
      if (ts[j] >= c.keys()[i + 1].time) continue;  // the segment's end: no inversion
      iterations += cbc::solve_time(solver, c.segment_time_cubic(i), Real(ts[j] - c.keys()[i].time)).iterations;
    }
    cbb::set_counter(state, vocab::counters::max_err_range_eps, worst);
    cbb::set_counter(state, vocab::counters::iterations, iterations / static_cast<double>(ts.size()));
  }
  for (auto _ : state) {
    if (sorted) {
      c.evaluate(ts, out);
      benchmark::DoNotOptimize(out.data());
    } else {
      for (const Real& t : ts) benchmark::DoNotOptimize(c.value(t));
    }
    benchmark::ClobberMemory();
  }
  cbb::per_operation(state, vocab::operations::channel_value, static_cast<double>(ts.size()));
}

void model_benchmark(benchmark::State& state, const curvebench::harness::channel_evaluator& at,
                     const std::vector<double>& ts) {
  for (auto _ : state)
    for (double t : ts) benchmark::DoNotOptimize(at(t));
  cbb::per_operation(state, vocab::operations::channel_value, static_cast<double>(ts.size()));
}

const int registered = [] {
  const std::vector<cbc::key<double>> k64 = keys64(), ease = css_ease();
  for (const auto* data : {&k64, &ease}) {
    const auto keys = static_cast<long long>(data->size());
    for (std::size_t s = 0; s < cbc::all_time_solvers.size(); ++s) {
      const cbc::time_solver solver = cbc::all_time_solvers[s];
      const vocab::method& m = *vocab::time_solver_methods[s];
      for (const char* calls : {"single", "sorted"}) {
        const bool sorted = calls[1] == 'o';
        // Each solver in double and in float: the same names but for bits.
        const auto add = [&](auto real, int bits) {
          using Real = decltype(real);
          cbb::register_benchmark(
              cbb::benchmark_name(family, m)
                  .arg("keys", keys)
                  .arg("bits", bits)
                  .variant(vocab::variant_keys::calls, calls)
                  .variant(vocab::variant_keys::timing, "throughput"),
              [d = *data, solver, sorted](benchmark::State& st) { solver_benchmark<Real>(st, d, solver, sorted); });
        };
        add(double{}, 64);
        add(float{}, 32);
      }
    }
  }
  nlohmann::json skipped;
  const std::vector<double> ts = random_times(k64);
  for (const auto& model : curvebench::harness::tool_models(k64, skipped))
    cbb::register_benchmark(cbb::benchmark_name(family, vocab::algorithm{model.name, "bits", ""})
                                .arg("keys", static_cast<long long>(k64.size()))
                                .arg("bits", model.storage_bits)
                                .variant(vocab::variant_keys::calls, "single")
                                .variant(vocab::variant_keys::timing, "throughput"),
                            [at = model.at, ts](benchmark::State& st) { model_benchmark(st, at, ts); });
  return 0;
}();

}  // namespace
