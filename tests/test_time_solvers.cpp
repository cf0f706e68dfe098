// Time solvers of a keyframe segment (channel/time_solver.hpp): every scheme in float and double on
// a stress set against a 50-digit truth that uses no solver of the library (a Bernstein sum and 200
// bisection steps written here), the exact solver at real50 against that bisection, monotonicity of
// u(t) over dense samples, the monotone-time proof checked numerically, and the errors.
#include "support/accuracy.hpp"
#include "support/fixtures.hpp"

#include "curvebench/channel/time_solver.hpp"
#include "curvebench/reference/multiprecision.hpp"

#include <gmock/gmock.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <map>
#include <random>
#include <string>
#include <vector>

namespace cb = curvebench;
namespace ch = curvebench::channel;
namespace cbt = curvebench::testing;
using cb::real50;
using ::testing::HasSubstr;

namespace {

// ---------------------------------------------------------------------------------------------
// The 50-digit truth: the cubic as the plain Bernstein sum and bisection of x(u) - t over [0, 1]
// for 200 steps (the bracket ends 2^-200 apart, below real50's 2^-166 resolution of u near 1).

real50 bernstein_sum(const std::array<real50, 4>& b, const real50& u) {
  const real50 w = real50(1) - u;
  return w * w * w * b[0] + 3 * u * w * w * b[1] + 3 * u * u * w * b[2] + u * u * u * b[3];
}

// x(u) - t as the sum of B_i(u) (x_i - t): the differences are exact near t, so a segment far from
// 0 (t0 = 1e5) keeps 50 digits relative to its span, not to its position.
real50 residual50(const std::array<real50, 4>& x, const real50& t, const real50& u) {
  return bernstein_sum({x[0] - t, x[1] - t, x[2] - t, x[3] - t}, u);
}

real50 bisect50(const std::array<real50, 4>& x, const real50& t) {
  real50 lo(0), hi(1);
  for (int k = 0; k < 200; ++k) {
    const real50 mid = (lo + hi) / 2;
    if (residual50(x, t, mid) < 0)
      lo = mid;
    else
      hi = mid;
  }
  return (lo + hi) / 2;
}

// A stress segment: control times and values (exact in float, or rounded once to Real and then
// converted back exactly, so the 50-digit twin holds the same data), and extra sample times.
struct segment {
  std::string name;
  std::array<double, 4> t;
  std::array<double, 4> v;
  std::vector<double> extra_fractions;  // sample times t0 + f (t3 - t0) besides the u grid
};

// The stress set. Time stays monotone while a = t1 - t0 >= 0, c = t3 - t2 >= 0 and (b = t2 - t1 >= 0
// or b^2 <= a c) (validated), so the extreme cases sit on that condition's boundary, where x' has a
// double root, and let the *value* handles overshoot:
// - handle_limit: time handles at the far ends (t1 = t3, t2 = t0: a = c = h, b = -h), x'(u) =
//   3 h (2u - 1)^2 vanishes at u = 1/2; value handles at 4/3 and -1/3 of the range.
// - regression_limit_a: the regression limit (a, c) = (1/3, 4/3) h, handles reaching
//   outside the interval (t2 = t0 - h/3): x'(u) = h (1 - 3u)^2, a vertical tangent at u = 1/3,
//   x = h/9; in normalized form (1/3 rounded to Real, which the validation's margin accepts).
// - regression_limit_b: the mirror (a, c) = (4/3, 1/3) h (t1 = t3 + h/3): vertical at u = 2/3,
//   x = 8 h / 9.
// - regression_limit_a_far, regression_limit_b_far: the same at t0 = 1e5 with h = 9, so every
//   control time is an integer, exact in float, and the segment sits exactly on the limit.
// - vertical_start / vertical_end: one time handle of zero length, x'(0) = 0 or x'(1) = 0.
// - cusp: x' and y' both vanish at u = 1/2 (times (0,1,0,1), values (0,1,1,0)).
// - zero_handles: both handles of zero length (x' = y' = 0 at both ends).
// - bold_s: handles crossing in time (0, 0.8, 0.2, 1), values overshooting.
// - css_1001, css_0101 (sampled densely near x = 0.001), css_04m31 = cubic-bezier(0, 4, 1, -3),
//   overshoot = cubic-bezier(0.3, 1.5, 0.7, -0.5), ease = cubic-bezier(0.25, 0.1, 0.25, 1).
// - far: t0 = 1e5 (span 10, 1280 ulps of 1e5 in float), values crossing zero.
std::vector<segment> stress_set() {
  std::vector<double> near_0001;
  for (int j = -50; j <= 50; ++j) near_0001.push_back(0.001 * (1 + j / 100.0));
  return {
      {"handle_limit", {0, 1, 0, 1}, {0, 4.0 / 3, -1.0 / 3, 1}, {}},
      {"regression_limit_a", {0, 1.0 / 3, -1.0 / 3, 1}, {0, 1.0 / 3, 4.0 / 3, 1}, {}},
      {"regression_limit_b", {0, 4.0 / 3, 2.0 / 3, 1}, {0, 1.0 / 3, 4.0 / 3, 1}, {}},
      {"regression_limit_a_far", {1e5, 1e5 + 3, 1e5 - 3, 1e5 + 9}, {-1, 2, -2, 1}, {}},
      {"regression_limit_b_far", {1e5, 1e5 + 12, 1e5 + 6, 1e5 + 9}, {1, -2, 2, -1}, {}},
      {"vertical_start", {0, 0, 2.0 / 3, 1}, {0, 1.0 / 3, 1, 1}, {}},
      {"vertical_end", {0, 1.0 / 3, 1, 1}, {0, 0, 2.0 / 3, 1}, {}},
      {"cusp", {0, 1, 0, 1}, {0, 1, 1, 0}, {}},
      {"zero_handles", {0, 0, 1, 1}, {0, 0, 1, 1}, {}},
      {"bold_s", {0, 0.8, 0.2, 1}, {0, -0.2, 1.2, 1}, {}},
      {"css_1001", {0, 1, 0, 1}, {0, 0, 1, 1}, {}},
      {"css_0101", {0, 0, 0, 1}, {0, 1, 1, 1}, near_0001},
      {"css_04m31", {0, 0, 1, 1}, {0, 4, -3, 1}, {}},
      {"overshoot", {0, 0.3, 0.7, 1}, {0, 1.5, -0.5, 1}, {}},
      {"ease", {0, 0.25, 0.25, 1}, {0, 0.1, 1, 1}, {}},
      {"far", {1e5, 1e5 + 2.5, 1e5 + 7.5, 1e5 + 10}, {-1, 2, -2, 1}, {}},
  };
}

template <class Real>
std::array<Real, 4> rounded(const std::array<double, 4>& a) {
  return {Real(a[0]), Real(a[1]), Real(a[2]), Real(a[3])};
}
template <class Real>
std::array<real50, 4> to50(const std::array<Real, 4>& a) {
  return {real50(a[0]), real50(a[1]), real50(a[2]), real50(a[3])};
}

// One sample: a time rounded to Real and its truth (u*, y*), with y* at the neighbouring times one
// ulp below and above (the window the value cannot be resolved inside, given t's own rounding).
template <class Real>
struct sample {
  Real t;
  real50 u;
  real50 y;
  real50 y_lo;  // min of y* over {t-, t, t+}
  real50 y_hi;  // max
};

template <class Real>
std::vector<sample<Real>> samples_of(const segment& s, int grid) {
  const auto tr = rounded<Real>(s.t);
  const auto x = to50(tr), v = to50(rounded<Real>(s.v));
  std::vector<Real> times;
  for (int k = 0; k <= grid; ++k) {  // u picked in real50, x(u) at 50 digits, rounded to Real
    const real50 u = real50(k) / grid;
    times.push_back(static_cast<Real>(bernstein_sum(x, u)));
  }
  for (double f : s.extra_fractions) times.push_back(tr[0] + (tr[3] - tr[0]) * Real(f));
  std::vector<sample<Real>> out;
  for (Real t : times) {
    t = std::clamp(t, tr[0], tr[3]);
    sample<Real> smp{t, bisect50(x, real50(t)), 0, 0, 0};
    smp.y = bernstein_sum(v, smp.u);
    smp.y_lo = smp.y_hi = smp.y;
    for (Real n : {std::nextafter(t, tr[0]), std::nextafter(t, tr[3])}) {
      const real50 yn = bernstein_sum(v, bisect50(x, real50(n)));
      smp.y_lo = std::min(smp.y_lo, yn);
      smp.y_hi = std::max(smp.y_hi, yn);
    }
    out.push_back(smp);
  }
  return out;
}

real50 value_range(const std::array<real50, 4>& v) {
  return *std::max_element(v.begin(), v.end()) - *std::min_element(v.begin(), v.end());
}

struct measured {
  double forward = 0;  // max |y(u) - y*(t)| in eps(Real) * value range
  double mixed = 0;    // max distance of y(u) to [y*(t-), y*(t+)] in the same unit
  int caps = 0;        // solutions stopped by an iteration cap (status cap_hit)
  double mean_evaluations = 0;
};

// Every solver on every stress segment in Real: the value at the returned u, evaluated in Real by
// de Casteljau (as a tool would), against the truth.
template <class Real>
std::map<ch::time_solver, std::map<std::string, measured>> measure_all(int grid) {
  std::map<ch::time_solver, std::map<std::string, measured>> result;
  for (const segment& s : stress_set()) {
    const auto tr = rounded<Real>(s.t), vr = rounded<Real>(s.v);
    const ch::time_cubic<Real> c{tr[0], tr[1], tr[2], tr[3]};
    const real50 range = value_range(to50(vr));
    const auto smp = samples_of<Real>(s, grid);
    for (ch::time_solver solver : ch::all_time_solvers) {
      measured m;
      long evaluations = 0;
      for (const auto& p : smp) {
        const auto sol = ch::solve_time(solver, c, p.t);
        evaluations += sol.evaluations;
        if (sol.status == cb::result_status::cap_hit) ++m.caps;
        const Real y = ch::detail::bernstein3(vr[0], vr[1], vr[2], vr[3], sol.u);
        const real50 y50(y);
        m.forward = std::max(m.forward, static_cast<double>(cbt::scaled_ulps(y, p.y, range)));
        const real50 outside = y50 < p.y_lo ? p.y_lo - y50 : (y50 > p.y_hi ? y50 - p.y_hi : real50(0));
        m.mixed = std::max(m.mixed, static_cast<double>(outside / (real50(cb::epsilon<Real>()) * range)));
      }
      m.mean_evaluations = static_cast<double>(evaluations) / static_cast<double>(smp.size());
      result[solver][s.name] = m;
    }
  }
  return result;
}

// ---------------------------------------------------------------------------------------------
// Bounds: the max over the stress set of the *mixed* error (distance of y(u) to the values the
// truth takes within one ulp of t, in eps(Real) * value range), per solver and type. Where the
// value's graph has a vertical tangent (x' = 0 with y' != 0) no forward bound in ulps exists:
// dy/dt is infinite and t itself is only known to half an ulp, so the mixed error is the one a
// solver can be held to. The value range is max v_i - min v_i of the control values, and
// |y'(u)| <= 3 max|v_{i+1} - v_i| <= 3 range.
// - bisection12, bisection30 (derived): |u - u*| <= 2^-(n+1) after n halvings and the midpoint,
//   so |y - y*| <= 3 range 2^-(n+1), plus y's own rounding in Real (de Casteljau, 3 levels of 2
//   roundings relative to the range: 6 ulps, rounded up to 8): 3 * 2^(digits-1-n-1) ulps + 8.
//   Measured: 3.07e3 and 1.65e12 (n = 12, at the derived bound), 1.08 and 6.29e6 (n = 30).
// - curvebench (the goal): 4 ulps of the range in double, mixed and forward; measured 0.66 mixed,
//   1.53 forward in double, 0.66 and 1.49 in float before the regression limits joined the set;
//   with them 0.76 mixed in double and 0.77 in float (forward: see forward_exempt). Asserted at 4
//   in both types.
// - exact: measured 0.66 mixed in both types; bound 2 (3x margin).
// - isolate_brent: measured 1.92 (float) and 1.87 (double); bound 4 (2x margin).
// - closed_form: measured 93.2 (float) and 7.73 (double, overshoot: Cardano's cancellation); 2x.
// - table_newton: |x(u) - s| < 1e-7 in normalized time, so y is off by |dy/ds| 1e-7, unbounded at
//   vertical tangents: measured 9.78e4 (float) and 5.25e13 (double, css_0101 near x = 0.001, where
//   dy/ds ~ 400); 2x margin.
// - newton_bisection: the same with 1e-6: measured 1.95e5 and 1.05e14 (css_0101); 2x margin.
struct bound {
  ch::time_solver solver;
  double float_ulps;
  double double_ulps;
};
constexpr double bisection_bound(int digits, int n) { return 3.0 * static_cast<double>(1ULL << (digits - n - 2)) + 8; }
constexpr std::array<bound, 8> bounds{{
    {ch::time_solver::closed_form, 200, 16},
    {ch::time_solver::table_newton, 2e5, 1.1e14},
    {ch::time_solver::newton_bisection, 4e5, 2.1e14},
    {ch::time_solver::bisection12, bisection_bound(24, 12), bisection_bound(53, 12)},
    {ch::time_solver::bisection30, 8 + 3.0 / 256, bisection_bound(53, 30)},
    {ch::time_solver::isolate_brent, 4, 4},
    {ch::time_solver::curvebench, 4, 4},
    {ch::time_solver::exact, 2, 2},
}};
// The forward error bound of the curvebench solver (the goal, in both types).
constexpr double curvebench_forward_ulps = 4;
// Segments where no forward bound exists: the normalized regression limits hold 1/3 rounded, which
// moves the double root of x' off its exact place by O(eps); x' is then O(eps h) near u = 1/3 (or
// 2/3), dy/dt is of order 1 / eps there, and the truth itself spreads over hundreds of ulps of the
// range within one ulp of t (measured forward errors in double: 750 and 917 for curvebench and for
// exact alike, while the mixed errors stay at 0.76 and 0.65). The exact twins at t0 = 1e5 (integer
// data, the limit held exactly) keep the forward bound: 0.75 and 1.5.
// The regression limits in float, for the two schemes whose rounding the triple root of x(u) - t at
// the vertical tangent amplifies to eps^(1/3) in u: closed_form (Cardano's cancellation) and
// bisection30 (the normalized handles (t_i - t0) / h rounded in float move the triple root by
// (eps / 3)^(1/3) ~ 3e-3 in u, beyond the window y*(t +- 1 ulp) on the far segment). Measured:
// closed_form 5010 (regression_limit_a), 1309 (a_far), 6621 (b); bisection30 741 (a_far). Bound
// 2x, on these segments only; the other segments keep the table's bounds.
double limit_bound(ch::time_solver solver, const std::string& name, double otherwise) {
  if (name.rfind("regression_limit", 0) != 0) return otherwise;
  if (solver == ch::time_solver::closed_form) return 1.4e4;
  if (solver == ch::time_solver::bisection30) return 1.5e3;
  return otherwise;
}
bool forward_exempt(const std::string& name) { return name == "regression_limit_a" || name == "regression_limit_b"; }

constexpr int stress_grid = 256;

}  // namespace

