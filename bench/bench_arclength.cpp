// Arc-length methods: speed and accuracy on a smooth cubic segment (the engine every cubic spline
// evaluates through, piecewise_cubic, one segment in power form), and u(s) queries.
// Lengths: fixed Gauss-Legendre (n points), nested fixed rule, our adaptive G7-K15, the
// forward-difference table and its Richardson extrapolation, Parent's adaptive subdivision; peers
// Boost.Math gauss<n>, gauss_kronrod<15/31> (adaptive) and tanh_sinh on the same speed function.
// u(s): the parameterization's O(1) Hermite table (with and without one Newton polish), its linear
// table, Newton from the segment bracket (no table); baselines: bisection on s(u) re-integrated
// from u0 each time, and the seed's forward-difference table with binary search + linear
// interpolation. Counters: evals (curve derivative/position evaluations per operation),
// rel_error (|value - L| / L against the 50-digit reference) or max_ds_rel (max |s(u(s)) - s| / L
// over the query set, measured once outside the timed loop against the reference).
// Names: arclength/<algorithm>/<arg>:<value>.
#include "curvebench/arclength/adaptive_subdivision.hpp"
#include "curvebench/arclength/forward_difference.hpp"
#include "curvebench/arclength/gauss_legendre.hpp"
#include "curvebench/arclength/length.hpp"
#include "curvebench/arclength/newton_inversion.hpp"
#include "curvebench/arclength/parameterization.hpp"
#include "curvebench/curves/piecewise_cubic.hpp"
#include "curvebench/reference/arc_length.hpp"
#include "curvebench/reference/multiprecision.hpp"

#include <boost/math/quadrature/gauss.hpp>
#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <boost/math/quadrature/tanh_sinh.hpp>
#include <benchmark/benchmark.h>

#include <array>
#include <cmath>
#include <span>
#include <cstdint>
#include <random>
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

auto speed_fn() {
  return [](double u) { return al::speed(curve(), u); };
}

// ---- lengths ----

void gauss_legendre_length(benchmark::State& state) {
  const auto& rule = al::gauss_legendre<double>(static_cast<int>(state.range(0)));
  const auto& c = curve();
  double v = 0;
  for (auto _ : state) {
    v = al::gauss_length(c, rule).value;
    keep(v);
  }
  state.counters["evals"] = static_cast<double>(rule.n);
  state.counters["rel_error"] = rel_error(v);
}

void gauss_legendre_power_cubic(benchmark::State& state) {
  const auto& rule = al::gauss_legendre<double>(static_cast<int>(state.range(0)));
  const power_cubic c;
  double v = 0;
  for (auto _ : state) {
    v = al::gauss_length(c, rule).value;
    keep(v);
  }
  state.counters["evals"] = static_cast<double>(rule.n);
  state.counters["rel_error"] = rel_error(v);
}

void newton_power_cubic(benchmark::State& state) {
  const power_cubic c;
  const al::segment_lengths<double> seg(c);
  al::newton_options<double> opt;
  opt.relative_tolerance = std::pow(10.0, -static_cast<double>(state.range(0)));
  const auto& q = queries();
  std::size_t i = 0;
  for (auto _ : state) {
    auto r = al::newton_invert(c, seg, q[i], opt);
    keep(r);
    i = (i + 1) & 1023;
  }
  double evals = 0;
  for (std::size_t k = 0; k < 64; ++k) evals += static_cast<double>(al::newton_invert(c, seg, q[k], opt).evaluations);
  state.counters["evals"] = evals / 64;
  state.counters["max_ds_rel"] = max_ds_rel([&](double s) { return al::newton_invert(c, seg, s, opt).u; });
}

void gauss_legendre_nested(benchmark::State& state) {
  const auto& rule = al::gauss_legendre<double>(static_cast<int>(state.range(0)));
  al::quadrature_result<double> r;
  for (auto _ : state) {
    r = al::gauss_length(curve(), rule, al::fixed_estimate::nested);
    keep(r);
  }
  state.counters["evals"] = static_cast<double>(r.evaluations);
  state.counters["rel_error"] = rel_error(r.value);
  state.counters["estimate_rel"] = r.error_estimate / r.value;
}

void adaptive_gk15(benchmark::State& state) {
  al::adaptive_options<double> opt;
  opt.relative_tolerance = std::pow(10.0, -static_cast<double>(state.range(0)));
  al::quadrature_result<double> r;
  for (auto _ : state) {
    r = al::adaptive_length(curve(), opt);
    keep(r);
  }
  state.counters["evals"] = static_cast<double>(r.evaluations);
  state.counters["rel_error"] = rel_error(r.value);
  state.counters["estimate_rel"] = r.error_estimate / r.value;
}

void forward_difference(benchmark::State& state) {
  const auto steps = static_cast<std::size_t>(state.range(0));
  double v = 0, rich = 0;
  std::size_t evals = 0;
  for (auto _ : state) {
    const al::forward_difference_table<double> t(curve(), steps);
    v = t.length().value;
    rich = t.richardson_length().value;
    evals = t.evaluations();
    keep(v);
  }
  state.counters["evals"] = static_cast<double>(evals);
  state.counters["rel_error"] = rel_error(v);
  state.counters["richardson_rel_error"] = rel_error(rich);
}

