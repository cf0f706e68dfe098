// Time inversion of a keyframe channel's Bezier segment: the parameter u in [0, 1] with x(u) = t,
// where x(u) = sum_i B_i^3(u) t_i is the cubic Bernstein polynomial of the segment's control times
// t0..t3. Every animation tool solves this before it evaluates the value v(u); each does it its
// own way, and this header offers each scheme behind one function, solve_time(solver, cubic, t).
//
// Monotone time: x'(u) / 3 is the quadratic Bernstein polynomial a (1-u)^2 + 2 b u (1-u) + c u^2
// with a = t1 - t0, c = t3 - t2 and b = t2 - t1 = (t3 - t0) - a - c, and a quadratic in this form
// is >= 0 on [0, 1] exactly when a >= 0, c >= 0 and (b >= 0 or b^2 <= a c). Handles may therefore
// reach outside [t0, t3] (t1 up to t0 + 4/3 h, t2 down to t3 - 4/3 h, h = t3 - t0); the limits
// (a, c) = (h/3, 4h/3) and (4h/3, h/3) give x'(u) = h (1 - 3u)^2 and h (2 - 3u)^2, a double
// root: a vertical tangent of the value's graph at 1/9 or 8/9 of the interval. The check decides
// b >= 0 exactly and b^2 <= a c with a margin of 8 eps relative (detail::time_handles_regress):
// every exactly monotone segment passes, the limits included, and what passes beyond them dips by
// rounding level only. So x is non-decreasing and every t in [t0, t3] has a root, unique except
// where x is flat (x' = 0 on an interval only when a = b = c = 0, which t0 < t3 excludes; isolated
// zeros of x' are points of vertical tangent in the value's graph). Every solver below returns a u
// in [0, 1]: none assumes the handles inside the interval (the bracket is always [0, 1], the
// closed form keeps the root in [0, 1], the table's samples stay ordered up to rounding).
//
// Solvers (each derived from its published description; no code is taken from the tools):
// - closed_form: Cardano's / the trigonometric solution of the cubic in power form on the
//   normalized segment (as Blender, USD and Unreal do), the root in [0, 1] (or the nearest one,
//   clamped into it: rounding can push a root at an end just outside; no root within 16 eps of
//   [0, 1], the formula having lost it, falls back to bisection); a leading coefficient below
//   16 eps of the others makes it a quadratic or a linear equation. Cost: one cbrt or acos + cos,
//   no iteration. Accuracy: the formula cancels near multiple roots; measured in
//   tests/test_time_solvers.cpp.
// - table_newton: the WebKit / Chromium scheme on the normalized cubic: x sampled at u = 0, 0.1,
//   ..., 1 picks the interval and a linear interpolation the start, at most 4 Newton steps, then
//   bisection of that interval. epsilon 1e-7 applies to the residual |x(u) - s| in normalized
//   time s = (t - t0) / (t3 - t0) (a fraction of the segment's duration) and is also the floor of
//   |x'| below which Newton gives up. Bisection cap: digits(Real) + 8 steps (then cap_hit).
// - newton_bisection: the Servo / @mapbox/unitbezier scheme: Newton from u = s for at most 8
//   steps, stopping when |x(u) - s| < 1e-6 (normalized time) or |x'| < 1e-6, then bisection of
//   [0, 1] to the same residual; bisection cap digits(Real) + 8 steps.
// - bisection12, bisection30: pure bisection of [0, 1] on the normalized cubic with 12 and 30
//   halvings, the midpoint of the last bracket (u within 2^-13 and 2^-31).
// - isolate_brent: the zeros of x'(u) in (0, 1) split [0, 1] into monotone pieces (Maya's
//   published evaluator approach), Brent's method (Brent 1973) on the piece whose end values
//   bracket t, to the full precision of Real (bracket below 4 eps |u|); cap 200 steps.
// - curvebench: Halley's iteration on the power form of x(u) - t (a chain of three multiply-adds
//   with both derivatives alongside) from u = s, inside the bracket [0, 1] and bisecting when a
//   step leaves it, until a step is below 2^-(digits/3); then Newton polish with the accurate
//   residual sum_i B_i(u) (t_i - t) by de Casteljau, which one step brings to rounding level at a
//   simple root. Where x' vanishes (vertical tangents) the polish shrinks slowly and after 3 steps
//   the safeguarded Newton-bisection of `exact` takes over. Cost: typically 2-3 Halley and 1-2
//   polish evaluations (4 on average over tests/test_time_solvers.cpp's stress set, against 6 for
//   exact). Accuracy: u is the root of the rounded data to rounding level, so y(u) is within a
//   few ulps of the value range (measured there, asserted within 4 in double).
// - exact: safeguarded Newton-bisection (Numerical Recipes' rtsafe rule: bisect when the Newton
//   step leaves the bracket or does not halve the previous step) from u = s on [0, 1], with the
//   residual sum_i B_i(u) (t_i - t) by de Casteljau (t_i - t is exact when t_i and t are within a
//   factor 2, so a segment far from 0 keeps the precision of its span), run until the bracket
//   cannot shrink in Real or the Newton step is below u's ulp; cap 4 digits(Real) + 16 steps.
//   At real50 it is the 50-digit truth of the other solvers.
// Cost: no allocation; one validation of the segment per call (a few comparisons). Residual
// evaluations per solve: closed_form none (a cbrt, or an acos and three cos); table_newton 11 for
// the table, then up to 4 Newton and the bisection; newton_bisection up to 8 Newton, then
// bisection; bisectionN exactly N; isolate_brent one quadratic and Brent's steps (about 10);
// curvebench about 4; exact about 6 (tests/test_time_solvers.cpp prints times and counts).
// Accuracy: as stated per solver; the measured maximum errors of each in float and double on the
// stress set are tabled in tests/test_time_solvers.cpp with the bounds asserted there.
// Every solver reports iterations, residual evaluations and a result_status (core/result_status.hpp):
// converged when it stopped by its own criterion (the residual test of table_newton and
// newton_bisection, Brent's bracket for isolate_brent, the full-precision stop of curvebench and
// exact); cap_hit when its iteration cap stopped it first (the best iterate returned);
// rounding_limited when a residual-tolerance scheme's bisection bracket could not shrink in Real
// before the residual met the tolerance (the tolerance is below what Real resolves there);
// not_guaranteed for the schemes with no test of their answer (closed_form, whose formula cancels
// near multiple roots; when it finds no root within 16 eps of [0, 1] it bisects instead and reports
// the bisection's status; bisection12 and bisection30, a fixed number of halvings with no residual
// check).
// Errors: a segment with non-finite times, t3 <= t0, a span t3 - t0 too narrow to be resolved
// (validate::resolvable), t1 < t0 or t2 > t3 (a handle pointing backwards in time), or handles that
// regress (x decreasing somewhere: the condition above) -> invalid_input naming the fields and
// values; t outside [t0, t3] (or NaN) -> std::domain_error naming t and the interval.
// Sources: CSS Easing Functions Level 1 (cubic-bezier), the WebKit / Chromium UnitBezier scheme,
// @mapbox/unitbezier, Brent (1973), Press et al. (Numerical Recipes, rtsafe); see docs/references.md.
#pragma once

