// curvebench compare (harness/compare.hpp): the Mann-Whitney U test against a count of every
// ordering and SciPy's documented values, and the comparison of recorded runs
// (tests/data/compare/README.md: how each was recorded): repeated runs of one revision pass, a
// slowed build and a degraded subject fail, naming what regressed.
#include "harness/compare.hpp"

#include "support/fixtures.hpp"
#include "support/source_dir.hpp"

#include <gmock/gmock.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <numeric>
#include <random>
#include <string>
#include <vector>

namespace h = curvebench::harness;
using ::testing::HasSubstr;

namespace {

std::string data_dir() { return curvebench::testing::source_dir() + "/tests/data/compare/"; }

/// The two-sided exact p of U for samples a, b (no ties) by listing every way to choose which of
/// the n1 + n2 ranks belong to a: independent of the implementation's recurrence.
double p_by_listing(const std::vector<double>& a, const std::vector<double>& b) {
  const std::size_t n1 = a.size(), n = a.size() + b.size();
  double u = 0;
  for (double x : a)
    for (double y : b) u += x > y ? 1 : 0;
  std::size_t total = 0, below = 0, above = 0;
  for (unsigned mask = 0; mask < (1u << n); ++mask) {
    if (static_cast<std::size_t>(__builtin_popcount(mask)) != n1) continue;
    // U of this choice: for each rank in a, the ranks below it not in a.
    double v = 0;
    for (std::size_t r = 0; r < n; ++r)
      if (mask & (1u << r))
        for (std::size_t s = 0; s < r; ++s) v += (mask & (1u << s)) ? 0 : 1;
    ++total;
    below += v <= u ? 1 : 0;
    above += v >= u ? 1 : 0;
  }
  return std::min(1.0, 2.0 * static_cast<double>(std::min(below, above)) / static_cast<double>(total));
}

h::run_results run_of(const std::string& name) { return h::read_run(data_dir() + name); }

}  // namespace

TEST(compare, exact_u_test_equals_the_listing_of_every_ordering) {
  // Samples of 2 to 6 values a side, interleaved in several ways; the listing counts C(n1+n2, n1)
  // orderings. Equal as doubles up to the division (both are k / C exactly rounded once).
  const std::vector<std::vector<double>> pool = {
      {1, 4, 9}, {2, 3, 10, 11}, {5, 6, 7, 8, 12}, {0.5, 13, 14, 15, 16, 17}};
  for (const auto& a : pool)
    for (const auto& b : pool) {
      if (&a == &b) continue;
      EXPECT_DOUBLE_EQ(h::mann_whitney_p(a, b), p_by_listing(a, b));
    }
  // Complete separation of 5 and 5: 2 of the 252 orderings are as extreme.
  const std::vector<double> low = {1, 2, 3, 4, 5}, high = {6, 7, 8, 9, 10};
  EXPECT_DOUBLE_EQ(h::mann_whitney_p(low, high), 2.0 / 252.0);
  EXPECT_DOUBLE_EQ(h::mann_whitney_min_p(5, 5), 2.0 / 252.0);
  EXPECT_DOUBLE_EQ(h::mann_whitney_min_p(3, 3), 0.1);  // 3 against 3 never reaches 0.05
}

TEST(compare, u_test_against_scipys_documented_example) {
  // scipy.stats.mannwhitneyu's documentation (SciPy 1.11): males [19, 22, 16, 29, 24] against
  // females [20, 11, 17, 12]: U1 = 17, exact two-sided p = 0.1111 (1/9: 14 of the 126 orderings).
  const std::vector<double> males = {19, 22, 16, 29, 24}, females = {20, 11, 17, 12};
  EXPECT_NEAR(h::mann_whitney_p(males, females), 0.1111, 5e-5);
  EXPECT_DOUBLE_EQ(h::mann_whitney_p(males, females), 14.0 / 126.0);
}

