// Kochanek-Bartels (TCB) splines: the combined incoming/outgoing tangents against the paper's
// formulas, seed 000's one-parameter formulas (tension, continuity; bias with its sign convention),
// reduction to Catmull-Rom, the paper's non-uniform time adjustment (C1 in time for c = 0),
// interpolation, closed loops, locality and bad input.
#include "support/accuracy.hpp"
#include "support/fixtures.hpp"

#include "curvebench/curves/cardinal_spline.hpp"
#include "curvebench/curves/kochanek_bartels.hpp"

#include <gmock/gmock.h>

#include <array>
#include <cmath>
#include <vector>

namespace cb = curvebench;
namespace cbt = curvebench::testing;
using ::testing::HasSubstr;

namespace {

// Tolerances, eps(Real) times the data scale (coordinates <= 4, chords <= 4, h >= 1/2):
// - knot_value_ulps: a segment's start value is the stored key (0 ulps); the last knot sums four
//   power coefficients: 8.
// - tangent_ulps: tangents are two products of three factors plus a sum (~6 roundings), divided
//   by h or (h0 + h1)/2 (2 more), then recovered from the power form at t = 0 or 1 (~4): 24.
// - continuity_ulps: left/right limits of P and P', two evaluations: 32.
constexpr double knot_value_ulps = 8;
constexpr double tangent_ulps = 24;
constexpr double continuity_ulps = 32;

template <class Real>
class kb_test : public ::testing::Test {};
TYPED_TEST_SUITE(kb_test, cbt::all_reals);

const std::vector<std::array<double, 2>> pd{{0.0, 0.0}, {1.0, 2.0}, {3.0, 2.5}, {3.5, 0.5}, {2.0, -1.0}, {4.0, -2.0}};
const std::vector<double> kd{0.0, 1.0, 1.5, 3.0, 4.0, 6.0};  // non-uniform key times
// Per-key (tension, continuity, bias), dyadic.
const std::vector<std::array<double, 3>> td{{0.25, -0.5, 0.5},  {0.5, 0.25, -0.25}, {-0.25, 0.75, 0.125},
                                            {0.0, -0.25, -0.5}, {0.75, 0.5, 0.25},  {0.125, 0.0, 0.75}};

template <class Real>
cb::point_list<Real, 2> pts() {
  return cbt::points_from<Real>(pd);
}
template <class Real>
std::vector<cb::tcb<Real>> params(bool zero_continuity = false) {
  std::vector<cb::tcb<Real>> r;
  for (auto& t : td) r.push_back({Real(t[0]), zero_continuity ? Real(0) : Real(t[1]), Real(t[2])});
  return r;
}
cb::point<cb::real50, 2> p50(std::size_t i) { return {pd[i][0], pd[i][1]}; }

}  // namespace

static_assert(cb::curve<cb::kochanek_bartels<double, 2>>);
static_assert(cb::curve<cb::kochanek_bartels<cb::real50, 2>>);

