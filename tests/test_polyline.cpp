// Polyline: exact interpolation of the vertices, values and slopes against the 50-digit closed form
// of linear interpolation, the one-sided derivative rule at vertices, segment lookup, affine
// invariance, reversal, linear precision, the segment convex hull, and bad input.
#include "support/accuracy.hpp"
#include "support/fixtures.hpp"

#include "curvebench/curves/polyline.hpp"

#include <gmock/gmock.h>

#include <array>
#include <functional>
#include <limits>
#include <string>
#include <vector>

namespace cb = curvebench;
namespace cbt = curvebench::testing;
using ::testing::HasSubstr;

static_assert(cb::curve<cb::polyline<float, 3>>);
static_assert(cb::curve<cb::polyline<double, 2>>);
static_assert(cb::curve<cb::polyline<cb::real50, 1>>);

namespace {

// Tolerances in eps(Real), relative to the scale of the vertices (largest |coordinate|):
// - value_ulps: the two weights (u_{i+1} - u)/h and (u - u_i)/h carry <= 3 roundings each (two
//   subtractions are exact or rounded once, one division), then two products and a sum: ~8
//   roundings of terms of at most the vertex scale. 8.
// - slope_ulps: (P_{i+1} - P_i) / h: one subtraction, one division, with h itself rounded once
//   when the parameters are not exact: 3 roundings relative to the slope's largest coordinate. 4.
// Measured maxima over the four types: value 0.66, slope 0.25, affine 1, hull 0.
// - affine_ulps: transforming the evaluated point (a 2x2 product and a shift, ~3 roundings of the
//   transformed scale ~ 3x the vertex scale) versus evaluating the transformed vertices (value_ulps
//   of that scale): 8 + 3 * 3 ~ 17, so 24.
// - hull_ulps: the weights sum to 1 within ~4 ulps, so a point may leave its segment's bounding
//   box by that much of the vertex scale. 4.
constexpr double value_ulps = 8;
constexpr double slope_ulps = 4;
constexpr double affine_ulps = 24;
constexpr double hull_ulps = 4;

template <class Real>
class polyline_test : public ::testing::Test {};
TYPED_TEST_SUITE(polyline_test, cbt::all_reals);

// Vertices with dyadic coordinates (exact in every type) and non-uniform parameters, some of which
// (0.1, 0.7) are not representable: the reference uses the same rounded values in 50 digits.
template <class Real>
cb::point_list<Real, 2> vertices() {
  return {cb::point<Real, 2>(Real(0), Real(0)), cb::point<Real, 2>(Real(1.5), Real(0.25)),
          cb::point<Real, 2>(Real(2), Real(-1.75)), cb::point<Real, 2>(Real(-0.5), Real(3)),
          cb::point<Real, 2>(Real(-0.5), Real(3.5))};
}
template <class Real>
std::vector<Real> parameters() {
  return {Real(-0.25), Real(0.1), Real(0.7), Real(2), Real(2.125)};
}
const cb::real50 vertex_scale(3.5);

// Reference value and slope on segment i by the textbook formula P_i + (u - u_i)/(u_{i+1} - u_i) dP.
template <class Real>
cb::point<cb::real50, 2> ref_value(const cb::polyline<Real, 2>& c, std::size_t i, const cb::real50& u) {
  const cb::point<cb::real50, 2> p = cb::point_cast<cb::real50>(c.vertices()[i]);
  const cb::point<cb::real50, 2> q = cb::point_cast<cb::real50>(c.vertices()[i + 1]);
  const cb::real50 u0(c.parameters()[i]);
  const cb::real50 u1(c.parameters()[i + 1]);
  return p + (u - u0) / (u1 - u0) * (q - p);
}
template <class Real>
cb::point<cb::real50, 2> ref_slope(const cb::polyline<Real, 2>& c, std::size_t i) {
  const cb::point<cb::real50, 2> d =
      cb::point_cast<cb::real50>(c.vertices()[i + 1]) - cb::point_cast<cb::real50>(c.vertices()[i]);
  return d / (cb::real50(c.parameters()[i + 1]) - cb::real50(c.parameters()[i]));
}

cb::real50 scale_of(const cb::point<cb::real50, 2>& p) { return std::max(abs(p[0]), abs(p[1])); }

using cbt::message_of;

}  // namespace

