// Speed against GSL on the same data, in the same run, so report.py can show each of
// ours as a ratio to GSL:
//   natural_cubic_1d   ours (natural_cubic_spline, Dim 1, power form)   vs gsl_interp_cspline
//                      (the same interpolant) and gsl_interp_akima (another interpolant a user
//                      might pick for the same data: its time only, it is a different curve)
//   periodic_cubic_1d  ours (natural_cubic_spline, end periodic)        vs gsl_interp_cspline_periodic
//   monotone_cubic_1d  ours (motion::monotone_cubic, Fritsch-Butland)   vs gsl_interp_steffen (a
//                      different monotone rule on the same data: both shape-preserving C1 cubics)
//   arclength_gsl      ours (adaptive_gk: G7-K15 split at breakpoints and speed minima) vs
//                      gsl_integration_qag (GAUSS15) and qags of the speed |P'(u)| over the whole
//                      domain, epsabs 0 and epsrel = tol, on a 3D natural cubic spline of 100 keys
// Evaluation: 1024 precomputed parameters, one call each, random or sorted (GSL's accelerator
// caches the last interval, so sorted queries show what locality is worth to each); operation
// evaluation, 1024 per iteration. Lengths: one length per iteration (set-up included), with the
// evaluations and the method's own error estimate as counters. The errors of these peers against
// the 50-digit references are measured by the accuracy runner (harness/sweep_peers.cpp), not here.
#include "curvebench/arclength/length.hpp"
#include "curvebench/curves/natural_cubic_spline.hpp"
#include "curvebench/motion/monotone_cubic.hpp"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_integration.h>
#include <gsl/gsl_spline.h>

#include "harness/bench_support.hpp"
#include "harness/length_methods.hpp"  // the vocabulary entries of the length and u(s) methods

#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

namespace cb = curvebench;
namespace al = curvebench::arclength;

