// Private mechanics of curvebench's B-spline and NURBS families (curves/bspline.hpp, curves/nurbs.hpp).
//
// `bspline_core<Real, V>` holds an order-m knot vector and the control data of the curve and of
// all its derivative curves (levels r = 0 .. m-1), with V any fixed-size Eigen column vector:
// point<Real, Dim> for a B-spline, Eigen::Matrix<Real, Dim + 1, 1> for the homogeneous control
// points (w P, w) of a NURBS. It implements span lookup, de Boor's algorithm, the Cox-de Boor
// basis sum and knot validation. Indexing and conventions are documented in curves/bspline.hpp.
#pragma once

#include "curvebench/core/detail/segment_lookup.hpp"
#include "curvebench/core/error.hpp"
#include "curvebench/core/real.hpp"

#include <Eigen/Core>

#include <algorithm>
#include <array>
#include <cstddef>
#include <limits>
#include <span>
#include <string>
#include <vector>

namespace curvebench {

/// Largest B-spline order (degree + 1) supported: de Boor's algorithm and the basis triangle run in
/// fixed stack arrays of this size, so evaluation never allocates.
inline constexpr int bspline_max_order = 16;

/// The two evaluation algorithms of a B-spline, kept side by side for comparison.
enum class bspline_evaluation {
  de_boor,    ///< de Boor's algorithm: m(m-1)/2 convex combinations of control points
  basis_sum,  ///< the m non-zero N_{i,m}(u) by the Cox-de Boor recursion, then sum N_i P_i
};

namespace detail {

/// a / b with the B-spline convention 0/0 = 0 (more generally x/0 = 0: a zero-length knot interval
/// carries a zero basis function, so the term it divides vanishes). Any finite value would do, since
/// the ratio always multiplies that zero function; what the guard prevents is 0/0 = NaN, which
/// would poison the sum (checked: without it tests/test_bspline.cpp fails on repeated knots).
template <class Real>
[[nodiscard]] Real bspline_ratio(const Real& a, const Real& b) {
  return b == Real(0) ? Real(0) : Real(a / b);
}

/// Validates an order, a control count and a knot vector (size count + order, finite,
/// non-decreasing, multiplicities <= order, non-empty domain [knots[order-1], knots[count]]).
template <class Real>
void bspline_validate(int order, std::size_t count, std::span<const Real> knots) {
  if (order < 1 || order > bspline_max_order)
    validate::fail("order = " + std::to_string(order) + ": must be in [1, " + std::to_string(bspline_max_order) +
                   "] (degree + 1)");
  const auto m = static_cast<std::size_t>(order);
  validate::count_at_least("control_points", count, m,
                           "order " + std::to_string(order) + " needs at least order points");
  if (knots.size() != count + m)
    validate::fail("knots: " + std::to_string(knots.size()) + " given, must be control_points + order = " +
                   std::to_string(count) + " + " + std::to_string(order) + " = " + std::to_string(count + m));
  validate::non_decreasing<Real>("knots", knots);
  std::size_t run_start = 0;
  for (std::size_t i = 1; i <= knots.size(); ++i) {
    if (i < knots.size() && knots[i] == knots[run_start]) continue;
    const std::size_t multiplicity = i - run_start;
    if (multiplicity > m)
      validate::fail("knots[" + std::to_string(run_start) + ".." + std::to_string(i - 1) +
                     "] = " + to_text(knots[run_start]) + ": multiplicity " + std::to_string(multiplicity) +
                     " exceeds order = " + std::to_string(order));
    run_start = i;
  }
  if (!(knots[m - 1] < knots[count]))
    validate::fail("knots: domain [knots[" + std::to_string(m - 1) + "], knots[" + std::to_string(count) + "]] = [" +
                   to_text(knots[m - 1]) + ", " + to_text(knots[count]) + "] is empty; knots[" + std::to_string(m - 1) +
                   "] < knots[" + std::to_string(count) + "] required");
}

/// Knots, control data of every derivative level, span lookup and the two evaluation algorithms.
/// Level r (0 <= r < m) is the r-th derivative as a B-spline of order m - r with control
/// Q^r_i (i = 0 .. n - 1 - r) on the knots t_{r} .. t_{n + m - 1 - r}:
///   Q^0 = P,  Q^r_i = (m - r) (Q^{r-1}_{i+1} - Q^{r-1}_i) / (t_{i+m} - t_{i+r})   (0/0 = 0).
template <class Real, class V>
class bspline_core {
 public:
  bspline_core() = default;

