// The peer sweep: the libraries users would pick instead of curvebench, run on the
// case's own data and measured against the same 50-digit reference (case_reference) as
// curvebench's methods, so that their records and ours compare directly.
//
// GSL (the Debian libgsl-dev the build requires):
//   eval    gsl_spline with gsl_interp_cspline (end "natural") or gsl_interp_cspline_periodic (end
//           "periodic"), one spline per coordinate on the spec's knots, at the eval sweep's
//           parameters; error in eps(double) x the curve's size like curvebench's eval records,
//           and the first derivative (gsl_spline_eval_deriv, setting "derivative=1") in eps x the
//           exact derivative's size beside curvebench's own derivative ("counterpart_error").
//           Only natural_cubic cases with those two ends are the same mathematical curve; GSL has
//           no clamped or not-a-knot end, and its akima and steffen interpolants are no curvebench
//           family, so they have no 50-digit reference here (bench_gsl times them).
//   length  gsl_integration_qag (GSL_INTEG_GAUSS15, the rule of curvebench's adaptive_gk) and
//           gsl_integration_qags of the speed |P'(u)| (the same arclength::speed curvebench
//           integrates) over the whole domain, as arc-length code commonly calls them: epsabs 0,
//           epsrel = each adaptive_gk tolerance of the sweep, a workspace of 1000 intervals. The
//           estimate is the abserr GSL returns (relative to L), so "bounded" says whether it
//           bounds the true error. GSL's own status is kept as "peer_status" (gsl_strerror).
//   u_of_s  what arc-length code built on GSL does for u(s): the total length by qag first (the
//           ends: s <= 0 gives the domain's start, s >= that length its end), then
//           gsl_root_fsolver_brent on g(u) = s(u) - s over the domain, each s(u) a qag from the
//           domain's start (GAUSS15, epsabs 0, epsrel = tol), stopping when |g(u)| <= tol L
//           (gsl_root_test_residual) or after 100 iterations (cap_hit); tol = each Newton
//           tolerance of the sweep, whose curvebench counterpart is Newton u(s) at the same tol.
//           Error: the anchored |s(u) - s| / L of case_reference::ds, like curvebench's u(s)
//           records; estimate: |g(u)| + the last qag's abserr, relative to L (what the two GSL
//           calls say about |s(u) - s|).
// Every peer record also carries the time per operation of the peer and of its curvebench
// counterpart, measured back to back on the same thread (best of three batches; the runner's
// other threads share the machine, so compare the ratio, not the absolute times), and the
// counterpart's method and setting so the report joins its error record.
#include "harness/peers.hpp"
#include "harness/sweeps.hpp"

#include "harness/length_methods.hpp"  // the vocabulary entries of adaptive_gk and newton
#include "harness/peer_record.hpp"

#include "harness/setting.hpp"

#include "curvebench/arclength/length.hpp"
#include "curvebench/arclength/parameterization.hpp"
#include "curvebench/arclength/result.hpp"
#include "curvebench/io/spec_data.hpp"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_integration.h>
#include <gsl/gsl_roots.h>
#include <gsl/gsl_spline.h>
#include <gsl/gsl_version.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <limits>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

namespace curvebench::harness {

namespace {

using json = nlohmann::json;

using namespace peers_detail;

/// "GSL <version>": the library field of GSL's records.
std::string gsl_library() { return "GSL " GSL_VERSION; }

/// GSL's default error handler aborts the process; the peers' failures are data here. The
/// handler is global in GSL, so it is switched off once, before any thread calls GSL.
void gsl_errors_are_statuses() {
  static std::once_flag once;
  std::call_once(once, [] { gsl_set_error_handler_off(); });
}

struct spline_deleter {
  void operator()(gsl_spline* s) const { gsl_spline_free(s); }
};
struct accel_deleter {
  void operator()(gsl_interp_accel* a) const { gsl_interp_accel_free(a); }
};

/// One GSL spline per coordinate of a natural_cubic spec, or nothing when GSL cannot represent it.
template <int Dim>
struct gsl_coordinate_splines {
  const vocab::peer* peer = nullptr;
  std::string peer_status;
  std::array<std::unique_ptr<gsl_spline, spline_deleter>, Dim> splines;
  std::array<std::unique_ptr<gsl_interp_accel, accel_deleter>, Dim> accels;

