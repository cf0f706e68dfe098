"""scripts/peers/chromium_driver.py and the steps() part of easing_results.py without Chromium: the
page asks for what the cases hold, the recorded dump of a real run (headless Chromium 156 from
Debian bookworm, --quick: tests/data/peers/chromium/dump_quick.html) parses into runs at the
requested fractions, malformed results are refused, and the measured figures of that run hold."""
import importlib.util
import json
import os
import sys
import unittest

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.join(HERE, "..", "..")
sys.path.insert(0, os.path.join(ROOT, "scripts"))
sys.path.insert(0, os.path.join(ROOT, "scripts", "peers"))
import chromium_driver as cd  # noqa: E402
import report_peers as rp  # noqa: E402
import peer_io  # noqa: E402

DUMP = os.path.join(HERE, "..", "data", "peers", "chromium", "dump_quick.html")


def css_specs():
    specs = {}
    cases = os.path.join(ROOT, "bench", "cases")
    for f in sorted(os.listdir(cases)):
        if f.startswith("css_") and f.endswith(".json"):
            with open(os.path.join(cases, f), encoding="utf-8") as fh:
                specs[f[:-5]] = json.load(fh)
    return specs


def recorded():
    easings = cd.easings_of(css_specs(), peer_io.sample_fractions(65))
    with open(DUMP, encoding="utf-8") as f:
        return easings, cd.runs_of(cd.parse_dump(f.read()), easings)


class Page(unittest.TestCase):
    def test_easings_and_times(self):
        specs = dict(css_specs(), other={"type": "bezier", "points": [[0, 0], [1, 1]]},
                     lin={"type": "channel", "tool": "css", "easing": "linear(0, 0.5, 1)"})
        easings = cd.easings_of(specs, peer_io.sample_fractions(65))
        names = [c for c, _, _ in easings]
        self.assertIn("css_wild_overshoot", names)
        self.assertNotIn("other", names)
        self.assertNotIn("lin", names)  # linear() is not among the easings this driver measures
        self.assertEqual(names[-len(cd.STEPS):], [cd.steps_case(e) for e in cd.STEPS])
        self.assertEqual(cd.steps_case("steps(4, jump-end)"), "steps_4_jump_end")
        steps3 = dict((c, t) for c, _, t in easings)["steps_3_jump_both"]
        for k in range(4):
            self.assertIn(k / 3, steps3)
        self.assertEqual(steps3, sorted(set(steps3)))
        html = cd.page(easings)
        self.assertIn(f'<pre id="{cd.RESULT_ID}">', html)
        self.assertIn('"cubic-bezier(0, 4, 1, -3)"', html)
        self.assertIn("1048576.0", html)

    def test_parsers(self):
        self.assertEqual(cd.parse_cubic_bezier("cubic-bezier(0, 4, 1, -3)"), [0.0, 4.0, 1.0, -3.0])
        self.assertIsNone(cd.parse_cubic_bezier("cubic-bezier(0, 4, 1)"))
        self.assertEqual(cd.parse_steps("steps(3)"), (3, "jump-end"))
        self.assertEqual(cd.parse_steps("steps(2, start)"), (2, "jump-start"))
        self.assertIsNone(cd.parse_steps("steps(2, sideways)"))
        self.assertEqual(cd.chromium_version("Chromium 156.0.8078.79 built on Debian GNU/Linux 12 (bookworm)\n"),
                         "156.0.8078.79")
        with self.assertRaises(cd.ChromiumDriverError):
            cd.chromium_version("Google Chrome for Testing")


class Vocabulary(unittest.TestCase):
    def test_peer_id_is_declared(self):
        with open(os.path.join(ROOT, "bench", "harness", "vocabulary.hpp"), encoding="utf-8") as f:
            self.assertIn(f'"{cd.PEER}"', f.read())


