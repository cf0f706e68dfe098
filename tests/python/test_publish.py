"""Tests of scripts/publish.py: the headline data from a run's files, the refusal of quick runs, the
plot budget, and that what is checked in (README's results block, docs/results.md) is exactly what
publish.py renders from docs/results/headline.json, so no figure in them is typed by hand.
Run by ctest (report_py): /usr/bin/python3 -m unittest discover -s tests/python"""
import glob
import json
import os
import shutil
import sys
import tempfile
import unittest

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.abspath(os.path.join(HERE, "..", ".."))
sys.path.insert(0, os.path.join(ROOT, "scripts"))
import publish  # noqa: E402
import report_peers  # noqa: E402
import report_summary  # noqa: E402

FIXTURES = os.path.join(HERE, "fixtures")


def record(case, quantity, method, error, setting="", estimate=None, bounded=None, status="not_guaranteed"):
    r = {"case": case, "quantity": quantity, "method": method, "setting": setting, "error": error,
         "evaluations": 10.0, "status": status, "group": "smooth"}
    if bounded is not None:
        r.update({"estimate": estimate, "bounded": bounded})
    return r


def order(case, observed, excluded=1):
    return {"case": case, "quantity": "length", "method": "composite_gauss", "observed": observed, "theory": 6.0,
            "points": 4, "excluded": excluded}


def accuracy(quick=False):
    return {"context": {"compiler": "gcc 12.2.0", "flags": " -O3", "quick": quick, "revision": "abc1234",
                        "seconds": 12.5},
            "suite": {"name": "curvebench-cases", "version": 2},
            "cases": [{"name": "deg20", "family": "bezier", "segments": 1},
                      {"name": "cr", "family": "catmull_rom", "segments": 1000}],
            "records": [record("deg20", "eval", "de_casteljau", 1.0), record("deg20", "eval", "horner", 2.0e7),
                        record("deg20", "eval", "default", 1.0), record("cr", "eval", "power", 0.5),
                        record("cr", "eval", "bezier", 1.5),
                        record("cr", "length", "gauss", 1e-9, "n=4", 1e-8, True, "converged"),
                        record("cr", "length", "gauss", 1e-7, "n=2", 1e-8, False, "converged")],
            "orders": [order("cr", 5.0), order("deg20", 7.0, 2), order("x", 6.5)]}


def make_run(directory, quick=False):
    for name in ("vocabulary.json", "bench_peers.json"):
        shutil.copy(os.path.join(FIXTURES, name), directory)
    with open(os.path.join(directory, "accuracy.json"), "w", encoding="utf-8") as f:
        json.dump(accuracy(quick), f)
    with open(os.path.join(directory, "run.json"), "w", encoding="utf-8") as f:
        json.dump({"quick": quick, "seconds_after_build": 321}, f)
    os.makedirs(os.path.join(directory, "plots"))
    for name in ("convergence.png", "pareto_length_runge_equispaced.png", "pareto_length_arch.png", "unrelated.png"):
        with open(os.path.join(directory, "plots", name), "wb") as f:
            f.write(b"\x89PNG" + name.encode())


