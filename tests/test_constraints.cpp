// basis_from_constraints: the seeds' constraint examples (Hermite, Bezier, seed 000's end points +
// mid-point tangent with its erratum, seed 001's quadratic f(.5), f'(.5), f''(.5) and its
// Catmull-Rom constraint rows), a quintic Hermite basis against its factored closed form,
// polynomial reproduction for mixed constraints of degree 6, and the singular-constraint errors.
#include "support/accuracy.hpp"

#include "curvebench/basis/constraints.hpp"
#include "curvebench/basis/cubic_matrices.hpp"

#include <gmock/gmock.h>

#include <array>
#include <limits>
#include <string>
#include <vector>

namespace cb = curvebench;
namespace cbt = curvebench::testing;
using ::testing::HasSubstr;
using ::testing::Not;

namespace {

// Tolerances in eps(Real), relative to the largest entry of the exact matrix (scaled ulps).
// Measured maxima over the four Real types are in brackets.
// - small_inverse_ulps: M = C^{-1} by fully pivoted LU for the cubic and quadratic examples. Every
//   C here has dyadic entries and cond_1(C) <= 60; a backward-stable LU bounds the error by
//   ~ n * cond * eps in the worst case, but eliminating these small integer matrices is nearly
//   exact [0.67]; 8 leaves room without hiding a wrong entry (off by >= 1/8 = 1e6 ulps in float).
// - quintic_ulps: 6 x 6 with cond_1(C) ~ 1e3 and entries up to 15; the blending functions are
//   sums of six products of M's entries with t^k <= 1 [16, as 16 / 6 of the bound used]; 64.
// - blending_ulps: T(t) · M for the cubic examples: n + 1 = 4 products of entries within
//   small_inverse_ulps plus one rounding each [0].
// - reproduction_ulps: degree-6 mixed constraints on [-1, 1]: the coefficients M · G carry
//   ~ cond * eps relative error in the worst case, mostly cancelling [3]; 64.
constexpr double small_inverse_ulps = 8;
constexpr double quintic_ulps = 64;
constexpr double blending_ulps = 4 * small_inverse_ulps;
constexpr double reproduction_ulps = 64;

template <class Real>
class constraints_test : public ::testing::Test {};
TYPED_TEST_SUITE(constraints_test, cbt::all_reals);

// An exact rational matrix: entries num / den, built in real50.
template <int N>
cb::basis::matrix_x<cb::real50> exact(const int (&num)[N][N], int den = 1) {
  cb::basis::matrix_x<cb::real50> m(N, N);
  for (int i = 0; i < N; ++i)
    for (int j = 0; j < N; ++j) m(i, j) = cb::real50(num[i][j]) / cb::real50(den);
  return m;
}

template <class Real>
::testing::AssertionResult matrix_within(const cb::basis::matrix_x<Real>& actual,
                                         const cb::basis::matrix_x<cb::real50>& ref, double max_ulps) {
  if (actual.rows() != ref.rows() || actual.cols() != ref.cols())
    return ::testing::AssertionFailure() << "shape " << actual.rows() << "x" << actual.cols() << " vs " << ref.rows()
                                         << "x" << ref.cols();
  cb::real50 scale(0);
  for (Eigen::Index i = 0; i < ref.rows(); ++i)
    for (Eigen::Index j = 0; j < ref.cols(); ++j) scale = std::max(scale, cb::real50(abs(ref(i, j))));
  for (Eigen::Index i = 0; i < ref.rows(); ++i)
    for (Eigen::Index j = 0; j < ref.cols(); ++j) {
      auto r = cbt::within_scaled_ulps(actual(i, j), ref(i, j), scale, max_ulps);
      if (!r) return r << "\nentry (" << i << ", " << j << ")";
    }
  return ::testing::AssertionSuccess();
}

template <class Real>
cb::basis::matrix_x<Real> dynamic(const cb::basis::matrix4<Real>& m) {
  return cb::basis::matrix_x<Real>(m);
}

template <class Real>
std::string message_of(const std::vector<cb::basis::constraint<Real>>& k) {
  try {
    (void)cb::basis::basis_from_constraints(k);
  } catch (const cb::invalid_input& e) {
    return e.what();
  }
  return "(no exception)";
}

}  // namespace

