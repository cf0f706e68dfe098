// The high-precision reference arc length: s(u) and u(s) of a curve (normally converted to real50
// by convert.hpp) integrated by Boost.Math, independent of curvebench's own quadrature.
// Algorithm: each segment is split at the interior minima of the speed (|P'|^2 sampled, minima
// refined by Brent's method, then Newton on P'.P'' to full precision); a piece ending at a minimum
// whose branch points (distance delta = sqrt(g_min / g'') from the axis) come within 1/32 of the
// segment width h is graded geometrically towards it, log2(h / delta) + 4 levels (at most 48, an
// exact cusp 48), so no singularity is closer to a panel than the panel's size. Each panel: Boost's
// G30-K61 rule, bisected while its estimate exceeds its share of the tolerance, to max_depth,
// stopped at the speed's rounding floor (detail/roundoff.hpp); past max_depth (up to max_extra_depth
// more levels) while its estimate is still truncation (above sqrt(eps) of its value, far from any
// rounding) or its value falls short of its chord |P(b) - P(a)|: a burst of speed narrower than
// the rule's node spacing (a conic of weight 1e6 covers its length within 1e-6 of its ends)
// escapes both rules of the pair alike, and only the chord shows it; at most max_panels panels per
// piece (the estimate of a piece stopped there stays in length_error); or tanh-sinh, ungraded. s(u) from
// the split point at or left of u; u(s) by Boost's bracketed newton_raphson_iterate.
// The estimates measure truncation, not the rounding of the speed itself, except on a segment whose
// whole sampled length is below 2^10 eps of its points' size (its speed is rounding at this
// precision): it is one rule, no split, and its error |value| + that bound.
// Sources: Piessens et al. (1983, QUADPACK); Takahasi & Mori (1974, tanh-sinh); Brent (1973).
// Cost: a few hundred evaluations per polynomial piece at 50 digits, ~50 panels more per speed
// minimum; u(s) one integral per Newton step. Accuracy: ~1e-45 relative in real50 against every
// closed form of the suite (tests/test_reference.cpp).
#pragma once

#include "curvebench/arclength/detail/roundoff.hpp"
#include "curvebench/arclength/result.hpp"
#include "curvebench/core/curve.hpp"
#include "curvebench/core/detail/segment_lookup.hpp"
#include "curvebench/core/error.hpp"
#include "curvebench/core/real.hpp"

#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <boost/math/quadrature/tanh_sinh.hpp>
#include <boost/math/tools/minima.hpp>
#include <boost/math/tools/roots.hpp>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <span>
#include <stdexcept>
#include <utility>
#include <vector>

namespace curvebench::reference {

enum class reference_integrator { gauss_kronrod, tanh_sinh };

template <class Real>
struct reference_options {
  /// Relative tolerance of each piece (Boost's criterion: error <= tol * integral |f|).
  Real tolerance{Real(4096) * epsilon<Real>()};
  unsigned max_depth{6};  // bisection levels per panel: 2^depth panels at worst; grading does the rest
  /// Bisection levels beyond max_depth for a panel whose estimate is still truncation or whose value
  /// falls short of its chord (only such halves go on): a burst 2^-64 of a panel wide is found.
  unsigned max_extra_depth{64};
  /// Panels (61 evaluations each) one piece's bisection may add: with the extra levels a piece whose
  /// speed is rounding noise at this precision (a circle of radius 1e-150 centred at 1e10) would
  /// halve for ever (`check` gave no answer in 5 minutes); a real feature needs a few hundred.
  std::size_t max_panels{4096};
  std::size_t samples_per_segment{64};
  /// A speed minimum below split_ratio * (max sampled speed of its segment) becomes a split point.
  Real split_ratio{Real(1) / Real(4)};
  reference_integrator integrator{reference_integrator::gauss_kronrod};
};

template <curve C>
class reference_arc_length {
 public:
  using Real = typename C::real_type;

