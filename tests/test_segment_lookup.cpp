// core/detail/segment_lookup.hpp: the one segment rule of every piecewise object, against the rule
// applied literally (a linear scan: the largest i with b_i <= u, clamped to the segments; the mirror
// rule the smallest i with u <= b_{i+1}), which shares no code with the binary search. The
// parameters are the breakpoints themselves, one ulp either side of each, the ends, points outside
// the domain and NaN; breakpoint lists with repeated interior and repeated last breakpoints. The
// lookups are exact (indices): no tolerance.
#include "support/fixtures.hpp"

#include "curvebench/core/detail/segment_lookup.hpp"

#include <gmock/gmock.h>

#include <cmath>
#include <cstddef>
#include <limits>
#include <span>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

namespace cbd = curvebench::detail;
namespace cbt = curvebench::testing;
using ::testing::HasSubstr;

template <class Real>
std::string hex(const Real& u) {
  std::ostringstream os;
  os << std::hexfloat << u;
  return os.str();
}

/// The rule as stated: the last i in 0..n with b_i <= u (0 if none, and for NaN the last, as a
/// comparison with NaN is false: u < b_i never holds), then clamped to 0..n-1.
template <class Real>
std::size_t scan_at_or_below(const std::vector<Real>& b, const Real& u) {
  std::size_t i = 0;
  for (std::size_t k = 0; k < b.size(); ++k)
    if (!(u < b[k])) i = k;
  return i;
}
template <class Real>
std::size_t scan_segment(const std::vector<Real>& b, const Real& u) {
  const std::size_t i = scan_at_or_below(b, u);
  return i < b.size() - 2 ? i : b.size() - 2;
}
/// The mirror: the first i with u <= b_{i+1}, clamped to 0..n-1 (n - 1 if none).
template <class Real>
std::size_t scan_segment_from_left(const std::vector<Real>& b, const Real& u) {
  for (std::size_t i = 0; i + 1 < b.size(); ++i)
    if (b[i + 1] >= u) return i;
  return b.size() - 2;
}

template <class Real>
std::vector<std::vector<Real>> breakpoint_lists() {
  return {
      {Real(0), Real(1)},                                                 // one segment
      {Real(0), Real(0.25), Real(0.5), Real(1)},                          // uneven
      {Real(-3), Real(-1), Real(2), Real(2), Real(2), Real(5), Real(8)},  // a triple interior breakpoint
      {Real(0), Real(0), Real(1), Real(2)},                               // repeated first breakpoint
      {Real(0), Real(1), Real(2), Real(2)},                               // repeated last breakpoint
      {Real(1e6), Real(1e6) + Real(0.125), Real(2e6)},                    // far from 0
  };
}

/// Every breakpoint, its neighbours one ulp away, midpoints, and points outside the domain.
template <class Real>
std::vector<Real> probes(const std::vector<Real>& b) {
  const Real inf = std::numeric_limits<Real>::infinity();
  std::vector<Real> us{-inf, inf, b.front() - Real(1), b.back() + Real(1)};
  for (std::size_t k = 0; k < b.size(); ++k) {
    us.push_back(b[k]);
    us.push_back(std::nextafter(b[k], -inf));
    us.push_back(std::nextafter(b[k], inf));
    if (k + 1 < b.size()) us.push_back(b[k] + (b[k + 1] - b[k]) / Real(2));
  }
  return us;
}

template <class Real>
class segment_lookup : public ::testing::Test {};
using lookup_reals = ::testing::Types<float, double>;
TYPED_TEST_SUITE(segment_lookup, lookup_reals);

TYPED_TEST(segment_lookup, matches_the_rule_at_breakpoints_one_ulp_either_side_and_outside) {
  using Real = TypeParam;
  for (const auto& b : breakpoint_lists<Real>()) {
    for (const Real& u : probes(b)) {
      EXPECT_EQ(cbd::segment_of<Real>(b, u), scan_segment(b, u)) << hex(u);
      EXPECT_EQ(cbd::breakpoint_at_or_below<Real>(b, u), scan_at_or_below(b, u)) << hex(u);
      EXPECT_EQ(cbd::segment_of_from_left<Real>(b, u), scan_segment_from_left(b, u)) << hex(u);
      const bool inside = b.front() <= u && u <= b.back();
      for (std::size_t i = 0; i + 1 < b.size(); ++i)
        EXPECT_EQ(cbd::in_segment<Real>(b, i, u), inside && cbd::segment_of<Real>(b, u) == i)
            << hex(u) << " segment " << i;
    }
  }
}

