"""scripts/peers/gltf_results.py without Node: the glTF 2.0 sampler truth against closed forms worked
by hand, and a recorded run of scripts/peers/gltf_driver.mjs (three 0.187.0 under Node 20.20.2,
--quick: tests/data/peers/three/three_driver.json, with `curvebench sample` of the same cases at
the same times beside it: <case>.model.csv) joined into the figures REPORT.md shows."""
import copy
import importlib.util
import json
import os
import sys
import unittest

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.join(HERE, "..", "..")
DATA = os.path.join(HERE, "..", "data", "peers", "three")
sys.path.insert(0, os.path.join(ROOT, "scripts"))
sys.path.insert(0, os.path.join(ROOT, "scripts", "peers"))
import report_peers as rp  # noqa: E402


def recorded():
    with open(os.path.join(DATA, "three_driver.json"), encoding="utf-8") as f:
        return json.load(f)


def specs():
    out = {}
    for run in recorded()["runs"]:
        with open(os.path.join(ROOT, "bench", "cases", run["case"] + ".json"), encoding="utf-8") as f:
            out[run["case"]] = json.load(f)
    return out


@unittest.skipUnless(importlib.util.find_spec("mpmath"), "the glTF truth needs python3-mpmath")
class Truth(unittest.TestCase):
    def setUp(self):
        import mpmath
        import gltf_results
        self.g = gltf_results
        self.mp = mpmath

    def scalar(self, interpolation, times, values):
        return self.g.keys_of({"interpolation": interpolation, "times": times, "values": values})

    def test_cubicspline_hermite(self):
        # Keys at 0 and 2 (td = 2): (in, value, out) = (0, 1, 3) and (-1, 5, 0). At s = 1/2 the basis
        # is 1/2, 1/8, 1/2, -1/8: 1/2 + 2 (1/8) 3 + 5/2 + 2 (-1/8)(-1) = 4.
        keys = self.scalar("cubicspline", [0, 2], [0, 1, 3, -1, 5, 0])
        self.assertEqual(self.g.sample("cubicspline", *keys, 0.0), 1)
        self.assertEqual(self.g.sample("cubicspline", *keys, 1.0), 4)
        self.assertEqual(self.g.sample("cubicspline", *keys, 2.0), 5)
        # The tangents are per unit time (the spec multiplies them by td): slope 3 leaving the first
        # key, -1 arriving at the second.
        h = self.mp.mpf(2) ** -100
        with self.mp.workdps(60):
            self.assertLess(abs((self.g.sample("cubicspline", *keys, h) - 1) / h - 3), 1e-25)
            self.assertLess(abs((5 - self.g.sample("cubicspline", *keys, 2 - h)) / h + 1), 1e-25)
        # Clamped outside the keys to the end values, never the tangents.
        self.assertEqual(self.g.sample("cubicspline", *keys, -7.0), 1)
        self.assertEqual(self.g.sample("cubicspline", *keys, 9.0), 5)

    def test_step_and_linear(self):
        keys = self.scalar("step", [0, 1, 3], [2, -4, 8])
        self.assertEqual(self.g.sample("step", *keys, 0.999), 2)
        self.assertEqual(self.g.sample("step", *keys, 1.0), -4)  # the key at t holds from t on
        self.assertEqual(self.g.sample("step", *keys, 3.0), 8)
        self.assertEqual(self.g.sample("step", *keys, -1.0), 2)
        keys = self.scalar("linear", [0, 1, 3], [2, -4, 8])
        self.assertEqual(self.g.sample("linear", *keys, 0.25), 0.5)
        self.assertEqual(self.g.sample("linear", *keys, 2.5), 5)
        self.assertEqual(self.g.sample("linear", *keys, 4.0), 8)

    def test_slerp_takes_the_short_path(self):
        # q' = (0, 0, sin 60, cos 60) stored as -q': at s = 1/2 from the identity the short path
        # ends half-way to q', (0, 0, sin 30, cos 30) (the 4-vectors 90 degrees apart: (0, 0, 0, 1)
        # and (0, 0, 1, 0) meet at (0, 0, 1, 1) / sqrt 2).
        mp = self.mp
        with mp.workdps(60):
            p = (mp.mpf(0), mp.mpf(0), mp.mpf(0), mp.mpf(1))
            q = (mp.mpf(0), mp.mpf(0), -mp.sin(mp.pi / 3), -mp.cos(mp.pi / 3))
            r = self.g.slerp(p, q, mp.mpf(1) / 2)
            for got, want in zip(r, (0, 0, mp.sin(mp.pi / 6), mp.cos(mp.pi / 6))):
                self.assertLess(abs(got - want), 1e-55)
            r = self.g.slerp(p, (mp.mpf(0), mp.mpf(0), mp.mpf(1), mp.mpf(0)), mp.mpf(1) / 2)
            for got, want in zip(r, (0, 0, mp.sqrt(mp.mpf(1) / 2), mp.sqrt(mp.mpf(1) / 2))):
                self.assertLess(abs(got - want), 1e-55)
            self.assertEqual(self.g.slerp(p, p, mp.mpf(1) / 3), p)  # a = 0: the limit

    def test_rotation_keys_and_normalized_cubicspline(self):
        spec = {"interpolation": "cubicspline", "path": "rotation", "times": [0, 1],
                "values": [0, 0, 0, 0, 0, 0, 0, 1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1, 0, 0, 0, 0, 0]}
        keys = self.g.keys_of(spec)
        # Zero tangents, keys (0, 0, 0, 1) and (0, 0, 1, 0): at s = 1/2 both value weights are 1/2, so
        # the Hermite is (0, 0, 1/2, 1/2), normalized to (0, 0, 1, 1) / sqrt 2.
        q = self.g.sample("cubicspline", *keys, 0.5, rotation=True)
        with self.mp.workdps(60):
            for got, want in zip(q, (0, 0, self.mp.sqrt(0.5), self.mp.sqrt(0.5))):
                self.assertLess(abs(got - want), 1e-50)
        with self.assertRaises(self.g.GltfResultError):
            self.g.keys_of(dict(spec, values=spec["values"][:-4]))

    def test_rotation_angle(self):
        mp = self.mp
        q = (0.1, -0.3, 0.05, 0.9486832980505138)
        self.assertEqual(self.g.rotation_angle(q, tuple(-x for x in q)), 0)  # q and -q: one rotation
        self.assertEqual(self.g.rotation_angle(q, tuple(4 * x for x in q)), 0)  # lengths do not count (4 q exact)
        with mp.workdps(60):
            phi = mp.mpf("1e-9")
            r = (0, 0, mp.sin(phi / 2), mp.cos(phi / 2))  # a rotation by phi about z
            self.assertLess(abs(self.g.rotation_angle(r, (0, 0, 0, 1)) / phi - 1), 1e-40)
            self.assertLess(abs(self.g.rotation_angle((0, 0, 1, 0), (0, 0, 0, 1)) - mp.pi), 1e-55)

    def test_float32_rounding(self):
        self.assertEqual(self.g.f32(0.5), 0.5)
        self.assertNotEqual(self.g.f32(0.1), 0.1)
        self.assertEqual(self.g.f32(0.1), 0.100000001490116119384765625)


