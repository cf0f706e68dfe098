"""Run inside Blender by scripts/peers/blender_length_driver.py: Spline.calc_length() and the
Follow Path position of Bezier curve objects built from the driver's input, written as JSON.

  blender -b --factory-startup --python scripts/peers/blender_length.py -- IN.json OUT.json

IN (written by blender_length_driver.py): {"resolutions": [12, 4, 64], "pass_ns", "passes", "cases":
[{"case", "splines": [{"cyclic": bool, "points": [[co, handle_left, handle_right], ...]}] (each an
[x, y] in the request's coordinates, z = 0), "s": [...], "spaced": n}]}.
OUT: {"blender": bpy.app.version_string, "cases": [{"case", "results": [{"resolution", "length",
"ns_length", "points", "spaced", "ns_point", "follow_note"}]} or {"case", "error"}]}.

A case with "nurbs" ({"points": [[x, y, z, w]], "order", "endpoint", "cyclic"}) is one NURBS spline
instead, and its results also carry "start" and "end": Follow Path at offset 0 and 1. Points are
read as (x, y, z) for NURBS cases, (x, y) for Bezier ones.

Per case one curve object ('3D', every handle FREE, so Blender keeps the given handles), one
spline per subpath. Per resolution, every spline's resolution_u (and the curve's) is set and the
length is the sum of Spline.calc_length() over the splines, as a user calls it; ns_length times
that sum with peer_io.best_ns (count doubled until a pass lasts pass_ns, best of `passes`).
Follow Path (single-spline cases; Blender's path follows the curve's first spline only): an empty at
the origin with a FOLLOW_PATH constraint on the curve, use_fixed_location on, the curve's use_path
on; offset_factor = min(s / L, 1) with L the calc_length at that resolution, then
depsgraph.update() and the empty's matrix_world translation (x, y) read back. spaced: offset_factor
k / (n - 1). ns_point: per point, the offset_factor change, the depsgraph update and the read,
averaged over the s (best of `passes` passes over all of them).
"""
import json
import os
import sys
import time

import bpy

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import peer_io  # noqa: E402


def argv_after_dashes():
    argv = sys.argv
    return argv[argv.index("--") + 1:] if "--" in argv else []


def build(case, index):
    cu = bpy.data.curves.new(f"cb_curve_{index}", 'CURVE')
    cu.dimensions = '3D'
    cu.use_path = True
    if "nurbs" in case:
        nu = case["nurbs"]
        sp = cu.splines.new('NURBS')
        sp.points.add(len(nu["points"]) - 1)
        for pt, co in zip(sp.points, nu["points"]):
            pt.co = co  # (x, y, z, w): co[3] is the weight (Blender 3.4's point.weight reads the same value)
        sp.order_u = nu["order"]
        sp.use_endpoint_u = bool(nu["endpoint"])
        sp.use_cyclic_u = bool(nu["cyclic"])
        ob = bpy.data.objects.new(f"cb_path_{index}", cu)
        bpy.context.scene.collection.objects.link(ob)
        return cu, ob
    for sp_in in case["splines"]:
        sp = cu.splines.new('BEZIER')
        pts = sp_in["points"]
        sp.bezier_points.add(len(pts) - 1)
        for bp, (co, hl, hr) in zip(sp.bezier_points, pts):
            bp.handle_left_type = 'FREE'
            bp.handle_right_type = 'FREE'
            bp.co = (co[0], co[1], 0.0)
            bp.handle_left = (hl[0], hl[1], 0.0)
            bp.handle_right = (hr[0], hr[1], 0.0)
        sp.use_cyclic_u = bool(sp_in["cyclic"])
    ob = bpy.data.objects.new(f"cb_path_{index}", cu)
    bpy.context.scene.collection.objects.link(ob)
    return cu, ob


def follow(ob, fractions, passes):
    """[(x, y)] of an empty following ob at each offset_factor, and ns per point."""
    e = bpy.data.objects.new("cb_follower", None)
    bpy.context.scene.collection.objects.link(e)
    c = e.constraints.new('FOLLOW_PATH')
    c.target = ob
    c.use_fixed_location = True
    c.use_curve_follow = False
    dg = bpy.context.evaluated_depsgraph_get()
    out = []
    for f in fractions:
        c.offset_factor = f
        dg.update()
        t = e.matrix_world.translation
        out.append([t[0], t[1], t[2]])
    best = None
    for _ in range(passes):
        t0 = time.perf_counter_ns()
        for f in fractions:
            c.offset_factor = f
            dg.update()
            t = e.matrix_world.translation
        dt = (time.perf_counter_ns() - t0) / max(1, len(fractions))
        best = dt if best is None else min(best, dt)
    bpy.data.objects.remove(e)
    return out, best


def run_case(case, index, resolutions, pass_ns, passes):
    cu, ob = build(case, index)
    results = []
    for res in resolutions:
        cu.resolution_u = res
        for sp in cu.splines:
            sp.resolution_u = res
        splines = list(cu.splines)

        def length():
            total = 0.0
            for sp in splines:
                total += sp.calc_length()
            return total
        L = length()
        _, ns = peer_io.best_ns(length, pass_ns, passes)
        r = {"resolution": res, "length": L, "ns_length": ns, "points": None, "spaced": None, "ns_point": None}
        if len(splines) == 1 and L > 0:
            fr = [min(s / L, 1.0) for s in case["s"]]
            r["points"], r["ns_point"] = follow(ob, fr, passes)
            n = case["spaced"]
            if n >= 2:
                r["spaced"], _ = follow(ob, [k / (n - 1) for k in range(n)], 1)
            if "nurbs" in case:  # the evaluated path's ends, for the driver's check of the knot vector
                r["start"], r["end"] = follow(ob, [0.0, 1.0], 1)[0]
            else:  # a Bezier case is planar: (x, y)
                r["points"] = [p[:2] for p in r["points"]]
                r["spaced"] = r["spaced"] and [p[:2] for p in r["spaced"]]
        results.append(r)
    bpy.data.objects.remove(ob)
    bpy.data.curves.remove(cu)
    return {"case": case["case"], "results": results}


def main():
    args = argv_after_dashes()
    if len(args) != 2:
        raise SystemExit("blender_length.py: expected -- IN.json OUT.json")
    with open(args[0], encoding="utf-8") as f:
        doc = json.load(f)
    out = {"blender": bpy.app.version_string, "cases": []}
    for i, case in enumerate(doc["cases"]):
        try:
            out["cases"].append(run_case(case, i, doc["resolutions"], doc["pass_ns"], doc["passes"]))
        except Exception as e:  # one case's failure is a finding for that case, not the end of the run
            out["cases"].append({"case": case["case"], "error": f"{type(e).__name__}: {e}"})
    with open(args[1] + ".tmp", "w", encoding="utf-8") as f:
        json.dump(out, f)
    os.replace(args[1] + ".tmp", args[1])


main()
