"""scripts/peers/shipped_browser_driver.py without a browser: the request's cases become the page's
jobs (a <path> for each, the basic shape beside it where the case has one), malformed requests and
results are refused, and the recorded results of a real run (Debian bookworm's headless Chromium 156
and Firefox ESR 153 on the six cases of tests/data/peers/shipped/browser_request.json, a copy of the
request.json there that the recorded outputs answer) parse into the run records of the recorded
driver output, tests/data/peers/shipped/shipped_browser_driver.json. Its figures are the engines':
float32 values; a quarter circle of radius 100 (an SVG arc, which both engines turn into cubics)
1.4e-4 long and its points within 2.6e-4 of the radius; Chromium's <ellipse> (Skia's contour
measure) 3.7e-3 short where its <path> of the same ellipse is within 1e-4; Firefox's cubic with
collinear control points measured as its chord, and its 1e-3-wide cubic 5 % short."""
import copy
import json
import math
import os
import struct
import sys
import unittest

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.join(HERE, "..", "..")
sys.path.insert(0, os.path.join(ROOT, "scripts"))
sys.path.insert(0, os.path.join(ROOT, "scripts", "peers"))
import shipped_browser_driver as sb  # noqa: E402

DATA = os.path.join(HERE, "..", "data", "peers", "shipped")
# 4 a E(e) for a = 10, b = 1 (mpmath, 30 digits): the thin ellipse's true length.
THIN_ELLIPSE = 40.63974180100895790638637780
R = 100.0  # svg_quarter_circle_arc's radius


CASES = [("svg_cubic_extent_1e-3", "path"), ("svg_cubic_offset_1e6", "path"), ("svg_cusp_fonttools", "path"),
         ("svg_every_command", "path"), ("svg_quarter_circle_arc", "path"), ("svg_thin_ellipse", "path"),
         ("svg_thin_ellipse", "shape")]


def load(name):
    with open(os.path.join(DATA, name), encoding="utf-8") as f:
        return f.read()


def request():
    return json.loads(load("browser_request.json"))


def recorded_docs():
    return {"chromium": sb.parse_dump(load("browser_chromium_dump.html")),
            "firefox": sb.parse_result(load("browser_firefox_result.json"))}


def recorded_output():
    return json.loads(load("shipped_browser_driver.json"))


def is_float32(x):
    return struct.unpack("f", struct.pack("f", x))[0] == x


class Jobs(unittest.TestCase):
    def test_a_path_per_case_and_the_shape_beside_it(self):
        jobs = sb.jobs_of(request())
        self.assertEqual([(j["case"], j["kind"]) for j in jobs], CASES)
        shape = jobs[6]
        self.assertEqual(shape["element"], "ellipse")
        self.assertEqual(shape["attributes"], {"cx": "0", "cy": "0", "rx": "10", "ry": "1"})
        self.assertEqual(jobs[5]["attributes"], {"d": request()["cases"][5]["d"]})
        self.assertEqual(len(jobs[4]["s"]), 17)
        self.assertEqual(jobs[4]["spaced"], 17)
        self.assertEqual(sb._attribute_text(0.1), "0.1")
        self.assertEqual(sb._attribute_text(2.0), "2")
        self.assertEqual(sb._attribute_text(1e-7), "1e-07")

    def test_malformed_requests_are_refused(self):
        def refused(edit, words):
            req = request()
            edit(req)
            with self.assertRaisesRegex(sb.DriverError, words):
                sb.jobs_of(req)
        refused(lambda r: r.update(format="curvebench-shipped-request-0"), "is not curvebench-shipped-request-1")
        refused(lambda r: r["cases"].append(copy.deepcopy(r["cases"][0])), "named twice")
        refused(lambda r: r["cases"][0].update(d=""), "no path data")
        refused(lambda r: r["cases"][0].update(s=[0, None]), "finite numbers")
        refused(lambda r: r["cases"][0].update(spaced=1), "spaced")
        refused(lambda r: r["cases"][5]["shape"].update(element="polygon"), "circle, ellipse or rect")
        refused(lambda r: r["cases"][5]["shape"]["attributes"].update(r=2), "attribute r=2")
        refused(lambda r: r["cases"][5]["shape"]["attributes"].update(rx="10"), "attribute rx='10'")