  explicit reference_arc_length(C c, const reference_options<Real>& opt = {}) : curve_(std::move(c)), opt_(opt) {
    validate::positive("tolerance", opt_.tolerance);
    validate::count_at_least("samples_per_segment", opt_.samples_per_segment, 3);
    const std::span<const Real> bp = curve_.breakpoints();
    for (std::size_t i = 0; i + 1 < bp.size(); ++i) {
      splits_.push_back(bp[i]);
      grade_levels_.push_back(0);
      if (!(bp[i + 1] > bp[i])) continue;
      Real noise(0);
      const auto minima = interior_minima(bp[i], bp[i + 1], noise);
      if (noise > Real(0)) noise_.push_back({bp[i], bp[i + 1], noise});
      for (const auto& [z, levels] : minima) {
        splits_.push_back(z);
        grade_levels_.push_back(levels);
        minima_.push_back(z);
      }
    }
    splits_.push_back(bp.back());
    grade_levels_.push_back(0);
    cumulative_.push_back(Real(0));
    cumulative_error_.push_back(Real(0));
    for (std::size_t i = 0; i + 1 < splits_.size(); ++i) {
      Real err(0);
      const Real v = splits_[i + 1] > splits_[i]
                         ? integrate(splits_[i], splits_[i + 1], grade_levels_[i], grade_levels_[i + 1], err)
                         : Real(0);
      cumulative_.push_back(cumulative_.back() + v);
      cumulative_error_.push_back(cumulative_error_.back() + err);
    }
  }

  [[nodiscard]] const C& curve() const { return curve_; }
  /// Breakpoints and the interior speed minima, ascending.
  [[nodiscard]] std::span<const Real> splits() const { return splits_; }
  /// The interior speed minima that were split at (cusps and near-cusps).
  [[nodiscard]] std::span<const Real> speed_minima() const { return minima_; }
  [[nodiscard]] Real length() const { return cumulative_.back(); }
  /// Sum of Boost's error estimates of the pieces.
  [[nodiscard]] Real length_error() const { return cumulative_error_.back(); }

  /// s(u) from u0, with its error estimate (Boost's).
  [[nodiscard]] arclength::quadrature_result<Real> s_result(const Real& u) const {
    check_parameter(u, interval<Real>(curve_.domain()));
    const std::size_t i = curvebench::detail::breakpoint_at_or_below<Real>(splits_, u);  // the last split <= u
    arclength::quadrature_result<Real> r;
    Real err(0);
    r.value =
        cumulative_[i] + (u > splits_[i] ? integrate(splits_[i], u, grade_levels_[i], next_levels(i), err) : Real(0));
    r.error_estimate = cumulative_error_[i] + err;
    r.status = arclength::result_status::converged;
    return r;
  }
  [[nodiscard]] Real s(const Real& u) const { return s_result(u).value; }

  /// s(b) - s(a) (signed), for the accuracy runner, which compares many methods' answers u near
  /// one target: s(u) = s(anchor) + s_between(anchor, u). When no split lies strictly between a and
  /// b this is one adaptive panel at the reference tolerance (a single G30-K61 rule for nearby
  /// parameters, instead of the two graded integrals from the splits that s(b) - s(a) needs). When
  /// splits lie between, the whole pieces come from the stored cumulative lengths and the two
  /// partial ones are single panels at relative tolerance 1e-30 (ungraded: near a speed minimum
  /// the graded integral at the full tolerance costs seconds per call on degree-20 Runge, and an
  /// answer that far from u* has an error far above 1e-30 L anyway).
  [[nodiscard]] Real s_between(const Real& a, const Real& b) const {
    check_parameter(a, interval<Real>(curve_.domain()));
    check_parameter(b, interval<Real>(curve_.domain()));
    if (a == b) return Real(0);
    const bool forward = a < b;
    const Real& lo = forward ? a : b;
    const Real& hi = forward ? b : a;
    const auto first = std::upper_bound(splits_.begin(), splits_.end(), lo);  // first split > lo
    const auto last = std::lower_bound(splits_.begin(), splits_.end(), hi);   // first split >= hi
    Real err(0), v(0);
    if (first == last || first == splits_.end() || !(*first < hi)) {
      v = integrate_short(lo, hi, opt_.tolerance, err);
    } else {
      using std::max;
      const Real tol = max(opt_.tolerance, Real(1) / Real(1000000000000000LL) / Real(1000000000000000LL));
      const std::size_t i = static_cast<std::size_t>(first - splits_.begin());
      const std::size_t k = static_cast<std::size_t>(last - splits_.begin()) - 1;  // last split < hi
      v = integrate_panel(lo, splits_[i], tol, err) + (cumulative_[k] - cumulative_[i]);
      if (hi > splits_[k]) v += integrate_panel(splits_[k], hi, tol, err);
    }
    return forward ? v : Real(-v);
  }