TEST(compare, normal_approximation_with_ties_is_symmetric_and_near_the_exact_tail) {
  // 20 against 20, no ties: the exact distribution and the normal approximation (continuity
  // corrected) agree to about 1e-3 in the tail; the implementation uses the exact one here, so the
  // approximation is checked through a tied copy (one tie moves U by 1/2 and p by less than 0.01).
  std::vector<double> a(20), b(20);
  std::iota(a.begin(), a.end(), 0.0);
  std::iota(b.begin(), b.end(), 6.0);  // shifted by 6: ties from 6 to 19 (14 ties)
  std::vector<double> b_untied = b;
  for (double& x : b_untied) x += 0.5;  // the same order without ties (a value between)
  const double tied = h::mann_whitney_p(a, b), untied = h::mann_whitney_p(a, b_untied);
  EXPECT_GT(tied, 0.0);
  EXPECT_LT(std::abs(tied - untied), 0.05) << tied << " " << untied;
  EXPECT_DOUBLE_EQ(h::mann_whitney_p(a, b), h::mann_whitney_p(b, a));
  const std::vector<double> same(7, 3.0);
  EXPECT_EQ(h::mann_whitney_p(same, same), 1.0);  // every value equal: no evidence either way
  EXPECT_EQ(h::mann_whitney_p({}, same), 1.0);
}

TEST(compare, repeated_runs_of_one_revision_pass) {
  // Four runs of one build, one after the other (10 interleaved repetitions each): the accuracy
  // records of two of them identical, the medians moving by up to 46 % between runs (this VM's
  // drift, tests/data/compare/README.md), under the default 50 % margin. Every ordered pair.
  for (int a = 1; a <= 4; ++a)
    for (int b = 1; b <= 4; ++b) {
      if (a == b) continue;
      const h::comparison c = h::compare_runs(run_of("run" + std::to_string(a)), run_of("run" + std::to_string(b)));
      EXPECT_EQ(c.regressions(), 0u) << a << " vs " << b << ": " << h::to_json(c).dump(1);
      EXPECT_EQ(c.times.size(), 4u);
      for (const auto& t : c.times) EXPECT_TRUE(t.testable) << t.name;
      EXPECT_LT(std::abs(c.drift), 0.5) << a << " vs " << b;
    }
  const h::comparison c = h::compare_runs(run_of("run1"), run_of("run2"));
  EXPECT_EQ(c.records_matched, 75u);  // 58 records and 17 of the peer libraries
  EXPECT_TRUE(c.records.empty());     // no error moved at all
  EXPECT_TRUE(c.records_removed.empty() && c.records_added.empty());
}

TEST(compare, a_slowed_build_fails_naming_the_benchmarks) {
  // The same benchmarks built at -O0: every one 100 to 400 times slower, p ~ 1e-5 (Holm: x4).
  const h::comparison c = h::compare_runs(run_of("run1"), run_of("slow"));
  ASSERT_EQ(c.times.size(), 4u);
  for (const auto& t : c.times) {
    EXPECT_GT(t.change, 50.0) << t.name;
    EXPECT_LT(t.p_holm, 0.001) << t.name;
    EXPECT_TRUE(t.slower) << t.name;
  }
  EXPECT_EQ(c.regressions(), 4u);
  EXPECT_EQ(c.records_removed.size(), 75u);  // slow/ holds no accuracy records: removed, not a regression
  // The other way round it is faster, which is no regression.
  const h::comparison back = h::compare_runs(run_of("slow"), run_of("run1"));
  EXPECT_EQ(back.regressions(), 0u);
  for (const auto& t : back.times) EXPECT_TRUE(t.faster && !t.slower) << t.name;
}

