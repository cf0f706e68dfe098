// Bezier curves: the three evaluation algorithms against the real50 de Casteljau reference,
// derivatives against the 50-digit derivative of the Bernstein sum (basis::bernstein_derivative,
// an independent code path), and the properties of the family: endpoint interpolation, partition of
// unity, affine invariance, convex hull, variation diminishing, linear precision, reversal,
// subdivision and degree elevation.
#include "support/accuracy.hpp"
#include "support/fixtures.hpp"

#include "curvebench/basis/bernstein.hpp"
#include "curvebench/curves/bezier.hpp"

#include <gmock/gmock.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <limits>
#include <random>
#include <vector>

namespace cb = curvebench;
namespace cbt = curvebench::testing;
using ::testing::HasSubstr;
using alg = cb::bezier_algorithm;

namespace {

static_assert(cb::curve<cb::bezier<float, 2>>);
static_assert(cb::curve<cb::bezier<double, 3>>);
static_assert(cb::curve<cb::bezier<long double, 1>>);
static_assert(cb::curve<cb::bezier<cb::real50, 4>>);

// ---------------------------------------------------------------------------------------------
// Tolerances, in eps(Real) units of the scale each test names (the largest control coordinate
// unless stated otherwise). L is the degree.
// - stable(L) = 2L + 4: de Casteljau is L levels of convex combinations (1-t) b_i + t b_{i+1},
//   each level adding at most ~2 roundings relative to the scale (plus the rounding of 1 - t);
//   the Bernstein sum multiplies ~L rounded factors per term with non-negative weights and adds
//   L terms. Measured: <= 4 ulps at L = 20 (see degree_20_error_by_algorithm).
// - param(L) = 2L: mapping u -> t = (u - a) / (b - a) on a domain other than [0, 1] rounds t once;
//   the value moves by |dP/dt| eps <= 2L scale eps.
// - horner(L) = 4 * 3^L: the conversion a_j = C(L,j) sum_i (-1)^(j-i) C(j,i) P_i carries an error
//   ~ C(L,j) 2^j eps scale in a_j, and sum_j C(L,j) 2^j = 3^L bounds the sum for t in [0, 1].
//   This is the a-priori bound, deliberately loose; the measured loss at L = 20 is ~3e8 ulps.
// - derivative of order k: the same bounds plus 2k for the k levels of differences, relative to
//   the derivative scale L!/(L-k)! 2^k max|P| / (b-a)^k (the bound of the hodograph's points).
// - elevation: each new control point is (i P_{i-1} + (L+1-i) P_i) / (L+1): 3 roundings, then
//   evaluated at degree L + 1: stable(L + 1) + 3.
// - subdivision: the pieces' control points are de Casteljau intermediates (stable(L) each), then
//   evaluated on a sub-interval (param(L) for the re-mapped t) by de Casteljau (stable(L)).
double stable(int L) { return 2.0 * L + 4; }
double param(int L) { return 2.0 * L; }
double horner(int L) { return 4.0 * std::pow(3.0, L); }
double tolerance(alg a, int L) { return a == alg::horner ? horner(L) : stable(L); }
double elevation(int L) { return stable(L + 1) + 3; }
double subdivision(int L) { return 2 * stable(L) + param(L); }
// Degree 20 in float: horner(20) is 1.4e10 float ulps = 1.7e3 times the scale, i.e. no accuracy at
// all; the loose bound still catches a broken conversion (wrong sign or binomial gives O(1) errors
// in every type, which in double is 5e15 ulps).

constexpr std::array<alg, 3> all_algorithms{alg::de_casteljau, alg::bernstein_sum, alg::horner};

template <class Real>
class bezier_test : public ::testing::Test {};
TYPED_TEST_SUITE(bezier_test, cbt::all_reals);

template <class Real>
class bezier_ieee_test : public ::testing::Test {};
TYPED_TEST_SUITE(bezier_ieee_test, cbt::ieee_reals);

// Random control points in [-1, 1]^Dim, rounded to Real (so the real50 copy is exact).
using cbt::random_points;

template <class Real, int Dim>
cb::point_list<cb::real50, Dim> to50(std::span<const cb::point<Real, Dim>> p) {
  return cb::points_cast<cb::real50>(p);
}

template <class Real, int Dim>
cb::real50 max_abs(std::span<const cb::point<Real, Dim>> p) {
  using std::abs;
  cb::real50 m(0);
  for (const auto& q : p)
    for (int d = 0; d < Dim; ++d) m = std::max(m, cb::real50(abs(q[d])));
  return m;
}

template <class Real, int Dim>
cb::bezier<cb::real50, Dim> reference_of(const cb::bezier<Real, Dim>& c) {
  return cb::bezier<cb::real50, Dim>(to50<Real, Dim>(c.control_points()),
                                     {cb::real50(c.domain().lo), cb::real50(c.domain().hi)});
}

// The k-th derivative in u of the Bernstein sum, in 50 digits, from the closed-form derivative of
// each basis function: sum_i d^k/dt^k B_i^L(t) P_i / h^k. Shares no code with the hodograph.
template <int Dim>
cb::point<cb::real50, Dim> bernstein_derivative_reference(std::span<const cb::point<cb::real50, Dim>> p,
                                                          const cb::interval<cb::real50>& dom, const cb::real50& u,
                                                          int k) {
  const int L = static_cast<int>(p.size()) - 1;
  const cb::real50 h = dom.hi - dom.lo;
  const cb::real50 t = (u - dom.lo) / h;
  cb::point<cb::real50, Dim> sum = cb::zero_point<cb::real50, Dim>();
  for (int i = 0; i <= L; ++i) sum += cb::basis::bernstein_derivative(L, i, t, k) * p[static_cast<std::size_t>(i)];
  return sum / cb::basis::pow_int(h, k);
}

// Parameters spread over the domain, computed in Real (the reference uses the same rounded values).
template <class Real>
Real spread(const cb::interval<Real>& d, int k, int count) {
  return d.lo + (d.hi - d.lo) * Real(k) / Real(count - 1);
}

// Max error of each algorithm over `count` parameters, in eps(Real) units of the control-point
// scale, against the real50 de Casteljau of the same (exactly converted) points.
template <class Real, int Dim, std::size_t N>
std::array<double, N> max_value_errors(const cb::bezier<Real, Dim>& c, const std::array<alg, N>& algorithms,
                                       int count) {
  const auto ref = reference_of(c);
  const cb::real50 scale = max_abs<Real, Dim>(c.control_points());
  std::array<double, N> worst{};
  for (int k = 0; k < count; ++k) {
    const Real u = spread(c.domain(), k, count);
    const cb::point<cb::real50, Dim> want = ref(cb::real50(u));
    for (std::size_t i = 0; i < N; ++i) {
      const cb::point<Real, Dim> got = c.evaluate(u, algorithms[i]);
      for (int d = 0; d < Dim; ++d)
        worst[i] = std::max(worst[i], static_cast<double>(cbt::scaled_ulps(got[d], want[d], scale)));
    }
  }
  return worst;
}

// 2D convex hull (Andrew's monotone chain) of exact real50 points, counter-clockwise.
std::vector<cb::point<cb::real50, 2>> convex_hull(std::vector<cb::point<cb::real50, 2>> p) {
  std::sort(p.begin(), p.end(),
            [](const auto& a, const auto& b) { return a[0] < b[0] || (a[0] == b[0] && a[1] < b[1]); });
  const auto cross = [](const auto& o, const auto& a, const auto& b) {
    return cb::real50((a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0]));
  };
  std::vector<cb::point<cb::real50, 2>> h(2 * p.size());
  std::size_t k = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    while (k >= 2 && cross(h[k - 2], h[k - 1], p[i]) <= 0) --k;
    h[k++] = p[i];
  }
  for (std::size_t i = p.size() - 1, lower = k + 1; i-- > 0;) {
    while (k >= lower && cross(h[k - 2], h[k - 1], p[i]) <= 0) --k;
    h[k++] = p[i];
  }
  h.resize(k - 1);
  return h;
}

