// Named cubic basis matrices (cubic_matrices.hpp) against independent derivations: the defining
// constraints solved in 50 digits (basis_from_constraints), the Bernstein polynomials, the closed
// B-spline pieces, and the matrices printed in the seeds after mapping their conventions
// (000 and 002 print rows for [t^3 t^2 t 1]; 001 uses [1 u u^2 u^3] with Hermite geometry
// [p0, p0', p1, p1']). Geometry conversions leave the evaluated curve unchanged.
#include "support/accuracy.hpp"

#include "curvebench/basis/bernstein.hpp"
#include "curvebench/basis/constraints.hpp"
#include "curvebench/basis/cubic_matrices.hpp"

#include <gmock/gmock.h>

#include <array>
#include <functional>
#include <string>
#include <vector>

namespace cb = curvebench;
namespace cbb = curvebench::basis;
namespace cbt = curvebench::testing;
using ::testing::HasSubstr;

namespace {

// Tolerances in eps(Real) (scaled ulps: relative to the largest entry, or to the geometry extent):
// - exact_ulps: Hermite, Bezier, Catmull-Rom and cardinal(s) with dyadic s have small integer or
//   half-integer entries: exactly representable, and cardinal_matrix's product with the Hermite
//   matrix is exact for them. Any difference is a bug.
// - sixth_ulps: the B-spline entries k/6 are one rounded division each: <= 1/2 ulp of the entry,
//   at most 4/6 of the largest entry: 1.
// - blend_ulps: T(t) · M evaluated as a sum of 4 products with t^k <= 1 and |M| <= 6, compared
//   with Bernstein / closed forms in 50 digits: a handful of roundings of terms of size <= 1
//   (the integer matrices make most products exact) [measured <= 1]; 8.
// - convert_ulps: a geometry conversion solves M_to X = M_from by LU (cond(M_to) <= ~100 for these
//   bases), then the curve is evaluated through M_to; relative to the geometry extent 4
//   [measured <= 1.5 over all 25 pairs and four types]; 16.
// - solved_ulps: where the reference is itself solved by LU in real50 (from the defining
//   constraints), it carries a few real50 roundings: 0 for IEEE types after rounding, up to a few
//   ulps for Real = real50 [measured <= 1]. 4.
constexpr double exact_ulps = 0;
constexpr double solved_ulps = 4;
constexpr double sixth_ulps = 1;
constexpr double blend_ulps = 8;
constexpr double convert_ulps = 16;

template <class Real>
class basis_matrices_test : public ::testing::Test {};
TYPED_TEST_SUITE(basis_matrices_test, cbt::all_reals);

// The matrix printed in a seed for the row vector [t^3 t^2 t 1], in the ascending convention
// (rows reversed), as exact real50 entries num / den.
cbb::matrix4<cb::real50> reversed_rows(const int (&m)[4][4], int den = 1) {
  cbb::matrix4<cb::real50> r;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) r(3 - i, j) = cb::real50(m[i][j]) / cb::real50(den);
  return r;
}

template <class Real>
::testing::AssertionResult matrix_within(const cbb::matrix4<Real>& actual, const cbb::matrix4<cb::real50>& ref,
                                         double max_ulps) {
  cb::real50 scale(0);
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) scale = std::max(scale, cb::real50(abs(ref(i, j))));
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) {
      auto r = cbt::within_scaled_ulps(actual(i, j), ref(i, j), scale, max_ulps);
      if (!r) return r << "\nentry (" << i << ", " << j << ")";
    }
  return ::testing::AssertionSuccess();
}

// The cubic fixed by four constraints, solved in 50 digits: an independent derivation of a basis.
cbb::matrix4<cb::real50> from_constraints(std::initializer_list<cbb::constraint<cb::real50>> k) {
  return cbb::matrix4<cb::real50>(cbb::basis_from_constraints<cb::real50>(k).m);
}

// A 2D geometry with dyadic coordinates (exact in every type): four rows, any role.
template <class Real>
Eigen::Matrix<Real, 4, 2> geometry() {
  Eigen::Matrix<Real, 4, 2> g;
  g << Real(0.25), Real(-1.5), Real(2.0), Real(0.75), Real(-0.625), Real(3.0), Real(1.125), Real(-2.25);
  return g;
}

