"""The arc-length peers' pipeline with the tool itself (CURVEBENCH_TOOL; ctest shipped):
scripts/peers/shipped_request.py's request, shipped_results.py's measurement through `curvebench
check --at-length`, and scripts/report_shipped.py's section.

The measurement is checked against closed forms, independently of curvebench's reference: on the
quarter circle of radius 100 (svg_quarter_circle_arc) the point at arc length s is
100 (cos(s / 100), sin(s / 100)), so a driver answering with it must be measured at rounding level
(tolerances: 1e-14 of L, a few ulps of the double points and of the 50-digit s(u) rounded), and one
answering with the point at s + delta must show an s error of delta / L and a point error of the
chord 2 * 100 * sin(delta / 200) / L. The recorded outputs of the real drivers
(tests/data/peers/shipped/) are measured too, so their parsing and joining is tested in CI where no
browser or npm package is installed."""
import json
import math
import os
import subprocess
import sys
import tempfile
import unittest

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.join(HERE, "..", "..")
sys.path.insert(0, os.path.join(ROOT, "scripts", "peers"))
sys.path.insert(0, os.path.join(ROOT, "scripts"))
import report_shipped  # noqa: E402
import shipped_results  # noqa: E402

CASES = os.path.join(ROOT, "bench", "cases")
RECORDED = os.path.join(ROOT, "tests", "data", "peers", "shipped")
TOOL = os.environ.get("CURVEBENCH_TOOL")
R = 100.0
L = math.pi * R / 2


def circle_point(s):
    return [R * math.cos(s / R), R * math.sin(s / R)]