// ---------------------------------------------------------------------------------------------
// Accuracy

TEST(time_solvers, measure_by_solver) {
  const auto f = measure_all<float>(stress_grid);
  const auto d = measure_all<double>(stress_grid);
  std::cout << std::setprecision(3);
  std::cout << "solver            | float mixed forward caps evals | double mixed forward caps evals\n";
  for (const bound& b : bounds) {
    measured mf, md;
    for (const auto& [name, m] : f.at(b.solver)) {
      mf.mixed = std::max(mf.mixed, m.mixed);
      mf.forward = std::max(mf.forward, m.forward);
      mf.caps += m.caps;
      mf.mean_evaluations = std::max(mf.mean_evaluations, m.mean_evaluations);
      EXPECT_LE(m.mixed, limit_bound(b.solver, name, b.float_ulps)) << ch::to_string(b.solver) << " float " << name;
      if (b.solver == ch::time_solver::curvebench && !forward_exempt(name)) {
        EXPECT_LE(m.forward, curvebench_forward_ulps) << name;
      }
      EXPECT_EQ(m.caps, 0) << ch::to_string(b.solver) << " float " << name;
    }
    for (const auto& [name, m] : d.at(b.solver)) {
      md.mixed = std::max(md.mixed, m.mixed);
      md.forward = std::max(md.forward, m.forward);
      md.caps += m.caps;
      md.mean_evaluations = std::max(md.mean_evaluations, m.mean_evaluations);
      EXPECT_LE(m.mixed, b.double_ulps) << ch::to_string(b.solver) << " double " << name;
      if (b.solver == ch::time_solver::curvebench && !forward_exempt(name)) {
        EXPECT_LE(m.forward, curvebench_forward_ulps) << name;
      }
      EXPECT_EQ(m.caps, 0) << ch::to_string(b.solver) << " double " << name;
    }
    std::cout << std::left << std::setw(18) << ch::to_string(b.solver) << "| " << mf.mixed << " " << mf.forward << " "
              << mf.caps << " " << mf.mean_evaluations << " | " << md.mixed << " " << md.forward << " " << md.caps
              << " " << md.mean_evaluations << "\n";
  }
  // The per-segment detail of the double errors, for the record.
  for (const auto& [solver, per] : d) {
    std::cout << ch::to_string(solver) << ":";
    for (const auto& [name, m] : per) std::cout << " " << name << "=" << m.mixed << "/" << m.forward;
    std::cout << "\n";
  }
}

