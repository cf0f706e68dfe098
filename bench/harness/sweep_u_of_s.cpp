// The u(s) sweep: tables (linear, Hermite, Hermite + Newton polish), Newton without a table, and
// forward-difference tables, each measured by the anchored |s(u) - s| / L of case_reference::ds.
#include "harness/accuracy.hpp"
#include "harness/sweeps.hpp"

#include "curvebench/arclength/forward_difference.hpp"
#include "curvebench/arclength/parameterization.hpp"

#include <algorithm>
#include <limits>

namespace curvebench::harness {

template <int Dim>
void sweep_u_of_s(record_sink& k, const any_curve<double, Dim>& c, case_reference<Dim>& ref, const sweep& w) {
  namespace al = curvebench::arclength;
  namespace m = vocab::methods;
  using curve = any_curve<double, Dim>;
  const auto& q = vocab::quantities::u_of_s;
  constexpr double none = std::numeric_limits<double>::quiet_NaN();
  const double L = ref.length();
  std::vector<double> targets = sample_fractions(w.params);
  for (double& t : targets) t = std::min(L * t, L);
  const interval<double> d = c.domain();
  const auto ds = [&](double u, double s) { return ref.ds(std::clamp(u, d.lo, d.hi), s); };
  // A method with theory 0 has no algebraic order to fit (the polished table converges as fast as Newton does).
  const auto table_sweep = [&](al::inversion_method im, bool polish, const vocab::method& method) {
    k.begin();
    for (std::size_t intervals : w.table_intervals) {
      al::parameterization_options<double> o;
      o.method = im;
      o.table_intervals = intervals;
      o.newton_polish = polish;
      const al::parameterization<curve> p(c, o);
      double err = 0, est = 0, query = 0;
      for (double target : targets) {
        // The target may exceed this method's own L by an ulp of rounding; u(s) rejects s > L.
        const double s = std::min(target, p.length());
        if (polish) {
          const auto r = p.invert(s, im);
          err = std::max(err, ds(r.u, target));
          est = std::max(est, r.s_error_estimate / L);
          query += static_cast<double>(r.evaluations);
        } else {
          err = std::max(err, ds(p.u(s, im), target));
        }
      }
      if (!polish) est = im == al::inversion_method::hermite_table ? p.table_error() / L : none;
      k.add(q, method, setting(method, {{"M", intervals}}), err, est,
            query / static_cast<double>(targets.size()) +
                static_cast<double>(p.construction_evaluations()) / amortized_queries,
            al::to_string(p.table_status()));
    }
    k.end(q, method);
  };
  table_sweep(al::inversion_method::linear_table, false, m::linear_table);
  table_sweep(al::inversion_method::hermite_table, false, m::hermite_table);
  table_sweep(al::inversion_method::hermite_table, true, m::hermite_table_polished);
  for (double tol : w.newton_tol) {
    al::parameterization_options<double> o;
    o.method = al::inversion_method::newton;
    o.newton.relative_tolerance = tol;
    const al::parameterization<curve> p(c, o);
    double err = 0, est = 0, query = 0;
    al::result_status status = al::result_status::converged;
    for (double target : targets) {
      const auto r = p.invert(std::min(target, p.length()), al::inversion_method::newton);
      err = std::max(err, ds(r.u, target));
      est = std::max(est, r.s_error_estimate / L);
      query += static_cast<double>(r.evaluations);
      if (r.status != al::result_status::converged) status = r.status;
    }
    k.add(q, m::newton, setting(m::newton, {{"tol", tol}}), err, est,
          query / static_cast<double>(targets.size()) +
              static_cast<double>(p.construction_evaluations()) / amortized_queries,
          al::to_string(status));
  }
  const double segments = static_cast<double>(c.breakpoints().size() - 1);
  k.begin();
  for (std::size_t steps : w.table_steps) {
    if (static_cast<double>(steps) * segments > w.max_table_evals) break;
    const al::forward_difference_table<double> t(c, steps);
    double err = 0;
    for (double target : targets) err = std::max(err, ds(t.u(std::min(target, t.length().value)), target));
    k.add(q, m::forward_difference, setting(m::forward_difference, {{"steps", steps}}), err, none,
          static_cast<double>(t.evaluations()) / amortized_queries, al::to_string(al::result_status::not_guaranteed));
  }
  k.end(q, m::forward_difference);
}

template void sweep_u_of_s<2>(record_sink&, const any_curve<double, 2>&, case_reference<2>&, const sweep&);
template void sweep_u_of_s<3>(record_sink&, const any_curve<double, 3>&, case_reference<3>&, const sweep&);

}  // namespace curvebench::harness
