// Channels checked by time (harness/check.hpp, kind times; harness::channel_values_of) against
// references that do not go through the channel models: closed forms of a CSS easing and of a
// linear channel, evaluated in long double.
//   cubic-bezier(0, 1, 0, 1): x(u) = u^3 and y(u) = 1 - (1 - u)^3, so the easing's value at time t
//   is 1 - (1 - cbrt(t))^3 and its slope y'(u) / x'(u) = (1 - u)^2 / u^2 at u = cbrt(t).
//   A linear exact channel from (0, 0) to (10, 5): value t / 2, slope 1/2.
#include "harness/check.hpp"

#include "support/fixtures.hpp"
#include "support/source_dir.hpp"

#include "curvebench/core/error.hpp"
#include "curvebench/io/json_fields.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>
#include <string>
#include <vector>

using namespace curvebench::harness;
using curvebench::testing::invalid_input_of;
using ::testing::HasSubstr;

namespace {

constexpr double eps = std::numeric_limits<double>::epsilon();

const char* const snappy = R"j({"type": "channel", "tool": "css", "easing": "cubic-bezier(0, 1, 0, 1)"})j";
const char* const ramp = R"({"type": "channel", "tool": "exact", "keys": [
  {"time": 0, "value": 0, "interpolation": "linear"}, {"time": 10, "value": 5}]})";

struct spec_doc {
  nlohmann::json j;
  curvebench::io::field f;
  explicit spec_doc(const char* text)
      : j(curvebench::io::parse(text, "test spec")), f(curvebench::io::root(j, "test spec")) {}
};

long double snappy_value(long double t) {
  const long double v = 1 - std::cbrt(t);
  return 1 - v * v * v;
}
long double snappy_slope(long double t) {
  const long double u = std::cbrt(t);
  return (1 - u) * (1 - u) / (u * u);
}

std::string g17(double x) {
  char b[40];
  std::snprintf(b, sizeof b, "%.17g", x);
  return b;
}

check_result times(const spec_doc& s, const std::string& csv, check_options o = {}) {
  return run_check(s.f, check_kind::values, parse_csv(csv, "mine.csv", true), o);
}

}  // namespace

// The truth printed by `sample` (channel_values_of, truth) is the closed form correctly rounded:
// long double carries 11 more bits than double, so the closed form's own error (a few ulps of
// long double) moves the comparison by < 0.01 ulps of double; 0.51 allows the rounding of the
// truth to double (0.5 ulp of the value) and that.
TEST(check_times, the_truth_of_a_css_easing_is_its_closed_form) {
  const spec_doc s(snappy);
  const channel_values truth = channel_values_of(s.f, check_against::truth);
  for (double t : {1e-5, 1e-3, 0.1, 0.3, 0.5, 0.7, 0.999}) {
    const auto v = truth.at(t, 0);
    ASSERT_TRUE(v.has_value());
    const long double want = snappy_value(t);
    EXPECT_LE(std::abs(static_cast<long double>(*v) - want) / (eps * std::abs(want)), 0.51) << "t = " << t;
    const auto d = truth.at(t, 1);
    ASSERT_TRUE(d.has_value());
    EXPECT_LE(std::abs(static_cast<long double>(*d) - snappy_slope(t)) / (eps * snappy_slope(t)), 2.0) << "t = " << t;
  }
  // At t = 0 the slope is infinite (x'(0) = 0): a vertical tangent, not a number.
  const auto d0 = truth.at(0, 1);
  EXPECT_TRUE(!d0 || std::isinf(*d0));
}

