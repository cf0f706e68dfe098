// piecewise_cubic engine: the three algorithms (power/Horner, matrix T·M·G, Bezier/de Casteljau)
// against a closed-form cubic and against the real50 instantiation of the same data, chain rule
// for derivatives, segment lookup (uniform O(1) path and the bucket index, both against a binary
// search at every knot, its float neighbours and random points), batched and sorted evaluation
// (the sorted power path bit-identical to single calls), continuity of Hermite assembly, and bad
// input.
#include "support/accuracy.hpp"

#include "curvebench/curves/piecewise_cubic.hpp"

#include <gmock/gmock.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <random>
#include <span>
#include <string>
#include <type_traits>
#include <utility>
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
  cb::real50 s = vmax + cb::real50(0.75) * tmax;                       // max h = 0.75
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
  std::vector<cb::basis::matrix4<double>> m{cb::basis::bezier_matrix<double>(),
                                            cb::basis::uniform_bspline_matrix<double>(),
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
  EXPECT_THAT(msg([&] { pc({0.0}, {}, cb::basis::hermite_matrix<double>()); }),
              HasSubstr("knots: 1 given, at least 2"));
  EXPECT_THAT(msg([&] {
                pc({0.0, 1.0, 1.0}, {g, g}, cb::basis::hermite_matrix<double>());
              }),
              HasSubstr("knots must be increasing: knots[2] = 1 <= knots[1] = 1"));
  EXPECT_THAT(msg([&] {
                pc({0.0, std::nan(""), 2.0}, {g, g}, cb::basis::hermite_matrix<double>());
              }),
              HasSubstr("knots[1] = nan: must be finite"));
  EXPECT_THAT(msg([&] {
                pc({0.0, 1.0, 2.0}, {g}, cb::basis::hermite_matrix<double>());
              }),
              HasSubstr("geometries: 1 given, must match segments (knots - 1): 2"));
  pc::geometry_type bad = g;
  bad(2, 1) = std::numeric_limits<double>::infinity();
  EXPECT_THAT(msg([&] {
                pc({0.0, 1.0, 2.0}, {g, bad}, cb::basis::hermite_matrix<double>());
              }),
              HasSubstr("geometries[1](2, 1) = inf: geometry must be finite"));
  cb::point_list<double, 2> v(3, cb::point<double, 2>::Zero());
  cb::point_list<double, 2> s2(2, cb::point<double, 2>::Zero());
  EXPECT_THAT(msg([&] {
                (void)pc::from_hermite({0.0, 1.0, 2.0}, v, v, s2);
              }),
              HasSubstr("outgoing slopes: 2 given, must match knots: 3"));
  cb::point_list<double, 2> vn = v;
  vn[1][0] = std::nan("");
  EXPECT_THAT(msg([&] {
                (void)pc::from_hermite({0.0, 1.0, 2.0}, vn, v, v);
              }),
              HasSubstr("values[1][0] = nan: coordinates must be finite"));
  const pc c({0.0, 1.0}, {g}, cb::basis::hermite_matrix<double>());
  EXPECT_THROW((void)c(1.5), std::domain_error);
  EXPECT_THAT(msg([&] { (void)c.derivative(0.5, -1); }), HasSubstr("order = -1"));
}

