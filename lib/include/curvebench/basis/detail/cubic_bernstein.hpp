// Private kernels of the cubic Bernstein form, shared by piecewise_cubic.hpp (the bezier
// algorithm), channel/detail/channel_segment.hpp (a keyframe segment's time and value) and
// channel/time_solver.hpp (the time residual): the value, the derivatives of every order and the
// split at t of b0 B_0^3(t) + b1 B_1^3(t) + b2 B_2^3(t) + b3 B_3^3(t), for a scalar or a point
// type P (anything with P + P, P - P and Real * P, e.g. Real itself or point<Real, Dim>).
// Not part of the public interface.
//
// Algorithm: de Casteljau's triangle (Farin, Curves and Surfaces for CAGD, ch. 4): three levels of
// steps between neighbours at t, r_k = step(b_k, b_{k+1}), q_k = step(r_k, r_{k+1}), P(t) =
// step(q_0, q_1). Its sides are the split: [b0, r0, q0, P] is the cubic on [0, t], [P, q1, r2, b3]
// the one on [t, 1], both reparameterized to [0, 1]. Derivatives from the differences: P' = 3 sum
// Δb_k B_k^2, P'' = 6 sum Δ²b_k B_k^1, P''' = 6 Δ³b_0 = 6 ((b3 - b0) - 3 (b2 - b1)); orders > 3
// are zero.
// Forms: a step is computed one of two ways, chosen at compile time, because results recorded by
// the callers (Blender's float32 F-curves through the channel, the harness records of the
// piecewise cubic's bezier algorithm) depend on the exact operations:
//   convex: s a + t b with s = fl(1 - t): exact at t = 0 and t = 1, each step a convex combination
//           (piecewise_cubic). P' = 3 (q1 - q0) from the triangle; P'' from the nested second
//           differences (b_{k+2} - b_{k+1}) - (b_{k+1} - b_k), blended convexly.
//   affine: a + t (b - a): exact at t = 0, one multiplication per step (the keyframe channel and
//           the time solvers). P' = 3 times the quadratic triangle of the first differences b_{k+1}
//           - b_k; P'' from the second differences (b_{k+2} - 2 b_{k+1}) + b_k, blended affinely.
// Both forms are O(1): 6 steps for the value (12 for convex, which multiplies twice), a few more
// for a derivative; no allocation, no branch on the data.
// Accuracy: backward stable. For t in [0, 1] and M = max_k |b_k|, a step of either form rounds by at
// most 5 u M (u = eps / 2: the difference or fl(1 - t), the product, the sum) and carries the errors
// of the level below with weights summing to 1, so the value is within 15 u M < 8 eps M of the
// exact one, and so is each coefficient of the split; the derivatives within small multiples of
// eps M, derived and checked against the power form at 50 digits in tests/test_cubic_bernstein.cpp.
#pragma once

#include <array>
#include <utility>

// The kernels are a few multiply-adds on small points: inlined into the caller's hot path always
// (GCC's heuristics otherwise call the order switch and the steps out of line, measured 10% slower
// on piecewise_cubic's bezier rows of bench_piecewise_cubic).
#if defined(__GNUC__)
#define CURVEBENCH_CB_INLINE [[gnu::always_inline]] inline
#else
#define CURVEBENCH_CB_INLINE inline
#endif

namespace curvebench::basis::detail {

/// How one de Casteljau step between a and b at t is computed (see the header).
enum class cubic_form { convex, affine };

/// One step of the chosen form at t: s a + t b (convex, s = fl(1 - t) computed once) or
/// a + t (b - a) (affine).
template <cubic_form Form, class Real>
class cubic_step {
 public:
  explicit cubic_step(const Real& t) : t_(t) {
    if constexpr (Form == cubic_form::convex) s_ = Real(1) - t;
  }
  template <class P>
  [[nodiscard]] CURVEBENCH_CB_INLINE P operator()(const P& a, const P& b) const {
    if constexpr (Form == cubic_form::convex)
      return P(s_ * a + t_ * b);
    else
      return P(a + t_ * (b - a));
  }

