// Bezier curves of any degree L (1 <= L <= bezier_max_degree = 60): P(t) = sum_k B_k^L(t) P_k on a
// domain [a, b] (default [0, 1]), t = (u - a) / (b - a).
// Algorithms (evaluate(u, algorithm)): de_casteljau (operator()), L(L+1)/2 convex combinations,
// O(L^2), backward stable, error ~L ulps of the control-point scale; bernstein_sum, O(L),
// non-negative weights, error ~L ulps; horner, power-basis coefficients converted once in the
// constructor, O(L), but the conversion cancels binomially large terms: error bound ~3^L ulps
// (kept on purpose: it is what the bench shows; tests/test_bezier.cpp measures it at L = 20).
// Derivatives of any order by the hodograph levels, all precomputed ((L+1)(L+2)/2 points), so
// derivative(u, k) does not allocate. Also: batch evaluate, split (de Casteljau, O(L^2)),
// elevate (O(L)), hodograph, power_coefficients. Evaluation uses a stack buffer of 61 points (the
// reason for the cap): no allocation, no mutable state, thread-safe. Bad data throw invalid_input;
// u outside the domain std::domain_error.
// rounding_bound(order), order 0 or 1 (core/curve.hpp), of the default de Casteljau evaluation:
// (3L + 4 + 2L c) eps max_i |D_i| (+1%) over the level's control points D_i: de Casteljau's L levels
// of s b_i + t b_{i+1} with s = fl(1 - t) err by at most gamma_{3L} sum_i B_i(t) |D_i| (the convex
// combination argument of Farouki & Rajan 1987), the hodograph level by gamma_4 (a difference, a
// product, a division by fl(b - a)), and t = fl((u - a) / (b - a)) by gamma_c, c = 3 (0 on a domain
// [0, 2^k], where t is exact), which moves the value by at most gamma_c 2L max |D_i|.
// Cost: O(L) once at construction.
// Sources: seed 000 (de Casteljau, Bernstein polynomials, derivatives), seed 002; Farin (2002),
// ch. 4-6; Farouki & Rajan (1987). Accuracy: O(L eps) for de Casteljau and Bernstein, O(3^L eps) for Horner.
#pragma once

#include "curvebench/core/curve.hpp"
#include "curvebench/core/error.hpp"
#include "curvebench/core/point.hpp"
#include "curvebench/core/real.hpp"
#include "curvebench/curves/detail/bezier_eval.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <span>
#include <string>
#include <utility>
#include <vector>

namespace curvebench {

/// How a Bezier curve is evaluated (see bezier.hpp for cost and accuracy of each).
enum class bezier_algorithm { de_casteljau, bernstein_sum, horner };

/// Name of an algorithm, as used in benchmark names and reports.
[[nodiscard]] inline const char* to_string(bezier_algorithm a) {
  switch (a) {
    case bezier_algorithm::de_casteljau: return "de_casteljau";
    case bezier_algorithm::bernstein_sum: return "bernstein_sum";
    case bezier_algorithm::horner: return "horner";
  }
  return "unknown";
}

namespace detail {

/// Validates a curve domain: finite ends with lo < hi, wide enough to be resolved (validate::resolvable).
template <class Real>
void check_bezier_domain(std::string_view name, const interval<Real>& d) {
  validate::finite(std::string(name) + ".lo", d.lo);
  validate::finite(std::string(name) + ".hi", d.hi);
  if (!(d.lo < d.hi))
    validate::fail(std::string(name) + " = [" + to_text(d.lo) + ", " + to_text(d.hi) + "]: must have lo < hi");
  validate::resolvable(std::string(name) + " width", d.lo, d.hi);
}

}  // namespace detail

template <class Real, int Dim>
class bezier {
 public:
  using real_type = Real;
  using point_type = point<Real, Dim>;
  static constexpr int dimension = Dim;

  /// A Bezier curve of degree control_points.size() - 1 on `domain`.
  explicit bezier(std::span<const point_type> control_points, interval<Real> domain = {Real(0), Real(1)})
      : domain_(domain), breaks_{domain.lo, domain.hi} {
    validate::count_at_least("control_points", control_points.size(), 2,
                             "a Bezier curve of degree L >= 1 has L + 1 control points");
    if (control_points.size() > static_cast<std::size_t>(bezier_max_degree) + 1)
      validate::fail("control_points: " + std::to_string(control_points.size()) + " given, at most " +
                     std::to_string(bezier_max_degree + 1) +
                     " allowed (degree <= " + std::to_string(bezier_max_degree) + ")");
    validate::finite_points<Real, Dim>("control_points", control_points);
    detail::check_bezier_domain("domain", domain);
    degree_ = static_cast<int>(control_points.size()) - 1;
    build(control_points);
  }

