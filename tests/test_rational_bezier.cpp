// Rational Bezier curves: values against the 50-digit closed form sum B w P / sum B w (Bernstein
// closed form, not de Casteljau), derivatives against the 50-digit quotient rule (orders 1, 2) and
// against Richardson-extrapolated central differences of the 50-digit closed form (orders 3..5; a
// test-only reference, the library itself never differences), the circular arc on its circle, the
// conics' implicit equation and classification, and bad input.
#include "support/accuracy.hpp"
#include "support/fixtures.hpp"

#include "curvebench/basis/bernstein.hpp"
#include "curvebench/curves/rational_bezier.hpp"

#include <gmock/gmock.h>
#include <Eigen/LU>

#include <algorithm>
#include <array>
#include <cmath>
#include <iostream>
#include <limits>
#include <random>
#include <vector>

namespace cb = curvebench;
namespace cbt = curvebench::testing;
using cb::real50;
using ::testing::HasSubstr;

namespace {

static_assert(cb::curve<cb::rational_bezier<float, 2>>);
static_assert(cb::curve<cb::rational_bezier<double, 3>>);
static_assert(cb::curve<cb::rational_bezier<real50, 2>>);

// ---------------------------------------------------------------------------------------------
// Tolerances, in eps(Real) units. L is the degree, rho = max w / min w the weight ratio.
// - value(L) = (2 stable(L) + 2) of the scale max|P| * rho: the numerator A = sum B w P and the
//   denominator w are each de Casteljau sums (stable(L) = 2L + 4 ulps of max|w P| resp. max w, see
//   test_bezier.cpp), and dividing by w(t) >= min w scales both by at most rho; +2 for the division.
// - derivative(L, k) = value(L) * (2 rho)^k of the scale max_t |C^(k)|: each step of the Leibniz
//   recurrence divides by w and multiplies earlier derivatives by w^(j) / w (|w^(j) / w| grows like
//   rho per order relative to the derivative's own growth), so the error of order k is at most the
//   value's error amplified by ~(2 rho)^k. Measured: < 4 ulps for rho = 4, k <= 5. This holds for
//   control points around the origin (the random ones); for a curve far from the origin A^(k) and
//   w^(j) C carry errors of the size of max|P| that cancel to the much smaller C^(k), so the
//   error is bounded in the absolute scale S_k = max|P| (2 L rho)^k instead (the circle test).
// - on_circle = 8 ulps of r: the control points and the weight cos(theta/2) are rounded once each
//   (~4 roundings for sin/cos, products and sums, each moving the curve by O(1) ulps of r, since
//   the far middle point r / w enters multiplied by w), and the homogeneous de Casteljau of degree 2
//   adds 2 levels plus the division. Measured <= 2 ulps in every type.
// - conic equation tau1^2 - 4 w^2 tau0 tau2 = 0 (barycentric coordinates): the first-order
//   distance |F| / |grad F| of a sample from the conic is at most its value error, value(2).
double stable(int L) { return 2.0 * L + 4; }
double value_tol(int L) { return 2 * stable(L) + 2; }
double derivative_tol(int L, int k, double rho) { return value_tol(L) * std::pow(2 * rho, k); }
constexpr double on_circle = 8;
// Richardson-extrapolated central differences at 50 digits are accurate to ~1e-28 relative here
// (step 2^-8 halved 5 times, truncation O(h^12), rounding 1e-50 / h^k): that decides long double
// (eps 1e-19) easily, but not real50 itself, which is checked against the quotient rule only.

template <class Real>
class rational_test : public ::testing::Test {};
TYPED_TEST_SUITE(rational_test, cbt::all_reals);

template <class Real>
class rational_ieee_test : public ::testing::Test {};
TYPED_TEST_SUITE(rational_ieee_test, cbt::ieee_reals);

using cbt::random_points;

// Weights in [0.5, 2] (ratio <= 4), rounded to Real.
template <class Real>
std::vector<Real> random_weights(int count, unsigned seed) {
  std::mt19937 gen(seed);
  std::uniform_real_distribution<double> dist(-1.0, 1.0);
  std::vector<Real> w(static_cast<std::size_t>(count));
  for (auto& x : w) x = static_cast<Real>(std::exp2(dist(gen)));
  return w;
}

// The closed form in 50 digits: A(t), w(t) and their t-derivatives of order k from the closed-form
// derivatives of the Bernstein polynomials (basis/bernstein.hpp), independent of de Casteljau.
template <int Dim>
struct closed_form {
  cb::point_list<real50, Dim> p;
  std::vector<real50> w;
  real50 lo, hi;

