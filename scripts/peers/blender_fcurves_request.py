"""Writes the request behind tests/data/blender_fcurves.json: the experiments that pin down how
Blender 3.4.1 computes F-curve handles (auto, auto_clamped, vector, aligned; free handles longer
than the key interval) and evaluates Bezier, linear, constant and eased segments, linear
extrapolation and the Cycles modifier (repeat, repeat_offset, mirror, with cycle counts).

Regenerate the fixture (Blender 3.4.1 from Debian bookworm was used):
    python3 scripts/peers/blender_fcurves_request.py > /tmp/blender_fcurves_request.json
    blender -b --factory-startup --python scripts/peers/blender_fcurves.py -- \
        /tmp/blender_fcurves_request.json tests/data/blender_fcurves.json
"""

import json
import random
import sys

COMMAND = ("python3 scripts/peers/blender_fcurves_request.py > /tmp/blender_fcurves_request.json && "
           "blender -b --factory-startup --python scripts/peers/blender_fcurves.py -- "
           "/tmp/blender_fcurves_request.json tests/data/blender_fcurves.json")

# Key layouts (frame, value): uneven spacing, a monotone run, extrema, a flat pair, a single key.
LAYOUTS = {
    "zigzag": ((1.0, 0.0), (4.0, 3.0), (11.0, 1.0), (13.0, 5.0), (30.0, -2.0)),
    "monotone": ((0.0, 0.0), (2.0, 1.0), (10.0, 1.5), (12.0, 6.0)),
    "flat_then_rise": ((0.0, 1.0), (5.0, 1.0), (6.0, 4.0), (20.0, 4.5)),
    "overshoot": ((0.0, 0.0), (1.0, 10.0), (2.0, 10.5), (9.0, 0.0)),
    "negative_frames": ((-7.5, 2.0), (-2.25, -1.0), (3.0, 0.5)),
    "two_keys": ((2.0, 1.0), (8.0, 3.0)),
    # monotone with uneven steps: clamping one key's slope changes what its neighbours' solve gives
    "clamp_chain": ((0.0, 0.0), (1.0, 1.0), (2.0, 1.1), (3.0, 3.0), (4.0, 3.2), (10.0, 3.3), (11.0, 8.0)),
}


def grid(t0, t1, n=48):
    return [t0 + (t1 - t0) * i / n for i in range(n + 1)]


def keys_of(layout, left, right, interp="BEZIER"):
    return [{"time": t, "value": v, "interpolation": interp, "handle_left_type": left, "handle_right_type": right}
            for t, v in layout]


