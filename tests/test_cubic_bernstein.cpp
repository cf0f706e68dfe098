// basis/detail/cubic_bernstein.hpp: the shared cubic Bernstein kernels (value, derivatives, split)
// in both forms, against the power form of the same cubic at 50 digits, in float, double and long
// double, for scalars and for points; and the operation order each caller's recorded results depend
// on (bit for bit).
//
// Reference: with the coefficients b_k of the Real under test converted exactly to real50, the power
// form a0 + a1 t + a2 t^2 + a3 t^3 with a0 = b0, a1 = 3 (b1 - b0), a2 = 3 (b2 - 2 b1 + b0),
// a3 = b3 - 3 b2 + 3 b1 - b0 and its derivatives, at t converted exactly (an algorithm independent
// of de Casteljau's triangle, evaluated 100 bits beyond double).
//
// Tolerances, in eps(Real) times M = max_k |b_k| for t in [0, 1], with u = eps / 2 (the header's
// analysis, each rounding at most u times the size of its result):
//   value        8: a step rounds by at most 5 u M (difference or fl(1 - t), product, sum) and
//                   carries the level below with weights summing to 1; three levels, 15 u M.
//   first       36: affine, the differences (2 u M each, |d| <= 2 M), two affine steps on them
//                   (20 u M), times 3 with its rounding: 72 u M; convex, q1 - q0 (12 u M + 2 u M)
//                   times 3: 48 u M.
//   second      96: affine, (b2 - 2 b1) + b0 within 7 u M (|d| <= 4 M), a step (20 u M), times 6
//                   with its rounding: 186 u M; convex, nested differences 8 u M, a convex step
//                   12 u M, times 6: 144 u M. 192 u M covers both.
//   third       96: (b3 - b0) - 3 (b2 - b1) within 22 u M, times 6 with its rounding: 180 u M.
//   split        8: every coefficient of either piece is a triangle entry (within 15 u M), and a
//                   cubic moves by at most its largest coefficient change (partition of unity).
// A wrong weight, sign, level or form breaks these bounds by orders of magnitude (checked by
// mutating the kernels when this test was written).
#include "support/accuracy.hpp"

#include "curvebench/basis/detail/cubic_bernstein.hpp"
#include "curvebench/core/point.hpp"
#include "curvebench/reference/multiprecision.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

namespace {

namespace cb = curvebench;
namespace cbt = curvebench::testing;
namespace bd = curvebench::basis::detail;
using cb::real50;

/// The order-th derivative of the power form of the cubic with Bernstein coefficients b at t.
real50 power_form(const std::array<real50, 4>& b, const real50& t, int order) {
  const real50 a0 = b[0], a1 = 3 * (b[1] - b[0]), a2 = 3 * (b[2] - 2 * b[1] + b[0]),
               a3 = b[3] - 3 * b[2] + 3 * b[1] - b[0];
  switch (order) {
    case 0: return a0 + t * (a1 + t * (a2 + t * a3));
    case 1: return a1 + t * (2 * a2 + t * 3 * a3);
    case 2: return 2 * a2 + 6 * t * a3;
    default: return 6 * a3;
  }
}

/// Coefficient sets: random in [-1, 1], random spread over 2^-20..2^20, a near-cancelling set (a
/// cubic whose value is much smaller than its coefficients) and constant / linear ones.
template <class Real>
std::vector<std::array<Real, 4>> coefficient_sets() {
  std::mt19937_64 rng(29);
  std::uniform_real_distribution<double> unit(-1.0, 1.0), exponent(-20.0, 20.0);
  std::vector<std::array<Real, 4>> out;
  for (int i = 0; i < 200; ++i) {
    std::array<Real, 4> b{};
    for (auto& x : b) x = static_cast<Real>(unit(rng));
    out.push_back(b);
  }
  for (int i = 0; i < 100; ++i) {
    std::array<Real, 4> b{};
    for (auto& x : b) x = static_cast<Real>(unit(rng) * std::exp2(exponent(rng)));
    out.push_back(b);
  }
  out.push_back({Real(1), Real(-1), Real(1), Real(-1)});
  out.push_back({Real(3), Real(3), Real(3), Real(3)});
  out.push_back({Real(0), Real(1) / Real(3), Real(2) / Real(3), Real(1)});
  return out;
}

/// Parameters: 0, 1, their neighbours, 1/2, and random ones in [0, 1].
template <class Real>
std::vector<Real> parameters() {
  std::vector<Real> ts{Real(0),
                       Real(1),
                       Real(1) / Real(2),
                       std::nextafter(Real(1), Real(0)),
                       std::numeric_limits<Real>::denorm_min(),
                       std::numeric_limits<Real>::epsilon()};
  std::mt19937_64 rng(2029);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int i = 0; i < 40; ++i) ts.push_back(static_cast<Real>(unit(rng)));
  return ts;
}