  [[nodiscard]] int degree() const { return static_cast<int>(p.size()) - 1; }
  [[nodiscard]] real50 local(const real50& u) const { return (u - lo) / (hi - lo); }
  // d^k/du^k of A and w.
  void numerator_denominator(const real50& u, int k, cb::point<real50, Dim>& a, real50& den) const {
    const real50 t = local(u);
    a = cb::zero_point<real50, Dim>();
    den = 0;
    for (int i = 0; i <= degree(); ++i) {
      const auto ui = static_cast<std::size_t>(i);
      const real50 b = cb::basis::bernstein_derivative(degree(), i, t, k);
      a += (b * w[ui]) * p[ui];
      den += b * w[ui];
    }
    const real50 hk = cb::basis::pow_int(real50(hi - lo), k);
    a /= hk;
    den /= hk;
  }
  [[nodiscard]] cb::point<real50, Dim> value(const real50& u) const {
    cb::point<real50, Dim> a;
    real50 d;
    numerator_denominator(u, 0, a, d);
    return a / d;
  }
  // The quotient rule written out: C' = (A' - w' C) / w, C'' = (A'' - 2 w' C' - w'' C) / w.
  [[nodiscard]] cb::point<real50, Dim> quotient_rule(const real50& u, int k) const {
    cb::point<real50, Dim> a0, a1, a2;
    real50 w0, w1, w2;
    numerator_denominator(u, 0, a0, w0);
    numerator_denominator(u, 1, a1, w1);
    numerator_denominator(u, 2, a2, w2);
    const cb::point<real50, Dim> c0 = a0 / w0;
    const cb::point<real50, Dim> c1 = (a1 - w1 * c0) / w0;
    if (k == 1) return c1;
    return cb::point<real50, Dim>((a2 - 2 * w1 * c1 - w2 * c0) / w0);
  }
  // Richardson extrapolation of k-th order central differences (steps 2^-8 .. 2^-13).
  [[nodiscard]] cb::point<real50, Dim> richardson(const real50& u, int k) const {
    constexpr int levels = 6;
    std::array<std::array<cb::point<real50, Dim>, levels>, levels> r;
    real50 h = real50(1) / 256;
    for (int i = 0; i < levels; ++i, h /= 2) {
      cb::point<real50, Dim> sum = cb::zero_point<real50, Dim>();
      for (int j = 0; j <= k; ++j) {
        const real50 c = cb::binomial<real50>(k, j) * ((j % 2 == 0) ? 1 : -1);
        sum += c * value(u + (real50(k) / 2 - j) * h);
      }
      r[static_cast<std::size_t>(i)][0] = sum / cb::basis::pow_int(h, k);
      real50 four(4);
      for (int j = 1; j <= i; ++j, four *= 4) {
        const auto ui = static_cast<std::size_t>(i);
        const auto uj = static_cast<std::size_t>(j);
        r[ui][uj] = r[ui][uj - 1] + (r[ui][uj - 1] - r[ui - 1][uj - 1]) / (four - 1);
      }
    }
    return r[levels - 1][levels - 1];
  }
};

template <class Real, int Dim>
closed_form<Dim> closed_form_of(const cb::rational_bezier<Real, Dim>& c) {
  closed_form<Dim> f;
  for (const auto& q : c.control_points()) f.p.push_back(cb::point_cast<real50>(q));
  for (const auto& x : c.weights()) f.w.push_back(real50(x));
  f.lo = real50(c.domain().lo);
  f.hi = real50(c.domain().hi);
  return f;
}

template <class Real, int Dim>
real50 max_abs(std::span<const cb::point<Real, Dim>> p) {
  using std::abs;
  real50 m(0);
  for (const auto& q : p)
    for (int d = 0; d < Dim; ++d) m = std::max(m, real50(abs(q[d])));
  return m;
}

template <class Real>
double weight_ratio(std::span<const Real> w) {
  const auto [lo, hi] = std::minmax_element(w.begin(), w.end());
  return static_cast<double>(*hi / *lo);
}

}  // namespace

