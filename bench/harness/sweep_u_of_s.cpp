// The u(s) sweep: every method and setting of the u(s) table (harness/length_methods.hpp: tables
// linear, Hermite, Hermite + Newton polish, Newton without a table, forward-difference tables),
// each measured by the anchored |s(u) - s| / L of case_reference::ds.
#include "harness/accuracy.hpp"
#include "harness/length_methods.hpp"
#include "harness/sweeps.hpp"

#include <algorithm>
#include <limits>
#include <string>

namespace curvebench::harness {

template <int Dim>
void sweep_u_of_s(record_sink& k, const any_curve<double, Dim>& c, case_reference<Dim>& ref, const sweep& w) {
  namespace al = curvebench::arclength;
  const auto& q = vocab::quantities::u_of_s;
  constexpr double none = std::numeric_limits<double>::quiet_NaN();
  const double L = ref.length();
  std::vector<double> targets = sample_fractions(w.params);
  for (double& t : targets) t = std::min(L * t, L);
  const interval<double> d = c.domain();
  const auto ds = [&](double u, double s) { return ref.ds(std::clamp(u, d.lo, d.hi), s); };
  const double segments = static_cast<double>(c.breakpoints().size() - 1);
  // A method with theory 0 has no algebraic order to fit (the polished table converges as fast as Newton does).
  for_each_row(u_of_s_methods, [&](const auto& row) {
    k.begin();
    for (const setting_values& v : row.series(w, segments)) {
      const u_of_s_run run = row.prepare(c, v);
      double err = 0, est = 0, query = 0;
      al::result_status status = al::result_status::converged;
      std::string reason;
      for (double target : targets) {
        // The target may exceed this method's own L by an ulp of rounding; u(s) rejects s > L.
        const u_of_s_answer a = run.query(std::min(target, run.length));
        err = std::max(err, ds(a.u, target));
        est = std::max(est, a.estimate / L);
        query += a.evaluations;
        if (a.status != al::result_status::converged) status = a.status, reason = a.reason;
      }
      if (!row.estimate)
        est = none;
      else if (run.table_estimate)
        est = *run.table_estimate / L;
      const double per_query = query / static_cast<double>(targets.size());
      k.add(q, *row.method, format_setting(row, v), err, est,
            per_query + run.construction_evaluations / amortized_queries, al::to_string(status), reason);
      // The cost's two parts apart: where a table competes with a per-query method, the report gives
      // the query count at which the table's build pays off (scripts/report_summary.py, break_even).
      k.annotate({{"query_evaluations", per_query}, {"build_evaluations", run.construction_evaluations}});
    }
    k.end(q, *row.method);
  });
}

template void sweep_u_of_s<2>(record_sink&, const any_curve<double, 2>&, case_reference<2>&, const sweep&);
template void sweep_u_of_s<3>(record_sink&, const any_curve<double, 3>&, case_reference<3>&, const sweep&);

}  // namespace curvebench::harness
