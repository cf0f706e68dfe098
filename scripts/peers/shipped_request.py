#!/usr/bin/python3
"""The request of the arc-length peers: which paths the drivers measure, and where.

  shipped_request.py --cases DIR --tool CURVEBENCH --out FILE [--only NAME,...]

Cases: every case of DIR that SVG path data can hold exactly: "svg_path" specs (path data or a basic
shape), and 2D "bezier" specs of 3 or 4 points and "composite_bezier" specs of polynomial segments
of degree <= 3 (written as path data here: M, then Q or C per segment, a new M where a segment does
not start at the previous one's end). Each becomes one element of one SVG file, which `curvebench
length --svg` reads, so that the path data in the request (a shape's: the path SVG 2 defines for
it, written by curvebench) and the length that places the query points are curvebench's own:

  {"format": "curvebench-shipped-request-1", "tool": <curvebench --version>,
   "cases": [{"case", "d", "segments": the subpaths of d as `length --svg` parses them (absolute
              lines, quadratics, cubics and arcs, an arc with its centre form: for peers that take
              segments, not path data), "shape": null or {"element", "attributes"}, "bezier": null or the 3 or 4
              control points when the case is one Bezier, "length": L (adaptive Gauss-Kronrod at
              tol 1e-14, to place s only; the results are measured against the 50-digit reference),
              "s": [k L_low / 16 for k = 0..16] with L_low = length - its error estimate, a lower
              bound of the true length, "spaced": 17}]}

and "catmull_rom": the cases a Catmull-Rom curve through points holds as three.js's
CatmullRomCurve3 does (type "catmull_rom", alpha 0, 1/2 or 1 without given knots, end "phantom" (the
default; three extrapolates P_-1 = 2 P_0 - P_1 the same way) or "closed", at most MAX_SPLINE_POINTS
points), for the peers that take points rather than path data:

  {"case", "points": [[x, y, z]] (z = 0 for a 2D case; generated point sets as the tool generates
   them), "dim": 2 or 3, "curve_type": "catmullrom" (alpha 0) | "centripetal" | "chordal", "closed",
   "knots": curvebench's parameter at each point (0, then + |P_i+1 - P_i|^alpha; the last is the
   tool's own domain end), "length", "s", "spaced" as above, and "t": [k / 32], a grid of three's
   own parameter (uniform in the segment index), with "u": curvebench's parameter at each t (the
   segment's knots, linearly: three's segment is the same cubic on [u_i, u_i+1] in w = (u - u_i) / h)}

and "splines": the "bspline" and "nurbs" cases, for the peers with B-spline curves (OpenCASCADE,
Blender's NURBS splines):

  {"case", "points": [[x, y, z]] (z = 0 for a 2D case), "dim", "degree", "weights": one per point or
   null, "knot_vector": "clamped" | "uniform" | "periodic" (curvebench's generated vectors: clamped
   uniform with end knots of multiplicity degree + 1; uniform, every knot simple, the curve on
   [u_degree, u_n]; periodic: the points a control loop) or "given" with "knots": the full
   non-decreasing vector, "start" and "end": curvebench's first and last point of the curve (where
   s = 0 and s = L are: a periodic curve's start), "length", "s", "spaced"}

The drivers (shipped_node_driver.mjs, shipped_browser_driver.py and the native and Python peers') answer it;
shipped_results.py measures their answers with `curvebench check --at-length`.
"""
import argparse
import glob
import json
import math
import os
import subprocess
import sys
import tempfile
from xml.sax.saxutils import quoteattr

import peer_io

FORMAT = "curvebench-shipped-request-1"
QUERIES = 16  # s = k L / QUERIES
SPACED = 17
T_GRID = 32  # three's parameter t = k / T_GRID for the evaluation check
# Catmull-Rom cases of at most this many points: each `curvebench check` builds the case's 50-digit
# reference, 1.3 s for 1001 points and 15 s for 10001 on this project's machine, and a case takes
# about a dozen checks (points, spaced, t_at_s, values per setting).
MAX_SPLINE_POINTS = 1001
CURVE_TYPES = {0: "catmullrom", 0.5: "centripetal", 1: "chordal"}