#include "curvebench/channel/detail/cubic_time.hpp"
#include "curvebench/core/error.hpp"
#include "curvebench/core/real.hpp"
#include "curvebench/core/result_status.hpp"

#include <boost/math/constants/constants.hpp>
#include <boost/math/special_functions/cbrt.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>

namespace curvebench::channel {

/// The control times of a keyframe segment's Bezier curve: t0 < t3, t1 >= t0, t2 <= t3 and the
/// handles not regressive (see the header).
template <class Real>
struct time_cubic {
  Real t0, t1, t2, t3;
};

/// Throws invalid_input unless c is a valid segment: "t1 = -1: must be >= t0 = 0 (the handle points
/// backwards in time)", "t1 = 0.3333, t2 = -0.5 with [t0, t3] = [0, 1]: the handles regress ...".
template <class Real>
void validate_time_cubic(const time_cubic<Real>& c) {
  validate::finite("t0", c.t0);
  validate::finite("t1", c.t1);
  validate::finite("t2", c.t2);
  validate::finite("t3", c.t3);
  if (!(c.t0 < c.t3))
    validate::fail("t3 = " + to_text(c.t3) + " <= t0 = " + to_text(c.t0) +
                   ": a segment's end time must follow its start");
  validate::resolvable("t3 - t0", c.t0, c.t3, validate::channel_min_span_bits);
  if (!(c.t1 >= c.t0))
    validate::fail("t1 = " + to_text(c.t1) + ": must be >= t0 = " + to_text(c.t0) +
                   " (the handle points backwards in time)");
  if (!(c.t2 <= c.t3))
    validate::fail("t2 = " + to_text(c.t2) + ": must be <= t3 = " + to_text(c.t3) +
                   " (the handle points backwards in time)");
  if (detail::time_handles_regress(c.t0, c.t1, c.t2, c.t3))
    validate::fail("t1 = " + to_text(c.t1) + ", t2 = " + to_text(c.t2) + " with [t0, t3] = [" + to_text(c.t0) + ", " +
                   to_text(c.t3) +
                   "]: the handles regress (time runs backwards inside the segment); with h = t3 - t0, "
                   "a = (t1 - t0) / h and c = (t3 - t2) / h, time is monotone only when 1 - a - c >= 0 or "
                   "(1 - a - c)^2 <= a c");
}

/// The time solvers, one per scheme (see the header comment).
enum class time_solver {
  closed_form,
  table_newton,
  newton_bisection,
  bisection12,
  bisection30,
  isolate_brent,
  curvebench,
  exact
};

inline constexpr std::array<time_solver, 8> all_time_solvers{
    time_solver::closed_form, time_solver::table_newton,  time_solver::newton_bisection, time_solver::bisection12,
    time_solver::bisection30, time_solver::isolate_brent, time_solver::curvebench,       time_solver::exact};

[[nodiscard]] inline const char* to_string(time_solver s) {
  switch (s) {
    case time_solver::closed_form: return "closed_form";
    case time_solver::table_newton: return "table_newton";
    case time_solver::newton_bisection: return "newton_bisection";
    case time_solver::bisection12: return "bisection12";
    case time_solver::bisection30: return "bisection30";
    case time_solver::isolate_brent: return "isolate_brent";
    case time_solver::curvebench: return "curvebench";
    case time_solver::exact: return "exact";
  }
  return "unknown";
}

/// The solver named by its snake_case id; invalid_input listing the ids otherwise.
[[nodiscard]] inline time_solver time_solver_from_string(std::string_view id) {
  std::string ids;
  for (time_solver s : all_time_solvers) {
    if (id == to_string(s)) return s;
    ids += ids.empty() ? "" : ", ";
    ids += to_string(s);
  }
  validate::fail("time solver = \"" + std::string(id) + "\": unknown, expected one of " + ids);
}

/// u with x(u) ~ t, the solver's iterations and residual evaluations, and how sure the solver is
/// (see the header: cap_hit when an iteration cap stopped it, then u is its best iterate).
template <class Real>
struct time_solution {
  Real u;
  int iterations;
  int evaluations;
  result_status status;

