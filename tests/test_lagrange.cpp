// Lagrange interpolation: exact interpolation at the nodes, exact reproduction of polynomials of
// degree <= n and of their derivatives (analytic, 50 digits), derivatives against the real50
// instantiation (at, near and between nodes), Chebyshev points, Runge's phenomenon on equispaced
// versus Chebyshev points, the monomial (Vandermonde) form's loss of accuracy at n = 20, bad input.
#include "support/accuracy.hpp"
#include "support/fixtures.hpp"

#include "curvebench/curves/lagrange.hpp"

#include <gmock/gmock.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <functional>
#include <limits>
#include <string>
#include <type_traits>
#include <vector>

namespace cb = curvebench;
namespace cbt = curvebench::testing;
using ::testing::HasSubstr;

static_assert(cb::curve<cb::lagrange<float, 3>>);
static_assert(cb::curve<cb::lagrange<double, 2>>);
static_assert(cb::curve<cb::lagrange<cb::real50, 1>>);

namespace {

// Tolerances in eps(Real), relative to a scale stated at each use (the largest |value| of the
// quantity compared on the interval). Measured maxima over the four types are in brackets.
// - reproduce_ulps[m], order m = 0..4: degree-6 data (rounded to Real) on 7 or 9 Chebyshev points
//   of [-1, 1]. The value carries the data rounding times the Lebesgue constant (~2.2 for these
//   points) plus ~ 3n roundings of the barycentric sums relative to |p| [0.34]: 4. Each derivative
//   order multiplies an error polynomial's size by up to n^2 (Markov's inequality on [-1, 1]) while
//   the derivative's own scale also grows; measured the growth is ~8x per order
//   [0.70, 10.7, 89, 472]: 16, 128, 1024, 8192.
// - versus_real50_ulps[m]: the same algorithm in Real and real50 on the same data (9 Chebyshev
//   points), sampled at, between, near (h/1024) and very near (64 eps) the nodes
//   [0.71, 4.3, 48, 359, 1570]: 4, 32, 256, 2048, 16384.
// - monomial_ulps: the Vandermonde form at n = 5 on [0, 1]: cond(V) ~ 1e4 is spent on the
//   coefficients, then Horner's sum cancels part of it [coefficients 130; values and derivatives
//   against the 50-digit interpolant, relative to their scale, 10]: 1024.
// - chebyshev_point_ulps: one sine (<= 1 ulp in the IEEE libraries) of a rounded argument, scaled
//   and shifted [1]: 4 ulps of the interval half-length.
constexpr std::array<double, 5> reproduce_ulps{4, 16, 128, 1024, 8192};
constexpr std::array<double, 5> versus_real50_ulps{4, 32, 256, 2048, 16384};
constexpr double monomial_ulps = 1024;
constexpr double chebyshev_point_ulps = 4;

template <class Real>
class lagrange_test : public ::testing::Test {};
TYPED_TEST_SUITE(lagrange_test, cbt::all_reals);

// q(x) = (sum_k qa_k x^k, sum_k qb_k x^k), degree 6, and its derivatives in 50 digits.
constexpr std::array<int, 7> qa{1, -3, 2, 5, -4, -1, 2};
constexpr std::array<int, 7> qb{-2, 1, 4, -1, 0, 3, -1};

cb::real50 poly_derivative(const std::array<int, 7>& q, const cb::real50& x, int order) {
  cb::real50 r(0);
  for (int k = 6; k >= order; --k) {
    cb::real50 f(1);
    for (int j = 0; j < order; ++j) f *= k - j;
    r = r * x + f * q[static_cast<std::size_t>(k)];
  }
  return r;
}
// A bound of |q^(m)| on [-1, 1]: sum_k k!/(k-m)! |q_k|.
cb::real50 poly_scale(const std::array<int, 7>& q, int order) {
  cb::real50 s(0);
  for (int k = order; k <= 6; ++k) {
    cb::real50 f(1);
    for (int j = 0; j < order; ++j) f *= k - j;
    s += f * std::abs(q[static_cast<std::size_t>(k)]);
  }
  return s;
}

template <class Real>
cb::point_list<Real, 2> sample_q(std::span<const Real> u) {
  cb::point_list<Real, 2> p;
  for (const Real& x : u)
    p.emplace_back(static_cast<Real>(poly_derivative(qa, cb::real50(x), 0)),
                   static_cast<Real>(poly_derivative(qb, cb::real50(x), 0)));
  return p;
}

// Runge's function on [-1, 1].
template <class Real>
Real runge(const Real& x) {
  return Real(1) / (Real(1) + Real(25) * x * x);
}

// Max |p(x) - f(x)| over 2001 points of [-1, 1], in double against the 50-digit f.
double runge_max_error(const std::vector<double>& nodes) {
  cb::point_list<double, 1> y;
  for (double x : nodes) y.emplace_back(runge(x));
  const cb::lagrange<double, 1> p(y, nodes);
  double worst = 0;
  for (int k = 0; k <= 2000; ++k) {
    const double x = -1.0 + 2.0 * k / 2000.0;
    worst = std::max(worst, static_cast<double>(abs(cb::real50(p(x)[0]) - runge(cb::real50(x)))));
  }
  return worst;
}

using cbt::message_of;

}  // namespace

