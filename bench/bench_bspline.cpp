// B-spline and NURBS evaluation speed, orders 2..6 (degree 1..5), double, Dim 3, 64 control points
// on a clamped knot vector: de Boor's algorithm vs the Cox-de Boor basis sum, the same for NURBS
// (homogeneous coordinates plus one division), and the first derivative by each.
// Names follow family/algorithm/arg:value.
#include "curvebench/curves/bspline.hpp"
#include "curvebench/curves/nurbs.hpp"

#include <benchmark/benchmark.h>

#include <vector>

namespace {

constexpr std::size_t control_count = 64;

curvebench::point_list<double, 3> control_points() {
  curvebench::point_list<double, 3> p;
  for (std::size_t i = 0; i < control_count; ++i) {
    const double x = static_cast<double>(i);
    p.emplace_back(x, static_cast<double>((i * 7) % 11) / 3.0, static_cast<double>((i * 5) % 13) / 4.0);
  }
  return p;
}

std::vector<double> weights() {
  std::vector<double> w;
  for (std::size_t i = 0; i < control_count; ++i) w.push_back(0.5 + static_cast<double>(i % 4) / 2.0);
  return w;
}

template <class Curve>
void run(benchmark::State& state, const Curve& c, int derivative_order, curvebench::bspline_evaluation algorithm) {
  double u = 0.0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(c.evaluate(u, derivative_order, algorithm));
    u = u < 0.999 ? u + 0.000731 : 0.0;  // a stride that visits every span in turn
  }
  state.counters["evals"] = benchmark::Counter(1.0, benchmark::Counter::kIsIterationInvariantRate);
}

void bspline_eval(benchmark::State& state, curvebench::bspline_evaluation algorithm, int derivative_order) {
  const int order = static_cast<int>(state.range(0));
  const curvebench::bspline<double, 3> c(order, curvebench::bspline_clamped_knots<double>(control_count, order, 0.0, 1.0),
                                         control_points());
  run(state, c, derivative_order, algorithm);
}

void nurbs_eval(benchmark::State& state, curvebench::bspline_evaluation algorithm, int derivative_order) {
  const int order = static_cast<int>(state.range(0));
  const curvebench::nurbs<double, 3> c(order, curvebench::bspline_clamped_knots<double>(control_count, order, 0.0, 1.0),
                                       control_points(), weights());
  run(state, c, derivative_order, algorithm);
}

void bspline_de_boor(benchmark::State& s) { bspline_eval(s, curvebench::bspline_evaluation::de_boor, 0); }
void bspline_basis_sum(benchmark::State& s) { bspline_eval(s, curvebench::bspline_evaluation::basis_sum, 0); }
void bspline_de_boor_d1(benchmark::State& s) { bspline_eval(s, curvebench::bspline_evaluation::de_boor, 1); }
void bspline_basis_sum_d1(benchmark::State& s) { bspline_eval(s, curvebench::bspline_evaluation::basis_sum, 1); }
void nurbs_de_boor(benchmark::State& s) { nurbs_eval(s, curvebench::bspline_evaluation::de_boor, 0); }
void nurbs_basis_sum(benchmark::State& s) { nurbs_eval(s, curvebench::bspline_evaluation::basis_sum, 0); }
void nurbs_de_boor_d1(benchmark::State& s) { nurbs_eval(s, curvebench::bspline_evaluation::de_boor, 1); }

}  // namespace

BENCHMARK(bspline_de_boor)->Name("bspline/de_boor")->ArgName("order")->DenseRange(2, 6);
BENCHMARK(bspline_basis_sum)->Name("bspline/basis_sum")->ArgName("order")->DenseRange(2, 6);
BENCHMARK(bspline_de_boor_d1)->Name("bspline/de_boor_derivative1")->ArgName("order")->DenseRange(2, 6);
BENCHMARK(bspline_basis_sum_d1)->Name("bspline/basis_sum_derivative1")->ArgName("order")->DenseRange(2, 6);
BENCHMARK(nurbs_de_boor)->Name("nurbs/de_boor")->ArgName("order")->DenseRange(2, 6);
BENCHMARK(nurbs_basis_sum)->Name("nurbs/basis_sum")->ArgName("order")->DenseRange(2, 6);
BENCHMARK(nurbs_de_boor_d1)->Name("nurbs/de_boor_quotient_rule_derivative1")->ArgName("order")->DenseRange(2, 6);
