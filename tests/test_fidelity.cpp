// The fidelity measure (harness/fidelity.hpp) on recordings whose tool values are known in closed
// form: linear keys (the value at any time is the chord, exact in binary at the chosen times), a
// value moved by a known amount (a disagreement of exactly that fraction of the range), a refused
// channel, the per-feature counts and the file errors.
#include "harness/fidelity.hpp"

#include "support/fixtures.hpp"

#include "curvebench/core/error.hpp"
#include "curvebench/io/json_fields.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

namespace cb = curvebench;
namespace h = curvebench::harness;
using ::testing::HasSubstr;

namespace {

// Maya, linear tangents from (0, 0) to (10, 5) and constant infinity: v(t) = t / 2 inside, 5 after.
const char* maya_linear = R"({"type": "channel", "tool": "maya",
  "keys": [{"time": 0, "value": 0, "in_type": "linear", "out_type": "linear"},
           {"time": 10, "value": 5, "in_type": "linear", "out_type": "linear"}]})";

nlohmann::json recording(const std::string& channels) {
  return cb::io::parse(R"({"tool": "maya", "source": {"implementation": "closed form", "commit": "none"},
                           "channels": [)" +
                           channels + "]}",
                       "test");
}

std::string channel(const std::string& name, const std::string& features, const std::string& spec,
                    const std::string& values, const std::string& extra = "") {
  return R"({"name": ")" + name + R"(", "features": [)" + features + R"(], "spec": )" + spec +
         R"(, "t": [0, 2.5, 5, 10, 20], "value": )" + values + extra + "}";
}

}  // namespace

TEST(fidelity, exact_values_agree_and_a_moved_value_is_measured) {
  // Range 5; moving the value at t = 5 (slope 1/2: the scale there is 5 + 5 / 2 = 7.5) by 2^-20
  // (2.5 + 2^-20 = 2.50000095367431640625 exactly) is an error of 2^-20 / 7.5: well above agree_ulps eps(double)
  // (2.8e-14), so a disagreement, measured to rounding (one division).
  const double moved = std::ldexp(1.0, -20);
  const h::fidelity_result r =
      h::measure_fidelity(recording(channel("exact", R"("tangent:linear")", maya_linear, "[0, 1.25, 2.5, 5, 5]") + "," +
                                    channel("moved", R"("tangent:linear", "post:constant")", maya_linear,
                                            "[0, 1.25, 2.50000095367431640625, 5, 5]")),
                          "rec.json");
  ASSERT_EQ(r.channels.size(), 2u);
  EXPECT_EQ(r.tool, "maya");
  EXPECT_EQ(r.channels[0].error, 0);
  EXPECT_TRUE(r.channels[0].agrees());
  EXPECT_EQ(r.channels[0].bits, 64);
  EXPECT_DOUBLE_EQ(r.channels[1].error, moved / 7.5);
  EXPECT_EQ(r.channels[1].worst_t, 5);
  EXPECT_EQ(r.channels[1].model, 2.5);
  EXPECT_FALSE(r.channels[1].agrees());
  EXPECT_EQ(r.agree, 1u);
  EXPECT_EQ(r.refused, 0u);
  EXPECT_DOUBLE_EQ(r.max_error, moved / 7.5);
  // Per feature: tangent:linear has both channels, post:constant only the moved one.
  ASSERT_EQ(r.features.size(), 2u);
  EXPECT_EQ(r.features[0].feature, "post:constant");
  EXPECT_EQ(r.features[0].channels, 1u);
  EXPECT_EQ(r.features[0].agree, 0u);
  EXPECT_EQ(r.features[1].feature, "tangent:linear");
  EXPECT_EQ(r.features[1].channels, 2u);
  EXPECT_EQ(r.features[1].agree, 1u);
  const nlohmann::json j = h::to_json({r});
  EXPECT_EQ(j["recordings"][0]["disagree"].size(), 1u);
  EXPECT_EQ(j["recordings"][0]["disagree"][0]["name"], "moved");
  EXPECT_EQ(j["recordings"][0]["source"]["implementation"], "closed form");
}

