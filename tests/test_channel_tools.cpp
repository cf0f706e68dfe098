// The tool models (channel/tool_model.hpp, channel/tools/<tool>.hpp) and their one list
// (io/tools/all.hpp): every tool of all_tools satisfies the concepts and parses its own example;
// each tool's model of generic keys (from_keys) evaluates what the keys say where the tool can hold
// them exactly, and refuses with the tool's reason where it cannot; the channel family's field docs
// are assembled from the tools'.
//
// Tolerances (against the exact tool's model of the same keys at 50 digits, in ulps of the value
// range of the storage precision):
//   - maya (double, isolate_brent), usd (double, closed_form), exact (double, exact): the keys are
//     the same bezier segments (Maya's weighted tangents are 3 x the handles; USD's widths and
//     slopes give back the handles; keep_ratio leaves monotone segments alone), so only the time
//     solver and the rounding of the handles through those forms differ: 64 ulps (test_usd.cpp
//     measured 58 for the closed form on harder segments; isolate_brent and exact stay below 8);
//   - blender (float storage, exact solver): the keys rounded to float, 64 eps_float (the rounding
//     of the data moves the value by a few eps_float times the slopes, below 3 here);
//   - gltf (cubicspline sampler): the handles at a third of each interval make the keys' bezier
//     the Hermite the sampler evaluates, 64 ulps (one Hermite evaluation against a solved bezier);
//   - css (table_newton): ease = cubic-bezier(0.25, 0.1, 0.25, 1), 1e-6 of the range (table_newton
//     stops at a time residual of 1e-7, times the slope of ease, below 2 here).
#include "support/fixtures.hpp"

#include "curvebench/channel/tool_model.hpp"
#include "curvebench/channel/tools/css.hpp"
#include "curvebench/io/families/channel.hpp"
#include "curvebench/io/spec.hpp"
#include "curvebench/reference/multiprecision.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>
#include <span>
#include <string>
#include <type_traits>
#include <vector>

namespace cb = curvebench;
namespace cbt = curvebench::testing;
namespace ch = curvebench::channel;
using R = cb::real50;
using ::testing::HasSubstr;

