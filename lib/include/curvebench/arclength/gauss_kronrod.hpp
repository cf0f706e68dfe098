// Gauss-Kronrod quadrature of our own: the (2n + 1)-point Kronrod extension of the n-point
// Gauss-Legendre rule for any n (G7-K15 by default), computed in Real (the Stieltjes polynomial's
// zeros by safeguarded Newton between the Gauss nodes, weights from the Legendre moment system; see
// make_gauss_kronrod); a single-panel rule with error estimate |G - K| (the Gauss rule's error, a
// conservative bound for smooth f) or QUADPACK's heuristic, both plus a rounding floor
// (detail/roundoff.hpp) and the floor of the panel's own node positions (resolution_floor); a globally adaptive
// integrator (bisect the panel of largest error) with an interval cap, an evaluation budget and a status; and an
// allocation-free recursive variant for hot paths (depth cap and evaluation budget). Cap or budget reached: cap_hit.
// Sources: Kronrod (1965); Monegato (1982); Piessens et al. (1983, QUADPACK) for the adaptive
// strategy and the heuristic resasc * min(1, (200 |K - G| / resasc)^1.5) (which allocates).
// Cost: rule O(n^3) once (cached); a panel 2n + 1 evaluations; an adaptive call at most its
// max_evaluations (default 2^24 global, 2^22 recursive) plus one panel per split interval.
// Accuracy: K_{2n+1} exact for degree <= 3n + 1 (3n + 2 for odd n), G_n for degree <= 2n - 1.
#pragma once

#include "curvebench/arclength/detail/linear_solve.hpp"
#include "curvebench/arclength/detail/roundoff.hpp"
#include "curvebench/arclength/detail/rule_cache.hpp"
#include "curvebench/arclength/gauss_legendre.hpp"
#include "curvebench/arclength/result.hpp"
#include "curvebench/core/error.hpp"
#include "curvebench/core/real.hpp"

#include <algorithm>
#include <cstddef>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace curvebench::arclength {

/// How a panel's error is estimated from its Gauss value G and Kronrod value K.
enum class error_model {
  gauss_difference,  ///< |G - K| (+ rounding floor): conservative, the default
  quadpack           ///< resasc * min(1, (200 |G - K| / resasc)^1.5) (+ floor): sharper, heuristic
};

/// One panel's result.
template <class Real>
struct kronrod_panel {
  Real kronrod{0};         ///< the (2n+1)-point value, the one reported
  Real gauss{0};           ///< the embedded n-point value
  Real error_estimate{0};  ///< per the error model, plus rounding_floor and resolution_floor
  Real magnitude{0};       ///< integral of |f| by the Kronrod rule
  Real rounding_floor{0};  ///< 50 eps * magnitude
  /// What the panel's own node positions resolve: 2 eps (|mid| + |half width|) (max f - min f).
  /// Each node mid + half x_i is placed within d = eps (|mid| + |half|) of where the rule puts it,
  /// which moves the panel's value by at most d times the variation of f over the panel, below
  /// this floor where f is monotone or has one extremum there. Far from 0 (a domain [1e15,
  /// 1e15 + 1e5]: d is 1e-6 of the width) that is the panel's largest error, and the Gauss and
  /// Kronrod values share it (the same nodes), so |G - K| alone does not show it: it is part of
  /// error_estimate, and the adaptive integrators stop refining a panel whose |G - K| is below both floors.
  Real resolution_floor{0};
  std::size_t evaluations{0};
};

/// The G_n - K_{2n+1} pair on [-1, 1]: nodes ascending; gauss_weights is zero at the new nodes.
template <class Real>
struct gauss_kronrod_rule {
  int n{0};
  std::vector<Real> nodes;
  std::vector<Real> kronrod_weights;
  std::vector<Real> gauss_weights;

