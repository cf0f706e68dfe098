"""Writes the request behind tests/data/blender_fcurves.json: the experiments that pin down how
Blender 3.4.1 computes F-curve handles (auto, auto_clamped, vector, aligned; free handles longer
than the key interval) and evaluates Bezier, linear, constant and eased segments, linear
extrapolation and the Cycles modifier (repeat, repeat_offset, mirror, with cycle counts).

Regenerate the fixture (Blender 3.4.1 from Debian bookworm was used):
    python3 scripts/peers/blender_fcurves_request.py > /tmp/blender_fcurves_request.json
    blender -b --factory-startup --python scripts/peers/blender_fcurves.py -- \
        /tmp/blender_fcurves_request.json tests/data/blender_fcurves.json

With --heldout it writes instead the request behind tests/data/recorded/blender_heldout.json: channels never
used to find the rules (seeded pseudo-random key layouts, not the hand-picked ones above) covering
every handle type with each extrapolation on both sides, free handles (broken, long, crossing),
every interpolation and easing sampled at and between the key times, the Cycles modifier with every
handle type and smoothing, and frames far from 0. Each channel carries its "features" (the tags of
the common recording format). Regenerate (curvebench's CLI marks the channels its reader refuses):
    python3 scripts/peers/blender_fcurves_request.py --heldout > /tmp/blender_heldout_request.json
    blender -b --factory-startup --python scripts/peers/blender_fcurves.py -- \
        /tmp/blender_heldout_request.json tests/data/recorded/blender_heldout.json --common build-test/bench/curvebench
"""

import itertools
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


HELDOUT_COMMAND = ("python3 scripts/peers/blender_fcurves_request.py --heldout > /tmp/blender_heldout_request.json && "
                   "blender -b --factory-startup --python scripts/peers/blender_fcurves.py -- "
                   "/tmp/blender_heldout_request.json tests/data/recorded/blender_heldout.json --common "
                   "build-test/bench/curvebench")
HELDOUT_SEED = 3102026
FAMILIES = ("SINE", "QUAD", "CUBIC", "QUART", "QUINT", "EXPO", "CIRC", "BACK", "BOUNCE", "ELASTIC")
EASING_NAMES = {"AUTO": "auto", "EASE_IN": "in", "EASE_OUT": "out", "EASE_IN_OUT": "in_out"}


def random_layout(rng, n_min=3, n_max=7, start=None, spread=10.0):
    """Keys (frame, value) at uneven random spacings: frames on a 1/8 grid (exact in float32 up to
    1e5), values to 3 decimals."""
    t = round(rng.uniform(-20, 20) * 8) / 8 if start is None else start
    layout = []
    for _ in range(rng.randint(n_min, n_max)):
        layout.append((t, round(rng.uniform(-spread, spread), 3)))
        t += rng.choice((1, 2, 3, 5, 8, 13, 24)) * rng.randint(2, 10) / 8
    return layout


def sample_times(layout, rng, beyond=None, between=5):
    """Every key time, `between` random times inside each segment, and 6 times beyond each end
    (up to `beyond` frames away; the span by default)."""
    t0, t1 = layout[0][0], layout[-1][0]
    span = t1 - t0 if t1 > t0 else 4.0
    beyond = span if beyond is None else beyond
    ts = [t for t, _ in layout]
    for (a, _), (b, _) in zip(layout, layout[1:]):
        ts += [a + (b - a) * rng.random() for _ in range(between)]
    ts += [t0 - beyond * rng.random() for _ in range(6)] + [t1 + beyond * rng.random() for _ in range(6)]
    return sorted(set(ts))


