"""Writes the request behind tests/data/recorded/usd_ts_splines.json: OpenUSD Ts splines, each as a
curvebench "usd" channel spec with the times to evaluate, covering every interpolation (held,
linear, curve), both curve types, every anti-regression mode on regressive and non-regressive
segments (centre, fringe, beyond 4/3, one zero width, contained but long), every extrapolation on
both sides (held, linear, sloped, loop repeat / reset / oscillate), dual-valued knots, inner loops,
one-knot splines, and seeded random splines; times on and between knots, at loop joins and far out.

Regenerate the fixture (see scripts/peers/usd_ts_record.cpp for building the recorder against a
local OpenUSD build):
    python3 scripts/peers/usd_ts_request.py > /tmp/usd_ts_request.json
    /tmp/usd/usd_ts_record /tmp/usd_ts_request.json tests/data/recorded/usd_ts_splines.json
    CURVEBENCH_SOURCE_DIR=$PWD build-test/tests/test_usd_ts |
        python3 scripts/peers/usd_ts_refusals.py tests/data/recorded/usd_ts_splines.json
"""

import json
import random
import sys

SEED = 20261126
EXTRAPOLATIONS = ("held", "linear", "sloped", "loop_repeat", "loop_reset", "loop_oscillate")
MODES = ("none", "contain", "keep_ratio", "keep_start")
LOOPS = ("loop_repeat", "loop_reset", "loop_oscillate")


def knot(t, v, interp="curve", pre_w=None, pre_s=None, post_w=None, post_s=None, pre_value=None):
    k = {"time": t, "value": v, "interpolation": interp}
    for name, x in (("pre_width", pre_w), ("pre_slope", pre_s), ("post_width", post_w), ("post_slope", post_s),
                    ("pre_value", pre_value)):
        if x is not None:
            k[name] = x
    return k


def times_for(knots, spec, dense=()):
    """Knot times, midpoints, a grid over two periods either side, loop joins, far times."""
    ts = [k["time"] for k in knots]
    t0, t1 = ts[0], ts[-1]
    span = t1 - t0 if t1 > t0 else 1.0
    loops = spec.get("inner_loops")
    if loops:
        p = loops["proto_end"] - loops["proto_start"]
        lo = loops["proto_start"] - loops.get("pre_loops", 0) * p
        hi = loops["proto_end"] + loops.get("post_loops", 0) * p
        t0, t1 = min(t0, lo), max(t1, hi)
        span = t1 - t0
        ts += [loops["proto_start"] + j * p for j in range(-loops.get("pre_loops", 0), loops.get("post_loops", 0) + 2)]
    out = set(ts)
    out.update((a + b) / 2 for a, b in zip(ts, ts[1:]))
    out.update(t0 - 2.5 * span + 7.0 * span * i / 56 for i in range(57))
    out.update(t0 - k * span for k in (1, 2, 3))
    out.update(t1 + k * span for k in (1, 2, 3))
    out.update((t0 - 1000.25 * span, t1 + 10000.5 * span, t0 - 0.5, t1 + 0.5))
    out.update(dense)
    return sorted(out)


def channel(name, features, knots, **fields):
    spec = {"type": "channel", "tool": "usd", "knots": knots}
    spec.update(fields)
    dense = spec.pop("_dense", ())
    return {"name": name, "features": sorted(set(features)), "spec": spec, "t": times_for(knots, spec, dense)}


def interp_tags(knots):
    return ["interp:" + k["interpolation"] for k in knots[:-1]]


def extrap_tags(spec):
    return ["pre:" + spec.get("before", "held"), "post:" + spec.get("after", "held")]


def regressive(a, c):
    return a + c > 1 and (a + c - 1) ** 2 > a * c


