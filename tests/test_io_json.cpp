// JSON spec field readers: values read exactly, every malformed field named by its path.
#include "curvebench/io/json_fields.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

namespace io = curvebench::io;
using ::testing::HasSubstr;

namespace {
std::string error_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const io::spec_error& e) {
    return e.what();
  }
  return "(no error)";
}
}  // namespace

TEST(io_json, reads_points_reals_and_options) {
  const auto j = io::parse(R"({"type": "bezier", "points": [[0, 0], [1, 2.5], [3, 0.1]], "knots": [0, 0.5, 1],
                               "closed": true, "degree": 3})");
  const auto spec = io::root(j);
  EXPECT_EQ(spec.member("type").one_of({"bezier", "nurbs"}), "bezier");
  EXPECT_EQ(spec.member("points").point_dimension(), 2);
  const auto pts = spec.member("points").points<double, 2>();
  ASSERT_EQ(pts.size(), 3u);
  EXPECT_EQ(pts[2][1], 0.1);  // the same double JSON parsed
  EXPECT_EQ(spec.member("knots").reals<double>(), (std::vector<double>{0, 0.5, 1}));
  EXPECT_TRUE(spec.member("closed").boolean());
  EXPECT_EQ(spec.member("degree").integer(), 3);
  EXPECT_NO_THROW(spec.only_members({"type", "points", "knots", "closed", "degree"}));
}

TEST(io_json, errors_name_the_field_and_what_is_expected) {
  const auto j = io::parse(R"({"type": "bezir", "points": [[0, 0], [1, "a"], [3]], "weights": "x", "tenson": 1})");
  const auto spec = io::root(j);
  EXPECT_EQ(error_of([&] { (void)spec.member("type").one_of({"bezier", "nurbs"}); }),
            "spec.type: \"bezir\" is not one of: bezier, nurbs");
  EXPECT_EQ(error_of([&] { (void)spec.member("points").points<double, 2>(); }),
            "spec.points[1][1]: expected a number, got \"a\"");
  EXPECT_EQ(error_of([&] { (void)spec.member("weights").reals<double>(); }),
            "spec.weights: expected an array, got \"x\"");
  EXPECT_EQ(error_of([&] { (void)spec.member("knots", "required for type \"bspline\""); }),
            "spec: knots is missing (required for type \"bspline\")");
  EXPECT_THAT(error_of([&] { spec.only_members({"type", "points", "weights"}); }),
              HasSubstr("spec: unknown field \"tenson\""));
  const auto short_point = io::parse(R"({"points": [[0, 0], [3]]})");
  EXPECT_EQ(error_of([&] { (void)io::root(short_point).member("points").points<double, 2>(); }),
            "spec.points[1]: expected an array of 2 numbers, got [3]");
  EXPECT_THAT(error_of([] { (void)io::parse("{\"points\": [1, 2", "case.json"); }), HasSubstr("case.json: not valid JSON"));
  // A number beyond double's range is a JSON error too, reported the same way.
  EXPECT_THAT(error_of([] { (void)io::parse("{\"x\": 1e999}", "case.json"); }), HasSubstr("case.json: not valid JSON"));
}

TEST(io_json, spec_error_is_an_invalid_input) {
  const auto j = io::parse(R"({"points": []})");
  EXPECT_THROW((void)io::root(j).member("points").point_dimension(), curvebench::invalid_input);
}
