"""Unit tests of scripts/report_peers.py (REPORT.md's "Peers" section) on outputs recorded from real
runs and checked into tests/data/peers/: accuracy_gsl.json is two cases of a quick accuracy run
(`curvebench accuracy --quick --only natural_cubic`, GSL 2.7.1, with the u(s) peer), trimmed to
the records the section joins; accuracy_boost_eigen.json is the Boost.Math and Eigen peers' records
of a quick run on catmull_rom_centripetal_2d and hermite_knot_ratio_1e4 (Boost 1.74.0) with the
curvebench records they join; scipy/ is scripts/peers/scipy_driver.py --quick on the same two
cases with the `curvebench check` output of each CSV. Run by ctest
(report_py) with the other tests of tests/python."""
import copy
import importlib.util
import json
import os
import shutil
import sys
import tempfile
import unittest

HERE = os.path.dirname(os.path.abspath(__file__))
SCRIPTS = os.path.join(HERE, "..", "..", "scripts")
DATA = os.path.join(HERE, "..", "data", "peers")
FIXTURES = os.path.join(HERE, "fixtures")
sys.path.insert(0, SCRIPTS)
import report_peers as rp  # noqa: E402
import report_fixture  # noqa: E402


def load(name):
    with open(os.path.join(DATA, name), encoding="utf-8") as f:
        return json.load(f)


def peer(case, method, setting, error, estimate, status="converged", peer_status="success", quantity="length"):
    r = {"case": case, "group": "g", "quantity": quantity, "method": method, "setting": setting, "error": error,
         "estimate": estimate, "evaluations": 15, "status": status, "peer_status": peer_status, "peer": True,
         "library": "GSL 2.7.1"}
    r["bounded"] = None if error is None or estimate is None else estimate >= error
    return r


class Findings(unittest.TestCase):
    def test_success_beyond_the_requested_tolerance_is_a_finding(self):
        f = rp.findings([peer("c", "peer_gsl_qag", "tol=1e-10", 5e-9, 1e-8)])
        self.assertEqual(len(f), 1)
        self.assertIn("peer_gsl_qag on c (tol=1e-10)", f[0])
        self.assertIn("50 times the requested tolerance", f[0])

    def test_an_estimate_below_the_error_is_a_finding(self):
        f = rp.findings([peer("c", "peer_gsl_qag", "tol=1e-6", 1e-7, 1e-8, status="rounding_limited",
                              peer_status="roundoff error")])
        self.assertEqual(len(f), 1)
        self.assertIn("does not bound its true error", f[0])
        self.assertIn("under by 10x", f[0])
        self.assertIn("roundoff error", f[0])

    def test_within_tolerance_and_bounded_is_no_finding(self):
        self.assertEqual(rp.findings([peer("c", "peer_gsl_qag", "tol=1e-6", 1e-9, 1e-7)]), [])
        # A peer that reported failure (cap_hit) beyond the tolerance said so: no contradiction.
        self.assertEqual(rp.findings([peer("c", "peer_gsl_qag", "tol=1e-10", 1e-8, 1e-7, status="cap_hit")]), [])

    def test_refused_settings_listed_apart(self):
        refused = peer("c", "peer_gsl_qag", "tol=1e-14", None, None, status="not_guaranteed",
                       peer_status="specified tolerance is invalid or theoretically unattainable")
        self.assertEqual(rp.findings([refused]), [])
        self.assertEqual(rp.refusals([refused, dict(refused, case="d")]),
                         ['peer_gsl_qag tol=1e-14: "specified tolerance is invalid or theoretically unattainable" '
                          'on 2 case(s)'])

    def test_recorded_run_finds_the_knot_ratio_case(self):
        # Recorded: qag at tol=1e-10 on natural_cubic_knot_ratio_1e4 reports success with
        # abserr / L = 1.78e-12 while |L_qag - L| / L = 5.35e-9 (whole-domain QUADPACK misses the
        # 1e-4-wide segments; curvebench splits at breakpoints).
        acc = load("accuracy_gsl.json")
        f = rp.findings(acc["peer_records"])
        self.assertTrue(any("peer_gsl_qag on natural_cubic_knot_ratio_1e4 (tol=1e-10): reported success" in x
                            for x in f), f)
        self.assertFalse(any("natural_cubic_2d" in x for x in f), f)