TEST(compare, holm_correction_over_many_benchmarks) {
  // 20 benchmarks, each 10 against 10 repetitions: one doubled (complete separation, p = 2 /
  // C(20, 10) = 1.1e-5, Holm x20 = 2.2e-4), one whose raw p (0.0288) passes alpha alone but not
  // corrected (x19 = 0.55).
  h::run_results base, now;
  for (int i = 0; i < 20; ++i) {
    std::vector<double> b(10), n(10);
    for (int r = 0; r < 10; ++r) b[r] = 100 + r, n[r] = 100 + r + 0.5;  // interleaved: no change
    if (i == 0)
      for (int r = 0; r < 10; ++r) n[r] = 200 + r;  // doubled
    if (i == 1)
      for (int r = 0; r < 10; ++r) n[r] = 103.5 + r;  // U = 79 of 100: exact p = 0.0288
    base.benchmarks.push_back({"BM_" + std::to_string(i), "b.json", b});
    now.benchmarks.push_back({"BM_" + std::to_string(i), "n.json", n});
  }
  const h::comparison c = h::compare_runs(base, now);
  EXPECT_TRUE(c.times[0].slower);
  EXPECT_LT(c.times[0].p_holm, 1e-3);
  EXPECT_NEAR(c.times[1].p, 0.0288, 1e-4);
  EXPECT_GE(c.times[1].p_holm, 0.05);
  EXPECT_FALSE(c.times[1].slower || c.times[1].significant);
  EXPECT_EQ(c.regressions(), 1u);
}

TEST(compare, a_grown_error_fails_and_a_shrunk_one_improves) {
  // check --json of one subject's values written with 17 digits, then with 7 (a float-like subject).
  const h::comparison c = h::compare_runs(run_of("check_17_digits.json"), run_of("check_7_digits.json"));
  ASSERT_GT(c.regressions(), 0u);
  for (const auto& r : c.records) {
    EXPECT_TRUE(r.error_grew) << r.key;
    EXPECT_GT(r.new_error, 1e3 * r.base_error) << r.key;
  }
  const h::comparison back = h::compare_runs(run_of("check_7_digits.json"), run_of("check_17_digits.json"));
  EXPECT_EQ(back.regressions(), 0u);
  ASSERT_FALSE(back.records.empty());
  for (const auto& r : back.records) EXPECT_TRUE(r.improved) << r.key;
}

TEST(compare, margins_decide_and_bounds_lost_always_regress) {
  auto rec = [](double error, double estimate) {
    return curvebench::harness::record::measured("c", "g", "length", "subdivision", "tol=1e-6", error, estimate, 10,
                                                 "converged");
  };
  h::run_results base, now;
  base.path = "base", now.path = "new";
  const auto add = [](h::run_results& r, const curvebench::harness::record& x) {
    r.records.push_back(x);
    r.record_where.push_back("r[" + std::to_string(r.records.size() - 1) + "]");
  };
  add(base, rec(1e-9, 1e-8));
  add(now, rec(1.05e-9, 1e-8));  // +5 %: within the default 10 %
  EXPECT_EQ(h::compare_runs(base, now).regressions(), 0u);
  h::compare_options strict;
  strict.max_error_growth = 0.01;
  EXPECT_EQ(h::compare_runs(base, now, strict).regressions(), 1u);
  // Rounding-level errors: 2e-16 -> 8e-16 is under the relative floor of 1e-15.
  h::run_results b2, n2;
  add(b2, rec(2e-16, 1e-8));
  add(n2, rec(8e-16, 1e-8));
  EXPECT_EQ(h::compare_runs(b2, n2).regressions(), 0u);
  // An estimate that stops bounding the error regresses whatever the growth.
  h::run_results b3, n3;
  add(b3, rec(1e-9, 2e-9));
  add(n3, rec(1.01e-9, 1e-9));
  const h::comparison c3 = h::compare_runs(b3, n3);
  ASSERT_EQ(c3.regressions(), 1u);
  EXPECT_TRUE(c3.records[0].bound_lost);
  // A finite error that became null: no longer measured.
  h::run_results b4, n4;
  add(b4, rec(1e-9, 2e-9));
  add(n4, rec(std::nan(""), 2e-9));
  ASSERT_EQ(h::compare_runs(b4, n4).regressions(), 1u);
  EXPECT_TRUE(h::compare_runs(b4, n4).records[0].unmeasured);
}