// Cost: nanoseconds per solve in double over the stress set's sample times (printed, not asserted:
// a timing depends on the machine and its load; the report quotes it), and the mean number of
// residual evaluations per solve per segment for the curvebench and exact solvers.
TEST(time_solvers, cost_by_solver) {
  struct query {
    ch::time_cubic<double> c;
    double t;
  };
  std::vector<query> queries;
  std::map<std::string, std::pair<double, double>> evaluations;  // segment -> (curvebench, exact) mean
  for (const segment& s : stress_set()) {
    const auto tr = rounded<double>(s.t);
    const ch::time_cubic<double> c{tr[0], tr[1], tr[2], tr[3]};
    double e_cb = 0, e_ex = 0;
    int n = 0;
    for (int k = 0; k <= 1000; ++k) {
      const double t = std::clamp(tr[0] + (tr[3] - tr[0]) * k / 1000.0, tr[0], tr[3]);
      queries.push_back({c, t});
      e_cb += ch::solve_time(ch::time_solver::curvebench, c, t).evaluations;
      e_ex += ch::solve_time(ch::time_solver::exact, c, t).evaluations;
      ++n;
    }
    evaluations[s.name] = {e_cb / n, e_ex / n};
  }
  for (const auto& [name, e] : evaluations)
    std::cout << name << ": evaluations curvebench " << e.first << ", exact " << e.second << "\n";
  for (ch::time_solver solver : ch::all_time_solvers) {
    double sink = 0;
    const auto start = std::chrono::steady_clock::now();
    constexpr int reps = 5;
    for (int r = 0; r < reps; ++r)
      for (const query& q : queries) sink += ch::solve_time(solver, q.c, q.t).u;
    const double ns = std::chrono::duration<double, std::nano>(std::chrono::steady_clock::now() - start).count() /
                      (reps * static_cast<double>(queries.size()));
    std::cout << std::left << std::setw(18) << ch::to_string(solver) << std::setprecision(3) << ns
              << " ns per solve (checksum " << sink << ")\n";
    EXPECT_TRUE(std::isfinite(sink));
  }
}