// Sign changes of a sequence, ignoring values within `dead` of zero.
int sign_changes(const std::vector<cb::real50>& f, const cb::real50& dead) {
  int changes = 0;
  int last = 0;
  for (const auto& v : f) {
    const int s = v > dead ? 1 : (v < -dead ? -1 : 0);
    if (s == 0) continue;
    if (last != 0 && s != last) ++changes;
    last = s;
  }
  return changes;
}

}  // namespace

// ---------------------------------------------------------------------------------------------
// Accuracy of each algorithm

TYPED_TEST(bezier_ieee_test, each_algorithm_matches_real50_de_casteljau) {
  using Real = TypeParam;
  for (int L : {1, 2, 3, 5, 7, 12, 20}) {
    const auto p = random_points<Real, 3>(L + 1, static_cast<unsigned>(100 + L));
    const cb::bezier<Real, 3> c(p);
    const auto errors = max_value_errors(c, all_algorithms, 257);
    for (std::size_t i = 0; i < errors.size(); ++i)
      EXPECT_LE(errors[i], tolerance(all_algorithms[i], L)) << cb::to_string(all_algorithms[i]) << " L=" << L;
  }
}

TEST(bezier_real50, algorithms_agree_in_50_digits) {
  // At 50 digits (eps 2^-166) even Horner's 3^L loss leaves ~130 bits at L = 20: all three agree.
  const auto p = random_points<cb::real50, 2>(21, 5);
  const cb::bezier<cb::real50, 2> c(p);
  for (int k = 0; k <= 64; ++k) {
    const cb::real50 u = cb::real50(k) / 64;
    const cb::point<cb::real50, 2> ref = c(u);
    for (alg a : all_algorithms)
      EXPECT_TRUE(cbt::point_within(c.evaluate(u, a), ref, cb::real50(1), tolerance(a, 20))) << cb::to_string(a);
  }
}

