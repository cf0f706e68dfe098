// B-splines: basis (Cox-de Boor, partition of unity, Bernstein and uniform-matrix special cases),
// polynomial reproduction by Marsden's identity (values and derivatives, non-uniform knots with
// a double knot), de Boor vs basis sum vs the 50-digit instantiation, clamped end interpolation,
// knot insertion, derivative curves, periodic seams, conversion to piecewise_cubic, bad input.
#include "support/accuracy.hpp"

#include "curvebench/basis/bernstein.hpp"
#include "curvebench/basis/cubic_matrices.hpp"
#include "curvebench/curves/bspline.hpp"

#include <gmock/gmock.h>

#include <array>
#include <limits>
#include <random>
#include <vector>

namespace cb = curvebench;
namespace cbt = curvebench::testing;
using ::testing::HasSubstr;

static_assert(cb::curve<cb::bspline<double, 2>>);
static_assert(cb::curve<cb::bspline<cb::real50, 3>>);

namespace {

// Tolerances, in eps(Real) times the stated scale:
// - basis values: each N is built by m - 1 levels of the recursion, each a sum of two products of
//   a rounded ratio and a value <= 1 (~3 roundings per level): 4m ulps of 1;
// - curve values (de Boor or basis sum): m - 1 levels of convex combinations of the control points,
//   plus rounding the control points (reference exact): 4m ulps of max |control point|;
// - derivatives of order r: each difference level divides by a knot gap (>= hmin) and multiplies
//   by <= m: the scale grows by (m / hmin) per level and the rounding by ~2 per level, so
//   8m (2m / hmin)^r ulps of max |control point|;
// - knot insertion: one more convex combination per control point, compared with the original
//   curve's value: 8m ulps of the scale (both sides carry ~4m).
double basis_ulps(int m) { return 4.0 * m; }
double value_ulps(int m) { return 4.0 * m; }
double derivative_ulps(int m, int r, double hmin) {
  double f = 8.0 * m;
  for (int j = 0; j < r; ++j) f *= 2.0 * m / hmin;
  return f;
}
double insertion_ulps(int m) { return 8.0 * m; }

template <class Real>
class bspline_typed : public ::testing::Test {};
TYPED_TEST_SUITE(bspline_typed, cbt::all_reals);

// A non-uniform, non-clamped knot vector of dyadic values (exact in every type) for order m with
// n control points: gaps cycle through 1/2, 3/4, 1/4, 1, with one double knot when m >= 3.
std::vector<double> mixed_knots(int m, std::size_t n) {
  const std::array<double, 4> gaps{0.5, 0.75, 0.25, 1.0};
  std::vector<double> t;
  double x = -2;
  for (std::size_t j = 0; j < n + static_cast<std::size_t>(m); ++j) {
    t.push_back(x);
    const bool doubled = m >= 3 && j == static_cast<std::size_t>(m) + 1;
    x += doubled ? 0.0 : gaps[j % gaps.size()];
  }
  return t;
}

// Elementary symmetric polynomial e_d of xs, in real50.
cb::real50 elementary(const std::vector<cb::real50>& xs, int d) {
  std::vector<cb::real50> e(static_cast<std::size_t>(d) + 1, cb::real50(0));
  e[0] = 1;
  for (const auto& x : xs)
    for (int k = d; k >= 1; --k) e[static_cast<std::size_t>(k)] += x * e[static_cast<std::size_t>(k - 1)];
  return e[static_cast<std::size_t>(d)];
}

template <class Real>
std::vector<Real> cast_all(const std::vector<double>& v) {
  return std::vector<Real>(v.begin(), v.end());
}

}  // namespace

