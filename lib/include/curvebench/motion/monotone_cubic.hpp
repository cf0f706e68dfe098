// Scalar piecewise cubics for speed control: a shape-preserving (monotone) cubic Hermite
// interpolant y(x) with exact derivatives and an exact running integral.
// Given knots x_0 < ... < x_n and values y_i: a C1 piecewise cubic whose knot slopes keep it
// monotone wherever the data are, and constant between equal neighbours (no overshoot), so user
// (t, s) keys give a distance-time function that never runs backwards and speed keys a speed that
// never goes negative (distance_time.hpp). Slopes: the weighted harmonic mean of Fritsch & Butland
// (1984) inside, the three-point parabola's slope clamped at the ends (as SLATEC PCHIP), both inside
// Fritsch & Carlson's (1980) monotonicity box; see monotone_slopes for the rule and the proof.
// Cost: construction O(n); evaluation O(log n) plus a Horner cubic; no allocation after
// construction. Accuracy: O(h^3) for smooth monotone data away from extrema (O(h^2) near them
// where the limiter acts); derivatives and the running integral exact for the cubic (a few
// roundings).
#pragma once

#include "curvebench/core/curve.hpp"
#include "curvebench/core/detail/segment_lookup.hpp"
#include "curvebench/core/error.hpp"
#include "curvebench/core/real.hpp"

#include <algorithm>
#include <array>
#include <cstddef>
#include <span>
#include <string>
#include <vector>

namespace curvebench::motion {

/// Which piece a piecewise function uses exactly at a joint: `right` takes the piece that starts
/// there (the default; the last piece at the right end), `left` the piece that ends there (the
/// first piece at the left end). Away from joints both give the same value.
enum class side { left, right };

/// A scalar piecewise cubic y(x) = c0 + c1 d + c2 d^2 + c3 d^3, d = x - x_k on [x_k, x_{k+1}],
/// with exact derivatives of every order and the exact integral from x_0. The representation
/// behind monotone_cubic and the speed curves (a piecewise-linear function is the case c2 = c3 = 0).
template <class Real>
class scalar_piecewise_cubic {
 public:
  using real_type = Real;
  using coefficients = std::array<Real, 4>;

  scalar_piecewise_cubic() = default;

  /// `knots` strictly increasing and finite (>= 2 of them), one coefficient set per interval.
  scalar_piecewise_cubic(std::vector<Real> knots, std::vector<coefficients> pieces)
      : knots_(std::move(knots)), pieces_(std::move(pieces)) {
    validate::count_at_least("knots", knots_.size(), 2, "a piecewise cubic needs one interval");
    validate::increasing<Real>("knots", knots_);
    validate::same_count("pieces", pieces_.size(), "intervals (knots - 1)", knots_.size() - 1);
    for (std::size_t k = 0; k < pieces_.size(); ++k)
      for (const Real& c : pieces_[k]) validate::finite("pieces", c, k);
    // Running integral at each knot: sum of the exact integrals of the previous pieces.
    cumulative_.assign(knots_.size(), Real(0));
    for (std::size_t k = 0; k + 1 < knots_.size(); ++k)
      cumulative_[k + 1] = cumulative_[k] + piece_integral(k, knots_[k + 1] - knots_[k]);
  }

  [[nodiscard]] interval<Real> domain() const { return {knots_.front(), knots_.back()}; }
  [[nodiscard]] std::span<const Real> breakpoints() const { return knots_; }
  [[nodiscard]] std::span<const coefficients> pieces() const { return pieces_; }

  /// Index of the interval holding x (the piece chosen at a knot follows `s`). x must be in domain.
  [[nodiscard]] std::size_t locate(const Real& x, side s = side::right) const {
    // right: x_k <= x < x_{k+1}; left: x_k < x <= x_{k+1} (core/detail/segment_lookup.hpp).
    if (s == side::right) return curvebench::detail::segment_of<Real>(knots_, x);
    return curvebench::detail::segment_of_from_left<Real>(knots_, x);
  }

  /// d^order y / dx^order at x (order 0 is the value; orders > 3 are 0). Throws std::domain_error
  /// outside the knot range, invalid_input for a negative order.
  [[nodiscard]] Real derivative(const Real& x, int order, side s = side::right) const {
    validate::derivative_order(order);
    check_parameter(x, domain());
    const std::size_t k = locate(x, s);
    const coefficients& c = pieces_[k];
    const Real d = x - knots_[k];
    switch (order) {
      case 0: return c[0] + d * (c[1] + d * (c[2] + d * c[3]));
      case 1: return c[1] + d * (Real(2) * c[2] + Real(3) * c[3] * d);
      case 2: return Real(2) * c[2] + Real(6) * c[3] * d;
      case 3: return Real(6) * c[3];
      default: return Real(0);
    }
  }
  [[nodiscard]] Real operator()(const Real& x) const { return derivative(x, 0); }

