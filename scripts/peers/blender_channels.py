#!/usr/bin/python3
"""Real Blender as a keyframe-channel peer: the suite's channel cases that a
Blender F-curve can hold, evaluated by Blender itself (scripts/peers/blender_fcurves.py run by
`blender -b`), beside curvebench's Blender model of the same keys and a 50-digit evaluation of the
keys Blender ended up with, into reports/peers_blender.json (REPORT.md's Peers section).

  blender_channels.py request --cases DIR --out REQUEST.json [--quick]
  blender_channels.py results --cases DIR --blender OUT.json --model-dir DIR --out FILE

Which cases: every "channel" case with "tool": "blender" (its keys, handle types, interpolation
and easing, extrapolation, smoothing and Cycles modifier as the spec says them), and every "exact"
case whose keys Blender can hold: explicit keys, every segment bezier, linear or constant, the same
extrapolation before and after (constant or linear); its keys become FREE handles at key + in and
key + out (a side without a handle: a zero-length handle at the key). The others are listed in the
notes with the reason. Times: 257 (65 with --quick) evenly spaced over the key range, and 16 on
each side beyond it over a tenth of the range (extrapolation).

Figures per case (all at the same times):
  vs_model   max |Blender - curvebench's Blender model|: the model is `curvebench sample` of the
             blender spec of the case (the case itself, or the exact case's keys as FREE handles),
             in float as Blender evaluates; MODEL_DIR/<case>.csv, written by scripts/peers.sh.
  vs_exact   max |Blender - truth| over the times inside a Bezier segment, the truth being the
             keys and handles Blender reports after fcurve.update() (the float32 values it stores,
             exact as doubles) evaluated at 60 digits in mpmath: x(u) = t solved by bisection to
             |du| < 2^-200 and y(u). Blender corrects handles that overreach the key interval
             before it evaluates; the truth does not, so a correction shows as a difference. A
             segment whose handles make time non-monotone has no value to compare (counted).
The record's error is vs_exact in eps(double) x the largest |value| of the truth; "unit_eps" 2^-23
tells the report's findings that Blender evaluates in float (a finding needs as many float ulps as
a double peer needs double ulps).
"""
import argparse
import json
import os
import sys

import peer_io

PEER = "peer_blender_fcurve"
INTERP = {"constant": "CONSTANT", "linear": "LINEAR", "bezier": "BEZIER"}
EASE = {"auto": "AUTO", "in": "EASE_IN", "out": "EASE_OUT", "in_out": "EASE_IN_OUT"}


class BlenderChannelError(Exception):
    pass


def query_times(t0, t1, quick):
    n = 64 if quick else 256
    span = t1 - t0
    inside = [t0 + span * i / n for i in range(n + 1)]
    before = [t0 - span * 0.1 * (16 - i) / 16 for i in range(16)]
    after = [t1 + span * 0.1 * (i + 1) / 16 for i in range(16)]
    return before + inside + after


def _upper(s):
    return s.upper()


