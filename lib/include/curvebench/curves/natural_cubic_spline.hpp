// natural_cubic_spline: the C2 interpolating cubic spline on non-uniform knots (the draftsman's
// spline of seed 001), with natural (P'' = 0), clamped, not-a-knot and periodic end conditions.
// The knot slopes solve the C2 conditions (rows above spline_end), a tridiagonal system by Thomas
// elimination or, periodic, a cyclic one by Sherman-Morrison (detail/tridiagonal.hpp), in any
// Real; the spline is then a Hermite spline on the piecewise_cubic engine.
// Sources: seed 001; de Boor (1978), ch. IV (not-a-knot).
// Cost: O(n) construction, O(1) evaluation. Accuracy: interpolates to rounding; reproduces cubics
// (not-a-knot, clamped with exact slopes) and, with natural ends, linear functions; O(h^4) away
// from natural ends for smooth data.
// The slopes' error, which the engine's rounding_bound adds, is bounded a posteriori: the residual
// of the solved slopes in the exact system, |A m - r| <= |fl(A m - r)| + 8 eps (|A||m| + |r| + the
// right side on the divided differences' norms) (the entries and the right side are within 8
// roundings of exact, the residual's own evaluation within 4), and the rows are strictly
// diagonally dominant by delta_i = |b_i| - |a_i| - |c_i| > 0 (h_{i-1} + h_i inside, 1 at natural and
// clamped ends), so |m - m*|_inf <= max_i |residual_i| / delta_i per coordinate (Varah 1975).
// Not-a-knot end rows are not dominant: subtracting them from their neighbours' rows gives
// dominant rows (delta = h_1, h_{n-2}), and the end slopes follow from the end rows.
#pragma once

#include "curvebench/core/error.hpp"
#include "curvebench/core/point.hpp"
#include "curvebench/curves/detail/cubic_family.hpp"
#include "curvebench/curves/detail/tridiagonal.hpp"
#include "curvebench/curves/piecewise_cubic.hpp"

#include <algorithm>
#include <cstddef>
#include <span>
#include <string>
#include <utility>
#include <vector>

namespace curvebench {

// Algorithm: the slopes m_i = dP/du at the knots solve the C2 conditions, for interior knots
//     h_i m_{i-1} + 2 (h_{i-1} + h_i) m_i + h_{i-1} m_{i+1} = 3 (h_i D_{i-1} + h_{i-1} D_i),
// D_i = (P_{i+1} - P_i)/h_i (second derivatives of adjacent Hermite segments equal at u_i), plus
// one row per end: natural 2 m_0 + m_1 = 3 D_0; clamped m_0 = given; not-a-knot
// h_1 m_0 + (h_0 + h_1) m_1 = (h_1 (3 h_0 + 2 h_1) D_0 + h_0^2 D_1)/(h_0 + h_1) (the P''' condition
// with m_2 eliminated through the first interior row, de Boor, "A Practical Guide to Splines",
// ch. IV), mirrored at the other end; periodic: the interior row wraps around (m_n = m_0).
/// End conditions of the C2 cubic spline.
enum class spline_end { natural, clamped, not_a_knot, periodic };

[[nodiscard]] inline const char* to_string(spline_end e) {
  switch (e) {
    case spline_end::natural: return "natural";
    case spline_end::clamped: return "clamped";
    case spline_end::not_a_knot: return "not_a_knot";
    case spline_end::periodic: return "periodic";
  }
  return "unknown";
}

template <class Real, int Dim>
class natural_cubic_spline : public detail::cubic_family<Real, Dim> {
  using base = detail::cubic_family<Real, Dim>;

 public:
  using typename base::point_type;

  /// natural (>= 2 points), not_a_knot (>= 4 points), periodic (>= 3 points, values.front() ==
  /// values.back()). For clamped ends use the constructor with end slopes.
  natural_cubic_spline(const std::vector<Real>& knots, const point_list<Real, Dim>& values,
                       spline_end end = spline_end::natural)
      : natural_cubic_spline(build(knots, values, not_clamped(end), point_type::Zero(), point_type::Zero()), values,
                             end) {}

  /// Clamped ends: dP/du = start_slope at u_0 and end_slope at u_n (>= 2 points).
  natural_cubic_spline(const std::vector<Real>& knots, const point_list<Real, Dim>& values,
                       const point_type& start_slope, const point_type& end_slope)
      : natural_cubic_spline(build(knots, values, spline_end::clamped, start_slope, end_slope), values,
                             spline_end::clamped) {}

  [[nodiscard]] const point_list<Real, Dim>& values() const { return values_; }
  /// The solved slopes dP/du at the knots.
  [[nodiscard]] const point_list<Real, Dim>& slopes() const { return slopes_; }
  [[nodiscard]] spline_end end_condition() const { return end_; }