TYPED_TEST(lagrange_test, interpolates_the_nodes_exactly) {
  using Real = TypeParam;
  const std::vector<Real> u = cb::chebyshev_parameters<Real>(9);
  const auto p = sample_q<Real>(u);
  const cb::lagrange<Real, 2> c(p, u);
  EXPECT_EQ(c.degree(), 8);
  EXPECT_EQ(c.algorithm(), cb::lagrange_algorithm::barycentric);
  EXPECT_EQ(c.domain().lo, Real(-1));
  EXPECT_EQ(c.domain().hi, Real(1));
  ASSERT_EQ(c.breakpoints().size(), 2u);
  for (std::size_t j = 0; j < u.size(); ++j) {
    EXPECT_EQ(c(u[j]), p[j]) << "node " << j;  // bit for bit
    EXPECT_EQ(c.derivative(u[j], 0), p[j]);
  }
  // Default parameters: equispaced on [0, 1].
  const cb::lagrange<Real, 2> e(p);
  EXPECT_EQ(e.domain().lo, Real(0));
  EXPECT_EQ(e.domain().hi, Real(1));
  for (std::size_t j = 0; j < p.size(); ++j) EXPECT_EQ(e(Real(static_cast<int>(j)) / Real(8)), p[j]);
}

TYPED_TEST(lagrange_test, reproduces_polynomials_and_their_derivatives) {
  using Real = TypeParam;
  // Degree 6 data on 7 Chebyshev points (n = 6, exact degree) and on 9 (n = 8 > 6).
  for (std::size_t count : {std::size_t(7), std::size_t(9)}) {
    const std::vector<Real> u = cb::chebyshev_parameters<Real>(count);
    const cb::lagrange<Real, 2> c(sample_q<Real>(u), u);
    for (int k = 0; k <= 64; ++k) {
      const Real x = Real(-1) + Real(2 * k + 1) / Real(65);  // off the nodes
      for (int m = 0; m <= 4; ++m) {
        const cb::point<cb::real50, 2> ref(poly_derivative(qa, cb::real50(x), m),
                                           poly_derivative(qb, cb::real50(x), m));
        const cb::real50 scale = std::max(poly_scale(qa, m), poly_scale(qb, m));
        EXPECT_TRUE(cbt::point_within(c.derivative(x, m), ref, scale, reproduce_ulps[static_cast<std::size_t>(m)]))
            << "n = " << count - 1 << ", order " << m << ", x = " << cbt::exact_text(x);
      }
    }
    // Order 6 of a degree-6 polynomial is the constant 720 (2, -1) = (1440, -720) (two orders past the
    // table: x 64); order > n is exactly zero.
    if (count == 7) {
      const cb::point<Real, 2> top = c.derivative(Real(0.25), 6);
      EXPECT_TRUE(
          cbt::point_within(top, cb::point<cb::real50, 2>(1440, -720), cb::real50(1440), 64 * reproduce_ulps[4]));
    }
    EXPECT_EQ(c.derivative(Real(0.25), static_cast<int>(count)), (cb::point<Real, 2>::Zero()));
  }
}