namespace {

// Knot sets on which the lookup must agree with a binary search: uniform (also far from the origin,
// where u0 + i h rounds), one knot moved by an ulp, random non-uniform, highly non-uniform (interval
// ratio 1e4: random log-uniform widths, and a cluster of 1e4-times shorter intervals in the middle,
// so that one bucket holds many segments), and the smallest cases (1 and 2 segments).
template <class Real>
std::vector<std::pair<std::string, std::vector<Real>>> lookup_knot_sets() {
  std::vector<std::pair<std::string, std::vector<Real>>> sets;
  std::mt19937_64 rng(2024);
  sets.emplace_back("uniform 64", cb::uniform_knots<Real>(64, Real(-2), Real(0.3)));
  sets.emplace_back("uniform 4096", cb::uniform_knots<Real>(4096));
  sets.emplace_back("uniform 100 far from 0", cb::uniform_knots<Real>(100, Real(1000), Real(0.125)));
  auto near = cb::uniform_knots<Real>(50, Real(0), Real(0.1));
  near[17] = std::nextafter(near[17], Real(10));
  sets.emplace_back("uniform, one knot moved an ulp", near);
  sets.emplace_back("one segment", std::vector<Real>{Real(-1), Real(3)});
  sets.emplace_back("two segments", std::vector<Real>{Real(0), Real(0.001), Real(10)});
  // float resolves no interval below 2^8 ulps of the knots (validate::resolvable), so its widest
  // ratio over many segments is 1e2 (and only on 64 segments); double takes 1e4 on 4096.
  constexpr bool is_float = std::is_same_v<Real, float>;
  const double small = is_float ? 1e-2 : 1e-4;
  // Adversarial for the bucket index: interior knots exactly at, or one ulp either side of, the
  // edges u0 + b (u1 - u0) / n of its n buckets (the engine's own formula), where rounding in the
  // bucket of u decides between neighbours; every 8th knot moved to the middle of its bucket so
  // that the knots are not uniform.
  for (std::size_t n : {64u, 1000u}) {
    const Real u0 = Real(0.1), u1 = Real(7.3);
    const Real width = (u1 - u0) / Real(static_cast<long long>(n));
    std::vector<Real> e{u0};
    for (std::size_t b = 1; b < n; ++b) {
      Real x = u0 + Real(static_cast<long long>(b)) * width;
      if (b % 8 == 0)
        x = x + width / Real(2);
      else if (b % 3 == 1)
        x = std::nextafter(x, u1);
      else if (b % 3 == 2)
        x = std::nextafter(x, u0);
      e.push_back(x);
    }
    e.push_back(u1);
    sets.emplace_back("knots at the bucket edges and an ulp off them, " + std::to_string(n), e);
  }
  // Adversarial for the non-uniform index's own map from u to its bucket (piecewise_cubic.hpp's
  // bucket_of: fl(fl(u - u0) fl(2n / (un - u0))) truncated, 2n buckets for n segments): interior
  // knots at the first parameter of a bucket under that rounded map, or an ulp either side, so that
  // u and the knot of a comparison round into the same or neighbouring buckets; every 8th knot on
  // an odd bucket's edge so that the knots are not uniform.
  for (std::size_t n : {64u, 1000u}) {
    const Real u0 = Real(-0.7), u1 = Real(5.9);
    const std::size_t buckets = 2 * n;
    const Real inv = Real(static_cast<long long>(buckets)) / (u1 - u0);
    const auto bucket = [&](Real u) {
      const Real x = (u - u0) * inv;
      return x < Real(static_cast<long long>(buckets - 1)) ? static_cast<std::size_t>(x) : buckets - 1;
    };
    std::vector<Real> e{u0};
    for (std::size_t j = 1; j < n; ++j) {
      const std::size_t b = 2 * j + (j % 8 == 0 ? 1 : 0);
      Real x = u0 + Real(static_cast<long long>(b)) * ((u1 - u0) / Real(static_cast<long long>(buckets)));
      while (bucket(x) >= b) x = std::nextafter(x, u0);
      while (bucket(x) < b) x = std::nextafter(x, u1);
      if (j % 3 == 1)
        x = std::nextafter(x, u1);
      else if (j % 3 == 2)
        x = std::nextafter(x, u0);
      e.push_back(x);
    }
    e.push_back(u1);
    sets.emplace_back("knots at the index's rounded bucket edges and an ulp off them, " + std::to_string(n), e);
  }
  std::uniform_real_distribution<double> step(0.25, 1.75), log_step(std::log10(small), 0.0);
  for (std::size_t n : {64u, 4096u}) {
    std::vector<Real> k{Real(0)};
    for (std::size_t i = 0; i < n; ++i) k.push_back(k.back() + Real(step(rng)));
    sets.emplace_back("random steps in [0.25, 1.75], " + std::to_string(n), k);
    if (is_float && n > 64) continue;
    std::vector<Real> r{Real(-5)};
    for (std::size_t i = 0; i < n; ++i) r.push_back(r.back() + Real(std::pow(10.0, log_step(rng))));
    sets.emplace_back("log-uniform steps in [" + std::to_string(small) + ", 1], " + std::to_string(n), r);
    std::vector<Real> c{Real(0)};
    for (std::size_t i = 0; i < n; ++i) c.push_back(c.back() + Real(i > n / 3 && i < 2 * n / 3 ? small : 1.0));
    sets.emplace_back("a cluster of " + std::to_string(small) + " steps among steps of 1, " + std::to_string(n), c);
  }
  return sets;
}

// A curve on the knots with random Hermite data in Dim 3, so that a wrong segment changes values.
template <class Real>
cb::piecewise_cubic<Real, 3> random_engine(const std::vector<Real>& knots, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> coord(-1.0, 1.0);
  cb::point_list<Real, 3> v(knots.size()), s(knots.size());
  for (std::size_t i = 0; i < knots.size(); ++i) {
    v[i] = cb::point<Real, 3>(Real(coord(rng)), Real(coord(rng)), Real(coord(rng)));
    s[i] = cb::point<Real, 3>(Real(coord(rng)), Real(coord(rng)), Real(coord(rng)));
  }
  return cb::piecewise_cubic<Real, 3>::from_hermite(knots, v, s, s);
}

// The parameters to check on knots k: every knot, both float neighbours of each (those inside the
// domain), and random points, sorted.
template <class Real>
std::vector<Real> lookup_parameters(const std::vector<Real>& k, std::size_t random_count) {
  std::vector<Real> us;
  for (const Real& x : k) {
    us.push_back(x);
    const Real below = std::nextafter(x, -std::numeric_limits<Real>::infinity());
    const Real above = std::nextafter(x, std::numeric_limits<Real>::infinity());
    if (below >= k.front()) us.push_back(below);
    if (above <= k.back()) us.push_back(above);
  }
  std::mt19937_64 rng(77);
  std::uniform_real_distribution<Real> u(k.front(), k.back());
  for (std::size_t j = 0; j < random_count; ++j) us.push_back(u(rng));
  std::sort(us.begin(), us.end());
  return us;
}

template <class Real>
class lookup_test : public ::testing::Test {};
using lookup_reals = ::testing::Types<float, double>;
TYPED_TEST_SUITE(lookup_test, lookup_reals);

}  // namespace

