// piecewise_cubic: the shared evaluation engine of every cubic spline family (Hermite,
// cardinal/Catmull-Rom, Kochanek-Bartels, natural, cubic B-splines).
// Knots u_0 < ... < u_n; segment i on [u_i, u_{i+1}] with local t = (u - u_i) / h_i (evaluated as
// (u - u_i) fl(1 / h_i): no division per call, one u more, see local_t) is P_i(t) = T(t) · M_i · G_i,
// T = [1 t t^2 t^3] (basis/cubic_matrices.hpp); an interior knot belongs to the segment on its
// right, u_n to the last. Stored per segment: power coefficients M_i G_i, G_i and M_i, and Bezier
// points. Algorithms (cubic_algorithm, per call): power (Horner, ~3 fma per
// coordinate), matrix (T · M · G per call, the textbook form), bezier (de Casteljau, 6 lerps).
// Derivatives of order <= 3 exact by the chain rule h_i^-k; higher orders zero. Segment lookup O(1)
// for uniform knots (index corrected against the neighbours); for other knots O(1) expected: an
// index of 2n uniform buckets over the domain, built at construction by the same rounded map from u
// to its bucket as the lookup uses, holds per bucket the number of interior knots below it and its
// own (at most two compared without a branch, more searched): the segment is the same as a binary
// search over all knots at every u. Per segment one 64-byte-aligned record holds what an
// evaluation reads (the lookup's fields and the power coefficients). evaluate_batch and
// evaluate_sorted (non-decreasing parameters; the default power evaluation walks the segments and,
// where the parameters are dense, runs a branch-free loop per segment over its parameters, the
// coefficients hoisted; sparse ones go point by point; both bit-identical to single calls) never
// allocate. second_derivative_bound bounds |P''| over an interval of one segment (Newton inversion
// bounds its steps with it).
// Sources: seeds 000, 001, 002 (basis matrices, T · M · G); Farin (2002) for de Casteljau.
// Cost: O(1) per value after lookup. Accuracy: O(eps · scale), scale the coefficients' size (power)
// or the control items' (matrix, bezier); de Casteljau the most stable.
// rounding_bound(order), order 0 or 1 (core/curve.hpp), of the default power evaluation, the largest
// over the segments of: the power coefficients' error (|M| dG for the geometry's own error dG, which
// from_hermite takes from the family (its slopes') and adds the rounding of h · slope to, plus the
// rounding of the product M G: for float, double and long double measured against the compensated
// dot product Dot2 of Ogita, Rump & Oishi (2005), itself within u |a| + gamma_4^2 |M||G| of the
// exact coefficient, so the bound holds the rounding that happened (a few ulps of |a|) rather than
// the worst case 4 eps |M| |G|, which far from the origin is 1e3 times larger; other Reals take the
// worst case), Horner's gamma_6 sum |a_j| (order 1: gamma_5 over 1, 2, 3 times |a_1..3|, the
// factor 3 rounding once) (Higham 2002, 5.1), and t = fl(fl(u - u_i) fl(1 / h_i))'s 4 u (the
// difference, h_i's own rounding, the reciprocal, the product; no division per evaluation) times
// max |P_i'(t)| (order 1: |P_i''|); order 1 multiplies by fl(1 / h_i) with 3 u more (h rounded,
// 1 / h, the product). u = eps / 2 is the unit roundoff;
// norms are Euclidean over the coordinates (the componentwise bounds summed as vectors), and 1%
// covers gamma_k = k u / (1 - k u) and the second-order terms.
#pragma once

#include "curvebench/basis/cubic_matrices.hpp"
#include "curvebench/basis/detail/cubic_bernstein.hpp"
#include "curvebench/core/curve.hpp"
#include "curvebench/core/error.hpp"
#include "curvebench/core/point.hpp"
#include "curvebench/core/real.hpp"

#include <Eigen/Core>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <span>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

// The single-evaluation hot path (operator(), the lookup, Horner) is forced inline: left to its
// heuristics GCC calls each of them out of line, which costs more than the evaluation itself.
#if defined(__GNUC__)
#define CURVEBENCH_PC_HOT [[gnu::always_inline]] inline
#else
#define CURVEBENCH_PC_HOT inline
#endif

namespace curvebench {

/// How piecewise_cubic evaluates a segment (see the header comment).
enum class cubic_algorithm { power, matrix, bezier };

/// Text name of an algorithm (benchmark and report labels).
[[nodiscard]] inline const char* to_string(cubic_algorithm a) {
  switch (a) {
    case cubic_algorithm::power: return "power";
    case cubic_algorithm::matrix: return "matrix";
    case cubic_algorithm::bezier: return "bezier";
  }
  return "unknown";
}

/// n + 1 uniform knots u0, u0 + h, ..., u0 + n h (each computed as u0 + i h, no accumulation).
template <class Real>
[[nodiscard]] std::vector<Real> uniform_knots(std::size_t segments, const Real& u0 = Real(0), const Real& h = Real(1)) {
  validate::finite("u0", u0);
  validate::positive("h", h);
  std::vector<Real> k(segments + 1);
  for (std::size_t i = 0; i <= segments; ++i) k[i] = u0 + Real(static_cast<long long>(i)) * h;
  return k;
}

template <class Real, int Dim>
class piecewise_cubic {
  // Per segment, what the lookup and t need, in one place: the knots to check u against (-inf,
  // +inf at the ends), u_i and fl(1 / h_i).
  struct lookup_record {
    Real left, right, knot, inv_h;
  };

