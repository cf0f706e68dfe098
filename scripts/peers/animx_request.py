"""Writes the request behind tests/data/recorded/animx_curves.json: Maya animCurves for Autodesk AnimX to
evaluate (scripts/peers/animx_record.cpp, which says how to build AnimX and the driver in /tmp).

Covers every tangent type AnimX evaluates (fixed, auto, flat, linear, step, step_next; spline,
clamped and plateau are stored tangents in Maya that AnimX has no rule for, so they are not here),
weighted and non-weighted curves, regressive weighted handles (AnimX's correction), every pre and
post infinity (constant, linear, cycle, cycle_relative, oscillate) on both sides, and evaluation
on the keys, between them, at exactly whole periods before and after the keyed range, and far
outside it. Seeded random curves plus hand-picked ones.

Times are seconds, as AnimX takes them, on Maya's ticks (1/141120000 s): keys on whole frames at
24 fps or on quarter seconds, evaluation times on quarter frames, so that AnimX's rounding of
wrapped infinity times to ticks changes nothing but the last bits.

    python3 scripts/peers/animx_request.py --commit HASH > /tmp/animx_request.json
"""

import argparse
import json
import math
import random
import sys

FPS = 24.0
TANGENTS = ("fixed", "auto", "flat", "linear", "step", "step_next")
INFINITIES = ("constant", "linear", "cycle", "cycle_relative", "oscillate")
COMMAND = ("python3 scripts/peers/animx_request.py --commit HASH > /tmp/animx_request.json && "
           "/tmp/animx_record /tmp/animx_request.json tests/data/recorded/animx_curves.json "
           "(driver and AnimX built as scripts/peers/animx_record.cpp says)")


def frames(f):
    return f / FPS


def key(t, v, tin, tout, vin=None, vout=None):
    k = {"time": t, "value": v, "in_type": tin, "out_type": tout}
    if tin == "fixed":
        k["in"] = vin
    if tout == "fixed":
        k["out"] = vout
    return k


def fixed_vector(rng, duration, weighted):
    """A fixed tangent (x, y): a random angle; weighted, x a random multiple of the segment."""
    angle = math.radians(rng.uniform(-75.0, 75.0))
    if not weighted:
        return [math.cos(angle), math.sin(angle)]
    x = duration * rng.choice((0.4, 0.8, 1.0, 1.5, 2.2, 3.1))
    return [x, x * math.tan(angle)]


def eval_times(keys, pre, post, on_frames=True):
    """On every key, quarter frames between keys, whole periods before and after (k = 1, 2, 3),
    half periods, and far outside (1000 periods and a bit). Quarter-frame grid in seconds."""
    t0, t1 = keys[0]["time"], keys[-1]["time"]
    rng_frames = round((t1 - t0) * FPS, 9)
    out = [k["time"] for k in keys]
    for a, b in zip(keys, keys[1:]):
        fa, fb = a["time"] * FPS, b["time"] * FPS
        for q in (0.25, 0.5, 0.75):
            out.append(frames(round(fa + q * (fb - fa)) + 0.25 * (q == 0.5)))
    f0, f1 = t0 * FPS, t1 * FPS
    for k in (1, 2, 3):
        out.append(frames(f0 - k * rng_frames))
        out.append(frames(f1 + k * rng_frames))
    for extra in (0.25, 1.0, 0.5 * rng_frames, rng_frames + 2.75):
        out.append(frames(f0 - extra))
        out.append(frames(f1 + extra))
    out.append(frames(f0 - 1000 * rng_frames - 7.25))
    out.append(frames(f1 + 1000 * rng_frames + 5.5))
    return sorted(set(out))


def features_of(keys, weighted, pre, post, extra=()):
    f = {"tangent:" + k[side] for k in keys for side in ("in_type", "out_type")}
    f.add("weighted" if weighted else "non_weighted")
    f.add("pre:" + pre)
    f.add("post:" + post)
    if pre != "constant" or post != "constant":
        f.add("boundary:whole_period")
    f.update(extra)
    return sorted(f)


def regressive(keys, weighted):
    """Whether a weighted segment's handles pass the other key (AnimX corrects those)."""
    if not weighted:
        return False
    for a, b in zip(keys, keys[1:]):
        h = b["time"] - a["time"]
        if (a["out_type"] == "fixed" and a["out"][0] / 3 > h) or (b["in_type"] == "fixed" and b["in"][0] / 3 > h):
            return True
    return False


def channel(name, keys, weighted, pre, post, extra=()):
    if regressive(keys, weighted):
        extra = tuple(extra) + ("regression",)
    return {"name": name, "features": features_of(keys, weighted, pre, post, extra), "weighted": weighted,
            "pre": pre, "post": post, "keys": keys, "t": eval_times(keys, pre, post)}