// ---------------------------------------------------------------------------------------------
// u against the truth directly, where the inversion is well conditioned (x' >= h / 4 at u*, so
// |du| <= 4 |dx| / h): the curvebench and exact solvers land within a few ulps of u*. Bound: the
// residual's rounding (de Casteljau of t_i - t: 3 levels of 2 roundings plus the differences,
// 8 eps h) divided by x' >= h / 4 gives 32 eps, plus u's own rounding (1/2 ulp): 33 eps absolute.
template <class Real>
void check_u_where_well_conditioned() {
  for (const segment& s : stress_set()) {
    const auto tr = rounded<Real>(s.t);
    const ch::time_cubic<Real> c{tr[0], tr[1], tr[2], tr[3]};
    const auto x = to50(tr);
    const real50 h = x[3] - x[0];
    for (const auto& p : samples_of<Real>(s, 64)) {
      const real50 w = real50(1) - p.u;  // x'(u*) from its Bernstein form
      const real50 slope = 3 * (w * w * (x[1] - x[0]) + 2 * p.u * w * (x[2] - x[1]) + p.u * p.u * (x[3] - x[2]));
      if (slope < h / 4) continue;
      for (ch::time_solver solver : {ch::time_solver::curvebench, ch::time_solver::exact}) {
        const Real u = ch::solve_time(solver, c, p.t).u;
        EXPECT_TRUE(cbt::within_scaled_ulps(u, p.u, real50(1), 33)) << s.name << " " << ch::to_string(solver);
      }
    }
  }
}
TEST(time_solvers, u_against_truth_float) { check_u_where_well_conditioned<float>(); }
TEST(time_solvers, u_against_truth_double) { check_u_where_well_conditioned<double>(); }