void subdivision(benchmark::State& state) {
  al::subdivision_options<double> opt;
  opt.tolerance = std::pow(10.0, -static_cast<double>(state.range(0)));
  al::quadrature_result<double> r;
  for (auto _ : state) {
    r = al::subdivision_length(curve(), opt);
    keep(r);
  }
  state.counters["evals"] = static_cast<double>(r.evaluations);
  state.counters["rel_error"] = rel_error(r.value);
}

/// Boost's fixed Gauss rule on the lean power-form cubic's speed: the same integrand as
/// gauss_legendre_power_cubic, so the two are compared like for like.
/// Boost's fixed N-point Gauss rule on the speed f over [0, 1], with its evaluations and error.
template <unsigned N, class F>
void run_boost_gauss(benchmark::State& state, const F& f) {
  double v = 0;
  for (auto _ : state) {
    v = boost::math::quadrature::gauss<double, N>::integrate(f, 0.0, 1.0);
    keep(v);
  }
  state.counters["evals"] = N;
  state.counters["rel_error"] = rel_error(v);
}

template <unsigned N>
void boost_gauss_power_cubic(benchmark::State& state) {
  const power_cubic c;
  run_boost_gauss<N>(state, [&c](double u) { return al::speed(c, u); });
}

template <unsigned N>
void boost_gauss(benchmark::State& state) {
  run_boost_gauss<N>(state, speed_fn());
}

template <unsigned N>
void boost_gauss_kronrod(benchmark::State& state) {
  const auto f = speed_fn();
  const double tol = std::pow(10.0, -static_cast<double>(state.range(0)));
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
  state.counters["evals"] = static_cast<double>(evals);
  state.counters["rel_error"] = rel_error(v);
}

void boost_tanh_sinh(benchmark::State& state) {
  const auto f = speed_fn();
  const double tol = std::pow(10.0, -static_cast<double>(state.range(0)));
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
  state.counters["evals"] = static_cast<double>(evals);
  state.counters["rel_error"] = rel_error(v);
}

// ---- u(s) ----

const al::parameterization<cb::piecewise_cubic<double, 2>>& param(al::inversion_method m, bool polish) {
  static const al::parameterization<cb::piecewise_cubic<double, 2>> hermite(curve());
  static const al::parameterization<cb::piecewise_cubic<double, 2>> hermite_polish(curve(), [] {
    al::parameterization_options<double> o;
    o.newton_polish = true;
    o.table_intervals = 256;
    return o;
  }());
  static const al::parameterization<cb::piecewise_cubic<double, 2>> linear(curve(), [] {
    al::parameterization_options<double> o;
    o.method = al::inversion_method::linear_table;
    o.table_intervals = 4096;
    return o;
  }());
  static const al::parameterization<cb::piecewise_cubic<double, 2>> newton(curve(), [] {
    al::parameterization_options<double> o;
    o.method = al::inversion_method::newton;
    return o;
  }());
  if (m == al::inversion_method::newton) return newton;
  if (m == al::inversion_method::linear_table) return linear;
  return polish ? hermite_polish : hermite;
}

void u_of_s(benchmark::State& state) {
  const auto m = static_cast<al::inversion_method>(state.range(0));
  const bool polish = state.range(1) != 0;
  const auto& p = param(m, polish);
  const auto& q = queries();
  std::size_t i = 0;
  for (auto _ : state) {
    const double u = p.u(q[i], m);
    keep(u);
    i = (i + 1) & 1023;
  }
  state.counters["table_intervals"] = static_cast<double>(p.table_intervals());
  state.counters["max_ds_rel"] = max_ds_rel([&](double s) { return p.u(s, m); });
  if (m == al::inversion_method::newton) {
    double evals = 0;
    for (std::size_t k = 0; k < 64; ++k) evals += static_cast<double>(p.invert(q[k], m).evaluations);
    state.counters["evals"] = evals / 64;
  }
}

// Baseline: bisection on s(u) = GL-16 integral from u0 each time, to |du| < 1e-15.
void bisection_full_reintegration(benchmark::State& state) {
  const auto& rule = al::gauss_legendre<double>(16);
  const auto f = speed_fn();
  auto solve = [&](double s) {
    double lo = 0, hi = 1;
    while (hi - lo > 1e-15) {
      const double mid = 0.5 * (lo + hi);
      if (rule.integrate(f, 0.0, mid) < s) lo = mid; else hi = mid;
    }
    return 0.5 * (lo + hi);
  };
  const auto& q = queries();
  std::size_t i = 0;
  for (auto _ : state) {
    const double u = solve(q[i]);
    keep(u);
    i = (i + 1) & 1023;
  }
  state.counters["evals"] = 16.0 * 50;
  state.counters["max_ds_rel"] = max_ds_rel(solve);
}