 public:
  using real_type = Real;
  using point_type = point<Real, Dim>;
  static constexpr int dimension = Dim;
  /// One segment's geometry: row r is the r-th control item (a point or a tangent).
  using geometry_type = Eigen::Matrix<Real, 4, Dim>;
  using matrix_type = basis::matrix4<Real>;

  /// knots: n + 1 strictly increasing finite values; geometries and bases: n each (segment i on
  /// [knots[i], knots[i+1]] is T(t) · bases[i] · geometries[i]).
  piecewise_cubic(std::vector<Real> knots, std::vector<geometry_type> geometries, std::vector<matrix_type> bases)
      : knots_(std::move(knots)), geometry_(std::move(geometries)), basis_(std::move(bases)) {
    validate::count_at_least("knots", knots_.size(), 2, "one segment needs two knots");
    validate::same_count("geometries", geometry_.size(), "segments (knots - 1)", knots_.size() - 1);
    validate::same_count("bases", basis_.size(), "segments (knots - 1)", knots_.size() - 1);
    build();
  }

  /// The same basis matrix for every segment.
  piecewise_cubic(std::vector<Real> knots, std::vector<geometry_type> geometries, const matrix_type& basis)
      : knots_(std::move(knots)), geometry_(std::move(geometries)), basis_(geometry_.size(), basis) {
    validate::count_at_least("knots", knots_.size(), 2, "one segment needs two knots");
    validate::same_count("geometries", geometry_.size(), "segments (knots - 1)", knots_.size() - 1);
    build();
  }

  /// Power coefficients given directly: coefficients[i] rows are a0..a3 of segment i (basis = identity).
  [[nodiscard]] static piecewise_cubic from_power(std::vector<Real> knots, std::vector<geometry_type> coefficients) {
    return piecewise_cubic(std::move(knots), std::move(coefficients), matrix_type::Identity());
  }

  /// Cubic Hermite segments from values and slopes per unit of the GLOBAL parameter u:
  /// segment i interpolates values[i] -> values[i+1] with dP/du = outgoing[i] at u_i and
  /// dP/du = incoming[i+1] at u_{i+1}. Its Hermite geometry is [P_i, P_{i+1}, h_i out_i, h_i in_{i+1}]
  /// (local tangents dP/dt = h dP/du). All three lists have n + 1 entries; incoming[0] and
  /// outgoing[n] do not enter any segment (they are still validated). Equal lists give a C1 curve.
  /// incoming_error / outgoing_error (n + 1 entries each, or empty for slopes that are exact data):
  /// bounds on |slope - exact slope| of the family's computed slopes, which rounding_bound adds.
  [[nodiscard]] static piecewise_cubic from_hermite(std::vector<Real> knots, std::span<const point_type> values,
                                                    std::span<const point_type> incoming,
                                                    std::span<const point_type> outgoing,
                                                    std::span<const Real> incoming_error = {},
                                                    std::span<const Real> outgoing_error = {}) {
    validate::count_at_least("knots", knots.size(), 2, "one segment needs two knots");
    validate::same_count("values", values.size(), "knots", knots.size());
    validate::same_count("incoming slopes", incoming.size(), "knots", knots.size());
    validate::same_count("outgoing slopes", outgoing.size(), "knots", knots.size());
    validate::increasing<Real>("knots", knots);
    validate::finite_points<Real, Dim>("values", values);
    validate::finite_points<Real, Dim>("incoming slopes", incoming);
    validate::finite_points<Real, Dim>("outgoing slopes", outgoing);
    if (!incoming_error.empty())
      validate::same_count("incoming slope errors", incoming_error.size(), "knots", knots.size());
    if (!outgoing_error.empty())
      validate::same_count("outgoing slope errors", outgoing_error.size(), "knots", knots.size());
    const std::size_t n = knots.size() - 1;
    std::vector<geometry_type> g(n);
    std::vector<std::array<Real, 4>> dg(n);
    const Real two_eps = Real(2) * epsilon<Real>();
    for (std::size_t i = 0; i < n; ++i) {
      const Real h = knots[i + 1] - knots[i];
      g[i].row(0) = values[i].transpose();
      g[i].row(1) = values[i + 1].transpose();
      g[i].row(2) = (h * outgoing[i]).transpose();
      g[i].row(3) = (h * incoming[i + 1]).transpose();
      // h = fl(u_{i+1} - u_i) and the product round once each; the slopes bring their own error.
      const Real out_err = outgoing_error.empty() ? Real(0) : outgoing_error[i];
      const Real in_err = incoming_error.empty() ? Real(0) : incoming_error[i + 1];
      dg[i] = {Real(0), Real(0), h * (out_err + two_eps * safe_norm(outgoing[i])),
               h * (in_err + two_eps * safe_norm(incoming[i + 1]))};
    }
    piecewise_cubic c(std::move(knots), std::move(g), basis::hermite_matrix<Real>());
    c.build_rounding_bounds(dg);
    return c;
  }

  /// Upper bound on the rounding of this curve's power evaluation of P (order 0) or P' (order 1)
  /// over the domain (see the header); +inf for other orders.
  [[nodiscard]] Real rounding_bound(int order) const {
    if (order < 0 || order > 1) return std::numeric_limits<Real>::infinity();
    return rounding_bound_[static_cast<std::size_t>(order)];
  }

