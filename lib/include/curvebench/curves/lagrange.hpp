// Lagrange interpolation: the polynomial curve of degree n through n + 1 points P_j at parameters
// u_0 < ... < u_n, by one of two algorithms (lagrange_algorithm):
//   barycentric (default): the second barycentric formula P(u) = sum_j (w_j / (u - u_j)) P_j /
//     sum_j w_j / (u - u_j), weights w_j = 1 / prod_{k != j} (u_j - u_k) once (O(n^2)); O(n) per
//     value, P_j exactly at u_j; forward stable, error growing with the Lebesgue constant (small for
//     Chebyshev nodes, ~2^n / (e n log n) for equispaced ones). Derivatives of any order exactly, by
//     divided differences with a repeated argument (Schneider & Werner 1986), O(n m^2) for order m.
//   monomial: the poor reference of seeds 001/002: the Vandermonde system solved by pivoted LU
//     (O(n^3) once), then Horner, O(n); cond(V) grows exponentially with n.
// equispaced_parameters and chebyshev_parameters (second kind, ends included) give the u_j. The
// domain is [u_0, u_n]; breakpoints {u_0, u_n}. Bad data (fewer than 2 points, non-finite values,
// non-increasing parameters, overflowing weights) throw invalid_input; u outside std::domain_error.
// rounding_bound(order), order 0 or 1 (core/curve.hpp): for the barycentric algorithm the a-priori
// bound (3n + 4) eps (K + Lambda |P|) of Higham (2004) for the second barycentric formula, with
// K = sum_j |P_j| max|l_j|, Lambda = sum_j max|l_j| and |P| = max|P(u)| (l_j the Lagrange basis);
// for the first derivative the same form with the derivative's condition numbers,
// (3n + 4) eps (sum_j |P_j| max|l_j'| + sum_j max|l_j'| |P| + Lambda max|P'|) (by analogy: the
// divided-difference recurrence has no published bound; tests/test_rounding_bound.cpp checks it
// against 50-digit evaluation and its looseness). The maxima are taken at the 4n + 1 Chebyshev
// extreme points of the domain and multiplied by sec(pi/8) < 1.0824, which bounds a degree-n
// polynomial by its values there (Ehlich & Zeller 1964). The monomial algorithm has no bound (+inf: cond(V) is
// not computed). Cost: O(n^2) once at construction (about four times the weights' cost).
// Limits, checked before any work: at most max_barycentric_points (10^4: O(n^2) weights, O(n) per
// value) and max_monomial_points (10^3: an n x n matrix, O(n^3) LU) points.
// Sources: Berrut & Trefethen (2004); Higham (2004); Schneider & Werner (1986); Ehlich & Zeller (1964).
// Accuracy: barycentric O(Lebesgue constant * eps); monomial O(cond(V) * eps).
#pragma once

#include "curvebench/core/curve.hpp"
#include "curvebench/core/error.hpp"
#include "curvebench/core/point.hpp"
#include "curvebench/core/real.hpp"

#include <Eigen/Core>
#include <Eigen/LU>
#include <boost/math/constants/constants.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <span>
#include <string>
#include <vector>

