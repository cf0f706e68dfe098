"""Unit tests of scripts/report_lib.py (report.py's pure helpers) on the small fixtures in
fixtures/: per-operation times, the vocabulary checks, pairing with peers, error targets, the
Pareto front and the join of length records with per-case timings. Run by ctest (report_py):
  /usr/bin/python3 -m unittest discover -s tests/python"""
import copy
import importlib.util
import io
import json
import os
import shutil
import subprocess
import sys
import tempfile
import unittest

HERE = os.path.dirname(os.path.abspath(__file__))
SCRIPTS = os.path.join(HERE, "..", "..", "scripts")
sys.path.insert(0, SCRIPTS)
import report_lib as lib  # noqa: E402

FIXTURES = os.path.join(HERE, "fixtures")


def fixture(name):
    with open(os.path.join(FIXTURES, name), encoding="utf-8") as f:
        return json.load(f)


def vocabulary():
    return lib.load_vocabulary(os.path.join(FIXTURES, "vocabulary.json"))


def rows_of(name):
    return lib.benchmark_rows(fixture(name), vocabulary(), name)


def by_name(rows):
    return {r["name"]: r for r in rows}


class PerOperation(unittest.TestCase):
    def test_batch_of_1024_at_2us_reads_2ns_per_evaluation(self):
        # 2.048 us per iteration for 1024 evaluations: 2 ns each (items_per_second 5e8).
        r = by_name(rows_of("bench_batch.json"))["piecewise_cubic/power/calls:sorted/segments:64/knots:uniform"]
        self.assertEqual(r["operation"], "evaluation")
        self.assertAlmostEqual(r["ns_per_iteration"], 2048.0, places=9)
        self.assertAlmostEqual(r["ns_per_op"], 2.0, places=12)

    def test_sorted_batch_faster_than_single_per_point(self):
        rows = by_name(rows_of("bench_batch.json"))
        single = rows["piecewise_cubic/power/calls:single/segments:64/knots:uniform"]
        sorted_ = rows["piecewise_cubic/power/calls:sorted/segments:64/knots:uniform"]
        # Per iteration (what the old report printed as "ns per call") the batch looks 400x slower...
        self.assertGreater(sorted_["ns_per_iteration"] / single["ns_per_iteration"], 400)
        # ...per evaluation it is 2.5x faster, and the two rank together.
        self.assertAlmostEqual(single["ns_per_op"] / sorted_["ns_per_op"], 2.5, places=12)
        groups = lib.speed_groups(list(rows.values()), vocabulary())
        key = ("piecewise_cubic", "evaluation", (("segments", "64"), ("knots", "uniform")))
        self.assertEqual(len(groups[key]), 3)
        self.assertEqual(min(groups[key], key=lambda r: r["ns_per_op"])["name"], sorted_["name"])

    def test_recorded_run_sorted_faster_per_point(self):
        # Three rows of a real bench_piecewise_cubic run (--benchmark_min_time=0.02, 2 loaded cores):
        # per iteration the sorted batch of 1024 took ~12 us against ~20 ns for a single call.
        v = lib.load_vocabulary(os.path.join(FIXTURES, "vocabulary.json"))
        rows = by_name(lib.benchmark_rows(fixture("bench_piecewise_cubic_run.json"), v))
        single = rows["piecewise_cubic/power/calls:single/segments:64/knots:uniform"]
        sorted_ = rows["piecewise_cubic/power/calls:sorted/segments:64/knots:uniform"]
        self.assertGreater(sorted_["ns_per_iteration"], 100 * single["ns_per_iteration"])
        self.assertLess(sorted_["ns_per_op"], single["ns_per_op"])
        # 1e9 / items_per_second is the time per iteration over the items per iteration.
        self.assertAlmostEqual(sorted_["ns_per_op"], sorted_["ns_per_iteration"] / 1024,
                               delta=1e-6 * sorted_["ns_per_op"])

    def test_median_aggregate_kept_others_skipped(self):
        rows = rows_of("bench_batch.json")
        self.assertEqual(len(rows), 3)
        r = by_name(rows)["piecewise_cubic/matrix/calls:batch/segments:64/knots:uniform"]
        self.assertAlmostEqual(r["ns_per_op"], 40.0, places=9)  # the median's 2.5e7 items/s

    def test_repetitions_of_a_repeated_benchmark_skipped(self):
        # bench.sh keeps every repetition in the JSON (--benchmark_display_aggregates_only) for
        # `curvebench compare`; the report shows the median only.
        data = copy.deepcopy(fixture("bench_batch.json"))
        median = data["benchmarks"][2]
        for i in range(3):
            rep = copy.deepcopy(median)
            rep.update(run_type="iteration", repetition_index=i, name=median["run_name"])
            rep.pop("aggregate_name", None)
            data["benchmarks"].append(rep)
        rows = lib.benchmark_rows(data, vocabulary())
        self.assertEqual(len(rows), 3)
        self.assertEqual(sum(r["name"] == median["run_name"] for r in rows), 1)

    def test_display_names_settings_and_variants(self):
        v = vocabulary()
        r = by_name(rows_of("bench_batch.json"))["piecewise_cubic/power/calls:sorted/segments:64/knots:uniform"]
        self.assertEqual(lib.display_algorithm(r, v), "power calls:sorted")
        self.assertEqual(lib.data_args(r, v), (("segments", "64"), ("knots", "uniform")))