  [[nodiscard]] int degree() const { return degree_; }
  [[nodiscard]] interval<Real> domain() const { return domain_; }
  [[nodiscard]] std::span<const Real> breakpoints() const { return breaks_; }
  [[nodiscard]] std::span<const point_type> control_points() const { return level(0); }

  /// The control points of the k-th derivative (k = 0..L): L!/(L-k)! D^k P_i / (b-a)^k,
  /// L - k + 1 points, a Bezier curve of degree L - k on the same domain.
  [[nodiscard]] std::span<const point_type> derivative_control_points(int k) const {
    if (k < 0 || k > degree_)
      validate::fail("k = " + std::to_string(k) + ": must be in [0, " + std::to_string(degree_) + "]");
    return level(k);
  }

  /// Upper bound on the rounding of this curve's de Casteljau evaluation of P (order 0) or P'
  /// (order 1) over the domain (see the header); +inf for other orders.
  [[nodiscard]] Real rounding_bound(int order) const {
    if (order < 0 || order > 1) return std::numeric_limits<Real>::infinity();
    return rounding_bound_[static_cast<std::size_t>(order)];
  }

  /// Power-basis coefficients a_j in t = (u - a) / (b - a): P = sum a_j t^j (used by horner).
  [[nodiscard]] std::span<const point_type> power_coefficients() const { return power_; }

  /// The value by de Casteljau's algorithm.
  [[nodiscard]] point_type operator()(const Real& u) const { return evaluate(u, bezier_algorithm::de_casteljau); }

  /// The value by the chosen algorithm.
  [[nodiscard]] point_type evaluate(const Real& u, bezier_algorithm algorithm) const {
    return derivative(u, 0, algorithm);
  }

  /// Batch evaluation: out[i] = the order-th derivative at us[i] (order 0: the value) by the chosen
  /// algorithm. Sizes must match (invalid_input); every parameter is checked (std::domain_error).
  /// No allocation; the order of the parameters does not matter for a single segment.
  void evaluate(std::span<const Real> us, std::span<point_type> out, bezier_algorithm algorithm, int order = 0) const {
    validate::same_count("out", out.size(), "us", us.size());
    for (std::size_t i = 0; i < us.size(); ++i) {
      check_parameter(us[i], domain_, "us", i);
      out[i] = derivative(us[i], order, algorithm);
    }
  }

  /// d^order P / du^order by de Casteljau on the precomputed hodograph control points.
  [[nodiscard]] point_type derivative(const Real& u, int order) const {
    return derivative(u, order, bezier_algorithm::de_casteljau);
  }

  /// d^order P / du^order by the chosen algorithm (horner differentiates the power form).
  [[nodiscard]] point_type derivative(const Real& u, int order, bezier_algorithm algorithm) const {
    validate::derivative_order(order);
    check_parameter(u, domain_);
    if (order > degree_) return zero_point<Real, Dim>();
    const Real t = local(u);
    switch (algorithm) {
      case bezier_algorithm::bernstein_sum:
        return detail::bezier_kernels::bernstein_sum(level(order), binomials(order), t);
      case bezier_algorithm::horner: {
        point_type v = detail::bezier_kernels::horner(std::span<const point_type>(power_), t, order);
        if (order > 0) v /= pow_h(order);
        return v;
      }
      case bezier_algorithm::de_casteljau: break;
    }
    return detail::bezier_kernels::de_casteljau(level(order), t);
  }

  /// The derivative curve dP/du as a Bezier curve of degree L - 1 on the same domain. The hodograph
  /// of a line (L = 1) is a constant, returned as a degree-1 curve with two equal control points.
  [[nodiscard]] bezier hodograph() const {
    std::span<const point_type> d = level(1);
    if (degree_ == 1) {
      const std::array<point_type, 2> twice{d[0], d[0]};
      return bezier(std::span<const point_type>(twice), domain_);
    }
    return bezier(d, domain_);
  }

