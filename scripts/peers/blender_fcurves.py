"""Evaluate keyframe channels with real Blender: the peer that records Blender's F-curve values.

Run inside Blender:
    blender -b --factory-startup --python scripts/peers/blender_fcurves.py -- IN.json OUT.json \
        [--common CURVEBENCH]
Without Blender, after a change of curvebench's model:
    python3 scripts/peers/blender_fcurves.py --refresh-refusals RECORDING.json CURVEBENCH

IN.json is a list of channels, or an object {"channels": [...], "note": "..."} (the note, e.g. the
command that regenerated the file, is copied to the output). A channel:
    {"name": "quad/in",                      (any text; copied)
     "keys": [{"time": 1, "value": 2,
               "interpolation": "QUAD",      (Blender's names: CONSTANT, LINEAR, BEZIER, SINE, ...)
               "easing": "EASE_IN",          (AUTO, EASE_IN, EASE_OUT, EASE_IN_OUT; optional)
               "back": 1.70158, "amplitude": 0.8, "period": 4.1,        (optional)
               "handle_left_type": "FREE", "handle_right_type": "FREE", (optional)
               "handle_left": [0, 2], "handle_right": [2, 2]},          (optional)
              ...],
     "extrapolation": "CONSTANT",            (or LINEAR; optional)
     "auto_smoothing": "NONE",               (or CONT_ACCEL; optional, Blender's default for new
                                              F-curves is CONT_ACCEL)
     "cycles": {"mode_before": "REPEAT", "mode_after": "REPEAT",
                "cycles_before": 0, "cycles_after": 0},                 (optional Cycles modifier)
     "times": [1, 1.5, ...]}                 (where to call fcurve.evaluate)
Each channel becomes an F-curve on location[0] of its own empty object in the factory scene. Keys are
set in the order given, handle types before handle coordinates, and fcurve.update() runs once after
all keys are set (it sorts the keys and recomputes automatic handles, as the UI would).

OUT.json: {"blender_version": "3.4.1", "note": ..., "channels": [{"name", "keys", "extrapolation",
"cycles", "times", "values"}]} where "keys" are read back from Blender after update() (so they hold
the float32 values Blender stores: back = 1.70158 reads back as 1.7015800476074219) and "values"
are fcurve.evaluate(t) at each time (float32 results, written as exact doubles).

With --common CURVEBENCH (the path of curvebench's CLI), OUT.json is written in the common recording
format of tests/data (tool, source, channels of {name, features, spec, t, value}): each channel's
spec is the "blender" tool's channel spec of the F-curve Blender holds after update(), made by
scripts/blender_export.py's spec_of (one conversion for both), and a spec that `CURVEBENCH sample`
refuses keeps its values with "refused": the CLI's message. A channel may carry "features" (tags,
copied).

The reading, checking and writing functions do not import bpy, so they can be tested with plain
Python (tests/python/test_blender_fcurves.py).
"""

import json
import math
import os
import sys

INTERPOLATIONS = ("CONSTANT", "LINEAR", "BEZIER", "SINE", "QUAD", "CUBIC", "QUART", "QUINT", "EXPO", "CIRC",
                  "BACK", "BOUNCE", "ELASTIC")
EASINGS = ("AUTO", "EASE_IN", "EASE_OUT", "EASE_IN_OUT")
HANDLE_TYPES = ("FREE", "ALIGNED", "VECTOR", "AUTO", "AUTO_CLAMPED")
EXTRAPOLATIONS = ("CONSTANT", "LINEAR")
CYCLE_MODES = ("NONE", "REPEAT", "REPEAT_OFFSET", "MIRROR")
KEY_FIELDS = ("time", "value", "interpolation", "easing", "back", "amplitude", "period", "handle_left_type",
              "handle_right_type", "handle_left", "handle_right")
CHANNEL_FIELDS = ("name", "features", "keys", "extrapolation", "auto_smoothing", "cycles", "times")
AUTO_SMOOTHINGS = ("NONE", "CONT_ACCEL")
CYCLE_FIELDS = ("mode_before", "mode_after", "cycles_before", "cycles_after")


class RequestError(ValueError):
    """A malformed request; the message names the field by its path."""