// The exact solver at real50 on arbitrary times (not images of chosen u) against the 200-step
// bisection: the residual |x(u) - t| within 16 eps50 h (de Casteljau's rounding bound 8 eps h,
// doubled), and u within 64 eps50 where x' >= h / 4 (16 eps h / (h / 4)).
TEST(time_solvers, exact_at_real50_matches_bisection) {
  for (const segment& s : stress_set()) {
    const auto x = to50(rounded<double>(s.t));
    const ch::time_cubic<real50> c{x[0], x[1], x[2], x[3]};
    const real50 h = x[3] - x[0];
    for (int k = 0; k <= 40; ++k) {
      const real50 t = x[0] + h * real50(k) / 40 + (k > 0 && k < 40 ? h / 7919 : real50(0));
      const auto sol = ch::solve_time(ch::time_solver::exact, c, t);
      ASSERT_EQ(sol.status, cb::result_status::converged) << s.name << " k=" << k;
      using std::abs;
      EXPECT_LE(abs(residual50(x, t, sol.u)), 16 * cb::epsilon<real50>() * h) << s.name << " k=" << k;
      const real50 truth = bisect50(x, t);
      const real50 w = real50(1) - truth;
      const real50 slope = 3 * (w * w * (x[1] - x[0]) + 2 * truth * w * (x[2] - x[1]) + truth * truth * (x[3] - x[2]));
      if (slope >= h / 4) {
        EXPECT_TRUE(cbt::within_scaled_ulps(sol.u, truth, real50(1), 64)) << s.name << " k=" << k;
      }
    }
  }
}

// u(t) non-decreasing over 20001 equispaced times of every stress segment, for every solver: the
// monotonicity the curvebench solver promises, and measured for the others too (no violation for
// any solver in float or double; bisection is monotone by construction, the iterative schemes
// because x is monotone and their stopping rules do not reorder neighbouring times here).
template <class Real>
void check_monotone() {
  for (const segment& s : stress_set()) {
    const auto tr = rounded<Real>(s.t);
    const ch::time_cubic<Real> c{tr[0], tr[1], tr[2], tr[3]};
    for (ch::time_solver solver : ch::all_time_solvers) {
      int violations = 0;
      Real previous(-1);
      for (int k = 0; k <= 20000; ++k) {
        const Real t = std::clamp(tr[0] + (tr[3] - tr[0]) * Real(k) / Real(20000), tr[0], tr[3]);
        const Real u = ch::solve_time(solver, c, t).u;
        if (u < previous) ++violations;
        previous = u;
      }
      EXPECT_EQ(violations, 0) << s.name << " " << ch::to_string(solver);
    }
  }
}
TEST(time_solvers, monotone_float) { check_monotone<float>(); }
TEST(time_solvers, monotone_double) { check_monotone<double>(); }