// The O(1) lookups (uniform index, bucket index) must be pure speed: the same segment as the
// binary search over the knots (first interior knot > u, minus one) at every parameter, including
// exactly at knots, one ulp either side and the domain ends; and the value at u must be that
// segment's polynomial at t = (u - u_i) fl(1 / h_i) (the engine's local parameter), bit for bit.
TYPED_TEST(lookup_test, segment_lookup_equals_binary_search_at_knots_neighbours_and_random_points) {
  using Real = TypeParam;
  for (const auto& [name, k] : lookup_knot_sets<Real>()) {
    const auto c = random_engine(k, 5);
    if (name.find("bucket edges") != std::string::npos) {
      ASSERT_FALSE(c.uniform()) << name;  // the index is under test
    }
    const auto us = lookup_parameters(k, 20000);
    for (const Real& u : us) {
      const std::size_t want =
          static_cast<std::size_t>(std::upper_bound(k.begin() + 1, k.end() - 1, u) - k.begin()) - 1;
      ASSERT_EQ(c.segment_index(u), want) << name << ": u = " << std::hexfloat << u;
      const Real t = (u - k[want]) * (Real(1) / (k[want + 1] - k[want]));
      ASSERT_EQ(c(u), c.evaluate_segment(want, t, 0)) << name << ": u = " << std::hexfloat << u;
    }
  }
}

// The local parameter by the reciprocal, t = fl(fl(u - u_i) fl(1 / h_i)), is within 4 u t of the
// exact (u - u_i) / (u_{i+1} - u_i) (unit roundoff u = eps / 2: four roundings, piecewise_cubic.hpp's
// local_t), which rounding_bound charges. Measured in real50 at every knot, its neighbours and
// random points of every knot set; 4 u (1 + 8 u) leaves room only for the second-order terms, and
// denorm_min the rounding of a t below the normal range (a parameter a few units of the smallest
// subnormal from u_0), whose error is absolute: at most half a unit of the smallest subnormal.
TYPED_TEST(lookup_test, reciprocal_local_parameter_is_within_four_roundings) {
  using Real = TypeParam;
  using R50 = cb::real50;
  const R50 u = R50(std::numeric_limits<Real>::epsilon()) / 2;
  R50 worst(0);
  for (const auto& [name, k] : lookup_knot_sets<Real>()) {
    for (const Real& x : lookup_parameters(k, 2000)) {
      const std::size_t i = static_cast<std::size_t>(std::upper_bound(k.begin() + 1, k.end() - 1, x) - k.begin()) - 1;
      const Real t = (x - k[i]) * (Real(1) / (k[i + 1] - k[i]));
      const R50 exact = (R50(x) - R50(k[i])) / (R50(k[i + 1]) - R50(k[i]));
      const R50 err = abs(R50(t) - exact);
      ASSERT_LE(err, R50(4) * u * (R50(1) + R50(8) * u) * exact + R50(std::numeric_limits<Real>::denorm_min()))
          << name << ": u = " << std::hexfloat << x << ", t = " << t;
      if (exact > R50(0)) worst = std::max(worst, R50(err / (exact * u)));
    }
  }
  EXPECT_GT(worst, R50(0));  // the check saw rounding: it was not vacuous
}

