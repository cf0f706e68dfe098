// The harness library: settings follow the vocabulary, run_case's records carry only vocabulary ids
// and declared setting keys and agree with the reference, run_accuracy's exit code reports a
// failed case, the results name the real compiler, and the pool, writers and order fit do their jobs.
#include "harness/accuracy.hpp"
#include "harness/length_methods.hpp"
#include "harness/order_fit.hpp"
#include "harness/peers.hpp"
#include "harness/pool.hpp"
#include "harness/setting.hpp"
#include "harness/sweep.hpp"
#include "harness/vocabulary.hpp"
#include "harness/vocabulary_json.hpp"
#include "harness/writers.hpp"

#include "curvebench/arclength/result.hpp"
#include "curvebench/io/spec.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <set>
#include <sstream>
#include <stdexcept>
#include <tuple>
#include <vector>

namespace hv = curvebench::harness::vocab;
namespace fs = std::filesystem;
using curvebench::invalid_input;
using nlohmann::json;
using ::testing::HasSubstr;

namespace {

// Tolerances, each the gate's own number for the quick suite (reports/thresholds.json), applied to
// the two cases below (a quadratic and a cubic Bezier arch, both in the "smooth" group):
constexpr double adaptive_1e14_max = 2e-15;  // length, adaptive_gk tol=1e-14: measured max 3.0e-16
constexpr double gauss16_max = 1e-13;        // length, gauss n=16 on smooth cases: measured 9.4e-15
constexpr double eval_default_max = 8;       // eval, default, in eps x size: measured max 1.8
constexpr double newton_1e12_max = 2e-12;    // u_of_s, newton tol=1e-12: the tolerance, 2x margin

/// A scratch case directory, removed at the end of the test.
struct case_dir {
  fs::path path;
  explicit case_dir(const std::string& name) : path(fs::temp_directory_path() / ("curvebench_" + name)) {
    fs::remove_all(path);
    fs::create_directories(path);
  }
  ~case_dir() { fs::remove_all(path); }
  void add(const std::string& name, const std::string& body) const {
    std::ofstream(path / (name + ".json"))
        << R"({"name": ")" << name << R"(", "group": "smooth", "reason": "test case", )" << body << "}";
  }
};

const char* parabola = R"("type": "bezier", "points": [[0, 0], [1, 2], [3, 0]])";
const char* arch = R"("type": "bezier", "points": [[0, 0], [1, 2], [3, 2], [4, 0]])";

bool is_status(const std::string& s) {
  namespace al = curvebench::arclength;
  for (auto st : {al::result_status::converged, al::result_status::cap_hit, al::result_status::rounding_limited,
                  al::result_status::not_guaranteed})
    if (s == al::to_string(st)) return true;
  return false;
}

std::string read(const fs::path& p) {
  std::ifstream in(p);
  std::ostringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

}  // namespace

TEST(setting, formats_declared_keys_in_order) {
  using curvebench::harness::setting;
  EXPECT_EQ(setting(hv::methods::composite_gauss, {{"n", 3}, {"panels", 16}}), "n=3,panels=16");
  EXPECT_EQ(setting(hv::methods::adaptive_gk, {{"tol", 1e-10}}), "tol=1e-10");
  EXPECT_EQ(setting(hv::methods::forward_difference, {{"steps", std::size_t{256}}}), "steps=256");
  EXPECT_EQ(setting(hv::methods::segments_adaptive, {}), "");
}

TEST(setting, rejects_undeclared_missing_and_reordered_keys) {
  using curvebench::harness::setting;
  try {
    (void)setting(hv::methods::gauss, {{"panels", 4}});
    FAIL() << "an undeclared key was accepted";
  } catch (const invalid_input& e) {
    EXPECT_THAT(e.what(), HasSubstr("gauss"));
    EXPECT_THAT(e.what(), HasSubstr("\"panels\""));
  }
  EXPECT_THROW((void)setting(hv::methods::composite_gauss, {{"n", 3}}), invalid_input);                 // missing
  EXPECT_THROW((void)setting(hv::methods::composite_gauss, {{"panels", 4}, {"n", 3}}), invalid_input);  // order
  EXPECT_THROW((void)setting(hv::methods::segments_adaptive, {{"n", 3}}), invalid_input);               // none declared
  EXPECT_THROW((void)curvebench::harness::parse_setting("n=3,panels"), invalid_input);
}

// ---- the method tables (harness/length_methods.hpp) --------------------------------------------

namespace {
namespace h = curvebench::harness;

/// The ids of the vocabulary's methods with records of quantity q, in the vocabulary's order.
std::vector<std::string> vocabulary_methods_of(const hv::quantity& q) {
  std::vector<std::string> ids;
  for (const hv::method* m : hv::all_methods())
    if (hv::lists(m->quantities, q.id)) ids.emplace_back(m->id);
  return ids;
}

// The parabola P(u) = (2u, 4u(1 - u)), the quadratic Bezier [[0,0],[1,2],[2,0]]: |P'| = sqrt(4 + t^2)
// with t = 4 - 8u, so s(u) = (F(4) - F(4 - 8u)) / 8 with F(t) = t/2 sqrt(t^2 + 4) + 2 asinh(t/2),
// and L = s(1) = sqrt(5) + asinh(2) / 2. In double each is a handful of correctly rounded
// operations: within 16 eps of the length (the slack the checks below allow for it).
const char* closed_form_parabola = R"({"type": "bezier", "points": [[0, 0], [1, 2], [2, 0]]})";
double parabola_F(double t) { return t / 2 * std::sqrt(t * t + 4) + 2 * std::asinh(t / 2); }
double parabola_s(double u) { return (parabola_F(4) - parabola_F(4 - 8 * u)) / 8; }
constexpr double closed_form_slack = 16 * std::numeric_limits<double>::epsilon();
}  // namespace

TEST(method_table, rows_are_the_vocabularys_methods_with_its_setting_keys) {
  std::vector<std::string> length_ids, u_of_s_ids;
  h::for_each_row(h::length_methods, [&](const auto& row) {
    length_ids.emplace_back(row.method->id);
    // format_setting throws unless the row's keys are its method's declared ones, in order.
    EXPECT_NO_THROW((void)h::format_setting(row, h::default_settings(row))) << row.method->id;
  });
  h::for_each_row(h::u_of_s_methods, [&](const auto& row) {
    u_of_s_ids.emplace_back(row.method->id);
    EXPECT_NO_THROW((void)h::format_setting(row, h::default_settings(row))) << row.method->id;
  });
  // The same methods (the records' order is the table's: forward_difference's u(s) comes last).
  std::vector<std::string> length_vocabulary = vocabulary_methods_of(hv::quantities::length);
  std::vector<std::string> u_of_s_vocabulary = vocabulary_methods_of(hv::quantities::u_of_s);
  EXPECT_EQ(length_ids, length_vocabulary);
  std::sort(u_of_s_ids.begin(), u_of_s_ids.end());
  std::sort(u_of_s_vocabulary.begin(), u_of_s_vocabulary.end());
  EXPECT_EQ(u_of_s_ids, u_of_s_vocabulary);
  // Settings print as records and benchmark names always did: integers as integers.
  EXPECT_EQ(h::format_setting(h::method_rows::composite_gauss, {{"n", 3}, {"panels", 16}}), "n=3,panels=16");
  EXPECT_EQ(h::format_setting(h::method_rows::subdivision, {{"tol", 1e-6}}), "tol=1e-06");
  EXPECT_EQ(h::format_setting(h::method_rows::forward_difference, {{"steps", 4096}}), "steps=4096");
  EXPECT_THROW((void)h::format_setting(h::method_rows::composite_gauss, {{"n", 3}}), invalid_input);
}

TEST(method_table, rows_sharing_a_cli_option_share_its_default_and_limits) {
  std::map<std::string, const h::setting_def*> by_option;
  h::for_each_row(h::length_methods, [&](const auto& row) {
    for (const h::setting_def& d : row.settings) {
      if (d.option.empty()) continue;
      const auto [it, added] = by_option.try_emplace(std::string(d.option), &d);
      if (added) continue;
      EXPECT_EQ(it->second->fallback, d.fallback) << d.option;
      EXPECT_EQ(it->second->min, d.min) << d.option;
      EXPECT_EQ(it->second->max, d.max) << d.option;
      EXPECT_EQ(it->second->integer, d.integer) << d.option;
    }
  });
  EXPECT_EQ(by_option.size(), 4u);  // --n, --panels, --tol, --steps
}

TEST(method_table, a_cost_known_before_the_work_is_refused_above_its_limit) {
  const h::length_cost g = h::method_rows::gauss.cost({{"n", 200}}, 100000);  // 1.4e8 > 2^26
  EXPECT_EQ(g.refusal, "--n 200: 100000 segments need 141700000 evaluations, more than the limit of 67108864");
  // gauss plans 7n + 17 per segment (the nested rule and its speed samples); a speed minimum adds
  // work no count before it knows, so its budget is planned, not a cap.
  EXPECT_EQ(h::method_rows::gauss.cost({{"n", 5}}, 3).budget, 156u);
  EXPECT_FALSE(h::method_rows::gauss.cost({{"n", 5}}, 3).at_most);
  // Without an estimate (`length --estimate none`) gauss costs exactly n per segment.
  const h::length_cost none = h::method_rows::gauss_cost({{"n", 5}}, 3, curvebench::arclength::fixed_estimate::none);
  EXPECT_EQ(none.budget, 15u);
  EXPECT_TRUE(none.at_most);
  EXPECT_THAT(h::method_rows::gauss_cost({{"n", 200}}, 1000000, curvebench::arclength::fixed_estimate::none).refusal,
              HasSubstr("--n 200 --estimate none: 1000000 segments need 200000000 evaluations"));
  EXPECT_TRUE(h::method_rows::composite_gauss.cost({{"n", 5}, {"panels", 4}}, 3).at_most);
  EXPECT_EQ(h::method_rows::composite_gauss.cost({{"n", 5}, {"panels", 4}}, 3).budget, 60u);
  EXPECT_THAT(h::method_rows::composite_gauss.cost({{"n", 200}, {"panels", 1000}}, 1000).refusal,
              HasSubstr("--n 200 --panels 1000: 1000 segments need 200000000 evaluations"));
  EXPECT_TRUE(h::method_rows::composite_gauss.cost({{"n", 200}, {"panels", 1000}}, 1).refusal.empty());
  EXPECT_THAT(h::method_rows::richardson.cost({{"steps", 10000000}}, 2).refusal,
              HasSubstr("--steps 10000000: 2 segments x 10000000 steps is more than the limit of 16777216"));
  EXPECT_EQ(h::method_rows::forward_difference.cost({{"steps", 256}}, 2).budget, 513u);
  EXPECT_TRUE(h::method_rows::adaptive_gk.cost({{"tol", 1e-12}}, 2).refusal.empty());
  // adaptive_gk's first panels (31 per segment) are always computed: its budget is 2^24 up to
  // 541200 segments, their count above (a 1e6-segment spline spent 31M evaluations against a
  // budget that said 2^24).
  EXPECT_EQ(h::method_rows::adaptive_gk.cost({{"tol", 1e-12}}, 541200).budget, 16777216u);
  EXPECT_EQ(h::method_rows::adaptive_gk.cost({{"tol", 1e-12}}, 1000000).budget, 31000000u);
}

// Every length row, at the CLI's defaults and over the quick sweep, on a curve of known length:
// a converged result lies within its estimate of the closed form (plus the closed form's own
// rounding); the finest setting of each series and the CLI's default lie within 1e-5 of it (the
// loosest of them, forward_difference at 256 steps, is a few 1e-6 off: O(h^2); the coarse ones,
// e.g. composite_gauss with one panel at 7e-3, are held to their estimates only).
TEST(method_table, every_length_row_measures_a_known_length_within_its_estimate) {
  const json spec = json::parse(closed_form_parabola);
  const auto c = curvebench::io::curve_from_spec<double, 2>(curvebench::io::root(spec, "parabola"));
  const double L = std::sqrt(5.0) + std::asinh(2.0) / 2;
  const h::sweep w = h::settings(true);
  std::size_t runs = 0;
  h::for_each_row(h::length_methods, [&](const auto& row) {
    std::vector<h::setting_values> all = row.series(w, 1.0);
    const std::size_t finest = all.size() - 1;
    all.push_back(h::default_settings(row));
    for (std::size_t i = 0; i < all.size(); ++i) {
      const h::setting_values& v = all[i];
      for (const double reference : {0.0, L}) {  // the CLI's context, then the sweep's
        h::run_context x;
        x.reference_length = reference;
        const auto r = row.prepare(c, v, x)();
        // Appended, not concatenated from a temporary: GCC 12's -Warray-bounds flagged the
        // concatenation falsely once the method table's u(s) rows shared table_run.
        std::string what(row.method->id);
        what.append(" ").append(h::format_setting(row, v));
        ++runs;
        ASSERT_TRUE(std::isfinite(r.value)) << what;
        EXPECT_GT(r.evaluations, 0u) << what;
        if (r.converged()) {
          EXPECT_LE(std::abs(r.value - L), r.error_estimate + closed_form_slack * L) << what;
        }
        if (i >= finest) {
          EXPECT_LE(std::abs(r.value - L), 1e-5 * L) << what;
        }
      }
    }
  });
  EXPECT_GT(runs, 40u);
}

// Every u(s) row over the quick sweep on the same curve: u(s) at five targets against the closed
// form s(u): |s(u) - s| / L within 1e-2 at every setting (the coarsest, a forward-difference
// table of 8 steps, is 3e-3 off) and 1e-5 at the finest of each series (forward_difference at
// 256 steps: 4e-6; the others far below), and within the row's estimate when it gives one (its
// per-query bound or its table's) and says converged.
TEST(method_table, every_u_of_s_row_inverts_a_known_arc_length) {
  const json spec = json::parse(closed_form_parabola);
  const auto c = curvebench::io::curve_from_spec<double, 2>(curvebench::io::root(spec, "parabola"));
  const double L = parabola_s(1.0);
  const h::sweep w = h::settings(true);
  h::for_each_row(h::u_of_s_methods, [&](const auto& row) {
    const std::vector<h::setting_values> series = row.series(w, 1.0);
    ASSERT_FALSE(series.empty()) << row.method->id;
    for (std::size_t i = 0; i < series.size(); ++i) {
      const h::u_of_s_run run = row.prepare(c, series[i]);
      const std::string what = std::string(row.method->id) + " " + h::format_setting(row, series[i]);
      for (const double f : {0.0, 0.2, 0.5, 0.77, 1.0}) {
        const double s = std::min(f * L, run.length);
        const h::u_of_s_answer a = run.query(s);
        ASSERT_TRUE(a.u >= 0 && a.u <= 1) << what << " at s = " << s;
        const double ds = std::abs(parabola_s(a.u) - f * L) / L;
        EXPECT_LE(ds, i + 1 == series.size() ? 1e-5 : 1e-2) << what << " at s = " << s;
        const double bound = run.table_estimate ? *run.table_estimate : a.estimate;
        if (row.estimate && a.status == curvebench::arclength::result_status::converged && std::isfinite(bound)) {
          EXPECT_LE(ds, bound / L + closed_form_slack) << what << " at s = " << s;
        }
      }
    }
  });
}

TEST(vocabulary, json_lists_every_entry_with_its_fields) {
  const json v = curvebench::harness::vocabulary_json();
  ASSERT_EQ(v["methods"].size(), hv::all_methods().size());
  ASSERT_EQ(v["quantities"].size(), std::size(hv::all_quantities));
  ASSERT_EQ(v["peers"].size(), std::size(hv::all_peers));
  ASSERT_EQ(v["operations"].size(), std::size(hv::all_operations));
  ASSERT_EQ(v["counters"].size(), std::size(hv::all_counters));
  std::set<std::string> ids;
  for (const auto& m : v["methods"]) {
    EXPECT_TRUE(ids.insert(m["id"].get<std::string>()).second) << "duplicate method id " << m["id"];
    EXPECT_FALSE(m["quantities"].empty()) << m["id"];
    for (const auto& q : m["quantities"]) EXPECT_NE(hv::find_quantity(q.get<std::string>()), nullptr) << q;
  }
  const json& cg = v["methods"][1];
  EXPECT_EQ(cg["id"], "composite_gauss");
  EXPECT_EQ(cg["settings"], json::array({"n", "panels"}));
  EXPECT_EQ(cg["theory"], 6.0);
  EXPECT_EQ(v["counters"][0],
            json({{"name", "evaluations"}, {"kind", "count"}, {"doc", std::string(hv::counters::evaluations.doc)}}));
}

TEST(run_case, records_use_vocabulary_ids_declared_settings_and_result_statuses) {
  const case_dir dir("run_case");
  dir.add("arch", arch);
  const auto cases = curvebench::harness::load_cases(dir.path.string());
  ASSERT_EQ(cases.size(), 1u);
  const json out = curvebench::harness::run_case(cases[0], true);
  // Without peer libraries (the installed harness: the subject API), no peer records; with them,
  // the same case has GSL's and Boost's.
  EXPECT_TRUE(out["peer_records"].empty());
  EXPECT_FALSE(
      curvebench::harness::run_case(cases[0], true, &curvebench::harness::library_peers())["peer_records"].empty());
  std::set<std::pair<std::string, std::string>> seen;  // (quantity, method)
  for (const auto& r : out["records"]) {
    const std::string q = r["quantity"], method = r["method"], setting = r["setting"], status = r["status"];
    SCOPED_TRACE(q + " " + method + " " + setting);
    EXPECT_EQ(r["case"], "arch");
    ASSERT_NE(hv::find_quantity(q), nullptr);
    EXPECT_TRUE(is_status(status));
    seen.emplace(q, method);
    if (q == hv::quantities::eval.id) {  // the algorithms of the family: no setting, no estimate
      EXPECT_EQ(setting, "");
      EXPECT_EQ(status, "not_guaranteed");
      EXPECT_TRUE(r["estimate"].is_null());
      continue;
    }
    const hv::method* m = hv::find_method(method);
    ASSERT_NE(m, nullptr) << "method not in the vocabulary";
    EXPECT_TRUE(hv::lists(m->quantities, q)) << "method declares no " << q << " records";
    std::string keys;
    for (const auto& [key, value] : curvebench::harness::parse_setting(setting)) {
      EXPECT_TRUE(hv::lists(m->settings, key)) << "undeclared setting key " << key;
      EXPECT_FALSE(value.empty());
      keys += (keys.empty() ? "" : " ") + key;
    }
    EXPECT_EQ(keys, m->settings) << "every declared key, in order";
    EXPECT_TRUE(r["error"].is_number());
    // A length record that is not converged names why (arclength/result.hpp's reason as
    // text); a converged one has null. (composite_gauss is never converged: the quick sweep has it.)
    if (q == hv::quantities::length.id) {
      if (status == "converged") {
        EXPECT_TRUE(r["reason"].is_null());
      } else {
        ASSERT_TRUE(r["reason"].is_string());
        EXPECT_FALSE(r["reason"].get<std::string>().empty());
        if (method == "composite_gauss") {
          EXPECT_EQ(r["reason"], "composite rule without an estimate");
        }
      }
    }
  }
  // Every method of the vocabulary produced records for each of its quantities (the channel
  // quantities come from channel cases only: tests/test_channel_sweep.cpp checks those).
  for (const hv::method* m : hv::all_methods()) {
    for (const hv::quantity* q : hv::all_quantities) {
      if (hv::lists(m->quantities, q->id) && !q->id.starts_with("channel_")) {
        EXPECT_TRUE(seen.count({std::string(q->id), std::string(m->id)})) << q->id << " " << m->id;
      }
    }
  }
  for (const char* algorithm : {"de_casteljau", "bernstein_sum", "horner"})
    EXPECT_TRUE(seen.count({"eval", algorithm})) << algorithm;
  // Orders carry the vocabulary's theory order of their method.
  ASSERT_FALSE(out["orders"].empty());
  for (const auto& o : out["orders"]) {
    const hv::method* m = hv::find_method(o["method"].get<std::string>());
    ASSERT_NE(m, nullptr);
    EXPECT_GT(m->theory, 0);
    EXPECT_EQ(o["theory"].get<double>(), m->theory);
    // The points fitted and those left out at the rounding floor (harness/order_fit.hpp).
    EXPECT_GE(o["points"].get<std::size_t>(), 3u) << o;
    EXPECT_TRUE(o["excluded"].is_number_unsigned()) << o;
  }
  // The values agree with the 50-digit reference as the gate requires.
  const auto record = [&](const std::string& q, const std::string& method, const std::string& setting) {
    for (const auto& r : out["records"])
      if (r["quantity"] == q && r["method"] == method && r["setting"] == setting) return r;
    ADD_FAILURE() << "no record " << q << " " << method << " " << setting;
    return json();
  };
  EXPECT_LE(record("length", "adaptive_gk", "tol=1e-14")["error"].get<double>(), adaptive_1e14_max);
  EXPECT_LE(record("length", "gauss", "n=16")["error"].get<double>(), gauss16_max);
  EXPECT_LE(record("eval", "default", "")["error"].get<double>(), eval_default_max);
  EXPECT_LE(record("u_of_s", "newton", "tol=1e-12")["error"].get<double>(), newton_1e12_max);
  EXPECT_TRUE(record("length", "composite_gauss", "n=3,panels=4").is_object());
  EXPECT_EQ(out["case"]["family"], "bezier");
}

// GSL's u(s) by Brent over qag (harness/sweep_peers.cpp): one record per Newton tolerance of the
// full sweep, paired with curvebench's Newton at that tolerance; a tolerance qag refuses (1e-14 with
// epsabs 0: below its 50 eps floor) is a record without a value that says why, never a u measured
// from an integral GSL did not compute.
TEST(run_case, gsl_u_of_s_records_pair_newton_and_keep_refusals_valueless) {
  const case_dir dir("gsl_u_of_s");
  dir.add("arch", arch);
  const auto cases = curvebench::harness::load_cases(dir.path.string());
  ASSERT_EQ(cases.size(), 1u);
  const json out = curvebench::harness::run_case(cases[0], false, &curvebench::harness::library_peers());
  std::map<std::string, json> by_setting;
  for (const auto& r : out["peer_records"])
    if (r["quantity"] == "u_of_s") by_setting[r["setting"].get<std::string>()] = r;
  ASSERT_EQ(by_setting.size(), curvebench::harness::settings(false).newton_tol.size());
  for (const auto& [setting, r] : by_setting) {
    SCOPED_TRACE(setting);
    EXPECT_EQ(r["method"], hv::peers::gsl_qag_brent.id);
    EXPECT_EQ(r["counterpart"]["method"], hv::methods::newton.id);
    EXPECT_EQ(r["counterpart"]["setting"], setting);
    if (setting == "tol=1e-14") {
      EXPECT_TRUE(r["error"].is_null());
      EXPECT_TRUE(r["estimate"].is_null());
      EXPECT_EQ(r["status"], "not_guaranteed");
      EXPECT_THAT(r["peer_status"].get<std::string>(), ::testing::HasSubstr("tolerance"));
      continue;
    }
    // A smooth one-segment arch: qag is accurate to its tolerance, so Brent's answer is too (x4:
    // the residual test and qag's error add; the anchored reference measures the sum).
    const double tol = std::stod(setting.substr(4));
    ASSERT_TRUE(r["error"].is_number());
    EXPECT_LE(r["error"].get<double>(), 4 * tol);
    EXPECT_GT(r["evaluations"].get<double>(), 0);
    EXPECT_GT(r["ns_per_op"].get<double>(), 0);
    EXPECT_GT(r["counterpart_ns_per_op"].get<double>(), 0);
  }
}

// The Boost.Math and Eigen peers (harness/sweep_peers_boost_eigen.cpp): each runs on the cases it
// represents, on the part of the domain where it is the case's curve, and is measured against the
// same reference. Tolerances: a peer evaluating the same curve in double loses a few roundings
// more than curvebench's power form (Barry-Goldman's pyramid: 6 lerps; de Boor in Eigen: 3 levels
// of convex combinations), measured at most 1.4 eps x size on these cases, so 16 fails on a
// different curve (a wrong knot or end tangent gives errors of 1e13 and more) but not on
// rounding. Lengths: on the one-segment arch every Boost rule meets its own test
// (error estimate <= tol x L1) at tol 1e-6 and 1e-10, and its estimate then bounds the error.
TEST(run_case, boost_and_eigen_peers_measure_the_cases_they_represent) {
  const case_dir dir("boost_eigen_peers");
  dir.add("arch", arch);
  dir.add("catmull", R"("type": "catmull_rom", "alpha": 0.5, "points": [[0, 0], [1, 2], [3, 3], [4, 0], [6, 1]])");
  dir.add("catmull_closed",
          R"("type": "catmull_rom", "alpha": 0.5, "end": "closed", "points": [[0, 0], [1, 2], [3, 3], [4, 0]])");
  dir.add("clamped", R"("type": "bspline", "degree": 3, "points": [[0, 0], [1, 2], [3, 3], [4, 0], [6, 1], [7, 4]])");
  dir.add("periodic", R"("type": "bspline", "degree": 3, "knot_vector": "periodic",
                         "points": [[1, 0], [0, 1], [-1, 0], [0, -1], [0.5, -0.5]])");
  dir.add("quintic", R"("type": "bspline", "degree": 5,
                        "points": [[0, 0, 0], [1, 2, 1], [3, 3, 0], [4, 0, -1], [6, 1, 2], [7, 4, 0]])");
  dir.add("hermite", R"("type": "hermite", "knots": [0, 0.5, 2], "points": [[0, 0], [2, 1], [3, 3]],
                        "slopes": [[1, 0], [1, 1], [0, 2]])");
  dir.add("hermite_broken", R"("type": "hermite", "points": [[0, 0], [2, 1], [3, 3]],
                               "incoming": [[1, 0], [1, 1], [0, 2]], "outgoing": [[1, 0], [2, -1], [0, 2]])");
  dir.add("clamped_cubic", R"("type": "natural_cubic", "end": "clamped", "start_slope": [1, 2], "end_slope": [1, -1],
                              "points": [[0, 0], [1, 2], [3, 3], [4, 0], [6, 1]])");
  dir.add("clamped_cubic_knots", R"("type": "natural_cubic", "end": "clamped", "start_slope": [1, 2],
                                    "end_slope": [1, -1], "knots": [0, 1, 3], "points": [[0, 0], [1, 2], [3, 3]])");
  const auto cases = curvebench::harness::load_cases(dir.path.string());
  // (case, method, setting) -> record, the eval peers only
  std::map<std::tuple<std::string, std::string, std::string>, json> eval;
  for (const auto& c : cases) {
    const json out = curvebench::harness::run_case(c, true, &curvebench::harness::library_peers());
    std::map<std::string, int> lengths;  // Boost length records per peer
    for (const auto& r : out["peer_records"]) {
      const std::string method = r["method"];
      if (method.rfind("peer_gsl", 0) == 0) continue;
      SCOPED_TRACE(c.name + " " + method + " " + r["setting"].get<std::string>());
      EXPECT_THAT(r["library"].get<std::string>(),
                  ::testing::StartsWith(method.find("eigen") != std::string::npos ? "Eigen 3." : "Boost.Math 1."));
      if (r["quantity"] == "eval") {
        eval[{c.name, method, r["setting"]}] = r;
        continue;
      }
      ASSERT_EQ(r["quantity"], "length");
      ++lengths[method];
      ASSERT_TRUE(r["error"].is_number());
      EXPECT_EQ(r["counterpart"]["method"], hv::methods::adaptive_gk.id);
      EXPECT_EQ(r["counterpart"]["setting"], r["setting"]);
      if (c.name == "arch" && r["setting"] != "tol=1e-14") {
        EXPECT_EQ(r["status"], "converged");
        EXPECT_EQ(r["bounded"], true);
      }
    }
    EXPECT_EQ(lengths, (std::map<std::string, int>{{std::string(hv::peers::boost_gauss_kronrod15.id), 3},
                                                   {std::string(hv::peers::boost_gauss_kronrod31.id), 3},
                                                   {std::string(hv::peers::boost_tanh_sinh.id), 3}}))
        << c.name << ": every Boost rule at each adaptive_gk tolerance of the quick sweep";
  }
  const auto expect_close = [&](const std::string& c, const hv::peer& p, const std::string& setting) {
    SCOPED_TRACE(c + " " + std::string(p.id) + " " + setting);
    const auto it = eval.find({c, std::string(p.id), setting});
    ASSERT_NE(it, eval.end()) << "no record";
    const json& r = it->second;
    ASSERT_TRUE(r["error"].is_number()) << r.dump();
    EXPECT_LE(r["error"].get<double>(), 16);
    EXPECT_LE(r["counterpart_error"].get<double>(), 16);
    EXPECT_GT(r["ns_per_op"].get<double>(), 0);
  };
  // Boost's open Catmull-Rom wraps its end tangents: only the interior segments are the case's.
  expect_close("catmull", hv::peers::boost_catmull_rom, "segments=interior");
  expect_close("catmull_closed", hv::peers::boost_catmull_rom, "");
  EXPECT_FALSE(eval.count({"catmull", std::string(hv::peers::boost_catmull_rom.id), ""}));
  for (const std::string c : {"clamped", "periodic", "quintic"})
    for (const std::string setting : {"", "derivative=1"}) {
      expect_close(c, hv::peers::eigen_spline_fixed_degree, setting);
      expect_close(c, hv::peers::eigen_spline_dynamic_degree, setting);
    }
  expect_close("hermite", hv::peers::boost_cubic_hermite, "");
  expect_close("hermite", hv::peers::boost_cubic_hermite, "derivative=1");
  // cardinal_cubic_b_spline: the clamped spline on uniform knots only.
  expect_close("clamped_cubic", hv::peers::boost_cardinal_cubic_b_spline, "");
  expect_close("clamped_cubic", hv::peers::boost_cardinal_cubic_b_spline, "derivative=1");
  for (const auto& [key, r] : eval)
    EXPECT_TRUE(std::get<0>(key) != "hermite_broken" && std::get<0>(key) != "clamped_cubic_knots")
        << "cubic_hermite has one slope per key, cardinal_cubic_b_spline uniform knots: " << r.dump();
}

TEST(run_accuracy, returns_1_and_leaves_out_a_failed_case_0_when_all_run) {
  const case_dir dir("run_accuracy");
  dir.add("parabola", parabola);
  dir.add("line_1d", R"("type": "polyline", "points": [[0], [1], [3]])");  // loads, but the runner takes 2D/3D only
  curvebench::harness::accuracy_options o;
  o.quick = true;
  o.cases_dir = dir.path.string();
  o.out = (dir.path / "out" / "results.json").string();
  o.threads = 2;
  // A run with a failed case is not the suite: it is written beside --out, which it never replaces.
  EXPECT_EQ(curvebench::harness::run_accuracy(o), 1);
  EXPECT_FALSE(std::filesystem::exists(o.out));
  json r = json::parse(read(dir.path / "out" / "results.partial.json"));
  ASSERT_EQ(r["cases"].size(), 1u);
  EXPECT_EQ(r["cases"][0]["name"], "parabola");
  EXPECT_EQ(r["suite"]["cases"], 2);
  EXPECT_EQ(r["context"]["failed_cases"], 1);
  for (const auto& rec : r["records"]) EXPECT_EQ(rec["case"], "parabola");
  EXPECT_EQ(r["context"]["compiler"], curvebench::harness::compiler_id());
  // The CSV beside it quotes the settings that hold a comma.
  const std::string csv = read(dir.path / "out" / "results.partial.csv");
  EXPECT_THAT(csv, HasSubstr(",length,composite_gauss,\"n=3,panels=4\","));

  o.only = "parabola";
  EXPECT_EQ(curvebench::harness::run_accuracy(o), 0);
  r = json::parse(read(o.out));
  EXPECT_EQ(r["suite"]["cases"], 1);
  EXPECT_EQ(r["context"]["failed_cases"], 0);
  // A later failing run leaves that good run as it was.
  const std::string good = read(o.out);
  o.only = "";
  EXPECT_EQ(curvebench::harness::run_accuracy(o), 1);
  EXPECT_EQ(read(o.out), good);
  o.only = "no_such_case";
  EXPECT_THROW((void)curvebench::harness::run_accuracy(o), invalid_input);
}

TEST(compiler_id, names_the_compiler_that_built_the_harness) {
  // The harness and this test are built by the same compiler.
  const std::string id = curvebench::harness::compiler_id();
#if defined(__clang__)
  EXPECT_EQ(id.rfind("clang " + std::to_string(__clang_major__) + ".", 0), 0u) << id;
#elif defined(__GNUC__)
  EXPECT_EQ(id.rfind("gcc " + std::to_string(__GNUC__) + ".", 0), 0u) << id;
#endif
  EXPECT_THAT(id, ::testing::Not(HasSubstr("g++")));
}

TEST(fit_order, recovers_a_power_law_and_needs_three_points) {
  using curvebench::harness::fit_order;
  std::vector<std::pair<double, double>> series;
  for (double cost : {10.0, 20.0, 40.0, 80.0, 1e6}) series.emplace_back(cost, 0.5 * std::pow(cost, -4.0));
  // The point at cost 1e6 (error 5e-25) is below the floor 1e-12 and left out; the slope is exact.
  const auto fit = fit_order(series, 1e-12, 1e-2);
  EXPECT_NEAR(fit.order, 4.0, 1e-9);
  EXPECT_EQ(fit.used, 4u);
  EXPECT_EQ(fit.excluded, 1u);
  series.resize(2);
  EXPECT_TRUE(std::isnan(fit_order(series, 1e-12, 1e-2).order));
}

TEST(fit_order, a_clean_algebraic_series_in_any_order_gives_its_order) {
  using curvebench::harness::fit_order;
  std::vector<std::pair<double, double>> series;
  for (double cost : {512.0, 16.0, 64.0, 32.0, 128.0, 256.0}) series.emplace_back(cost, 3.0 * std::pow(cost, -2.5));
  const auto fit = fit_order(series, 1e-12, 1e-2);
  EXPECT_NEAR(fit.order, 2.5, 1e-9);
  EXPECT_EQ(fit.used, 6u);
  EXPECT_EQ(fit.excluded, 0u);
}

TEST(fit_order, leaves_out_the_plateau_at_the_rounding_floor) {
  using curvebench::harness::fit_order;
  // Order 4 down to 1e-9, then the rounding level: flat, noisy, then a lucky lower point after it.
  const std::vector<std::pair<double, double>> series{{10, 1e-5},    {20, 6.25e-7}, {40, 3.90625e-8}, {80, 2.4e-9},
                                                      {160, 2.3e-9}, {320, 3e-9},   {640, 1e-10},     {1280, 2e-9}};
  const auto fit = fit_order(series, 1e-12, 1e-2);
  // {160, 2.3e-9} is not 10 % below 2.4e-9: it and every costlier point are the plateau.
  EXPECT_EQ(fit.used, 4u);
  EXPECT_EQ(fit.excluded, 4u);
  EXPECT_NEAR(fit.order, 4.0, 0.02);
  // Without the cut the lucky point and the plateau would pull the slope far from 4.
}

TEST(fit_order, needs_three_points_spanning_a_factor_four_in_cost) {
  using curvebench::harness::fit_order;
  // A plateau from the second point on: one point left, no order.
  const std::vector<std::pair<double, double>> flat{{10, 1e-8}, {20, 1e-8}, {40, 1.1e-8}, {80, 0.95e-8}};
  const auto f = fit_order(flat, 1e-12, 1e-2);
  EXPECT_TRUE(std::isnan(f.order));
  EXPECT_EQ(f.used, 1u);
  EXPECT_EQ(f.excluded, 3u);
  // Three clean points spanning only a factor 3 in cost: no order.
  const std::vector<std::pair<double, double>> narrow{{10, 1e-4}, {20, 1e-5}, {30, 1e-6}};
  EXPECT_TRUE(std::isnan(fit_order(narrow, 1e-12, 1e-2).order));
  // Pre-asymptotic points above the ceiling are skipped, not a plateau.
  const std::vector<std::pair<double, double>> late{{1, 0.5}, {2, 0.6}, {4, 1e-3}, {8, 1e-4}, {16, 1e-5}};
  const auto l = fit_order(late, 1e-12, 1e-2);
  EXPECT_EQ(l.used, 3u);
  EXPECT_EQ(l.excluded, 0u);
  EXPECT_NEAR(l.order, std::log2(10.0), 1e-9);
}

TEST(pool, runs_every_job_once_and_rethrows_a_failure) {
  std::vector<std::size_t> order{3, 0, 2, 1, 4};
  std::vector<std::atomic<int>> runs(order.size());
  std::vector<std::size_t> finished;
  curvebench::harness::run_pool(
      order, 3, [&](std::size_t i) { ++runs[i]; }, [&](std::size_t, std::size_t k) { finished.push_back(k); });
  for (const auto& r : runs) EXPECT_EQ(r.load(), 1);
  EXPECT_EQ(finished, (std::vector<std::size_t>{1, 2, 3, 4, 5}));
  EXPECT_THROW(curvebench::harness::run_pool(
                   order, 2,
                   [](std::size_t i) {
                     if (i == 2) throw std::runtime_error("job 2");
                   },
                   [](std::size_t, std::size_t) {}),
               std::runtime_error);
  EXPECT_EQ(curvebench::harness::pool_threads(0, 1), 1u);
  EXPECT_EQ(curvebench::harness::pool_threads(8, 3), 3u);
}