template <class Real>
std::array<real50, 4> to50(const std::array<Real, 4>& b) {
  return {real50(b[0]), real50(b[1]), real50(b[2]), real50(b[3])};
}

template <class Real>
real50 scale_of(const std::array<Real, 4>& b) {
  using std::abs;
  real50 m(0);
  for (const Real& x : b) m = std::max(m, real50(abs(x)));
  return m == 0 ? real50(1) : m;
}

constexpr std::array<double, 4> derivative_ulps{8, 36, 96, 96};  // see the header
constexpr double split_ulps = 8;

template <class Real>
class cubic_bernstein_kernels : public ::testing::Test {};
TYPED_TEST_SUITE(cubic_bernstein_kernels, cbt::ieee_reals);

template <bd::cubic_form Form, class Real>
void check_value_and_derivatives() {
  for (const auto& b : coefficient_sets<Real>()) {
    const auto b50 = to50(b);
    const real50 m = scale_of(b);
    for (const Real& t : parameters<Real>()) {
      for (int order = 0; order <= 3; ++order) {
        const Real got = bd::cubic_derivative<Form>(b, t, order);
        ASSERT_TRUE(cbt::within_scaled_ulps(got, power_form(b50, real50(t), order), m,
                                            derivative_ulps[static_cast<std::size_t>(order)]))
            << "form " << static_cast<int>(Form) << " order " << order << " t " << cbt::exact_text(t);
      }
      // The single-purpose kernels are the same computations as cubic_derivative's cases.
      EXPECT_EQ(bd::cubic_value<Form>(b[0], b[1], b[2], b[3], t), bd::cubic_derivative<Form>(b, t, 0));
      EXPECT_EQ(bd::cubic_de_casteljau<Form>(b[0], b[1], b[2], b[3], t).p, bd::cubic_derivative<Form>(b, t, 0));
    }
  }
}

TYPED_TEST(cubic_bernstein_kernels, convex_form_matches_the_power_form_at_50_digits) {
  check_value_and_derivatives<bd::cubic_form::convex, TypeParam>();
}

TYPED_TEST(cubic_bernstein_kernels, affine_form_matches_the_power_form_at_50_digits) {
  check_value_and_derivatives<bd::cubic_form::affine, TypeParam>();
}

// The pieces of the split, evaluated exactly (power form at 50 digits) at tau, are the cubic at
// t tau (left) and t + (1 - t) tau (right); both start / end at the original end points exactly
// and meet at the value at t.
template <bd::cubic_form Form, class Real>
void check_split() {
  using std::abs;
  for (const auto& b : coefficient_sets<Real>()) {
    const auto b50 = to50(b);
    const real50 m = scale_of(b);
    for (const Real& t : parameters<Real>()) {
      const auto [left, right] = bd::cubic_split<Form>(b, t);
      EXPECT_EQ(left[0], b[0]);
      EXPECT_EQ(right[3], b[3]);
      EXPECT_EQ(left[3], right[0]);
      EXPECT_EQ(left[3], bd::cubic_value<Form>(b[0], b[1], b[2], b[3], t));
      const auto l50 = to50(left), r50 = to50(right);
      const real50 t50(t);
      for (int k = 0; k <= 8; ++k) {
        const real50 tau = real50(k) / 8;
        // Both sides are exact (50 digits) evaluations, so the distance is the split's own error,
        // measured in eps(Real) * M.
        const real50 unit = real50(cb::epsilon<Real>()) * m;
        ASSERT_LE(abs(power_form(l50, tau, 0) - power_form(b50, t50 * tau, 0)) / unit, split_ulps)
            << "left, t " << cbt::exact_text(t) << " tau " << k << "/8";
        ASSERT_LE(abs(power_form(r50, tau, 0) - power_form(b50, t50 + (1 - t50) * tau, 0)) / unit, split_ulps)
            << "right, t " << cbt::exact_text(t) << " tau " << k << "/8";
      }
    }
  }
}

TYPED_TEST(cubic_bernstein_kernels, convex_split_pieces_are_the_cubic_on_each_side) {
  check_split<bd::cubic_form::convex, TypeParam>();
}

