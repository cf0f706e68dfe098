"""The OpenCASCADE peer driver (bench/peers/occt/occt_driver.cpp) on its recorded output
(tests/data/peers/occt/, README there: source, version, command), so that the output's parsing and
joining is tested in CI where OCCT is not installed: validated against its request with
shipped_results.validate, checked against hand-worked values, and, with CURVEBENCH_TOOL set (ctest
shipped), measured by shipped_results.measure with errors asserted in bands that follow from what
OCCT's GCPnts computes (the driver's header comment)."""
import json
import math
import os
import sys
import tempfile
import unittest

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.join(HERE, "..", "..")
sys.path.insert(0, os.path.join(ROOT, "scripts", "peers"))
import shipped_results  # noqa: E402

DATA = os.path.join(ROOT, "tests", "data", "peers", "occt")
CASES = os.path.join(ROOT, "bench", "cases")
TOOL = os.environ.get("CURVEBENCH_TOOL")
SETTINGS = {"": None, "tolerance=1e-06": 1e-6, "tolerance=1e-10": 1e-10}
# On paths with a quadratic segment, the same calls with each quadratic as a Geom2d_Parabola's arc.
PARABOLA = {"parabola": None, "parabola, tolerance=1e-06": 1e-6, "parabola, tolerance=1e-10": 1e-10}
TOLERANCE = {**SETTINGS, **PARABOLA}


def load():
    with open(os.path.join(DATA, "occt_driver.json"), encoding="utf-8") as f:
        driver = json.load(f)
    with open(os.path.join(DATA, "request.json"), encoding="utf-8") as f:
        request = json.load(f)
    return driver, request