namespace curvebench {

/// How a Lagrange curve is represented and evaluated (see lagrange.hpp).
enum class lagrange_algorithm { barycentric, monomial };

/// The most points a Lagrange curve takes, per algorithm (see the header).
inline constexpr std::size_t max_barycentric_points = 10000;
inline constexpr std::size_t max_monomial_points = 1000;

/// Name of an algorithm, as used in benchmark names and reports.
[[nodiscard]] inline const char* to_string(lagrange_algorithm a) {
  switch (a) {
    case lagrange_algorithm::barycentric: return "barycentric";
    case lagrange_algorithm::monomial: return "monomial";
  }
  return "unknown";
}

/// count equispaced parameters a + (b - a) j / (count - 1), j = 0..count-1; the ends are exact.
template <class Real>
[[nodiscard]] std::vector<Real> equispaced_parameters(std::size_t count, const Real& a = Real(0),
                                                      const Real& b = Real(1)) {
  validate::count_at_least("count", count, 2, "the two ends of the interval");
  validate::finite("a", a);
  validate::finite("b", b);
  if (!(a < b)) validate::fail("[a, b] = [" + to_text(a) + ", " + to_text(b) + "]: must have a < b");
  const Real n = from_int<Real>(static_cast<long long>(count - 1));
  std::vector<Real> u(count);
  for (std::size_t j = 0; j < count; ++j) {
    const Real s = from_int<Real>(static_cast<long long>(j)) / n;
    u[j] = (Real(1) - s) * a + s * b;
  }
  u.back() = b;
  return u;
}

/// The count Chebyshev points of the second kind on [a, b], increasing:
/// (a + b)/2 + (b - a)/2 sin(pi (2j - n) / (2n)), n = count - 1 (= -cos(j pi / n) mapped; the sine
/// form is exactly symmetric). The ends are exact.
template <class Real>
[[nodiscard]] std::vector<Real> chebyshev_parameters(std::size_t count, const Real& a = Real(-1),
                                                     const Real& b = Real(1)) {
  validate::count_at_least("count", count, 2, "the two ends of the interval");
  validate::finite("a", a);
  validate::finite("b", b);
  if (!(a < b)) validate::fail("[a, b] = [" + to_text(a) + ", " + to_text(b) + "]: must have a < b");
  using std::sin;
  const auto n = static_cast<long long>(count - 1);
  const Real pi = boost::math::constants::pi<Real>();
  const Real mid = (a + b) / Real(2);
  const Real half = (b - a) / Real(2);
  std::vector<Real> u(count);
  for (long long j = 0; j <= n; ++j)
    u[static_cast<std::size_t>(j)] = mid + half * sin(pi * from_int<Real>(2 * j - n) / from_int<Real>(2 * n));
  u.front() = a;
  u.back() = b;
  return u;
}

template <class Real, int Dim>
class lagrange {
 public:
  using real_type = Real;
  using point_type = point<Real, Dim>;
  static constexpr int dimension = Dim;

  /// Interpolates points at n + 1 equispaced parameters on [0, 1].
  explicit lagrange(std::span<const point_type> points, lagrange_algorithm algorithm = lagrange_algorithm::barycentric)
      : lagrange(points, default_parameters(points.size()), algorithm) {}

  /// Interpolates points[j] at parameters[j] (finite, strictly increasing, one per point).
  lagrange(std::span<const point_type> points, std::span<const Real> parameters,
           lagrange_algorithm algorithm = lagrange_algorithm::barycentric)
      : algorithm_(algorithm), points_(points.begin(), points.end()), params_(parameters.begin(), parameters.end()) {
    validate::count_at_least("points", points_.size(), 2, "a Lagrange curve of degree n >= 1 has n + 1 points");
    const std::size_t limit = algorithm_ == lagrange_algorithm::monomial ? max_monomial_points : max_barycentric_points;
    if (points_.size() > limit)
      validate::fail("points: " + std::to_string(points_.size()) + " points, more than the " +
                     std::string(to_string(algorithm_)) + " algorithm's limit of " + std::to_string(limit) +
                     (algorithm_ == lagrange_algorithm::monomial ? " (an n x n Vandermonde matrix, O(n^3) to solve)"
                                                                 : " (O(n^2) weights, O(n) per value)"));
    validate::finite_points<Real, Dim>("points", points_);
    validate::same_count("parameters", params_.size(), "points", points_.size());
    validate::increasing<Real>("parameters", params_);
    breaks_ = {params_.front(), params_.back()};
    if (algorithm_ == lagrange_algorithm::barycentric) {
      build_weights();
      build_rounding_bounds();
    } else {
      build_monomial();
    }
  }

  [[nodiscard]] int degree() const { return static_cast<int>(points_.size()) - 1; }
  [[nodiscard]] lagrange_algorithm algorithm() const { return algorithm_; }
  [[nodiscard]] interval<Real> domain() const { return {breaks_[0], breaks_[1]}; }
  [[nodiscard]] std::span<const Real> breakpoints() const { return breaks_; }
  [[nodiscard]] std::span<const point_type> points() const { return points_; }
  [[nodiscard]] std::span<const Real> parameters() const { return params_; }
  /// Barycentric weights, scaled so that max |w_j| = 1 (empty for the monomial algorithm).
  [[nodiscard]] std::span<const Real> weights() const { return weights_; }
  /// Upper bound on the rounding of this curve's own evaluation of P (order 0) or P' (order 1) over
  /// the domain (see the header); +inf for the monomial algorithm and for other orders.
  [[nodiscard]] Real rounding_bound(int order) const {
    if (algorithm_ != lagrange_algorithm::barycentric || order < 0 || order > 1)
      return std::numeric_limits<Real>::infinity();
    return rounding_bound_[static_cast<std::size_t>(order)];
  }
  /// Power coefficients a_k, P(u) = sum a_k u^k (empty for the barycentric algorithm).
  [[nodiscard]] std::span<const point_type> monomial_coefficients() const { return coeffs_; }