TYPED_TEST(kb_test, tangents_are_the_papers_with_time_adjustment) {
  using Real = TypeParam;
  const cb::kochanek_bartels<Real, 2> c(std::vector<Real>(kd.begin(), kd.end()), pts<Real>(), params<Real>(), {});
  const auto& e = c.engine();
  for (std::size_t i = 1; i + 1 < pd.size(); ++i) {
    // Paper: DS_i (incoming) = (1-t)(1+b)(1-c)/2 L + (1-t)(1-b)(1+c)/2 R,
    //        DD_i (outgoing) = (1-t)(1+b)(1+c)/2 L + (1-t)(1-b)(1-c)/2 R, L = P_i - P_{i-1}, R = P_{i+1} - P_i;
    // adjusted for frame counts N_{i-1} = h_{i-1}, N_i = h_i: DS *= 2N_{i-1}/(N_{i-1}+N_i), DD *= 2N_i/(N_{i-1}+N_i).
    // These are tangents in segment units (dP/dt); the engine's geometry holds exactly those.
    const cb::real50 t(td[i][0]), cc(td[i][1]), b(td[i][2]);
    const cb::point<cb::real50, 2> L = p50(i) - p50(i - 1), R = p50(i + 1) - p50(i);
    const cb::real50 n0 = cb::real50(kd[i]) - cb::real50(kd[i - 1]), n1 = cb::real50(kd[i + 1]) - cb::real50(kd[i]);
    const cb::point<cb::real50, 2> ds =
        ((1 - t) * (1 + b) * (1 - cc) / 2 * L + (1 - t) * (1 - b) * (1 + cc) / 2 * R) * (2 * n0 / (n0 + n1));
    const cb::point<cb::real50, 2> dd =
        ((1 - t) * (1 + b) * (1 + cc) / 2 * L + (1 - t) * (1 - b) * (1 - cc) / 2 * R) * (2 * n1 / (n0 + n1));
    const cb::point<Real, 2> in_geom = e.geometry(i - 1).row(3).transpose();
    const cb::point<Real, 2> out_geom = e.geometry(i).row(2).transpose();
    ASSERT_TRUE(cbt::point_within(in_geom, ds, cb::real50(8), tangent_ulps)) << "incoming at " << i;
    ASSERT_TRUE(cbt::point_within(out_geom, dd, cb::real50(8), tangent_ulps)) << "outgoing at " << i;
    // And as derivatives in u: the one-sided limits are the segment tangents divided by that side's h.
    ASSERT_TRUE(cbt::point_within(e.evaluate_segment(i - 1, Real(1), 1), cb::point<cb::real50, 2>(ds / n0),
                                  cb::real50(16), tangent_ulps));
    ASSERT_TRUE(cbt::point_within(e.evaluate_segment(i, Real(0), 1), cb::point<cb::real50, 2>(dd / n1), cb::real50(16),
                                  tangent_ulps));
  }
  for (std::size_t i = 0; i < pd.size(); ++i)
    ASSERT_TRUE(cbt::point_within(c(Real(kd[i])), p50(i), cb::real50(4), knot_value_ulps)) << i;
}

TYPED_TEST(kb_test, time_adjustment_makes_zero_continuity_c1_in_time) {
  using Real = TypeParam;
  const std::vector<Real> k(kd.begin(), kd.end());
  typename cb::kochanek_bartels<Real, 2>::options adjusted{}, raw{};
  raw.time_adjust = false;
  const cb::kochanek_bartels<Real, 2> a(k, pts<Real>(), params<Real>(true), adjusted);
  const cb::kochanek_bartels<Real, 2> r(k, pts<Real>(), params<Real>(true), raw);
  for (std::size_t i = 1; i + 1 < kd.size(); ++i) {
    // With c = 0 both sides' adjusted tangents divided by their h equal 2 D / (h_{i-1} + h_i).
    for (int order = 0; order <= 1; ++order)
      ASSERT_TRUE(cbt::point_within(a.engine().evaluate_segment(i - 1, Real(1), order),
                                    cb::point_cast<cb::real50>(a.engine().evaluate_segment(i, Real(0), order)),
                                    cb::real50(16), continuity_ulps))
          << "adjusted C" << order << " at " << i;
    // Without the adjustment the velocity jumps by the ratio of the intervals (h differs at every knot here).
    const auto jump =
        (r.engine().evaluate_segment(i - 1, Real(1), 1) - r.engine().evaluate_segment(i, Real(0), 1)).norm();
    EXPECT_GT(static_cast<double>(jump), 1e-2) << "raw at " << i;
  }
}