// The measurement for the README: each algorithm on degree-20 curves, max error over 1000
// parameters (and 5 random curves) against 50 digits, in ulps of the curve's scale (the largest
// control coordinate), for float, double and long double.
TEST(bezier_measure, degree_20_error_by_algorithm) {
  constexpr int L = 20;
  constexpr int samples = 1000;
  struct row {
    double f = 0, d = 0, ld = 0;
  };
  std::array<row, 3> worst{};
  for (unsigned seed = 1; seed <= 5; ++seed) {
    const cb::bezier<float, 2> cf(random_points<float, 2>(L + 1, seed));
    const cb::bezier<double, 2> cd(random_points<double, 2>(L + 1, seed));
    const cb::bezier<long double, 2> cl(random_points<long double, 2>(L + 1, seed));
    const auto ef = max_value_errors(cf, all_algorithms, samples);
    const auto ed = max_value_errors(cd, all_algorithms, samples);
    const auto el = max_value_errors(cl, all_algorithms, samples);
    for (std::size_t i = 0; i < all_algorithms.size(); ++i) {
      worst[i].f = std::max(worst[i].f, ef[i]);
      worst[i].d = std::max(worst[i].d, ed[i]);
      worst[i].ld = std::max(worst[i].ld, el[i]);
    }
  }
  std::cout << "Bezier degree " << L << ", max |error| / (eps(Real) * max|P_i|) over " << samples
            << " parameters x 5 random curves, against real50:\n"
            << "  algorithm       float          double         long double\n";
  for (std::size_t i = 0; i < all_algorithms.size(); ++i) {
    std::cout << "  " << std::left << std::setw(15) << cb::to_string(all_algorithms[i]) << std::setw(15) << worst[i].f
              << std::setw(15) << worst[i].d << worst[i].ld << "\n";
    for (double w : {worst[i].f, worst[i].d, worst[i].ld}) EXPECT_LE(w, tolerance(all_algorithms[i], L));
  }
  // The power basis really does lose accuracy at degree 20 (this is what the bench measures): a
  // conversion that stopped cancelling would be a change worth noticing, so assert the loss too.
  EXPECT_GT(worst[2].d, 1e4);
  EXPECT_LT(worst[0].d, 10.0);
  EXPECT_LT(worst[1].d, 10.0);
}

// ---------------------------------------------------------------------------------------------
// Derivatives

