// B-splines against peers: Eigen's unsupported Spline module (evaluation and derivatives on the
// same knots and control points) and Boost.Math's cardinal_cubic_b_spline (a cubic B-spline that
// interpolates uniformly spaced data, rebuilt here as a curvebench::bspline).
#include "support/accuracy.hpp"

#include "curvebench/curves/bspline.hpp"

#include <Eigen/Dense>
#include <boost/math/interpolators/cardinal_cubic_b_spline.hpp>
#include <unsupported/Eigen/Splines>

#include <cmath>
#include <iostream>
#include <random>
#include <vector>

namespace cb = curvebench;
namespace cbt = curvebench::testing;

namespace {

// Tolerances (double), in eps times max |control point| (values) or times the derivative scale:
// - both libraries evaluate the same piecewise polynomial exactly up to rounding; each carries
//   ~4m ulps of the control scale for values (de Boor here, the triangular basis of Piegl & Tiller
//   A2.2 in Eigen), so they agree to 8m;
// - derivatives of order r: Eigen differentiates the basis (A2.3), we difference the control
//   points; both scale by up to (m / hmin) per order with ~2 roundings per level:
//   16m (2m / hmin)^r ulps of the control scale;
// - Boost's cardinal spline solves its own tridiagonal system in double (diagonally dominant,
//   condition <= 3): its coefficients are within ~N ulps of the 50-digit solution; value error
//   ~ (N + 8) ulps of max |data|, first / second derivative the same divided by h / h^2 (~4 / h^r
//   more roundings): 64 / h^r ulps of max |data| with N = 12.
double eigen_value_ulps(int m) { return 8.0 * m; }
double eigen_derivative_ulps(int m, int r, double hmin) {
  double f = 16.0 * m;
  for (int j = 0; j < r; ++j) f *= 2.0 * m / hmin;
  return f;
}
double boost_ulps(int r, double h) { return 64.0 / std::pow(h, r); }

// Mapping to Eigen: Eigen::Spline<Scalar, Dim> stores the knot vector U (n + p + 1 values, p the
// degree) and the control points as columns. That is exactly our knot vector for order m = p + 1
// and n control points, and Eigen's span search (Piegl & Tiller A2.1, upper_bound on U[p-1 ..
// n]) evaluates on the same domain [t_p, t_n] = [t_{m-1}, t_n] with the same half-open spans and
// the same last-span rule at the right end, so no parameter change is needed.
using eigen_spline = Eigen::Spline<double, 2>;

eigen_spline to_eigen(const cb::bspline<double, 2>& c) {
  Eigen::Array<double, 1, Eigen::Dynamic> knots(static_cast<Eigen::Index>(c.knots().size()));
  for (std::size_t i = 0; i < c.knots().size(); ++i) knots(static_cast<Eigen::Index>(i)) = c.knots()[i];
  Eigen::Array<double, 2, Eigen::Dynamic> ctrl(2, static_cast<Eigen::Index>(c.control_points().size()));
  for (std::size_t i = 0; i < c.control_points().size(); ++i) {
    ctrl(0, static_cast<Eigen::Index>(i)) = c.control_points()[i][0];
    ctrl(1, static_cast<Eigen::Index>(i)) = c.control_points()[i][1];
  }
  return eigen_spline(knots, ctrl);
}

}  // namespace