 private:
  const Real& t_;
  Real s_{};  // fl(1 - t) for the convex form (unused by the affine one)
};

/// De Casteljau's triangle of b0..b3 at t: the first level r, the second q and the value p.
template <class P>
struct cubic_triangle {
  P r0, r1, r2, q0, q1, p;
};

/// The whole triangle at t (every level; the split and the triangle's derivative read it).
template <cubic_form Form, class P, class Real>
[[nodiscard]] CURVEBENCH_CB_INLINE cubic_triangle<P> cubic_de_casteljau(const P& b0, const P& b1, const P& b2,
                                                                        const P& b3, const Real& t) {
  const cubic_step<Form, Real> step(t);
  const P r0 = step(b0, b1), r1 = step(b1, b2), r2 = step(b2, b3);
  const P q0 = step(r0, r1), q1 = step(r1, r2);
  return {r0, r1, r2, q0, q1, step(q0, q1)};
}

/// The value at t by de Casteljau's algorithm.
template <cubic_form Form, class P, class Real>
[[nodiscard]] CURVEBENCH_CB_INLINE P cubic_value(const P& b0, const P& b1, const P& b2, const P& b3, const Real& t) {
  const cubic_step<Form, Real> step(t);
  const P r0 = step(b0, b1), r1 = step(b1, b2), r2 = step(b2, b3);
  return step(step(r0, r1), step(r1, r2));
}

/// The first derivative in t: 3 (q1 - q0) of the triangle (convex) or 3 times the quadratic
/// triangle of the differences (affine).
template <cubic_form Form, class P, class Real>
[[nodiscard]] CURVEBENCH_CB_INLINE P cubic_first_derivative(const P& b0, const P& b1, const P& b2, const P& b3,
                                                            const Real& t) {
  const cubic_step<Form, Real> step(t);
  if constexpr (Form == cubic_form::convex) {
    const P r0 = step(b0, b1), r1 = step(b1, b2), r2 = step(b2, b3);
    return P(Real(3) * (step(r1, r2) - step(r0, r1)));
  } else {
    const P d0 = b1 - b0, d1 = b2 - b1, d2 = b3 - b2;
    return P(Real(3) * step(step(d0, d1), step(d1, d2)));
  }
}

/// The second derivative in t: 6 times the linear blend of the second differences (see the header
/// for each form's operation order).
template <cubic_form Form, class P, class Real>
[[nodiscard]] CURVEBENCH_CB_INLINE P cubic_second_derivative(const P& b0, const P& b1, const P& b2, const P& b3,
                                                             const Real& t) {
  const cubic_step<Form, Real> step(t);
  if constexpr (Form == cubic_form::convex) {
    const P d0 = (b2 - b1) - (b1 - b0), d1 = (b3 - b2) - (b2 - b1);
    return P(Real(6) * step(d0, d1));
  } else {
    const P d0 = b2 - Real(2) * b1 + b0, d1 = b3 - Real(2) * b2 + b1;
    return P(Real(6) * step(d0, d1));
  }
}

/// The third derivative (constant): 6 ((b3 - b0) - 3 (b2 - b1)).
template <class P, class Real>
[[nodiscard]] CURVEBENCH_CB_INLINE P cubic_third_derivative(const P& b0, const P& b1, const P& b2, const P& b3) {
  return P(Real(6) * ((b3 - b0) - Real(3) * (b2 - b1)));
}

/// The derivative of the given order at t: 0 the value, 1..3 as above. order must be in 0..3 (the
/// callers validate it and answer orders above 3, zero, themselves).
template <cubic_form Form, class P, class Real>
[[nodiscard]] CURVEBENCH_CB_INLINE P cubic_derivative(const std::array<P, 4>& b, const Real& t, int order) {
  switch (order) {
    case 0: return cubic_value<Form>(b[0], b[1], b[2], b[3], t);
    case 1: return cubic_first_derivative<Form>(b[0], b[1], b[2], b[3], t);
    case 2: return cubic_second_derivative<Form>(b[0], b[1], b[2], b[3], t);
    default: return cubic_third_derivative<P, Real>(b[0], b[1], b[2], b[3]);
  }
}

/// The split at t: the Bernstein coefficients of the cubic on [0, t] and on [t, 1], each
/// reparameterized to [0, 1] (the sides of the triangle). Both share the point at t.
template <cubic_form Form, class P, class Real>
[[nodiscard]] std::pair<std::array<P, 4>, std::array<P, 4>> cubic_split(const std::array<P, 4>& b, const Real& t) {
  const cubic_triangle<P> tri = cubic_de_casteljau<Form>(b[0], b[1], b[2], b[3], t);
  return {{b[0], tri.r0, tri.q0, tri.p}, {tri.p, tri.q1, tri.r2, b[3]}};
}

}  // namespace curvebench::basis::detail

#undef CURVEBENCH_CB_INLINE