namespace {

static_assert(ch::tool_model<ch::tools::maya::model<R>>);
static_assert(ch::tool_model<ch::tools::gltf::model<float>>);
static_assert(ch::tools::blender::model<double>::storage_bits == 32);
static_assert(ch::tools::usd::model<float>::storage_bits == 64);
static_assert(cb::io::all_tools::size == cb::io::all_tool_names.size());

std::vector<ch::key<double>> keys_at(double third) {
  // Four bezier keys; the handles' time lengths are `third` of each interval (monotone for <= 1/2).
  const double t[] = {0, 1, 2.5, 3}, v[] = {0, 1, -0.5, 0.25}, s[] = {0.5, -1, 0.2, 2};
  std::vector<ch::key<double>> k(4);
  for (int i = 0; i < 4; ++i) {
    k[i].time = t[i], k[i].value = v[i], k[i].interp = ch::interpolation::bezier;
    if (i > 0) k[i].in = {-third * (t[i] - t[i - 1]), -third * (t[i] - t[i - 1]) * s[i]};
    if (i < 3) k[i].out = {third * (t[i + 1] - t[i]), third * (t[i + 1] - t[i]) * s[i]};
  }
  return k;
}

// The largest error of a tool's model of the keys over the keyed range, in storage ulps of the
// value range, against the exact tool's model of the same keys at 50 digits.
template <class Tool>
double worst_against_exact(const std::vector<ch::key<double>>& keys) {
  using S = typename Tool::storage_type;
  const auto m = Tool::template from_keys<S>(std::span<const ch::key<double>>(keys));
  const auto truth = ch::tools::exact::from_keys<R>(std::span<const ch::key<double>>(keys));
  const double lo = keys.front().time, hi = keys.back().time;
  std::vector<R> v;
  for (int j = 0; j <= 400; ++j) {
    const S t = static_cast<S>(lo + (hi - lo) * j / 400);
    v.push_back(truth.value(R(t)));
  }
  const R range = *std::max_element(v.begin(), v.end()) - *std::min_element(v.begin(), v.end());
  double worst = 0;
  for (int j = 0; j <= 400; ++j) {
    const S t = static_cast<S>(lo + (hi - lo) * j / 400);
    const R e = abs(R(m.value(t)) - v[static_cast<std::size_t>(j)]) / (range * R(std::numeric_limits<S>::epsilon()));
    worst = std::max(worst, static_cast<double>(e));
  }
  return worst;
}

TEST(ChannelTools, EveryToolParsesItsExampleAndNamesItself) {
  std::set<std::string_view> names;
  cb::io::for_each_tool([&](auto t) {
    using T = typename decltype(t)::type;
    EXPECT_TRUE(names.insert(T::name).second) << "two tools named " << T::name;
    const nlohmann::json j = nlohmann::json::parse(cb::io::tool_spec<T>::example);
    EXPECT_EQ(j.at("tool").get<std::string>(), T::name);
    const auto m = cb::io::tool_spec<T>::template parse<double>(cb::io::root(j, "example"));
    EXPECT_EQ(decltype(m)::name, T::name);
    EXPECT_EQ(decltype(m)::storage_bits, ch::storage_bits_of<typename T::storage_type>);
    // The type-erased model of the spec is the tool model's.
    const auto erased = cb::io::channel_model_of_spec<double>(cb::io::root(j, "example"));
    const double t0 = m.view().keys().front().time, t1 = m.view().keys().back().time;
    for (double x : {t0, (t0 + t1) / 3, t1})
      for (int order = 0; order <= 2; ++order) EXPECT_EQ(erased.at(x, order), m.derivative(x, order)) << T::name;
  });
  EXPECT_EQ(names.size(), cb::io::all_tools::size);
}

TEST(ChannelTools, ModelsOfKeysEvaluateTheKeys) {
  const auto thirds = keys_at(1.0 / 3), longer = keys_at(0.45);
  EXPECT_LE(worst_against_exact<ch::tools::exact>(longer), 64);
  EXPECT_LE(worst_against_exact<ch::tools::maya>(longer), 64);
  EXPECT_LE(worst_against_exact<ch::tools::usd>(longer), 64);
  EXPECT_LE(worst_against_exact<ch::tools::blender>(longer), 64);
  EXPECT_LE(worst_against_exact<ch::tools::gltf>(thirds), 64);
  // glTF drops the handle lengths: with handles at 0.45 of the interval it is another curve.
  EXPECT_GT(worst_against_exact<ch::tools::gltf>(longer), 1e6);
  const std::vector<ch::key<double>> ease{{0, 0, {}, {0.25, 0.1}, ch::interpolation::bezier},
                                          {1, 1, {-0.75, 0}, {}, ch::interpolation::bezier}};
  EXPECT_LE(worst_against_exact<ch::tools::css>(ease) * std::numeric_limits<double>::epsilon(), 1e-6);
}

// steps() evaluates in closed form (css_steps), with no keys made: against the channel of the
// n + 1 keys (its own binary search over the key times) it is bit-identical, at every key time,
// one ulp either side of it and between keys, for every position and n up to 2^16; above 2^16 the
// model evaluates without a view (the reason named), the value the step algorithm's at times whose
// key is known exactly (k / n for n a power of two), and n past 2^53 is refused.
TEST(ChannelTools, CssStepsEvaluateInClosedFormForAnyCount) {
  using ch::step_position;
  for (const step_position pos :
       {step_position::jump_start, step_position::jump_end, step_position::jump_none, step_position::jump_both}) {
    for (const long long n : {2LL, 3LL, 7LL, 1000LL, 65536LL}) {
      SCOPED_TRACE(std::to_string(n) + " " + std::string(ch::to_string(pos)));
      const auto f = ch::css_easing<double>::steps(n, pos);
      const auto m = ch::tools::css::of_easing<double>(f);
      const ch::channel<double> keys(ch::css_keys<double>(f), ch::extrapolation::constant, ch::extrapolation::constant);
      ASSERT_FALSE(m.view_refusal().has_value());
      std::vector<double> ts{-1.0, -0.0, 1.0, 1.5, std::nextafter(1.0, 0.0), std::nextafter(0.0, 1.0)};
      const long long stride = std::max(1LL, n / 257);
      for (long long k = 1; k < n; k += stride) {
        const double tk = static_cast<double>(k) / static_cast<double>(n);
        ts.insert(ts.end(), {tk, std::nextafter(tk, 0.0), std::nextafter(tk, 1.0), tk + 0.5 / static_cast<double>(n)});
      }
      for (double t : ts) {
        EXPECT_EQ(m.value(t), keys.value(t)) << "t = " << t;
        EXPECT_EQ(m.derivative(t, 1), 0.0);
        EXPECT_EQ(m.derivative(t, 2), 0.0);
      }
    }
  }
  EXPECT_THAT(
      ch::tools::css::of_easing<double>(ch::css_easing<double>::steps(ch::css_max_step_keys + 1)).view_refusal(),
      ::testing::Optional(HasSubstr("steps(65537) has no curve view")));
  // Past the view's cap: no view, the reason named; n = 2^30 (k / n exact), jump-end, so the value
  // at k / n and just below it is k / n and (k - 1) / n.
  const long long n = 1LL << 30;
  const auto big = ch::tools::css::of_easing<double>(ch::css_easing<double>::steps(n));
  ASSERT_TRUE(big.view_refusal().has_value());
  EXPECT_THAT(*big.view_refusal(), HasSubstr("steps(1073741824) has no curve view"));
  EXPECT_THAT(cbt::message_of([&] { (void)big.view(); }), HasSubstr("sample --at and check --values evaluate it"));
  EXPECT_EQ(big.key_times(), (std::vector<double>{0, 1}));
  for (const long long k : {1LL, 12345LL, n / 3, n - 1}) {
    const double tk = std::ldexp(static_cast<double>(k), -30);
    EXPECT_EQ(big.value(tk), tk) << k;
    EXPECT_EQ(big.value(std::nextafter(tk, 0.0)), std::ldexp(static_cast<double>(k - 1), -30)) << k;
  }
  EXPECT_EQ(big.value(1.0), 1.0);
  EXPECT_EQ(big.value(-3.0), 0.0);
  EXPECT_THAT(cbt::message_of([&] { (void)big.value(std::numeric_limits<double>::infinity()); }),
              HasSubstr("finite times only"));
  // In 50 digits the same, and n = 1e9 (not a power of two): the key below t is the last k with
  // k / n <= t, checked against the definition.
  const auto b50 = ch::tools::css::of_easing<cb::real50>(ch::css_easing<double>::steps(1000000000));
  for (const long long k : {1LL, 999999999LL, 333333333LL}) {
    const cb::real50 tk = cb::real50(k) / cb::real50(1000000000);
    EXPECT_EQ(b50.value(tk), tk) << k;
    EXPECT_EQ(b50.value(tk - cb::real50(1e-30)), cb::real50(k - 1) / cb::real50(1000000000)) << k;
  }
  EXPECT_NO_THROW((void)ch::css_easing<double>::steps(1LL << 53, step_position::jump_both));
  EXPECT_THAT(cbt::message_of([] { (void)ch::css_easing<double>::steps((1LL << 53) + 1); }), HasSubstr("at most 2^53"));
}

TEST(ChannelTools, KeysAToolCannotHoldAreRefusedWithTheReason) {
  auto keys = keys_at(0.4);
  keys[1].interp = ch::interpolation::step_next;
  cb::io::for_each_tool([&](auto t) {
    using T = typename decltype(t)::type;
    if constexpr (!std::is_same_v<T, ch::tools::exact>) {
      EXPECT_THAT(cbt::message_of([&] { (void)T::template from_keys<double>(keys); }),
                  HasSubstr("keys[1] is step_next"))
          << T::name;
    }
  });
  EXPECT_THAT(cbt::message_of([&] { (void)ch::tools::css::from_keys<double>(keys_at(0.4)); }),
              HasSubstr("from time 0 to time 1"));
  auto vertical = keys_at(0.4);
  vertical[2].out = {0, 1};
  EXPECT_THAT(cbt::message_of([&] { (void)ch::tools::usd::from_keys<double>(vertical); }), HasSubstr("vertical"));
  EXPECT_THAT(cbt::message_of([&] { (void)ch::tools::gltf::from_keys<double>(vertical); }), HasSubstr("vertical"));
  EXPECT_THAT(cbt::message_of([&] { (void)ch::tools::maya::from_keys<double>(vertical); }),
              HasSubstr("keys[2]: a handle of zero time length"));
  auto mixed = keys_at(0.4);
  mixed[0].interp = ch::interpolation::linear;
  EXPECT_THAT(cbt::message_of([&] { (void)ch::tools::gltf::from_keys<double>(mixed); }), HasSubstr("mix"));
}

// Blender holds F-curves in float32: a finite double past float's range is refused naming the key's
// field (it used to become inf, reported as "keys[0].value = inf: must be finite"); in double
// the same keys are held.
TEST(ChannelTools, BlenderRefusesKeysPastFloatRangeNamingTheField) {
  auto big = keys_at(0.4);
  big[1].value = 1e300;
  EXPECT_THAT(cbt::message_of([&] { (void)ch::tools::blender::from_keys<float>(big); }),
              HasSubstr("keys[1].value = " + cb::to_text(1e300) +
                        " is past float's range (3.4e38): Blender stores F-curves in float32"));
  EXPECT_NO_THROW((void)ch::tools::blender::from_keys<double>(big));
  auto handle = keys_at(0.4);
  handle[0].out.dv = 1e39;
  EXPECT_THAT(cbt::message_of([&] { (void)ch::tools::blender::from_keys<float>(handle); }),
              HasSubstr("keys[0].value + out.dv = " + cb::to_text(1e39) + " is past float's range"));
  auto fits = keys_at(0.4);
  fits[2].value = 3e38;  // within float's range: held
  EXPECT_NO_THROW((void)ch::tools::blender::from_keys<float>(fits));
}

TEST(ChannelTools, TheFamilyFieldsAreAssembledFromTheTools) {
  const auto& fields = cb::io::channel_family::fields;
  const auto doc = [&](std::string_view name) {
    for (const auto& f : fields)
      if (f.name == name) return std::string(f.doc);
    return std::string();
  };
  EXPECT_EQ(fields.front().name, "tool");
  EXPECT_TRUE(fields.front().required());
  std::string listed;
  for (std::size_t i = 0; i < cb::io::all_tool_names.size(); ++i)
    listed += std::string(i == 0                                   ? ""
                          : i + 1 == cb::io::all_tool_names.size() ? " or "
                                                                   : ", ") +
              std::string(cb::io::all_tool_names[i]);
  EXPECT_EQ(doc("tool"), "whose rules evaluate the keys: " + listed);
  EXPECT_THAT(doc("keys"), HasSubstr("exact: [{time, value, interpolation"));
  EXPECT_THAT(doc("keys"), HasSubstr("; maya: [{time, value, in_type"));
  EXPECT_THAT(doc("keys"), HasSubstr("; blender: [{time, value, handle_left"));
  EXPECT_THAT(doc("before"), HasSubstr("exact: extrapolation before the first key"));
  EXPECT_THAT(doc("before"), HasSubstr("; usd: held, linear, sloped"));
  EXPECT_THAT(doc("solver"), HasSubstr("isolate_brent"));
  // Every tool's field appears once.
  cb::io::for_each_tool([&](auto t) {
    for (const auto& f : cb::io::tool_spec<typename decltype(t)::type>::fields)
      EXPECT_EQ(std::count_if(fields.begin(), fields.end(), [&](const auto& g) { return g.name == f.name; }), 1)
          << f.name;
  });
  EXPECT_EQ(std::size(cb::io::channel_family::examples), cb::io::all_tools::size);
}

TEST(ChannelTools, AnUnknownToolIsRefusedListingEveryTool) {
  const nlohmann::json j = {{"type", "channel"}, {"tool", "no_such_tool"}};
  std::string listed;
  for (std::string_view n : cb::io::all_tool_names) listed += (listed.empty() ? "" : ", ") + std::string(n);
  EXPECT_THAT(cbt::message_of([&] { (void)cb::io::channel_model_of_spec<double>(cb::io::root(j, "spec")); }),
              HasSubstr("\"no_such_tool\" is not one of: " + listed));
  EXPECT_THAT(listed, HasSubstr("exact, css, gltf, maya, blender, usd"));
}

}  // namespace