// The header's monotonicity condition checked against x' itself on a grid of handle positions
// a, c in [0, 1.5] (steps of 1/24, exact in real50 up to the 1/3 multiples): the validation
// accepts exactly the segments whose min over u of x'(u) (the quadratic's minimum at its vertex
// when inside [0, 1], else at the ends; computed in real50) is >= -1e-40 (real50's rounding), and
// the two regression limits are among the accepted ones, in double and in real50.
TEST(time_solvers, monotone_condition_is_exact) {
  int accepted = 0, rejected = 0;
  for (int i = 0; i <= 36; ++i)
    for (int j = 0; j <= 36; ++j) {
      const real50 a = real50(i) / 24, c = real50(j) / 24, b = 1 - a - c;
      // min over [0, 1] of a (1-u)^2 + 2 b u (1-u) + c u^2 = (a - 2b + c) u^2 + 2 (b - a) u + a.
      const real50 qa = a - 2 * b + c, qb = 2 * (b - a);
      real50 m = std::min(a, c);
      if (qa > 0) {
        const real50 u = -qb / (2 * qa);
        if (u > 0 && u < 1) m = std::min(m, (qa * u + qb) * u + a);
      }
      const bool monotone = m >= real50(-1e-40);
      const ch::time_cubic<real50> c50{real50(0), a, 1 - c, real50(1)};
      const ch::time_cubic<double> c64{0, static_cast<double>(a), static_cast<double>(1 - c), 1};
      bool ok50 = true;
      try {
        ch::validate_time_cubic(c50);
      } catch (const cb::invalid_input&) {
        ok50 = false;
      }
      EXPECT_EQ(ok50, monotone) << "a=" << a << " c=" << c << " min x'/3h=" << m;
      // In double the rounded handles may cross the boundary by rounding; away from it (min x'/3h
      // beyond 1e-12 either way) the verdict must agree.
      if (abs(m) > real50(1e-12)) {
        bool ok64 = true;
        try {
          ch::validate_time_cubic(c64);
        } catch (const cb::invalid_input&) {
          ok64 = false;
        }
        EXPECT_EQ(ok64, monotone) << "a=" << a << " c=" << c;
      }
      (monotone ? accepted : rejected)++;
    }
  EXPECT_GT(accepted, 0);
  EXPECT_GT(rejected, 0);
  for (const ch::time_cubic<double>& lim :
       {ch::time_cubic<double>{0, 1.0 / 3, -1.0 / 3, 1}, ch::time_cubic<double>{0, 4.0 / 3, 2.0 / 3, 1},
        ch::time_cubic<double>{0, 3, -3, 9}, ch::time_cubic<double>{0, 12, 6, 9}})
    EXPECT_NO_THROW(ch::validate_time_cubic(lim)) << lim.t1 << " " << lim.t2;
  const real50 third = real50(1) / 3;
  EXPECT_NO_THROW(ch::validate_time_cubic(ch::time_cubic<real50>{real50(0), third, -third, real50(1)}));
  EXPECT_NO_THROW(ch::validate_time_cubic(ch::time_cubic<real50>{real50(0), 4 * third, 2 * third, real50(1)}));
}

// Every solver on the regression limits returns u in [0, 1] with x(u) = t to its own tolerance:
// |x(u) - t| / h within the solver's stopping rule, checked at 2003 times each, including the
// vertical-tangent times h/9 and 8h/9. Here x'(u) = h (1 - 3u)^2 (or h (2 - 3u)^2), at most 4 h.
TEST(time_solvers, regression_limits_solve_inside) {
  for (const ch::time_cubic<double>& c :
       {ch::time_cubic<double>{0, 1.0 / 3, -1.0 / 3, 1}, ch::time_cubic<double>{0, 4.0 / 3, 2.0 / 3, 1},
        ch::time_cubic<double>{1e5, 1e5 + 3, 1e5 - 3, 1e5 + 9},
        ch::time_cubic<double>{1e5, 1e5 + 12, 1e5 + 6, 1e5 + 9}}) {
    const double h = c.t3 - c.t0;
    std::vector<double> times;
    for (int k = 0; k <= 2000; ++k) times.push_back(c.t0 + h * k / 2000.0);
    times.push_back(c.t0 + h / 9);
    times.push_back(c.t0 + 8 * h / 9);
    for (ch::time_solver solver : ch::all_time_solvers) {
      double worst = 0;
      for (double t : times) {
        t = std::clamp(t, c.t0, c.t3);
        const double u = ch::solve_time(solver, c, t).u;
        ASSERT_GE(u, 0.0) << ch::to_string(solver);
        ASSERT_LE(u, 1.0) << ch::to_string(solver);
        const auto x = to50(std::array<double, 4>{c.t0, c.t1, c.t2, c.t3});
        worst = std::max(worst, static_cast<double>(abs(residual50(x, real50(t), real50(u))) / real50(h)));
      }
      // The tolerance of each scheme on |x(u) - t| / h: closed_form's cancellation at the triple
      // root of x(u) - t at the vertical tangent (cube root of eps: 1e-5 relative), the tool
      // schemes' 1e-7 and 1e-6, bisection's midpoint within 2^-(n+1) of the root times max x' = 4 h,
      // the others' rounding level (a few eps, 1e-11 here relative to h since t0 = 1e5 carries
      // 1e5 / 9 times h's ulp).
      const double allowed = solver == ch::time_solver::closed_form        ? 1e-5
                             : solver == ch::time_solver::table_newton     ? 1e-7
                             : solver == ch::time_solver::newton_bisection ? 1e-6
                             : solver == ch::time_solver::bisection12      ? 4 * 0x1p-13
                             : solver == ch::time_solver::bisection30      ? 4 * 0x1p-31
                                                                           : 1e-11;
      EXPECT_LE(worst, allowed) << ch::to_string(solver) << " t1=" << c.t1 << " t2=" << c.t2;
      std::cout << "regression limit t1=" << c.t1 << " t2=" << c.t2 << " " << ch::to_string(solver)
                << ": max |x(u) - t| / h = " << worst << "\n";
    }
  }
}

