// Cardinal / Catmull-Rom splines: alpha knots, seed 000's non-uniform slopes (erratum fixed) and
// one-sided end slopes, the uniform case against the cardinal basis matrix (seed 002, with its 1/2),
// interpolation, C1 continuity, quadratic reproduction, end conditions (phantom, one-sided, given,
// closed, control points), locality, and bad input. The control-point ends (the textbook
// Catmull-Rom through P_1..P_{n-2}) are checked against an independent Barry-Goldman pyramid in
// real50 and, on uniform knots, against the given-tangent form.
#include "support/accuracy.hpp"
#include "support/fixtures.hpp"

#include "curvebench/curves/cardinal_spline.hpp"
#include "curvebench/motion/keyframes.hpp"

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

// Chords near the ends of double's exponent range: points scaled by 2^515 (about 1e155, where
// |dP|^2 overflows) and 2^-540 (about 1e-162, where it underflows to 0 and the chord read as a
// repeated point). The knot steps are the scaled chords' |dP|^alpha: checked against real50, whose
// exponent range holds the squares, within knot_value_ulps (one sqrt, one pow, the scaling exact).
TEST(cardinal_spline, alpha_knots_of_chords_whose_squares_leave_the_double_range) {
  for (const int e : {515, -540}) {
    cb::point_list<double, 2> p;
    for (const auto& q : pd) p.push_back(cb::point<double, 2>(std::ldexp(q[0], e), std::ldexp(q[1], e)));
    for (const double alpha : {0.5, 1.0}) {
      cb::cardinal_spline<double, 2>::options opt;
      opt.alpha = alpha;
      const cb::cardinal_spline<double, 2> c(p, opt);
      const auto k = c.breakpoints();
      for (std::size_t i = 0; i + 1 < p.size(); ++i) {
        using std::pow;
        const cb::real50 d = (cb::point_cast<cb::real50>(p[i + 1]) - cb::point_cast<cb::real50>(p[i])).norm();
        ASSERT_TRUE(cbt::within_ulps(k[i + 1] - k[i], pow(d, cb::real50(alpha)), knot_value_ulps))
            << "2^" << e << " alpha " << alpha << " chord " << i;
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
        ASSERT_TRUE(cbt::point_within(c(Real(static_cast<double>(i) + k / 8.0)),
                                      cb::point<cb::real50, 2>(ref.transpose()), cb::real50(4), value_ulps))
            << "s=" << sd << " segment " << i << " t=" << k;
      }
  }
}

TYPED_TEST(cardinal_test, catmull_rom_with_one_sided_or_control_point_ends_reproduces_quadratics_on_any_knots) {
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
  for (const cb::cardinal_end end : {cb::cardinal_end::one_sided, cb::cardinal_end::control_points}) {
    typename cb::cardinal_spline<Real, 2>::options opt;
    opt.end = end;
    const cb::cardinal_spline<Real, 2> c(std::vector<Real>(kd.begin(), kd.end()), p, opt);
    // control_points: the curve is the part [kd[1], kd[4]]; samples outside it are skipped.
    int sampled = 0;
    for (int j = 0; j <= 64; ++j) {
      const double u = -1.0 + 4.0 * j / 64.0;
      if (Real(u) < c.domain().lo || Real(u) > c.domain().hi) continue;
      ++sampled;
      for (int order = 0; order <= 2; ++order)
        ASSERT_TRUE(cbt::point_within(c.derivative(Real(u), order), q(u, order),
                                      cb::real50(4) * cb::real50(std::pow(4.0, order)), value_ulps))
            << cb::to_string(end) << " " << u << " order " << order;
      EXPECT_EQ(c.derivative(Real(u), 3), (cb::point<Real, 2>::Zero()));
    }
    EXPECT_EQ(sampled, end == cb::cardinal_end::one_sided ? 65 : 33) << cb::to_string(end);
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
  EXPECT_THAT(
      msg([&] { cb::cardinal_spline<double, 2> c(rep, centripetal); }),
      HasSubstr("points[2] repeats points[1]: a zero chord gives a zero knot interval |dP|^alpha with alpha = 0.5"));
  EXPECT_NO_THROW((cb::cardinal_spline<double, 2>(rep)));  // alpha = 0: repeated points are fine
  cb::cardinal_spline<double, 2>::options bad_alpha;
  bad_alpha.alpha = 1.5;
  EXPECT_THAT(msg([&] { cb::cardinal_spline<double, 2> c(rep, bad_alpha); }),
              HasSubstr("alpha = 1.5: must be in [0, 1]"));
  EXPECT_THAT(msg([&] { cb::cardinal_spline<double, 2> c({P(0, 0)}); }),
              HasSubstr("points: 1 given, at least 2 required"));
  cb::cardinal_spline<double, 2>::options closed;
  closed.end = cb::cardinal_end::closed;
  EXPECT_THAT(msg([&] {
                cb::cardinal_spline<double, 2> c({P(0, 0), P(1, 0)}, closed);
              }),
              HasSubstr("points: 2 given, at least 3 required"));
  EXPECT_THAT(msg([&] {
                cb::cardinal_spline<double, 2> c({0.0, 1.0, 2.0, 3.0}, rep, closed);
              }),
              HasSubstr("knots: 4 given, must match points + 1 (closed loop): 5"));
  EXPECT_THAT(msg([&] {
                cb::cardinal_spline<double, 2> c({0.0, 1.0, 2.0, 3.0}, rep, centripetal);
              }),
              HasSubstr("alpha = 0.5: must be 0 when knots are given"));
  EXPECT_THAT(msg([&] {
                cb::cardinal_spline<double, 2> c({0.0, 1.0, 1.0, 3.0}, rep, {});
              }),
              HasSubstr("knots must be increasing: knots[2] = 1 <= knots[1] = 1"));
  auto nan = rep;
  nan[3][0] = std::nan("");
  EXPECT_THAT(msg([&] { cb::cardinal_spline<double, 2> c(nan); }), HasSubstr("points[3][0] = nan"));
  cb::cardinal_spline<double, 2>::options s_nan;
  s_nan.s = std::nan("");
  EXPECT_THAT(msg([&] { cb::cardinal_spline<double, 2> c(rep, s_nan); }), HasSubstr("s = nan: must be finite"));
}

// ---- control-point ends: the textbook Catmull-Rom through P_1..P_{n-2} ----

namespace {

// Eight points in 2D and 3D with a mix of chord lengths (so alpha matters), exact in float.
const std::vector<std::array<double, 2>> pd8{{0.0, 0.0},  {1.0, 2.0},  {3.0, 2.5},  {3.5, 0.5},
                                             {2.0, -1.0}, {4.0, -2.0}, {5.5, 0.25}, {7.0, 1.0}};
const std::vector<std::array<double, 3>> pd8_3d{{0.0, 0.0, 0.0},  {1.0, 2.0, 0.5}, {2.5, 1.5, 2.0},  {3.0, -0.5, 1.25},
                                                {4.5, 0.0, -1.0}, {5.0, 2.0, 0.0}, {6.25, 1.0, 1.5}, {8.0, 0.5, 0.75}};

template <int Dim>
struct value_and_slope {
  cb::point<cb::real50, Dim> value;
  cb::point<cb::real50, Dim> slope;
};

/// Barry & Goldman's pyramid for the middle segment (P1 -> P2) of four points on knots t0 < t1 <
/// t2 < t3, written out on its own: three linear interpolations in knot space, then two, then one;
/// the derivative of each level by the product rule.
template <int Dim>
value_and_slope<Dim> barry_goldman(const std::array<cb::point<cb::real50, Dim>, 4>& p,
                                   const std::array<cb::real50, 4>& t, const cb::real50& u) {
  using P50 = cb::point<cb::real50, Dim>;
  // ((tb - u) a + (u - ta) b) / (tb - ta), and d/du of it given a' and b'.
  auto lerp = [&](const value_and_slope<Dim>& a, const value_and_slope<Dim>& b, const cb::real50& ta,
                  const cb::real50& tb) {
    const cb::real50 w = tb - ta;
    value_and_slope<Dim> r;
    r.value = P50(((tb - u) * a.value + (u - ta) * b.value) / w);
    r.slope = P50((b.value - a.value) / w + ((tb - u) * a.slope + (u - ta) * b.slope) / w);
    return r;
  };
  std::array<value_and_slope<Dim>, 4> pts;
  for (std::size_t i = 0; i < 4; ++i) pts[i] = {p[i], P50::Zero()};
  const auto a1 = lerp(pts[0], pts[1], t[0], t[1]);
  const auto a2 = lerp(pts[1], pts[2], t[1], t[2]);
  const auto a3 = lerp(pts[2], pts[3], t[2], t[3]);
  const auto b1 = lerp(a1, a2, t[0], t[2]);
  const auto b2 = lerp(a2, a3, t[1], t[3]);
  return lerp(b1, b2, t[1], t[2]);
}

/// Knots u_0 = 0, u_{i+1} = u_i + |P_{i+1} - P_i|^alpha in real50 (alpha as the Real holds it).
template <int Dim>
std::vector<cb::real50> knots50(const cb::point_list<cb::real50, Dim>& p, const cb::real50& alpha) {
  std::vector<cb::real50> t{cb::real50(0)};
  for (std::size_t i = 0; i + 1 < p.size(); ++i) {
    using std::pow;
    const cb::real50 d = cb::point<cb::real50, Dim>(p[i + 1] - p[i]).norm();
    t.push_back(t.back() + (alpha == 0 ? cb::real50(1) : cb::real50(pow(d, alpha))));
  }
  return t;
}

// Tolerances of the pyramid comparison, in eps(Real) times a scale: values relative to the
// data's size (8), slopes relative to the largest reference slope of the curve (1.1 to 2.9 here).
// The reference parameter is placed at the same fraction of the segment as the Real one, so only
// the ratios of the Real's rounded knots count (pow, sqrt, sums: a few ulps), not their absolute
// rounding. The Real slope at a point is the three-point formula (~8 roundings of terms <= the
// slope scale); a value is the Hermite cubic with those slopes times h/3 (<= 1) plus ~4 roundings
// of power-basis terms of the data's size: 8 ulps of the size (observed <= 1 on these points). A
// slope is the derivative of that cubic, the same errors over h (>= 1 here) in 3 terms: 16 ulps of
// the slope scale (observed <= 4.5, float 3D chordal). For real50 these bounds are below 1e-48 x
// scale, i.e. the 50-digit spline equals the 50-digit pyramid to ~48 digits.
constexpr double pyramid_value_ulps = 8;
constexpr double pyramid_slope_ulps = 16;

template <class Real, int Dim>
void expect_barry_goldman_pyramid(const cb::point_list<Real, Dim>& p) {
  const auto p50 = cb::points_cast<cb::real50, Real, Dim>(std::span<const cb::point<Real, Dim>>(p));
  const std::size_t n = p.size();
  for (double alpha : {0.0, 0.5, 1.0, 0.3}) {
    SCOPED_TRACE("alpha " + std::to_string(alpha) + ", Dim " + std::to_string(Dim));
    typename cb::cardinal_spline<Real, Dim>::options opt;
    opt.alpha = Real(alpha);
    opt.end = cb::cardinal_end::control_points;
    const cb::cardinal_spline<Real, Dim> c(p, opt);
    const std::vector<cb::real50> t = knots50<Dim>(p50, cb::real50(Real(alpha)));
    const auto bp = c.breakpoints();
    ASSERT_EQ(bp.size(), n - 2);
    ASSERT_EQ(c.engine().segment_count(), n - 3);
    struct sample {
      Real u;
      value_and_slope<Dim> ref;
    };
    std::vector<sample> samples;
    cb::real50 slope_scale(0);
    for (std::size_t k = 0; k + 3 < n; ++k) {  // segment k runs from P_{k+1} to P_{k+2}
      const std::array<cb::point<cb::real50, Dim>, 4> q{p50[k], p50[k + 1], p50[k + 2], p50[k + 3]};
      const std::array<cb::real50, 4> tk{t[k], t[k + 1], t[k + 2], t[k + 3]};
      for (int j = 0; j <= 8; ++j) {
        const Real u = j == 8 ? bp[k + 1] : Real(bp[k] + Real(j) / Real(8) * (bp[k + 1] - bp[k]));
        // The same fraction of the reference segment.
        const cb::real50 f = (cb::real50(u) - cb::real50(bp[k])) / (cb::real50(bp[k + 1]) - cb::real50(bp[k]));
        const auto ref = barry_goldman<Dim>(q, tk, tk[1] + f * (tk[2] - tk[1]));
        for (int d = 0; d < Dim; ++d) slope_scale = std::max(slope_scale, cb::real50(abs(ref.slope[d])));
        samples.push_back({u, ref});
      }
    }
    for (const auto& s : samples) {
      ASSERT_TRUE(cbt::point_within(c(s.u), s.ref.value, cb::real50(8), pyramid_value_ulps)) << "u = " << s.u;
      ASSERT_TRUE(cbt::point_within(c.derivative(s.u, 1), s.ref.slope, slope_scale, pyramid_slope_ulps))
          << "u = " << s.u;
    }
  }
}

}  // namespace

TYPED_TEST(cardinal_test, control_point_ends_are_the_barry_goldman_pyramid_for_any_alpha) {
  using Real = TypeParam;
  expect_barry_goldman_pyramid<Real, 2>(cbt::points_from<Real>(pd8));
  expect_barry_goldman_pyramid<Real, 3>(cbt::points_from<Real>(pd8_3d));
}

TYPED_TEST(cardinal_test, control_point_ends_on_uniform_knots_are_given_tangents_on_the_inner_points) {
  using Real = TypeParam;
  // alpha = 0: knots 0..n-1, the curve on [1, n-2]. The given-tangent spline on P_1..P_{n-2} with
  // knots 0..n-3 (unit spacing, so dP/du is per unit step as well) and end tangents
  // (P_2 - P_0)/2, (P_{n-1} - P_{n-3})/2 is the same curve shifted by one in u.
  const auto p = cbt::points_from<Real>(pd8);
  const std::size_t n = p.size();
  typename cb::cardinal_spline<Real, 2>::options opt;
  opt.end = cb::cardinal_end::control_points;
  const cb::cardinal_spline<Real, 2> c(p, opt);
  typename cb::cardinal_spline<Real, 2>::options given;
  given.end = cb::cardinal_end::given_tangents;
  given.start_tangent = (p[2] - p[0]) / Real(2);
  given.end_tangent = (p[n - 1] - p[n - 3]) / Real(2);
  std::vector<Real> k;
  for (std::size_t i = 0; i + 2 < n; ++i) k.push_back(Real(static_cast<double>(i)));
  const cb::cardinal_spline<Real, 2> g(k, cb::point_list<Real, 2>(p.begin() + 1, p.end() - 1), given);
  EXPECT_EQ(c.domain().lo, Real(1));
  EXPECT_EQ(c.domain().hi, Real(static_cast<double>(n - 2)));
  // Both are Hermite cubics on the same points with slopes that differ by the rounding of
  // (P_1 - P_0 + P_2 - P_1)/2 vs (P_2 - P_0)/2 (2 ulps of the data's size 8); evaluation rounds
  // each the same way: 8 ulps.
  for (int j = 0; j <= 40; ++j) {
    const Real v = Real(static_cast<double>(n - 3) * j / 40.0);
    for (int order = 0; order <= 1; ++order)
      ASSERT_TRUE(cbt::point_within(c.derivative(v + Real(1), order),
                                    cb::point_cast<cb::real50>(g.derivative(v, order)), cb::real50(8), 8))
          << "v = " << v << " order " << order;
  }
}

TYPED_TEST(cardinal_test, control_point_ends_interpolate_the_inner_points_on_the_inner_domain) {
  using Real = TypeParam;
  const auto p = cbt::points_from<Real>(pd8);
  const std::size_t n = p.size();
  for (double alpha : {0.0, 0.5, 1.0}) {
    typename cb::cardinal_spline<Real, 2>::options opt;
    opt.alpha = Real(alpha);
    opt.end = cb::cardinal_end::control_points;
    const cb::cardinal_spline<Real, 2> c(p, opt);
    const auto t = cb::alpha_knots<Real, 2>(std::span<const cb::point<Real, 2>>(p), Real(alpha));
    ASSERT_EQ(t.size(), n);
    EXPECT_EQ(c.domain().lo, t[1]) << alpha;
    EXPECT_EQ(c.domain().hi, t[n - 2]) << alpha;
    ASSERT_EQ(c.breakpoints().size(), n - 2);
    ASSERT_EQ(c.slopes().size(), n - 2);
    // The interior slopes are the phantom-end spline's: the end mode only drops the end segments.
    typename cb::cardinal_spline<Real, 2>::options phantom = opt;
    phantom.end = cb::cardinal_end::phantom;
    const cb::cardinal_spline<Real, 2> ph(p, phantom);
    for (std::size_t i = 1; i + 1 < n; ++i) {
      EXPECT_EQ(c.breakpoints()[i - 1], t[i]);
      EXPECT_EQ(c.slopes()[i - 1], ph.slopes()[i]) << i;
      ASSERT_TRUE(cbt::point_within(c(t[i]), cb::point_cast<cb::real50>(p[i]), cb::real50(8), knot_value_ulps))
          << "alpha " << alpha << " point " << i;
    }
    EXPECT_THROW((void)c(t[0]), std::domain_error);
  }
}

TEST(cardinal, control_point_ends_end_points_only_shape_the_end_segments) {
  const auto p = cbt::points_from<double>(pd8);
  const std::size_t n = p.size();
  cb::cardinal_spline<double, 2>::options opt;
  opt.end = cb::cardinal_end::control_points;
  // Given non-uniform knots: the parameterization stays put, so segments compare bit for bit.
  const std::vector<double> knots{0.0, 0.75, 2.0, 2.5, 3.25, 4.5, 5.0, 6.5};
  const cb::cardinal_spline<double, 2> a(knots, p, opt);
  for (const std::size_t j : {std::size_t{0}, n - 1}) {
    auto moved = p;
    moved[j] += cb::point<double, 2>(0.5, -1.25);
    const cb::cardinal_spline<double, 2> b(knots, moved, opt);
    const std::size_t only = j == 0 ? 0 : a.engine().segment_count() - 1;
    for (std::size_t i = 0; i < a.engine().segment_count(); ++i)
      EXPECT_EQ(a.engine().power_coefficients(i) == b.engine().power_coefficients(i), i != only)
          << "moving P" << j << ", segment " << i;
  }
  // Alpha knots: moving P_0 shifts every knot by the change of |P_1 - P_0|^alpha, the curve
  // beyond the first segment keeps its shape (compared at the same offset from u_1). The shifted
  // knots and parameters are rounded (u <= 14: ~2 ulps of 14 each, times slopes <= 3, over the
  // data's size 8 gives ~10) and the segments rebuilt from them: 16 ulps of the data's size.
  opt.alpha = 0.5;
  const cb::cardinal_spline<double, 2> c(p, opt);
  auto moved = p;
  moved[0] += cb::point<double, 2>(0.5, -1.25);
  const cb::cardinal_spline<double, 2> d(moved, opt);
  const double shift = d.domain().lo - c.domain().lo;
  EXPECT_NE(shift, 0.0);
  const auto cb_ = c.breakpoints();
  for (int j = 0; j <= 64; ++j) {
    const double u = cb_[1] + (cb_.back() - cb_[1]) * j / 64.0;
    EXPECT_TRUE(
        cbt::point_within(d(std::min(u + shift, d.domain().hi)), cb::point_cast<cb::real50>(c(u)), cb::real50(8), 16))
        << u;
  }
  EXPECT_NE(d(d.breakpoints()[0] + 0.5 * (d.breakpoints()[1] - d.breakpoints()[0])),
            c(cb_[0] + 0.5 * (cb_[1] - cb_[0])));
}

TEST(cardinal, control_point_ends_need_four_points) {
  using P = cb::point<double, 2>;
  cb::cardinal_spline<double, 2>::options opt;
  opt.end = cb::cardinal_end::control_points;
  const cb::point_list<double, 2> three{P(0, 0), P(1, 1), P(2, 0)};
  const std::string expected = "points: 3 given, at least 4 required (end = control_points";
  EXPECT_THAT(cbt::message_of([&] { cb::cardinal_spline<double, 2> c(three, opt); }), HasSubstr(expected));
  EXPECT_THAT(cbt::message_of([&] {
                cb::cardinal_spline<double, 2> c({0.0, 1.0, 2.0}, three, opt);
              }),
              HasSubstr(expected));
  opt.alpha = 0.5;
  EXPECT_THAT(cbt::message_of([&] { cb::cardinal_spline<double, 2> c(three, opt); }), HasSubstr(expected));
  // Four points: one segment, P_1 -> P_2.
  const cb::cardinal_spline<double, 2> one({P(0, 0), P(1, 1), P(2, 0), P(3, 1)}, opt);
  EXPECT_EQ(one.engine().segment_count(), 1u);
  EXPECT_EQ(one(one.domain().lo), P(1, 1));
  // A repeated point still gives a zero knot interval with alpha > 0, whichever segment it is in.
  EXPECT_THAT(cbt::message_of([&] {
                cb::cardinal_spline<double, 2> c({P(0, 0), P(0, 0), P(2, 0), P(3, 1)}, opt);
              }),
              HasSubstr("points[1] repeats points[0]: a zero chord gives a zero knot interval"));
  EXPECT_STREQ(cb::to_string(cb::cardinal_end::control_points), "control_points");
  // Keyframe tracks pass through every key: the end mode that skips the first and last is refused.
  const std::vector<cb::motion::key<double, 1>> keys{{0, cb::point<double, 1>(1.0)},
                                                     {10, cb::point<double, 1>(2.0)},
                                                     {20, cb::point<double, 1>(0.0)},
                                                     {30, cb::point<double, 1>(1.0)}};
  EXPECT_THAT(
      cbt::message_of([&] { (void)cb::motion::catmull_rom_track<double, 1>(keys, cb::cardinal_end::control_points); }),
      HasSubstr("ends = control_points: a keyframe track passes through every key"));
}
