#!/usr/bin/python3
"""Arc length and the point at arc length as Blender's curve objects compute them:
Spline.calc_length() and the Follow Path constraint on Bezier curves built from the cases of a
shipped-peer request, written as JSON (format curvebench-shipped-driver-1) for
scripts/peers/shipped_results.py to measure.

  blender_length_driver.py --request FILE --out FILE [--quick] [--only CASE,...] [--blender PATH]
                           [--timeout SECONDS] [--keep DIR]

Runs `blender -b --factory-startup --python scripts/peers/blender_length.py -- IN OUT` (Debian's
blender 3.4) once for all cases, under a time limit (--timeout, default 600 s), and turns its answer
into runs. Peer peer_blender_calc_length, settings "" (resolution_u 12, Blender's default),
"resolution=4" and "resolution=64".

What Blender computes (from its sources): each Bezier segment is sampled by forward
differences at resolution_u points (float), and calc_length sums the chords of that polyline
(float); coordinates are stored as float32. Follow Path places an object along the curve's path,
built from the same evaluated polyline; with use_fixed_location, offset_factor is the fraction of
that path's length.

The request's segments become one Bezier spline per subpath, every handle FREE: a cubic as is; a
quadratic raised exactly to a cubic (handles 2/3 of the way from each end to its control point);
a line as a cubic with its handles at one and two thirds of the line (so Blender samples it
uniformly); an elliptical arc has no exact Bezier form: its case is skipped. A closed subpath (its
last segment ends at its start) is a cyclic spline (use_cyclic_u) of one point per segment (no
explicit closing point: the cyclic spline's own segment from its last point back to its first
carries one of the request's segments with its handles). Blender's path of a cyclic spline begins
with that wrap-around segment (observed in 3.4: a square's Follow Path started at its last point),
so the points are rotated by one: point j is the start of segment j + 1, and the wrap-around
segment is the subpath's first, from its start. Coordinates go in unchanged (SVG's
y down: a reflection, which changes no length) and points come back in them.

The request's "splines" (curvebench's bspline/nurbs cases) become one NURBS spline each: order =
degree + 1, point.co = (x, y, z, w) with w the weight (1 without; in 3.4 point.weight is that same
co[3]), use_endpoint_u for "clamped", use_cyclic_u for "periodic", neither for "uniform"; a "given"
knot vector is skipped (Blender makes its own knots). Blender's knots for these flags must give
curvebench's curve: Follow Path's position at offset 0 must be the request's "start" to float32
rounding and at offset 1 its "end" to END_GAP (see there), else the case is skipped. Blender samples
a NURBS spline at resolution_u points per control-point interval, uniformly in the parameter.
Points of those cases come back with the request's "dim" coordinates.

Points: Follow Path at every resolution, for paths of one subpath (Blender's path follows the first
spline only; several subpaths: points null). The point at s is asked with offset_factor =
min(s / L_blender, 1) (an s beyond Blender's own length asked at its length); spaced at
offset_factor k / (n - 1). Times (time.perf_counter_ns inside Blender): ns_length the sum of
calc_length() over the splines (count doubled until a pass lasts 1 ms, best of 5 passes; quick:
0.2 ms, best of 3); ns_point one offset_factor change, depsgraph update and matrix_world read,
averaged over the s (best of the passes); ns_build null.
"""
import argparse
import json
import math
import os
import shutil
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import peer_io  # noqa: E402
from peer_io import DriverError, cubic_of, load_request, read_cpu  # noqa: E402,F401

DRIVER = "blender_length"
FORMAT = "curvebench-shipped-driver-1"
PEER = "peer_blender_calc_length"
RESOLUTIONS = ((12, ""), (4, "resolution=4"), (64, "resolution=64"))
SCRIPT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "blender_length.py")
TIMEOUT_S = 600.0


def cubics_of(subpath):
    """The subpath's segments as cubics, and whether it closes on its start (closed, and its last
    segment ends exactly at its start)."""
    cubics = [cubic_of(s) for s in subpath["segments"]]
    closes = bool(subpath.get("closed")) and bool(cubics) and cubics[-1][3] == cubics[0][0]
    return cubics, closes


def spline_of(subpath):
    """{"cyclic", "points": [[co, handle_left, handle_right]]} of a subpath: one Bezier point per
    segment start; an open spline adds its end point (its outer handles on the point itself); a
    cyclic one starts at segment 1's start, its wrap-around segment being segment 0."""
    cubics, cyclic = cubics_of(subpath)
    if not cubics:
        raise DriverError("a subpath without segments")
    n = len(cubics)
    if cyclic:
        # Point j is the start of segment j + 1 (mod n): Blender's path of a cyclic spline begins
        # with its wrap-around segment (from the last point to the first, observed in 3.4), which is
        # then the subpath's first segment, so Follow Path starts where the request starts.
        pts = [[cubics[(j + 1) % n][0], cubics[j][2], cubics[(j + 1) % n][1]] for j in range(n)]
    else:
        pts = [[cubics[0][0], cubics[0][0], cubics[0][1]]]
        pts += [[cubics[i][0], cubics[i - 1][2], cubics[i][1]] for i in range(1, n)]
        pts.append([cubics[-1][3], cubics[-1][2], cubics[-1][3]])
    return {"cyclic": cyclic, "points": pts}