  [[nodiscard]] point_type operator()(const Real& u) const {
    check_parameter(u, domain());
    return algorithm_ == lagrange_algorithm::barycentric ? barycentric_value(u) : horner(u, 0);
  }

  /// d^order P / du^order, exact (order 0 is the value; order > n is zero).
  [[nodiscard]] point_type derivative(const Real& u, int order) const {
    validate::derivative_order(order);
    check_parameter(u, domain());
    if (order > degree()) return zero_point<Real, Dim>();
    if (algorithm_ == lagrange_algorithm::monomial) return horner(u, order);
    if (order == 0) return barycentric_value(u);
    constexpr int stack_orders = 16;
    if (order < stack_orders) {
      std::array<point_type, stack_orders> d;
      return barycentric_derivative(u, order, std::span<point_type>(d.data(), static_cast<std::size_t>(order) + 1));
    }
    std::vector<point_type> d(static_cast<std::size_t>(order) + 1);
    return barycentric_derivative(u, order, std::span<point_type>(d));
  }

 private:
  static std::vector<Real> default_parameters(std::size_t count) {
    validate::count_at_least("points", count, 2, "a Lagrange curve of degree n >= 1 has n + 1 points");
    return equispaced_parameters<Real>(count);
  }

  void build_weights() {
    // w_j = 1 / prod_{k != j} (u_j - u_k) * c^{-n}, c = 4 / (u_n - u_0): the factor c keeps the products
    // near 1 in magnitude (the capacity of an interval is a quarter of its length), then all weights are
    // divided by the largest. Neither scaling changes the barycentric formula.
    const std::size_t m = params_.size();
    const Real c = Real(4) / (params_.back() - params_.front());
    weights_.assign(m, Real(0));
    using std::abs;
    Real biggest(0);
    for (std::size_t j = 0; j < m; ++j) {
      Real prod(1);
      for (std::size_t k = 0; k < m; ++k)
        if (k != j) prod *= c * (params_[j] - params_[k]);
      weights_[j] = Real(1) / prod;
      if (!is_finite(weights_[j]) || weights_[j] == Real(0))
        validate::fail("parameters: barycentric weight " + std::to_string(j) + " = " + to_text(weights_[j]) +
                       " is out of range for this Real (" + std::to_string(m) + " points: use fewer, or a wider type)");
      biggest = std::max(biggest, Real(abs(weights_[j])));
    }
    for (Real& w : weights_) w /= biggest;
  }

