"""scripts/peers/godot_driver.py without Godot: the request's segments become Curve2D points with
relative handles (a quadratic raised exactly, a line with zero handles), the binary exchange with
godot_driver.gd round-trips (runs, non-finite answers skipped with what was non-finite), the CSS
channel cases become bezier-track jobs at the sample fractions, and the recorded outputs of a real
run (Godot 3.2.3, Debian bookworm: tests/data/peers/godot/, README there) validate against their
request and join easing_results. With the tool (CURVEBENCH_TOOL) the recorded Curve2D output is
measured and its errors kept in the bands Godot's bake gives."""
import json
import os
import struct
import sys
import tempfile
import unittest

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.join(HERE, "..", "..")
sys.path.insert(0, os.path.join(ROOT, "scripts"))
sys.path.insert(0, os.path.join(ROOT, "scripts", "peers"))
import easing_results  # noqa: E402
import godot_driver as gd  # noqa: E402
import peer_io  # noqa: E402
import shipped_results  # noqa: E402

DATA = os.path.join(HERE, "..", "data", "peers", "godot")
CASES = os.path.join(ROOT, "bench", "cases")
TOOL = os.environ.get("CURVEBENCH_TOOL")


def load(name):
    with open(os.path.join(DATA, name), encoding="utf-8") as f:
        return json.load(f)


def is_float32(x):
    return struct.unpack("f", struct.pack("f", x))[0] == x


def seg(kind, pts):
    return {"kind": kind, "points": pts}


class Conversion(unittest.TestCase):
    def test_curve_points(self):
        sub = {"closed": False, "segments": [seg("quadratic", [[0, 0], [3, 6], [6, 0]]),
                                             seg("line", [[6, 0], [9, 0]]),
                                             seg("cubic", [[9, 0], [10, 1], [11, 1], [12, 0]])]}
        # The quadratic raised: handles (2, 4) and (4, 4), i.e. out (2, 4) from (0, 0) and in (-2, 4)
        # from (6, 0); the line has zero handles at both ends; the cubic's handles relative to its ends.
        self.assertEqual(gd.curve_points(sub), [((0.0, 0.0), (0.0, 0.0), (2.0, 4.0)),
                                                ((6.0, 0.0), (-2.0, 4.0), (0.0, 0.0)),
                                                ((9.0, 0.0), (0.0, 0.0), (1.0, 1.0)),
                                                ((12.0, 0.0), (-1.0, 1.0), (0.0, 0.0))])

    def test_jobs_and_skips(self):
        jobs, skipped = gd.curve_jobs(load("request.json")["cases"])
        self.assertEqual([s["case"] for s in skipped], ["svg_every_command"])
        two = {"case": "two", "segments": [{"closed": False, "segments": [seg("line", [[0, 0], [1, 0]])]}] * 2,
               "s": [0], "spaced": 2}
        _, skipped = gd.curve_jobs([two])
        self.assertIn("2 subpaths", skipped[0]["reason"])
        self.assertEqual(len(jobs), 6)

    def test_binary_round_trip(self):
        jobs = [("c", [((0.0, 0.0), (0.0, 0.0), (1.0, 0.0)), ((3.0, 0.0), (-1.0, 0.0), (0.0, 0.0))], [0.0, 3.5], 2)]
        data = gd.curve_input(jobs)
        r = gd.Reader(data)
        self.assertEqual((r.u32(), r.u32(), r.f64(1), r.u32(), r.u32()), (gd.MAGIC, 1, [2000.0], 5, 1))
        self.assertEqual((r.u32(), r.f64(6)), (2, [0.0, 0.0, 0.0, 0.0, 1.0, 0.0]))
        # Godot's answer: per interval the length, 2 points, 2 spaced, 3 times.
        w = gd.Writer()
        w.u32(gd.MAGIC)
        w.u32(4)
        w.parts.append(b"3.2x")
        for i, _ in enumerate(gd.INTERVALS):
            nan = float("nan") if i == 1 else 3.0
            w.f64(3.0, 0.0, 0.0, 3.0, 0.0, 0.0, 0.0, nan, 0.0, 500.0, 80.0, 110.0)
        version, runs, skipped = gd.curve_runs(w.data(), jobs)
        self.assertEqual(version, "3.2x")
        self.assertEqual([r["setting"] for r in runs], ["", "bake_interval=0.1"])
        self.assertEqual(runs[0]["points"], [[0.0, 0.0], [3.0, 0.0]])
        self.assertEqual((runs[0]["ns_build"], runs[0]["ns_length"], runs[0]["ns_point"]), (500.0, 80.0, 110.0))
        self.assertIn("1 s beyond Godot's own length", runs[0]["note"])
        self.assertEqual(skipped[0]["setting"], "bake_interval=1")
        self.assertIn("at 0 of 2 s and 1 of 2 spaced points; the baked length 3.0 is a whole multiple",
                      skipped[0]["reason"])
        with self.assertRaisesRegex(gd.DriverError, "bytes more"):
            gd.curve_runs(w.data() + b"x", jobs)

    def test_easing_jobs(self):
        self.assertEqual(gd.cubic_bezier("cubic-bezier(0.3, 1.5, 0.7, -0.5)"), [0.3, 1.5, 0.7, -0.5])
        self.assertIsNone(gd.cubic_bezier("ease-in"))
        cases, _ = gd.easing_cases(CASES)
        self.assertIn(("css_wild_overshoot", [0.0, 4.0, 1.0, -3.0]), cases)
        times = peer_io.sample_fractions(5)
        data = gd.easing_input(cases[:1], times, quick=True)
        r = gd.Reader(data)
        self.assertEqual((r.u32(), r.u32(), r.f64(1), r.u32(), r.u32()), (gd.MAGIC, 2, [200.0], 3, 1))
        self.assertEqual(r.f64(4), cases[0][1])
        self.assertEqual((r.u32(), r.f64(5)), (5, times))  # the same doubles Python computed