TYPED_TEST(rational_test, value_matches_50_digit_closed_form) {
  using Real = TypeParam;
  for (int L : {1, 2, 3, 6, 12}) {
    const auto p = random_points<Real, 3>(L + 1, static_cast<unsigned>(L));
    const auto w = random_weights<Real>(L + 1, static_cast<unsigned>(50 + L));
    const cb::rational_bezier<Real, 3> c(p, w, {Real(-1), Real(2)});
    const auto ref = closed_form_of(c);
    const double rho = weight_ratio<Real>(w);
    const real50 scale = max_abs<Real, 3>(p) * real50(rho);
    // + 2L: t = (u + 1) / 3 is rounded (the curve moves by |dC/dt| eps, |dC/dt| <= 2 L rho max|P|).
    for (int s = 0; s <= 60; ++s) {
      const Real u = Real(-1) + Real(3) * Real(s) / Real(60);
      ASSERT_TRUE(cbt::point_within(c(u), ref.value(real50(u)), scale, value_tol(L) + 2 * L)) << "L=" << L;
    }
    // End points interpolate exactly (w_0 P_0 / w_0 is P_0 up to one rounding of the product).
    EXPECT_TRUE(cbt::point_within(c(Real(-1)), cb::point_cast<real50>(p.front()), scale, 1));
    EXPECT_TRUE(cbt::point_within(c(Real(2)), cb::point_cast<real50>(p.back()), scale, 1));
  }
}

TYPED_TEST(rational_test, first_two_derivatives_match_50_digit_quotient_rule) {
  using Real = TypeParam;
  for (int L : {1, 2, 5, 9}) {
    const auto p = random_points<Real, 2>(L + 1, static_cast<unsigned>(70 + L));
    const auto w = random_weights<Real>(L + 1, static_cast<unsigned>(80 + L));
    const cb::rational_bezier<Real, 2> c(p, w);
    const auto ref = closed_form_of(c);
    const double rho = weight_ratio<Real>(w);
    for (int k : {1, 2}) {
      std::vector<cb::point<real50, 2>> want;
      real50 scale(0);
      for (int s = 0; s <= 40; ++s) {
        want.push_back(ref.quotient_rule(real50(s) / 40, k));
        scale = std::max(scale, real50(want.back().cwiseAbs().maxCoeff()));
      }
      for (int s = 0; s <= 40; ++s)
        ASSERT_TRUE(cbt::point_within(c.derivative(Real(s) / Real(40), k), want[static_cast<std::size_t>(s)], scale,
                                      derivative_tol(L, k, rho)))
            << "L=" << L << " k=" << k << " s=" << s;
    }
  }
}

TYPED_TEST(rational_ieee_test, higher_derivatives_match_50_digit_extrapolated_differences) {
  using Real = TypeParam;
  double worst = 0;
  for (int L : {2, 4}) {
    const auto p = random_points<Real, 2>(L + 1, static_cast<unsigned>(90 + L));
    const auto w = random_weights<Real>(L + 1, static_cast<unsigned>(95 + L));
    const cb::rational_bezier<Real, 2> c(p, w, {Real(0), Real(2)});
    const auto ref = closed_form_of(c);
    const double rho = weight_ratio<Real>(w);
    for (int k = 1; k <= 5; ++k) {  // orders beyond L included: they do not vanish
      std::vector<cb::point<real50, 2>> want;
      real50 scale(0);
      for (int s = 0; s <= 16; ++s) {
        want.push_back(ref.richardson(real50(s) / 8, k));
        scale = std::max(scale, real50(want.back().cwiseAbs().maxCoeff()));
      }
      for (int s = 0; s <= 16; ++s) {
        const cb::point<Real, 2> got = c.derivative(Real(s) / Real(8), k);
        const auto& ws = want[static_cast<std::size_t>(s)];
        ASSERT_TRUE(cbt::point_within(got, ws, scale, derivative_tol(L, k, rho))) << "L=" << L << " k=" << k;
        for (int d = 0; d < 2; ++d)
          worst = std::max(worst, static_cast<double>(cbt::scaled_ulps(got[d], ws[d], scale)));
      }
    }
  }
  std::cout << "rational derivatives of order <= 5, max error " << worst << " eps * max|C^(k)|\n";
}