  /// Both rules on [a, b] in 2n + 1 evaluations of f; with `values`, f at the nodes (ascending) is
  /// also written there (2n + 1 entries).
  template <class F>
  [[nodiscard]] kronrod_panel<Real> apply(F&& f, const Real& a, const Real& b,
                                          error_model model = error_model::gauss_difference,
                                          Real* values = nullptr) const {
    if (model == error_model::quadpack) return apply_quadpack(f, a, b, values);
    using std::abs;
    const Real half = (b - a) / Real(2);
    const Real mid = (a + b) / Real(2);
    Real k(0), g(0), kabs(0), fmin(0), fmax(0);
    for (std::size_t i = 0; i < nodes.size(); ++i) {
      const Real fi = f(mid + half * nodes[i]);
      if (values) values[i] = fi;
      k += kronrod_weights[i] * fi;
      g += gauss_weights[i] * fi;
      kabs += kronrod_weights[i] * abs(fi);
      // min and max without a data-dependent branch (a mispredicted one per node cost more than
      // the node's arithmetic); a NaN node leaves them as they were, as the comparisons did.
      if (i == 0) {
        fmin = fi;
        fmax = fi;
      } else {
        fmin = std::min(fmin, fi);
        fmax = std::max(fmax, fi);
      }
    }
    kronrod_panel<Real> p;
    p.kronrod = k * half;
    p.gauss = g * half;
    p.magnitude = kabs * abs(half);
    p.rounding_floor = detail::rounding_floor(p.magnitude);
    p.resolution_floor = Real(2) * epsilon<Real>() * (abs(mid) + abs(half)) * (fmax - fmin);
    p.evaluations = nodes.size();
    p.error_estimate = abs(p.kronrod - p.gauss) + p.rounding_floor + p.resolution_floor;
    return p;
  }

 private:
  template <class F>
  [[nodiscard]] kronrod_panel<Real> apply_quadpack(F&& f, const Real& a, const Real& b, Real* values) const {
    using std::abs;
    using std::min;
    using std::pow;
    const Real half = (b - a) / Real(2);
    const Real mid = (a + b) / Real(2);
    std::vector<Real> fv(nodes.size());
    Real k(0), g(0), kabs(0);
    for (std::size_t i = 0; i < nodes.size(); ++i) {
      fv[i] = f(mid + half * nodes[i]);
      if (values) values[i] = fv[i];
      k += kronrod_weights[i] * fv[i];
      g += gauss_weights[i] * fv[i];
      kabs += kronrod_weights[i] * abs(fv[i]);
    }
    const Real mean = k / Real(2);
    Real asc(0);
    for (std::size_t i = 0; i < nodes.size(); ++i) asc += kronrod_weights[i] * abs(fv[i] - mean);
    kronrod_panel<Real> p;
    p.kronrod = k * half;
    p.gauss = g * half;
    p.magnitude = kabs * abs(half);
    p.rounding_floor = detail::rounding_floor(p.magnitude);
    const auto [lo_it, hi_it] = std::minmax_element(fv.begin(), fv.end());
    p.resolution_floor = Real(2) * epsilon<Real>() * (abs(mid) + abs(half)) * (*hi_it - *lo_it);
    p.evaluations = nodes.size();
    asc *= abs(half);
    Real diff = abs(p.kronrod - p.gauss);
    if (asc > Real(0) && diff > Real(0))
      diff = asc * min(Real(1), Real(pow(Real(200) * diff / asc, Real(3) / Real(2))));
    p.error_estimate = diff + p.rounding_floor + p.resolution_floor;
    return p;
  }
};

namespace detail {

/// P_0..P_m(x) and their derivatives (m >= 1), by the recurrences
/// (k+1) P_{k+1} = (2k+1) x P_k - k P_{k-1},  P'_{k+1} = P'_{k-1} + (2k+1) P_k.
template <class Real>
void legendre_all(int m, const Real& x, std::vector<Real>& p, std::vector<Real>& dp) {
  p.assign(static_cast<std::size_t>(m) + 1, Real(0));
  dp.assign(static_cast<std::size_t>(m) + 1, Real(0));
  p[0] = Real(1);
  p[1] = x;
  dp[1] = Real(1);
  for (int k = 1; k < m; ++k) {
    const auto uk = static_cast<std::size_t>(k);
    p[uk + 1] = (Real(2 * k + 1) * x * p[uk] - Real(k) * p[uk - 1]) / Real(k + 1);
    dp[uk + 1] = dp[uk - 1] + Real(2 * k + 1) * p[uk];
  }
}

}  // namespace detail