class Vocabulary(unittest.TestCase):
    def entry(self, **changes):
        e = copy.deepcopy(fixture("bench_batch.json")["benchmarks"][0])
        e.update(changes)
        return e

    def assert_fails(self, entry, *words):
        with self.assertRaises(lib.ReportError) as cm:
            lib.benchmark_row(entry, vocabulary())
        for w in words:
            self.assertIn(w, str(cm.exception))

    def test_valid_entry_passes(self):
        self.assertIsNotNone(lib.benchmark_row(self.entry(), vocabulary()))

    def test_unknown_counter_fails(self):
        self.assert_fails(self.entry(evals=1.0), "piecewise_cubic/power/calls:single", "counter 'evals'")

    def test_unknown_label_fails(self):
        self.assert_fails(self.entry(label="call"), "piecewise_cubic/power/calls:single", "label 'call'")

    def test_missing_label_fails(self):
        e = self.entry()
        del e["label"]
        self.assert_fails(e, "piecewise_cubic/power/calls:single", "label ''")

    def test_missing_items_fails(self):
        e = self.entry()
        del e["items_per_second"]
        self.assert_fails(e, "piecewise_cubic/power/calls:single", "items processed")

    def test_unknown_algorithm_fails(self):
        name = "arclength/adaptive_gk15/tol:1e-10"
        self.assert_fails(self.entry(name=name, run_name=name), name, "adaptive_gk15")

    def test_old_peer_spelling_fails(self):
        name = "catmull_rom/peer_boost/points:1000"
        self.assert_fails(self.entry(name=name, run_name=name), name, "peer_boost")

    def test_integer_variant_fails(self):
        name = "piecewise_cubic/power/calls:1"
        self.assert_fails(self.entry(name=name, run_name=name), name, "calls:1")

    def test_argument_without_key_fails(self):
        name = "piecewise_cubic/power/64"
        self.assert_fails(self.entry(name=name, run_name=name), name, "key:value")

    def test_case_benchmark_method_checked(self):
        v = vocabulary()
        ok = self.entry(name="arclength_case/runge/gauss/n=8", run_name="arclength_case/runge/gauss/n=8",
                        label="length")
        del ok["max_err_eps"]
        r = lib.benchmark_row(ok, v)
        self.assertEqual((r["case"], r["algorithm"], r["setting"]), ("runge", "gauss", "n=8"))
        name = "arclength_case/runge/adaptive/tol=1e-10"
        bad = dict(ok, name=name, run_name=name)
        self.assert_fails(bad, "arclength_case/runge/adaptive", "method 'adaptive'")

    def test_file_error_names_the_file(self):
        d = tempfile.mkdtemp()
        try:
            data = fixture("bench_batch.json")
            data["benchmarks"][1]["evals"] = 1024
            path = os.path.join(d, "bench_x.json")
            with open(path, "w", encoding="utf-8") as f:
                json.dump(data, f)
            with self.assertRaises(lib.ReportError) as cm:
                lib.load_benchmark_files([path], vocabulary())
            self.assertIn("bench_x.json", str(cm.exception))
            self.assertIn("piecewise_cubic/power/calls:sorted", str(cm.exception))
        finally:
            shutil.rmtree(d)


