"""scripts/peers/fonttools_driver.py without fontTools: the request's segments become the calls of
each peer (lines by their distance, quadratics and cubics to the right bezierTools function, the
tolerance passed only when it is not the default), arcs are skipped, and the recorded output of a
real run (fontTools 4.38.0, Debian bookworm: tests/data/peers/fonttools/, README there) validates
against its request and keeps fontTools' documented figures. With the tool (CURVEBENCH_TOOL) the
recorded output also goes through shipped_results.measure."""
import json
import math
import os
import sys
import tempfile
import types
import unittest

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.join(HERE, "..", "..")
sys.path.insert(0, os.path.join(ROOT, "scripts"))
sys.path.insert(0, os.path.join(ROOT, "scripts", "peers"))
import fonttools_driver as fd  # noqa: E402
import shipped_results  # noqa: E402

DATA = os.path.join(HERE, "..", "data", "peers", "fonttools")
CASES = os.path.join(ROOT, "bench", "cases")
TOOL = os.environ.get("CURVEBENCH_TOOL")


def load(name):
    with open(os.path.join(DATA, name), encoding="utf-8") as f:
        return json.load(f)


def fake_bezier_tools(calls):
    """A stand-in for fontTools.misc.bezierTools recording each call and returning a tag value."""
    def rec(name, value):
        def f(*args):
            calls.append((name, args))
            return value
        return f
    return types.SimpleNamespace(calcCubicArcLengthC=rec("calcCubic", 1000.0),
                                 calcQuadraticArcLengthC=rec("calcQuad", 100.0),
                                 approximateCubicArcLengthC=rec("approxCubic", 10000.0),
                                 approximateQuadraticArcLengthC=rec("approxQuad", 10.0))


class Conversion(unittest.TestCase):
    CASE = {"case": "x", "segments": [{"start": [0, 0], "closed": False, "segments": [
        {"kind": "line", "points": [[0, 0], [3, 4]]},
        {"kind": "quadratic", "points": [[3, 4], [5, 4], [6, 0]]},
        {"kind": "cubic", "points": [[6, 0], [7, 1], [8, 1], [9, 0]]}]}]}

    def test_segments_and_calls(self):
        segs = fd.segment_list(self.CASE)
        self.assertEqual([k for k, _ in segs], ["line", "quadratic", "cubic"])
        self.assertEqual(segs[1][1], [3 + 4j, 5 + 4j, 6 + 0j])
        calls = []
        bt = fake_bezier_tools(calls)
        # The line is its exact distance, 5 (a 3-4-5 triangle); the others the functions' values.
        self.assertEqual(fd.path_length_function(segs, "peer_fonttools_calc", None, bt)(), 5 + 100 + 1000)
        self.assertEqual(calls, [("calcQuad", (3 + 4j, 5 + 4j, 6 + 0j)),
                                 ("calcCubic", (6 + 0j, 7 + 1j, 8 + 1j, 9 + 0j))])
        calls.clear()
        fd.path_length_function(segs, "peer_fonttools_calc", 1e-8, bt)()
        self.assertEqual(calls[1], ("calcCubic", (6 + 0j, 7 + 1j, 8 + 1j, 9 + 0j, 1e-8)))
        calls.clear()
        self.assertEqual(fd.path_length_function(segs, "peer_fonttools_approx", None, bt)(), 5 + 10 + 10000)
        self.assertEqual([c[0] for c in calls], ["approxQuad", "approxCubic"])

    def test_settings_arcs_and_notes(self):
        self.assertEqual(fd.peer_settings(), [("peer_fonttools_calc", "", None),
                                              ("peer_fonttools_calc", "tolerance=1e-08", 1e-8),
                                              ("peer_fonttools_approx", "", None)])
        arc = {"case": "a", "segments": [{"start": [1, 0], "closed": False, "segments": [
            {"kind": "arc", "points": [[1, 0], [0, 1]], "rx": 1, "ry": 1}]}]}
        runs, skipped = fd.run_case(arc, fake_bezier_tools([]))
        self.assertEqual(runs, [])
        self.assertEqual([s["peer"] for s in skipped], ["peer_fonttools_calc", "peer_fonttools_approx"])
        self.assertIn("no elliptical arc", skipped[0]["reason"])
        note = fd.note_of("peer_fonttools_calc", "", fd.segment_list(self.CASE))
        self.assertIn("calcCubicArcLength(tolerance=0.005)", note)
        self.assertIn("lines by their exact distance", note)
        with self.assertRaisesRegex(fd.DriverError, "'spline'"):
            fd.segment_list({"case": "b", "segments": [{"segments": [{"kind": "spline", "points": [[0, 0]]}]}]})

    def test_a_non_finite_length_is_skipped(self):
        bt = fake_bezier_tools([])
        bt.approximateCubicArcLengthC = lambda *a: float("nan")
        runs, skipped = fd.run_case(self.CASE, bt, pass_ns=1000, passes=1)
        self.assertEqual([r["peer"] for r in runs], ["peer_fonttools_calc", "peer_fonttools_calc"])
        self.assertEqual(skipped, [{"peer": "peer_fonttools_approx", "case": "x", "setting": "",
                                    "reason": "fontTools returned nan"}])

    def test_timing_and_cpu(self):
        value, ns = fd.peer_io.best_ns(lambda: 42, pass_ns=10_000, passes=2, slow_call_ns=fd.SLOW_CALL_NS)
        self.assertEqual(value, 42)
        self.assertGreater(ns, 0)
        self.assertEqual(fd.cpu_model("processor\t: 0\nmodel name\t: AMD EPYC 7B13\n"), "AMD EPYC 7B13")


