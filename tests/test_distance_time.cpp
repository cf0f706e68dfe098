// Distance-time functions S(t) and the monotone cubic behind the key-based ones: S(0) = 0,
// S(1) = 1, values and exact derivatives against the real50 instantiation, the real50 derivatives
// against central differences of the real50 function (an independent check of every formula),
// continuity at the joints and at rest, monotonicity, the parabolic maximum speed, the monotone
// cubic's shape preservation (derived in monotone_cubic.hpp), exact speed integration, and the
// error messages.
#include "support/accuracy.hpp"

#include "curvebench/motion/distance_time.hpp"
#include "curvebench/motion/monotone_cubic.hpp"

#include <gmock/gmock.h>

#include <cstdint>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

namespace cb = curvebench;
namespace cbm = curvebench::motion;
namespace cbt = curvebench::testing;
using cb::real50;
using ::testing::HasSubstr;

namespace {

// Tolerances, in eps(Real) times a scale (the maximum of |S^(k)| over [0, 1] for derivative k, so
// that values crossing zero are measured against the size of the function):
// - value_ulps: S is a short closed form (<= ~8 roundings on numbers <= 1) or a Horner cubic of
//   the key-based pieces; 8 eps of scale 1 covers it;
// - derivative_ulps: sin/cos of a rounded argument (pi t: ~2 roundings, so ~|arg| * 2 eps absolute
//   at |arg| <= pi), times a rounded factor; the key cubics' c2, c3 come from differences of slopes
//   divided by h and h^2, which carries ~|secant| eps relative to the piece's derivative scale;
//   16 eps of scale bounds both (observed: <= 4);
// - fd_relative: real50 central differences with step 1e-12: truncation h^2 |S'''| / 6 <= 1e-21
//   (|S'''| < 1e3 here), rounding 1e-49 / 1e-12; 1e-18 relative to the scale is far below any
//   formula error (a wrong coefficient shows up at 1e-1);
// - joint_ulps: left and right limits at a joint are evaluated from two different pieces, each
//   within derivative_ulps: twice that;
// - jump_fraction: a derivative documented to jump (the first order above continuity()) must
//   jump by at least 1% of its scale for the generic parameters used here; the real jumps are
//   O(scale) (e.g. the parabolic acceleration jumps by its full size), so 1% cannot be met by
//   rounding and cannot be missed by a genuine jump.
constexpr double value_ulps = 8;
constexpr double derivative_ulps = 16;
const real50 fd_relative("1e-18");
constexpr double joint_ulps = 2 * derivative_ulps;
constexpr double jump_fraction = 0.01;

template <class Real>
class distance_time_test : public ::testing::Test {};
TYPED_TEST_SUITE(distance_time_test, cbt::all_reals);

static_assert(cbm::distance_time<cbm::linear_ease<double>>);
static_assert(cbm::distance_time<cbm::sine_ease<float>>);
static_assert(cbm::distance_time<cbm::sine_plateau_ease<long double>>);
static_assert(cbm::distance_time<cbm::parabolic_ease<real50>>);
static_assert(cbm::distance_time<cbm::smoothstep_ease<double>>);
static_assert(cbm::distance_time<cbm::smootherstep_ease<double>>);
static_assert(cbm::distance_time<cbm::distance_keys_ease<double>>);
static_assert(cbm::distance_time<cbm::speed_curve_ease<double>>);

template <class Real>
std::vector<Real> eighths(std::initializer_list<int> k) {
  std::vector<Real> v;
  for (int i : k) v.push_back(Real(i) / Real(8));
  return v;
}

template <class F>
struct named {
  const char* name;
  F f;
};
template <class F>
named(const char*, F) -> named<F>;

// Every distance-time function with exactly representable parameters (so the Real and the real50
// instances are the same mathematical function).
template <class Real>
auto make_eases() {
  const auto dk_t = eighths<Real>({0, 1, 3, 4, 6, 8});
  const auto dk_s = eighths<Real>({0, 1, 2, 2, 7, 8});  // a pause on [3/8, 1/2]
  const auto sp_t = eighths<Real>({0, 2, 4, 6, 8});
  const auto sp_v = eighths<Real>({0, 8, 24, 8, 0});   // stopped at both ends
  const auto sp_v2 = eighths<Real>({4, 16, 0, 8, 2});  // moving at both ends, a stop at t = 1/2
  return std::make_tuple(
      named{"linear", cbm::linear_ease<Real>{}}, named{"sine", cbm::sine_ease<Real>{}},
      named{"sine_plateau", cbm::sine_plateau_ease<Real>(Real(1) / Real(4), Real(5) / Real(8))},
      named{"parabolic", cbm::parabolic_ease<Real>(Real(1) / Real(4), Real(5) / Real(8))},
      named{"smoothstep", cbm::smoothstep_ease<Real>{}}, named{"smootherstep", cbm::smootherstep_ease<Real>{}},
      named{"distance_keys", cbm::distance_keys_ease<Real>(dk_t, dk_s)},
      named{"speed_linear", cbm::speed_curve_ease<Real>(sp_t, sp_v, cbm::speed_interpolation::linear)},
      named{"speed_cubic", cbm::speed_curve_ease<Real>(sp_t, sp_v, cbm::speed_interpolation::monotone_cubic)},
      named{"speed_cubic_moving", cbm::speed_curve_ease<Real>(sp_t, sp_v2, cbm::speed_interpolation::monotone_cubic)});
}

template <class Real, class Visitor>
void for_each_pair(Visitor&& visit) {
  auto a = make_eases<Real>();
  auto r = make_eases<real50>();
  [&]<std::size_t... I>(std::index_sequence<I...>) { (visit(std::get<I>(a), std::get<I>(r)), ...); }
  (std::make_index_sequence<std::tuple_size_v<decltype(a)>>{});
}

constexpr int grid = 256;  // t = k / 256 is exact in every type

// max over the grid (and the joints, both sides) of |S^(order)| of the reference.
template <class F>
real50 scale_of(const F& ref, int order) {
  using std::abs;
  real50 m(0);
  for (int k = 0; k <= grid; ++k) {
    const real50 t = real50(k) / grid;
    m = std::max(m, real50(abs(ref.derivative(t, order, cbm::side::left))));
    m = std::max(m, real50(abs(ref.derivative(t, order, cbm::side::right))));
  }
  for (const real50& b : ref.breakpoints()) {
    m = std::max(m, real50(abs(ref.derivative(b, order, cbm::side::left))));
    m = std::max(m, real50(abs(ref.derivative(b, order, cbm::side::right))));
  }
  return m == 0 ? real50(1) : m;
}

}  // namespace