  // The bounds of the header. At each sample x (not a node) l_j(x) = c_j / sum_k c_k with
  // c_j = w_j / (x - u_j) and l_j'(x) = l_j(x) (sum_{k != j} 1 / (x - u_k)); at a node u_i, l_j(u_i) =
  // delta_ij, l_j'(u_i) = (w_j / w_i) / (u_i - u_j) for j != i and l_i'(u_i) = sum_{k != i} 1 / (u_i - u_k)
  // (Berrut & Trefethen, sec. 9). O(n) per sample, 4n + 1 samples.
  void build_rounding_bounds() {
    using std::abs;
    using std::cos;
    using std::sqrt;
    const std::size_t m1 = params_.size();
    const long long n = static_cast<long long>(m1) - 1;
    const long long samples = 4 * n;
    const Real pi = boost::math::constants::pi<Real>();
    const Real mid = (params_.front() + params_.back()) / Real(2), half = (params_.back() - params_.front()) / Real(2);
    std::vector<Real> max_l(m1, Real(0)), max_dl(m1, Real(0)), c(m1);
    Real max_p(0), max_dp(0);
    for (long long k = 0; k <= samples; ++k) {
      Real x = k == 0         ? params_.front()
               : k == samples ? params_.back()
                              : Real(mid - half * cos(pi * from_int<Real>(k) / from_int<Real>(samples)));
      x = std::clamp(x, params_.front(), params_.back());
      max_p = std::max(max_p, safe_norm(point_type(barycentric_value(x))));
      max_dp = std::max(max_dp, safe_norm(point_type(derivative(x, 1))));
      const auto at = std::find(params_.begin(), params_.end(), x);
      if (at != params_.end()) {
        const auto i = static_cast<std::size_t>(at - params_.begin());
        Real di(0);
        for (std::size_t j = 0; j < m1; ++j) {
          if (j == i) continue;
          di += Real(1) / (params_[i] - params_[j]);
          max_dl[j] = std::max(max_dl[j], Real(abs(weights_[j] / weights_[i] / (params_[i] - params_[j]))));
        }
        max_l[i] = std::max(max_l[i], Real(1));
        max_dl[i] = std::max(max_dl[i], Real(abs(di)));
        continue;
      }
      Real den(0), s(0);
      for (std::size_t j = 0; j < m1; ++j) {
        c[j] = weights_[j] / (x - params_[j]);
        den += c[j];
        s += Real(1) / (x - params_[j]);
      }
      for (std::size_t j = 0; j < m1; ++j) {
        const Real l = c[j] / den;
        max_l[j] = std::max(max_l[j], Real(abs(l)));
        max_dl[j] = std::max(max_dl[j], Real(abs(l * (s - Real(1) / (x - params_[j])))));
      }
    }
    // sec(n pi / (2 * 4n)) = sec(pi / 8) for degree n; the derivatives have degree n - 1, a smaller secant.
    const Real sec = Real(1) / cos(pi / Real(8));
    Real k0(0), k1(0), lambda0(0), lambda1(0);
    for (std::size_t j = 0; j < m1; ++j) {
      const Real pj = safe_norm(points_[j]);  // no overflow of the square past 1e154
      k0 += pj * max_l[j];
      k1 += pj * max_dl[j];
      lambda0 += max_l[j];
      lambda1 += max_dl[j];
    }
    const Real gamma = from_int<Real>(3 * n + 4) * epsilon<Real>();
    rounding_bound_[0] = gamma * sec * (k0 + sec * lambda0 * max_p);
    rounding_bound_[1] = gamma * sec * (k1 + sec * (lambda1 * max_p + lambda0 * max_dp));
  }

  void build_monomial() {
    using matrix = Eigen::Matrix<Real, Eigen::Dynamic, Eigen::Dynamic>;
    const auto m = static_cast<Eigen::Index>(params_.size());
    matrix v(m, m);
    matrix y(m, Dim);
    for (Eigen::Index j = 0; j < m; ++j) {
      Real p(1);
      for (Eigen::Index k = 0; k < m; ++k) {
        v(j, k) = p;
        p *= params_[static_cast<std::size_t>(j)];
      }
      for (int d = 0; d < Dim; ++d) y(j, d) = points_[static_cast<std::size_t>(j)][d];
    }
    const matrix a = Eigen::PartialPivLU<matrix>(v).solve(y);
    coeffs_.resize(params_.size());
    for (Eigen::Index k = 0; k < m; ++k)
      for (int d = 0; d < Dim; ++d) {
        if (!is_finite(a(k, d)))
          validate::fail("points: monomial coefficient a_" + std::to_string(k) + " = " + to_text(a(k, d)) +
                         " is not finite (the Vandermonde system is too ill-conditioned for this Real)");
        coeffs_[static_cast<std::size_t>(k)][d] = a(k, d);
      }
  }

  // Second barycentric formula; the node value itself at a node.
  point_type barycentric_value(const Real& u) const {
    point_type num = zero_point<Real, Dim>();
    Real den(0);
    for (std::size_t j = 0; j < params_.size(); ++j) {
      const Real diff = u - params_[j];
      if (diff == Real(0)) return points_[j];
      const Real cj = weights_[j] / diff;
      num += cj * points_[j];
      den += cj;
    }
    return point_type(num / den);
  }