// Marsden's identity: u^d = sum_i [e_d(t_{i+1}, ..., t_{i+m-1}) / C(m-1, d)] N_{i,m}(u) for d < m,
// on any knot vector. Control points from that closed form (in 50 digits, then rounded) must give
// the curve (u^a, u^b) and its derivatives exactly, with both algorithms.
TYPED_TEST(bspline_typed, marsden_polynomial_reproduction_values_and_derivatives) {
  using Real = TypeParam;
  for (int m = 1; m <= 6; ++m) {
    const std::size_t n = static_cast<std::size_t>(m) + 5;
    const std::vector<double> td = mixed_knots(m, n);
    const int a = m - 1;
    const int b = (m - 1) / 2;
    cb::point_list<Real, 2> ctrl(n);
    double cmax = 1;
    for (std::size_t i = 0; i < n; ++i) {
      std::vector<cb::real50> window;
      for (int j = 1; j < m; ++j) window.emplace_back(td[i + static_cast<std::size_t>(j)]);
      const cb::real50 ca = elementary(window, a) / cb::binomial<cb::real50>(m - 1, a);
      const cb::real50 cb_ = elementary(window, b) / cb::binomial<cb::real50>(m - 1, b);
      ctrl[i] = cb::point<Real, 2>(static_cast<Real>(ca), static_cast<Real>(cb_));
      using std::abs;
      cmax = std::max({cmax, static_cast<double>(abs(ca)), static_cast<double>(abs(cb_))});
    }
    const cb::bspline<Real, 2> c(m, cast_all<Real>(td), ctrl);
    const auto dom = c.domain();
    for (int s = 0; s <= 64; ++s) {
      const double ud =
          static_cast<double>(dom.lo) + (static_cast<double>(dom.hi) - static_cast<double>(dom.lo)) * s / 64.0;
      const Real u = static_cast<Real>(ud);
      const cb::real50 u50(u);
      for (int r = 0; r <= m; ++r) {
        cb::point<cb::real50, 2> ref;
        const int exps[2] = {a, b};
        for (int d = 0; d < 2; ++d) {
          const int e = exps[d];
          cb::real50 f = e >= r ? cb::real50(1) : cb::real50(0);
          for (int j = 0; j < r && e >= r; ++j) f *= e - j;
          ref[d] = e >= r ? f * cb::basis::pow_int(u50, e - r) : cb::real50(0);
        }
        const double tol = r == 0 ? value_ulps(m) : derivative_ulps(m, r, 0.25);
        for (auto alg : {cb::bspline_evaluation::de_boor, cb::bspline_evaluation::basis_sum}) {
          const auto got = c.evaluate(u, r, alg);
          ASSERT_TRUE(cbt::point_within(got, ref, cb::real50(cmax), tol))
              << "m=" << m << " r=" << r << " u=" << ud << " alg=" << cb::to_string(alg);
        }
      }
    }
  }
}

// With n = m and clamped knots on [0, 1] the B-spline is the Bezier curve of its control points:
// N_{i,m} = B_i^{m-1} (closed form in basis/bernstein.hpp, evaluated in 50 digits). All orders 1..16.
TYPED_TEST(bspline_typed, single_span_clamped_is_bernstein) {
  using Real = TypeParam;
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> dist(-1, 1);
  for (int m = 1; m <= cb::bspline_max_order; ++m) {
    const auto n = static_cast<std::size_t>(m);
    const std::vector<Real> t = cb::bspline_clamped_knots<Real>(n, m, Real(0), Real(1));
    cb::point_list<Real, 2> p(n);
    for (auto& q : p) q = cb::point<Real, 2>(static_cast<Real>(dist(rng)), static_cast<Real>(dist(rng)));
    const cb::bspline<Real, 2> c(m, t, p);
    std::vector<Real> nb(n);
    for (int s = 0; s <= 32; ++s) {
      const Real u = Real(s) / Real(32);
      c.nonzero_basis(u, nb);
      cb::point<cb::real50, 2> ref = cb::zero_point<cb::real50, 2>();
      for (int i = 0; i < m; ++i) {
        const cb::real50 bern = cb::basis::bernstein(m - 1, i, cb::real50(u));
        ASSERT_TRUE(cbt::within_scaled_ulps(nb[static_cast<std::size_t>(i)], bern, cb::real50(1), basis_ulps(m)))
            << "m=" << m << " i=" << i << " u=" << s << "/32";
        ref += bern * cb::point_cast<cb::real50>(p[static_cast<std::size_t>(i)]);
      }
      for (auto alg : {cb::bspline_evaluation::de_boor, cb::bspline_evaluation::basis_sum})
        ASSERT_TRUE(cbt::point_within(c.evaluate(u, 0, alg), ref, cb::real50(1), value_ulps(m))) << "m=" << m;
    }
    // Clamped ends: exactly the first and last control points (the right end uses the left limit).
    EXPECT_EQ(c(Real(0)), p.front());
    EXPECT_EQ(c(Real(1)), p.back());
    // The recursive seed formula at both ends: at u = 0 only N_{0,m} = 1 (0/0 = 0 terms drop out of
    // the repeated knots); at the right end the half-open rule alone would give 0 everywhere, the
    // last-span rule gives N_{n-1,m}(1) = 1.
    EXPECT_EQ(c.basis(0, m, Real(0)), Real(1));
    EXPECT_EQ(c.basis(n - 1, m, Real(1)), Real(1));
    if (m > 1) {
      EXPECT_EQ(c.basis(0, m, Real(1)), Real(0));
    }
  }
}

