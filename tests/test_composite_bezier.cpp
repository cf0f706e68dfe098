// Composite Bezier curves: values and derivatives against a 50-digit closed form per segment
// (Bernstein-derivative sums with the chain rule, segment found by a linear scan), the knot
// convention, the binary search, a subdivided curve reassembled as a chain, and the join check on
// chains built to be C1, G1 only, kinked and broken.
#include "support/accuracy.hpp"
#include "support/fixtures.hpp"

#include "curvebench/basis/bernstein.hpp"
#include "curvebench/curves/composite_bezier.hpp"

#include <gmock/gmock.h>

#include <algorithm>
#include <array>
#include <limits>
#include <random>
#include <vector>

namespace cb = curvebench;
namespace cbt = curvebench::testing;
using cb::real50;
using ::testing::HasSubstr;

namespace {

static_assert(cb::curve<cb::composite_bezier<float, 2>>);
static_assert(cb::curve<cb::composite_bezier<double, 3>>);
static_assert(cb::curve<cb::composite_bezier<real50, 2>>);

// ---------------------------------------------------------------------------------------------
// Tolerances, in eps(Real) units. L is a segment's degree, k the derivative order.
// - segment(L, k) = stable(L) + param(L) + 2k of the derivative scale L!/(L-k)! 2^k max|P| / h^k:
//   the segment is a bezier (test_bezier.cpp: de Casteljau stable(L) = 2L + 4, the rounding of the
//   local t = (u - u_i) / h_i moves the value by param(L) = 2L, and k levels of differences).
// - reassembled(L) = 2 stable(L) + param(L) + 2: a split piece's control points are de Casteljau
//   intermediates (stable(L)), then evaluated on its sub-interval (stable(L) + param(L)).
double stable(int L) { return 2.0 * L + 4; }
double param(int L) { return 2.0 * L; }
double segment_tol(int L, int k) { return stable(L) + param(L) + 2.0 * k; }
double reassembled(int L) { return 2 * stable(L) + param(L) + 2; }

template <class Real>
class composite_test : public ::testing::Test {};
TYPED_TEST_SUITE(composite_test, cbt::all_reals);

using cbt::random_points;

template <class Real, int Dim>
real50 max_abs(std::span<const cb::point<Real, Dim>> p) {
  using std::abs;
  real50 m(0);
  for (const auto& q : p)
    for (int d = 0; d < Dim; ++d) m = std::max(m, real50(abs(q[d])));
  return m;
}

// 50-digit reference: segment by linear scan with the documented convention, then the closed-form
// derivative of the Bernstein sum divided by h^k.
template <class Real, int Dim>
cb::point<real50, Dim> reference(const std::vector<cb::point_list<Real, Dim>>& segs, const std::vector<Real>& knots,
                                 const real50& u, int k, std::size_t* seg_out = nullptr) {
  std::size_t i = 0;
  while (i + 1 < segs.size() && real50(knots[i + 1]) <= u) ++i;
  if (seg_out) *seg_out = i;
  const real50 h = real50(knots[i + 1]) - real50(knots[i]);
  const real50 t = (u - real50(knots[i])) / h;
  const int L = static_cast<int>(segs[i].size()) - 1;
  cb::point<real50, Dim> sum = cb::zero_point<real50, Dim>();
  for (int j = 0; j <= L; ++j)
    sum += cb::basis::bernstein_derivative(L, j, t, k) * cb::point_cast<real50>(segs[i][static_cast<std::size_t>(j)]);
  return sum / cb::basis::pow_int(h, k);
}

template <class Real>
std::vector<Real> knots_of(std::initializer_list<double> v) {
  std::vector<Real> k;
  for (double x : v) k.push_back(static_cast<Real>(x));
  return k;
}

}  // namespace