class Peers(unittest.TestCase):
    def test_pairs_only_same_operation_data_and_settings(self):
        v = vocabulary()
        pairs = {(o["name"], p["name"]) for o, p in lib.peer_pairs(rows_of("bench_peers.json"), v)}
        self.assertEqual(pairs, {
            ("catmull_rom/power/points:1000/queries:random",
             "catmull_rom/peer_boost_catmull_rom/points:1000/queries:random"),
            ("arclength/gauss/n:10", "arclength/peer_boost_gauss/n:10"),
        })
        # Not paired: the query row (another operation on the same data), the sorted peer (other
        # data), gauss n:20 and adaptive_gk (other settings).

    def test_headline_ratio_per_operation(self):
        heads = {p["name"]: ratio for _, p, ratio in lib.headline_ratios(rows_of("bench_peers.json"), vocabulary())}
        self.assertAlmostEqual(heads["catmull_rom/peer_boost_catmull_rom/points:1000/queries:random"], 0.5, places=12)
        self.assertAlmostEqual(heads["arclength/peer_boost_gauss/n:10"], 0.8, places=12)
        self.assertEqual(len(heads), 2)


class Targets(unittest.TestCase):
    def test_fastest_at_targets(self):
        out = lib.fastest_at_targets(rows_of("bench_peers.json"), vocabulary(), targets=(1e-9, 1e-15))
        got = {(t["family"], t["counter"], t["target"]): t for t in out}
        t9 = got[("arclength", "rel_error", 1e-9)]
        self.assertEqual(t9["best"]["name"], "arclength/gauss/n:10")
        self.assertEqual(t9["best_peer"]["name"], "arclength/peer_boost_gauss/n:10")
        t15 = got[("arclength", "rel_error", 1e-15)]
        self.assertEqual(t15["best"]["name"], "arclength/gauss/n:20")  # 700 ns beats adaptive's 4000
        self.assertIsNone(t15["best_peer"])
        # max_err_eps is in eps units: no relative targets for it.
        self.assertFalse(any(t["counter"] == "max_err_eps" for t in
                             lib.fastest_at_targets(rows_of("bench_batch.json"), vocabulary())))


class Pareto(unittest.TestCase):
    def test_front(self):
        pts = [(10, 1e-3, "a"), (20, 1e-2, "b"), (30, 1e-6, "c"), (5, 1e-1, "d"), (30, 1e-7, "e"), (40, 1e-7, "f")]
        self.assertEqual(lib.pareto_front(pts), [(5, 1e-1, "d"), (10, 1e-3, "a"), (30, 1e-7, "e")])

    def test_empty(self):
        self.assertEqual(lib.pareto_front([]), [])


class Spread(unittest.TestCase):
    def test_largest_ratio_of_two_methods_within_one_decade_of_cost(self):
        # decade 1e2: a 1e-6, b 1e-9 (ratio 1e3); decade 1e3: a 1e-8 alone (no second method)
        pts = [(200, 1e-6, "a"), (500, 1e-9, "b"), (300, 1e-5, "a"), (2000, 1e-8, "a")]
        self.assertAlmostEqual(lib.method_spread(pts), 1e3)
        self.assertEqual(lib.method_spread([(10, 1e-3, "a"), (1e4, 1e-9, "b")]), 1.0)  # never at equal cost
        # errors below eps(double) are rounding: they compare at eps, a lucky 0 is not an infinite spread
        self.assertAlmostEqual(lib.method_spread([(10, 0.0, "a"), (20, 1e-12, "b")]), 1e-12 / 2.0 ** -52)
        self.assertEqual(lib.method_spread([(10, 0.0, "a"), (20, 1e-17, "b")]), 1.0)

    def test_featured_cases_largest_spread_first(self):
        per_case = {"flat": [(10, 1e-6, "a"), (20, 1e-6, "b")], "wide": [(10, 1e-3, "a"), (20, 1e-12, "b")],
                    "mid": [(10, 1e-3, "a"), (20, 1e-6, "b")]}
        self.assertEqual([c for c, _ in lib.featured_cases(per_case, 2)], ["wide", "mid"])


@unittest.skipUnless(importlib.util.find_spec("matplotlib"), "report.py plots with matplotlib")
class Convergence(unittest.TestCase):
    def setUp(self):
        import report
        self.report = report

    def test_series_of_a_theory_method_without_an_order_are_named(self):
        records = [{"case": c, "quantity": "length", "method": m, "setting": "n=2", "error": 1e-3}
                   for c in ("a", "b") for m in ("gauss", "composite_gauss")]
        orders = [{"case": "a", "quantity": "length", "method": "composite_gauss", "observed": 6.0}]
        vocab = lib.Vocabulary({"quantities": [], "peers": [], "operations": [], "counters": [],
                                "methods": [{"id": "gauss", "theory": 0}, {"id": "composite_gauss", "theory": 6}]})
        self.assertEqual(self.report.series_without_order(records, orders, vocab),
                         {("length", "composite_gauss"): ["b"]})

    def test_panels_name_at_most_ten_cases_of_extreme_orders(self):
        orders = [{"case": f"c{i:02d}", "quantity": "length", "method": "m", "observed": float(i)} for i in range(14)]
        records = [{"case": o["case"], "quantity": "length", "method": "m", "error": 10.0 ** -k, "evaluations": 2 ** k}
                   for o in orders for k in (1, 2, 3)]
        panels, labelled = self.report.convergence_panels(orders, records)
        self.assertEqual(list(panels), [("length", "m")])
        self.assertEqual(len(panels[("length", "m")]), 14)
        self.assertEqual(labelled[("length", "m")], [f"c{i:02d}" for i in (0, 1, 2, 3, 4, 9, 10, 11, 12, 13)])