  bspline_core(int order, std::vector<Real> knots, std::vector<V> control) : order_(order), knots_(std::move(knots)) {
    bspline_validate<Real>(order, control.size(), knots_);
    n_ = control.size();
    const auto m = static_cast<std::size_t>(order_);
    // Derivative levels, stored one after the other.
    offsets_.resize(m + 1);
    offsets_[0] = 0;
    for (std::size_t r = 0; r < m; ++r) offsets_[r + 1] = offsets_[r] + (n_ - r);
    levels_.resize(offsets_[m]);
    std::copy(control.begin(), control.end(), levels_.begin());
    for (std::size_t r = 1; r < m; ++r) {
      const Real factor = Real(static_cast<long long>(m - r));
      for (std::size_t i = 0; i + r < n_; ++i) {
        const V diff = levels_[offsets_[r - 1] + i + 1] - levels_[offsets_[r - 1] + i];
        const Real den = knots_[i + m] - knots_[i + r];
        levels_[offsets_[r] + i] = den == Real(0) ? V(V::Zero()) : V(diff * Real(factor / den));
      }
    }
    // Last non-empty span inside the domain: used at the right end u = t_n (left limit there).
    last_span_ = n_ - 1;
    while (!(knots_[last_span_] < knots_[last_span_ + 1])) --last_span_;
    for (std::size_t i = m - 1; i <= n_; ++i)
      if (breaks_.empty() || knots_[i] != breaks_.back()) breaks_.push_back(knots_[i]);
  }

  [[nodiscard]] int order() const { return order_; }
  [[nodiscard]] std::size_t count() const { return n_; }
  [[nodiscard]] std::span<const Real> knots() const { return knots_; }
  [[nodiscard]] std::span<const Real> breakpoints() const { return breaks_; }
  [[nodiscard]] std::span<const V> control(std::size_t level = 0) const {
    return std::span<const V>(levels_).subspan(offsets_[level], n_ - level);
  }
  /// The factor c_r of de Boor's rounding on level r (0 or 1): its result is within c_r max_i |Q^r_i|
  /// of the exact level-r curve of the stored control data, per coordinate and in the Euclidean norm.
  /// Each of the p = m - 1 - r levels forms alpha = (u - s_a) / (s_b - s_a) with 3 roundings, which
  /// moves the combination by 3 u |d_j - d_{j-1}| <= 3 eps max |Q|, and the convex combination
  /// (1 - alpha) d_{j-1} + alpha d_j rounds 3 times (the argument of Farouki & Rajan 1987 for de
  /// Casteljau, bezier.hpp): (9p + 4) eps covers both with the factor of two of eps = 2u; level 1
  /// adds the 4 roundings of its control points (a difference, the knot difference, a quotient, a
  /// product), each relative to Q^1_i itself: 2 eps more.
  [[nodiscard]] Real de_boor_rounding_factor(int level) const {
    const long long p = order_ - 1 - level;
    if (p < 0) return Real(0);
    return from_int<Real>(9 * p + 4 + (level > 0 ? 2 : 0)) * epsilon<Real>();
  }

  /// The non-empty spans k (t_k < t_{k+1}, m - 1 <= k <= n - 1): each holds a polynomial piece.
  [[nodiscard]] std::vector<std::size_t> spans() const {
    std::vector<std::size_t> out;
    for (std::size_t k = static_cast<std::size_t>(order_) - 1; k < n_; ++k)
      if (knots_[k] < knots_[k + 1]) out.push_back(k);
    return out;
  }

  /// The control data of level r (0 or more, < m) that de Boor combines on span k.
  [[nodiscard]] std::span<const V> active_control(int level, std::size_t k) const {
    const auto r = static_cast<std::size_t>(level);
    const std::size_t p = static_cast<std::size_t>(order_) - 1 - r;
    return std::span<const V>(levels_).subspan(offsets_[r] + (k - r) - p, p + 1);
  }

  /// The smallest knot difference t_{i+m} - t_{i+1} dividing a level-1 control point active on span
  /// k (how much an error in the control points is amplified on level 1); +inf for m = 1.
  [[nodiscard]] Real level1_min_span(std::size_t k) const {
    const auto m = static_cast<std::size_t>(order_);
    Real best = std::numeric_limits<Real>::infinity();
    if (m < 2) return best;
    for (std::size_t i = k + 1 - m; i + 1 <= k; ++i) {  // level-1 indices (k - 1) - (m - 2) .. k - 1
      const Real den = knots_[i + m] - knots_[i + 1];
      if (den > Real(0) && den < best) best = den;
    }
    return best;
  }

  [[nodiscard]] Real lo() const { return knots_[static_cast<std::size_t>(order_) - 1]; }
  [[nodiscard]] Real hi() const { return knots_[n_]; }