TYPED_TEST(composite_test, values_and_derivatives_match_50_digit_closed_form) {
  using Real = TypeParam;
  std::mt19937 gen(11);
  const std::array<int, 4> degrees{3, 1, 5, 2};  // mixed degrees
  std::vector<cb::point_list<Real, 2>> segs;
  for (int L : degrees) segs.push_back(random_points<Real, 2>(L + 1, gen));
  const auto knots = knots_of<Real>({-1, -0.25, 0.5, 2, 2.125});
  const cb::composite_bezier<Real, 2> c(segs, knots);
  EXPECT_EQ(c.segment_count(), 4u);
  EXPECT_EQ(c.domain().lo, knots.front());
  EXPECT_EQ(c.domain().hi, knots.back());
  ASSERT_EQ(c.breakpoints().size(), knots.size());
  EXPECT_TRUE(std::equal(knots.begin(), knots.end(), c.breakpoints().begin()));
  for (int k = 0; k <= 6; ++k)
    for (int s = 0; s <= 200; ++s) {
      const Real u = Real(-1) + Real(3.125) * Real(s) / Real(200);
      std::size_t seg = 0;
      const cb::point<real50, 2> want = reference(segs, knots, real50(u), k, &seg);
      const int L = degrees[seg];
      real50 scale = max_abs<Real, 2>(segs[seg]);
      const real50 h = real50(knots[seg + 1]) - real50(knots[seg]);
      for (int j = 0; j < std::min(k, L); ++j) scale *= 2 * (L - j) / h;
      ASSERT_EQ(c.segment_index(u), seg) << "u=" << static_cast<double>(u);
      ASSERT_TRUE(cbt::point_within(c.derivative(u, k), want, scale, segment_tol(L, k)))
          << "k=" << k << " u=" << static_cast<double>(u) << " segment " << seg;
      if (k > L) {
        ASSERT_EQ(c.derivative(u, k), (cb::zero_point<Real, 2>()));
      }
    }
}

TYPED_TEST(composite_test, batch_evaluation_equals_single_evaluation) {
  using Real = TypeParam;
  std::mt19937 gen(3);
  std::vector<cb::point_list<Real, 2>> segs;
  for (int L : {2, 4, 1, 3}) segs.push_back(random_points<Real, 2>(L + 1, gen));
  const auto knots = knots_of<Real>({0, 0.5, 0.75, 2, 3});
  const cb::composite_bezier<Real, 2> c(segs, knots);
  std::vector<Real> sorted_us, shuffled_us;
  for (int s = 0; s <= 48; ++s) sorted_us.push_back(Real(3) * Real(s) / Real(48));  // hits every knot
  for (int s = 0; s <= 48; ++s) shuffled_us.push_back(sorted_us[static_cast<std::size_t>((s * 17) % 49)]);
  std::vector<cb::point<Real, 2>> out(sorted_us.size());
  for (const auto* us : {&sorted_us, &shuffled_us})
    for (int order : {0, 1, 3}) {
      c.evaluate(std::span<const Real>(*us), std::span<cb::point<Real, 2>>(out), order);
      for (std::size_t i = 0; i < us->size(); ++i) ASSERT_EQ(out[i], c.derivative((*us)[i], order)) << i;
    }
}