// Where fl(1 / h_i) is not a normal number (h_i subnormal: its reciprocal overflows; h_i beyond
// 1 / DBL_MIN: its reciprocal is subnormal and has lost digits) the engine divides instead: every
// value is the segment's polynomial at t = fl(u - u_i) / h_i bit for bit (the reciprocal would give
// 0 x inf = NaN at the knots of the first set), and the speed on the wide segments divides by h_i
// too: within 8 eps of the real50 derivative of the same coefficients (Horner's 5 roundings, t's 3,
// the division; the coefficients are O(1)). On subnormal segments the true speed, O(1) / 1e-310,
// overflows double, so only the values are checked there.
TEST(engine, local_parameter_divides_where_the_reciprocal_is_not_normal) {
  using R50 = cb::real50;
  const std::vector<std::vector<double>> knot_sets = {
      {0.0, 1e-310, 2e-310, 3.5e-310}, {0.0, 1.5e308}, {-1.0, 0.0, 1.5e308}};
  for (const auto& k : knot_sets) {
    std::mt19937_64 rng(3);
    std::uniform_real_distribution<double> coord(-1.0, 1.0);
    std::vector<cb::piecewise_cubic<double, 3>::geometry_type> a(k.size() - 1);
    for (auto& g : a)
      for (int r = 0; r < 4; ++r)
        for (int d = 0; d < 3; ++d) g(r, d) = coord(rng);
    const auto c = cb::piecewise_cubic<double, 3>::from_power(k, a);
    const bool wide = !(k.back() < 1.0);
    for (const double x : lookup_parameters(k, 200)) {
      const std::size_t i = c.segment_index(x);
      const double t = (x - k[i]) / (k[i + 1] - k[i]);
      const auto p = c(x);
      ASSERT_EQ(p, c.evaluate_segment(i, t, 0)) << "u = " << std::hexfloat << x;
      ASSERT_TRUE(p.allFinite()) << "u = " << std::hexfloat << x;
      if (!wide) continue;
      const R50 h = R50(k[i + 1]) - R50(k[i]), t50 = (R50(x) - R50(k[i])) / h;
      const auto d = c.derivative(x, 1);
      for (int j = 0; j < 3; ++j) {
        const auto& g = a[i];
        const R50 exact = (R50(g(1, j)) + t50 * (R50(2) * R50(g(2, j)) + t50 * R50(3) * R50(g(3, j)))) / h;
        const R50 size = (abs(R50(g(1, j))) + R50(2) * abs(R50(g(2, j))) + R50(3) * abs(R50(g(3, j)))) / h;
        ASSERT_LE(abs(R50(d[j]) - exact), R50(8) * R50(std::numeric_limits<double>::epsilon()) * size)
            << "u = " << std::hexfloat << x << ", coordinate " << j;
      }
    }
  }
}

// The sorted power path (per-segment runs, coefficients hoisted, where parameters are dense; point
// by point where they are sparse) computes what single calls do, in the same order: bit-identical
// values, also with repeated parameters, runs that skip segments, every knot and its neighbours,
// and both domain ends. lookup_parameters puts about 3 parameters per segment before the random
// ones, so each knot set takes the sparse path (fewer than 4 per segment) at 3 random parameters
// and the dense one (runs longer than the 8 a block takes) at 50000; 1024 gives either.
TYPED_TEST(lookup_test, sorted_power_path_is_bit_identical_to_single_calls) {
  using Real = TypeParam;
  for (const auto& [name, k] : lookup_knot_sets<Real>()) {
    const auto c = random_engine(k, 9);
    for (std::size_t random_count : {std::size_t{3}, std::size_t{1024}, std::size_t{50000}}) {
      auto us = lookup_parameters(k, random_count);
      us.insert(us.begin() + static_cast<std::ptrdiff_t>(us.size() / 2), us[us.size() / 2]);  // a repeat
      std::vector<cb::point<Real, 3>> out(us.size());
      c.evaluate_sorted(us, out);
      for (std::size_t j = 0; j < us.size(); ++j)
        ASSERT_EQ(out[j], c(us[j])) << name << ": us[" << j << "] = " << std::hexfloat << us[j];
      // A span that starts and ends inside the domain (not at its ends).
      const std::size_t lo = us.size() / 3, hi = 2 * us.size() / 3;
      std::span<const Real> part(us.data() + lo, hi - lo);
      std::vector<cb::point<Real, 3>> out_part(part.size());
      c.evaluate_sorted(part, out_part);
      for (std::size_t j = 0; j < part.size(); ++j) ASSERT_EQ(out_part[j], out[lo + j]) << name << ": " << j;
    }
  }
}

