// The settings the harness sweeps, shared by the accuracy runner (errors, harness/sweep_*.cpp)
// and the per-case arc-length benchmarks (times, bench/bench_arclength_cases.cpp), so that a
// record's (case, method, setting) and a benchmark's name arclength_case/<case>/<method>/<setting>
// denote the same computation and report.py can join error with time.
#pragma once

#include "harness/setting.hpp"
#include "harness/vocabulary.hpp"

#include "curvebench/arclength/adaptive_subdivision.hpp"
#include "curvebench/arclength/forward_difference.hpp"
#include "curvebench/arclength/length.hpp"

#include <cstddef>
#include <string>
#include <vector>

namespace curvebench::harness {

/// Settings of one run: the full sweep, or the quick one used by CI (each quick list is a subset
/// of the full one, so quick and full records share keys).
struct sweep {
  std::vector<int> gauss_n;
  std::vector<int> panels;
  std::vector<double> adaptive_tol;
  std::vector<std::size_t> table_steps;
  std::vector<double> subdivision_tol;
  std::vector<std::size_t> table_intervals;
  std::vector<double> newton_tol;
  std::size_t params;       ///< s(u), u(s) sample count
  std::size_t eval_params;  ///< evaluation-accuracy sample count
  double max_table_evals;   ///< skip forward-difference settings above this many evaluations
  std::size_t channel_times;  ///< keyframe-channel sample times (sorted; monotonicity is checked between them)
};

inline sweep settings(bool quick) {
  if (quick)
    return {{2, 4, 8, 16}, {1, 2, 4, 8, 16}, {1e-6, 1e-10, 1e-14}, {8, 16, 32, 64, 128, 256}, {1e-4, 1e-6, 1e-8},
            {16, 64, 256, 1024}, {1e-8, 1e-12}, 9, 65, 2e5, 600};
  return {{1, 2, 3, 4, 5, 6, 8, 10, 12, 16, 20},
          {1, 2, 4, 8, 16, 32, 64},
          {1e-4, 1e-6, 1e-8, 1e-10, 1e-12, 1e-14},
          {4, 8, 16, 32, 64, 128, 256, 512, 1024, 2048, 4096},
          {1e-3, 1e-4, 1e-5, 1e-6, 1e-7, 1e-8, 1e-9},
          {16, 32, 64, 128, 256, 512, 1024, 2048, 4096},
          {1e-6, 1e-9, 1e-12, 1e-14},
          33,
          257,
          4e6,
          4000};
}

/// Calls f(method, setting, run) for every length method (a vocab::method; its `theory` is the
/// convergence order in evaluations to fit over its series, 0 where none is fitted) and setting
/// (harness/setting.hpp) of the sweep, in series: run() (which refers to c, so c must outlive it)
/// computes the length of c once and returns its quadrature_result (evaluations include the
/// set-up, e.g. a forward-difference table's). `length` scales the subdivision tolerances, which
/// are absolute (tol * length).
template <class C, class F>
void for_each_length_method(const C& c, const sweep& w, double length, F&& f) {
  namespace al = curvebench::arclength;
  using result = al::quadrature_result<double>;
  const double segments = static_cast<double>(c.breakpoints().size() - 1);
  namespace m = vocab::methods;
  for (int n : w.gauss_n)
    f(m::gauss, setting(m::gauss, {{"n", n}}), [&c, n] { return al::gauss_length(c, n, al::fixed_estimate::nested); });
  // The rule cache outlives every run (gauss_legendre returns a reference into it).
  constexpr int composite_n = 3;
  const al::gauss_legendre_rule<double>* rule = &al::gauss_legendre<double>(composite_n);
  for (int p : w.panels)
    f(m::composite_gauss, setting(m::composite_gauss, {{"n", composite_n}, {"panels", p}}),
      [&c, p, rule] { return al::composite_gauss_length(c, p, *rule); });
  for (double tol : w.adaptive_tol)
    f(m::adaptive_gk, setting(m::adaptive_gk, {{"tol", tol}}), [&c, tol] {
      al::adaptive_options<double> o;
      o.relative_tolerance = tol;
      return al::adaptive_length(c, o);
    });
  for (const vocab::method* table : {&m::forward_difference, &m::richardson})
    for (std::size_t steps : w.table_steps) {
      if (static_cast<double>(steps) * segments > w.max_table_evals) break;
      const bool richardson = table == &m::richardson;
      f(*table, setting(*table, {{"steps", steps}}), [&c, steps, richardson] {
        const al::forward_difference_table<double> t(c, steps);
        result r = richardson ? t.richardson_length() : t.length();
        r.evaluations = t.evaluations();
        return r;
      });
    }
  for (double tol : w.subdivision_tol)
    f(m::subdivision, setting(m::subdivision, {{"tol", tol}}), [&c, tol, length] {
      al::subdivision_options<double> o;
      o.tolerance = tol * length;
      o.relative_tolerance = 0;  // tol is relative to the reference length, given absolute here
      return al::subdivision_length(c, o);
    });
}

}  // namespace curvebench::harness