TYPED_TEST(kb_test, zero_tcb_on_uniform_times_is_catmull_rom) {
  using Real = TypeParam;
  const auto p = pts<Real>();
  const cb::kochanek_bartels<Real, 2> kb(p, std::vector<cb::tcb<Real>>(p.size()), {});
  const cb::cardinal_spline<Real, 2> cr(p);  // s = 1/2, uniform, phantom ends
  for (int k = 0; k <= 80; ++k) {
    const Real u = Real(5) * Real(k) / Real(80);
    for (int order = 0; order <= 3; ++order)
      ASSERT_TRUE(cbt::point_within(kb.derivative(u, order), cb::point_cast<cb::real50>(cr.derivative(u, order)),
                                    cb::real50(16), continuity_ulps))
          << k << " " << order;
  }
}

TEST(kochanek_bartels, seed_000_one_parameter_formulas) {
  // Uniform times, one parameter at a time, at key 2 (L = P2 - P1, R = P3 - P2), in real50.
  using R50 = cb::real50;
  const auto p = pts<R50>();
  const cb::point<R50, 2> L = p[2] - p[1], Rr = p[3] - p[2];
  auto spline = [&](cb::tcb<R50> k) {
    std::vector<cb::tcb<R50>> ps(p.size());
    ps[2] = k;
    return cb::kochanek_bartels<R50, 2>(p, ps, {});
  };
  auto in_out = [&](const cb::kochanek_bartels<R50, 2>& c) {
    return std::pair{c.engine().evaluate_segment(1, R50(1), 1), c.engine().evaluate_segment(2, R50(0), 1)};
  };
  const double tol = 64;
  const R50 v(0.375), cc(0.625), b(0.25);
  // Tension: P'(t_k) = (1 - v)/2 (P_{k+1} - P_{k-1}) on both sides.
  auto [ti, to] = in_out(spline({v, 0, 0}));
  const cb::point<R50, 2> tension = (1 - v) / 2 * (p[3] - p[1]);
  EXPECT_TRUE(cbt::point_within(ti, tension, R50(4), tol));
  EXPECT_TRUE(cbt::point_within(to, tension, R50(4), tol));
  // Continuity: incoming R'_{k-1}(1) = (1-c)/2 L + (1+c)/2 R; outgoing R'_k(0) = (1+c)/2 L + (1-c)/2 R.
  auto [ci, co] = in_out(spline({0, cc, 0}));
  EXPECT_TRUE(cbt::point_within(ci, cb::point<R50, 2>((1 - cc) / 2 * L + (1 + cc) / 2 * Rr), R50(4), tol));
  EXPECT_TRUE(cbt::point_within(co, cb::point<R50, 2>((1 + cc) / 2 * L + (1 - cc) / 2 * Rr), R50(4), tol));
  // Bias: seed 000 prints (1 - b)/2 L + (1 + b)/2 R; the paper (which we follow) has (1 + b) on L.
  // So our bias b equals the seed's formula at -b, and differs from it at +b.
  auto [bi, bo] = in_out(spline({0, 0, b}));
  const cb::point<R50, 2> seed_at_minus_b = (1 + b) / 2 * L + (1 - b) / 2 * Rr;
  const cb::point<R50, 2> seed_at_b = (1 - b) / 2 * L + (1 + b) / 2 * Rr;
  EXPECT_TRUE(cbt::point_within(bi, seed_at_minus_b, R50(4), tol));
  EXPECT_TRUE(cbt::point_within(bo, seed_at_minus_b, R50(4), tol));
  EXPECT_GT(static_cast<double>((bo - seed_at_b).norm()), 0.1);
}