TYPED_TEST(lagrange_test, derivatives_match_real50_at_near_and_between_nodes) {
  using Real = TypeParam;
  const std::vector<Real> u = cb::chebyshev_parameters<Real>(9);
  // Data: a smooth non-polynomial curve, rounded to Real; the reference interpolates the same data.
  cb::point_list<Real, 2> p;
  for (const Real& x : u) {
    using std::cos;
    using std::sin;
    p.emplace_back(cos(Real(2) * x), sin(Real(3) * x) + x);
  }
  const cb::lagrange<Real, 2> c(p, u);
  std::vector<cb::real50> u50;
  for (const Real& x : u) u50.push_back(cb::real50(x));
  const cb::lagrange<cb::real50, 2> r(cb::points_cast<cb::real50, Real, 2>(p), u50);
  std::vector<Real> xs;
  for (std::size_t j = 0; j < u.size(); ++j) {
    xs.push_back(u[j]);  // at a node
    if (j + 1 < u.size()) {
      const Real h = u[j + 1] - u[j];
      xs.push_back(u[j] + h / Real(2));                         // between
      xs.push_back(u[j] + h * Real(1) / Real(1024));            // near (right of u_j)
      xs.push_back(u[j + 1] - Real(64) * cb::epsilon<Real>());  // very near (left of u_{j+1})
    }
  }
  for (int m = 0; m <= 4; ++m) {
    cb::real50 scale(0);  // the largest |reference| of this order over the sample
    for (const Real& x : xs) scale = std::max(scale, cb::real50(r.derivative(cb::real50(x), m).cwiseAbs().maxCoeff()));
    for (const Real& x : xs) {
      EXPECT_TRUE(cbt::point_within(c.derivative(x, m), r.derivative(cb::real50(x), m), scale,
                                    versus_real50_ulps[static_cast<std::size_t>(m)]))
          << "order " << m << ", x = " << cbt::exact_text(x);
    }
  }
}

TYPED_TEST(lagrange_test, monomial_form_agrees_at_low_degree) {
  using Real = TypeParam;
  // n = 5 on [0, 1]: the Vandermonde form is still usable; same data, same polynomial.
  const std::vector<Real> u = cb::equispaced_parameters<Real>(6);
  cb::point_list<Real, 2> p;
  for (const Real& x : u) p.emplace_back(Real(1) / (Real(1) + x), x * x - Real(0.5));
  const cb::lagrange<Real, 2> b(p);
  const cb::lagrange<Real, 2> m(p, cb::lagrange_algorithm::monomial);
  EXPECT_EQ(m.algorithm(), cb::lagrange_algorithm::monomial);
  EXPECT_EQ(m.monomial_coefficients().size(), 6u);
  EXPECT_TRUE(m.weights().empty());
  EXPECT_TRUE(b.monomial_coefficients().empty());
  // The second coordinate is x^2 - 1/2 exactly: coefficients (-1/2, 0, 1, 0, 0, 0).
  const std::array<double, 6> x2{-0.5, 0, 1, 0, 0, 0};
  for (std::size_t k = 0; k < 6; ++k)
    EXPECT_TRUE(
        cbt::within_scaled_ulps(m.monomial_coefficients()[k][1], cb::real50(x2[k]), cb::real50(1), monomial_ulps))
        << "a_" << k;
  // Reference: the interpolant of the same data in 50 digits (barycentric on real50).
  std::vector<cb::real50> u50;
  for (const Real& x : u) u50.push_back(cb::real50(x));
  const cb::lagrange<cb::real50, 2> r(cb::points_cast<cb::real50, Real, 2>(p), u50);
  for (int o = 0; o <= 3; ++o) {
    cb::real50 scale(0);  // the largest |P^(o)| over the sample
    for (int k = 0; k <= 32; ++k)
      scale = std::max(scale, cb::real50(r.derivative(cb::real50(k) / 32, o).cwiseAbs().maxCoeff()));
    for (int k = 0; k <= 32; ++k) {
      const Real x = Real(k) / Real(32);
      // For Real = real50 the reference has the same precision: its own error (the barycentric
      // derivative's, on these equispaced points) adds to the monomial's.
      const double tol =
          monomial_ulps + (std::is_same_v<Real, cb::real50> ? versus_real50_ulps[static_cast<std::size_t>(o)] : 0.0);
      EXPECT_TRUE(cbt::point_within(m.derivative(x, o), r.derivative(cb::real50(x), o), scale, tol))
          << "order " << o << " at " << k << "/32";
    }
  }
  EXPECT_EQ(m.derivative(Real(0.5), 6), (cb::point<Real, 2>::Zero()));
}