def hand_picked():
    out = []
    # Extrapolation: every mode on both sides, the same on each (so that each side's rule stands
    # alone), over a curve-ended and a linear/held-ended spline.
    curve_ends = [knot(0.0, 1.0, "curve", 0.5, 3.0, 0.5, 2.0), knot(1.5, 2.5, "curve", 0.5, 0.0, 0.75, -1.0),
                  knot(4.0, 0.5, "curve", 1.0, -0.5, 0.5, 4.0)]
    line_ends = [knot(-2.0, 3.0, "linear"), knot(-1.0, 1.0, "curve", 0.25, 0.0, 0.5, 1.5),
                 knot(2.0, 2.0, "held", 0.5, 2.0), knot(3.0, -1.0, "linear"), knot(5.0, 0.5)]
    for e in EXTRAPOLATIONS:
        for shape, ks in (("curve_ends", curve_ends), ("line_ends", line_ends)):
            f = {"before": e, "after": e}
            if e == "sloped":
                f.update(slope_before=-0.75, slope_after=1.25)
            ch = channel(f"extrap/{e}/{shape}", interp_tags(ks) + ["curve:bezier"] + extrap_tags(f), ks, **f)
            out.append(ch)
    # Different modes on the two sides (every post mode under another pre mode).
    for i, post in enumerate(EXTRAPOLATIONS):
        pre = EXTRAPOLATIONS[(i + 2) % len(EXTRAPOLATIONS)]
        f = {"before": pre, "after": post}
        if pre == "sloped":
            f["slope_before"] = 0.5
        if post == "sloped":
            f["slope_after"] = -2.0
        out.append(channel(f"extrap/mixed/{pre}-{post}", interp_tags(curve_ends) + ["curve:bezier", "extrap:mixed"] +
                           extrap_tags(f), curve_ends, **f))
    # Anti-regression: each mode on each kind of segment, normalized widths (a, c) on [0, 2].
    kinds = {"centre": (1.2, 1.2), "asymmetric": (2.0, 0.5), "fringe_inside": (1.2, 0.1),
             "fringe_below": (1.2, 0.01), "fringe_below_2": (1.3, 0.05), "beyond_4_3": (1.6, 0.9),
             "zero_start": (0.0, 1.5), "zero_end": (1.7, 0.0), "contained_long": (0.9, 0.95),
             "one_over_not_regressive": (1.05, 0.05), "far": (3.0, 2.5)}
    h = 2.0
    for kind, (a, c) in kinds.items():
        for mode in MODES:
            ks = [knot(0.0, 0.0, "curve", None, None, a * h, 1.5), knot(h, 1.0, "curve", c * h, -0.5, 0.5, 0.0),
                  knot(h + 1.0, 0.25, "linear")]
            dense = [h * i / 200 for i in range(1, 200)]
            f = {"anti_regression": mode, "before": "linear", "after": "linear", "_dense": dense}
            tags = ["curve:bezier", "anti_regression:" + mode, "interp:curve", "interp:linear", "pre:linear",
                    "post:linear", "regressive" if regressive(a, c) else "not_regressive"]
            out.append(channel(f"regression/{kind}/{mode}", tags, ks, **f))
    # Dual-valued knots: after held, linear and curve segments, first and last knot.
    dual = [
        ("after_held", [knot(0.0, 0.0, "held"), knot(1.0, 2.0, "linear", pre_value=5.0), knot(2.0, 1.0)], {}),
        ("after_linear", [knot(0.0, 0.0, "linear"), knot(1.0, 2.0, "curve", pre_value=-1.0, post_w=0.25, post_s=1.0),
                          knot(3.0, 0.5, "curve", 0.5, 0.0)], {}),
        ("after_curve", [knot(0.0, 0.0, "curve", None, None, 0.5, 2.0),
                         knot(2.0, 1.0, "held", 0.5, -1.0, pre_value=3.0), knot(3.0, 2.0)], {}),
        ("first_knot_linear", [knot(0.0, 1.0, "linear", pre_value=4.0), knot(2.0, 3.0, "linear"), knot(3.0, 0.0)],
         {"before": "linear", "after": "linear"}),
        ("first_knot_sloped", [knot(0.0, 1.0, "curve", None, None, 0.5, 1.0, pre_value=-2.0),
                               knot(2.0, 3.0, "curve", 0.5, 0.5)], {"before": "sloped", "slope_before": 0.5}),
        ("last_knot_linear", [knot(0.0, 1.0, "linear"), knot(2.0, 3.0, "linear", pre_value=2.0)],
         {"before": "linear", "after": "linear"}),
        ("last_knot_curve", [knot(0.0, 1.0, "curve", None, None, 0.5, 1.0),
                             knot(2.0, 3.0, "curve", 0.5, 2.0, pre_value=0.0)],
         {"before": "linear", "after": "linear"}),
        ("repeat_first_dual", [knot(0.0, 1.0, "linear", pre_value=0.0), knot(1.0, 3.0, "curve", 0.25, 0.0, 0.25, 0.0),
                               knot(2.5, 2.0)], {"before": "loop_repeat", "after": "loop_repeat"}),
        ("oscillate_last_dual", [knot(0.0, 1.0, "linear"), knot(1.0, 3.0, "linear"), knot(2.0, 2.0, pre_value=5.0)],
         {"before": "loop_oscillate", "after": "loop_oscillate"}),
        ("reset_after_held", [knot(0.0, 1.0, "linear"), knot(1.0, 3.0, "held"), knot(2.0, 2.0, pre_value=5.0)],
         {"before": "loop_reset", "after": "loop_reset"}),
    ]
    for name, ks, f in dual:
        out.append(channel(f"dual/{name}", interp_tags(ks) + ["curve:bezier", "dual_valued"] + extrap_tags(f), ks, **f))
    # Hermite: widths fixed at a third of the interval (the given widths are not authored).
    herm = [knot(0.0, 0.0, "curve", None, None, None, 2.0), knot(1.0, 1.0, "curve", None, -1.0, None, 0.5),
            knot(3.0, 0.0, "linear"), knot(4.0, 1.0)]
    for f in ({"before": "linear", "after": "linear"}, {"before": "loop_repeat", "after": "loop_repeat"}):
        out.append(channel(f"hermite/{f['before']}", interp_tags(herm) + ["curve:hermite"] + extrap_tags(f), herm,
                           curve_type="hermite", **f))
    # Inner loops: with unlooped knots before and after, shadowed knots, a knot at proto_end,
    # value offsets, and with extrapolating loops.
    inner = [knot(-3.0, 0.0, "linear"), knot(0.0, 1.0, "curve", None, None, 0.25, 1.0),
             knot(0.5, 2.0, "linear", 0.25, 0.0), knot(1.0, 1.5, "curve", None, None, 0.25, 0.0),
             knot(2.0, 9.0, "linear", 0.25, 0.0), knot(3.0, 7.0, "held"), knot(9.0, 4.0)]
    loop_cases = [
        ("both_sides", {"proto_start": 0.0, "proto_end": 1.5, "pre_loops": 1, "post_loops": 2, "value_offset": 0.5},
         {}),
        ("post_only_at_knot", {"proto_start": 0.0, "proto_end": 1.0, "post_loops": 3, "value_offset": -1.0}, {}),
        ("pre_only", {"proto_start": 0.5, "proto_end": 2.0, "pre_loops": 2}, {"before": "linear", "after": "linear"}),
        ("with_extrap_repeat", {"proto_start": 0.0, "proto_end": 1.5, "pre_loops": 1, "post_loops": 1,
                                "value_offset": 0.25}, {"before": "loop_repeat", "after": "loop_repeat"}),
        ("invalid_no_knot", {"proto_start": 0.25, "proto_end": 1.5, "post_loops": 2}, {}),
    ]
    for name, lp, f in loop_cases:
        out.append(channel(f"inner_loops/{name}", interp_tags(inner) + ["curve:bezier", "inner_loops"] +
                           extrap_tags(f), inner, inner_loops=lp, **f))
    # One knot.
    one = [knot(1.0, 2.0, "curve", 0.5, 1.0, 0.5, -1.0)]
    for f in ({"before": "linear", "after": "linear"}, {"before": "sloped", "slope_before": 2.0, "after": "sloped",
                                                        "slope_after": -0.5},
              {"before": "loop_repeat", "after": "loop_oscillate"}):
        out.append(channel(f"one_knot/{f['before']}-{f['after']}", ["one_knot", "curve:bezier"] + extrap_tags(f), one,
                           **f))
    return out


