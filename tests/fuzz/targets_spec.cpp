// The spec target (targets.hpp): a JSON curve spec through everything the tool's `length` and
// `sample` do with it, in double: every length method of the length table
// (harness/length_methods.hpp), with the tool's default options where they scale the work only
// with the curve (adaptive tolerance 1e-12), the library's default subdivision tolerance (1e-6 of
// the curve's size), a budget of 2^19 evaluations for both adaptive methods, and small fixed
// options where they scale the work by themselves (gauss n = 5, 4 panels, 64 table steps, a u(s)
// table of at most 1024 intervals), so that the time an input takes comes from the input.
//
// Properties, each a distinct name in the violation message:
//   documented exceptions only   parse and build refuse with invalid_input / io::spec_error only
//   no internal domain error     nothing after the build throws std::domain_error: every parameter
//                                and arc length asked for lies inside the domain / [0, L]
//   finite domain                the domain is finite with lo <= hi
//   (out of range)               P(u), P'(u), P''(u) at 9 parameters across the domain: when one is
//                                not finite the curve leaves double's range and its results are
//                                not representable (the tool refuses them), so nothing else is checked
//   finite length                each length method's value is finite and >= 0
//   estimate is a number         no error estimate is NaN or negative
//   converged means bounded      a converged result has a finite error estimate
//   length at least the chord    a length plus its (finite) estimate is at least the polygon
//                                through P at the 9 parameters and the interior breakpoints,
//                                broken where segments do not meet (64 ulps of rounding allowed)
//   converged estimates agree    two converged lengths differ by at most the sum of their
//                                estimates plus 64 ulps of the length (else one estimate lies)
//   s(u) finite and in [0, L]    at 9 parameters (outside by at most the larger of 1e-9 L and the
//                                two estimates: s(u) integrates from the nearest table node, L sums
//                                the segments; a degenerate curve's s(u) is noise, not checked)
//   u(s) inside the domain       table lookup, invert() and Newton at 5 arc lengths in [0, L]
//   bounded work                 every phase stays within its budget of curve evaluations: 1e6
//                                plus 2000 per segment (the documented caps of the methods above
//                                stay far below it on every case file), and within 30 s of wall
//                                time; a method without an overall cap stops here, named, instead
//                                of running into libFuzzer's timeout
// Curves of more than 1000 segments are built and evaluated only (see max_segments).
#include "guard.hpp"
#include "targets.hpp"

#include "harness/length_methods.hpp"

#include "curvebench/arclength/adaptive_subdivision.hpp"
#include "curvebench/arclength/forward_difference.hpp"
#include "curvebench/arclength/length.hpp"
#include "curvebench/arclength/parameterization.hpp"
#include "curvebench/core/any_curve.hpp"
#include "curvebench/io/spec.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>
#include <optional>
#include <span>
#include <sstream>
#include <string>
#include <vector>

namespace curvebench::fuzz {

namespace {

namespace al = curvebench::arclength;
constexpr std::string_view name = "spec";
constexpr std::size_t max_segments = 1000;

std::string num(double x) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", x);
  return buf;
}

/// Counts the curve evaluations of the phase under way and stops a phase that exceeds its budget.
struct meter {
  std::string phase;
  std::size_t count = 0;
  std::size_t budget = 0;
  std::chrono::steady_clock::time_point start{};
  static constexpr double max_seconds = 30;

  void begin(std::string p) {
    phase = std::move(p);
    count = 0;
    start = std::chrono::steady_clock::now();
  }
  void tick() {
    ++count;
    if (count > budget)
      violation(name, "bounded work",
                phase + ": more than " + std::to_string(budget) + " curve evaluations (no overall cap stopped it)");
    if (count % 65536 == 0) {
      const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      if (s > max_seconds)
        violation(name, "bounded work",
                  phase + ": still running after " + num(s) + " s and " + std::to_string(count) + " curve evaluations");
    }
  }
};

/// The curve with every evaluation counted by a meter (shared: the parameterization copies it).
template <int Dim>
struct metered_curve {
  using real_type = double;
  using point_type = point<double, Dim>;
  static constexpr int dimension = Dim;

  any_curve<double, Dim> c;
  std::shared_ptr<meter> m;