// WebKit's solver (the css tool's own evaluation) is what `sample --as-tool` prints and what
// `check --against tool` compares with; at t = 1e-5 it is off the truth by 1.7e-4 (it
// prints 0.0630783 where the curve's value is 0.0632506). A CSV of the truth checks at <= 0.5 ulp
// against the truth and fails against the tool, and the other way round.
TEST(check_times, truth_and_tool_are_kept_apart) {
  const spec_doc s(snappy);
  const channel_values tool = channel_values_of(s.f, check_against::tool);
  EXPECT_THAT(tool.what, HasSubstr("css"));
  EXPECT_THAT(tool.what, HasSubstr("table_newton"));
  const double webkit = *tool.at(1e-5, 0);
  EXPECT_NEAR(webkit, 0.0630783, 5e-8);
  EXPECT_NEAR(static_cast<double>(snappy_value(1e-5L)), 0.0632506, 5e-8);

  std::string exact = "t,value\n", emulated = "t,value\n";
  for (double t : {1e-5, 0.1, 0.5, 0.9}) {
    exact += g17(t) + "," + g17(static_cast<double>(snappy_value(t))) + "\n";
    emulated += g17(t) + "," + g17(*tool.at(t, 0)) + "\n";
  }
  check_options to_tool;
  to_tool.against = check_against::tool;
  const check_result a = times(s, exact), b = times(s, emulated, to_tool), c = times(s, emulated),
                     d = times(s, exact, to_tool);
  EXPECT_EQ(a.kind, check_kind::times);
  EXPECT_LE(a.summary.max, 0.5);  // the closed form rounded once; the range is 1
  EXPECT_EQ(b.summary.max, 0.0);  // the tool's own values against themselves
  EXPECT_GT(c.rows[0].absolute, 1.7e-4);
  EXPECT_LT(c.rows[0].absolute, 1.73e-4);
  EXPECT_GT(d.summary.max, 7e11);  // 1.72e-4 / eps
  EXPECT_THAT(b.against, HasSubstr("own evaluation"));
  EXPECT_THAT(a.against, HasSubstr("50 digits"));
}

// An injected error is reported exactly in each unit, with the absolute error beside it and the
// time error of a late value. 2^-40 added to a value below 5 is exact in double, and the ramp's
// truth t / 2 is exact at these times, so every figure below is exact up to one rounding.
TEST(check_times, reports_an_injected_error_in_every_unit_and_the_time_error) {
  const spec_doc s(ramp);
  const double off = std::ldexp(1.0, -40);
  const std::string csv = "t,value,dvalue\n1,0.5,0.5\n3," + g17(1.5 + off) + ",0.5\n7,3.5,0.25\n";
  const check_result r = times(s, csv);
  ASSERT_EQ(r.rows.size(), 3u);
  EXPECT_EQ(r.unit, value_unit::ulp_double);  // 17 digits written in row 3
  EXPECT_EQ(r.size, 5.0);                     // the value range of the keys
  EXPECT_DOUBLE_EQ(r.rows[1].absolute, off);
  EXPECT_DOUBLE_EQ(r.rows[1].error, off / (eps * 5));
  EXPECT_DOUBLE_EQ(r.rows[1].time_error, off / 0.5);  // late by 2 x 2^-40 frames
  EXPECT_EQ(r.rows[0].error, 0.0);
  // dvalue 0.25 against 0.5: 0.25 of the derivative's size 0.5, in ulps of double.
  EXPECT_DOUBLE_EQ(r.rows[2].derivative_errors[0], 0.25 / (eps * 0.5));
  EXPECT_EQ(r.worst.front(), 2u);
  for (value_unit u : {value_unit::ulp_float, value_unit::rel, value_unit::abs}) {
    check_options o;
    o.unit = u;
    const check_result ru = times(s, csv, o);
    EXPECT_DOUBLE_EQ(ru.rows[1].error, in_unit(off, 5.0, u));
    EXPECT_EQ(ru.unit, u);
  }
  const std::vector<std::string> over = rows_over(r, 100);  // row 3: 819 ulps; row 4: its dvalue
  ASSERT_EQ(over.size(), 2u);
  EXPECT_THAT(over[0], HasSubstr("row 3 (t = 3)"));
  EXPECT_THAT(over[0], HasSubstr("ulps of double x max(|value|, value range)"));
}

