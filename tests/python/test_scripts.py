"""The scripts' command lines: `bench.sh --help` prints its usage comment and nothing else (it
printed `set -euo pipefail`, a fixed line range having drifted from the comment)."""
import os
import subprocess
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


if __name__ == "__main__":
    unittest.main()