  explicit gsl_coordinate_splines(const io::field& spec) {
    if (spec.member("type").string() != "natural_cubic") return;
    const std::string end = spec.has("end") ? spec.member("end").string() : "natural";
    const gsl_interp_type* type = nullptr;
    if (end == "natural") {
      type = gsl_interp_cspline;
      peer = &vocab::peers::gsl_cspline;
    } else if (end == "periodic") {
      type = gsl_interp_cspline_periodic;
      peer = &vocab::peers::gsl_cspline_periodic;
    } else {
      return;  // clamped, not_a_knot: GSL has neither end condition
    }
    const point_list<double, Dim> p = io::points_of<double, Dim>(spec);
    const std::vector<double> x = io::knots_of<double>(spec, p.size());
    std::vector<double> y(p.size());
    for (int d = 0; d < Dim; ++d) {
      for (std::size_t i = 0; i < p.size(); ++i) y[i] = p[i][d];
      splines[d].reset(gsl_spline_alloc(type, x.size()));
      accels[d].reset(gsl_interp_accel_alloc());
      if (!splines[d] || !accels[d]) throw std::bad_alloc();
      const int status = gsl_spline_init(splines[d].get(), x.data(), y.data(), x.size());
      if (status != GSL_SUCCESS) {
        peer_status = gsl_strerror(status);
        return;
      }
    }
    peer_status = gsl_strerror(GSL_SUCCESS);
  }

  [[nodiscard]] bool ready() const { return peer && peer_status == gsl_strerror(GSL_SUCCESS); }