TEST(bspline_peers, eigen_spline_values_and_derivatives) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> coord(-2, 2);
  std::uniform_real_distribution<double> gap(0.25, 1.5);
  double worst_value = 0, worst_first = 0;  // measured agreement, eps * 2 (the control scale)
  for (int m = 2; m <= 6; ++m) {
    for (bool clamped : {false, true}) {
      const std::size_t n = static_cast<std::size_t>(m) + 6;
      std::vector<double> t;
      double hmin = 1e300;
      if (clamped) {
        std::vector<double> br{0};
        for (std::size_t j = 0; j + static_cast<std::size_t>(m) <= n; ++j) br.push_back(br.back() + gap(rng));
        for (std::size_t j = 1; j < br.size(); ++j) hmin = std::min(hmin, br[j] - br[j - 1]);
        t = cb::bspline_clamped_knots<double>(std::span<const double>(br), m);
      } else {
        t.push_back(-1);
        for (std::size_t j = 1; j < n + static_cast<std::size_t>(m); ++j) {
          t.push_back(t.back() + gap(rng));
          hmin = std::min(hmin, t.back() - t[j - 1]);
        }
      }
      cb::point_list<double, 2> p(n);
      for (auto& q : p) q = cb::point<double, 2>(coord(rng), coord(rng));
      const cb::bspline<double, 2> c(m, t, p);
      const eigen_spline e = to_eigen(c);
      ASSERT_EQ(e.degree(), m - 1);
      const auto dom = c.domain();
      for (int s = 0; s <= 100; ++s) {
        const double u = s == 100 ? dom.hi : dom.lo + (dom.hi - dom.lo) * s / 100.0;
        const Eigen::Array<double, 2, Eigen::Dynamic> d = e.derivatives(u, m - 1);
        for (int r = 0; r < m; ++r) {
          const cb::point<double, 2> ours = c.derivative(u, r);
          const cb::point<cb::real50, 2> theirs(d(0, r), d(1, r));
          const double tol = r == 0 ? eigen_value_ulps(m) : eigen_derivative_ulps(m, r, hmin);
          ASSERT_TRUE(cbt::point_within(ours, theirs, cb::real50(2), tol))
              << "m=" << m << " clamped=" << clamped << " u=" << u << " r=" << r;
          if (r <= 1)
            for (int dd = 0; dd < 2; ++dd) {
              const double ul = static_cast<double>(cbt::scaled_ulps(ours[dd], theirs[dd], cb::real50(2)));
              (r == 0 ? worst_value : worst_first) = std::max(r == 0 ? worst_value : worst_first, ul);
            }
        }
        const Eigen::Array<double, 2, 1> v = e(u);
        ASSERT_TRUE(cbt::point_within(c(u), cb::point<cb::real50, 2>(v(0), v(1)), cb::real50(2), eigen_value_ulps(m)));
      }
    }
  }
  std::cout << "[ measured ] curvebench vs Eigen Spline, orders 2..6: values within " << worst_value
            << " eps*scale, first derivatives within " << worst_first << " eps*scale\n";
}