@unittest.skipUnless(importlib.util.find_spec("matplotlib") and importlib.util.find_spec("PIL"),
                     "the palette PNG needs matplotlib and Pillow")
class PalettePng(unittest.TestCase):
    def test_a_plot_is_saved_with_a_palette_and_keeps_its_colours(self):
        import report
        from PIL import Image
        fig, ax = report.plt.subplots(figsize=(3, 2))
        ax.plot([0, 1], [0, 1], color="#1f77b4", lw=4)
        data = report.png_bytes(fig)
        report.plt.close(fig)
        im = Image.open(io.BytesIO(data))
        self.assertEqual(im.mode, "P")
        colours = {c for _, c in im.convert("RGB").getcolors(65536)}
        # The line's colour survives the palette within a few levels per channel (median cut).
        self.assertTrue(any(max(abs(a - b) for a, b in zip(c, (0x1F, 0x77, 0xB4))) <= 8 for c in colours))
        self.assertIn((255, 255, 255), colours)


class ManySegments(unittest.TestCase):
    def test_query_time_is_given_per_case_with_its_ratio_to_one_segment(self):
        def row(family, case, ns, cells):
            return {"family": family, "args": [("case", case), ("tol", "1e-12")], "ns_per_op": ns,
                    "counters": {"table_intervals": cells}}
        rows = [row("u_of_s_case", "one", 5.0, 64), row("u_of_s_build_case", "one", 2e6, 64),
                row("u_of_s_case", "road", 8.0, 250000.0), row("u_of_s_build_case", "road", 4e8, 250000),
                {"family": "arclength", "args": [], "ns_per_op": 1.0, "counters": {}}]
        md = "\n".join(lib.table_per_segments(rows, {"one": 1, "road": 1000}))
        self.assertIn("the one-segment case one's in the same run", md)
        lines = [x for x in md.splitlines() if x.startswith("| road")]
        self.assertEqual(len(lines), 1)
        cells = [c.strip() for c in lines[0].strip("|").split("|")]
        self.assertEqual(cells[:4], ["road", "1000", "1e-12", "250000"])
        self.assertEqual(cells[4], "400")  # build in ms
        self.assertEqual(cells[6], "1.6")  # 8 ns against 5 ns
        self.assertEqual(lib.table_per_segments(rows[-1:], {}), [])


class Join(unittest.TestCase):
    def test_unmatched_reported_both_ways(self):
        records = [
            {"case": "runge", "quantity": "length", "method": "gauss", "setting": "n=8", "error": 1e-9},
            {"case": "runge", "quantity": "length", "method": "gauss", "setting": "n=64", "error": 1e-15},
            {"case": "runge", "quantity": "length", "method": "subdivision", "setting": "tol=1e-06", "error": None},
            {"case": "runge", "quantity": "u_of_s", "method": "hermite_table", "setting": "M=256", "error": 1e-12},
        ]
        times = {("runge", "gauss", "n=8"): 300.0, ("runge", "adaptive_gk", "tol=1e-10"): 2000.0,
                 ("runge", "subdivision", "tol=1e-06"): 9000.0}
        joined, no_time, no_record, no_error = lib.join_lengths(records, times)
        self.assertEqual(joined, {"runge": [(300.0, 1e-9, "gauss", "n=8")]})
        self.assertEqual(no_time, [("runge", "gauss", "n=64")])
        self.assertEqual(no_record, [("runge", "adaptive_gk", "tol=1e-10")])
        self.assertEqual(no_error, [("runge", "subdivision", "tol=1e-06")])

    def test_case_times_need_length(self):
        rows = [{"family": lib.CASE_FAMILY, "name": "arclength_case/c/gauss/n=8", "case": "c", "algorithm": "gauss",
                 "setting": "n=8", "operation": "query", "ns_per_op": 1.0}]
        with self.assertRaises(lib.ReportError):
            lib.case_times(rows)