def nurbs_of(c):
    """Blender's NURBS spline of a request "splines" case: {"points": [[x, y, z, w]] (w the weight, 1
    without weights), "order": degree + 1, "endpoint": clamped, "cyclic": periodic}; DriverError for a
    knot vector Blender's flags cannot make ("given")."""
    kind = c["knot_vector"]
    if kind not in ("clamped", "uniform", "periodic"):
        raise DriverError(f"knot_vector {kind!r}: Blender's NURBS splines make their own knots (endpoint, "
                          "cyclic or uniform flags) and cannot hold a given vector")
    w = c.get("weights") or [1.0] * len(c["points"])
    if len(w) != len(c["points"]):
        raise DriverError("not one weight per point")
    pts = [[float(p[0]), float(p[1]), float(p[2]) if len(p) > 2 else 0.0, float(wi)] for p, wi in zip(c["points"], w)]
    return {"points": pts, "order": int(c["degree"]) + 1, "endpoint": kind == "clamped", "cyclic": kind == "periodic"}


def blender_input(cases, quick=False, spline_cases=()):
    """(Blender's input document, skipped entries for the cases it cannot represent); `splines` the
    request's "splines" cases (NURBS splines)."""
    out, skipped = [], []
    for c in cases:
        try:
            splines = [spline_of(sub) for sub in c["segments"]]
        except DriverError as e:
            skipped.append({"peer": PEER, "case": c["case"], "reason": f"{e}: Blender's curves have no such segment"
                            if "arc" in str(e) else str(e)})
            continue
        out.append({"case": c["case"], "splines": splines, "s": [float(x) for x in c["s"]],
                    "spaced": int(c["spaced"])})
    for c in spline_cases:
        try:
            nurbs = nurbs_of(c)
        except DriverError as e:
            skipped.append({"peer": PEER, "case": c["case"], "reason": str(e)})
            continue
        out.append({"case": c["case"], "nurbs": nurbs, "s": [float(x) for x in c["s"]], "spaced": int(c["spaced"]),
                    "dim": int(c["dim"]), "start": c["start"], "end": c["end"]})
    doc = {"resolutions": [r for r, _ in RESOLUTIONS], "pass_ns": 200_000 if quick else 1_000_000,
           "passes": 3 if quick else 5, "cases": out}
    return doc, skipped


def _finite_points(pts):
    return pts is None or all(len(p) in (2, 3) and all(math.isfinite(v) for v in p) for p in pts)


# Blender's curve points are float32: its start may differ from curvebench's (double) by rounding,
# a few float32 ulps of the curve's size (2^-24 relative each); more means another curve. Its end
# (Follow Path at offset 1) was observed short of the last point on open NURBS splines in 3.4 by about
# 1e-6 of the size at resolution 12 (2.6e-7 at 64: it shrinks with the resolution, so it is Blender's
# evaluation of the last sample, not another knot vector, which would move the end by a sizeable
# fraction of a span): the end is checked to END_GAP, and the gap stated in the run's note.
F32_ENDS = 16 * 2.0 ** -24
END_GAP = 1e-4


def ends_differ(case, r):
    """Why Blender's evaluated start/end (Follow Path at offset 0 and 1) are not the request's, or None."""
    pts = case["nurbs"]["points"]
    size = math.dist([min(p[i] for p in pts) for i in range(3)], [max(p[i] for p in pts) for i in range(3)])
    for name, band in (("start", F32_ENDS), ("end", END_GAP)):
        want = list(case[name]) + [0.0] * (3 - len(case[name]))
        got = r.get(name)
        if got is None or math.dist(got, want) > band * max(size, 1e-300):
            return (f"Blender's NURBS {name} {got} is not curvebench's {case[name]} (beyond {band:.2g} of the "
                    "curve's size): its knot vector for these flags is not curvebench's")
    return None