// A channel far from zero with a small range (a location at 1.0 moving by 0.125): a float engine
// one float ulp off at 1.0 has stored the value as well as a float can, and the ulp units say 1
// (ulps of max(|value|, range)), where ulps of the range alone said 1 / 0.125 = 8; rel keeps the
// range (the motion's size). The records keep ulps of double of the same scale and carry the
// check's own figure: the keys and the range are dyadic, so every figure below is exact and
// compared to within EXPECT_DOUBLE_EQ's 4 ulps.
TEST(check_times, ulp_units_scale_by_the_value_itself_where_it_exceeds_the_range) {
  const spec_doc s(R"({"type": "channel", "tool": "exact", "keys": [
    {"time": 0, "value": 1, "interpolation": "linear"}, {"time": 10, "value": 1.125}]})");
  const double ulp_f = std::numeric_limits<float>::epsilon();  // the ulp of float at 1.0
  const std::string csv = "t,value\n0," + g17(1.0 + ulp_f) + "\n10,1.125\n";
  check_options o;
  o.unit = value_unit::ulp_float;
  const check_result r = times(s, csv, o);
  EXPECT_DOUBLE_EQ(r.size, 0.125);
  EXPECT_DOUBLE_EQ(r.rows[0].scale, 1.0);
  EXPECT_DOUBLE_EQ(r.rows[0].error, 1.0);
  ASSERT_FALSE(r.records.empty());
  EXPECT_EQ(r.records[0]["unit"], "ulp-float");
  EXPECT_DOUBLE_EQ(r.records[0]["error_in_unit"].get<double>(), 1.0);
  EXPECT_DOUBLE_EQ(r.records[0]["error"].get<double>(), ulp_f / eps);  // 2^29 ulps of double at 1.0
  o.unit = value_unit::rel;
  const check_result rel = times(s, csv, o);
  EXPECT_DOUBLE_EQ(rel.rows[0].error, ulp_f / 0.125);
  EXPECT_DOUBLE_EQ(rel.records[0]["error_in_unit"].get<double>(), ulp_f / 0.125);
  EXPECT_DOUBLE_EQ(rel.records[0]["error"].get<double>(), ulp_f / eps);  // the records' scale is the ulp one
  // A channel crossing zero keeps the range where the value is small: one float ulp of the range
  // at a value of 0 is 1, not the 1 / ulp(0) of ulps of the value alone.
  const spec_doc z(R"({"type": "channel", "tool": "exact", "keys": [
    {"time": 0, "value": -1, "interpolation": "linear"}, {"time": 10, "value": 1}]})");
  o.unit = value_unit::ulp_float;
  const check_result rz = times(z, "t,value\n5," + g17(2 * ulp_f) + "\n", o);
  EXPECT_DOUBLE_EQ(rz.rows[0].scale, 2.0);
  EXPECT_DOUBLE_EQ(rz.rows[0].error, 1.0);
}

// The unit follows the digits the CSV carries: a float program's %.9g is read in float ulps (its
// own rounding is then below one), a double's %.17g in double ulps; values cut to 5 digits get a
// warning, exact short values (0.5) do not.
TEST(check_times, the_unit_follows_the_digits_and_warns_when_they_cannot_carry_it) {
  const spec_doc s(snappy);
  const auto text = [](const char* fmt) {
    std::string csv = "t,value\n";
    for (double t : {0.1, 0.3, 0.6}) {
      char b[64];
      std::snprintf(b, sizeof b, fmt, static_cast<double>(snappy_value(t)));
      csv += g17(t) + "," + b + "\n";
    }
    return csv;
  };
  const check_result f9 = times(s, text("%.9g")), f17 = times(s, text("%.17g")), f5 = times(s, text("%.5g"));
  EXPECT_EQ(f9.unit, value_unit::ulp_float);
  EXPECT_LE(f9.summary.max, 0.5);  // rounding to 9 digits: < 5e-9 relative, below half a float ulp (6e-8)
  EXPECT_TRUE(f9.digits_warning.empty());
  EXPECT_EQ(f17.unit, value_unit::ulp_double);
  EXPECT_LE(f17.summary.max, 0.5);
  EXPECT_EQ(f5.unit, value_unit::ulp_float);
  EXPECT_THAT(f5.digits_warning, HasSubstr("5 significant digits"));
  EXPECT_TRUE(times(spec_doc(ramp), "t,value\n1,0.5\n").digits_warning.empty());
}