  /// k with t_k <= u < t_{k+1}, m - 1 <= k <= n - 1 (half-open spans); at the right end u = t_n the
  /// last non-empty span, so the curve there is the limit from the left. u must lie in the domain.
  [[nodiscard]] std::size_t find_span(const Real& u) const {
    if (!(u < knots_[n_])) return last_span_;
    // The spans t_{m-1} .. t_n as breakpoints: u < t_n, so the segment rule needs no clamp here.
    const std::size_t first = static_cast<std::size_t>(order_) - 1;
    const std::span<const Real> spans = std::span<const Real>(knots_).subspan(first, n_ + 1 - first);
    return first + segment_of<Real>(spans, u);
  }

  /// The derivative of the given order at u (in the domain) by de Boor's algorithm on level r.
  [[nodiscard]] V de_boor(const Real& u, int derivative_order) const {
    if (derivative_order >= order_) return V::Zero();
    return de_boor_at(u, derivative_order, find_span(u));
  }

  [[nodiscard]] V de_boor_at(const Real& u, int derivative_order, std::size_t k) const {
    const auto r = static_cast<std::size_t>(derivative_order);
    const std::size_t p = static_cast<std::size_t>(order_) - 1 - r;  // degree at this level
    const V* q = levels_.data() + offsets_[r];
    const Real* s = knots_.data() + r;  // level-r knots s_j = t_{j+r}
    const std::size_t kk = k - r;       // span index among level-r knots
    std::array<V, bspline_max_order> d;
    for (std::size_t j = 0; j <= p; ++j) d[j] = q[j + kk - p];
    for (std::size_t lev = 1; lev <= p; ++lev)
      for (std::size_t j = p; j >= lev; --j) {
        // t_{j+1+k-lev} - t_{j+k-p} >= t_{k+1} - t_k > 0 on a non-empty span: no 0/0 here.
        const Real left = s[j + kk - p];
        const Real alpha = (u - left) / (s[j + 1 + kk - lev] - left);
        d[j] = (Real(1) - alpha) * d[j - 1] + alpha * d[j];
      }
    return d[p];
  }

  /// The non-zero basis functions N_{k-p+i, p+1}(u), i = 0..p, of level r (order m - r, p its
  /// degree) by the Cox-de Boor recursion in its triangular form, with 0/0 = 0; returns k.
  std::size_t nonzero_basis(const Real& u, int derivative_order, std::array<Real, bspline_max_order>& b) const {
    const std::size_t k = find_span(u);
    nonzero_basis_at(u, derivative_order, k, b);
    return k;
  }

  void nonzero_basis_at(const Real& u, int derivative_order, std::size_t k,
                        std::array<Real, bspline_max_order>& b) const {
    const auto r = static_cast<std::size_t>(derivative_order);
    const std::size_t mm = static_cast<std::size_t>(order_) - r;  // order at this level
    const Real* s = knots_.data() + r;
    const std::size_t kk = k - r;
    // b[j] holds N_{i, q}(u) with i = kk - mm + 1 + j, for q = 1 .. mm. Order 1: the indicator of
    // the span kk (half-open, right end handled by find_span); the others vanish on this span.
    for (std::size_t j = 0; j + 1 < mm; ++j) b[j] = Real(0);
    b[mm - 1] = Real(1);
    for (std::size_t q = 2; q <= mm; ++q)
      for (std::size_t j = 0; j < mm; ++j) {
        const std::size_t i = kk + 1 + j - mm;
        // N_{i,q} = (u - s_i)/(s_{i+q-1} - s_i) N_{i,q-1} + (s_{i+q} - u)/(s_{i+q} - s_{i+1}) N_{i+1,q-1};
        // b[j + 1] is still the order q-1 value (ascending j), N_{kk+1, q-1} = 0 on span kk.
        Real v = bspline_ratio<Real>(u - s[i], s[i + q - 1] - s[i]) * b[j];
        if (j + 1 < mm) v += bspline_ratio<Real>(s[i + q] - u, s[i + q] - s[i + 1]) * b[j + 1];
        b[j] = v;
      }
  }

  /// The derivative of the given order at u as sum_i N_{i, m-r}(u) Q^r_i (Cox-de Boor basis sum).
  [[nodiscard]] V basis_sum(const Real& u, int derivative_order) const {
    if (derivative_order >= order_) return V::Zero();
    std::array<Real, bspline_max_order> b;
    const std::size_t k = nonzero_basis(u, derivative_order, b);
    const auto r = static_cast<std::size_t>(derivative_order);
    const std::size_t mm = static_cast<std::size_t>(order_) - r;
    const V* q = levels_.data() + offsets_[r] + (k - r + 1 - mm);
    V sum = V::Zero();
    for (std::size_t j = 0; j < mm; ++j) sum += b[j] * q[j];
    return sum;
  }

 private:
  int order_ = 1;
  std::size_t n_ = 0;
  std::size_t last_span_ = 0;
  std::vector<Real> knots_;
  std::vector<std::size_t> offsets_;
  std::vector<V> levels_;
  std::vector<Real> breaks_;
};

}  // namespace detail
}  // namespace curvebench
