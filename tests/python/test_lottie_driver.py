"""scripts/peers/lottie_driver.py: the Lottie document and page ask for what the segments hold, the
recorded dump of a real run (lottie-web 5.13.0 in headless Chromium 156 from Debian bookworm:
tests/data/peers/lottie/dump.html) parses into the layer's positions at the requested frames,
malformed results are refused; with the tool (CURVEBENCH_TOOL; ctest lottie) the recorded positions
measured against the exact motion keep their figures."""
import json
import os
import shutil
import sys
import tempfile
import unittest

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "..", "scripts", "peers"))
import lottie_driver as ld  # noqa: E402

DUMP = os.path.join(HERE, "..", "data", "peers", "lottie", "dump.html")
TOOL = os.environ.get("CURVEBENCH_TOOL")


def recorded_doc():
    with open(DUMP, encoding="utf-8") as f:
        return ld.parse_dump(f.read())


class Document(unittest.TestCase):
    def test_keys_tangents_and_easing(self):
        anim = ld.animation()
        layer = anim["layers"][0]
        self.assertEqual(layer["ln"], ld.LAYER_ID)
        keys = layer["ks"]["p"]["k"]
        self.assertEqual(len(keys), len(ld.SEGMENTS) + 1)
        self.assertEqual(keys[-1], {"t": 4 * ld.SEGMENT_FRAMES, "s": [56, 456, 0]})
        arch = keys[0]
        self.assertEqual((arch["t"], arch["s"], arch["to"], arch["ti"]),
                         (0, [56, 256, 0], [120, -160, 0], [-120, -160, 0]))
        self.assertEqual((arch["o"], arch["i"]), ({"x": 0.8, "y": 0}, {"x": 0.2, "y": 1}))
        # The spatial Bezier of a segment: A, A + to (A's out tangent), B + ti (B's in tangent), B.
        self.assertEqual(ld.bezier_points(0), [[56, 256], [176, 96], [336, 96], [456, 256]])
        self.assertEqual(ld.bezier_points(2), [[256, 456], [556, 356], [-44, 156], [256, 56]])
        self.assertEqual(ld.easing_text(1), "cubic-bezier(0.68, -0.55, 0.265, 1.55)")
        self.assertEqual(anim["op"], 4 * ld.SEGMENT_FRAMES + 1)

    def test_queries_cover_every_segment_at_exact_fractions(self):
        qs = ld.queries()
        self.assertEqual(len(qs), len(ld.SEGMENTS) * ld.FRACTIONS)
        for k in range(len(ld.SEGMENTS)):
            fs = [f for s, f, _ in qs if s == k]
            self.assertEqual((min(fs), max(fs), len(set(fs))), (0.0, 1.0, ld.FRACTIONS))
        for k, f, frame in qs:
            self.assertEqual(f, (frame - k * 64) / 64)  # the fraction lottie computes from the frame
        frames = ld.page_frames(qs)
        # A segment's last frame is the next one's first: 4 x 65 - 3 distinct frames, most not integers.
        self.assertEqual(len(frames), 257)
        self.assertEqual(frames, sorted(frames))
        self.assertGreater(sum(fr != int(fr) for fr in frames), 240)

    def test_page(self):
        page = ld.page(ld.page_frames(ld.queries()))
        self.assertIn(f'<script src="{ld.LOTTIE_FILE}"></script>', page)
        self.assertIn(f'<pre id="{ld.RESULT_ID}">', page)
        self.assertIn('renderer: "svg"', page)
        self.assertIn("autoplay: false", page)
        self.assertIn("anim.goToAndStop(256, true)", page)  # seek: from the last frame
        self.assertIn(json.dumps(ld.animation()), page)

    def test_float32_rounding(self):
        self.assertEqual(ld.float32_half_ulp(256), 2.0 ** -16)
        self.assertEqual(ld.float32_half_ulp(-300), 2.0 ** -16)
        self.assertEqual(ld.float32_half_ulp(1), 2.0 ** -24)


