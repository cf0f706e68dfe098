// The evaluation sweep: the error of each evaluation algorithm the case's family offers, in
// eps(double) x the curve's size, against the 50-digit points of case_reference. The algorithms
// come from the family registry (io/registry.hpp), so a new family's algorithms are measured
// without an edit here.
#include "harness/sweeps.hpp"

#include "curvebench/io/registry.hpp"

#include <string>

namespace curvebench::harness {

template <int Dim>
void sweep_eval(record_sink& k, const any_curve<double, Dim>& c, case_reference<Dim>& ref, const sweep& w,
                const nlohmann::json& spec) {
  const interval<double> d = c.domain();
  const std::vector<double> us = sample_parameters(d.lo, d.hi, w.eval_params);
  ref.set_eval_parameters(us);
  std::vector<point<double, Dim>> values(us.size());
  const auto measure = [&](std::string_view algorithm, auto&& eval) {
    for (std::size_t j = 0; j < us.size(); ++j) values[j] = eval(us[j]);
    k.add_eval(algorithm, ref.eval_error(values), static_cast<double>(us.size()));
  };
  measure(vocab::methods::eval_default.id, [&](double u) { return c(u); });
  // The other algorithms the family offers, from its registry entry (io/families/<type>.hpp).
  for (const auto& [name, eval] : io::evaluation_algorithms<Dim>(c, spec)) measure(name, eval);
}

template void sweep_eval<2>(record_sink&, const any_curve<double, 2>&, case_reference<2>&, const sweep&,
                            const nlohmann::json&);
template void sweep_eval<3>(record_sink&, const any_curve<double, 3>&, case_reference<3>&, const sweep&,
                            const nlohmann::json&);

}  // namespace curvebench::harness