template <class Real>
cbb::matrix4<Real> named(int which) {
  switch (which) {
    case 0: return cbb::hermite_matrix<Real>();
    case 1: return cbb::bezier_matrix<Real>();
    case 2: return cbb::catmull_rom_matrix<Real>();
    case 3: return cbb::uniform_bspline_matrix<Real>();
    default: return cbb::cardinal_matrix<Real>(Real(0.375));
  }
}
const std::array<const char*, 5> names{"hermite", "bezier", "catmull_rom", "bspline", "cardinal(0.375)"};

}  // namespace

TYPED_TEST(basis_matrices_test, hermite_matches_constraints_and_all_three_seeds) {
  using Real = TypeParam;
  const cbb::matrix4<Real> m = cbb::hermite_matrix<Real>();
  // G = [P0, P1, T0, T1]: P(0) = P0, P(1) = P1, P'(0) = T0, P'(1) = T1.
  EXPECT_TRUE(matrix_within<Real>(
      m, from_constraints({{cb::real50(0), 0}, {cb::real50(1), 0}, {cb::real50(0), 1}, {cb::real50(1), 1}}),
      solved_ulps));
  // Seed 000: M_h for [t^3 t^2 t 1] and G_h = [P1 P4 R1 R4] (same geometry order as ours).
  static constexpr int s000[4][4] = {{2, -2, 1, 1}, {-3, 3, -2, -1}, {0, 0, 1, 0}, {1, 0, 0, 0}};
  EXPECT_TRUE(matrix_within<Real>(m, reversed_rows(s000), exact_ulps));
  // Seed 002: a = 2(P(0) - P(1)) + P'(0) + P'(1), b = 3(P(1) - P(0)) - 2P'(0) - P'(1), c = P'(0),
  // d = P(0), for P(u) = a u^3 + b u^2 + c u + d; rows a, b, c, d over [P(0), P(1), P'(0), P'(1)].
  static constexpr int s002[4][4] = {{2, -2, 1, 1}, {-3, 3, -2, -1}, {0, 0, 1, 0}, {1, 0, 0, 0}};
  EXPECT_TRUE(matrix_within<Real>(m, reversed_rows(s002), exact_ulps));
  // Seed 001: [1 u u^2 u^3] (our row order) but geometry [f(0), f'(0), f(1), f'(1)]: column j of
  // ours is column from_col[j] of the seed's.
  static constexpr int s001[4][4] = {{1, 0, 0, 0}, {0, 1, 0, 0}, {-3, -2, 3, -1}, {2, 1, -2, 1}};
  const std::array<int, 4> from_col{0, 2, 1, 3};
  cbb::matrix4<cb::real50> mapped;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) mapped(i, j) = s001[i][from_col[static_cast<std::size_t>(j)]];
  EXPECT_TRUE(matrix_within<Real>(m, mapped, exact_ulps));
  // Seed 000's and 001's blending functions: 2t^3 - 3t^2 + 1, -2t^3 + 3t^2, t^3 - 2t^2 + t, t^3 - t^2.
  for (int k = 0; k <= 16; ++k) {
    const cb::real50 t = cb::real50(k) / 16;
    const Eigen::Matrix<Real, 1, 4> b = cbb::power_row(Real(k) / Real(16)) * m;
    const std::array<cb::real50, 4> f{2 * t * t * t - 3 * t * t + 1, -2 * t * t * t + 3 * t * t,
                                      t * t * t - 2 * t * t + t, t * t * t - t * t};
    for (int j = 0; j < 4; ++j)
      EXPECT_TRUE(cbt::within_scaled_ulps(b(j), f[static_cast<std::size_t>(j)], cb::real50(1), blend_ulps));
  }
}

