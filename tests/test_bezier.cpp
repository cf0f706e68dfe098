// Bezier curves: the three evaluation algorithms against the real50 de Casteljau reference,
// derivatives against the 50-digit Bernstein-derivative sum, and the curve properties.
#include "support/accuracy.hpp"

#include "curvebench/basis/bernstein.hpp"
#include "curvebench/curves/bezier.hpp"

#include <gmock/gmock.h>

#include <random>
#include <vector>

namespace cb = curvebench;
namespace cbt = curvebench::testing;

namespace {

static_assert(cb::curve<cb::bezier<double, 2>>);
static_assert(cb::curve<cb::bezier<cb::real50, 3>>);

template <class Real>
class bezier_test : public ::testing::Test {};
TYPED_TEST_SUITE(bezier_test, cbt::all_reals);

template <class Real, int Dim>
cb::point_list<Real, Dim> random_points(int count, unsigned seed) {
  std::mt19937 gen(seed);
  std::uniform_real_distribution<double> dist(-1.0, 1.0);
  cb::point_list<Real, Dim> p(static_cast<std::size_t>(count));
  for (auto& q : p)
    for (int d = 0; d < Dim; ++d) q[d] = static_cast<Real>(dist(gen));
  return p;
}

}  // namespace

TYPED_TEST(bezier_test, endpoints_interpolate) {
  using Real = TypeParam;
  const auto p = random_points<Real, 2>(8, 1);
  const cb::bezier<Real, 2> c(p, {Real(-1), Real(2)});
  for (auto a : {cb::bezier_algorithm::de_casteljau, cb::bezier_algorithm::bernstein_sum}) {
    EXPECT_EQ(c.evaluate(Real(-1), a), p.front());
    EXPECT_EQ(c.evaluate(Real(2), a), p.back());
  }
}

namespace {

template <class Real, int Dim>
cb::point_list<cb::real50, Dim> to50(const cb::point_list<Real, Dim>& p) {
  return cb::points_cast<cb::real50>(std::span<const cb::point<Real, Dim>>(p));
}

template <int Dim>
cb::real50 max_abs(const cb::point_list<cb::real50, Dim>& p) {
  using std::abs;
  cb::real50 m(0);
  for (const auto& q : p)
    for (int d = 0; d < Dim; ++d) m = std::max(m, cb::real50(abs(q[d])));
  return m;
}

// Max error of one algorithm over `count` parameters spread over the domain, in eps(Real) units of
// the control-point scale, against the real50 de Casteljau of the same (exactly converted) points.
template <class Real, int Dim>
double max_error_ulps(const cb::bezier<Real, Dim>& c, cb::bezier_algorithm a, int order, int count) {
  const cb::bezier<cb::real50, Dim> ref(to50(cb::point_list<Real, Dim>(c.control_points().begin(),
                                                                       c.control_points().end())),
                                        {cb::real50(c.domain().lo), cb::real50(c.domain().hi)});
  const auto dps = ref.derivative_control_points(std::min(order, ref.degree()));
  const cb::real50 scale = max_abs<Dim>(cb::point_list<cb::real50, Dim>(dps.begin(), dps.end()));
  double worst = 0;
  for (int k = 0; k < count; ++k) {
    const Real u = c.domain().lo + (c.domain().hi - c.domain().lo) * Real(k) / Real(count - 1);
    const cb::point<Real, Dim> got = c.derivative(u, order, a);
    const cb::point<cb::real50, Dim> want = ref.derivative(cb::real50(u), order);
    for (int d = 0; d < Dim; ++d)
      worst = std::max(worst, static_cast<double>(cbt::scaled_ulps(got[d], want[d], scale)));
  }
  return worst;
}

}  // namespace

TEST(bezier_measure, degree_20_error_by_algorithm) {
  for (int deg : {3, 7, 20}) {
    const auto pf = random_points<float, 2>(deg + 1, 7);
    const auto pd = random_points<double, 2>(deg + 1, 7);
    const auto pl = random_points<long double, 2>(deg + 1, 7);
    const cb::bezier<float, 2> cf(pf);
    const cb::bezier<double, 2> cd(pd);
    const cb::bezier<long double, 2> cl(pl);
    for (auto a : {cb::bezier_algorithm::de_casteljau, cb::bezier_algorithm::bernstein_sum,
                   cb::bezier_algorithm::horner})
      for (int order : {0, 1, 2})
        std::cout << "degree " << deg << " " << cb::to_string(a) << " order " << order << ": float "
                  << max_error_ulps(cf, a, order, 1000) << " double " << max_error_ulps(cd, a, order, 1000)
                  << " long double " << max_error_ulps(cl, a, order, 1000) << "\n";
  }
}