  /// An upper bound of |P''(u)| (Euclidean norm) over u in [a, b] (a <= b, both in the domain) when
  /// [a, b] lies in one segment's closed interval [u_i, u_{i+1}]: the speed |P'| is then Lipschitz
  /// with it on [a, b] (core/curve.hpp). P''(u) = (2 a_2 + 6 a_3 t) / h_i^2 is affine in t, so its
  /// norm is largest at an end: the larger of the two, each coordinate raised by 8 u (2 |a_2| +
  /// 6 |a_3|) for the rounding of t (4 u, local_t) and of the sum (3 u), the result by 16 eps for
  /// the norm, the scaling by h_i^-2 and h_i's own rounding. +inf when [a, b] crosses a knot, where
  /// P' may jump. Throws std::domain_error for a or b outside the domain.
  [[nodiscard]] CURVEBENCH_PC_HOT Real second_derivative_bound(const Real& a, const Real& b) const {
    if (!(lo_ <= a && a <= hi_)) check_parameter(a, domain(), "a");
    if (!(lo_ <= b && b <= hi_)) check_parameter(b, domain(), "b");
    const std::size_t i = locate(a);
    const segment_record& r = seg_[i];
    if (!(a <= b && b <= r.lookup.right)) return std::numeric_limits<Real>::infinity();  // right: +inf at the end
    using std::abs;
    using std::max;
    const std::array<point_type, 4>& c = r.power;
    const Real slack = Real(4) * epsilon<Real>();  // 8 u
    const Real ta = local_t(i, r.lookup, a), tb = local_t(i, r.lookup, b);
    point_type wa, wb;
    for (int d = 0; d < Dim; ++d) {
      const Real two_a2 = Real(2) * c[2][d], six_a3 = Real(6) * c[3][d];
      const Real room = slack * (abs(two_a2) + abs(six_a3));
      wa[d] = abs(two_a2 + six_a3 * ta) + room;
      wb[d] = abs(two_a2 + six_a3 * tb) + room;
    }
    const Real m = max(safe_norm(wa), safe_norm(wb)) * (Real(1) + Real(16) * epsilon<Real>());
    return per_h_i(per_h_i(m, i, r.lookup), i, r.lookup);
  }

  // ---- the curve concept ----
  [[nodiscard]] interval<Real> domain() const { return {knots_.front(), knots_.back()}; }
  [[nodiscard]] std::span<const Real> breakpoints() const { return knots_; }
  [[nodiscard]] CURVEBENCH_PC_HOT point_type operator()(const Real& u) const {
    // The hot path: the domain check inline (NaN fails it), the lookup, t and Horner.
    if (!(lo_ <= u && u <= hi_)) out_of_domain(u);
    const std::size_t i = locate(u);
    const lookup_record& r = seg_[i].lookup;
    return horner(seg_[i].power, local_t(i, r, u));
  }
  [[nodiscard]] CURVEBENCH_PC_HOT point_type derivative(const Real& u, int order) const {
    // P'(u), the speed of every arc-length method, inline like operator(): the same operations as
    // the general path (t by local_t, the power-form derivative, the chain rule's
    // fl(1 / h)), so the same rounding bound; where FMA is enabled (-march=native) the compiler
    // may contract them differently in the two contexts, a difference of an ulp or so.
    if (order == 1) {
      if (!(lo_ <= u && u <= hi_)) out_of_domain(u);
      const std::size_t i = locate(u);
      const lookup_record& r = seg_[i].lookup;
      const Real t = local_t(i, r, u);
      const std::array<point_type, 4>& a = seg_[i].power;
      // The chain rule's factor fl(1 / h_i), computed once: no division per call (the divider,
      // shared with the speed's square root, is what limits the arc-length methods).
      const point_type dt = a[1] + t * (Real(2) * a[2] + t * (Real(3) * a[3]));
      return per_h_i(dt, i, r);
    }
    return evaluate(u, order, cubic_algorithm::power);
  }

  /// d^order P / du^order at u by the chosen algorithm. Throws std::domain_error outside the domain,
  /// invalid_input for a negative order.
  [[nodiscard]] CURVEBENCH_PC_HOT point_type evaluate(const Real& u, int order, cubic_algorithm algorithm) const {
    if (order == 0 && algorithm == cubic_algorithm::power) return (*this)(u);
    return evaluate_general(u, order, algorithm);
  }

 private:
  [[nodiscard]] point_type evaluate_general(const Real& u, int order, cubic_algorithm algorithm) const {
    validate::derivative_order(order);
    check_parameter(u, domain());
    const std::size_t i = locate(u);
    return eval_segment(i, local_t(i, seg_[i].lookup, u), order, algorithm);
  }

 public:
  /// d^order P / du^order of segment i at its local parameter t in [0, 1] (t = 1 gives the left
  /// limit at knot i + 1, t = 0 the right limit at knot i: what continuity checks need).
  /// Throws std::out_of_range for i >= segment_count(), std::domain_error for t outside [0, 1].
  [[nodiscard]] point_type evaluate_segment(std::size_t i, const Real& t, int order,
                                            cubic_algorithm algorithm = cubic_algorithm::power) const {
    validate::derivative_order(order);
    if (i >= segment_count())
      throw std::out_of_range("segment " + std::to_string(i) + " does not exist (" + std::to_string(segment_count()) +
                              " segments)");
    check_parameter(t, interval<Real>{Real(0), Real(1)});
    return eval_segment(i, t, order, algorithm);
  }