// Construction of the rule (derived here, checked by tests against Boost.Math's stored constants
// and by polynomial exactness): the n + 1 new nodes are the zeros of the Stieltjes polynomial
// E_{n+1}, defined by  integral_{-1}^{1} E_{n+1}(x) P_n(x) P_k(x) dx = 0 for k = 0..n.
// Writing E_{n+1} = P_{n+1} + sum_{j<n} c_j P_j (only j of the parity of n + 1), the conditions
// for odd k form a small linear system whose entries, integrals of products of three Legendre
// polynomials (degree <= 3n + 1), are computed exactly by a Gauss-Legendre rule of
// ceil((3n + 2)/2) + 1 points. The zeros interlace with the Gauss nodes (Szego), so each is found
// by safeguarded Newton in its bracket (-1, g_1), (g_1, g_2), ..., (g_n, 1). The 2n + 1 weights
// solve sum_i w_i P_k(x_i) = 2 delta_k0, k = 0..2n (Legendre basis: well conditioned). Nodes and
// weights are symmetrized. Everything runs in Real, so a real50 rule is exact to 50 digits.
/// Computes the G_n - K_{2n+1} rule in Real (uncached). Throws invalid_input unless 1 <= n <= 60.
template <class Real>
[[nodiscard]] gauss_kronrod_rule<Real> make_gauss_kronrod(int n) {
  if (n < 1 || n > 60)
    validate::fail("n = " + std::to_string(n) + ": number of Gauss points of a Gauss-Kronrod pair must be in [1, 60]");
  using std::abs;
  const auto un = static_cast<std::size_t>(n);
  const gauss_legendre_rule<Real> gauss = make_gauss_legendre<Real>(n);
  // 1. The Stieltjes polynomial E_{n+1} = P_{n+1} + sum_j c_j P_j in the Legendre basis.
  const gauss_legendre_rule<Real> exact = make_gauss_legendre<Real>((3 * n + 3) / 2 + 1);
  std::vector<int> js, ks;
  for (int j = n - 1; j >= 0; j -= 2) js.push_back(j);
  for (int k = 1; k <= n; k += 2) ks.push_back(k);
  const std::size_t m = js.size();
  std::vector<Real> a(m * m, Real(0)), rhs(m, Real(0)), p, dp;
  for (std::size_t q = 0; q < exact.nodes.size(); ++q) {
    detail::legendre_all(n + 1, exact.nodes[q], p, dp);
    const Real wpn = exact.weights[q] * p[un];
    for (std::size_t r = 0; r < m; ++r) {
      const Real wpnk = wpn * p[static_cast<std::size_t>(ks[r])];
      for (std::size_t c = 0; c < m; ++c) a[r * m + c] += wpnk * p[static_cast<std::size_t>(js[c])];
      rhs[r] -= wpnk * p[un + 1];
    }
  }
  const std::vector<Real> coef = m > 0 ? detail::solve_dense(a, rhs, m) : std::vector<Real>{};
  auto stieltjes = [&](const Real& x, Real& value, Real& slope) {
    detail::legendre_all(n + 1, x, p, dp);
    value = p[un + 1];
    slope = dp[un + 1];
    for (std::size_t c = 0; c < m; ++c) {
      value += coef[c] * p[static_cast<std::size_t>(js[c])];
      slope += coef[c] * dp[static_cast<std::size_t>(js[c])];
    }
  };
  // 2. Its zeros, one in each gap of -1 < g_1 < ... < g_n < 1, by safeguarded Newton.
  std::vector<Real> ends;
  ends.push_back(Real(-1));
  for (const Real& g : gauss.nodes) ends.push_back(g);
  ends.push_back(Real(1));
  std::vector<Real> knodes;
  for (std::size_t gap = 0; gap + 1 < ends.size(); ++gap) {
    Real lo = ends[gap], hi = ends[gap + 1], flo, fhi, s;
    stieltjes(lo, flo, s);
    stieltjes(hi, fhi, s);
    if (flo == Real(0)) {
      knodes.push_back(lo);
      continue;
    }
    if ((flo > Real(0)) == (fhi > Real(0)))
      validate::fail("make_gauss_kronrod: Stieltjes polynomial has no sign change in gap " + std::to_string(gap));
    Real x = (lo + hi) / Real(2);
    for (int iter = 0; iter < 400; ++iter) {
      Real fx, dfx;
      stieltjes(x, fx, dfx);
      if (fx == Real(0)) break;
      if ((fx > Real(0)) == (flo > Real(0)))
        lo = x;
      else
        hi = x;
      Real next = dfx != Real(0) ? x - fx / dfx : (lo + hi) / Real(2);
      if (!(next > lo && next < hi)) next = (lo + hi) / Real(2);
      const Real step = abs(next - x);
      x = next;
      if (step <= epsilon<Real>() / Real(4) || hi - lo <= epsilon<Real>() / Real(4)) break;
    }
    knodes.push_back(x);
  }
  // 3. Merge: k_0 < g_1 < k_1 < ... < g_n < k_n, then symmetrize.
  gauss_kronrod_rule<Real> r;
  r.n = n;
  const std::size_t total = 2 * un + 1;
  r.nodes.resize(total);
  r.gauss_weights.assign(total, Real(0));
  for (std::size_t i = 0; i <= un; ++i) r.nodes[2 * i] = knodes[i];
  for (std::size_t i = 0; i < un; ++i) {
    r.nodes[2 * i + 1] = gauss.nodes[i];
    r.gauss_weights[2 * i + 1] = gauss.weights[i];
  }
  for (std::size_t i = 0; i < un; ++i) {
    const Real x = (r.nodes[total - 1 - i] - r.nodes[i]) / Real(2);
    r.nodes[i] = -x;
    r.nodes[total - 1 - i] = x;
  }
  r.nodes[un] = Real(0);
  // 4. Kronrod weights: exact integration of P_0..P_{2n}.
  std::vector<Real> v(total * total, Real(0)), e(total, Real(0));
  e[0] = Real(2);
  for (std::size_t i = 0; i < total; ++i) {
    detail::legendre_all(static_cast<int>(total), r.nodes[i], p, dp);
    for (std::size_t k = 0; k < total; ++k) v[k * total + i] = p[k];
  }
  r.kronrod_weights = detail::solve_dense(v, e, total);
  for (std::size_t i = 0; i < un; ++i) {
    const Real w = (r.kronrod_weights[i] + r.kronrod_weights[total - 1 - i]) / Real(2);
    r.kronrod_weights[i] = w;
    r.kronrod_weights[total - 1 - i] = w;
  }
  return r;
}