  /// u with s(u) = s (0 <= s <= L): bracketed Newton on the reference integrals. Throws
  /// std::domain_error for s outside [0, L].
  [[nodiscard]] Real u(const Real& s) const {
    if (!(s >= Real(0) && s <= length()))
      throw std::domain_error("s = " + to_text(s) + " is outside the arc-length range [0, " + to_text(length()) + "]");
    const std::size_t i = curvebench::detail::breakpoint_at_or_below<Real>(cumulative_, s);  // the last piece end <= s
    if (i + 1 >= splits_.size()) return splits_.back();
    if (s == cumulative_[i]) return splits_[i];
    const Real lo = splits_[i], hi = splits_[i + 1];
    const Real s0 = cumulative_[i];
    auto f = [&](const Real& x) {
      Real err(0);
      const Real v = x > lo ? integrate(lo, x, grade_levels_[i], grade_levels_[i + 1], err) : Real(0);
      using std::sqrt;
      const typename C::point_type d = curve_.derivative(x, 1);
      return std::make_pair(s0 + v - s, Real(sqrt(d.squaredNorm())));
    };
    const Real guess = lo + (s - s0) / (cumulative_[i + 1] - s0) * (hi - lo);
    std::uintmax_t iters = 200;
    return boost::math::tools::newton_raphson_iterate(f, guess, lo, hi, std::numeric_limits<Real>::digits - 4, iters);
  }

 private:
  [[nodiscard]] Real speed2(const Real& u) const { return curve_.derivative(u, 1).squaredNorm(); }

  [[nodiscard]] int next_levels(std::size_t i) const { return i + 1 < grade_levels_.size() ? grade_levels_[i + 1] : 0; }

  // One piece, graded geometrically towards an end that is (or lies next to) a speed minimum: the
  // near-singularity there is then never closer to a panel than the panel's own size, so every
  // panel converges at Boost's first levels instead of bisecting towards the end (whose halving
  // absolute tolerance makes Boost's recursion blow up exponentially near rounding level).
  // levels_a, levels_b: grading levels towards a and b (0: none).
  [[nodiscard]] Real integrate(const Real& a, const Real& b, int levels_a, int levels_b, Real& err) const {
    const bool grade_a = levels_a > 0, grade_b = levels_b > 0;
    err = Real(0);
    // tanh-sinh clusters its nodes doubly exponentially at both ends already: no grading.
    if (opt_.integrator == reference_integrator::tanh_sinh) return integrate_panel(a, b, opt_.tolerance, err);
    if (grade_a && grade_b) {
      const Real mid = (a + b) / Real(2);
      Real e1(0), e2(0);
      const Real v = integrate(a, mid, levels_a, 0, e1) + integrate(mid, b, 0, levels_b, e2);
      err = e1 + e2;
      return v;
    }
    if (!grade_a && !grade_b) return integrate_panel(a, b, opt_.tolerance, err);
    const int levels = grade_a ? levels_a : levels_b;
    using std::max;
    using std::min;
    using std::sqrt;
    // Near the minimum the speed is tiny and computed with an absolute (not relative) rounding of
    // the curve's scale, so a relative tolerance per panel is unreachable there; each panel gets the
    // relative tolerance that makes its absolute error tolerance / 64 of the whole piece's length.
    const Real piece_scale = (b - a) * max(sqrt(speed2(a)), max(sqrt(speed2(b)), sqrt(speed2((a + b) / Real(2)))));
    const Real loosest = Real(1) / Real(10000000000LL);
    auto panel = [&](const Real& lo, const Real& hi, Real& e) {
      const Real guess = (hi - lo) * sqrt(speed2((lo + hi) / Real(2)));
      Real rel = opt_.tolerance;
      if (guess > Real(0)) rel = max(rel, min(loosest, opt_.tolerance / Real(64) * piece_scale / guess));
      return integrate_panel(lo, hi, rel, e);
    };
    Real total(0);
    Real near = grade_a ? a : b;
    Real far = grade_a ? b : a;
    for (int k = 0; k < levels; ++k) {  // [near + (far-near)/2, far], then halves towards near
      const Real m = near + (far - near) / Real(2);
      Real e(0);
      total += grade_a ? panel(m, far, e) : panel(far, m, e);
      err += e;
      far = m;
    }
    Real e(0);
    total += grade_a ? panel(near, far, e) : panel(far, near, e);
    err += e;
    return total;
  }