class GroupedFindings(unittest.TestCase):
    """One line per (peer, defect kind, case): the settings it holds for and the worst figures."""

    def under(self, case, method, setting, error, estimate):
        # an estimate below the error, the peer saying it did not converge: one finding, estimate_under
        return peer(case, method, setting, error, estimate, status="rounding_limited", peer_status="roundoff error")

    def test_settings_of_one_defect_merge_into_one_line_with_the_range_and_the_worst(self):
        # under by 2, 3, 100, 4 and 5 times: the worst is tol=1e-10, the range in the sweep's order.
        records = [self.under("c", "peer_x", f"tol={t}", e, 1e-9)
                   for t, e in (("1e-6", 2e-9), ("1e-8", 3e-9), ("1e-10", 1e-7), ("1e-12", 4e-9), ("1e-14", 5e-9))]
        self.assertEqual(len(rp.findings(records)), 5)
        groups = rp.grouped_findings(records)
        self.assertEqual(len(groups), 1)
        g = groups[0]
        self.assertEqual((g["peer"], g["case"], g["kind"]), ("peer_x", "c", "estimate_under"))
        self.assertEqual(g["settings"], ["tol=1e-6", "tol=1e-8", "tol=1e-10", "tol=1e-12", "tol=1e-14"])
        self.assertEqual(g["worst"]["setting"], "tol=1e-10")
        self.assertEqual(g["line"], "peer_x on c (tol=1e-6 .. 1e-14, 5 settings; worst at tol=1e-10): its error "
                                    "estimate 1.00e-09 does not bound its true error 1.00e-07 (under by 100x; status "
                                    "\"roundoff error\").")

    def test_settings_in_the_order_of_the_records(self):
        records = [self.under("c", "peer_x", "tol=1e-6", 2e-9, 1e-9),
                   self.under("c", "peer_x", "tol=1e-10", 2e-9, 1e-9)]
        g = rp.grouped_findings(list(reversed(records)))
        self.assertEqual(g[0]["settings"], ["tol=1e-10", "tol=1e-6"])  # as given: the sweep's order
        g = rp.grouped_findings(records)
        self.assertEqual(g[0]["settings"], ["tol=1e-6", "tol=1e-10"])
        # equal figures: the first setting is the worst
        self.assertIn("(tol=1e-6, 1e-10; worst at tol=1e-6)", g[0]["line"])

    def test_one_setting_reads_as_the_finding_itself(self):
        records = [peer("c", "peer_gsl_qag", "tol=1e-10", 5e-9, 1e-8)]
        self.assertEqual([g["line"] for g in rp.grouped_findings(records)], rp.findings(records))

    def test_distinct_cases_peers_and_kinds_stay_apart(self):
        records = [self.under("c", "peer_x", "tol=1e-6", 2e-9, 1e-9), self.under("c", "peer_x", "tol=1e-8", 2e-9, 1e-9),
                   self.under("d", "peer_x", "tol=1e-6", 2e-9, 1e-9), self.under("c", "peer_y", "tol=1e-6", 2e-9, 1e-9),
                   # converged with 5e-9 at tol 1e-10: beyond its tolerance, and an estimate under its error
                   peer("c", "peer_z", "tol=1e-10", 5e-9, 1e-9), peer("c", "peer_z", "tol=1e-12", 5e-9, 1e-9)]
        groups = rp.grouped_findings(records)
        self.assertEqual([(g["case"], g["peer"], g["kind"], len(g["settings"])) for g in groups],
                         [("c", "peer_x", "estimate_under", 2), ("c", "peer_y", "estimate_under", 1),
                          ("c", "peer_z", "beyond_tolerance", 2), ("c", "peer_z", "estimate_under", 2),
                          ("d", "peer_x", "estimate_under", 1)])
        beyond = groups[2]
        # 5e-9 is 5e3 times 1e-12 and 50 times 1e-10: the worst is the tighter tolerance
        self.assertEqual(beyond["worst"]["setting"], "tol=1e-12")
        self.assertAlmostEqual(beyond["worst"]["excess"], 5e3)
        self.assertIn("is 5e+03 times the requested tolerance 1.00e-12", beyond["line"])

    def test_settings_text(self):
        self.assertEqual(rp.settings_text(["tol=1e-6"]), "tol=1e-6")
        self.assertEqual(rp.settings_text(["n=2", "n=8"]), "n=2, 8")
        self.assertEqual(rp.settings_text(["n=2", "n=4", "n=8"]), "n=2 .. 8, 3 settings")
        self.assertEqual(rp.settings_text(["", "derivative=1"]), "no setting; derivative=1")
        self.assertEqual(rp.settings_text(["a=1,b=2", "a=1,b=3", "a=2,b=3"]), "a=1,b=2 .. a=2,b=3, 3 settings")

    def test_recorded_run_groups_the_two_u_of_s_findings_apart(self):
        # The recorded Brent-over-qag findings at tol=1e-12 on the knot-ratio case are two defects:
        # two lines, each for its one setting.
        acc = load("accuracy_gsl.json")
        hit = [g for g in rp.grouped_findings(acc["peer_records"])
               if g["peer"] == "peer_gsl_qag_brent" and g["case"] == "natural_cubic_knot_ratio_1e4"]
        self.assertEqual(sorted(g["kind"] for g in hit), ["beyond_tolerance", "estimate_under"])
        self.assertLessEqual(len(rp.grouped_findings(acc["peer_records"])), len(rp.findings(acc["peer_records"])))


