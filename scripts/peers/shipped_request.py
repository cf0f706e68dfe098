#!/usr/bin/python3
"""The request of the arc-length peers (issue 35): which paths the drivers measure, and where.

  shipped_request.py --cases DIR --tool CURVEBENCH --out FILE [--only NAME,...]

Cases: every case of DIR that SVG path data can hold exactly: "svg_path" specs (path data or a basic
shape), and 2D "bezier" specs of 3 or 4 points and "composite_bezier" specs of polynomial segments
of degree <= 3 (written as path data here: M, then Q or C per segment, a new M where a segment does
not start at the previous one's end). Each becomes one element of one SVG file, which `curvebench
length --svg` reads, so that the path data in the request (a shape's: the path SVG 2 defines for
it, written by curvebench) and the length that places the query points are curvebench's own:

  {"format": "curvebench-shipped-request-1", "tool": <curvebench --version>,
   "cases": [{"case", "d", "shape": null or {"element", "attributes"}, "bezier": null or the 3 or 4
              control points when the case is one Bezier, "length": L (adaptive Gauss-Kronrod at
              tol 1e-14, to place s only; the results are measured against the 50-digit reference),
              "s": [k L_low / 16 for k = 0..16] with L_low = length - its error estimate, a lower
              bound of the true length, "spaced": 17}]}

The drivers (shipped_node_driver.mjs, shipped_browser_driver.py) answer it; shipped_results.py
measures their answers with `curvebench check --at-length`.
"""
import argparse
import glob
import json
import os
import subprocess
import sys
import tempfile
from xml.sax.saxutils import quoteattr

import peer_io

FORMAT = "curvebench-shipped-request-1"
QUERIES = 16  # s = k L / QUERIES
SPACED = 17


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
        out.append({"case": name, "d": m["d"], "shape": shape, "bezier": bezier, "length": length, "s": s,
                    "spaced": SPACED})
    return {"format": FORMAT, "tool": version, "cases": out}


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--cases", required=True)
    ap.add_argument("--tool", required=True)
    ap.add_argument("--out", required=True)
    ap.add_argument("--only", help="comma-separated case names")
    a = ap.parse_args()
    only = set(a.only.split(",")) if a.only else None
    cases = []
    for path in sorted(glob.glob(os.path.join(a.cases, "*.json"))):
        with open(path, encoding="utf-8") as f:
            spec = json.load(f)
        name = spec.get("name")
        if only is not None and name not in only:
            continue
        el = element_of(spec)
        if el is not None:
            cases.append((name, el))
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
    peer_io.write_json(a.out, request_of(cases, measured, version))
    print(f"shipped_request.py: {len(cases)} cases in {a.out}")
    return 0


if __name__ == "__main__":
    try:
        sys.exit(main())
    except RequestError as e:
        print(f"shipped_request.py: {e}", file=sys.stderr)
        sys.exit(1)