def _number(path, value):
    if isinstance(value, bool) or not isinstance(value, (int, float)) or not math.isfinite(value):
        raise RequestError(f"{path} = {value!r}: expected a finite number")
    return float(value)


def _choice(path, value, allowed):
    if value not in allowed:
        raise RequestError(f"{path} = {value!r}: expected one of {', '.join(allowed)}")
    return value


def _pair(path, value):
    if not isinstance(value, list) or len(value) != 2:
        raise RequestError(f"{path} = {value!r}: expected [time, value]")
    return [_number(f"{path}[{i}]", v) for i, v in enumerate(value)]


def _unknown(path, obj, known):
    for k in obj:
        if k not in known:
            raise RequestError(f"{path}.{k}: unknown field (known: {', '.join(known)})")


def check_request(data):
    """Returns (channels, note) with every field checked; raises RequestError naming the bad field."""
    note = None
    if isinstance(data, dict):
        _unknown("request", data, ("channels", "note"))
        note = data.get("note")
        data = data.get("channels")
    if not isinstance(data, list) or not data:
        raise RequestError("channels: expected a non-empty list")
    out = []
    for ci, ch in enumerate(data):
        p = f"channels[{ci}]"
        if not isinstance(ch, dict):
            raise RequestError(f"{p}: expected an object")
        _unknown(p, ch, CHANNEL_FIELDS)
        keys = ch.get("keys")
        if not isinstance(keys, list) or len(keys) < 1:
            raise RequestError(f"{p}.keys: expected a non-empty list")
        checked_keys = []
        for ki, k in enumerate(keys):
            kp = f"{p}.keys[{ki}]"
            if not isinstance(k, dict):
                raise RequestError(f"{kp}: expected an object")
            _unknown(kp, k, KEY_FIELDS)
            ck = {"time": _number(f"{kp}.time", k.get("time")), "value": _number(f"{kp}.value", k.get("value"))}
            ck["interpolation"] = _choice(f"{kp}.interpolation", k.get("interpolation", "BEZIER"), INTERPOLATIONS)
            ck["easing"] = _choice(f"{kp}.easing", k.get("easing", "AUTO"), EASINGS)
            for f in ("back", "amplitude", "period"):
                if f in k:
                    ck[f] = _number(f"{kp}.{f}", k[f])
            for f in ("handle_left_type", "handle_right_type"):
                if f in k:
                    ck[f] = _choice(f"{kp}.{f}", k[f], HANDLE_TYPES)
            for f in ("handle_left", "handle_right"):
                if f in k:
                    ck[f] = _pair(f"{kp}.{f}", k[f])
            checked_keys.append(ck)
        times = ch.get("times")
        if not isinstance(times, list) or not times:
            raise RequestError(f"{p}.times: expected a non-empty list of numbers")
        features = ch.get("features", [])
        if not isinstance(features, list) or not all(isinstance(f, str) for f in features):
            raise RequestError(f"{p}.features = {features!r}: expected a list of strings")
        c = {"name": str(ch.get("name", f"channel{ci}")), "keys": checked_keys,
             "extrapolation": _choice(f"{p}.extrapolation", ch.get("extrapolation", "CONSTANT"), EXTRAPOLATIONS),
             "times": [_number(f"{p}.times[{i}]", t) for i, t in enumerate(times)]}
        if features:
            c["features"] = features
        if "auto_smoothing" in ch:
            c["auto_smoothing"] = _choice(f"{p}.auto_smoothing", ch["auto_smoothing"], AUTO_SMOOTHINGS)
        if "cycles" in ch:
            cy = ch["cycles"]
            if not isinstance(cy, dict):
                raise RequestError(f"{p}.cycles: expected an object")
            _unknown(f"{p}.cycles", cy, CYCLE_FIELDS)
            c["cycles"] = {
                "mode_before": _choice(f"{p}.cycles.mode_before", cy.get("mode_before", "REPEAT"), CYCLE_MODES),
                "mode_after": _choice(f"{p}.cycles.mode_after", cy.get("mode_after", "REPEAT"), CYCLE_MODES),
                "cycles_before": int(_number(f"{p}.cycles.cycles_before", cy.get("cycles_before", 0))),
                "cycles_after": int(_number(f"{p}.cycles.cycles_after", cy.get("cycles_after", 0)))}
        out.append(c)
    return out, note


