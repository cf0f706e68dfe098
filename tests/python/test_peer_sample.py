"""The optional peers' `curvebench sample` of curvebench's own tool models, with the tool itself
(CURVEBENCH_TOOL; ctest peer_sample): scripts/peers/peer_io.py's command and reader. The readers
were tested on recorded CSVs only, so when `sample` began printing the 50-digit truth by default
(the model's own evaluation moved to --as-tool) under a first '#' line, every peer with a model
beside it (Blender, d3-ease, the CSS easings, three.js) failed or would have compared the truth."""
import os
import subprocess
import sys
import tempfile
import unittest

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "..", "scripts", "peers"))
import peer_io  # noqa: E402

CASES = os.path.join(HERE, "..", "..", "bench", "cases")
TOOL = os.environ.get("CURVEBENCH_TOOL")


def float_digits(x):
    """Whether x was printed to float's 9 digits (sample prints a float model so, a double one to 17)."""
    return float(f"{x:.9g}") == x


@unittest.skipUnless(TOOL, "needs CURVEBENCH_TOOL (ctest peer_sample sets it)")
class ModelSamples(unittest.TestCase):
    def sample(self, case, times, as_tool=True, columns=("value",), exact_times=True, commented=True):
        d = tempfile.mkdtemp()
        path = os.path.join(d, "t.times")
        with open(path, "w", encoding="utf-8") as f:
            f.write("".join(repr(t) + "\n" for t in times))
        out = os.path.join(d, "s.csv")
        with open(out, "w", encoding="utf-8") as f:
            subprocess.run(peer_io.sample_command(TOOL, os.path.join(CASES, case + ".json"), path, as_tool),
                           stdout=f, check=True, timeout=120)
        with open(out, encoding="utf-8") as f:  # what the reader skips (a rotation's CSV has none)
            self.assertEqual(f.readline().startswith("# curvebench sample: "), commented)
        return peer_io.read_sample(out, times, columns, exact_times=exact_times)

    def test_the_blender_model_is_sampled_in_float_as_blender_evaluates(self):
        times = [0.1 + 0.37 * k for k in range(40)]
        model = self.sample("blender_auto_clamped", times, exact_times=False)
        self.assertEqual(len(model), len(times))
        self.assertTrue(all(float_digits(v) for v in model), model[:5])
        # Without --as-tool: the truth of the keys in double, which float cannot hold.
        truth = self.sample("blender_auto_clamped", times, as_tool=False)
        self.assertFalse(all(float_digits(v) for v in truth))
        # Both the same channel: the float model within float's rounding of its range of the truth.
        span = max(truth) - min(truth)
        self.assertLess(max(abs(a - b) for a, b in zip(model, truth)), 1e-5 * span)

    def test_a_css_easing_is_read_at_the_very_times_asked(self):
        times = [k / 64 for k in range(65)]
        values = self.sample("css_overshoot", times)
        self.assertEqual(values[0], 0.0)
        self.assertEqual(values[-1], 1.0)

    def test_a_gltf_rotation_has_four_columns_and_no_as_tool(self):
        times = [0.0, 0.25, 0.5]
        q = self.sample("gltf_rotation_linear", times, as_tool=False, columns=("x", "y", "z", "w"),
                        commented=False)
        self.assertEqual(len(q), 3)
        for x, y, z, w in q:
            self.assertAlmostEqual(x * x + y * y + z * z + w * w, 1.0, places=12)

    def test_a_wrong_header_or_count_names_the_file(self):
        d = tempfile.mkdtemp()
        path = os.path.join(d, "x.csv")
        with open(path, "w", encoding="utf-8") as f:
            f.write("# what\nt,value,dvalue\n0,1,2\n")
        with self.assertRaisesRegex(ValueError, "x.csv: expected the header t,value, not t,value,dvalue"):
            peer_io.read_sample(path, [0.0])
        with open(path, "w", encoding="utf-8") as f:
            f.write("t,value\n0,1\n")
        with self.assertRaisesRegex(ValueError, "x.csv: 1 rows for 2 times"):
            peer_io.read_sample(path, [0.0, 1.0])


if __name__ == "__main__":
    unittest.main()
