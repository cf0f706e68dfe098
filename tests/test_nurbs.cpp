// NURBS: the 9- and 7-point circles are circles to a few ulps in every type (and so are all their
// derivatives, through d^k |C - c|^2 / du^k = 0), equal weights reduce to the B-spline, scaling
// all weights changes nothing, a single-span NURBS equals the rational Bezier closed form and its
// derivatives of any order equal the Taylor-series quotient computed independently in 50 digits
// from the Bernstein derivative formula; bad input.
#include "support/accuracy.hpp"

#include "curvebench/basis/bernstein.hpp"
#include "curvebench/curves/bspline.hpp"
#include "curvebench/curves/nurbs.hpp"

#include <gmock/gmock.h>

#include <iostream>
#include <limits>
#include <random>
#include <vector>

namespace cb = curvebench;
namespace cbt = curvebench::testing;

static_assert(cb::curve<cb::nurbs<double, 2>>);
static_assert(cb::curve<cb::nurbs<cb::real50, 4>>);  // Dim + 1 = 5 homogeneous coordinates

namespace {

// Tolerances, in eps(Real):
// - circle radius: the control points are c +- r (exact for the data used) and c +- r sqrt(3)
//   (one rounding); each quarter / third is the exact conic of its rounded weight (sqrt(2)/2 is
//   rounded by <= 1/2 ulp, which moves the arc off the circle by at most ~0.17 * 1/2 ulp of r);
//   then two de Boor levels in 3 homogeneous coordinates (4 roundings), one division (1), and the
//   distance computed exactly in real50. Measured in all four types: <= 1.5 eps r for the unit
//   circles, <= 4 eps r for the offset circle (coordinates up to 5 = 2.5 r, so its roundings are
//   larger relative to r); allow 6 eps r;
// - derivative identity sum_i C(k,i) D_i . D_{k-i} = 0: each D_i carries ~(4 + 2i) ulps of its
//   own scale |D_i|; the sum of 2^k products is checked against sum C(k,i) |D_i||D_{k-i}|:
//   allow 16 (k + 1) ulps of that scale;
// - NURBS with equal weights vs the B-spline: the homogeneous de Boor computes w P (rounded) and
//   w, then divides: 4m + 2 ulps of the control scale, derivatives as in test_bspline;
// - rational Bezier vs the 50-digit Taylor reference: value 4m + 4 ulps of the control scale;
//   derivative k: each recurrence step divides by W >= wmin and sums k terms of size
//   C(k,i) |W^(i)| |C^(k-i)|: 64 * 4^k ulps of the reference's own scale (its largest term).
constexpr double circle_ulps = 6;
double identity_ulps(int k) { return 16.0 * (k + 1); }
double equal_weight_ulps(int m) { return 4.0 * m + 2; }
double rational_value_ulps(int m) { return 4.0 * m + 4; }
double rational_derivative_ulps(int k) {
  double f = 64;
  for (int j = 0; j < k; ++j) f *= 4;
  return f;
}

template <class Real>
class nurbs_typed : public ::testing::Test {};
TYPED_TEST_SUITE(nurbs_typed, cbt::all_reals);

template <class Real>
void check_circle(const cb::nurbs<Real, 2>& c, const cb::point<Real, 2>& center, const Real& r, const char* name) {
  double worst = 0;
  for (int s = 0; s <= 720; ++s) {
    const Real u = Real(s) / Real(720);
    const cb::point<Real, 2> p = c(u);
    const cb::point<cb::real50, 2> d = cb::point_cast<cb::real50>(p) - cb::point_cast<cb::real50>(center);
    using std::sqrt;
    const cb::real50 dist = sqrt(d.squaredNorm());
    ASSERT_TRUE(cbt::within_scaled_ulps(Real(0), dist - cb::real50(r), cb::real50(r), circle_ulps))
        << name << " u=" << s << "/720";
    worst = std::max(worst, static_cast<double>(cbt::scaled_ulps(Real(0), dist - cb::real50(r), cb::real50(r))));
    // All derivatives: |C - c|^2 is constant, so d^k/du^k of it vanishes for k = 1..4.
    std::array<cb::point<cb::real50, 2>, 5> dv;
    dv[0] = d;
    for (int k = 1; k <= 4; ++k) dv[static_cast<std::size_t>(k)] = cb::point_cast<cb::real50>(c.derivative(u, k));
    for (int k = 1; k <= 4; ++k) {
      cb::real50 sum = 0;
      cb::real50 scale = 0;
      for (int i = 0; i <= k; ++i) {
        const cb::real50 b = cb::binomial<cb::real50>(k, i);
        sum += b * dv[static_cast<std::size_t>(i)].dot(dv[static_cast<std::size_t>(k - i)]);
        scale += b * dv[static_cast<std::size_t>(i)].norm() * dv[static_cast<std::size_t>(k - i)].norm();
      }
      ASSERT_TRUE(cbt::within_scaled_ulps(Real(0), sum, scale, identity_ulps(k))) << name << " k=" << k << " u=" << s;
    }
  }
  // Measured worst radius error, reported in the test log (the numbers quoted in docs and reports).
  std::cout << "[ measured ] " << name << " max | |C(u) - c| - r | = " << worst << " eps * r (" << sizeof(Real)
            << "-byte Real, digits " << std::numeric_limits<Real>::digits << ")\n";
}

}  // namespace

