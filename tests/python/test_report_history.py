"""Tests of scripts/report_history.py: the history line of a run is built from its
headline data; the history file is read strictly (a bad line is named); publishing appends one line
per revision (a revision published again replaces its line); REPORT.md tables and plots the figures
over the runs with the current run last; the checked-in docs/results/history.jsonl holds the line
of the published docs/results/headline.json, so none of its figures is typed by hand.
Run by ctest (report_py): /usr/bin/python3 -m unittest discover -s tests/python"""
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
import report_history as rh  # noqa: E402
import report_lib as lib  # noqa: E402
from report_fixture import run_report  # noqa: E402
from test_publish import make_run  # noqa: E402


def headline(revision="abc1234", ns=5.0, bounded=9):
    return {"run": {"revision": revision, "date": "2026-11-27T10:00:00+00:00", "host": "vm", "cpus": 2, "mhz": 2600,
                    "compiler": "gcc 12.2.0", "quick": False, "accuracy_seconds": 250.0},
            "targets": [{"family": "u_of_s", "operation": "query", "target": 1e-10, "best": "hermite_table",
                         "best_ns": ns},
                        {"family": "arclength", "operation": "length", "target": 1e-14, "best": None,
                         "best_ns": None}],
            "honesty": {"bounded": bounded, "with_estimate": 10, "dishonest": [{}] * (10 - bounded), "records": 20},
            "channel": {"goal": {"max64": 2.5}}}


class Entry(unittest.TestCase):
    def test_figures_come_from_the_headline(self):
        e = rh.entry(headline())
        self.assertEqual(e["revision"], "abc1234")
        self.assertEqual(e["figures"], {"u_of_s query: fastest at 1e-10 (ns)": 5.0,
                                        "estimates that bound their error (share)": 0.9,
                                        "estimates that do not (count)": 1,
                                        "channel time solver max error (ulps)": 2.5,
                                        "accuracy run (s)": 250.0})
        self.assertEqual(e["methods"], {"u_of_s query: fastest at 1e-10 (ns)": "hermite_table"})
        # A target no benchmark reached is left out, not written as null.
        self.assertFalse(any("1e-14" in k for k in e["figures"]))

    def test_appending_a_revision_again_replaces_its_line(self):
        h = [rh.entry(headline("a")), rh.entry(headline("b"))]
        again = rh.appended(h, rh.entry(headline("a", ns=4.0)))
        self.assertEqual([x["revision"] for x in again], ["b", "a"])
        self.assertEqual(again[-1]["figures"]["u_of_s query: fastest at 1e-10 (ns)"], 4.0)


class Load(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.mkdtemp()
        self.addCleanup(shutil.rmtree, self.tmp)
        self.path = os.path.join(self.tmp, "history.jsonl")

    def write(self, *lines):
        with open(self.path, "w", encoding="utf-8") as f:
            f.write("".join(line + "\n" for line in lines))

    def test_round_trip_and_missing_file(self):
        self.assertEqual(rh.load(self.path), [])
        h = [rh.entry(headline("a")), rh.entry(headline("b"))]
        rh.write(self.path, h)
        self.assertEqual(rh.load(self.path), h)

    def test_a_bad_line_is_named(self):
        good = json.dumps(rh.entry(headline()))
        for bad, says in (("{", "line 2: not JSON"),
                          (json.dumps(dict(rh.entry(headline()), version=2)), "line 2: version 2"),
                          (json.dumps(dict(rh.entry(headline()), revision="")), "line 2: revision"),
                          (good.replace("250.0", "NaN"), "is not a finite number"),
                          (good.replace("250.0", "true"), "is not a finite number")):
            self.write(good, bad)
            with self.assertRaises(lib.ReportError) as cm:
                rh.load(self.path)
            self.assertIn(says, str(cm.exception))


class Publishing(unittest.TestCase):
    def test_each_publish_appends_its_revision_once(self):
        tmp = tempfile.mkdtemp()
        self.addCleanup(shutil.rmtree, tmp)
        reports, docs = os.path.join(tmp, "reports"), os.path.join(tmp, "docs")
        os.makedirs(reports)
        make_run(reports)
        publish.publish(reports, docs, None, allow_missing_peers=True)
        publish.publish(reports, docs, None, allow_missing_peers=True)  # the same revision again: one line
        history = rh.load(os.path.join(docs, "results", "history.jsonl"))
        self.assertEqual([e["revision"] for e in history], ["abc1234"])
        with open(os.path.join(docs, "results", "headline.json"), encoding="utf-8") as f:
            self.assertEqual(history[0], rh.entry(json.load(f)))


class Report(unittest.TestCase):
    def test_section_tables_every_run_and_marks_this_one(self):
        runs = [rh.entry(headline("a", 6.0)), rh.entry(headline("b", 5.0))]
        md = "\n".join(rh.section(runs, rh.entry(headline("c", 4.0)), tempfile.gettempdir(), None, None))
        self.assertIn("c (this run)", md)
        row = next(line for line in md.splitlines() if line.startswith("| u_of_s query"))
        self.assertEqual([c.strip() for c in row.split("|")[2:5]], ["6", "5", "4"])
        self.assertIn("No published run yet", "\n".join(rh.section([], None, "", None, None)))

    def test_report_plots_the_history(self):
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        tmp = tempfile.mkdtemp()
        self.addCleanup(shutil.rmtree, tmp)
        saved = []
        md = rh.section([rh.entry(headline("a"))], rh.entry(headline("b")), tmp, plt,
                        lambda fig, path: (fig.savefig(path), saved.append(path)))
        self.assertEqual(saved, [os.path.join(tmp, "history.png")])
        self.assertTrue(os.path.getsize(saved[0]) > 1000)
        self.assertIn("![history](plots/history.png)", md)

    def test_report_md_has_the_published_history(self):
        acc = {"context": {"revision": "xyz9876", "quick": True}, "records": [], "cases": []}
        text = run_report(self, acc)
        self.assertIn("## History", text)
        for e in rh.load(os.path.join(ROOT, rh.HISTORY)):
            self.assertIn(e["revision"], text)
        self.assertIn("xyz9876 (this run)", text)
        self.assertIn("quick run)", text)  # a quick run is said to be one beside the published full runs


class CheckedIn(unittest.TestCase):
    def test_the_published_run_is_in_the_history(self):
        with open(os.path.join(ROOT, "docs", "results", "headline.json"), encoding="utf-8") as f:
            published = rh.entry(json.load(f))
        self.assertIn(published, rh.load(os.path.join(ROOT, rh.HISTORY)))


if __name__ == "__main__":
    unittest.main()