def random_curve(rng, i, weighted, pre, post):
    n = rng.randint(2, 6)
    f = rng.randint(-30, 30)
    keys = []
    times = []
    for _ in range(n):
        times.append(f)
        f += rng.randint(1, 20)
    for j, fr in enumerate(times):
        v = round(rng.uniform(-10.0, 10.0), 3)
        tin, tout = rng.choice(TANGENTS), rng.choice(TANGENTS)
        d_in = frames(times[j] - times[j - 1]) if j > 0 else frames(times[1] - times[0])
        d_out = frames(times[j + 1] - times[j]) if j + 1 < n else d_in
        keys.append(key(frames(fr), v, tin, tout, fixed_vector(rng, d_in, weighted),
                        fixed_vector(rng, d_out, weighted)))
    return channel(f"random/{i:02d}/{'w' if weighted else 'nw'}/{pre}/{post}", keys, weighted, pre, post)


def hand_picked():
    out = []
    # Auto on the cases its bound decides: an extremum, an equal neighbour, a steep chord beside a
    # shallow one (the bound 3 min(|d_l|, |d_r|) active), a monotone run; both weightings.
    layouts = {
        "extremum": ((0, 0.0), (6, 4.0), (10, 1.0), (24, 3.0)),
        "equal_neighbour": ((0, 1.0), (5, 1.0), (9, 4.0), (12, 4.0)),
        "steep_shallow": ((0, 0.0), (2, 0.1), (4, 9.0), (30, 9.5)),
        "monotone": ((-12, -3.0), (-4, -1.0), (3, 2.5), (8, 7.0)),
    }
    for name, lay in layouts.items():
        for w in (False, True):
            keys = [key(frames(f), v, "auto", "auto") for f, v in lay]
            out.append(channel(f"auto/{name}/{'w' if w else 'nw'}", keys, w, "oscillate", "cycle_relative"))
    # Every infinity on both sides, with each tangent type throughout, on the same layout.
    lay = ((0, 1.0), (6, 5.0), (9, -2.0), (16, 3.5))
    for ti, ty in enumerate(TANGENTS):
        for pi, (pre, post) in enumerate(zip(INFINITIES, INFINITIES[2:] + INFINITIES[:2])):
            for w in ((ti + pi) % 2 == 1,):
                keys = [key(frames(f), v, ty, ty, [frames(4), frames(4) * 0.7], [frames(5), frames(5) * -0.4])
                        for f, v in lay]
                out.append(channel(f"type/{ty}/{'w' if w else 'nw'}/{pre}/{post}", keys, w, pre, post))
    # Regressive weighted handles: the out handle reaching past the next key (a > 1, the in handle
    # moved to the ellipse's upper or lower edge), past a = 4/3 (both moved to its tip), the in
    # handle past the previous key, and overlapping handles that stay monotone (untouched).
    h = 0.5  # seconds, keys on quarter seconds
    cases = {
        "out_past_upper": (1.2, 0.9),
        "out_just_past_upper": (1.2, 0.76),  # the upper edge at a = 1.2 is c = 0.7464
        "out_past_lower": (1.1, 0.005),  # the lower edge at a = 1.1 is c = 0.0112
        "out_beyond_tip": (2.5, 0.6),
        "in_past": (0.2, 1.7),
        "both_past": (1.6, 1.6),
        "overlap_monotone": (0.9, 0.6),
    }
    for name, (a, c) in cases.items():
        for pre, post in (("cycle", "oscillate"), ("linear", "cycle_relative")):
            keys = [key(0.25, -1.0, "auto", "fixed", None, [3 * a * h, 3 * a * h * 1.8]),
                    key(0.25 + h, 2.0, "fixed", "flat", [3 * c * h, 3 * c * h * -0.6], None),
                    key(1.25, 0.5, "auto", "auto")]
            out.append(channel(f"regression/{name}/{pre}/{post}", keys, True, pre, post))
    # Linear spans beside curved ones, and step / step_next spans wrapped by the cycles.
    mix = [key(frames(0), 0.0, "linear", "linear"), key(frames(5), 3.0, "linear", "auto"),
           key(frames(8), 1.0, "step", "step"), key(frames(11), 6.0, "flat", "step_next"),
           key(frames(15), -1.0, "linear", "linear")]
    for w in (False, True):
        for pre in INFINITIES:
            out.append(channel(f"mixed/{'w' if w else 'nw'}/{pre}/{pre}", mix, w, pre, pre))
    return out


def request(commit):
    rng = random.Random(31)
    channels = hand_picked()
    for i in range(50):
        pre, post = INFINITIES[i % 5], INFINITIES[(i // 5) % 5]
        channels.append(random_curve(rng, i, (i // 25) % 2 == 1, pre, post))
    source = {"implementation": "Autodesk AnimX (Maya's animation-curve evaluator, Apache-2.0)",
              "repository": "https://github.com/Autodesk/animx", "commit": commit,
              "version": "AnimX at that commit (Maya 2025 upgrade)",
              "build": "CMake Release (g++ 12.2, -O3), MAYA_64BIT_TIME_PRECISION=ON (64-bit time, Maya's "
                       "default since 2017 update 3), static library, -include limits; driver "
                       "scripts/peers/animx_record.cpp -O2",
              "recorded": "2026-11-26", "command": COMMAND.replace("HASH", commit)}
    return {"source": source, "channels": channels}


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--commit", required=True, help="the AnimX commit the driver is built against")
    args = parser.parse_args()
    json.dump(request(args.commit), sys.stdout, indent=1)
    sys.stdout.write("\n")


if __name__ == "__main__":
    main()
