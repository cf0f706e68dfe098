"""Export the F-curves of a .blend file as curvebench channel specs, so that an animator's real scene
is checked without typing keys.

Run inside Blender (--python-exit-code: without it Blender exits 0 when the script fails):
    blender -b scene.blend --python-exit-code 2 --python scripts/blender_export.py -- OUT_DIR [--values]

Writes one spec per F-curve of every action, OUT_DIR/<action>.<data path>.<index>.json, in the
"blender" tool's format (keys with their handles, handle types, interpolation, easing and its
parameters; extrapolation; auto-handle smoothing; the Cycles modifier; "handles": "stored", since
Blender evaluates the handles it stored, not their rules' results), and OUT_DIR/index.json
listing them with Blender's version and the file. Names that clean to the same file name (actions
"Walk.001" and "Walk_001", or names differing only in case) get a suffix "-2", "-3", ... in the order
exported, so that no channel overwrites another. An F-curve with a key that is not a finite number
(NaN, infinity) is skipped with the key's index (JSON holds no NaN). Files are written as
scripts/safe_output.py writes: a symbolic link, directory or device at an output path is refused,
never followed. An F-curve with another modifier (noise,
envelope, ...) or a Cycles modifier with a restricted frame range or influence is listed under
"skipped" with the reason, not exported: curvebench's Blender model would not evaluate what Blender
does. With --values, OUT_DIR/<same name>.blender.csv holds Blender's own fcurve.evaluate(t) every
half frame of the scene's range widened by 10 frames on each side (extrapolation and cycles
included; t,value: float32 results written exactly), so that
    curvebench check OUT_DIR/X.json --values OUT_DIR/X.blender.csv --against tool
shows whether curvebench reproduces Blender on this scene, and `curvebench sample OUT_DIR/X.json
--frames A:B` gives the truth to check an engine's values against. Each spec is also a case: it
carries "group": "channel" and a "reason" naming the .blend file and Blender's version, so that
`curvebench accuracy --cases OUT_DIR` measures every method on the scene's channels (the case
reader takes index.json for the folder's index, not a case).

The mapping from Blender's F-curve to the spec (spec_of) does not import bpy and is tested with
plain Python on recorded F-curves (tests/python/test_blender_export.py).
"""

import json
import os
import re
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "peers"))
import blender_fcurves  # noqa: E402  (read_fcurve, blender_version: shared with the peer driver)
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import safe_output  # noqa: E402  (write_text: never through a link)
import math  # noqa: E402

HANDLE_TYPES = {"FREE": "free", "ALIGNED": "aligned", "VECTOR": "vector", "AUTO": "auto",
                "AUTO_CLAMPED": "auto_clamped"}
EASINGS = {"AUTO": "auto", "EASE_IN": "in", "EASE_OUT": "out", "EASE_IN_OUT": "in_out"}
# Easing parameters, written only for the interpolations that read them (Blender keeps them on
# every key).
PARAMETERS = {"BACK": ("back",), "ELASTIC": ("amplitude", "period")}
EASED = {"SINE", "QUAD", "CUBIC", "QUART", "QUINT", "EXPO", "CIRC", "BACK", "BOUNCE", "ELASTIC"}


class ExportError(ValueError):
    """An F-curve the blender tool's spec cannot hold; the message says why."""


def spec_of(fcurve, name, source=""):
    """The channel spec of an F-curve read by blender_fcurves.read_fcurve (Blender's names); source
    names the .blend file and Blender's version in the case's reason."""
    if fcurve.get("modifiers"):
        raise ExportError("modifiers " + ", ".join(fcurve["modifiers"]) + " are not modelled (only Cycles)")
    if not fcurve["keys"]:
        raise ExportError("no keyframes")
    for i, k in enumerate(fcurve["keys"]):
        for field in ("time", "value", "handle_left", "handle_right") + PARAMETERS.get(k["interpolation"], ()):
            for x in (k[field] if isinstance(k[field], (list, tuple)) else [k[field]]):
                if not math.isfinite(x):
                    raise ExportError(f"key {i}: {field} is {x!r}, not a finite number (JSON holds no NaN)")
    keys = []
    for k in fcurve["keys"]:
        key = {"time": k["time"], "value": k["value"], "interpolation": k["interpolation"].lower(),
               "handle_left": list(k["handle_left"]), "handle_right": list(k["handle_right"]),
               "handle_left_type": HANDLE_TYPES[k["handle_left_type"]],
               "handle_right_type": HANDLE_TYPES[k["handle_right_type"]]}
        if k["interpolation"] in EASED:
            key["easing"] = EASINGS[k["easing"]]
            for p in PARAMETERS.get(k["interpolation"], ()):
                key[p] = k[p]
        keys.append(key)
    spec = {"name": name, "group": "channel",
            "reason": f"the F-curve {name}" + (f" of {source}" if source else "") + ", exported by blender_export.py",
            "type": "channel", "tool": "blender", "handles": "stored", "keys": keys,
            "extrapolation": fcurve["extrapolation"].lower(),
            "smoothing": fcurve.get("auto_smoothing", "CONT_ACCEL").lower()}
    cy = fcurve.get("cycles")
    if cy is not None:
        spec["cycles"] = {"before": cy["mode_before"].lower(), "after": cy["mode_after"].lower(),
                          "count_before": int(cy["cycles_before"]), "count_after": int(cy["cycles_after"])}
    return spec