TEST(fidelity, a_refused_channel_is_counted_with_todays_reason) {
  const std::string bad = R"({"type": "channel", "tool": "maya",
    "keys": [{"time": 0, "value": 0, "in_type": "bogus"}, {"time": 10, "value": 5}]})";
  const h::fidelity_result r = h::measure_fidelity(
      recording(channel("bogus", R"("tangent:bogus")", bad, "[0, 1, 2, 3, 4]", R"(, "refused": "old reason")")),
      "rec.json");
  ASSERT_EQ(r.channels.size(), 1u);
  EXPECT_TRUE(r.channels[0].refused);
  EXPECT_TRUE(r.channels[0].marked_refused);
  EXPECT_FALSE(r.channels[0].agrees());
  EXPECT_THAT(r.channels[0].reason, HasSubstr("keys[0].in_type: not a Maya tangent type"));
  EXPECT_EQ(r.refused, 1u);
  EXPECT_EQ(r.features[0].refused, 1u);
}

TEST(fidelity, a_float_tool_is_held_to_float) {
  // Blender's linear interpolation in float: v(2.5) = 1.25 exactly; agree_ulps eps(float) is the bound.
  const char* blender = R"({"type": "channel", "tool": "blender", "keys": [
    {"time": 0, "value": 0, "interpolation": "linear"}, {"time": 10, "value": 5, "interpolation": "linear"}]})";
  const h::fidelity_result r =
      h::measure_fidelity(cb::io::parse(R"({"tool": "blender", "source": {}, "channels": [)" +
                                            channel("linear", "", blender, "[0, 1.25, 2.5, 5, 5.0000001]") + "]}",
                                        "b.json"),
                          "b.json");
  EXPECT_EQ(r.channels[0].bits, 32);
  EXPECT_DOUBLE_EQ(r.channels[0].tolerance(), h::agree_ulps * std::numeric_limits<float>::epsilon());
  EXPECT_NEAR(r.channels[0].error, 1e-7 / 5, 1e-15);  // the last value's 1e-7 (constant extrapolation)
  EXPECT_TRUE(r.channels[0].agrees());
}

TEST(fidelity, malformed_recordings_name_the_field) {
  const auto msg = [](const std::string& text) {
    return cb::testing::invalid_input_of([&] { (void)h::measure_fidelity(cb::io::parse(text, "r.json"), "r.json"); });
  };
  EXPECT_THAT(msg(R"({"source": {}, "channels": []})"), HasSubstr("tool"));
  EXPECT_THAT(msg(R"({"tool": "maya", "source": {}, "channels": [], "extra": 1})"), HasSubstr("extra"));
  EXPECT_THAT(msg(R"({"tool": "maya", "source": {}, "channels": [)" + channel("n", "", maya_linear, "[0, 1]") + "]}"),
              HasSubstr("5 times and 2 values"));
  // A channel of another tool in a maya recording.
  const char* blender = R"({"type": "channel", "tool": "blender", "keys": [{"time": 0, "value": 0}]})";
  EXPECT_THAT(msg(R"({"tool": "maya", "source": {}, "channels": [)" + channel("b", "", blender, "[0,0,0,0,0]") + "]}"),
              HasSubstr("not the recording's tool"));
}

TEST(fidelity, a_channel_the_tool_gave_no_values_for_is_unverified) {
  // Recorder fields of its own (Ts's pre_value) are kept and not measured.
  const h::fidelity_result r = h::measure_fidelity(
      recording(R"({"name": "hermite", "features": ["curve:hermite"], "spec": )" + std::string(maya_linear) +
                R"(, "t": [0, 1], "unverified": "the tool does not evaluate these", "pre_value": [0, 0]})"),
      "rec.json");
  ASSERT_EQ(r.channels.size(), 1u);
  EXPECT_TRUE(r.channels[0].unverified);
  EXPECT_FALSE(r.channels[0].agrees());
  EXPECT_EQ(r.channels[0].reason, "the tool does not evaluate these");
  EXPECT_EQ(r.unverified, 1u);
  EXPECT_EQ(r.agree, 0u);
  EXPECT_EQ(r.features[0].unverified, 1u);
  EXPECT_EQ(h::to_json({r})["recordings"][0]["unverified_channels"][0]["name"], "hermite");
}