TYPED_TEST(distance_time_test, starts_at_zero_ends_at_one) {
  using Real = TypeParam;
  for_each_pair<Real>([](const auto& a, const auto&) {
    EXPECT_EQ(a.f(Real(0)), Real(0)) << a.name;
    EXPECT_TRUE(cbt::within_ulps(a.f(Real(1)), real50(1), 2)) << a.name;
  });
}

TYPED_TEST(distance_time_test, value_and_derivatives_match_real50) {
  using Real = TypeParam;
  for_each_pair<Real>([](const auto& a, const auto& r) {
    for (int order = 0; order <= 2; ++order) {
      const real50 scale = scale_of(r.f, order);
      const double tol = order == 0 ? value_ulps : derivative_ulps;
      for (int k = 0; k <= grid; ++k) {
        for (auto s : {cbm::side::left, cbm::side::right}) {
          const Real t = Real(k) / Real(grid);
          ASSERT_TRUE(
              cbt::within_scaled_ulps(a.f.derivative(t, order, s), r.f.derivative(real50(t), order, s), scale, tol))
              << a.name << " order " << order << " t = " << k << "/" << grid;
        }
      }
    }
  });
}

TEST(distance_time_reference, derivatives_match_central_differences_in_real50) {
  // Independent of the derivative formulas: S' and S'' against central differences of S and S' of
  // the real50 function, away from the joints (where one-sided pieces would be mixed).
  for_each_pair<real50>([](const auto&, const auto& r) {
    const real50 h("1e-12");
    for (int order = 1; order <= 2; ++order) {
      const real50 scale = scale_of(r.f, order);
      for (int k = 1; k < grid; ++k) {
        const real50 t = (real50(k) + real50(1) / 3) / grid;  // off the dyadic joints
        const real50 fd = (r.f.derivative(t + h, order - 1) - r.f.derivative(t - h, order - 1)) / (2 * h);
        using std::abs;
        ASSERT_LE(abs(r.f.derivative(t, order) - fd), fd_relative * scale)
            << r.name << " order " << order << " t = " << static_cast<double>(t);
      }
    }
  });
}

