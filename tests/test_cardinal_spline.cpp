// Cardinal / Catmull-Rom splines: alpha knots, seed 000's non-uniform slopes (erratum fixed) and
// one-sided end slopes, the uniform case against the cardinal basis matrix (seed 002, with its 1/2),
// interpolation, C1 continuity, quadratic reproduction, end conditions (phantom, one-sided, given,
// closed), locality, and bad input.
#include "support/accuracy.hpp"
#include "support/fixtures.hpp"

#include "curvebench/curves/cardinal_spline.hpp"

#include <gmock/gmock.h>

#include <array>
#include <cmath>
#include <vector>

namespace cb = curvebench;
namespace cbt = curvebench::testing;
using ::testing::HasSubstr;

namespace {

// Tolerances, eps(Real) times the data scale (coordinates <= 4; knots from |dP|^alpha):
// - knot_value_ulps: a segment's start value is the stored point (0 ulps); the end of the last
//   segment sums 4 power coefficients: 4 roundings of items of size <= scale; 8 for margin.
// - slope_ulps: the slope is a three-point formula (~8 roundings) on knots that are themselves
//   rounded (pow, sqrt: ~3 ulps each, amplified by 1/h ~ 2): 48.
// - value_ulps: curve values against an independent real50 evaluation of the same rounded data:
//   slopes (48) times h plus ~10 roundings of evaluation: 64.
// - continuity_ulps: value and slope jumps at interior knots: two evaluations, 32.
constexpr double knot_value_ulps = 8;
constexpr double slope_ulps = 48;
constexpr double value_ulps = 64;
constexpr double continuity_ulps = 32;

template <class Real>
class cardinal_test : public ::testing::Test {};
TYPED_TEST_SUITE(cardinal_test, cbt::all_reals);

const std::vector<std::array<double, 2>> pd{{0.0, 0.0}, {1.0, 2.0}, {3.0, 2.5}, {3.5, 0.5}, {2.0, -1.0}, {4.0, -2.0}};

template <class Real>
cb::point_list<Real, 2> pts() {
  return cbt::points_from<Real>(pd);
}

template <class Real>
cb::real50 scale_of() {
  return cb::real50(4);
}

}  // namespace

static_assert(cb::curve<cb::cardinal_spline<double, 2>>);
static_assert(cb::curve<cb::cardinal_spline<cb::real50, 2>>);

TYPED_TEST(cardinal_test, alpha_knots_interpolation_and_c1_for_each_parameterization) {
  using Real = TypeParam;
  const auto p = pts<Real>();
  for (double alpha : {0.0, 0.5, 1.0}) {
    typename cb::cardinal_spline<Real, 2>::options opt;
    opt.alpha = Real(alpha);
    const cb::cardinal_spline<Real, 2> c(p, opt);
    // Knots: u_{i+1} - u_i = |dP|^alpha, checked against real50 (independent sqrt/pow).
    const auto k = c.breakpoints();
    ASSERT_EQ(k.size(), p.size());
    for (std::size_t i = 0; i + 1 < p.size(); ++i) {
      using std::pow;
      const cb::real50 d = (cb::point_cast<cb::real50>(p[i + 1]) - cb::point_cast<cb::real50>(p[i])).norm();
      const cb::real50 step = alpha == 0 ? cb::real50(1) : pow(d, cb::real50(alpha));
      ASSERT_TRUE(cbt::within_ulps(Real(k[i + 1] - k[i]), step, 8)) << "alpha " << alpha << " chord " << i;
    }
    const auto& e = c.engine();
    for (std::size_t i = 0; i < p.size(); ++i) {
      ASSERT_TRUE(cbt::point_within(c(k[i]), cb::point_cast<cb::real50>(p[i]), scale_of<Real>(), knot_value_ulps))
          << "alpha " << alpha << " point " << i;
      if (i > 0 && i + 1 < p.size()) {
        for (int order = 0; order <= 1; ++order)
          ASSERT_TRUE(cbt::point_within(e.evaluate_segment(i - 1, Real(1), order),
                                        cb::point_cast<cb::real50>(e.evaluate_segment(i, Real(0), order)),
                                        scale_of<Real>() * 4, continuity_ulps))
              << "alpha " << alpha << " C" << order << " at " << i;
      }
    }
  }
}

