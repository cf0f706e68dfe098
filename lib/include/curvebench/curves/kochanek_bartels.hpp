// kochanek_bartels: Kochanek-Bartels (TCB) splines, interpolating cubic Hermite splines whose
// tangents are shaped per key by tension t, continuity c and bias b (t = c = b = 0: Catmull-Rom).
// The tangents from the arriving and leaving chords, the bias sign (the paper's, not seed 000's
// misprint) and the paper's non-uniform time adjustment (dP/du = 2 D / (h_{i-1} + h_i), C1 in u on
// any knots when c = 0) are derived above kochanek_bartels_tangents. Open ends use phantom keys
// P_{-1} = 2 P_0 - P_1, P_{n+1} = 2 P_n - P_{n-1} at mirrored times; closed splines wrap around.
// Evaluated by the piecewise_cubic engine.
// Sources: Kochanek & Bartels (1984); seed 000 (tension, continuity and bias one at a time).
// Cost: O(n) construction, O(1) evaluation; local control (a key moves at most four segments).
// Accuracy: interpolates the keys to rounding.
#pragma once

#include "curvebench/core/error.hpp"
#include "curvebench/core/point.hpp"
#include "curvebench/curves/detail/cubic_family.hpp"
#include "curvebench/curves/piecewise_cubic.hpp"

#include <cstddef>
#include <utility>
#include <vector>

namespace curvebench {

/// Per-key tension, continuity, bias (each finite; 0, 0, 0 is Catmull-Rom).
template <class Real>
struct tcb {
  Real tension = Real(0);
  Real continuity = Real(0);
  Real bias = Real(0);
};

// With chords L_i = P_i - P_{i-1} (arriving) and R_i = P_{i+1} - P_i (leaving), the tangents at key
// i in "per segment" units are
//   outgoing (start of segment i)  DD_i = (1-t)(1+b)(1+c)/2 L_i + (1-t)(1-b)(1-c)/2 R_i
//   incoming (end of segment i-1)  DS_i = (1-t)(1+b)(1-c)/2 L_i + (1-t)(1-b)(1+c)/2 R_i.
// t = c = b = 0 is Catmull-Rom. Seed 000's tension and continuity formulas are these; its bias
// formula is printed with the opposite sign of b (it weights L by (1 - b)); we follow the paper:
// b = +1 weights the arriving chord ("overshoot" after the key).
// Non-uniform time (the paper's adjustment): for frame counts (knot intervals) N_{i-1} = h_{i-1},
// N_i = h_i around key i, DS_i is scaled by 2 N_{i-1}/(N_{i-1} + N_i) and DD_i by 2 N_i/(N_{i-1} + N_i).
// In slopes per unit of u (our Hermite convention, local tangent = h dP/du) both become
// dP/du = 2 D / (h_{i-1} + h_i): with c = 0 the spline is C1 in u on ANY knots (derivation: the
// velocity on each side is the adjusted tangent divided by that side's h). Without the adjustment
// the tangents are used as local tangents as they are (dP/du = DD_i / h_i, DS_i / h_{i-1}), C1 only on
// uniform knots.
/// Outgoing (DD) and incoming (DS) tangents at a key from its arriving chord L and leaving chord R,
/// in per-segment units (before any time adjustment).
template <class Real, int Dim>
struct tcb_tangents {
  point<Real, Dim> incoming;
  point<Real, Dim> outgoing;
};

template <class Real, int Dim>
[[nodiscard]] tcb_tangents<Real, Dim> kochanek_bartels_tangents(const tcb<Real>& k, const point<Real, Dim>& arriving,
                                                                const point<Real, Dim>& leaving) {
  const Real half = Real(1) / Real(2);
  const Real s = (Real(1) - k.tension) * half;
  const Real bp = Real(1) + k.bias, bm = Real(1) - k.bias;
  const Real cp = Real(1) + k.continuity, cm = Real(1) - k.continuity;
  tcb_tangents<Real, Dim> r;
  r.outgoing = (s * bp * cp) * arriving + (s * bm * cm) * leaving;
  r.incoming = (s * bp * cm) * arriving + (s * bm * cp) * leaving;
  return r;
}

template <class Real, int Dim>
class kochanek_bartels : public detail::cubic_family<Real, Dim> {
  using base = detail::cubic_family<Real, Dim>;

 public:
  using typename base::point_type;

  struct options {
    /// A closed loop (the segment back to the first key is added).
    bool closed = false;
    /// Apply the paper's non-uniform time adjustment (C1 in u for c = 0 on any knots).
    bool time_adjust = true;
  };

  /// Keys at knots (times): open: knots.size() == points.size() >= 2; closed: knots.size() ==
  /// points.size() + 1 >= 4 (the last knot is the return to points[0]). params: one per point.
  kochanek_bartels(const std::vector<Real>& knots, const point_list<Real, Dim>& points,
                   const std::vector<tcb<Real>>& params, options opt)
      : base(build(knots, points, params, opt)), points_(points), params_(params), options_(opt) {}