TYPED_TEST(distance_time_test, continuity_at_the_joints_is_as_documented) {
  using Real = TypeParam;
  for_each_pair<Real>([](const auto& a, const auto& r) {
    const auto bps = a.f.breakpoints();
    for (std::size_t j = 1; j + 1 < bps.size(); ++j) {
      const Real b = bps[j];
      for (int order = 0; order <= 2; ++order) {
        const real50 scale = scale_of(r.f, order);
        const Real left = a.f.derivative(b, order, cbm::side::left);
        const Real right = a.f.derivative(b, order, cbm::side::right);
        if (order <= a.f.continuity()) {
          EXPECT_TRUE(cbt::within_scaled_ulps(left, real50(right), scale, joint_ulps))
              << a.name << " order " << order << " at joint " << j;
        } else if (order == a.f.continuity() + 1) {
          using std::abs;
          EXPECT_GE(real50(abs(left - right)), real50(jump_fraction) * scale)
              << a.name << ": order " << order << " should jump at joint " << j;
        }
      }
    }
  });
}

TYPED_TEST(distance_time_test, continuity_at_rest_is_as_documented) {
  // Extended by S = 0 before 0 and S = 1 after 1, the derivatives of order 1..k vanish at the ends
  // and order k + 1 (<= 2) does not.
  using Real = TypeParam;
  for_each_pair<Real>([](const auto& a, const auto& r) {
    // (the order k + 1 jump need only show at one of the two ends)
    const int k = a.f.rest_continuity();
    for (int order = 1; order <= 2; ++order) {
      const real50 scale = scale_of(r.f, order);
      using std::abs;
      const real50 d0 = abs(real50(a.f.derivative(Real(0), order, cbm::side::right)));
      const real50 d1 = abs(real50(a.f.derivative(Real(1), order, cbm::side::left)));
      if (order <= k) {
        EXPECT_LE(std::max(d0, d1), real50(derivative_ulps) * real50(cb::epsilon<Real>()) * scale)
            << a.name << " order " << order;
      } else if (order == k + 1) {
        EXPECT_GE(std::max(d0, d1), real50(jump_fraction) * scale) << a.name << " order " << order;
      }
    }
  });
  EXPECT_EQ(cbm::sine_plateau_ease<Real>(Real(0), Real(1) / Real(2)).rest_continuity(), 0);
  EXPECT_EQ(cbm::parabolic_ease<Real>(Real(1) / Real(4), Real(1)).rest_continuity(), 0);
}

TYPED_TEST(distance_time_test, monotone_non_negative_speed) {
  using Real = TypeParam;
  for_each_pair<Real>([](const auto& a, const auto& r) {
    const real50 vscale = scale_of(r.f, 1);
    Real previous = a.f(Real(0));
    for (int k = 1; k <= 4 * grid; ++k) {
      const Real t = Real(k) / Real(4 * grid);
      const Real s = a.f(t);
      ASSERT_GE(real50(s), real50(previous) - real50(value_ulps) * real50(cb::epsilon<Real>())) << a.name;
      ASSERT_GE(real50(a.f.velocity(t)), -real50(derivative_ulps) * real50(cb::epsilon<Real>()) * vscale) << a.name;
      previous = s;
    }
  });
}

TYPED_TEST(distance_time_test, symmetric_eases_are_symmetric) {
  // S(1 - t) = 1 - S(t) for the eases whose speed profile is symmetric (checked in real50 against
  // the Real value: both sides carry the value tolerance).
  using Real = TypeParam;
  const cbm::sine_ease<Real> sine;
  const cbm::smoothstep_ease<Real> cubic;
  const cbm::smootherstep_ease<Real> quintic;
  const cbm::parabolic_ease<Real> para(Real(3) / Real(8), Real(5) / Real(8));
  const cbm::sine_plateau_ease<Real> plateau(Real(1) / Real(8), Real(7) / Real(8));
  for (int k = 0; k <= grid; ++k) {
    const Real t = Real(k) / Real(grid);
    const Real u = Real(1) - t;  // exact
    EXPECT_TRUE(cbt::within_scaled_ulps(sine(u), real50(1) - real50(sine(t)), 1, 2 * value_ulps));
    EXPECT_TRUE(cbt::within_scaled_ulps(cubic(u), real50(1) - real50(cubic(t)), 1, 2 * value_ulps));
    EXPECT_TRUE(cbt::within_scaled_ulps(quintic(u), real50(1) - real50(quintic(t)), 1, 2 * value_ulps));
    EXPECT_TRUE(cbt::within_scaled_ulps(para(u), real50(1) - real50(para(t)), 1, 2 * value_ulps));
    EXPECT_TRUE(cbt::within_scaled_ulps(plateau(u), real50(1) - real50(plateau(t)), 1, 2 * value_ulps));
  }
}