TYPED_TEST(composite_test, knot_convention_right_segment_except_last) {
  using Real = TypeParam;
  // A broken chain: segment ends do not meet, so the value at a knot shows which side was taken.
  using P = cb::point<Real, 2>;
  const std::vector<cb::point_list<Real, 2>> segs{
      {P(0, 0), P(1, 1)}, {P(5, 5), P(6, 4), P(7, 7)}, {P(-1, 0), P(-2, 3)}};
  const auto knots = knots_of<Real>({0, 1, 1.5, 4});
  const cb::composite_bezier<Real, 2> c(segs, knots);
  EXPECT_EQ(c.segment_index(Real(0)), 0u);
  EXPECT_EQ(c.segment_index(Real(0.999)), 0u);
  EXPECT_EQ(c.segment_index(Real(1)), 1u);  // interior knot: the right segment
  EXPECT_EQ(c.segment_index(Real(1.25)), 1u);
  EXPECT_EQ(c.segment_index(Real(1.5)), 2u);
  EXPECT_EQ(c.segment_index(Real(4)), 2u);  // the last knot: the last segment
  EXPECT_EQ(c(Real(1)), P(5, 5));           // right segment's first control point, exactly
  EXPECT_EQ(c(Real(1.5)), P(-1, 0));
  EXPECT_EQ(c(Real(4)), P(-2, 3));
  // Right derivative at an interior knot: 2 (P1 - P0) / h = 2 (1, -1) / 0.5 = (4, -4), exact.
  EXPECT_EQ(c.derivative(Real(1), 1), P(4, -4));
  // Left derivative at the last knot: (P1 - P0) / 2.5.
  EXPECT_TRUE(cbt::point_within(c.derivative(Real(4), 1),
                                cb::point<real50, 2>(real50(-1) / real50(2.5), real50(3) / real50(2.5)), real50(2), 2));
  const auto joins = c.continuity_at_joins(Real(0.001));
  ASSERT_EQ(joins.size(), 2u);
  for (const auto& j : joins) EXPECT_FALSE(j.c0 || j.c1 || j.g1) << j.join;
  // gap at u = 1: |(1,1) - (5,5)| / scale 7 = sqrt(32) / 7
  EXPECT_TRUE(cbt::within_ulps(joins[0].gap, sqrt(real50(32)) / 7, 4));
  EXPECT_EQ(joins[0].join, 1u);
  EXPECT_EQ(joins[1].knot, Real(1.5));
}

TYPED_TEST(composite_test, subdivided_curve_reassembled_is_unchanged_and_c1) {
  using Real = TypeParam;
  std::mt19937 gen(5);
  const int L = 6;
  const auto p = random_points<Real, 3>(L + 1, gen);
  const cb::bezier<Real, 3> whole(p, {Real(0), Real(2)});
  // Split at 0.5, 1.25, 1.5: four pieces, each with its own sub-domain; their control points and
  // the knots make a composite curve that must be the original curve, C1 (indeed C-infinity) at
  // every join.
  std::vector<cb::point_list<Real, 3>> segs;
  std::vector<Real> knots{Real(0)};
  cb::bezier<Real, 3> rest = whole;
  for (Real at : {Real(0.5), Real(1.25), Real(1.5)}) {
    auto [left, right] = rest.split(at);
    segs.emplace_back(left.control_points().begin(), left.control_points().end());
    knots.push_back(at);
    rest = right;
  }
  segs.emplace_back(rest.control_points().begin(), rest.control_points().end());
  knots.push_back(Real(2));
  const cb::composite_bezier<Real, 3> c(segs, knots);
  const std::vector<cb::point_list<Real, 3>> original{p};
  const std::vector<Real> original_knots{Real(0), Real(2)};
  const real50 scale = max_abs<Real, 3>(p);
  for (int k = 0; k <= 2; ++k) {
    real50 dscale = scale;
    for (int j = 0; j < k; ++j) dscale *= 2 * (L - j) / real50(0.25);  // shortest piece h = 0.25
    for (int s = 0; s <= 160; ++s) {
      const Real u = Real(s) / Real(80);
      // Pieces re-map t on sub-intervals (exact here: dyadic knots), and carry the split's error.
      ASSERT_TRUE(cbt::point_within(c.derivative(u, k), reference(original, original_knots, real50(u), k), dscale,
                                    reassembled(L) + 2 * k))
          << "k=" << k << " u=" << static_cast<double>(u);
    }
  }
  // Joins: the two one-sided values and derivatives agree to the split's error; relative to the
  // data scale, resp. to the derivative there (bounded below by the reference derivative).
  const auto joins = c.continuity_at_joins(Real(0));
  ASSERT_EQ(joins.size(), 3u);
  for (const auto& j : joins) {
    const real50 d_ref = reference(original, original_knots, real50(j.knot), 1).norm();
    const double gap_tol = 2 * reassembled(L) * static_cast<double>(cb::epsilon<Real>());
    const double jump_tol = static_cast<double>(real50(2 * reassembled(L) + 4) * real50(cb::epsilon<Real>()) *
                                                (real50(2 * L) * scale / real50(0.25)) / d_ref);
    EXPECT_LE(static_cast<double>(j.gap), gap_tol);
    EXPECT_LE(static_cast<double>(j.derivative_jump), jump_tol);
    const auto with_tol = c.continuity_at_joins(static_cast<Real>(std::max(gap_tol, jump_tol)))[j.join - 1];
    EXPECT_TRUE(with_tol.c0 && with_tol.c1 && with_tol.g1 && with_tol.regular) << "join " << j.join;
  }
}

