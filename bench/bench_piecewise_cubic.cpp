// piecewise_cubic engine: speed of the three evaluation algorithms (power-coefficient Horner,
// matrix form T·M·G per call, Bezier form by de Casteljau) for single random parameters and for
// batches of 1024 (unsorted: one lookup each; sorted: the segment-walking fast path), on uniform
// knots (O(1) lookup) and non-uniform knots (bucket index), beside floors timed in the same run:
//   floor_horner        the simplest correct single evaluation: a flat coefficient array, the O(1)
//                       uniform index (std::upper_bound on other knots), t = (u - u_i) fl(1 / h_i)
//                       (the engine's local parameter, within 4 u), Horner, no checks;
//   floor_soa_sorted    a sorted batch with each segment's coefficients hoisted and the coordinates
//                       in separate arrays (SoA), one branch-free loop per segment;
//   floor_store_stream  a store-only stream of the batch's output bytes: the memory bound, timed at
//                       1024 points (in cache) and at 1e6 points (24 MB in double: memory-bound).
// Operation evaluation: one per iteration for single calls, the batch size for a batch, so the
// report's time per evaluation compares single calls, batches and floors directly.
// timing:throughput: the parameters are fixed in advance, the evaluations independent;
// timing:latency: each parameter is the next fixed one plus 0 x the previous result's first
// coordinate (the compiler cannot drop it), a dependent chain timing lookup + t + Horner end to end.
// Counters: flops, the kernel's arithmetic per evaluation counted by hand (t: 2; power Horner 6 per
// coordinate; matrix T·M 28 + 2 for t^2, t^3 + 7 per coordinate; de Casteljau 1 + 18 per
// coordinate); max_err_eps, the maximum error of the outputs the timed path produced (every
// output up to 4096, else a stride through them) against the real50 engine of the same data, in
// units of eps(double) times the data scale (also for float, so the two precisions read on one
// scale), measured after the timed loop. The sorted power path is also checked bit for bit against
// single calls there: a mismatch fails the benchmark.
// Names: piecewise_cubic/<algorithm>/calls:<single|batch|sorted>/timing:<throughput|latency>/
//        segments:<n>/knots:<uniform|nonuniform>[/real:float][/points:1000000].
#include "curvebench/curves/piecewise_cubic.hpp"
#include "curvebench/reference/multiprecision.hpp"

#include "harness/bench_support.hpp"

#include <benchmark/benchmark.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <initializer_list>
#include <limits>
#include <map>
#include <memory>
#include <random>
#include <string_view>
#include <type_traits>
#include <utility>
#include <vector>