def request():
    channels = []
    # 1. Automatic handle types on every layout, with both extrapolations (the end keys' handles
    #    may depend on it), and vector handles.
    for name, layout in LAYOUTS.items():
        t0, t1 = layout[0][0], layout[-1][0]
        for ht in ("AUTO", "AUTO_CLAMPED", "VECTOR"):
            for ex in ("CONSTANT", "LINEAR"):
                for sm in ("NONE", "CONT_ACCEL"):
                    channels.append({"name": f"handles/{ht.lower()}/{name}/{ex.lower()}/{sm.lower()}",
                                     "keys": keys_of(layout, ht, ht), "extrapolation": ex, "auto_smoothing": sm,
                                     "times": grid(t0 - 3, t1 + 3, 96)})
    # 2. Mixed types (with smoothing NONE; the model does not cover mixing under CONT_ACCEL): vector
    #    on one side, auto on the other; free beside auto.
    z = LAYOUTS["zigzag"]
    mixed = keys_of(z, "AUTO_CLAMPED", "AUTO_CLAMPED")
    mixed[1]["handle_left_type"] = "VECTOR"
    mixed[2]["handle_right_type"] = "VECTOR"
    mixed[3].update({"handle_left_type": "FREE", "handle_right_type": "FREE",
                     "handle_left": [12.0, 6.0], "handle_right": [15.0, 3.0]})
    channels.append({"name": "handles/mixed/zigzag", "keys": mixed, "auto_smoothing": "NONE",
                     "times": grid(0, 31, 124)})
    # 3. Aligned: the given right handle, the left handle's length kept, its direction turned.
    al = keys_of(z, "AUTO_CLAMPED", "AUTO_CLAMPED")
    al[2].update({"handle_left_type": "ALIGNED", "handle_right_type": "ALIGNED",
                  "handle_left": [9.0, 2.0], "handle_right": [12.0, 3.0]})
    channels.append({"name": "handles/aligned/zigzag", "keys": al, "auto_smoothing": "NONE", "times": grid(0, 31, 124)})
    al2 = keys_of(z, "AUTO_CLAMPED", "AUTO_CLAMPED")
    al2[1].update({"handle_left_type": "ALIGNED", "handle_right_type": "ALIGNED",
                   "handle_left": [3.0, 1.0], "handle_right": [5.5, 3.0]})
    channels.append({"name": "handles/aligned_left_free/zigzag", "keys": al2, "auto_smoothing": "NONE",
                     "times": grid(0, 31, 124)})
    # 4. Free handles inside, at and beyond the interval (Blender's handle correction).
    for label, (a, c) in {"inside": (0.3, 0.25), "thirds": (1 / 3, 1 / 3), "sum_one": (0.6, 0.4),
                          "long_out": (1.5, 0.2), "long_both": (0.9, 0.8), "very_long": (3.0, 2.0),
                          "zero": (0.0, 0.0)}.items():
        k0 = {"time": 2.0, "value": 1.0, "interpolation": "BEZIER", "handle_left_type": "FREE",
              "handle_right_type": "FREE", "handle_left": [1.0, 1.0], "handle_right": [2.0 + 10 * a, 4.0]}
        k1 = {"time": 12.0, "value": 3.0, "interpolation": "BEZIER", "handle_left_type": "FREE",
              "handle_right_type": "FREE", "handle_left": [12.0 - 10 * c, -1.0], "handle_right": [13.0, 3.0]}
        channels.append({"name": f"free/{label}", "keys": [k0, k1], "times": grid(2, 12, 80)})
    # 4b. Free handles under linear extrapolation: flat or steep outer handles, inner ones elsewhere,
    #     and times beyond both ends (Blender follows the outer handle there).
    for label, (left0, right1) in {"flat_outer": ([1.0, 1.0], [13.0, 3.0]),
                                   "steep_outer": ([0.0, 2.5], [14.0, 1.0])}.items():
        k0 = {"time": 2.0, "value": 1.0, "interpolation": "BEZIER", "handle_left_type": "FREE",
              "handle_right_type": "FREE", "handle_left": left0, "handle_right": [4.0, 4.0]}
        k1 = {"time": 12.0, "value": 3.0, "interpolation": "BEZIER", "handle_left_type": "FREE",
              "handle_right_type": "FREE", "handle_left": [10.0, -1.0], "handle_right": right1}
        channels.append({"name": f"free_linear/{label}", "keys": [k0, k1], "extrapolation": "LINEAR",
                         "times": grid(-8, 22, 120)})
    # 4c. Frames far from 0 on a steep segment: Blender evaluates at float32(t) (spacing 1/128 near
    #     1e5), at times that float32 cannot hold.
    far = [{"time": 100000.0, "value": 0.0, "interpolation": "LINEAR"},
           {"time": 100010.0, "value": 50.0, "interpolation": "LINEAR"}]
    channels.append({"name": "far/steep_linear", "keys": far, "extrapolation": "CONSTANT",
                     "times": [100000.0 + 0.3 * i + 0.001 for i in range(7)]})
    # 5. Interpolation per segment: constant, linear, eased, bezier in one channel, both
    #    extrapolations.
    seq = [{"time": 0.0, "value": 0.0, "interpolation": "CONSTANT"},
           {"time": 3.0, "value": 2.0, "interpolation": "LINEAR"},
           {"time": 5.0, "value": -1.0, "interpolation": "QUAD", "easing": "EASE_IN_OUT"},
           {"time": 9.0, "value": 4.0, "interpolation": "ELASTIC", "easing": "AUTO", "amplitude": 0.8,
            "period": 4.1},
           {"time": 15.0, "value": 1.0, "interpolation": "BEZIER", "handle_left_type": "AUTO_CLAMPED",
            "handle_right_type": "AUTO_CLAMPED"},
           {"time": 19.0, "value": 2.0, "interpolation": "BACK", "easing": "EASE_OUT", "back": 1.70158},
           {"time": 23.0, "value": 0.5, "interpolation": "LINEAR"}]
    for ex in ("CONSTANT", "LINEAR"):
        channels.append({"name": f"mixed_interpolation/{ex.lower()}", "keys": seq, "extrapolation": ex,
                         "times": grid(-4, 27, 124)})
    # 6. Cycles modifier: every mode pair of interest, with and without counts, and with linear
    #    extrapolation underneath (which the modifier replaces).
    cyc_keys = keys_of(((1.0, 0.0), (5.0, 2.0), (7.0, 1.5), (11.0, 3.0)), "AUTO_CLAMPED", "AUTO_CLAMPED")
    for before, after, nb, na in (("REPEAT", "REPEAT", 0, 0), ("REPEAT_OFFSET", "REPEAT_OFFSET", 0, 0),
                                  ("MIRROR", "MIRROR", 0, 0), ("REPEAT", "REPEAT_OFFSET", 2, 1),
                                  ("MIRROR", "REPEAT", 1, 2), ("NONE", "MIRROR", 0, 3),
                                  ("REPEAT_OFFSET", "NONE", 2, 0), ("MIRROR", "REPEAT_OFFSET", 3, 2)):
        for ex in ("CONSTANT", "LINEAR"):
            channels.append({"name": f"cycles/{before.lower()}_{nb}/{after.lower()}_{na}/{ex.lower()}",
                             "keys": cyc_keys, "extrapolation": ex,
                             "cycles": {"mode_before": before, "mode_after": after, "cycles_before": nb,
                                        "cycles_after": na},
                             "times": grid(-40, 50, 360) + [1.0 - 1e-3, 11.0 + 1e-3, 21.0, 31.0, -9.0]})
    # 7. Pseudo-random layouts (fixed seed): the rules beyond the designed cases, for the auto types
    #    under both smoothing modes and extrapolations, and as a cyclic curve.
    rng = random.Random(12)
    for r in range(6):
        t, layout = 0.0, []
        for _ in range(rng.randint(3, 9)):
            layout.append((t, round(rng.uniform(-5, 5), 3)))
            t = round(t + rng.choice((0.5, 1.0, 2.0, 3.0, 7.0, 12.0)) * rng.uniform(0.5, 1.5), 3)
        t0, t1 = layout[0][0], layout[-1][0]
        for ht in ("AUTO", "AUTO_CLAMPED"):
            for sm in ("NONE", "CONT_ACCEL"):
                for ex in ("CONSTANT", "LINEAR"):
                    channels.append({"name": f"random{r}/{ht.lower()}/{sm.lower()}/{ex.lower()}",
                                     "keys": keys_of(layout, ht, ht), "extrapolation": ex, "auto_smoothing": sm,
                                     "times": grid(t0 - 2, t1 + 2, 64)})
                channels.append({"name": f"random{r}/{ht.lower()}/{sm.lower()}/cyclic",
                                 "keys": keys_of(layout, ht, ht), "auto_smoothing": sm,
                                 "cycles": {"mode_before": "REPEAT_OFFSET", "mode_after": "REPEAT", "cycles_before": 0,
                                            "cycles_after": 0},
                                 "times": grid(t0 - (t1 - t0) * 1.5, t1 + (t1 - t0) * 1.5, 96)})
    # 8. A single key.
    channels.append({"name": "single_key", "keys": [{"time": 3.0, "value": 2.5, "interpolation": "BEZIER"}],
                     "extrapolation": "LINEAR", "times": [-1.0, 3.0, 7.0]})
    return {"note": "recorded output of real Blender; regenerate with: " + COMMAND, "channels": channels}


if __name__ == "__main__":
    json.dump(request(), sys.stdout, indent=1)
    sys.stdout.write("\n")