TYPED_TEST(cardinal_test, slopes_are_seed_000_finite_differences_with_the_erratum_fixed) {
  using Real = TypeParam;
  // Given non-uniform knots; s = 1/2 so the slopes are exactly seed 000's (no 2s factor).
  const std::vector<double> kd{0.0, 0.5, 1.75, 2.0, 3.0, 4.5};
  const auto p = pts<Real>();
  typename cb::cardinal_spline<Real, 2>::options opt;
  opt.end = cb::cardinal_end::one_sided;
  const cb::cardinal_spline<Real, 2> c(std::vector<Real>(kd.begin(), kd.end()), p, opt);
  auto y = [&](std::size_t i, int d) { return cb::real50(pd[i][static_cast<std::size_t>(d)]); };
  auto t = [&](std::size_t i) { return cb::real50(kd[i]); };
  const std::size_t n = kd.size() - 1;
  for (std::size_t i = 0; i <= n; ++i) {
    cb::point<cb::real50, 2> ref;
    for (int d = 0; d < 2; ++d) {
      if (i == 0) {
        // s_0 = ((t2 - t0)/(t2 - t1)) · (y1 - y0)/(t1 - t0) - ((t1 - t0)/(t2 - t1)) · (y2 - y0)/(t2 - t0)
        ref[d] = (t(2) - t(0)) / (t(2) - t(1)) * (y(1, d) - y(0, d)) / (t(1) - t(0)) -
                 (t(1) - t(0)) / (t(2) - t(1)) * (y(2, d) - y(0, d)) / (t(2) - t(0));
      } else if (i == n) {
        // The "symmetric formula for the end": the same with the knots mirrored (t -> -t).
        ref[d] = (t(n) - t(n - 2)) / (t(n - 1) - t(n - 2)) * (y(n, d) - y(n - 1, d)) / (t(n) - t(n - 1)) -
                 (t(n) - t(n - 1)) / (t(n - 1) - t(n - 2)) * (y(n, d) - y(n - 2, d)) / (t(n) - t(n - 2));
      } else {
        // s_i = ((t_i - t_{i-1})/(t_{i+1} - t_{i-1})) · (y_{i+1} - y_i)/(t_{i+1} - t_i)
        //     + ((t_{i+1} - t_i)/(t_{i+1} - t_{i-1})) · (y_i - y_{i-1})/(t_i - t_{i-1})
        ref[d] = (t(i) - t(i - 1)) / (t(i + 1) - t(i - 1)) * (y(i + 1, d) - y(i, d)) / (t(i + 1) - t(i)) +
                 (t(i + 1) - t(i)) / (t(i + 1) - t(i - 1)) * (y(i, d) - y(i - 1, d)) / (t(i) - t(i - 1));
      }
    }
    ASSERT_TRUE(cbt::point_within(c.slopes()[i], ref, cb::real50(8), slope_ulps)) << i;
    ASSERT_TRUE(cbt::point_within(c.derivative(Real(kd[i]), 1), ref, cb::real50(8), slope_ulps)) << i;
  }
  // Uniform knots: the interior formula reduces to the central difference (y_{i+1} - y_{i-1})/(2 dt).
  typename cb::cardinal_spline<Real, 2>::options uni;
  const cb::cardinal_spline<Real, 2> cu(p, uni);
  for (std::size_t i = 1; i < n; ++i)
    ASSERT_TRUE(cbt::point_within(cu.slopes()[i],
                                  cb::point_cast<cb::real50>(cb::point<Real, 2>((p[i + 1] - p[i - 1]) / Real(2))),
                                  cb::real50(4), 4));
}

TYPED_TEST(cardinal_test, uniform_knots_match_the_cardinal_basis_matrix_with_phantom_points) {
  using Real = TypeParam;
  const auto p = pts<Real>();
  const std::size_t n = p.size() - 1;
  for (double sd : {0.5, 0.25}) {
    typename cb::cardinal_spline<Real, 2>::options opt;
    opt.s = Real(sd);
    const cb::cardinal_spline<Real, 2> c(p, opt);
    // Extended control polygon with the extrapolated phantoms 2P0 - P1 and 2Pn - P(n-1), in real50.
    cb::point_list<cb::real50, 2> ext;
    const auto p50 = cb::points_cast<cb::real50, Real, 2>(p);
    ext.push_back(cb::real50(2) * p50[0] - p50[1]);
    for (auto& q : p50) ext.push_back(q);
    ext.push_back(cb::real50(2) * p50[n] - p50[n - 1]);
    const auto m = cb::basis::cardinal_matrix<cb::real50>(cb::real50(sd));
    for (std::size_t i = 0; i < n; ++i)
      for (int k = 0; k <= 8; ++k) {
        const cb::real50 t = cb::real50(k) / 8;
        Eigen::Matrix<cb::real50, 4, 2> g;
        for (int r = 0; r < 4; ++r) g.row(r) = ext[i + static_cast<std::size_t>(r)].transpose();
        const Eigen::Matrix<cb::real50, 1, 2> ref = cb::basis::power_row(t) * m * g;
        if (k == 8 && i + 1 < n) continue;  // u = i + 1 belongs to the next segment
        ASSERT_TRUE(cbt::point_within(c(Real(static_cast<double>(i) + k / 8.0)), cb::point<cb::real50, 2>(ref.transpose()),
                                      cb::real50(4), value_ulps))
            << "s=" << sd << " segment " << i << " t=" << k;
      }
  }
}