  // Index of the node nearest to u (u in the domain).
  std::size_t nearest_node(const Real& u) const {
    const auto it = std::lower_bound(params_.begin(), params_.end(), u);
    auto i = static_cast<std::size_t>(it - params_.begin());
    if (i == params_.size()) return i - 1;
    if (i > 0 && (u - params_[i - 1]) < (params_[i] - u)) --i;
    return i;
  }

  // Derivatives by divided differences with a repeated argument. For fixed u, q_k(z) = P[z, u, ..., u]
  // (u repeated k times) is a polynomial of degree n - k in z, so the barycentric formula
  // reproduces it; q_k(u) = P[u, ..., u] (k + 1 times) = P^(k)(u) / k!, and
  //     q_0(u_j) = P_j,   q_k(u_j) = (q_{k-1}(u) - q_{k-1}(u_j)) / (u - u_j)
  // (Schneider & Werner, "Some new aspects of rational interpolation", Math. Comp. 47 (1986)).
  // The division by u - u_i is unstable when u is close to a node u_i, so at the nearest node i the
  // value q_k(u_i) is instead taken from the identity sum_j w_j q(u_j) = 0, valid for any polynomial q
  // of degree < n (it is the leading coefficient of q's interpolant):
  //     q_k(u_i) = -(1 / w_i) sum_{j != i} w_j q_k(u_j)          (k >= 1)
  // which at u = u_i is the differentiation-matrix formula of Berrut & Trefethen (sec. 9). Then
  //     q_k(u) = sum_j c_j q_k(u_j) / sum_j c_j,  c_j = w_j / (u - u_j)   (q_k(u) = q_k(u_i) at u = u_i).
  // Cost O(n m^2) for order m (the chains q_1(u_j) .. q_m(u_j) are recomputed per level so that
  // nothing of size n is stored); orders <= 15 use a stack buffer, higher orders allocate m + 1
  // points. Order > n is zero.
  // d[k] holds q_k(u) = P^(k)(u) / k!; d has order + 1 entries.
  point_type barycentric_derivative(const Real& u, int order, std::span<point_type> d) const {
    const std::size_t n1 = params_.size();
    const std::size_t i = nearest_node(u);
    const bool at_node = (u == params_[i]);
    d[0] = barycentric_value(u);
    const Real ci = at_node ? Real(0) : weights_[i] / (u - params_[i]);
    for (int k = 1; k <= order; ++k) {
      point_type sum_w = zero_point<Real, Dim>();  // sum_{j != i} w_j q_k(u_j)
      point_type sum_c = zero_point<Real, Dim>();  // sum_{j != i} c_j q_k(u_j)
      Real sum_cj(0);                              // sum_{j != i} c_j
      for (std::size_t j = 0; j < n1; ++j) {
        if (j == i) continue;
        const Real diff = u - params_[j];
        point_type q = points_[j];  // q_0(u_j)
        for (int l = 1; l <= k; ++l) q = (d[static_cast<std::size_t>(l - 1)] - q) / diff;
        sum_w += weights_[j] * q;
        const Real cj = weights_[j] / diff;
        sum_c += cj * q;
        sum_cj += cj;
      }
      const point_type qi = -sum_w / weights_[i];  // q_k(u_i)
      d[static_cast<std::size_t>(k)] = at_node ? qi : point_type((ci * qi + sum_c) / (ci + sum_cj));
    }
    Real factorial(1);
    for (int k = 2; k <= order; ++k) factorial *= Real(k);
    return point_type(factorial * d[static_cast<std::size_t>(order)]);
  }

  // sum_{k >= order} k!/(k - order)! a_k u^(k - order) by Horner.
  point_type horner(const Real& u, int order) const {
    const int n = degree();
    auto falling = [order](int k) {
      Real f(1);
      for (int j = 0; j < order; ++j) f *= Real(k - j);
      return f;
    };
    point_type r = falling(n) * coeffs_[static_cast<std::size_t>(n)];
    for (int k = n - 1; k >= order; --k) r = point_type(r * u + falling(k) * coeffs_[static_cast<std::size_t>(k)]);
    return r;
  }

  lagrange_algorithm algorithm_;
  point_list<Real, Dim> points_;
  std::vector<Real> params_;
  std::array<Real, 2> breaks_{};
  std::vector<Real> weights_;
  std::array<Real, 2> rounding_bound_{};
  point_list<Real, Dim> coeffs_;
};

}  // namespace curvebench