TYPED_TEST(lagrange_test, chebyshev_and_equispaced_parameters) {
  using Real = TypeParam;
  for (std::size_t count : {std::size_t(2), std::size_t(5), std::size_t(12)}) {
    const auto ch = cb::chebyshev_parameters<Real>(count, Real(-2), Real(6));
    const auto eq = cb::equispaced_parameters<Real>(count, Real(-2), Real(6));
    ASSERT_EQ(ch.size(), count);
    EXPECT_EQ(ch.front(), Real(-2));
    EXPECT_EQ(ch.back(), Real(6));
    EXPECT_EQ(eq.front(), Real(-2));
    EXPECT_EQ(eq.back(), Real(6));
    const auto n = static_cast<int>(count) - 1;
    for (int j = 0; j <= n; ++j) {
      using std::cos;
      // x_j = 2 - 4 cos(j pi / n) in 50 digits.
      const cb::real50 ref = 2 - 4 * cos(boost::math::constants::pi<cb::real50>() * j / n);
      EXPECT_TRUE(cbt::within_scaled_ulps(ch[static_cast<std::size_t>(j)], ref, cb::real50(4), chebyshev_point_ulps))
          << "j = " << j;
      EXPECT_TRUE(cbt::within_scaled_ulps(eq[static_cast<std::size_t>(j)], cb::real50(-2) + cb::real50(8 * j) / n,
                                          cb::real50(8), 2))
          << "j = " << j;
      // Exact symmetry on [-1, 1] (the sine is odd; on a shifted interval the final addition rounds
      // differently on both sides of the midpoint).
      const auto sym = cb::chebyshev_parameters<Real>(count);
      EXPECT_EQ(sym[static_cast<std::size_t>(j)], -sym[static_cast<std::size_t>(n - j)]);
      if (j > 0) {
        EXPECT_LT(ch[static_cast<std::size_t>(j - 1)], ch[static_cast<std::size_t>(j)]);
      }
    }
  }
}

TEST(lagrange, runge_equispaced_diverges_chebyshev_converges) {
  std::vector<double> eq_err, ch_err;
  const std::array<std::size_t, 6> degrees{4, 8, 12, 16, 20, 24};
  for (std::size_t n : degrees) {
    eq_err.push_back(runge_max_error(cb::equispaced_parameters<double>(n + 1, -1.0, 1.0)));
    ch_err.push_back(runge_max_error(cb::chebyshev_parameters<double>(n + 1, -1.0, 1.0)));
    std::printf("runge n = %2zu  max error: equispaced %.3e  chebyshev %.3e\n", n, eq_err.back(), ch_err.back());
  }
  for (std::size_t k = 1; k < degrees.size(); ++k) {
    // Equispaced: the error grows with n (Runge's phenomenon, ~ exp(0.5 n) near the ends) ...
    EXPECT_GT(eq_err[k], 2 * eq_err[k - 1]) << "n = " << degrees[k];
    // ... Chebyshev: it decreases geometrically (rate ~ exp(-0.2 n) for this function's poles at +-i/5).
    EXPECT_LT(ch_err[k], 0.6 * ch_err[k - 1]) << "n = " << degrees[k];
  }
  EXPECT_GT(eq_err[4], 10.0);  // n = 20: off by more than 10 where the function is below 1
  EXPECT_LT(ch_err[4], 0.05);
}