// Baseline: seed 002's table (forward differencing, N steps), binary search + linear interpolation.
void table_linear_search(benchmark::State& state) {
  const al::forward_difference_table<double> t(curve(), static_cast<std::size_t>(state.range(0)));
  const auto& q = queries();
  const double scale = t.arc_lengths().back() / static_cast<double>(reference().length());
  std::size_t i = 0;
  for (auto _ : state) {
    const double u = t.u(q[i] * scale);
    keep(u);
    i = (i + 1) & 1023;
  }
  state.counters["max_ds_rel"] = max_ds_rel([&](double s) { return t.u(s * scale); });
}

// Newton without a table: segment lengths precomputed, then newton_invert per query.
void newton_no_table(benchmark::State& state) {
  const al::segment_lengths<double> seg(curve());
  al::newton_options<double> opt;
  opt.relative_tolerance = std::pow(10.0, -static_cast<double>(state.range(0)));  // |ds| + bound <= tol L
  const auto& q = queries();
  std::size_t i = 0;
  for (auto _ : state) {
    const auto r = al::newton_invert(curve(), seg, q[i], opt);
    keep(r);
    i = (i + 1) & 1023;
  }
  double evals = 0, iters = 0;
  for (std::size_t k = 0; k < 64; ++k) {
    const auto r = al::newton_invert(curve(), seg, q[k], opt);
    evals += static_cast<double>(r.evaluations);
    iters += r.iterations;
  }
  state.counters["evals"] = evals / 64;
  state.counters["iterations"] = iters / 64;
  state.counters["max_ds_rel"] = max_ds_rel([&](double s) { return al::newton_invert(curve(), seg, s, opt).u; });
}

}  // namespace

BENCHMARK(gauss_legendre_length)->Name("arclength/gauss_legendre")->ArgName("n")->DenseRange(4, 16, 2)->Arg(20)->Arg(24);
// The lean power-form cubic (no segment lookup): ours and Boost's rule on the same integrand.
BENCHMARK(gauss_legendre_power_cubic)->Name("arclength_lean_cubic/gauss_legendre")->ArgName("n")->Arg(12)->Arg(16)->Arg(20);
BENCHMARK(boost_gauss_power_cubic<10>)->Name("arclength_lean_cubic/boost_gauss/n:10");
BENCHMARK(boost_gauss_power_cubic<15>)->Name("arclength_lean_cubic/boost_gauss/n:15");
BENCHMARK(boost_gauss_power_cubic<20>)->Name("arclength_lean_cubic/boost_gauss/n:20");
BENCHMARK(newton_power_cubic)->Name("arclength_lean_cubic/u_of_s_newton_no_table")->ArgName("tol_exp")->Arg(13);
BENCHMARK(gauss_legendre_nested)->Name("arclength/gauss_legendre_nested")->ArgName("n")->Arg(4)->Arg(8);
BENCHMARK(adaptive_gk15)->Name("arclength/adaptive_gk15")->ArgName("tol_exp")->Arg(6)->Arg(10)->Arg(13);
BENCHMARK(forward_difference)->Name("arclength/forward_difference")->ArgName("steps")->RangeMultiplier(4)->Range(16, 4096);
BENCHMARK(subdivision)->Name("arclength/subdivision")->ArgName("tol_exp")->Arg(4)->Arg(6)->Arg(8);
BENCHMARK(boost_gauss<7>)->Name("arclength/boost_gauss/n:7");
BENCHMARK(boost_gauss<10>)->Name("arclength/boost_gauss/n:10");
BENCHMARK(boost_gauss<15>)->Name("arclength/boost_gauss/n:15");
BENCHMARK(boost_gauss<20>)->Name("arclength/boost_gauss/n:20");
BENCHMARK(boost_gauss_kronrod<15>)->Name("arclength/boost_gauss_kronrod15")->ArgName("tol_exp")->Arg(10)->Arg(13);
BENCHMARK(boost_gauss_kronrod<31>)->Name("arclength/boost_gauss_kronrod31")->ArgName("tol_exp")->Arg(10)->Arg(13);
BENCHMARK(boost_tanh_sinh)->Name("arclength/boost_tanh_sinh")->ArgName("tol_exp")->Arg(10)->Arg(13);
BENCHMARK(u_of_s)->Name("arclength/u_of_s")->ArgNames({"method", "polish"})
    ->Args({static_cast<int>(al::inversion_method::hermite_table), 0})
    ->Args({static_cast<int>(al::inversion_method::hermite_table), 1})
    ->Args({static_cast<int>(al::inversion_method::linear_table), 0})
    ->Args({static_cast<int>(al::inversion_method::newton), 0});
BENCHMARK(bisection_full_reintegration)->Name("arclength/u_of_s_bisection_full_reintegration");
BENCHMARK(table_linear_search)->Name("arclength/u_of_s_table_linear_search")->ArgName("steps")->Arg(256)->Arg(4096);
BENCHMARK(newton_no_table)->Name("arclength/u_of_s_newton_no_table")->ArgName("tol_exp")->Arg(13);
