// B-spline and NURBS evaluation speed, orders 2..6 (degree 1..5), double, Dim 3, 64 control points
// on a clamped knot vector: de Boor's algorithm vs the Cox-de Boor basis sum, the same for NURBS
// (homogeneous coordinates plus one division), and the first derivative by each (NURBS by de Boor:
// the quotient rule). Operation evaluation, one per iteration; the parameter advances by a fixed
// stride independent of the result, so the evaluations are independent (throughput).
// Names: <bspline|nurbs>/<algorithm>/order:<k>/derivative:<0|1>.
#include "curvebench/curves/bspline.hpp"
#include "curvebench/curves/nurbs.hpp"

#include "harness/bench_support.hpp"

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
  curvebench::bench::per_operation(state, curvebench::harness::vocab::operations::evaluation, 1);
}

void bspline_eval(benchmark::State& state, curvebench::bspline_evaluation algorithm, int order, int derivative_order) {
  const curvebench::bspline<double, 3> c(
      order, curvebench::bspline_clamped_knots<double>(control_count, order, 0.0, 1.0), control_points());
  run(state, c, derivative_order, algorithm);
}

void nurbs_eval(benchmark::State& state, curvebench::bspline_evaluation algorithm, int order, int derivative_order) {
  const curvebench::nurbs<double, 3> c(order, curvebench::bspline_clamped_knots<double>(control_count, order, 0.0, 1.0),
                                       control_points(), weights());
  run(state, c, derivative_order, algorithm);
}

namespace vocab = curvebench::harness::vocab;
using curvebench::bspline_evaluation;

const bool registered = [] {
  using curvebench::bench::benchmark_name;
  using curvebench::bench::register_benchmark;
  struct variant {
    const vocab::algorithm* id;
    bspline_evaluation algorithm;
    bool nurbs;
    int derivative;
  };
  // NURBS derivatives by de Boor only (the quotient rule on the homogeneous curve).
  const variant variants[] = {{&vocab::algorithms::de_boor, bspline_evaluation::de_boor, false, 0},
                              {&vocab::algorithms::basis_sum, bspline_evaluation::basis_sum, false, 0},
                              {&vocab::algorithms::de_boor, bspline_evaluation::de_boor, false, 1},
                              {&vocab::algorithms::basis_sum, bspline_evaluation::basis_sum, false, 1},
                              {&vocab::algorithms::de_boor, bspline_evaluation::de_boor, true, 0},
                              {&vocab::algorithms::basis_sum, bspline_evaluation::basis_sum, true, 0},
                              {&vocab::algorithms::de_boor, bspline_evaluation::de_boor, true, 1}};
  for (const variant& v : variants)
    for (int order = 2; order <= 6; ++order)
      register_benchmark(
          benchmark_name(v.nurbs ? "nurbs" : "bspline", *v.id).arg("order", order).arg("derivative", v.derivative),
          [v, order](benchmark::State& s) {
            if (v.nurbs)
              nurbs_eval(s, v.algorithm, order, v.derivative);
            else
              bspline_eval(s, v.algorithm, order, v.derivative);
          });
  return true;
}();

}  // namespace