TYPED_TEST(bezier_test, derivatives_match_50_digit_bernstein_derivative) {
  using Real = TypeParam;
  const cb::interval<Real> dom{Real(-1), Real(2)};  // h = 3: t = (u + 1) / 3 is rounded (param(L))
  for (int L : {1, 3, 7, 12}) {
    const auto p = random_points<Real, 2>(L + 1, static_cast<unsigned>(200 + L));
    const cb::bezier<Real, 2> c(p, dom);
    const auto p50 = to50<Real, 2>(c.control_points());
    const cb::interval<cb::real50> dom50{cb::real50(-1), cb::real50(2)};
    for (int k = 0; k <= L + 1; ++k) {
      // derivative scale L!/(L-k)! 2^k max|P| / h^k
      cb::real50 scale = max_abs<Real, 2>(p);
      for (int j = 0; j < k; ++j) scale *= cb::real50(2 * (L - j)) / cb::real50(3);
      if (k > L) scale = max_abs<Real, 2>(p);
      for (alg a : all_algorithms) {
        if (a == alg::horner && L > 7) continue;  // covered by the value test; 3^12 says nothing here
        const double tol = tolerance(a, L) + param(L) + 2.0 * k;
        for (int s = 0; s <= 40; ++s) {
          const Real u = spread(dom, s, 41);
          const cb::point<Real, 2> got = c.derivative(u, k, a);
          const auto want = bernstein_derivative_reference<2>(p50, dom50, cb::real50(u), k);
          ASSERT_TRUE(cbt::point_within(got, want, scale, tol)) << cb::to_string(a) << " L=" << L << " k=" << k;
        }
      }
    }
    // Order > L vanishes exactly; order 0 is the value.
    EXPECT_EQ(c.derivative(Real(0), L + 1), (cb::zero_point<Real, 2>()));
    EXPECT_EQ(c.derivative(Real(0), L + 5, alg::horner), (cb::zero_point<Real, 2>()));
    EXPECT_EQ(c.derivative(Real(1), 0), c(Real(1)));
  }
}

TYPED_TEST(bezier_test, hodograph_is_the_first_derivative_curve) {
  using Real = TypeParam;
  for (int L : {1, 2, 6}) {
    const auto p = random_points<Real, 2>(L + 1, static_cast<unsigned>(300 + L));
    const cb::bezier<Real, 2> c(p, {Real(0), Real(4)});
    const cb::bezier<Real, 2> h = c.hodograph();
    EXPECT_EQ(h.degree(), std::max(L - 1, 1));
    EXPECT_EQ(h.domain().lo, Real(0));
    EXPECT_EQ(h.domain().hi, Real(4));
    // Its control points are L (P_{i+1} - P_i) / 4 (exact division by 4; one rounding each for the
    // difference and the product: 2 ulps of the scale L * 2 max|P| / 4).
    const cb::real50 scale = cb::real50(L) * 2 * max_abs<Real, 2>(p) / 4;
    for (int i = 0; i < L; ++i) {
      const auto ui = static_cast<std::size_t>(i);
      const cb::point<cb::real50, 2> want = cb::real50(L) * (to50<Real, 2>(p)[ui + 1] - to50<Real, 2>(p)[ui]) / 4;
      EXPECT_TRUE(cbt::point_within(h.control_points()[ui], want, scale, 2.0));
    }
    // and it evaluates to the second-order data of the curve: h' = c''.
    for (int s = 0; s <= 8; ++s) {
      const Real u = Real(s) / Real(2);
      EXPECT_TRUE(
          cbt::point_within(h.derivative(u, 1), cb::point_cast<cb::real50>(c.derivative(u, 2)), scale * L, stable(L)));
    }
  }
}

// ---------------------------------------------------------------------------------------------
// Properties

TYPED_TEST(bezier_test, endpoints_interpolate) {
  using Real = TypeParam;
  for (int L : {1, 4, 20}) {
    const auto p = random_points<Real, 3>(L + 1, static_cast<unsigned>(L));
    const cb::bezier<Real, 3> c(p, {Real(-1), Real(2)});
    // de Casteljau and the Bernstein sum reproduce the end control points exactly: at t = 0 or 1
    // every other weight is an exact zero.
    for (alg a : {alg::de_casteljau, alg::bernstein_sum}) {
      EXPECT_EQ(c.evaluate(Real(-1), a), p.front()) << cb::to_string(a);
      EXPECT_EQ(c.evaluate(Real(2), a), p.back()) << cb::to_string(a);
    }
    // Horner gives a_0 = P_0 exactly at t = 0; at t = 1 it sums the rounded coefficients.
    EXPECT_EQ(c.evaluate(Real(-1), alg::horner), p.front());
    EXPECT_TRUE(
        cbt::point_within(c.evaluate(Real(2), alg::horner), to50<Real, 3>(p).back(), max_abs<Real, 3>(p), horner(L)));
  }
}

