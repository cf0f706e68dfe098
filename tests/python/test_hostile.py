"""The hostile-input suite: every class of bad or extreme input as one case file in
tests/hostile/*.json, run through the curvebench tool with its expected exit code, the words its
message must contain and a wall-time bound that catches a hang.

A case file (unknown keys are an error, so that a typo cannot switch a check off):
  "why"             what the case guards against (required)
  "files"           name -> content: a string is written as is, another JSON value as its JSON
                    text, {"$pieces": [[text, count], ...]} as each text repeated count times
                    (deep nesting, huge values without a huge case file)
  "args"            the tool's arguments, run in the directory of the files (a name may hold one
                    directory: "cases/a.json"); "{name}" is replaced by that file's path
  "exit"            the exact exit code expected (required)
  "stderr_contains", "stdout_contains"   substrings that must appear
  "stdout_json"     stdout parsed as JSON must hold these key/values ("$finite": a finite number)
  "stdout_empty"    true: nothing on stdout (an error part-way must not leave a partial table)
  "seconds"         the wall-time bound (required), on the -O2 test build of this machine
  "memory_mb"       an address-space limit (RLIMIT_AS) for the run: an input whose work must stay
                    bounded fails with bad_alloc, or dies, past it
Whatever the case expects, the tool may never die of a signal, print "terminate called", or
exit non-zero without a "curvebench: error: " line on stderr.

Needs the tool: CURVEBENCH_TOOL=path/to/curvebench (the `hostile` ctest sets it); skipped
without, as under `report_py`'s unittest discover."""
import glob
import json
import math
import os
import resource
import shutil
import subprocess
import tempfile
import time
import unittest

ROOT = os.path.abspath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
TOOL = os.environ.get("CURVEBENCH_TOOL", "")
CASE_DIR = os.path.join(ROOT, "tests", "hostile")
KEYS = {"why", "files", "args", "exit", "stderr_contains", "stdout_contains", "stdout_json", "stdout_empty", "seconds",
        "memory_mb"}
REQUIRED = {"why", "args", "exit", "seconds"}


def case_files():
    return sorted(glob.glob(os.path.join(CASE_DIR, "*.json")))


def file_text(content):
    if isinstance(content, str):
        return content
    if isinstance(content, dict) and set(content) == {"$pieces"}:
        return "".join(text * count for text, count in content["$pieces"])
    return json.dumps(content)


def json_subset_problems(want, got, path="stdout"):
    """The ways `got` fails to hold `want` (a dict of key -> value, nested dicts recursively)."""
    problems = []
    if not isinstance(got, dict):
        return [f"{path} is not a JSON object"]
    for key, value in want.items():
        where = f"{path}.{key}"
        if key not in got:
            problems.append(f"{where} is missing")
        elif value == "$finite":
            v = got[key]
            if not (isinstance(v, (int, float)) and not isinstance(v, bool) and math.isfinite(v)):
                problems.append(f"{where} = {v!r}, expected a finite number")
        elif isinstance(value, dict):
            problems += json_subset_problems(value, got[key], where)
        elif got[key] != value:
            problems.append(f"{where} = {got[key]!r}, expected {value!r}")
    return problems