class Pure(unittest.TestCase):
    def test_spacing_cv_is_zero_for_equal_gaps_and_the_population_cv_otherwise(self):
        self.assertEqual(shipped_results.spacing_cv([0.0, 1.0, 2.0, 3.0]), 0.0)
        # gaps 1 and 3: mean 2, population standard deviation 1.
        self.assertAlmostEqual(shipped_results.spacing_cv([0.0, 1.0, 4.0]), 0.5, places=15)
        self.assertIsNone(shipped_results.spacing_cv([0.0, 1.0]))

    def test_a_run_with_the_wrong_number_of_points_or_a_nan_is_refused_naming_it(self):
        request = {"format": shipped_results.REQUEST_FORMAT, "cases": [{"case": "c", "s": [0, 1]}]}
        driver = {"format": shipped_results.DRIVER_FORMAT,
                  "runs": [{"peer": "peer_x", "case": "c", "points": [[0, 0]]}]}
        with self.assertRaisesRegex(shipped_results.ShippedError, r"runs\[0\] \(peer_x, c\): 1 points"):
            shipped_results.validate(driver, request)
        driver["runs"][0]["points"] = [[0, 0], [float("nan"), 1]]
        with self.assertRaisesRegex(shipped_results.ShippedError, r"points\[1\]"):
            shipped_results.validate(driver, request)
        driver["runs"][0] = {"peer": "peer_x", "case": "other"}
        with self.assertRaisesRegex(shipped_results.ShippedError, "not in the request"):
            shipped_results.validate(driver, request)

    def test_runs_of_one_peer_setting_and_case_get_distinct_files(self):
        case = {"case": "c", "s": [0.0, 1.0]}
        runs = [{"peer": "p", "setting": "a/b", "case": "c", "points": [[0.0, 0.0], [1.0, 0.0]]},
                {"peer": "p", "setting": "a_b", "case": "c", "points": [[0.0, 0.0], [2.0, 0.0]]},
                {"peer": "p", "setting": "a_b", "case": "c", "points": [[0.0, 0.0], [3.0, 0.0]]}]
        with tempfile.TemporaryDirectory() as work:
            paths = [shipped_results.write_csvs(r, case, work, i)["points"] for i, r in enumerate(runs)]
            self.assertEqual(len(set(paths)), 3, paths)
            for path, want in zip(paths, ("1.0", "2.0", "3.0")):
                with open(path) as f:
                    self.assertEqual(f.read().splitlines()[-1], f"1.0,{want},0.0")

    def test_a_link_in_the_work_folder_is_refused_and_its_target_kept(self):
        case = {"case": "c", "s": [0.0]}
        run = {"peer": "p", "case": "c", "points": [[0.0, 0.0]]}
        with tempfile.TemporaryDirectory() as work:
            target = os.path.join(work, "precious")
            with open(target, "w") as f:
                f.write("keep")
            os.symlink(target, os.path.join(work, shipped_results.file_stem(run, 0) + ".points.csv"))
            with self.assertRaisesRegex(shipped_results.ShippedError, "--work: .*a symbolic link"):
                shipped_results.write_csvs(run, case, work, 0)
            with open(target) as f:
                self.assertEqual(f.read(), "keep")

    def test_a_driver_output_that_is_not_an_object_is_one_clear_error(self):
        request = {"format": shipped_results.REQUEST_FORMAT, "cases": [{"case": "c", "s": [0, 1]}]}
        for driver, message in (([], "driver output: expected a JSON object, got list"),
                                ({"format": shipped_results.DRIVER_FORMAT, "runs": {}}, "runs: expected a list"),
                                ({"format": shipped_results.DRIVER_FORMAT, "runs": [3]},
                                 r"runs\[0\]: expected an object")):
            with self.assertRaisesRegex(shipped_results.ShippedError, message):
                shipped_results.validate(driver, request)
        with self.assertRaisesRegex(shipped_results.ShippedError, "request: expected a JSON object"):
            shipped_results.validate({"format": shipped_results.DRIVER_FORMAT}, [request])

    def test_a_nan_tolerance_or_timing_is_refused_naming_it(self):
        request = {"format": shipped_results.REQUEST_FORMAT, "cases": [{"case": "c", "s": [0, 1]}]}
        base = {"peer": "p", "case": "c", "length": 1.0}
        for field, value in (("documented_length_tolerance", math.nan), ("documented_length_tolerance", -1.0),
                             ("ns_length", math.nan), ("ns_point", math.inf), ("ns_build", -3.0)):
            driver = {"format": shipped_results.DRIVER_FORMAT, "runs": [dict(base, **{field: value})]}
            with self.assertRaisesRegex(shipped_results.ShippedError, rf"runs\[0\] \(p, c\): {field} "):
                shipped_results.validate(driver, request)

    def test_three_s_parameter_maps_to_the_segment_s_knots(self):
        import shipped_request
        knots = [0.0, 2.0, 3.0, 7.0]  # three segments of lengths 2, 1, 4 in curvebench's parameter
        # three: segment floor(3 t) at weight 3 t - floor(3 t); t = 1 is the last segment at weight 1.
        self.assertEqual(shipped_request.three_parameter(0.0, knots, False), 0.0)
        self.assertEqual(shipped_request.three_parameter(0.5, knots, False), 2.5)  # segment 1, w = 1/2
        self.assertEqual(shipped_request.three_parameter(1.0, knots, False), 7.0)
        self.assertAlmostEqual(shipped_request.three_parameter(5 / 6, knots, False), 5.0, delta=1e-15)
        # Knots: 0, then + |P_i+1 - P_i|^alpha; a closed loop adds the way back.
        pts = [[0, 0], [3, 4], [3, 0]]
        self.assertEqual(shipped_request.knots_of(pts, 0.5, False), [0.0, 5 ** 0.5, 5 ** 0.5 + 2])
        self.assertEqual(shipped_request.knots_of(pts, 1, True), [0.0, 5.0, 9.0, 12.0])
        self.assertEqual(shipped_request.knots_of(pts, 0, False), [0.0, 1.0, 2.0])

    def test_the_setting_reaching_a_target_is_the_cheapest_on_every_case_the_defaults_measured(self):
        def row(setting, case, err, ns, peer="peer_p"):
            return {"peer": peer, "setting": setting, "case": case, "length_error": err, "ns_length": ns}
        rows = [row("", "a", 1e-3, 10), row("", "b", 1e-4, 10),
                row("tol=1", "a", 1e-7, 50), row("tol=1", "b", 1e-8, 70),      # 1e-6 at median 60 ns
                row("tol=2", "a", 1e-11, 900), row("tol=2", "b", 1e-12, 900),  # 1e-10 and 1e-6 at 900 ns
                row("tol=3", "a", 1e-12, 5),                                   # cheap, but skips case b
                row("centripetal", "c", 1e-2, 3, "peer_q"), row("centripetal, divisions=9", "c", 1e-7, 4, "peer_q")]
        got = {r[0]: r for r in report_shipped.accurate_settings(rows)}
        self.assertEqual(got["p"], ["p", 2, "0.001", "tol=1 (60 ns)", "tol=2 (900 ns)"])
        # A mode (a setting part without '=') belongs to the peer's name; its default is the mode alone.
        self.assertEqual(got["q (centripetal)"],
                         ["q (centripetal)", 1, "0.01", "divisions=9 (4 ns)", "no measured setting"])

    def test_a_length_outside_its_documented_tolerance_is_a_finding(self):
        rows = [{"peer": "peer_2geom", "setting": "tolerance=1e-08", "case": "c", "length": 1.0 + 3e-8,
                 "true_length": 1.0, "documented_tolerance": 1e-8, "outside_tolerance": True},
                {"peer": "peer_2geom", "setting": "tolerance=1e-08", "case": "d", "length": 2.0,
                 "true_length": 2.0, "documented_tolerance": 1e-8, "outside_tolerance": False}]
        # shipped_results' row: the bound the run carries, and whether |L_peer - L| exceeds it.
        run = {"peer": "peer_2geom", "case": "c", "setting": "tolerance=1e-08", "length": 1.0 + 3e-8,
               "documented_length_tolerance": 1e-8}
        r = shipped_results.row_of(run, {}, 1.0)
        self.assertEqual((r["documented_tolerance"], r["outside_tolerance"]), (1e-8, True))
        self.assertFalse(shipped_results.row_of(dict(run, length=1.0 + 5e-9), {}, 1.0)["outside_tolerance"])
        md = report_shipped.tolerance_findings(rows)
        self.assertEqual(len(md), 1)
        self.assertIn("2geom (tolerance=1e-08)** is outside its documented length tolerance on 1 case(s): on c", md[0])
        self.assertIn("bounds the error by 1.00e-08", md[0])

    def test_a_browser_that_did_not_run_is_listed_as_not_run(self):
        # The browser driver writes a null version for a browser it could not start; the versions
        # row read "firefox None", and the Peers section's versions table likewise.
        d = tempfile.mkdtemp()
        self.addCleanup(__import__("shutil").rmtree, d)
        row = {"peer": "peer_chromium", "case": "c", "setting": "", "length": 1.0, "true_length": 1.0,
               "length_error": 0.0}
        doc = {"driver": "shipped_browser", "versions": {"chromium": "Chromium 156", "firefox": None}, "cpu": "x",
               "peer_records": [], "rows": [row]}
        with open(os.path.join(d, "peers_shipped_browser.json"), "w", encoding="utf-8") as f:
            json.dump(doc, f)
        md = "\n".join(report_shipped.section({}, d))
        self.assertIn("| chromium Chromium 156, firefox not run |", md)
        self.assertNotIn("None", md)
        import report_peers
        rows = report_peers.version_rows({"context": {"peers": {"GSL": None}}}, report_peers.load_peer_files(d))
        self.assertEqual([r[0] for r in rows], ["GSL not run", "chromium Chromium 156, firefox not run"])

    def test_the_section_says_not_run_without_results(self):
        md = report_shipped.section({}, tempfile.mkdtemp())
        self.assertIn("## Arc length in shipped software", md)
        self.assertTrue(any(line.startswith("Not run") for line in md))