TYPED_TEST(distance_time_test, parabolic_max_speed_and_phase_distances) {
  // v = 2 / (1 + t2 - t1) (derived from the trapezoid area = 1); S(t1) = v t1 / 2 and
  // S(t2) = 1 - v (1 - t2) / 2; the speed never exceeds v and equals it on [t1, t2].
  using Real = TypeParam;
  const Real t1 = Real(12) / Real(45), t2 = Real(28) / Real(45);  // seed 002: frames 22, 34, 50, 67
  const auto f = cbm::parabolic_ease<Real>::from_frames(22, 34, 50, 67);
  const real50 T1(t1), T2(t2);
  const real50 v = 2 / (1 + T2 - T1);
  EXPECT_TRUE(cbt::within_ulps(f.max_velocity(), v, 4));
  EXPECT_TRUE(cbt::within_ulps(f.velocity(t1), v, 4));
  EXPECT_TRUE(cbt::within_ulps(f.velocity((t1 + t2) / Real(2)), v, 4));
  EXPECT_TRUE(cbt::within_ulps(f(t1), v * T1 / 2, value_ulps));
  EXPECT_TRUE(cbt::within_ulps(f(t2), 1 - v * (1 - T2) / 2, value_ulps));
  EXPECT_TRUE(cbt::within_ulps(f.acceleration(t1 / Real(2)), v / T1, value_ulps));
  EXPECT_TRUE(cbt::within_ulps(f.acceleration(Real(1) - (Real(1) - t2) / Real(2)), -v / (1 - T2), value_ulps));
  for (int k = 0; k <= grid; ++k)
    EXPECT_LE(real50(f.velocity(Real(k) / Real(grid))), v * (1 + real50(4) * real50(cb::epsilon<Real>())));
  // The exact seed fractions 12/61 and 44/61 when evaluated in 50 digits (t1 = 12/45, t2 = 28/45).
  const auto g = cbm::parabolic_ease<real50>::from_frames(22, 34, 50, 67);
  EXPECT_TRUE(cbt::within_ulps(g.max_velocity(), real50(90) / 61, 4));
  EXPECT_TRUE(cbt::within_ulps(g(real50(12) / 45), real50(12) / 61, 8));
  EXPECT_TRUE(cbt::within_ulps(g(real50(28) / 45), real50(44) / 61, 8));
}

TYPED_TEST(distance_time_test, sine_plateau_max_speed) {
  // v = 1 / (2 t1 / pi + t2 - t1 + 2 (1 - t2) / pi); the speed reaches v at t1 and keeps it to t2.
  using Real = TypeParam;
  const Real t1 = Real(1) / Real(4), t2 = Real(5) / Real(8);
  const cbm::sine_plateau_ease<Real> f(t1, t2);
  const real50 pi = boost::math::constants::pi<real50>();
  const real50 v = 1 / (2 * real50(t1) / pi + real50(t2) - real50(t1) + 2 * (1 - real50(t2)) / pi);
  EXPECT_TRUE(cbt::within_ulps(f.max_velocity(), v, value_ulps));
  EXPECT_TRUE(cbt::within_ulps(f.velocity(t1), v, value_ulps));
  EXPECT_TRUE(cbt::within_ulps(f.velocity(t2), v, value_ulps));
  EXPECT_TRUE(cbt::within_ulps(f(t1), v * 2 * real50(t1) / pi, value_ulps));
  // the no-plateau, no-ease limits: t1 = 0, t2 = 1 is the linear ease
  const cbm::sine_plateau_ease<Real> lin(Real(0), Real(1));
  EXPECT_TRUE(cbt::within_ulps(lin(Real(3) / Real(8)), real50(3) / 8, value_ulps));
  EXPECT_EQ(lin.breakpoints().size(), 2u);  // empty phases add no joints
  EXPECT_EQ(f.breakpoints().size(), 4u);
  // t1 = t2 = 1/2 is the sine ease rescaled: max speed pi / 2 at 1/2, same values
  const cbm::sine_plateau_ease<Real> sine_like(Real(1) / Real(2), Real(1) / Real(2));
  EXPECT_EQ(sine_like.breakpoints().size(), 3u);
  const cbm::sine_ease<real50> sine;
  for (int k = 0; k <= 16; ++k) {
    const Real t = Real(k) / Real(16);
    EXPECT_TRUE(cbt::within_scaled_ulps(sine_like(t), sine(real50(t)), 1, value_ulps)) << k;
    EXPECT_TRUE(cbt::within_scaled_ulps(sine_like.velocity(t), sine.velocity(real50(t)), pi / 2, derivative_ulps));
  }
}

