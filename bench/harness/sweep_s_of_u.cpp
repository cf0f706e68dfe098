// The s(u) sweep: s(u) from adaptive segment lengths (no table) and from forward-difference tables.
#include "harness/accuracy.hpp"
#include "harness/length_methods.hpp"
#include "harness/sweeps.hpp"

#include "curvebench/arclength/forward_difference.hpp"
#include "curvebench/arclength/parameterization.hpp"

#include <algorithm>
#include <limits>
#include <string>

namespace curvebench::harness {

template <int Dim>
void sweep_s_of_u(record_sink& k, const any_curve<double, Dim>& c, case_reference<Dim>& ref, const sweep& w) {
  namespace al = curvebench::arclength;
  namespace m = vocab::methods;
  const auto& q = vocab::quantities::s_of_u;
  const interval<double> d = c.domain();
  const std::vector<double> us = sample_parameters(d.lo, d.hi, w.params);
  ref.set_s_parameters(us);
  const double segments = static_cast<double>(c.breakpoints().size() - 1);
  const double L = ref.length();
  {
    al::parameterization_options<double> o;
    o.method = al::inversion_method::newton;  // no table: s(u) uses the segment lengths only
    const al::parameterization<any_curve<double, Dim>> p(c, o);
    double err = 0, est = 0, evals = 0;
    for (std::size_t j = 0; j < us.size(); ++j) {
      const auto r = p.s_result(us[j]);
      err = std::max(err, ref.s_error(j, r.value));
      est = std::max(est, r.error_estimate / L);
      evals += static_cast<double>(r.evaluations);
    }
    const double per_query = evals / static_cast<double>(us.size());
    const double build = static_cast<double>(p.construction_evaluations());
    k.add(q, m::segments_adaptive, setting(m::segments_adaptive, {}), err, est, per_query + build / amortized_queries,
          al::to_string(p.length_result().status), al::to_text(p.length_result().reason));
    k.annotate({{"query_evaluations", per_query}, {"build_evaluations", build}});
  }
  k.begin();
  for (std::size_t steps : w.table_steps) {
    if (static_cast<double>(steps) * segments > w.max_table_evals) break;
    const al::forward_difference_table<double> t(c, steps);
    double err = 0;
    for (std::size_t j = 0; j < us.size(); ++j) err = std::max(err, ref.s_error(j, t.s(us[j])));
    k.add(q, m::forward_difference, setting(m::forward_difference, {{"steps", steps}}), err,
          std::numeric_limits<double>::quiet_NaN(), static_cast<double>(t.evaluations()) / amortized_queries,
          al::to_string(al::result_status::not_guaranteed), std::string(al::reasons::chord_table_no_estimate));
    k.annotate({{"query_evaluations", 0.0}, {"build_evaluations", static_cast<double>(t.evaluations())}});
  }
  k.end(q, m::forward_difference);
}

template void sweep_s_of_u<2>(record_sink&, const any_curve<double, 2>&, case_reference<2>&, const sweep&);
template void sweep_s_of_u<3>(record_sink&, const any_curve<double, 3>&, case_reference<3>&, const sweep&);

}  // namespace curvebench::harness
