// JSON spec field readers: values read exactly, every malformed field named by its path.
#include "curvebench/io/json_fields.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <functional>
#include <limits>
#include <string>

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
  EXPECT_EQ(error_of([&] {
              (void)spec.member("type").one_of({"bezier", "nurbs"});
            }),
            "spec.type: \"bezir\" is not one of: bezier, nurbs");
  EXPECT_EQ(error_of([&] { (void)spec.member("points").points<double, 2>(); }),
            "spec.points[1][1]: expected a number, got \"a\"");
  EXPECT_EQ(error_of([&] { (void)spec.member("weights").reals<double>(); }),
            "spec.weights: expected an array, got \"x\"");
  EXPECT_EQ(error_of([&] { (void)spec.member("knots", "required for type \"bspline\""); }),
            "spec: knots is missing (required for type \"bspline\")");
  EXPECT_THAT(error_of([&] {
                spec.only_members({"type", "points", "weights"});
              }),
              HasSubstr("spec: unknown field \"tenson\""));
  const auto short_point = io::parse(R"({"points": [[0, 0], [3]]})");
  EXPECT_EQ(error_of([&] { (void)io::root(short_point).member("points").points<double, 2>(); }),
            "spec.points[1]: expected an array of 2 numbers, got [3]");
  EXPECT_THAT(error_of([] { (void)io::parse("{\"points\": [1, 2", "case.json"); }),
              HasSubstr("case.json: not valid JSON"));
  // A number beyond double's range is named by its path, as written (it was a syntax
  // error of the whole file, or an inf later echoed as null).
  EXPECT_EQ(error_of([] { (void)io::parse("{\"x\": [0, 1e999]}", "case.json"); }),
            "case.json.x[1]: the number 1e999 is beyond double's range (magnitudes up to about 1.8e308)");
}

TEST(io_json, spec_error_is_an_invalid_input) {
  const auto j = io::parse(R"({"points": []})");
  EXPECT_THROW((void)io::root(j).member("points").point_dimension(), curvebench::invalid_input);
}

// A UTF-8 byte order mark was refused with the invisible character in the message.
TEST(io_json, a_utf8_byte_order_mark_is_skipped) {
  const auto j = io::parse("\xEF\xBB\xBF{\"type\": \"bezier\"}", "bom.json");
  EXPECT_EQ(j["type"], "bezier");
  // Only at the start: elsewhere it is the stray bytes it is.
  EXPECT_THROW((void)io::parse("{\"type\": \"bezier\"}\xEF\xBB\xBF", "bom.json"), curvebench::invalid_input);
}

// ---- hostile input ---------------------------------------------------------------------------

namespace {
/// `levels` arrays nested in one another, closed: valid JSON of that depth.
std::string nested_arrays(std::size_t levels) { return std::string(levels, '[') + std::string(levels, ']'); }
}  // namespace

// 1e6 levels crashed the tool (recursive copies and dumps of the parsed value overflowed the stack).
// parse() refuses the 65th level while reading, so no deep value is ever built, walked or destroyed.
TEST(io_json, nesting_beyond_the_limit_is_an_error_naming_file_path_and_limit) {
  EXPECT_EQ(io::max_nesting_depth, 64u);
  EXPECT_NO_THROW((void)io::parse(nested_arrays(io::max_nesting_depth), "case.json"));
  const std::string root_deep = error_of([] { (void)io::parse(nested_arrays(1000000), "case.json"); });
  std::string path = "case.json";
  for (std::size_t i = 0; i < io::max_nesting_depth; ++i) path += "[0]";  // the 65th array's place
  EXPECT_EQ(root_deep, path + ": JSON nested more than 64 levels deep (the limit; no spec needs more than a few)");
  EXPECT_EQ(error_of([] { (void)io::parse(nested_arrays(io::max_nesting_depth + 1), "case.json"); }), root_deep);
  // Deep in a field the spec never reads (a case's reason) is refused all the same, objects too.
  std::string deep_objects;
  for (int i = 0; i < 1000000; ++i) deep_objects += "{\"k\":";
  const std::string in_field =
      error_of([&] { (void)io::parse(R"({"type": "bezier", "reason": [1, 2, )" + deep_objects, "deep.json"); });
  EXPECT_THAT(in_field, ::testing::StartsWith("deep.json.reason[2].k.k.k"));
  EXPECT_THAT(in_field, HasSubstr(": JSON nested more than 64 levels deep"));
}