class Joins(unittest.TestCase):
    def test_eval_rows_join_curvebench_default_of_the_same_case(self):
        acc = load("accuracy_gsl.json")
        rows = rp.eval_rows(acc["records"], acc["peer_records"])
        self.assertEqual([r[:2] for r in rows], [["natural_cubic_2d", "peer_gsl_cspline"],
                                                 ["natural_cubic_2d", "peer_gsl_cspline derivative=1"],
                                                 ["natural_cubic_knot_ratio_1e4", "peer_gsl_cspline"],
                                                 ["natural_cubic_knot_ratio_1e4", "peer_gsl_cspline derivative=1"]])
        own = {r["case"]: r["error"] for r in acc["records"] if r["quantity"] == "eval"}
        derivative = {r["case"]: r for r in acc["peer_records"] if r["setting"] == "derivative=1"}
        for r in rows:
            if r[1].endswith("derivative=1"):
                # curvebench keeps no derivative record: its error was measured beside GSL's.
                self.assertEqual(r[3], "default derivative=1")
                self.assertEqual(r[4], derivative[r[0]]["counterpart_error"])
            else:
                self.assertEqual(r[3], "default")
                self.assertEqual(r[4], own[r[0]])
            self.assertAlmostEqual(r[7], r[6] / r[5])

    def test_length_rows_pair_each_tolerance_with_adaptive_gk_at_the_same_tolerance(self):
        acc = load("accuracy_gsl.json")
        rows = rp.length_rows(acc["records"], acc["peer_records"])
        own = {(r["case"], r["setting"]): r for r in acc["records"] if r["method"] == "adaptive_gk"}
        self.assertTrue(rows)
        for case, setting, method, err, est, bounded, evals, status, own_err, own_evals, *_ in rows:
            self.assertTrue(method.startswith("peer_gsl_"))
            self.assertEqual(own_err, own[(case, setting)]["error"])
            self.assertEqual(own_evals, own[(case, setting)]["evaluations"])
            self.assertEqual(bounded, est >= err)
        # Refused settings (GSL: epsrel 1e-14 with epsabs 0) have no row, only a refusal line.
        self.assertFalse(any(r[1] == "tol=1e-14" for r in rows))
        self.assertTrue(rp.refusals(acc["peer_records"]))

    def test_u_of_s_rows_pair_each_tolerance_with_newton_at_the_same_tolerance(self):
        acc = load("accuracy_gsl.json")
        rows = rp.length_rows(acc["records"], acc["peer_records"], "u_of_s")
        own = {(r["case"], r["setting"]): r for r in acc["records"] if r["method"] == "newton"}
        self.assertEqual(sorted((r[0], r[1]) for r in rows), sorted(own))
        for case, setting, method, err, est, bounded, evals, status, own_err, own_evals, ns, ours_ns, ratio in rows:
            self.assertEqual(method, "peer_gsl_qag_brent")
            self.assertEqual(own_err, own[(case, setting)]["error"])
            self.assertEqual(bounded, est >= err)
            self.assertGreater(evals, own_evals)  # a quadrature per root-finding step
            self.assertAlmostEqual(ratio, ours_ns / ns)

    def test_recorded_u_of_s_finding(self):
        # Recorded: Brent over qag at tol=1e-12 on natural_cubic_knot_ratio_1e4 reports success with
        # its own account 8.2e-13 L while |s(u) - s| = 5.35e-9 L (qag from the domain's start
        # steps over the 1e-4-wide segments, as it does for the whole length).
        acc = load("accuracy_gsl.json")
        f = rp.findings(acc["peer_records"])
        hit = [x for x in f if x.startswith("peer_gsl_qag_brent on natural_cubic_knot_ratio_1e4 (tol=1e-12)")]
        self.assertEqual(len(hit), 2, f)  # success beyond the tolerance, and an estimate that does not bound
        self.assertTrue(any("reported success" in x for x in hit))
        self.assertTrue(any("does not bound" in x for x in hit))

    def test_versions_from_the_runner_and_the_driver_files(self):
        acc = load("accuracy_gsl.json")
        scipy = {"driver": "scipy", "versions": {"SciPy": "1.10.1"}, "peer_records": [{}, {}]}
        rows = rp.version_rows(acc, [("/r/peers_scipy.json", scipy)])
        self.assertEqual(rows[0], ["GSL 2.7.1", "accuracy runner (always)", 20])
        self.assertEqual(rows[1], ["SciPy 1.10.1", "peers_scipy.json (scripts/peers.sh)", 2])
        self.assertEqual(rp.missing_drivers([("p", {"driver": "scipy"}), ("q", {"driver": "chromium"}),
                                             ("r", {"driver": "penner"}), ("s", {"driver": "blender"}),
                                             ("t", {"driver": "three"}), ("u", {"driver": "shipped_node"}),
                                             ("v", {"driver": "shipped_browser"}), ("w", {"driver": "lottie"}),
                                             ("x", {"driver": "qt"}), ("y", {"driver": "occt"}),
                                             ("z", {"driver": "lib2geom"}), ("a", {"driver": "fonttools"}),
                                             ("b", {"driver": "blender_length"}), ("c", {"driver": "godot"})]),
                         ["bezier-easing 3.2.0 / 2.1.0, @mapbox/unitbezier, Babylon.js's BezierCurve.Interpolate and "
                          "lottie-web's BezierEaser (scripts/peers/easing_driver.mjs)"])
        self.assertIn("three.js's glTF interpolants (scripts/peers/gltf_driver.mjs)",
                      rp.missing_drivers([("p", {"driver": "scipy"})]))

    def test_malformed_peer_file_names_the_file(self):
        d = tempfile.mkdtemp()
        self.addCleanup(shutil.rmtree, d)
        with open(os.path.join(d, "peers_x.json"), "w", encoding="utf-8") as f:
            json.dump({"peer_records": [{"case": "c", "quantity": 3, "method": "m"}]}, f)
        with self.assertRaises(rp.lib.ReportError) as e:
            rp.load_peer_files(d)
        self.assertIn("peers_x.json", str(e.exception))
        self.assertIn("peer_records[0].quantity", str(e.exception))


sys.path.insert(0, os.path.join(SCRIPTS, "peers"))
import peer_results as pr  # noqa: E402

SCIPY = os.path.join(DATA, "scipy")