  /// Exact integral of y from x_0 to x.
  [[nodiscard]] Real integral(const Real& x) const {
    check_parameter(x, domain());
    const std::size_t k = locate(x, side::right);
    return cumulative_[k] + piece_integral(k, x - knots_[k]);
  }
  /// Exact integral over the whole domain.
  [[nodiscard]] Real total_integral() const { return cumulative_.back(); }

 private:
  [[nodiscard]] Real piece_integral(std::size_t k, const Real& d) const {
    const coefficients& c = pieces_[k];
    return d * (c[0] + d * (c[1] / Real(2) + d * (c[2] / Real(3) + d * c[3] / Real(4))));
  }

  std::vector<Real> knots_;
  std::vector<coefficients> pieces_;
  std::vector<Real> cumulative_;
};

/// Coefficients of the cubic Hermite piece with values y0, y1 and slopes m0, m1 over a width h,
/// in powers of d = x - x_k: c2 = (3 secant - 2 m0 - m1) / h, c3 = (m0 + m1 - 2 secant) / h^2.
template <class Real>
[[nodiscard]] std::array<Real, 4> hermite_piece(const Real& y0, const Real& y1, const Real& m0, const Real& m1,
                                                const Real& h) {
  const Real secant = (y1 - y0) / h;
  return {y0, m0, (Real(3) * secant - Real(2) * m0 - m1) / h, (m0 + m1 - Real(2) * secant) / (h * h)};
}

// Algorithm (Fritsch & Carlson, "Monotone piecewise cubic interpolation", SIAM J. Numer. Anal. 17,
// 1980; slopes by the weighted harmonic mean of Fritsch & Butland, SIAM J. Sci. Stat. Comput. 5,
// 1984, the rule also used by SLATEC PCHIP). With h_k = x_{k+1} - x_k and secants
// d_k = (y_{k+1} - y_k) / h_k:
//   interior slope m_k = 0 when d_{k-1} d_k <= 0 (a local extremum or a flat neighbour), else
//   m_k = 3 (h_{k-1} + h_k) / ((2 h_k + h_{k-1}) / d_{k-1} + (h_k + 2 h_{k-1}) / d_k);
//   end slope m_0 = ((2 h_0 + h_1) d_0 - h_0 d_1) / (h_0 + h_1) (the slope of the parabola through
//   the first three points), set to 0 if its sign differs from d_0 and to 3 d_0 if the secants
//   change sign and |m_0| > 3 |d_0|; symmetrically at the last knot; m_0 = m_1 = d_0 for two knots.
// Why it is monotone (derivation, tested in tests/test_distance_time.cpp). On one interval with
// secant d != 0 write m_k = a d, m_{k+1} = b d and tau = (x - x_k) / h in [0, 1]. The Hermite
// cubic's derivative is
//   y'(tau) / d = a (1 - tau)(1 - 3 tau) + b tau (3 tau - 2) + 6 tau (1 - tau).
// For fixed tau this is affine in (a, b), so over the box [0, 3]^2 its minimum is at a corner:
//   (0, 0): 6 tau (1 - tau);  (3, 0): 3 (1 - tau)^2;  (0, 3): 3 tau^2;  (3, 3): 3 (1 - 2 tau)^2,
// all >= 0. Hence (a, b) in [0, 3]^2 is sufficient for monotonicity (Fritsch-Carlson's box).
// The harmonic-mean slope has the sign of d and is 1 / (w_1 / d_{k-1} + w_2 / d_k) with weights
// w_1 = (2 h_k + h_{k-1}) / (3 (h_{k-1} + h_k)) >= 1/3 and w_2 >= 1/3, so m_k <= 3 d_{k-1} and
// m_k <= 3 d_k: a, b in [0, 3]. The end rule keeps the sign of d_0 (else 0), and |m_0| <= 3 |d_0|:
// when d_1 has the sign of d_0, m_0 = d_0 + h_0 (d_0 - d_1) / (h_0 + h_1) is below 2 d_0 in
// magnitude; otherwise the clamp to 3 d_0 applies. When d = 0 both end slopes are 0 and the
// piece is constant. Consequently the interpolant also stays inside [min(y_k, y_{k+1}),
// max(y_k, y_{k+1})] on every interval, so non-negative data give a non-negative interpolant.
/// The shape-preserving knot slopes of Fritsch-Carlson / Fritsch-Butland (rule and proof above).
/// x strictly increasing (>= 2 knots), y of the same size; no validation here (callers validate
/// with their own argument names).
template <class Real>
[[nodiscard]] std::vector<Real> monotone_slopes(std::span<const Real> x, std::span<const Real> y) {
  const std::size_t n = x.size();
  std::vector<Real> h(n - 1), d(n - 1), m(n, Real(0));
  for (std::size_t k = 0; k + 1 < n; ++k) {
    h[k] = x[k + 1] - x[k];
    d[k] = (y[k + 1] - y[k]) / h[k];
  }
  if (n == 2) {
    m[0] = m[1] = d[0];
    return m;
  }
  const auto sign = [](const Real& v) { return v > Real(0) ? 1 : (v < Real(0) ? -1 : 0); };
  for (std::size_t k = 1; k + 1 < n; ++k) {
    if (sign(d[k - 1]) * sign(d[k]) <= 0) continue;  // extremum or flat neighbour: m_k = 0
    const Real w1 = Real(2) * h[k] + h[k - 1];
    const Real w2 = h[k] + Real(2) * h[k - 1];
    m[k] = Real(3) * (h[k - 1] + h[k]) / (w1 / d[k - 1] + w2 / d[k]);
  }
  // One-sided three-point end slope, limited to keep the end piece shape-preserving.
  const auto end_slope = [&](const Real& h0, const Real& h1, const Real& d0, const Real& d1) {
    Real s = ((Real(2) * h0 + h1) * d0 - h0 * d1) / (h0 + h1);
    using std::abs;
    if (sign(s) != sign(d0)) return Real(0);
    if (sign(d0) != sign(d1) && abs(s) > Real(3) * abs(d0)) return Real(3) * d0;
    return s;
  };
  m[0] = end_slope(h[0], h[1], d[0], d[1]);
  m[n - 1] = end_slope(h[n - 2], h[n - 3], d[n - 2], d[n - 3]);
  return m;
}

/// The monotone (shape-preserving) C1 cubic Hermite interpolant of (x_i, y_i).
template <class Real>
class monotone_cubic {
 public:
  using real_type = Real;