/// The cached G_n - K_{2n+1} rule (thread-safe; the reference stays valid until exit).
template <class Real>
[[nodiscard]] const gauss_kronrod_rule<Real>& gauss_kronrod(int n = 7) {
  return detail::rule_cache<gauss_kronrod_rule<Real>>::get(n, &make_gauss_kronrod<Real>);
}

/// Options of the adaptive integrators. The target is max(absolute, relative * |integral|); at
/// least one tolerance must be > 0.
template <class Real>
struct adaptive_options {
  Real absolute_tolerance{0};
  Real relative_tolerance{Real(128) * epsilon<Real>()};  ///< above the panels' rounding floor (detail/roundoff.hpp)
  std::size_t max_intervals{4000};  ///< cap on the number of panels (global) / 2^max_depth (recursive)
  /// Total evaluations of f allowed for one call: integrate_adaptive refines no panel once the next
  /// bisection would pass it (the first panel of each split interval is always computed);
  /// segment_lengths and the length functions share it over the whole curve. Reaching it ends in
  /// cap_hit with the estimate of the panels so far (each still |G - K| + floor).
  std::size_t max_evaluations{std::size_t(1) << 24};
  int gauss_points{7};  ///< n of the G_n - K_{2n+1} pair
  error_model model{error_model::gauss_difference};
  /// Curve lengths only (length.hpp, segment_lengths): samples of |P'|^2 per segment used to find
  /// interior speed minima (near-cusps) and split there first; 0 turns it off. adaptive_length
  /// takes them only where a screen flags the segment: its first panel is then G15-K31, whose 31
  /// node speeds show a low minimum or a low end with the speed falling towards it (length.hpp);
  /// segment_lengths takes them on every segment.
  std::size_t speed_minimum_samples{16};
};