TEST(kochanek_bartels, closed_loop_is_periodic_and_c1_with_zero_continuity) {
  const auto p = pts<double>();
  cb::kochanek_bartels<double, 2>::options closed{};
  closed.closed = true;
  std::vector<double> k(kd.begin(), kd.end());
  k.push_back(7.0);  // the return to P0
  const cb::kochanek_bartels<double, 2> c(k, p, params<double>(true), closed);
  EXPECT_EQ(c.engine().segment_count(), p.size());
  const double eps = std::numeric_limits<double>::epsilon();
  for (int order = 0; order <= 1; ++order)
    EXPECT_NEAR((c.derivative(7.0, order) - c.derivative(0.0, order)).norm(), 0.0, 64 * 16 * eps) << order;
  // With continuity != 0 at key 0 the seam keeps C0 but not C1.
  const cb::kochanek_bartels<double, 2> cc(k, p, params<double>(false), closed);
  EXPECT_NEAR((cc(7.0) - cc(0.0)).norm(), 0.0, 64 * 4 * eps);
  EXPECT_GT((cc.derivative(7.0, 1) - cc.derivative(0.0, 1)).norm(), 1e-2);
}

TEST(kochanek_bartels, moving_one_key_changes_at_most_four_segments) {
  cb::point_list<double, 2> p;
  for (int i = 0; i < 9; ++i) p.push_back(cb::point<double, 2>(i, (i * 3) % 4));
  const std::vector<cb::tcb<double>> ps(p.size(), cb::tcb<double>{0.25, -0.5, 0.125});
  const cb::kochanek_bartels<double, 2> a(p, ps, {});
  for (std::size_t j = 0; j < p.size(); ++j) {
    auto moved = p;
    moved[j] += cb::point<double, 2>(-0.75, 0.5);
    const cb::kochanek_bartels<double, 2> b(moved, ps, {});
    std::size_t changed = 0;
    for (std::size_t i = 0; i < a.engine().segment_count(); ++i)
      if (a.engine().power_coefficients(i) != b.engine().power_coefficients(i)) {
        ++changed;
        EXPECT_TRUE(i + 2 >= j && i <= j + 1) << "key " << j << " moved segment " << i;
      }
    EXPECT_GE(changed, 1u);
    EXPECT_LE(changed, 4u);
  }
}

TEST(kochanek_bartels, bad_input_names_what_and_where) {
  using P = cb::point<double, 2>;
  auto msg = [](auto&& f) -> std::string {
    try {
      f();
    } catch (const cb::invalid_input& e) {
      return e.what();
    }
    return "no exception";
  };
  const cb::point_list<double, 2> p{P(0, 0), P(1, 1), P(2, 0)};
  std::vector<cb::tcb<double>> ps(3);
  EXPECT_THAT(msg([&] { cb::kochanek_bartels<double, 2>(p, std::vector<cb::tcb<double>>(2), {}); }),
              HasSubstr("params: 2 given, must match points: 3"));
  ps[1].continuity = std::nan("");
  EXPECT_THAT(msg([&] { cb::kochanek_bartels<double, 2>(p, ps, {}); }),
              HasSubstr("params.continuity[1] = nan: must be finite"));
  EXPECT_THAT(msg([&] {
                cb::kochanek_bartels<double, 2>({0.0, 2.0, 1.0}, p, std::vector<cb::tcb<double>>(3), {});
              }),
              HasSubstr("knots must be increasing: knots[2] = 1 <= knots[1] = 2"));
  cb::kochanek_bartels<double, 2>::options closed{};
  closed.closed = true;
  EXPECT_THAT(msg([&] {
                cb::kochanek_bartels<double, 2>({0.0, 1.0, 2.0}, p, std::vector<cb::tcb<double>>(3), closed);
              }),
              HasSubstr("knots: 3 given, must match points + 1 (closed loop): 4"));
  EXPECT_THAT(msg([&] {
                cb::kochanek_bartels<double, 2>({P(0, 0), P(1, 0)}, std::vector<cb::tcb<double>>(2), closed);
              }),
              HasSubstr("points: 2 given, at least 3 required (a closed loop needs three keys)"));
  EXPECT_THAT(msg([&] { cb::kochanek_bartels<double, 2>({P(0, 0)}, std::vector<cb::tcb<double>>(1), {}); }),
              HasSubstr("points: 1 given, at least 2 required"));
}