class CaseFormat(unittest.TestCase):
    """The case files themselves (no tool needed): known keys, required keys, types."""

    def test_there_are_cases(self):
        self.assertGreater(len(case_files()), 0, CASE_DIR)

    def test_every_case_is_well_formed(self):
        for path in case_files():
            with self.subTest(case=os.path.basename(path)):
                with open(path, encoding="utf-8") as f:
                    case = json.load(f)
                self.assertIsInstance(case, dict)
                self.assertLessEqual(set(case), KEYS, f"unknown keys {set(case) - KEYS}")
                self.assertLessEqual(REQUIRED, set(case), f"missing keys {REQUIRED - set(case)}")
                self.assertIsInstance(case["args"], list)
                self.assertTrue(all(isinstance(a, str) for a in case["args"]))
                self.assertIsInstance(case["exit"], int)
                self.assertTrue(0 < case["seconds"] <= 120, "a bound between 0 and 120 s")
                for name, content in case.get("files", {}).items():
                    self.assertFalse(os.path.isabs(name) or ".." in name.split("/"), name)
                    if isinstance(content, dict) and "$pieces" in content:
                        self.assertEqual(set(content), {"$pieces"})
                        for text, count in content["$pieces"]:
                            self.assertIsInstance(text, str)
                            self.assertIsInstance(count, int)
                # A case must check something beyond the exit code of an error.
                if case["exit"] != 0:
                    self.assertTrue(case.get("stderr_contains"), "an error case names the words of its message")

    def test_subset_matcher(self):
        self.assertEqual(json_subset_problems({"a": 1, "b": "$finite"}, {"a": 1, "b": 2.5, "c": 0}), [])
        self.assertEqual(len(json_subset_problems({"b": "$finite"}, {"b": None})), 1)
        self.assertEqual(len(json_subset_problems({"a": 1}, {"a": 2})), 1)
        self.assertEqual(len(json_subset_problems({"a": {"b": 1}}, {"a": {}})), 1)


@unittest.skipUnless(TOOL and os.path.isfile(TOOL), "CURVEBENCH_TOOL is not set (the hostile ctest sets it)")
class Hostile(unittest.TestCase):
    def test_cases(self):
        for path in case_files():
            name = os.path.basename(path)
            with self.subTest(case=name):
                with open(path, encoding="utf-8") as f:
                    case = json.load(f)
                self.run_case(case)

    def run_case(self, case):
        work = tempfile.mkdtemp(prefix="curvebench_hostile_")
        try:
            paths = {}
            for fname, content in case.get("files", {}).items():
                paths[fname] = os.path.join(work, fname)
                os.makedirs(os.path.dirname(paths[fname]), exist_ok=True)
                with open(paths[fname], "w", encoding="utf-8") as f:
                    f.write(file_text(content))
            args = []
            for a in case["args"]:
                for fname, p in paths.items():
                    a = a.replace("{" + fname + "}", p)
                args.append(a)
            start = time.monotonic()
            try:
                limit = case.get("memory_mb")

                def cap():  # in the child, before exec
                    resource.setrlimit(resource.RLIMIT_AS, (limit << 20, limit << 20))
                p = subprocess.run([TOOL, *args], capture_output=True, text=True, errors="replace",
                                   timeout=case["seconds"], cwd=work, preexec_fn=cap if limit else None)
            except subprocess.TimeoutExpired:
                self.fail(f"no answer within {case['seconds']} s: {case['why']}")
            took = time.monotonic() - start
            shown = f"\n  args: {args}\n  exit {p.returncode} after {took:.2f} s\n  stderr: {p.stderr[:2000]}" \
                    f"\n  stdout: {p.stdout[:2000]}\n  why: {case['why']}"
            self.assertGreaterEqual(p.returncode, 0, "killed by a signal" + shown)
            self.assertNotIn("terminate called", p.stderr, shown)
            if p.returncode != 0:
                self.assertIn("curvebench: error: ", p.stderr, shown)
            self.assertEqual(p.returncode, case["exit"], shown)
            for w in case.get("stderr_contains", []):
                self.assertIn(w, p.stderr, shown)
            for w in case.get("stdout_contains", []):
                self.assertIn(w, p.stdout, shown)
            if case.get("stdout_empty"):
                self.assertEqual(p.stdout, "", shown)
            if "stdout_json" in case:
                try:
                    got = json.loads(p.stdout)
                except json.JSONDecodeError as e:
                    self.fail(f"stdout is not JSON ({e})" + shown)
                self.assertEqual(json_subset_problems(case["stdout_json"], got), [], shown)
            # The tool writes no stray files beside the ones the case created (e.g. DIR.tmp).
            left = [os.path.relpath(os.path.join(d, f), work) for d, ds, fs in os.walk(work) for f in ds + fs]
            self.assertEqual([f for f in left if f.endswith(".tmp")], [], "temporary files left" + shown)
        finally:
            shutil.rmtree(work, ignore_errors=True)


if __name__ == "__main__":
    unittest.main()