  /// out[k] = d^order P / du^order (us[k]) for any order of parameters (each looked up on its own).
  /// No allocation. Throws invalid_input when the spans differ in size, std::domain_error for a
  /// parameter outside the domain (out[0..k) is then already written).
  void evaluate_batch(std::span<const Real> us, std::span<point_type> out, int order = 0,
                      cubic_algorithm algorithm = cubic_algorithm::power) const {
    validate::same_count("out", out.size(), "us", us.size());
    validate::derivative_order(order);
    const interval<Real> d = domain();
    for (std::size_t k = 0; k < us.size(); ++k) {
      check_parameter(us[k], d, "us", k);
      const std::size_t i = locate(us[k]);
      out[k] = eval_segment(i, local_t(i, seg_[i].lookup, us[k]), order, algorithm);
    }
  }

  /// As evaluate_batch for non-decreasing parameters: walks the segments forward, hoisting each
  /// segment's data. Every parameter is checked (out[0..k) is already written when us[k] throws):
  /// std::domain_error for one above the domain or NaN, invalid_input for us[k] < us[k-1]. Two
  /// comparisons per parameter: us[0] >= u0 and non-decreasing imply the lower bound for the rest.
  void evaluate_sorted(std::span<const Real> us, std::span<point_type> out, int order = 0,
                       cubic_algorithm algorithm = cubic_algorithm::power) const {
    validate::same_count("out", out.size(), "us", us.size());
    validate::derivative_order(order);
    if (us.empty()) return;
    const interval<Real> d = domain();
    check_parameter(us.front(), d, "us", 0);
    if (algorithm == cubic_algorithm::power && order == 0 && sorted_in_domain(us)) {
      sorted_power(us, out);
      return;
    }
    // Checked walk: the other algorithms and orders, and input that fails a check (which then
    // throws at its first bad parameter with out[0..k) written, as documented).
    std::size_t i = locate(us.front());
    const std::size_t last = segment_count() - 1;
    for (std::size_t k = 0; k < us.size(); ++k) {
      const Real& u = us[k];
      // Written so that NaN fails it (every comparison with NaN is false).
      if (!(u <= d.hi)) check_parameter(u, d, "us", k);
      if (k > 0 && u < us[k - 1])
        validate::fail("us must be non-decreasing for evaluate_sorted: " + validate::indexed("us", k) + " = " +
                       to_text(u) + " < " + validate::indexed("us", k - 1) + " = " + to_text(us[k - 1]));
      while (i < last && !(u < knots_[i + 1])) ++i;
      out[k] = eval_segment(i, local_t(i, seg_[i].lookup, u), order, algorithm);
    }
  }

  // ---- structure ----
  [[nodiscard]] std::size_t segment_count() const { return h_.size(); }
  [[nodiscard]] std::span<const Real> knots() const { return knots_; }
  /// True when the knots were detected uniform (segment lookup is then O(1)).
  [[nodiscard]] bool uniform() const { return uniform_; }
  /// The segment holding u (u in the domain; an interior knot u_i maps to segment i).
  [[nodiscard]] std::size_t segment_index(const Real& u) const {
    check_parameter(u, domain());
    return locate(u);
  }
  /// Power coefficients a0..a3 of segment i in the local parameter t.
  [[nodiscard]] const std::array<point_type, 4>& power_coefficients(std::size_t i) const { return seg_.at(i).power; }
  /// Bezier control points of segment i (same curve, local parameter t).
  [[nodiscard]] const std::array<point_type, 4>& bezier_points(std::size_t i) const { return bezier_.at(i); }
  [[nodiscard]] const geometry_type& geometry(std::size_t i) const { return geometry_.at(i); }
  [[nodiscard]] const matrix_type& basis_matrix(std::size_t i) const { return basis_.at(i); }

