"""`scripts/report.py --checks FILE...`: the user's own `curvebench check --json` results in the
report. The files under fixtures/checks/ are the tool's own output (fixtures/checks/README.md says
how each was made): a values check in ulps of float and one in ulps of double over --max-error 4, a
lengths and inverse check relative to L, and a channel's float values in ulps of float x max(|V|,
range) with a scale per row. Run with /usr/bin/python3 (report.py plots with matplotlib)."""
import importlib.util
import json
import os
import shutil
import subprocess
import sys
import tempfile
import unittest

HERE = os.path.dirname(os.path.abspath(__file__))
SCRIPTS = os.path.join(HERE, "..", "..", "scripts")
CHECKS = os.path.join(HERE, "fixtures", "checks")
sys.path.insert(0, SCRIPTS)
import report_checks  # noqa: E402

FILES = [os.path.join(CHECKS, n) for n in ("arch_pass.json", "arch_over.json", "bent_pass.json", "bold_s_float.json")]


class Pure(unittest.TestCase):
    def setUp(self):
        self.files = report_checks.load(FILES)

    def test_each_check_is_judged_by_the_limit_the_tool_applied_to_its_kind(self):
        verdicts = [(os.path.basename(p), c["kind"], report_checks.verdict(doc, c))
                    for p, doc in self.files for c in doc["checks"]]
        self.assertEqual(verdicts, [("arch_pass.json", "values", "passed"), ("arch_over.json", "values", "over"),
                                    ("bent_pass.json", "lengths", "passed"), ("bent_pass.json", "inverse", "passed"),
                                    ("bold_s_float.json", "times", "passed")])
        # a file's own limit of a kind wins over --max-error, as limit_of in check.cpp
        doc = {"max_error": 1.0, "max_length_error": 1e-20}
        self.assertEqual(report_checks.limit(doc, "lengths"), 1e-20)
        self.assertEqual(report_checks.limit(doc, "inverse"), 1.0)
        self.assertIsNone(report_checks.limit({}, "values"))
        over = {"kind": "values", "unit": "u", "summary": {"max": None}}  # a non-finite max: over, as the tool says
        self.assertEqual(report_checks.verdict({"max_error": 4.0}, over), "over")
        self.assertEqual(report_checks.verdict({}, over), "no gate")

    def test_the_rows_say_each_figure_in_its_checks_unit(self):
        rows = {(r[0], r[3]): r for r in report_checks.rows(self.files)}
        over = rows[("arch_over.json", "values")]
        self.assertEqual(over[5:8], ["2.25e+06", "1.01e+06", "ulps of double x size"])
        self.assertEqual(over[8:], ["size 4", "line 4 of arch_values_off.csv", "4", "over"])
        self.assertEqual(rows[("arch_pass.json", "values")][7], "ulps of float x size")
        times = rows[("bold_s_float.json", "times")]
        self.assertEqual(times[7], "ulps of float x max(|value|, value range)")
        self.assertEqual(times[8], "row scale 1")  # max(|V(t)|, range) with range 1 on every row
        self.assertEqual(rows[("bent_pass.json", "inverse")][7], "relative to L")

    def test_counts(self):
        n = report_checks.counts(self.files)
        self.assertEqual((n["files"], n["passed"], n["failed"], n["checks"], n["over"]), (4, 3, 1, 5, 1))
        self.assertEqual(report_checks.summary_text(self.files),
                         "4 check result files (5 checks): 3 passed, 1 failed; 1 check over its gate: "
                         "arch_over.json values: max 2.25e+06 ulps of double x size > 4.")

    def test_what_is_not_a_check_result_is_refused_naming_the_file(self):
        d = tempfile.mkdtemp()
        self.addCleanup(shutil.rmtree, d)
        bad = os.path.join(d, "accuracy.json")
        with open(bad, "w", encoding="utf-8") as f:
            json.dump({"records": []}, f)
        with self.assertRaises(report_checks.ChecksError) as e:
            report_checks.load([bad])
        self.assertIn(f"{bad}: not a `curvebench check --json` result", str(e.exception))


@unittest.skipUnless(importlib.util.find_spec("matplotlib"), "report.py plots with matplotlib")
class ReportOfChecks(unittest.TestCase):
    def run_report(self, d, *extra):
        p = subprocess.run([sys.executable, os.path.join(SCRIPTS, "report.py"), "--reports", d, *extra],
                           capture_output=True, text=True, timeout=600)
        return p

    def test_a_report_of_the_users_checks_alone_counts_them_in_its_summary(self):
        d = tempfile.mkdtemp()
        self.addCleanup(shutil.rmtree, d)
        p = self.run_report(d, "--checks", *FILES)
        self.assertEqual(p.returncode, 0, p.stderr)
        with open(os.path.join(d, "REPORT.md"), encoding="utf-8") as f:
            md = f.read()
        summary = md[md.index("## Summary"):md.index("## Contents")]
        self.assertIn("- **How did my own implementations do?** 4 check result files (5 checks): 3 passed, 1 failed; "
                      "1 check over its gate: arch_over.json values: max 2.25e+06 ulps of double x size > 4. See "
                      "[your checks](#your-checks-curvebench-check---json).", summary)
        # user rows are shown: the summary never says there are no records at all
        self.assertNotIn("No accuracy records.", md)
        self.assertIn("No records of curvebench's own methods in this run", summary)
        self.assertIn("\n## Your checks (curvebench check --json)\n", md)
        self.assertIn("| arch_over.json | ../../../../bench/cases/arch_cubic_bezier.json | my_engine | values | 5 | "
                      "2.25e+06 | 1.01e+06 | ulps of double x size | size 4 | line 4 of arch_values_off.csv | 4 "
                      "| over |", md)
        # the files' records are the user's implementations, in their own section
        self.assertIn("\n## Your implementations (subjects) beside curvebench's methods\n", md)
        self.assertIn("| channel_bold_s | eval | my_player |", md)
        self.assertTrue(os.path.exists(os.path.join(d, "REPORT.html")))

    def test_a_file_that_is_not_a_check_result_stops_the_report_naming_it(self):
        d = tempfile.mkdtemp()
        self.addCleanup(shutil.rmtree, d)
        p = self.run_report(d, "--checks", os.path.join(CHECKS, "arch_values.csv"))
        self.assertEqual(p.returncode, 1)
        self.assertIn("arch_values.csv: not JSON", p.stderr)

    def test_help_documents_the_option(self):
        p = subprocess.run([sys.executable, os.path.join(SCRIPTS, "report.py"), "--help"], capture_output=True,
                           text=True, timeout=120)
        self.assertIn("--checks FILE [FILE ...]", p.stdout)
        self.assertIn("curvebench check ... --json", p.stdout)


if __name__ == "__main__":
    unittest.main()