  // One panel: Boost's G30-K61 rule, bisected while its error estimate exceeds the panel's share
  // of the tolerance (as Boost's own adaptive gauss_kronrod does, to depth max_depth), with two
  // differences that decide the cost on ill-conditioned curves:
  // - The rule is applied to g(x) = (b - a)/2 f(mid + x (b - a)/2) on [-1, 1], so its estimate is
  //   the error of this panel's integral. Boost 1.74's recursion reports and tests |K61 - G30| of
  //   the [-1, 1] integral unscaled, an error overstated by 2 / (b - a): on a graded panel of width
  //   1e-7 that demands 2e7 times the requested accuracy.
  // - Roundoff detection stops the bisection (arclength/detail/roundoff.hpp): once an estimate is
  //   below sqrt(eps) ~ 1e-25 of the panel's integral (far below anything a double method can
  //   show), two bisections in a row whose halves do not halve it are noise, not truncation.
  //   Degree-20 Lagrange through equispaced points has a Lebesgue constant near 1e4, so its
  //   50-digit speed carries ~1e-46 relative noise near the ends; bisecting to full depth there
  //   cost 10-20 s per s(u).
  // The nodes of a narrow panel are rounded to the spacing of Real near |a|, a relative
  // perturbation eps |a| / (b - a) of the panel that no relative tolerance below it can survive: the
  // tolerance is raised to that resolution, and a panel too narrow to matter gets one rule.
  [[nodiscard]] Real integrate_panel(const Real& a, const Real& b, const Real& tolerance, Real& err) const {
    using std::abs;
    using std::max;
    if (const Real* bound = noise_bound(a, b)) {  // one rule: its value is rounding, and its error says so
      const Real v = rule(a, b).value;
      err = abs(v) + *bound;
      return v;
    }
    const Real resolution = Real(64) * epsilon<Real>() * (abs(a) + abs(b)) / abs(b - a);
    const Real tol = max(tolerance, resolution);
    auto f = [this](const Real& x) {
      using std::sqrt;
      return Real(sqrt(speed2(x)));
    };
    if (opt_.integrator == reference_integrator::tanh_sinh) {
      Real l1(0);
      boost::math::quadrature::tanh_sinh<Real> ts;
      return ts.integrate(f, a, b, tol, &err, &l1);
    }
    const unsigned depth = resolution > Real(1) / Real(10000000000LL) ? 0u : opt_.max_depth;
    const panel_estimate whole = rule(a, b);
    const Real abs_tol = tol * abs(whole.value);
    err = Real(0);
    std::size_t panels = opt_.max_panels;
    return bisect(a, b, whole, depth, opt_.max_extra_depth, tol, abs_tol, false, err, panels);
  }

  struct panel_estimate {
    Real value, error;
  };

  // A panel between nearby parameters (s_between's answers near one target, check's sorted rows):
  // Boost's G7-K15 rule first, kept when its estimate |K15 - G7| meets the tolerance integrate_panel
  // would ask, else integrate_panel. 15 evaluations instead of G30-K61's 61: at widths of 1e-4 of
  // a smooth piece the 15-point rule is already exact to 50 digits.
  [[nodiscard]] Real integrate_short(const Real& a, const Real& b, const Real& tolerance, Real& err) const {
    using std::abs;
    using std::max;
    if (opt_.integrator != reference_integrator::tanh_sinh && noise_bound(a, b) == nullptr) {
      const Real resolution = Real(64) * epsilon<Real>() * (abs(a) + abs(b)) / abs(b - a);
      const Real half = (b - a) / Real(2), mid = a + half;
      auto g = [&](const Real& x) {
        using std::sqrt;
        return Real(half * sqrt(speed2(mid + half * x)));
      };
      Real e(0);
      const Real v = boost::math::quadrature::gauss_kronrod<Real, 15>::integrate(g, Real(-1), Real(1), 0, Real(0), &e);
      if (e <= max(tolerance, resolution) * abs(v) && !below_chord(a, b, {v, e}, max(tolerance, resolution))) {
        err += e;
        return v;
      }
    }
    return integrate_panel(a, b, tolerance, err);
  }

  // The noise bound of the segment [a, b] lies in (see interior_minima), or nullptr: on such a
  // segment the true length is taken to be below the bound (its sampled length is), so a computed
  // value v is within |v| + bound of it, which is the error reported.
  [[nodiscard]] const Real* noise_bound(const Real& a, const Real& b) const {
    for (const noise_segment& n : noise_)
      if (a >= n.lo && b <= n.hi) return &n.bound;
    return nullptr;
  }