class Page(unittest.TestCase):
    def test_page(self):
        jobs = sb.jobs_of(request())
        text = sb.page(jobs)
        self.assertIn(f'<pre id="{sb.RESULT_ID}"></pre>', text)
        self.assertIn("const POST = null;", text)
        self.assertIn('"M100 0 A100 100 0 0 1 0 100"', text)
        self.assertIn("const PASS_MS = 25.0;", text)
        posting = sb.page(jobs, "/result", pass_ms=5, passes=2)
        self.assertIn('const POST = "/result";', posting)
        self.assertIn("const PASSES = 2;", posting)
        # No case name or path data ends the script element early.
        req = request()
        req["cases"][0]["case"] = "a</script><b>"
        text = sb.page(sb.jobs_of(req))
        self.assertEqual(text.count("</script>"), 1)

    def test_firefox_profile(self):
        prefs = sb.user_js().splitlines()
        self.assertTrue(all(p.startswith("user_pref(\"") and p.endswith(");") for p in prefs))
        for p in ('"toolkit.telemetry.enabled", false', '"app.update.auto", false',
                  '"browser.shell.checkDefaultBrowser", false', '"dom.max_script_run_time", 0',
                  '"privacy.reduceTimerPrecision", false', '"startup.homepage_welcome_url", ""'):
            self.assertIn(f"user_pref({p});", prefs)

    def test_cpu_model(self):
        self.assertEqual(sb.cpu_model("processor\t: 0\nmodel name\t: AMD EPYC 7B13\nflags\t: x\n"), "AMD EPYC 7B13")
        self.assertIsNone(sb.cpu_model("processor\t: 0\n"))