TYPED_TEST(constraints_test, hermite_from_end_values_and_tangents) {
  using Real = TypeParam;
  // Geometry order of cubic_matrices.hpp: [P(0), P(1), P'(0), P'(1)].
  const auto r = cb::basis::basis_from_constraints<Real>({{Real(0), 0}, {Real(1), 0}, {Real(0), 1}, {Real(1), 1}});
  // C rows: T(0), T(1), T'(0), T'(1) (seed 000's B_h with columns reversed; seed 002's 4 equations).
  static constexpr int c[4][4] = {{1, 0, 0, 0}, {1, 1, 1, 1}, {0, 1, 0, 0}, {0, 1, 2, 3}};
  EXPECT_TRUE(matrix_within<Real>(r.c, exact(c), 0));
  // Seed 001 derives the same M in its own order [1 u u^2 u^3] with geometry [f(0), f'(0), f(1), f'(1)]:
  // rows 1 0 0 0 / 0 1 0 0 / -3 -2 3 -1 / 2 1 -2 1; reorder its columns to [f(0), f(1), f'(0), f'(1)].
  static constexpr int seed001[4][4] = {{1, 0, 0, 0}, {0, 1, 0, 0}, {-3, -2, 3, -1}, {2, 1, -2, 1}};
  cb::basis::matrix_x<cb::real50> mapped(4, 4);
  const std::array<int, 4> from_col{0, 2, 1, 3};
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) mapped(i, j) = seed001[i][from_col[static_cast<std::size_t>(j)]];
  EXPECT_TRUE(matrix_within<Real>(r.m, mapped, small_inverse_ulps));
  EXPECT_TRUE(matrix_within<Real>(r.m, dynamic(cb::basis::hermite_matrix<cb::real50>()), small_inverse_ulps));
  EXPECT_EQ(r.degree(), 3);
  EXPECT_GT(r.rcond, Real(0));
  EXPECT_LE(r.rcond, Real(1));
}

TYPED_TEST(constraints_test, bezier_from_control_point_rows) {
  using Real = TypeParam;
  // Each control point as a functional of the cubic: P0 = P(0), P1 = P(0) + P'(0)/3,
  // P2 = P(1) - P'(1)/3, P3 = P(1) (from P'(0) = 3(P1 - P0), P'(1) = 3(P3 - P2)).
  cb::basis::matrix_x<Real> c(4, 4);
  c.row(0) = cb::basis::power_basis_row(3, Real(0));
  c.row(1) = cb::basis::power_basis_row(3, Real(0)) + cb::basis::power_basis_row(3, Real(0), 1) / Real(3);
  c.row(2) = cb::basis::power_basis_row(3, Real(1)) - cb::basis::power_basis_row(3, Real(1), 1) / Real(3);
  c.row(3) = cb::basis::power_basis_row(3, Real(1));
  const auto r = cb::basis::basis_from_constraint_matrix(c);
  // Seed 002's Bezier matrix [u^3 u^2 u 1]: -1 3 -3 1 / 3 -6 3 0 / -3 3 0 0 / 1 0 0 0, rows reversed.
  static constexpr int bez[4][4] = {{1, 0, 0, 0}, {-3, 3, 0, 0}, {3, -6, 3, 0}, {-1, 3, -3, 1}};
  EXPECT_TRUE(matrix_within<Real>(r.m, exact(bez), small_inverse_ulps));
  // Equivalently (seed 000): M_b = M_h · M_bh with M_h from the Hermite constraints.
  const auto h = cb::basis::basis_from_constraints<Real>({{Real(0), 0}, {Real(1), 0}, {Real(0), 1}, {Real(1), 1}});
  const cb::basis::matrix_x<Real> mb = h.m * dynamic(cb::basis::bezier_to_hermite<Real>());
  EXPECT_TRUE(matrix_within<Real>(mb, exact(bez), small_inverse_ulps));
}