  [[nodiscard]] panel_estimate rule(const Real& a, const Real& b) const {
    const Real half = (b - a) / Real(2), mid = a + half;
    auto g = [&](const Real& x) {
      using std::sqrt;
      return Real(half * sqrt(speed2(mid + half * x)));
    };
    panel_estimate e{Real(0), Real(0)};
    e.value = boost::math::quadrature::gauss_kronrod<Real, 61>::integrate(g, Real(-1), Real(1), 0, Real(0), &e.error);
    return e;
  }

  // Whether a rule's value plus its estimate falls short of the chord |P(b) - P(a)| by more than
  // the tolerance and the rounding of the two points (64 eps of their size): arc length is at
  // least the chord, so the rule missed speed between its nodes, whatever its estimate says.
  [[nodiscard]] bool below_chord(const Real& a, const Real& b, const panel_estimate& p, const Real& tol) const {
    using std::abs;
    const typename C::point_type pa = curve_(a), pb = curve_(b);
    const Real chord = Real((pb - pa).norm());
    const Real size = Real(pa.norm() + pb.norm());
    return abs(p.value) + p.error + tol * chord + Real(64) * epsilon<Real>() * size < chord;
  }

  // p is the rule's estimate on [a, b]; abs_tol the absolute tolerance of this panel; suspect: the
  // bisection that made it stagnated (arclength/detail/roundoff.hpp), a second one stops it;
  // extra: the levels left past depth 0 to a panel whose estimate is still truncation (above
  // sqrt(eps) of its value) or whose value falls short of its chord (below_chord, which bisects it
  // whatever its estimate).
  [[nodiscard]] Real bisect(const Real& a, const Real& b, const panel_estimate& p, unsigned depth, unsigned extra,
                            const Real& tol, const Real& abs_tol, bool suspect, Real& err, std::size_t& panels) const {
    using std::abs;
    using std::max;
    using std::sqrt;
    const bool short_of_chord = extra > 0 && below_chord(a, b, p, tol);
    const bool met = p.error <= max(abs_tol, tol * abs(p.value));
    const bool truncation = p.error > sqrt(epsilon<Real>()) * abs(p.value);
    // panels < 2: the piece's budget (max_panels) is spent; the panel is kept with its estimate, so
    // the reference's own error (length_error) says how far it is from converged.
    if (panels < 2 || (!short_of_chord && (met || (depth == 0 && (extra == 0 || !truncation))))) {
      err += p.error;
      return p.value;
    }
    panels -= 2;
    const Real m = a + (b - a) / Real(2);
    const panel_estimate left = rule(a, m), right = rule(m, b);
    const bool stagnated =
        arclength::detail::bisection_stagnated(p.error, Real(left.error + right.error), Real(abs(p.value)));
    if (stagnated && suspect && !short_of_chord) {
      err += left.error + right.error;
      return left.value + right.value;
    }
    const unsigned next = depth > 0 ? depth - 1 : 0u;
    const unsigned next_extra = (depth == 0 || short_of_chord) && extra > 0 ? extra - 1 : extra;
    return bisect(a, m, left, next, next_extra, tol, abs_tol / Real(2), stagnated, err, panels) +
           bisect(m, b, right, next, next_extra, tol, abs_tol / Real(2), stagnated, err, panels);
  }