class Recorded(unittest.TestCase):
    def setUp(self):
        self.request, self.out = load("request.json"), load("fonttools_driver.json")
        self.truth = {c["case"]: c["length"] for c in self.request["cases"]}
        self.runs = {(r["peer"], r["setting"], r["case"]): r for r in self.out["runs"]}

    def rel(self, peer, setting, case):
        return (self.runs[(peer, setting, case)]["length"] - self.truth[case]) / self.truth[case]

    def test_validates_and_has_every_run(self):
        shipped_results.validate(self.out, self.request)
        self.assertEqual(self.out["driver"], "fonttools")
        self.assertEqual(self.out["versions"], {"fontTools": "4.38.0"})
        cases = [c["case"] for c in self.request["cases"] if c["case"] != "svg_every_command"]
        self.assertEqual(sorted(self.runs), sorted((p, s, c) for p, s, _ in fd.peer_settings() for c in cases))
        self.assertEqual([(s["peer"], s["case"]) for s in self.out["skipped"]],
                         [("peer_fonttools_calc", "svg_every_command"), ("peer_fonttools_approx", "svg_every_command")])
        for r in self.out["runs"]:
            self.assertIsNone(r["points"])
            self.assertIsNone(r["spaced"])
            self.assertGreater(r["ns_length"], 0)

    def test_fonttools_documented_figures(self):
        # approximateCubicArcLength's docstring: the collinear cusp of length 150 gives 136.9267662156362.
        self.assertEqual(self.runs[("peer_fonttools_approx", "", "svg_cusp_fonttools")]["length"], 136.9267662156362)
        # calcQuadraticArcLength is a closed form: both settings give the same double, at rounding level.
        for setting in ("", "tolerance=1e-08"):
            self.assertLess(abs(self.rel("peer_fonttools_calc", setting, "parabola_quadratic_bezier")), 1e-14)
        # calcCubicArcLength stops a piece when chord x (1 + 1.5 tol) >= polygon and returns their mean,
        # so each piece's error is within 0.75 tol of its length: the sum is within 0.75 tol too.
        for case in self.truth:
            if ("peer_fonttools_calc", "", case) in self.runs:
                self.assertLess(abs(self.rel("peer_fonttools_calc", "", case)), 0.75 * 0.005, case)
                self.assertLess(abs(self.rel("peer_fonttools_calc", "tolerance=1e-08", case)), 0.75 * 1e-8, case)
        # The test is relative: a nearly straight cubic passes at the first level, 4e-9 long, at both tolerances.
        self.assertAlmostEqual(self.rel("peer_fonttools_calc", "", "svg_near_straight"), 4e-9, delta=1e-10)
        # One 5-point Gauss-Lobatto panel on a smooth cubic: 0.4 % short on the 1-wide test cubic.
        self.assertLess(abs(self.rel("peer_fonttools_approx", "", "svg_cubic_extent_1e0")), 5e-3)

    @unittest.skipUnless(TOOL, "needs CURVEBENCH_TOOL (the tool checks the runs)")
    def test_measured(self):
        result = shipped_results.measure(self.out, self.request, CASES, TOOL, tempfile.mkdtemp())
        self.assertEqual(len(result["rows"]), len(self.out["runs"]))
        # fontTools gives lengths only: shipped_results takes the 50-digit L from a check of the case's
        # start point, so every row has its length error against the reference, not the request.
        for row in result["rows"]:
            self.assertIsNone(row["point_error"])
            self.assertTrue(math.isfinite(row["length"]))
            self.assertGreater(row["ns_length"], 0)
            # The request's adaptive_gk length agrees with the reference to 1e-14 (its tolerance).
            self.assertLess(abs(row["true_length"] - self.truth[row["case"]]) / row["true_length"], 1e-14, row)
            self.assertEqual(row["length_error"], abs(row["length"] - row["true_length"]) / row["true_length"])
        rows = {(r["peer"], r["setting"], r["case"]): r for r in result["rows"]}
        # The cusp's closed form is 150: the docstring's 136.9267662156362 is 8.7 % short.
        self.assertAlmostEqual(rows[("peer_fonttools_approx", "", "svg_cusp_fonttools")]["length_error"],
                               (150 - 136.9267662156362) / 150, delta=1e-15)


if __name__ == "__main__":
    unittest.main()
