// C2 cubic spline: the O(n) tridiagonal and cyclic (Sherman-Morrison) solvers by residuals, the
// four end conditions (natural P'' = 0, clamped, not-a-knot, periodic), C2 continuity at knots,
// cubic reproduction (not-a-knot; clamped with exact slopes), agreement with the real50 instance
// of the same data, and bad input.
#include "support/accuracy.hpp"
#include "support/fixtures.hpp"

#include "curvebench/curves/detail/tridiagonal.hpp"
#include "curvebench/curves/natural_cubic_spline.hpp"

#include <gmock/gmock.h>

#include <array>
#include <cmath>
#include <vector>

namespace cb = curvebench;
namespace cbt = curvebench::testing;
using ::testing::HasSubstr;

namespace {

// Tolerances, eps(Real) times a scale:
// - solver_ulps: residual |A x - r| of a diagonally dominant system (dominance ratio >= 2,
//   condition number <= 3): backward error of Thomas elimination is a few ulps per row, times
//   the condition: 16 relative to max|r|.
// - reference_ulps: the spline against the real50 spline of the same (rounded) data: slopes solve
//   a well-conditioned system (~16 ulps), values add ~10 roundings; derivatives of order k are
//   divided by h^k (h >= 1/4, carried by the scale). 64.
// - continuity_ulps: jumps of P, P', P'' at interior knots, relative to the scale of that order.
// - reproduction_ulps: cubic reproduction, relative to the scale of the cubic's order-k values.
constexpr double solver_ulps = 16;
constexpr double reference_ulps = 64;
constexpr double continuity_ulps = 64;
constexpr double reproduction_ulps = 96;

template <class Real>
class natural_test : public ::testing::Test {};
TYPED_TEST_SUITE(natural_test, cbt::all_reals);

const std::vector<double> kd{0.0, 0.25, 1.0, 1.5, 1.75, 3.0, 4.0};
const std::vector<std::array<double, 2>> vd{{0.0, 1.0},  {1.0, 2.0},  {2.5, 1.5}, {3.0, -0.5},
                                            {2.0, -1.0}, {0.5, -2.0}, {0.0, 1.0}};  // first == last

template <class Real>
cb::point_list<Real, 2> pts() {
  return cbt::points_from<Real>(vd);
}
template <class Real>
std::vector<Real> knots() {
  return std::vector<Real>(kd.begin(), kd.end());
}
// The data have |P| <= 3 and chords/h <= 8; derivative k scale: 8 * 4^k (h_min = 1/4).
cb::real50 scale(int order) { return cb::real50(8) * cb::real50(std::pow(4.0, order)); }

template <class Real>
std::vector<cb::natural_cubic_spline<Real, 2>> all_ends() {
  using P = cb::point<Real, 2>;
  return {cb::natural_cubic_spline<Real, 2>(knots<Real>(), pts<Real>(), cb::spline_end::natural),
          cb::natural_cubic_spline<Real, 2>(knots<Real>(), pts<Real>(), P(Real(1), Real(-2)), P(Real(0.5), Real(3))),
          cb::natural_cubic_spline<Real, 2>(knots<Real>(), pts<Real>(), cb::spline_end::not_a_knot),
          cb::natural_cubic_spline<Real, 2>(knots<Real>(), pts<Real>(), cb::spline_end::periodic)};
}

}  // namespace

static_assert(cb::curve<cb::natural_cubic_spline<double, 2>>);
static_assert(cb::curve<cb::natural_cubic_spline<cb::real50, 2>>);

TYPED_TEST(natural_test, solvers_have_small_residuals) {
  using Real = TypeParam;
  for (std::size_t n : {1u, 2u, 3u, 4u, 11u}) {
    std::vector<Real> a(n), b(n), c(n), r(n), x;
    for (std::size_t i = 0; i < n; ++i) {
      a[i] = Real(static_cast<double>((i * 5) % 7 + 1) / 8);  // in (0, 1]
      c[i] = Real(static_cast<double>((i * 3) % 5 + 1) / 8);
      b[i] = Real(2) * (a[i] + c[i]) + Real(0.5);  // dominance >= 2
      r[i] = Real(static_cast<double>((i * 11) % 13) - 6);
    }
    for (bool cyclic : {false, true}) {
      x = r;
      if (cyclic)
        cb::detail::solve_cyclic_tridiagonal<Real, Real>(a, b, c, std::span<Real>(x));
      else
        cb::detail::solve_tridiagonal<Real, Real>(a, b, c, std::span<Real>(x));
      for (std::size_t i = 0; i < n; ++i) {
        // Residual in real50 of the Real solution.
        cb::real50 ax = cb::real50(b[i]) * cb::real50(x[i]);
        if (cyclic || i > 0) ax += cb::real50(a[i]) * cb::real50(x[(i + n - 1) % n]);
        if (cyclic || i + 1 < n) ax += cb::real50(c[i]) * cb::real50(x[(i + 1) % n]);
        if (n == 1 && !cyclic) ax = cb::real50(b[i]) * cb::real50(x[i]);
        ASSERT_TRUE(cbt::within_scaled_ulps(Real(0), ax - cb::real50(r[i]), cb::real50(6) * cb::real50(4), solver_ulps))
            << "n=" << n << " cyclic=" << cyclic << " row " << i;
      }
    }
  }
}

