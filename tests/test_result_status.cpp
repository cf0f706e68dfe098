// core/result_status.hpp: the names round-trip, unknown names are rejected with the list of names,
// worst orders by certainty, and the arclength names are the same type and functions (the move to
// core/ keeps arclength code compiling unchanged).
#include "support/fixtures.hpp"

#include "curvebench/arclength/result.hpp"
#include "curvebench/core/result_status.hpp"

#include <gmock/gmock.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <string>
#include <type_traits>

namespace cb = curvebench;
namespace cbt = curvebench::testing;
using ::testing::HasSubstr;

TEST(result_status, names_round_trip) {
  EXPECT_EQ(cb::to_string(cb::result_status::converged), "converged");
  EXPECT_EQ(cb::to_string(cb::result_status::cap_hit), "cap_hit");
  EXPECT_EQ(cb::to_string(cb::result_status::rounding_limited), "rounding_limited");
  EXPECT_EQ(cb::to_string(cb::result_status::not_guaranteed), "not_guaranteed");
  for (cb::result_status s : cb::all_result_statuses) EXPECT_EQ(cb::result_status_from_string(cb::to_string(s)), s);
}

TEST(result_status, unknown_names_are_invalid_input_listing_the_names) {
  EXPECT_THROW((void)cb::result_status_from_string("Converged"), cb::invalid_input);  // exact names only
  EXPECT_THAT(cbt::message_of([] { (void)cb::result_status_from_string("done"); }),
              HasSubstr("result status = \"done\": unknown, expected one of converged, cap_hit, rounding_limited, "
                        "not_guaranteed"));
}

// The order of certainty, as the header states it: converged < rounding_limited < cap_hit <
// not_guaranteed; worst of any pair, in either order, is the later one.
TEST(result_status, worst_is_the_less_certain) {
  using S = cb::result_status;
  const std::array<S, 4> order{S::converged, S::rounding_limited, S::cap_hit, S::not_guaranteed};
  for (std::size_t i = 0; i < order.size(); ++i)
    for (std::size_t j = 0; j < order.size(); ++j) {
      EXPECT_EQ(cb::worst(order[i], order[j]), order[std::max(i, j)]) << i << " " << j;
    }
}

TEST(result_status, arclength_names_the_same_type) {
  static_assert(std::is_same_v<cb::arclength::result_status, cb::result_status>);
  EXPECT_EQ(cb::arclength::to_string(cb::arclength::result_status::cap_hit), "cap_hit");
  EXPECT_EQ(cb::arclength::worst(cb::arclength::result_status::converged, cb::result_status::cap_hit),
            cb::result_status::cap_hit);
  cb::arclength::quadrature_result<double> a, b;
  b.status = cb::result_status::rounding_limited;
  a += b;
  EXPECT_EQ(a.status, cb::result_status::rounding_limited);
}