TYPED_TEST(distance_time_test, smoothstep_family_end_conditions) {
  // smoothstep: S'(0) = S'(1) = 0, S''(0) = 6, S''(1) = -6, max speed 3/2;
  // smootherstep: S' = S'' = 0 at both ends, max speed 15/8.
  using Real = TypeParam;
  const cbm::smoothstep_ease<Real> c;
  const cbm::smootherstep_ease<Real> q;
  const Real half = Real(1) / Real(2);
  EXPECT_EQ(c.velocity(Real(0)), Real(0));
  EXPECT_EQ(c.velocity(Real(1)), Real(0));
  EXPECT_EQ(c.acceleration(Real(0)), Real(6));
  EXPECT_EQ(c.acceleration(Real(1)), Real(-6));
  EXPECT_EQ(c.velocity(half), Real(3) / Real(2));
  EXPECT_EQ(q.velocity(Real(0)), Real(0));
  EXPECT_EQ(q.acceleration(Real(0)), Real(0));
  EXPECT_EQ(q.velocity(Real(1)), Real(0));
  EXPECT_EQ(q.acceleration(Real(1)), Real(0));
  EXPECT_EQ(q.velocity(half), Real(15) / Real(8));
  EXPECT_EQ(c(half), half);
  EXPECT_EQ(q(half), half);
}

// ---- monotone cubic -------------------------------------------------------------------------

namespace {

// Deterministic data: x with random gaps, y a random walk with runs up, down and flat.
struct lcg {
  std::uint64_t state;
  double next() {
    state = state * 6364136223846793005ULL + 1442695040888963407ULL;
    return static_cast<double>(state >> 11) / 9007199254740992.0;
  }
};

std::pair<std::vector<real50>, std::vector<real50>> walk_data(std::uint64_t seed, int n) {
  lcg g{seed};
  std::vector<real50> x{real50(0)}, y{real50(0)};
  for (int i = 1; i < n; ++i) {
    x.push_back(x.back() + real50(0.05 + g.next()));
    const double r = g.next();
    // a mix of steep and shallow steps, a few exactly flat ones
    y.push_back(r < 0.15 ? y.back() : y.back() + real50((g.next() < 0.7 ? 1 : -1) * (0.01 + 10 * r * r)));
  }
  return {x, y};
}

// min over [0, h] of the derivative of the piece c0 + c1 d + c2 d^2 + c3 d^3, exactly (a quadratic:
// the ends and the vertex).
real50 min_derivative(const std::array<real50, 4>& c, const real50& h, real50* max_out) {
  const auto q = [&](const real50& d) { return c[1] + d * (2 * c[2] + 3 * c[3] * d); };
  real50 lo = std::min(q(real50(0)), q(h)), hi = std::max(q(real50(0)), q(h));
  if (c[3] != 0) {
    const real50 v = -c[2] / (3 * c[3]);
    if (v > 0 && v < h) {
      lo = std::min(lo, q(v));
      hi = std::max(hi, q(v));
    }
  }
  *max_out = hi;
  return lo;
}

}  // namespace