  // Interior local minima of the speed on (a, b) below split_ratio * max speed, refined.
  // (location, grading levels), see the header. Beside the sampled minima (a sample below both
  // neighbours), a minimum inside an end interval (the end sample lowest, the speed falling
  // towards the end) and any interval across which P' turns back by more than 90 degrees (its dot
  // product negative) are searched too, and kept only where Newton converges strictly inside: a 1D
  // Hermite spline with end slopes of 1e-6 of its chords has exact cusps 1e-7 from its knots, in
  // no sample's bracket, and the reference missed their 1e-12 of length while claiming 1e-49.
  // The last sample is taken just inside b: at an interior breakpoint P'(b) is the next segment's.
  // noise (out): > 0 when the segment's whole sampled length, sqrt(max |P'|^2) (b - a), is below
  // 2^10 eps of its points' size: its speed is then the rounding of the evaluation at this
  // precision (a circle of radius 1e-150 centred at 1e10 has all its control points rounded to the
  // centre), with sampled minima everywhere; no minimum is split at (each would be graded, and the
  // pieces multiplied the work without bound), and the value is that bound (see noise_bound).
  [[nodiscard]] std::vector<std::pair<Real, int>> interior_minima(const Real& a, const Real& b, Real& noise) const {
    using std::abs;
    using std::sqrt;
    const std::size_t m = opt_.samples_per_segment;
    const Real tiny = Real(64) * epsilon<Real>() * (abs(a) + abs(b) + (b - a));
    std::vector<Real> us(m + 1), g(m + 1);
    std::vector<typename C::point_type> d1s(m + 1);
    Real gmax(0);
    for (std::size_t k = 0; k <= m; ++k) {
      us[k] = k == m ? Real(b - tiny) : a + (b - a) * Real(static_cast<long long>(k)) / Real(static_cast<long long>(m));
      d1s[k] = curve_.derivative(us[k], 1);
      g[k] = d1s[k].squaredNorm();
      gmax = std::max(gmax, g[k]);
    }
    std::vector<std::pair<Real, int>> out;
    if (!(gmax > Real(0))) return out;  // speed zero on the whole segment: nothing to split
    using std::max;
    const Real size = max(Real(curve_(a).norm()), max(Real(curve_((a + b) / Real(2)).norm()), Real(curve_(b).norm())));
    if (sqrt(gmax) * (b - a) <= Real(1024) * epsilon<Real>() * size) {
      noise = Real(1024) * epsilon<Real>() * size;
      return out;
    }
    const Real threshold = opt_.split_ratio * opt_.split_ratio * gmax;
    // Brent's minimum of |P'|^2 on [lo, hi], then Newton on h = P'.P'' (zero at a minimum of |P'|^2)
    // kept inside the bracket; `strict`: kept only when Newton converged strictly inside it.
    const auto search = [&](const Real& lo, const Real& hi, bool strict) {
      auto obj = [this](const Real& x) { return speed2(x); };
      const auto res = boost::math::tools::brent_find_minima(obj, lo, hi, std::numeric_limits<Real>::digits / 2);
      Real x = res.first;
      bool converged = false;
      for (int it = 0; it < 40; ++it) {
        const typename C::point_type d1 = curve_.derivative(x, 1);
        const typename C::point_type d2 = curve_.derivative(x, 2);
        const typename C::point_type d3 = curve_.derivative(x, 3);
        const Real h = d1.dot(d2);
        const Real dh = d2.squaredNorm() + d1.dot(d3);
        if (h == Real(0)) {
          converged = true;
          break;
        }
        if (!(dh > Real(0))) break;
        const Real next = x - h / dh;
        if (!(next > lo && next < hi)) break;
        const bool done = abs(next - x) <= epsilon<Real>() * (abs(x) + abs(b - a));
        x = next;
        if (done) {
          converged = true;
          break;
        }
      }
      if (strict && !(converged && x > lo + tiny && x < hi - tiny)) return;
      if (x > a && x < b && (out.empty() || x > out.back().first + tiny)) {
        const Real g0 = speed2(x);
        int levels = 48;  // an exact cusp (g0 = 0, or no curvature term to measure delta by)
        const typename C::point_type d1 = curve_.derivative(x, 1), d2 = curve_.derivative(x, 2),
                                     d3 = curve_.derivative(x, 3);
        const Real g2 = d2.squaredNorm() + d1.dot(d3);
        if (g0 > Real(0) && g2 > Real(0)) {
          using std::ceil;
          using std::log2;
          const Real ratio = (b - a) / sqrt(g0 / g2);
          levels = ratio > Real(32) ? static_cast<int>(std::min(Real(48), ceil(log2(ratio)) + Real(4))) : 0;
        }
        out.emplace_back(x, levels);
      }
    };
    const auto turns_back = [&](std::size_t k) { return d1s[k].dot(d1s[k + 1]) < Real(0); };
    if (g[0] <= g[1] && g[0] <= threshold) search(a, us[1], true);
    for (std::size_t k = 1; k < m; ++k) {
      if (turns_back(k - 1)) search(us[k - 1], us[k], true);
      if (!(g[k] <= g[k - 1] && g[k] <= g[k + 1]) || g[k] > threshold) continue;
      if (g[k] == g[k - 1] && g[k] == Real(0)) continue;  // inside a zero-speed stretch: one split is enough
      search(us[k - 1], us[k + 1], false);
    }
    if (turns_back(m - 1)) search(us[m - 1], b, true);
    if (g[m] <= g[m - 1] && g[m] <= threshold) search(us[m - 1], b, true);
    return out;
  }

  struct noise_segment {
    Real lo, hi, bound;
  };

  C curve_;
  reference_options<Real> opt_;
  std::vector<noise_segment> noise_;  // segments whose speed is rounding (interior_minima)
  std::vector<Real> splits_, minima_, cumulative_, cumulative_error_;
  std::vector<int> grade_levels_;
};

}  // namespace curvebench::reference