class RequestError(Exception):
    pass


def num(v):
    """The shortest text that reads back as the same double (Python's repr)."""
    v = float(v)
    return repr(int(v)) if v.is_integer() and abs(v) < 1e15 else repr(v)


def bezier_data(segments):
    """Path data of polynomial Bezier segments (lists of 2 to 4 [x, y]); a new subpath where one does
    not start at the previous one's end."""
    d, end = [], None
    for seg in segments:
        if len(seg) < 2 or len(seg) > 4 or any(len(p) != 2 for p in seg):
            raise RequestError(f"segment {seg!r} is not a 2D Bezier of degree 1 to 3")
        if end != seg[0]:
            d.append(f"M{num(seg[0][0])} {num(seg[0][1])}")
        letter = {2: "L", 3: "Q", 4: "C"}[len(seg)]
        d.append(letter + " ".join(f"{num(x)} {num(y)}" for x, y in seg[1:]))
        end = seg[-1]
    return " ".join(d)


def element_of(spec):
    """(SVG element text, shape or None, bezier points or None) for a case spec SVG can hold exactly;
    None when it cannot."""
    kind = spec.get("type")
    if kind == "svg_path":
        if "d" in spec:
            return f"<path d={quoteattr(spec['d'])}", None, None
        shape = dict(spec["shape"])
        element = shape.pop("element")
        if element in ("polyline", "polygon"):
            pts = " ".join(f"{num(x)},{num(y)}" for x, y in shape.pop("points"))
            return f"<{element} points={quoteattr(pts)}", {"element": element, "attributes": {"points": pts}}, None
        attrs = " ".join(f"{k}={quoteattr(num(v))}" for k, v in shape.items())
        return f"<{element} {attrs}", {"element": element, "attributes": shape}, None
    if kind == "bezier":
        pts = spec.get("points", [])
        if len(pts) in (3, 4) and all(len(p) == 2 for p in pts) and "weights" not in spec:
            return f"<path d={quoteattr(bezier_data([pts]))}", None, pts
        return None
    if kind == "composite_bezier" and "weights" not in spec:
        segs = spec.get("segments", [])
        if segs and all(2 <= len(s) <= 4 and all(len(p) == 2 for p in s) for s in segs):
            return f"<path d={quoteattr(bezier_data(segs))}", None, None
    return None


def generated_points(g):
    """The points of a {"generate": ...} object, computed as the tool computes them (io/family.hpp:
    double, the same operations in the same order, so the same doubles)."""
    n = int(g["count"])
    two_pi = 2 * math.pi
    out = []
    for i in range(n):
        f = i / (n - 1)
        kind = g["generate"]
        if kind == "helix":
            th = two_pi * g.get("turns", 1) * f
            r = g.get("radius", 1)
            out.append([r * math.cos(th), r * math.sin(th), g.get("pitch", 1) * th / two_pi])
        elif kind == "lissajous":
            th = two_pi * g.get("turns", 1) * f
            out.append([math.sin(g.get("a", 3) * th + two_pi / 4), math.sin(g.get("b", 2) * th)])
        elif kind == "spiral":
            th = two_pi * g.get("turns", 1) * f
            out.append([f * math.cos(th), f * math.sin(th)])
        elif kind == "runge":
            x = -1 + 2 * f if g.get("nodes", "equispaced") == "equispaced" else -math.cos(math.pi * f)
            out.append([x, 1 / (1 + 25 * x * x)])
        else:
            raise RequestError(f"unknown point generator {kind!r}")
    return out


def catmull_rom_of(spec):
    """(points as given or generated, curve type, closed) for a catmull_rom spec three's
    CatmullRomCurve3 draws as the same curve; None otherwise."""
    if spec.get("type") != "catmull_rom" or "knots" in spec:
        return None
    alpha = float(spec.get("alpha", 0))
    end = spec.get("end", "phantom")
    if alpha not in CURVE_TYPES or end not in ("phantom", "closed"):
        return None
    pts = spec["points"]
    pts = generated_points(pts) if isinstance(pts, dict) else pts
    if len(pts) < 2 or len(pts) > MAX_SPLINE_POINTS or any(len(p) not in (2, 3) or len(p) != len(pts[0]) for p in pts):
        return None
    return pts, CURVE_TYPES[alpha], end == "closed", alpha