TEST(compare, too_few_repetitions_warn_and_never_fail) {
  h::run_results base, now;
  base.benchmarks.push_back({"BM_x", "b.json", {10, 11, 12}});
  now.benchmarks.push_back({"BM_x", "n.json", {30, 31, 32}});  // 3x slower, but 3 against 3
  const h::comparison c = h::compare_runs(base, now);
  EXPECT_EQ(c.regressions(), 0u);
  ASSERT_EQ(c.times.size(), 1u);
  EXPECT_FALSE(c.times[0].testable);
  EXPECT_NEAR(c.times[0].change, 31.0 / 11.0 - 1, 1e-12);  // the medians
  ASSERT_EQ(c.warnings.size(), 1u);
  EXPECT_THAT(c.warnings[0], HasSubstr("at least 4 a side"));
}

TEST(compare, bad_inputs_are_named) {
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / "curvebench_test_compare";
  fs::create_directories(dir);
  const auto write = [&](const std::string& name, const std::string& text) {
    std::ofstream(dir / name) << text;
    return (dir / name).string();
  };
  const auto msg = [](const std::string& path) {
    return curvebench::testing::message_of([&] { (void)h::read_run(path); });
  };
  EXPECT_THAT(msg(write("neither.json", "{\"x\": 1}")), HasSubstr("neither \"records\""));
  EXPECT_THAT(msg(write("bad_time.json", R"({"benchmarks": [{"name": "BM_a", "cpu_time": "fast"}]})")),
              HasSubstr("bad_time.json: benchmarks[0].cpu_time: expected a number"));
  EXPECT_THAT(msg(write("bad_unit.json", R"({"benchmarks": [{"name": "BM_a", "cpu_time": 1, "time_unit": "h"}]})")),
              HasSubstr("benchmarks[0].time_unit: \"h\" is not ns, us, ms or s"));
  EXPECT_THAT(msg(write("bad_record.json", R"({"records": [{"case": 3}]})")), HasSubstr("records[0].case"));
  EXPECT_THAT(msg(write("negative.json", R"({"records": [{"case": "c", "error": -1}]})")),
              HasSubstr("negative.json: records[0].error: -1 is negative"));
  // A record written twice: which one to match would depend on the file's order.
  const std::string twice =
      write("twice.json", R"({"records": [{"case": "c", "quantity": "length", "method": "gauss", "error": 1e-9},
                                          {"case": "c", "quantity": "length", "method": "gauss", "error": 1.0}]})");
  const std::string once = write("once.json", R"({"records": [{"case": "c", "quantity": "length", "method": "gauss",
                                                               "error": 1e-9}]})");
  const auto compared = [&](const std::string& b, const std::string& n) {
    return curvebench::testing::message_of([&] { (void)h::compare_runs(h::read_run(b), h::read_run(n)); });
  };
  EXPECT_THAT(compared(once, twice), HasSubstr("twice.json: records[1]: the same record as"));
  EXPECT_THAT(compared(twice, once), HasSubstr("twice.json: records[1]: the same record as"));
  // Nothing in common: refused, not passed.
  EXPECT_THAT(compared(once, data_dir() + "slow"), HasSubstr("share no record and no benchmark: nothing was compared"));
  // One benchmark in two files of a run: the message names both files.
  const fs::path two = dir / "two_files";
  fs::create_directories(two);
  for (const char* f : {"bench_a.json", "bench_b.json"})
    std::ofstream(two / f) << R"({"benchmarks": [{"name": "BM_a", "cpu_time": 1}]})";
  EXPECT_THAT(msg(two.string()),
              HasSubstr("bench_b.json: benchmark BM_a is in " + (two / "bench_a.json").string() + " of this run too"));
  const fs::path empty = dir / "empty_dir";
  fs::create_directories(empty);
  EXPECT_THAT(msg(empty.string()), HasSubstr("no accuracy.json and no bench_*.json"));
  fs::remove_all(dir);
}