// Uniform cubic: on span [k, k+1] the curve is T(t) M G with the seed's uniform B-spline matrix
// (basis/cubic_matrices.hpp) and G = [P_{k-3}, P_{k-2}, P_{k-1}, P_k], computed in 50 digits.
TYPED_TEST(bspline_typed, uniform_cubic_matches_basis_matrix) {
  using Real = TypeParam;
  const std::size_t n = 7;
  cb::point_list<Real, 2> p;
  for (std::size_t i = 0; i < n; ++i)
    p.emplace_back(Real(static_cast<long long>(i * i % 5)) - Real(2), Real(static_cast<long long>(i % 3)));
  const cb::bspline<Real, 2> c(4, cb::bspline_uniform_knots<Real>(n, 4), p);
  EXPECT_EQ(c.domain().lo, Real(3));
  EXPECT_EQ(c.domain().hi, Real(7));
  const auto m50 = cb::basis::uniform_bspline_matrix<cb::real50>();
  for (std::size_t k = 3; k < n; ++k)
    for (int s = 0; s < 8; ++s) {
      const cb::real50 t50 = cb::real50(s) / 8;
      Eigen::Matrix<cb::real50, 4, 2> g;
      for (int r = 0; r < 4; ++r)
        g.row(r) = cb::point_cast<cb::real50>(p[k - 3 + static_cast<std::size_t>(r)]).transpose();
      for (int order = 0; order <= 3; ++order) {
        const Eigen::Matrix<cb::real50, 1, 2> ref = cb::basis::power_row(t50, order) * m50 * g;
        const auto got = c.derivative(Real(static_cast<long long>(k)) + Real(s) / Real(8), order);
        ASSERT_TRUE(cbt::point_within(got, cb::point<cb::real50, 2>(ref.transpose()), cb::real50(4), value_ulps(4) * 4))
            << "k=" << k << " s=" << s << " order=" << order;
      }
    }
}

// Partition of unity, non-negativity and the recursive seed formula against the triangular form,
// on a knot vector with a double knot and a triple knot, including the right end of the domain.
TYPED_TEST(bspline_typed, basis_partition_nonnegativity_recursion) {
  using Real = TypeParam;
  for (int m = 1; m <= 6; ++m) {
    const std::size_t n = static_cast<std::size_t>(m) + 6;
    std::vector<double> td = mixed_knots(m, n);
    const cb::bspline<Real, 1> c(m, cast_all<Real>(td), cb::point_list<Real, 1>(n, cb::point<Real, 1>(Real(1))));
    std::vector<Real> nb(static_cast<std::size_t>(m));
    const auto dom = c.domain();
    for (int s = 0; s <= 40; ++s) {
      const Real u = dom.lo + (dom.hi - dom.lo) * Real(s) / Real(40);
      const std::size_t k = c.nonzero_basis(u, nb);
      Real sum(0);
      for (int j = 0; j < m; ++j) {
        const Real v = nb[static_cast<std::size_t>(j)];
        ASSERT_GE(v, Real(0));
        sum += v;
        const std::size_t i = k + 1 + static_cast<std::size_t>(j) - static_cast<std::size_t>(m);
        ASSERT_TRUE(cbt::within_scaled_ulps(c.basis(i, m, u), cb::real50(v), cb::real50(1), 2 * basis_ulps(m)))
            << "m=" << m << " i=" << i;
      }
      ASSERT_TRUE(cbt::within_ulps(sum, cb::real50(1), m * basis_ulps(m))) << "m=" << m << " s=" << s;
      // Functions outside k-m+1..k vanish at u.
      if (k + 1 < n) {
        EXPECT_EQ(c.basis(k + 1, m, u), Real(0));
      }
    }
  }
}