// Boost's cardinal_cubic_b_spline(f, N, t0, h, f'(t0), f'(t_{N-1})) is the cubic spline on the
// uniform grid t_i = t0 + i h interpolating f_i with the given end slopes, written as
// S(t) = sum_{k=-1..N} a_k B3((t - t0)/h - k), B3 the centred cubic B-spline (support [-2, 2]).
// Mapping: B3(x - k) is our order-4 basis function on the uniform knots t0 + (k-2) h .. t0 + (k+2) h,
// so S is cb::bspline(4, knots t0 + (j - 3) h for j = 0..N+5, control a_{-1} .. a_N), with domain
// [t0, t0 + (N-1) h]. The coefficients solve (from B3(0) = 2/3, B3(+-1) = 1/6, B3'(+-1) = -+1/2):
//   (a_{i-1} + 4 a_i + a_{i+1}) / 6 = f_i,  (a_1 - a_{-1}) / (2h) = f'(t0),  (a_N - a_{N-2}) / (2h) = f'(t_{N-1}).
// We solve that system in 50 digits (dense LU), build the B-spline in real50 (reference) and in
// double (coefficients rounded), and check Boost and ours against the reference.
TEST(bspline_peers, boost_cardinal_cubic_b_spline) {
  const int N = 12;
  const double t0 = -0.5, h = 0.375;
  auto f = [](double x) { return std::sin(2 * x) + 0.25 * x * x; };
  auto fp = [](double x) { return 2 * std::cos(2 * x) + 0.5 * x; };
  std::vector<double> y(N);
  double ymax = 0;
  for (int i = 0; i < N; ++i) {
    y[static_cast<std::size_t>(i)] = f(t0 + i * h);
    ymax = std::max(ymax, std::abs(y[static_cast<std::size_t>(i)]));
  }
  const double d0 = fp(t0), d1 = fp(t0 + (N - 1) * h);
  const boost::math::interpolators::cardinal_cubic_b_spline<double> spline(y.data(), y.size(), t0, h, d0, d1);

  using mat50 = Eigen::Matrix<cb::real50, Eigen::Dynamic, Eigen::Dynamic>;
  using vec50 = Eigen::Matrix<cb::real50, Eigen::Dynamic, 1>;
  const int M = N + 2;  // unknowns a_{-1} .. a_N at index k + 1
  mat50 A = mat50::Zero(M, M);
  vec50 rhs(M);
  const cb::real50 h50(h);
  A(0, 0) = cb::real50(-1) / (2 * h50);
  A(0, 2) = cb::real50(1) / (2 * h50);
  rhs(0) = cb::real50(d0);
  for (int i = 0; i < N; ++i) {
    A(i + 1, i) = cb::real50(1) / 6;
    A(i + 1, i + 1) = cb::real50(4) / 6;
    A(i + 1, i + 2) = cb::real50(1) / 6;
    rhs(i + 1) = cb::real50(y[static_cast<std::size_t>(i)]);
  }
  A(M - 1, M - 3) = cb::real50(-1) / (2 * h50);
  A(M - 1, M - 1) = cb::real50(1) / (2 * h50);
  rhs(M - 1) = cb::real50(d1);
  const vec50 a = A.fullPivLu().solve(rhs);

  std::vector<cb::real50> k50;
  std::vector<double> kd;
  for (int j = 0; j < M + 4; ++j) {
    k50.push_back(cb::real50(t0) + cb::real50(j - 3) * h50);
    kd.push_back(t0 + (j - 3) * h);  // exact: t0 and h are short dyadic numbers
  }
  cb::point_list<cb::real50, 1> c50;
  cb::point_list<double, 1> cd;
  for (int k = 0; k < M; ++k) {
    c50.emplace_back(a(k));
    cd.emplace_back(static_cast<double>(a(k)));
  }
  const cb::bspline<cb::real50, 1> ref(4, k50, c50);
  const cb::bspline<double, 1> ours(4, kd, cd);
  ASSERT_EQ(ours.domain().lo, t0);
  ASSERT_EQ(ours.domain().hi, t0 + (N - 1) * h);
  // The reference interpolates the data (a check of the system above).
  for (int i = 0; i < N; ++i)
    ASSERT_TRUE(cbt::within_scaled_ulps(static_cast<double>(ref(cb::real50(kd[static_cast<std::size_t>(i) + 3]))[0]),
                                        cb::real50(y[static_cast<std::size_t>(i)]), cb::real50(ymax), 1));
  double worst[2][3] = {{0, 0, 0}, {0, 0, 0}};  // [Boost, ours][order], eps * max |data|
  for (int s = 0; s <= 220; ++s) {
    const double u = t0 + (N - 1) * h * s / 220.0;
    const cb::real50 u50(u);
    const double theirs[3] = {spline(u), spline.prime(u), spline.double_prime(u)};
    for (int r = 0; r <= 2; ++r) {
      const cb::real50 want = ref.derivative(u50, r)[0];
      ASSERT_TRUE(cbt::within_scaled_ulps(theirs[r], want, cb::real50(ymax), boost_ulps(r, h)))
          << "Boost, u=" << u << " r=" << r;
      ASSERT_TRUE(cbt::within_scaled_ulps(ours.derivative(u, r)[0], want, cb::real50(ymax), boost_ulps(r, h)))
          << "ours, u=" << u << " r=" << r;
      worst[0][r] = std::max(worst[0][r], static_cast<double>(cbt::scaled_ulps(theirs[r], want, cb::real50(ymax))));
      worst[1][r] = std::max(worst[1][r],
                             static_cast<double>(cbt::scaled_ulps(ours.derivative(u, r)[0], want, cb::real50(ymax))));
    }
  }
  std::cout
      << "[ measured ] vs the 50-digit cardinal cubic B-spline (eps * max|f|), value / first / second derivative: "
      << "Boost " << worst[0][0] << " / " << worst[0][1] << " / " << worst[0][2] << ", curvebench " << worst[1][0]
      << " / " << worst[1][1] << " / " << worst[1][2] << "\n";
}