  [[nodiscard]] bool converged() const { return status == result_status::converged; }
};

/// Throws std::domain_error unless t0 <= t <= t3: "t = 2 is outside the segment's time interval [0, 1]".
template <class Real>
void check_time(const time_cubic<Real>& c, const Real& t) {
  if (c.t0 <= t && t <= c.t3) return;
  throw std::domain_error("t = " + to_text(t) + " is outside the segment's time interval [" + to_text(c.t0) + ", " +
                          to_text(c.t3) + "]");
}

namespace detail {

/// The normalized cubic of the tools: x(0) = 0, x(1) = 1, handles x1, x2, target s.
template <class Real>
struct unit_cubic {
  Real x1, x2, s;
  Real value(const Real& u) const { return bernstein3(Real(0), x1, x2, Real(1), u); }
  Real slope(const Real& u) const { return bernstein3_derivative(Real(0), x1, x2, Real(1), u); }
};

template <class Real>
unit_cubic<Real> normalize(const time_cubic<Real>& c, const Real& t) {
  const Real h = c.t3 - c.t0;
  const Real s = (t - c.t0) / h;
  return {(c.t1 - c.t0) / h, (c.t2 - c.t0) / h, std::clamp(s, Real(0), Real(1))};
}

template <class Real>
[[nodiscard]] int bisection_cap() {
  return std::numeric_limits<Real>::digits + 8;
}

/// Bisection of [lo, hi] (x(lo) <= s <= x(hi)) until |x(u) - s| < tol or the cap.
template <class Real>
time_solution<Real> bisect_to_residual(const unit_cubic<Real>& q, Real lo, Real hi, const Real& tol, int iterations,
                                       int evaluations) {
  using std::abs;
  const int cap = bisection_cap<Real>();
  for (int k = 0; k < cap; ++k) {
    const Real u = lo + (hi - lo) / Real(2);
    const Real x = q.value(u);
    ++evaluations;
    ++iterations;
    if (abs(x - q.s) < tol) return {u, iterations, evaluations, result_status::converged};
    // The bracket cannot shrink in Real before the residual met tol.
    if (u == lo || u == hi) return {u, iterations, evaluations, result_status::rounding_limited};
    if (x < q.s)
      lo = u;
    else
      hi = u;
  }
  return {lo + (hi - lo) / Real(2), iterations, evaluations, result_status::cap_hit};
}

template <class Real>
time_solution<Real> solve_closed_form(const time_cubic<Real>& c, const Real& t) {
  using std::abs;
  using std::acos;
  using std::cos;
  using std::sqrt;
  const unit_cubic<Real> q = normalize(c, t);
  // The ends directly: there x(u) - s may have a double root (a zero-length handle) that the
  // formula only approximates. The ends are exact roots (x(0) = 0, x(1) = 1).
  if (q.s <= Real(0)) return {Real(0), 0, 0, result_status::converged};
  if (q.s >= Real(1)) return {Real(1), 0, 0, result_status::converged};
  // x(u) - s = A u^3 + B u^2 + C u + D.
  const Real A = Real(1) + Real(3) * q.x1 - Real(3) * q.x2;
  const Real B = Real(3) * q.x2 - Real(6) * q.x1;
  const Real C = Real(3) * q.x1;
  const Real D = -q.s;
  const Real eps = epsilon<Real>();
  std::array<Real, 3> roots{};
  int n = 0;
  if (abs(A) <= Real(16) * eps * (abs(B) + abs(C))) {
    if (abs(B) <= Real(16) * eps * abs(C)) {  // linear (C >= 3 * 16 eps here since x1 ~ 0 makes B, C small too)
      if (C != Real(0)) roots[n++] = -D / C;
    } else {
      const Real disc = C * C - Real(4) * B * D;
      if (disc >= Real(0)) {
        const Real r = sqrt(disc);
        // The two roots without cancellation: q = -(C + sign(C) r) / 2, roots q / B and D / q.
        const Real qq = -(C + (C >= Real(0) ? r : Real(-r))) / Real(2);
        roots[n++] = qq / B;
        if (qq != Real(0)) roots[n++] = D / qq;
      }
    }
  } else {
    const Real b = B / A, cc = C / A, d = D / A;  // u^3 + b u^2 + cc u + d
    const Real third = Real(1) / Real(3);
    const Real p = cc - b * b * third;
    const Real qd = Real(2) * b * b * b / Real(27) - b * cc * third + d;
    const Real shift = -b * third;
    const Real disc = qd * qd / Real(4) + p * p * p / Real(27);
    if (disc >= Real(0)) {
      const Real r = sqrt(disc);
      const Real w = boost::math::cbrt(-qd / Real(2) + r) + boost::math::cbrt(-qd / Real(2) - r);
      roots[n++] = w + shift;
    } else {
      const Real m = Real(2) * sqrt(-p * third);
      Real arg = Real(3) * qd / (p * m);
      arg = std::clamp(arg, Real(-1), Real(1));
      const Real phi = acos(arg) * third;
      const Real two_pi_3 = Real(2) * boost::math::constants::pi<Real>() * third;
      for (int k = 0; k < 3; ++k) roots[n++] = m * cos(phi - Real(k) * two_pi_3) + shift;
    }
  }
  // The root in [0, 1]; else the nearest one within rounding of it, clamped. No residual is tested:
  // not_guaranteed.
  Real best = q.s;
  Real best_distance = std::numeric_limits<Real>::infinity();
  for (int i = 0; i < n; ++i) {
    const Real r = roots[static_cast<std::size_t>(i)];
    const Real distance = r < Real(0) ? -r : (r > Real(1) ? r - Real(1) : Real(0));
    if (is_finite(r) && distance < best_distance) {
      best_distance = distance;
      best = std::clamp(r, Real(0), Real(1));
    }
  }
  // x is monotone on [0, 1] and 0 < s < 1, so a root lies in [0, 1]. No root within 16 eps of it
  // means the formula lost it: next to a double root at an end (a zero-width handle, s a few ulps
  // from 0 or 1) the discriminant's rounding can flip its sign, and the one real root the formula
  // then gives lies far outside (at u = 6 where the root is 3e-8: OpenUSD Ts's recorded
  // random/17, tests/data/recorded/usd_ts_splines.json). Bisection of [0, 1] finds it, with its status.
  if (!(best_distance <= Real(16) * eps)) return bisect_to_residual(q, Real(0), Real(1), Real(4) * eps, 0, 0);
  return {best, 0, 0, result_status::not_guaranteed};
}

template <class Real>
time_solution<Real> solve_table_newton(const time_cubic<Real>& c, const Real& t) {
  using std::abs;
  const unit_cubic<Real> q = normalize(c, t);
  const Real tol = Real(1) / Real(10000000);  // 1e-7 on |x(u) - s|, normalized time
  constexpr int samples = 11;
  std::array<Real, samples> table{};
  for (int i = 0; i < samples; ++i) table[static_cast<std::size_t>(i)] = q.value(Real(i) / Real(samples - 1));
  int evaluations = samples;
  // The interval [i/10, (i+1)/10] whose samples bracket s, and the linear interpolation in it.
  int i = 0;
  while (i < samples - 2 && table[static_cast<std::size_t>(i + 1)] < q.s) ++i;
  const Real lo = Real(i) / Real(samples - 1), hi = Real(i + 1) / Real(samples - 1);
  const Real x_lo = table[static_cast<std::size_t>(i)], x_hi = table[static_cast<std::size_t>(i + 1)];
  Real u = x_hi > x_lo ? lo + (q.s - x_lo) / (x_hi - x_lo) * (hi - lo) : lo;
  int iterations = 0;
  for (int k = 0; k < 4; ++k) {
    const Real r = q.value(u) - q.s;
    ++evaluations;
    if (abs(r) < tol) return {u, iterations, evaluations, result_status::converged};
    const Real d = q.slope(u);
    if (abs(d) < tol) break;
    ++iterations;
    u -= r / d;
    if (!(u >= Real(0) && u <= Real(1))) break;  // Newton left the segment: bisect instead
  }
  return bisect_to_residual(q, lo, hi, tol, iterations, evaluations);
}

template <class Real>
time_solution<Real> solve_newton_bisection(const time_cubic<Real>& c, const Real& t) {
  using std::abs;
  const unit_cubic<Real> q = normalize(c, t);
  const Real tol = Real(1) / Real(1000000);  // 1e-6 on |x(u) - s| and on |x'|
  Real u = q.s;
  int iterations = 0, evaluations = 0;
  for (int k = 0; k < 8; ++k) {
    const Real r = q.value(u) - q.s;
    ++evaluations;
    if (abs(r) < tol) return {u, iterations, evaluations, result_status::converged};
    const Real d = q.slope(u);
    if (abs(d) < tol) break;
    ++iterations;
    u -= r / d;
    if (!(u >= Real(0) && u <= Real(1))) break;
  }
  return bisect_to_residual(q, Real(0), Real(1), tol, iterations, evaluations);
}

template <class Real>
time_solution<Real> solve_bisection(const time_cubic<Real>& c, const Real& t, int steps) {
  const unit_cubic<Real> q = normalize(c, t);
  Real lo(0), hi(1);
  for (int k = 0; k < steps; ++k) {
    const Real u = lo + (hi - lo) / Real(2);
    if (q.value(u) < q.s)
      lo = u;
    else
      hi = u;
  }
  return {lo + (hi - lo) / Real(2), steps, steps, result_status::not_guaranteed};  // no residual test
}

template <class Real>
time_solution<Real> solve_isolate_brent(const time_cubic<Real>& c, const Real& t) {
  using std::abs;
  using std::sqrt;
  // x'(u) / 3 = a (1-u)^2 + 2 b u (1-u) + c u^2 = (a - 2b + c) u^2 + 2 (b - a) u + a.
  const Real a = c.t1 - c.t0, b = c.t2 - c.t1, e = c.t3 - c.t2;
  const Real qa = a - Real(2) * b + e, qb = Real(2) * (b - a), qc = a;
  std::array<Real, 4> cuts{Real(0), Real(0), Real(0), Real(0)};
  int n = 1;
  const auto add = [&](const Real& r) {
    if (r > Real(0) && r < Real(1)) cuts[static_cast<std::size_t>(n++)] = r;
  };
  if (qa != Real(0)) {
    const Real disc = qb * qb - Real(4) * qa * qc;
    if (disc >= Real(0)) {
      const Real r = sqrt(disc);
      const Real qq = -(qb + (qb >= Real(0) ? r : Real(-r))) / Real(2);
      if (qq != Real(0)) {
        add(qq / qa);
        add(qc / qq);
      } else {
        add(Real(0));  // qb = qc = 0: double root at 0, no interior cut
      }
    }
  } else if (qb != Real(0)) {
    add(-qc / qb);
  }
  if (n == 3 && cuts[2] < cuts[1]) std::swap(cuts[1], cuts[2]);  // at most two interior cuts, in order
  cuts[static_cast<std::size_t>(n++)] = Real(1);
  const auto f = [&](const Real& u) { return bernstein3(c.t0 - t, c.t1 - t, c.t2 - t, c.t3 - t, u); };
  int evaluations = 0;
  // The monotone piece whose end values bracket t.
  Real lo = cuts[0], flo = c.t0 - t;
  for (int i = 1; i < n; ++i) {
    const Real hi = cuts[static_cast<std::size_t>(i)];
    const Real fhi = i == n - 1 ? c.t3 - t : f(hi);
    if (i != n - 1) ++evaluations;
    if (fhi >= Real(0) || i == n - 1) {
      const auto r = brent_root(f, lo, hi, flo, fhi, Real(0), 200);
      return {r.root, r.iterations, evaluations + r.evaluations, r.status};
    }
    lo = hi;
    flo = fhi;
  }
  return {Real(1), 0, evaluations, result_status::not_guaranteed};  // not reached: x(1) - t >= 0
}

/// Safeguarded Newton-bisection on f(u) = x(u) - t over [lo, hi] with f(lo) < 0 < f(hi) certain.
/// `residual` evaluates f, `noise` bounds its rounding error: the bracket moves only where
/// |f| > noise, and the iteration stops when |f| <= noise, the step is below `step_tol` or the
/// bracket cannot shrink.
template <class Real, class F>
time_solution<Real> rtsafe(const time_cubic<Real>& c, F&& residual, const Real& noise, Real& lo, Real& hi, Real u,
                           const Real& step_tol, int cap, int iterations, int evaluations, bool& stalled) {
  using std::abs;
  Real dx_old = hi - lo, dx = dx_old;
  stalled = false;
  for (int k = 0; k < cap; ++k) {
    const Real f = residual(u);
    ++evaluations;
    if (abs(f) <= noise) return {u, iterations, evaluations, result_status::converged};
    if (f < Real(0))
      lo = u;
    else
      hi = u;
    const Real d = bernstein3_derivative(c.t0, c.t1, c.t2, c.t3, u);
    ++iterations;
    const Real newton = u - f / d;
    if (d > Real(0) && newton == u) return {u, iterations, evaluations, result_status::converged};  // step < ulp(u)
    if (!(d > Real(0)) || !(newton > lo && newton < hi) || abs(Real(2) * f) > abs(dx_old * d)) {
      dx_old = dx;
      dx = (hi - lo) / Real(2);
      u = lo + dx;
      if (u == lo || u == hi) {
        stalled = true;
        return {u, iterations, evaluations, result_status::converged};  // full precision: the bracket is 1 ulp
      }
    } else {
      dx_old = dx;
      dx = f / d;
      u = newton;
    }
    if (abs(dx) <= step_tol) return {u, iterations, evaluations, result_status::converged};
  }
  return {u, iterations, evaluations, result_status::cap_hit};
}

template <class Real>
time_solution<Real> solve_curvebench(const time_cubic<Real>& c, const Real& t) {
  using std::abs;
  using std::ldexp;
  if (t == c.t0) return {Real(0), 0, 0, result_status::converged};
  if (t == c.t3) return {Real(1), 0, 0, result_status::converged};
  // Phase 1: Halley's iteration on the power form x(u) - t = ((c3 u + c2) u + c1) u + c0 (three
  // multiply-adds in a chain, its two derivatives beside them), from u = s inside the bracket
  // [0, 1], bisecting when a step leaves it; until a step is below 2^-(digits / 3), after which
  // the iterate is within about that step cubed of the root.
  const Real a = c.t1 - c.t0, b = c.t2 - c.t1, e = c.t3 - c.t2;
  const Real c1 = Real(3) * a, c2 = Real(3) * (b - a), c3 = a - Real(2) * b + e, c0 = c.t0 - t;
  const Real tol = ldexp(Real(1), -std::numeric_limits<Real>::digits / 3);
  const int cap = 2 * std::numeric_limits<Real>::digits + 16;
  Real lo(0), hi(1);
  Real u = std::clamp((t - c.t0) / (c.t3 - c.t0), Real(0), Real(1));
  int iterations = 0, evaluations = 0;
  bool close = false;
  for (int k = 0; k < cap && !close; ++k) {
    const Real f = ((c3 * u + c2) * u + c1) * u + c0;
    const Real d = (Real(3) * c3 * u + Real(2) * c2) * u + c1;
    const Real dd = Real(6) * c3 * u + Real(2) * c2;
    ++evaluations;
    ++iterations;
    if (f == Real(0)) break;
    if (f < Real(0))
      lo = u;
    else
      hi = u;
    const Real denominator = d * d - f * dd / Real(2);
    const Real step = denominator > Real(0) ? f * d / denominator : (d > Real(0) ? f / d : Real(0));
    Real next = u - step;
    if (!(next > lo && next < hi)) {
      next = lo + (hi - lo) / Real(2);
      if (next == lo || next == hi) break;
    } else {
      close = abs(step) <= tol;
    }
    u = next;
  }
  // Phase 2: Newton polish with the residual sum B_i(u) (t_i - t) by de Casteljau (the accurate
  // form: each t_i - t exact near the root's neighbours, rounding bound 8 eps max|t_i - t|). Near
  // a simple root one step lands within rounding; where x' is small the steps shrink slowly, and
  // after 3 of them the safeguarded Newton-bisection takes over from the bracket found so far.
  const auto residual = [&](const Real& v) { return bernstein3(c.t0 - t, c.t1 - t, c.t2 - t, c.t3 - t, v); };
  const Real eps = epsilon<Real>();
  for (int k = 0; k < 3; ++k) {
    const Real f = residual(u);
    const Real d = bernstein3_derivative(c.t0, c.t1, c.t2, c.t3, u);
    ++evaluations;
    ++iterations;
    if (f == Real(0) || !(d > Real(0))) break;
    const Real step = f / d;
    const Real next = std::clamp(u - step, Real(0), Real(1));
    if (abs(step) <= Real(4) * eps * u || next == u) return {next, iterations, evaluations, result_status::converged};
    u = next;
    if (k == 2) {
      bool stalled = false;
      Real l(0), h(1);
      return rtsafe(c, residual, Real(0), l, h, u, Real(0), cap, iterations, evaluations, stalled);
    }
  }
  return {u, iterations, evaluations, result_status::converged};
}

template <class Real>
time_solution<Real> solve_exact(const time_cubic<Real>& c, const Real& t) {
  if (t == c.t0) return {Real(0), 0, 0, result_status::converged};
  if (t == c.t3) return {Real(1), 0, 0, result_status::converged};
  Real lo(0), hi(1);
  bool stalled = false;
  // The residual as the cubic of t_i - t (each difference exact when t_i and t are within a factor
  // 2, so a segment far from 0 keeps the precision of its span, not of its position).
  const auto plain = [&](const Real& u) { return bernstein3(c.t0 - t, c.t1 - t, c.t2 - t, c.t3 - t, u); };
  const Real u0 = std::clamp((t - c.t0) / (c.t3 - c.t0), Real(0), Real(1));
  return rtsafe(c, plain, Real(0), lo, hi, u0, Real(0), 4 * std::numeric_limits<Real>::digits + 16, 0, 0, stalled);
}

}  // namespace detail

/// u in [0, 1] with x(u) = t by the chosen scheme. Throws invalid_input for an invalid segment and
/// std::domain_error for t outside [t0, t3].
template <class Real>
[[nodiscard]] time_solution<Real> solve_time(time_solver solver, const time_cubic<Real>& c, const Real& t) {
  validate_time_cubic(c);
  check_time(c, t);
  switch (solver) {
    case time_solver::closed_form: return detail::solve_closed_form(c, t);
    case time_solver::table_newton: return detail::solve_table_newton(c, t);
    case time_solver::newton_bisection: return detail::solve_newton_bisection(c, t);
    case time_solver::bisection12: return detail::solve_bisection(c, t, 12);
    case time_solver::bisection30: return detail::solve_bisection(c, t, 30);
    case time_solver::isolate_brent: return detail::solve_isolate_brent(c, t);
    case time_solver::curvebench: return detail::solve_curvebench(c, t);
    case time_solver::exact: return detail::solve_exact(c, t);
  }
  validate::fail("time solver = " + std::to_string(static_cast<int>(solver)) + ": not a time_solver");
}

}  // namespace curvebench::channel