namespace detail {

template <class Real>
void check_tolerances(const Real& absolute, const Real& relative) {
  validate::finite("absolute_tolerance", absolute);
  validate::finite("relative_tolerance", relative);
  if (absolute < Real(0)) validate::fail("absolute_tolerance = " + to_text(absolute) + ": must be >= 0");
  if (relative < Real(0)) validate::fail("relative_tolerance = " + to_text(relative) + ": must be >= 0");
  if (!(absolute > Real(0)) && !(relative > Real(0)))
    validate::fail("tolerance: absolute_tolerance = " + to_text(absolute) +
                   " and relative_tolerance = " + to_text(relative) + ": at least one must be > 0");
}

template <class Real>
struct heap_panel {
  Real a, b;
  kronrod_panel<Real> r;
  bool suspect{false};  ///< the bisection that made it stagnated (detail/roundoff.hpp)
};

// Recursive bisection of a panel whose rule estimate p is known. suspect: the bisection that made
// this panel stagnated (see detail/roundoff.hpp); a second stagnation stops it.
template <class Real, class F>
[[nodiscard]] quadrature_result<Real> bisect(F& f, const Real& a, const Real& b, const kronrod_panel<Real>& p,
                                             const Real& tolerance, const gauss_kronrod_rule<Real>& rule, int max_depth,
                                             bool suspect, std::size_t& budget) {
  quadrature_result<Real> out{p.kronrod, p.error_estimate, 0, result_status::converged};
  if (p.error_estimate <= tolerance) return out;
  const Real mid = (a + b) / Real(2);
  if (!(p.error_estimate > Real(2) * (p.rounding_floor + p.resolution_floor)) || !(mid > (a < b ? a : b)) ||
      !(mid < (a < b ? b : a))) {
    out.status = result_status::rounding_limited;
    out.reason =
        status_reason<Real>{reasons::panels_at_floor, status_reason<Real>::npos, a, b, p.error_estimate, tolerance};
    return out;
  }
  if (max_depth <= 0 || budget < 2 * rule.nodes.size()) {
    out.status = result_status::cap_hit;
    out.reason = status_reason<Real>{max_depth <= 0 ? reasons::max_depth : reasons::budget,
                                     status_reason<Real>::npos,
                                     a,
                                     b,
                                     p.error_estimate,
                                     tolerance};
    return out;
  }
  budget -= 2 * rule.nodes.size();
  const kronrod_panel<Real> l = rule.apply(f, a, mid);
  const kronrod_panel<Real> r = rule.apply(f, mid, b);
  const bool stagnated = bisection_stagnated(p.error_estimate, l.error_estimate + r.error_estimate, p.magnitude);
  if (stagnated && suspect) {  // the halves are f's rounding: accept them, converged if they happen to pass
    const bool pass = l.error_estimate <= tolerance / Real(2) && r.error_estimate <= tolerance / Real(2);
    quadrature_result<Real> halves{l.kronrod + r.kronrod, l.error_estimate + r.error_estimate,
                                   l.evaluations + r.evaluations,
                                   pass ? result_status::converged : result_status::rounding_limited};
    if (!pass)
      halves.reason = status_reason<Real>{
          reasons::halves_no_better, status_reason<Real>::npos, a, b, halves.error_estimate, tolerance};
    return halves;
  }
  quadrature_result<Real> left = bisect(f, a, mid, l, tolerance / Real(2), rule, max_depth - 1, stagnated, budget);
  left += bisect(f, mid, b, r, tolerance / Real(2), rule, max_depth - 1, stagnated, budget);
  left.evaluations += l.evaluations + r.evaluations;
  return left;
}

}  // namespace detail