TYPED_TEST(composite_test, join_check_tells_c1_from_g1_from_kinks_and_gaps) {
  using Real = TypeParam;
  using P = cb::point<Real, 2>;
  // Join 1 at u = 1: left cubic on [0, 1] ends (2,1),(3,1): P' = 3 (1, 0) / 1 = (3, 0). Right
  //   cubic on [1, 3] starts (3,1),(5,1): P' = 3 (2, 0) / 2 = (3, 0). C1, exactly.
  // Join 2 at u = 3: left ends (7,2),(8,2): P' = 3 (1, 0) / 2 = (1.5, 0); right line on [3, 4] starts
  //   (8,2) with P' = (4, 0): same direction, other length: G1 but not C1 (jump 2.5 / 4).
  // Join 3 at u = 4: left ends (8,2)->(12,2), P' = (4, 0); right line (12,2)->(12,5), P' = (0, 3): a
  //   corner, C0 only.
  // Join 4 at u = 5: right starts at (12, 5.001), a gap of 0.001 (relative 0.001 / 12): C0 only
  //   under a tolerance above that.
  const std::vector<cb::point_list<Real, 2>> segs{{P(0, 0), P(1, 2), P(2, 1), P(3, 1)},
                                                  {P(3, 1), P(5, 1), P(7, 2), P(8, 2)},
                                                  {P(8, 2), P(12, 2)},
                                                  {P(12, 2), P(12, 5)},
                                                  {P(12, Real(5.001)), P(13, 6)}};
  const auto knots = knots_of<Real>({0, 1, 3, 4, 5, 6});
  const cb::composite_bezier<Real, 2> c(segs, knots);
  EXPECT_EQ(c.scale(), Real(13));
  const Real eps = cb::epsilon<Real>();
  const auto joins = c.continuity_at_joins(Real(64) * eps);
  ASSERT_EQ(joins.size(), 4u);
  // 1: C1 and G1
  EXPECT_TRUE(joins[0].c0 && joins[0].c1 && joins[0].g1);
  EXPECT_EQ(joins[0].gap, Real(0));
  // 2: G1, not C1 (derivative jump |(1.5,0) - (4,0)| / 4 = 0.625)
  EXPECT_TRUE(joins[1].c0 && !joins[1].c1 && joins[1].g1);
  EXPECT_TRUE(cbt::within_ulps(joins[1].derivative_jump, real50(0.625), 8));
  // 3: a right-angle corner: unit tangents (1,0), (0,1), |difference| = sqrt(2)
  EXPECT_TRUE(joins[2].c0 && !joins[2].c1 && !joins[2].g1);
  EXPECT_TRUE(cbt::within_ulps(joins[2].tangent_jump, sqrt(real50(2)), 8));
  // 4: the gap
  EXPECT_FALSE(joins[3].c0 || joins[3].c1 || joins[3].g1);
  const real50 gap_ref = (real50(Real(5.001)) - 5) / 13;
  EXPECT_TRUE(cbt::within_relative(joins[3].gap, gap_ref, 1e-3));
  const auto loose = c.continuity_at_joins(Real(0.001));
  EXPECT_TRUE(loose[3].c0);
  EXPECT_FALSE(loose[2].g1);  // still a corner
  // A degenerate join (both one-sided derivatives zero) is C1, hence G1, and not regular.
  const std::vector<cb::point_list<Real, 2>> cusp{{P(0, 0), P(1, 1), P(1, 1)}, {P(1, 1), P(1, 1), P(2, 0)}};
  const cb::composite_bezier<Real, 2> cc(cusp, knots_of<Real>({0, 1, 2}));
  const auto cj = cc.continuity_at_joins(Real(0));
  EXPECT_TRUE(cj[0].c1 && cj[0].g1 && !cj[0].regular);
}

