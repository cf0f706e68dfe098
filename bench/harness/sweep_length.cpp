// The length sweep: every length method and setting of the length table
// (harness/length_methods.hpp) against the reference L.
#include "harness/length_methods.hpp"
#include "harness/sweeps.hpp"

#include "curvebench/arclength/result.hpp"

#include <limits>

namespace curvebench::harness {

template <int Dim>
void sweep_length(record_sink& k, const any_curve<double, Dim>& c, const case_reference<Dim>& ref, const sweep& w) {
  const double L = ref.length();
  const double segments = static_cast<double>(c.breakpoints().size() - 1);
  run_context x;
  x.reference_length = L;
  for_each_row(length_methods, [&](const auto& row) {
    k.begin();
    for (const setting_values& v : row.series(w, segments)) {
      const auto r = row.prepare(c, v, x)();
      k.add(vocab::quantities::length, *row.method, format_setting(row, v), ref.length_error_of(r.value),
            row.estimate ? r.error_estimate / L : std::numeric_limits<double>::quiet_NaN(),
            static_cast<double>(r.evaluations), arclength::to_string(r.status), arclength::to_text(r.reason));
    }
    k.end(vocab::quantities::length, *row.method);
  });
}

template void sweep_length<2>(record_sink&, const any_curve<double, 2>&, const case_reference<2>&, const sweep&);
template void sweep_length<3>(record_sink&, const any_curve<double, 3>&, const case_reference<3>&, const sweep&);

}  // namespace curvebench::harness