namespace detail {

/// integrate_adaptive's refinement from the given first panels (out.evaluations already counts
/// them): see integrate_adaptive. Allocates its panel lists.
template <class Real, class F>
[[nodiscard]] quadrature_result<Real> refine_adaptive(F& f, const gauss_kronrod_rule<Real>& rule,
                                                      const adaptive_options<Real>& opt,
                                                      std::vector<heap_panel<Real>> heap, quadrature_result<Real> out) {
  using std::abs;
  using std::max;
  std::vector<heap_panel<Real>> frozen;
  auto less = [](const heap_panel<Real>& x, const heap_panel<Real>& y) {
    return x.r.error_estimate < y.r.error_estimate;
  };
  std::make_heap(heap.begin(), heap.end(), less);
  // Exact-as-possible totals: the value by Neumaier's compensated summation (error <= 2 eps |sum|
  // + O(n eps^2) for any number of panels), estimates by a plain sum.
  auto totals = [&](Real& value, Real& err) {
    value = Real(0);
    err = Real(0);
    Real comp(0);
    auto add = [&](const heap_panel<Real>& h) {
      const Real t = value + h.r.kronrod;
      comp += abs(value) >= abs(h.r.kronrod) ? (value - t) + h.r.kronrod : (h.r.kronrod - t) + value;
      value = t;
      err += h.r.error_estimate;
    };
    for (const auto& h : heap) add(h);
    for (const auto& h : frozen) add(h);
    value += comp;
  };
  // The compensated sum of the panels rounds by at most ~2 eps |value|: part of every estimate.
  auto estimate = [&](const Real& e, const Real& v) { return e + Real(4) * epsilon<Real>() * abs(v); };
  auto target = [&](const Real& v) { return max(opt.absolute_tolerance, opt.relative_tolerance * abs(v)); };
  Real value, err;
  totals(value, err);
  out.status = result_status::converged;
  std::string_view why;
  while (true) {
    if (estimate(err, value) <= target(value)) {
      totals(value, err);  // confirm with exact sums (the running ones drift by rounding)
      if (estimate(err, value) <= target(value)) break;
    }
    if (heap.empty()) {
      out.status = result_status::rounding_limited;
      why = reasons::panels_at_floor;
      break;
    }
    if (heap.size() + frozen.size() >= opt.max_intervals ||
        out.evaluations + 2 * rule.nodes.size() > opt.max_evaluations) {
      out.status = result_status::cap_hit;
      why = heap.size() + frozen.size() >= opt.max_intervals ? reasons::interval_cap : reasons::budget;
      break;
    }
    std::pop_heap(heap.begin(), heap.end(), less);
    heap_panel<Real> worst_panel = heap.back();
    heap.pop_back();
    const Real mid = (worst_panel.a + worst_panel.b) / Real(2);
    if (!(worst_panel.r.error_estimate > Real(2) * (worst_panel.r.rounding_floor + worst_panel.r.resolution_floor)) ||
        !(mid > worst_panel.a) || !(mid < worst_panel.b)) {
      frozen.push_back(worst_panel);  // cannot be improved in Real
      continue;
    }
    heap_panel<Real> left{worst_panel.a, mid, rule.apply(f, worst_panel.a, mid, opt.model)};
    heap_panel<Real> right{mid, worst_panel.b, rule.apply(f, mid, worst_panel.b, opt.model)};
    out.evaluations += left.r.evaluations + right.r.evaluations;
    value += left.r.kronrod + right.r.kronrod - worst_panel.r.kronrod;
    err += left.r.error_estimate + right.r.error_estimate - worst_panel.r.error_estimate;
    const bool stagnated = bisection_stagnated(worst_panel.r.error_estimate,
                                               left.r.error_estimate + right.r.error_estimate, worst_panel.r.magnitude);
    if (stagnated && worst_panel.suspect) {
      frozen.push_back(left);  // the second stagnation in a row: f's own rounding, refining cannot help
      frozen.push_back(right);
      continue;
    }
    left.suspect = right.suspect = stagnated;
    heap.push_back(left);
    std::push_heap(heap.begin(), heap.end(), less);
    heap.push_back(right);
    std::push_heap(heap.begin(), heap.end(), less);
  }
  totals(value, err);
  out.value = value;
  out.error_estimate = estimate(err, value);
  if (out.status != result_status::converged) {
    // The estimate reached against the target; at the rounding floor also the frozen panel with the
    // largest estimate (its segment is found by the caller that knows the breakpoints).
    out.reason = global_reason<Real>(why, out.error_estimate, target(value));
    if (out.status == result_status::rounding_limited && !frozen.empty()) {
      const auto top = std::max_element(frozen.begin(), frozen.end(), less);
      out.reason.a = top->a;
      out.reason.b = top->b;
    }
  }
  return out;
}

}  // namespace detail