  /// Keys at uniform times 0, 1, 2, ... (closed: one more knot for the return).
  kochanek_bartels(const point_list<Real, Dim>& points, const std::vector<tcb<Real>>& params, options opt)
      : kochanek_bartels(uniform_knots<Real>(opt.closed ? points.size() : (points.empty() ? 0 : points.size() - 1)),
                         points, params, opt) {}

  [[nodiscard]] const point_list<Real, Dim>& points() const { return points_; }
  [[nodiscard]] const std::vector<tcb<Real>>& parameters() const { return params_; }
  [[nodiscard]] options settings() const { return options_; }

 private:
  static typename base::engine_type build(const std::vector<Real>& knots, const point_list<Real, Dim>& pts,
                                          const std::vector<tcb<Real>>& params, options opt) {
    const std::size_t np = pts.size();
    validate::count_at_least("points", np, opt.closed ? 3 : 2,
                             opt.closed ? "a closed loop needs three keys" : "a segment needs two keys");
    validate::same_count("knots", knots.size(), opt.closed ? "points + 1 (closed loop)" : "points",
                         opt.closed ? np + 1 : np);
    validate::same_count("params", params.size(), "points", np);
    validate::increasing<Real>("knots", knots);
    validate::finite_points<Real, Dim>("points", pts);
    for (std::size_t i = 0; i < np; ++i) {
      validate::finite("params.tension", params[i].tension, i);
      validate::finite("params.continuity", params[i].continuity, i);
      validate::finite("params.bias", params[i].bias, i);
    }
    point_list<Real, Dim> v(pts.begin(), pts.end());
    if (opt.closed) v.push_back(pts.front());
    const std::size_t n = v.size() - 1;  // segments
    auto h = [&](std::size_t i) { return knots[i + 1] - knots[i]; };
    point_list<Real, Dim> in(n + 1), out(n + 1);
    // Bounds on the tangents' rounding (piecewise_cubic::from_hermite): a weight (1 - t)/2 (1 +- b)
    // (1 +- c) rounds 5 times, a chord of data once (relative to itself), the weighted sum 3 times,
    // the time scaling (the division by h, or w = 2 / (h_l + h_r) and its product) at most 5 times
    // with the intervals' own rounding: 14 roundings, within 8 eps of sum |weight| |chord|; 16 eps
    // keeps a factor of two.
    std::vector<Real> in_err(n + 1), out_err(n + 1);
    for (std::size_t i = 0; i <= n; ++i) {
      const std::size_t key = (opt.closed && i == n) ? 0 : i;
      // Arriving chord L and its interval hl; leaving chord R and hr (phantoms or wrap-around at ends).
      point_type left, right;
      Real hl, hr, left_size, right_size;  // the chords' norms
      auto chord = [&](std::size_t a, std::size_t b, point_type& d, Real& size) {
        d = v[b] - v[a];
        size = safe_norm(d);
      };
      if (i > 0) {
        chord(i - 1, i, left, left_size);
        hl = h(i - 1);
      } else if (opt.closed) {
        chord(n - 1, n, left, left_size);
        hl = h(n - 1);
      } else {
        chord(0, 1, left, left_size);
        hl = h(0);
      }
      if (i < n) {
        chord(i, i + 1, right, right_size);
        hr = h(i);
      } else if (opt.closed) {
        chord(0, 1, right, right_size);
        hr = h(0);
      } else {
        chord(n - 1, n, right, right_size);
        hr = h(n - 1);
      }
      const tcb<Real>& k = params[key];
      const auto t = kochanek_bartels_tangents<Real, Dim>(k, left, right);
      using std::abs;
      const Real s = abs((Real(1) - k.tension) / Real(2));
      const Real bp = abs(Real(1) + k.bias), bm = abs(Real(1) - k.bias);
      const Real cp = abs(Real(1) + k.continuity), cm = abs(Real(1) - k.continuity);
      const Real out_size = s * (bp * cp * left_size + bm * cm * right_size);
      const Real in_size = s * (bp * cm * left_size + bm * cp * right_size);
      const Real bound = Real(16) * epsilon<Real>();
      if (opt.time_adjust) {
        const Real w = Real(2) / (hl + hr);
        in[i] = w * t.incoming;
        out[i] = w * t.outgoing;
        in_err[i] = bound * w * in_size;
        out_err[i] = bound * w * out_size;
      } else {
        in[i] = t.incoming / hl;
        out[i] = t.outgoing / hr;
        in_err[i] = bound * in_size / hl;
        out_err[i] = bound * out_size / hr;
      }
    }
    return base::engine_type::from_hermite(knots, v, in, out, in_err, out_err);
  }

  point_list<Real, Dim> points_;
  std::vector<tcb<Real>> params_;
  options options_;
};

}  // namespace curvebench
