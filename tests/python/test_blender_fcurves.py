"""scripts/peers/blender_fcurves.py without Blender: the request checker names bad fields by their
path, the writer keeps float32 values exact and writes a document json reads back, the easing
request covers every family x easing, and the recorded fixtures were produced from their requests
(blender_easing.json, blender_fcurves.json, blender_heldout.json)."""
import json
import os
import sys
import tempfile
import unittest

ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..")
sys.path.insert(0, os.path.join(ROOT, "scripts", "peers"))

import blender_easing_request  # noqa: E402
import blender_fcurves as bf  # noqa: E402
import blender_fcurves_request  # noqa: E402


def channel(**over):
    ch = {"name": "c", "keys": [{"time": 0, "value": 1, "interpolation": "QUAD", "easing": "EASE_IN"},
                                {"time": 4, "value": 3}], "times": [0, 1, 2]}
    ch.update(over)
    return ch


class CheckRequest(unittest.TestCase):
    def test_defaults_filled(self):
        channels, note = bf.check_request([channel()])
        self.assertIsNone(note)
        self.assertEqual(channels[0]["keys"][1]["interpolation"], "BEZIER")
        self.assertEqual(channels[0]["keys"][1]["easing"], "AUTO")
        self.assertEqual(channels[0]["extrapolation"], "CONSTANT")
        self.assertEqual(channels[0]["times"], [0.0, 1.0, 2.0])

    def test_object_form_keeps_note_and_cycles(self):
        channels, note = bf.check_request({"note": "n", "channels": [channel(cycles={"mode_after": "MIRROR"})]})
        self.assertEqual(note, "n")
        self.assertEqual(channels[0]["cycles"], {"mode_before": "REPEAT", "mode_after": "MIRROR",
                                                 "cycles_before": 0, "cycles_after": 0})

    def test_errors_name_the_field(self):
        cases = [
            ([channel(times=[0, float("nan")])], "channels[0].times[1] = nan: expected a finite number"),
            ([channel(keys=[{"time": 0, "value": 1, "interpolation": "SMOOTH"}])],
             "channels[0].keys[0].interpolation = 'SMOOTH': expected one of CONSTANT"),
            ([channel(keys=[{"time": 0, "value": 1, "handle_left": [1]}])],
             "channels[0].keys[0].handle_left = [1]: expected [time, value]"),
            ([channel(keys=[{"time": 0, "value": 1, "bounce": 2}])], "channels[0].keys[0].bounce: unknown field"),
            ([channel(extrapolation="CYCLIC")], "channels[0].extrapolation = 'CYCLIC'"),
            ([channel(auto_smoothing="SMOOTH")], "channels[0].auto_smoothing = 'SMOOTH': expected one of NONE"),
            ([], "channels: expected a non-empty list"),
            ([channel(keys=[{"time": True, "value": 1}])], "channels[0].keys[0].time = True"),
        ]
        for data, words in cases:
            with self.assertRaises(bf.RequestError) as e:
                bf.check_request(data)
            self.assertIn(words, str(e.exception))

    def test_auto_smoothing_is_optional(self):
        channels, _ = bf.check_request([channel(), channel(auto_smoothing="NONE")])
        self.assertNotIn("auto_smoothing", channels[0])
        self.assertEqual(channels[1]["auto_smoothing"], "NONE")

    def test_script_arguments(self):
        self.assertEqual(bf.script_arguments(["blender", "-b", "--python", "x.py", "--", "a", "b"]), ["a", "b"])
        with self.assertRaises(bf.RequestError):
            bf.script_arguments(["blender", "--", "a"])


class WriteResult(unittest.TestCase):
    def test_float32_values_round_trip(self):
        # 1.70158 stored as float32 reads back as this double; the file must keep every digit.
        v = 1.7015800476074219
        doc = bf.result_document("3.4.1", "note", [{"name": "c", "times": [0.1], "values": [v, 1e-45]}])
        with tempfile.TemporaryDirectory() as d:
            path = os.path.join(d, "out.json")
            bf.write_result(path, doc)
            with open(path, encoding="utf-8") as f:
                back = json.load(f)
        self.assertEqual(back, doc)
        self.assertEqual(back["channels"][0]["values"][0], v)


class EasingFixture(unittest.TestCase):
    def test_request_covers_every_family_and_easing(self):
        req = blender_easing_request.request()
        bf.check_request(req)
        seen = {(ch["keys"][0]["interpolation"], ch["keys"][0]["easing"]) for ch in req["channels"]}
        self.assertEqual(len(seen), 10 * 4)

    def test_fixture_is_the_recorded_output_of_the_request(self):
        with open(os.path.join(ROOT, "tests", "data", "blender_easing.json"), encoding="utf-8") as f:
            fixture = json.load(f)
        req = blender_easing_request.request()
        self.assertEqual(fixture["note"], req["note"])
        self.assertEqual([c["name"] for c in fixture["channels"]], [c["name"] for c in req["channels"]])
        for rec, asked in zip(fixture["channels"], req["channels"]):
            self.assertEqual(rec["times"], asked["times"])
            self.assertEqual(len(rec["values"]), len(asked["times"]))


