"""scripts/peers/blender_length_driver.py without Blender: the request's segments become Bezier spline
points (a quadratic raised exactly, a line with its handles at thirds, a closed subpath a cyclic
spline whose wrap-around segment is the subpath's first), Blender's answer becomes runs (errors and
non-finite values skipped), and the recorded output of a real run (Blender 3.4.1, Debian bookworm:
tests/data/peers/blender_length/, README there) validates against its request. With the tool
(CURVEBENCH_TOOL) the recorded output is measured and its errors kept in the bands Blender's
algorithm gives (polyline of resolution_u chords per segment)."""
import copy
import json
import math
import os
import sys
import tempfile
import unittest

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.join(HERE, "..", "..")
sys.path.insert(0, os.path.join(ROOT, "scripts"))
sys.path.insert(0, os.path.join(ROOT, "scripts", "peers"))
import blender_length_driver as bd  # noqa: E402
import shipped_results  # noqa: E402

DATA = os.path.join(HERE, "..", "data", "peers", "blender_length")
CASES = os.path.join(ROOT, "bench", "cases")
TOOL = os.environ.get("CURVEBENCH_TOOL")


def load(name):
    with open(os.path.join(DATA, name), encoding="utf-8") as f:
        return json.load(f)


def seg(kind, pts):
    return {"kind": kind, "points": pts}


class Conversion(unittest.TestCase):
    def test_raise_and_line_handles(self):
        # Quadratic (0,0) (3,6) (6,0): the cubic's handles 2/3 of the way to the control point.
        self.assertEqual(bd.cubic_of(seg("quadratic", [[0, 0], [3, 6], [6, 0]])), [[0, 0], [2, 4], [4, 4], [6, 0]])
        # A line from (0,0) to (3,-6): handles at one and two thirds.
        self.assertEqual(bd.cubic_of(seg("line", [[0, 0], [3, -6]])), [[0, 0], [1, -2], [2, -4], [3, -6]])
        c = [[0, 0], [1, 2], [3, 2], [4, 0]]
        self.assertEqual(bd.cubic_of(seg("cubic", c)), c)
        with self.assertRaisesRegex(bd.DriverError, "no exact Bezier"):
            bd.cubic_of(seg("arc", [[1, 0], [0, 1]]))

    def test_open_spline(self):
        sub = {"closed": False, "segments": [seg("cubic", [[0, 0], [1, 2], [3, 2], [4, 0]]),
                                             seg("line", [[4, 0], [7, 0]])]}
        self.assertEqual(bd.spline_of(sub), {"cyclic": False, "points": [
            [[0, 0], [0, 0], [1, 2]], [[4, 0], [3, 2], [5, 0]], [[7, 0], [6, 0], [7, 0]]]})

    def test_closed_spline_starts_with_its_first_segment(self):
        # A triangle (0,0) -> (3,0) -> (0,3) -> back: three points, point j the start of segment j + 1,
        # the wrap-around (last point to first) carrying segment 0 from (0,0) to (3,0).
        sub = {"closed": True, "segments": [seg("line", [[0, 0], [3, 0]]), seg("line", [[3, 0], [0, 3]]),
                                            seg("line", [[0, 3], [0, 0]])]}
        sp = bd.spline_of(sub)
        self.assertTrue(sp["cyclic"])
        self.assertEqual(sp["points"], [[[3, 0], [2, 0], [2, 1]], [[0, 3], [1, 2], [0, 2]], [[0, 0], [0, 1], [1, 0]]])
        # Closed but not ending on its start: an open spline.
        sub["segments"][-1] = seg("line", [[0, 3], [0, 1]])
        self.assertFalse(bd.spline_of(sub)["cyclic"])

    def test_input_and_skips(self):
        request = load("request.json")
        doc, skipped = bd.blender_input(request["cases"], quick=True)
        self.assertEqual(doc["resolutions"], [12, 4, 64])
        self.assertEqual((doc["pass_ns"], doc["passes"]), (200_000, 3))
        self.assertEqual([s["case"] for s in skipped], ["svg_every_command"])
        self.assertIn("elliptical arc", skipped[0]["reason"])
        self.assertEqual(len(doc["cases"]), len(request["cases"]) - 1)
        self.assertTrue(all(len(c["s"]) == 17 and c["spaced"] == 17 for c in doc["cases"]))

    def test_answers(self):
        doc, _ = bd.blender_input(load("request.json")["cases"])
        good = {"resolution": 12, "length": 1.5, "ns_length": 100.0, "points": [[0, 0]] * 17,
                "spaced": [[0, 0]] * 17, "ns_point": 5000.0}
        answer = {"blender": "3.4.1", "cases": [{"case": c["case"], "results": [dict(good)]} for c in doc["cases"]]}
        answer["cases"][0] = {"case": doc["cases"][0]["case"], "error": "RuntimeError: x"}
        answer["cases"][1]["results"][0]["points"] = [[float("nan"), 0]] * 17
        runs, skipped = bd.runs_of(answer, doc)
        self.assertEqual(len(runs), len(doc["cases"]) - 2)
        self.assertEqual(skipped[0]["reason"], "Blender raised RuntimeError: x")
        self.assertIn("non-finite", skipped[1]["reason"])
        self.assertIn("s beyond Blender's own length asked at its length", runs[0]["note"])
        bad = copy.deepcopy(answer)
        bad["cases"].pop()
        with self.assertRaisesRegex(bd.DriverError, "answered cases"):
            bd.runs_of(bad, doc)

    def test_nurbs_of(self):
        c = {"case": "x", "points": [[0, 0, 0], [1, 2, 0], [2, 0, 1]], "degree": 2, "weights": [1, 3, 0.5],
             "knot_vector": "clamped"}
        self.assertEqual(bd.nurbs_of(c), {"points": [[0, 0, 0, 1], [1, 2, 0, 3], [2, 0, 1, 0.5]], "order": 3,
                                          "endpoint": True, "cyclic": False})
        self.assertTrue(bd.nurbs_of(dict(c, weights=None, knot_vector="periodic"))["cyclic"])
        with self.assertRaisesRegex(bd.DriverError, "given"):
            bd.nurbs_of(dict(c, knot_vector="given", knots=[0, 0, 0, 1, 1, 1]))