  /// Subdivision by de Casteljau at u (strictly inside the domain): the left piece on [a, u] and the
  /// right piece on [u, b], each the same polynomial restricted to its interval, so left(v) and
  /// right(v) equal this curve's value at v.
  [[nodiscard]] std::pair<bezier, bezier> split(const Real& u) const {
    check_parameter(u, domain_);
    if (!(domain_.lo < u && u < domain_.hi))
      validate::fail("split: u = " + to_text(u) + ": must be strictly inside (" + to_text(domain_.lo) + ", " +
                     to_text(domain_.hi) + ")");
    const Real t = local(u);
    const Real s = Real(1) - t;
    const auto n = static_cast<std::size_t>(degree_);
    point_list<Real, Dim> b(control_points().begin(), control_points().end());
    point_list<Real, Dim> left(n + 1), right(n + 1);
    left[0] = b[0];
    right[n] = b[n];
    for (std::size_t m = 1; m <= n; ++m) {
      for (std::size_t i = 0; i + m <= n; ++i) b[i] = s * b[i] + t * b[i + 1];
      left[m] = b[0];
      right[n - m] = b[n - m];
    }
    return {bezier(std::span<const point_type>(left), {domain_.lo, u}),
            bezier(std::span<const point_type>(right), {u, domain_.hi})};
  }

  /// The same curve as degree L + 1: Q_i = (i P_{i-1} + (L + 1 - i) P_i) / (L + 1).
  [[nodiscard]] bezier elevate() const {
    std::span<const point_type> p = control_points();
    const int n = degree_ + 1;
    point_list<Real, Dim> q(static_cast<std::size_t>(n) + 1);
    q.front() = p.front();
    q.back() = p.back();
    for (int i = 1; i < n; ++i) {
      const auto ui = static_cast<std::size_t>(i);
      q[ui] = (Real(i) * p[ui - 1] + Real(n - i) * p[ui]) / Real(n);
    }
    return bezier(std::span<const point_type>(q), domain_);
  }

 private:
  [[nodiscard]] Real local(const Real& u) const { return (u - domain_.lo) / (domain_.hi - domain_.lo); }

  [[nodiscard]] Real pow_h(int k) const {
    const Real h = domain_.hi - domain_.lo;
    Real r(1);
    for (int j = 0; j < k; ++j) r *= h;
    return r;
  }

  // Level k (0..L) holds L - k + 1 entries starting at offset(k) = sum_{j<k} (L - j + 1).
  [[nodiscard]] std::size_t offset(int k) const {
    const auto n = static_cast<std::size_t>(degree_);
    const auto uk = static_cast<std::size_t>(k);
    return uk * (n + 1) - uk * (uk - 1) / 2;
  }
  [[nodiscard]] std::span<const point_type> level(int k) const {
    return std::span<const point_type>(levels_).subspan(offset(k), static_cast<std::size_t>(degree_ - k) + 1);
  }
  [[nodiscard]] std::span<const Real> binomials(int k) const {
    return std::span<const Real>(binomials_).subspan(offset(k), static_cast<std::size_t>(degree_ - k) + 1);
  }

  void build(std::span<const point_type> cps) {
    const int n = degree_;
    const std::size_t total = offset(n) + 1;
    levels_.reserve(total);
    binomials_.reserve(total);
    levels_.assign(cps.begin(), cps.end());
    const Real h = domain_.hi - domain_.lo;
    for (int k = 1; k <= n; ++k) {
      const std::size_t prev = offset(k - 1);
      const Real factor = Real(n - k + 1);
      for (int i = 0; i <= n - k; ++i) {
        const std::size_t j = prev + static_cast<std::size_t>(i);
        point_type d = (factor * (levels_[j + 1] - levels_[j])) / h;
        levels_.push_back(d);
      }
    }
    for (int k = 0; k <= n; ++k)
      for (int i = 0; i <= n - k; ++i) binomials_.push_back(binomial<Real>(n - k, i));
    power_ = detail::bezier_kernels::to_power_basis<point_type, Real>(cps);
    for (int k = 0; k <= 1; ++k) {
      Real biggest(0);
      // safe_norm: the square of a norm past 1e154 would overflow (no bound at all for such a curve)
      for (const point_type& d : level(std::min(k, n))) biggest = std::max(biggest, safe_norm(d));
      // c of the header: u - 0 and a division by a power of two are exact.
      using std::frexp;
      int exponent = 0;
      const bool exact_t = domain_.lo == Real(0) && frexp(domain_.hi, &exponent) == Real(0.5);
      const long long c = exact_t ? 0 : 3;
      rounding_bound_[static_cast<std::size_t>(k)] =
          from_int<Real>(3LL * n + 4 + 2LL * n * c) * epsilon<Real>() * biggest * (Real(101) / Real(100));
    }
  }

  interval<Real> domain_;
  std::array<Real, 2> breaks_;
  int degree_ = 0;
  point_list<Real, Dim> levels_;  // control points, then the hodograph levels 1..L
  std::vector<Real> binomials_;   // C(L - k, i) per level, same layout as levels_
  point_list<Real, Dim> power_;   // power-basis coefficients in t
  std::array<Real, 2> rounding_bound_{};
};

}  // namespace curvebench