TYPED_TEST(natural_test, interpolates_is_c2_and_honours_each_end_condition) {
  using Real = TypeParam;
  const auto p = pts<Real>();
  const auto splines = all_ends<Real>();
  for (const auto& s : splines) {
    const auto& e = s.engine();
    const char* name = cb::to_string(s.end_condition());
    for (std::size_t i = 0; i < kd.size(); ++i) {
      ASSERT_TRUE(cbt::point_within(s(Real(kd[i])), cb::point_cast<cb::real50>(p[i]), scale(0), 8)) << name << " " << i;
      if (i == 0 || i + 1 == kd.size()) continue;
      for (int order = 0; order <= 2; ++order)
        ASSERT_TRUE(cbt::point_within(e.evaluate_segment(i - 1, Real(1), order),
                                      cb::point_cast<cb::real50>(e.evaluate_segment(i, Real(0), order)), scale(order),
                                      continuity_ulps))
            << name << " C" << order << " at knot " << i;
    }
    const auto d = s.domain();
    switch (s.end_condition()) {
      case cb::spline_end::natural:
        ASSERT_TRUE(
            cbt::point_within(s.derivative(d.lo, 2), cb::point<cb::real50, 2>(0, 0), scale(2), continuity_ulps));
        ASSERT_TRUE(
            cbt::point_within(s.derivative(d.hi, 2), cb::point<cb::real50, 2>(0, 0), scale(2), continuity_ulps));
        break;
      case cb::spline_end::clamped:
        ASSERT_TRUE(
            cbt::point_within(s.derivative(d.lo, 1), cb::point<cb::real50, 2>(1, -2), scale(1), continuity_ulps));
        ASSERT_TRUE(
            cbt::point_within(s.derivative(d.hi, 1), cb::point<cb::real50, 2>(0.5, 3), scale(1), continuity_ulps));
        break;
      case cb::spline_end::not_a_knot:
        // P''' continuous at u_1 and u_{n-1}.
        for (std::size_t i : {std::size_t(1), kd.size() - 2})
          ASSERT_TRUE(cbt::point_within(e.evaluate_segment(i - 1, Real(1), 3),
                                        cb::point_cast<cb::real50>(e.evaluate_segment(i, Real(0), 3)), scale(3),
                                        continuity_ulps))
              << "P''' at " << i;
        break;
      case cb::spline_end::periodic:
        for (int order = 0; order <= 2; ++order)
          ASSERT_TRUE(cbt::point_within(s.derivative(d.hi, order),
                                        cb::point_cast<cb::real50>(s.derivative(d.lo, order)), scale(order),
                                        continuity_ulps))
              << "periodic order " << order;
        break;
    }
  }
}

TYPED_TEST(natural_test, agrees_with_the_real50_spline_of_the_same_data) {
  using Real = TypeParam;
  const auto splines = all_ends<Real>();
  const auto refs = all_ends<cb::real50>();
  for (std::size_t s = 0; s < splines.size(); ++s)
    for (int k = 0; k <= 64; ++k) {
      const double u = 4.0 * k / 64.0;
      for (int order = 0; order <= 3; ++order)
        ASSERT_TRUE(cbt::point_within(splines[s].derivative(Real(u), order), refs[s].derivative(cb::real50(u), order),
                                      scale(order), reference_ulps))
            << cb::to_string(splines[s].end_condition()) << " u=" << u << " order=" << order;
    }
}