def read_request(path):
    with open(path, encoding="utf-8") as f:
        return check_request(json.load(f))


def result_document(version, note, channels):
    """The output document; `channels` are the checked channels with "keys" read back and "values" added."""
    doc = {"blender_version": version}
    if note is not None:
        doc["note"] = note
    doc["channels"] = channels
    return doc


def write_result(path, doc):
    # json writes floats with repr(): the shortest text that reads back as the same double, so the
    # float32 values Blender returns survive exactly.
    # One channel per line keeps recorded fixtures small and their diffs readable.
    with open(path, "w", encoding="utf-8") as f:
        f.write("{\n")
        for k, v in doc.items():
            if k != "channels":
                f.write(f" {json.dumps(k)}: {json.dumps(v)},\n")
        f.write(' "channels": [\n')
        f.write(",\n".join("  " + json.dumps(ch, separators=(",", ":")) for ch in doc["channels"]))
        f.write("\n ]\n}\n")


def script_arguments(argv):
    """The arguments after Blender's "--" separator: [IN.json, OUT.json] (and the CLI's path after
    --common, when given: [IN.json, OUT.json, CURVEBENCH])."""
    args = argv[argv.index("--") + 1:] if "--" in argv else []
    if len(args) == 4 and args[2] == "--common":
        return [args[0], args[1], args[3]]
    if len(args) != 2:
        raise RequestError("usage: blender -b --factory-startup --python blender_fcurves.py -- IN.json OUT.json "
                           "[--common CURVEBENCH]")
    return args


def refusal(curvebench, spec, times):
    """None when `curvebench sample` evaluates the spec at the times (values only), as the truth and
    with --as-tool, else its message."""
    import subprocess
    import tempfile
    with tempfile.TemporaryDirectory() as d:
        path = f"{d}/spec.json"
        with open(path, "w", encoding="utf-8") as f:
            json.dump(spec, f)
        with open(f"{d}/t.txt", "w", encoding="utf-8") as f:
            f.write("".join(f"{t!r}\n" for t in times))
        for tool in ([], ["--as-tool"]):  # the spec's reader, then the tool's own (float32) evaluation
            run = subprocess.run([curvebench, "sample", path, "--at-file", f"{d}/t.txt", "--derivatives", "0",
                                  "--quiet"] + tool, capture_output=True, text=True)
            if run.returncode != 0:
                return " ".join(run.stderr.replace(path, "spec.json").split())
    return None


def common_document(source, channels, spec_of, curvebench):
    """The common recording format: {"tool": "blender", "source", "channels": [{"name", "features",
    "spec", "t", "value"} and "refused" when curvebench's reader refuses the spec]}."""
    out = []
    for ch in channels:
        spec = spec_of(ch, ch["name"])
        entry = {"name": ch["name"], "features": ch.get("features", []), "spec": spec, "t": ch["times"],
                 "value": ch["values"]}
        why = refusal(curvebench, spec, ch["times"])
        if why is not None:
            entry["refused"] = why
        out.append(entry)
    return {"tool": "blender", "source": source, "channels": out}


def read_fcurve(fc):
    """An F-curve as Blender holds it: {"keys", "extrapolation", "auto_smoothing"} and "cycles" when it
    has a Cycles modifier, in Blender's names (the request's format); "modifiers" lists the types of
    any other modifiers (which curvebench's Blender model does not evaluate)."""
    keys = [{"time": kp.co[0], "value": kp.co[1], "interpolation": kp.interpolation, "easing": kp.easing,
             "back": kp.back, "amplitude": kp.amplitude, "period": kp.period,
             "handle_left_type": kp.handle_left_type, "handle_right_type": kp.handle_right_type,
             "handle_left": list(kp.handle_left), "handle_right": list(kp.handle_right)}
            for kp in fc.keyframe_points]
    r = {"keys": keys, "extrapolation": fc.extrapolation, "auto_smoothing": fc.auto_smoothing}
    others = []
    for m in fc.modifiers:
        if m.type == "CYCLES" and "cycles" not in r:
            r["cycles"] = {f: getattr(m, f) for f in CYCLE_FIELDS}
        else:
            others.append(m.type)
    if others:
        r["modifiers"] = others
    return r


