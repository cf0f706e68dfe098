// Cross-checks of the cubic families against independent implementations in Boost.Math:
//   - boost::math::catmull_rom (Barry-Goldman pyramid) vs cardinal_spline with s = 1/2;
//   - boost::math::interpolators::cubic_hermite vs hermite_spline;
//   - boost::math::interpolators::cardinal_cubic_b_spline with given end derivatives vs the
//     clamped natural_cubic_spline.
// Same inputs, agreement to the tolerances below, in double, long double and real50.
//
// How Boost's catmull_rom conventions map onto ours (read from boost/math/interpolators/catmull_rom.hpp):
//   - parameter: Boost's s starts at 0 at points[0] and grows by |P_{i+1} - P_i|^alpha: exactly our
//     alpha_knots, so the parameters are the same numbers (parameter_at_point(i) == knots[i]);
//   - end handling: Boost ALWAYS wraps around: the neighbour before P_0 is P_{n-1} and the one after
//     P_{n-1} is P_0, whether `closed` or not. `closed = true` adds the segment P_{n-1} -> P_0, which
//     is our cardinal_end::closed with the same alpha (the whole loop). `closed = false` stops at
//     P_{n-1} but keeps the wrapped end tangents, which is our closed loop restricted to
//     [0, u_{n-1}], or equivalently our open spline with cardinal_end::given_tangents set to the
//     closed loop's slopes at P_0 and P_{n-1} (both are checked);
//   - the curve itself: Barry-Goldman's non-uniform Catmull-Rom has, at P_i, the derivative of the
//     parabola through P_{i-1}, P_i, P_{i+1} (D_{i-1} + D_i - (P_{i+1} - P_{i-1})/(h_{i-1} + h_i) equals
//     (h_i D_{i-1} + h_{i-1} D_i)/(h_{i-1} + h_i)), i.e. our cardinal slopes with s = 1/2. Boost's
//     `prime` should be dP/ds, our derivative(u, 1) with u = s, but in Boost 1.74 it is not the
//     derivative of Boost's own curve (pinned below), so derivatives are compared with a
//     high-order finite difference of Boost's real50 operator() instead.
// cubic_hermite: x, y, dy/dx per knot: our knots, values and slopes per unit of the global
// parameter (Dim = 1). cardinal_cubic_b_spline(f, n, t0, h, f'(t0), f'(tn)): uniform knots t0 + i h,
// interpolation plus the two end derivatives, i.e. our clamped C2 spline on those knots.
#include "support/accuracy.hpp"

#include "curvebench/curves/cardinal_spline.hpp"
#include "curvebench/curves/hermite_spline.hpp"
#include "curvebench/curves/natural_cubic_spline.hpp"

#include <boost/math/interpolators/cardinal_cubic_b_spline.hpp>
#include <boost/math/interpolators/catmull_rom.hpp>
#include <boost/math/interpolators/cubic_hermite.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace cb = curvebench;
namespace cbt = curvebench::testing;

namespace {

// Tolerances, eps(Real) times the data scale (coordinates <= 4):
// - catmull_rom_ulps: Boost evaluates a 3-level pyramid of affine combinations whose weights are
//   ratios of knot differences (each level can amplify rounding by (s_{i+2} - s_{i-1})/h ~ 4 with
//   these chords); ours rounds ~10 times. Derivatives additionally divide by h (>= 0.5 here, and
//   for alpha = 1/2 the knots are square roots, rounded once). 256 covers both sides with margin.
// - hermite_ulps: both evaluate the same cubic from the same data with ~10 roundings each: 32.
// - bspline_ulps: Boost solves for B-spline coefficients (Thomas, after subtracting the mean),
//   we solve for slopes; both well conditioned: 64 for values, x4 for the first derivative (1/h).
constexpr double catmull_rom_ulps = 256;
constexpr double hermite_ulps = 32;
constexpr double bspline_ulps = 64;

template <class Real>
class peers_test : public ::testing::Test {};
TYPED_TEST_SUITE(peers_test, cbt::all_reals);
// Boost's catmull_rom is instantiated twice per type (Real and the real50 reference); float is left
// out to keep this file's compile time down: it exercises no code path that double does not.
template <class Real>
class catmull_rom_peer_test : public ::testing::Test {};
using catmull_rom_reals = ::testing::Types<double, long double, cb::real50>;
TYPED_TEST_SUITE(catmull_rom_peer_test, catmull_rom_reals);

const std::vector<std::array<double, 2>> pd{{0.0, 0.0},  {1.0, 2.0},  {3.0, 2.5}, {3.5, 0.5},
                                            {2.0, -1.0}, {4.0, -2.0}, {1.0, -3.0}};

}  // namespace