@unittest.skipUnless(TOOL, "needs CURVEBENCH_TOOL (ctest shipped sets it)")
class WithTool(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.work = tempfile.mkdtemp()
        cls.request_path = os.path.join(cls.work, "request.json")
        only = "svg_quarter_circle_arc,svg_cusp_fonttools,svg_thin_ellipse,svg_every_command,arch_cubic_bezier"
        subprocess.run([sys.executable, os.path.join(ROOT, "scripts", "peers", "shipped_request.py"), "--cases", CASES,
                        "--tool", TOOL, "--out", cls.request_path, "--only", only],
                       check=True, capture_output=True, timeout=300)
        with open(cls.request_path, encoding="utf-8") as f:
            cls.request = json.load(f)

    def case(self, name):
        return next(c for c in self.request["cases"] if c["case"] == name)

    def test_the_request_holds_curvebench_s_path_data_and_lengths(self):
        names = [c["case"] for c in self.request["cases"]]
        self.assertEqual(sorted(names), sorted(["svg_quarter_circle_arc", "svg_cusp_fonttools", "svg_thin_ellipse",
                                                "svg_every_command", "arch_cubic_bezier"]))
        q = self.case("svg_quarter_circle_arc")
        self.assertLess(abs(q["length"] - L) / L, 1e-14)  # adaptive_gk at tol 1e-14
        self.assertEqual(len(q["s"]), 17)
        # The grid ends at the length's lower bound (value - estimate): at most L, and close to it.
        self.assertLessEqual(q["s"][-1], L)
        self.assertGreater(q["s"][-1], L * (1 - 1e-11))  # adaptive_gk's estimate is conservative
        e = self.case("svg_thin_ellipse")  # a shape: its path as curvebench wrote it, its attributes for browsers
        self.assertTrue(e["d"].startswith("M10 0 A10 1 0 0 1 0 1"), e["d"])
        self.assertEqual(e["shape"], {"element": "ellipse", "attributes": {"cx": 0, "cy": 0, "rx": 10, "ry": 1}})
        self.assertEqual(self.case("svg_cusp_fonttools")["bezier"], [[0, 0], [50, 0], [100, 0], [-50, 0]])
        self.assertEqual(self.case("svg_cusp_fonttools")["d"], "M0 0 C50 0 100 0 -50 0")

    def measure(self, runs):
        driver = {"format": shipped_results.DRIVER_FORMAT, "driver": "test", "runs": runs}
        return shipped_results.measure(driver, self.request, CASES, TOOL, tempfile.mkdtemp())["rows"]

    def test_exact_answers_are_measured_at_rounding_level(self):
        q = self.case("svg_quarter_circle_arc")
        spaced = [circle_point(L * k / 16) for k in range(17)]
        row = self.measure([{"peer": "peer_exact", "case": q["case"], "length": L,
                             "points": [circle_point(s) for s in q["s"]], "spaced": spaced}])[0]
        self.assertLess(row["length_error"], 1e-15)
        self.assertLess(row["point_error"], 1e-14)
        self.assertLess(row["s_error"], 1e-14)
        self.assertLess(row["off_curve"], 1e-14)
        self.assertLess(row["spacing_cv"], 1e-13)

    def test_a_point_late_along_the_curve_shows_its_delay_as_s_error_and_its_chord_as_point_error(self):
        q = self.case("svg_quarter_circle_arc")
        delta = 1e-3 * L
        s_inner = [min(s, L - delta) for s in q["s"]]  # stays on the arc
        row = self.measure([{"peer": "peer_late", "case": q["case"], "length": L * (1 + 1e-6),
                             "points": [circle_point(s + delta) for s in s_inner], "spaced": None}])[0]
        self.assertAlmostEqual(row["length_error"], 1e-6, delta=1e-15)
        self.assertAlmostEqual(row["s_error"], 1e-3, delta=1e-12)
        self.assertAlmostEqual(row["point_error"], 2 * R * math.sin(delta / (2 * R)) / L, delta=1e-12)
        self.assertLess(row["off_curve"], 1e-14)  # on the curve, only in the wrong place

    def test_the_cusp_point_takes_the_branch_nearest_its_s(self):
        # fontTools' cusp turns back at x = 50 (s = 50); x = 40 is on both branches, at s = 40 and 60.
        c = self.case("svg_cusp_fonttools")
        pts = [[40.0, 0.0] for _ in c["s"]]
        row = self.measure([{"peer": "peer_x", "case": c["case"], "length": 150.0, "points": pts, "spaced": None}])[0]
        self.assertAlmostEqual(row["length_error"], 0.0, delta=1e-15)  # 150 is the closed form
        self.assertLess(row["off_curve"], 1e-15)
        # Each row is charged the branch nearer its s: the worst is the last s (150 less the length's
        # error bound) against s = 60, about 90 / 150 (the first branch, s = 40, would make it 110 / 150).
        self.assertAlmostEqual(row["s_error"], (c["s"][-1] - 60) / 150, delta=1e-14)

    def test_recorded_driver_outputs_are_measured_and_reported(self):
        files = sorted(f for f in os.listdir(RECORDED) if f.endswith("_driver.json"))
        self.assertTrue(files, "the recorded driver outputs are missing")
        reports = tempfile.mkdtemp()
        with open(os.path.join(RECORDED, "request.json"), encoding="utf-8") as f:
            request = json.load(f)
        for name in files:
            with open(os.path.join(RECORDED, name), encoding="utf-8") as f:
                driver = json.load(f)
            result = shipped_results.measure(driver, request, CASES, TOOL, tempfile.mkdtemp())
            self.assertTrue(result["rows"], name)
            asked = {c["case"]: c["length"] for c in request["cases"]}
            for row in result["rows"]:
                if row.get("length") is None:
                    continue
                # The truth joined is the case's (the request's adaptive_gk length agrees to 1e-14), and
                # the error is the peer's own length against it (engines can be far off: Firefox ESR
                # measured fontTools' cusp as 50 for 150).
                self.assertLess(abs(row["true_length"] - asked[row["case"]]) / asked[row["case"]], 1e-14, row)
                self.assertEqual(row["length_error"], abs(row["length"] - row["true_length"]) / row["true_length"])
            with open(os.path.join(reports, "peers_" + driver["driver"] + ".json"), "w", encoding="utf-8") as f:
                json.dump(result, f)
        md = "\n".join(report_shipped.section({}, reports))
        self.assertIn("### Every peer, worst case first", md)
        self.assertIn("### Findings", md)

    def test_three_s_catmull_rom_is_measured_against_curvebench_s_spline(self):
        """Recorded: three 0.187.0's CatmullRomCurve3 (shipped_node_driver.mjs --quick, Node 20.20.2) on
        tests/data/peers/shipped/catmull_rom_request.json (shipped_request.py --only four catmull_rom
        cases and svg_quarter_circle_arc)."""
        with open(os.path.join(RECORDED, "catmull_rom_request.json"), encoding="utf-8") as f:
            request = json.load(f)
        with open(os.path.join(RECORDED, "catmull_rom_three.json"), encoding="utf-8") as f:
            driver = json.load(f)
        self.assertEqual({c["case"]: (c["curve_type"], c["dim"]) for c in request["catmull_rom"]},
                         {"catmull_rom_centripetal_2d": ("centripetal", 2), "catmull_rom_uniform_2d": ("catmullrom", 2),
                          "helix_catmull_rom_3d": ("centripetal", 3), "road_catmull_rom_100": ("centripetal", 2)})
        rows = {(r["case"], r["setting"]): r
                for r in shipped_results.measure(driver, request, CASES, TOOL, tempfile.mkdtemp())["rows"]}
        for (case, setting), r in rows.items():
            # The same curve: three's getPoint (phantom ends 2 P_0 - P_1, nonuniform Catmull-Rom tangents)
            # against the 50-digit point of curvebench's spline, within curvebench's own double
            # evaluation or the parameter's rounding, plus 4 ulps (a Hermite form's few roundings).
            self.assertLessEqual(r["eval_error"], max(r["eval_floor"], r["curvebench_eval_error"]) + 4, r)
            self.assertLess(r["curvebench_eval_error"], 4, r)
            # A polyline inscribed in the curve is shorter than it (up to its sum's rounding).
            self.assertLess(r["length"], r["true_length"] * (1 + 1e-15), r)
            # getPointAt(u) = getPoint(getUtoTmapping(u)): the point's s error is its table's.
            self.assertAlmostEqual(r["s_error"], r["map_s_error"], delta=1e-9 + 0.02 * r["map_s_error"], msg=str(r))
        self.assertEqual(rows[("catmull_rom_uniform_2d", "catmullrom")]["eval_floor"], 0.0)  # u = (n - 1) t exactly
        for case in ("catmull_rom_centripetal_2d", "catmull_rom_uniform_2d", "helix_catmull_rom_3d"):
            kind = [k for c, k in rows if c == case and "divisions" not in k][0]
            coarse, fine = rows[(case, kind)], rows[(case, kind + ", divisions=1000")]
            # Chords of a smooth curve miss its length by O(h^2): 200 -> 1000 divisions divides the
            # error by about 25 (measured 24.9 to 25.1; the band allows the curvature's variation).
            self.assertGreater(coarse["length_error"] / fine["length_error"], 18, case)
            self.assertLess(coarse["length_error"] / fine["length_error"], 32, case)
        md = "\n".join(report_shipped.catmull_rom_findings(list(rows.values())))
        self.assertIn("three's CatmullRomCurve3", md)
        self.assertIn("no run exceeds both", md)


if __name__ == "__main__":
    unittest.main()