def handle_keys(layout, ht, rng):
    """Keys with handle type ht on both sides; aligned and free get random handles (aligned ones
    are given pointing apart, as the UI would leave them; Blender's update() turns the right one),
    free ones broken: each side its own direction and length, some past the neighbour key."""
    keys = []
    for i, (t, v) in enumerate(layout):
        k = {"time": t, "value": v, "interpolation": "BEZIER", "handle_left_type": ht, "handle_right_type": ht}
        if ht in ("ALIGNED", "FREE"):
            dl = (t - layout[i - 1][0]) if i > 0 else (layout[1][0] - t if len(layout) > 1 else 2.0)
            dr = (layout[i + 1][0] - t) if i + 1 < len(layout) else dl
            sl = rng.uniform(-3, 3)
            sr = sl if ht == "ALIGNED" else rng.uniform(-3, 3)
            ll, lr = dl * rng.uniform(0.1, 1.6), dr * rng.uniform(0.1, 1.6)
            k["handle_left"] = [t - ll, v - sl * ll]
            k["handle_right"] = [t + lr, v + sr * lr]
        keys.append(k)
    return keys


def heldout_request(seed=HELDOUT_SEED):
    rng = random.Random(seed)
    channels = []

    def add(name, features, keys, times, extrapolation="CONSTANT", smoothing="CONT_ACCEL", cycles=None):
        ch = {"name": name, "features": features, "keys": keys, "extrapolation": extrapolation,
              "auto_smoothing": smoothing, "times": times}
        if cycles is not None:
            ch["cycles"] = cycles
        channels.append(ch)

    handle_types = ("AUTO", "AUTO_CLAMPED", "VECTOR", "ALIGNED", "FREE")
    # 1. Every handle type with each extrapolation, times beyond both ends; the automatic types
    #    under both smoothings, two layouts each.
    for ht in handle_types:
        for ex in ("CONSTANT", "LINEAR"):
            for sm in (("NONE", "CONT_ACCEL") if ht.startswith("AUTO") else ("CONT_ACCEL",)):
                for r in range(2):
                    layout = random_layout(rng)
                    add(f"handles/{ht.lower()}/{ex.lower()}/{sm.lower()}/{r}",
                        [f"handle:{ht.lower()}", f"pre:{ex.lower()}", f"post:{ex.lower()}", f"smoothing:{sm.lower()}"],
                        handle_keys(layout, ht, rng), sample_times(layout, rng), ex, sm)
    # 2. Free handles: broken (each side its own direction), long (past the neighbour key, which
    #    Blender's correction shortens), crossing (the two handles of a segment overtaking each
    #    other in time), with both extrapolations (the outer handles' slopes beyond the ends).
    for kind in ("broken", "long", "crossing"):
        for ex in ("CONSTANT", "LINEAR"):
            layout = random_layout(rng, 2, 4)
            keys = handle_keys(layout, "FREE", rng)
            for i, k in enumerate(keys):
                t, v = k["time"], k["value"]
                dl = t - layout[i - 1][0] if i > 0 else layout[1][0] - t
                dr = layout[i + 1][0] - t if i + 1 < len(layout) else dl
                if kind == "long":
                    k["handle_left"] = [t - dl * rng.uniform(1.2, 3.0), v + rng.uniform(-6, 6)]
                    k["handle_right"] = [t + dr * rng.uniform(1.2, 3.0), v + rng.uniform(-6, 6)]
                elif kind == "crossing":
                    k["handle_left"] = [t - dl * rng.uniform(0.6, 0.95), v + rng.uniform(-6, 6)]
                    k["handle_right"] = [t + dr * rng.uniform(0.6, 0.95), v + rng.uniform(-6, 6)]
            add(f"free/{kind}/{ex.lower()}", ["handle:free", f"free:{kind}", f"pre:{ex.lower()}", f"post:{ex.lower()}"],
                keys, sample_times(layout, rng, between=8), ex)
    # 3. Every interpolation on every segment (three or four keys), sampled at the key times and
    #    between them; the eased families with each easing and random back / amplitude / period.
    for interp in ("CONSTANT", "LINEAR", "BEZIER"):
        for ex in ("CONSTANT", "LINEAR"):
            layout = random_layout(rng, 3, 4)
            keys = [{"time": t, "value": v, "interpolation": interp} for t, v in layout]
            add(f"interpolation/{interp.lower()}/{ex.lower()}",
                [f"interpolation:{interp.lower()}", f"pre:{ex.lower()}", f"post:{ex.lower()}"], keys,
                sample_times(layout, rng, between=8), ex)
    for fam in FAMILIES:
        for easing in ("AUTO", "EASE_IN", "EASE_OUT", "EASE_IN_OUT"):
            layout = random_layout(rng, 3, 4)
            ex = rng.choice(("CONSTANT", "LINEAR"))
            keys = []
            for t, v in layout:
                k = {"time": t, "value": v, "interpolation": fam, "easing": easing}
                if fam == "BACK":
                    k["back"] = round(rng.uniform(0, 4), 3)
                if fam == "ELASTIC":
                    k["amplitude"] = round(rng.uniform(0, 3), 3)
                    k["period"] = round(rng.uniform(0.2, 8), 3)
                keys.append(k)
            add(f"easing/{fam.lower()}/{EASING_NAMES[easing]}",
                [f"interpolation:{fam.lower()}", f"easing:{EASING_NAMES[easing]}", "at:key_times",
                 f"pre:{ex.lower()}", f"post:{ex.lower()}"], keys, sample_times(layout, rng, between=8), ex)
    # 4. The Cycles modifier with every handle type and both smoothings: repeating forever on both
    #    sides (the handle rules see a cyclic curve), and random modes with counts (they do not).
    modes = ("REPEAT", "REPEAT_OFFSET", "MIRROR")
    for ht in handle_types:
        for sm in ("NONE", "CONT_ACCEL"):
            for form in ("infinite", "counted"):
                layout = random_layout(rng, 3, 6)
                if form == "infinite":
                    before, after = rng.choice(modes[:2]), rng.choice(modes[:2])
                    nb = na = 0
                else:
                    before, after = rng.choice(modes), rng.choice(modes)
                    nb, na = rng.randint(1, 3), rng.randint(1, 3)
                ex = rng.choice(("CONSTANT", "LINEAR"))
                span = layout[-1][0] - layout[0][0]
                add(f"cycles/{ht.lower()}/{sm.lower()}/{form}",
                    [f"handle:{ht.lower()}", f"smoothing:{sm.lower()}", f"pre:cycles_{before.lower()}",
                     f"post:cycles_{after.lower()}", f"cycles:{form}", f"pre:{ex.lower()}", f"post:{ex.lower()}"],
                    handle_keys(layout, ht, rng), sample_times(layout, rng, beyond=span * 4.5, between=3) +
                    [layout[0][0] - span * j for j in range(1, 5)] + [layout[-1][0] + span * j for j in range(1, 5)],
                    ex, sm, {"mode_before": before, "mode_after": after, "cycles_before": nb, "cycles_after": na})
    # 5. Frames far from 0 (float32's spacing 1/1024 near 1e4, 1/128 near 1e5): bezier with auto
    #    clamped handles, linear, an eased family and a cycle, keys starting there.
    #    Key spacings as random as elsewhere (some below what curvebench's float model resolves
    #    there: 2^8 float32 spacings, 3 frames near 1e5) and 8 times wider.
    for start in (10000.0, 100000.0):
        for what, width in itertools.product(("auto_clamped", "linear", "quad", "cycles"), ("narrow", "wide")):
            layout = random_layout(rng, 3, 5, start=start, spread=50.0)
            if width == "wide":
                layout = [(start + 8 * (t - start), v) for t, v in layout]
            ex = "LINEAR"
            if what == "linear":
                keys = [{"time": t, "value": v, "interpolation": "LINEAR"} for t, v in layout]
            elif what == "quad":
                keys = [{"time": t, "value": v, "interpolation": "QUAD", "easing": "EASE_IN_OUT"} for t, v in layout]
            else:
                keys = handle_keys(layout, "AUTO_CLAMPED", rng)
            cycles = None
            feats = [f"far:{int(start)}", f"interpolation:{'bezier' if what in ('auto_clamped', 'cycles') else what}"]
            if what == "cycles":
                cycles = {"mode_before": "REPEAT_OFFSET", "mode_after": "REPEAT", "cycles_before": 0,
                          "cycles_after": 0}
                feats += ["pre:cycles_repeat_offset", "post:cycles_repeat"]
            else:
                feats += ["pre:linear", "post:linear"]
            times = sample_times(layout, rng, between=10)
            times += [t + 0.001 * j for t, _ in layout for j in (1, 3)]  # below float32's spacing there
            add(f"far/{int(start)}/{what}/{width}", feats, keys, sorted(set(times)), ex, "CONT_ACCEL", cycles)
    #    The control: the same channels moved to start at frame 0 (what differs there and not here
    #    is the rounding of absolute frames near 1e4 and 1e5).
    for far in [c for c in channels if c["name"].startswith("far/")]:
        start = far["keys"][0]["time"]
        keys = [dict(k, time=k["time"] - start) for k in far["keys"]]
        for k in keys:
            for side in ("handle_left", "handle_right"):
                if side in k:
                    k[side] = [k[side][0] - start, k[side][1]]
        add("far/0/" + far["name"].split("/", 2)[2], ["far:0"] + far["features"][1:], keys,
            [t - start for t in far["times"]], far["extrapolation"], far["auto_smoothing"], far.get("cycles"))
    # 6. Linear extrapolation past an end key whose own interpolation differs from its segment's:
    #    the last key's interpolation (which no segment uses) against the one of the segment
    #    before it; and a single key of each interpolation.
    for last, seg in itertools.product(("CONSTANT", "LINEAR", "BEZIER", "SINE"), ("BEZIER", "LINEAR", "ELASTIC")):
        layout = random_layout(rng, 3, 4)
        keys = handle_keys(layout, "AUTO_CLAMPED", rng)
        for k in keys[:-1]:
            k["interpolation"] = seg
        keys[-1]["interpolation"] = last
        add(f"end_key/{last.lower()}_after_{seg.lower()}",
            ["post:linear", f"end_key:{last.lower()}", f"interpolation:{seg.lower()}"], keys,
            sample_times(layout, rng), "LINEAR")
    for interp in ("CONSTANT", "LINEAR", "BEZIER", "SINE"):
        t, v = round(rng.uniform(-20, 20) * 8) / 8, round(rng.uniform(-10, 10), 3)
        k = {"time": t, "value": v, "interpolation": interp, "handle_left_type": "FREE", "handle_right_type": "FREE",
             "handle_left": [t - 1.5, v - 2.0], "handle_right": [t + 0.5, v + 1.5]}
        add(f"single_key/{interp.lower()}", ["single_key", f"end_key:{interp.lower()}", "pre:linear", "post:linear"],
            [k], [t - 7.25, t - 1.0, t, t + 0.75, t + 9.5], "LINEAR")
    # 7. What curvebench does not model, kept to be counted: a free key among auto ones under
    #    cont_accel, and auto on one side of a key beside free on the other.
    layout = random_layout(rng, 4, 5)
    keys = handle_keys(layout, "AUTO_CLAMPED", rng)
    keys[1].update({"handle_left_type": "FREE", "handle_right_type": "FREE",
                    "handle_left": [layout[1][0] - 0.5, layout[1][1] + 1.0],
                    "handle_right": [layout[1][0] + 0.5, layout[1][1] - 1.0]})
    add("mixed/free_among_auto_clamped/cont_accel", ["handle:mixed", "smoothing:cont_accel"], keys,
        sample_times(layout, rng))
    layout = random_layout(rng, 4, 5)
    keys = handle_keys(layout, "AUTO", rng)
    keys[2].update({"handle_right_type": "FREE", "handle_right": [layout[2][0] + 0.75, layout[2][1] + 2.0]})
    add("mixed/auto_left_free_right/none", ["handle:mixed", "smoothing:none"], keys, sample_times(layout, rng),
        "LINEAR", "NONE")
    return {"note": "recorded output of real Blender; regenerate with: " + HELDOUT_COMMAND, "channels": channels}