 private:
  struct built {
    typename base::engine_type engine;
    point_list<Real, Dim> slopes;
  };

  natural_cubic_spline(built b, const point_list<Real, Dim>& values, spline_end end)
      : base(std::move(b.engine)), values_(values), slopes_(std::move(b.slopes)), end_(end) {}

  static spline_end not_clamped(spline_end end) {
    if (end == spline_end::clamped)
      validate::fail("end = clamped needs the end slopes: use the constructor with start_slope and end_slope");
    return end;
  }

  static built build(const std::vector<Real>& knots, const point_list<Real, Dim>& v, spline_end end,
                     const point_type& start_slope, const point_type& end_slope) {
    const std::size_t minimum = end == spline_end::not_a_knot ? 4 : (end == spline_end::periodic ? 3 : 2);
    const char* why = end == spline_end::not_a_knot ? "not-a-knot ends need four points"
                      : end == spline_end::periodic ? "a periodic spline needs three points (first = last)"
                                                    : "a segment needs two points";
    validate::count_at_least("values", v.size(), minimum, why);
    validate::same_count("knots", knots.size(), "values", v.size());
    validate::increasing<Real>("knots", knots);
    validate::finite_points<Real, Dim>("values", v);
    validate::finite_point<Real, Dim>("start_slope", 0, start_slope);
    validate::finite_point<Real, Dim>("end_slope", 0, end_slope);
    const std::size_t n = v.size() - 1;  // segments
    if (end == spline_end::periodic) {
      for (int d = 0; d < Dim; ++d)
        if (v[n][d] != v[0][d])
          validate::fail("periodic spline: " + validate::indexed("values", n) + "[" + std::to_string(d) +
                         "] = " + to_text(v[n][d]) + " differs from values[0][" + std::to_string(d) +
                         "] = " + to_text(v[0][d]) + ": the last value must equal the first");
    }
    std::vector<Real> h(n);
    point_list<Real, Dim> dd(n);
    for (std::size_t i = 0; i < n; ++i) {
      h[i] = knots[i + 1] - knots[i];
      dd[i] = (v[i + 1] - v[i]) / h[i];
    }
    const Real two(2), three(3);
    point_list<Real, Dim> m(n + 1, point_type::Zero());
    // The right side's size per row (the divided differences' norms: a difference of data rounds
    // relative to itself), for the slope bound.
    std::vector<Real> dd_size(n);
    for (std::size_t i = 0; i < n; ++i) dd_size[i] = safe_norm(dd[i]);
    std::vector<Real> err(n + 1, Real(0));
    if (end == spline_end::periodic) {
      // Unknowns m_0..m_{n-1}; row i couples m_{i-1}, m_i, m_{i+1} cyclically.
      std::vector<Real> a(n), b(n), c(n);
      point_list<Real, Dim> r(n);
      for (std::size_t i = 0; i < n; ++i) {
        const std::size_t p = (i + n - 1) % n;
        a[i] = h[i];
        b[i] = two * (h[p] + h[i]);
        c[i] = h[p];
        r[i] = three * (h[i] * dd[p] + h[p] * dd[i]);
      }
      const point_list<Real, Dim> rhs = r;
      detail::solve_cyclic_tridiagonal<Real, point_type>(a, b, c, std::span<point_type>(r));
      for (std::size_t i = 0; i < n; ++i) m[i] = r[i];
      m[n] = m[0];
      Real worst(0);
      for (std::size_t i = 0; i < n; ++i) {
        const std::size_t p = (i + n - 1) % n, q = (i + 1) % n;
        const Real size = three * (h[i] * dd_size[p] + h[p] * dd_size[i]);
        worst = std::max(worst, residual_bound(a[i], b[i], c[i], m[p], m[i], m[q], rhs[i], size) / (h[p] + h[i]));
      }
      std::fill(err.begin(), err.end(), slope_bound(worst));
    } else {
      std::vector<Real> a(n + 1, Real(0)), b(n + 1), c(n + 1, Real(0));
      for (std::size_t i = 1; i < n; ++i) {
        a[i] = h[i];
        b[i] = two * (h[i - 1] + h[i]);
        c[i] = h[i - 1];
        m[i] = three * (h[i] * dd[i - 1] + h[i - 1] * dd[i]);
      }
      switch (end) {
        case spline_end::natural:
          b[0] = two;
          c[0] = Real(1);
          m[0] = three * dd[0];
          a[n] = Real(1);
          b[n] = two;
          m[n] = three * dd[n - 1];
          break;
        case spline_end::clamped:
          b[0] = Real(1);
          m[0] = start_slope;
          b[n] = Real(1);
          m[n] = end_slope;
          break;
        case spline_end::not_a_knot: {
          const Real s0 = h[0] + h[1];
          b[0] = h[1];
          c[0] = s0;
          m[0] = (h[1] * (three * h[0] + two * h[1]) * dd[0] + h[0] * h[0] * dd[1]) / s0;
          const Real s1 = h[n - 2] + h[n - 1];
          a[n] = s1;
          b[n] = h[n - 2];
          m[n] = (h[n - 1] * h[n - 1] * dd[n - 2] + h[n - 2] * (three * h[n - 1] + two * h[n - 2]) * dd[n - 1]) / s1;
          break;
        }
        case spline_end::periodic: break;
      }
      const point_list<Real, Dim> rhs = m;
      detail::solve_tridiagonal<Real, point_type>(a, b, c, std::span<point_type>(m));
      // Residual bounds per row; the end rows' right sides are data (clamped), one divided
      // difference (natural) or two (not-a-knot).
      std::vector<Real> res(n + 1);
      const point_type zero = point_type::Zero();
      for (std::size_t i = 1; i < n; ++i)
        res[i] = residual_bound(a[i], b[i], c[i], m[i - 1], m[i], m[i + 1], rhs[i],
                                three * (h[i] * dd_size[i - 1] + h[i - 1] * dd_size[i]));
      Real size0(0), size_n(0);
      if (end == spline_end::natural) {
        size0 = three * dd_size[0];
        size_n = three * dd_size[n - 1];
      } else if (end == spline_end::not_a_knot) {
        size0 = (h[1] * (three * h[0] + two * h[1]) * dd_size[0] + h[0] * h[0] * dd_size[1]) / (h[0] + h[1]);
        size_n =
            (h[n - 1] * h[n - 1] * dd_size[n - 2] + h[n - 2] * (three * h[n - 1] + two * h[n - 2]) * dd_size[n - 1]) /
            (h[n - 2] + h[n - 1]);
      }
      res[0] = residual_bound(Real(0), b[0], c[0], zero, m[0], m[1], rhs[0], size0);
      res[n] = residual_bound(a[n], b[n], Real(0), m[n - 1], m[n], zero, rhs[n], size_n);
      if (end == spline_end::not_a_knot) {
        // Rows 1 - row 0 and (n-1) - row n: dominant by h_1 and h_{n-2}; then the end rows.
        Real worst(0);
        for (std::size_t i = 1; i < n; ++i) {
          Real r = res[i], delta = h[i - 1] + h[i];
          if (i == 1) {
            r += res[0];
            delta = h[1];
          }
          if (i == n - 1) {  // n >= 3, so this is not row 1
            r += res[n];
            delta = h[n - 2];
          }
          worst = std::max(worst, r / delta);
        }
        const Real inner = slope_bound(worst);
        for (std::size_t i = 1; i < n; ++i) err[i] = inner;
        err[0] = slope_bound((res[0] + (h[0] + h[1]) * worst) / h[1]);
        err[n] = slope_bound((res[n] + (h[n - 2] + h[n - 1]) * worst) / h[n - 2]);
      } else {
        Real worst(0);
        for (std::size_t i = 0; i <= n; ++i) {
          // End rows: natural 2 m_0 + m_1 (delta 1), clamped m_0 alone (delta 1).
          const Real delta = i == 0 || i == n ? Real(1) : h[i - 1] + h[i];
          worst = std::max(worst, res[i] / delta);
        }
        std::fill(err.begin(), err.end(), slope_bound(worst));
      }
    }
    auto engine = base::engine_type::from_hermite(knots, v, m, m, err, err);
    return built{std::move(engine), std::move(m)};
  }