TYPED_TEST(cardinal_test, catmull_rom_with_one_sided_ends_reproduces_quadratics_on_any_knots) {
  using Real = TypeParam;
  // Points of q(u) = (1 - u + u^2/2, 2u - u^2/4) at non-uniform dyadic knots: every slope (parabola
  // through three points of a parabola) is exact, so the Hermite segments are q itself.
  const std::vector<double> kd{-1.0, -0.5, 0.25, 1.0, 1.5, 3.0};
  auto q = [](double u, int order) {
    if (order == 0) return cb::point<cb::real50, 2>(1 - u + u * u / 2, 2 * u - u * u / 4);
    if (order == 1) return cb::point<cb::real50, 2>(-1 + u, 2 - u / 2);
    return cb::point<cb::real50, 2>(1, -0.5);
  };
  cb::point_list<Real, 2> p;
  for (double u : kd) p.push_back(cb::point_cast<Real>(q(u, 0)));
  typename cb::cardinal_spline<Real, 2>::options opt;
  opt.end = cb::cardinal_end::one_sided;
  const cb::cardinal_spline<Real, 2> c(std::vector<Real>(kd.begin(), kd.end()), p, opt);
  for (int j = 0; j <= 64; ++j) {
    const double u = -1.0 + 4.0 * j / 64.0;
    for (int order = 0; order <= 2; ++order)
      ASSERT_TRUE(cbt::point_within(c.derivative(Real(u), order), q(u, order),
                                    cb::real50(4) * cb::real50(std::pow(4.0, order)), value_ulps))
          << u << " order " << order;
    EXPECT_EQ(c.derivative(Real(u), 3), (cb::point<Real, 2>::Zero()));
  }
}

TYPED_TEST(cardinal_test, closed_loop_is_periodic_in_value_and_first_derivative) {
  using Real = TypeParam;
  const auto p = pts<Real>();
  typename cb::cardinal_spline<Real, 2>::options opt;
  opt.end = cb::cardinal_end::closed;
  opt.alpha = Real(0.5);
  const cb::cardinal_spline<Real, 2> c(p, opt);
  const auto d = c.domain();
  EXPECT_EQ(c.engine().segment_count(), p.size());
  for (int order = 0; order <= 1; ++order)
    ASSERT_TRUE(cbt::point_within(c.derivative(d.hi, order), cb::point_cast<cb::real50>(c.derivative(d.lo, order)),
                                  cb::real50(8), continuity_ulps))
        << "order " << order;
}

TEST(cardinal, end_conditions_phantom_and_given_tangents) {
  using P = cb::point<double, 2>;
  const auto p = pts<double>();
  const double eps = std::numeric_limits<double>::epsilon();
  // Phantom ends, uniform: m_0 = 2s (P1 - P0), m_n = 2s (Pn - P(n-1)).
  cb::cardinal_spline<double, 2>::options opt;
  opt.s = 0.3;
  const cb::cardinal_spline<double, 2> ph(p, opt);
  EXPECT_NEAR((ph.derivative(0.0, 1) - 0.6 * (p[1] - p[0])).norm(), 0.0, 16 * eps);
  EXPECT_NEAR((ph.derivative(5.0, 1) - 0.6 * (p[5] - p[4])).norm(), 0.0, 64 * eps);
  // Given tangents are used as dP/du as they are (not scaled by 2s).
  opt.end = cb::cardinal_end::given_tangents;
  opt.start_tangent = P(1.0, -3.0);
  opt.end_tangent = P(0.5, 0.25);
  const cb::cardinal_spline<double, 2> gt(p, opt);
  EXPECT_NEAR((gt.derivative(0.0, 1) - opt.start_tangent).norm(), 0.0, 16 * eps);
  EXPECT_NEAR((gt.derivative(5.0, 1) - opt.end_tangent).norm(), 0.0, 64 * eps);
  // Interior slopes do not depend on the end condition.
  for (std::size_t i = 1; i + 1 < p.size(); ++i) EXPECT_EQ(ph.slopes()[i], gt.slopes()[i]);
}