namespace {

namespace cb = curvebench;
namespace vocab = curvebench::harness::vocab;
constexpr int dim = 3;

template <class Real>
struct test_data {
  std::vector<Real> knots;
  cb::point_list<Real, dim> values, slopes;
};

// Random Hermite data (values and slopes in [-1, 1]) on n segments; non-uniform knots have
// intervals in [0.25, 1.75]. Cast to Real (float: rounded once), then widened exactly to real50 for
// the reference, so the error counters measure evaluation, not the rounding of the data.
template <class Real>
test_data<Real> make_data(std::size_t n, bool uniform) {
  std::mt19937_64 rng(12345);
  std::uniform_real_distribution<double> coord(-1.0, 1.0), step(0.25, 1.75);
  test_data<Real> d;
  d.knots = uniform ? cb::uniform_knots<Real>(n) : std::vector<Real>{Real(0)};
  for (std::size_t i = 0; i <= n; ++i) {
    if (!uniform && i > 0) d.knots.push_back(d.knots.back() + Real(step(rng)));
    d.values.emplace_back(Real(coord(rng)), Real(coord(rng)), Real(coord(rng)));
    d.slopes.emplace_back(Real(coord(rng)), Real(coord(rng)), Real(coord(rng)));
  }
  return d;
}

template <class Real>
std::vector<Real> random_parameters(const cb::interval<Real>& dom, std::size_t count, bool sorted) {
  std::mt19937_64 rng(987);
  std::uniform_real_distribution<double> u(static_cast<double>(dom.lo), static_cast<double>(dom.hi));
  std::vector<Real> us(count);
  for (auto& x : us) x = std::clamp(Real(u(rng)), dom.lo, dom.hi);
  if (sorted) std::sort(us.begin(), us.end());
  return us;
}

template <class Real>
struct fixture {
  cb::piecewise_cubic<Real, dim> curve;
  cb::piecewise_cubic<cb::real50, dim> reference;
};

template <class Real>
fixture<Real> make_fixture(std::size_t n, bool uniform) {
  const auto d = make_data<Real>(n, uniform);
  std::vector<cb::real50> k50(d.knots.begin(), d.knots.end());
  return {cb::piecewise_cubic<Real, dim>::from_hermite(d.knots, d.values, d.slopes, d.slopes),
          cb::piecewise_cubic<cb::real50, dim>::from_hermite(k50, cb::points_cast<cb::real50, Real, dim>(d.values),
                                                             cb::points_cast<cb::real50, Real, dim>(d.slopes),
                                                             cb::points_cast<cb::real50, Real, dim>(d.slopes))};
}

// The fixture of (n, uniform), built once per program: the real50 engine of 4096 segments takes
// seconds, and Google Benchmark calls a benchmark once per repetition.
template <class Real>
const fixture<Real>& cached_fixture(std::size_t n, bool uniform) {
  static std::map<std::pair<std::size_t, bool>, std::unique_ptr<fixture<Real>>> cache;
  auto& slot = cache[{n, uniform}];
  if (!slot) slot = std::make_unique<fixture<Real>>(make_fixture<Real>(n, uniform));
  return *slot;
}

// Max |got(u_k) - real50(u_k)| over (a stride of at most 4096 of) the outputs, in eps(double) units
// of the data scale (values and slopes <= 1, intervals <= 1.75: geometry items <= 1.75).
template <class Real, class Got>
double max_error(const cb::piecewise_cubic<cb::real50, dim>& ref, const std::vector<Real>& us, Got&& got) {
  cb::real50 worst(0);
  const std::size_t stride = std::max<std::size_t>(1, us.size() / 4096);
  for (std::size_t k = 0; k < us.size(); k += stride) {
    const auto r = ref.evaluate(cb::real50(us[k]), 0, cb::cubic_algorithm::power);
    for (int d = 0; d < dim; ++d) {
      using std::abs;
      worst = std::max(worst, cb::real50(abs(cb::real50(got(k, d)) - r[d])));
    }
  }
  return static_cast<double>(worst / (cb::real50(std::numeric_limits<double>::epsilon()) * cb::real50(1.75)));
}

// ---- the floors: hand-written kernels on plain arrays taken from the engine ------------------

template <class Real>
struct floor_kernel {
  std::vector<Real> knots, rcp_h;              // rcp_h[i] = fl(1 / h_i)
  std::vector<Real> coef;                      // AoS: coef[(4 i + j) dim + d]
  std::array<std::vector<Real>, 4 * dim> soa;  // SoA: soa[j dim + d][i]
  bool uniform = false;
  Real u0{}, inv_h{};
  std::size_t last = 0;

  explicit floor_kernel(const cb::piecewise_cubic<Real, dim>& c) {
    const auto k = c.knots();
    knots.assign(k.begin(), k.end());
    const std::size_t n = c.segment_count();
    last = n - 1;
    for (std::size_t i = 0; i < n; ++i) {
      rcp_h.push_back(Real(1) / (knots[i + 1] - knots[i]));
      for (std::size_t j = 0; j < 4; ++j)
        for (int d = 0; d < dim; ++d) {
          coef.push_back(c.power_coefficients(i)[j][d]);
          soa[j * dim + static_cast<std::size_t>(d)].push_back(c.power_coefficients(i)[j][d]);
        }
    }
    uniform = c.uniform();
    u0 = knots.front();
    inv_h = Real(static_cast<long long>(n)) / (knots.back() - knots.front());
  }

  [[nodiscard]] std::size_t segment(Real u) const {
    if (uniform) {
      const Real x = (u - u0) * inv_h;
      return x < Real(static_cast<long long>(last)) ? static_cast<std::size_t>(x) : last;
    }
    return static_cast<std::size_t>(std::upper_bound(knots.begin() + 1, knots.end() - 1, u) - knots.begin()) - 1;
  }

  [[nodiscard]] cb::point<Real, dim> operator()(Real u) const {
    const std::size_t i = segment(u);
    const Real t = (u - knots[i]) * rcp_h[i];
    const Real* a = coef.data() + 4 * dim * i;
    cb::point<Real, dim> p;
    for (int d = 0; d < dim; ++d) p[d] = a[d] + t * (a[dim + d] + t * (a[2 * dim + d] + t * a[3 * dim + d]));
    return p;
  }