TYPED_TEST(basis_matrices_test, bezier_matches_seeds_and_bernstein_polynomials) {
  using Real = TypeParam;
  const cbb::matrix4<Real> m = cbb::bezier_matrix<Real>();
  // Seed 002, [u^3 u^2 u 1] over [P1 P2 P3 P4].
  static constexpr int s002[4][4] = {{-1, 3, -3, 1}, {3, -6, 3, 0}, {-3, 3, 0, 0}, {1, 0, 0, 0}};
  EXPECT_TRUE(matrix_within<Real>(m, reversed_rows(s002), exact_ulps));
  // Seed 000: M_b = M_h · M_bh with M_bh = [1 0 0 0; 0 0 0 1; -3 3 0 0; 0 0 -3 3] (bezier_to_hermite).
  static constexpr int mbh[4][4] = {{1, 0, 0, 0}, {0, 0, 0, 1}, {-3, 3, 0, 0}, {0, 0, -3, 3}};
  cbb::matrix4<cb::real50> seed_mbh;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) seed_mbh(i, j) = mbh[i][j];
  EXPECT_TRUE(matrix_within<Real>(cbb::bezier_to_hermite<Real>(), seed_mbh, exact_ulps));
  const cbb::matrix4<cb::real50> mh = cbb::hermite_matrix<cb::real50>();
  EXPECT_TRUE(matrix_within<Real>(m, cbb::matrix4<cb::real50>(mh * seed_mbh), exact_ulps));
  // T · M_b are the cubic Bernstein polynomials (closed form of bernstein.hpp in 50 digits).
  for (int k = 0; k <= 32; ++k) {
    const Real t = Real(k) / Real(32);
    const Eigen::Matrix<Real, 1, 4> b = cbb::power_row(t) * m;
    for (int i = 0; i < 4; ++i)
      EXPECT_TRUE(cbt::within_scaled_ulps(b(i), cbb::bernstein(3, i, cb::real50(k) / 32), cb::real50(1), blend_ulps))
          << "B_" << i << " at " << k << "/32";
  }
}

TYPED_TEST(basis_matrices_test, catmull_rom_and_cardinal_match_seeds_and_their_definition) {
  using Real = TypeParam;
  const cbb::matrix4<Real> m = cbb::catmull_rom_matrix<Real>();
  // Seed 002, s = 1/2, [u^3 u^2 u 1] over [P_{i-1} P_i P_{i+1} P_{i+2}], printed without its 1/2.
  static constexpr int s002[4][4] = {{-1, 3, -3, 1}, {2, -5, 4, -1}, {-1, 0, 1, 0}, {0, 2, 0, 0}};
  EXPECT_TRUE(matrix_within<Real>(m, reversed_rows(s002, 2), exact_ulps));
  // Seed 002 as printed is twice the true matrix: its curve would not interpolate P_i (T(0) M G = 2 P_i).
  EXPECT_EQ(reversed_rows(s002)(0, 1), cb::real50(2));
  // Seed 001: constraint rows p0 = f(1) - 2f'(0), p1 = f(0), p2 = f(1), p3 = f(0) + 2f'(1); B = C^-1.
  cbb::matrix_x<cb::real50> c(4, 4);
  c << 1, -1, 1, 1, 1, 0, 0, 0, 1, 1, 1, 1, 1, 2, 4, 6;
  EXPECT_TRUE(matrix_within<Real>(m, cbb::matrix4<cb::real50>(cbb::basis_from_constraint_matrix(c).m), solved_ulps));
  // Cardinal(s), from its definition: with G = [P_{-1}, P0, P1, P2], P(0) = P0, P(1) = P1,
  // P'(0) = s (P1 - P_{-1}), P'(1) = s (P2 - P0). Solved independently in 50 digits as
  // M = M_h · K(s) where M_h comes from the Hermite constraints.
  for (double sd : {0.0, 0.25, 0.375, 0.5, 1.0}) {
    const cb::real50 s(sd);
    cbb::matrix4<cb::real50> k = cbb::matrix4<cb::real50>::Zero();
    k(0, 1) = 1;   // P(0)  = P0
    k(1, 2) = 1;   // P(1)  = P1
    k(2, 0) = -s;  // P'(0) = s (P1 - P_{-1})
    k(2, 2) = s;
    k(3, 1) = -s;  // P'(1) = s (P2 - P0)
    k(3, 3) = s;
    const cbb::matrix4<cb::real50> ref =
        from_constraints({{cb::real50(0), 0}, {cb::real50(1), 0}, {cb::real50(0), 1}, {cb::real50(1), 1}}) * k;
    EXPECT_TRUE(matrix_within<Real>(cbb::cardinal_matrix<Real>(Real(sd)), ref, solved_ulps)) << "s = " << sd;
    // Property form of the same definition on a concrete geometry.
    const Eigen::Matrix<Real, 4, 2> g = geometry<Real>();
    const Eigen::Matrix<Real, 4, 2> a = cbb::cardinal_matrix<Real>(Real(sd)) * g;
    const Eigen::Matrix<Real, 1, 2> p0 = cbb::power_row(Real(0)) * a;
    const Eigen::Matrix<Real, 1, 2> p1 = cbb::power_row(Real(1)) * a;
    const Eigen::Matrix<Real, 1, 2> d0 = cbb::power_row(Real(0), 1) * a;
    const Eigen::Matrix<Real, 1, 2> d1 = cbb::power_row(Real(1), 1) * a;
    const Eigen::Matrix<Real, 1, 2> e0 = Real(sd) * (g.row(2) - g.row(0));
    const Eigen::Matrix<Real, 1, 2> e1 = Real(sd) * (g.row(3) - g.row(1));
    for (int d = 0; d < 2; ++d) {
      EXPECT_TRUE(cbt::within_scaled_ulps(p0(d), cb::real50(g(1, d)), cb::real50(4), blend_ulps));
      EXPECT_TRUE(cbt::within_scaled_ulps(p1(d), cb::real50(g(2, d)), cb::real50(4), blend_ulps));
      EXPECT_TRUE(cbt::within_scaled_ulps(d0(d), cb::real50(e0(d)), cb::real50(4), blend_ulps));
      EXPECT_TRUE(cbt::within_scaled_ulps(d1(d), cb::real50(e1(d)), cb::real50(4), blend_ulps));
    }
  }
}