TYPED_TEST(rational_test, equal_weights_give_the_polynomial_curve) {
  using Real = TypeParam;
  const int L = 5;
  const auto p = random_points<Real, 2>(L + 1, 3);
  const std::vector<Real> w(L + 1, Real(1.5));
  const cb::rational_bezier<Real, 2> r(p, w);
  const cb::bezier<Real, 2> b(p);
  // The weight differences are exact zeros, so C^(k) = (1.5 P)^(k) / 1.5: the polynomial curve's
  // derivative up to ~2 roundings of the hodograph scale L!/(L-k)! 2^k; order > L vanishes exactly.
  for (int k = 0; k <= L + 2; ++k) {
    real50 scale = max_abs<Real, 2>(p);
    for (int j = 0; j < std::min(k, L); ++j) scale *= 2 * (L - j);
    for (int s = 0; s <= 20; ++s) {
      const Real u = Real(s) / Real(20);
      if (k > L) {
        EXPECT_EQ(r.derivative(u, k), (cb::zero_point<Real, 2>()));
      } else {
        ASSERT_TRUE(
            cbt::point_within(r.derivative(u, k), cb::point_cast<real50>(b.derivative(u, k)), scale, 2 * stable(L)))
            << "k=" << k;
      }
    }
  }
}

TYPED_TEST(rational_test, circular_arc_lies_on_its_circle) {
  using Real = TypeParam;
  const cb::point<Real, 2> center(Real(0.5), Real(-2));
  const Real r(3);
  double worst = 0, worst_identity = 0;
  for (Real sweep : {Real(0.125), Real(1), Real(2), Real(3)}) {
    const auto arc = cb::circular_arc(center, r, Real(0.25), sweep);
    const double rho = 1 / std::cos(static_cast<double>(sweep) / 2);  // weights 1, cos(sweep/2), 1
    const double pmax = static_cast<double>(max_abs<Real, 2>(arc.control_points()));
    EXPECT_EQ(arc.conic_type(), cb::conic_kind::ellipse);
    const cb::point<real50, 2> c50 = cb::point_cast<real50>(center);
    for (int s = 0; s <= 200; ++s) {
      const Real u = Real(s) / Real(200);
      const cb::point<real50, 2> x = cb::point_cast<real50>(arc(u));
      const real50 dist = (x - c50).norm();
      const double err = static_cast<double>(cbt::scaled_ulps(r, dist, real50(r)));  // | r - |P - c| | / (eps r)
      worst = std::max(worst, err);
      ASSERT_LE(err, on_circle) << "sweep " << static_cast<double>(sweep) << " u " << static_cast<double>(u);
      // Every derivative of |C - c|^2 vanishes: with D = C - c, sum_j C(k, j) D^(j).D^(k-j) = 0, an
      // identity the Leibniz recurrence does not build in. Checked to k = 4 with the absolute
      // derivative scales S_j = max|P| (4 rho)^j (see the table: offset curves).
      for (int k = 1; k <= 4; ++k) {
        real50 sum(0), allowed(0);
        for (int j = 0; j <= k; ++j) {
          cb::point<real50, 2> a = cb::point_cast<real50>(arc.derivative(u, j));
          cb::point<real50, 2> b = cb::point_cast<real50>(arc.derivative(u, k - j));
          if (j == 0) a -= c50;
          if (j == k) b -= c50;
          sum += cb::binomial<real50>(k, j) * a.dot(b);
          // error of D^(j).D^(k-j) <~ S_j |D^(k-j)| + |D^(j)| S_(k-j)
          allowed += cb::binomial<real50>(k, j) * real50(pmax) *
                     (real50(std::pow(4 * rho, j)) * b.norm() + a.norm() * real50(std::pow(4 * rho, k - j)));
        }
        const double identity = static_cast<double>(abs(sum) / (allowed * real50(cb::epsilon<Real>())));
        worst_identity = std::max(worst_identity, identity);
        ASSERT_LE(identity, value_tol(2)) << "k=" << k;
      }
    }
    // The ends are at the start and end angles.
    using std::cos;
    using std::sin;
    const cb::point<Real, 2> e(center[0] + r * cos(Real(0.25) + sweep), center[1] + r * sin(Real(0.25) + sweep));
    EXPECT_TRUE(cbt::point_within(arc(Real(1)), cb::point_cast<real50>(e), real50(r), 4));
  }
  std::cout << "circular arc: max | |P - c| - r | = " << worst
            << " eps * r; derivative identity to order 4: " << worst_identity << " eps\n";
}