 private:
  void build() {
    validate::increasing<Real>("knots", knots_);
    const std::size_t n = knots_.size() - 1;
    for (std::size_t i = 0; i < n; ++i) {
      for (int r = 0; r < 4; ++r)
        for (int d = 0; d < Dim; ++d)
          if (!is_finite(geometry_[i](r, d)))
            validate::fail(validate::indexed("geometries", i) + "(" + std::to_string(r) + ", " + std::to_string(d) +
                           ") = " + to_text(geometry_[i](r, d)) + ": geometry must be finite");
      for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c)
          if (!is_finite(basis_[i](r, c)))
            validate::fail(validate::indexed("bases", i) + "(" + std::to_string(r) + ", " + std::to_string(c) +
                           ") = " + to_text(basis_[i](r, c)) + ": basis matrix must be finite");
    }
    h_.resize(n);
    inv_h_.resize(n);
    seg_.resize(n);
    bezier_.resize(n);
    // 3 M_bezier^{-1}: Bezier points from power coefficients are b = M_bezier^{-1} a; the integer
    // form keeps C = M_bezier^{-1} M exact for integer M up to one final division by 3.
    static constexpr int bezier_inverse3[4][4] = {{3, 0, 0, 0}, {3, 1, 0, 0}, {3, 2, 1, 0}, {3, 3, 3, 3}};
    const matrix_type binv3 = basis::detail::integer_matrix<Real>(bezier_inverse3, Real(1));
    for (std::size_t i = 0; i < n; ++i) {
      h_[i] = knots_[i + 1] - knots_[i];
      inv_h_[i] = Real(1) / h_[i];
      const geometry_type a = basis_[i] * geometry_[i];
      const matrix_type c = (binv3 * basis_[i]) / Real(3);
      const geometry_type b = c * geometry_[i];
      for (int r = 0; r < 4; ++r) {
        seg_[i].power[static_cast<std::size_t>(r)] = a.row(r).transpose();
        bezier_[i][static_cast<std::size_t>(r)] = b.row(r).transpose();
      }
    }
    // Uniform detection: every knot within a few ulps of u0 + i h. The lookup corrects the guess
    // against the actual knots, so this tolerance only decides speed, never correctness.
    using std::abs;
    using std::max;
    const Real hbar = (knots_.back() - knots_.front()) / Real(static_cast<long long>(n));
    const Real tol = Real(16) * epsilon<Real>() * max(abs(knots_.front()), abs(knots_.back()));
    uniform_ = true;
    for (std::size_t i = 0; i <= n && uniform_; ++i)
      if (abs(knots_[i] - (knots_.front() + Real(static_cast<long long>(i)) * hbar)) > tol) uniform_ = false;
    inv_hbar_ = Real(1) / hbar;
    lo_ = knots_.front();
    hi_ = knots_.back();
    last_ = n - 1;
    last_real_ = Real(static_cast<long long>(last_));
    for (std::size_t i = 0; i < n; ++i)
      seg_[i].lookup = {i == 0 ? -std::numeric_limits<Real>::infinity() : knots_[i],
                        i == last_ ? std::numeric_limits<Real>::infinity() : knots_[i + 1], knots_[i], inv_h_[i]};
    // t by the reciprocal needs fl(1 / h_i) in the normal range for every segment, where it is
    // within u of 1 / h_i (see local_t); otherwise every segment divides.
    reciprocal_ = true;
    for (std::size_t i = 0; i < n; ++i)
      if (!(is_finite(inv_h_[i]) && abs(inv_h_[i]) >= std::numeric_limits<Real>::min())) reciprocal_ = false;
    build_buckets();
    build_rounding_bounds(std::vector<std::array<Real, 4>>(n, std::array<Real, 4>{}));
  }

  // The bounds of the header; dg[i][r]: a bound on the error of geometry row r of segment i.
  void build_rounding_bounds(const std::vector<std::array<Real, 4>>& dg) {
    using std::abs;
    using std::max;
    const Real eps = epsilon<Real>();
    Real b0(0), b1(0);
    for (std::size_t i = 0; i < h_.size(); ++i) {
      std::array<Real, 4> g{}, a{}, da{};
      for (int r = 0; r < 4; ++r) {
        g[static_cast<std::size_t>(r)] = safe_norm(point_type(geometry_[i].row(r).transpose()));
        a[static_cast<std::size_t>(r)] = safe_norm(seg_[i].power[static_cast<std::size_t>(r)]);
      }
      for (int r = 0; r < 4; ++r) {
        Real e(0);
        for (int k = 0; k < 4; ++k) e += abs(basis_[i](r, k)) * dg[i][static_cast<std::size_t>(k)];
        da[static_cast<std::size_t>(r)] = e + product_rounding(i, r, g);
      }
      const Real sum_a = a[0] + a[1] + a[2] + a[3];
      const Real slope = a[1] + Real(2) * a[2] + Real(3) * a[3];  // max |P_i'(t)| on [0, 1], and sum |b_j|
      const Real curvature = Real(2) * a[2] + Real(6) * a[3];     // max |P_i''(t)|
      const Real u = eps / Real(2);
      const Real e0 = da[0] + da[1] + da[2] + da[3] + Real(6) * u * sum_a + Real(4) * u * slope;
      const Real e1 = (da[1] + Real(2) * da[2] + Real(3) * da[3] + Real(5) * u * slope + Real(4) * u * curvature +
                       Real(3) * u * slope) /
                      h_[i];
      b0 = max(b0, e0);
      b1 = max(b1, e1);
    }
    const Real margin = Real(101) / Real(100);
    rounding_bound_ = {b0 * margin, b1 * margin};
  }