@unittest.skipUnless(importlib.util.find_spec("mpmath"), "the glTF truth needs python3-mpmath")
class Recorded(unittest.TestCase):
    def setUp(self):
        import gltf_results
        self.g = gltf_results

    def model(self, run, spec):
        return self.g.read_sample(os.path.join(DATA, run["case"] + ".model.csv"), run["times"],
                                  spec.get("path") == "rotation")

    def doc(self, driver=None):
        return self.g.assemble(driver or recorded(), specs(), self.model)

    def test_the_driver_ran_three_loaders_interpolants(self):
        d = recorded()
        self.assertEqual(d["versions"]["three"], "0.187.0")
        runs = {r["case"]: r for r in d["runs"]}
        self.assertEqual({c: r["interpolant"] for c, r in runs.items()},
                         {"gltf_cubicspline": "GLTFCubicSplineInterpolant",
                          "gltf_rotation_cubicspline": "GLTFCubicSplineQuaternionInterpolant",
                          "gltf_rotation_linear": "QuaternionLinearInterpolant",
                          "gltf_rotation_step": "DiscreteInterpolant"})
        sp = specs()
        for case, r in runs.items():
            keys = sp[case]["times"]
            span = keys[-1] - keys[0]
            self.assertTrue(set(keys) <= set(r["times"]), case)  # the keys themselves
            self.assertEqual(r["times"], sorted(set(r["times"])))
            self.assertAlmostEqual(r["times"][0], keys[0] - 0.1 * span)  # beyond the ends: clamped
            self.assertAlmostEqual(r["times"][-1], keys[-1] + 0.1 * span)
            # three's result buffer is a Float32Array: every value is a float32
            for v in r["values"]:
                self.assertEqual([self.g.f32(x) for x in v], v)

    def test_figures(self):
        doc = self.doc()
        self.assertEqual(doc["driver"], "three")
        rows = {c["case"]: c for c in doc["cases"]}
        self.assertEqual(len(rows), 4)
        for case, c in rows.items():
            # float32 storage of the keys and of the result: about one float32 ulp, never more than two
            self.assertLess(c["error_eps32"], 2, case)
            self.assertLess(c["vs_float32_keys_eps32"], 1, case)
            self.assertLess(c["vs_model"], 1e-6, case)
        # STEP returns the stored float32 key: exact against the float32 keys, not against the doubles
        self.assertEqual(rows["gltf_rotation_step"]["vs_float32_keys_eps32"], 0)
        self.assertGreater(rows["gltf_rotation_step"]["error_eps32"], 0)
        self.assertEqual(rows["gltf_cubicspline"]["max_abs_yz"], 0)  # y and z of the translation stay 0
        self.assertGreater(rows["gltf_rotation_linear"]["max_angle_rad"], 0)
        recs = {r["case"]: r for r in doc["peer_records"]}
        for case, r in recs.items():
            self.assertEqual(r["library"], "three 0.187.0")
            self.assertEqual(r["method"], self.g.PEER)
            self.assertLess(r["counterpart_error"], 8, case)  # curvebench's double model: a few eps(double)
            # the record's eps(double) x size is the row's eps(float32) x size in float32's unit
            self.assertAlmostEqual(r["error"] * 2.0 ** -52 / r["unit_eps"], rows[case]["error_eps32"], delta=1e-9)
        self.assertEqual(rp.findings(doc["peer_records"]), [])  # float32 rounding is no finding

    def test_a_wrong_value_is_measured(self):
        d = recorded()
        run = next(r for r in d["runs"] if r["case"] == "gltf_cubicspline")
        i = run["times"].index(1.0) if 1.0 in run["times"] else len(run["times"]) // 2
        run["values"][i][0] += 1e-3
        row = next(c for c in self.doc(d)["cases"] if c["case"] == "gltf_cubicspline")
        self.assertGreater(row["max_abs_error"], 9e-4)
        self.assertEqual(row["worst_time"], run["times"][i])
        d = recorded()
        run = next(r for r in d["runs"] if r["case"] == "gltf_rotation_linear")
        i = run["times"].index(1.25)  # a key: (-0.430, -0.860, -0.215, 0.174)
        run["values"][i] = [-x for x in run["values"][i]]  # the same rotation: no error added
        base = next(c for c in self.doc()["cases"] if c["case"] == "gltf_rotation_linear")
        flipped = next(c for c in self.doc(d)["cases"] if c["case"] == "gltf_rotation_linear")
        self.assertEqual(flipped["max_angle_rad"], base["max_angle_rad"])
        run["values"][i] = [run["values"][i][1], run["values"][i][0]] + run["values"][i][2:]
        self.assertGreater(next(c for c in self.doc(d)["cases"] if c["case"] == "gltf_rotation_linear")
                           ["max_angle_rad"], 1e-3)

    def test_malformed(self):
        d = recorded()
        d["runs"][0]["values"].pop()
        with self.assertRaises(self.g.GltfResultError):
            self.doc(d)
        with self.assertRaises(self.g.GltfResultError):
            self.g.assemble({"runs": []}, {})
        run = recorded()["runs"][0]
        with self.assertRaises(self.g.GltfResultError):
            self.g.read_sample(os.path.join(DATA, run["case"] + ".model.csv"), run["times"][:-1], False)
        with self.assertRaises(self.g.GltfResultError):  # a scalar case's CSV read as a rotation
            self.g.read_sample(os.path.join(DATA, run["case"] + ".model.csv"), run["times"], True)

    def test_report_table(self):
        doc = self.doc()
        md = "\n".join(rp.three_lines([("peers_three.json", doc)]))
        self.assertIn("### three.js glTF interpolants", md)
        self.assertIn("three 0.187.0's GLTFLoader", md)
        row = next(c for c in doc["cases"] if c["case"] == "gltf_rotation_linear")
        self.assertIn(f"| gltf_rotation_linear (rotation) | linear | QuaternionLinearInterpolant | {row['times']} | "
                      f"{rp.lib.fmt(row['error_eps32'])} | {rp.lib.fmt(row['max_angle_rad'])} |", md)
        self.assertIn("| gltf_cubicspline | cubicspline | GLTFCubicSplineInterpolant |", md)
        self.assertIn("up to float32 storage of the keys and of the result", md)
        # A mutated value changes the table (and withdraws the sentence that three is only storage).
        mutated = copy.deepcopy(doc)
        c = next(c for c in mutated["cases"] if c["case"] == "gltf_rotation_linear")
        c["error_eps32"], c["vs_float32_keys_eps32"] = 512.0, 300.0
        md2 = "\n".join(rp.three_lines([("peers_three.json", mutated)]))
        self.assertNotEqual(md, md2)
        self.assertIn("| 512 |", md2)
        self.assertNotIn("up to float32 storage", md2)
        self.assertIn("the largest error is 512 eps(float32)", md2)
        self.assertEqual(rp.three_lines([]), ["", "### three.js glTF interpolants", "",
                                              "Not run: no reports/peers_three.json (scripts/peers.sh runs it when "
                                              "build-peers/node has three)."])


class Vocabulary(unittest.TestCase):
    def test_peer_id_is_declared(self):
        with open(os.path.join(ROOT, "bench", "harness", "vocabulary.hpp"), encoding="utf-8") as f:
            text = f.read()
        with open(os.path.join(ROOT, "scripts", "peers", "gltf_results.py"), encoding="utf-8") as f:
            peer = next(line for line in f if line.startswith("PEER = ")).split('"')[1]
        self.assertIn(f'"{peer}"', text)

    def test_three_is_pinned(self):
        with open(os.path.join(ROOT, "scripts", "peers", "node", "package.json"), encoding="utf-8") as f:
            self.assertEqual(json.load(f)["dependencies"]["three"], "0.187.0")


if __name__ == "__main__":
    unittest.main()