  [[nodiscard]] interval<double> domain() const { return c.domain(); }
  [[nodiscard]] point_type operator()(const double& u) const {
    m->tick();
    return c(u);
  }
  [[nodiscard]] point_type derivative(const double& u, int order) const {
    m->tick();
    return c.derivative(u, order);
  }
  [[nodiscard]] point_type value_from_left(const double& u) const {
    m->tick();
    return c.value_from_left(u);
  }
  [[nodiscard]] std::span<const double> breakpoints() const { return c.breakpoints(); }
};

void check_result(std::string_view method, const al::quadrature_result<double>& r) {
  const std::string what = std::string(method) + ": value " + num(r.value) + ", estimate " + num(r.error_estimate) +
                           ", status " + std::string(al::to_string(r.status));
  if (!std::isfinite(r.value) || r.value < 0) violation(name, "finite length", what);
  if (std::isnan(r.error_estimate) || r.error_estimate < 0) violation(name, "estimate is a number", what);
  if (r.status == al::result_status::converged && !std::isfinite(r.error_estimate))
    violation(name, "converged means bounded", what);
}

/// The 9 parameters lo, lo + (hi - lo) k / 8, hi, each inside the domain.
std::vector<double> parameters(interval<double> d) {
  std::vector<double> us;
  for (int k = 0; k <= 8; ++k) {
    double u = k == 0 ? d.lo : k == 8 ? d.hi : d.lo + (d.hi - d.lo) * (k / 8.0);
    if (!(u >= d.lo && u <= d.hi)) u = d.lo * (1 - k / 8.0) + d.hi * (k / 8.0);  // hi - lo overflowed
    if (u >= d.lo && u <= d.hi) us.push_back(u);
  }
  return us;
}

template <int Dim>
void check_curve(const any_curve<double, Dim>& built) {
  const interval<double> d = built.domain();
  if (!std::isfinite(d.lo) || !std::isfinite(d.hi) || !(d.lo <= d.hi))
    violation(name, "finite domain", "[" + num(d.lo) + ", " + num(d.hi) + "]");
  const auto m = std::make_shared<meter>();
  const std::size_t segments = built.breakpoints().empty() ? 1 : built.breakpoints().size() - 1;
  m->budget = 1000000 + 2000 * segments;
  const metered_curve<Dim> c{built, m};
  const std::vector<double> us = parameters(d);
  // Past max_segments only the build and the evaluation run: the length methods cost in proportion
  // to the segments (seconds per input under the sanitizers at 1e5), which measures scale, not bugs.
  const bool measure = segments <= max_segments;

  m->begin("evaluation");
  bool out_of_range = false;  // a value or derivative beyond double's range somewhere
  run_step(name, "evaluation", domain_errors::violation, [&] {
    for (double u : us)
      for (int order = 0; order <= 2; ++order) {
        const point<double, Dim> p = order == 0 ? c(u) : c.derivative(u, order);
        for (int i = 0; i < Dim; ++i)
          if (!std::isfinite(p[i])) out_of_range = true;
      }
  });
  // A curve whose values or derivatives leave double's range (data near 1e308, a knot span of
  // 1e-300 whose 1/h^2 overflows) has results that are not representable: the tool refuses to print
  // them (tool::require_finite, hostile cases edge_*), so nothing below applies. Every other curve
  // must give finite lengths, s(u) and u(s): "finite length" below is the property that caught
  // null lengths for coordinates near 1e200, whose evaluations are all finite.
  if (out_of_range || !measure) return;

  // Length by every method of the length table (harness/length_methods.hpp), as `curvebench
  // length` runs them, at its defaults but for the settings that scale the work by themselves
  // (table steps: 64) and subdivision's tolerance (the library's default, 1e-6 of the curve's
  // size). A cap of 2^19 evaluations on the adaptive methods (their defaults, 2^22 and 2^24, are
  // above this target's meter): that the cap is honoured is what "bounded work" checks here.
  std::vector<std::pair<std::string, al::quadrature_result<double>>> lengths;
  harness::run_context context;
  context.max_evaluations = std::size_t(1) << 19;
  harness::for_each_row(harness::length_methods, [&](const auto& row) {
    harness::setting_values v = harness::default_settings(row);
    if (v.count("steps")) v["steps"] = 64;
    if (row.method == &harness::vocab::methods::subdivision)
      v["tol"] = al::subdivision_options<double>{}.relative_tolerance;
    const std::string method(row.method->id);
    m->begin("length " + method);
    run_step(name, "length " + method, domain_errors::violation, [&] {
      const al::quadrature_result<double> r = row.prepare(c, v, context)();
      check_result(method, r);
      lengths.emplace_back(method, r);
    });
  });
  // The polygon through P(us) and the interior breakpoints, broken at each breakpoint (from P(b-)
  // to P(b): segments need not meet, and L is the integral of |P'| over them, without the jumps),
  // is never longer than the curve: a length (with its estimate) below it is wrong, whatever its
  // status says. stableNorm: the chords of 1e-170 coordinates must not underflow to 0 as the
  // lengths do. Evaluated on the built curve: the meter counts the methods' work only.
  std::vector<double> qs(us);
  const std::span<const double> bp = built.breakpoints();
  for (std::size_t i = 1; i + 1 < bp.size(); ++i)
    if (bp[i] > d.lo && bp[i] < d.hi) qs.push_back(bp[i]);
  std::sort(qs.begin(), qs.end());
  qs.erase(std::unique(qs.begin(), qs.end()), qs.end());  // a breakpoint among us: one leg ends there
  double chord = 0;
  for (std::size_t k = 0; k + 1 < qs.size(); ++k)
    chord += (built.value_from_left(qs[k + 1]) - built(qs[k])).stableNorm();
  if (std::isfinite(chord))
    for (const auto& [method, r] : lengths)
      if (std::isfinite(r.error_estimate) &&
          r.value + r.error_estimate < chord * (1 - 64 * std::numeric_limits<double>::epsilon()))
        violation(name, "length at least the chord",
                  method + ": value " + num(r.value) + " + estimate " + num(r.error_estimate) + " < chord " +
                      num(chord) + " through 9 points (status " + std::string(al::to_string(r.status)) + ")");
  for (std::size_t i = 0; i < lengths.size(); ++i)
    for (std::size_t j = i + 1; j < lengths.size(); ++j) {
      const auto& [ni, a] = lengths[i];
      const auto& [nj, b] = lengths[j];
      if (!a.converged() || !b.converged()) continue;
      const double slack = 64 * std::numeric_limits<double>::epsilon() * std::max(a.value, b.value);
      if (!(std::abs(a.value - b.value) <= a.error_estimate + b.error_estimate + slack))
        violation(name, "converged estimates agree",
                  ni + " " + num(a.value) + " +- " + num(a.error_estimate) + " and " + nj + " " + num(b.value) +
                      " +- " + num(b.error_estimate) + " differ by " + num(std::abs(a.value - b.value)));
    }

  // s(u) and u(s), as `sample` computes them: the Hermite table (capped small) and Newton.
  for (const al::inversion_method method : {al::inversion_method::hermite_table, al::inversion_method::newton}) {
    const std::string label = method == al::inversion_method::newton ? "newton" : "hermite_table";
    al::parameterization_options<double> opt;
    opt.method = method;
    opt.max_table_intervals = 1024;
    opt.max_evaluations = std::size_t(1) << 19;  // under this target's meter (the default is 2^25)
    std::optional<al::parameterization<metered_curve<Dim>>> param;
    m->begin("parameterization " + label);
    // A curve of zero length has no arc-length parameterization: invalid_input, documented.
    if (!run_step(name, "parameterization " + label, domain_errors::violation, [&] { param.emplace(c, opt); }))
      continue;
    const double L = param->length();
    if (!std::isfinite(L) || !(L > 0)) violation(name, "finite length", label + ": parameterization length " + num(L));
    m->begin("s(u) " + label);
    run_step(name, "s(u) " + label, domain_errors::violation, [&] {
      for (double u : us) {
        const al::quadrature_result<double> q = param->s_result(u);
        check_result("s(u) " + label + " at u = " + num(u), q);
        // Outside [0, L] by more than both estimates. A degenerate curve (length 0 or rounding noise
        // of its size) has s(u) and L at its noise level, documented as such: not checked.
        const double slack = std::max(1e-9 * L, q.error_estimate + param->length_result().error_estimate);
        if (!param->degenerate() && !(q.value >= -slack && q.value <= L + slack))
          violation(name, "s(u) finite and in [0, L]",
                    label + ": s(" + num(u) + ") = " + num(q.value) + ", L = " + num(L));
      }
    });
    m->begin("u(s) " + label);
    run_step(name, "u(s) " + label, domain_errors::violation, [&] {
      for (int k = 0; k <= 4; ++k) {
        const double s = k == 4 ? L : L * (k / 4.0);
        const double u = param->u(s);
        if (!(u >= d.lo && u <= d.hi))
          violation(name, "u(s) inside the domain",
                    label + ": u(" + num(s) + ") = " + num(u) + " outside [" + num(d.lo) + ", " + num(d.hi) + "]");
        const al::inversion_result<double> r = param->invert(s, method);
        const std::string what = label + " invert(" + num(s) + "): u " + num(r.u) + ", estimate " +
                                 num(r.s_error_estimate) + ", status " + std::string(al::to_string(r.status));
        if (!(r.u >= d.lo && r.u <= d.hi)) violation(name, "u(s) inside the domain", what);
        if (std::isnan(r.s_error_estimate) || r.s_error_estimate < 0) violation(name, "estimate is a number", what);
        if (r.status == al::result_status::converged && !std::isfinite(r.s_error_estimate))
          violation(name, "converged means bounded", what);
      }
    });
  }
}

template <int Dim>
void build_and_check(const io::field& spec) {
  std::optional<any_curve<double, Dim>> c;
  if (!run_step(name, "build", domain_errors::violation, [&] { c.emplace(io::curve_from_spec<double, Dim>(spec)); }))
    return;
  check_curve<Dim>(*c);
}

}  // namespace

int spec_target(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  io::json j;
  if (!run_step(name, "parse", domain_errors::violation, [&] { j = io::parse(text, "fuzz.json"); })) return 0;
  const io::field spec = io::root(j, "fuzz.json");
  int dim = 0;
  if (!run_step(name, "dimension", domain_errors::violation, [&] { dim = io::spec_dimension(spec); })) return 0;
  switch (dim) {
    case 1: build_and_check<1>(spec); break;
    case 2: build_and_check<2>(spec); break;
    case 3: build_and_check<3>(spec); break;
    case 4: build_and_check<4>(spec); break;
    default: violation(name, "documented exceptions only", "spec_dimension returned " + std::to_string(dim));
  }
  return 0;
}

}  // namespace curvebench::fuzz
