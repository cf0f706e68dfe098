// The accuracy runner's sweeps, one translation unit each, all double code: the exact values they
// compare against come from case_reference (harness/reference.hpp, the one 50-digit unit). Each
// adds its records (and fitted orders) to the case's record_sink; run_case (harness/accuracy.cpp)
// calls them in this order. Explicitly instantiated for Dim 2 and 3.
#pragma once

#include "harness/records.hpp"
#include "harness/reference.hpp"
#include "harness/sweep.hpp"

#include "curvebench/core/any_curve.hpp"

#include <nlohmann/json.hpp>

#include <cmath>
#include <cstddef>
#include <string>
#include <vector>

namespace curvebench::harness {

/// n sample fractions in [0, 1]: 0, 1 and the golden-ratio sequence frac(j / phi) in between.
/// The points are spread evenly but never on a uniform grid, so they do not coincide with the
/// nodes of the tables being measured (which would measure the table's exact nodes, not its error).
inline std::vector<double> sample_fractions(std::size_t n) {
  std::vector<double> f(n);
  const double inv_phi = 0.6180339887498949;  // 1 / golden ratio
  for (std::size_t j = 0; j < n; ++j)
    f[j] = j == 0 ? 0.0 : j + 1 == n ? 1.0 : std::fmod(static_cast<double>(j) * inv_phi, 1.0);
  return f;
}

/// n sample parameters over the domain [lo, hi] (fractions of sample_fractions; 1 maps to hi exactly).
inline std::vector<double> sample_parameters(double lo, double hi, std::size_t n) {
  std::vector<double> us = sample_fractions(n);
  for (double& u : us) u = u == 1.0 ? hi : lo + (hi - lo) * u;
  return us;
}

/// length: every length method and setting of the length table (harness/length_methods.hpp), |L_method - L| / L.
template <int Dim>
void sweep_length(record_sink& k, const any_curve<double, Dim>& c, const case_reference<Dim>& ref, const sweep& w);

/// s_of_u: s(u) from adaptive segment lengths, and from forward-difference tables, at w.params parameters.
template <int Dim>
void sweep_s_of_u(record_sink& k, const any_curve<double, Dim>& c, case_reference<Dim>& ref, const sweep& w);

/// u_of_s: every method and setting of the u(s) table (harness/length_methods.hpp), at
/// w.params targets, measured by the anchored |s(u) - s| / L (case_reference::ds).
template <int Dim>
void sweep_u_of_s(record_sink& k, const any_curve<double, Dim>& c, case_reference<Dim>& ref, const sweep& w);

/// eval: the evaluation error of each algorithm the family offers (spec: the case's spec, from
/// which families whose algorithm is fixed at construction are rebuilt).
template <int Dim>
void sweep_eval(record_sink& k, const any_curve<double, Dim>& c, case_reference<Dim>& ref, const sweep& w,
                const nlohmann::json& spec);

/// channel (cases of type "channel"): per time solver (vocab::time_solver_methods) in float and
/// double (setting bits=32 / bits=64), records of channel_value, channel_keys, channel_monotone and
/// channel_time against the same spec evaluated at real50 with the exact inversion, at
/// w.channel_times sorted times over the keyed range widened by a quarter on each side. Returns
/// the case's channel summary: tool, keys, value_range, window, samples, refused (solvers whose
/// float model refuses the rounded keys, with the message), picture (values and handles), and for
/// tool "exact" models (each tool's rules applied to the same keys and the largest difference per
/// pair over the keyed range, in value ranges).
nlohmann::json sweep_channel(record_sink& k, const case_info& info, const sweep& w);

/// glTF rotation channels (gltf cases with "path": "rotation"): per rotation method of the case's
/// interpolation (step; linear: slerp and nlerp; cubicspline) in float and double, a
/// channel_rotation record (the angle to the same sampler at real50, in eps radians; fields rms
/// and norm) at w.channel_times times over the keys widened by a quarter on each side. Returns the
/// case's channel summary: tool, path, interpolation, keys, largest_segment_angle (radians),
/// window, samples, refused.
nlohmann::json sweep_rotation(record_sink& k, const case_info& info, const sweep& w);

/// Seed 001's properties measured on a 2D case: the markdown row, or null when not audited.
nlohmann::json sweep_audit(const case_info& info);

}  // namespace curvebench::harness
