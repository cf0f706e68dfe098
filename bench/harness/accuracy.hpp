// The accuracy runner: for every case x quantity x method x setting, the error against the 50-digit
// reference, the method's own error estimate and whether it bounded the error, and the cost in
// curve-derivative evaluations; observed convergence orders by fitting log error against log cost.
//
// Quantities (all errors relative to the case's reference length L, except "eval"):
//   length   |L_method - L| / L
//   s_of_u   max over parameters u_j of |s_method(u_j) - s(u_j)| / L
//   u_of_s   max over targets s_j of |s(u_method(s_j)) - s_j| / L   (the |ds| measure)
//   eval     max over parameters of |P_method(u) - P(u)|_inf / (eps(double) * scale), the
//            evaluation error of each algorithm in units of double's epsilon times the curve's size
//   channel_value, channel_keys, channel_monotone, channel_time   (cases of type "channel" only) a
//            keyframe channel's value error per time solver in float and double, in ulps of its
//            value range, at the key times, its monotonicity violations and the solver's time
//            residual (sweeps.hpp, sweep_channel; the case's "channel" summary holds the value range,
//            a picture, and for tool "exact" the tools' models of the same keys and their disagreement)
// (vocab::quantities; the methods, settings and theory orders are those of harness/vocabulary.hpp.
// Eval records name the evaluation algorithm, have the setting "" and the status "not_guaranteed":
// an evaluation gives no error estimate of its own.)
// Costs: length records count the evaluations of one call; s_of_u and u_of_s records count one
// query plus the set-up (tables, segment lengths) amortized over `amortized_queries` queries, and
// carry the two apart: "query_evaluations" (a query's own, the mean over the targets) and
// "build_evaluations" (the set-up's, once), so that a reader can find where a table pays off.
// The reference is the same spec instantiated on real50 (exact twin of the double data) and
// integrated by reference::reference_arc_length (Boost.Math, ~1e-45).
// Peers: the libraries users would pick instead (GSL's splines and QUADPACK, today) are
// run on every case they can represent by harness/sweep_peers.cpp and measured against the same
// reference; their records go to "peer_records" (the record format plus "peer": true, "library",
// "peer_status", the time per operation of the peer and of its curvebench "counterpart"), kept
// apart from "records" so that the gate judges curvebench's methods only, and the versions to
// context.peers.
// Implementation: the curvebench_harness library (bench/harness/): one unit per sweep
// (sweep_length, sweep_s_of_u, sweep_u_of_s, sweep_eval, sweep_audit, sweep_channel), the 50-digit
// reference and u(s) anchors (reference.cpp; sweep_channel also builds the channel at 50 digits), the record sink and
// order fit (records, order_fit), the worker pool (pool), the writers (writers) and run_case/run_accuracy composing
// them (accuracy.cpp).
#pragma once

#include "harness/cases.hpp"
#include "harness/order_fit.hpp"

#include "curvebench/core/any_curve.hpp"

#include <nlohmann/json.hpp>

#include <functional>
#include <string>

namespace curvebench::harness {

template <int Dim>
class case_reference;
struct sweep;

/// Libraries measured beside curvebench's methods on each case, into "peer_records": for a 2D and
/// a 3D case (the case, its curve, its reference, the sweep's settings) and the libraries'
/// versions (context.peers). The tool passes GSL, Boost.Math and Eigen (harness/peers.hpp,
/// library_peers(), the curvebench_peers library); without them the results have no peer records.
struct peer_sweeps {
  std::function<nlohmann::json(const case_info&, const any_curve<double, 2>&, case_reference<2>&, const sweep&)> dim2;
  std::function<nlohmann::json(const case_info&, const any_curve<double, 3>&, case_reference<3>&, const sweep&)> dim3;
  std::function<nlohmann::json()> versions;
};

/// Set-up cost of tables and segment lengths is spread over this many queries in s_of_u/u_of_s costs.
inline constexpr double amortized_queries = 1000;

struct accuracy_options {
  bool quick = false;     ///< fewer settings and samples; cases marked "quick": false skipped
  std::string cases_dir;  ///< directory of case specs
  std::string out = "reports/accuracy.json";
  unsigned threads = 0;                ///< 0: all cores
  std::string only;                    ///< run only cases whose name contains this text
  bool quiet = false;                  ///< no progress lines on stderr (failures and the summary still)
  const peer_sweeps* peers = nullptr;  ///< the peer libraries to run on each case (none: no peer records)
};

/// Runs every selected case (on opt.threads threads) and writes `out` (JSON) and the same path
/// with .csv (records) from the cases that ran. Returns 0 when every case ran, 1 when any case
/// failed (each failure is printed on stderr and its records left out; the files are written
/// either way). Throws invalid_input when no case matches or the cases cannot be loaded.
int run_accuracy(const accuracy_options& opt);

/// One case's records and orders: {"records": [...], "orders": [...], "case": {...}}.
/// Throws invalid_input for a case that is not 2D or 3D (or whose spec is invalid).
/// peers: as accuracy_options::peers.
nlohmann::json run_case(const case_info& c, bool quick, const peer_sweeps* peers = nullptr);

/// The compiler that built the harness, "gcc 12.2.0" or "clang 16.0.6" (its __VERSION__ for others).
std::string compiler_id();

}  // namespace curvebench::harness