MIXED_COMMAND = ("python3 scripts/peers/blender_fcurves_request.py --mixed > /tmp/blender_mixed_request.json && "
                 "blender -b --factory-startup --python scripts/peers/blender_fcurves.py -- "
                 "/tmp/blender_mixed_request.json tests/data/recorded/blender_mixed.json --common "
                 "build-test/bench/curvebench")
MIXED_SEED = 26112026


def mixed_request(seed=MIXED_SEED):
    """The request behind tests/data/recorded/blender_mixed.json: curves mixing automatic keys with
    vector, aligned and free ones (and keys auto on one side, vector or free on the other), under
    both smoothings and both extrapolations, free handles from 0.1 to 1.6 of their interval; a few
    with an infinite Cycles modifier. Seeded, never used to find the rules."""
    rng = random.Random(seed)
    channels = []
    whole = ("AUTO", "AUTO_CLAMPED", "VECTOR", "ALIGNED", "FREE")
    for r in range(48):
        smoothing = "CONT_ACCEL" if r % 4 != 3 else "NONE"
        extrapolation = "LINEAR" if r % 2 else "CONSTANT"
        layout = random_layout(rng, 4, 8)
        keys = handle_keys(layout, "AUTO_CLAMPED" if r % 3 == 0 else "AUTO", rng)
        types = set()
        for i, k in enumerate(keys):
            u = rng.random()
            if u < 0.45:
                continue  # stays automatic
            if u < 0.85:
                ht = rng.choice(whole[2:])
                other = handle_keys(layout, ht, rng)[i]
                k.update({f: other[f] for f in other if f.startswith("handle")})
                types.add(ht.lower())
            else:  # automatic on one side, vector or free on the other
                side, kind = rng.choice(("left", "right")), rng.choice(("VECTOR", "FREE"))
                if kind == "FREE" and k["handle_left_type"] == "AUTO_CLAMPED":
                    kind = "VECTOR"  # auto_clamped beside free: refused by the model, kept out
                k[f"handle_{side}_type"] = kind
                if kind == "FREE":
                    dt = (layout[1][0] - layout[0][0]) * rng.uniform(0.1, 1.6)
                    t, v = layout[i]
                    k[f"handle_{side}"] = [t - dt if side == "left" else t + dt, v + rng.uniform(-3, 3) * dt]
                types.add(f"{k['handle_left_type'].lower()}_{k['handle_right_type'].lower()}")
        features = ["handle:mixed", f"smoothing:{smoothing.lower()}", f"pre:{extrapolation.lower()}",
                    f"post:{extrapolation.lower()}"] + sorted(f"with:{t}" for t in types)
        ch = {"name": f"mixed/{r:02d}", "features": features, "keys": keys, "extrapolation": extrapolation,
              "auto_smoothing": smoothing, "times": sample_times(layout, rng)}
        channels.append(ch)
    for r in range(4):
        layout = random_layout(rng, 4, 6)
        keys = handle_keys(layout, "AUTO_CLAMPED", rng)
        keys[1 + r % 2].update(handle_keys(layout, ("VECTOR", "FREE")[r % 2], rng)[1 + r % 2])
        features = ["handle:mixed", "smoothing:cont_accel", "cycles:infinite"]
        channels.append({"name": f"mixed/cyclic/{r}", "features": features,
                         "keys": keys, "extrapolation": "CONSTANT", "auto_smoothing": "CONT_ACCEL",
                         "cycles": {"mode_before": "REPEAT", "mode_after": "REPEAT", "cycles_before": 0,
                                    "cycles_after": 0},
                         "times": sample_times(layout, rng, beyond=2 * (layout[-1][0] - layout[0][0]))})
    return {"note": "recorded output of real Blender; regenerate with: " + MIXED_COMMAND, "channels": channels}


if __name__ == "__main__":
    args = sys.argv[1:]
    json.dump(heldout_request() if "--heldout" in args else mixed_request() if "--mixed" in args else request(),
              sys.stdout, indent=1)
    sys.stdout.write("\n")