TEST(composite_bad_input, messages_name_argument_index_and_value) {
  using P = cb::point<double, 2>;
  using C = cb::composite_bezier<double, 2>;
  const auto message_of = [](auto&& make) -> std::string {
    try {
      make();
    } catch (const cb::invalid_input& e) {
      return e.what();
    }
    return "no exception";
  };
  const std::vector<cb::point_list<double, 2>> two{{P(0, 0), P(1, 1)}, {P(1, 1), P(2, 0), P(3, 3)}};
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THAT(message_of([] { C c(std::vector<cb::point_list<double, 2>>{}, std::vector<double>{0}); }),
              HasSubstr("segments: 0 given, at least 1 required"));
  EXPECT_THAT(message_of([&] {
                C c(two, std::vector<double>{0, 1});
              }),
              HasSubstr("knots: 2 given, must match segments + 1: 3"));
  EXPECT_THAT(message_of([&] {
                C c(two, std::vector<double>{0, 1, 1});
              }),
              HasSubstr("knots must be increasing: knots[2] = 1 <= knots[1] = 1"));
  EXPECT_THAT(message_of([&] {
                C c(two, std::vector<double>{0, nan, 2});
              }),
              HasSubstr("knots[1] = nan: must be finite"));
  EXPECT_THAT(
      message_of([] {
        C c(std::vector<cb::point_list<double, 2>>{{P(0, 0), P(1, 1)}, {P(1, 1)}}, std::vector<double>{0, 1, 2});
      }),
      HasSubstr("segments[1]: 1 given, at least 2 required"));
  EXPECT_THAT(message_of([&] {
                C c(std::vector<cb::point_list<double, 2>>{cb::point_list<double, 2>{P(0, 0), P(1, nan)}},
                    std::vector<double>{0, 1});
              }),
              HasSubstr("segments[0][1][1] = nan: coordinates must be finite"));
  const C c(two, std::vector<double>{0, 1, 2});
  EXPECT_THAT(message_of([&] { (void)c.continuity_at_joins(-1.0); }), HasSubstr("tol = -1: must be >= 0"));
  EXPECT_THAT(message_of([&] { (void)c.continuity_at_joins(nan); }), HasSubstr("tol = nan: must be finite"));
  EXPECT_THAT(message_of([&] { (void)c.segment(2); }), HasSubstr("i = 2: segment index must be < 2"));
  EXPECT_THAT(message_of([&] { (void)c.derivative(0.5, -1); }), HasSubstr("order = -1: derivative order must be >= 0"));
  std::vector<double> us{0.0, 3.0};
  std::vector<P> out(1);
  EXPECT_THAT(message_of([&] { c.evaluate(std::span<const double>(us), std::span<P>(out)); }),
              HasSubstr("out: 1 given, must match us: 2"));
  out.resize(2);
  EXPECT_THROW(c.evaluate(std::span<const double>(us), std::span<P>(out)), std::domain_error);
  // NaN anywhere in the batch is a domain error naming its index (the segment cache never holds it).
  const std::vector<double> with_nan{0.0, 0.25, 0.5, 0.75, 1.0, nan, 1.5};
  std::vector<P> out7(with_nan.size());
  try {
    c.evaluate(std::span<const double>(with_nan), std::span<P>(out7));
    ADD_FAILURE() << "NaN at us[5] accepted";
  } catch (const std::domain_error& e) {
    EXPECT_THAT(e.what(), HasSubstr("us[5] = nan is outside the domain [0, 2]"));
  }
  EXPECT_THROW((void)c(2.5), std::domain_error);
  EXPECT_THROW((void)c.segment_index(-0.5), std::domain_error);
  EXPECT_THROW((void)c.derivative(-0.5, 1), std::domain_error);
}