namespace {

/// U counted pair by pair, as the test defines it: a beats b, half for a tie.
double u_by_pairs(const std::vector<double>& a, const std::vector<double>& b) {
  double u = 0;
  for (double x : a)
    for (double y : b) u += x > y ? 1.0 : x == y ? 0.5 : 0.0;
  return u;
}

}  // namespace

TEST(compare, u_from_ranks_equals_the_pairwise_count_with_ties) {
  // Random samples of 1 to 40 values drawn from few distinct values (many ties within and between
  // the samples), and from many (few ties): U from one sort's ranks against the pairwise count.
  std::mt19937 rng(20261207);
  for (int trial = 0; trial < 400; ++trial) {
    const int distinct = trial % 2 == 0 ? 5 : 1000;
    std::uniform_int_distribution<int> size(1, 40), value(0, distinct - 1);
    std::vector<double> a(static_cast<std::size_t>(size(rng))), b(static_cast<std::size_t>(size(rng)));
    for (double& x : a) x = 0.25 * value(rng);
    for (double& y : b) y = 0.25 * value(rng);
    ASSERT_EQ(h::mann_whitney_u(a, b), u_by_pairs(a, b)) << "trial " << trial;
    ASSERT_EQ(h::mann_whitney_u(a, b) + h::mann_whitney_u(b, a), static_cast<double>(a.size() * b.size()));
    EXPECT_DOUBLE_EQ(h::mann_whitney_p(a, b), h::mann_whitney_p(b, a)) << "trial " << trial;
  }
  const std::vector<double> with_nan = {1, std::nan(""), 2}, one = {1};
  EXPECT_THAT(curvebench::testing::message_of([&] { (void)h::mann_whitney_p(with_nan, one); }), HasSubstr("NaN"));
}

TEST(compare, u_of_two_hundred_thousand_a_side_is_exact) {
  // 2e5 repetitions a side: 4e10 pairs, which the pairwise count took minutes for; the ranks give U
  // exactly. a_i = i + 1/2 beats b_j = j for j <= i: U = n (n + 1) / 2. b against itself: every
  // pair a tie, U = n^2 / 2 and no evidence (p = 1). Values in pairs, v = floor(i / 2) < m = n / 2,
  // against the same plus one: each copy of v >= 1 beats the 2 (v - 1) values below it and ties 2,
  // U = 2 sum_{v=1}^{m-1} (2 v - 1) = 2 (m - 1)^2.
  const std::size_t n = 200000;
  std::vector<double> a(n), b(n), pairs(n), shifted(n);
  for (std::size_t i = 0; i < n; ++i) {
    a[i] = static_cast<double>(i) + 0.5;
    b[i] = static_cast<double>(i);
    pairs[i] = static_cast<double>(i / 2);
    shifted[i] = static_cast<double>(i / 2 + 1);
  }
  const double nd = static_cast<double>(n);
  EXPECT_EQ(h::mann_whitney_u(a, b), nd * (nd + 1) / 2);
  EXPECT_EQ(h::mann_whitney_u(b, b), nd * nd / 2);
  EXPECT_EQ(h::mann_whitney_p(b, b), 1.0);
  const double m = nd / 2;
  EXPECT_EQ(h::mann_whitney_u(pairs, shifted), 2 * (m - 1) * (m - 1));
  // Shifting every value of one sample past the other: complete separation, p far below 1e-300.
  for (double& x : a) x += nd;
  EXPECT_EQ(h::mann_whitney_u(a, b), nd * nd);
  EXPECT_LT(h::mann_whitney_p(a, b), 1e-300);
}