class Dump(unittest.TestCase):
    def test_recorded_positions(self):
        doc = recorded_doc()
        self.assertEqual(doc["lottie"], "5.13.0")
        self.assertTrue(doc["loaded"])
        qs = ld.queries()
        pos = ld.positions(doc, qs)
        for order in ld.ORDERS:
            got = dict(((k, f), p) for (k, f, _), p in zip(qs, pos[order]))
            for k in range(len(ld.SEGMENTS)):
                pts = ld.bezier_points(k)
                self.assertEqual(got[(k, 0.0)], tuple(pts[0]), (order, k))
                self.assertEqual(got[(k, 1.0)], tuple(pts[3]), (order, k))
        # Seek and playback agree except where lottie's walk along the curve resumes from a chord past
        # the point (segment 1's easeInOutBack, which backs up and overshoots).
        differ = {k for (k, _, _), a, b in zip(qs, pos["seek"], pos["playback"]) if a != b}
        self.assertEqual(differ, {1})

    def test_malformed_results_are_refused(self):
        doc = recorded_doc()
        qs = ld.queries()
        bad = json.loads(json.dumps(doc))
        bad["orders"]["seek"][5] = "matrix(0.5,0,0,1,3,4)"
        with self.assertRaisesRegex(ld.LottieDriverError, r"order seek, frame .*matrix\(1,0,0,1,x,y\)"):
            ld.positions(bad, qs)
        bad = json.loads(json.dumps(doc))
        bad["orders"]["playback"].pop()
        with self.assertRaisesRegex(ld.LottieDriverError, "order playback: expected 257 transforms"):
            ld.positions(bad, qs)
        bad = json.loads(json.dumps(doc))
        bad["frames"][3] += 1e-9
        with self.assertRaisesRegex(ld.LottieDriverError, "frames are not the request's"):
            ld.positions(bad, qs)
        bad = dict(doc, internal_mismatches=2)
        with self.assertRaisesRegex(ld.LottieDriverError, "2 layer transforms differ"):
            ld.positions(bad, qs)
        with self.assertRaisesRegex(ld.LottieDriverError, "no result"):
            ld.parse_dump(f'<pre id="{ld.RESULT_ID}"></pre>')
        with self.assertRaisesRegex(ld.LottieDriverError, "script failed: ReferenceError"):
            ld.parse_dump(f'<pre id="{ld.RESULT_ID}">{{"error": "ReferenceError: lottie is not defined"}}</pre>')
        self.assertEqual(ld.translation("matrix(1,0,0,1,56.03782653808594,255.95)"), (56.03782653808594, 255.95))


class Join(unittest.TestCase):
    def test_row_from_a_check(self):
        # Segment 1 (A = (456, 256), B = (256, 456)), three fractions: one inside [0, 1] checked, one
        # with E < 0 where lottie shows B, one at f = 1.
        check = {"checks": [{"length": 100.0, "rows": [
            {"s": 50.0, "error": 2e-5, "s_error": 1e-6, "off_curve": 1.5e-5},
            {"s": 100.0, "error": 0.0, "s_error": 0.0, "off_curve": 0.0}]}]}
        row = ld.segment_row(1, "seek", [0.5, 0.05, 1.0], [0.5, -0.02, 1.0],
                             [(300.0, 300.0), (256.0, 456.0), (256.0, 456.0)], 100.0, check)
        self.assertEqual((row["peer"], row["case"], row["setting"]), (ld.PEER, "lottie_overshoot", "seek"))
        self.assertEqual((row["point_error"], row["point_error_at"], row["s_error"], row["off_curve"]),
                         (2e-5, 50.0, 1e-6, 1.5e-5))
        self.assertEqual(row["true_length"], 100.0)
        for key in ("length", "length_error", "spacing_cv", "ns_length", "ns_point", "ns_build"):
            self.assertIsNone(row[key])
        self.assertIn("E(f) outside [0, 1] at 1 fractions (E from -0.02 to -0.02", row["note"])
        self.assertIn("at most 0 L from B", row["note"])
        self.assertIn("(B exactly, also where E < 0)", row["note"])
        with self.assertRaisesRegex(ld.LottieDriverError, "1 checked rows for 2 points"):
            ld.segment_row(1, "seek", [0.5, 1.0], [0.5, 1.0], [(0, 0), (256, 456)], 100.0,
                           {"checks": [{"rows": check["checks"][0]["rows"][:1]}]})

    def test_csv_keeps_s_inside_the_curve(self):
        d = tempfile.mkdtemp()
        self.addCleanup(shutil.rmtree, d)
        path = os.path.join(d, "p.csv")
        n = ld.at_length_csv(path, [(1, 2), (3, 4), (5, 6)], [0.25, 1.2, 1.0], 332.86534820652935)
        with open(path, encoding="utf-8") as f:
            lines = f.read().splitlines()
        self.assertEqual(n, 2)
        self.assertEqual(lines[0], "s,x,y")
        self.assertEqual(lines[1], f"{332.86534820652935 * 0.25!r},1.0,2.0")
        # E = 1: L rounded to double may lie above L; the double below it is written.
        self.assertEqual(lines[2], "332.8653482065293,5.0,6.0")