class Recorded(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.driver, cls.request = load()

    def run_of(self, case, setting):
        return next(r for r in self.driver["runs"] if r["case"] == case and r["setting"] == setting)

    def test_the_output_validates_against_its_request(self):
        shipped_results.validate(self.driver, self.request)
        self.assertEqual(self.driver["driver"], "occt")
        self.assertEqual(self.driver["versions"]["opencascade"], "7.6.3")

    def test_every_case_and_setting_is_a_run_or_a_skip(self):
        done = {(r["case"], r["setting"]) for r in self.driver["runs"]}
        skipped = {s["case"] for s in self.driver["skipped"]}
        for c in self.request["cases"]:
            for setting in SETTINGS:
                self.assertTrue((c["case"], setting) in done or c["case"] in skipped, (c["case"], setting))
        for r in self.driver["runs"]:
            self.assertTrue(r["peer"].startswith("peer_occt_"))
            self.assertEqual(len(r["spaced"]), self.request["cases"][0]["spaced"])
            for k in ("ns_length", "ns_point", "ns_build"):
                self.assertGreater(r[k], 0)

    def test_the_quarter_circle_is_the_closed_form(self):
        # M100 0 A100 100 0 0 1 0 100: a Geom2d_Circle of radius 100 about the origin from angle 0 to
        # pi/2 (y down is just the sign of the coordinates), whose point at arc length s is
        # 100 (cos(s/100), sin(s/100)) and whose length is 50 pi: OCCT's circle is analytic, so to
        # rounding (a few ulps of 100).
        case = next(c for c in self.request["cases"] if c["case"] == "svg_quarter_circle_arc")
        for setting in SETTINGS:
            run = self.run_of("svg_quarter_circle_arc", setting)
            self.assertAlmostEqual(run["length"], 50 * math.pi, delta=1e-12)
            for s, (x, y) in zip(case["s"], run["points"]):
                s = min(s, run["length"])
                self.assertAlmostEqual(x, 100 * math.cos(s / 100), delta=1e-11)
                self.assertAlmostEqual(y, 100 * math.sin(s / 100), delta=1e-11)

    def test_a_multi_segment_path_ends_at_its_last_point(self):
        # svg_every_command ends with V-3 Z back at the origin: the point at the path's own length.
        run = self.run_of("svg_every_command", "tolerance=1e-10")
        self.assertAlmostEqual(run["spaced"][-1][0], 0.0, delta=1e-9)
        self.assertAlmostEqual(run["spaced"][-1][1], 0.0, delta=1e-9)
        self.assertIn("point at k L/(n-1)", run["note"])

    def test_every_spline_is_a_run_with_its_dimension(self):
        # request["splines"]: curvebench's bspline and nurbs cases as Geom_BSplineCurve, no skip (each
        # starts and ends at curvebench's start and end: the driver's check of the knot vector).
        self.assertEqual(len(self.request["splines"]), 4)
        self.assertFalse({s["case"] for s in self.driver["skipped"]} & {c["case"] for c in self.request["splines"]})
        for c in self.request["splines"]:
            for setting in SETTINGS:
                run = self.run_of(c["case"], setting)
                self.assertIn("Geom_BSplineCurve", run["note"])
                for p in run["points"] + run["spaced"]:
                    self.assertEqual(len(p), c["dim"], c["case"])
                for got, want in zip(run["points"][0], c["start"]):
                    self.assertAlmostEqual(got, want, delta=1e-12)

    def test_the_periodic_spline_starts_at_curvebench_start(self):
        # OCCT's periodic curve is measured from the knot whose point is the request's start:
        # for this cubic control loop (P0 + 4 P1 + P2) / 6 = (0.6333..., 0.6333...), where s = 0 and
        # s = L (its first and last spaced points) are.
        c = next(c for c in self.request["splines"] if c["case"] == "bspline_periodic_closed")
        self.assertEqual(c["knot_vector"], "periodic")
        want = [(1.0 + 4 * 0.7 + 0.0) / 6, (0.0 + 4 * 0.7 + 1.0) / 6]
        for setting in SETTINGS:
            run = self.run_of(c["case"], setting)
            for p in (run["points"][0], run["spaced"][0], run["spaced"][-1]):
                self.assertAlmostEqual(p[0], want[0], delta=1e-12)
                self.assertAlmostEqual(p[1], want[1], delta=1e-12)


@unittest.skipUnless(TOOL, "needs CURVEBENCH_TOOL (ctest shipped sets it)")
class Measured(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        driver, request = load()
        cls.result = shipped_results.measure(driver, request, CASES, TOOL, tempfile.mkdtemp())
        cls.rows = {(r["case"], r["setting"]): r for r in cls.result["rows"]}

    def test_with_a_tolerance_the_length_is_within_it(self):
        # Length(adaptor, tol) repeats the Gauss integration until it agrees to tol: measured relative
        # errors stay below tol on every recorded case (4.9e-13 the worst at 1e-10, on the 1e-3 cubic).
        for (case, setting), row in self.rows.items():
            tol = TOLERANCE[setting]
            if tol is not None:
                self.assertLessEqual(row["length_error"], tol, (case, setting))

    def test_with_a_tolerance_the_point_is_within_it_except_at_a_cusp(self):
        # AbscissaPoint with tol: a Newton-type solve of Integral(U0, u)|C'| = s to tol; at the cusp of
        # svg_cusp_fonttools |C'| = 0 slows it (2e-10 of L measured at 1e-10): a band of 1e-8 there.
        for (case, setting), row in self.rows.items():
            tol = TOLERANCE[setting]
            if tol is not None:
                band = max(tol, 1e-8) if case == "svg_cusp_fonttools" else tol
                self.assertLessEqual(row["point_error"], band, (case, setting))

    def test_a_quadratic_as_a_parabola_is_the_same_curve(self):
        # parabola_of turns the quadratic Bezier into the arc of OCCT's analytic Geom2d_Parabola (vertex,
        # axis along A - 2B + C, focal length |w|^2 / (4 |D|)): a wrong vertex, axis or range would show
        # as an error of the order of the curve; measured 1.4e-16 on the wide parabola (OCCT measures
        # a parabola's arc in closed form-like precision), so 1e-12 with margin at every setting.
        for setting in PARABOLA:
            for case in ("svg_wide_parabola", "svg_every_command"):
                row = self.rows[(case, setting)]
                bound = 1e-12 if case == "svg_wide_parabola" or TOLERANCE[setting] else 1e-4
                self.assertLess(row["length_error"], bound, (case, setting))
                self.assertLess(row["off_curve"], 1e-12, (case, setting))
        # Only paths with a quadratic get these settings.
        self.assertNotIn(("svg_quarter_circle_arc", "parabola"), self.rows)

    def test_the_default_is_one_fixed_gauss_rule(self):
        # Without a tolerance: one fixed-order Gauss rule, no error control. Circles are analytic
        # (0); the smooth cubics 4.1e-4 of L (the same at every offset: a relative, scale-free error);
        # the cusp about 2 % (|C'| has a kink there a polynomial rule cannot follow).
        self.assertLess(self.rows[("svg_quarter_circle_arc", "")]["length_error"], 1e-14)
        for case in ("svg_cubic_extent_1e-3", "svg_cubic_offset_1e6"):
            self.assertLess(self.rows[(case, "")]["length_error"], 1e-3)
            self.assertGreater(self.rows[(case, "")]["length_error"], 1e-5)
        self.assertGreater(self.rows[("svg_cusp_fonttools", "")]["length_error"], 1e-2)
        self.assertLess(self.rows[("svg_cusp_fonttools", "")]["length_error"], 5e-2)

    def test_splines_at_tolerance_1e10_are_within_it(self):
        # Length(adaptor, tol) on a Geom_BSplineCurve integrates |C'| span by span (one Gauss rule per
        # C^N interval, between knots) and repeats until successive results agree to tol: the smooth
        # polynomial and rational spans converge fast, 1.8e-11 measured the worst (the quintic). A band
        # of the tolerance itself, 1e-10 (relative), is OCCT's own claim; a wrong knot vector (another
        # curve) shows as an error of order 1 instead. The point: the same Newton solve to tol.
        for c in ("bspline_cubic_clamped", "bspline_periodic_closed", "bspline_quintic_3d", "nurbs_weighted_3d"):
            row = self.rows[(c, "tolerance=1e-10")]
            self.assertLess(row["length_error"], 1e-10, c)
            self.assertLess(row["point_error"], 1e-10, c)


if __name__ == "__main__":
    unittest.main()
