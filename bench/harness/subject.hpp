// The subject API: your own implementation (a "subject") through the accuracy measurement of
// curvebench's own methods. A subject is a name and up to three callables:
//   eval     u -> P(u)            your curve (any callable, or a curvebench::curve via curve_subject)
//   length   (u0, u1) -> length    your arc length between two parameters
//   inverse  s -> u                your parameter at arc length s from the domain's start
// or, for a keyframe channel's case, a channel_subject: t -> value (and optionally its slope).
// measure_case / measure_spec sample the case's parameters as the accuracy runner does
// (harness/sweeps.hpp: the eval sweep's sample_parameters, the s(u) and u(s) sweeps' counts of
// harness/sweep.hpp), call your functions there, and measure them through the check core
// (harness/check.hpp) against the 50-digit reference. The result is a results JSON in the format
// of reports/accuracy.json (harness/gate.hpp): records with "method": <your name>, "subject": true,
//   eval     max |P_yours(u) - P(u)|_inf / (eps(double) x size) over the eval parameters (ulps)
//   length   |length(lo, hi) - L| / L                     (as curvebench's length records)
//   s_of_u   max over u_j of |length(lo, u_j) - s(u_j)| / L (as the s_of_u records)
//   u_of_s   max over targets s_j of |s(inverse(s_j)) - s_j| / L (as the u_of_s records)
// which `curvebench gate --results` (or subject_gate below) checks with rules naming your method,
// and scripts/report.py shows beside curvebench's own methods on the same case.
//
// This header is double-only: the callables cross into the curvebench_harness library as
// std::function, where the 50-digit work is compiled once (link curvebench::harness).
//
//   namespace h = curvebench::harness;
//   h::subject<2> s;
//   s.name = "my_catmull_rom";
//   s.eval = [&](double u) { return my_curve(u); };   // a curvebench::point<double, 2>
//   s.length = [&](double u0, double u1) { return my_table.length(u0, u1); };
//   const auto results = h::measure_case(CURVEBENCH_CASES_DIR, "catmull_rom_uniform_2d", s);
//   h::write_results(results, "subject.json");            // harness/writers.hpp
//   for (const auto& b : h::subject_gate(results, "thresholds.json")) std::puts(b.c_str());
#pragma once

#include "harness/check.hpp"

#include "curvebench/core/curve.hpp"
#include "curvebench/core/point.hpp"

#include <nlohmann/json.hpp>

#include <concepts>
#include <functional>
#include <string>
#include <utility>
#include <vector>

namespace curvebench::harness {

/// Your implementation: a name (the records' "method": letters, digits, '_' and '-') and the
/// functions you have; leave the others empty. Each is called only inside the case's domain
/// (inverse: for s in [0, L]); an exception it throws is reported naming the subject and argument.
template <int Dim>
struct subject {
  std::string name;
  std::function<point<double, Dim>(double)> eval;  ///< u -> P(u)
  std::function<double(double, double)> length;    ///< (u0, u1) -> arc length from u0 to u1
  std::function<double(double)> inverse;           ///< s -> u with s(u) = s
};

/// A subject evaluating a curve of the curvebench::curve concept (double, 2D or 3D); the subject
/// keeps a copy of the curve.
template <curve C>
requires std::same_as<typename C::real_type, double>
[[nodiscard]] subject<C::dimension> curve_subject(std::string name, C c) {
  subject<C::dimension> s;
  s.name = std::move(name);
  s.eval = [c = std::move(c)](double u) -> point<double, C::dimension> { return c(u); };
  return s;
}

/// Your keyframe channel or easing (a channel spec's case): a name (as subject's) and its value at
/// time t, optionally its slope dvalue/dt. It is called at times across the keys and a quarter of
/// their span beyond each end (extrapolation included) and at the key times.
struct channel_subject {
  std::string name;
  std::function<double(double)> value;  ///< t -> value
  std::function<double(double)> slope;  ///< t -> dvalue/dt (optional)
};

struct subject_options {
  bool quick = false;  ///< the quick sweep's sample counts (65 eval, 9 s(u)/u(s); full: 257, 33)
  /// A channel subject's reference: the channel's truth, or the tool's own evaluation (what the
  /// tool shows; harness/check.hpp).
  check_against against = check_against::truth;
  std::string group;          ///< the records' group (default: the case's group)
  bool with_methods = false;  ///< also curvebench's own records for the case (the accuracy runner's
                              ///< sweeps, seconds), so that the results compare both side by side
};

/// Measures the subject on case `case_name` of the directory `cases_dir` (bench/cases, or the
/// installed share/curvebench/cases: CMake's CURVEBENCH_CASES_DIR). Returns the results JSON
/// {"schema", "suite", "records", "orders", "cases", "context"}, and "findings" when an inverse
/// answer lies outside the domain (measured, not refused: harness/check.hpp). Throws invalid_input for an
/// unknown case, a case of another dimension, a subject without a name or functions, a function
/// that throws (an inverse answer outside the domain is measured and listed in "findings").
template <int Dim>
[[nodiscard]] nlohmann::json measure_case(const std::string& cases_dir, const std::string& case_name,
                                          const subject<Dim>& s, const subject_options& options = {});

/// The same for a spec of your own (a JSON object of io/spec.hpp; "name", "group" and "reason"
/// optional: they default to "spec", "subject" and ""). `file` names the spec in errors.
template <int Dim>
[[nodiscard]] nlohmann::json measure_spec(const nlohmann::json& spec, const subject<Dim>& s,
                                          const subject_options& options = {}, const std::string& file = "spec");

/// A channel subject on a channel case or spec: records quantity eval (the value; setting
/// "derivative=1" for the slope) in ulps of double of the channel's value range, measured through
/// the check core's times check (harness/check.hpp) against options.against. A row whose value is
/// not finite is an error naming the subject and t.
[[nodiscard]] nlohmann::json measure_case(const std::string& cases_dir, const std::string& case_name,
                                          const channel_subject& s, const subject_options& options = {});
[[nodiscard]] nlohmann::json measure_spec(const nlohmann::json& spec, const channel_subject& s,
                                          const subject_options& options = {}, const std::string& file = "spec");

/// The gate (harness/gate.hpp) on results with the thresholds file at `thresholds_path` (its rules
/// may name subject methods): one line per breach, "RULE at WHERE: MESSAGE"; empty when it passes.
/// Throws invalid_input for an unreadable thresholds file or a rule naming an unknown id.
[[nodiscard]] std::vector<std::string> subject_gate(const nlohmann::json& results, const std::string& thresholds_path);

/// Results of several measurements in one (records, orders and cases appended; the first's suite
/// and context kept): e.g. a subject on several cases, or subject results beside accuracy.json's.
[[nodiscard]] nlohmann::json merge_results(nlohmann::json into, const nlohmann::json& more);

extern template nlohmann::json measure_case<2>(const std::string&, const std::string&, const subject<2>&,
                                               const subject_options&);
extern template nlohmann::json measure_case<3>(const std::string&, const std::string&, const subject<3>&,
                                               const subject_options&);
extern template nlohmann::json measure_spec<2>(const nlohmann::json&, const subject<2>&, const subject_options&,
                                               const std::string&);
extern template nlohmann::json measure_spec<3>(const nlohmann::json&, const subject<3>&, const subject_options&,
                                               const std::string&);

}  // namespace curvebench::harness