def random_splines(rng, count):
    out = []
    for n in range(count):
        nk = rng.randint(2, 6)
        t = rng.uniform(-5, 5)
        knots = []
        for i in range(nk):
            if i:
                t += rng.choice((0.25, 0.5, 1.0, 1.5, 2.0, 3.0)) * rng.choice((1.0, 1.0, 1.0 + rng.random()))
            interp = rng.choice(("curve", "curve", "curve", "linear", "held"))
            k = knot(t, rng.uniform(-3, 3), interp, None, rng.uniform(-3, 3), None, rng.uniform(-3, 3))
            knots.append(k)
        for i, k in enumerate(knots):  # widths as fractions of the adjacent intervals, some regressive
            if i:
                k["pre_width"] = (k["time"] - knots[i - 1]["time"]) * rng.choice((0.0, 0.2, 0.33, 0.6, 0.9, 1.3, 2.2))
            if i + 1 < nk:
                k["post_width"] = (knots[i + 1]["time"] - k["time"]) * rng.choice((0.0, 0.2, 0.33, 0.6, 1.0, 1.5))
            if rng.random() < 0.15 and i:
                k["pre_value"] = rng.uniform(-3, 3)
        mode = rng.choice(MODES)
        pre, post = rng.choice(EXTRAPOLATIONS), rng.choice(EXTRAPOLATIONS)
        if pre in LOOPS or post in LOOPS:  # one loop mode for both sides: each side's rule alone
            pre = post = pre if pre in LOOPS else post
        f = {"anti_regression": mode, "before": pre, "after": post}
        if pre == "sloped":
            f["slope_before"] = rng.uniform(-2, 2)
        if post == "sloped":
            f["slope_after"] = rng.uniform(-2, 2)
        tags = interp_tags(knots) + ["curve:bezier", "anti_regression:" + mode, "random"] + extrap_tags(f)
        if any("pre_value" in k for k in knots):
            tags.append("dual_valued")
        for a, b in zip(knots, knots[1:]):
            h = b["time"] - a["time"]
            if a["interpolation"] == "curve" and regressive(a["post_width"] / h, b["pre_width"] / h):
                tags.append("regressive")
        out.append(channel(f"random/{n:02d}", tags, knots, **f))
    return out


def main():
    rng = random.Random(SEED)
    channels = hand_picked() + random_splines(rng, 36)
    json.dump({"channels": channels}, sys.stdout, indent=1)
    sys.stdout.write("\n")


if __name__ == "__main__":
    main()