def knots_of(points, alpha, closed):
    """curvebench's knots: 0, then + |P_i+1 - P_i|^alpha (a closed loop adds the way back to P_0)."""
    pts = list(points) + ([points[0]] if closed else [])
    u = [0.0]
    for a, b in zip(pts, pts[1:]):
        u.append(u[-1] + (math.dist(a, b) ** alpha if alpha else 1.0))
    return u


def three_parameter(t, knots, closed):
    """curvebench's parameter at three's CatmullRomCurve3 parameter t in [0, 1]: three takes segment
    floor(p) at weight p - floor(p), p = segments t (the last segment at weight 1 for t = 1)."""
    segments = len(knots) - 1
    p = segments * t
    i = math.floor(p)
    w = p - i
    if i >= segments:
        i, w = segments - 1, 1.0
    return knots[i] + w * (knots[i + 1] - knots[i])


def catmull_rom_request(name, spec, tool, case_path):
    """The request entry of a catmull_rom case (see the module's doc)."""
    pts, curve_type, closed, alpha = catmull_rom_of(spec)
    length, s = length_and_grid(tool, case_path)
    d = subprocess.run([tool, "sample", case_path, "--count", "2", "--derivatives", "0", "--quiet"],
                       capture_output=True, text=True)
    if d.returncode != 0:
        raise RequestError(f"curvebench sample {case_path} failed: {d.stderr.strip()}")
    end = float(d.stdout.splitlines()[-1].split(",")[0])
    knots = knots_of(pts, alpha, closed)
    knots[-1] = end  # the tool's own domain end (a sum rounded its way), so no u is past it
    t = [k / T_GRID for k in range(T_GRID + 1)]
    u = [min(three_parameter(x, knots, closed), end) for x in t]
    return {"case": name, "points": [list(map(float, q)) + [0.0] * (3 - len(q)) for q in pts], "dim": len(pts[0]),
            "curve_type": curve_type, "closed": closed, "knots": knots, "length": length,
            "s": s, "spaced": SPACED, "t": t, "u": u}


def spline_of(spec):
    """The request entry's curve fields of a bspline or nurbs case; None for another type."""
    if spec.get("type") not in ("bspline", "nurbs"):
        return None
    pts = spec["points"]
    pts = generated_points(pts) if isinstance(pts, dict) else pts
    if any(len(p) not in (2, 3) or len(p) != len(pts[0]) for p in pts):
        return None
    return {"points": [list(map(float, q)) + [0.0] * (3 - len(q)) for q in pts], "dim": len(pts[0]),
            "degree": int(spec["degree"]),
            "weights": [float(w) for w in spec["weights"]] if "weights" in spec else None,
            "knot_vector": "given" if "knots" in spec else spec.get("knot_vector", "clamped"),
            "knots": [float(k) for k in spec["knots"]] if "knots" in spec else None}


def length_and_grid(tool, case_path):
    """(L, the request's s grid) of a case spec file: adaptive Gauss-Kronrod at 1e-14, the grid
    ending at L less the estimate (below the true length, as for the path cases)."""
    p = subprocess.run([tool, "length", case_path, "--method", "adaptive_gk", "--tol", "1e-14", "--quiet"],
                       capture_output=True, text=True)
    if p.returncode != 0:
        raise RequestError(f"curvebench length {case_path} failed: {p.stderr.strip()}")
    m = json.loads(p.stdout)
    length = m["value"]
    low = length - m["estimate"] if m.get("status") == "converged" and m.get("estimate") is not None \
        else length * (1 - 1e-12)
    return length, [low * k / QUERIES for k in range(QUERIES + 1)]