// de Boor, basis sum and the real50 instantiation agree on a random non-uniform cubic and quintic.
TYPED_TEST(bspline_typed, algorithms_agree_with_50_digit_instantiation) {
  using Real = TypeParam;
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> dist(-1, 1);
  for (int m : {2, 4, 6}) {
    const std::size_t n = 10;
    std::vector<double> td = mixed_knots(m, n);
    cb::point_list<double, 3> pd(n);
    for (auto& q : pd) q = cb::point<double, 3>(dist(rng), dist(rng), dist(rng));
    std::vector<cb::point<Real, 3>> pr;
    std::vector<cb::point<cb::real50, 3>> p50;
    for (const auto& q : pd) {
      pr.push_back(cb::point_cast<Real>(q));
      p50.push_back(cb::point_cast<cb::real50>(pr.back()));
    }
    const cb::bspline<Real, 3> c(m, cast_all<Real>(td), pr);
    const cb::bspline<cb::real50, 3> ref(m, cast_all<cb::real50>(td), p50);
    for (int s = 0; s <= 50; ++s) {
      const Real u = c.domain().lo + (c.domain().hi - c.domain().lo) * Real(s) / Real(50);
      for (int r = 0; r < m; ++r) {
        const auto want = ref.derivative(cb::real50(u), r);
        const double tol = r == 0 ? value_ulps(m) : derivative_ulps(m, r, 0.25);
        ASSERT_TRUE(cbt::point_within(c.evaluate(u, r, cb::bspline_evaluation::de_boor), want, cb::real50(1), tol));
        ASSERT_TRUE(cbt::point_within(c.evaluate(u, r, cb::bspline_evaluation::basis_sum), want, cb::real50(1), tol));
      }
      EXPECT_EQ(c.derivative(u, m), (cb::zero_point<Real, 3>()));
    }
  }
}

// Boehm insertion leaves the curve unchanged: at new knots, existing knots (raising the
// multiplicity) and the ends of the domain; the derivative curve equals derivative(u, 1).
TYPED_TEST(bspline_typed, knot_insertion_and_derivative_curve) {
  using Real = TypeParam;
  for (int m = 1; m <= 5; ++m) {
    const std::size_t n = static_cast<std::size_t>(m) + 4;
    std::vector<double> td = mixed_knots(m, n);
    cb::point_list<Real, 2> p;
    for (std::size_t i = 0; i < n; ++i)
      p.emplace_back(Real(static_cast<long long>((i * 7) % 5)) / Real(4),
                     Real(static_cast<long long>((i * 3) % 4)) / Real(2));
    const cb::bspline<Real, 2> c(m, cast_all<Real>(td), p);
    const auto dom = c.domain();
    std::vector<Real> inserts{dom.lo, dom.lo + (dom.hi - dom.lo) / Real(3), dom.hi};
    for (std::size_t j = static_cast<std::size_t>(m); j < n; ++j) inserts.push_back(Real(td[j]));
    for (const Real& x : inserts) {
      if (x < dom.lo || x > dom.hi) continue;
      // Inserting is allowed unless it would exceed multiplicity m.
      std::size_t mult = 0;
      for (double k : td) mult += Real(k) == x ? 1 : 0;
      if (mult >= static_cast<std::size_t>(m)) {
        EXPECT_THROW((void)c.insert_knot(x), cb::invalid_input);
        continue;
      }
      const cb::bspline<Real, 2> d = c.insert_knot(x);
      ASSERT_EQ(d.control_points().size(), n + 1);
      ASSERT_EQ(d.knots().size(), td.size() + 1);
      for (int s = 0; s <= 30; ++s) {
        const Real u = dom.lo + (dom.hi - dom.lo) * Real(s) / Real(30);
        ASSERT_TRUE(cbt::point_within(d(u), cb::point_cast<cb::real50>(c(u)), cb::real50(2), insertion_ulps(m)))
            << "m=" << m << " insert " << static_cast<double>(x);
      }
    }
    if (m >= 2) {
      const cb::bspline<Real, 2> dc = c.derivative_curve();
      EXPECT_EQ(dc.order(), m - 1);
      EXPECT_EQ(dc.domain().lo, dom.lo);
      EXPECT_EQ(dc.domain().hi, dom.hi);
      for (int s = 0; s <= 30; ++s) {
        const Real u = dom.lo + (dom.hi - dom.lo) * Real(s) / Real(30);
        EXPECT_EQ(dc(u), c.derivative(u, 1));  // the same level-1 data and the same algorithm
        if (m >= 3) {
          EXPECT_EQ(dc.derivative(u, 1), c.derivative(u, 2));
        }
      }
    } else {
      try {
        (void)c.derivative_curve();
        ADD_FAILURE() << "order 1 has no derivative curve";
      } catch (const cb::invalid_input& e) {
        EXPECT_THAT(e.what(), HasSubstr("order 1 B-spline has derivative 0"));
      }
    }
  }
}