class Recorded(unittest.TestCase):
    def test_curves_validate(self):
        request, out = load("request.json"), load("godot_driver.json")
        shipped_results.validate(request=request, driver=out)
        self.assertEqual(out["driver"], "godot")
        self.assertTrue(out["versions"]["Godot"].startswith("3.2.3"))
        # Godot 3's Vector2 and baked arrays are float32: every length and point is one.
        for r in out["runs"]:
            values = [r["length"]] + [x for p in r["points"] + r["spaced"] for x in p]
            self.assertTrue(all(is_float32(v) for v in values), r["case"])
            self.assertGreater(r["ns_build"], 0)
        # A curve never farther than bake_interval from its start bakes no inner point: its length is
        # its chord (the 1-wide test cubic at the default 5, 1 from (0, 0) to (1, 0)); at interval 1 that
        # length 1.0 is a whole multiple of the interval and interpolate_baked returns inf/NaN.
        runs = {(r["setting"], r["case"]): r for r in out["runs"]}
        self.assertEqual(runs[("", "svg_cubic_extent_1e0")]["length"], 1.0)
        self.assertEqual([(s["case"], s.get("setting")) for s in out["skipped"]],
                         [("svg_every_command", None), ("svg_cubic_extent_1e0", "bake_interval=1")])

    def test_easing_joins(self):
        doc = load("godot_easing.json")
        self.assertEqual((doc["driver"], doc["quick"]), ("godot_easing", True))
        specs = {}
        for run in doc["runs"]:
            self.assertEqual(run["times"], peer_io.sample_fractions(65))
            self.assertTrue(all(is_float32(v) for v in run["values"]))  # Godot evaluates in float32
            with open(os.path.join(CASES, run["case"] + ".json"), encoding="utf-8") as f:
                specs[run["case"]] = json.load(f)
        result = easing_results.assemble(doc, specs, lambda case, times: None)
        self.assertEqual(len(result["peer_records"]), 4)
        for rec in result["peer_records"]:
            p = next(r["easing"] for r in doc["runs"] if r["case"] == rec["case"])
            # 10 bisections on t leave a bracket 2^-10 wide; a linear interpolation inside it is off
            # by at most the bracket's rise, max |y'(u)| / 1024 with |y'| <= 3 max(|y1|, |y2 - y1|, |1 - y2|).
            bound = 3 * max(abs(p[1]), abs(p[3] - p[1]), abs(1 - p[3])) / 1024
            self.assertLess(rec["abs_error"], bound, rec["case"])
            self.assertGreater(rec["ns_per_op"], 0)

    @unittest.skipUnless(TOOL, "needs CURVEBENCH_TOOL (the tool checks the runs)")
    def test_measured_in_godots_bands(self):
        request, out = load("request.json"), load("godot_driver.json")
        out = dict(out, runs=[dict(r, spaced=None) for r in out["runs"] if r["case"] == "svg_quarter_circle_cubic"])
        rows = {r["setting"]: r for r in shipped_results.measure(out, request, CASES, TOOL, tempfile.mkdtemp())["rows"]}
        # Godot 3.2 bakes a point where the distance from the last one passes the interval h, found by
        # 10 bisections inside a t-step of 0.1, so each point is placed to within L x 0.1 / 2^10 of
        # arc (L = 157 on the quarter circle), and counts h per point: the length is off by at most
        # that over h, relative, plus the chords' shortfall (h / R)^2 / 24 (R = 100).
        for setting, h in (("", 5.0), ("bake_interval=1", 1.0), ("bake_interval=0.1", 0.1)):
            bound = 157.1 * 0.1 / 1024 / h + (h / 100) ** 2 / 24
            self.assertLess(rows[setting]["length_error"], bound, setting)
        # Hence a finer interval is worse here: 0.1 is 2.4 % off where the default 5 is 3.6e-4.
        self.assertGreater(rows["bake_interval=0.1"]["length_error"], 10 * rows[""]["length_error"])


if __name__ == "__main__":
    unittest.main()