TEST(compare, runs_of_different_suites_are_refused_naming_both_files) {
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / "curvebench_test_compare_suites";
  fs::create_directories(dir);
  // An accuracy.json as the runner writes it (harness/accuracy.cpp), one record, with the fields
  // compare checks given per file.
  const auto accuracy = [&](const std::string& name, const std::string& schema, const std::string& suite, int version,
                            bool quick, const std::string& revision) {
    std::ofstream(dir / name) << R"({"schema": )" << schema << R"(, "suite": {"name": ")" << suite
                              << R"(", "version": )" << version << R"(, "cases": 1}, "context": {"quick": )"
                              << (quick ? "true" : "false") << R"(, "revision": ")" << revision
                              << R"(", "compiler": "gcc"}, "records": [{"case": "c", "quantity": "length",
                                  "method": "gauss", "setting": "n=4", "error": 1e-9}]})";
    return (dir / name).string();
  };
  const std::string base = accuracy("base.json", "1", "curvebench-cases", 4, true, "aaaa");
  const auto refusal = [&](const std::string& now) {
    return curvebench::testing::message_of([&] { (void)h::compare_runs(h::read_run(base), h::read_run(now)); });
  };
  // Another build of the same suite: compared (that is what compare is for).
  const h::comparison same =
      h::compare_runs(h::read_run(base), h::read_run(accuracy("new.json", "1", "curvebench-cases", 4, true, "bbbb")));
  EXPECT_EQ(same.records_matched, 1u);
  const std::string version = accuracy("v5.json", "1", "curvebench-cases", 5, true, "aaaa");
  EXPECT_THAT(refusal(version),
              HasSubstr(base + " and " + version + " are not runs of one suite: suite.version is 4 in " + base +
                        " and 5 in " + version));
  EXPECT_THAT(refusal(accuracy("mine.json", "1", "my-cases", 4, true, "aaaa")),
              HasSubstr("suite.name is \"curvebench-cases\" in"));
  EXPECT_THAT(refusal(accuracy("full.json", "1", "curvebench-cases", 4, false, "aaaa")),
              HasSubstr("context.quick is true in " + base + " and false in"));
  EXPECT_THAT(refusal(accuracy("schema2.json", "2", "curvebench-cases", 4, true, "aaaa")),
              HasSubstr("\"schema\" is 1 in " + base + " and 2 in"));
  // Both of a schema this build does not know: refused too, naming the file.
  const std::string schema2 = (dir / "schema2.json").string();
  EXPECT_THAT(
      curvebench::testing::message_of([&] { (void)h::compare_runs(h::read_run(schema2), h::read_run(schema2)); }),
      HasSubstr(schema2 + ": \"schema\" 2: this curvebench compares results of schema 1"));
  // check --json output (the same record as a subject's) against accuracy results: another kind.
  std::ofstream(dir / "check.json") << R"({"spec": "c.json", "name": "mine", "checks": [], "records": [
      {"case": "c", "quantity": "length", "method": "gauss", "setting": "n=4", "error": 1e-9}]})";
  EXPECT_THAT(refusal((dir / "check.json").string()),
              HasSubstr("the kind is accuracy results in " + base + " and check --json output in"));
  // Benchmarks: Google Benchmark's own schema version, where both files write one.
  const auto bench = [&](const std::string& name, const std::string& context) {
    std::ofstream(dir / name) << R"({"context": )" << context
                              << R"(, "benchmarks": [{"name": "BM_a", "run_type": "iteration", "cpu_time": 10}]})";
    return (dir / name).string();
  };
  const std::string b1 = bench("b1.json", R"({"json_schema_version": 1, "host_name": "a"})");
  const std::string b2 = bench("b2.json", R"({"json_schema_version": 2, "host_name": "a"})");
  const std::string b_none = bench("b_none.json", R"({"host_name": "b"})");
  EXPECT_THAT(curvebench::testing::message_of([&] { (void)h::compare_runs(h::read_run(b1), h::read_run(b2)); }),
              HasSubstr("context.json_schema_version is 1 in " + b1 + " and 2 in " + b2));
  EXPECT_EQ(h::compare_runs(h::read_run(b1), h::read_run(b_none)).times.size(), 1u);  // an older writer: no version
  fs::remove_all(dir);
}