TYPED_TEST(polyline_test, interpolates_vertices_exactly_and_is_continuous) {
  using Real = TypeParam;
  const auto v = vertices<Real>();
  const auto t = parameters<Real>();
  const cb::polyline<Real, 2> c(v, t);
  EXPECT_EQ(c.domain().lo, t.front());
  EXPECT_EQ(c.domain().hi, t.back());
  ASSERT_EQ(c.breakpoints().size(), t.size());
  EXPECT_TRUE(std::equal(t.begin(), t.end(), c.breakpoints().begin()));
  EXPECT_EQ(c.segment_count(), 4u);
  for (std::size_t i = 0; i < v.size(); ++i) {
    EXPECT_EQ(c(t[i]), v[i]) << "vertex " << i;  // bit for bit
    // Continuity: just left of an interior vertex (on the previous segment) the curve is within
    // |slope| * d + rounding of the vertex.
    if (i > 0) {
      const Real d = Real(64) * cb::epsilon<Real>();
      const cb::point<Real, 2> left = c(Real(t[i] - d));
      const cb::real50 slope = cb::point_cast<cb::real50>(cb::point<Real, 2>(v[i] - v[i - 1])).norm() /
                               (cb::real50(t[i]) - cb::real50(t[i - 1]));
      EXPECT_LE(cb::real50((left - v[i]).norm()),
                slope * cb::real50(d) * 2 + value_ulps * cb::real50(cb::epsilon<Real>()) * vertex_scale)
          << "vertex " << i;
    }
  }
  // The default parameters are 0, 1, ..., n - 1.
  const cb::polyline<Real, 2> u(v);
  EXPECT_EQ(u.domain().lo, Real(0));
  EXPECT_EQ(u.domain().hi, Real(4));
  for (std::size_t i = 0; i < v.size(); ++i) EXPECT_EQ(u(Real(static_cast<int>(i))), v[i]);
}

TYPED_TEST(polyline_test, values_and_slopes_match_the_50_digit_closed_form) {
  using Real = TypeParam;
  const cb::polyline<Real, 2> c(vertices<Real>(), parameters<Real>());
  const auto t = parameters<Real>();
  for (int k = 0; k <= 200; ++k) {
    const Real u = c.domain().lo + (c.domain().hi - c.domain().lo) * Real(k) / Real(200);
    if (u > c.domain().hi) continue;
    // The segment by linear scan, independently of the binary search.
    std::size_t i = 0;
    while (i + 2 < t.size() && !(u < t[i + 1])) ++i;
    ASSERT_EQ(c.segment(u), i) << "u = " << cbt::exact_text(u);
    EXPECT_TRUE(cbt::point_within(c(u), ref_value(c, i, cb::real50(u)), vertex_scale, value_ulps))
        << "u = " << cbt::exact_text(u);
    EXPECT_TRUE(cbt::point_within(c.derivative(u, 1), ref_slope(c, i), scale_of(ref_slope(c, i)), slope_ulps))
        << "u = " << cbt::exact_text(u);
    for (int order = 2; order <= 4; ++order) EXPECT_EQ(c.derivative(u, order), (cb::point<Real, 2>::Zero()));
  }
}

TYPED_TEST(polyline_test, slope_at_a_vertex_is_right_handed_except_at_the_end) {
  using Real = TypeParam;
  const cb::polyline<Real, 2> c(vertices<Real>(), parameters<Real>());
  const auto t = parameters<Real>();
  for (std::size_t i = 0; i + 1 < t.size(); ++i) {
    EXPECT_EQ(c.segment(t[i]), i);
    EXPECT_TRUE(cbt::point_within(c.derivative(t[i], 1), ref_slope(c, i), scale_of(ref_slope(c, i)), slope_ulps)) << i;
  }
  EXPECT_EQ(c.segment(t.back()), t.size() - 2);
  EXPECT_TRUE(cbt::point_within(c.derivative(t.back(), 1), ref_slope(c, t.size() - 2),
                                scale_of(ref_slope(c, t.size() - 2)), slope_ulps));
  // Interior vertices have a real jump in slope here (C0, not C1).
  EXPECT_GT((c.derivative(t[1], 1) - ref_slope(c, 0).template cast<Real>()).norm(), Real(1));
}

