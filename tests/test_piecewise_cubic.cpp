// piecewise_cubic engine: the three algorithms (power/Horner, matrix T·M·G, Bezier/de Casteljau)
// against a closed-form cubic and against the real50 instantiation of the same data, chain rule
// for derivatives, segment lookup (uniform O(1) path and binary search), batched and sorted
// evaluation, continuity of Hermite assembly, and bad input.
#include "support/accuracy.hpp"

#include "curvebench/curves/piecewise_cubic.hpp"

#include <gmock/gmock.h>

#include <array>
#include <cmath>
#include <limits>
#include <vector>

namespace cb = curvebench;
namespace cbt = curvebench::testing;
using ::testing::HasSubstr;

namespace {

// Tolerances, in eps(Real) times a scale (see `data_scale` below):
// - algorithm_ulps: each algorithm rounds ~10 times (Hermite -> power or Bezier conversion: <= 3
//   additions of items of size <= scale; evaluation: 3 fma-like steps or 6 lerps; T·M: 4 products
//   per blend). Derivatives of order k are divided by h^k and their error by the same factor; the
//   scale below carries that factor. 32 leaves a 3x margin over the worst observed.
// - reproduction_ulps50: the real50 engine against the closed-form cubic: the same ~10 roundings at
//   50 digits, measured in eps(real50) units of the scale.
constexpr double algorithm_ulps = 32;
constexpr double reproduction_ulps50 = 32;

template <class Real>
class engine_test : public ::testing::Test {};
TYPED_TEST_SUITE(engine_test, cbt::all_reals);

// A global cubic q(u) = c0 + c1 u + c2 u^2 + c3 u^3 per coordinate (closed form, evaluated in real50).
using cubic2 = std::array<std::array<double, 4>, 2>;
const cubic2 q_coeffs{{{0.75, -1.5, 2.0, 0.625}, {-2.0, 0.5, -3.25, 1.125}}};

cb::point<cb::real50, 2> q_derivative(const cb::real50& u, int order) {
  cb::point<cb::real50, 2> p;
  for (int d = 0; d < 2; ++d) {
    cb::real50 s(0);
    for (int k = order; k < 4; ++k) {
      cb::real50 f(q_coeffs[static_cast<std::size_t>(d)][static_cast<std::size_t>(k)]);
      for (int j = 0; j < order; ++j) f *= cb::real50(k - j);
      for (int j = 0; j < k - order; ++j) f *= u;
      s += f;
    }
    p[d] = s;
  }
  return p;
}

// Non-uniform dyadic knots (exact in every type).
const std::vector<double> knots_d{-1.0, -0.5, 0.25, 0.5, 1.25, 2.0};

// Hermite data of q at the knots, computed in real50 and rounded to Real.
template <class Real>
struct hermite_data {
  std::vector<Real> knots;
  cb::point_list<Real, 2> values, slopes;
};

template <class Real>
hermite_data<Real> q_data() {
  hermite_data<Real> h;
  for (double u : knots_d) {
    h.knots.push_back(Real(u));
    h.values.push_back(cb::point_cast<Real>(q_derivative(cb::real50(u), 0)));
    h.slopes.push_back(cb::point_cast<Real>(q_derivative(cb::real50(u), 1)));
  }
  return h;
}

template <class Real>
cb::piecewise_cubic<Real, 2> q_engine(const hermite_data<Real>& h) {
  return cb::piecewise_cubic<Real, 2>::from_hermite(h.knots, h.values, h.slopes, h.slopes);
}

// Scale of the data for derivative order k: (max |value| + max h |slope|) / h_min^k. The engine's
// geometry items have size <= max|value| + max h|slope|, and order k divides by h^k.
cb::real50 data_scale(int order) {
  cb::real50 vmax(0), tmax(0);
  using std::abs;
  for (double u : knots_d) {
    auto v = q_derivative(cb::real50(u), 0);
    auto s = q_derivative(cb::real50(u), 1);
    for (int d = 0; d < 2; ++d) {
      vmax = std::max(vmax, cb::real50(abs(v[d])));
      tmax = std::max(tmax, cb::real50(abs(s[d])));
    }
  }
  cb::real50 s = vmax + cb::real50(0.75) * tmax;  // max h = 0.75
  for (int k = 0; k < std::min(order, 3); ++k) s /= cb::real50(0.25);  // min h = 0.25
  return s;
}

constexpr std::array<cb::cubic_algorithm, 3> algorithms{cb::cubic_algorithm::power, cb::cubic_algorithm::matrix,
                                                        cb::cubic_algorithm::bezier};

}  // namespace