def channel_of(case, spec):
    """(request channel for blender_fcurves.py, blender spec for curvebench's model) of a case, or
    (None, reason) when Blender cannot hold it."""
    if spec.get("type") != "channel":
        return None, "not a channel"
    keys = spec.get("keys")
    if not isinstance(keys, list):
        return None, "generated keys (no explicit key list)"
    tool = spec.get("tool")
    if tool == "blender":
        req = []
        for k in keys:
            r = {"time": k["time"], "value": k["value"], "interpolation": _upper(k.get("interpolation", "bezier")),
                 "easing": EASE[k.get("easing", "auto")]}
            for f in ("back", "amplitude", "period"):
                if f in k:
                    r[f] = k[f]
            for f in ("handle_left_type", "handle_right_type"):
                r[f] = _upper(k.get(f, "auto_clamped"))
            for f in ("handle_left", "handle_right"):
                if f in k:
                    r[f] = list(k[f])
            req.append(r)
        ch = {"name": case, "keys": req, "extrapolation": _upper(spec.get("extrapolation", "constant"))}
        if "smoothing" in spec:
            ch["auto_smoothing"] = _upper(spec["smoothing"])
        if "cycles" in spec:
            cy = spec["cycles"]
            ch["cycles"] = {"mode_before": _upper(cy.get("before", "repeat")),
                            "mode_after": _upper(cy.get("after", "repeat")),
                            "cycles_before": cy.get("count_before", 0), "cycles_after": cy.get("count_after", 0)}
        return ch, dict(spec)
    if tool != "exact":
        return None, f"tool {tool}: not a Blender F-curve"
    ex = {spec.get("before", "constant"), spec.get("after", "constant")}
    if len(ex) != 1 or not ex <= {"constant", "linear"}:
        return None, f"extrapolation before {spec.get('before', 'constant')} / after {spec.get('after', 'constant')}"
    req, model = [], []
    for i, k in enumerate(keys):
        interp = k.get("interpolation", "bezier")
        if interp not in INTERP:
            return None, f"keys[{i}].interpolation {interp}: no Blender interpolation"
        t, v = k["time"], k["value"]
        hl = [t + k["in"][0], v + k["in"][1]] if "in" in k else [t, v]
        hr = [t + k["out"][0], v + k["out"][1]] if "out" in k else [t, v]
        r = {"time": t, "value": v, "interpolation": INTERP[interp], "handle_left_type": "FREE",
             "handle_right_type": "FREE", "handle_left": hl, "handle_right": hr}
        req.append(r)
        model.append({"time": t, "value": v, "interpolation": interp, "handle_left_type": "free",
                      "handle_right_type": "free", "handle_left": hl, "handle_right": hr})
    extrap = ex.pop()
    return ({"name": case, "keys": req, "extrapolation": extrap.upper()},
            {"type": "channel", "tool": "blender", "keys": model, "extrapolation": extrap})


def request(specs, quick):
    """(request document, model specs {case: spec}, notes)."""
    channels, models, notes = [], {}, []
    for case, spec in sorted(specs.items()):
        ch, model = channel_of(case, spec)
        if ch is None:
            if spec.get("type") == "channel" and spec.get("tool") in ("blender", "exact"):
                notes.append(f"{case}: not run in Blender ({model})")
            continue
        ts = [k["time"] for k in ch["keys"]]
        ch["times"] = query_times(min(ts), max(ts), quick)
        channels.append(ch)
        models[case] = model
    return {"note": "scripts/peers/blender_channels.py request", "channels": channels}, models, notes


def _bezier_monotone(x0, x1, x2, x3):
    a, b, c = x1 - x0, x2 - x1, x3 - x2
    return a >= 0 and c >= 0 and (b >= 0 or b * b <= a * c)


def truth(keys, t):
    """The 60-digit value at t of the Bezier segment of Blender's read-back keys holding t; None
    outside the keys, on a segment that is not BEZIER, or where time is not monotone."""
    import mpmath
    with mpmath.workdps(60):
        t = mpmath.mpf(t)
        for k0, k1 in zip(keys, keys[1:]):
            if not (k0["time"] <= t <= k1["time"]):
                continue
            if k0["interpolation"] != "BEZIER":
                return None
            xs = [mpmath.mpf(x) for x in (k0["time"], k0["handle_right"][0], k1["handle_left"][0], k1["time"])]
            ys = [mpmath.mpf(y) for y in (k0["value"], k0["handle_right"][1], k1["handle_left"][1], k1["value"])]
            if not _bezier_monotone(*xs):
                return None

            def bez(p, u):
                v = 1 - u
                return v ** 3 * p[0] + 3 * v * v * u * p[1] + 3 * v * u * u * p[2] + u ** 3 * p[3]
            lo, hi = mpmath.mpf(0), mpmath.mpf(1)
            for _ in range(200):
                mid = (lo + hi) / 2
                if bez(xs, mid) < t:
                    lo = mid
                else:
                    hi = mid
            return bez(ys, (lo + hi) / 2)
        return None


def read_model(path, times):
    """The Blender model's values (`curvebench sample --as-tool`, float: its t printed to 9 digits)."""
    return peer_io.read_sample(path, times, error=BlenderChannelError, exact_times=False)