def spline_request(name, spec, tool, case_path):
    """The request entry of a bspline or nurbs case (see the module's doc)."""
    length, s = length_and_grid(tool, case_path)
    d = subprocess.run([tool, "sample", case_path, "--count", "2", "--derivatives", "0", "--quiet"],
                       capture_output=True, text=True)
    if d.returncode != 0:
        raise RequestError(f"curvebench sample {case_path} failed: {d.stderr.strip()}")
    ends = [[float(v) for v in line.split(",")[2:]] for line in d.stdout.splitlines()[1:3]]
    return dict({"case": name}, **spline_of(spec), start=ends[0], end=ends[1], length=length, s=s, spaced=SPACED)


def svg_document(cases):
    """One SVG file holding each case as an element whose id is the case's name."""
    body = [f'  {text} id={quoteattr(name)}/>' for name, (text, _, _) in cases]
    return '<svg xmlns="http://www.w3.org/2000/svg">\n' + "\n".join(body) + "\n</svg>\n"


def request_of(cases, measured, version):
    """The request from the cases [(name, (element text, shape, bezier))] and `length --svg`'s output."""
    by_id = {m["id"]: m for m in measured}
    out = []
    for name, (_, shape, bezier) in cases:
        m = by_id.get(name)
        if m is None:
            raise RequestError(f"curvebench length --svg did not measure {name}")
        # The s grid ends at a lower bound of L (value - estimate: curvebench's estimates bound
        # their error when converged), so no s is past the true length, which check refuses.
        length = m["value"]
        low = length - m["estimate"] if m.get("status") == "converged" and m.get("estimate") is not None \
            else length * (1 - 1e-12)
        s = [low * k / QUERIES for k in range(QUERIES + 1)]
        out.append({"case": name, "d": m["d"], "segments": m["segments"], "shape": shape, "bezier": bezier,
                    "length": length, "s": s, "spaced": SPACED})
    return {"format": FORMAT, "tool": version, "cases": out}


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--cases", required=True)
    ap.add_argument("--tool", required=True)
    ap.add_argument("--out", required=True)
    ap.add_argument("--only", help="comma-separated case names")
    a = ap.parse_args()
    only = set(a.only.split(",")) if a.only else None
    cases, catmull_roms, splines = [], [], []
    for path in sorted(glob.glob(os.path.join(a.cases, "*.json"))):
        with open(path, encoding="utf-8") as f:
            spec = json.load(f)
        name = spec.get("name")
        if only is not None and name not in only:
            continue
        el = element_of(spec)
        if el is not None:
            cases.append((name, el))
        elif catmull_rom_of(spec) is not None:
            catmull_roms.append(catmull_rom_request(name, spec, a.tool, path))
        elif spline_of(spec) is not None:
            splines.append(spline_request(name, spec, a.tool, path))
    if not cases:
        raise RequestError(f"no case of {a.cases} is SVG path data, a shape or a Bezier of degree <= 3")
    with tempfile.TemporaryDirectory() as tmp:
        svg = os.path.join(tmp, "cases.svg")
        with open(svg, "w", encoding="utf-8") as f:
            f.write(svg_document(cases))
        p = subprocess.run([a.tool, "length", "--svg", svg, "--method", "adaptive_gk", "--tol", "1e-14", "--quiet"],
                           capture_output=True, text=True)
        if p.returncode != 0:
            raise RequestError(f"curvebench length --svg failed: {p.stderr.strip()}")
        measured = json.loads(p.stdout)
    version = subprocess.run([a.tool, "--version"], capture_output=True, text=True).stdout.strip()
    request = request_of(cases, measured, version)
    request["catmull_rom"] = catmull_roms
    request["splines"] = splines
    peer_io.write_json(a.out, request)
    print(f"shipped_request.py: {len(cases)} cases, {len(catmull_roms)} Catmull-Rom and {len(splines)} B-spline "
          f"cases in {a.out}")
    return 0


if __name__ == "__main__":
    try:
        sys.exit(main())
    except RequestError as e:
        print(f"shipped_request.py: {e}", file=sys.stderr)
        sys.exit(1)