def read_check(csv):
    with open(os.path.join(SCIPY, csv + ".check.json"), encoding="utf-8") as f:
        return json.load(f)


def scipy_doc():
    """peers_scipy.json assembled from the recorded driver output and its recorded checks
    (scripts/peers.sh --quick, SciPy 1.10.1, cases natural_cubic_2d and natural_cubic_knot_ratio_1e4)."""
    return pr.assemble(load(os.path.join("scipy", "scipy_driver.json")), read_check)


class ScipyRecorded(unittest.TestCase):
    def test_every_run_becomes_records(self):
        doc = scipy_doc()
        self.assertEqual(doc["driver"], "scipy")
        self.assertEqual(doc["versions"]["SciPy"], "1.10.1")
        recs = {(r["case"], r["method"], r["setting"]): r for r in doc["peer_records"]}
        # Two value runs per case (points and first derivative each), three quad tolerances and two
        # u(s) tolerances.
        self.assertEqual(len(doc["peer_records"]), 2 * (2 * 2 + 3 + 2))
        for r in doc["peer_records"]:
            self.assertTrue(r["peer"])
            self.assertNotIn("subject", r)
            self.assertEqual(r["library"], "SciPy 1.10.1")
        pts = recs[("natural_cubic_2d", "peer_scipy_cubic_spline", "")]
        self.assertEqual(pts["counterpart"], {"method": "default", "setting": ""})
        self.assertGreater(pts["ns_per_op"], 0)
        self.assertIsNone(recs[("natural_cubic_2d", "peer_scipy_cubic_spline", "derivative=1")]["ns_per_op"])

    def test_quad_records_join_check_rows_in_order(self):
        recs = {(r["case"], r["setting"]): r for r in scipy_doc()["peer_records"] if r["method"] == "peer_scipy_quad"}
        check = read_check("natural_cubic_knot_ratio_1e4.peer_scipy_quad.lengths.csv")["checks"][0]
        r6 = recs[("natural_cubic_knot_ratio_1e4", "tol=1e-06")]
        r10 = recs[("natural_cubic_knot_ratio_1e4", "tol=1e-10")]
        self.assertEqual(r6["error"], check["rows"][0]["error"])
        self.assertEqual(r10["error"], check["rows"][1]["error"])
        # Recorded: QUADPACK's qags through quad misses the 1e-4-wide segments like GSL's.
        self.assertGreater(r10["error"], 5e-9)
        self.assertFalse(r10["bounded"])
        self.assertEqual(r10["status"], "converged")
        self.assertEqual(r10["counterpart"], {"method": "adaptive_gk", "setting": "tol=1e-10"})
        refused = recs[("natural_cubic_knot_ratio_1e4", "tol=1e-14")]
        self.assertIsNone(refused["error"])
        self.assertIn("epsrel", refused["peer_status"])

    def test_inverse_runs_become_u_of_s_records_beside_newton(self):
        doc = scipy_doc()
        recs = {(r["case"], r["setting"]): r for r in doc["peer_records"] if r["quantity"] == "u_of_s"}
        self.assertEqual(sorted(recs), [(c, t) for c in ("natural_cubic_2d", "natural_cubic_knot_ratio_1e4")
                                        for t in ("tol=1e-08", "tol=1e-12")])
        run = next(r for r in load(os.path.join("scipy", "scipy_driver.json"))["runs"]
                   if r["kind"] == "inverse" and r["case"] == "natural_cubic_2d" and r["setting"] == "tol=1e-12")
        check = read_check(run["csv"])["checks"][0]
        r = recs[("natural_cubic_2d", "tol=1e-12")]
        self.assertEqual(r["method"], "peer_scipy_quad_brentq")
        self.assertEqual(r["error"], check["records"][0]["error"])
        self.assertAlmostEqual(r["estimate"], run["estimate_abs"] / check["length"])
        self.assertEqual(r["bounded"], r["estimate"] >= r["error"])
        self.assertEqual(r["counterpart"], {"method": "newton", "setting": "tol=1e-12"})
        self.assertEqual(r["status"], "converged")
        # The runner's GSL record of the same case and tolerance times curvebench's Newton: the row uses it.
        acc = load("accuracy_gsl.json")
        rows = rp.length_rows(acc["records"], acc["peer_records"] + doc["peer_records"], "u_of_s")
        row = next(x for x in rows if x[:3] == ["natural_cubic_2d", "tol=1e-12", "peer_scipy_quad_brentq"])
        gsl = next(x for x in acc["peer_records"] if x["quantity"] == "u_of_s" and x["case"] == "natural_cubic_2d"
                   and x["setting"] == "tol=1e-12")
        self.assertEqual(row[11], gsl["counterpart_ns_per_op"])
        self.assertAlmostEqual(row[12], row[11] / row[10])

    def test_an_inverse_check_of_another_kind_fails(self):
        driver = load(os.path.join("scipy", "scipy_driver.json"))
        wrong = read_check("natural_cubic_2d.peer_scipy_quad.lengths.csv")
        with self.assertRaises(pr.PeerResultError) as e:
            pr.assemble(driver, lambda csv: wrong if csv.endswith(".inverse.csv") else read_check(csv))
        self.assertIn("expected one check of kind inverse", str(e.exception))

    def test_make_interp_spline_on_the_knot_ratio_case_is_a_finding(self):
        doc = scipy_doc()
        own = load("accuracy_gsl.json")["records"]
        f = rp.findings(doc["peer_records"], own)
        self.assertTrue(any(x.startswith("peer_scipy_make_interp_spline on natural_cubic_knot_ratio_1e4: error 661")
                            and "curvebench's default evaluation: 0.813" in x for x in f), f)
        self.assertFalse(any("peer_scipy_cubic_spline" in x and "eps(double)" in x for x in f), f)
        prefix = "peer_scipy_make_interp_spline on natural_cubic_knot_ratio_1e4 (derivative=1)"
        d1 = [x for x in f if x.startswith(prefix)]
        self.assertEqual(len(d1), 1, f)
        self.assertNotIn("curvebench's default evaluation", d1[0])  # a value's error is no derivative's peer

    def test_a_check_with_other_rows_than_the_driver_ran_fails(self):
        driver = load(os.path.join("scipy", "scipy_driver.json"))

        def short(csv):
            c = read_check(csv)
            if csv.endswith("lengths.csv"):
                c["checks"][0]["rows"] = c["checks"][0]["rows"][:1]
            return c
        with self.assertRaises(pr.PeerResultError) as e:
            pr.assemble(driver, short)
        self.assertIn("1 rows measured, the driver ran 2 tolerances", str(e.exception))

    def test_a_values_check_of_another_peer_fails(self):
        driver = load(os.path.join("scipy", "scipy_driver.json"))

        def renamed(csv):
            c = read_check(csv)
            for r in c["checks"][0]["records"]:
                r["method"] = "other"
            return c
        with self.assertRaises(pr.PeerResultError):
            pr.assemble(driver, renamed)

    def test_quad_status(self):
        self.assertEqual(pr.quad_status("success", False), "converged")
        self.assertEqual(pr.quad_status("The maximum number of subdivisions (50) has been achieved.", True), "cap_hit")
        self.assertEqual(pr.quad_status("The occurrence of roundoff error is detected, which prevents", True),
                         "rounding_limited")
        self.assertEqual(pr.quad_status("The integral is probably divergent, or slowly convergent.", True),
                         "not_guaranteed")