TYPED_TEST(basis_matrices_test, uniform_bspline_pieces_and_c2_joins) {
  using Real = TypeParam;
  const cbb::matrix4<Real> m = cbb::uniform_bspline_matrix<Real>();
  // The four pieces of the uniform cubic B-spline N(x) on [0, 4] read on the unit segment:
  // (1-t)^3/6, (3t^3 - 6t^2 + 4)/6, (-3t^3 + 3t^2 + 3t + 1)/6, t^3/6 (the pieces of N(t + 3),
  // N(t + 2), N(t + 1), N(t)). Their coefficients, times 6:
  static constexpr int pieces6[4][4] = {{1, 4, 1, 0}, {-3, 0, 3, 0}, {3, -6, 3, 0}, {-1, 3, -3, 1}};
  cbb::matrix4<cb::real50> ref;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) ref(i, j) = cb::real50(pieces6[i][j]) / 6;
  EXPECT_TRUE(matrix_within<Real>(m, ref, sixth_ulps));
  for (int k = 0; k <= 16; ++k) {
    const cb::real50 t = cb::real50(k) / 16;
    const cb::real50 u = 1 - t;
    const std::array<cb::real50, 4> f{u * u * u / 6, (3 * t * t * t - 6 * t * t + 4) / 6,
                                      (-3 * t * t * t + 3 * t * t + 3 * t + 1) / 6, t * t * t / 6};
    const Eigen::Matrix<Real, 1, 4> b = cbb::power_row(Real(k) / Real(16)) * m;
    for (int j = 0; j < 4; ++j)
      EXPECT_TRUE(cbt::within_scaled_ulps(b(j), f[static_cast<std::size_t>(j)], cb::real50(1), blend_ulps));
  }
  // C2 joins: for control points Q_0..Q_4, segment 0 uses Q_0..Q_3 and segment 1 uses Q_1..Q_4; the
  // value and first two derivatives at the end of segment 0 equal those at the start of segment 1.
  const Eigen::Matrix<Real, 4, 2> g0 = geometry<Real>();
  Eigen::Matrix<Real, 4, 2> g1;
  g1.topRows(3) = g0.bottomRows(3);
  g1.row(3) << Real(-0.5), Real(1.75);
  for (int order = 0; order <= 2; ++order) {
    const Eigen::Matrix<Real, 1, 2> end0 = cbb::power_row(Real(1), order) * m * g0;
    const Eigen::Matrix<Real, 1, 2> start1 = cbb::power_row(Real(0), order) * m * g1;
    for (int d = 0; d < 2; ++d)
      EXPECT_TRUE(cbt::within_scaled_ulps(end0(d), cb::real50(start1(d)), cb::real50(4), blend_ulps))
          << "order " << order;
  }
  // The third derivative jumps (a cubic spline is only C2): nonzero difference for this geometry.
  const Eigen::Matrix<Real, 1, 2> j0 = cbb::power_row(Real(1), 3) * m * g0;
  const Eigen::Matrix<Real, 1, 2> j1 = cbb::power_row(Real(0), 3) * m * g1;
  EXPECT_GT((j0 - j1).norm(), Real(1));
}