// A closed curve: value and derivatives up to m - 2 agree at the seam (u = b_0 vs u = b_s), and the
// (m-1)-th derivative generally does not (a uniform cubic is C2, not C3).
TYPED_TEST(bspline_typed, periodic_seam_is_smooth) {
  using Real = TypeParam;
  cb::point_list<Real, 2> loop{{Real(1), Real(0)},
                               {Real(0), Real(1)},
                               {Real(-1), Real(0)},
                               {Real(0), Real(-1)},
                               {Real(1) / Real(2), Real(-1) / Real(2)}};
  const std::vector<Real> breaks{Real(0), Real(0.5), Real(1.25), Real(2), Real(2.5), Real(3.5)};
  for (int m = 2; m <= 6; ++m) {
    const auto c = cb::periodic_bspline<Real, 2>(m, loop, breaks);
    EXPECT_EQ(c.domain().lo, Real(0));
    EXPECT_EQ(c.domain().hi, Real(3.5));
    for (int r = 0; r <= m - 2; ++r)
      ASSERT_TRUE(cbt::point_within(c.derivative(Real(0), r), cb::point_cast<cb::real50>(c.derivative(Real(3.5), r)),
                                    cb::real50(1), derivative_ulps(m, r, 0.5)))
          << "m=" << m << " r=" << r;
  }
  const auto u4 = cb::periodic_bspline<Real, 2>(4, loop);
  const cb::point<Real, 2> jump = u4.derivative(Real(0), 3) - u4.derivative(Real(5), 3);
  EXPECT_GT(jump.norm(), Real(1) / Real(10));
}

// The cubic converts to the piecewise_cubic engine: the same values and derivatives up to order 3,
// one segment per non-empty span, on knots with a double knot.
TYPED_TEST(bspline_typed, cubic_converts_to_piecewise_cubic) {
  using Real = TypeParam;
  const std::size_t n = 9;
  std::vector<double> td = mixed_knots(4, n);
  cb::point_list<Real, 2> p;
  for (std::size_t i = 0; i < n; ++i)
    p.emplace_back(Real(static_cast<long long>((i * 5) % 7)) / Real(4), Real(static_cast<long long>((i * 2) % 3)));
  const cb::bspline<Real, 2> c(4, cast_all<Real>(td), p);
  const auto pc = c.to_piecewise_cubic();
  ASSERT_EQ(pc.breakpoints().size(), c.breakpoints().size());
  for (std::size_t j = 0; j < pc.breakpoints().size(); ++j) EXPECT_EQ(pc.breakpoints()[j], c.breakpoints()[j]);
  const auto dom = c.domain();
  for (int s = 0; s <= 60; ++s) {
    const Real u = dom.lo + (dom.hi - dom.lo) * Real(s) / Real(60);
    for (int r = 0; r <= 3; ++r)
      for (auto alg : {cb::cubic_algorithm::power, cb::cubic_algorithm::matrix, cb::cubic_algorithm::bezier})
        ASSERT_TRUE(cbt::point_within(pc.evaluate(u, r, alg), cb::point_cast<cb::real50>(c.derivative(u, r)),
                                      cb::real50(1), 4 * derivative_ulps(4, r, 0.25)))
            << "s=" << s << " r=" << r << " alg=" << cb::to_string(alg);
  }
  const cb::bspline<Real, 2> quad(3, cb::bspline_uniform_knots<Real>(4, 3),
                                  cb::point_list<Real, 2>(4, cb::zero_point<Real, 2>()));
  EXPECT_THROW((void)quad.to_piecewise_cubic(), cb::invalid_input);
}

// Knot-vector builders: sizes, domains and values.
TEST(bspline_builders, knot_vectors) {
  const auto u = cb::bspline_uniform_knots<double>(6, 4, -1.0, 0.5);
  ASSERT_EQ(u.size(), 10u);
  EXPECT_EQ(u.front(), -1.0);
  EXPECT_EQ(u.back(), 3.5);
  const auto cl = cb::bspline_clamped_knots<double>(7, 3, 0.0, 1.0);
  EXPECT_THAT(cl, ::testing::ElementsAre(0, 0, 0, 0.2, 0.4, 0.6, 0.8, 1, 1, 1));
  const std::vector<double> br{0, 1, 3};
  EXPECT_THAT(cb::bspline_clamped_knots<double>(std::span<const double>(br), 2), ::testing::ElementsAre(0, 0, 1, 3, 3));
  // Periodic, order 3 on breaks 0, 1, 3 (period 3): two knots before 0 and after 3 continue the
  // pattern of gaps 1, 2: -3, -2 | 0, 1, 3 | 4, 6.
  EXPECT_THAT(cb::bspline_periodic_knots<double>(std::span<const double>(br), 3),
              ::testing::ElementsAre(-3, -2, 0, 1, 3, 4, 6));
}