TYPED_TEST(natural_test, not_a_knot_and_exact_clamped_reproduce_cubics) {
  using Real = TypeParam;
  // q(u) = 2 - u + 3u^2/4 - u^3/8 in x, 1 + u^3/4 in y (dyadic coefficients).
  auto q = [](double u, int order) {
    const double x[4] = {2, -1, 0.75, -0.125}, y[4] = {1, 0, 0, 0.25};
    cb::point<cb::real50, 2> r(0, 0);
    for (int k = order; k < 4; ++k) {
      cb::real50 f(1);
      for (int j = 0; j < order; ++j) f *= k - j;
      for (int j = 0; j < k - order; ++j) f *= cb::real50(u);
      r[0] += f * x[k];
      r[1] += f * y[k];
    }
    return r;
  };
  cb::point_list<Real, 2> v;
  for (double u : kd) v.push_back(cb::point_cast<Real>(q(u, 0)));
  const cb::natural_cubic_spline<Real, 2> nak(knots<Real>(), v, cb::spline_end::not_a_knot);
  const cb::natural_cubic_spline<Real, 2> cl(knots<Real>(), v, cb::point_cast<Real>(q(0, 1)),
                                             cb::point_cast<Real>(q(4, 1)));
  // Four points are the minimum for not-a-knot: the single interpolating cubic.
  const std::vector<Real> k4{Real(0), Real(0.5), Real(2), Real(3)};
  cb::point_list<Real, 2> v4;
  for (const Real& u : k4) v4.push_back(cb::point_cast<Real>(q(static_cast<double>(u), 0)));
  const cb::natural_cubic_spline<Real, 2> nak4(k4, v4, cb::spline_end::not_a_knot);
  for (int k = 0; k <= 64; ++k) {
    const double u = 4.0 * k / 64.0;
    for (int order = 0; order <= 3; ++order) {
      const cb::real50 sc = cb::real50(8) * cb::real50(std::pow(4.0, order));
      ASSERT_TRUE(cbt::point_within(nak.derivative(Real(u), order), q(u, order), sc, reproduction_ulps))
          << u << " " << order;
      ASSERT_TRUE(cbt::point_within(cl.derivative(Real(u), order), q(u, order), sc, reproduction_ulps))
          << u << " " << order;
      if (u <= 3) {
        ASSERT_TRUE(cbt::point_within(nak4.derivative(Real(u), order), q(u, order), sc, reproduction_ulps))
            << u << " " << order;
      }
    }
  }
  // Natural ends reproduce straight lines (P'' = 0 holds for them), not cubics.
  cb::point_list<Real, 2> line;
  for (double u : kd) line.push_back(cb::point<Real, 2>(Real(1 - u / 2), Real(3 * u)));
  const cb::natural_cubic_spline<Real, 2> nat(knots<Real>(), line);
  for (int k = 0; k <= 16; ++k) {
    const double u = 4.0 * k / 16.0;
    ASSERT_TRUE(cbt::point_within(nat(Real(u)), cb::point<cb::real50, 2>(1 - u / 2, 3 * u), cb::real50(12), 32));
  }
  const cb::natural_cubic_spline<Real, 2> nat_cubic(knots<Real>(), v);
  EXPECT_GT(static_cast<double>((nat_cubic(Real(0.5)) - cb::point_cast<Real>(q(0.5, 0))).norm()), 1e-3);
}

TEST(natural, bad_input_names_what_and_where) {
  using P = cb::point<double, 1>;
  auto msg = [](auto&& f) -> std::string {
    try {
      f();
    } catch (const cb::invalid_input& e) {
      return e.what();
    }
    return "no exception";
  };
  const cb::point_list<double, 1> v{P(0), P(1), P(0.5), P(2)};
  const std::vector<double> k{0, 1, 2, 3};
  EXPECT_THAT(
      msg([&] { cb::natural_cubic_spline<double, 1>(k, v, cb::spline_end::periodic); }),
      HasSubstr(
          "periodic spline: values[3][0] = 2 differs from values[0][0] = 0: the last value must equal the first"));
  EXPECT_THAT(msg([&] {
                cb::natural_cubic_spline<double, 1>({0, 1, 2}, {P(0), P(1), P(0)}, cb::spline_end::not_a_knot);
              }),
              HasSubstr("values: 3 given, at least 4 required (not-a-knot ends need four points)"));
  EXPECT_THAT(msg([&] { cb::natural_cubic_spline<double, 1>(k, v, cb::spline_end::clamped); }),
              HasSubstr("end = clamped needs the end slopes"));
  EXPECT_THAT(msg([&] {
                cb::natural_cubic_spline<double, 1>({0, 1, 2}, v);
              }),
              HasSubstr("knots: 3 given, must match values: 4"));
  EXPECT_THAT(msg([&] {
                cb::natural_cubic_spline<double, 1>({0, 1, 3, 2}, v);
              }),
              HasSubstr("knots must be increasing: knots[3] = 2 <= knots[2] = 3"));
  EXPECT_THAT(msg([&] {
                cb::natural_cubic_spline<double, 1>({0, 1, std::nan(""), 3}, v);
              }),
              HasSubstr("knots[2] = nan"));
  EXPECT_THAT(msg([&] { cb::natural_cubic_spline<double, 1>(k, v, P(std::nan("")), P(0)); }),
              HasSubstr("start_slope[0][0] = nan"));
  EXPECT_THAT(msg([&] { cb::natural_cubic_spline<double, 1>({0}, {P(0)}); }),
              HasSubstr("values: 1 given, at least 2 required"));
  // A periodic spline on two segments uses the 2 x 2 branch of the cyclic solver.
  const cb::natural_cubic_spline<double, 1> two({0, 1, 3}, {P(0), P(1), P(0)}, cb::spline_end::periodic);
  EXPECT_NEAR(two.derivative(0, 1)[0], two.derivative(3, 1)[0], 1e-14);
  EXPECT_NEAR(two.derivative(0, 2)[0], two.derivative(3, 2)[0], 1e-13);
}