static_assert(cb::curve<cb::piecewise_cubic<double, 1>>);
static_assert(cb::curve<cb::piecewise_cubic<float, 3>>);
static_assert(cb::curve<cb::piecewise_cubic<cb::real50, 2>>);

TYPED_TEST(engine_test, algorithms_agree_with_real50_reference_of_same_data) {
  using Real = TypeParam;
  const auto data = q_data<Real>();
  const auto c = q_engine(data);
  // The reference: the same (rounded) data, exactly widened, in real50.
  hermite_data<cb::real50> wide;
  for (std::size_t i = 0; i < data.knots.size(); ++i) {
    wide.knots.push_back(cb::real50(data.knots[i]));
    wide.values.push_back(cb::point_cast<cb::real50>(data.values[i]));
    wide.slopes.push_back(cb::point_cast<cb::real50>(data.slopes[i]));
  }
  const auto ref = q_engine(wide);
  for (int k = 0; k <= 96; ++k) {
    const double ud = -1.0 + 3.0 * k / 96.0;
    const Real u = Real(ud);
    for (int order = 0; order <= 4; ++order) {
      const auto r = ref.evaluate(cb::real50(u), order, cb::cubic_algorithm::power);
      for (auto alg : algorithms) {
        const auto got = c.evaluate(u, order, alg);
        ASSERT_TRUE(cbt::point_within(got, r, data_scale(order), algorithm_ulps))
            << "u=" << ud << " order=" << order << " algorithm=" << cb::to_string(alg);
      }
    }
  }
}

TEST(engine_reference, real50_reproduces_the_global_cubic_with_all_algorithms) {
  // Hermite data of one global cubic -> every segment is that cubic: value and derivatives 1..3
  // are the closed form's (chain rule 1/h^k), order 4 is zero.
  const auto c = q_engine(q_data<cb::real50>());
  for (int k = 0; k <= 60; ++k) {
    const cb::real50 u = cb::real50(-1) + cb::real50(3 * k) / cb::real50(60);
    for (int order = 0; order <= 3; ++order)
      for (auto alg : algorithms)
        ASSERT_TRUE(cbt::point_within(c.evaluate(u, order, alg), q_derivative(u, order), data_scale(order),
                                      reproduction_ulps50))
            << "k=" << k << " order=" << order << " " << cb::to_string(alg);
    EXPECT_EQ(c.derivative(u, 4), (cb::point<cb::real50, 2>::Zero()));
  }
}