// dP/ds of a Boost catmull_rom<real50> by a fourth-order central difference of its operator()
// (step 1e-10: truncation ~1e-40, rounding ~1e-40 relative): the derivative reference, because
// Boost 1.74's own `prime` does not differentiate its operator() (see the pinned test below).
template <class BoostCurve>
cb::point<cb::real50, 2> boost_derivative50(const BoostCurve& c, const cb::real50& s) {
  const cb::real50 d("1e-10");
  const auto f = [&](const cb::real50& x) {
    const auto v = c(x);
    return cb::point<cb::real50, 2>(v[0], v[1]);
  };
  return cb::point<cb::real50, 2>((f(s - 2 * d) - 8 * f(s - d) + 8 * f(s + d) - f(s + 2 * d)) / (12 * d));
}

TYPED_TEST(catmull_rom_peer_test, boost_catmull_rom_open_and_closed) {
  using Real = TypeParam;
  using bpoint = std::array<Real, 2>;
  using bpoint50 = std::array<cb::real50, 2>;
  cb::point_list<Real, 2> p;
  for (auto& q : pd) p.push_back(cb::point<Real, 2>(Real(q[0]), Real(q[1])));
  // The derivative reference is good to ~1e-40 relative (finite difference), which is below
  // eps(Real) * 256 for the IEEE types but not for real50: there the bound is 1e-36 of the scale.
  const double derivative_ulps = std::max(catmull_rom_ulps, 1e-36 / static_cast<double>(cb::epsilon<Real>()));
  for (double alpha : {0.0, 0.5, 1.0}) {
    std::vector<bpoint> bp;
    std::vector<bpoint50> bp50;
    for (auto& q : pd) {
      bp.push_back({Real(q[0]), Real(q[1])});
      bp50.push_back({cb::real50(Real(q[0])), cb::real50(Real(q[1]))});
    }
    std::vector<bpoint> bp2 = bp;
    std::vector<bpoint50> bp50b = bp50;
    const boost::math::catmull_rom<bpoint> open(std::move(bp), false, Real(alpha));
    const boost::math::catmull_rom<bpoint> closed(std::move(bp2), true, Real(alpha));
    const boost::math::catmull_rom<bpoint50> open50(std::move(bp50), false, cb::real50(Real(alpha)));
    const boost::math::catmull_rom<bpoint50> closed50(std::move(bp50b), true, cb::real50(Real(alpha)));
    typename cb::cardinal_spline<Real, 2>::options opt;
    opt.alpha = Real(alpha);
    opt.end = cb::cardinal_end::closed;
    const cb::cardinal_spline<Real, 2> loop(p, opt);
    // The open Boost curve = our open spline with the wrapped end tangents given.
    typename cb::cardinal_spline<Real, 2>::options given = opt;
    given.end = cb::cardinal_end::given_tangents;
    given.start_tangent = loop.slopes().front();
    given.end_tangent = loop.slopes()[p.size() - 1];
    const cb::cardinal_spline<Real, 2> open_ours(p, given);
    // Same parameter values.
    for (std::size_t i = 0; i < p.size(); ++i)
      ASSERT_TRUE(cbt::within_ulps(loop.breakpoints()[i], cb::real50(open.parameter_at_point(i)), 4)) << i;
    ASSERT_TRUE(cbt::within_ulps(loop.domain().hi, cb::real50(closed.max_parameter()), 8));
    const int samples = 96;
    const cb::real50 margin("1e-9");
    for (int k = 0; k < samples; ++k) {
      // Bin midpoints: never on a knot for alpha = 0 (7 (2k + 1)/192 is not an integer).
      const Real s = closed.max_parameter() * Real(2 * k + 1) / Real(2 * samples);
      const bpoint bv = closed(s);
      const auto v = loop(s);
      const auto& e = loop.engine();
      const std::size_t seg = e.segment_index(s);
      // The finite difference needs s +- 2e-10 inside one segment.
      const bool smooth_here = cb::real50(e.knots()[seg]) + margin < cb::real50(s) &&
                               cb::real50(s) + margin < cb::real50(e.knots()[seg + 1]);
      for (int c = 0; c < 2; ++c)
        ASSERT_TRUE(
            cbt::within_scaled_ulps(v[c], cb::real50(bv[static_cast<std::size_t>(c)]), cb::real50(4), catmull_rom_ulps))
            << "closed alpha=" << alpha << " s=" << s;
      if (smooth_here) {
        ASSERT_TRUE(cbt::point_within(loop.derivative(s, 1), boost_derivative50(closed50, cb::real50(s)),
                                      cb::real50(16), derivative_ulps))
            << "closed alpha=" << alpha << " s=" << s;
      }
      if (s <= open.max_parameter()) {
        const bpoint ov = open(s);
        const auto w = open_ours(s);
        for (int c = 0; c < 2; ++c)
          ASSERT_TRUE(cbt::within_scaled_ulps(w[c], cb::real50(ov[static_cast<std::size_t>(c)]), cb::real50(4),
                                              catmull_rom_ulps))
              << "open alpha=" << alpha << " s=" << s;
        if (smooth_here && s + Real(1e-3) < open.max_parameter()) {
          ASSERT_TRUE(cbt::point_within(open_ours.derivative(s, 1), boost_derivative50(open50, cb::real50(s)),
                                        cb::real50(16), derivative_ulps))
              << "open alpha=" << alpha << " s=" << s;
        }
      }
    }
  }
}