class Recorded(unittest.TestCase):
    def setUp(self):
        self.jobs = sb.jobs_of(request())
        self.docs = recorded_docs()

    def test_the_recorded_results_give_the_recorded_runs(self):
        out = recorded_output()
        self.assertEqual(out["driver"], "shipped_browser")
        self.assertEqual(out["format"], "curvebench-shipped-driver-1")
        self.assertTrue(out["versions"]["chromium"].startswith("Chromium 156."))
        self.assertTrue(out["versions"]["firefox"].startswith("Mozilla Firefox 153."))
        self.assertEqual(out["skipped"], [])
        outcomes = {b: sb.runs_of(self.docs[b], self.jobs, b) for b in sb.BROWSERS}
        rebuilt = sb.assemble(out["versions"], out["cpu"], outcomes,
                              {b: sb.page_info_of(self.docs[b]) for b in sb.BROWSERS})
        self.assertEqual(rebuilt, out)
        self.assertEqual([(r["peer"], r["case"]) for r in out["runs"]],
                         [(sb.peer_id(b, kind), case) for b in sb.BROWSERS for case, kind in CASES])
        keys = {"peer", "case", "setting", "length", "points", "spaced", "ns_length", "ns_point", "ns_build", "note"}
        for r in out["runs"]:
            self.assertEqual(set(r), keys)
            self.assertEqual(r["setting"], "")
            self.assertEqual(len(r["points"]), 17)
            self.assertEqual(len(r["spaced"]), 17)
            for k in ("ns_length", "ns_point", "ns_build"):
                self.assertGreater(r[k], 0, (r["peer"], r["case"], k))
            self.assertIn("performance.now() step", r["note"])

    def test_the_engines_figures(self):
        out = recorded_output()
        runs = {(r["peer"], r["case"]): r for r in out["runs"]}
        truth = {c["case"]: c["length"] for c in request()["cases"]}

        def rel(peer, case):
            return (runs[(peer, case)]["length"] - truth[case]) / truth[case]
        # Both engines compute lengths and points in float32.
        for r in out["runs"]:
            values = [r["length"]] + [x for p in r["points"] + r["spaced"] for x in p]
            self.assertTrue(all(is_float32(x) for x in values), (r["peer"], r["case"]))
        # The quarter circle of radius 100: the arc as cubic Beziers, a little long and off the circle.
        for browser in sb.BROWSERS:
            peer = f"peer_{browser}_path"
            r = runs[(peer, "svg_quarter_circle_arc")]
            self.assertLess(abs(r["length"] - math.pi * R / 2), 2.5e-4 * R, browser)
            self.assertGreater(rel(peer, "svg_quarter_circle_arc"), 1e-4, browser)
            for x, y in r["points"] + r["spaced"]:
                self.assertLess(abs(math.hypot(x, y) - R), 3e-4 * R, (browser, x, y))
            self.assertEqual(r["points"][0], [R, 0.0])
            self.assertLess(math.dist(r["spaced"][-1], [0, R]), 1e-6 * R, browser)
            # The request's last s, the true length, is short of the engines' longer length: near (0, R).
            self.assertLess(math.dist(r["points"][-1], [0, R]), 3e-4 * R, browser)
        # The thin ellipse: <path> within 1e-4 in both engines, Firefox's <ellipse> too; Chromium's
        # <ellipse> (Skia's contour measure) 3.7e-3 short.
        for peer in ("peer_chromium_path", "peer_firefox_path", "peer_firefox_shape"):
            self.assertLess(abs(runs[(peer, "svg_thin_ellipse")]["length"] - THIN_ELLIPSE), 1e-4 * THIN_ELLIPSE, peer)
        self.assertLess(rel("peer_chromium_shape", "svg_thin_ellipse"), -2e-3)
        for peer in ("peer_chromium_shape", "peer_firefox_shape"):
            r = runs[(peer, "svg_thin_ellipse")]
            self.assertEqual(r["spaced"][0], [10.0, 0.0])
            self.assertLess(math.dist(r["spaced"][4], [0, 1]), 1e-5, peer)  # SVG 2: through +y first
            self.assertLess(math.dist(r["spaced"][8], [-10, 0]), 1e-5, peer)
        # A cubic whose control points lie on one line, doubling back (x: 0 -> 50 -> -50): Chromium
        # follows it (150); Firefox measures the chord from its start to its end (50).
        self.assertEqual(runs[("peer_chromium_path", "svg_cusp_fonttools")]["length"], 150.0)
        self.assertEqual(runs[("peer_firefox_path", "svg_cusp_fonttools")]["length"], 50.0)
        # Scale: a cubic 1e-3 wide is within 1e-5 in Chromium and 5 % short in Firefox; the same
        # cubic 1e6 from the origin is lost to float32 coordinates in both.
        self.assertLess(abs(rel("peer_chromium_path", "svg_cubic_extent_1e-3")), 1e-5)
        self.assertLess(rel("peer_firefox_path", "svg_cubic_extent_1e-3"), -1e-2)
        for browser in sb.BROWSERS:
            self.assertGreater(rel(f"peer_{browser}_path", "svg_cubic_offset_1e6"), 1e-2, browser)

    def test_malformed_results_are_refused(self):
        doc = self.docs["chromium"]

        def refused(edit, words, jobs=None):
            bad = copy.deepcopy(doc)
            edit(bad)
            with self.assertRaisesRegex(sb.DriverError, words):
                sb.runs_of(bad, jobs or self.jobs, "chromium")
        refused(lambda d: d["results"].pop(), "expected 7 results, got 6")
        refused(lambda d: d["results"][1].update(case="elsewhere"), "elsewhere")
        refused(lambda d: d["results"][6].update(kind="path"), "'path'")
        refused(lambda d: d["results"][0].update(length=None), "getTotalLength\\(\\) gave None")
        refused(lambda d: d["results"][0]["points"].pop(), "expected 17 points, got 16")
        refused(lambda d: d["results"][2]["spaced"][1].__setitem__(0, None), "point 1 is \\[None")
        refused(lambda d: d["results"][0].update(ns_point=0), "ns_point: 0 is not a positive time")
        with self.assertRaisesRegex(sb.DriverError, "no result"):
            sb.parse_dump(f'<html><body><pre id="{sb.RESULT_ID}"></pre></body></html>')
        with self.assertRaisesRegex(sb.DriverError, "script failed: TypeError"):
            sb.parse_result('{"error": "TypeError: x"}')
        with self.assertRaisesRegex(sb.DriverError, "not JSON"):
            sb.parse_result("{")

    def test_a_failed_job_is_skipped_and_a_changed_length_drops_ns_build(self):
        bad = copy.deepcopy(self.docs["firefox"])
        bad["results"][6] = {"case": "svg_thin_ellipse", "kind": "shape", "error": "NotSupportedError: x"}
        bad["results"][0]["build_same"] = False
        runs, skipped = sb.runs_of(bad, self.jobs, "firefox")
        self.assertEqual(len(runs), 6)
        self.assertEqual(skipped, [{"peer": "peer_firefox_shape", "case": "svg_thin_ellipse",
                                    "reason": "the page's script failed: NotSupportedError: x"}])
        self.assertIsNone(runs[0]["ns_build"])
        self.assertIn("ns_build not recorded", runs[0]["note"])

    def test_a_missing_browser(self):
        outcomes = {"chromium": sb.runs_of(self.docs["chromium"], self.jobs, "chromium"),
                    "firefox": ([], sb.skipped_all(self.jobs, "firefox", "firefox-esr is not on PATH"))}
        out = sb.assemble({"chromium": "Chromium 156", "firefox": None}, "cpu", outcomes)
        self.assertEqual(out["versions"], {"chromium": "Chromium 156", "firefox": None})
        self.assertEqual(len(out["runs"]), 7)
        self.assertEqual([(s["peer"], s["case"]) for s in out["skipped"]],
                         [(sb.peer_id("firefox", j["kind"]), j["case"]) for j in self.jobs])
        self.assertNotIn("pages", out)


if __name__ == "__main__":
    unittest.main()