// The circle to a few ulps. Why the accuracy differs per type: the only non-representable datum of
// the 9-point circle is the weight sqrt(2)/2, rounded by a different fraction of an ulp in each
// format (measured with Boost.Math's constants against 50 digits: float by -0.20 ulp, double by
// +0.44 ulp, long double by -0.35 ulp of the value), and the evaluation's four or five roundings
// may cancel or add; the 7-point circle rounds sqrt(3) in the control coordinates instead (float
// -0.26, double -0.45, long double +0.43 ulp; its weights 1/2 are exact). real50 rounds the weight at 50
// digits and its ulps are measured against its own epsilon: the same few ulps.
TYPED_TEST(nurbs_typed, nine_and_seven_point_circles) {
  using Real = TypeParam;
  const cb::point<Real, 2> c0(Real(0), Real(0));
  check_circle(cb::nurbs_circle_9<Real>(c0, Real(1)), c0, Real(1), "circle_9 unit");
  check_circle(cb::nurbs_circle_7<Real>(c0, Real(1)), c0, Real(1), "circle_7 unit");
  // Off-centre, radius a power of two: the control coordinates c +- r stay exact.
  const cb::point<Real, 2> c1(Real(-3), Real(5) / Real(4));
  check_circle(cb::nurbs_circle_9<Real>(c1, Real(2)), c1, Real(2), "circle_9 offset");
  // Start point, quarter points, end point exactly on the axes.
  const auto c9 = cb::nurbs_circle_9<Real>(c0, Real(1));
  EXPECT_EQ(c9(Real(0)), (cb::point<Real, 2>(Real(1), Real(0))));
  EXPECT_EQ(c9(Real(1) / Real(4)), (cb::point<Real, 2>(Real(0), Real(1))));
  EXPECT_EQ(c9(Real(1)), (cb::point<Real, 2>(Real(1), Real(0))));
}

// Equal weights: the NURBS is the B-spline of the same knots and points (values and derivatives);
// scaling every weight by the same factor leaves the curve unchanged.
TYPED_TEST(nurbs_typed, equal_weights_reduce_to_bspline) {
  using Real = TypeParam;
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> dist(-1, 1);
  for (int m : {2, 3, 4, 5}) {
    const std::size_t n = 8;
    const auto t = cb::bspline_clamped_knots<Real>(n, m, Real(0), Real(2));
    cb::point_list<Real, 3> p(n);
    for (auto& q : p) q = cb::point<Real, 3>(Real(dist(rng)), Real(dist(rng)), Real(dist(rng)));
    const cb::bspline<Real, 3> b(m, t, p);
    const cb::nurbs<Real, 3> r1(m, t, p, std::vector<Real>(n, Real(1)));
    const cb::nurbs<Real, 3> r3(m, t, p, std::vector<Real>(n, Real(3)));
    for (int s = 0; s <= 40; ++s) {
      const Real u = Real(s) / Real(20);
      for (int k = 0; k <= m + 1; ++k) {
        double tol = equal_weight_ulps(m);
        for (int j = 0; j < k; ++j) tol *= 4.0 * m * (n - static_cast<std::size_t>(m) + 1) / 2.0;
        const auto ref = cb::point_cast<cb::real50>(b.derivative(u, k));
        ASSERT_TRUE(cbt::point_within(r1.derivative(u, k), ref, cb::real50(1), tol)) << "m=" << m << " k=" << k;
        ASSERT_TRUE(cbt::point_within(r3.derivative(u, k), ref, cb::real50(1), tol)) << "m=" << m << " k=" << k;
        ASSERT_TRUE(cbt::point_within(r3.evaluate(u, k, cb::bspline_evaluation::basis_sum), ref, cb::real50(1), tol));
      }
    }
  }
}

