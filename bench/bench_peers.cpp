// Evaluation speed against peer libraries on the same data and the same query parameters:
//   catmull_rom    ours (cardinal_spline, centripetal, power form)  vs Boost.Math catmull_rom
//   cubic_hermite  ours (hermite_spline, Dim 1)                     vs Boost.Math cubic_hermite
//   bspline_cubic  ours (bspline, de Boor)                          vs Eigen Spline<double,3,3>
//                                                                      and Spline<double,3> (dynamic degree)
//   uniform_bspline_1d  ours (bspline on uniform knots, Dim 1)      vs Boost.Math cardinal_cubic_b_spline
// B-splines are also measured after to_piecewise_cubic() (the shared engine: O(1) lookup on uniform
// knots, power form), which is what a user evaluating a cubic B-spline many times should do.
// Names: family/algorithm/timing:throughput/points:N/queries:random|sorted, the algorithm one of ours (power,
// de_boor, to_piecewise_cubic) or a peer id (vocabulary.hpp, "peer_<library>_<what>"), so
// scripts/report.py reports each of ours as a ratio to each peer measured in the same run.
// Parameters are precomputed (1024 per curve) and evaluated one call each, in both orders: operation
// evaluation, 1024 per iteration, independent of each other (throughput). The sorted order shows
// what segment-lookup locality is worth to each implementation.
#include "curvebench/curves/bspline.hpp"
#include "curvebench/curves/cardinal_spline.hpp"
#include "curvebench/curves/hermite_spline.hpp"

#include <boost/math/interpolators/cardinal_cubic_b_spline.hpp>
#include <boost/math/interpolators/catmull_rom.hpp>
#include <boost/math/interpolators/cubic_hermite.hpp>
#include <unsupported/Eigen/Splines>

#include "harness/bench_support.hpp"

#include <benchmark/benchmark.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace cb = curvebench;