TYPED_TEST(bezier_test, partition_of_unity) {
  using Real = TypeParam;
  // Equal control points: the value is sum_i B_i^L(t) c, so c itself iff the weights sum to 1.
  const cb::point<Real, 2> k(Real(0.75), Real(-3));
  for (int L : {1, 5, 20}) {
    const cb::bezier<Real, 2> c(cb::point_list<Real, 2>(static_cast<std::size_t>(L) + 1, k));
    const cb::point<cb::real50, 2> want(cb::real50(0.75), cb::real50(-3));
    for (alg a : all_algorithms)
      for (int s = 0; s <= 100; ++s)
        ASSERT_TRUE(cbt::point_within(c.evaluate(Real(s) / Real(100), a), want, cb::real50(3), tolerance(a, L)))
            << cb::to_string(a) << " L=" << L;
  }
}

TYPED_TEST(bezier_test, affine_invariance) {
  using Real = TypeParam;
  const int L = 6;
  const auto p = random_points<Real, 2>(L + 1, 17);
  Eigen::Matrix<Real, 2, 2> m;
  m << Real(1.5), Real(-0.25), Real(0.5), Real(2);
  const cb::point<Real, 2> b(Real(3), Real(-1));
  cb::point_list<Real, 2> q;
  for (const auto& x : p) q.push_back(cb::point<Real, 2>(m * x + b));
  const cb::bezier<Real, 2> cp(p), cq(q);
  // Both sides carry the evaluation error (stable(L) of scales <= |m| max|P| and max|Q|) plus the
  // rounding of the transform itself (3 ulps of max|Q| <= 5.25): 2 stable(L) + 3 of scale 6.
  for (alg a : {alg::de_casteljau, alg::bernstein_sum})
    for (int s = 0; s <= 50; ++s) {
      const Real u = Real(s) / Real(50);
      const cb::point<Real, 2> x = cp.evaluate(u, a);
      const cb::point<Real, 2> tx = m * x + b;
      const cb::point<Real, 2> y = cq.evaluate(u, a);
      ASSERT_TRUE(cbt::point_within(y, cb::point_cast<cb::real50>(tx), cb::real50(6), 2 * stable(L) + 3))
          << cb::to_string(a);
    }
}

TYPED_TEST(bezier_test, convex_hull) {
  using Real = TypeParam;
  for (unsigned seed = 1; seed <= 4; ++seed) {
    const int L = 5 + static_cast<int>(seed);
    // A real 2D hull test: every sample is on the inner side of every hull edge (half-plane test,
    // exact in real50), up to the evaluation error stable(L) * eps * scale.
    const auto p = random_points<Real, 2>(L + 1, seed);
    const cb::bezier<Real, 2> c(p);
    const auto hull = convex_hull(to50<Real, 2>(std::span<const cb::point<Real, 2>>(p)));
    const cb::real50 slack = cb::real50(stable(L)) * cb::real50(cb::epsilon<Real>()) * max_abs<Real, 2>(p);
    for (alg a : {alg::de_casteljau, alg::bernstein_sum})
      for (int s = 0; s <= 200; ++s) {
        const cb::point<cb::real50, 2> x = cb::point_cast<cb::real50>(c.evaluate(Real(s) / Real(200), a));
        for (std::size_t e = 0; e < hull.size(); ++e) {
          const auto& o = hull[e];
          const auto& d = hull[(e + 1) % hull.size()];
          const cb::point<cb::real50, 2> edge = d - o;
          const cb::real50 side = edge[0] * (x[1] - o[1]) - edge[1] * (x[0] - o[0]);  // >= 0: inside
          ASSERT_GE(side, -slack * edge.norm()) << cb::to_string(a) << " seed " << seed << " edge " << e;
        }
      }
    // The weaker per-coordinate box check in 3D.
    const auto p3 = random_points<Real, 3>(L + 1, seed + 50);
    const cb::bezier<Real, 3> c3(p3);
    for (int s = 0; s <= 200; ++s) {
      const cb::point<Real, 3> x = c3(Real(s) / Real(200));
      for (int d = 0; d < 3; ++d) {
        Real lo = p3[0][d], hi = p3[0][d];
        for (const auto& q : p3) lo = std::min(lo, q[d]), hi = std::max(hi, q[d]);
        const Real pad = Real(stable(L)) * cb::epsilon<Real>();  // scale <= 1
        ASSERT_GE(x[d], lo - pad);
        ASSERT_LE(x[d], hi + pad);
      }
    }
  }
}

