"""Shared by the report tests: runs scripts/report.py on a temporary reports directory holding the
fixtures' vocabulary and benchmark file, the given accuracy document and optional peer files, and
returns REPORT.md's text (the test fails on a non-zero exit, with report.py's stderr)."""
import json
import os
import shutil
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
SCRIPTS = os.path.join(HERE, "..", "..", "scripts")
FIXTURES = os.path.join(HERE, "fixtures")


def run_report(test, acc, peer_files=(), directory=None):
    """directory: where to run (the caller reads REPORT.html there too); default a temporary one."""
    d = directory
    if d is None:
        d = tempfile.mkdtemp()
        test.addCleanup(shutil.rmtree, d)
    for name, doc in peer_files:
        with open(os.path.join(d, name), "w", encoding="utf-8") as f:
            json.dump(doc, f)
    shutil.copy(os.path.join(FIXTURES, "vocabulary.json"), d)
    shutil.copy(os.path.join(FIXTURES, "bench_batch.json"), os.path.join(d, "bench_x.json"))
    with open(os.path.join(d, "accuracy.json"), "w", encoding="utf-8") as f:
        json.dump(acc, f)
    p = subprocess.run([sys.executable, os.path.join(SCRIPTS, "report.py"), "--reports", d],
                       capture_output=True, text=True)
    test.assertEqual(p.returncode, 0, p.stderr)
    with open(os.path.join(d, "REPORT.md"), encoding="utf-8") as f:
        return f.read()