TEST(lagrange, monomial_form_loses_to_barycentric_at_degree_20) {
  // n = 20, equispaced on [0, 1], data Runge's function mapped to [0, 1], rounded to double. The
  // reference is the interpolant of the same double data in 50 digits (barycentric on real50), so
  // what is measured is the evaluation error of each algorithm, not the interpolation error.
  const std::size_t count = 21;
  const auto u = cb::equispaced_parameters<double>(count);
  cb::point_list<double, 1> y;
  for (double x : u) y.emplace_back(runge(2 * x - 1));
  std::vector<cb::real50> u50(u.begin(), u.end());
  const cb::lagrange<cb::real50, 1> ref(cb::points_cast<cb::real50, double, 1>(y), u50);
  const cb::lagrange<double, 1> bary(y, u);
  const cb::lagrange<double, 1> mono(y, u, cb::lagrange_algorithm::monomial);
  const cb::lagrange<cb::real50, 1> mono50(cb::points_cast<cb::real50, double, 1>(y), u50,
                                           cb::lagrange_algorithm::monomial);
  cb::real50 scale(0);
  double bary_err = 0, mono_err = 0, mono50_err = 0, bary_d1 = 0, mono_d1 = 0, d1_scale = 0;
  for (int k = 0; k <= 1000; ++k) {
    const double x = k / 1000.0;
    const cb::real50 r = ref(cb::real50(x))[0];
    const cb::real50 r1 = ref.derivative(cb::real50(x), 1)[0];
    scale = std::max(scale, cb::real50(abs(r)));
    d1_scale = std::max(d1_scale, static_cast<double>(abs(r1)));
    bary_err = std::max(bary_err, static_cast<double>(abs(cb::real50(bary(x)[0]) - r)));
    mono_err = std::max(mono_err, static_cast<double>(abs(cb::real50(mono(x)[0]) - r)));
    mono50_err = std::max(mono50_err, static_cast<double>(abs(mono50(cb::real50(x))[0] - r)));
    bary_d1 = std::max(bary_d1, static_cast<double>(abs(cb::real50(bary.derivative(x, 1)[0]) - r1)));
    mono_d1 = std::max(mono_d1, static_cast<double>(abs(cb::real50(mono.derivative(x, 1)[0]) - r1)));
  }
  std::printf(
      "n = 20 equispaced on [0, 1], max |p| = %.3g: max error barycentric %.3e, monomial %.3e "
      "(ratio %.3g); monomial in real50 %.3e\n",
      static_cast<double>(scale), bary_err, mono_err, mono_err / bary_err, mono50_err);
  std::printf("first derivative, max |p'| = %.3g: barycentric %.3e, monomial %.3e (ratio %.3g)\n", d1_scale, bary_d1,
              mono_d1, mono_d1 / bary_d1);
  // Higham's bound for the second barycentric form: (3n + 4) u Lambda_n |p|, u = eps/2, with the
  // equispaced Lebesgue constant Lambda_20 ~ 2^21 / (e n ln n) ~ 1.3e4.
  const double lebesgue_20 = std::ldexp(1.0, 21) / (std::exp(1.0) * 20 * std::log(20.0));
  EXPECT_LT(bary_err, (3 * 20 + 4) * 0.5 * cb::epsilon<double>() * lebesgue_20 * static_cast<double>(scale));
  // The monomial form is worse by several orders of magnitude in double ...
  EXPECT_GT(mono_err, 1e3 * bary_err);
  EXPECT_GT(mono_d1, 1e3 * bary_d1);
  // ... while in 50 digits the same algorithm is fine: the loss is rounding, not a wrong formula.
  EXPECT_LT(mono50_err, 1e-25);
}

TEST(lagrange, near_node_derivatives_are_stable_in_double) {
  // u within 1e-13 of a node: the Schneider-Werner recurrence alone divides a rounding error by
  // u - u_i; the nearest-node identity keeps the derivative accurate.
  const auto u = cb::chebyshev_parameters<double>(11);
  cb::point_list<double, 1> y;
  for (double x : u) y.emplace_back(std::exp(x));
  std::vector<cb::real50> u50(u.begin(), u.end());
  const cb::lagrange<cb::real50, 1> ref(cb::points_cast<cb::real50, double, 1>(y), u50);
  const cb::lagrange<double, 1> c(y, u);
  for (std::size_t j = 1; j + 1 < u.size(); ++j) {
    for (double off : {1e-13, -1e-13, 1e-9}) {
      const double x = u[j] + off;
      for (int m = 1; m <= 3; ++m) {
        EXPECT_TRUE(cbt::within_relative(c.derivative(x, m)[0], ref.derivative(cb::real50(x), m)[0], 1e-11))
            << "node " << j << " offset " << off << " order " << m;
      }
    }
  }
}