EASING = os.path.join(DATA, "easing")


@unittest.skipUnless(importlib.util.find_spec("mpmath"), "the easing truth needs python3-mpmath")
class EasingRecorded(unittest.TestCase):
    """Recorded: scripts/peers.sh --quick with Node 20.20.2 (bezier-easing 3.2.0 and 2.1.0,
    @mapbox/unitbezier 1.0.0; @babylonjs/core 9.37.1's runs, then lottie-web 5.13.0's, added later by
    easing_driver.mjs --quick on the same two cases, the others' values unchanged), cases css_vertical_start and
    css_wild_overshoot, and curvebench sample's values of the same cases at the same times (exact and
    table_newton solvers)."""

    def setUp(self):
        import easing_results
        self.er = easing_results

    def doc(self):
        driver = load(os.path.join("easing", "easing_driver.json"))
        specs = {}
        for case in {r["case"] for r in driver["runs"]}:
            with open(os.path.join(HERE, "..", "..", "bench", "cases", case + ".json"), encoding="utf-8") as f:
                specs[case] = json.load(f)

        def reader(suffix):
            return lambda case, times: self.er.read_curvebench(os.path.join(EASING, case + suffix), times)
        return self.er.assemble(driver, specs, reader(".csv"), reader(".table_newton.csv"))

    def test_truth_of_the_definition(self):
        # cubic-bezier(0, 0, 1, 1) has x(u) = y(u): the value is the progress itself.
        for t in (0.0, 0.1, 0.37, 0.5, 0.999, 1.0):
            self.assertLess(abs(float(self.er.cubic_bezier_truth([0, 0, 1, 1], t)) - t), 1e-45)
        # A point-symmetric easing (x1, y1, x2, y2) = (a, b, 1 - a, 1 - b) passes through (0.5, 0.5),
        # and y(1 - t) = 1 - y(t).
        p = [0.25, 1.5, 0.75, -0.5]  # exact in binary, so the symmetry is exact
        self.assertLess(abs(self.er.cubic_bezier_truth(p, 0.5) - 0.5), 1e-45)
        self.assertLess(abs(self.er.cubic_bezier_truth(p, 0.25) + self.er.cubic_bezier_truth(p, 0.75) - 1), 1e-45)

    def test_recorded_errors(self):
        recs = {(r["case"], r["method"]): r for r in self.doc()["peer_records"]}
        self.assertEqual(len(recs), 10)
        # bezier-easing 3.2.0 solves x(t) = x in closed form: a few eps; 2.1.0's Newton / bisection
        # stops 1.2e-9 away on the wild overshoot; unitbezier's epsilon 1e-6 shows as ~1e-5 there.
        self.assertLess(recs[("css_wild_overshoot", "peer_bezier_easing_3")]["error"], 64)
        self.assertGreater(recs[("css_wild_overshoot", "peer_bezier_easing_2")]["abs_error"], 1e-10)
        unit = recs[("css_wild_overshoot", "peer_mapbox_unitbezier")]
        self.assertGreater(unit["abs_error"], unit["documented_tolerance"])
        for r in recs.values():
            self.assertLess(r["counterpart_error"], 64)  # curvebench with the exact solver
            versions = {"peer_bezier_easing_3": "3.2.0", "peer_bezier_easing_2": "2.1.0",
                        "peer_mapbox_unitbezier": "1.0.0", "peer_babylon_bezier_interpolate": "9.37.1",
                        "peer_lottie_bezier_easing": "5.13.0"}
            self.assertEqual(r["library"].split(" ")[1], versions[r["method"]])
        # Babylon's BezierCurve.Interpolate: five Newton steps from u = x, no convergence test. On
        # cubic-bezier(0, 1, 0, 1) (x = u^3) they have not converged near x = 0: 0.038 off in y.
        babylon = recs[("css_vertical_start", "peer_babylon_bezier_interpolate")]
        self.assertGreater(babylon["abs_error"], 1e-2)
        self.assertEqual((babylon["peer_status"], babylon.get("non_finite")), ("success", None))
        # lottie-web's BezierEaser: float32 sample table, then 4 Newton steps (slope >= 1e-3) or at most
        # 10 bisections to 1e-7 in x. On cubic-bezier(0, 4, 1, -3) its steps stop about 1e-9 off in y
        # (the bisection's 1e-7 in x times the slope dy/dx); far above curvebench's exact solver
        # (counterpart_error < 64 ulps above), yet within its own 1e-7 scale.
        lottie = recs[("css_wild_overshoot", "peer_lottie_bezier_easing")]
        self.assertGreater(lottie["abs_error"], 1e-11)
        self.assertLess(lottie["abs_error"], 1e-6)
        # At x = 1 on cubic-bezier(0, 4, 1, -3), x'(1) = 0 and the step is 0 x infinity: NaN, written
        # as null, counted and named; the error is over the other 64 fractions.
        nan = recs[("css_wild_overshoot", "peer_babylon_bezier_interpolate")]
        self.assertEqual(nan["non_finite"], 1)
        self.assertEqual(nan["peer_status"], "non-finite value at 1 of 65 fractions")
        self.assertEqual(nan["evaluations"], 65)
        self.assertLess(nan["abs_error"], 1e-4)
        self.assertIn("css_wild_overshoot (peer_babylon_bezier_interpolate): non-finite value at 1 of 65 fractions "
                      "(x = 1: NaN where the definition gives 1.0); its error is over the other 64",
                      self.doc()["notes"])

    def test_values_neither_numbers_nor_null_are_refused(self):
        driver = load(os.path.join("easing", "easing_driver.json"))
        driver["runs"] = [r for r in driver["runs"] if r["case"] == "css_wild_overshoot"][:1]
        driver["runs"][0]["values"][3] = "0.5"
        spec = {"css_wild_overshoot": {"type": "channel", "tool": "css", "easing": "cubic-bezier(0, 4, 1, -3)"}}
        with self.assertRaisesRegex(self.er.EasingResultError, "value 3 is '0.5'"):
            self.er.assemble(driver, spec, lambda case, times: None)
        # Every value null: no error to measure; the record is a refusal with the peer's status.
        driver["runs"][0]["values"] = [None] * len(driver["runs"][0]["times"])
        rec = self.er.assemble(driver, spec, lambda case, times: None)["peer_records"][0]
        self.assertIsNone(rec["error"])
        self.assertEqual(rp.refusals([rec]), ['peer_bezier_easing_3: "non-finite value at 65 of 65 fractions" '
                                              'on 1 case(s)'])

    def test_findings_and_table(self):
        doc = self.doc()
        f = rp.findings(doc["peer_records"])
        self.assertTrue(any(x.startswith("peer_mapbox_unitbezier on css_wild_overshoot: absolute error") for x in f), f)
        self.assertFalse(any(x.startswith("peer_bezier_easing_3") for x in f), f)
        # bezier-easing 2.1.0 documents no precision: held to the lost-digits rule, beside curvebench's exact solver.
        self.assertTrue(any(x.startswith("peer_bezier_easing_2 on css_wild_overshoot: error 4.22e+06 eps(double)")
                            and "(curvebench css channel, solver exact: 1.32)" in x for x in f), f)
        # unitbezier is held to its documented 1e-6 once, not twice.
        self.assertEqual(sum(x.startswith("peer_mapbox_unitbezier on css_wild_overshoot") for x in f), 1, f)
        # Babylon's NaN at x = 1 is a finding of its own, the worst of the peer's (nothing promised holds).
        self.assertIn("peer_babylon_bezier_interpolate on css_wild_overshoot: 1 of 65 values not finite (NaN or "
                      "infinity); its error 3.85e+10 eps(double) x size is over the others.", f)
        worst = max((g for g in rp.grouped_findings(doc["peer_records"])
                     if g["peer"] == "peer_babylon_bezier_interpolate"), key=lambda g: g["worst"]["excess"])
        self.assertEqual(worst["kind"], "non_finite")
        rows = rp.eval_rows([], doc["peer_records"])
        self.assertTrue(all(r[3] == "curvebench css channel, solver exact" and r[4] < 64 for r in rows), rows)
        self.assertTrue(any("table_newton" in n for n in doc["notes"]))

    def test_curvebench_values_at_other_times_are_refused(self):
        times = load(os.path.join("easing", "easing_driver.json"))["runs"][0]["times"]
        with self.assertRaises(self.er.EasingResultError):
            self.er.read_curvebench(os.path.join(EASING, "css_vertical_start.csv"), times[:-1])
        with self.assertRaises(self.er.EasingResultError):
            self.er.read_curvebench(os.path.join(EASING, "css_vertical_start.csv"), [t + 1e-9 for t in times])