// A single-span clamped cubic NURBS (n = m = 4) is the rational Bezier curve. Reference in 50
// digits, independent of the implementation: A(u0 + s) and W(u0 + s) as Taylor series from the
// Bernstein derivative closed form (basis/bernstein.hpp), then the series quotient C = A / W,
// whose coefficients c_k give C^(k) = k! c_k. Orders 0..7 (the rational curve has non-zero
// derivatives of every order).
TYPED_TEST(nurbs_typed, rational_bezier_derivatives_match_series_quotient) {
  using Real = TypeParam;
  const cb::point_list<Real, 2> p{{Real(0), Real(0)}, {Real(1), Real(2)}, {Real(3), Real(2)}, {Real(4), Real(0)}};
  const std::vector<Real> w{Real(1), Real(3), Real(1) / Real(2), Real(2)};
  const cb::nurbs<Real, 2> c(4, {Real(0), Real(0), Real(0), Real(0), Real(1), Real(1), Real(1), Real(1)}, p, w);
  constexpr int kmax = 7;
  for (int s = 0; s <= 16; ++s) {
    const Real u = Real(s) / Real(16);
    const cb::real50 u50(u);
    std::array<cb::point<cb::real50, 2>, kmax + 1> a;
    std::array<cb::real50, kmax + 1> wt;
    cb::real50 fact = 1;
    for (int k = 0; k <= kmax; ++k) {
      if (k > 0) fact *= k;
      a[static_cast<std::size_t>(k)] = cb::zero_point<cb::real50, 2>();
      wt[static_cast<std::size_t>(k)] = 0;
      for (int i = 0; i < 4; ++i) {
        const cb::real50 bd = cb::basis::bernstein_derivative(3, i, u50, k) / fact;
        a[static_cast<std::size_t>(k)] += bd * cb::real50(w[static_cast<std::size_t>(i)]) *
                                          cb::point_cast<cb::real50>(p[static_cast<std::size_t>(i)]);
        wt[static_cast<std::size_t>(k)] += bd * cb::real50(w[static_cast<std::size_t>(i)]);
      }
    }
    std::array<cb::point<cb::real50, 2>, kmax + 1> cs;
    fact = 1;
    for (int k = 0; k <= kmax; ++k) {
      const auto uk = static_cast<std::size_t>(k);
      cb::point<cb::real50, 2> acc = a[uk];
      cb::real50 scale = a[uk].norm();
      for (int i = 1; i <= k; ++i) {
        acc -= wt[static_cast<std::size_t>(i)] * cs[uk - static_cast<std::size_t>(i)];
        using std::abs;
        scale += abs(wt[static_cast<std::size_t>(i)]) * cs[uk - static_cast<std::size_t>(i)].norm();
      }
      cs[uk] = acc / wt[0];
      if (k > 0) fact *= k;
      const cb::point<cb::real50, 2> ref = fact * cs[uk];
      // The control points span 4 units: values are measured against that, derivatives against
      // their largest recurrence term (never below 1, C(0) = P0 = 0 at u = 0).
      using std::max;
      const cb::real50 ref_scale =
          k == 0 ? cb::real50(4) : max(cb::real50(fact * scale / wt[0] + ref.norm()), cb::real50(1));
      const double tol = k == 0 ? rational_value_ulps(4) : rational_derivative_ulps(k);
      for (auto alg : {cb::bspline_evaluation::de_boor, cb::bspline_evaluation::basis_sum})
        ASSERT_TRUE(cbt::point_within(c.evaluate(u, k, alg), ref, ref_scale, tol)) << "u=" << s << "/16 k=" << k;
    }
  }
  // End tangent of a rational Bezier: C'(0) = 3 (w1 / w0) (P1 - P0) = (9, 18) (closed form).
  EXPECT_TRUE(cbt::point_within(c.derivative(Real(0), 1), cb::point<cb::real50, 2>(9, 18), cb::real50(18), 8));
}