TEST(lagrange, bad_input_is_rejected_with_a_clear_message) {
  using p2 = cb::point<double, 2>;
  const cb::point_list<double, 2> one{p2(0, 0)};
  EXPECT_EQ(message_of([&] { cb::lagrange<double, 2> c(one); }),
            "points: 1 given, at least 2 required (a Lagrange curve of degree n >= 1 has n + 1 points)");
  const cb::point_list<double, 2> nan{p2(0, 0), p2(1, std::numeric_limits<double>::quiet_NaN())};
  EXPECT_EQ(message_of([&] { cb::lagrange<double, 2> c(nan); }), "points[1][1] = nan: coordinates must be finite");
  const cb::point_list<double, 2> three{p2(0, 0), p2(1, 1), p2(2, 0)};
  const std::vector<double> two{0, 1};
  EXPECT_EQ(message_of([&] { cb::lagrange<double, 2> c(three, two); }), "parameters: 2 given, must match points: 3");
  const std::vector<double> dup{0, 0.5, 0.5};
  EXPECT_EQ(message_of([&] { cb::lagrange<double, 2> c(three, dup); }),
            "parameters must be increasing: parameters[2] = 0.5 <= parameters[1] = 0.5");
  const std::vector<double> inf{0, 0.5, std::numeric_limits<double>::infinity()};
  EXPECT_EQ(message_of([&] { cb::lagrange<double, 2> c(three, inf); }), "parameters[2] = inf: must be finite");
  // 400 equispaced points overflow the barycentric weights in float.
  const auto many = cb::equispaced_parameters<float>(400);
  const cb::point_list<float, 1> ys(400, cb::point<float, 1>(1.0f));
  EXPECT_THAT(message_of([&] { cb::lagrange<float, 1> c(ys, many); }),
              HasSubstr("is out of range for this Real (400 points: use fewer, or a wider type)"));
  // Huge parameters overflow the Vandermonde matrix in float.
  const std::vector<float> huge{0.0f, 1e20f, 2e20f};
  const cb::point_list<float, 1> y3(3, cb::point<float, 1>(1.0f));
  EXPECT_THAT(message_of([&] { cb::lagrange<float, 1> c(y3, huge, cb::lagrange_algorithm::monomial); }),
              HasSubstr("is not finite (the Vandermonde system is too ill-conditioned for this Real)"));
  EXPECT_NO_THROW((cb::lagrange<float, 1>(y3, huge)));  // the barycentric form copes
  // The point count is checked against the algorithm's limit before any work (1e5
  // monomial nodes threw a bare std::bad_alloc for an 80 GB matrix).
  const cb::point_list<double, 1> over(cb::max_monomial_points + 1, cb::point<double, 1>(1.0));
  EXPECT_EQ(message_of([&] { cb::lagrange<double, 1> c(over, cb::lagrange_algorithm::monomial); }),
            "points: 1001 points, more than the monomial algorithm's limit of 1000 (an n x n Vandermonde matrix, "
            "O(n^3) to solve)");
  const cb::point_list<double, 1> far_over(cb::max_barycentric_points + 1, cb::point<double, 1>(1.0));
  EXPECT_THAT(message_of([&] { cb::lagrange<double, 1> c(far_over); }),
              HasSubstr("points: 10001 points, more than the barycentric algorithm's limit of 10000"));
  const cb::lagrange<double, 2> c(three);
  EXPECT_THAT(message_of([&] { (void)c(1.5); }), HasSubstr("u = 1.5 is outside the domain [0, 1]"));
  EXPECT_EQ(message_of([&] { (void)c.derivative(0.5, -2); }), "order = -2: derivative order must be >= 0");
  EXPECT_EQ(message_of([&] { (void)cb::chebyshev_parameters<double>(1); }),
            "count: 1 given, at least 2 required (the two ends of the interval)");
  EXPECT_EQ(message_of([&] { (void)cb::equispaced_parameters<double>(3, 1.0, 1.0); }),
            "[a, b] = [1, 1]: must have a < b");
  EXPECT_STREQ(cb::to_string(cb::lagrange_algorithm::monomial), "monomial");
}