namespace {

constexpr std::size_t queries = 1024;

/// A smooth, non-trivial 3D key set (a wobbly helix), deterministic.
cb::point_list<double, 3> keys(std::size_t n) {
  cb::point_list<double, 3> p(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double t = static_cast<double>(i) * 0.37;
    p[i] = {std::cos(t) * (2 + std::sin(3 * t)), std::sin(t) * (2 + std::sin(3 * t)), 0.25 * t};
  }
  return p;
}

/// Query parameters in [lo, hi]: random (fixed seed) or sorted.
std::vector<double> parameters(double lo, double hi, bool sorted) {
  return curvebench::bench::query_parameters(lo, hi, queries, sorted);
}

template <class F>
void run(benchmark::State& state, const std::vector<double>& us, F&& eval) {
  for (auto _ : state) {
    for (double u : us) {
      auto p = eval(u);
      benchmark::DoNotOptimize(p);  // the value must be computed; no memory to flush per evaluation
    }
  }
  curvebench::bench::per_operation(state, curvebench::harness::vocab::operations::evaluation,
                                   static_cast<double>(us.size()));
}

// The benchmark's arguments: the number of points and whether the queries are sorted.
struct shape {
  std::size_t points;
  bool sorted;
};

// ---- Catmull-Rom -----------------------------------------------------------------------------

void catmull_rom_ours(benchmark::State& state, shape q) {
  const auto pts = keys(q.points);
  cb::cardinal_options<double, 3> opt;
  opt.alpha = 0.5;
  const cb::cardinal_spline<double, 3> c(pts, opt);
  run(state, parameters(c.domain().lo, c.domain().hi, q.sorted), [&](double u) { return c(u); });
}

void catmull_rom_boost(benchmark::State& state, shape q) {
  const auto pts = keys(q.points);
  std::vector<std::array<double, 3>> a(pts.size());
  for (std::size_t i = 0; i < pts.size(); ++i) a[i] = {pts[i][0], pts[i][1], pts[i][2]};
  const boost::math::catmull_rom<std::array<double, 3>> c(std::move(a), false, 0.5);
  run(state, parameters(0, c.max_parameter(), q.sorted), [&](double u) { return c(u); });
}

// ---- cubic Hermite (scalar) ------------------------------------------------------------------

struct hermite_data {
  std::vector<double> x, y, dydx;
  explicit hermite_data(std::size_t n) : x(n), y(n), dydx(n) {
    for (std::size_t i = 0; i < n; ++i) {
      x[i] = static_cast<double>(i) + 0.3 * std::sin(static_cast<double>(i));  // non-uniform, increasing
      y[i] = std::sin(0.1 * x[i]);
      dydx[i] = 0.1 * std::cos(0.1 * x[i]);
    }
  }
};

void cubic_hermite_ours(benchmark::State& state, shape q) {
  const hermite_data d(q.points);
  cb::point_list<double, 1> v(d.y.size()), s(d.y.size());
  for (std::size_t i = 0; i < v.size(); ++i) {
    v[i][0] = d.y[i];
    s[i][0] = d.dydx[i];
  }
  const cb::hermite_spline<double, 1> c(d.x, v, s);
  run(state, parameters(d.x.front(), d.x.back(), q.sorted), [&](double u) { return c(u)[0]; });
}

void cubic_hermite_boost(benchmark::State& state, shape q) {
  hermite_data d(q.points);
  const double lo = d.x.front(), hi = d.x.back();
  const boost::math::interpolators::cubic_hermite<std::vector<double>> c(std::move(d.x), std::move(d.y),
                                                                         std::move(d.dydx));
  run(state, parameters(lo, hi, q.sorted), [&](double u) { return c(u); });
}

// ---- cubic B-spline, clamped, 3D: ours vs Eigen ----------------------------------------------

void bspline_ours(benchmark::State& state, shape q) {
  const auto pts = keys(q.points);
  const cb::bspline<double, 3> c(4, cb::bspline_clamped_knots<double>(pts.size(), 4), pts);
  run(state, parameters(0, 1, q.sorted), [&](double u) { return c(u); });
}

template <int Degree>
void bspline_eigen(benchmark::State& state, shape q) {
  const auto pts = keys(q.points);
  const std::vector<double> k = cb::bspline_clamped_knots<double>(pts.size(), 4);
  Eigen::Array<double, 1, Eigen::Dynamic> knots(static_cast<Eigen::Index>(k.size()));
  for (std::size_t i = 0; i < k.size(); ++i) knots(static_cast<Eigen::Index>(i)) = k[i];
  Eigen::Matrix<double, 3, Eigen::Dynamic> ctrl(3, static_cast<Eigen::Index>(pts.size()));
  for (std::size_t i = 0; i < pts.size(); ++i) ctrl.col(static_cast<Eigen::Index>(i)) = pts[i];
  const Eigen::Spline<double, 3, Degree> c(knots, ctrl);
  run(state, parameters(0, 1, q.sorted), [&](double u) { return c(u); });
}

// ---- uniform cubic B-spline, scalar: ours vs Boost cardinal_cubic_b_spline -------------------

void uniform_bspline_ours(benchmark::State& state, shape q) {
  // The same shape of work as Boost's: a uniform cubic B-spline with n + 2 coefficients on a
  // uniform grid. (Coefficients differ: Boost solves for interpolation; speed does not depend on them.)
  const auto n = q.points;
  cb::point_list<double, 1> coef(n + 2);
  for (std::size_t i = 0; i < coef.size(); ++i) coef[i][0] = std::sin(0.1 * static_cast<double>(i));
  const cb::bspline<double, 1> c(4, cb::bspline_uniform_knots<double>(coef.size(), 4), coef);
  run(state, parameters(c.domain().lo, c.domain().hi, q.sorted), [&](double u) { return c(u)[0]; });
}

/// The same curve converted to the shared cubic engine (O(1) lookup on uniform knots, power form):
/// what a user who evaluates a cubic B-spline many times should do.
void uniform_bspline_engine(benchmark::State& state, shape q) {
  const auto n = q.points;
  cb::point_list<double, 1> coef(n + 2);
  for (std::size_t i = 0; i < coef.size(); ++i) coef[i][0] = std::sin(0.1 * static_cast<double>(i));
  const cb::bspline<double, 1> b(4, cb::bspline_uniform_knots<double>(coef.size(), 4), coef);
  const auto c = b.to_piecewise_cubic();
  run(state, parameters(c.domain().lo, c.domain().hi, q.sorted), [&](double u) { return c(u)[0]; });
}

void bspline_engine(benchmark::State& state, shape q) {
  const auto pts = keys(q.points);
  const cb::bspline<double, 3> b(4, cb::bspline_clamped_knots<double>(pts.size(), 4), pts);
  const auto c = b.to_piecewise_cubic();
  run(state, parameters(0, 1, q.sorted), [&](double u) { return c(u); });
}

void uniform_bspline_boost(benchmark::State& state, shape q) {
  const auto n = q.points;
  std::vector<double> f(n);
  for (std::size_t i = 0; i < n; ++i) f[i] = std::sin(0.1 * static_cast<double>(i));
  const boost::math::interpolators::cardinal_cubic_b_spline<double> c(f.data(), f.size(), 0.0, 1.0);
  run(state, parameters(0, static_cast<double>(n - 1), q.sorted), [&](double u) { return c(u); });
}

namespace vocab = curvebench::harness::vocab;

template <class F>
void add(std::string_view family, const auto& id, F fn) {
  for (bool sorted : {false, true}) {
    const shape a{1000, sorted};
    curvebench::bench::register_benchmark(curvebench::bench::benchmark_name(family, id)
                                              .variant(curvebench::harness::vocab::variant_keys::timing, "throughput")
                                              .arg("points", a.points)
                                              .arg("queries", sorted ? "sorted" : "random"),
                                          [fn, a](benchmark::State& s) { fn(s, a); });
  }
}

const bool registered = [] {
  namespace alg = vocab::algorithms;
  namespace peers = vocab::peers;
  add("catmull_rom", alg::power, catmull_rom_ours);
  add("catmull_rom", peers::boost_catmull_rom, catmull_rom_boost);
  add("cubic_hermite", alg::power, cubic_hermite_ours);
  add("cubic_hermite", peers::boost_cubic_hermite, cubic_hermite_boost);
  add("bspline_cubic", alg::de_boor, bspline_ours);
  add("bspline_cubic", alg::to_piecewise_cubic, bspline_engine);
  add("bspline_cubic", peers::eigen_spline_fixed_degree, bspline_eigen<3>);
  add("bspline_cubic", peers::eigen_spline_dynamic_degree, bspline_eigen<Eigen::Dynamic>);
  add("uniform_bspline_1d", alg::de_boor, uniform_bspline_ours);
  add("uniform_bspline_1d", alg::to_piecewise_cubic, uniform_bspline_engine);
  add("uniform_bspline_1d", peers::boost_cardinal_cubic_b_spline, uniform_bspline_boost);
  return true;
}();

}  // namespace