def blender_version(bpy):
    """Blender's version as "3.4.1"."""
    return ".".join(str(v) for v in bpy.app.version)


def evaluate_in_blender(bpy, channels):
    """Builds one F-curve per channel and evaluates it; returns the channels with keys read back and values."""
    scene = bpy.context.scene
    results = []
    for ci, ch in enumerate(channels):
        obj = bpy.data.objects.new(f"curvebench_{ci}", None)
        scene.collection.objects.link(obj)
        action = bpy.data.actions.new(f"curvebench_action_{ci}")
        obj.animation_data_create()
        obj.animation_data.action = action
        fc = action.fcurves.new("location", index=0)
        if "auto_smoothing" in ch:
            fc.auto_smoothing = ch["auto_smoothing"]
        fc.keyframe_points.add(len(ch["keys"]))
        for kp, k in zip(fc.keyframe_points, ch["keys"]):
            kp.co = (k["time"], k["value"])
            kp.interpolation = k["interpolation"]
            kp.easing = k["easing"]
            for f in ("back", "amplitude", "period"):
                if f in k:
                    setattr(kp, f, k[f])
            for f in ("handle_left_type", "handle_right_type", "handle_left", "handle_right"):
                if f in k:
                    setattr(kp, f, k[f])
        fc.extrapolation = ch["extrapolation"]
        if "cycles" in ch:
            m = fc.modifiers.new("CYCLES")
            for f in CYCLE_FIELDS:
                setattr(m, f, ch["cycles"][f])
        fc.update()
        r = {"name": ch["name"], **read_fcurve(fc)}
        if "features" in ch:
            r["features"] = ch["features"]
        r["times"] = ch["times"]
        r["values"] = [fc.evaluate(t) for t in ch["times"]]
        results.append(r)
    return results


def source_of(bpy, note):
    """The "source" of the common recording format for this Blender."""
    import datetime
    import platform

    def text(b):
        return b.decode() if isinstance(b, bytes) else str(b)
    return {"implementation": "Blender", "repository": "https://projects.blender.org/blender/blender",
            "commit": f"{bpy.app.version_string} (build hash {text(bpy.app.build_hash)})",
            "version": bpy.app.version_string,
            "build": f"the distribution's binary ({platform.system()} {platform.machine()}, build type "
                     f"{text(bpy.app.build_type)}); F-curves evaluated in float32 by fcurve.evaluate",
            "recorded": datetime.date.today().isoformat(),
            "command": note.split("regenerate with: ", 1)[-1] if note else "scripts/peers/blender_fcurves.py"}


def refresh_refusals(path, curvebench):
    """Recomputes each channel's "refused" in a common recording (no Blender needed): after a model
    change, a refusal curvebench no longer makes is dropped and a new one recorded with its message.
    Returns (dropped, added)."""
    with open(path, encoding="utf-8") as f:
        doc = json.load(f)
    dropped = added = 0
    for entry in doc["channels"]:
        why = refusal(curvebench, entry["spec"], entry["t"])
        if why is None and "refused" in entry:
            del entry["refused"]
            dropped += 1
        elif why is not None and entry.get("refused") != why:
            entry["refused"] = why
            added += 1
    write_result(path, doc)
    return dropped, added


def main(argv):
    if len(argv) == 4 and argv[1] == "--refresh-refusals":
        dropped, added = refresh_refusals(argv[2], argv[3])
        print(f"{dropped} refusals dropped, {added} recorded", file=sys.stderr)
        return
    args = script_arguments(argv)
    channels, note = read_request(args[0])
    import bpy  # only inside Blender
    results = evaluate_in_blender(bpy, channels)
    if len(args) == 3:
        sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
        import blender_export  # noqa: E402  (spec_of: the one conversion of an F-curve to a spec)
        write_result(args[1], common_document(source_of(bpy, note), results, blender_export.spec_of, args[2]))
    else:
        write_result(args[1], result_document(blender_version(bpy), note, results))


if __name__ == "__main__":
    try:
        main(sys.argv)
    except RequestError as e:
        print(f"blender_fcurves.py: {e}", file=sys.stderr)
        sys.exit(2)