// A descent or a parameter past u_n after a long sorted prefix still throws at its index with the
// prefix written (the fast path checks first and hands bad input to the checked walk).
TEST(engine, sorted_power_path_rejects_bad_input_at_its_index_with_the_prefix_written) {
  const auto k = cb::uniform_knots<double>(64);
  const auto c = random_engine(k, 3);
  std::vector<double> us;
  for (int j = 0; j < 500; ++j) us.push_back(0.125 * j);
  std::vector<cb::point<double, 3>> out(us.size(), cb::point<double, 3>::Constant(7.0));
  auto desc = us;
  desc[300] = desc[299] - 1.0;
  try {
    c.evaluate_sorted(desc, out);
    FAIL() << "descent accepted";
  } catch (const cb::invalid_input& e) {
    EXPECT_THAT(e.what(), HasSubstr("us[300]"));
  }
  for (std::size_t j = 0; j < 300; ++j) ASSERT_EQ(out[j], c(desc[j])) << j;
  auto past = us;
  past.back() = std::nextafter(64.0, 65.0);
  EXPECT_THROW(c.evaluate_sorted(past, out), std::domain_error);
}

// second_derivative_bound: on every segment of every lookup knot set (random Hermite data, so every
// sign pattern of a_2, a_3 occurs), over the whole segment and over random sub-intervals, at least
// |P''| of the stored coefficients at 65 points of the interval, its ends included, evaluated in
// real50 (P''(u) = (2 a_2 + 6 a_3 t) / h_i^2 with the exact t and h_i); and at most that plus
// 1e-5 of the coefficients' scale (2 |a_2| + 6 |a_3|) / h_i^2: the bound is the norm at the ends
// (exact, the norm of an affine function is largest at an end) raised by 8 u of the scale and
// 16 eps, 1e-5 leaving room for float's 8 u = 4.8e-7. +inf across a knot (P' may jump there); the
// domain is checked.
TYPED_TEST(lookup_test, second_derivative_bound_covers_the_second_derivative_and_is_tight) {
  using Real = TypeParam;
  using R50 = cb::real50;
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> frac(0.0, 1.0);
  for (const auto& [name, k] : lookup_knot_sets<Real>()) {
    const auto c = random_engine(k, 9);
    for (std::size_t i = 0; i + 1 < k.size(); ++i) {
      const auto& a = c.power_coefficients(i);
      const R50 h = R50(k[i + 1]) - R50(k[i]);
      R50 scale_sq(0);
      for (int d = 0; d < 3; ++d) {
        const R50 s = (R50(2) * abs(R50(a[2][d])) + R50(6) * abs(R50(a[3][d]))) / (h * h);
        scale_sq += s * s;
      }
      const R50 scale = sqrt(scale_sq);
      for (int trial = 0; trial < 4; ++trial) {
        Real lo = k[i], hi = k[i + 1];
        if (trial > 0) {
          const Real x = k[i] + Real(frac(rng)) * (k[i + 1] - k[i]), y = k[i] + Real(frac(rng)) * (k[i + 1] - k[i]);
          lo = std::min(x, y);
          hi = std::max(x, y);
          if (!(lo >= k[i] && hi <= k[i + 1])) continue;
        }
        R50 top(0);
        for (int j = 0; j <= 64; ++j) {
          const R50 t = (R50(lo) + (R50(hi) - R50(lo)) * R50(j) / 64 - R50(k[i])) / h;
          R50 sq(0);
          for (int d = 0; d < 3; ++d) {
            const R50 v = (R50(2) * R50(a[2][d]) + R50(6) * R50(a[3][d]) * t) / (h * h);
            sq += v * v;
          }
          top = std::max(top, R50(sqrt(sq)));
        }
        const Real b = c.second_derivative_bound(lo, hi);
        ASSERT_GE(R50(b), top) << name << ": segment " << i << " [" << lo << ", " << hi << "]";
        ASSERT_LE(R50(b), top + R50(1e-5) * scale) << name << ": segment " << i << " [" << lo << ", " << hi << "]";
      }
      if (i + 2 < k.size()) {
        const Real mid = k[i] + (k[i + 1] - k[i]) / Real(2);
        ASSERT_EQ(c.second_derivative_bound(mid, k[i + 2]), std::numeric_limits<Real>::infinity()) << name;
      }
    }
    EXPECT_THROW((void)c.second_derivative_bound(k.front(), k.back() + Real(1)), std::domain_error);
    EXPECT_THROW((void)c.second_derivative_bound(std::numeric_limits<Real>::quiet_NaN(), k.back()), std::domain_error);
  }
}