TEST(engine, mixed_bases_match_their_own_closed_forms) {
  // Segment 0 in Bezier form, segment 1 as a uniform B-spline segment, segment 2 as power
  // coefficients: each evaluated against its own definition (Bernstein sum, B-spline blending,
  // polynomial) at a local t, in double with a tight bound (data of size ~4, ~10 roundings).
  using geo = cb::piecewise_cubic<double, 1>::geometry_type;
  geo g0, g1, g2;
  g0 << 1.0, 3.0, -2.0, 0.5;
  g1 << 0.5, -1.0, 2.0, 4.0;
  g2 << 0.25, -1.0, 0.5, 2.0;
  std::vector<cb::basis::matrix4<double>> m{cb::basis::bezier_matrix<double>(), cb::basis::uniform_bspline_matrix<double>(),
                                            cb::basis::matrix4<double>::Identity()};
  const cb::piecewise_cubic<double, 1> c({0.0, 1.0, 3.0, 3.5}, {g0, g1, g2}, m);
  EXPECT_FALSE(c.uniform());
  // t = 1 is excluded for segments 0 and 1: u = 1 and u = 3 belong to the next segment.
  for (int k = 0; k <= 16; ++k) {
    const double t = k / 16.0;
    const double s = 1 - t;
    const double bez = s * s * s * g0(0) + 3 * s * s * t * g0(1) + 3 * s * t * t * g0(2) + t * t * t * g0(3);
    const double bsp = (s * s * s * g1(0) + (3 * t * t * t - 6 * t * t + 4) * g1(1) +
                        (-3 * t * t * t + 3 * t * t + 3 * t + 1) * g1(2) + t * t * t * g1(3)) /
                       6;
    const double pw = g2(0) + t * (g2(1) + t * (g2(2) + t * g2(3)));
    for (auto alg : algorithms) {
      if (k < 16) {
        EXPECT_NEAR(c.evaluate(t, 0, alg)[0], bez, 16 * 4 * std::numeric_limits<double>::epsilon()) << t;
        EXPECT_NEAR(c.evaluate(1.0 + 2.0 * t, 0, alg)[0], bsp, 16 * 4 * std::numeric_limits<double>::epsilon()) << t;
      }
      EXPECT_NEAR(c.evaluate(3.0 + 0.5 * t, 0, alg)[0], pw, 16 * 4 * std::numeric_limits<double>::epsilon()) << t;
    }
  }
  // The Bezier points of a Bezier segment are its geometry, exactly.
  for (int r = 0; r < 4; ++r) EXPECT_EQ(c.bezier_points(0)[static_cast<std::size_t>(r)][0], g0(r));
}

TEST(engine, segment_lookup_uniform_and_binary_search) {
  using pc = cb::piecewise_cubic<double, 1>;
  auto build = [](std::vector<double> knots) {
    std::vector<pc::geometry_type> g(knots.size() - 1, pc::geometry_type::Zero());
    return pc(std::move(knots), std::move(g), cb::basis::hermite_matrix<double>());
  };
  const pc uni = build(cb::uniform_knots<double>(10, -2.0, 0.3));
  EXPECT_TRUE(uni.uniform());
  std::vector<double> nk{0.0, 0.1, 0.5, 0.6, 2.0};
  const pc non = build(nk);
  EXPECT_FALSE(non.uniform());
  // Nearly uniform: one knot moved by one ulp -> still detected uniform, lookup still exact.
  auto near = cb::uniform_knots<double>(10, 0.0, 0.1);
  near[3] = std::nextafter(near[3], 1.0);
  const pc nea = build(near);
  EXPECT_TRUE(nea.uniform());
  for (const pc* c : {&uni, &non, &nea}) {
    const auto k = c->knots();
    for (std::size_t i = 0; i < k.size(); ++i) {
      // Exactly at a knot: the right segment (the last knot belongs to the last segment).
      EXPECT_EQ(c->segment_index(k[i]), std::min(i, k.size() - 2));
      if (i + 1 < k.size()) {
        const double before = std::nextafter(k[i + 1], k[i]);
        EXPECT_EQ(c->segment_index(before), i) << "just below knot " << i + 1;
        EXPECT_EQ(c->segment_index(0.5 * (k[i] + k[i + 1])), i);
      }
    }
  }
  EXPECT_THROW((void)uni.segment_index(std::nextafter(-2.0, -3.0)), std::domain_error);
}