/// Globally adaptive Gauss-Kronrod over [splits.front(), splits.back()], never integrating across
/// an interior split point (pass a curve's breakpoints): start with one panel per split interval,
/// then repeatedly bisect the panel with the largest error estimate until the summed estimate
/// meets the target (converged), the panel count reaches max_intervals or the next bisection would
/// pass max_evaluations (cap_hit), or no panel can
/// usefully be refined because its estimate is its rounding floor, its halves do not improve on
/// it (detail/roundoff.hpp: f's own rounding), or it is too narrow to bisect
/// (rounding_limited). Allocates its panel list (not for per-query hot paths: see
/// integrate_recursive). Throws invalid_input for fewer than 2 split points or bad tolerances.
template <class Real, class F>
[[nodiscard]] quadrature_result<Real> integrate_adaptive(F&& f, std::span<const Real> splits,
                                                         const adaptive_options<Real>& opt = {}) {
  validate::count_at_least("splits", splits.size(), 2, "an integration interval");
  validate::non_decreasing<Real>("splits", splits);
  detail::check_tolerances(opt.absolute_tolerance, opt.relative_tolerance);
  const gauss_kronrod_rule<Real>& rule = gauss_kronrod<Real>(opt.gauss_points);
  std::vector<detail::heap_panel<Real>> heap;
  quadrature_result<Real> out;
  for (std::size_t i = 0; i + 1 < splits.size(); ++i) {
    if (!(splits[i + 1] > splits[i])) continue;  // empty interval: contributes 0
    heap.push_back({splits[i], splits[i + 1], rule.apply(f, splits[i], splits[i + 1], opt.model)});
    out.evaluations += heap.back().r.evaluations;
  }
  return detail::refine_adaptive(f, rule, opt, std::move(heap), out);
}

/// Adaptive Gauss-Kronrod on [a, b] by recursive bisection with the tolerance halved per level,
/// depth <= max_depth and at most max_evaluations evaluations of f (the first panel always; then
/// depth first, so a panel reached after the budget ran out keeps its one-panel value and
/// estimate): no allocation (for per-query paths such as Newton inversion). The status
/// is converged when every accepted panel met its share, cap_hit when the depth cap or the budget
/// stopped a panel, rounding_limited when a panel's estimate was its rounding floor or its halves did not
/// improve on it (twice in a row, see detail/roundoff.hpp; the halves' sum is then accepted).
template <class Real, class F>
[[nodiscard]] quadrature_result<Real> integrate_recursive(F&& f, const Real& a, const Real& b, const Real& tolerance,
                                                          const gauss_kronrod_rule<Real>& rule, int max_depth = 20,
                                                          std::size_t max_evaluations = std::size_t(1) << 22) {
  const kronrod_panel<Real> p = rule.apply(f, a, b);
  std::size_t budget = max_evaluations > p.evaluations ? max_evaluations - p.evaluations : 0;
  quadrature_result<Real> out = detail::bisect(f, a, b, p, tolerance, rule, max_depth, false, budget);
  out.evaluations += p.evaluations;
  return out;
}

}  // namespace curvebench::arclength
