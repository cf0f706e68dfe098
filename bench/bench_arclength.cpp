// Arc-length methods on a smooth cubic segment (the engine every cubic spline evaluates through,
// piecewise_cubic, one segment in power form): lengths and u(s) queries, ours and peers.
// Lengths (operation length, one whole-curve length per iteration): iterations are independent of
// each other (throughput of whole lengths), each length a chain of dependent steps inside, so at
// these microsecond scales the time per length is also its latency. Fixed Gauss-Legendre with and
// without the nested estimate, adaptive G7-K15, forward-difference chord sums and their Richardson
// extrapolation, adaptive subdivision; peers Boost.Math gauss<n>, gauss_kronrod<15/31> and
// tanh_sinh on the same speed function.
// u(s) (operation query, one query per iteration cycling through 1024 random targets, independent
// of each other: throughput of single queries): the parameterization's Hermite table (with and
// without the Newton polish), its linear table, Newton from the segment bracket (through the
// parameterization and by newton_invert directly), the seed's forward-difference table searched
// with linear interpolation; peer: bisection on s(u) re-integrated from u0 each time.
// The lean power-form cubic (families arclength_lean_cubic, u_of_s_lean_cubic) separates a
// method's cost from the engine's per-call overhead (segment lookup, chain rule).
// Counters (vocabulary.hpp): evaluations per operation, rel_error (|value - L| / L against the
// 50-digit reference), estimate_rel, max_ds_rel (max |s(u(s)) - s| / L over 64 queries),
// iterations, table_intervals; all measured once outside the timed loop.
// Names: arclength/<method|peer>/<setting>:<value>, u_of_s/<method|peer>[/<setting>:<value>].
#include "curvebench/arclength/adaptive_subdivision.hpp"
#include "curvebench/arclength/forward_difference.hpp"
#include "curvebench/arclength/gauss_legendre.hpp"
#include "curvebench/arclength/length.hpp"
#include "curvebench/arclength/newton_inversion.hpp"
#include "curvebench/arclength/parameterization.hpp"
#include "curvebench/curves/piecewise_cubic.hpp"
#include "curvebench/reference/arc_length.hpp"
#include "curvebench/reference/multiprecision.hpp"

#include <benchmark/benchmark.h>
#include <boost/math/quadrature/gauss.hpp>
#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <boost/math/quadrature/tanh_sinh.hpp>

#include "harness/bench_support.hpp"
#include "harness/length_methods.hpp"  // the vocabulary entries of the length and u(s) methods

#include <array>
#include <cmath>
#include <cstdint>
#include <random>
#include <span>
#include <vector>

