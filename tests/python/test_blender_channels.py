"""scripts/peers/blender_channels.py without Blender: the request holds the channel cases an F-curve
can hold (and says why the others are left out), and a recorded run (Blender 3.4.1 from Debian
bookworm on the --quick request: tests/data/peers/blender/blender.json, with `curvebench sample`
of the Blender model beside it) joins into the figures REPORT.md shows."""
import importlib.util
import json
import os
import sys
import unittest

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.join(HERE, "..", "..")
DATA = os.path.join(HERE, "..", "data", "peers", "blender")
sys.path.insert(0, os.path.join(ROOT, "scripts"))
sys.path.insert(0, os.path.join(ROOT, "scripts", "peers"))
import blender_channels as bc  # noqa: E402
import blender_fcurves as bf  # noqa: E402
import report_peers as rp  # noqa: E402


def cases():
    specs = {}
    d = os.path.join(ROOT, "bench", "cases")
    for f in sorted(os.listdir(d)):
        if f.endswith(".json"):
            with open(os.path.join(d, f), encoding="utf-8") as fh:
                specs[f[:-5]] = json.load(fh)
    return specs


def recorded():
    with open(os.path.join(DATA, "blender.json"), encoding="utf-8") as f:
        return json.load(f)


def model(case, times):
    path = os.path.join(DATA, case + ".model.csv")
    return bc.read_model(path, times) if os.path.exists(path) else None


class Request(unittest.TestCase):
    def test_cases_and_reasons(self):
        req, models, notes = bc.request(cases(), quick=True)
        bf.check_request(req)  # what blender_fcurves.py accepts
        names = [c["name"] for c in req["channels"]]
        self.assertIn("blender_auto_clamped", names)
        self.assertIn("channel_regression_limit", names)
        self.assertNotIn("css_overshoot", names)
        self.assertTrue(any(n.startswith("channel_holds: not run in Blender (keys[2].interpolation step_next")
                            for n in notes), notes)
        self.assertEqual(set(models), set(names))
        for ch in req["channels"]:
            self.assertEqual(len(ch["times"]), 65 + 32)
        # The recorded run is this request's output.
        rec = recorded()
        self.assertEqual([c["name"] for c in rec["channels"]], names)
        for got, asked in zip(rec["channels"], req["channels"]):
            self.assertEqual(got["times"], asked["times"])

    def test_exact_keys_become_free_handles(self):
        spec = {"type": "channel", "tool": "exact", "keys": [
            {"time": 0, "value": 0, "interpolation": "bezier", "out": [1, 0.5]},
            {"time": 3, "value": 1.5, "interpolation": "linear", "in": [-1, 0]}, {"time": 4, "value": 1}],
            "before": "linear", "after": "linear"}
        ch, m = bc.channel_of("c", spec)
        self.assertEqual(ch["keys"][0]["handle_right"], [1, 0.5])
        self.assertEqual(ch["keys"][0]["handle_left"], [0, 0])  # no in handle: zero length
        self.assertEqual(ch["keys"][1]["handle_left"], [2, 1.5])
        self.assertEqual(ch["keys"][1]["interpolation"], "LINEAR")
        self.assertEqual(ch["extrapolation"], "LINEAR")
        self.assertEqual(m["tool"], "blender")
        self.assertEqual(m["keys"][1]["handle_left_type"], "free")
        self.assertEqual(bc.channel_of("c", dict(spec, after="cycle")),
                         (None, "extrapolation before linear / after cycle"))

    def test_blender_case_keeps_its_rules(self):
        ch, m = bc.channel_of("b", cases()["blender_auto_clamped"])
        self.assertEqual(ch["auto_smoothing"], "CONT_ACCEL")
        self.assertEqual(ch["extrapolation"], "LINEAR")
        self.assertEqual({k["handle_left_type"] for k in ch["keys"]}, {"AUTO_CLAMPED"})
        self.assertEqual(m, cases()["blender_auto_clamped"])


@unittest.skipUnless(importlib.util.find_spec("mpmath"), "the exact keys need python3-mpmath")
class Recorded(unittest.TestCase):
    def test_truth(self):
        # A straight segment (handles on the chord at thirds): the value is linear in time.
        keys = [{"time": 0.0, "value": 0.0, "interpolation": "BEZIER", "handle_right": [1.0, 2.0]},
                {"time": 3.0, "value": 6.0, "interpolation": "BEZIER", "handle_left": [2.0, 4.0]}]
        for t in (0.0, 0.7, 1.5, 3.0):
            self.assertLess(abs(bc.truth(keys, t) - 2 * t), 1e-50)
        self.assertIsNone(bc.truth(keys, 3.5))
        keys[0]["handle_right"] = [5.0, 2.0]  # time runs backwards inside the segment
        self.assertIsNone(bc.truth(keys, 1.0))

    def test_figures(self):
        doc = bc.assemble(recorded(), model, ["n"])
        self.assertEqual(doc["versions"], {"Blender": "3.4.1"})
        rows = {c["case"]: c for c in doc["channels"]}
        # Blender and curvebench's model of it agree to float rounding on every case.
        for case, c in rows.items():
            self.assertLess(c["vs_model"], 1e-5, case)
        # Handles at the regression limit: Blender corrects them before evaluating, the exact keys
        # do not; everywhere else Blender is float rounding away from the exact keys.
        self.assertGreater(rows["channel_regression_limit"]["vs_exact"], 0.1)
        self.assertLess(rows["blender_auto_clamped"]["vs_exact"], 1e-5)
        self.assertLess(rows["channel_far_frames"]["vs_exact"], 1e-5)
        recs = {r["case"]: r for r in doc["peer_records"]}
        f = rp.findings(doc["peer_records"])
        self.assertTrue(any(x.startswith("peer_blender_fcurve on channel_regression_limit: error") for x in f), f)
        self.assertFalse(any("blender_auto_clamped" in x for x in f), f)  # float rounding is no finding
        self.assertEqual(recs["channel_regression_limit"]["library"], "Blender 3.4.1")
        md = "\n".join(rp.blender_lines([("peers_blender.json", doc)]))
        self.assertIn("| channel_regression_limit | 3.4.1 | 97 | 65 |", md)

    def test_malformed(self):
        bad = recorded()
        bad["channels"][0]["values"] = bad["channels"][0]["values"][:-1]
        with self.assertRaises(bc.BlenderChannelError):
            bc.assemble(bad, model)
        with self.assertRaises(bc.BlenderChannelError):
            bc.assemble({"channels": []}, model)
        with self.assertRaises(bc.BlenderChannelError):
            bc.read_model(os.path.join(DATA, "channel_cusp.model.csv"), [0.0])


class Vocabulary(unittest.TestCase):
    def test_peer_id_is_declared(self):
        with open(os.path.join(ROOT, "bench", "harness", "vocabulary.hpp"), encoding="utf-8") as f:
            self.assertIn(f'"{bc.PEER}"', f.read())


if __name__ == "__main__":
    unittest.main()
