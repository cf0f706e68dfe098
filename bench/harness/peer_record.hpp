// What every peer of the accuracy runner shares (harness/sweep_peers.cpp: GSL;
// harness/sweep_peers_boost_eigen.cpp: Boost.Math and Eigen): the peer's record (harness/record.hpp),
// the back-to-back timing, and the evaluation records of a peer that evaluates a curve (values and
// first derivative) at parameters inside the case's domain. Internal to the harness.
#pragma once

#include "harness/cases.hpp"
#include "harness/record.hpp"
#include "harness/reference.hpp"
#include "harness/sweep.hpp"
#include "harness/vocabulary.hpp"

#include "curvebench/arclength/length.hpp"
#include "curvebench/arclength/result.hpp"
#include "curvebench/core/any_curve.hpp"
#include "curvebench/io/spec.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <exception>
#include <limits>
#include <map>
#include <string>
#include <vector>

namespace curvebench::harness::peers_detail {

using json = nlohmann::json;
inline constexpr double nan = std::numeric_limits<double>::quiet_NaN();

/// Best of three batches of the time per call of f, each batch repeating f until 2 ms have passed.
template <class F>
double ns_per_call(F&& f) {
  using clock = std::chrono::steady_clock;
  double best = std::numeric_limits<double>::infinity();
  for (int batch = 0; batch < 3; ++batch) {
    std::size_t calls = 0;
    const auto t0 = clock::now();
    double elapsed = 0;
    do {
      f();
      ++calls;
      elapsed = std::chrono::duration<double, std::nano>(clock::now() - t0).count();
    } while (elapsed < 2e6);
    best = std::min(best, elapsed / static_cast<double>(calls));
  }
  return best;
}

struct peer_record {
  const vocab::quantity* quantity;
  const vocab::peer* peer;
  std::string setting;
  double error;
  double estimate;
  double evaluations;
  std::string status;       ///< a result_status name
  std::string peer_status;  ///< the library's own words for its status
  double ns_per_op;
  std::string counterpart_algorithm;  ///< eval: the family's algorithm; otherwise the method id
  std::string counterpart_setting;
  double counterpart_ns_per_op;
};

/// The record (harness/record.hpp) of a peer; library: "<library> <version>". counterpart_error:
/// curvebench's error measured here beside the peer's, on the same parameters, where curvebench's
/// own sweeps keep no record of the same quantity (a derivative, a part of the domain); NaN: none,
/// left out.
inline record to_record(const case_info& info, const peer_record& r, const std::string& library,
                        double counterpart_error = nan) {
  record out = record::measured(info.name, info.group, r.quantity->id, r.peer->id, r.setting, r.error, r.estimate,
                                r.evaluations, r.status);
  out.peer = peer_fields{library,
                         r.peer_status,
                         r.ns_per_op,
                         r.counterpart_algorithm,
                         r.counterpart_setting,
                         r.counterpart_ns_per_op,
                         counterpart_error};
  return out;
}

/// The record as accuracy.json holds it.
inline json to_json(const case_info& info, const peer_record& r, const std::string& library,
                    double counterpart_error = nan) {
  return harness::to_json(to_record(info, r, library, counterpart_error));
}

/// eval records of a peer evaluating the case's curve at the parameters us: the values (setting
/// `part`; error in eps(double) x size, as curvebench's eval records) and the first derivative
/// (setting "derivative=1" after `part`, in eps(double) x the size of the exact derivative at the
/// same parameters, as `curvebench check` measures a user's derivative), each with curvebench's
/// own error at the same parameters beside it (counterpart_error) and both times per evaluation.
/// `part` ("" for the whole domain) names the part of the domain the peer represents.
/// ok_status: the library's words for a run without failure; refused: its words for why it built
/// no curve ("" when it did), which leaves both records without a value.
/// f(u, order, failure) -> P(u) (order 0) or P'(u) (order 1) at u inside the domain; a failure (a
/// library's status written to `failure`, or an exception's message) leaves the record without a
/// value, that message its peer_status.
/// curvebench's adaptive_gk timed once per tolerance for every peer of a case's lengths (GSL's
/// qag and qags, Boost's three rules): the counterpart of them all. It costs 0.2 s a call on the
/// 1e5-segment case.
template <int Dim>
class adaptive_gk_times {
 public:
  explicit adaptive_gk_times(const any_curve<double, Dim>& c) : c_(&c) {}
  /// ns per adaptive_length(c) at relative tolerance tol.
  double operator()(double tol) {
    const auto [it, added] = ns_.try_emplace(tol, 0.0);
    if (added) {
      arclength::adaptive_options<double> o;
      o.relative_tolerance = tol;
      it->second = ns_per_call([&] {
        const auto l = arclength::adaptive_length(*c_, o);
        asm volatile("" : : "g"(&l) : "memory");
      });
    }
    return it->second;
  }

