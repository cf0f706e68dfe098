"""Unit tests of report_lib's subject helpers: a user's implementation (records with
"subject": true) beside curvebench's own records of the same case and quantity. Run by ctest
(report_py) with the other tests of tests/python."""
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
sys.path.insert(0, SCRIPTS)
import report_lib as lib  # noqa: E402


def rec(case, quantity, method, error, evaluations=10, setting="", subject=False):
    r = {"case": case, "group": "smooth", "quantity": quantity, "method": method, "setting": setting,
         "error": error, "estimate": None, "bounded": None, "evaluations": evaluations, "status": "not_guaranteed"}
    if subject:
        r["subject"] = True
    return r


RECORDS = [
    rec("cr", "length", "gauss", 1e-3, 4, "n=2"),
    rec("cr", "length", "gauss", 1e-9, 16, "n=8"),
    rec("cr", "length", "adaptive_gk", 1e-15, 200, "tol=1e-14"),
    rec("cr", "eval", "default", 0.8, 65),
    rec("cr", "length", "own_table", 2e-5, 1, subject=True),
    rec("cr", "eval", "own_spline", 0.5, 65, subject=True),
    rec("other", "u_of_s", "own_table", 3e-5, 9, subject=True),
]


class Subjects(unittest.TestCase):
    def test_split_keeps_own_records_apart(self):
        own, subjects = lib.split_subjects(RECORDS)
        self.assertEqual(len(own), 4)
        self.assertEqual([s["method"] for s in subjects], ["own_table", "own_spline", "own_table"])

    def test_rows_beside_the_most_accurate_and_the_cheapest_as_accurate(self):
        own, subjects = lib.split_subjects(RECORDS)
        rows = lib.subject_rows(own, subjects)
        self.assertEqual(rows[0], ["cr", "eval", "own_spline", 0.5, "default", 0.8, "none"])
        # gauss n=8 (1e-9, 16 evaluations) is the cheapest record at least as accurate as 2e-5.
        self.assertEqual(rows[1], ["cr", "length", "own_table", 2e-5, "adaptive_gk tol=1e-14", 1e-15,
                                   "gauss n=8 (16 evals)"])
        # A subject measured on a case with no records of ours.
        self.assertEqual(rows[2], ["other", "u_of_s", "own_table", 3e-5, "-", "-", "-"])

    def test_no_subjects_no_rows(self):
        own, subjects = lib.split_subjects(RECORDS[:4])
        self.assertEqual(subjects, [])
        self.assertEqual(lib.subject_rows(own, subjects), [])


@unittest.skipUnless(importlib.util.find_spec("matplotlib"), "report.py plots with matplotlib")
class ReportWithSubjects(unittest.TestCase):
    def run_report(self, records):
        d = tempfile.mkdtemp()
        self.addCleanup(shutil.rmtree, d)
        shutil.copy(os.path.join(HERE, "fixtures", "vocabulary.json"), d)
        with open(os.path.join(d, "accuracy.json"), "w", encoding="utf-8") as f:
            json.dump({"records": records, "orders": [], "cases": []}, f)
        p = subprocess.run([sys.executable, os.path.join(SCRIPTS, "report.py"), "--reports", d],
                           capture_output=True, text=True)
        with open(os.path.join(d, "REPORT.md"), encoding="utf-8") as f:
            return p, f.read()

    def test_section_only_with_subjects(self):
        p, report = self.run_report(RECORDS)
        self.assertEqual(p.returncode, 0, p.stderr)
        self.assertIn("## Your implementations (subjects)", report)
        self.assertIn("| cr | length | own_table | 2.00e-05 | adaptive_gk tol=1e-14 | 1.00e-15 "
                      "| gauss n=8 (16 evals) |",
                      report)
        p, report = self.run_report(RECORDS[:4])
        self.assertEqual(p.returncode, 0, p.stderr)
        self.assertNotIn("## Your implementations", report)


if __name__ == "__main__":
    unittest.main()