TEST(engine, batch_and_sorted_paths_equal_single_evaluation) {
  const auto c = q_engine(q_data<double>());
  std::vector<double> us;
  for (int k = 0; k <= 200; ++k) us.push_back(-1.0 + 3.0 * ((k * 37) % 201) / 200.0);  // a permutation
  std::vector<double> sorted = us;
  std::sort(sorted.begin(), sorted.end());
  std::vector<cb::point<double, 2>> out(us.size()), out_sorted(us.size());
  for (int order = 0; order <= 3; ++order)
    for (auto alg : algorithms) {
      c.evaluate_batch(us, out, order, alg);
      c.evaluate_sorted(sorted, out_sorted, order, alg);
      for (std::size_t k = 0; k < us.size(); ++k) {
        // Same segment, same t, same arithmetic: bit for bit.
        ASSERT_EQ(out[k], c.evaluate(us[k], order, alg)) << k;
        ASSERT_EQ(out_sorted[k], c.evaluate(sorted[k], order, alg)) << k;
      }
    }
  std::vector<double> bad{0.0, 0.5, 0.25};
  std::vector<cb::point<double, 2>> o3(3), o2(2);
  try {
    c.evaluate_sorted(bad, o3);
    FAIL() << "unsorted input accepted";
  } catch (const cb::invalid_input& e) {
    EXPECT_THAT(e.what(), HasSubstr("us[2] = 0.25 < us[1] = 0.5"));
  }
  EXPECT_THROW(c.evaluate_batch(bad, o2), cb::invalid_input);
  std::vector<double> outside{0.0, 2.5};
  EXPECT_THROW(c.evaluate_sorted(outside, o2), std::domain_error);
  EXPECT_THROW(c.evaluate_batch(outside, o2), std::domain_error);
}

TEST(engine, batch_and_sorted_paths_reject_nan_anywhere_in_the_span) {
  // The error policy: a parameter outside the domain throws std::domain_error naming it, never a
  // silent value. A NaN fails every comparison, so a check written as "u > hi" or "u < previous"
  // lets it through; it must be caught at any index, not only at us[0], and reported by index.
  const auto c = q_engine(q_data<double>());
  const double nan = std::numeric_limits<double>::quiet_NaN();
  std::vector<double> us{-1.0, -0.5, 0.0, 0.25, 0.5, nan, 1.0, 1.5};
  std::vector<cb::point<double, 2>> out(us.size());
  for (int order : {0, 1})
    for (auto alg : algorithms) {
      try {
        c.evaluate_sorted(us, out, order, alg);
        FAIL() << "NaN at us[5] accepted by evaluate_sorted (order " << order << ", " << cb::to_string(alg) << ")";
      } catch (const std::domain_error& e) {
        EXPECT_THAT(e.what(), HasSubstr("us[5] = nan"));
        EXPECT_THAT(e.what(), HasSubstr("outside the domain [-1, 2]"));
      }
      try {
        c.evaluate_batch(us, out, order, alg);
        FAIL() << "NaN at us[5] accepted by evaluate_batch";
      } catch (const std::domain_error& e) {
        EXPECT_THAT(e.what(), HasSubstr("us[5] = nan"));
      }
    }
  // Also directly after the first element, and last.
  for (std::size_t at : {std::size_t{1}, us.size() - 1}) {
    std::vector<double> v{-1.0, -0.5, 0.0, 0.25, 0.5, 0.75, 1.0, 1.5};
    v[at] = nan;
    EXPECT_THROW(c.evaluate_sorted(v, out), std::domain_error) << "NaN at " << at;
  }
  // An unsorted span is rejected wherever the descent is (the API documents non-decreasing input).
  std::vector<double> down{-1.0, -0.5, 0.0, 0.25, 0.5, 0.4, 1.0, 1.5};
  try {
    c.evaluate_sorted(down, out);
    FAIL() << "unsorted input accepted";
  } catch (const cb::invalid_input& e) {
    EXPECT_THAT(e.what(), HasSubstr("us[5] = 0.40000000000000002 < us[4] = 0.5"));
  }
}