 private:
  const any_curve<double, Dim>* c_;
  std::map<double, double> ns_;
};

template <int Dim, class F>
void eval_records(const case_info& info, json& out, const any_curve<double, Dim>& c, case_reference<Dim>& ref,
                  const std::vector<double>& us, const vocab::peer& peer, const std::string& library,
                  const std::string& part, const std::string& ok_status, const std::string& refused, F&& f) {
  const double n = static_cast<double>(us.size());
  const double eps = std::numeric_limits<double>::epsilon();
  for (int order : {0, 1}) {
    std::string setting = part;
    if (order == 1) setting += std::string(setting.empty() ? "" : ",") + "derivative=1";
    peer_record r{&vocab::quantities::eval,
                  &peer,
                  setting,
                  nan,
                  nan,
                  n,
                  std::string(arclength::to_string(arclength::result_status::not_guaranteed)),
                  ok_status,
                  nan,
                  std::string(vocab::methods::eval_default.id),
                  setting,
                  nan};
    const auto ours = [&](double u) { return order == 0 ? c(u) : c.derivative(u, 1); };
    std::vector<point<double, Dim>> values(us.size());
    std::string failed = refused;
    try {
      for (std::size_t j = 0; j < us.size() && failed.empty(); ++j) values[j] = f(us[j], order, failed);
    } catch (const std::exception& e) {
      failed = e.what();
    }
    double counterpart_error = nan;
    if (failed.empty()) {
      double size = 0;
      for (double u : us) size = std::max(size, ref.exact(u, order).cwiseAbs().maxCoeff());
      if (!(size > 0)) size = 1;
      double peer_max = 0, ours_max = 0;
      for (std::size_t j = 0; j < us.size(); ++j) {
        peer_max = std::max(peer_max, ref.difference(us[j], order, values[j]));
        ours_max = std::max(ours_max, ref.difference(us[j], order, ours(us[j])));
      }
      r.error = peer_max / (eps * size);
      counterpart_error = ours_max / (eps * size);
      std::string ignored;
      r.ns_per_op = ns_per_call([&] {
                      for (double u : us) {
                        const point<double, Dim> p = f(u, order, ignored);
                        asm volatile("" : : "g"(&p) : "memory");  // keep p
                      }
                    }) /
                    n;
      r.counterpart_ns_per_op = ns_per_call([&] {
                                  for (double u : us) {
                                    const point<double, Dim> p = ours(u);
                                    asm volatile("" : : "g"(&p) : "memory");
                                  }
                                }) /
                                n;
    } else {
      r.peer_status = failed;
    }
    out.push_back(to_json(info, r, library, counterpart_error));
  }
}

}  // namespace curvebench::harness::peers_detail

namespace curvebench::harness {

/// The Boost.Math and Eigen peers of a case (harness/sweep_peers_boost_eigen.cpp), appended to out.
template <int Dim>
void boost_eigen_peers(const case_info& info, nlohmann::json& out, const any_curve<double, Dim>& c,
                       case_reference<Dim>& ref, const sweep& w, const io::field& spec,
                       peers_detail::adaptive_gk_times<Dim>& adaptive_gk_ns);

std::string boost_version();  ///< "1.74.0"
std::string eigen_version();  ///< "3.4.0"

}  // namespace curvebench::harness