// The statements of the rule, spelled out on one list: an interior breakpoint belongs to the
// segment on its right (one ulp below it to the left one), repeated breakpoints to the segment
// after the last copy, the last breakpoint to the last segment; the mirror rule the other way.
TEST(segment_lookup_rule, interior_breakpoints_belong_to_the_segment_on_their_right) {
  const std::vector<double> b{-3, -1, 2, 2, 2, 5, 8};  // segments 0..5; 2 and 3 are empty
  EXPECT_EQ(cbd::segment_of<double>(b, -3.0), 0u);
  EXPECT_EQ(cbd::segment_of<double>(b, -1.0), 1u);
  EXPECT_EQ(cbd::segment_of<double>(b, std::nextafter(-1.0, -2.0)), 0u);
  EXPECT_EQ(cbd::segment_of<double>(b, 2.0), 4u);  // past the empty segments 2 and 3
  EXPECT_EQ(cbd::segment_of<double>(b, std::nextafter(2.0, 0.0)), 1u);
  EXPECT_EQ(cbd::segment_of<double>(b, 8.0), 5u);  // the last breakpoint: the last segment
  EXPECT_EQ(cbd::breakpoint_at_or_below<double>(b, 8.0), 6u);
  EXPECT_EQ(cbd::segment_of_from_left<double>(b, 2.0), 1u);  // mirror: the segment ending there
  EXPECT_EQ(cbd::segment_of_from_left<double>(b, -3.0), 0u);
  EXPECT_EQ(cbd::segment_of_from_left<double>(b, std::nextafter(2.0, 3.0)), 4u);
  EXPECT_EQ(cbd::segment_of<double>(b, std::numeric_limits<double>::quiet_NaN()), 5u);
  const std::vector<double> last_repeated{0, 1, 2, 2};
  EXPECT_EQ(cbd::segment_of<double>(last_repeated, 2.0), 2u);  // the empty last segment (see the header)
}

TEST(segment_lookup_rule, checked_lookup_is_a_domain_error_outside_and_for_nan) {
  const std::vector<double> b{0, 0.5, 1};
  EXPECT_EQ(cbd::checked_segment_of<double>(b, 1.0), 1u);
  EXPECT_EQ(cbd::checked_segment_of<double>(b, 0.0), 0u);
  EXPECT_THROW((void)cbd::checked_segment_of<double>(b, std::nextafter(1.0, 2.0)), std::domain_error);
  EXPECT_THROW((void)cbd::checked_segment_of<double>(b, std::nextafter(0.0, -1.0)), std::domain_error);
  EXPECT_THROW((void)cbd::checked_segment_of<double>(b, std::numeric_limits<double>::quiet_NaN()), std::domain_error);
  EXPECT_THAT(cbt::message_of([&] { (void)cbd::checked_segment_of<double>(b, 2.0); }),
              HasSubstr("u = 2 is outside the domain [0, 1]"));
  EXPECT_THAT(cbt::message_of([&] { (void)cbd::checked_segment_of<double>(b, -1.0, "us", 3); }),
              HasSubstr("us[3] = -1 is outside the domain [0, 1]"));
}

// The records' variant (keys whose time is a member) answers as the plain one on their times.
TEST(segment_lookup_rule, records_by_member_match_the_plain_lookup) {
  struct key {
    double time;
    int tag;
  };
  const std::vector<double> b{-3, -1, 2, 2, 2, 5, 8};
  std::vector<key> keys;
  for (const double t : b) keys.push_back(key{t, 0});
  const auto time = [](const key& k) -> const double& { return k.time; };
  for (const double u : {-4.0, -3.0, -2.0, -1.0, 0.0, 2.0, std::nextafter(2.0, 0.0), 3.0, 5.0, 8.0, 9.0,
                         std::numeric_limits<double>::quiet_NaN()}) {
    EXPECT_EQ(cbd::breakpoint_at_or_below(std::span<const key>(keys), u, time),
              cbd::breakpoint_at_or_below<double>(b, u))
        << "u = " << u;
  }
}

}  // namespace