TYPED_TEST(bezier_test, variation_diminishing) {
  using Real = TypeParam;
  std::mt19937 gen(99);
  std::uniform_real_distribution<double> dist(-1.0, 1.0);
  int lines_that_cross = 0;
  for (unsigned seed = 1; seed <= 3; ++seed) {
    const int L = 7;
    const auto p = random_points<Real, 2>(L + 1, seed + 10);
    const cb::bezier<Real, 2> c(p);
    const auto p50 = to50<Real, 2>(std::span<const cb::point<Real, 2>>(p));
    std::vector<cb::point<cb::real50, 2>> samples;
    for (int s = 0; s <= 2000; ++s) samples.push_back(cb::point_cast<cb::real50>(c(Real(s) / Real(2000))));
    for (int line = 0; line < 30; ++line) {
      // Line n . (x - o) = 0 with o in the box and a random direction; evaluated in real50.
      const cb::point<cb::real50, 2> o(cb::real50(0.5 * dist(gen)), cb::real50(0.5 * dist(gen)));
      const double ang = 3.14159 * (dist(gen) + 1);
      const cb::point<cb::real50, 2> n(cb::real50(std::cos(ang)), cb::real50(std::sin(ang)));
      std::vector<cb::real50> poly, curve;
      for (const auto& q : p50) poly.push_back(n.dot(q - o));
      for (const auto& x : samples) curve.push_back(n.dot(x - o));
      // Samples within the evaluation error of the line are not counted as a side (a grazing
      // touch must not count as two crossings); the polygon vertices are exact.
      const cb::real50 dead = cb::real50(stable(L)) * cb::real50(cb::epsilon<Real>()) * 2;
      const int crossings = sign_changes(curve, dead);
      lines_that_cross += crossings > 0;
      ASSERT_LE(crossings, sign_changes(poly, cb::real50(0))) << "seed " << seed << " line " << line;
    }
  }
  EXPECT_GT(lines_that_cross, 20);  // the test saw crossings, it is not vacuous
}

TYPED_TEST(bezier_test, linear_precision_and_reversal) {
  using Real = TypeParam;
  // Evenly spaced collinear control points (i, 2i), L = 4: P(t) = (4t, 8t), exact for t = s/64.
  cb::point_list<Real, 2> p;
  for (int i = 0; i <= 4; ++i) p.emplace_back(Real(i), Real(2 * i));
  const cb::bezier<Real, 2> c(p);
  for (int s = 0; s <= 64; ++s) {
    const Real t = Real(s) / Real(64);
    const cb::point<cb::real50, 2> want(cb::real50(4 * s) / 64, cb::real50(8 * s) / 64);
    for (alg a : all_algorithms) ASSERT_TRUE(cbt::point_within(c.evaluate(t, a), want, cb::real50(8), tolerance(a, 4)));
  }
  // Reversed control points trace the curve backwards. With t dyadic, 1 - t is exact and de
  // Casteljau performs the same products in mirrored order: bit-for-bit equal.
  const auto q = random_points<Real, 2>(10, 5);
  const cb::point_list<Real, 2> r(q.rbegin(), q.rend());
  const cb::bezier<Real, 2> cq(q), cr(r);
  for (int s = 0; s <= 64; ++s) {
    const Real t = Real(s) / Real(64);
    EXPECT_EQ(cq(t), cr(Real(1) - t));
    EXPECT_TRUE(cbt::point_within(cr.evaluate(Real(1) - t, alg::bernstein_sum), cb::point_cast<cb::real50>(cq(t)),
                                  cb::real50(1), 2 * stable(9)));
  }
}