TYPED_TEST(polyline_test, affine_invariance_reversal_linear_precision_and_hull) {
  using Real = TypeParam;
  const auto v = vertices<Real>();
  const auto t = parameters<Real>();
  const cb::polyline<Real, 2> c(v, t);
  // Affine map x -> A x + b applied to the vertices or to the curve.
  Eigen::Matrix<Real, 2, 2> a;
  a << Real(0.75), Real(-1.25), Real(0.5), Real(2);
  const cb::point<Real, 2> b(Real(-3), Real(0.625));
  cb::point_list<Real, 2> w;
  for (const auto& p : v) w.push_back(cb::point<Real, 2>(a * p + b));
  const cb::polyline<Real, 2> cw(w, t);
  // Reversal: vertices reversed at the default parameters 0..4; u -> 4 - u is exact for u = 4k/64.
  const cb::point_list<Real, 2> rv(v.rbegin(), v.rend());
  const cb::polyline<Real, 2> cu(v);
  const cb::polyline<Real, 2> cr(rv);
  for (int k = 0; k <= 64; ++k) {
    const Real u = Real(4) * Real(k) / Real(64);
    EXPECT_TRUE(cbt::point_within(cr(Real(4) - u), cb::point_cast<cb::real50>(cu(u)), vertex_scale, 2 * value_ulps))
        << "u = " << k << "/16";
  }
  for (int k = 0; k <= 64; ++k) {
    const Real u = t.front() + (t.back() - t.front()) * Real(k) / Real(64);
    if (u > t.back()) continue;
    const cb::point<Real, 2> p = c(u);
    const cb::point<Real, 2> mapped = a * p + b;
    EXPECT_TRUE(cbt::point_within(cw(u), cb::point_cast<cb::real50>(mapped), 3 * vertex_scale, affine_ulps));
    // Convex hull of the segment: inside the bounding box of its two vertices.
    const std::size_t i = c.segment(u);
    for (int d = 0; d < 2; ++d) {
      const cb::real50 lo = std::min(cb::real50(v[i][d]), cb::real50(v[i + 1][d]));
      const cb::real50 hi = std::max(cb::real50(v[i][d]), cb::real50(v[i + 1][d]));
      const cb::real50 slack = hull_ulps * cb::real50(cb::epsilon<Real>()) * vertex_scale;
      EXPECT_GE(cb::real50(p[d]), lo - slack);
      EXPECT_LE(cb::real50(p[d]), hi + slack);
    }
  }
  // Linear precision: vertices on a line x = 3u - 1 at their parameters reproduce the line.
  cb::point_list<Real, 2> line;
  for (const Real& ui : t) line.push_back(cb::point<Real, 2>(Real(3) * ui - Real(1), Real(2)));
  const cb::polyline<Real, 2> cl(line, t);
  for (int k = 0; k <= 64; ++k) {
    const Real u = t.front() + (t.back() - t.front()) * Real(k) / Real(64);
    if (u > t.back()) continue;
    EXPECT_TRUE(cbt::within_scaled_ulps(cl(u)[0], 3 * cb::real50(u) - 1, cb::real50(6), 4 * value_ulps))
        << cbt::exact_text(u);
    // A constant coordinate is reproduced to the rounding of the weights (which need not sum to 1 exactly).
    EXPECT_TRUE(cbt::within_scaled_ulps(cl(u)[1], cb::real50(2), cb::real50(2), value_ulps));
  }
}

TYPED_TEST(polyline_test, chord_length_parameters_give_unit_speed) {
  using Real = TypeParam;
  const auto v = vertices<Real>();
  const std::vector<Real> u = cb::chord_length_parameters<Real, 2>(v);
  ASSERT_EQ(u.size(), v.size());
  EXPECT_EQ(u.front(), Real(0));
  // u_i is the length of the control polygon up to vertex i (50-digit closed form); each chord is a
  // rounded norm (~2 ulps) and the running sum adds one rounding per step: 2 i + 2 ulps of the total.
  cb::real50 length(0);
  for (std::size_t i = 1; i < v.size(); ++i) {
    length += (cb::point_cast<cb::real50>(v[i]) - cb::point_cast<cb::real50>(v[i - 1])).norm();
    EXPECT_TRUE(cbt::within_ulps(u[i], length, 2.0 * static_cast<double>(i) + 2)) << "u_" << i;
  }
  // With these parameters the polyline is parameterized by arc length: |P'(u)| = 1 everywhere
  // (each chord and its parameter step carry a few roundings: 4 * slope_ulps).
  const cb::polyline<Real, 2> c(v, u);
  for (int k = 0; k <= 64; ++k) {
    const Real s = u.back() * Real(k) / Real(64);
    if (s > u.back()) continue;
    EXPECT_TRUE(cbt::within_ulps(Real(c.derivative(s, 1).norm()), cb::real50(1), 4 * slope_ulps))
        << "u = " << cbt::exact_text(s);
  }
}