namespace {

namespace vocab = curvebench::harness::vocab;
using curvebench::bench::benchmark_name;
using curvebench::bench::per_operation;
using curvebench::bench::register_benchmark;
using curvebench::bench::set_counter;

constexpr std::size_t queries = 1024;
constexpr std::size_t points = 1000;

template <class T>
void keep(T& x) {
  T* p = &x;
  benchmark::DoNotOptimize(p);
  benchmark::ClobberMemory();
}

/// Query parameters in [lo, hi]: random (fixed seed) or sorted.
std::vector<double> parameters(double lo, double hi, bool sorted) {
  return curvebench::bench::query_parameters(lo, hi, queries, sorted);
}

template <class F>
void run(benchmark::State& state, const std::vector<double>& us, F&& eval) {
  for (auto _ : state) {
    for (double u : us) {
      double v = eval(u);
      keep(v);
    }
  }
  per_operation(state, vocab::operations::evaluation, static_cast<double>(us.size()));
}

/// Scalar data on non-uniform increasing knots. kind: smooth (sin), periodic (one period, the last
/// value equal to the first, as a periodic spline requires), monotone (non-decreasing with flat runs).
struct data {
  std::vector<double> x, y;
  enum class kind { smooth, periodic, monotone };
  data(std::size_t n, kind k) : x(n), y(n) {
    for (std::size_t i = 0; i < n; ++i) x[i] = static_cast<double>(i) + 0.3 * std::sin(static_cast<double>(i));
    const double span = x.back() - x.front();
    double run = 0;
    for (std::size_t i = 0; i < n; ++i) {
      switch (k) {
        case kind::smooth: y[i] = std::sin(0.1 * x[i]); break;
        case kind::periodic: y[i] = std::sin(2 * std::numbers::pi * (x[i] - x.front()) / span); break;
        case kind::monotone:
          if (i % 7 != 3) run += 1 + std::sin(0.05 * x[i]);  // every 7th step flat
          y[i] = run;
          break;
      }
    }
    if (k == kind::periodic) y.back() = y.front();
  }
};

struct gsl_spline_1d {
  std::unique_ptr<gsl_spline, void (*)(gsl_spline*)> s;
  std::unique_ptr<gsl_interp_accel, void (*)(gsl_interp_accel*)> a;
  gsl_spline_1d(const gsl_interp_type* type, const data& d)
      : s(gsl_spline_alloc(type, d.x.size()), gsl_spline_free), a(gsl_interp_accel_alloc(), gsl_interp_accel_free) {
    if (!s || !a) throw std::bad_alloc();
    const int status = gsl_spline_init(s.get(), d.x.data(), d.y.data(), d.x.size());
    if (status != GSL_SUCCESS) throw std::runtime_error(std::string("gsl_spline_init: ") + gsl_strerror(status));
  }
  double operator()(double u) const { return gsl_spline_eval(s.get(), u, a.get()); }
};

cb::natural_cubic_spline<double, 1> ours_spline(const data& d, cb::spline_end end) {
  cb::point_list<double, 1> v(d.y.size());
  for (std::size_t i = 0; i < v.size(); ++i) v[i][0] = d.y[i];
  return {d.x, v, end};
}

struct shape {
  data::kind kind;
  bool sorted;
};

void spline_ours(benchmark::State& state, shape q, cb::spline_end end) {
  const data d(points, q.kind);
  const auto c = ours_spline(d, end);
  run(state, parameters(d.x.front(), d.x.back(), q.sorted), [&](double u) { return c(u)[0]; });
}

void monotone_ours(benchmark::State& state, shape q) {
  const data d(points, q.kind);
  const cb::motion::monotone_cubic<double> c(d.x, d.y);
  run(state, parameters(d.x.front(), d.x.back(), q.sorted), [&](double u) { return c(u); });
}

void spline_gsl(benchmark::State& state, shape q, const gsl_interp_type* type) {
  const data d(points, q.kind);
  const gsl_spline_1d c(type, d);
  run(state, parameters(d.x.front(), d.x.back(), q.sorted), [&](double u) { return c(u); });
}

// ---- arc length ----

/// A 3D natural cubic spline through 100 keys of a wobbly helix.
const cb::natural_cubic_spline<double, 3>& curve() {
  static const cb::natural_cubic_spline<double, 3> c = [] {
    cb::point_list<double, 3> p(100);
    std::vector<double> k(p.size());
    for (std::size_t i = 0; i < p.size(); ++i) {
      const double t = static_cast<double>(i) * 0.37;
      p[i] = {std::cos(t) * (2 + std::sin(3 * t)), std::sin(t) * (2 + std::sin(3 * t)), 0.25 * t};
      k[i] = static_cast<double>(i);
    }
    return cb::natural_cubic_spline<double, 3>(k, p);
  }();
  return c;
}

void length_ours(benchmark::State& state, double tol) {
  al::adaptive_options<double> opt;
  opt.relative_tolerance = tol;
  al::quadrature_result<double> r;
  for (auto _ : state) {
    r = al::adaptive_length(curve(), opt);
    keep(r);
  }
  per_operation(state, vocab::operations::length, 1);
  set_counter(state, vocab::counters::evaluations, static_cast<double>(r.evaluations));
  set_counter(state, vocab::counters::estimate_rel, r.error_estimate / r.value);
}

struct counted_speed {
  std::size_t calls = 0;
  static double call(double u, void* self) {
    ++static_cast<counted_speed*>(self)->calls;
    return al::speed(curve(), u);
  }
};

void length_gsl(benchmark::State& state, double tol, bool qags) {
  constexpr std::size_t limit = 1000;
  const std::unique_ptr<gsl_integration_workspace, void (*)(gsl_integration_workspace*)> ws(
      gsl_integration_workspace_alloc(limit), gsl_integration_workspace_free);
  counted_speed f;
  gsl_function F{&counted_speed::call, &f};
  const double lo = curve().domain().lo, hi = curve().domain().hi;
  double value = 0, abserr = 0;
  int status = GSL_SUCCESS;
  std::size_t calls = 0;
  for (auto _ : state) {
    f.calls = 0;
    status = qags ? gsl_integration_qags(&F, lo, hi, 0.0, tol, limit, ws.get(), &value, &abserr)
                  : gsl_integration_qag(&F, lo, hi, 0.0, tol, limit, GSL_INTEG_GAUSS15, ws.get(), &value, &abserr);
    calls = f.calls;
    keep(value);
  }
  if (status != GSL_SUCCESS && status != GSL_EMAXITER && status != GSL_EROUND)
    state.SkipWithError((std::string("GSL: ") + gsl_strerror(status)).c_str());
  per_operation(state, vocab::operations::length, 1);
  set_counter(state, vocab::counters::evaluations, static_cast<double>(calls));
  set_counter(state, vocab::counters::estimate_rel, abserr / value);
}

template <class F>
void add(std::string_view family, const auto& id, data::kind kind, F fn) {
  for (bool sorted : {false, true}) {
    const shape a{kind, sorted};
    register_benchmark(benchmark_name(family, id).arg("points", points).arg("queries", sorted ? "sorted" : "random"),
                       [fn, a](benchmark::State& s) { fn(s, a); });
  }
}

const bool registered = [] {
  gsl_set_error_handler_off();  // statuses, not aborts (GSL's default handler aborts)
  namespace peers = vocab::peers;
  namespace alg = vocab::algorithms;
  using k = data::kind;
  add("natural_cubic_1d", alg::power, k::smooth,
      [](benchmark::State& s, shape q) { spline_ours(s, q, cb::spline_end::natural); });
  add("natural_cubic_1d", peers::gsl_cspline, k::smooth,
      [](benchmark::State& s, shape q) { spline_gsl(s, q, gsl_interp_cspline); });
  add("natural_cubic_1d", peers::gsl_akima, k::smooth,
      [](benchmark::State& s, shape q) { spline_gsl(s, q, gsl_interp_akima); });
  add("periodic_cubic_1d", alg::power, k::periodic,
      [](benchmark::State& s, shape q) { spline_ours(s, q, cb::spline_end::periodic); });
  add("periodic_cubic_1d", peers::gsl_cspline_periodic, k::periodic,
      [](benchmark::State& s, shape q) { spline_gsl(s, q, gsl_interp_cspline_periodic); });
  add("monotone_cubic_1d", alg::monotone_cubic, k::monotone, monotone_ours);
  add("monotone_cubic_1d", peers::gsl_steffen, k::monotone,
      [](benchmark::State& s, shape q) { spline_gsl(s, q, gsl_interp_steffen); });
  // GSL refuses epsrel below 50 eps(double) when epsabs is 0, so the sweep's 1e-14 has no GSL time.
  for (double tol : {1e-6, 1e-8, 1e-10, 1e-12}) {
    register_benchmark(benchmark_name("arclength_gsl", vocab::methods::adaptive_gk).arg("tol", tol),
                       [tol](benchmark::State& s) { length_ours(s, tol); });
    register_benchmark(benchmark_name("arclength_gsl", peers::gsl_qag).arg("tol", tol),
                       [tol](benchmark::State& s) { length_gsl(s, tol, false); });
    register_benchmark(benchmark_name("arclength_gsl", peers::gsl_qags).arg("tol", tol),
                       [tol](benchmark::State& s) { length_gsl(s, tol, true); });
  }
  return true;
}();

}  // namespace