TEST(fidelity, values_near_the_largest_double_are_measured_without_overflow) {
  // Recorded +-1e308 against a model of 0 .. 5: the range, 2e308, passes double (it overflowed to
  // infinity, and every error divided by it was 0: "1 of 1 agree, max error 0"). Taken of halves it
  // is 1e308, so the error at t = 0 is (1e308 / 2) / 1e308 = 1/2 (the slope's reach, 0 there, is
  // nothing beside it): a disagreement, measured.
  const std::string big = R"({"name": "huge", "features": ["tangent:linear"], "spec": )" + std::string(maya_linear) +
                          R"(, "t": [0, 10], "value": [1e308, -1e308]})";
  const h::fidelity_result r = h::measure_fidelity(recording(big), "rec.json");
  ASSERT_EQ(r.channels.size(), 1u);
  EXPECT_TRUE(std::isinf(r.channels[0].scale));
  EXPECT_DOUBLE_EQ(r.channels[0].error, 0.5);
  EXPECT_FALSE(r.channels[0].agrees());
  EXPECT_EQ(r.agree, 0u);
  EXPECT_DOUBLE_EQ(r.max_error, 0.5);
  EXPECT_EQ(h::to_json({r})["recordings"][0]["disagree"][0]["name"], "huge");
  // One value of 1e308 and the model's: the gap alone passes double only through the halves too.
  const std::string one =
      R"({"name": "one", "features": [], "spec": )" + std::string(maya_linear) + R"(, "t": [10], "value": [-1.7e308]})";
  const h::fidelity_result r1 = h::measure_fidelity(recording(one), "rec.json");
  EXPECT_NEAR(r1.channels[0].error, (5 + 1.7e308) / (1.7e308 + 5), 1e-12);  // |5 - v| / (|v| + |t V'|)
  EXPECT_FALSE(r1.channels[0].agrees());
}

TEST(fidelity, a_recorded_value_that_is_not_finite_is_refused_naming_the_channel) {
  // JSON text has no NaN (and io::parse refuses a number past double), but a recording built in
  // memory can hold one: refused naming the channel and the index, not measured as an error of 0.
  for (const char* key : {"value", "t"}) {
    nlohmann::json rec = recording(channel("late", "", maya_linear, "[0, 1.25, 2.5, 5, 5]"));
    rec["channels"][0][key][3] = std::numeric_limits<double>::quiet_NaN();
    const std::string msg = cb::testing::invalid_input_of([&] { (void)h::measure_fidelity(rec, "rec.json"); });
    EXPECT_THAT(msg, HasSubstr("rec.json.channels[0]." + std::string(key) + "[3]: channel \"late\": " + key +
                               "[3] is not a finite number"));
    rec["channels"][0][key][3] = std::numeric_limits<double>::infinity();
    EXPECT_THAT(cb::testing::invalid_input_of([&] { (void)h::measure_fidelity(rec, "rec.json"); }),
                HasSubstr("channel \"late\""));
    rec["channels"][0][key][3] = "5";
    EXPECT_THAT(cb::testing::invalid_input_of([&] { (void)h::measure_fidelity(rec, "rec.json"); }),
                HasSubstr("is not a finite number, got \"5\""));
  }
}

TEST(fidelity, an_unverified_channel_is_no_disagreement_and_no_evaluation) {
  const h::fidelity_result r =
      h::measure_fidelity(recording(R"({"name": "hermite", "features": [], "spec": )" + std::string(maya_linear) +
                                    R"(, "t": [0, 1], "unverified": "the tool does not evaluate these"})"),
                          "rec.json");
  EXPECT_EQ(r.evaluated(), 0u);
  const nlohmann::json j = h::to_json({r})["recordings"][0];
  EXPECT_TRUE(j["disagree"].empty());
  EXPECT_EQ(j["unverified_channels"].size(), 1u);
  EXPECT_EQ(h::measure_fidelity(recording(""), "rec.json").evaluated(), 0u);  // "channels": []
}