TEST(compare, every_change_carries_its_errors_unit) {
  // check --json of one subject, 17 then 7 digits: point errors in ulps of double, s(u) relative to L.
  const h::comparison c = h::compare_runs(run_of("check_17_digits.json"), run_of("check_7_digits.json"));
  ASSERT_FALSE(c.records.empty());
  for (const auto& r : c.records) {
    const bool relative = r.key.find("/s_of_u/") != std::string::npos;
    EXPECT_EQ(r.unit, relative ? "rel-L" : "ulp-double") << r.key;
  }
  const nlohmann::json j = h::to_json(c);
  for (const auto& r : j["records"]) EXPECT_TRUE(r["unit"].is_string()) << r.dump();
  // The channel quantities are in eps of the model's precision, which the setting's bits names.
  const auto unit = [](const std::string& quantity, const std::string& setting) {
    curvebench::harness::record r;
    r.quantity = quantity;
    r.setting = setting;
    return h::error_unit(r);
  };
  EXPECT_EQ(unit("length", "n=4"), "rel-L");
  EXPECT_EQ(unit("u_of_s", "M=16"), "rel-L");
  EXPECT_EQ(unit("eval", "derivative=1"), "ulp-double");
  EXPECT_EQ(unit("channel_value", "bits=32"), "ulp-float");
  EXPECT_EQ(unit("channel_time", "bits=64"), "ulp-double");
  EXPECT_EQ(unit("channel_keys", ""), "ulp-double");
  EXPECT_EQ(unit("channel_rotation", "bits=32"), "ulp-float-rad");
  EXPECT_EQ(unit("channel_monotone", "bits=32"), "count");
  EXPECT_EQ(unit("channel_value", "bits=320"), "ulp-double");  // a key=value, not a prefix of one
  EXPECT_EQ(unit("mystery", ""), "");
}

// A check's records carry the figure the check printed in its own unit (harness/check.hpp:
// "unit", "error_in_unit"); compare shows the change in that unit, the records' ulps of double
// beside it. A float engine's 18.5 float ulps is 18.5 x 2^29 = 9.93e9 ulps of double: printed
// alone, that figure did not say what the check had said.
TEST(compare, a_checks_records_are_shown_in_the_checks_unit) {
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / "curvebench_test_compare_check_unit";
  fs::create_directories(dir);
  const double ratio = std::numeric_limits<float>::epsilon() / std::numeric_limits<double>::epsilon();
  const auto write = [&](const std::string& name, double float_ulps, const std::string& unit) {
    nlohmann::json rec{{"case", "walk"},
                       {"group", "channel"},
                       {"quantity", "eval"},
                       {"method", "mine"},
                       {"setting", ""},
                       {"error", float_ulps * ratio},
                       {"estimate", nullptr},
                       {"bounded", nullptr},
                       {"evaluations", 10},
                       {"status", "not_guaranteed"},
                       {"subject", true},
                       {"unit", unit},
                       {"error_in_unit", float_ulps}};
    std::ofstream(dir / name) << nlohmann::json{
        {"spec", "walk.json"}, {"name", "mine"}, {"checks", nlohmann::json::array()}, {"records", {rec}}};
    return (dir / name).string();
  };
  const h::comparison c =
      h::compare_runs(h::read_run(write("a.json", 12.3, "ulp-float")), h::read_run(write("b.json", 18.5, "ulp-float")));
  ASSERT_EQ(c.records.size(), 1u);
  EXPECT_EQ(c.records[0].unit, "ulp-double");
  EXPECT_EQ(c.records[0].check_unit, "ulp-float");
  EXPECT_DOUBLE_EQ(c.records[0].new_in_unit, 18.5);
  EXPECT_TRUE(c.records[0].error_grew);
  EXPECT_EQ(h::to_json(c)["records"][0]["check_unit"], "ulp-float");
  // Checks in different units: no common figure of the check's, the records' alone.
  const h::comparison mixed =
      h::compare_runs(h::read_run(write("c.json", 1, "rel")), h::read_run(write("d.json", 18.5, "ulp-float")));
  ASSERT_EQ(mixed.records.size(), 1u);
  EXPECT_EQ(mixed.records[0].check_unit, "");
  EXPECT_TRUE(std::isnan(mixed.records[0].new_in_unit));
  fs::remove_all(dir);
}