TYPED_TEST(constraints_test, seed000_end_points_and_mid_point_tangent) {
  using Real = TypeParam;
  // x(0), x(0.5), x'(0.5), x(1).
  const Real h = Real(1) / Real(2);
  const auto r = cb::basis::basis_from_constraints<Real>({{Real(0), 0}, {h, 0}, {h, 1}, {Real(1), 0}});
  // Seed 000's constraint matrix B (columns t^3 t^2 t 1): 0 0 0 1 / .125 .25 .5 1 / .75 1 1 0 / 1 1 1 1;
  // ours has the columns reversed; entries in eighths.
  static constexpr int c8[4][4] = {{8, 0, 0, 0}, {8, 4, 2, 1}, {0, 8, 8, 6}, {8, 8, 8, 8}};
  EXPECT_TRUE(matrix_within<Real>(r.c, exact(c8, 8), 0));
  // Seed 000's M (rows t^3 .. 1) with the DESIGN.md erratum applied: -4 0 -4 4 / 8 -4 6 -4 /
  // -5 4 -2 1 / 1 0 0 0, reversed to ascending rows.
  static constexpr int m[4][4] = {{1, 0, 0, 0}, {-5, 4, -2, 1}, {8, -4, 6, -4}, {-4, 0, -4, 4}};
  EXPECT_TRUE(matrix_within<Real>(r.m, exact(m), small_inverse_ulps));
  // The row as printed (-5 5 -2 1) is wrong: f_2 = -4t^2 + 4t needs 4 in the t row.
  EXPECT_GT(cbt::scaled_ulps(r.m(1, 1), cb::real50(5), cb::real50(8)), cb::real50(1e5));
  // The seed's blending functions (which DESIGN.md says are right) equal T(t) · M.
  for (int k = 0; k <= 16; ++k) {
    const Real t = Real(k) / Real(16);
    const cb::real50 s = cb::real50(k) / 16;
    const std::array<cb::real50, 4> f{-4 * s * s * s + 8 * s * s - 5 * s + 1, -4 * s * s + 4 * s,
                                      -4 * s * s * s + 6 * s * s - 2 * s, 4 * s * s * s - 4 * s * s + s};
    const Eigen::Matrix<Real, 1, Eigen::Dynamic> b = cb::basis::power_basis_row(3, t) * r.m;
    for (int j = 0; j < 4; ++j)
      EXPECT_TRUE(cbt::within_scaled_ulps(b(j), f[static_cast<std::size_t>(j)], cb::real50(8), blending_ulps))
          << "f_" << j + 1 << " at t = " << k << "/16";
  }
}

TYPED_TEST(constraints_test, seed001_quadratic_value_slope_curvature_at_half) {
  using Real = TypeParam;
  const Real h = Real(1) / Real(2);
  const auto r = cb::basis::basis_from_constraints<Real>({{h, 0}, {h, 1}, {h, 2}});
  // Seed 001: C = [1 .5 .25; 0 1 1; 0 0 2], B = C^-1 = [1 -.5 .125; 0 1 -.5; 0 0 .5] (same convention).
  static constexpr int c4[3][3] = {{4, 2, 1}, {0, 4, 4}, {0, 0, 8}};
  static constexpr int b8[3][3] = {{8, -4, 1}, {0, 8, -4}, {0, 0, 4}};
  EXPECT_TRUE(matrix_within<Real>(r.c, exact(c4, 4), 0));
  EXPECT_TRUE(matrix_within<Real>(r.m, exact(b8, 8), small_inverse_ulps));
  EXPECT_EQ(r.degree(), 2);
}

TYPED_TEST(constraints_test, seed001_catmull_rom_constraint_rows) {
  using Real = TypeParam;
  // Seed 001 (s = 1/2), geometry [p0, p1, p2, p3] for the segment p1 -> p2:
  //   p0 = f(1) - 2 f'(0) = a0 - a1 + a2 + a3,   p1 = f(0) = a0,
  //   p2 = f(1) = a0 + a1 + a2 + a3,             p3 = f(0) + 2 f'(1) = a0 + 2a1 + 4a2 + 6a3.
  cb::basis::matrix_x<Real> c(4, 4);
  c.row(0) = cb::basis::power_basis_row(3, Real(1)) - Real(2) * cb::basis::power_basis_row(3, Real(0), 1);
  c.row(1) = cb::basis::power_basis_row(3, Real(0));
  c.row(2) = cb::basis::power_basis_row(3, Real(1));
  c.row(3) = cb::basis::power_basis_row(3, Real(0)) + Real(2) * cb::basis::power_basis_row(3, Real(1), 1);
  static constexpr int seed_c[4][4] = {{1, -1, 1, 1}, {1, 0, 0, 0}, {1, 1, 1, 1}, {1, 2, 4, 6}};
  EXPECT_TRUE(matrix_within<Real>(c, exact(seed_c), 0));
  const auto r = cb::basis::basis_from_constraint_matrix(c);
  // Catmull-Rom, (1/2) [0 2 0 0; -1 0 1 0; 2 -5 4 -1; -1 3 -3 1] (seed 002's matrix, rows reversed,
  // with its missing factor 1/2).
  static constexpr int cr[4][4] = {{0, 2, 0, 0}, {-1, 0, 1, 0}, {2, -5, 4, -1}, {-1, 3, -3, 1}};
  EXPECT_TRUE(matrix_within<Real>(r.m, exact(cr, 2), small_inverse_ulps));
  EXPECT_TRUE(matrix_within<Real>(r.m, dynamic(cb::basis::catmull_rom_matrix<cb::real50>()), small_inverse_ulps));
}

