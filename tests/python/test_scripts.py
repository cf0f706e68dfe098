"""The scripts' command lines: `bench.sh --help` prints its usage comment and nothing else (it
printed `set -euo pipefail`, a fixed line range having drifted from the comment)."""
import os
import shutil
import subprocess
import sys
import tempfile
import unittest

ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..")


def usage_comment(path):
    """The comment block under a script's shebang, without its "# ": what --help must print."""
    with open(path, encoding="utf-8") as f:
        lines = f.read().splitlines()
    comment = []
    for line in lines[1:]:
        if not line.startswith("#"):
            break
        comment.append(line[2:] if line.startswith("# ") else line[1:])
    return comment


class BenchHelp(unittest.TestCase):
    def test_help_is_the_usage_comment(self):
        path = os.path.join(ROOT, "scripts", "bench.sh")
        comment = usage_comment(path)
        p = subprocess.run(["bash", path, "--help"], capture_output=True, text=True, timeout=60)
        self.assertEqual(p.returncode, 0, p.stderr)
        self.assertEqual(p.stdout.splitlines(), comment)
        self.assertIn("scripts/bench.sh --quick", p.stdout)
        self.assertNotIn("set -euo pipefail", p.stdout)


class FuzzHelp(unittest.TestCase):
    """`fuzz.sh --help` likewise (it builds nothing and installs nothing), and a bad argument is a
    usage error (exit 2) naming it, before anything is installed or built."""

    def test_help_is_the_usage_comment(self):
        path = os.path.join(ROOT, "scripts", "fuzz.sh")
        comment = usage_comment(path)
        p = subprocess.run(["bash", path, "--help"], capture_output=True, text=True, timeout=60)
        self.assertEqual(p.returncode, 0, p.stderr)
        self.assertEqual(p.stdout.splitlines(), comment)
        self.assertIn("scripts/fuzz.sh [SECONDS] [TARGET...]", p.stdout)

    def test_bad_argument_is_a_usage_error(self):
        path = os.path.join(ROOT, "scripts", "fuzz.sh")
        for arg in ("ten", "0", "specs"):
            p = subprocess.run(["bash", path, arg], capture_output=True, text=True, timeout=60)
            self.assertEqual(p.returncode, 2, arg)
            self.assertIn("'" + arg + "'", p.stderr)


class ReportNeedsMatplotlib(unittest.TestCase):
    """`python3 scripts/report.py` under a python3 without matplotlib (a venv made from the system's
    python3 without its packages) exits 1 naming the module, itself and the interpreter that has it,
    where it used to end in a bare ImportError traceback."""

    def test_a_python3_without_matplotlib_is_told_which_one_has_it(self):
        with_it = subprocess.run(["/usr/bin/python3", "-c", "import matplotlib"], capture_output=True)
        if with_it.returncode != 0:
            self.skipTest("/usr/bin/python3 has no matplotlib here")
        d = tempfile.mkdtemp()
        self.addCleanup(shutil.rmtree, d)
        made = subprocess.run(["/usr/bin/python3", "-m", "venv", "--without-pip", os.path.join(d, "venv")],
                              capture_output=True, text=True, timeout=120)
        if made.returncode != 0:
            self.skipTest(f"no venv module: {made.stderr[-200:]}")
        python = os.path.join(d, "venv", "bin", "python3")
        p = subprocess.run([python, os.path.join(ROOT, "scripts", "report.py"), "--reports", d],
                           capture_output=True, text=True, timeout=300)
        self.assertEqual(p.returncode, 1, p.stderr)
        self.assertNotIn("Traceback", p.stderr)
        self.assertIn(f"this python3 ({python}", p.stderr)
        self.assertIn("cannot import 'matplotlib'", p.stderr)
        self.assertIn("run it with /usr/bin/python3 (which has it)", p.stderr)