TYPED_TEST(bezier_test, subdivision_leaves_the_curve_unchanged) {
  using Real = TypeParam;
  for (int L : {1, 3, 9}) {
    const auto p = random_points<Real, 2>(L + 1, static_cast<unsigned>(400 + L));
    const cb::bezier<Real, 2> c(p, {Real(1), Real(3)});
    const auto ref = reference_of(c);
    const cb::real50 scale = max_abs<Real, 2>(p);
    for (Real at : {Real(1.25), Real(2), Real(2.6)}) {
      const auto [left, right] = c.split(at);
      EXPECT_EQ(left.degree(), L);
      EXPECT_EQ(left.domain().hi, at);
      EXPECT_EQ(right.domain().lo, at);
      EXPECT_EQ(left.control_points().front(), p.front());  // the outer ends are copied
      EXPECT_EQ(right.control_points().back(), p.back());
      EXPECT_EQ(left.control_points().back(), right.control_points().front());  // they meet exactly
      for (int s = 0; s <= 40; ++s) {
        const Real ul = spread(left.domain(), s, 41), ur = spread(right.domain(), s, 41);
        ASSERT_TRUE(cbt::point_within(left(ul), ref(cb::real50(ul)), scale, subdivision(L)));
        ASSERT_TRUE(cbt::point_within(right(ur), ref(cb::real50(ur)), scale, subdivision(L)));
      }
    }
  }
}

TYPED_TEST(bezier_test, degree_elevation_leaves_the_curve_unchanged) {
  using Real = TypeParam;
  for (int L : {1, 4, 10}) {
    const auto p = random_points<Real, 3>(L + 1, static_cast<unsigned>(500 + L));
    const cb::bezier<Real, 3> c(p, {Real(0), Real(2)});
    const cb::bezier<Real, 3> e = c.elevate();
    EXPECT_EQ(e.degree(), L + 1);
    EXPECT_EQ(e.control_points().front(), p.front());
    EXPECT_EQ(e.control_points().back(), p.back());
    const auto ref = reference_of(c);
    const cb::real50 scale = max_abs<Real, 3>(p);
    for (int s = 0; s <= 60; ++s) {
      const Real u = spread(c.domain(), s, 61);
      ASSERT_TRUE(cbt::point_within(e(u), ref(cb::real50(u)), scale, elevation(L)));
    }
    // Twice more: the elevated control polygon converges towards the curve, the curve stays.
    const cb::bezier<Real, 3> e3 = e.elevate().elevate();
    for (int s = 0; s <= 60; ++s) {
      const Real u = spread(c.domain(), s, 61);
      ASSERT_TRUE(cbt::point_within(e3(u), ref(cb::real50(u)), scale, elevation(L + 2) + 6));
    }
  }
}

TYPED_TEST(bezier_test, batch_evaluation_equals_single_evaluation) {
  using Real = TypeParam;
  const auto p = random_points<Real, 2>(8, 23);
  const cb::bezier<Real, 2> c(p, {Real(-2), Real(1)});
  std::vector<Real> us;
  for (int s = 0; s <= 30; ++s) us.push_back(spread(c.domain(), (s * 7) % 31, 31));  // unsorted on purpose
  std::vector<cb::point<Real, 2>> out(us.size());
  for (alg a : all_algorithms)
    for (int order : {0, 2}) {
      c.evaluate(std::span<const Real>(us), std::span<cb::point<Real, 2>>(out), a, order);
      for (std::size_t i = 0; i < us.size(); ++i) ASSERT_EQ(out[i], c.derivative(us[i], order, a));
    }
}

// ---------------------------------------------------------------------------------------------
// Bad input