class Recorded(unittest.TestCase):
    def setUp(self):
        self.request, self.out = load("request.json"), load("blender_length_driver.json")

    def test_validates(self):
        shipped_results.validate(self.out, self.request)
        self.assertEqual(self.out["driver"], "blender_length")
        self.assertEqual(self.out["versions"], {"Blender": "3.4.1"})
        self.assertEqual({r["setting"] for r in self.out["runs"]}, {"", "resolution=4", "resolution=64"})
        self.assertEqual([s["case"] for s in self.out["skipped"]], ["svg_every_command"])
        periodic = next(c for c in self.request["splines"] if c["case"] == "bspline_periodic_closed")
        for r in self.out["runs"]:
            if r["case"] == "bspline_periodic_closed":  # Follow Path starts at curvebench's start
                self.assertLess(math.dist(r["points"][0], periodic["start"]), 1e-7)
        f32 = [v for r in self.out["runs"] for v in [r["length"]] + [x for p in r["points"] + r["spaced"] for x in p]]
        # Blender computes in float: every recorded value is a float32.
        import struct
        self.assertTrue(all(struct.unpack("f", struct.pack("f", v))[0] == v for v in f32))

    @unittest.skipUnless(TOOL, "needs CURVEBENCH_TOOL (the tool checks the runs)")
    def test_measured_in_blenders_bands(self):
        # Without the spaced points (not asserted here): half the tool's checks.
        out = dict(self.out, runs=[dict(r, spaced=None) for r in self.out["runs"]])
        rows = {(r["setting"], r["case"]): r
                for r in shipped_results.measure(out, self.request, CASES, TOOL, tempfile.mkdtemp())["rows"]}
        # The quarter circle (one cubic close to the circle, parameter close to uniform in angle) as
        # resolution_u chords: each chord short of its arc by theta^2 / 24 with theta = (pi / 2) / r.
        for setting, res in (("", 12), ("resolution=4", 4), ("resolution=64", 64)):
            chord = (math.pi / 2 / res) ** 2 / 24
            self.assertAlmostEqual(rows[(setting, "svg_quarter_circle_cubic")]["length_error"], chord,
                                   delta=0.06 * chord, msg=setting)
        # A polyline's error falls as 1 / r^2: 9x from 4 to 12, 28x from 12 to 64 on the curved cases.
        for case in ("svg_quarter_circle_cubic", "parabola_quadratic_bezier", "composite_bezier_g1",
                     "svg_cubic_extent_1e0"):
            e4, e12, e64 = (rows[(s, case)]["length_error"] for s in ("resolution=4", "", "resolution=64"))
            self.assertTrue(5 < e4 / e12 < 13, (case, e4 / e12))
            self.assertTrue(20 < e12 / e64 < 40, (case, e12 / e64))
            # Follow Path at offset_factor s / L: off by about the length error plus the chords'
            # sagitta (theta^2 / 8 of a chord), within 4x the length error.
            for s in ("resolution=4", "", "resolution=64"):
                self.assertLess(rows[(s, case)]["point_error"], 4 * rows[(s, case)]["length_error"], (case, s))
        # NURBS splines (request["splines"]): Blender samples resolution_u points per control-point
        # interval, uniformly in the parameter, and sums the chords: each chord of a curve with
        # curvature k is short of its arc by k^2 h^3 / 24, a relative error (k h)^2 / 24 that falls as
        # 1 / r^2. Measured: 9x from 4 to 12, about 30x from 12 to 64; at 64 below 5e-5 (k h <= 0.035
        # on these curves; 1.9e-5 the worst, the weighted NURBS). The point at s = L s / L_blender:
        # within 2x the length error plus the float32 floor. A wrong knot vector would be a
        # different curve: errors of order 1e-1.
        for case in ("bspline_cubic_clamped", "bspline_periodic_closed", "bspline_quintic_3d", "nurbs_weighted_3d"):
            e4, e12, e64 = (rows[(s, case)]["length_error"] for s in ("resolution=4", "", "resolution=64"))
            self.assertTrue(5 < e4 / e12 < 13, (case, e4 / e12))
            self.assertTrue(20 < e12 / e64 < 40, (case, e12 / e64))
            self.assertLess(e64, 5e-5, case)
            for s in ("resolution=4", "", "resolution=64"):
                self.assertLess(rows[(s, case)]["point_error"], 2 * rows[(s, case)]["length_error"] + 1e-6, (case, s))
        # Collinear control points: the polyline is the curve, the length exact in float32.
        for s in ("resolution=4", "", "resolution=64"):
            self.assertEqual(rows[(s, "svg_cusp_fonttools")]["length"], 150.0)
            self.assertLess(rows[(s, "svg_near_straight")]["length_error"], 1e-7)


if __name__ == "__main__":
    unittest.main()
