// The evaluation sweep: the error of each evaluation algorithm the case's family offers, in
// eps(double) x the curve's size, against the 50-digit points of case_reference. The per-family
// dispatch below (concrete types behind any_curve, Lagrange rebuilt from the spec) is to be
// replaced by the family registry of io/.
#include "harness/sweeps.hpp"

#include "curvebench/io/spec.hpp"

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
  if (const auto* b = c.template target<bezier<double, Dim>>()) {
    for (auto a : {bezier_algorithm::de_casteljau, bezier_algorithm::bernstein_sum, bezier_algorithm::horner})
      measure(to_string(a), [&](double u) { return b->evaluate(u, a); });
  }
  const auto cubic = [&](const auto* f) {
    if (!f) return;
    for (auto a : {cubic_algorithm::power, cubic_algorithm::matrix, cubic_algorithm::bezier})
      measure(to_string(a), [&](double u) { return f->engine().evaluate(u, 0, a); });
  };
  cubic(c.template target<cardinal_spline<double, Dim>>());
  cubic(c.template target<hermite_spline<double, Dim>>());
  cubic(c.template target<kochanek_bartels<double, Dim>>());
  cubic(c.template target<natural_cubic_spline<double, Dim>>());
  const auto spline = [&](const auto* f) {
    if (!f) return;
    for (auto a : {bspline_evaluation::de_boor, bspline_evaluation::basis_sum})
      measure(to_string(a), [&](double u) { return f->evaluate(u, 0, a); });
  };
  spline(c.template target<bspline<double, Dim>>());
  spline(c.template target<nurbs<double, Dim>>());
  if (c.family() == "lagrange") {  // the algorithm is fixed at construction: build both from the spec
    for (const char* a : {"barycentric", "monomial"}) {
      nlohmann::json twin = spec;
      twin["algorithm"] = a;
      const any_curve<double, Dim> t = io::curve_from_spec<double, Dim>(io::root(twin));
      measure(a, [&](double u) { return t(u); });
    }
  }
}

template void sweep_eval<2>(record_sink&, const any_curve<double, 2>&, case_reference<2>&, const sweep&,
                            const nlohmann::json&);
template void sweep_eval<3>(record_sink&, const any_curve<double, 3>&, case_reference<3>&, const sweep&,
                            const nlohmann::json&);

}  // namespace curvebench::harness
