"""The curvebench tool's command line for users checking their own implementation: `sample --at`
round trips through `check --values`, a perturbed cell fails naming its row, every class of bad
input fails with the row, column and value in its message, `--version` names the revision built
from, every subcommand's --help ends with an example, and an installed layout finds its cases.

Needs the tool: CURVEBENCH_TOOL=path/to/curvebench (the `tool_cli` ctest sets it); skipped without,
as under `report_py`'s unittest discover."""
import json
import math
import os
import re
import shutil
import subprocess
import tempfile
import unittest

ROOT = os.path.abspath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
TOOL = os.environ.get("CURVEBENCH_TOOL", "")
CASES = os.path.join(ROOT, "bench", "cases")
ARCH = os.path.join(CASES, "arch_cubic_bezier.json")  # cubic Bezier (0,0) (1,2) (3,2) (4,0), u in [0, 1]
BENT = '{"type": "polyline", "points": [[0,0],[3,4],[3,10]]}'  # s(u) = 5u, then 5 + 6 (u - 1); L = 11

SVG_NS = 'xmlns="http://www.w3.org/2000/svg"'


def run(*args, cwd=None):
    return subprocess.run([TOOL, *args], capture_output=True, text=True, timeout=300, cwd=cwd)


@unittest.skipUnless(TOOL and os.path.isfile(TOOL), "CURVEBENCH_TOOL is not set (the tool_cli ctest sets it)")
class ToolCli(unittest.TestCase):
    def setUp(self):
        self.dir = tempfile.mkdtemp(prefix="curvebench_cli_")

    def tearDown(self):
        shutil.rmtree(self.dir, ignore_errors=True)

    def write(self, name, text):
        path = os.path.join(self.dir, name)
        with open(path, "w", encoding="utf-8") as f:
            f.write(text)
        return path

    def sample(self, *args, spec=ARCH):
        p = run("sample", spec, *args)
        self.assertEqual(p.returncode, 0, p.stderr)
        return p.stdout

    def assert_error(self, p, *words):
        self.assertEqual(p.returncode, 1, p.stdout + p.stderr)
        self.assertTrue(p.stderr.startswith("curvebench: error: "), p.stderr)
        for w in words:
            self.assertIn(w, p.stderr)

    def test_output_the_system_does_not_take_is_an_error(self):
        # stdout on /dev/full: every write fails; the tool says so and exits 1 instead of 0 with
        # the output lost (a full disk gives a silently truncated file otherwise).
        with open("/dev/full", "w") as full:
            p = subprocess.run([TOOL, "list", "all"], stdout=full, stderr=subprocess.PIPE, text=True, timeout=60)
        self.assertEqual(p.returncode, 1, p.stderr)
        self.assertIn("curvebench: error: writing the standard output failed", p.stderr)

    def test_a_sample_table_the_system_does_not_take_is_an_error(self):
        # sample holds its table and writes it at the end; restoring std::cout's buffer after the
        # write cleared the failure, so a table past the pipe's first 4 kB was lost with exit 0.
        # A curve and a channel, 10,001 rows each.
        spec = self.write("line.json", '{"type": "channel", "tool": "exact", "keys": [{"time": 0, "value": 0, '
                                       '"interpolation": "linear"}, {"time": 10, "value": 5}]}')
        for args in (["sample", spec, "--frames", "0:10:0.001"], ["sample", ARCH, "--count", "10001"]):
            with open("/dev/full", "w") as full:
                p = subprocess.run([TOOL, *args], stdout=full, stderr=subprocess.PIPE, text=True, timeout=60)
            self.assertEqual(p.returncode, 1, args)
            self.assertIn("curvebench: error: writing the standard output failed", p.stderr)

    def test_a_case_directory_entry_that_is_no_file_is_refused_not_waited_on(self):
        # A FIFO named *.json in a case directory blocked `list cases` and `accuracy` at its open.
        cases = os.path.join(self.dir, "cases")
        os.makedirs(cases)
        shutil.copy(ARCH, cases)
        os.mkfifo(os.path.join(cases, "stray.json"))
        for args in (["list", "cases", "--cases", cases], ["accuracy", "--quick", "--cases", cases, "--quiet",
                                                           "--out", os.path.join(self.dir, "a.json")]):
            p = run(*args)
            self.assert_error(p, "stray.json is not a regular file (a case is a *.json file)")

    def test_a_syntax_error_names_no_library_tag_and_shows_a_bad_byte_replaced(self):
        path = os.path.join(self.dir, "bad.json")
        with open(path, "wb") as f:
            f.write(b'{"type": "channel", "tool": "css", "easing": "ease\xff"}')
        p = run("sample", path, "--at", "0.5")
        self.assert_error(p, "bad.json: not valid JSON: parse error at line 1", "ill-formed UTF-8 byte",
                          '"ease\ufffd')
        self.assertNotIn("json.exception", p.stderr)
        self.assertNotIn("\\xff", p.stderr)

    def test_compare_exits_1_only_on_a_confident_regression(self):
        # tests/data/compare/README.md: runs of one build pass, the -O0 build and the subject
        # rounded to 7 digits fail naming what regressed; --json carries every change.
        data = os.path.join(ROOT, "tests", "data", "compare")
        same = run("compare", os.path.join(data, "run1"), os.path.join(data, "run2"))
        self.assertEqual(same.returncode, 0, same.stdout + same.stderr)
        self.assertIn("records: 75 matched", same.stdout)
        self.assertIn("compare: no confident regression", same.stdout)
        slow = run("compare", os.path.join(data, "run1"), os.path.join(data, "slow"))
        self.assertEqual(slow.returncode, 1, slow.stdout + slow.stderr)
        self.assertIn("SLOWER bezier/horner/calls:single/degree:3:", slow.stdout)
        self.assertIn("compare: 4 regressions", slow.stdout)
        self.assertIn("curvebench: compare: 4 confident regressions (exit 1)", slow.stderr)  # CI logs see it
        worse = run("compare", os.path.join(data, "check_17_digits.json"), os.path.join(data, "check_7_digits.json"),
                    "--json")
        self.assertEqual(worse.returncode, 1, worse.stdout + worse.stderr)
        j = json.loads(worse.stdout)
        self.assertEqual(j["regressions"], 2)
        self.assertEqual({r["key"] for r in j["records"]},
                         {"arch/eval/my_bezier [smooth] (subject)", "arch/s_of_u/my_bezier [smooth] (subject)"})
        # Each error in its unit, on the table and in --json: a bare 2.81e+08 says nothing.
        self.assertEqual({r["key"]: r["unit"] for r in j["records"]},
                         {"arch/eval/my_bezier [smooth] (subject)": "ulp-double",
                          "arch/s_of_u/my_bezier [smooth] (subject)": "rel-L"})
        table = run("compare", os.path.join(data, "check_17_digits.json"), os.path.join(data, "check_7_digits.json"))
        self.assertIn("error 0.587 ulp-double -> 2.81e+08 ulp-double", table.stdout)
        self.assertIn("error 8.05e-16 rel-L -> 8.79e-08 rel-L", table.stdout)
        # Even a 300 % margin fails it: the 7-digit subject's errors grew 1e8 times.
        loose = run("compare", os.path.join(data, "check_17_digits.json"), os.path.join(data, "check_7_digits.json"),
                    "--max-error-growth", "3")
        self.assertEqual(loose.returncode, 1, loose.stdout)
        self.assert_error(run("compare", self.write("x.json", '{"y": 1}'), os.path.join(data, "run1")),
                          "x.json: holds neither \"records\"")

    def test_compare_shows_a_checks_records_in_the_checks_unit(self):
        # Blender's own values of an exported channel, then the same values 1e-5 off: the check
        # prints float ulps (--unit ulp-float), and so must compare, the records' ulps of double
        # beside them (the records stay in ulps of double whatever the unit).
        data = os.path.join(ROOT, "tests", "data", "blender_export")
        spec = os.path.join(data, "easesAction.location.1.json")
        with open(os.path.join(data, "easesAction.location.1.blender.csv")) as f:
            lines = [ln for ln in f.read().splitlines() if not ln.startswith("#")]
        off = [lines[0]] + ["%s,%.9g" % (t, float(v) + 1e-5) for t, v in (ln.split(",") for ln in lines[1:])]
        runs = []
        for name, text in (("good.csv", "\n".join(lines) + "\n"), ("off.csv", "\n".join(off) + "\n")):
            p = run("check", spec, "--values", self.write(name, text), "--against", "tool", "--unit", "ulp-float",
                    "--json")
            self.assertEqual(p.returncode, 0, p.stderr)
            record = json.loads(p.stdout)["records"][0]
            self.assertEqual(record["unit"], "ulp-float")
            runs.append(self.write(name + ".json", p.stdout))
        table = run("compare", *runs)
        self.assertEqual(table.returncode, 1, table.stdout + table.stderr)
        self.assertRegex(table.stdout, r"error [0-9.e+-]+ ulp-float -> [0-9.e+-]+ ulp-float "
                                       r"\(records: [0-9.e+-]+ ulp-double -> [0-9.e+-]+ ulp-double\)")

    def test_at_file_takes_a_byte_order_mark_and_refuses_a_column_named_twice(self):
        bom = os.path.join(self.dir, "bom.csv")
        with open(bom, "wb") as f:
            f.write(b"\xef\xbb\xbfu,x\n0.25,1\n")
        self.assertEqual(self.sample("--at-file", bom), self.sample("--at", "0.25"))
        twice = self.write("twice.csv", "u,x,u\n0.25,1,0.5\n")
        self.assert_error(run("sample", ARCH, "--at-file", twice), "twice.csv: row 1",
                          "the u column twice (columns 1 and 3)")

    def test_empty_range_and_frames_are_refused(self):
        # A usage error: CLI11's exit code for a failed validation (105), with the tool's prefix.
        for option in ("--range", "--frames", "--at"):
            p = run("sample", ARCH, option, "")
            self.assertEqual(p.returncode, 105, p.stdout + p.stderr)
            self.assertTrue(p.stderr.startswith("curvebench: error: " + option + ": an empty value"), p.stderr)

    # ---- sample at chosen parameters ---------------------------------------------------------

    def test_sample_at_range_and_file_give_the_same_rows(self):
        at = self.sample("--at", "0,0.25,0.5,0.75,1", "--derivatives", "2")
        self.assertEqual(at.splitlines()[0], "u,s,x,y,dx,dy,d2x,d2y")
        self.assertEqual(len(at.splitlines()), 6)
        self.assertEqual(self.sample("--range", "0:1:0.25", "--derivatives", "2"), at)
        values = self.write("u.txt", "0\n0.25\n\n0.5\n0.75\n1\n")
        self.assertEqual(self.sample("--at-file", values, "--derivatives", "2"), at)
        csv = self.write("u.csv", at)  # a CSV with a u column: its other columns are ignored
        self.assertEqual(self.sample("--at-file", csv, "--derivatives", "2"), at)
        # The default output is unchanged: u, s, the point, the first derivative.
        self.assertEqual(self.sample("--count", "3").splitlines()[0], "u,s,x,y,dx,dy")
        header, row = self.sample("--at", "0.5", "--derivatives", "0").splitlines()
        self.assertEqual(header, "u,s,x,y")
        u, s, x, y = row.split(",")
        self.assertEqual((u, x, y), ("0.5", "2", "1.5"))  # the arch's closed form at 1/2: exact
        self.assertAlmostEqual(float(s), 2.6341827715092569, delta=1e-14)  # s(1/2) = L/2 by symmetry
        # The truth and the tool's own evaluation, apart and named; the CSV
        # sample writes is what sample --at-file and check --values read back. cubic-bezier(0, 1,
        # 0, 1) at t = 1e-5 is 1 - (1 - cbrt(1e-5))^3 = 0.0632506 exactly; WebKit's table and
        # Newton give 0.0630783.
        with tempfile.TemporaryDirectory() as tmp:
            snappy = os.path.join(tmp, "snappy.json")
            with open(snappy, "w") as out:
                json.dump({"type": "channel", "tool": "css", "easing": "cubic-bezier(0, 1, 0, 1)"}, out)
            truth = run("sample", snappy, "--at", "1e-5,0.5", "--derivatives", "0")
            tool = run("sample", snappy, "--at", "1e-5,0.5", "--derivatives", "0", "--as-tool")
            self.assertEqual(truth.returncode + tool.returncode, 0, truth.stderr + tool.stderr)
            self.assertAlmostEqual(float(truth.stdout.splitlines()[2].split(",")[1]), 0.0632506, delta=5e-8)
            self.assertAlmostEqual(float(tool.stdout.splitlines()[2].split(",")[1]), 0.0630783, delta=5e-8)
            self.assertIn("tool css's own evaluation (solver table_newton", tool.stdout.splitlines()[0])
            mine = os.path.join(tmp, "mine.csv")
            with open(mine, "w") as out:
                out.write(tool.stdout)
            again = run("sample", snappy, "--at-file", mine, "--derivatives", "0", "--as-tool")
            self.assertEqual(again.stdout, tool.stdout, again.stderr)
            against_truth = run("check", snappy, "--values", mine, "--max-error", "4")
            self.assertEqual(against_truth.returncode, 1, against_truth.stdout)
            self.assertIn("row 3 (t = 1.0000000000000001e-05)", against_truth.stdout)
            self.assertIn("absolute: max 0.000172", against_truth.stdout)
            self.assertIn("curvebench: check: 2 failures (exit 1)", against_truth.stderr)
            against_tool = run("check", snappy, "--values", mine, "--max-error", "0", "--against", "tool")
            self.assertEqual(against_tool.returncode, 0, against_tool.stdout + against_tool.stderr)
        # B is kept when it lies on the grid up to rounding (0.1 steps do not add up to 1 exactly).
        self.assertEqual(self.sample("--range", "0:1:0.1").splitlines()[-1].split(",")[0], "1")

    def test_sample_at_works_for_every_family_of_the_suite(self):
        for name in sorted(os.listdir(CASES)):
            spec = os.path.join(CASES, name)
            with open(spec) as f:
                j = json.load(f)
                if j["type"] == "channel":  # --at gives times: t, value, dvalue, d2value
                    p = run("sample", spec, "--at", "-1,0.37,1e300", "--derivatives", "2")  # off the vertical tangents
                    self.assertEqual(p.returncode, 0, name + ": " + p.stderr)
                    # A glTF rotation's value is a quaternion: t, x, y, z, w and their derivatives.
                    header = ("t,x,y,z,w,dx,dy,dz,dw,d2x,d2y,d2z,d2w" if j.get("path") == "rotation"
                              else "t,value,dvalue,d2value")
                    lines = [line for line in p.stdout.splitlines() if not line.startswith("#")]
                    self.assertEqual(lines[0], header, name)
                    self.assertEqual(len(lines), 4, name)
                    continue
            # The domain, from the error of a parameter outside it (sample --count builds a u(s)
            # table: minutes on degree-20 Runge).
            p = run("sample", spec, "--at", "1e300")
            self.assertEqual(p.returncode, 1, p.stderr)
            lo, hi = (float(v) for v in p.stderr.split("domain [")[1].split("]")[0].split(", "))
            out = self.sample("--at", f"{lo!r},{(lo + hi) / 2!r},{hi!r}", "--derivatives", "3", spec=spec)
            header = out.splitlines()[0].split(",")
            dim = sum(1 for c in header if c in ("x", "y", "z", "w"))
            self.assertEqual(len(header), 2 + 4 * dim, name)
            self.assertEqual(len(out.splitlines()), 4, name)

    def test_sample_rejects_bad_parameters_naming_option_item_and_text(self):
        self.assert_error(run("sample", ARCH, "--at", "0,,1"), "--at", "item 2", "empty")
        self.assert_error(run("sample", ARCH, "--at", "0,1.5x"), "--at", "item 2", '"1.5x"')
        self.assert_error(run("sample", ARCH, "--at", "nan"), "item 1", '"nan"')
        self.assert_error(run("sample", ARCH, "--at", "0.5,2"), "item 2", "u = 2", "domain [0, 1]")
        self.assert_error(run("sample", ARCH, "--range", "0:1:0"), "--range", "STEP", '"0"', "not positive")
        self.assert_error(run("sample", ARCH, "--range", "0:1"), "--range", "A:B:STEP")
        self.assert_error(run("sample", ARCH, "--range", "0:1:1e-9"), "--range", "maximum 1000000")
        self.assert_error(run("sample", ARCH, "--range", "0:x:0.1"), "item 2", "(B)", '"x"')
        bad = self.write("bad.txt", "0.5\n0.7q\n")
        self.assert_error(run("sample", ARCH, "--at-file", bad), "bad.txt", "row 2", '"0.7q"')
        self.assert_error(run("sample", ARCH, "--at-file", self.write("e.txt", "")), "e.txt", "no values")
        self.assert_error(run("sample", ARCH, "--at", "0.5", "--by", "arclength"), "--by arclength", "--at")
        p = run("sample", ARCH, "--at", "0.5", "--count", "3")  # a usage error: CLI11's message and code
        self.assertNotEqual(p.returncode, 0)
        self.assertIn("--count excludes --at", p.stderr)

    # ---- check ---------------------------------------------------------------------------------

    def test_round_trip_passes_and_a_perturbed_cell_fails_naming_its_row(self):
        text = self.sample("--at", "0,0.1,0.2,0.3,0.4,0.5,0.6,0.7,0.8,0.9,1", "--derivatives", "2")
        f = self.write("f.csv", text)
        p = run("check", ARCH, "--values", f, "--max-error", "4")
        self.assertEqual(p.returncode, 0, p.stdout + p.stderr)
        self.assertIn("check: passed", p.stdout)
        self.assertIn("worst rows", p.stdout)
        lines = text.splitlines()
        cells = lines[4].split(",")  # row 5 of the file: u = 0.3
        cells[2] = repr(float(cells[2]) * (1 + 1e-9))
        lines[4] = ",".join(cells)
        g = self.write("g.csv", "\n".join(lines) + "\n")
        p = run("check", ARCH, "--values", g, "--max-error", "4")
        self.assertEqual(p.returncode, 1, p.stdout + p.stderr)
        self.assertIn("check: OVER", p.stdout)
        self.assertIn("g.csv: row 5 (u = 0.29999999999999999)", p.stdout)
        self.assertEqual(p.stdout.count("check: OVER"), 1)

    def test_json_holds_summary_worst_rows_and_records(self):
        f = self.write("f.csv", self.sample("--at", "0,0.5,1", "--derivatives", "1"))
        p = run("check", ARCH, "--values", f, "--json", "--name", "my_engine", "--max-error", "4")
        self.assertEqual(p.returncode, 0, p.stderr)
        out = json.loads(p.stdout)
        self.assertTrue(out["passed"])
        check = out["checks"][0]
        self.assertEqual(check["summary"]["rows"], 3)
        self.assertEqual(len(check["rows"]), 3)
        self.assertLessEqual(len(check["worst"]), 5)
        self.assertEqual({(r["quantity"], r["setting"]) for r in out["records"]},
                         {("eval", ""), ("eval", "derivative=1"), ("s_of_u", "")})
        for r in out["records"]:
            self.assertEqual(r["method"], "my_engine")
            self.assertTrue(r["subject"])
            self.assertEqual(r["case"], "arch_cubic_bezier")

    def test_lengths_inverse_and_thresholds(self):
        spec = self.write("bent.json", BENT)
        lengths = self.write("len.csv", "u0,u1,length\n0,2,11\n0.5,1.5,5.5\n")
        inverse = self.write("inv.csv", "s,u\n0,0\n8,1.5\n11,2\n")
        p = run("check", spec, "--lengths", lengths, "--inverse", inverse, "--max-error", "1e-15")
        self.assertEqual(p.returncode, 0, p.stdout + p.stderr)
        rules = self.write("rules.json", json.dumps({"rules": [
            {"quantity": "length", "method": "my_table", "max_error": 1e-15, "why": "test"},
            {"quantity": "u_of_s", "method": "my_table", "max_error": 1e-15, "why": "test"}]}))
        p = run("check", spec, "--lengths", lengths, "--inverse", inverse, "--name", "my_table", "--thresholds", rules)
        self.assertEqual(p.returncode, 0, p.stdout + p.stderr)
        worse = self.write("inv2.csv", "s,u\n0,0\n8,1.5001\n")
        p = run("check", spec, "--lengths", lengths, "--inverse", worse, "--name", "my_table", "--thresholds", rules)
        self.assertEqual(p.returncode, 1, p.stdout + p.stderr)
        self.assertIn("check: BREACH u_of_s/my_table/*", p.stdout)
        p = run("check", spec, "--inverse", worse, "--max-error", "1e-6")
        self.assertEqual(p.returncode, 1)
        self.assertIn("inv2.csv: row 3 (s = 8, u = 1.5001)", p.stdout)
        # A length row running backwards is refused, not charged twice its length.
        back = self.write("back.csv", "u0,u1,length\n1.5,0.5,5.5\n")
        self.assert_error(run("check", spec, "--lengths", back), "back.csv", "row 2", "column u1",
                          "u1 = 0.5 is below u0 = 1.5")

    def test_options_without_effect_are_refused(self):
        spec = self.write("bent.json", BENT)
        lengths = self.write("len.csv", "u0,u1,length\n0,2,11\n")
        values = self.write("v.csv", self.sample("--at", "0,0.5,1"))
        cases = [
            ((spec, "--lengths", lengths, "--unit", "rel"), ["--unit rel", "no --values file is given"]),
            ((spec, "--lengths", lengths, "--max-value-error", "4"), ["--max-value-error", "no --values file"]),
            ((spec, "--lengths", lengths, "--max-inverse-error", "4"), ["--max-inverse-error", "no --inverse file"]),
            ((spec, "--lengths", lengths, "--max-at-length-error", "4"),
             ["--max-at-length-error", "no --at-length file"]),
            ((spec, "--lengths", lengths, "--max-length-error", "1e-15", "--max-error", "1"),
             ["--max-error applies to the files without a limit of their own"]),
            ((ARCH, "--values", values, "--against", "truth"), ["against = truth", "a channel spec's values at times"]),
        ]
        for args, words in cases:
            with self.subTest(args=args):
                self.assert_error(run("check", *args), *words)
        # With a file of its own kind each takes effect.
        p = run("check", spec, "--lengths", lengths, "--max-length-error", "1e-15")
        self.assertEqual(p.returncode, 0, p.stdout + p.stderr)

    def test_thousands_of_failing_rows_print_a_count_not_a_line_each(self):
        us = ",".join(str(i / 1000) for i in range(1001))
        lines = self.sample("--at", us, "--derivatives", "0").splitlines()
        shifted = [lines[0]] + [",".join(c.split(",")[:2] + [repr(float(c.split(",")[2]) + 1e-6)] + c.split(",")[3:])
                                for c in lines[1:]]
        f = self.write("off.csv", "\n".join(shifted) + "\n")
        p = run("check", ARCH, "--values", f, "--max-error", "4")
        self.assertEqual(p.returncode, 1, p.stderr)
        self.assertEqual(p.stdout.count("check: OVER"), 20)
        self.assertIn("check: ... and 981 more (--json lists them all)", p.stdout)
        p = run("check", ARCH, "--values", f, "--max-error", "4", "--json")
        self.assertEqual(len(json.loads(p.stdout)["failures"]), 1001)
        self.assertEqual(p.stderr.count("check: OVER"), 20)

    def test_at_length_takes_a_tools_own_length_and_refuses_overflow(self):
        spec = self.write("bent.json", BENT)
        scaled = self.write("tool.csv", "s,L,x,y\n0,22,0,0\n5,22,1.5,2\n16,22,3,7\n")
        p = run("check", spec, "--at-length", scaled, "--json")
        self.assertEqual(p.returncode, 0, p.stderr)
        check = json.loads(p.stdout)["checks"][0]
        self.assertEqual(check["tool_length"], 22)
        self.assertEqual(check["tool_length_error"], 1)
        self.assertLessEqual(check["summary"]["max"], 1e-30)
        p = run("check", spec, "--at-length", scaled)
        self.assertIn("the L column (s on its scale, asked at s / L of the way): 22, relative error 1", p.stdout)
        far = self.write("far.csv", "x,y\n1.7e308,-1.7e308\n")
        self.assert_error(run("check", spec, "--at-length", far), "far.csv", "row 2", "overflows double")

    def test_accuracy_with_a_failed_case_leaves_the_earlier_results_and_writes_beside_them(self):
        cases = os.path.join(self.dir, "cases")
        os.makedirs(cases)
        shutil.copy(ARCH, cases)
        out = os.path.join(self.dir, "acc", "accuracy.json")
        p = run("accuracy", "--quick", "--cases", cases, "--out", out, "--quiet")
        self.assertEqual(p.returncode, 0, p.stderr)
        with open(out, "rb") as f:
            good = f.read()
        with open(os.path.join(cases, "broken.json"), "w") as f:
            # Read, but refused when run: its length is rounding noise at its coordinates.
            json.dump({"name": "broken", "group": "test", "reason": "fails when run", "quick": True, "type": "circle",
                       "center": [1e10, 1e10], "radius": 1e-150}, f)
        p = run("accuracy", "--quick", "--cases", cases, "--out", out, "--quiet")
        self.assertEqual(p.returncode, 1, p.stderr)
        self.assertIn("accuracy: case failed: broken", p.stderr)
        self.assertIn(out + " is left as it was; the cases that ran are in", p.stderr)
        with open(out, "rb") as f:
            self.assertEqual(f.read(), good)
        with open(os.path.join(self.dir, "acc", "accuracy.partial.json")) as f:
            partial = json.load(f)
        self.assertEqual(partial["context"]["failed_cases"], 1)
        self.assertEqual([c["name"] for c in partial["cases"]], ["arch_cubic_bezier"])

    def test_bad_input_names_file_row_column_and_value(self):
        cases = [
            ("", ["empty file"]),
            ("u,x,y\n", ["header row has no rows"]),
            ("u,x,y\n0.5,1.5x,2\n", ["row 2", "column x", '"1.5x"']),
            ("u,x,y\n0.5,inf,2\n", ["row 2", "column x", '"inf"']),
            ("u,x,y\n0.5,1\n", ["row 2", "column y", "missing value"]),
            ("u,x,y\n0.5,1,2,3\n", ["row 2", "column 4", '"3"']),
            ("u,x\n0.5,1\n", ["row 1", "no column y"]),
            ("u,x,y,q\n0.5,1,2,3\n", ["row 1", "column q", "unknown column"]),
            ("u,x,y\n0,0,0\n1.5,1,2\n", ["row 3", "column u", "1.5", "domain [0, 1]"]),
            ("t,x,y\n0.5,1,2\n", ["column t", "parameter is u"]),
        ]
        for i, (text, words) in enumerate(cases):
            name = f"bad{i}.csv"
            with self.subTest(text=text):
                self.assert_error(run("check", ARCH, "--values", self.write(name, text)), name, *words)
        self.assert_error(run("check", ARCH), "--values")

    # ---- hostile input --------------------------------------------------------------------------

    def test_long_sample_prints_progress_on_stderr_only_and_quiet_silences_it(self):
        # Runs over a second report "case k of n, percent, elapsed" on stderr; stdout stays
        # the CSV. 400000 samples of the 1e5-segment Lissajous take several seconds here.
        spec = os.path.join(CASES, "lissajous_many_segments_1e5.json")
        p = run("sample", spec, "--count", "400000")
        self.assertEqual(p.returncode, 0, p.stderr)
        self.assertRegex(p.stderr, r"sample: \d+ of 400000 \(\d+\.\d%\), \d+\.\d s elapsed")
        self.assertNotIn("elapsed", p.stdout)
        self.assertEqual(len(p.stdout.splitlines()), 400001)
        q = run("sample", spec, "--count", "400000", "--quiet")
        self.assertEqual(q.returncode, 0, q.stderr)
        self.assertEqual(q.stderr, "")
        self.assertEqual(q.stdout, p.stdout)

    def test_long_length_and_check_print_progress_and_quiet_silences_it(self):
        # length reports its evaluations against the method's budget, check its rows; both
        # on stderr once a run takes over a second. 6e7 evaluations of the 1e5-segment Lissajous
        # (composite Gauss, 20 points x 30 panels) take a few seconds here.
        spec = os.path.join(CASES, "lissajous_many_segments_1e5.json")
        args = ("length", spec, "--method", "composite_gauss", "--n", "20", "--panels", "30")
        p = run(*args)
        self.assertEqual(p.returncode, 0, p.stderr)
        self.assertRegex(p.stderr, r"length: evaluations \(at most\): \d+ of 60000000 \(\d+\.\d%\), \d+\.\d s elapsed")
        self.assertEqual(json.loads(p.stdout)["evaluations"], 60000000)
        q = run(*args, "--quiet")
        self.assertEqual(q.returncode, 0, q.stderr)
        self.assertEqual(q.stderr, "")
        self.assertEqual(q.stdout, p.stdout)
        # check: every row's 50-digit reference (its value and its s(u), where the time goes, so the
        # progress counts the s(u) integrals as rows); 300 rows of the degree-20 Bezier take about
        # 4.5 s here. (The Lissajous took 41 s to set up its 50-digit length first.)
        bezier = os.path.join(CASES, "bezier_degree_20.json")
        values = self.write("values.csv", run("sample", bezier, "--count", "300", "--quiet").stdout)
        c = run("check", bezier, "--values", values)
        self.assertEqual(c.returncode, 0, c.stderr)
        self.assertRegex(c.stderr, r"check .*values\.csv: rows: \d+ of 300 \(\d+\.\d%\), \d+\.\d s elapsed")
        self.assertNotIn("elapsed", c.stdout)
        self.assertEqual(run("check", bezier, "--values", values, "--quiet").stderr, "")

    def test_length_names_its_fields_as_the_records_do_for_every_method(self):
        # The length output and the accuracy records share their field names ("estimate", not
        # "error_estimate"); every method of the table runs, with its options, within its estimate
        # of the arch's length when it converges (adaptive_gk at 1e-14 as the yardstick).
        spec = os.path.join(CASES, "arch_cubic_bezier.json")
        ref = json.loads(run("length", spec, "--tol", "1e-14").stdout)
        methods = {"gauss": ("--n", "8"), "composite_gauss": ("--n", "5", "--panels", "8"),
                   "adaptive_gk": ("--tol", "1e-10"), "forward_difference": ("--steps", "512"),
                   "richardson": ("--steps", "512"), "subdivision": ("--tol", "1e-8")}
        for method, options in methods.items():
            p = run("length", spec, "--method", method, *options)
            self.assertEqual(p.returncode, 0, p.stderr)
            out = json.loads(p.stdout)
            self.assertEqual(sorted(out), ["estimate", "evaluations", "method", "reason", "status", "value"], method)
            self.assertEqual(out["method"], method)
            self.assertGreater(out["evaluations"], 0, method)
            if out["status"] == "converged":
                self.assertLessEqual(abs(out["value"] - ref["value"]), out["estimate"] + ref["estimate"], method)
        # An option of another method would be ignored: refused, naming the method's own.
        self.assert_error(run("length", spec, "--method", "gauss", "--tol", "1e-3"),
                          "--tol does not apply to --method gauss (its options: --n)")
        # A fixed rule's cost is refused before the work, naming the options.
        many = os.path.join(CASES, "lissajous_many_segments_1e5.json")
        self.assert_error(run("length", many, "--method", "gauss", "--n", "200"), "--n 200: ", " segments need ",
                          "more than the limit of 67108864")

    def test_length_names_the_reason_of_a_status_not_converged(self):
        # "reason" beside "status" says why a result is not converged (the failed bound or
        # cap, the segment and interval where the method knows them, the quantity against its
        # bound); null when converged.
        spec = os.path.join(CASES, "arch_cubic_bezier.json")
        out = json.loads(run("length", spec, "--method", "adaptive_gk", "--tol", "1e-10").stdout)
        self.assertEqual(out["status"], "converged")
        self.assertIsNone(out["reason"])
        out = json.loads(run("length", spec, "--method", "forward_difference", "--steps", "10").stdout)
        self.assertEqual(out["status"], "not_guaranteed")
        self.assertEqual(out["reason"], "steps per segment not a multiple of 4 of at least 16: no coarser sums "
                                        "(measured 10, bound 16)")
        out = json.loads(run("length", spec, "--method", "composite_gauss").stdout)
        self.assertEqual(out["reason"], "composite rule without an estimate")
        # The midpoint rule never shows the order the nested test asks for: the segment is named.
        out = json.loads(run("length", spec, "--method", "gauss", "--n", "1").stdout)
        self.assertEqual(out["status"], "not_guaranteed")
        self.assertRegex(out["reason"], r"^segment 0 \(u 0 to 0\.0625\): order test failed: \|Q1 - Q2\| < 16 "
                                        r"\|Q2 - Q4\| \(measured [0-9.e+-]+, bound [0-9.e+-]+\)$")
        self.assertIn("--estimate", run("length", "--help").stdout)

    def test_length_svg_measures_every_path_and_shape_of_a_drawing(self):
        # tests/data/svg/drawing.svg: groups, a transform (not applied, as getTotalLength), defs, a
        # px unit. Closed forms; tolerance 1e-12 relative, adaptive_gk's default tolerance of 1e-10
        # with its usual margin (the arcs' control data are exact to the last bit of a double).
        svg = os.path.join(ROOT, "tests", "data", "svg", "drawing.svg")
        p = run("length", "--svg", svg, "--tol", "1e-13")
        self.assertEqual(p.returncode, 0, p.stderr)
        out = json.loads(p.stdout)
        self.assertEqual([(e["element"], e["id"], e["index"]) for e in out],
                         [("path", "track", 0), ("circle", "ring", 1), ("rect", "badge", 2), ("polygon", "arrow", 3),
                          ("path", "wave", 4), ("path", "leaf", 5), ("line", "", 6)])
        by_id = {e["id"] or e["element"]: e for e in out}
        want = {"track": math.pi * 50, "ring": 2 * math.pi * 40, "badge": 2 * (120 + 40) - 4 * 2 * 8 + 2 * math.pi * 8,
                "arrow": 12.0, "line": 50.0}
        for name, length in want.items():
            self.assertLess(abs(by_id[name]["value"] - length), 1e-12 * length, by_id[name])
            # At 1e-13 some reach double's rounding first; either way the estimate bounds the error.
            self.assertIn(by_id[name]["status"], ("converged", "rounding_limited"))
            self.assertLessEqual(abs(by_id[name]["value"] - length), by_id[name]["estimate"], by_id[name])
        # A shape's path data is SVG 2's equivalent path; a polygon's points are a moveto with linetos.
        self.assertEqual(by_id["ring"]["d"], "M140 100 A40 40 0 0 1 100 140 A40 40 0 0 1 60 100 "
                                             "A40 40 0 0 1 100 60 A40 40 0 0 1 140 100 Z")
        self.assertEqual(by_id["arrow"]["d"], "M0,0 3,0 3,4 Z")
        # The segments, absolute and explicit: the leaf's relative quadratics and T's reflected
        # control point, the closing line of Z; the track's arcs with their centre form (centre
        # (50, 50), radius 50, from angle pi a quarter turn in the direction of increasing angle).
        leaf_segments = by_id["leaf"]["segments"]
        self.assertEqual(len(leaf_segments), 1)
        self.assertTrue(leaf_segments[0]["closed"])
        self.assertEqual([(s["kind"], s["points"]) for s in leaf_segments[0]["segments"]],
                         [("quadratic", [[200, 200], [220, 170], [240, 200]]),
                          ("quadratic", [[240, 200], [260, 230], [280, 200]]), ("line", [[280, 200], [200, 200]])])
        arc = by_id["track"]["segments"][0]["segments"][0]
        self.assertEqual((arc["kind"], arc["points"], arc["sweep"], arc["large"]),
                         ("arc", [[0, 50], [50, 0]], True, False))
        for key, want_value in (("cx", 50), ("cy", 50), ("rx", 50), ("ry", 50), ("phi", 0), ("theta1", math.pi),
                                ("dtheta", math.pi / 2)):
            # atan2 of exact data: within 2 ulps of the angle.
            self.assertAlmostEqual(arc["center"][key], want_value, delta=4e-16 * max(1, abs(want_value)), msg=key)
        # The relative quadratics of the leaf against the same curve as a spec.
        leaf = self.write("leaf.json",
                          json.dumps({"type": "svg_path", "d": "M200 200 Q220 170 240 200 T280 200 Z"}))
        self.assertAlmostEqual(json.loads(run("length", leaf, "--tol", "1e-13").stdout)["value"],
                               by_id["leaf"]["value"], delta=1e-11)
        one = json.loads(run("length", "--svg", svg, "--id", "ring", "--method", "gauss", "--n", "8").stdout)
        self.assertEqual([e["id"] for e in one], ["ring"])
        self.assertEqual(one[0]["method"], "gauss")
        self.assert_error(run("length", "--svg", svg, "--id", "nope"), "--id nope: no path or shape of " + svg
                          + " has this id (ids: track, ring, badge, arrow, wave, leaf)")
        self.assert_error(run("length", "--svg", svg, ARCH), "give a spec file or --svg FILE, not both")
        self.assert_error(run("length", ARCH, "--id", "x"), "--id selects an element of --svg FILE")
        bad = self.write("bad.svg", '<svg xmlns="http://www.w3.org/2000/svg"><circle id="c" r="2em"/></svg>')
        self.assert_error(run("length", "--svg", bad), '<circle id="c"> (shape or path 0, byte ')
        self.assert_error(run("length", "--svg", bad), 'r="2em" is not a number in user units')
        broken = self.write("broken.svg", '<svg><path d="M0 0 L1 1"')
        self.assert_error(run("length", "--svg", broken), "not well-formed XML at byte offset")
        cut = self.write("cut.svg", '<svg xmlns="http://www.w3.org/2000/svg"><path id="p" d="M0 0 L1 1 L2"/></svg>')
        self.assert_error(run("length", "--svg", cut), "at offset 12 (the end of the data): expected a number")
        none = self.write("none.svg", '<svg xmlns="http://www.w3.org/2000/svg"><text>no path</text></svg>')
        self.assert_error(run("length", "--svg", none), "no <path> or basic shape")
        html = self.write("page.svg", '<html><path d="M0 0 L1 1"/></html>')
        self.assert_error(run("length", "--svg", html), "the root element is <html> in no namespace, not SVG's <svg>")

    def svg(self, body, root="svg", declarations=SVG_NS, name="t.svg"):
        return self.write(name, f'<{root} {declarations}>{body}</{root}>')

    def test_length_svg_refuses_what_xml_refuses(self):
        # pugixml accepts all of these; XML 1.0 (and Namespaces in XML) does not, so neither does
        # the reader: each is refused with the file and the byte offset, before anything is printed.
        cases = [
            # A character reference to U+0000 was decoded into d, which then ended there: a path of
            # 1010 was measured as 10.
            ('<path d="M0 0 L10 0&#0; L1000 0"/>', 59,
             "character reference &#0; is to U+0000, a character XML does not allow"),
            ('<path d="M0 0 L10 0&#x8; L1000 0"/>', 59, "character reference &#x8; is to U+0008"),
            ('<path d="M0 0 &#xD800;"/>', 54, "character reference &#xD800; is to U+D800"),
            ('<path d="M0 0 &#xFFFE;"/>', 54, "character reference &#xFFFE; is to U+FFFE"),
            ('<path d="M0 0 &#1114112;"/>', 54, "character reference &#1114112; is to a number past U+10FFFF"),
            ('<path d="M0 0 &#12a;"/>', 54, "&#12a; is not a character reference"),
            # A second d was ignored: XML 1.0's Unique Att Spec.
            ('<path d="M0 0 L10 0" d="M0 0 L1000 0"/>', 61,
             "attribute d appears twice on <path> (XML 1.0: Unique Att Spec)"),
            ('<path d="M0 0 L1<2"/>', 56, "'<' in an attribute value"),
            ('<path d="M0 0 & L1 2"/>', 54, "'&' that does not start a reference"),
            ('<path d="&ent;"/>', 49, "entity &ent; is not declared"),
            ('<!-- a -- b -->', 47, '"--" inside a comment'),
            ('a ]]> b', 42, '"]]>" in character data'),
            ('<path d="M0 0 L1 1" \x01/>', 60, "character U+0001 is not allowed in XML"),
            ('<path d="M0 0 L1 1"/></svg><svg xmlns="http://www.w3.org/2000/svg">', 67, "a second root element"),
            ('<path 1d="M0 0 L1 1"/>', 46, "Error parsing start element tag"),  # pugixml's own check
        ]
        for body, offset, words in cases:
            with self.subTest(body=body):
                p = run("length", "--svg", self.svg(body))
                self.assert_error(p, "t.svg: not well-formed XML at byte offset %d: %s" % (offset, words))
                self.assertEqual(p.stdout, "")
        root = '<svg xmlns="http://www.w3.org/2000/svg"/>'
        top = [('<?xml version="1.0"?>' + root + 'junk', 62, "text outside the root element"),
               (' <?xml version="1.0"?>' + root, 1, "an XML declaration is allowed only at the very start"),
               ('<?xml version="1.0" encoding="ISO-8859-1"?><svg xmlns="http://www.w3.org/2000/svg"/>', 30,
                'encoding "ISO-8859-1": curvebench reads SVG files in UTF-8 only'),
               ('<!DOCTYPE svg [<!ENTITY d "M0 0 L1 1">]><svg xmlns="http://www.w3.org/2000/svg"><path d="&d;"/></svg>',
                15, "the DOCTYPE declares entities, which curvebench does not read")]
        for text, offset, words in top:
            with self.subTest(text=text):
                self.assert_error(run("length", "--svg", self.write("top.svg", text)),
                                  "top.svg: not well-formed XML at byte offset %d: %s" % (offset, words))
        # The decoded value is measured: references and XML's attribute normalisation (a tab, CR LF
        # and a referenced space are separators); an id's entities are replaced before it is printed.
        ok = self.svg('<path id="a&amp;b" d="M0&#32;0\tL10&#x20;0\r\nL10 5"/>')
        out = json.loads(run("length", "--svg", ok).stdout)
        self.assertEqual((out[0]["id"], out[0]["d"]), ("a&b", "M0 0 L10 0 L10 5"))
        self.assertAlmostEqual(out[0]["value"], 15, delta=1e-12)

    def test_length_svg_reads_elements_by_namespace(self):
        # SVG's elements are those of http://www.w3.org/2000/svg, under any prefix: an svg:-prefixed
        # document was refused at its root and its svg:path skipped, while a <path> of another
        # namespace was measured as SVG.
        prefixed = self.svg('<svg:path id="a" d="M0 0 L10 0"/><svg:g><svg:circle r="1"/></svg:g>', root="svg:svg",
                            declarations='xmlns:svg="http://www.w3.org/2000/svg"')
        p = run("length", "--svg", prefixed)
        self.assertEqual(p.returncode, 0, p.stderr)
        self.assertEqual([(e["element"], e["id"], e["index"]) for e in json.loads(p.stdout)],
                         [("path", "a", 0), ("circle", "", 1)])
        other = self.svg('<o:path d="M0 0 L1000 0"/><path d="M0 0 L10 0"/><g xmlns="urn:x"><path d="M0 0 L5 0"/></g>',
                         declarations=SVG_NS + ' xmlns:o="urn:other"')
        p = run("length", "--svg", other)
        self.assertEqual(p.returncode, 0, p.stderr)
        out = json.loads(p.stdout)
        self.assertEqual([round(e["value"]) for e in out], [10])
        self.assertIn("curvebench: note: " + other + ": 2 <path> or shape elements are not in the SVG namespace "
                      '(http://www.w3.org/2000/svg) and not measured; the first: <o:path> at byte 60 (namespace '
                      '"urn:other")', p.stderr)
        self.assertEqual(run("length", "--svg", other, "--quiet").stderr, "")
        only_other = self.svg('<o:path d="M0 0 L1 0"/>', declarations=SVG_NS + ' xmlns:o="urn:other"')
        self.assert_error(run("length", "--svg", only_other), "no <path> or basic shape (circle, ellipse, rect, line, "
                          "polyline, polygon) in the SVG namespace (1 outside it were skipped, the first <o:path>")
        self.assert_error(run("length", "--svg", self.svg("", declarations="")),
                          "the root element is <svg> in no namespace, not SVG's <svg> (namespace "
                          'http://www.w3.org/2000/svg: xmlns="http://www.w3.org/2000/svg" on the root)')
        self.assert_error(run("length", "--svg", self.svg("", declarations='xmlns="urn:x"')),
                          "the root element is <svg> of namespace urn:x, not SVG's <svg>")
        for body, offset, words in [
                ('<p:path d="M0 0 L1 0"/>', 41, "element p:path: prefix p is not declared"),
                ('<path d="M0 0 L1 0" a:b:c="1"/>', 60, "attribute a:b:c is not a QName"),
                ('<path xmlns:a="urn:x" xmlns:b="urn:x" a:k="1" b:k="2" d="M0 0 L1 0"/>', 86,
                 "attribute b:k on <path> has the namespace and local name of another of its attributes"),
                ('<path xmlns:p="" d="M0 0 L1 0"/>', 46, 'xmlns:p="": a prefix cannot be undeclared in XML 1.0'),
                ('<path xmlns:xmlns="urn:x" d="M0 0 L1 0"/>', 46, "the prefix xmlns cannot be declared")]:
            with self.subTest(body=body):
                self.assert_error(run("length", "--svg", self.svg(body)),
                                  "t.svg: not namespace-well-formed XML at byte offset %d: %s" % (offset, words))

    def test_length_svg_errors_name_the_file_the_element_and_the_offset(self):
        # Path data refused in a file said only "at offset 6 (the end of the data): expected a
        # number": now the file, the element as written, its index, its id, its byte offset and
        # the attribute's are named too, before any element is printed.
        f = self.svg('<path id="ok" d="M0 0 L1 0"/><svg:path xmlns:svg="http://www.w3.org/2000/svg" id="bad" '
                     'd="M0 0 L1"/>')
        p = run("length", "--svg", f)
        self.assert_error(p, f + ': <svg:path id="bad"> (shape or path 1, byte 69): d (value at byte 130: "M0 0 L1"): '
                          "svg path data: at offset 7 (the end of the data): expected a number")
        self.assertEqual(p.stdout, "")
        # A polygon's points: the offset counts in the attribute, not in the path data made of it.
        p = run("length", "--svg", self.svg('<polygon points="0,0 1,1 x"/>'))
        self.assert_error(p, '<polygon> (shape or path 0, byte 40): points (value at byte 57: "0,0 1,1 x"): '
                          "svg path data: at offset 8 ('x')")
        # A byte of a UTF-8 sequence the parser quotes is shown \xNN.
        p = run("length", "--svg", self.svg('<path d="M0 0 \u00e9"/>'))
        self.assert_error(p, "at offset 5 ('\\xc3')")
        # A refusal of the measurement's options comes before any output too: a cost above the
        # limit on the second element only (10000 segments) would otherwise cut the array short.
        f = self.svg('<path d="M0 0 L1 0"/><path id="long" d="M0 0' + " L1 1 L0 0" * 5000 + '"/>')
        p = run("length", "--svg", f, "--method", "composite_gauss", "--n", "10", "--panels", "1000")
        self.assert_error(p, f + ': <path id="long"> (shape or path 1, byte 61): --n 10 --panels 1000: 10000 segments '
                          "need 100000000 evaluations, more than the limit of 67108864")
        self.assertEqual(p.stdout, "")

    def test_length_svg_refuses_bytes_that_are_not_utf8(self):
        # A non-UTF-8 id printed 126 bytes of JSON, then nlohmann's json.exception: now refused
        # with the byte offset before any output.
        path = os.path.join(self.dir, "latin1.svg")
        with open(path, "wb") as f:
            f.write(b'<svg xmlns="http://www.w3.org/2000/svg"><path id="caf\xe9" d="M0 0 L1 0"/></svg>')
        p = run("length", "--svg", path)
        self.assert_error(p, path + ": not UTF-8 at byte offset 53 (byte \\xe9): curvebench reads SVG files in UTF-8")
        self.assertEqual(p.stdout, "")
        for data, offset in ((b"\xc0\x80", 0), (b"ok\xed\xa0\x80", 2), (b"\xf4\x90\x80\x80", 0), (b"\xe2\x82", 0)):
            with self.subTest(data=data):
                with open(path, "wb") as f:
                    f.write(b'<svg xmlns="http://www.w3.org/2000/svg"><!--' + data + b"--></svg>")
                self.assert_error(run("length", "--svg", path), "not UTF-8 at byte offset %d" % (44 + offset))
        with open(path, "wb") as f:
            f.write('<svg xmlns="http://www.w3.org/2000/svg"/>'.encode("utf-16"))
        self.assert_error(run("length", "--svg", path), "starts with a UTF-16 byte order mark")
        # UTF-8 with a byte order mark, and text past ASCII, are read.
        with open(path, "wb") as f:
            f.write('\ufeff<svg xmlns="http://www.w3.org/2000/svg"><path id="café" d="M0 0 L1 0"/></svg>'.encode())
        p = run("length", "--svg", path)
        self.assertEqual(p.returncode, 0, p.stderr)
        self.assertEqual(json.loads(p.stdout)[0]["id"], "café")

    def test_length_svg_bounds_the_elements_and_streams_its_output(self):
        # 1e6 paths grew to 3 GB of memory: more than 1e5 are refused before any work, naming the
        # limit and the first element past it.
        many = self.svg('<path d="M0 0 L1 0"/>' * 100001)
        p = run("length", "--svg", many)
        self.assert_error(p, many + ": more than 100000 path and shape elements (the limit per file of curvebench "
                          "length --svg; element 100000 is <path> at byte 2100040)")
        self.assertEqual(p.stdout, "")
        # Streamed, in the layout of the whole array printed at once (two spaces per level).
        two = self.svg('<path id="a" d="M0 0 L3 4"/><line x2="1"/>')
        text = run("length", "--svg", two).stdout
        out = json.loads(text)
        self.assertEqual([e["id"] for e in out], ["a", ""])
        for e, length in zip(out, (5, 1)):
            self.assertAlmostEqual(e["value"], length, delta=1e-14)
        self.assertTrue(text.startswith('[\n  {\n    "d": "M0 0 L3 4",\n    "element": "path",\n'), text[:80])
        self.assertRegex(text, r'\n    "value": [0-9.e-]+\n  }\n]\n$')
        self.assertIn('\n  },\n  {\n    "d": "M0 0 L1 0",', text)

    def test_length_gauss_estimate_none_is_the_fixed_rule_without_an_estimate(self):
        # gauss's estimate is a setting of the CLI: nested (the default, with a bound) or none (the
        # benchmarks' fast fixed rule: n evaluations per segment, no estimate, and says so).
        spec = os.path.join(CASES, "arch_cubic_bezier.json")  # one segment
        nested = json.loads(run("length", spec, "--method", "gauss", "--n", "8").stdout)
        self.assertEqual(nested, json.loads(run("length", spec, "--method", "gauss", "--n", "8",
                                                "--estimate", "nested").stdout))
        self.assertEqual(nested["status"], "converged")
        p = run("length", spec, "--method", "gauss", "--n", "8", "--estimate", "none")
        self.assertEqual(p.returncode, 0, p.stderr)
        none = json.loads(p.stdout)
        self.assertEqual(none["status"], "not_guaranteed")
        self.assertIsNone(none["estimate"])
        self.assertEqual(none["reason"], "fixed rule without an estimate (estimate:none)")
        self.assertEqual(none["evaluations"], 8)
        # The same length by one 8-point panel: its error, about |Q1 - Q2| of the nested rule, is
        # 1.6e-8 relative on the arch (measured); 1e-6 only says it measured the same curve.
        self.assertLessEqual(abs(none["value"] - nested["value"]), 1e-6 * nested["value"])
        self.assert_error(run("length", spec, "--method", "adaptive_gk", "--estimate", "none"),
                          "--estimate none does not apply to --method adaptive_gk (only gauss takes it)")
        p = run("length", spec, "--method", "gauss", "--estimate", "nothing")
        self.assertNotEqual(p.returncode, 0)
        self.assertIn("--estimate", p.stderr)

    def test_channel_sample_checks_the_solver_and_names_the_file(self):
        # The truth replaces the spec's solver with the exact one; a misspelt solver is still an
        # error, and the model's own refusals (keys out of order) name the file.
        bad = self.write("solver.json", '{"type": "channel", "tool": "exact", "solver": "newton", '
                         '"keys": [{"time": 0, "value": 0}, {"time": 1, "value": 1}]}')
        self.assert_error(run("sample", bad, "--at", "0.5"), "solver.json.solver", "not a time solver")
        order = self.write("order.json", '{"type": "channel", "tool": "exact", '
                           '"keys": [{"time": 1, "value": 0}, {"time": 0, "value": 1}]}')
        self.assert_error(run("sample", order, "--at", "0.5"), "order.json: ", "keys[1].time = 0")

    def test_channel_specs_sample_at_times(self):
        # --at, --frames and --range give times for channel specs: t, value, dvalue, d2value.
        spec = os.path.join(CASES, "channel_regression_limit.json")
        p = run("sample", spec, "--at", "0,4.5,9,12", "--derivatives", "2")
        self.assertEqual(p.returncode, 0, p.stderr)
        # A first comment line says what the values are (the truth by default).
        self.assertTrue(p.stdout.startswith("# curvebench sample: the channel at 50 digits"), p.stdout[:200])
        rows = p.stdout.splitlines()[1:]
        self.assertEqual(rows[0], "t,value,dvalue,d2value")
        self.assertEqual([r.split(",")[:2] for r in rows[1:]][0], ["0", "0"])
        self.assertEqual(rows[3].split(",")[1], "1")  # the last key
        self.assertEqual(rows[4].split(",")[1:3], ["1", "0"])  # constant extrapolation after it
        f = run("sample", os.path.join(CASES, "css_overshoot.json"), "--frames", "0:1:0.25", "--derivatives", "0")
        self.assertEqual(f.returncode, 0, f.stderr)
        self.assertEqual(len(f.stdout.splitlines()), 7)
        self.assertEqual(f.stdout.splitlines()[-1], "1,1")
        # --frames A:B steps by 1 (its errors name --frames), and a decimal grid
        # prints the decimals it names (0.3, not 0.30000000000000004).
        g = run("sample", spec, "--frames", "1:4", "--derivatives", "0")
        self.assertEqual(g.returncode, 0, g.stderr)
        self.assertEqual([r.split(",")[0] for r in g.stdout.splitlines()[2:]], ["1", "2", "3", "4"])
        d = run("sample", spec, "--frames", "0:1:0.1", "--derivatives", "0")
        self.assertEqual(d.returncode, 0, d.stderr)
        self.assertEqual([r.split(",")[0] for r in d.stdout.splitlines()[2:]],
                         ["0", "0.1", "0.2", "0.3", "0.4", "0.5", "0.6", "0.7", "0.8", "0.9", "1"])
        # A grid whose exact decimal needs more than 10^30 (17 decimals of A against a 17-digit STEP)
        # takes double arithmetic: every time within rounding of A + i STEP, none from an overflow.
        step = 99999999999999999
        w = run("sample", spec, "--range", f"0.00000000000000001:1e22:{step}", "--derivatives", "0")
        self.assertEqual(w.returncode, 0, w.stderr)
        times = [float(r.split(",")[0]) for r in w.stdout.splitlines()[2:]]
        self.assertEqual(len(times), 100001)
        for i in (1, 1000, 100000):
            self.assertLess(abs(times[i] - i * float(step)), 1e-15 * i * step, i)
        self.assert_error(run("sample", spec, "--frames", "1"), "--frames", "A:B[:STEP]")
        self.assert_error(run("sample", spec, "--frames", "1:x"), "--frames: item 2", '"x"')
        # Without times a channel samples its curve view by u, as every family does.
        u = run("sample", spec, "--count", "3")
        self.assertEqual(u.returncode, 0, u.stderr)
        self.assertTrue(u.stdout.startswith("u,s,x,y"))
        self.assert_error(run("sample", spec, "--at", "1", "--derivatives", "3"), "--derivatives 3", "order 2")

    def test_gltf_rotation_samples_quaternions_at_times(self):
        # A rotation channel prints t, x, y, z, w (and their time derivatives); 90 degrees about z in
        # one second, so at t = 0.5 slerp is 45 degrees: (0, 0, sin(pi/8), cos(pi/8)).
        spec = self.write("rot.json", '{"type": "channel", "tool": "gltf", "path": "rotation", '
                                      '"interpolation": "linear", "times": [0, 1], '
                                      '"values": [0, 0, 0, 1, 0, 0, 0.7071067811865476, 0.7071067811865476]}')
        p = run("sample", spec, "--at", "0.5,2", "--derivatives", "1")
        self.assertEqual(p.returncode, 0, p.stderr)
        rows = p.stdout.splitlines()
        self.assertEqual(rows[0], "t,x,y,z,w,dx,dy,dz,dw")
        half = [float(x) for x in rows[1].split(",")]
        self.assertAlmostEqual(half[3], math.sin(math.pi / 8), places=15)
        self.assertAlmostEqual(half[4], math.cos(math.pi / 8), places=15)
        # dq/dt = (pi/4) (0, 0, cos(pi/8), -sin(pi/8)) per second (half the rotation rate pi/2).
        self.assertAlmostEqual(half[7], math.pi / 4 * math.cos(math.pi / 8), places=14)
        self.assertEqual(rows[2].split(",")[1:5], ["0", "0", "0.70710678118654757", "0.70710678118654757"])  # clamped
        # No curve view: sampling by u says how to evaluate it; a key off unit length names its index.
        self.assert_error(run("sample", spec, "--count", "3"), "path", "unit quaternion", "--at")
        bad = self.write("bad.json", '{"type": "channel", "tool": "gltf", "path": "rotation", '
                                     '"interpolation": "linear", "times": [0, 1], '
                                     '"values": [0, 0, 0, 1, 0, 0, 0.8, 0.8]}')
        self.assert_error(run("sample", bad, "--at", "0.5"), "bad.json: values[4..7] (key 1 value)", "unit quaternions")

    def test_sample_count_has_a_documented_limit(self):
        p = run("sample", ARCH, "--count", "1000001")
        self.assertNotEqual(p.returncode, 0)
        self.assertIn("--count", p.stderr)
        self.assertIn("1000000", run("sample", "--help").stdout)

    def test_sample_ease_phases_are_exactly_two_finite_numbers(self):
        # Both were accepted, the trailing text ignored.
        self.assert_error(run("sample", ARCH, "--by", "arclength", "--ease", "sine_plateau:0.2,0.8junk"),
                          '--ease "sine_plateau:0.2,0.8junk"', 'phase T2 "0.8junk" is not a finite number',
                          "expected sine_plateau:T1,T2")
        self.assert_error(run("sample", ARCH, "--by", "arclength", "--ease", "parabolic:0.3,0.7,0.9"),
                          '--ease "parabolic:0.3,0.7,0.9"', "3 phases given", "expected parabolic:T1,T2")
        self.assert_error(run("sample", ARCH, "--by", "arclength", "--ease", "parabolic:0.3"), "1 phase given")
        # The ease's own refusal names the option and the phases as given.
        self.assert_error(run("sample", ARCH, "--by", "arclength", "--ease", "sine_plateau:0.8,0.2"),
                          '--ease "sine_plateau:0.8,0.2": phases T1 "0.8", T2 "0.2": ')
        self.assert_error(run("sample", ARCH, "--by", "arclength", "--ease", "parabolic"), "needs its phases")
        self.assert_error(run("sample", ARCH, "--by", "arclength", "--ease", "parabolic:,0.7"), 'phase T1 ""')
        rows = self.sample("--by", "arclength", "--count", "5", "--ease", "parabolic: 0.3 , 0.7").splitlines()
        self.assertEqual(len(rows), 6)  # spaces around a number are fine, as in every numeric cell

    def test_sample_by_arclength_reports_its_table_and_takes_a_target(self):
        # The u(s) table is sized per segment to --table-tol; its size, measured error,
        # status and build time go to stderr, the samples to stdout.
        road = self.write("road.json", json.dumps({"type": "catmull_rom", "alpha": 0.5, "points": [
            [k, (k * 7919 % 13) / 4.0] for k in range(201)]}))
        p = run("sample", road, "--by", "arclength", "--count", "9", "--table-tol", "1e-9")
        self.assertEqual(p.returncode, 0, p.stderr)
        self.assertEqual(len(p.stdout.splitlines()), 10)
        m = re.search(r"u\(s\) table of (\d+) cells over 200 segments, measured error (\S+) L "
                      r"\(converged, target 1e-09 L\), \d+ evaluations, built in \S+ s", p.stderr)
        self.assertIsNotNone(m, p.stderr)
        self.assertGreaterEqual(int(m.group(1)), 200)
        self.assertLessEqual(float(m.group(2)), 1e-9)
        self.assertEqual(run("sample", road, "--by", "arclength", "--quiet").stderr, "")
        self.assert_error(run("sample", road, "--table-tol", "1e-9"), "--table-tol", "--by arclength")
        self.assert_error(run("sample", road, "--by", "arclength", "--method", "newton", "--table-tol", "1e-9"),
                          "--table-tol", "newton builds none")

    def test_specs_nested_too_deep_or_with_a_repeated_key_fail_naming_the_file(self):
        deep = self.write("deep.json", '{"type": "bezier", "reason": ' + "[" * 1000000 + "]" * 1000000 + "}")
        p = run("length", deep)  # a SIGSEGV before
        self.assert_error(p, "deep.json.reason[0][0]", "nested more than 64 levels deep")
        self.assertLess(len(p.stderr), 600)
        twice = self.write("twice.json", '{"type": "bezier", "points": [[0,0],[1,1]], "type": "polyline"}')
        self.assert_error(run("length", twice), "twice.json", 'key "type" appears twice')
        huge = self.write("huge.json", '{"type": "bspline", "degree": 18446744073709551615, "points": [[0,0],[1,1]]}')
        self.assert_error(run("length", huge), "huge.json.degree", "18446744073709551615")

    def test_gate_checks_both_files_structure_naming_the_file(self):
        results = self.write("results.json", json.dumps({"records": [
            {"case": "c", "group": "g", "quantity": "length", "method": "adaptive_gk", "setting": "tol=1e-12",
             "error": 1e-16, "estimate": 1e-15, "bounded": True, "evaluations": 30, "status": "converged"}]}))
        good = self.write("good.json", json.dumps({"rules": [{"quantity": "length", "max_error": 1e-15}]}))
        p = run("gate", "--results", results, "--thresholds", good)
        self.assertEqual(p.returncode, 0, p.stdout + p.stderr)
        self.assertIn("gate: 1 rules, 0 breaches", p.stdout)
        self.assertEqual(p.stderr, "")
        strict = self.write("strict.json", json.dumps({"rules": [{"quantity": "length", "max_error": 1e-17}]}))
        p = run("gate", "--results", results, "--thresholds", strict)
        self.assertEqual(p.returncode, 1, p.stdout + p.stderr)
        self.assertIn("gate: BREACH length/*/* case c setting tol=1e-12: error 1e-16 > allowed 1e-17", p.stdout)
        self.assertIn("curvebench: gate: 1 breach (exit 1)", p.stderr)  # the verdict where a CI log shows it
        # Each of these passed with exit 0.
        typo = self.write("typo.json", json.dumps({"rules": [{"quantity": "length", "max_eror": 1e-15}]}))
        self.assert_error(run("gate", "--results", results, "--thresholds", typo),
                          "typo.json rule 0", 'unknown key "max_eror"')
        empty = self.write("empty.json", json.dumps({"rules": []}))
        self.assert_error(run("gate", "--results", results, "--thresholds", empty), "empty.json", '"rules" is empty')
        obj = self.write("object.json", json.dumps({"rules": {"quantity": "length", "max_error": 1e-15}}))
        self.assert_error(run("gate", "--results", results, "--thresholds", obj), "object.json", "must be an array")
        no_records = self.write("norec.json", json.dumps({"orders": []}))
        self.assert_error(run("gate", "--results", no_records, "--thresholds", good), "norec.json", '"records" array')
        broken = self.write("broken.json", '{"rules": [')  # the parser's text named no file
        self.assert_error(run("gate", "--results", results, "--thresholds", broken), "broken.json: not valid JSON")

    # ---- version, help, installed layout -------------------------------------------------------

    def test_version_names_the_revision_built_from(self):
        p = run("--version")
        self.assertEqual(p.returncode, 0, p.stderr)
        self.assertRegex(p.stdout, r"^curvebench \d+\.\d+\.\d+ \((unknown|[0-9a-f]{4,}(\+dirty)?)\)\n$")
        git = shutil.which("git")
        if not git or not os.path.isdir(os.path.join(ROOT, ".git")) and not os.path.isfile(os.path.join(ROOT, ".git")):
            self.skipTest("no git checkout")
        head = subprocess.run([git, "-C", ROOT, "rev-parse", "--short", "HEAD"], capture_output=True, text=True)
        self.assertEqual(p.stdout.split("(")[1].split(")")[0].split("+")[0], head.stdout.strip())

    # ---- fidelity: the tool models against recordings of the real tools ------------------------

    def test_fidelity_counts_agreement_and_gates_on_request(self):
        spec = {"type": "channel", "tool": "maya", "keys": [
            {"time": 0, "value": 0, "in_type": "linear", "out_type": "linear"},
            {"time": 10, "value": 5, "in_type": "linear", "out_type": "linear"}]}
        rec = {"tool": "maya", "source": {"implementation": "closed form", "version": "1"}, "channels": [
            {"name": "right", "features": ["tangent:linear"], "spec": spec, "t": [0, 5, 20], "value": [0, 2.5, 5]},
            # 0.25 off at t = 5, where the scale is the recorded range 2.75 + |t V'(t)| = 2.5: 0.0476.
            {"name": "late", "features": ["tangent:linear"], "spec": spec, "t": [0, 5], "value": [0, 2.75]}]}
        path = self.write("rec.json", json.dumps(rec))
        p = run("fidelity", path)
        self.assertEqual(p.returncode, 0, p.stderr)
        self.assertIn("1 of 2 evaluated channels agree", p.stdout)
        self.assertIn("disagrees: late: 0.0476 of the scale at t = 5 (model 2.5, tool 2.75)", p.stdout)
        p = run("fidelity", path, "--require-agreement")
        self.assertEqual(p.returncode, 1)
        self.assertIn("late disagrees with the tool", p.stderr)
        j = json.loads(run("fidelity", path, "--json").stdout)
        self.assertEqual(j["recordings"][0]["agree"], 1)
        self.assertTrue(j["curvebench"].startswith("curvebench "))
        rec["channels"] = rec["channels"][:1]
        self.assertEqual(run("fidelity", self.write("ok.json", json.dumps(rec)), "--require-agreement").returncode, 0)
        # A channel the tool gave no values for is unverified, not a disagreement; under
        # --require-agreement it fails as what it is, and a recording with nothing evaluated fails.
        unverified = dict(rec, channels=rec["channels"] + [
            {"name": "hermite", "features": [], "spec": spec, "t": [0, 5], "unverified": "no values"}])
        path = self.write("unverified.json", json.dumps(unverified))
        p = run("fidelity", path)
        self.assertEqual(p.returncode, 0, p.stderr)
        self.assertIn("unverified: hermite: no values", p.stdout)
        self.assertNotIn("disagrees", p.stdout)
        p = run("fidelity", path, "--require-agreement")
        self.assertEqual(p.returncode, 1)
        self.assertIn("hermite is unverified", p.stderr)
        self.assertNotIn("disagrees", p.stderr)
        p = run("fidelity", self.write("none.json", json.dumps(dict(rec, channels=unverified["channels"][1:]))),
                "--require-agreement")
        self.assertEqual(p.returncode, 1)
        self.assertIn("curvebench: error: ", p.stderr)
        self.assertIn("no channel was evaluated (0 refused, 1 unverified)", p.stderr)
        rec["channels"][0]["value"] = [0]
        self.assert_error(run("fidelity", self.write("bad.json", json.dumps(rec))), "bad.json.channels[0]",
                          "3 times and 1 values")

    def test_the_published_fidelity_block_is_what_the_models_measure_now(self):
        # docs/results.md's fidelity block (scripts/publish.py --fidelity-only) must say what the
        # models and the recordings of this checkout give: a model change that alters a count fails
        # here until the block is refreshed. Only the line naming the measuring revision may differ.
        import glob
        import sys
        sys.path.insert(0, os.path.join(ROOT, "scripts"))
        import publish
        recordings = sorted(glob.glob(os.path.join(ROOT, "tests", "data", "recorded", "*.json")))
        self.assertTrue(recordings)
        p = subprocess.run([TOOL, "fidelity", "--json", *[os.path.relpath(r, ROOT) for r in recordings]],
                           capture_output=True, text=True, timeout=600, cwd=ROOT)
        self.assertEqual(p.returncode, 0, p.stderr)
        vocab = json.loads(run("list", "vocabulary", "--json").stdout)
        block = publish.render_fidelity(json.loads(p.stdout), vocab["tools"])
        with open(os.path.join(ROOT, "docs", "results.md"), encoding="utf-8") as f:
            page = f.read()
        i, j = page.find(publish.FIDELITY_BEGIN), page.find(publish.FIDELITY_END)
        self.assertTrue(0 <= i < j, "docs/results.md has no fidelity block")

        def body(text):
            return [line for line in text.splitlines() if not line.startswith("Measured by ")]
        self.assertEqual(body(page[i:j + len(publish.FIDELITY_END)]), body(block),
                         "refresh it: curvebench fidelity --json tests/data/recorded/*.json > reports/fidelity.json; "
                         "curvebench list vocabulary --json > reports/vocabulary.json; "
                         "python3 scripts/publish.py --fidelity-only")

    def test_every_tool_says_what_it_is_verified_against(self):
        p = run("list", "tools")
        self.assertEqual(p.returncode, 0, p.stderr)
        self.assertEqual(p.stdout.count("verification: "), 6, p.stdout)
        self.assertIn("spline, clamped and plateau tangents", p.stdout)  # Maya's, documented, not verified
        self.assertIn("(curvebench list tools:", run("list", "families").stdout)

    def test_every_subcommand_help_ends_with_an_example(self):
        for sub in ["list", "sample", "check", "length", "accuracy", "gate", "fidelity"]:
            with self.subTest(sub=sub):
                p = run(sub, "--help")
                self.assertEqual(p.returncode, 0, p.stderr)
                tail = [line for line in p.stdout.splitlines() if line.strip()][-2:]
                self.assertEqual(tail[0], "Example:")
                self.assertTrue(tail[1].startswith(f"  curvebench {sub} "), tail[1])
                # The files an example reads exist (from the repository's root):
                # its spec, thresholds and cases (values.csv is what sample's example writes, and
                # easing.csv sample's channel example, reports/accuracy.json what accuracy's writes).
                words = tail[1].split()
                made = {"values.csv", "easing.csv", "reports/accuracy.json"}
                for w in words:
                    if w.endswith((".json", ".csv")) and w not in made:
                        self.assertTrue(os.path.isfile(os.path.join(ROOT, w)), f"{sub}: {w} in {tail[1]}")
                if "--only" in words:
                    only = words[words.index("--only") + 1]
                    self.assertTrue(any(only in f for f in os.listdir(CASES)), f"--only {only} matches no case")

    def test_an_installed_tool_finds_its_cases_beside_it(self):
        prefix = os.path.join(self.dir, "prefix")
        os.makedirs(os.path.join(prefix, "bin"))
        cases = os.path.join(prefix, "share", "curvebench", "cases")
        os.makedirs(cases)
        shutil.copy(ARCH, cases)
        shutil.copy(TOOL, os.path.join(prefix, "bin", "curvebench"))
        p = subprocess.run([os.path.join(prefix, "bin", "curvebench"), "list", "cases"], capture_output=True,
                           text=True, timeout=60, cwd=self.dir)
        self.assertEqual(p.returncode, 0, p.stderr)
        self.assertIn(f"cases ({cases})", p.stdout)
        self.assertEqual(p.stdout.count("\n  "), 1, p.stdout)  # the one case copied there, not the source tree's
        # Without the installed layout, the source tree's cases.
        p = run("list", "cases")
        self.assertIn(f"cases ({CASES})", p.stdout)
        # Every row's name, group and reason stand apart, the longest name too.
        names = {os.path.splitext(f)[0] for f in os.listdir(CASES) if f.endswith(".json")}
        rows = [r for r in p.stdout.splitlines() if r.startswith("  ")]
        self.assertEqual(len(rows), len(names))
        for r in rows:
            name = r.split()[0]
            self.assertIn(name, names, r)
            self.assertTrue(r[2 + len(name):].startswith("  "), r)

    def test_length_help_shows_defaults_and_the_estimate_unit(self):
        # `length --help` hid the defaults of --n and --tol and whether the estimate
        # is absolute.
        h = run("length", "--help")
        self.assertEqual(h.returncode, 0, h.stderr)
        self.assertIn("estimate (absolute, in the curve's length units", h.stdout)
        for option in ("--n", "--tol"):
            line = next(r for r in h.stdout.splitlines() if r.strip().startswith(option + " "))
            self.assertRegex(line, option + r" [^=]*\S=\S+  ", line)  # CLI11 prints a captured default as TYPE=value


if __name__ == "__main__":
    unittest.main()