TEST(cardinal, moving_one_point_changes_at_most_four_segments) {
  const auto p = []() {
    cb::point_list<double, 2> r;
    for (int i = 0; i < 10; ++i) r.push_back(cb::point<double, 2>(i, (i * 7) % 5));
    return r;
  }();
  const cb::cardinal_spline<double, 2> a(p);
  for (std::size_t j = 0; j < p.size(); ++j) {
    auto moved = p;
    moved[j] += cb::point<double, 2>(0.5, -1.25);
    const cb::cardinal_spline<double, 2> b(moved);
    std::size_t changed = 0;
    for (std::size_t i = 0; i < a.engine().segment_count(); ++i) {
      const bool same = a.engine().power_coefficients(i) == b.engine().power_coefficients(i);
      if (!same) {
        ++changed;
        // Only segments j-2 .. j+1 may change (they are the ones whose 4 control points include P_j).
        EXPECT_TRUE(i + 2 >= j && i <= j + 1) << "moving P" << j << " changed segment " << i;
      }
    }
    EXPECT_GE(changed, 1u);
    EXPECT_LE(changed, 4u);
  }
}

TEST(cardinal, bad_input_names_what_and_where) {
  using P = cb::point<double, 2>;
  auto msg = [](auto&& f) -> std::string {
    try {
      f();
    } catch (const cb::invalid_input& e) {
      return e.what();
    }
    return "no exception";
  };
  cb::cardinal_spline<double, 2>::options centripetal;
  centripetal.alpha = 0.5;
  const cb::point_list<double, 2> rep{P(0, 0), P(1, 1), P(1, 1), P(2, 0)};
  EXPECT_THAT(msg([&] { cb::cardinal_spline<double, 2> c(rep, centripetal); }),
              HasSubstr("points[2] repeats points[1]: a zero chord gives a zero knot interval |dP|^alpha with alpha = 0.5"));
  EXPECT_NO_THROW((cb::cardinal_spline<double, 2>(rep)));  // alpha = 0: repeated points are fine
  cb::cardinal_spline<double, 2>::options bad_alpha;
  bad_alpha.alpha = 1.5;
  EXPECT_THAT(msg([&] { cb::cardinal_spline<double, 2> c(rep, bad_alpha); }), HasSubstr("alpha = 1.5: must be in [0, 1]"));
  EXPECT_THAT(msg([&] { cb::cardinal_spline<double, 2> c({P(0, 0)}); }), HasSubstr("points: 1 given, at least 2 required"));
  cb::cardinal_spline<double, 2>::options closed;
  closed.end = cb::cardinal_end::closed;
  EXPECT_THAT(msg([&] { cb::cardinal_spline<double, 2> c({P(0, 0), P(1, 0)}, closed); }),
              HasSubstr("points: 2 given, at least 3 required"));
  EXPECT_THAT(msg([&] { cb::cardinal_spline<double, 2> c({0.0, 1.0, 2.0, 3.0}, rep, closed); }),
              HasSubstr("knots: 4 given, must match points + 1 (closed loop): 5"));
  EXPECT_THAT(msg([&] { cb::cardinal_spline<double, 2> c({0.0, 1.0, 2.0, 3.0}, rep, centripetal); }),
              HasSubstr("alpha = 0.5: must be 0 when knots are given"));
  EXPECT_THAT(msg([&] { cb::cardinal_spline<double, 2> c({0.0, 1.0, 1.0, 3.0}, rep, {}); }),
              HasSubstr("knots must be increasing: knots[2] = 1 <= knots[1] = 1"));
  auto nan = rep;
  nan[3][0] = std::nan("");
  EXPECT_THAT(msg([&] { cb::cardinal_spline<double, 2> c(nan); }), HasSubstr("points[3][0] = nan"));
  cb::cardinal_spline<double, 2>::options s_nan;
  s_nan.s = std::nan("");
  EXPECT_THAT(msg([&] { cb::cardinal_spline<double, 2> c(rep, s_nan); }), HasSubstr("s = nan: must be finite"));
}