// closed_form next to a double root at u = 0 (a zero-width start handle: x(u) = 1.2 u^2 - 0.2 u^3)
// with t a few ulps after the start: the discriminant, truly -8 (t / h) + O(t^2), is a difference of
// two 64s and rounds to >= 0, and the one root the formula then gives is u = 6, clamped to 1 (the
// segment's end value; OpenUSD Ts's recorded random/17 showed it). The root is sqrt(t / 1.2) ~ 2e-8;
// closed_form now bisects when it finds no root within 16 eps of [0, 1]. Checked: the residual
// |x(u) - t| / h within the bisection's tolerance, 4 eps, and u below 1e-7 (u itself is
// ill-conditioned there: a double root amplifies eps to sqrt(eps)).
TEST(time_solvers, closed_form_finds_the_root_next_to_a_double_root_at_the_start) {
  const ch::time_cubic<double> c{0, 0, 0.4, 1};
  for (double t : {0x1p-52, 0x1p-51, 0x1p-50}) {
    const auto s = ch::solve_time(ch::time_solver::closed_form, c, t);
    EXPECT_LT(s.u, 1e-7) << t;
    const double x = 1.2 * s.u * s.u - 0.2 * s.u * s.u * s.u;
    EXPECT_LE(std::abs(x - t), 4 * std::numeric_limits<double>::epsilon()) << t;
  }
}

// ---------------------------------------------------------------------------------------------
// Interface and errors

TEST(time_solvers, ids_round_trip) {
  for (ch::time_solver s : ch::all_time_solvers) EXPECT_EQ(ch::time_solver_from_string(ch::to_string(s)), s);
  EXPECT_STREQ(ch::to_string(ch::time_solver::table_newton), "table_newton");
  const std::string m = cbt::message_of([] { (void)ch::time_solver_from_string("newton"); });
  EXPECT_THAT(m, HasSubstr("time solver = \"newton\""));
  EXPECT_THAT(m, HasSubstr("closed_form"));
}

TEST(time_solvers, ends_and_counts) {
  const ch::time_cubic<double> c{2, 2.5, 3, 4};
  for (ch::time_solver s : ch::all_time_solvers) {
    const auto lo = ch::solve_time(s, c, 2.0), hi = ch::solve_time(s, c, 4.0);
    // Bisection returns the midpoint of its last bracket: within 2^-(n+1) of the end.
    const double slack =
        s == ch::time_solver::bisection12 ? 0x1p-13 : (s == ch::time_solver::bisection30 ? 0x1p-31 : 1e-6);
    EXPECT_NEAR(lo.u, 0.0, slack) << ch::to_string(s);
    EXPECT_NEAR(hi.u, 1.0, slack) << ch::to_string(s);
    const auto mid = ch::solve_time(s, c, 3.0);
    // The schemes that test their answer converge here; closed_form and bisectionN test nothing.
    const bool untested =
        s == ch::time_solver::closed_form || s == ch::time_solver::bisection12 || s == ch::time_solver::bisection30;
    EXPECT_EQ(mid.status, untested ? cb::result_status::not_guaranteed : cb::result_status::converged)
        << ch::to_string(s);
    EXPECT_EQ(mid.converged(), !untested) << ch::to_string(s);
    EXPECT_GE(mid.evaluations, s == ch::time_solver::closed_form ? 0 : 1) << ch::to_string(s);
  }
}

TEST(time_solvers, bad_segments_name_the_field) {
  using C = ch::time_cubic<double>;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const auto msg = [](C c) { return cbt::message_of([&] { (void)ch::solve_time(ch::time_solver::exact, c, c.t0); }); };
  EXPECT_THAT(msg({0, nan, 0.5, 1}), HasSubstr("t1 = nan: must be finite"));
  EXPECT_THAT(msg({1, 1, 1, 1}), HasSubstr("t3 = 1 <= t0 = 1"));
  EXPECT_THAT(msg({0, -0.5, 0.5, 1}), HasSubstr("t1 = -0.5: must be >= t0 = 0 (the handle points backwards"));
  EXPECT_THAT(msg({0, 0.5, 1.5, 1}), HasSubstr("t2 = 1.5: must be <= t3 = 1 (the handle points backwards"));
  // a = 1.5, c = 0.5, 1 - a - c = -1: (-1)^2 > 0.75, x'(1/2) < 0.
  EXPECT_THAT(msg({0, 1.5, 0.5, 1}), HasSubstr("t1 = 1.5, t2 = 0.5 with [t0, t3] = [0, 1]: the handles regress"));
  EXPECT_THAT(msg({0, 1.5, 0.5, 1}), HasSubstr("time runs backwards"));
  // Just past the limit (1/3, 4/3) by 1/64 of h: b^2 - a c = 0.0117 h^2, clearly regressive.
  EXPECT_THAT(msg({0, 1.0 / 3 + 1.0 / 64, -1.0 / 3, 1}), HasSubstr("the handles regress"));
  // Handles outside the interval that keep time monotone are valid now: a = 0.5, c = 1.25.
  EXPECT_NO_THROW((void)ch::solve_time(ch::time_solver::exact, C{0, 0.5, -0.25, 1}, 0.5));
  EXPECT_THAT(msg({1e15, 1e15, 1e15, 1e15 + 1}), HasSubstr("t3 - t0"));
  EXPECT_THROW((void)ch::solve_time(ch::time_solver::exact, C{0, nan, 0.5, 1}, 0.0), cb::invalid_input);
}