def runs_of(answer, doc):
    """(runs, skipped) from Blender's answer to the input doc; DriverError when it does not answer
    the cases asked."""
    asked = [c["case"] for c in doc["cases"]]
    got = [c.get("case") for c in answer.get("cases", [])]
    if got != asked:
        raise DriverError(f"Blender answered cases {got[:5]}..., asked {asked[:5]}...")
    settings = dict(RESOLUTIONS)
    runs, skipped = [], []
    for case, res in zip(doc["cases"], answer["cases"]):
        if "error" in res:
            skipped.append({"peer": PEER, "case": case["case"], "reason": f"Blender raised {res['error']}"})
            continue
        nurbs = "nurbs" in case
        several = not nurbs and len(case["splines"]) > 1
        why = next((w for w in (ends_differ(case, r) for r in res["results"]) if w), None) if nurbs else None
        if why:
            skipped.append({"peer": PEER, "case": case["case"], "reason": why})
            continue
        for r in res["results"]:
            if nurbs:
                dim = case["dim"]
                r = dict(r, points=[p[:dim] for p in r["points"]], spaced=[p[:dim] for p in r["spaced"]])
            L = r["length"]
            if not (isinstance(L, (int, float)) and math.isfinite(L)) or not _finite_points(r["points"]) \
                    or not _finite_points(r["spaced"]):
                skipped.append({"peer": PEER, "case": case["case"], "setting": settings[r["resolution"]],
                                "reason": f"resolution {r['resolution']}: a non-finite length or point"})
                continue
            beyond = sum(1 for s in case["s"] if s > L)
            what = (f"a NURBS spline (order {case['nurbs']['order']}, "
                    + ("use_endpoint_u" if case["nurbs"]["endpoint"] else "use_cyclic_u" if case["nurbs"]["cyclic"]
                       else "uniform knots") + ", weights in co[3])") if nurbs else f"{len(case['splines'])} spline(s)"
            if nurbs:
                gap = math.dist(r["end"], list(case["end"]) + [0.0] * (3 - len(case["end"])))
                what += f" (its path's end {gap:.2g} from curvebench's end)"
            note = (f"Spline.calc_length() at resolution_u {r['resolution']} summed over {what}"
                    + ("; several subpaths: no Follow Path points (Blender follows the first spline only)" if several
                       else "; points: Follow Path with use_fixed_location, offset_factor = s / calc_length"
                       + (f" ({beyond} s beyond Blender's own length asked at its length)" if beyond else "")
                       + ", spaced at offset_factor k/(n-1); ns_point: offset_factor change + depsgraph update"))
            runs.append({"peer": PEER, "case": case["case"], "setting": settings[r["resolution"]], "length": L,
                         "points": r["points"], "spaced": r["spaced"], "ns_length": r["ns_length"],
                         "ns_point": r["ns_point"], "ns_build": None, "note": note})
    return runs, skipped


def run_blender(program, doc, work, timeout):
    """Blender's answer to doc (run in work); DriverError on a failure or a timeout."""
    inp, out = os.path.join(work, "blender_in.json"), os.path.join(work, "blender_out.json")
    with open(inp, "w", encoding="utf-8") as f:
        json.dump(doc, f)
    cmd = [program, "-b", "--factory-startup", "--python-exit-code", "1", "--python", SCRIPT, "--", inp, out]
    peer_io.run_batch(cmd, out, timeout, "blender")
    with open(out, encoding="utf-8") as f:
        return json.load(f)


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--request", required=True)
    ap.add_argument("--out", required=True)
    ap.add_argument("--quick", action="store_true")
    ap.add_argument("--only", help="comma-separated case names")
    ap.add_argument("--blender", default="blender")
    ap.add_argument("--timeout", type=float, default=TIMEOUT_S)
    ap.add_argument("--keep", help="keep Blender's input and output in this directory")
    a = ap.parse_args(argv)
    program = shutil.which(a.blender)
    if program is None:
        raise DriverError(f"{a.blender!r} is not on PATH (Debian: apt-get install blender); nothing measured")
    only = [n for n in a.only.split(",") if n] if a.only else None
    request, cases = load_request(a.request, only)
    spline_cases = [c for c in request.get("splines", []) if only is None or c["case"] in only]
    doc, skipped = blender_input(cases, a.quick, spline_cases)
    with peer_io.work_dir(a.keep, "cb_blender_length_") as work:
        answer = run_blender(program, doc, work, a.timeout)
    runs, more = runs_of(answer, doc)
    out = {"driver": DRIVER, "format": FORMAT, "versions": {"Blender": answer.get("blender")}, "cpu": read_cpu(),
           "runs": runs, "skipped": skipped + more}
    peer_io.write_json(a.out, out)
    print(f"blender_length_driver.py: {len(runs)} runs, {len(out['skipped'])} skipped -> {a.out}")
    return 0


if __name__ == "__main__":
    try:
        sys.exit(main())
    except (DriverError, OSError, ValueError, KeyError) as e:
        print(f"blender_length_driver.py: {e}", file=sys.stderr)
        sys.exit(1)