TEST(bezier_bad_input, messages_name_argument_index_and_value) {
  using P = cb::point<double, 2>;
  const auto message_of = [](auto&& make) -> std::string {
    try {
      make();
    } catch (const cb::invalid_input& e) {
      return e.what();
    }
    return "no exception";
  };
  EXPECT_THAT(message_of([] { cb::bezier<double, 2> c(cb::point_list<double, 2>{}); }),
              HasSubstr("control_points: 0 given, at least 2 required"));
  EXPECT_THAT(message_of([] { cb::bezier<double, 2> c(cb::point_list<double, 2>{P(1, 2)}); }),
              HasSubstr("control_points: 1 given, at least 2 required"));
  EXPECT_THAT(message_of([] {
                cb::bezier<double, 2> c(
                    cb::point_list<double, 2>{P(0, 0), P(1, 1), P(2, std::numeric_limits<double>::quiet_NaN())});
              }),
              HasSubstr("control_points[2][1] = nan: coordinates must be finite"));
  EXPECT_THAT(
      message_of([] {
        cb::bezier<double, 2> c(cb::point_list<double, 2>{P(std::numeric_limits<double>::infinity(), 0), P(1, 1)});
      }),
      HasSubstr("control_points[0][0] = inf: coordinates must be finite"));
  EXPECT_THAT(message_of([] { cb::bezier<double, 2> c(cb::point_list<double, 2>(62, P(0, 0))); }),
              HasSubstr("control_points: 62 given, at most 61 allowed (degree <= 60)"));
  const cb::point_list<double, 2> two{P(0, 0), P(1, 1)};
  EXPECT_THAT(message_of([&] {
                cb::bezier<double, 2> c(two, {1.0, 1.0});
              }),
              HasSubstr("domain = [1, 1]: must have lo < hi"));
  EXPECT_THAT(message_of([&] {
                cb::bezier<double, 2> c(two, {std::numeric_limits<double>::quiet_NaN(), 1.0});
              }),
              HasSubstr("domain.lo = nan: must be finite"));
  const cb::bezier<double, 2> c(two);
  EXPECT_THAT(message_of([&] { (void)c.derivative(0.5, -1); }), HasSubstr("order = -1: derivative order must be >= 0"));
  EXPECT_THAT(message_of([&] { (void)c.split(0.0); }), HasSubstr("split: u = 0: must be strictly inside (0, 1)"));
  EXPECT_THAT(message_of([&] { (void)c.derivative_control_points(2); }), HasSubstr("k = 2: must be in [0, 1]"));
  std::vector<double> us{0.0, 0.5, 1.0};
  std::vector<P> out(2);
  EXPECT_THAT(message_of([&] { c.evaluate(std::span<const double>(us), std::span<P>(out), alg::horner); }),
              HasSubstr("out: 2 given, must match us: 3"));
  // Degree 60 is accepted, and evaluates.
  const cb::bezier<double, 2> c60(cb::point_list<double, 2>(61, P(1, 2)));
  EXPECT_EQ(c60(0.5), P(1, 2));
}

TEST(bezier_bad_input, outside_the_domain_is_a_domain_error) {
  const cb::bezier<float, 2> c(cb::point_list<float, 2>{{0, 0}, {1, 1}}, {0.0f, 2.0f});
  for (alg a : all_algorithms) EXPECT_THROW((void)c.evaluate(2.5f, a), std::domain_error);
  EXPECT_THROW((void)c.derivative(-0.5f, 1), std::domain_error);
  EXPECT_THROW((void)c.split(3.0f), std::domain_error);
  try {
    (void)c(2.5f);
    FAIL() << "expected std::domain_error";
  } catch (const std::domain_error& e) {
    EXPECT_THAT(e.what(), HasSubstr("u = 2.5 is outside the domain [0, 2]"));
  }
  // Batch evaluation names the offending element by index, NaN included, at any position.
  const std::vector<float> us{0.0f, 0.5f, 1.0f, 1.5f, 2.0f, std::numeric_limits<float>::quiet_NaN(), 1.0f};
  std::vector<cb::point<float, 2>> out(us.size());
  for (alg a : all_algorithms) {
    try {
      c.evaluate(std::span<const float>(us), std::span<cb::point<float, 2>>(out), a);
      FAIL() << "NaN at us[5] accepted";
    } catch (const std::domain_error& e) {
      EXPECT_THAT(e.what(), HasSubstr("us[5] = nan is outside the domain [0, 2]"));
    }
  }
}