class PublishNeedsEveryPeer(unittest.TestCase):
    """`peers.sh --check` names every driver that would be skipped and exits 1; `bench.sh --publish`
    asks it first and refuses (exit 2) before installing or building anything, where it used to find
    out after the whole run. Run from a copy of the scripts in an empty checkout (no build-peers/node:
    the Node peers are missing) with a PATH holding no blender."""

    def setUp(self):
        self.root = tempfile.mkdtemp()
        self.addCleanup(shutil.rmtree, self.root)
        os.makedirs(os.path.join(self.root, "scripts"))
        for name in ("peers.sh", "bench.sh"):
            shutil.copy(os.path.join(ROOT, "scripts", name), os.path.join(self.root, "scripts", name))
        self.bin = os.path.join(self.root, "bin")
        os.makedirs(self.bin)
        for tool in ("bash", "dirname", "head", "rm", "mkdir", "cat", "awk"):
            os.symlink(shutil.which(tool), os.path.join(self.bin, tool))
        self.env = dict(os.environ, PATH=self.bin)

    def test_check_names_the_missing_peers_and_fails(self):
        p = subprocess.run(["bash", os.path.join(self.root, "scripts", "peers.sh"), "--check"],
                           capture_output=True, text=True, timeout=60, env=self.env)
        self.assertEqual(p.returncode, 1, p.stderr)
        for name in ("easing", "penner", "three", "blender"):
            self.assertIn(f"peers.sh: {name}: ", p.stderr)
        self.assertNotIn("every optional peer is installed", p.stdout)
        self.assertFalse(os.path.exists(os.path.join(self.root, "reports")))  # nothing run, nothing removed

    def test_publish_is_refused_before_the_build(self):
        p = subprocess.run(["bash", os.path.join(self.root, "scripts", "bench.sh"), "--publish"],
                           capture_output=True, text=True, timeout=60, env=self.env)
        self.assertEqual(p.returncode, 2, p.stderr)
        self.assertIn("--publish: the optional peers above are not installed", p.stderr)
        self.assertIn("--allow-missing-peers", p.stderr)
        self.assertFalse(os.path.exists(os.path.join(self.root, "build-bench")))


class BaselineCheck(unittest.TestCase):
    """`bench.sh --baseline DIR` refuses a baseline that cannot be compared before the build: one
    cut short ran the whole 905 s and then reported "a confident regression"."""

    def setUp(self):
        self.dir = tempfile.mkdtemp(prefix="curvebench_baseline_")
        self.script = os.path.join(ROOT, "scripts", "baseline_check.py")

    def tearDown(self):
        shutil.rmtree(self.dir, ignore_errors=True)

    def write(self, name, text):
        with open(os.path.join(self.dir, name), "w", encoding="utf-8") as f:
            f.write(text)

    def check(self):
        return subprocess.run([sys.executable, self.script, self.dir], capture_output=True, text=True, timeout=60)

    def test_a_whole_baseline_passes(self):
        self.write("accuracy.json", '{"schema": 1, "records": [{"case": "a"}]}')
        self.write("bench_core.json", '{"context": {}, "benchmarks": [{"name": "b", "cpu_time": 1}]}')
        p = self.check()
        self.assertEqual(p.returncode, 0, p.stderr)

    def test_what_compare_cannot_read_is_named(self):
        cases = [
            ({}, "no accuracy.json and no bench_*.json"),
            ({"accuracy.json": '{"schema": 1, "records": [{"case": "a"}, {"ca'}, "not whole JSON"),
            ({"accuracy.json": '{"records": [{"error": NaN}]}'}, "NaN is not JSON"),
            ({"bench_x.json": '{"context": {}}'}, "holds neither"),
            ({"accuracy.json": '{"records": {}}'}, '"records" is not an array'),
            ({"accuracy.json": '{"records": [1]}'}, "records[0] is not an object"),
        ]
        for files, words in cases:
            with self.subTest(files=files):
                for name in os.listdir(self.dir):
                    os.remove(os.path.join(self.dir, name))
                for name, text in files.items():
                    self.write(name, text)
                p = self.check()
                self.assertEqual(p.returncode, 1, p.stdout)
                self.assertIn(words, p.stderr)
                for name in files:
                    self.assertIn(name, p.stderr)

    def test_a_quick_baseline_is_refused_for_a_full_run(self):
        self.write("accuracy.json", '{"records": [], "context": {"quick": true}}')
        p = subprocess.run([sys.executable, self.script, self.dir, "--full"], capture_output=True, text=True,
                           timeout=60)
        self.assertEqual(p.returncode, 1, p.stdout)
        self.assertIn("a quick run (context.quick is true), and this run is full", p.stderr)
        p = subprocess.run([sys.executable, self.script, self.dir, "--quick"], capture_output=True, text=True,
                           timeout=60)
        self.assertEqual(p.returncode, 0, p.stderr)

    def test_bench_sh_refuses_it_before_the_build(self):
        self.write("accuracy.json", '{"records": [')
        work = tempfile.mkdtemp(prefix="curvebench_bench_")
        try:
            shutil.copytree(os.path.join(ROOT, "scripts"), os.path.join(work, "scripts"))
            p = subprocess.run(["bash", os.path.join(work, "scripts", "bench.sh"), "--quick", "--baseline", self.dir],
                               capture_output=True, text=True, timeout=60)
            self.assertEqual(p.returncode, 2, p.stderr)
            self.assertIn("not whole JSON", p.stderr)
            self.assertIn("cannot be compared", p.stderr)
            self.assertFalse(os.path.exists(os.path.join(work, "build-bench")))
        finally:
            shutil.rmtree(work, ignore_errors=True)


if __name__ == "__main__":
    unittest.main()