  // A bound on |fl(M G)_r - (M G)_r| (Euclidean over the coordinates) for segment i's power row r;
  // g holds the geometry rows' norms (the worst case's sizes).
  [[nodiscard]] Real product_rounding(std::size_t i, int r, const std::array<Real, 4>& g) const {
    using std::abs;
    const Real eps = epsilon<Real>();
    Real worst_case(0);
    for (int k = 0; k < 4; ++k) worst_case += abs(basis_[i](r, k)) * g[static_cast<std::size_t>(k)];
    worst_case *= Real(4) * eps;
    if constexpr (std::is_floating_point_v<Real>) {
      // Dot2 per coordinate: (p, s) accumulates the products' exact high parts and their errors
      // (TwoProduct by fma, TwoSum by Knuth: both exact in round-to-nearest, whatever the contraction
      // of the surrounding code); res is within u |res| + gamma_4^2 sum |M||G| of the exact value.
      const Real u = eps / Real(2);
      point_type e;
      for (int d = 0; d < Dim; ++d) {
        Real p(0), sum(0), size(0);
        for (int k = 0; k < 4; ++k) {
          const Real m = basis_[i](r, k), x = geometry_[i](k, d);
          const Real h = m * x;
          const Real lo = std::fma(m, x, -h);
          const Real t = p + h;
          const Real z = t - p;
          const Real q = (p - (t - z)) + (h - z);
          p = t;
          sum += q + lo;
          size += abs(h);
        }
        const Real res = p + sum;
        const Real gamma4 = Real(4) * u / (Real(1) - Real(4) * u);
        // Products below the normal range are not error-free: 4 units of the smallest subnormal each.
        e[d] = abs(seg_[i].power[static_cast<std::size_t>(r)][d] - res) * (Real(1) + eps) + u * abs(res) +
               gamma4 * gamma4 * size + Real(8) * std::numeric_limits<Real>::denorm_min();
        if (!is_finite(e[d])) return worst_case;
      }
      const Real measured = safe_norm(e) * (Real(1) + eps);
      return measured < worst_case ? measured : worst_case;
    } else {
      return worst_case;
    }
  }

  // The throwing path of operator(), kept out of line so that the hot path stays small enough to inline.
#if defined(__GNUC__)
  [[gnu::noinline, gnu::cold]]
#endif
  [[noreturn]] void
  out_of_domain(Real u) const {
    check_parameter(u, domain());
    throw std::logic_error("piecewise_cubic: out_of_domain called for a parameter inside the domain");
  }

  // Whether the parameters (us[0] already checked against the domain) are non-decreasing and at
  // most u_n (NaN fails both): one pass without early exit, which the compiler vectorises.
  [[nodiscard]] bool sorted_in_domain(std::span<const Real> us) const {
    const Real hi = knots_.back();
    bool ok = us.back() <= hi;
    for (std::size_t k = 1; k < us.size(); ++k) ok &= us[k - 1] <= us[k];
    return ok;
  }

  // evaluate_sorted's power path for checked input. Dense parameters (at least 4 per segment they
  // span, on average) go by runs: per segment, its run of parameters, found 8 at a time (one
  // comparison per 8, since the parameters are sorted), then one loop over the run with the
  // segment's coefficients hoisted, which the compiler vectorises. Sparse ones go point by point,
  // stepping the segment forward over the knots: a run of one or two parameters costs more than
  // it saves. The arithmetic is horner()'s, in the same order, so each value is bit-identical to
  // operator().
  void sorted_power(std::span<const Real> us, std::span<point_type> out) const {
    const std::size_t count = us.size(), last = segment_count() - 1;
    std::size_t i = locate(us.front());
    const std::size_t spanned = locate(us.back()) - i + 1;
    if (count < 4 * spanned) {
      for (std::size_t k = 0; k < count; ++k) {
        // Stepped over the dense knots (a cache line holds 8 segments' in double), not over the
        // segment records (two lines each).
        while (i < last && !(us[k] < knots_[i + 1])) ++i;
        out[k] = horner(seg_[i].power, local_t(i, seg_[i].lookup, us[k]));
      }
      return;
    }
    std::size_t k = 0;
    while (k < count) {
      const std::size_t e = i < last ? run_end(us, k, knots_[i + 1]) : count;
      run_power(i, us.data() + k, out.data() + k, e - k);
      k = e;
      if (k < count)
        while (i < last && !(us[k] < knots_[i + 1])) ++i;
    }
  }

  // The first index e >= k with us[e] >= right (or the size): the first 8 one by one (most runs of
  // sparse parameters end there), then whole blocks of 8 by their last parameter, then one by one.
  [[nodiscard]] static std::size_t run_end(std::span<const Real> us, std::size_t k, const Real& right) {
    constexpr std::size_t block = 8;
    const std::size_t count = us.size(), first = std::min(count, k + block);
    std::size_t e = k;
    while (e < first && us[e] < right) ++e;
    if (e < k + block) return e;
    while (e + block <= count && us[e + block - 1] < right) e += block;
    while (e < count && us[e] < right) ++e;
    return e;
  }

  void run_power(std::size_t i, const Real* us, point_type* out, std::size_t m) const {
    if (reciprocal_)
      run_power_kernel<true>(i, us, out, m);
    else
      run_power_kernel<false>(i, us, out, m);
  }

  // One segment's run: t as local_t computes it (the branch hoisted), Horner per coordinate.
  template <bool Reciprocal>
  void run_power_kernel(std::size_t i, const Real* us, point_type* out, std::size_t m) const {
    const Real ui = knots_[i], scale = Reciprocal ? inv_h_[i] : h_[i];
    std::array<std::array<Real, 4>, Dim> c;
    for (int d = 0; d < Dim; ++d)
      for (std::size_t j = 0; j < 4; ++j) c[static_cast<std::size_t>(d)][j] = seg_[i].power[j][d];
    for (std::size_t k = 0; k < m; ++k) {
      const Real t = per_h<Reciprocal>(Real(us[k] - ui), scale);
      for (int d = 0; d < Dim; ++d) {
        const auto& a = c[static_cast<std::size_t>(d)];
        out[k][d] = a[0] + t * (a[1] + t * (a[2] + t * a[3]));
      }
    }
  }