namespace {

namespace cb = curvebench;
namespace al = curvebench::arclength;
using R = cb::real50;

// A smooth, curved cubic segment (power coefficients, dyadic: exact in every type).
template <class Real>
cb::piecewise_cubic<Real, 2> smooth_cubic() {
  typename cb::piecewise_cubic<Real, 2>::geometry_type g;
  g << Real(0), Real(0), Real(1), Real(2), Real(3), Real(-1), Real(-2), Real(0.5);
  return cb::piecewise_cubic<Real, 2>::from_power({Real(0), Real(1)}, {g});
}

// The same segment as a lean curve type (Horner on power coefficients, domain check only):
// separates the method's cost from the engine's per-call overhead (segment lookup, chain rule).
struct power_cubic {
  using real_type = double;
  using point_type = cb::point<double, 2>;
  static constexpr int dimension = 2;
  std::array<point_type, 4> a{point_type(0, 0), point_type(1, 2), point_type(3, -1), point_type(-2, 0.5)};
  std::array<double, 2> breaks{0.0, 1.0};
  [[nodiscard]] cb::interval<double> domain() const { return {0.0, 1.0}; }
  [[nodiscard]] std::span<const double> breakpoints() const { return breaks; }
  [[nodiscard]] point_type operator()(double u) const { return derivative(u, 0); }
  [[nodiscard]] point_type derivative(double u, int order) const {
    cb::check_parameter(u, domain());
    switch (order) {
      case 0: return a[0] + u * (a[1] + u * (a[2] + u * a[3]));
      case 1: return a[1] + u * (2.0 * a[2] + u * (3.0 * a[3]));
      case 2: return 2.0 * a[2] + (6.0 * u) * a[3];
      case 3: return 6.0 * a[3];
      default: return point_type::Zero();
    }
  }
};
static_assert(cb::curve<power_cubic>);

const cb::piecewise_cubic<double, 2>& curve() {
  static const auto c = smooth_cubic<double>();
  return c;
}
const cb::reference::reference_arc_length<cb::piecewise_cubic<R, 2>>& reference() {
  static const cb::reference::reference_arc_length<cb::piecewise_cubic<R, 2>> r(smooth_cubic<R>());
  return r;
}
double rel_error(double value) {
  const R L = reference().length();
  return static_cast<double>(abs(R(value) - L) / L);
}

// Query set: 1024 arc lengths, random in [0, L]; errors are measured on the first 64 of them.
const std::vector<double>& queries() {
  static const std::vector<double> q = [] {
    std::mt19937_64 rng(2024);
    const double L = static_cast<double>(reference().length());
    std::uniform_real_distribution<double> d(0.0, L);
    std::vector<double> v(1024);
    for (auto& x : v) x = d(rng);
    return v;
  }();
  return q;
}
// max |s_ref(u(s)) - s| / L over the first 64 queries.
template <class F>
double max_ds_rel(F&& u_of_s) {
  R worst(0);
  const R L = reference().length();
  for (std::size_t i = 0; i < 64; ++i) {
    const double s = queries()[i];
    const double u = u_of_s(s);
    worst = std::max(worst, R(abs(reference().s(R(u)) - R(s))));
  }
  return static_cast<double>(worst / L);
}

// Keeps a result alive through its address: GCC 12 with this Google Benchmark's
// DoNotOptimize(double&) ("+m,r" constraint) was seen to corrupt the double it protects.
template <class T>
void keep(T& x) {
  T* p = &x;
  benchmark::DoNotOptimize(p);
  benchmark::ClobberMemory();
}

namespace vocab = curvebench::harness::vocab;
namespace methods = vocab::methods;
namespace peers = vocab::peers;
namespace ops = vocab::operations;
namespace ctr = vocab::counters;
using curvebench::bench::benchmark_name;
using curvebench::bench::per_operation;
using curvebench::bench::register_benchmark;
using curvebench::bench::set_counter;

auto speed_fn() {
  return [](double u) { return al::speed(curve(), u); };
}

// ---- lengths: one length per iteration ----

template <class C>
void gauss_length(benchmark::State& state, const C& c, int n, al::fixed_estimate estimate) {
  const auto& rule = al::gauss_legendre<double>(n);
  al::quadrature_result<double> r;
  for (auto _ : state) {
    r = al::gauss_length(c, rule, estimate);
    keep(r);
  }
  per_operation(state, ops::length, 1);
  set_counter(state, ctr::evaluations, static_cast<double>(r.evaluations));
  set_counter(state, ctr::rel_error, rel_error(r.value));
  if (estimate == al::fixed_estimate::nested) set_counter(state, ctr::estimate_rel, r.error_estimate / r.value);
}

void adaptive_gk(benchmark::State& state, double tol) {
  al::adaptive_options<double> opt;
  opt.relative_tolerance = tol;
  al::quadrature_result<double> r;
  for (auto _ : state) {
    r = al::adaptive_length(curve(), opt);
    keep(r);
  }
  per_operation(state, ops::length, 1);
  set_counter(state, ctr::evaluations, static_cast<double>(r.evaluations));
  set_counter(state, ctr::rel_error, rel_error(r.value));
  set_counter(state, ctr::estimate_rel, r.error_estimate / r.value);
}

// The table is built inside the timed loop: a length by chord sums pays for its table.
void chord_sums(benchmark::State& state, std::size_t steps, bool richardson) {
  double v = 0;
  std::size_t evals = 0;
  for (auto _ : state) {
    const al::forward_difference_table<double> t(curve(), steps);
    v = richardson ? t.richardson_length().value : t.length().value;
    evals = t.evaluations();
    keep(v);
  }
  per_operation(state, ops::length, 1);
  set_counter(state, ctr::evaluations, static_cast<double>(evals));
  set_counter(state, ctr::rel_error, rel_error(v));
}

void subdivision(benchmark::State& state, double tol) {
  al::subdivision_options<double> opt;
  opt.tolerance = tol;
  opt.relative_tolerance = 0;  // absolute, as the benchmark names it
  al::quadrature_result<double> r;
  for (auto _ : state) {
    r = al::subdivision_length(curve(), opt);
    keep(r);
  }
  per_operation(state, ops::length, 1);
  set_counter(state, ctr::evaluations, static_cast<double>(r.evaluations));
  set_counter(state, ctr::rel_error, rel_error(r.value));
}

/// Boost's fixed N-point Gauss rule on the speed f over [0, 1].
template <unsigned N, class F>
void boost_gauss(benchmark::State& state, const F& f) {
  double v = 0;
  for (auto _ : state) {
    v = boost::math::quadrature::gauss<double, N>::integrate(f, 0.0, 1.0);
    keep(v);
  }
  per_operation(state, ops::length, 1);
  set_counter(state, ctr::evaluations, N);
  set_counter(state, ctr::rel_error, rel_error(v));
}

template <unsigned N>
void boost_gauss_kronrod(benchmark::State& state, double tol) {
  const auto f = speed_fn();
  std::size_t evals = 0;
  auto counted = [&](double u) {
    ++evals;
    return f(u);
  };
  double v = 0;
  for (auto _ : state) {
    evals = 0;
    v = boost::math::quadrature::gauss_kronrod<double, N>::integrate(counted, 0.0, 1.0, 15, tol);
    keep(v);
  }
  per_operation(state, ops::length, 1);
  set_counter(state, ctr::evaluations, static_cast<double>(evals));
  set_counter(state, ctr::rel_error, rel_error(v));
}

void boost_tanh_sinh(benchmark::State& state, double tol) {
  const auto f = speed_fn();
  boost::math::quadrature::tanh_sinh<double> ts;  // Boost 1.74's integrate is not const
  std::size_t evals = 0;
  auto counted = [&](double u) {
    ++evals;
    return f(u);
  };
  double v = 0;
  for (auto _ : state) {
    evals = 0;
    v = ts.integrate(counted, 0.0, 1.0, tol);
    keep(v);
  }
  per_operation(state, ops::length, 1);
  set_counter(state, ctr::evaluations, static_cast<double>(evals));
  set_counter(state, ctr::rel_error, rel_error(v));
}

// ---- u(s): one query per iteration, cycling through the 1024 targets ----

template <class Solve>
void queries_loop(benchmark::State& state, const Solve& solve) {
  const auto& q = queries();
  std::size_t i = 0;
  for (auto _ : state) {
    auto u = solve(q[i]);
    keep(u);
    i = (i + 1) & 1023;
  }
  per_operation(state, ops::query, 1);
}

using param_type = al::parameterization<cb::piecewise_cubic<double, 2>>;

// Newton's relative tolerance in the u(s) benchmarks (|ds| + bound <= tol L).
constexpr double newton_tol = 1e-13;

void u_of_s_param(benchmark::State& state, const al::parameterization_options<double>& opt) {
  const param_type p(curve(), opt);
  queries_loop(state, [&](double s) { return p.u(s, opt.method); });
  set_counter(state, ctr::max_ds_rel, max_ds_rel([&](double s) { return p.u(s, opt.method); }));
  if (opt.method == al::inversion_method::newton) {
    double evals = 0;
    for (std::size_t k = 0; k < 64; ++k) evals += static_cast<double>(p.invert(queries()[k], opt.method).evaluations);
    set_counter(state, ctr::evaluations, evals / 64);
  } else {
    set_counter(state, ctr::table_intervals, static_cast<double>(p.table_intervals()));
  }
}

// Newton without a table, by newton_invert: segment lengths and their length prefix (32 bounded
// sub-panel lengths per segment, as parameterization's newton method builds them) precomputed, then
// one solve per query.
template <class C>
void newton_direct(benchmark::State& state, const C& c) {
  const al::segment_lengths<double> seg(c, al::segment_lengths<double>::default_options(),
                                        al::segment_lengths<double>::newton_prefix_panels);
  al::newton_options<double> opt;
  opt.relative_tolerance = newton_tol;
  queries_loop(state, [&](double s) { return al::newton_invert(c, seg, s, opt); });
  double evals = 0, iters = 0;
  for (std::size_t k = 0; k < 64; ++k) {
    const auto r = al::newton_invert(c, seg, queries()[k], opt);
    evals += static_cast<double>(r.evaluations);
    iters += r.iterations;
  }
  set_counter(state, ctr::evaluations, evals / 64);
  set_counter(state, ctr::iterations, iters / 64);
  set_counter(state, ctr::max_ds_rel, max_ds_rel([&](double s) { return al::newton_invert(c, seg, s, opt).u; }));
}

// Peer (common practice): bisection on s(u) = GL-16 integral from u0 each time, to |du| < 1e-15,
// or, given a relative tolerance (rel_tol > 0, the row paired with Newton at the same tol), until
// |s(mid) - s| <= rel_tol L as well.
void bisection_full_reintegration(benchmark::State& state, double rel_tol = 0) {
  const auto& rule = al::gauss_legendre<double>(16);
  const auto f = speed_fn();
  const double tol = rel_tol * static_cast<double>(reference().length());
  std::size_t evals = 0;
  auto solve = [&](double s) {
    double lo = 0, hi = 1;
    while (hi - lo > 1e-15) {
      const double mid = 0.5 * (lo + hi);
      evals += 16;
      const double sm = rule.integrate(f, 0.0, mid);
      if (tol > 0 && std::abs(sm - s) <= tol) return mid;
      if (sm < s)
        lo = mid;
      else
        hi = mid;
    }
    return 0.5 * (lo + hi);
  };
  queries_loop(state, solve);
  evals = 0;
  set_counter(state, ctr::max_ds_rel, max_ds_rel(solve));
  set_counter(state, ctr::evaluations, static_cast<double>(evals) / 64);
}

// Seed 002's table (forward differencing, N steps), binary search + linear interpolation; its
// lengths are rescaled to the reference so that only the inversion's error is measured.
void forward_difference_u(benchmark::State& state, std::size_t steps) {
  const al::forward_difference_table<double> t(curve(), steps);
  const double scale = t.arc_lengths().back() / static_cast<double>(reference().length());
  queries_loop(state, [&](double s) { return t.u(s * scale); });
  set_counter(state, ctr::max_ds_rel, max_ds_rel([&](double s) { return t.u(s * scale); }));
}

// ---- registration ----

const bool registered = [] {
  const auto none = std::string_view("none"), nested = std::string_view("nested");
  for (int n : {4, 6, 8, 10, 12, 14, 16, 20, 24})
    register_benchmark(
        benchmark_name("arclength", methods::gauss).arg("n", n).variant(vocab::variant_keys::estimate, none),
        [n](benchmark::State& s) { gauss_length(s, curve(), n, al::fixed_estimate::none); });
  for (int n : {4, 8})
    register_benchmark(
        benchmark_name("arclength", methods::gauss).arg("n", n).variant(vocab::variant_keys::estimate, nested),
        [n](benchmark::State& s) { gauss_length(s, curve(), n, al::fixed_estimate::nested); });
  for (double tol : {1e-6, 1e-10, 1e-13})
    register_benchmark(benchmark_name("arclength", methods::adaptive_gk).arg("tol", tol),
                       [tol](benchmark::State& s) { adaptive_gk(s, tol); });
  for (std::size_t steps = 16; steps <= 4096; steps *= 4) {
    register_benchmark(benchmark_name("arclength", methods::forward_difference).arg("steps", steps),
                       [steps](benchmark::State& s) { chord_sums(s, steps, false); });
    register_benchmark(benchmark_name("arclength", methods::richardson).arg("steps", steps),
                       [steps](benchmark::State& s) { chord_sums(s, steps, true); });
  }
  for (double tol : {1e-4, 1e-6, 1e-8})
    register_benchmark(benchmark_name("arclength", methods::subdivision).arg("tol", tol),
                       [tol](benchmark::State& s) { subdivision(s, tol); });
  const auto boost_n = [](int n) { return benchmark_name("arclength", peers::boost_gauss).arg("n", n); };
  register_benchmark(boost_n(7), [](benchmark::State& s) { boost_gauss<7>(s, speed_fn()); });
  register_benchmark(boost_n(10), [](benchmark::State& s) { boost_gauss<10>(s, speed_fn()); });
  register_benchmark(boost_n(15), [](benchmark::State& s) { boost_gauss<15>(s, speed_fn()); });
  register_benchmark(boost_n(20), [](benchmark::State& s) { boost_gauss<20>(s, speed_fn()); });
  for (double tol : {1e-10, 1e-13}) {
    register_benchmark(benchmark_name("arclength", peers::boost_gauss_kronrod15).arg("tol", tol),
                       [tol](benchmark::State& s) { boost_gauss_kronrod<15>(s, tol); });
    register_benchmark(benchmark_name("arclength", peers::boost_gauss_kronrod31).arg("tol", tol),
                       [tol](benchmark::State& s) { boost_gauss_kronrod<31>(s, tol); });
    register_benchmark(benchmark_name("arclength", peers::boost_tanh_sinh).arg("tol", tol),
                       [tol](benchmark::State& s) { boost_tanh_sinh(s, tol); });
  }

  // The lean power-form cubic: ours and Boost's rule on the same integrand, and Newton's u(s).
  for (int n : {12, 16, 20})
    register_benchmark(
        benchmark_name("arclength_lean_cubic", methods::gauss).arg("n", n).variant(vocab::variant_keys::estimate, none),
        [n](benchmark::State& s) { gauss_length(s, power_cubic{}, n, al::fixed_estimate::none); });
  const auto lean = [](double u) { return al::speed(power_cubic{}, u); };
  const auto lean_n = [](int n) { return benchmark_name("arclength_lean_cubic", peers::boost_gauss).arg("n", n); };
  register_benchmark(lean_n(10), [lean](benchmark::State& s) { boost_gauss<10>(s, lean); });
  register_benchmark(lean_n(15), [lean](benchmark::State& s) { boost_gauss<15>(s, lean); });
  register_benchmark(lean_n(20), [lean](benchmark::State& s) { boost_gauss<20>(s, lean); });
  register_benchmark(benchmark_name("u_of_s_lean_cubic", methods::newton).arg("tol", newton_tol),
                     [](benchmark::State& s) { newton_direct(s, power_cubic{}); });

  // u(s) through the parameterization (the API users call), each method with its options.
  al::parameterization_options<double> hermite;
  register_benchmark(benchmark_name("u_of_s", methods::hermite_table),
                     [hermite](benchmark::State& s) { u_of_s_param(s, hermite); });
  al::parameterization_options<double> polished;
  polished.newton_polish = true;
  polished.table_intervals = 256;
  register_benchmark(benchmark_name("u_of_s", methods::hermite_table_polished).arg("M", polished.table_intervals),
                     [polished](benchmark::State& s) { u_of_s_param(s, polished); });
  al::parameterization_options<double> linear;
  linear.method = al::inversion_method::linear_table;
  linear.table_intervals = 4096;
  register_benchmark(benchmark_name("u_of_s", methods::linear_table).arg("M", linear.table_intervals),
                     [linear](benchmark::State& s) { u_of_s_param(s, linear); });
  al::parameterization_options<double> newton;
  newton.method = al::inversion_method::newton;
  newton.newton.relative_tolerance = newton_tol;
  register_benchmark(benchmark_name("u_of_s", methods::newton).arg("tol", newton_tol),
                     [newton](benchmark::State& s) { u_of_s_param(s, newton); });
  // The same Newton solve called directly (no parameterization object).
  register_benchmark(benchmark_name("u_of_s", methods::newton)
                         .arg("tol", newton_tol)
                         .variant(vocab::variant_keys::api, "newton_invert"),
                     [](benchmark::State& s) { newton_direct(s, curve()); });
  for (std::size_t steps : {std::size_t(256), std::size_t(4096)})
    register_benchmark(benchmark_name("u_of_s", methods::forward_difference).arg("steps", steps),
                       [steps](benchmark::State& s) { forward_difference_u(s, steps); });
  register_benchmark(benchmark_name("u_of_s", peers::bisection_reintegration),
                     [](benchmark::State& s) { bisection_full_reintegration(s); });
  // Newton and the peer at the same tolerances (paired in the report by the setting tol); 1e-12 L
  // is the target for Newton without a table.
  al::parameterization_options<double> newton12 = newton;
  newton12.newton.relative_tolerance = 1e-12;
  register_benchmark(benchmark_name("u_of_s", methods::newton).arg("tol", 1e-12),
                     [newton12](benchmark::State& s) { u_of_s_param(s, newton12); });
  for (double tol : {1e-12, newton_tol})
    register_benchmark(benchmark_name("u_of_s", peers::bisection_reintegration).arg("tol", tol),
                       [tol](benchmark::State& s) { bisection_full_reintegration(s, tol); });
  return true;
}();

}  // namespace