class SpeedRows(unittest.TestCase):
    def test_gsl_peers_timed_without_accuracy_records_are_listed(self):
        # Recorded: bench_gsl's median rows (random queries) of the quick run, with the vocabulary
        # of the same build (`curvebench list vocabulary --json`).
        vocab = rp.lib.load_vocabulary(os.path.join(DATA, "vocabulary.json"))
        rows = rp.lib.benchmark_rows(load("bench_gsl.json"), vocab)
        sp = rp.speed_rows(rows, vocab, {"GSL"})
        peers = {r[3] for r in sp}
        self.assertEqual(peers, {"peer_gsl_cspline", "peer_gsl_akima", "peer_gsl_cspline_periodic",
                                 "peer_gsl_steffen"})
        for family, data, ours, peer, ours_ns, peer_ns, ratio in sp:
            self.assertEqual(data, "points:1000/queries:random")
            self.assertAlmostEqual(ratio, ours_ns / peer_ns)
        self.assertEqual(rp.speed_rows(rows, vocab, {"SciPy"}), [])


class BoostEigenRecorded(unittest.TestCase):
    """The runner's Boost.Math peers as the section shows them (recorded, Boost 1.74.0)."""

    def setUp(self):
        self.acc = load("accuracy_boost_eigen.json")

    def test_a_peer_on_part_of_the_domain_is_compared_with_curvebench_on_the_same_part(self):
        # Boost's open catmull_rom is the case's curve on the interior segments only: its rows name
        # the part and carry curvebench's error measured on the same parameters, not the whole
        # domain's record (0.55 for the values on the interior; 0.36 for the default over the domain).
        rows = {r[1]: r for r in rp.eval_rows(self.acc["records"], self.acc["peer_records"])}
        interior = rows["peer_boost_catmull_rom segments=interior"]
        self.assertEqual(interior[3], "default segments=interior")
        record = next(r for r in self.acc["peer_records"]
                      if r["method"] == "peer_boost_catmull_rom" and r["setting"] == "segments=interior")
        self.assertEqual(interior[4], record["counterpart_error"])
        self.assertLess(interior[2], 16)
        # cubic_hermite represents the whole domain: the row joins the default evaluation's record.
        whole = rows["peer_boost_cubic_hermite"]
        own = next(r for r in self.acc["records"] if r["case"] == "hermite_knot_ratio_1e4" and r["method"] == "default")
        self.assertEqual(whole[4], own["error"])

    def test_recorded_findings(self):
        # Boost 1.74's catmull_rom::prime is not the derivative of its curve (tests/test_spline_peers.cpp
        # pins it); whole-domain Gauss-Kronrod steps over the 1e-4-wide segments and says it converged.
        f = rp.findings(self.acc["peer_records"], self.acc["records"])
        self.assertTrue(any(x.startswith("peer_boost_catmull_rom on catmull_rom_centripetal_2d "
                                         "(segments=interior,derivative=1): error 6.20e+14") for x in f), f)
        self.assertTrue(any(x.startswith("peer_boost_gauss_kronrod31 on hermite_knot_ratio_1e4 (tol=1e-10): "
                                         "reported success") for x in f), f)
        self.assertFalse(any("peer_boost_cubic_hermite" in x for x in f), f)

    def test_versions_name_each_library_with_its_records(self):
        rows = {r[0]: r[2] for r in rp.version_rows(self.acc, [])}
        self.assertEqual(rows["Boost.Math 1.74.0"], 22)
        self.assertEqual(rows["Eigen 3.4.0"], 0)