  // Sorted parameters to SoA outputs x[d][k]: per segment, its run of parameters, coefficients hoisted.
  void sorted(const Real* us, std::size_t count, std::array<Real*, dim> x) const {
    std::size_t k = 0, i = segment(us[0]);
    while (k < count) {
      std::size_t e = count;
      if (i < last) {
        e = k;
        while (e < count && us[e] < knots[i + 1]) ++e;
      }
      const Real ui = knots[i], ri = rcp_h[i];
      Real a[4][dim];
      for (std::size_t j = 0; j < 4; ++j)
        for (int d = 0; d < dim; ++d) a[j][d] = soa[j * dim + static_cast<std::size_t>(d)][i];
      for (std::size_t m = k; m < e; ++m) {
        const Real t = (us[m] - ui) * ri;
        for (int d = 0; d < dim; ++d)
          x[static_cast<std::size_t>(d)][m] = a[0][d] + t * (a[1][d] + t * (a[2][d] + t * a[3][d]));
      }
      k = e;
      if (k < count)
        while (i < last && !(us[k] < knots[i + 1])) ++i;
    }
  }
};

static_assert(sizeof(cb::point<double, dim>) == dim * sizeof(double) &&
                  sizeof(cb::point<float, dim>) == dim * sizeof(float),
              "floor_store_stream writes the bytes of the points as one array of coordinates");

enum class mode { single, batch, sorted };
enum class impl { engine, floor_horner, floor_soa_sorted, floor_store_stream };

constexpr double flops_per_evaluation(impl kind, cb::cubic_algorithm alg) {
  if (kind == impl::floor_store_stream) return 0;
  switch (alg) {
    case cb::cubic_algorithm::power: return 2 + 6 * dim;
    case cb::cubic_algorithm::matrix: return 32 + 7 * dim;
    case cb::cubic_algorithm::bezier: return 3 + 18 * dim;
  }
  return 0;
}

struct config {
  std::size_t segments;
  bool uniform;
  bool latency;
  std::size_t points;  // the batch (and the pool single calls cycle through)
};

template <class Real, impl Kind, cb::cubic_algorithm Alg, mode Mode>
void evaluate(benchmark::State& state, config cfg) {
  const auto& f = cached_fixture<Real>(cfg.segments, cfg.uniform);
  const auto us = random_parameters(f.curve.domain(), cfg.points, Mode == mode::sorted);
  const floor_kernel<Real> fk(f.curve);
  std::vector<cb::point<Real, dim>> out(Mode == mode::single || Kind == impl::floor_store_stream ? 0 : us.size());
  std::array<std::vector<Real>, dim> soa_out;
  for (auto& v : soa_out) v.resize(Kind == impl::floor_soa_sorted ? us.size() : 0);
  std::vector<cb::point<Real, dim>> single_out(Mode == mode::single ? us.size() : 0);
  std::vector<Real> flat(Kind == impl::floor_store_stream ? us.size() * dim : 0);
  std::size_t k = 0;
  const std::size_t n = us.size();

  auto one = [&](Real u) {
    if constexpr (Kind == impl::engine)
      return f.curve.evaluate(u, 0, Alg);
    else
      return fk(u);
  };

  if constexpr (Mode == mode::single) {
    if (cfg.latency) {
      Real carry(0);
      for (auto _ : state) {
        const auto p = one(us[k] + carry);
        carry = p[0] * Real(0);
        k = k + 1 == n ? 0 : k + 1;
      }
      benchmark::DoNotOptimize(carry);
    } else {
      for (auto _ : state) {
        auto p = one(us[k]);
        benchmark::DoNotOptimize(p);
        k = k + 1 == n ? 0 : k + 1;
      }
    }
    for (std::size_t j = 0; j < n; ++j) single_out[j] = one(us[j]);
  } else {
    for (auto _ : state) {
      if constexpr (Kind == impl::floor_store_stream) {
        // The output's bytes (no padding in a point: asserted above) as one array of Real.
        std::fill(flat.begin(), flat.end(), Real(0.5));
        benchmark::DoNotOptimize(flat.data());
      } else if constexpr (Kind == impl::floor_soa_sorted) {
        fk.sorted(us.data(), n, {soa_out[0].data(), soa_out[1].data(), soa_out[2].data()});
        benchmark::DoNotOptimize(soa_out[0].data());
      } else if constexpr (Mode == mode::batch) {
        f.curve.evaluate_batch(us, out, 0, Alg);
      } else {
        f.curve.evaluate_sorted(us, out, 0, Alg);
      }
      benchmark::DoNotOptimize(out.data());
      benchmark::ClobberMemory();  // once per batch: the stores must happen
    }
  }
  curvebench::bench::per_operation(state, vocab::operations::evaluation,
                                   Mode == mode::single ? 1.0 : static_cast<double>(n));
  curvebench::bench::set_counter(state, vocab::counters::flops, flops_per_evaluation(Kind, Alg));
  if constexpr (Kind == impl::floor_store_stream) return;
  double err = 0;
  if constexpr (Mode == mode::single) {
    err = max_error(f.reference, us, [&](std::size_t j, int d) { return single_out[j][d]; });
  } else if constexpr (Kind == impl::floor_soa_sorted) {
    err = max_error(f.reference, us, [&](std::size_t j, int d) { return soa_out[static_cast<std::size_t>(d)][j]; });
  } else {
    err = max_error(f.reference, us, [&](std::size_t j, int d) { return out[j][d]; });
    if (Mode == mode::sorted && Alg == cb::cubic_algorithm::power)
      for (std::size_t j = 0; j < n; ++j)
        if (!(out[j] == f.curve(us[j]))) {
          state.SkipWithError("evaluate_sorted differs from single evaluation");
          return;
        }
  }
  curvebench::bench::set_counter(state, vocab::counters::max_err_eps, err);
}

using cb::cubic_algorithm;

template <class Real, impl Kind, cubic_algorithm Alg, mode Mode>
void add(const vocab::algorithm& id, std::string_view calls, bool latency, std::initializer_list<std::size_t> segments,
         std::size_t points = 1024) {
  for (std::size_t n : segments)
    for (bool uniform : {true, false}) {
      auto name = curvebench::bench::benchmark_name("piecewise_cubic", id);
      name.variant(vocab::variant_keys::calls, calls)
          .variant(vocab::variant_keys::timing, latency ? "latency" : "throughput")
          .arg("segments", n)
          .arg("knots", uniform ? "uniform" : "nonuniform");
      if constexpr (std::is_same_v<Real, float>) name.arg("real", "float");
      if (points != 1024) name.arg("points", points);
      const config cfg{n, uniform, latency, points};
      curvebench::bench::register_benchmark(name,
                                            [cfg](benchmark::State& s) { evaluate<Real, Kind, Alg, Mode>(s, cfg); });
    }
}

const bool registered = [] {
  namespace a = vocab::algorithms;
  constexpr auto power = cubic_algorithm::power, matrix = cubic_algorithm::matrix, bezier = cubic_algorithm::bezier;
  constexpr auto E = impl::engine;
  const auto all = {std::size_t{8}, std::size_t{64}, std::size_t{4096}};
  // double: the engine's three algorithms in the three call patterns, throughput.
  add<double, E, power, mode::single>(a::power, "single", false, all);
  add<double, E, matrix, mode::single>(a::matrix, "single", false, all);
  add<double, E, bezier, mode::single>(a::bezier, "single", false, all);
  add<double, E, power, mode::batch>(a::power, "batch", false, all);
  add<double, E, matrix, mode::batch>(a::matrix, "batch", false, all);
  add<double, E, bezier, mode::batch>(a::bezier, "batch", false, all);
  add<double, E, power, mode::sorted>(a::power, "sorted", false, all);
  add<double, E, matrix, mode::sorted>(a::matrix, "sorted", false, all);
  add<double, E, bezier, mode::sorted>(a::bezier, "sorted", false, all);
  // double: latency, and the floors.
  add<double, E, power, mode::single>(a::power, "single", true, all);
  add<double, impl::floor_horner, power, mode::single>(a::floor_horner, "single", false, all);
  add<double, impl::floor_horner, power, mode::single>(a::floor_horner, "single", true, all);
  add<double, impl::floor_soa_sorted, power, mode::sorted>(a::floor_soa_sorted, "sorted", false, all);
  add<double, impl::floor_store_stream, power, mode::sorted>(a::floor_store_stream, "sorted", false, all);
  // 1e6 sorted points (24 MB out): the memory-bound case against the store-only stream.
  const auto one_size = {std::size_t{64}};
  add<double, E, power, mode::sorted>(a::power, "sorted", false, one_size, 1000000);
  add<double, impl::floor_soa_sorted, power, mode::sorted>(a::floor_soa_sorted, "sorted", false, one_size, 1000000);
  add<double, impl::floor_store_stream, power, mode::sorted>(a::floor_store_stream, "sorted", false, one_size, 1000000);
  // float: the hot paths and their floors.
  const auto hot = {std::size_t{64}, std::size_t{4096}};
  add<float, E, power, mode::single>(a::power, "single", false, hot);
  add<float, E, power, mode::single>(a::power, "single", true, hot);
  add<float, E, power, mode::sorted>(a::power, "sorted", false, hot);
  add<float, impl::floor_horner, power, mode::single>(a::floor_horner, "single", false, hot);
  add<float, impl::floor_horner, power, mode::single>(a::floor_horner, "single", true, hot);
  add<float, impl::floor_soa_sorted, power, mode::sorted>(a::floor_soa_sorted, "sorted", false, hot);
  add<float, impl::floor_store_stream, power, mode::sorted>(a::floor_store_stream, "sorted", false, hot);
  return true;
}();

}  // namespace