class FcurvesFixture(unittest.TestCase):
    def test_request_is_valid_and_covers_the_rules(self):
        req = blender_fcurves_request.request()
        channels, _ = bf.check_request(req)
        names = [c["name"] for c in channels]
        for prefix in ("handles/auto/", "handles/auto_clamped/", "handles/vector/", "handles/aligned/", "free/",
                       "mixed_interpolation/", "cycles/"):
            self.assertTrue(any(n.startswith(prefix) for n in names), prefix)
        self.assertEqual({c.get("auto_smoothing") for c in channels}, {None, "NONE", "CONT_ACCEL"})

    def test_fixture_is_the_recorded_output_of_the_request(self):
        with open(os.path.join(ROOT, "tests", "data", "blender_fcurves.json"), encoding="utf-8") as f:
            fixture = json.load(f)
        req = blender_fcurves_request.request()
        self.assertEqual(fixture["note"], req["note"])
        self.assertEqual([c["name"] for c in fixture["channels"]], [c["name"] for c in req["channels"]])
        for rec, asked in zip(fixture["channels"], req["channels"]):
            self.assertEqual(rec["times"], asked["times"])
            self.assertEqual(len(rec["values"]), len(asked["times"]))
            self.assertEqual(len(rec["keys"]), len(asked["keys"]))
            if "auto_smoothing" in asked:
                self.assertEqual(rec["auto_smoothing"], asked["auto_smoothing"])


class HeldoutFixture(unittest.TestCase):
    def test_fixture_is_the_recorded_output_of_the_heldout_request(self):
        with open(os.path.join(ROOT, "tests", "data", "recorded", "blender_heldout.json"), encoding="utf-8") as f:
            fixture = json.load(f)
        req = blender_fcurves_request.heldout_request()
        channels, _ = bf.check_request(req)
        self.assertEqual(fixture["tool"], "blender")
        self.assertEqual(fixture["source"]["command"], blender_fcurves_request.HELDOUT_COMMAND)
        self.assertEqual([c["name"] for c in fixture["channels"]], [c["name"] for c in channels])
        for rec, asked in zip(fixture["channels"], channels):
            self.assertEqual(rec["t"], asked["times"])
            self.assertEqual(rec["features"], asked["features"])
            self.assertEqual(len(rec["value"]), len(asked["times"]))
            self.assertEqual(len(rec["spec"]["keys"]), len(asked["keys"]))
            self.assertEqual(rec["spec"]["extrapolation"], asked["extrapolation"].lower())

    def test_fixture_is_the_recorded_output_of_the_mixed_request(self):
        with open(os.path.join(ROOT, "tests", "data", "recorded", "blender_mixed.json"), encoding="utf-8") as f:
            fixture = json.load(f)
        channels, _ = bf.check_request(blender_fcurves_request.mixed_request())
        self.assertEqual(fixture["source"]["command"], blender_fcurves_request.MIXED_COMMAND)
        self.assertEqual([c["name"] for c in fixture["channels"]], [c["name"] for c in channels])
        for rec, asked in zip(fixture["channels"], channels):
            self.assertEqual(rec["t"], asked["times"])
            self.assertEqual(rec["features"], asked["features"])
            self.assertEqual(len(rec["spec"]["keys"]), len(asked["keys"]))
            self.assertEqual([k["handle_left_type"] for k in rec["spec"]["keys"]],
                             [k["handle_left_type"].lower() for k in asked["keys"]])


class RefreshRefusals(unittest.TestCase):
    """--refresh-refusals re-asks curvebench (here a stand-in CLI that refuses specs whose first key
    is at time 1) and rewrites only the "refused" members: a stale one dropped, a new one recorded."""

    def test_a_stale_refusal_is_dropped_and_a_new_one_recorded(self):
        with tempfile.TemporaryDirectory() as d:
            cli = os.path.join(d, "curvebench")
            with open(cli, "w", encoding="utf-8") as f:
                f.write("#!/bin/sh\ngrep -q '\"time\": 1' \"$2\" && { echo 'curvebench: error: no' >&2; exit 1; }\n"
                        "exit 0\n")
            os.chmod(cli, 0o755)
            doc = {"tool": "blender", "source": {"version": "x"}, "channels": [
                {"name": "was_refused", "spec": {"keys": [{"time": 0}]}, "t": [0.5], "value": [1.0],
                 "refused": "curvebench: error: old"},
                {"name": "now_refused", "spec": {"keys": [{"time": 1}]}, "t": [1.5], "value": [2.0]}]}
            path = os.path.join(d, "rec.json")
            bf.write_result(path, doc)
            self.assertEqual(bf.refresh_refusals(path, cli), (1, 1))
            with open(path, encoding="utf-8") as f:
                out = json.load(f)
            self.assertNotIn("refused", out["channels"][0])
            self.assertEqual(out["channels"][1]["refused"], "curvebench: error: no")
            self.assertEqual(out["channels"][1]["value"], [2.0])
            self.assertEqual(bf.refresh_refusals(path, cli), (0, 0))


if __name__ == "__main__":
    unittest.main()