TEST(monotone_cubic, preserves_monotonicity_exactly_on_random_data) {
  // On every interval the derivative keeps the sign of the secant (the quadratic's exact minimum /
  // maximum), the slope ratios lie in Fritsch-Carlson's box [0, 3], and flat data give flat pieces.
  // The same data with Catmull-Rom (central-difference) slopes overshoot: the test can tell.
  int catmull_rom_violations = 0;
  for (std::uint64_t seed = 1; seed <= 40; ++seed) {
    const auto [x, y] = walk_data(seed, 12);
    const cbm::monotone_cubic<real50> f(x, y);
    const auto m = f.slopes();
    for (std::size_t k = 0; k + 1 < x.size(); ++k) {
      const real50 h = x[k + 1] - x[k];
      const real50 d = (y[k + 1] - y[k]) / h;
      real50 hi;
      const real50 lo = min_derivative(f.pieces().pieces()[k], h, &hi);
      // (a derivative that touches 0 inside the piece - the (3, 3) corner - rounds to +-1e-50 |d|)
      using std::abs;
      const real50 touch = real50("1e-45") * abs(d);
      if (d > 0) {
        ASSERT_GE(lo, -touch) << "seed " << seed << " interval " << k;
        ASSERT_GE(m[k] / d, real50(0));
        ASSERT_LE(m[k] / d, real50(3) + real50("1e-40"));
        ASSERT_LE(m[k + 1] / d, real50(3) + real50("1e-40"));
      } else if (d < 0) {
        ASSERT_LE(hi, touch) << "seed " << seed << " interval " << k;
      } else {
        ASSERT_EQ(m[k], real50(0));
        ASSERT_EQ(m[k + 1], real50(0));
      }
      // interpolation and C1 at the knots
      ASSERT_LE(abs(f(x[k]) - y[k]), real50("1e-45"));
      if (k > 0) {
        ASSERT_LE(abs(f.derivative(x[k], 1, cbm::side::left) - f.derivative(x[k], 1, cbm::side::right)),
                  real50("1e-44") * (1 + abs(m[k])));
      }
      // Catmull-Rom slopes (secant over two intervals) on the same interval
      if (k > 0 && k + 2 < x.size() && d != 0) {
        const real50 m0 = (y[k + 1] - y[k - 1]) / (x[k + 1] - x[k - 1]);
        const real50 m1 = (y[k + 2] - y[k]) / (x[k + 2] - x[k]);
        real50 chi;
        const real50 clo = min_derivative(cbm::hermite_piece(y[k], y[k + 1], m0, m1, h), h, &chi);
        if ((d > 0 && clo < 0) || (d < 0 && chi > 0)) ++catmull_rom_violations;
      }
    }
    using std::abs;
    ASSERT_LE(abs(f(x.back()) - y.back()), real50("1e-45"));
  }
  EXPECT_GT(catmull_rom_violations, 0);
}

TEST(monotone_cubic, box_corners_of_the_derivation) {
  // The four corners of [0, 3]^2 give the derivative profiles derived in the header:
  // 6 tau (1 - tau), 3 (1 - tau)^2, 3 tau^2, 3 (1 - 2 tau)^2 (secant 1 on [0, 1]).
  for (int a : {0, 3})
    for (int b : {0, 3}) {
      const auto c = cbm::hermite_piece(real50(0), real50(1), real50(a), real50(b), real50(1));
      for (int k = 0; k <= 16; ++k) {
        const real50 tau = real50(k) / 16;
        const real50 deriv = c[1] + tau * (2 * c[2] + 3 * c[3] * tau);
        real50 expect;
        if (a == 0 && b == 0) expect = 6 * tau * (1 - tau);
        if (a == 3 && b == 0) expect = 3 * (1 - tau) * (1 - tau);
        if (a == 0 && b == 3) expect = 3 * tau * tau;
        if (a == 3 && b == 3) expect = 3 * (1 - 2 * tau) * (1 - 2 * tau);
        EXPECT_TRUE(cbt::within_scaled_ulps(deriv, expect, 1, 8)) << a << " " << b << " " << k;
      }
    }
  // just outside the box the cubic is no longer monotone for (a, b) = (4, 4): y'(1/2) = -1/2
  const auto c = cbm::hermite_piece(real50(0), real50(1), real50(4), real50(4), real50(1));
  const real50 half(0.5);
  EXPECT_LT(c[1] + half * (2 * c[2] + 3 * c[3] * half), real50(0));
}

TEST(monotone_cubic, integral_is_exact) {
  // Full pieces against h (y0 + y1) / 2 + h^2 (m0 - m1) / 12, partial pieces against Simpson's rule
  // (exact for cubics).
  const auto [x, y] = walk_data(7, 9);
  const cbm::monotone_cubic<real50> f(x, y);
  const auto m = f.slopes();
  real50 acc(0);
  for (std::size_t k = 0; k + 1 < x.size(); ++k) {
    const real50 h = x[k + 1] - x[k];
    const real50 mid = x[k] + h / 3;
    const real50 simpson = (mid - x[k]) / 6 * (f(x[k]) + 4 * f((x[k] + mid) / 2) + f(mid));
    EXPECT_TRUE(cbt::within_scaled_ulps(f.integral(mid), acc + simpson, 1 + abs(acc), 64)) << k;
    acc += h * (y[k] + y[k + 1]) / 2 + h * h * (m[k] - m[k + 1]) / 12;
    EXPECT_TRUE(cbt::within_scaled_ulps(f.integral(x[k + 1]), acc, 1 + abs(acc), 64)) << k;
  }
}