  /// x: >= 2 finite, strictly increasing knots; y: finite values, one per knot.
  /// Throws invalid_input naming the argument, index and value.
  monotone_cubic(std::span<const Real> x, std::span<const Real> y) {
    validate::count_at_least("x", x.size(), 2, "an interpolant needs two knots");
    validate::same_count("y", y.size(), "x", x.size());
    validate::increasing<Real>("x", x);
    for (std::size_t i = 0; i < y.size(); ++i) validate::finite("y", y[i], i);
    slopes_ = monotone_slopes<Real>(x, y);
    std::vector<std::array<Real, 4>> pieces(x.size() - 1);
    for (std::size_t k = 0; k + 1 < x.size(); ++k)
      pieces[k] = hermite_piece(y[k], y[k + 1], slopes_[k], slopes_[k + 1], x[k + 1] - x[k]);
    cubic_ = scalar_piecewise_cubic<Real>(std::vector<Real>(x.begin(), x.end()), std::move(pieces));
  }

  [[nodiscard]] interval<Real> domain() const { return cubic_.domain(); }
  [[nodiscard]] std::span<const Real> breakpoints() const { return cubic_.breakpoints(); }
  /// The knot slopes m_i chosen by the limiter.
  [[nodiscard]] std::span<const Real> slopes() const { return slopes_; }
  [[nodiscard]] Real operator()(const Real& x) const { return cubic_.derivative(x, 0); }
  [[nodiscard]] Real derivative(const Real& x, int order, side s = side::right) const {
    return cubic_.derivative(x, order, s);
  }
  /// Exact integral from the first knot to x.
  [[nodiscard]] Real integral(const Real& x) const { return cubic_.integral(x); }
  [[nodiscard]] const scalar_piecewise_cubic<Real>& pieces() const { return cubic_; }

 private:
  std::vector<Real> slopes_;
  scalar_piecewise_cubic<Real> cubic_;
};

}  // namespace curvebench::motion