// {"type":"bezier","type":"polyline"} silently measured a polyline: the last key won.
TEST(io_json, a_repeated_key_is_an_error_naming_the_object_and_the_key) {
  EXPECT_EQ(error_of([] { (void)io::parse(R"({"type": "bezier", "type": "polyline"})", "case.json"); }),
            "case.json: key \"type\" appears twice in this object (JSON keeps only one of them)");
  EXPECT_EQ(error_of([] { (void)io::parse(R"({"items": [{"w": 1}, {"w": 1, "x": [], "w": 2}]})", "case.json"); }),
            "case.json.items[1]: key \"w\" appears twice in this object (JSON keeps only one of them)");
  // The same key in different objects is fine, and the value is the one written.
  const auto j = io::parse(R"({"a": {"w": 1}, "b": {"w": 2}, "w": [{"w": 3}]})");
  EXPECT_EQ(j["b"]["w"], 2);
  EXPECT_EQ(j["w"][0]["w"], 3);
}

// 2^64-1 was read as -1 ("degree -1 is not allowed"): a value beyond long long is quoted as written.
TEST(io_json, integers_beyond_long_long_are_reported_as_written) {
  const auto j = io::parse(R"({"a": 18446744073709551615, "b": 9223372036854775808, "c": 9223372036854775807,
                               "d": -9223372036854775808})");
  const auto spec = io::root(j);
  EXPECT_EQ(error_of([&] { (void)spec.member("a").integer(); }),
            "spec.a: 18446744073709551615 is too large (at most 9223372036854775807)");
  EXPECT_EQ(error_of([&] { (void)spec.member("b").integer(); }),
            "spec.b: 9223372036854775808 is too large (at most 9223372036854775807)");
  EXPECT_EQ(spec.member("c").integer(), std::numeric_limits<long long>::max());
  EXPECT_EQ(spec.member("d").integer(), std::numeric_limits<long long>::min());
}

// shown() dumped the whole value before cutting it to 60 characters: a 10 MB value was serialised
// in full, and a deep one (built in code, not parsed) overflowed the stack.
TEST(io_json, echoes_serialise_a_bounded_prefix_of_large_and_deep_values) {
  const auto j = io::parse(R"({"points": [[1, "abcdefghijklmnopqrstuvwxyzabcdefghijklmnopqrstuvwxyzabcdefghijkl"]],
                               "w": [1, [2, [3]], {"k": null}]})");
  EXPECT_EQ(io::root(j).member("points").shown(), "[[1,\"abcdefghijklmnopqrstuvwxyzabcdefghijklmnopqrstuvwxyz...");
  EXPECT_EQ(io::root(j).member("w").shown(), "[1,[2,[3]],{\"k\":null}]");  // short values as dump() writes them
  // 10 MB in a value and in an unknown key: messages stay short.
  const std::string big(10'000'000, 'z');
  const io::json huge{{"type", big}, {big, 1}};
  const std::string value_error = error_of([&] { (void)io::root(huge).member("type").number(); });
  EXPECT_EQ(value_error, "spec.type: expected a number, got \"" + std::string(56, 'z') + "...");
  const std::string key_error = error_of([&] { io::root(huge).only_members({"type"}); });
  EXPECT_THAT(key_error, ::testing::StartsWith("spec: unknown field \"zzz"));
  EXPECT_LT(key_error.size(), 200u);
  // A million levels built in code: the echo stops after about 60 of them.
  io::json deep = 1;
  for (int i = 0; i < 1000000; ++i) {
    io::json outer = io::json::array();
    outer.push_back(std::move(deep));
    deep = std::move(outer);
  }
  const std::string deep_error = error_of([&] { (void)io::root(deep).number(); });
  EXPECT_EQ(deep_error, "spec: expected a number, got " + std::string(57, '[') + "...");
  // A syntax error quotes the last token read: an unterminated 10 MB string is cut.
  const std::string syntax = error_of([&] { (void)io::parse("{\"type\": \"" + big, "case.json"); });
  EXPECT_THAT(syntax, ::testing::StartsWith("case.json: not valid JSON: "));
  EXPECT_THAT(syntax, HasSubstr("missing closing quote"));
  EXPECT_LT(syntax.size(), 400u);
}