TEST(monotone_cubic, rejects_bad_data) {
  const std::vector<double> x{0, 1, 1}, y{0, 1, 2};
  try {
    cbm::monotone_cubic<double> f(x, y);
    FAIL();
  } catch (const cb::invalid_input& e) {
    EXPECT_STREQ(e.what(), "x must be increasing: x[2] = 1 <= x[1] = 1");
  }
  EXPECT_THROW((cbm::monotone_cubic<double>(std::vector<double>{0}, std::vector<double>{0})), cb::invalid_input);
  const cbm::monotone_cubic<double> f(std::vector<double>{0, 1}, std::vector<double>{0, 2});
  EXPECT_THROW((void)f(1.5), std::domain_error);
  EXPECT_EQ(f(0.25), 0.5);  // two knots: the line
}

// ---- key-based eases ------------------------------------------------------------------------

TEST(distance_keys_ease, interpolates_keys_and_pauses) {
  const auto t = eighths<double>({0, 1, 3, 4, 6, 8});
  const auto s = eighths<double>({0, 1, 2, 2, 7, 8});
  const cbm::distance_keys_ease<double> f(t, s);
  for (std::size_t i = 0; i < t.size(); ++i) EXPECT_TRUE(cbt::within_ulps(f(t[i]), real50(s[i]), 2)) << i;
  // the pause: S constant, speed 0 on [3/8, 1/2]
  for (int k = 0; k <= 8; ++k) {
    const double u = 0.375 + 0.125 * k / 8;
    EXPECT_EQ(f(u), 0.25);
    EXPECT_EQ(f.velocity(u), 0.0);
  }
}

TEST(speed_curve_ease, integrates_exactly_and_normalizes) {
  // Piecewise linear speed: area = trapezoid sum; S at the keys = cumulative trapezoids / area;
  // S' = v / area at the keys. Monotone cubic speed: area from the Hermite integral formula.
  const auto t = eighths<real50>({0, 2, 3, 6, 8});
  const auto v = eighths<real50>({0, 8, 24, 4, 0});
  const cbm::speed_curve_ease<real50> lin(t, v, cbm::speed_interpolation::linear);
  real50 area(0);
  std::vector<real50> cum{real50(0)};
  for (std::size_t k = 0; k + 1 < t.size(); ++k) cum.push_back(area += (t[k + 1] - t[k]) * (v[k] + v[k + 1]) / 2);
  EXPECT_TRUE(cbt::within_ulps(lin.area(), area, 4));
  for (std::size_t k = 0; k < t.size(); ++k) {
    EXPECT_TRUE(cbt::within_scaled_ulps(lin(t[k]), cum[k] / area, 1, 8)) << k;
    EXPECT_TRUE(cbt::within_scaled_ulps(lin.velocity(t[k]), v[k] / area, 1, 8)) << k;
  }
  const cbm::speed_curve_ease<real50> cub(t, v, cbm::speed_interpolation::monotone_cubic);
  const auto m = cbm::monotone_slopes<real50>(t, v);
  real50 carea(0);
  for (std::size_t k = 0; k + 1 < t.size(); ++k) {
    const real50 h = t[k + 1] - t[k];
    carea += h * (v[k] + v[k + 1]) / 2 + h * h * (m[k] - m[k + 1]) / 12;
  }
  EXPECT_TRUE(cbt::within_ulps(cub.area(), carea, 8));
  for (std::size_t k = 0; k < t.size(); ++k)
    EXPECT_TRUE(cbt::within_scaled_ulps(cub.velocity(t[k]), v[k] / carea, 1, 8)) << k;
  // the cubic speed never dips below zero between the non-negative keys (exact piece minima)
  for (std::size_t k = 0; k + 1 < t.size(); ++k) {
    const auto& c = cub.speed().pieces()[k];
    const real50 h = t[k + 1] - t[k];
    for (int j = 0; j <= 64; ++j) {
      const real50 d = h * j / 64;
      EXPECT_GE(c[0] + d * (c[1] + d * (c[2] + d * c[3])), real50(0));
    }
  }
}