  /// P(u) (order 0) or P'(u) (order 1) and GSL's status (the first failing coordinate's).
  point<double, Dim> operator()(double u, int order, int& status) const {
    point<double, Dim> out;
    status = GSL_SUCCESS;
    for (int d = 0; d < Dim; ++d) {
      const int s = order == 0 ? gsl_spline_eval_e(splines[d].get(), u, accels[d].get(), &out[d])
                               : gsl_spline_eval_deriv_e(splines[d].get(), u, accels[d].get(), &out[d]);
      if (s != GSL_SUCCESS && status == GSL_SUCCESS) status = s;
    }
    return out;
  }
};

/// eval records of the GSL splines (peers_detail::eval_records) at the eval sweep's parameters; a
/// spline GSL refused to build is a record without a value that keeps GSL's status.
template <int Dim>
void gsl_eval(const case_info& info, json& out, const any_curve<double, Dim>& c, case_reference<Dim>& ref,
              const sweep& w, const io::field& spec) {
  const gsl_coordinate_splines<Dim> g(spec);
  if (!g.peer) return;
  const interval<double> d = c.domain();
  const std::vector<double> us = sample_parameters(d.lo, d.hi, w.eval_params);
  eval_records<Dim>(info, out, c, ref, us, *g.peer, gsl_library(), "", gsl_strerror(GSL_SUCCESS),
                    g.ready() ? std::string() : g.peer_status, [&](double u, int order, std::string& failure) {
                      int status = GSL_SUCCESS;
                      const point<double, Dim> p = g(u, order, status);
                      if (status != GSL_SUCCESS) failure = gsl_strerror(status);
                      return p;
                    });
}

template <int Dim>
struct speed_integrand {
  const any_curve<double, Dim>* c;
  std::size_t calls = 0;
  static double call(double u, void* self) {
    auto* s = static_cast<speed_integrand*>(self);
    ++s->calls;
    return arclength::speed(*s->c, u);
  }
};

/// Whether a QUADPACK status comes with a value: GSL_EBADTOL and the like return before integrating.
bool integrated(int status) {
  return status == GSL_SUCCESS || status == GSL_EMAXITER || status == GSL_EROUND || status == GSL_ESING ||
         status == GSL_EDIVERGE;
}

/// QUADPACK's statuses as result_status names: converged, or the reason it stopped.
std::string status_name(int status) {
  using arclength::result_status;
  switch (status) {
    case GSL_SUCCESS: return std::string(arclength::to_string(result_status::converged));
    case GSL_EMAXITER: return std::string(arclength::to_string(result_status::cap_hit));
    case GSL_EROUND: return std::string(arclength::to_string(result_status::rounding_limited));
    default: return std::string(arclength::to_string(result_status::not_guaranteed));
  }
}

template <int Dim>
void gsl_length(const case_info& info, json& out, const any_curve<double, Dim>& c, const case_reference<Dim>& ref,
                const sweep& w, adaptive_gk_times<Dim>& adaptive_gk_ns) {
  constexpr std::size_t limit = 1000;  // the workspace size of GSL's own examples
  const std::unique_ptr<gsl_integration_workspace, void (*)(gsl_integration_workspace*)> ws(
      gsl_integration_workspace_alloc(limit), gsl_integration_workspace_free);
  if (!ws) throw std::bad_alloc();
  const interval<double> d = c.domain();
  const double L = ref.length();
  namespace m = vocab::methods;
  for (const vocab::peer* peer : {&vocab::peers::gsl_qag, &vocab::peers::gsl_qags}) {
    const bool qags = peer == &vocab::peers::gsl_qags;
    for (double tol : w.adaptive_tol) {
      speed_integrand<Dim> f{&c};
      gsl_function F{&speed_integrand<Dim>::call, &f};
      double value = 0, abserr = 0;
      const auto integrate = [&] {
        return qags
                   ? gsl_integration_qags(&F, d.lo, d.hi, 0.0, tol, limit, ws.get(), &value, &abserr)
                   : gsl_integration_qag(&F, d.lo, d.hi, 0.0, tol, limit, GSL_INTEG_GAUSS15, ws.get(), &value, &abserr);
      };
      const int status = integrate();
      const std::size_t calls = f.calls;
      const bool has_value = integrated(status);
      const std::string s = setting(m::adaptive_gk, {{"tol", tol}});
      peer_record r{&vocab::quantities::length,
                    peer,
                    s,
                    has_value ? ref.length_error_of(value) : std::numeric_limits<double>::quiet_NaN(),
                    has_value ? abserr / L : std::numeric_limits<double>::quiet_NaN(),
                    static_cast<double>(calls),
                    status_name(status),
                    gsl_strerror(status),
                    std::numeric_limits<double>::quiet_NaN(),
                    std::string(m::adaptive_gk.id),
                    s,
                    std::numeric_limits<double>::quiet_NaN()};
      if (has_value) {
        r.ns_per_op = ns_per_call([&] {
          integrate();
          asm volatile("" : : "g"(&value) : "memory");
        });
        r.counterpart_ns_per_op = adaptive_gk_ns(tol);
      }
      out.push_back(to_json(info, r, gsl_library()));
    }
  }
}

/// gsl_u_of_s's root function: g(u) = qag(speed, lo, u) - target, remembering the last point it
/// was called at (Brent's root after an iteration is the point it evaluated last).
template <int Dim>
struct s_of_u_root {
  speed_integrand<Dim>* speed;
  gsl_integration_workspace* ws;
  std::size_t limit;
  double lo, tol, target;
  double last_u = 0, last_g = 0, last_abserr = 0;
  int worst_status = GSL_SUCCESS;
  static double call(double u, void* self) {
    auto* r = static_cast<s_of_u_root*>(self);
    gsl_function F{&speed_integrand<Dim>::call, r->speed};
    double s = 0, abserr = 0;
    const int status =
        u > r->lo ? gsl_integration_qag(&F, r->lo, u, 0.0, r->tol, r->limit, GSL_INTEG_GAUSS15, r->ws, &s, &abserr)
                  : GSL_SUCCESS;
    if (status != GSL_SUCCESS && r->worst_status == GSL_SUCCESS) r->worst_status = status;
    r->last_u = u;
    r->last_g = s - r->target;
    r->last_abserr = abserr;
    return r->last_g;
  }
};

template <int Dim>
void gsl_u_of_s(const case_info& info, json& out, const any_curve<double, Dim>& c, case_reference<Dim>& ref,
                const sweep& w) {
  constexpr std::size_t limit = 1000;
  constexpr int max_iterations = 100;
  const std::unique_ptr<gsl_integration_workspace, void (*)(gsl_integration_workspace*)> ws(
      gsl_integration_workspace_alloc(limit), gsl_integration_workspace_free);
  const std::unique_ptr<gsl_root_fsolver, void (*)(gsl_root_fsolver*)> brent(
      gsl_root_fsolver_alloc(gsl_root_fsolver_brent), gsl_root_fsolver_free);
  if (!ws || !brent) throw std::bad_alloc();
  const interval<double> d = c.domain();
  const double L = ref.length();
  std::vector<double> targets = sample_fractions(w.params);
  for (double& t : targets) t = std::min(L * t, L);
  namespace m = vocab::methods;
  for (double tol : w.newton_tol) {
    speed_integrand<Dim> speed{&c};
    s_of_u_root<Dim> root{&speed, ws.get(), limit, d.lo, tol, 0.0};
    gsl_function G{&s_of_u_root<Dim>::call, &root};
    int status = GSL_SUCCESS;  // the first failure over the targets
    bool capped = false;
    double estimate = 0;  // max over the targets, relative to L
    // The curve's length by qag, once: the targets at or beyond it map to the domain's end.
    root.target = 0;
    const double total = s_of_u_root<Dim>::call(d.hi, &root), total_abserr = root.last_abserr;
    status = root.worst_status;
    const std::string s = setting(m::newton, {{"tol", tol}});
    if (!integrated(status)) {  // a tolerance qag refuses: no u to measure, the refusal is the record
      out.push_back(
          to_json(info,
                  peer_record{&vocab::quantities::u_of_s, &vocab::peers::gsl_qag_brent, s, nan, nan, 0.0,
                              status_name(status), gsl_strerror(status), nan, std::string(m::newton.id), s, nan},
                  gsl_library()));
      continue;
    }
    // One query: u with |s(u) - s| <= tol L by GSL's account, or the status of why not.
    const auto solve = [&](double target) {
      root.target = target;
      root.worst_status = GSL_SUCCESS;
      double u = d.hi, residual = 0, abserr = total_abserr;
      if (!(target > 0)) {
        u = d.lo;
        abserr = 0;
      } else if (target < total) {
        int st = gsl_root_fsolver_set(brent.get(), &G, d.lo, d.hi);
        int iter = 0;
        while (st == GSL_SUCCESS) {
          st = gsl_root_fsolver_iterate(brent.get());
          u = gsl_root_fsolver_root(brent.get());
          if (root.last_u != u) s_of_u_root<Dim>::call(u, &root);
          residual = std::abs(root.last_g);
          abserr = root.last_abserr;
          if (st != GSL_SUCCESS || gsl_root_test_residual(root.last_g, tol * L) == GSL_SUCCESS) break;
          if (++iter == max_iterations) {
            capped = true;
            break;
          }
        }
        if (st != GSL_SUCCESS && status == GSL_SUCCESS) status = st;
      } else {
        residual = std::abs(total - target);
      }
      if (root.worst_status != GSL_SUCCESS && status == GSL_SUCCESS) status = root.worst_status;
      estimate = std::max(estimate, (residual + abserr) / L);
      return u;
    };
    double err = 0;
    for (double target : targets) err = std::max(err, ref.ds(std::clamp(solve(target), d.lo, d.hi), target));
    const double calls = static_cast<double>(speed.calls) / static_cast<double>(targets.size());
    peer_record r{&vocab::quantities::u_of_s,
                  &vocab::peers::gsl_qag_brent,
                  s,
                  err,
                  estimate,
                  calls,
                  status_name(capped && status == GSL_SUCCESS ? GSL_EMAXITER : status),
                  capped && status == GSL_SUCCESS ? "gsl_root_fsolver_brent: 100 iterations without the residual test"
                                                  : gsl_strerror(status),
                  nan,
                  std::string(m::newton.id),
                  s,
                  nan};
    const double n = static_cast<double>(targets.size());
    r.ns_per_op = ns_per_call([&] {
                    for (double target : targets) {
                      const double u = solve(target);
                      asm volatile("" : : "g"(&u) : "memory");
                    }
                  }) /
                  n;
    arclength::parameterization_options<double> o;
    o.method = arclength::inversion_method::newton;
    o.newton.relative_tolerance = tol;
    const arclength::parameterization<any_curve<double, Dim>> p(c, o);
    r.counterpart_ns_per_op = ns_per_call([&] {
                                for (double target : targets) {
                                  const auto q =
                                      p.invert(std::min(target, p.length()), arclength::inversion_method::newton);
                                  asm volatile("" : : "g"(&q) : "memory");
                                }
                              }) /
                              n;
    out.push_back(to_json(info, r, gsl_library()));
  }
}

}  // namespace

json peer_versions() { return {{"GSL", GSL_VERSION}, {"Boost.Math", boost_version()}, {"Eigen", eigen_version()}}; }

template <int Dim>
json sweep_peers(const case_info& info, const any_curve<double, Dim>& c, case_reference<Dim>& ref, const sweep& w) {
  gsl_errors_are_statuses();
  json out = json::array();
  const io::field spec = io::root(info.spec, info.name);
  gsl_eval<Dim>(info, out, c, ref, w, spec);
  adaptive_gk_times<Dim> adaptive_gk_ns(c);
  gsl_length<Dim>(info, out, c, ref, w, adaptive_gk_ns);
  gsl_u_of_s<Dim>(info, out, c, ref, w);
  boost_eigen_peers<Dim>(info, out, c, ref, w, spec, adaptive_gk_ns);
  return out;
}

template json sweep_peers<2>(const case_info&, const any_curve<double, 2>&, case_reference<2>&, const sweep&);
template json sweep_peers<3>(const case_info&, const any_curve<double, 3>&, case_reference<3>&, const sweep&);

const peer_sweeps& library_peers() {
  static const peer_sweeps peers{sweep_peers<2>, sweep_peers<3>, peer_versions};
  return peers;
}

}  // namespace curvebench::harness
