// The family registry (io/registry.hpp): every spec type has a case file, documented fields,
// examples that build in double and real50 to the same curve, evaluation algorithms that agree
// with the default evaluation, audit hooks that rebuild the spec, and docs/specs.md's spec section
// is the registry's generated text.
#include "support/accuracy.hpp"
#include "support/source_dir.hpp"
#include "tools/families_section.hpp"

#include "curvebench/io/spec.hpp"

#include <gmock/gmock.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

namespace cb = curvebench;
namespace io = curvebench::io;
namespace cbt = curvebench::testing;
using ::testing::HasSubstr;

namespace {

// Tolerances, in eps(double) x the curve's size (the largest |coordinate| at the sample points).
// - double vs real50 build of an example: the same control data (exactly converted) evaluated in
//   two precisions; the double evaluation of these small (degree <= 3, <= 5 points) examples
//   errs by a few roundings of the coordinates: 8.
constexpr double twin_ulps = 8;
// - an evaluation algorithm vs the default evaluation of the same double curve: both err by a
//   few roundings on these examples; the issue asks for 8 eps x size.
constexpr double algorithm_ulps = 8;

std::string read_text(const std::filesystem::path& p) {
  std::ifstream in(p);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

/// n + 1 parameters spread over the domain, ends included.
template <int Dim>
std::vector<double> params_of(const cb::any_curve<double, Dim>& c, int n) {
  const auto d = c.domain();
  std::vector<double> u;
  for (int k = 0; k <= n; ++k) u.push_back(k == n ? d.hi : d.lo + (d.hi - d.lo) * k / n);
  return u;
}

template <int Dim>
double size_of(const cb::any_curve<double, Dim>& c, const std::vector<double>& us) {
  double s = 0;
  for (double u : us)
    for (int i = 0; i < Dim; ++i) s = std::max(s, std::abs(c(u)[i]));
  return s > 0 ? s : 1;
}

/// Calls f(std::integral_constant<int, Dim>) for the spec's dimension (2 or 3: the examples').
template <class F>
void with_dimension(const io::field& spec, F&& f) {
  switch (io::spec_dimension(spec)) {
    case 2: f(std::integral_constant<int, 2>{}); break;
    case 3: f(std::integral_constant<int, 3>{}); break;
    default: FAIL() << spec.path << ": examples are 2D or 3D";
  }
}

std::string build_error(const io::json& j) {
  try {
    with_dimension(io::root(j),
                   [&](auto dim) { (void)io::curve_from_spec<double, decltype(dim)::value>(io::root(j)); });
  } catch (const io::spec_error& e) {
    return e.what();
  }
  return "(no error)";
}

}  // namespace

TEST(registry, every_family_has_a_case_file_and_every_case_a_family) {
  std::set<std::string> case_types;
  for (const auto& e : std::filesystem::directory_iterator(curvebench::testing::source_dir() + "/bench/cases")) {
    if (e.path().extension() != ".json") continue;
    const io::json j = io::parse(read_text(e.path()), e.path().string());
    const std::string type = io::root(j, e.path().string()).member("type").string();
    EXPECT_NE(io::find_family(type), nullptr) << e.path() << ": type \"" << type << "\" is not in the registry";
    case_types.insert(type);
  }
  io::for_each_family([&](const io::family_descriptor& d) {
    EXPECT_TRUE(case_types.contains(std::string(d.type)))
        << "no case under bench/cases has \"type\": \"" << d.type << "\" (add bench/cases/<name>.json)";
  });
}

TEST(registry, every_family_appears_in_curvebench_list) {
#ifndef CURVEBENCH_TOOL
  GTEST_SKIP() << "the curvebench tool is not built in this configuration (CURVEBENCH_BUILD_BENCH=OFF)";
#else
  const std::string command = std::string(CURVEBENCH_TOOL) + " list families";
  FILE* pipe = popen(command.c_str(), "r");
  ASSERT_NE(pipe, nullptr) << command;
  std::string out;
  char buf[4096];
  for (std::size_t n; (n = std::fread(buf, 1, sizeof buf, pipe)) > 0;) out.append(buf, n);
  ASSERT_EQ(pclose(pipe), 0) << command << " failed:\n" << out;
  io::for_each_family([&](const io::family_descriptor& d) {
    EXPECT_THAT(out, HasSubstr("  " + std::string(d.type) + " ")) << "curvebench list families misses " << d.type;
    EXPECT_THAT(out, HasSubstr(std::string(d.summary))) << d.type;
    EXPECT_THAT(out, HasSubstr(io::fields_line(d))) << d.type;
  });
#endif
}

TEST(registry, names_are_unique_and_spec_types_follow_the_registry) {
  std::set<std::string_view> names;
  for (const auto& d : io::families()) EXPECT_TRUE(names.insert(d.type).second) << d.type << " twice";
  const auto types = io::spec_types();
  ASSERT_EQ(types.size(), io::families().size());
  for (std::size_t i = 0; i < types.size(); ++i) {
    const auto& d = io::families()[i];
    EXPECT_EQ(types[i].type, d.type);
    for (const auto& f : d.fields) EXPECT_THAT(std::string(types[i].fields), HasSubstr(std::string(f.name))) << d.type;
    EXPECT_EQ(io::find_family(d.type), &d);
  }
  EXPECT_EQ(io::find_family("bezir"), nullptr);
}

TEST(registry, fields_are_documented_and_required_ones_are_required) {
  const std::string md = io::families_markdown();
  for (const auto& d : io::families()) {
    SCOPED_TRACE(std::string(d.type));
    EXPECT_FALSE(d.summary.empty());
    EXPECT_EQ(d.summary.find('\n'), std::string_view::npos);
    ASSERT_FALSE(d.examples.empty());
    ASSERT_FALSE(d.fields.empty());
    std::set<std::string_view> seen;
    for (const auto& f : d.fields) {
      EXPECT_TRUE(seen.insert(f.name).second) << f.name << " documented twice";
      EXPECT_FALSE(f.doc.empty()) << f.name;
      EXPECT_EQ(f.doc.find('\n'), std::string_view::npos) << f.name;
      EXPECT_THAT(md, HasSubstr("  - `" + std::string(f.name) + "`" + (f.required() ? " (required)" : "") + ": " +
                                std::string(f.doc)));
    }
    for (auto text : d.examples) {
      const io::json j = io::parse(text, d.type);
      EXPECT_EQ(j.at("type"), std::string(d.type)) << text;
      for (const auto& [key, value] : j.items()) {
        if (key == "type") continue;
        EXPECT_NE(d.find_field(key), nullptr) << key << " in " << text << " is not documented";
      }
      // A required field is in every example, and the example without it names it as missing.
      for (const auto& f : d.fields) {
        if (!f.required()) continue;
        ASSERT_TRUE(j.contains(std::string(f.name))) << text << " lacks the required " << f.name;
        io::json without = j;
        without.erase(std::string(f.name));
        EXPECT_THAT(build_error(without), HasSubstr(std::string(f.name) + " is missing")) << text;
      }
    }
  }
  // An undocumented field is refused by every type.
  for (const auto& d : io::families()) {
    io::json j = io::parse(d.examples[0], d.type);
    j["not_a_field"] = 1;
    EXPECT_THAT(build_error(j), HasSubstr("unknown field \"not_a_field\" for type \"" + std::string(d.type) + "\""));
  }
}

TEST(registry, examples_build_the_same_curve_in_double_and_real50) {
  for (const auto& d : io::families()) {
    for (auto text : d.examples) {
      SCOPED_TRACE(std::string(text));
      const io::json j = io::parse(text, d.type);
      const io::field spec = io::root(j);
      with_dimension(spec, [&](auto dim) {
        constexpr int Dim = decltype(dim)::value;
        const auto c = io::curve_from_spec<double, Dim>(spec);
        const auto c50 = io::curve_from_spec<cb::real50, Dim>(spec);
        EXPECT_EQ(c.family(), d.type);
        EXPECT_EQ(c50.family(), d.type);
        EXPECT_EQ(cb::real50(c.domain().lo), c50.domain().lo);
        EXPECT_EQ(cb::real50(c.domain().hi), c50.domain().hi);
        const auto us = params_of(c, 8);
        const double size = size_of(c, us);
        for (double u : us)
          EXPECT_TRUE((cbt::point_within<double, Dim>(c(u), c50(cb::real50(u)), cb::real50(size), twin_ulps)))
              << "u = " << u;
      });
    }
  }
}

TEST(registry, evaluation_algorithms_agree_with_the_default_evaluation) {
  for (const auto& d : io::families()) {
    for (auto text : d.examples) {
      SCOPED_TRACE(std::string(text));
      const io::json j = io::parse(text, d.type);
      with_dimension(io::root(j), [&](auto dim) {
        constexpr int Dim = decltype(dim)::value;
        const auto c = io::curve_from_spec<double, Dim>(io::root(j));
        const auto algorithms = io::evaluation_algorithms<Dim>(c, j);
        ASSERT_EQ(algorithms.size(), d.algorithms.size());
        const auto us = params_of(c, 16);
        const double size = size_of(c, us);
        for (std::size_t a = 0; a < algorithms.size(); ++a) {
          EXPECT_EQ(algorithms[a].first, d.algorithms[a]);
          for (double u : us) {
            const auto p = algorithms[a].second(u);
            const auto q = c(u);
            for (int i = 0; i < Dim; ++i)
              EXPECT_LE(std::abs(p[i] - q[i]), algorithm_ulps * cb::epsilon<double>() * size)
                  << algorithms[a].first << " at u = " << u << ", coordinate " << i;
          }
        }
      });
    }
  }
  // An algorithm the family does not offer is refused by name.
  const io::json bez = io::parse(R"({"type": "bezier", "points": [[0,0],[1,1]]})");
  const auto c = io::curve_from_spec<double, 2>(io::root(bez));
  try {
    (void)io::bezier_family::evaluator<2>(c, bez, "de_boor");
    ADD_FAILURE() << "de_boor accepted for a bezier";
  } catch (const cb::invalid_input& e) {
    EXPECT_THAT(e.what(), HasSubstr("algorithm \"de_boor\" of type \"bezier\": not one of de_casteljau"));
  }
}

TEST(registry, audit_items_rebuild_the_spec) {
  for (const auto& d : io::families()) {
    for (auto text : d.examples) {
      SCOPED_TRACE(std::string(text));
      const io::json j = io::parse(text, d.type);
      const auto items = io::audit_items_of(j);
      const bool hermite_without_slopes = d.type == "hermite" && !j.contains("slopes");
      if (!d.audited() || hermite_without_slopes) {
        EXPECT_FALSE(items.has_value());
        continue;
      }
      ASSERT_TRUE(items.has_value());
      const std::size_t n = j.at("points").size();
      ASSERT_EQ(items->roles.size(), items->items.size());
      ASSERT_EQ(items->items.size(), d.type == "hermite" ? 2 * n : n);
      for (std::size_t i = 0; i < items->roles.size(); ++i)
        EXPECT_EQ(items->roles[i], i < n ? io::audit_role::point : io::audit_role::tangent) << i;
      // Unchanged items give the same curve; a moved item moves the curve.
      const auto c = io::curve_from_spec<double, 2>(io::root(j));
      const io::json same = io::with_items(j, items->items);
      const auto c_same = io::curve_from_spec<double, 2>(io::root(same));
      for (double u : params_of(c, 8)) EXPECT_EQ(c(u), c_same(u)) << u;
      cb::point_list<double, 2> moved = items->items;
      moved[0][1] += 0.5;
      const io::json m = io::with_items(j, moved);
      EXPECT_EQ(m.at("points").at(0).at(1).get<double>(), items->items[0][1] + 0.5);
      const auto c_moved = io::curve_from_spec<double, 2>(io::root(m));
      bool differs = false;
      for (double u : params_of(c, 8)) differs = differs || c_moved(u) != c(u);
      EXPECT_TRUE(differs);
    }
  }
  // Not audited: generated points, more than audit_max_points points, 3D points.
  EXPECT_FALSE(io::audit_items_of(io::parse(R"({"type": "polyline", "points": {"generate": "spiral", "count": 5}})")));
  io::json many = {{"type", "polyline"}, {"points", io::json::array()}};
  for (std::size_t i = 0; i <= io::audit_max_points; ++i) many["points"].push_back({static_cast<double>(i), 0.0});
  EXPECT_FALSE(io::audit_items_of(many));
  many["points"].erase(0);
  EXPECT_TRUE(io::audit_items_of(many));
  EXPECT_FALSE(io::audit_items_of(io::parse(R"({"type": "bezier", "points": [[0,0,0],[1,1,1]]})")));
}

TEST(registry, readme_spec_section_is_generated_from_the_registry) {
  const std::string readme = read_text(curvebench::testing::source_dir() + "/docs/specs.md");
  EXPECT_EQ(cb::docs::families_section(readme), io::families_markdown())
      << "docs/specs.md's families section differs from the registry; regenerate it with\n  "
      << cb::docs::regenerate_command;
  EXPECT_THROW((void)cb::docs::families_section("no markers"), cb::invalid_input);
}