@unittest.skipUnless(TOOL, "needs CURVEBENCH_TOOL (ctest lottie sets it)")
class Measured(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        qs = ld.queries()
        cls.work = tempfile.mkdtemp()
        rows, cls.notes = ld.measure(ld.positions(recorded_doc(), qs), qs, TOOL, cls.work)
        cls.rows = {(r["case"], r["setting"]): r for r in rows}

    @classmethod
    def tearDownClass(cls):
        shutil.rmtree(cls.work)

    def test_lengths_are_the_references(self):
        # 483.868308087655652683... by mpmath's quad of the arch's speed at 40 digits.
        self.assertEqual(self.rows[("lottie_arch_ease_in_out", "seek")]["true_length"], 483.86830808765563)

    def test_lottie_is_its_chord_table_away_from_the_exact_motion(self):
        for name, *_ in ld.SEGMENTS:
            seek = self.rows[(name, "seek")]
            # 150 points by their chords: 1e-5 to 4e-5 of L off, far above float32's 6e-8 and below 1e-4.
            self.assertLess(seek["point_error"], 1e-4, name)
            self.assertGreater(seek["point_error"], 5e-6, name)
            self.assertLess(seek["s_error"], seek["point_error"], name)
            if name != "lottie_overshoot":
                self.assertEqual(self.rows[(name, "playback")]["point_error"], seek["point_error"], name)
        # Linear timing: lottie's easing returns f itself and the truth is f: the chord table alone.
        with open(os.path.join(self.work, "lottie_s_curve_linear.easing.csv"), encoding="utf-8") as f:
            rows = [r.split(",") for r in f.read().splitlines() if r and not r.startswith(("#", "t,"))]
        self.assertTrue(all(float(t) == float(v) for t, v in rows))

    def test_the_backing_up_ease_in_playback(self):
        seek, play = self.rows[("lottie_overshoot", "seek")], self.rows[("lottie_overshoot", "playback")]
        # Where E(f) < 0 or > 1 lottie shows the segment's end B, in both orders.
        for r in (seek, play):
            self.assertIn("E(f) outside [0, 1] at 45 fractions (E from -0.09264 to 1.093", r["note"])
            self.assertIn("(B exactly, also where E < 0)", r["note"])
        # Played forward, the layer then stays at B for the rest of the segment: every fraction after
        # the backing up whose E is in (0, 1) shows B (18 of 20: not f = 0, A, and f = 1, B), up to
        # 0.85 L from where it should be.
        self.assertIn("18 of the 20 fractions with E(f) in [0, 1) show the segment's end B exactly", play["note"])
        self.assertGreater(play["point_error"], 0.8)
        self.assertNotIn("show the segment's end B", seek["note"])
        self.assertEqual(len(self.notes), 2)


if __name__ == "__main__":
    unittest.main()