// ---- errors ---------------------------------------------------------------------------------

namespace {
template <class Fn>
std::string message_of(Fn&& fn) {
  try {
    fn();
  } catch (const cb::invalid_input& e) {
    return e.what();
  }
  return "(no invalid_input thrown)";
}
}  // namespace

TEST(distance_time_errors, messages_name_argument_index_value) {
  using V = std::vector<double>;
  EXPECT_EQ(
      message_of([] { cbm::parabolic_ease<double>(0.5, 0.25); }),
      "t2 = 0.25 < t1 = 0.5: the constant-speed phase [t1, t2] must not end before it starts (0 <= t1 <= t2 <= 1)");
  EXPECT_EQ(message_of([] { cbm::sine_plateau_ease<double>(-0.5, 0.25); }), "t1 = -0.5: must be in [0, 1]");
  EXPECT_EQ(message_of([] { (void)cbm::parabolic_ease<double>::from_frames(22, 34, 70, 67); }),
            "start_decel = 70: must be in [end_accel, stop] = [34, 67]");
  EXPECT_EQ(message_of([] { (void)cbm::parabolic_ease<double>::from_frames(22, 34, 50, 22); }),
            "stop = 22 <= start = 22: the move must end after it starts");
  EXPECT_EQ(message_of([] {
              cbm::distance_keys_ease<double>(V{0, 0.5, 1}, V{0, 0.5, 0.75});
            }),
            "distances[2] = 0.75: S(1) must be 1");
  EXPECT_EQ(message_of([] {
              cbm::distance_keys_ease<double>(V{0, 0.25, 0.5, 1}, V{0, 0.5, 0.25, 1});
            }),
            "distances must be non-decreasing: distances[2] = 0.25 < distances[1] = 0.5 (a distance-time function "
            "must not run backwards)");
  EXPECT_EQ(message_of([] {
              cbm::distance_keys_ease<double>(V{0, 0.5, 1}, V{0, 1.5, 1});
            }),
            "distances[1] = 1.5: must be in [0, 1]");
  EXPECT_EQ(message_of([] {
              cbm::distance_keys_ease<double>(V{0, -0.5, 1}, V{0, 0.5, 1});
            }),
            "times[1] = -0.5: must be in [0, 1]");
  EXPECT_EQ(message_of([] {
              cbm::distance_keys_ease<double>(V{0.25, 0.5, 1}, V{0, 0.5, 1});
            }),
            "times[0] = 0.25: the first key must be at t = 0");
  EXPECT_EQ(message_of([] {
              cbm::distance_keys_ease<double>(V{0, 0.5, 0.75}, V{0, 0.5, 1});
            }),
            "times[2] = 0.75: the last key must be at t = 1");
  EXPECT_EQ(message_of([] {
              cbm::distance_keys_ease<double>(V{0, 0.5, 0.5, 1}, V{0, 0.5, 0.5, 1});
            }),
            "times must be increasing: times[2] = 0.5 <= times[1] = 0.5");
  EXPECT_EQ(message_of([] {
              cbm::distance_keys_ease<double>(V{0, 1}, V{0, 0.5, 1});
            }),
            "distances: 3 given, must match times: 2");
  EXPECT_EQ(message_of([] {
              cbm::speed_curve_ease<double>(V{0, 0.5, 1}, V{1, -1, 1});
            }),
            "speeds[1] = -1: must be >= 0 (a negative speed would run the motion backwards)");
  EXPECT_EQ(message_of([] {
              cbm::speed_curve_ease<double>(V{0, 1}, V{0, 0});
            }),
            "speeds: all zero, at least one must be > 0 (the motion must cover the path)");
  EXPECT_EQ(message_of([] { (void)cbm::sine_ease<double>{}.derivative(0.5, 3); }),
            "order = 3: distance-time functions provide orders 0 (distance), 1 (velocity) and 2 (acceleration)");
  EXPECT_EQ(message_of([] { (void)cbm::sine_ease<double>{}.derivative(0.5, -1); }),
            "order = -1: derivative order must be >= 0");
  try {
    (void)cbm::smoothstep_ease<double>{}(1.5);
    FAIL();
  } catch (const std::domain_error& e) {
    EXPECT_THAT(e.what(), HasSubstr("1.5 is outside the domain [0, 1]"));
  }
}
