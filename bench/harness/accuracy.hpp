// The accuracy runner: for every case x quantity x method x setting, the error against the 50-digit
// reference, the method's own error estimate and whether it bounded the error, and the cost in
// curve-derivative evaluations; observed convergence orders by fitting log error against log cost.
//
// Quantities (all errors relative to the case's reference length L, except "eval"):
//   length   |L_method - L| / L
//   s_of_u   max over parameters u_j of |s_method(u_j) - s(u_j)| / L
//   u_of_s   max over targets s_j of |s(u_method(s_j)) - s_j| / L   (the |ds| measure of issue 4)
//   eval     max over parameters of |P_method(u) - P(u)|_inf / (eps(double) * scale), the
//            evaluation error of each algorithm in units of double's epsilon times the curve's size
// Costs: length records count the evaluations of one call; s_of_u and u_of_s records count one
// query plus the set-up (tables, segment lengths) amortized over `amortized_queries` queries.
// The reference is the same spec instantiated on real50 (exact twin of the double data) and
// integrated by reference::reference_arc_length (Boost.Math, ~1e-45).
// Implementation: bench/tool/accuracy.cpp (the one translation unit with 50-digit families).
#pragma once

#include "harness/cases.hpp"

#include <nlohmann/json.hpp>

#include <string>
#include <utility>
#include <vector>

namespace curvebench::harness {

/// Set-up cost of tables and segment lengths is spread over this many queries in s_of_u/u_of_s costs.
inline constexpr double amortized_queries = 1000;

struct accuracy_options {
  bool quick = false;             ///< fewer settings and samples; cases marked "quick": false skipped
  std::string cases_dir;          ///< directory of case specs
  std::string out = "reports/accuracy.json";
  unsigned threads = 0;           ///< 0: all cores
  std::string only;               ///< run only cases whose name contains this text
};

/// Runs the sweep and writes `out` (JSON) and the same path with .csv (records); returns 0.
int run_accuracy(const accuracy_options& opt);

/// One case's records and orders: {"records": [...], "orders": [...], "case": {...}}.
nlohmann::json run_case(const case_info& c, bool quick);

/// The convergence order -d log(error) / d log(cost) by least squares over the points whose error
/// lies in (floor, ceiling); nullopt-like NaN when fewer than 3 points qualify.
double fit_order(const std::vector<std::pair<double, double>>& cost_error, double floor, double ceiling);

}  // namespace curvebench::harness