@unittest.skipUnless(importlib.util.find_spec("matplotlib"), "report.py plots with matplotlib")
class ReportScript(unittest.TestCase):
    """report.py itself: per-operation speed tables, and exit 1 naming an unknown benchmark."""

    def run_report(self, benchmarks, vocabulary=None):
        d = tempfile.mkdtemp()
        self.addCleanup(shutil.rmtree, d)
        if vocabulary is None:
            shutil.copy(os.path.join(FIXTURES, "vocabulary.json"), d)
        else:
            with open(os.path.join(d, "vocabulary.json"), "w", encoding="utf-8") as f:
                json.dump(vocabulary, f)
        with open(os.path.join(d, "bench_x.json"), "w", encoding="utf-8") as f:
            json.dump(benchmarks, f)
        p = subprocess.run([sys.executable, os.path.join(SCRIPTS, "report.py"), "--reports", d],
                           capture_output=True, text=True)
        report = ""
        if os.path.exists(os.path.join(d, "REPORT.md")):
            with open(os.path.join(d, "REPORT.md"), encoding="utf-8") as f:
                report = f.read()
        return p, report

    def test_speed_table_per_evaluation(self):
        p, report = self.run_report(fixture("bench_batch.json"))
        self.assertEqual(p.returncode, 0, p.stderr)
        self.assertIn("| data | algorithm | ns per evaluation |", report)
        self.assertIn("| segments:64/knots:uniform | power calls:sorted | 2 | 1 |", report)
        self.assertIn("| segments:64/knots:uniform | power calls:single | 5 | 2.5 |", report)

    def test_floor_ratio_per_evaluation_with_matching_calls_and_timing(self):
        # A sorted batch of 1024 taking 2.048 us is 2 ns per evaluation; its floor, a batch of 4096 at
        # 4.096 us, 1 ns: ratio 2 whatever the batch sizes. The single call (5 ns) has a floor only
        # for timing:latency, so it gets no ratio; FLOPs are per evaluation as the counter says.
        with open(os.path.join(FIXTURES, "vocabulary.json"), encoding="utf-8") as f:
            vocabulary = json.load(f)
        vocabulary["algorithms"].append({"id": "floor_soa_sorted", "settings": [], "doc": "floor"})
        vocabulary["algorithms"].append({"id": "floor_horner", "settings": [], "doc": "floor"})
        vocabulary["variant_keys"].append({"id": "timing", "values": ["throughput", "latency"], "doc": "t"})
        vocabulary["counters"].append({"name": "flops", "kind": "count", "doc": "per evaluation"})

        def entry(name, cpu_ns, items_per_iteration, flops):
            return {"name": name, "run_name": name, "run_type": "iteration", "repetitions": 1, "repetition_index": 0,
                    "threads": 1, "iterations": 1000, "real_time": cpu_ns, "cpu_time": cpu_ns, "time_unit": "ns",
                    "items_per_second": items_per_iteration * 1e9 / cpu_ns, "flops": flops, "label": "evaluation"}
        data = "segments:64/knots:uniform"
        benchmarks = {"context": {}, "benchmarks": [
            entry(f"piecewise_cubic/power/calls:sorted/timing:throughput/{data}", 2048.0, 1024, 20),
            entry(f"piecewise_cubic/floor_soa_sorted/calls:sorted/timing:throughput/{data}", 4096.0, 4096, 20),
            entry(f"piecewise_cubic/power/calls:single/timing:throughput/{data}", 5.0, 1, 20),
            entry(f"piecewise_cubic/floor_horner/calls:single/timing:latency/{data}", 4.0, 1, 20)]}
        p, report = self.run_report(benchmarks, vocabulary)
        self.assertEqual(p.returncode, 0, p.stderr)
        self.assertIn("| piecewise_cubic | segments:64/knots:uniform | power calls:sorted timing:throughput | 2 | "
                      "floor_soa_sorted: 2 | 20 | 10 |", report)
        self.assertNotIn("power calls:single timing:throughput | 5 | floor", report)

    def test_unknown_counter_exits_1_naming_the_benchmark(self):
        data = fixture("bench_batch.json")
        data["benchmarks"][0]["max_rel_s_err"] = 1e-9
        p, _ = self.run_report(data)
        self.assertEqual(p.returncode, 1)
        self.assertIn("piecewise_cubic/power/calls:single/segments:64/knots:uniform", p.stderr)
        self.assertIn("max_rel_s_err", p.stderr)


if __name__ == "__main__":
    unittest.main()