TYPED_TEST(cubic_bernstein_kernels, affine_split_pieces_are_the_cubic_on_each_side) {
  check_split<bd::cubic_form::affine, TypeParam>();
}

// Points: each coordinate is the scalar kernel on that coordinate's coefficients (the kernels are
// coordinate-wise), so the scalar bounds above hold per coordinate.
TEST(cubic_bernstein_kernels_points, each_coordinate_is_the_scalar_kernel) {
  using P = cb::point<double, 3>;
  const auto sets = coefficient_sets<double>();
  for (std::size_t i = 0; i + 2 < sets.size(); i += 3) {
    std::array<P, 4> b;
    for (std::size_t k = 0; k < 4; ++k) b[k] = P(sets[i][k], sets[i + 1][k], sets[i + 2][k]);
    for (const double t : parameters<double>()) {
      for (int order = 0; order <= 3; ++order) {
        const P conv = bd::cubic_derivative<bd::cubic_form::convex>(b, t, order);
        const P aff = bd::cubic_derivative<bd::cubic_form::affine>(b, t, order);
        for (int d = 0; d < 3; ++d) {
          const auto& s = sets[i + static_cast<std::size_t>(d)];
          EXPECT_EQ(conv[d], bd::cubic_derivative<bd::cubic_form::convex>(s, t, order)) << order;
          EXPECT_EQ(aff[d], bd::cubic_derivative<bd::cubic_form::affine>(s, t, order)) << order;
        }
      }
    }
  }
}

// The operation order the callers' recorded results were computed with, written out: the convex
// form is piecewise_cubic's bezier algorithm (harness records of the "bezier" algorithm), the affine
// form the keyframe channel's segments and time residual (Blender's float32 F-curves are compared
// with it). The kernels must reproduce them bit for bit (in float, where a reordering shows most).
TEST(cubic_bernstein_kernels_recorded_order, both_forms_are_bit_identical_to_the_recorded_operations) {
  for (const auto& b : coefficient_sets<float>()) {
    for (const float t : parameters<float>()) {
      // convex (piecewise_cubic before the kernels were shared)
      const float s = 1.0f - t;
      const float r0 = s * b[0] + t * b[1], r1 = s * b[1] + t * b[2], r2 = s * b[2] + t * b[3];
      const float q0 = s * r0 + t * r1, q1 = s * r1 + t * r2;
      const float n0 = (b[2] - b[1]) - (b[1] - b[0]), n1 = (b[3] - b[2]) - (b[2] - b[1]);
      EXPECT_EQ(bd::cubic_derivative<bd::cubic_form::convex>(b, t, 0), s * q0 + t * q1);
      EXPECT_EQ(bd::cubic_derivative<bd::cubic_form::convex>(b, t, 1), 3.0f * (q1 - q0));
      EXPECT_EQ(bd::cubic_derivative<bd::cubic_form::convex>(b, t, 2), 6.0f * (s * n0 + t * n1));
      EXPECT_EQ(bd::cubic_derivative<bd::cubic_form::convex>(b, t, 3), 6.0f * ((b[3] - b[0]) + 3.0f * (b[1] - b[2])));
      // affine (channel/detail/cubic_time.hpp and channel_segment.hpp before)
      const float a0 = b[0] + t * (b[1] - b[0]), a1 = b[1] + t * (b[2] - b[1]), a2 = b[2] + t * (b[3] - b[2]);
      const float c0 = a0 + t * (a1 - a0), c1 = a1 + t * (a2 - a1);
      const float d0 = b[1] - b[0], d1 = b[2] - b[1], d2 = b[3] - b[2];
      const float e0 = d0 + t * (d1 - d0), e1 = d1 + t * (d2 - d1);
      const float f0 = b[2] - 2.0f * b[1] + b[0], f1 = b[3] - 2.0f * b[2] + b[1];
      EXPECT_EQ(bd::cubic_derivative<bd::cubic_form::affine>(b, t, 0), c0 + t * (c1 - c0));
      EXPECT_EQ(bd::cubic_derivative<bd::cubic_form::affine>(b, t, 1), 3.0f * (e0 + t * (e1 - e0)));
      EXPECT_EQ(bd::cubic_derivative<bd::cubic_form::affine>(b, t, 2), 6.0f * (f0 + t * (f1 - f0)));
      EXPECT_EQ(bd::cubic_derivative<bd::cubic_form::affine>(b, t, 3), 6.0f * ((b[3] - b[0]) - 3.0f * (b[2] - b[1])));
    }
  }
}

}  // namespace