  // The segment of u, u in the domain: the one a binary search over the knots gives (first
  // interior knot > u, minus one; u_n in the last segment).
  [[nodiscard]] CURVEBENCH_PC_HOT std::size_t locate(const Real& u) const {
    // Segment i holds u when left <= u < right in its lookup record (-inf and +inf at the ends
    // stand for "no knot to check"), so the corrections need no bounds tests.
    if (uniform_) {
      // u >= u0, so x = fl(fl(u - u0) / hbar) >= 0; it can exceed n - 1 (u in the last segment, or
      // rounding), so clamp before converting.
      const Real x = (u - lo_) * inv_hbar_;
      std::size_t i = x < last_real_ ? to_index(x) : last_;
      while (u < seg_[i].lookup.left) --i;
      while (!(u < seg_[i].lookup.right)) ++i;
      return i;
    }
    if (!buckets_.empty()) {
      // The bucket of u and of every knot is the same function (bucket_of), monotone in u, so the
      // interior knots of lower buckets are all <= u and those of higher buckets all > u: the
      // segment is the bucket's count of lower knots (first) plus its own knots <= u. At most two
      // of them (almost every bucket): compared without a branch, +inf standing for none.
      const bucket_record& e = buckets_[bucket_of(u)];
      if (e.count <= 2) [[likely]]
        return e.first + static_cast<std::size_t>(!(u < e.split[0])) + static_cast<std::size_t>(!(u < e.split[1]));
      const auto from = knots_.begin() + static_cast<std::ptrdiff_t>(e.first) + 1;
      return static_cast<std::size_t>(std::upper_bound(from, from + e.count, u) - knots_.begin()) - 1;
    }
    return locate_binary(u);
  }

  [[nodiscard]] std::size_t locate_binary(const Real& u) const {
    // core/detail/segment_lookup.hpp's rule over the interior knots only: u_n -> the last segment.
    const auto it = std::upper_bound(knots_.begin() + 1, knots_.end() - 1, u);
    return static_cast<std::size_t>(it - knots_.begin()) - 1;
  }

  // The bucket of u in the index of non-uniform knots: fl(fl(u - u_0) / w) truncated (by the
  // reciprocal of the width w = (u_n - u_0) / B), clamped to the last of the B buckets. Each step
  // rounds monotonically, so the map is non-decreasing in u; the index is built by the same
  // function on the knots, so no rounding in it can move a knot to the wrong side of u (locate).
  [[nodiscard]] CURVEBENCH_PC_HOT std::size_t bucket_of(const Real& u) const {
    const Real x = (u - lo_) * inv_bucket_width_;  // >= 0: u >= u_0
    return x < bucket_last_real_ ? to_index(x) : bucket_last_;
  }

  // The bucket index: B = 2n buckets (so that most hold at most one interior knot); per bucket the
  // number of interior knots in lower buckets, its own count and, up to two, its knots.
  void build_buckets() {
    buckets_.clear();
    const std::size_t n = h_.size();
    if (uniform_ || n < 2 || n >= std::size_t(std::numeric_limits<std::uint32_t>::max() / 2)) return;
    const std::size_t count = 2 * n;
    inv_bucket_width_ = Real(static_cast<long long>(count)) / (knots_.back() - knots_.front());
    if (!is_finite(inv_bucket_width_) || !(inv_bucket_width_ > Real(0))) return;
    bucket_last_ = count - 1;
    bucket_last_real_ = Real(static_cast<long long>(bucket_last_));
    const Real none = std::numeric_limits<Real>::infinity();
    buckets_.assign(count, bucket_record{{none, none}, 0, 0});
    for (std::size_t j = 1; j < n; ++j) {
      bucket_record& e = buckets_[bucket_of(knots_[j])];
      if (e.count < 2) e.split[e.count] = knots_[j];
      ++e.count;
    }
    std::uint32_t below = 0;
    for (bucket_record& e : buckets_) {
      e.first = below;
      below += e.count;
    }
  }

  // The local parameter of u in segment i (r = seg_[i].lookup): t = fl(fl(u - u_i) fl(1 / h_i)), no
  // division. Its error against (u - u_i) / (u_{i+1} - u_i): the difference, h_i = fl(u_{i+1} -
  // u_i), the reciprocal and the product round once each, so |t - t_exact| <= 4 u t (1 + O(u)) when
  // fl(1 / h_i) is a normal number (a product or difference below the normal range is off by less
  // than the smallest normal, absolutely; t <= 1 makes that negligible against 4 u max |P'|), one u
  // more than the division's 3 u; rounding_bound charges the 4 u. Where some fl(1 / h_i) is not
  // normal (h_i beyond 1 / DBL_MIN, or subnormal) the curve divides: fl(fl(u - u_i) / h_i), 3 u.
  // At u = u_{i+1} (the last knot) t may round to 1 +- 2 u instead of 1: within the same bound.
  [[nodiscard]] CURVEBENCH_PC_HOT Real local_t(std::size_t i, const lookup_record& r, const Real& u) const {
    return per_h_i(Real(u - r.knot), i, r);
  }