// Orders around the stack-buffer limit (32) and beyond, in 50 digits where the comparison is
// meaningful: the same series-quotient reference as above, through order 34 (the heap path).
// Also the homogeneous accessor: (W C, W).
TEST(nurbs_high_order, derivatives_beyond_the_stack_buffer) {
  using R = cb::real50;
  const cb::point_list<R, 2> p{{R(0), R(0)}, {R(1), R(2)}, {R(3), R(2)}, {R(4), R(0)}};
  const std::vector<R> w{R(1), R(3), R(1) / 2, R(2)};
  const cb::nurbs<R, 2> c(4, {R(0), R(0), R(0), R(0), R(1), R(1), R(1), R(1)}, p, w);
  constexpr int kmax = 34;
  const R u = R(3) / 8;
  std::vector<cb::point<R, 2>> a(kmax + 1), cs(kmax + 1);
  std::vector<R> wt(kmax + 1);
  R fact = 1;
  for (int k = 0; k <= kmax; ++k) {
    if (k > 0) fact *= k;
    a[static_cast<std::size_t>(k)] = cb::zero_point<R, 2>();
    wt[static_cast<std::size_t>(k)] = 0;
    for (int i = 0; i < 4; ++i) {
      const R bd = cb::basis::bernstein_derivative(3, i, u, k) / fact;
      a[static_cast<std::size_t>(k)] += bd * w[static_cast<std::size_t>(i)] * p[static_cast<std::size_t>(i)];
      wt[static_cast<std::size_t>(k)] += bd * w[static_cast<std::size_t>(i)];
    }
  }
  fact = 1;
  for (int k = 0; k <= kmax; ++k) {
    const auto uk = static_cast<std::size_t>(k);
    cb::point<R, 2> acc = a[uk];
    for (int i = 1; i <= k; ++i) acc -= wt[static_cast<std::size_t>(i)] * cs[uk - static_cast<std::size_t>(i)];
    cs[uk] = acc / wt[0];
    if (k > 0) fact *= k;
    if (k < 30) continue;
    const cb::point<R, 2> ref = fact * cs[uk];
    // 1e20 eps(real50) relative to the reference's size, i.e. 1e-30: the recurrence's rounding grows
    // with its sum of binomially weighted terms (2^k ~ 1.7e10 at k = 34) times their cancellation;
    // a wrong term would be off by O(1).
    ASSERT_TRUE(cbt::point_within(c.derivative(u, k), ref, ref.norm(), 1e20)) << "k=" << k;
  }
  const auto h = c.homogeneous(u, 0);
  const cb::point<R, 2> cu = c(u);
  EXPECT_TRUE(cbt::within_ulps(h[2], wt[0], 8));
  EXPECT_TRUE(cbt::point_within(cb::point<R, 2>(h.head<2>() / h[2]), cu, R(4), 8));
  // Equal weights: every derivative of order >= m is exactly zero (the weight differences vanish).
  const cb::nurbs<double, 2> flat(3, {0, 0, 0, 0.5, 1, 1, 1}, {{0, 0}, {1, 2}, {2, 0}, {3, 1}}, {2, 2, 2, 2});
  EXPECT_EQ(flat.derivative(0.7, 3), (cb::point<double, 2>(0, 0)));
  EXPECT_EQ(flat.derivative(0.7, 40), (cb::point<double, 2>(0, 0)));
}

// Bad input names the argument, the index and the rule; the knot checks are the B-spline's.
TEST(nurbs_bad_input, messages) {
  const cb::point_list<double, 2> p(4, cb::point<double, 2>(0, 0));
  const std::vector<double> t{0, 0, 0, 0.5, 1, 1, 1};
  auto message = [](auto&& f) -> std::string {
    try {
      f();
    } catch (const cb::invalid_input& e) {
      return e.what();
    }
    return "no exception";
  };
  EXPECT_EQ(message([&] {
              cb::nurbs<double, 2>(3, t, p, {1, 1, 1});
            }),
            "weights: 3 given, must match control_points: 4");
  EXPECT_EQ(message([&] { cb::nurbs<double, 2>(3, t, p, {1, 0, 1, 1}); }), "weights[1] = 0: must be > 0");
  EXPECT_EQ(message([&] { cb::nurbs<double, 2>(3, t, p, {1, 1, -2, 1}); }), "weights[2] = -2: must be > 0");
  EXPECT_EQ(message([&] {
              cb::nurbs<double, 2>(3, t, p, {1, 1, 1, std::numeric_limits<double>::quiet_NaN()});
            }),
            "weights[3] = nan: must be finite");
  EXPECT_EQ(message([&] {
              cb::nurbs<double, 2>(3, {0, 0, 0, 0.5, 0.25, 1, 1}, p, {1, 1, 1, 1});
            }),
            "knots must be non-decreasing: knots[4] = 0.25 < knots[3] = 0.5");
  EXPECT_EQ(message([&] {
              cb::nurbs<double, 2>(3, {0, 0, 0, 1, 1, 1}, p, {1, 1, 1, 1});
            }),
            "knots: 6 given, must be control_points + order = 4 + 3 = 7");
  EXPECT_EQ(message([&] { (void)cb::nurbs_circle_9<double>({0, 0}, -1.0); }), "radius = -1: must be > 0");
  const auto c = cb::nurbs_circle_7<double>({0, 0}, 1.0);
  EXPECT_THROW((void)c(1.5), std::domain_error);
  EXPECT_THROW((void)c.derivative(0.5, -1), cb::invalid_input);
}