class PeerIdsInTheVocabulary(unittest.TestCase):
    def test_every_peer_id_written_is_declared(self):
        import re
        with open(os.path.join(HERE, "..", "..", "bench", "harness", "vocabulary.hpp"), encoding="utf-8") as f:
            declared = set(re.findall(r'"(peer_[a-z0-9_]+)"', f.read()))
        written = {r["method"] for r in load("accuracy_gsl.json")["peer_records"]}
        written |= {r["method"] for r in load("accuracy_boost_eigen.json")["peer_records"]}
        written |= {r["method"] for r in scipy_doc()["peer_records"]}
        with open(os.path.join(SCRIPTS, "peers", "scipy_driver.py"), encoding="utf-8") as f:
            peers_line = next(line for line in f if line.startswith("PEERS = "))
        written |= set(re.findall(r'"(peer_[a-z0-9_]+)"', peers_line))
        with open(os.path.join(SCRIPTS, "peers", "easing_driver.mjs"), encoding="utf-8") as f:
            written |= set(re.findall(r"^\s*(peer_[a-z0-9_]+):", f.read(), re.M))
        written |= {r["peer"] for r in load(os.path.join("easing", "easing_driver.json"))["runs"]}
        self.assertTrue(written)
        self.assertEqual(written - declared, set())