TEST(engine, hermite_assembly_is_c1_and_broken_slopes_break_it) {
  // Random-ish non-polynomial data: equal incoming/outgoing slopes give continuous value and first
  // derivative at every interior knot (to rounding: 8 ulps of the data scale ~ 4); different ones
  // give the requested one-sided slopes exactly as assembled.
  std::vector<double> knots{0.0, 0.3, 1.1, 1.5, 2.75};
  cb::point_list<double, 1> v{cb::point<double, 1>(1.0), cb::point<double, 1>(-2.0), cb::point<double, 1>(0.5),
                              cb::point<double, 1>(3.0), cb::point<double, 1>(0.0)};
  cb::point_list<double, 1> s{cb::point<double, 1>(0.0), cb::point<double, 1>(4.0), cb::point<double, 1>(-1.0),
                              cb::point<double, 1>(2.0), cb::point<double, 1>(1.0)};
  cb::point_list<double, 1> in = s;
  in[2] = cb::point<double, 1>(5.0);
  const auto smooth = cb::piecewise_cubic<double, 1>::from_hermite(knots, v, s, s);
  const auto broken = cb::piecewise_cubic<double, 1>::from_hermite(knots, v, in, s);
  const double eps = std::numeric_limits<double>::epsilon();
  for (std::size_t i = 1; i + 1 < knots.size(); ++i) {
    const double left = std::nextafter(knots[i], 0.0);  // evaluates segment i-1 at t ~ 1
    for (int order = 0; order <= 1; ++order)
      EXPECT_NEAR(smooth.derivative(left, order)[0], smooth.derivative(knots[i], order)[0], 64 * eps * 16) << i;
    EXPECT_NEAR(broken.derivative(left, 1)[0], in[i][0], 64 * eps * 16) << i;
    EXPECT_NEAR(broken.derivative(knots[i], 1)[0], s[i][0], 64 * eps * 16) << i;
  }
}

TEST(engine, bad_input_is_rejected_with_a_message) {
  using pc = cb::piecewise_cubic<double, 2>;
  const pc::geometry_type g = pc::geometry_type::Zero();
  auto msg = [](auto&& f) -> std::string {
    try {
      f();
    } catch (const cb::invalid_input& e) {
      return e.what();
    }
    return "no exception";
  };
  EXPECT_THAT(msg([&] { pc({0.0}, {}, cb::basis::hermite_matrix<double>()); }), HasSubstr("knots: 1 given, at least 2"));
  EXPECT_THAT(msg([&] { pc({0.0, 1.0, 1.0}, {g, g}, cb::basis::hermite_matrix<double>()); }),
              HasSubstr("knots must be increasing: knots[2] = 1 <= knots[1] = 1"));
  EXPECT_THAT(msg([&] { pc({0.0, std::nan(""), 2.0}, {g, g}, cb::basis::hermite_matrix<double>()); }),
              HasSubstr("knots[1] = nan: must be finite"));
  EXPECT_THAT(msg([&] { pc({0.0, 1.0, 2.0}, {g}, cb::basis::hermite_matrix<double>()); }),
              HasSubstr("geometries: 1 given, must match segments (knots - 1): 2"));
  pc::geometry_type bad = g;
  bad(2, 1) = std::numeric_limits<double>::infinity();
  EXPECT_THAT(msg([&] { pc({0.0, 1.0, 2.0}, {g, bad}, cb::basis::hermite_matrix<double>()); }),
              HasSubstr("geometries[1](2, 1) = inf: geometry must be finite"));
  cb::point_list<double, 2> v(3, cb::point<double, 2>::Zero());
  cb::point_list<double, 2> s2(2, cb::point<double, 2>::Zero());
  EXPECT_THAT(msg([&] { (void)pc::from_hermite({0.0, 1.0, 2.0}, v, v, s2); }),
              HasSubstr("outgoing slopes: 2 given, must match knots: 3"));
  cb::point_list<double, 2> vn = v;
  vn[1][0] = std::nan("");
  EXPECT_THAT(msg([&] { (void)pc::from_hermite({0.0, 1.0, 2.0}, vn, v, v); }),
              HasSubstr("values[1][0] = nan: coordinates must be finite"));
  const pc c({0.0, 1.0}, {g}, cb::basis::hermite_matrix<double>());
  EXPECT_THROW((void)c(1.5), std::domain_error);
  EXPECT_THAT(msg([&] { (void)c.derivative(0.5, -1); }), HasSubstr("order = -1"));
}