TYPED_TEST(constraints_test, quintic_hermite_blending_functions) {
  using Real = TypeParam;
  // Value, first and second derivative at both ends: degree 5. Closed forms, derived from the zeros
  // each function must have (a triple zero at the other end, a zero of the right order at its own):
  //   H00 = (1-t)^3 (1 + 3t + 6t^2)   H01 = t (1-t)^3 (1 + 3t)   H02 = t^2 (1-t)^3 / 2
  //   H10 = t^3 (10 - 15t + 6t^2)     H11 = t^3 (1-t) (3t - 4)   H12 = t^3 (1-t)^2 / 2
  const auto r = cb::basis::basis_from_constraints<Real>(
      {{Real(0), 0}, {Real(0), 1}, {Real(0), 2}, {Real(1), 0}, {Real(1), 1}, {Real(1), 2}});
  ASSERT_EQ(r.degree(), 5);
  // Exact coefficients of the six closed forms (columns), in halves.
  static constexpr int m2[6][6] = {{2, 0, 0, 0, 0, 0},        {0, 2, 0, 0, 0, 0},       {0, 0, 1, 0, 0, 0},
                                   {-20, -12, -3, 20, -8, 1}, {30, 16, 3, -30, 14, -2}, {-12, -6, -1, 12, -6, 1}};
  EXPECT_TRUE(matrix_within<Real>(r.m, exact(m2, 2), quintic_ulps));
  for (int k = 0; k <= 32; ++k) {
    const Real t = Real(k) / Real(32);
    const cb::real50 s = cb::real50(k) / 32;
    const cb::real50 u = 1 - s;
    const std::array<cb::real50, 6> h{
        u * u * u * (1 + 3 * s + 6 * s * s),   s * u * u * u * (1 + 3 * s), s * s * u * u * u / 2,
        s * s * s * (10 - 15 * s + 6 * s * s), s * s * s * u * (3 * s - 4), s * s * s * u * u / 2};
    const Eigen::Matrix<Real, 1, Eigen::Dynamic> b = cb::basis::power_basis_row(5, t) * r.m;
    for (int j = 0; j < 6; ++j)
      EXPECT_TRUE(cbt::within_scaled_ulps(b(j), h[static_cast<std::size_t>(j)], cb::real50(1), quintic_ulps))
          << "H" << j << " at t = " << k << "/32";
    // The value functions are a partition of unity (any constant is reproduced).
    EXPECT_TRUE(cbt::within_scaled_ulps(Real(b(0) + b(3)), cb::real50(1), cb::real50(1), quintic_ulps));
  }
}

TYPED_TEST(constraints_test, mixed_degree6_constraints_reproduce_a_polynomial) {
  using Real = TypeParam;
  // q(t) = sum_k q_k t^k, degree 6; the constraint values are q's derivatives at the constraint
  // parameters (computed in real50 from the exact coefficients); M · G must give back q_k.
  const std::array<int, 7> q{3, -2, 5, 1, -4, 2, -1};
  const std::vector<cb::basis::constraint<Real>> k{{Real(-1), 0},   {Real(-1), 1}, {Real(-0.5), 0}, {Real(0), 2},
                                                   {Real(0.25), 3}, {Real(1), 0},  {Real(1), 1}};
  const auto r = cb::basis::basis_from_constraints(k);
  cb::basis::matrix_x<cb::real50> g50(7, 1);
  cb::real50 qmax(0);
  for (std::size_t j = 0; j < k.size(); ++j) {
    const Eigen::Matrix<cb::real50, 1, Eigen::Dynamic> row =
        cb::basis::power_basis_row(6, cb::real50(k[j].t), k[j].order);
    cb::real50 v(0);
    for (int i = 0; i <= 6; ++i) v += row(i) * q[static_cast<std::size_t>(i)];
    g50(static_cast<Eigen::Index>(j), 0) = v;
  }
  for (int qi : q) qmax = std::max(qmax, cb::real50(std::abs(qi)));
  const cb::basis::matrix_x<Real> g = g50.template cast<Real>();
  const cb::basis::matrix_x<Real> a = r.m * g;
  for (int i = 0; i <= 6; ++i)
    EXPECT_TRUE(cbt::within_scaled_ulps(a(i, 0), cb::real50(q[static_cast<std::size_t>(i)]), qmax, reproduction_ulps))
        << "coefficient " << i;
}