  // A bound on |A* m - r*| for one row (the header): the computed residual plus 8 eps of the row's
  // size, |a||m_prev| + |b||m| + |c||m_next| + |r| + the right side's size on norms.
  static Real residual_bound(const Real& a, const Real& b, const Real& c, const point_type& prev, const point_type& mid,
                             const point_type& next, const point_type& rhs, const Real& rhs_size) {
    using std::abs;
    const point_type res = a * prev + b * mid + c * next - rhs;
    const Real size = abs(a) * safe_norm(prev) + abs(b) * safe_norm(mid) + abs(c) * safe_norm(next) + safe_norm(rhs);
    return safe_norm(res) + Real(8) * epsilon<Real>() * (size + rhs_size);
  }

  // From max_i |residual_i| / delta_i (a bound per coordinate, each coordinate's residual being at
  // most the norm) to a bound on the slope vector's norm: sqrt(Dim) times, plus 1% for the rounding
  // of the margins delta_i themselves.
  static Real slope_bound(const Real& per_coordinate) {
    using std::sqrt;
    return sqrt(Real(Dim)) * per_coordinate * (Real(101) / Real(100));
  }

  point_list<Real, Dim> values_;
  point_list<Real, Dim> slopes_;
  spline_end end_;
};

}  // namespace curvebench