def spec_text(spec):
    """The spec as JSON with one key per line (numbers as repr: the float32 values Blender stores,
    exactly)."""
    lines = []
    for k, v in spec.items():
        if k == "keys":
            inner = ",\n".join("  " + json.dumps(key, separators=(", ", ": "), allow_nan=False) for key in v)
            lines.append(f' "keys": [\n{inner}\n ]')
        else:
            lines.append(f" {json.dumps(k)}: {json.dumps(v, allow_nan=False)}")
    return "{\n" + ",\n".join(lines) + "\n}\n"


def file_name(action, data_path, index):
    """<action>.<data path>.<index>, with every character but letters, digits, '_' and '-' as '_'."""
    def clean(s):
        return re.sub(r"[^A-Za-z0-9_-]", "_", s)
    return f"{clean(action)}.{clean(data_path)}.{index}"


class Names:
    """Collision-free file names: file_name's cleaning maps "Walk.001" and "Walk_001" to one name, and a
    case-insensitive file system maps "Walk" and "walk" to one file; the second of such names gets the
    first free suffix "-2", "-3", ..., compared without case."""

    def __init__(self):
        self.used = set()

    def take(self, action, data_path, index):
        base = file_name(action, data_path, index)
        name, n = base, 1
        while name.lower() in self.used:
            n += 1
            name = f"{base}-{n}"
        self.used.add(name.lower())
        return name


def write_output(out_dir, file, text):
    """text at out_dir/file through safe_output (a link, directory or device there is refused)."""
    safe_output.write_text(os.path.join(out_dir, file), text)


def cycles_restricted(fc):
    """Why a Cycles modifier does more than repeat (a frame range, a blend, an influence), or None."""
    for m in fc.modifiers:
        if m.type != "CYCLES":
            continue
        if m.use_restricted_range:
            return "its Cycles modifier has a restricted frame range"
        if m.use_influence and m.influence != 1:
            return "its Cycles modifier has an influence below 1"
        if m.mute:
            return "its Cycles modifier is muted"
    return None


def export(bpy, out_dir, with_values):
    os.makedirs(out_dir, exist_ok=True)
    scene = bpy.context.scene
    index = {"blender_version": blender_fcurves.blender_version(bpy), "file": os.path.basename(bpy.data.filepath),
             "frames": [scene.frame_start, scene.frame_end], "channels": [], "skipped": []}
    names = Names()
    for action in bpy.data.actions:
        for fc in action.fcurves:
            name = names.take(action.name, fc.data_path, fc.array_index)
            try:
                why = cycles_restricted(fc)
                if why:
                    raise ExportError(why)
                if fc.mute:
                    raise ExportError("the F-curve is muted")
                spec = spec_of(blender_fcurves.read_fcurve(fc), name,
                               f"{index['file']} (Blender {index['blender_version']})")
            except ExportError as e:
                index["skipped"].append({"name": name, "why": str(e)})
                print(f"blender_export.py: {name}: skipped: {e}", file=sys.stderr)
                continue
            write_output(out_dir, name + ".json", spec_text(spec))
            entry = {"name": name, "spec": name + ".json"}
            if with_values:
                rows = [f"# Blender {index['blender_version']} fcurve.evaluate every half frame of the scene's "
                        "range widened by 10 frames on each side\n", "t,value\n"]
                for i in range(2 * (scene.frame_end - scene.frame_start + 20) + 1):
                    t = scene.frame_start - 10 + i / 2
                    rows.append(f"{t!r},{fc.evaluate(t)!r}\n")
                write_output(out_dir, name + ".blender.csv", "".join(rows))
                entry["values"] = name + ".blender.csv"
            index["channels"].append(entry)
    write_output(out_dir, "index.json", json.dumps(index, indent=1, allow_nan=False) + "\n")
    return index


def arguments(argv):
    args = argv[argv.index("--") + 1:] if "--" in argv else []
    values = "--values" in args
    rest = [a for a in args if a != "--values"]
    if len(rest) != 1:
        raise ExportError("usage: blender -b scene.blend --python-exit-code 2 --python scripts/blender_export.py -- "
                          "OUT_DIR [--values]")
    return rest[0], values


def main(argv):
    out_dir, values = arguments(argv)
    import bpy  # only inside Blender
    index = export(bpy, out_dir, values)
    print(f"blender_export.py: {len(index['channels'])} channels written to {out_dir}, "
          f"{len(index['skipped'])} skipped")


if __name__ == "__main__":
    try:
        main(sys.argv)
    except (ExportError, safe_output.OutputError) as e:
        print(f"blender_export.py: {e}", file=sys.stderr)
        sys.exit(2)