@unittest.skipUnless(importlib.util.find_spec("scipy"), "the SciPy driver needs python3-scipy")
class ScipyDriver(unittest.TestCase):
    def setUp(self):
        import scipy_driver
        self.d = scipy_driver

    def test_clamped_knots_as_the_spec_documents(self):
        self.assertEqual(list(self.d.clamped_knots(6, 3)), [0, 0, 0, 0, 1 / 3, 2 / 3, 1, 1, 1, 1])

    def test_parameters_are_the_runners(self):
        us = self.d.sample_parameters(0.0, 5.0, 65)
        self.assertEqual((us[0], us[-1], len(set(us))), (0.0, 5.0, 65))
        self.assertEqual(us[1], 5.0 * 0.6180339887498949)

    def test_natural_end_means_zero_second_derivative(self):
        built, reason = self.d.curves({"type": "natural_cubic", "points": [[0, 0], [1, 2], [3, 3], [4, 0]]})
        self.assertIsNone(reason)
        for peer, p, dp, dom in built:
            d2 = dp.derivative()
            for u in dom:
                self.assertLess(abs(d2(u)).max(), 1e-13, peer)


@unittest.skipUnless(importlib.util.find_spec("matplotlib"), "report.py plots with matplotlib")
class ReportWithAndWithoutPeers(unittest.TestCase):
    def run_report(self, acc, peer_files=()):
        return report_fixture.run_report(self, acc, peer_files)

    def test_with_peer_records(self):
        report = self.run_report(load("accuracy_gsl.json"))
        self.assertIn("## Peers: the libraries users would pick instead", report)
        self.assertIn("| GSL 2.7.1 | accuracy runner (always) | 20 |", report)
        self.assertIn("| natural_cubic_2d | peer_gsl_cspline | 0.438 | default | 0.343 |", report)
        self.assertIn("reported success, but its true relative error 5.35e-09", report)

    def test_with_the_scipy_driver_joined(self):
        report = self.run_report(load("accuracy_gsl.json"), [("peers_scipy.json", scipy_doc())])
        self.assertIn("| SciPy 1.10.1, NumPy 1.24.2, Python 3.11.2 | peers_scipy.json (scripts/peers.sh) | 18 |",
                      report)
        self.assertIn("Optional peers that did not run (no reports/peers_<driver>.json; run scripts/peers.sh): "
                      "real Blender F-curves", report)
        self.assertIn("### Real Blender F-curves\n\nNot run: no reports/peers_blender.json", report)
        self.assertIn("### three.js glTF interpolants\n\nNot run: no reports/peers_three.json", report)
        self.assertIn("bezier-easing 3.2.0 / 2.1.0, @mapbox/unitbezier, Babylon.js's BezierCurve.Interpolate and "
                      "lottie-web's BezierEaser (scripts/peers/easing_driver.mjs), ", report)
        self.assertIn("| natural_cubic_knot_ratio_1e4 | peer_scipy_make_interp_spline | 661 | default | 0.813 |",
                      report)
        self.assertIn("| natural_cubic_knot_ratio_1e4 | tol=1e-10 | peer_scipy_quad | 5.35e-09 |", report)

    @unittest.skipUnless(importlib.util.find_spec("mpmath"), "the glTF truth needs python3-mpmath")
    def test_with_the_three_driver_joined(self):
        # The recorded three.js run (tests/data/peers/three, see test_gltf_results.py) measured and
        # rendered by report.py: the table with its figures, and a changed value changes it.
        import gltf_results as gr
        three = os.path.join(DATA, "three")
        with open(os.path.join(three, "three_driver.json"), encoding="utf-8") as f:
            driver = json.load(f)
        specs = {}
        for run in driver["runs"]:
            with open(os.path.join(HERE, "..", "..", "bench", "cases", run["case"] + ".json"), encoding="utf-8") as f:
                specs[run["case"]] = json.load(f)

        def model(run, spec):
            return gr.read_sample(os.path.join(three, run["case"] + ".model.csv"), run["times"],
                                  spec.get("path") == "rotation")
        doc = gr.assemble(driver, specs, model)
        report = self.run_report(load("accuracy_gsl.json"), [("peers_three.json", doc)])
        self.assertIn("| three 0.187.0, Node 20.20.2 | peers_three.json (scripts/peers.sh) | 4 |", report)
        step = next(c for c in doc["cases"] if c["case"] == "gltf_rotation_step")
        self.assertIn(f"| gltf_rotation_step (rotation) | step | DiscreteInterpolant | {step['times']} | "
                      f"{rp.lib.fmt(step['error_eps32'])} | {rp.lib.fmt(step['max_angle_rad'])} | 0 | "
                      f"{rp.lib.fmt(step['vs_model'])} |", report)
        self.assertNotIn("three.js's glTF interpolants (scripts/peers/gltf_driver.mjs)", report)  # it ran
        run = next(r for r in driver["runs"] if r["case"] == "gltf_rotation_step")
        run["values"][-1] = [0.0, 0.0, 0.0, 1.0]  # after the end: the identity instead of the last key
        changed = self.run_report(load("accuracy_gsl.json"), [("peers_three.json", gr.assemble(driver, specs, model))])
        self.assertNotIn(f"| gltf_rotation_step (rotation) | step | DiscreteInterpolant | {step['times']} | "
                         f"{rp.lib.fmt(step['error_eps32'])} |", changed)
        self.assertIn("| gltf_rotation_step (rotation) | step | DiscreteInterpolant |", changed)

    def test_without_peer_records(self):
        acc = copy.deepcopy(load("accuracy_gsl.json"))
        del acc["peer_records"]
        del acc["context"]["peers"]
        report = self.run_report(acc)
        self.assertIn("No peer results (this accuracy.json has no peer_records", report)
        self.assertIn("## Convergence orders", report)


if __name__ == "__main__":
    unittest.main()
