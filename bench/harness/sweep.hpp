// The settings the harness sweeps, shared by the accuracy runner (errors, harness/sweep_*.cpp)
// and the per-case arc-length benchmarks (times, bench/bench_arclength_cases.cpp), so that a
// record's (case, method, setting) and a benchmark's name arclength_case/<case>/<method>/<setting>
// denote the same computation and report.py can join error with time. Which setting series each
// method runs over is its row's `series` in the method tables (harness/length_methods.hpp).
#pragma once

#include "harness/setting.hpp"  // the settings of records (kept for the sweeps that format their own)
#include "harness/vocabulary.hpp"

#include <cstddef>
#include <vector>

namespace curvebench::harness {

/// Settings of one run: the full sweep, or the quick one used by CI (each quick list is a subset
/// of the full one, so quick and full records share keys). Built by name (designated initialisers
/// in settings()); the series are read by the method tables' rows and by the peers.
struct sweep {
  bool quick = false;                        ///< the quick sweep (a row with series of its own picks by it)
  std::vector<int> gauss_n;                  ///< gauss: n
  std::vector<int> panels;                   ///< composite_gauss: panels (n = composite_gauss_n)
  std::vector<double> adaptive_tol;          ///< adaptive_gk (and its peers): relative tolerance
  std::vector<std::size_t> table_steps;      ///< forward_difference, richardson: steps per segment
  std::vector<double> subdivision_tol;       ///< subdivision: tolerance relative to the reference length
  std::vector<std::size_t> table_intervals;  ///< linear_table, hermite_table(_polished): M
  std::vector<double> linear_table_tol;      ///< linear_table_sized: target relative to L
  std::vector<double> hermite_table_tol;     ///< hermite_table_sized: target relative to L
  std::vector<double> newton_tol;            ///< newton (and its peers): relative tolerance
  std::size_t params = 0;                    ///< s(u), u(s) sample count
  std::size_t eval_params = 0;               ///< evaluation-accuracy sample count
  double max_table_evals = 0;                ///< skip forward-difference settings above this many evaluations
  std::size_t channel_times = 0;  ///< keyframe-channel sample times (sorted; monotonicity is checked between them)
};

/// The n of composite_gauss in the sweep: 3 points per panel (theory order 2n = 6).
inline constexpr int composite_gauss_n = 3;

inline sweep settings(bool quick) {
  if (quick)
    return {.quick = true,
            .gauss_n = {2, 4, 8, 16},
            .panels = {1, 2, 4, 8, 16},
            .adaptive_tol = {1e-6, 1e-10, 1e-14},
            .table_steps = {8, 16, 32, 64, 128, 256},
            .subdivision_tol = {1e-4, 1e-6, 1e-8},
            .table_intervals = {16, 64, 256, 1024},
            .linear_table_tol = {1e-4, 1e-6},
            .hermite_table_tol = {1e-6, 1e-9, 1e-12},
            .newton_tol = {1e-8, 1e-12},
            .params = 9,
            .eval_params = 65,
            .max_table_evals = 2e5,
            .channel_times = 600};
  return {.quick = false,
          .gauss_n = {1, 2, 3, 4, 5, 6, 8, 10, 12, 16, 20},
          .panels = {1, 2, 4, 8, 16, 32, 64},
          .adaptive_tol = {1e-4, 1e-6, 1e-8, 1e-10, 1e-12, 1e-14},
          .table_steps = {4, 8, 16, 32, 64, 128, 256, 512, 1024, 2048, 4096},
          .subdivision_tol = {1e-3, 1e-4, 1e-5, 1e-6, 1e-7, 1e-8, 1e-9},
          .table_intervals = {16, 32, 64, 128, 256, 512, 1024, 2048, 4096},
          .linear_table_tol = {1e-4, 1e-5, 1e-6, 1e-7, 1e-8},
          .hermite_table_tol = {1e-6, 1e-8, 1e-9, 1e-10, 1e-12, 1e-14},
          .newton_tol = {1e-6, 1e-9, 1e-12, 1e-14},
          .params = 33,
          .eval_params = 257,
          .max_table_evals = 4e6,
          .channel_times = 4000};
}

}  // namespace curvebench::harness