// An empty derivative cell (what `sample` writes where the slope is infinite) is not checked and
// counted; where the truth's derivative is infinite the cell is not checked either. An empty cell
// elsewhere, a u column on a channel spec's curve-only data, a glTF rotation and unknown columns
// are refused, naming what is wrong.
TEST(check_times, empty_and_unbounded_derivative_cells_are_not_checked) {
  const spec_doc s(snappy);
  const check_result r =
      times(s, "t,value,dvalue\n0,0,\n0.5," + g17(static_cast<double>(snappy_value(0.5L))) + ",0.0675\n");
  EXPECT_EQ(r.unchecked, 1u);
  EXPECT_TRUE(std::isnan(r.rows[0].derivative_errors[0]));
  EXPECT_THAT(invalid_input_of([&] { (void)times(s, "t,value\n0.5,\n"); }),
              HasSubstr("mine.csv: row 2, column value: an empty cell is not finite"));
  EXPECT_THAT(invalid_input_of([&] { (void)times(s, "t,value,speed\n0.5,1,2\n"); }),
              HasSubstr("column speed: unknown column"));
  const spec_doc rot(R"({"type": "channel", "tool": "gltf", "path": "rotation", "interpolation": "linear",
    "times": [0, 1], "values": [[0, 0, 0, 1], [0, 0, 1, 0]]})");
  EXPECT_THROW((void)times(rot, "t,value\n0.5,1\n"), curvebench::io::spec_error);
  // A curve spec refuses a t column, saying that time is for channels.
  const spec_doc curve(R"({"type": "bezier", "points": [[0,0],[1,2],[3,2],[4,0]]})");
  EXPECT_THAT(invalid_input_of([&] { (void)times(curve, "t,x,y\n0.5,1,1\n"); }),
              HasSubstr("time columns are for channel specs"));
  EXPECT_THAT(invalid_input_of([&] { (void)times(curve, "u,x,y\n0.5,,1\n"); }), HasSubstr("column x: an empty cell"));
}

// Blender evaluates an F-curve at float32(t): near frame 1e5 float32's spacing is 1/128 frame, so
// on a steep segment (5 per frame) the time's rounding moves the value by up to 0.02. The tool's
// own evaluation (sample --as-tool, check --against tool) reproduces Blender 3.4.1's recorded
// values there to float rounding; the truth at the double time does not, and says so in a check
// against it.
TEST(check_times, blenders_own_evaluation_rounds_the_time_to_float) {
  std::ifstream in(curvebench::testing::source_dir() + "/tests/data/blender_fcurves.json");
  const nlohmann::json data = nlohmann::json::parse(in);
  const nlohmann::json* rec = nullptr;
  for (const auto& c : data.at("channels"))
    if (c.at("name") == "far/steep_linear") rec = &c;
  ASSERT_NE(rec, nullptr);
  const spec_doc s(R"({"type": "channel", "tool": "blender", "keys": [
    {"time": 100000, "value": 0, "interpolation": "linear"}, {"time": 100010, "value": 50}]})");
  const channel_values tool = channel_values_of(s.f, check_against::tool);
  const channel_values truth = channel_values_of(s.f, check_against::truth);
  EXPECT_EQ(tool.bits, 32);
  double moved = 0;
  std::string csv = "t,value\n";
  for (std::size_t j = 0; j < rec->at("times").size(); ++j) {
    const double t = rec->at("times")[j], blender = rec->at("values")[j];
    // Within one float ulp of the value: Blender's linear interpolation rounds in another order
    // (7.5 against the model's 7.50000048 at t = 100001.501; equal at the other times).
    EXPECT_LE(std::abs(*tool.at(t, 0) - blender), std::numeric_limits<float>::epsilon() * std::abs(blender))
        << "t = " << t;
    moved = std::max(moved, std::abs(*truth.at(t, 0) - blender));
    csv += g17(t) + "," + g17(blender) + "\n";
  }
  EXPECT_GT(moved, 0.018);  // 0.0184 at t = 100000.301: 3.7 float32 time spacings x 5 per frame
  check_options o;
  o.against = check_against::tool;
  EXPECT_LE(times(s, csv, o).summary.max, 1.0);  // float ulps of the range: 0.08 measured
  // Blender's values carry float's digits, so the default unit is float ulps of the range 50:
  // 0.0184 is 3093 of them.
  const check_result against_truth = times(s, csv);
  EXPECT_EQ(against_truth.unit, value_unit::ulp_float);
  EXPECT_GT(against_truth.summary.max, 3000.0);
}