class Dump(unittest.TestCase):
    def test_recorded_dump_parses_at_the_requested_fractions(self):
        easings, runs = recorded()
        self.assertEqual(len(runs), len(easings))
        for (case, easing, times), run in zip(easings, runs):
            self.assertEqual(run["case"], case)
            # Blink evaluated where the driver asked, up to the last bits its time conversions cost
            # (localTime / duration is not always x itself: the truth is taken at what Blink reports).
            for x, bx in zip(times, run["times"]):
                self.assertLessEqual(abs(x - bx), 4 * 2.0 ** -52 * max(x, 2.0 ** -20), (case, x, bx))
            self.assertEqual(run["times"][0], 0.0)
            self.assertEqual(run["times"][-1], 1.0)
            self.assertEqual(len(run["values"]), len(times))
            self.assertEqual("steps" in run, easing.startswith("steps("))

    def test_malformed_results_are_refused(self):
        easings, _ = recorded()
        with open(DUMP, encoding="utf-8") as f:
            doc = cd.parse_dump(f.read())
        bad = json.loads(json.dumps(doc))
        bad["results"][0]["progress"][3] = None
        with self.assertRaisesRegex(cd.ChromiumDriverError, "query 3"):
            cd.runs_of(bad, easings)
        bad = json.loads(json.dumps(doc))
        bad["results"][1]["case"] = "elsewhere"
        with self.assertRaisesRegex(cd.ChromiumDriverError, "elsewhere"):
            cd.runs_of(bad, easings)
        with self.assertRaisesRegex(cd.ChromiumDriverError, "expected"):
            cd.runs_of(doc, easings[:-1])
        with self.assertRaisesRegex(cd.ChromiumDriverError, "no result"):
            cd.parse_dump('<html><body><pre id="curvebench-result"></pre></body></html>')
        with self.assertRaisesRegex(cd.ChromiumDriverError, "script failed: TypeError"):
            cd.parse_dump('<pre id="curvebench-result">{"error": "TypeError: x"}</pre>')


@unittest.skipUnless(importlib.util.find_spec("mpmath"), "the easing truth needs python3-mpmath")
class Measured(unittest.TestCase):
    def setUp(self):
        import easing_results
        self.er = easing_results

    def test_steps_definition(self):
        t = self.er.steps_truth
        self.assertEqual(t(4, "jump-start", 0.0), 0.25)
        self.assertEqual(t(4, "jump-end", 0.0), 0)
        self.assertEqual(t(4, "jump-end", 1.0), 1)
        self.assertEqual(t(5, "jump-none", 1.0), 1)
        self.assertEqual(t(5, "jump-none", 0.2), 0.25)
        self.assertEqual(t(3, "jump-both", 0.0), 0.25)
        self.assertEqual(t(3, "jump-both", 1.0), 1)
        # The double 0.6 is below 3/5: the step before the boundary.
        self.assertEqual(t(5, "jump-none", 0.6), 0.5)
        with self.assertRaises(self.er.EasingResultError):
            t(1, "jump-none", 0.5)

    def test_recorded_run(self):
        _, runs = recorded()
        specs = css_specs()
        driver = {"driver": "chromium", "versions": {"Chromium": "156.0.8078.79"}, "runs": runs}
        doc = self.er.assemble(driver, specs, lambda case, times: None)
        recs = {r["case"]: r for r in doc["peer_records"]}
        self.assertEqual(recs["css_wild_overshoot"]["library"], "Chromium 156.0.8078.79")
        # Blink's cubic-bezier: within its unit tests' 1.5e-4, and not at double precision (its
        # solver stops at about 1e-7 in x).
        for case in specs:
            self.assertLess(recs[case]["abs_error"], 1.5e-4, case)
            self.assertGreater(recs[case]["abs_error"], 1e-9, case)
        # steps(): exact where x n is exact; a whole step off at the doubles just below k / n whose
        # product rounds up to k (0.6 x 5, 0.3 x 10), named in the notes.
        self.assertEqual(recs["steps_4_jump_end"]["error"], 0)
        self.assertEqual(recs["steps_4_jump_start"]["error"], 0)
        self.assertAlmostEqual(recs["steps_5_jump_none"]["abs_error"], 0.25)
        self.assertAlmostEqual(recs["steps_10_jump_end"]["abs_error"], 0.1)
        note = next(n for n in doc["notes"] if n.startswith("steps_10_jump_end (peer_chromium_waapi)"))
        self.assertIn("x = 0.3 ", note)
        findings = rp.findings(doc["peer_records"])
        self.assertTrue(any(f.startswith("peer_chromium_waapi on steps_5_jump_none: error") and
                            "against CSS steps(5, jump-none) as CSS Easing defines it, at 50 digits" in f
                            for f in findings))
        self.assertFalse(any("steps_4_jump_end" in f for f in findings))


if __name__ == "__main__":
    unittest.main()