TYPED_TEST(rational_test, conics_satisfy_their_equation_and_classify) {
  using Real = TypeParam;
  const cb::point<Real, 2> p0(Real(0), Real(0)), p1(Real(1), Real(2)), p2(Real(3), Real(0.5));
  const cb::point<real50, 2> q0 = cb::point_cast<real50>(p0), q1 = cb::point_cast<real50>(p1),
                             q2 = cb::point_cast<real50>(p2);
  // Barycentric coordinates tau = M^-1 (x, y, 1) for the triangle P0 P1 P2, in 50 digits.
  Eigen::Matrix<real50, 3, 3> m;
  m << q0[0], q1[0], q2[0], q0[1], q1[1], q2[1], 1, 1, 1;
  const Eigen::Matrix<real50, 3, 3> mi = m.inverse();
  const struct {
    Real w;
    cb::conic_kind kind;
  } cases[] = {{Real(0.5), cb::conic_kind::ellipse},
               {Real(1), cb::conic_kind::parabola},
               {Real(2), cb::conic_kind::hyperbola},
               {Real(0.0625), cb::conic_kind::ellipse}};
  for (const auto& cs : cases) {
    const auto c = cb::conic(p0, p1, p2, cs.w);
    EXPECT_EQ(c.conic_type(), cs.kind) << cb::to_string(cs.kind);
    const real50 w(cs.w);
    // The implicit equation in barycentric coordinates, tau1^2 = 4 w^2 tau0 tau2 (from the weights
    // (1-t)^2 : 2 w t(1-t) : t^2), whose Cartesian quadratic part has discriminant B^2 - 4AC < 0,
    // = 0, > 0 for an ellipse, parabola, hyperbola: an independent check of the classification.
    const real50 a = mi(1, 0) * mi(1, 0) - 4 * w * w * mi(0, 0) * mi(2, 0);
    const real50 b = 2 * mi(1, 0) * mi(1, 1) - 4 * w * w * (mi(0, 0) * mi(2, 1) + mi(0, 1) * mi(2, 0));
    const real50 cc = mi(1, 1) * mi(1, 1) - 4 * w * w * mi(0, 1) * mi(2, 1);
    const real50 disc = b * b - 4 * a * cc;
    const real50 disc_scale = b * b + abs(4 * a * cc);
    const cb::conic_kind from_disc = disc < -disc_scale * real50(1e-40)  ? cb::conic_kind::ellipse
                                     : disc > disc_scale * real50(1e-40) ? cb::conic_kind::hyperbola
                                                                         : cb::conic_kind::parabola;
    EXPECT_EQ(from_disc, cs.kind) << cb::to_string(cs.kind);
    // Distance of each sample from the conic, |F| / |grad F| for F = tau1^2 - 4 w^2 tau0 tau2 (the
    // first-order geometric distance), in eps(Real) units of the scale max|P| * rho.
    const double rho = std::max(static_cast<double>(cs.w), 1 / static_cast<double>(cs.w));
    for (int s = 0; s <= 50; ++s) {
      const cb::point<real50, 2> x = cb::point_cast<real50>(c(Real(s) / Real(50)));
      const Eigen::Matrix<real50, 3, 1> tau = mi * Eigen::Matrix<real50, 3, 1>(x[0], x[1], real50(1));
      const real50 f = tau[1] * tau[1] - 4 * w * w * tau[0] * tau[2];
      cb::point<real50, 2> grad;
      for (int d = 0; d < 2; ++d) grad[d] = 2 * tau[1] * mi(1, d) - 4 * w * w * (tau[0] * mi(2, d) + tau[2] * mi(0, d));
      const real50 distance = abs(f) / grad.norm();
      ASSERT_LE(static_cast<double>(distance / (real50(3 * rho) * real50(cb::epsilon<Real>()))), value_tol(2))
          << cb::to_string(cs.kind) << " s=" << s;
    }
    if (cs.kind == cb::conic_kind::parabola) {
      // w = 1 is the polynomial quadratic: the same curve as the Bezier curve of the three points.
      const cb::bezier<Real, 2> q(cb::point_list<Real, 2>{p0, p1, p2});
      for (int s = 0; s <= 50; ++s)
        ASSERT_TRUE(cbt::point_within(c(Real(s) / Real(50)), cb::point_cast<real50>(q(Real(s) / Real(50))), real50(3),
                                      2 * stable(2)));
    }
  }
}