TEST(time_solvers, time_outside_the_segment_is_a_domain_error) {
  const ch::time_cubic<double> c{0, 0.25, 0.75, 2};
  EXPECT_THROW((void)ch::solve_time(ch::time_solver::curvebench, c, 2.5), std::domain_error);
  EXPECT_THAT(cbt::message_of([&] { (void)ch::solve_time(ch::time_solver::curvebench, c, 2.5); }),
              HasSubstr("t = 2.5 is outside the segment's time interval [0, 2]"));
  EXPECT_THROW((void)ch::solve_time(ch::time_solver::closed_form, c, std::nan("")), std::domain_error);
}

// Caps are reported: the solvers with a residual tolerance converge on every stress sample
// (measure_by_solver asserts zero caps), so the flag is exercised through the iteration limit of
// Brent's method, and bisection12 reports exactly its 12 halvings.
TEST(time_solvers, caps_are_reported_not_hidden) {
  const ch::time_cubic<double> c{0, 0, 1, 1};
  const auto b = ch::solve_time(ch::time_solver::bisection12, c, 0.3);
  EXPECT_EQ(b.iterations, 12);
  int evaluations = 0;
  const auto r = ch::detail::brent_root(
      [&](double u) {
        ++evaluations;
        return u * u * u - 0.3;  // not linear: the secant does not hit the root at once
      },
      0.0, 1.0, -0.3, 0.7, 0.0, 2);
  EXPECT_EQ(r.status, cb::result_status::cap_hit);
  EXPECT_EQ(r.iterations, 2);
  EXPECT_EQ(evaluations, 2);
}

// Beyond the stress set: 120 random segments (handle times uniform in [t0, t3], values in
// [-1, 1], t0 in [-10, 10], span in [0.1, 10]) and 16 random times each, in double: the curvebench
// and exact solvers' mixed error within the 4-ulp goal. Measured: 2.37 for both. The two solvers
// agree, so the excess over the stress set is y's own rounding (relative to max|v_i|, which
// exceeds the range when the values do not straddle zero), which is also why exact's stress-set
// bound of 2 does not carry over to these data.
TEST(time_solvers, random_segments_double) {
  std::mt19937 gen(20261124);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  double worst_cb = 0, worst_exact = 0;
  for (int seg = 0; seg < 120; ++seg) {
    const double t0 = -10 + 20 * unit(gen), h = 0.1 + 9.9 * unit(gen);
    segment s{"random", {t0, t0 + h * unit(gen), t0 + h * unit(gen), t0 + h}, {0, 0, 0, 0}, {}};
    for (double& v : s.v) v = 2 * unit(gen) - 1;
    const auto tr = rounded<double>(s.t), vr = rounded<double>(s.v);
    const ch::time_cubic<double> c{tr[0], tr[1], tr[2], tr[3]};
    const auto x = to50(tr), v = to50(vr);
    const real50 range = value_range(v);
    for (int k = 0; k < 16; ++k) {
      const double t = std::clamp(tr[0] + (tr[3] - tr[0]) * unit(gen), tr[0], tr[3]);
      real50 lo = bernstein_sum(v, bisect50(x, real50(t))), hi = lo;
      for (double n : {std::nextafter(t, tr[0]), std::nextafter(t, tr[3])}) {
        const real50 yn = bernstein_sum(v, bisect50(x, real50(n)));
        lo = std::min(lo, yn);
        hi = std::max(hi, yn);
      }
      for (ch::time_solver solver : {ch::time_solver::curvebench, ch::time_solver::exact}) {
        const double u = ch::solve_time(solver, c, t).u;
        const real50 y(ch::detail::bernstein3(vr[0], vr[1], vr[2], vr[3], u));
        const real50 out = y < lo ? lo - y : (y > hi ? y - hi : real50(0));
        const double e = static_cast<double>(out / (real50(cb::epsilon<double>()) * range));
        (solver == ch::time_solver::curvebench ? worst_cb : worst_exact) =
            std::max(solver == ch::time_solver::curvebench ? worst_cb : worst_exact, e);
      }
    }
  }
  std::cout << "random segments, max mixed error in double: curvebench " << worst_cb << ", exact " << worst_exact
            << " ulps of the value range\n";
  EXPECT_LE(worst_cb, 4);
  EXPECT_LE(worst_exact, 4);
}