class Headline(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.mkdtemp()
        make_run(self.tmp)
        self.h = publish.headline(*publish.load_run(self.tmp))

    def tearDown(self):
        shutil.rmtree(self.tmp)

    def test_eval_spread_ranks_cases_by_worst_over_best(self):
        ev = self.h["eval"]
        self.assertEqual([e["case"] for e in ev], ["deg20", "cr"])
        self.assertAlmostEqual(ev[0]["spread"], 2.0e7)
        self.assertNotIn("default", ev[0]["errors"])  # the default is one of the algorithms, not another
        self.assertAlmostEqual(ev[1]["spread"], 3.0)

    def test_honesty_names_each_estimate_that_does_not_bound(self):
        ho = self.h["honesty"]
        self.assertEqual((ho["with_estimate"], ho["bounded"]), (2, 1))
        self.assertEqual([(d["case"], d["setting"]) for d in ho["dishonest"]], [("cr", "n=2")])

    def test_orders_are_medians_over_cases(self):
        (o,) = self.h["orders"]
        self.assertEqual((o["median"], o["min"], o["max"], o["cases"], o["theory"]), (6.5, 5.0, 7.0, 3, 6.0))
        self.assertEqual(o["excluded"], 4)  # the points left out at the rounding floor, summed over the cases

    def test_pareto_rows_carry_the_segment_count(self):
        acc = accuracy()
        times = {("cr", "gauss", "n=4"): 50.0, ("cr", "gauss", "n=2"): 20.0}
        (row,) = publish.pareto_fastest(acc["records"], times, acc["cases"])
        self.assertEqual((row["case"], row["segments"]), ("cr", 1000))
        self.assertEqual(row["1e-06"], {"method": "gauss n=2", "ns": 20.0})
        # one method (two settings of gauss): nothing to compare at equal cost, spread 1
        self.assertEqual(publish.featured(acc["records"], times), [{"case": "cr", "spread": 1.0}])

    def test_results_page_shows_segments_and_excluded_points_when_the_run_has_them(self):
        h = dict(self.h, pareto=[{"case": "cr", "segments": 1000, "1e-06": {"method": "gauss n=2", "ns": 20.0},
                                  "1e-10": None, "1e-14": None}])
        page = publish.render_results(h, [])
        self.assertIn("| cr | 1000 | gauss n=2 (20 ns) | none reached | none reached |", page)
        self.assertIn("| length | composite_gauss | 6.5 | 5 | 7 | 3 | 6 | 4 |", page)
        # a headline published before the segment counts and excluded points renders as it was
        old = dict(h, pareto=[{k: v for k, v in h["pareto"][0].items() if k != "segments"}],
                   orders=[{k: v for k, v in o.items() if k != "excluded"} for o in h["orders"]])
        page = publish.render_results(old, [])
        self.assertIn("| cr | gauss n=2 (20 ns) | none reached | none reached |", page)
        self.assertNotIn("excluded points", page)

    def test_peers_come_from_the_benchmarks(self):
        self.assertTrue(self.h["peers"])
        for p in self.h["peers"]:
            self.assertAlmostEqual(p["ratio"], p["ours_ns"] / p["peer_ns"])
            self.assertTrue(p["peer"].startswith("peer_"))

    def test_readme_block_quotes_the_data(self):
        text = publish.render_readme(self.h)
        self.assertTrue(text.startswith(publish.BEGIN) and text.endswith(publish.END))
        self.assertIn("abc1234", text)
        self.assertIn("321 s after the build", text)
        self.assertIn("horner 2.00e+07", text)
        self.assertNotIn("catmull_rom): power", text)  # a spread of 3 is not a headline
        self.assertIn("1 of the 2 records", text)


class ChannelHeadline(unittest.TestCase):
    """The keyframe-channel figures come from the channel records and the channel benchmarks."""

    def test_channel_summary_and_its_lines(self):
        def ch(case, quantity, method, bits, error, **extra):
            r = record(case, quantity, method, error, f"bits={bits}")
            r.update(extra)
            return r
        records = [ch("s", "channel_value", "curvebench", 64, 3.0), ch("t", "channel_value", "curvebench", 64, 1.0),
                   ch("s", "channel_value", "curvebench", 32, 2.0), ch("s", "channel_value", "closed_form", 64, 19.0),
                   ch("s", "channel_monotone", "curvebench", 64, 0), ch("s", "channel_monotone", "closed_form", 32, 2),
                   ch("r", "channel_rotation", "rotation_slerp", 64, 5.0, rms=1.0, norm=1.0),
                   ch("q", "channel_rotation", "rotation_slerp", 64, 7.0, rms=1.0, norm=1.0)]
        rows = [{"family": "channel_value", "algorithm": "curvebench",
                 "args": [["keys", "64"], ["bits", "64"], ["calls", "single"]],
                 "ns_per_op": 80.0}]
        c = publish.channel_summary(records, rows)
        self.assertEqual(c["goal"], {"max64": 3.0, "case": "s", "monotone": 0, "accurate_others": []})
        self.assertEqual(c["solvers"][0], {"solver": "curvebench", "max64": 3.0, "case": "s", "max32": 2.0,
                                           "monotone": 0, "ns": 80.0, "ns_sorted": None})
        self.assertEqual(c["solvers"][1]["monotone"], 2)
        self.assertEqual(c["rotation"], {"rotation_slerp": 7.0})
        self.assertIsNone(publish.channel_summary([record("a", "eval", "default", 1.0)], rows))
        h = {"run": {"revision": "r", "date": "2026-01-01", "host": "h", "cpus": 2, "mhz": 1, "compiler": "c",
                     "flags": "-O3", "suite": "s", "suite_version": 1, "cases": 1, "records": 1, "quick": False,
                     "seconds_after_build": 1, "accuracy_seconds": 1},
             "eval": [], "peers": [], "targets": [], "pareto": [], "orders": [],
             "honesty": {"bounded": 0, "with_estimate": 0, "dishonest": [], "records": 0}, "channel": c}
        readme = publish.render_readme(h)
        self.assertIn("curvebench's solver 3 ulps (goal <= 4), 0 monotonicity violations, 80 ns per value", readme)
        self.assertIn("`closed_form` 19 ulps", readme)
        page = publish.render_results(h, [])
        self.assertIn("## Keyframe channels", page)
        self.assertIn("`rotation_slerp` 7", page)


class Publish(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.mkdtemp()
        self.reports = os.path.join(self.tmp, "reports")
        self.docs = os.path.join(self.tmp, "docs")
        os.makedirs(self.reports)
        self.readme = os.path.join(self.tmp, "README.md")
        with open(self.readme, "w", encoding="utf-8") as f:
            f.write(f"intro\n{publish.BEGIN}\nstale 1.0 ns\n{publish.END}\noutro\n")

    def tearDown(self):
        shutil.rmtree(self.tmp)

    def test_full_run_writes_pages_and_replaces_only_the_block(self):
        make_run(self.reports)
        h = publish.publish(self.reports, self.docs, self.readme, allow_missing_peers=True)
        with open(self.readme, encoding="utf-8") as f:
            text = f.read()
        self.assertTrue(text.startswith("intro\n") and text.endswith("\noutro\n"))
        self.assertNotIn("stale", text)
        self.assertIn(publish.render_readme(h), text)
        plots = sorted(os.path.basename(p) for p in glob.glob(os.path.join(self.docs, "results", "*.png")))
        self.assertEqual(plots[0], "convergence.png")
        self.assertIn("pareto_length_runge_equispaced.png", plots)
        self.assertNotIn("unrelated.png", plots)
        with open(os.path.join(self.docs, "results", "headline.json"), encoding="utf-8") as f:
            self.assertEqual(json.load(f)["run"]["revision"], "abc1234")

    def test_fidelity_block_is_written_and_refreshed_alone(self):
        make_run(self.reports)
        publish.publish(self.reports, self.docs, self.readme, allow_missing_peers=True)
        page = os.path.join(self.docs, "results.md")
        with open(page, encoding="utf-8") as f:
            before = f.read()
        self.assertIn(publish.FIDELITY_BEGIN, before)
        self.assertIn("No recordings were measured", before)
        fidelity = {"agree_ulps": 128, "curvebench": "curvebench 9.9 (fff0000)", "recordings": [{
            "file": "r.json", "tool": "maya", "source": {"implementation": "AnimX"}, "channels": 1, "agree": 1,
            "refused": 0, "tolerance": 2.8e-14, "max_error": 0.0, "features": [], "disagree": [],
            "refused_channels": []}]}
        with open(os.path.join(self.reports, "fidelity.json"), "w", encoding="utf-8") as f:
            json.dump(fidelity, f)
        argv = sys.argv
        sys.argv = ["publish.py", "--reports", self.reports, "--docs", self.docs, "--fidelity-only"]
        try:
            self.assertEqual(publish.main(), 0)
        finally:
            sys.argv = argv
        with open(page, encoding="utf-8") as f:
            after = f.read()
        head = before[:before.index(publish.FIDELITY_BEGIN)]
        self.assertTrue(after.startswith(head))  # the run's part is untouched
        self.assertIn("| maya | AnimX | r.json | 1 | 1 of 1 | 0 | 0 | 0 |", after)
        self.assertIn("Measured by curvebench 9.9 (fff0000).", after)
        self.assertEqual(after.count(publish.FIDELITY_BEGIN), 1)

    def test_quick_run_is_refused(self):
        make_run(self.reports, quick=True)
        with self.assertRaises(publish.PublishError):
            publish.publish(self.reports, self.docs, self.readme)

    def test_readme_without_markers_is_an_error(self):
        make_run(self.reports)
        with open(self.readme, "w", encoding="utf-8") as f:
            f.write("no block\n")
        with self.assertRaisesRegex(publish.PublishError, "results:begin"):
            publish.publish(self.reports, self.docs, self.readme, allow_missing_peers=True)

    def peers(self, drivers):
        for name in drivers:
            with open(os.path.join(self.reports, f"peers_{name}.json"), "w", encoding="utf-8") as f:
                json.dump({"driver": name, "versions": {name: "1.0"}, "peer_records": []}, f)

    def test_a_missing_optional_peer_refuses_the_publish_unless_allowed(self):
        make_run(self.reports)
        self.peers(d for d in report_peers.OPTIONAL_DRIVERS if d != "blender")
        with self.assertRaises(publish.PublishError) as cm:
            publish.publish(self.reports, self.docs, self.readme)
        self.assertIn("real Blender F-curves", str(cm.exception))
        self.assertIn("--allow-missing-peers", str(cm.exception))
        self.assertFalse(os.path.exists(os.path.join(self.docs, "results.md")))  # nothing published
        publish.publish(self.reports, self.docs, self.readme, allow_missing_peers=True)
        with open(os.path.join(self.docs, "results.md"), encoding="utf-8") as f:
            page = f.read()
        self.assertIn("Optional peers missing from this run (published with --allow-missing-peers): real Blender", page)

    def test_every_peer_run_publishes_with_the_summary_and_the_peers_section(self):
        make_run(self.reports)
        self.peers(report_peers.OPTIONAL_DRIVERS)
        h = publish.publish(self.reports, self.docs, self.readme)
        self.assertEqual(h["peers_missing"], [])
        with open(os.path.join(self.docs, "results.md"), encoding="utf-8") as f:
            page = f.read()
        self.assertNotIn("Optional peers missing", page)
        # REPORT.md's sections of the same run, by the same code, in the published page; the summary
        # with its "Details:" links to the sections of this page (report_summary.link_details).
        without_links = "\n".join(line for line in page.split("\n") if not line.startswith("Details: "))
        for section in (h["summary"], h["peers_section"]):
            # the summary's links to sections resolved against this page's headings
            section = report_summary.resolve_section_links(section, page.split("\n"))
            self.assertIn("\n".join(report_summary.flat(section)).replace("\n\n\n", "\n\n"),
                          without_links.replace("\n\n\n", "\n\n"))
        self.assertIn("Details: [Peers: the libraries users would pick instead]"
                      "(#peers-the-libraries-users-would-pick-instead).", page)
        self.assertIn("## Summary", page)
        self.assertIn("## Peers: the libraries users would pick instead", page)
        self.assertIn("peers_three.json (scripts/peers.sh)", page)  # the versions table names each driver

    def test_the_many_segment_u_of_s_table_is_published(self):
        # The time per u(s) query on many segments against one segment, in the same
        # run, on the published page as REPORT.md gives it (report_lib.table_per_segments).
        make_run(self.reports)
        self.peers(report_peers.OPTIONAL_DRIVERS)
        with open(os.path.join(self.reports, "vocabulary.json"), encoding="utf-8") as f:
            vocab = json.load(f)
        vocab["counters"].append({"name": "table_intervals", "kind": "count", "doc": "cells of the table"})
        vocab["methods"].append({"id": "hermite_table_sized", "quantities": ["u_of_s"], "settings": ["tol"],
                                 "theory": 0, "doc": "sized Hermite table"})
        with open(os.path.join(self.reports, "vocabulary.json"), "w", encoding="utf-8") as f:
            json.dump(vocab, f)
        run = {"context": {"host_name": "fixture"}, "benchmarks": []}
        for case, ns, cells in (("arch", 6.0, 2048), ("road", 7.5, 266304)):
            run["benchmarks"].append({"name": f"u_of_s_case/hermite_table_sized/case:{case}/tol:1e-12",
                                      "run_type": "iteration", "iterations": 1000, "real_time": ns, "cpu_time": ns,
                                      "time_unit": "ns", "items_per_second": 1e9 / ns, "label": "query",
                                      "table_intervals": cells})
        with open(os.path.join(self.reports, "bench_arclength_cases.json"), "w", encoding="utf-8") as f:
            json.dump(run, f)
        acc_path = os.path.join(self.reports, "accuracy.json")
        with open(acc_path, encoding="utf-8") as f:
            acc = json.load(f)
        acc["cases"] = acc.get("cases", []) + [{"name": "arch", "segments": 1}, {"name": "road", "segments": 1000}]
        with open(acc_path, "w", encoding="utf-8") as f:
            json.dump(acc, f)
        h = publish.publish(self.reports, self.docs, self.readme)
        with open(os.path.join(self.docs, "results.md"), encoding="utf-8") as f:
            page = f.read()
        self.assertIn("\n## u(s) on many segments\n", page)
        self.assertIn("\n".join(h["u_of_s_many"][1:]).strip(), page)
        self.assertIn("| road | 1000 | 1e-12 | 266304 | - | 7.5 | 1.25 |", page)


class OneAnswer(unittest.TestCase):
    """The README's headline, docs/results.md and REPORT.md give the same recommendation from the
    same records (report_summary.run_recommendations), with the break-even query count of a table
    against a per-query method computed from the records' build and query evaluations. The summary
    said newton where the README and the many-segment section said hermite_table before."""

    def setUp(self):
        self.tmp = tempfile.mkdtemp()
        self.addCleanup(shutil.rmtree, self.tmp)
        self.reports = os.path.join(self.tmp, "reports")
        self.docs = os.path.join(self.tmp, "docs")
        os.makedirs(self.reports)
        self.readme = os.path.join(self.tmp, "README.md")
        with open(self.readme, "w", encoding="utf-8") as f:
            f.write(f"intro\n{publish.BEGIN}\n{publish.END}\n")
        make_run(self.reports)

    def with_road(self, table_build):
        """A 1000-segment road in the run: newton (1000 evaluations a query, 5e4 to build) and the
        sized Hermite table (none a query, table_build to build), both under 1e-10; evaluations is
        the query's plus the build amortized over 1000 queries, as the accuracy runner writes it."""
        path = os.path.join(self.reports, "accuracy.json")
        with open(path, encoding="utf-8") as f:
            acc = json.load(f)
        acc["cases"] = [c for c in acc["cases"] if c["name"] != "road"] + [
            {"name": "road", "family": "composite_bezier", "group": "road", "segments": 1000}]
        acc["records"] = [r for r in acc["records"] if r["case"] != "road"]
        for c in acc["cases"]:  # every case as the accuracy runner writes it, with its group (REPORT.md's References)
            c.setdefault("group", "smooth")
        for method, err, query, build in (("newton", 1e-13, 1000.0, 5e4),
                                          ("hermite_table_sized", 3e-13, 0.0, table_build)):
            acc["records"].append({"case": "road", "group": "road", "quantity": "u_of_s", "method": method,
                                   "setting": "tol=1e-12", "error": err, "estimate": 2 * err, "bounded": True,
                                   "evaluations": query + build / 1000, "status": "converged",
                                   "query_evaluations": query, "build_evaluations": build})
        with open(path, "w", encoding="utf-8") as f:
            json.dump(acc, f)

    def pages(self):
        h = publish.publish(self.reports, self.docs, self.readme, allow_missing_peers=True)
        with open(self.readme, encoding="utf-8") as f:
            readme = f.read()
        with open(os.path.join(self.docs, "results.md"), encoding="utf-8") as f:
            results = f.read()
        import report_fixture
        with open(os.path.join(self.reports, "accuracy.json"), encoding="utf-8") as f:
            acc = json.load(f)
        report = report_fixture.run_report(self, acc)
        return h, readme, results, report

    def road_answer(self, h):
        (line,) = [a for a in report_summary.answer_lines(h["recommendations"]) if a.startswith("`u_of_s`")]
        return line

    def test_readme_results_and_report_agree_and_the_break_even_comes_from_the_records(self):
        self.with_road(2.2e6)
        h, readme, results, report = self.pages()
        line = self.road_answer(h)
        # newton is the cheaper at the records' 1000 queries; the table pays off past
        # (2.2e6 - 5e4) / (1000 - 0) = 2150 queries
        self.assertEqual(line, "`u_of_s`, 100+ segments (road, 1 case): newton tol=1e-12 (1.05e+03 evals); by query "
                               "count: newton tol=1e-12 (1e+03 evals a query, 5.00e+04 to build) up to 2150 queries, "
                               "then hermite_table_sized tol=1e-12 (0 evals a query, 2.20e+06 to build)")
        self.assertIn(f"  {line};", readme)  # an item of the headline
        for page in (results, report):
            summary = page[page.index("## Summary"):page.index("## Contents")]
            self.assertIn(f"  - {line}", summary)
            self.assertIn("| `u_of_s` | road | 100+ segments | 1 |", summary)
            self.assertIn("newton tol=1e-12 (1.05e+03 evals); by query count: newton tol=1e-12 (1e+03 evals a query, "
                          "5.00e+04 to build) up to 2150 queries", summary)
        self.assertNotIn("u(s), fastest reaching", readme)  # the one-curve benchmark no longer answers it
        # A cheaper table build moves the break-even: (1.3e6 - 5e4) / 1000 = 1250 queries.
        self.with_road(1.3e6)
        h, readme, results, report = self.pages()
        line = self.road_answer(h)
        self.assertIn("up to 1250 queries, then hermite_table_sized tol=1e-12 (0 evals a query, 1.30e+06 to build)",
                      line)
        for page in (readme, results, report):
            self.assertIn(line, page)

    def test_records_without_the_split_say_so_and_give_no_break_even(self):
        self.with_road(2.2e6)
        path = os.path.join(self.reports, "accuracy.json")
        with open(path, encoding="utf-8") as f:
            acc = json.load(f)
        for r in acc["records"]:
            r.pop("query_evaluations", None)
            r.pop("build_evaluations", None)
        with open(path, "w", encoding="utf-8") as f:
            json.dump(acc, f)
        h, readme, results, report = self.pages()
        self.assertEqual(self.road_answer(h),
                         "`u_of_s`, 100+ segments (road, 1 case): newton tol=1e-12 (1.05e+03 evals)")
        self.assertIn("do not carry `build_evaluations` and `query_evaluations` apart", report)


class CheckedIn(unittest.TestCase):
    """What the repository holds was rendered from its own headline.json, from a full run."""

    def setUp(self):
        with open(os.path.join(ROOT, "docs", "results", "headline.json"), encoding="utf-8") as f:
            self.h = json.load(f)

    def test_headline_is_a_full_run(self):
        self.assertFalse(self.h["run"]["quick"])

    def test_the_page_opens_with_the_summary_then_the_contents(self):
        # The published page, like REPORT.md, answers first (its summary), then lists its sections.
        with open(os.path.join(ROOT, "docs", "results.md"), encoding="utf-8") as f:
            sections = [line for line in f.read().splitlines() if line.startswith("## ")]
        self.assertEqual(sections[:3], ["## Summary", "## Contents", "## Machine and run"])

    def test_readme_figures_are_generated(self):
        with open(os.path.join(ROOT, "README.md"), encoding="utf-8") as f:
            readme = f.read()
        self.assertIn(publish.render_readme(self.h), readme)

    def test_results_page_is_generated_and_small(self):
        plots = sorted(os.path.basename(p) for p in glob.glob(os.path.join(ROOT, "docs", "results", "*.png")))
        with open(os.path.join(ROOT, "docs", "results.md"), encoding="utf-8") as f:
            page = f.read()
        self.assertLessEqual(len(plots), publish.MAX_PLOTS)
        for p in plots:
            self.assertIn(f"(results/{p})", page)
        size = sum(os.path.getsize(p) for p in glob.glob(os.path.join(ROOT, "docs", "results", "*")))
        self.assertLess(size + len(page.encode()), publish.MAX_PLOT_BYTES)
        # Same text as publish.py renders, whatever order the plots were chosen in.
        shown = [line[2:line.index("]")] for line in page.splitlines() if line.startswith("![")]
        # The fidelity block (refreshed alone by publish.py --fidelity-only) follows the run's part.
        i, j = page.find(publish.FIDELITY_BEGIN), page.find(publish.FIDELITY_END)
        self.assertTrue(0 <= i < j, "docs/results.md has its fidelity block")
        block = page[i:j + len(publish.FIDELITY_END)]
        self.assertEqual(page, publish.replace_fidelity(publish.render_results(self.h, shown) + "\n", block))


if __name__ == "__main__":
    unittest.main()