  // x / h_i of segment i (r = seg_[i].lookup) the curve's way: by fl(1 / h_i) where every
  // reciprocal is normal (reciprocal_), else divided. For t (local_t), the chain rule and
  // second_derivative_bound.
  template <class X>
  [[nodiscard]] CURVEBENCH_PC_HOT X per_h_i(const X& x, std::size_t i, const lookup_record& r) const {
    return reciprocal_ ? per_h<true>(x, r.inv_h) : per_h<false>(x, h_[i]);
  }

  // x / h_i, by the reciprocal (scale = fl(1 / h_i)) or by the division (scale = h_i): the one
  // place both forms are written, for t (local_t, the sorted runs) and for the chain rule.
  template <bool Reciprocal, class X>
  [[nodiscard]] CURVEBENCH_PC_HOT static X per_h(const X& x, const Real& scale) {
    if constexpr (Reciprocal)
      return X(x * scale);
    else
      return X(x / scale);
  }

  [[nodiscard]] static std::size_t to_index(const Real& x) {
    if constexpr (std::is_floating_point_v<Real>) {
      return static_cast<std::size_t>(x);
    } else {
      return static_cast<std::size_t>(x.template convert_to<long long>());
    }
  }

  [[nodiscard]] Real chain_scale(std::size_t i, int order) const {
    Real s(1);
    for (int k = 0; k < order; ++k) s /= h_[i];
    return s;
  }

  [[nodiscard]] point_type eval_segment(std::size_t i, const Real& t, int order, cubic_algorithm algorithm) const {
    if (order > 3) return point_type::Zero();
    const point_type p = algorithm == cubic_algorithm::power    ? eval_power(seg_[i].power, t, order)
                         : algorithm == cubic_algorithm::matrix ? eval_matrix(basis_[i], geometry_[i], t, order)
                                                                : eval_bezier(bezier_[i], t, order);
    if (order == 0) return p;
    return point_type(p * chain_scale(i, order));
  }

  [[nodiscard]] CURVEBENCH_PC_HOT static point_type horner(const std::array<point_type, 4>& a, const Real& t) {
    return a[0] + t * (a[1] + t * (a[2] + t * a[3]));
  }

  [[nodiscard]] static point_type eval_power(const std::array<point_type, 4>& a, const Real& t, int order) {
    switch (order) {
      case 0: return horner(a, t);
      case 1: return a[1] + t * (Real(2) * a[2] + t * (Real(3) * a[3]));
      case 2: return Real(2) * a[2] + (Real(6) * t) * a[3];
      default: return Real(6) * a[3];
    }
  }

  [[nodiscard]] static point_type eval_matrix(const matrix_type& m, const geometry_type& g, const Real& t, int order) {
    // T(t) (or its derivative) as a row, then (T · M) · G: the blending functions weight the items.
    Eigen::Matrix<Real, 1, 4> row;
    const Real t2 = t * t;
    switch (order) {
      case 0: row << Real(1), t, t2, t2 * t; break;
      case 1: row << Real(0), Real(1), Real(2) * t, Real(3) * t2; break;
      case 2: row << Real(0), Real(0), Real(2), Real(6) * t; break;
      default: row << Real(0), Real(0), Real(0), Real(6); break;
    }
    const Eigen::Matrix<Real, 1, 4> blend = row * m;
    const Eigen::Matrix<Real, 1, Dim> p = blend * g;
    return p.transpose();
  }

  [[nodiscard]] static point_type eval_bezier(const std::array<point_type, 4>& b, const Real& t, int order) {
    // de Casteljau's three levels of convex combinations (the shared kernel, convex form); the first
    // derivative from the triangle, the second from the second differences blended linearly.
    return basis::detail::cubic_derivative<basis::detail::cubic_form::convex>(b, t, order);
  }

  std::vector<Real> knots_;
  std::vector<geometry_type> geometry_;
  std::vector<matrix_type> basis_;
  std::vector<Real> h_;
  std::vector<Real> inv_h_;  // fl(1 / h_i): the first derivative's chain-rule factor
  // Per segment, everything a power evaluation reads (the lookup's record and the coefficients) in
  // one record on its own cache lines: 64 bytes for 1D double, 128 for 3D double (it was two arrays,
  // so a random evaluation touched three or four lines where two hold it).
  struct alignas(64) segment_record {
    std::array<point_type, 4> power;
    lookup_record lookup;
  };
  std::vector<segment_record> seg_;
  std::vector<std::array<point_type, 4>> bezier_;
  bool uniform_ = false;
  Real inv_hbar_ = Real(1);
  Real lo_ = Real(0), hi_ = Real(0);  // the domain, kept beside the hot path's other members
  bool reciprocal_ = true;            // t = (u - u_i) fl(1 / h_i) (see local_t); false: (u - u_i) / h_i
  std::size_t last_ = 0;              // segment_count() - 1
  Real last_real_ = Real(0);
  // One bucket of the non-uniform index (build_buckets): the interior knots in lower buckets, the
  // bucket's own count and its first two knots (+inf where it has fewer).
  struct bucket_record {
    std::array<Real, 2> split;
    std::uint32_t first, count;
  };
  std::vector<bucket_record> buckets_;  // non-uniform knots: 2n buckets
  Real inv_bucket_width_ = Real(1);
  std::size_t bucket_last_ = 0;  // the number of buckets - 1
  Real bucket_last_real_ = Real(0);
  std::array<Real, 2> rounding_bound_{};
};

}  // namespace curvebench

#undef CURVEBENCH_PC_HOT