TEST(polyline, three_dimensions_and_many_segments_use_binary_search) {
  // 1000 vertices on a helix-like staircase; each parameter's segment is found exactly.
  cb::point_list<double, 3> v;
  std::vector<double> t;
  for (int i = 0; i < 1000; ++i) {
    v.emplace_back(i % 7, i % 3, i);
    t.push_back(0.5 * i + 0.001 * (i % 5));
  }
  const cb::polyline<double, 3> c(v, t);
  for (std::size_t i = 0; i + 1 < t.size(); i += 37) {
    EXPECT_EQ(c.segment(t[i]), i);
    EXPECT_EQ(c.segment(0.5 * (t[i] + t[i + 1])), i);
    EXPECT_EQ(c(t[i]), v[i]);
    EXPECT_DOUBLE_EQ(c(0.5 * (t[i] + t[i + 1]))[2], static_cast<double>(i) + 0.5);
  }
  EXPECT_EQ(c.segment(t.back()), 998u);
}

TEST(polyline, bad_input_is_rejected_with_a_clear_message) {
  using p2 = cb::point<double, 2>;
  const cb::point_list<double, 2> one{p2(0, 0)};
  EXPECT_EQ(message_of([&] { cb::polyline<double, 2> c(one); }),
            "vertices: 1 given, at least 2 required (a polyline has at least one segment)");
  const cb::point_list<double, 2> nan{p2(0, 0), p2(std::numeric_limits<double>::quiet_NaN(), 1)};
  EXPECT_EQ(message_of([&] { cb::polyline<double, 2> c(nan); }), "vertices[1][0] = nan: coordinates must be finite");
  const cb::point_list<double, 2> inf{p2(0, 0), p2(1, std::numeric_limits<double>::infinity())};
  EXPECT_EQ(message_of([&] { cb::polyline<double, 2> c(inf); }), "vertices[1][1] = inf: coordinates must be finite");
  const cb::point_list<double, 2> three{p2(0, 0), p2(1, 1), p2(2, 0)};
  const std::vector<double> two_params{0, 1};
  EXPECT_EQ(message_of([&] { cb::polyline<double, 2> c(three, two_params); }),
            "parameters: 2 given, must match vertices: 3");
  const std::vector<double> repeated{0, 1, 1};
  EXPECT_EQ(message_of([&] { cb::polyline<double, 2> c(three, repeated); }),
            "parameters must be increasing: parameters[2] = 1 <= parameters[1] = 1");
  const std::vector<double> decreasing{0, 2, 1};
  EXPECT_EQ(message_of([&] { cb::polyline<double, 2> c(three, decreasing); }),
            "parameters must be increasing: parameters[2] = 1 <= parameters[1] = 2");
  const std::vector<double> nan_param{0, std::numeric_limits<double>::quiet_NaN(), 2};
  EXPECT_EQ(message_of([&] { cb::polyline<double, 2> c(three, nan_param); }), "parameters[1] = nan: must be finite");
  const cb::point_list<double, 2> repeated_vertex{p2(0, 0), p2(1, 1), p2(1, 1)};
  EXPECT_EQ(message_of([&] { (void)cb::chord_length_parameters<double, 2>(repeated_vertex); }),
            "vertices[2] equals vertices[1]: zero chord, chord-length parameters must increase");
  EXPECT_EQ(message_of([&] { (void)cb::chord_length_parameters<double, 2>(one); }),
            "vertices: 1 given, at least 2 required (a polyline has at least one segment)");
  const cb::polyline<double, 2> c(three);
  EXPECT_THROW((void)c(2.5), std::domain_error);
  EXPECT_THAT(message_of([&] { (void)c(-0.5); }), HasSubstr("u = -0.5 is outside the domain [0, 2]"));
  EXPECT_EQ(message_of([&] { (void)c.derivative(1.0, -1); }), "order = -1: derivative order must be >= 0");
}
