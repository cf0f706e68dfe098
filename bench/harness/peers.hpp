// The peer libraries of the accuracy runner: GSL's splines and QUADPACK integrators
// (harness/sweep_peers.cpp) and Boost.Math's quadratures and interpolators and Eigen's splines
// (harness/sweep_peers_boost_eigen.cpp), measured on each case beside curvebench's methods.
// They are the curvebench_peers library, which the tool and the tests link and which is not
// installed: the installed harness (the subject API, check, the gate) needs no GSL. The runner
// reaches them through accuracy_options::peers (harness/accuracy.hpp), library_peers() below.
#pragma once

#include "harness/accuracy.hpp"
#include "harness/cases.hpp"
#include "harness/reference.hpp"
#include "harness/sweep.hpp"

#include "curvebench/core/any_curve.hpp"

#include <nlohmann/json.hpp>

namespace curvebench::harness {

/// The peers (harness/sweep_peers.cpp: GSL's splines and QUADPACK integrators;
/// harness/sweep_peers_boost_eigen.cpp: Boost.Math's quadratures and interpolators, Eigen's
/// splines) on the case's data,
/// against the same reference: records in the accuracy format plus "peer": true, "library",
/// "peer_status" (the library's own status), "ns_per_op" and the curvebench counterpart's
/// "counterpart" {method, setting} and "counterpart_ns_per_op" (timed back to back). Empty when
/// no peer represents the case.
template <int Dim>
nlohmann::json sweep_peers(const case_info& info, const any_curve<double, Dim>& c, case_reference<Dim>& ref,
                           const sweep& w);

/// The versions of the peer libraries the harness was built against, by library name:
/// {"GSL": "2.7.1", "Boost.Math": "1.74.0", "Eigen": "3.4.0"}.
nlohmann::json peer_versions();

/// The peers above as the runner takes them (accuracy_options::peers, run_case).
const peer_sweeps& library_peers();

}  // namespace curvebench::harness
