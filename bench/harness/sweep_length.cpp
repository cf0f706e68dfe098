// The length sweep: every length method and setting of harness/sweep.hpp against the reference L.
#include "harness/sweeps.hpp"

#include "curvebench/arclength/result.hpp"

namespace curvebench::harness {

template <int Dim>
void sweep_length(record_sink& k, const any_curve<double, Dim>& c, const case_reference<Dim>& ref, const sweep& w) {
  const double L = ref.length();
  const vocab::method* current = nullptr;  // the method whose series is open
  k.begin();
  for_each_length_method(c, w, L, [&](const vocab::method& m, const std::string& setting, auto run) {
    if (&m != current) {
      if (current) k.end(vocab::quantities::length, *current);
      current = &m;
    }
    const auto r = run();
    k.add(vocab::quantities::length, m, setting, ref.length_error_of(r.value), r.error_estimate / L,
          static_cast<double>(r.evaluations), arclength::to_string(r.status));
  });
  if (current) k.end(vocab::quantities::length, *current);
}

template void sweep_length<2>(record_sink&, const any_curve<double, 2>&, const case_reference<2>&, const sweep&);
template void sweep_length<3>(record_sink&, const any_curve<double, 3>&, const case_reference<3>&, const sweep&);

}  // namespace curvebench::harness