// Bad input: every message names the argument, the place and the rule.
TEST(bspline_bad_input, messages) {
  const cb::point_list<double, 2> p4(4, cb::point<double, 2>(0, 0));
  auto message = [](auto&& f) -> std::string {
    try {
      f();
    } catch (const cb::invalid_input& e) {
      return e.what();
    }
    return "no exception";
  };
  EXPECT_EQ(message([&] {
              cb::bspline<double, 2>(0, {0, 1, 2, 3}, p4);
            }),
            "order = 0: must be in [1, 16] (degree + 1)");
  EXPECT_EQ(message([&] { cb::bspline<double, 2>(17, std::vector<double>(21, 0.0), p4); }),
            "order = 17: must be in [1, 16] (degree + 1)");
  EXPECT_EQ(message([&] {
              cb::bspline<double, 2>(5, {0, 1, 2, 3, 4, 5, 6, 7, 8}, p4);
            }),
            "control_points: 4 given, at least 5 required (order 5 needs at least order points)");
  EXPECT_EQ(message([&] {
              cb::bspline<double, 2>(3, {0, 1, 2, 3, 4, 5}, p4);
            }),
            "knots: 6 given, must be control_points + order = 4 + 3 = 7");
  EXPECT_EQ(message([&] {
              cb::bspline<double, 2>(3, {0, 1, 2, 3.5, 3, 5, 6}, p4);
            }),
            "knots must be non-decreasing: knots[4] = 3 < knots[3] = 3.5");
  EXPECT_EQ(message([&] {
              cb::bspline<double, 2>(3, {0, 1, 2, std::numeric_limits<double>::quiet_NaN(), 4, 5, 6}, p4);
            }),
            "knots[3] = nan: must be finite");
  EXPECT_EQ(message([&] {
              cb::bspline<double, 2>(2, {0, 1, 1, 1, 2, 3}, p4);
            }),
            "knots[1..3] = 1: multiplicity 3 exceeds order = 2");
  EXPECT_EQ(message([&] {
              cb::bspline<double, 2>(2, {0, 1, 1, 1, 1, 3}, p4);
            }),
            "knots[1..4] = 1: multiplicity 4 exceeds order = 2");
  EXPECT_EQ(message([&] {
              cb::bspline<double, 2>(3, {0, 0, 0, 0, 1, 1, 1}, p4);
            }),
            "knots[0..3] = 0: multiplicity 4 exceeds order = 3");
  cb::point_list<double, 2> bad = p4;
  bad[2][1] = std::numeric_limits<double>::infinity();
  EXPECT_EQ(message([&] {
              cb::bspline<double, 2>(2, {0, 1, 2, 3, 4, 5}, bad);
            }),
            "control_points[2][1] = inf: coordinates must be finite");
  EXPECT_EQ(message([&] { (void)cb::bspline_uniform_knots<double>(3, 4); }),
            "count: 3 given, at least 4 required (a B-spline needs at least order points)");
  const std::vector<double> dec{0, 2, 1};
  EXPECT_EQ(message([&] { (void)cb::bspline_clamped_knots<double>(std::span<const double>(dec), 3); }),
            "breaks must be increasing: breaks[2] = 1 <= breaks[1] = 2");
  // Empty domain: order 2, 2 points, knots 0 1 1 2 -> [knots[1], knots[2]] = [1, 1].
  EXPECT_EQ(message([&] {
              cb::bspline<double, 2>(2, {0, 1, 1, 2}, cb::point_list<double, 2>(2, {0, 0}));
            }),
            "knots: domain [knots[1], knots[2]] = [1, 1] is empty; knots[1] < knots[2] required");
  // Evaluation outside the domain is a domain_error, a negative order invalid_input.
  const cb::bspline<double, 2> c(2, {0, 1, 2, 3, 4, 5}, p4);
  EXPECT_THROW((void)c(0.5), std::domain_error);
  EXPECT_THROW((void)c(4.5), std::domain_error);
  EXPECT_THROW((void)c.derivative(2.0, -1), cb::invalid_input);
  EXPECT_THROW((void)c.insert_knot(0.5), std::domain_error);
}