def assemble(blender, model_values, notes=()):
    """The peers_blender.json document from Blender's output and model_values(case, times) (the
    model's values, or None)."""
    import mpmath
    if "blender_version" not in blender or not isinstance(blender.get("channels"), list):
        raise BlenderChannelError("Blender's output: expected blender_version and channels")
    records, summary = [], []
    for ch in blender["channels"]:
        case, times, values = ch["name"], ch["times"], ch["values"]
        if len(values) != len(times):
            raise BlenderChannelError(f"{case}: {len(values)} values for {len(times)} times")
        truths = [truth(ch["keys"], t) for t in times]
        inside = [(v, y) for v, y in zip(values, truths) if y is not None]
        in_range = sum(1 for t in times if ch["keys"][0]["time"] <= t <= ch["keys"][-1]["time"])
        row = {"case": case, "times": len(times), "compared_with_exact": len(inside),
               "in_key_range": in_range}
        rec = {"case": case, "group": "channel", "quantity": "eval", "method": PEER, "setting": "", "estimate": None,
               "bounded": None, "status": "not_guaranteed", "peer": True, "peer_status": "success",
               "library": f"Blender {blender['blender_version']}", "evaluations": len(times), "ns_per_op": None,
               "counterpart_ns_per_op": None, "definition": "the keys Blender holds, evaluated",
               "unit_eps": 2.0 ** -23}  # Blender evaluates in float: findings count its own ulps
        if inside:
            with mpmath.workdps(60):
                size = max(abs(y) for _, y in inside) or mpmath.mpf(1)
                worst = max(abs(mpmath.mpf(v) - y) for v, y in inside)
            row["vs_exact"] = float(worst)
            rec.update({"error": float(worst / (2.0 ** -52 * size)), "abs_error": float(worst)})
        else:
            rec.update({"error": None})
        model = model_values(case, times)
        if model is not None:
            row["vs_model"] = max(abs(a - b) for a, b in zip(values, model))
            rec["vs_model"] = row["vs_model"]
            if inside:
                with mpmath.workdps(60):
                    mi = [(m, y) for m, y in zip(model, truths) if y is not None]
                    rec["counterpart"] = {"method": "curvebench blender model (float)", "setting": ""}
                    rec["counterpart_error"] = float(max(abs(mpmath.mpf(m) - y) for m, y in mi) / (2.0 ** -52 * size))
        records.append(rec)
        summary.append(row)
    return {"driver": "blender", "versions": {"Blender": blender["blender_version"]}, "notes": list(notes),
            "channels": summary, "peer_records": records}


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("step", choices=("request", "results"))
    ap.add_argument("--cases", required=True)
    ap.add_argument("--out", required=True)
    ap.add_argument("--quick", action="store_true")
    ap.add_argument("--blender", help="results: blender_fcurves.py's output")
    ap.add_argument("--model-dir", help="request: where the model specs go; results: where their samples are")
    a = ap.parse_args()
    try:
        specs = {}
        for f in sorted(os.listdir(a.cases)):
            if f.endswith(".json"):
                with open(os.path.join(a.cases, f), encoding="utf-8") as fh:
                    specs[f[:-5]] = json.load(fh)
        req, models, notes = request(specs, a.quick)
        if a.step == "request":
            os.makedirs(a.model_dir, exist_ok=True)
            for case, model in models.items():
                with open(os.path.join(a.model_dir, case + ".json"), "w", encoding="utf-8") as f:
                    json.dump(model, f)
            for ch in req["channels"]:
                with open(os.path.join(a.model_dir, ch["name"] + ".times"), "w", encoding="utf-8") as f:
                    f.write("".join(repr(t) + "\n" for t in ch["times"]))
            with open(a.out, "w", encoding="utf-8") as f:
                json.dump(req, f, indent=1)
            print(f"blender_channels: {len(req['channels'])} channels -> {a.out}")
            return 0
        with open(a.blender, encoding="utf-8") as f:
            blender = json.load(f)

        def model(case, times):
            path = os.path.join(a.model_dir, case + ".csv")
            return read_model(path, times) if os.path.exists(path) else None
        doc = assemble(blender, model, notes)
    except (OSError, KeyError, json.JSONDecodeError, BlenderChannelError) as e:
        print(f"blender_channels: {e}", file=sys.stderr)
        return 1
    peer_io.write_json(a.out, doc)
    print(f"blender_channels: {len(doc['peer_records'])} channels -> {a.out}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