TEST(constraints, singular_and_bad_constraints_name_the_culprits) {
  EXPECT_EQ(message_of<double>({}), "constraints: 0 given, at least 1 required (one per polynomial coefficient)");
  EXPECT_EQ(message_of<double>({{0.0, 0}, {std::numeric_limits<double>::quiet_NaN(), 0}}),
            "constraints[1].t = nan: must be finite");
  EXPECT_EQ(message_of<double>({{0.0, 0}, {1.0, -1}}), "constraints[1].order = -1: derivative order must be >= 0");
  EXPECT_THAT(message_of<double>({{0.0, 0}, {1.0, 0}, {0.0, 1}, {1.0, 4}}),
              HasSubstr("constraints[3].order = 4 > degree 3 (4 constraints fix a polynomial of that degree): its row "
                        "of C is zero"));
  EXPECT_EQ(message_of<double>({{0.0, 0}, {0.5, 1}, {1.0, 0}, {0.5, 1}}),
            "constraints[3] (t = 0.5, order 1) repeats constraints[1]: two equal rows of C, the constraints are "
            "singular");
  // A parabola's slope at the midpoint is fixed by its values at -1 and 1: all three rows dependent.
  EXPECT_EQ(message_of<double>({{-1.0, 0}, {1.0, 0}, {0.0, 1}}),
            "constraints are singular: constraints[0] (t = -1, order 0), constraints[1] (t = 1, order 0), "
            "constraints[2] (t = 0, order 1) are linearly dependent (rank 2 of 3); no polynomial of degree 2 is "
            "fixed by them");
  // A cubic's second derivative is linear: f''(0.5) = (f''(0) + f''(1)) / 2. constraints[3] is not involved.
  const std::string m = message_of<double>({{0.0, 2}, {1.0, 2}, {0.5, 2}, {0.0, 0}});
  EXPECT_THAT(m, HasSubstr("constraints[0] (t = 0, order 2), constraints[1] (t = 1, order 2), constraints[2] (t = "
                           "0.5, order 2) are linearly dependent (rank 3 of 4)"));
  EXPECT_THAT(m, Not(HasSubstr("constraints[3]")));
  // Numerically coincident parameters: rank-deficient at double precision.
  EXPECT_THAT(message_of<double>({{0.0, 0}, {1e-17, 0}}), HasSubstr("constraints are singular"));
  // Hand-built matrices: shape, finiteness and singularity.
  EXPECT_THROW((void)cb::basis::basis_from_constraint_matrix(cb::basis::matrix_x<double>(2, 3)), cb::invalid_input);
  cb::basis::matrix_x<double> s(2, 2);
  s << 1, 2, 2, 4;
  try {
    (void)cb::basis::basis_from_constraint_matrix(s);
    FAIL();
  } catch (const cb::invalid_input& e) {
    EXPECT_THAT(e.what(), HasSubstr("row 0, row 1 are linearly dependent (rank 1 of 2)"));
  }
  s(1, 1) = std::numeric_limits<double>::infinity();
  try {
    (void)cb::basis::basis_from_constraint_matrix(s);
    FAIL();
  } catch (const cb::invalid_input& e) {
    EXPECT_STREQ(e.what(), "constraint matrix(1, 1) = inf: must be finite");
  }
}

TEST(constraints, ill_conditioned_float_interpolation_is_rejected) {
  // Value constraints at 14 equispaced points of [0, 1]: the monomial Vandermonde matrix has
  // cond ~ 1e10 >> 1 / eps(float) ~ 8e6. In float this is rejected (as singular or with a
  // reciprocal condition below eps), in double it is accepted (1e10 * 1.1e-16 ~ 1e-6).
  std::vector<cb::basis::constraint<float>> kf;
  std::vector<cb::basis::constraint<double>> kd;
  for (int i = 0; i < 14; ++i) {
    kf.push_back({static_cast<float>(i) / 13.0f, 0});
    kd.push_back({static_cast<double>(i) / 13.0, 0});
  }
  EXPECT_THAT(message_of<float>(kf), HasSubstr("singular"));
  const auto r = cb::basis::basis_from_constraints(kd);
  EXPECT_LT(r.rcond, 1e-8);
  EXPECT_GT(r.rcond, 1e-16);
}