#if BOOST_VERSION <= 107400
TEST(peers, boost_1_74_catmull_rom_prime_is_not_the_derivative_of_its_value) {
  // Pinned peer defect: in Boost 1.74 catmull_rom::prime blends A1 and A2 with the weights of
  // [s_i, s_{i+1}] instead of [s_{i-1}, s_{i+1}] when forming B1, so it disagrees with the
  // derivative of its own operator() (here by ~0.07 at s = 0.073 on uniform knots). Our cardinal
  // spline agrees with the differentiated operator() (test above); this test documents why Boost's
  // prime is not used as the reference and fails if a newer Boost fixes it.
  using bp = std::array<double, 2>;
  std::vector<bp> v;
  for (auto& q : pd) v.push_back({q[0], q[1]});
  const boost::math::catmull_rom<bp> c(std::move(v), true, 0.0);
  const double s = 0.073, d = 1e-6;
  const double fd = (c(s + d)[0] - c(s - d)[0]) / (2 * d);
  EXPECT_GT(std::abs(c.prime(s)[0] - fd), 1e-2);
}
#endif

TYPED_TEST(peers_test, boost_cubic_hermite) {
  using Real = TypeParam;
  const std::vector<double> x{-1.0, -0.25, 0.5, 1.25, 1.5, 3.0};
  const std::vector<double> y{0.5, 2.0, -1.0, 0.25, 1.0, -2.0};
  const std::vector<double> dy{1.0, -3.0, 0.5, 4.0, -1.0, 0.0};
  std::vector<Real> bx(x.begin(), x.end()), by(y.begin(), y.end()), bd(dy.begin(), dy.end());
  const boost::math::interpolators::cubic_hermite<std::vector<Real>> peer(std::move(bx), std::move(by), std::move(bd));
  cb::point_list<Real, 1> v, s;
  for (std::size_t i = 0; i < x.size(); ++i) {
    v.push_back(cb::point<Real, 1>(Real(y[i])));
    s.push_back(cb::point<Real, 1>(Real(dy[i])));
  }
  const cb::hermite_spline<Real, 1> ours(std::vector<Real>(x.begin(), x.end()), v, s);
  for (int k = 0; k <= 128; ++k) {
    const Real u = Real(-1) + Real(4) * Real(k) / Real(128);
    ASSERT_TRUE(cbt::within_scaled_ulps(ours(u)[0], cb::real50(peer(u)), cb::real50(4), hermite_ulps)) << k;
    ASSERT_TRUE(
        cbt::within_scaled_ulps(ours.derivative(u, 1)[0], cb::real50(peer.prime(u)), cb::real50(16), hermite_ulps))
        << k;
  }
}

TYPED_TEST(peers_test, boost_cardinal_cubic_b_spline_with_end_derivatives_is_the_clamped_spline) {
  using Real = TypeParam;
  const std::vector<double> f{0.5, 2.0, -1.0, 0.25, 1.0, -2.0, 0.0, 1.5};
  const Real t0(-1), h(0.5), d0(1.5), d1(-0.75);
  std::vector<Real> fr(f.begin(), f.end());
  const boost::math::interpolators::cardinal_cubic_b_spline<Real> peer(fr.data(), fr.size(), t0, h, d0, d1);
  cb::point_list<Real, 1> v;
  for (double q : f) v.push_back(cb::point<Real, 1>(Real(q)));
  const cb::natural_cubic_spline<Real, 1> ours(cb::uniform_knots<Real>(f.size() - 1, t0, h), v, cb::point<Real, 1>(d0),
                                               cb::point<Real, 1>(d1));
  const Real hi = t0 + h * Real(static_cast<long long>(f.size() - 1));
  for (int k = 0; k <= 112; ++k) {
    const Real u = t0 + (hi - t0) * Real(k) / Real(112);
    ASSERT_TRUE(cbt::within_scaled_ulps(ours(u)[0], cb::real50(peer(u)), cb::real50(4), bspline_ulps)) << k;
    ASSERT_TRUE(
        cbt::within_scaled_ulps(ours.derivative(u, 1)[0], cb::real50(peer.prime(u)), cb::real50(16), bspline_ulps))
        << k;
  }
}