TEST(rational_bad_input, messages_name_argument_index_and_value) {
  using P = cb::point<double, 2>;
  const auto message_of = [](auto&& make) -> std::string {
    try {
      make();
    } catch (const cb::invalid_input& e) {
      return e.what();
    }
    return "no exception";
  };
  const cb::point_list<double, 2> three{P(0, 0), P(1, 1), P(2, 0)};
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  using R = cb::rational_bezier<double, 2>;
  EXPECT_THAT(message_of([] { R c(cb::point_list<double, 2>{}, std::vector<double>{}); }),
              HasSubstr("control_points: 0 given, at least 2 required"));
  EXPECT_THAT(message_of([] { R c(cb::point_list<double, 2>{P(0, 0)}, std::vector<double>{1}); }),
              HasSubstr("control_points: 1 given, at least 2 required"));
  EXPECT_THAT(message_of([&] {
                R c(three, std::vector<double>{1, 1});
              }),
              HasSubstr("weights: 2 given, must match control_points: 3"));
  EXPECT_THAT(message_of([&] { R c(three, std::vector<double>{1, 0, 1}); }), HasSubstr("weights[1] = 0: must be > 0"));
  EXPECT_THAT(message_of([&] {
                R c(three, std::vector<double>{1, 1, -2});
              }),
              HasSubstr("weights[2] = -2: must be > 0"));
  EXPECT_THAT(message_of([&] {
                R c(three, std::vector<double>{nan, 1, 1});
              }),
              HasSubstr("weights[0] = nan: must be finite"));
  EXPECT_THAT(message_of([&] {
                R c(three, std::vector<double>{1, inf, 1});
              }),
              HasSubstr("weights[1] = inf: must be finite"));
  EXPECT_THAT(message_of([&] {
                R c(cb::point_list<double, 2>{P(0, 0), P(0, inf)}, std::vector<double>{1, 1});
              }),
              HasSubstr("control_points[1][1] = inf: coordinates must be finite"));
  EXPECT_THAT(message_of([&] {
                R c(three, std::vector<double>{1, 1, 1}, {2.0, 1.0});
              }),
              HasSubstr("domain = [2, 1]: must have lo < hi"));
  EXPECT_THAT(message_of([] { (void)cb::conic(P(0, 0), P(1, 1), P(2, 0), 0.0); }), HasSubstr("w = 0: must be > 0"));
  EXPECT_THAT(message_of([] { (void)cb::circular_arc(P(0, 0), 1.0, 0.0, 3.5); }),
              HasSubstr("sweep = 3.5: must be in (0, pi)"));
  EXPECT_THAT(message_of([] { (void)cb::circular_arc(P(0, 0), 0.0, 0.0, 1.0); }), HasSubstr("radius = 0: must be > 0"));
  EXPECT_THAT(message_of([] {
                (void)cb::rational_bezier<double, 2>(cb::point_list<double, 2>{P(0, 0), P(1, 1), P(2, 0), P(3, 3)},
                                                     std::vector<double>{1, 1, 1, 1})
                    .conic_type();
              }),
              HasSubstr("conic_type: degree = 3, only a rational quadratic is a conic"));
  const R c(three, std::vector<double>{1, 2, 1});
  EXPECT_THAT(message_of([&] { (void)c.derivative(0.5, -2); }), HasSubstr("order = -2: derivative order must be >= 0"));
  EXPECT_THROW((void)c(1.5), std::domain_error);
  EXPECT_THROW((void)c.derivative(-0.5, 3), std::domain_error);
}