TYPED_TEST(basis_matrices_test, blending_functions_sum_to_one) {
  using Real = TypeParam;
  // Bezier, B-spline and Catmull-Rom (all four weights are positions) blend affinely: the row sums
  // of M are [1 0 0 0], so the weights T(t) M sum to 1. Hermite's position weights sum to 1 too.
  for (int which : {1, 2, 3, 4}) {
    const cbb::matrix4<Real> m = named<Real>(which);
    for (int k = 0; k <= 32; ++k) {
      const Eigen::Matrix<Real, 1, 4> b = cbb::power_row(Real(k) / Real(32)) * m;
      EXPECT_TRUE(cbt::within_scaled_ulps(Real(b.sum()), cb::real50(1), cb::real50(1), blend_ulps))
          << names[static_cast<std::size_t>(which)] << " at " << k << "/32";
    }
  }
  for (int k = 0; k <= 32; ++k) {
    const Eigen::Matrix<Real, 1, 4> b = cbb::power_row(Real(k) / Real(32)) * cbb::hermite_matrix<Real>();
    EXPECT_TRUE(cbt::within_scaled_ulps(Real(b(0) + b(1)), cb::real50(1), cb::real50(1), blend_ulps));
  }
}

TYPED_TEST(basis_matrices_test, geometry_conversion_keeps_the_curve) {
  using Real = TypeParam;
  const Eigen::Matrix<Real, 4, 2> g = geometry<Real>();
  for (int from = 0; from < 5; ++from)
    for (int to = 0; to < 5; ++to) {
      const cbb::matrix4<Real> conv = cbb::geometry_conversion<Real>(named<Real>(from), named<Real>(to));
      const Eigen::Matrix<Real, 4, 2> g_to = conv * g;
      // Reference: the original curve in 50 digits.
      const Eigen::Matrix<cb::real50, 4, 2> a50 = named<cb::real50>(from) * g.template cast<cb::real50>();
      for (int k = 0; k <= 8; ++k) {
        const Eigen::Matrix<Real, 1, 2> p = cbb::power_row(Real(k) / Real(8)) * named<Real>(to) * g_to;
        const Eigen::Matrix<cb::real50, 1, 2> r = cbb::power_row(cb::real50(k) / 8) * a50;
        for (int d = 0; d < 2; ++d)
          EXPECT_TRUE(cbt::within_scaled_ulps(p(d), r(d), cb::real50(4), convert_ulps))
              << names[static_cast<std::size_t>(from)] << " -> " << names[static_cast<std::size_t>(to)] << " at " << k
              << "/8";
      }
    }
  // bezier_to_hermite is the Bezier -> Hermite conversion.
  cbb::matrix4<cb::real50> b2h50 = cbb::bezier_to_hermite<cb::real50>();
  EXPECT_TRUE(matrix_within<Real>(
      cbb::geometry_conversion<Real>(cbb::bezier_matrix<Real>(), cbb::hermite_matrix<Real>()), b2h50, blend_ulps));
  EXPECT_TRUE(matrix_within<cb::real50>(
      cbb::geometry_conversion<cb::real50>(cbb::bezier_matrix<cb::real50>(), cbb::hermite_matrix<cb::real50>()), b2h50,
      blend_ulps));
}

TEST(basis_matrices, singular_target_basis_throws) {
  // cardinal(0) has zero tangents: rank 2, nothing can be expressed in it.
  try {
    (void)cbb::geometry_conversion<double>(cbb::bezier_matrix<double>(), cbb::cardinal_matrix<double>(0.0));
    FAIL() << "expected invalid_input";
  } catch (const cb::invalid_input& e) {
    EXPECT_STREQ(e.what(), "to: basis matrix is singular (rank 2 of 4); geometry cannot be expressed in it");
  }
  // Converting FROM a singular basis is fine (it is just a curve family with fewer curves).
  EXPECT_NO_THROW(
      (void)cbb::geometry_conversion<double>(cbb::cardinal_matrix<double>(0.0), cbb::bezier_matrix<double>()));
  try {
    (void)cbb::cardinal_matrix<double>(std::numeric_limits<double>::quiet_NaN());
    FAIL() << "expected invalid_input";
  } catch (const cb::invalid_input& e) {
    EXPECT_STREQ(e.what(), "s = nan: must be finite");
  }
}
