#!/usr/bin/python3
"""Arc length as fontTools computes it: the length functions of fontTools.misc.bezierTools
(Debian python3-fonttools, pure Python) on the cases of a shipped-peer request, written as JSON
(format curvebench-shipped-driver-1) for scripts/peers/shipped_results.py to measure.

  fonttools_driver.py --request FILE --out FILE [--quick] [--only CASE,CASE...]

Peers (what the installed bezierTools.py does, read from its source, fontTools 4.38):
  peer_fonttools_calc    calcCubicArcLength(p0, p1, p2, p3, tolerance) per cubic: recursive halving
                         (de Casteljau at t = 1/2) until chord x (1 + 1.5 tolerance) >= control
                         polygon length (a *relative* test), then (chord + polygon) / 2 per piece;
                         tolerance 0.005 by default (setting "") and 1e-8 (setting "tolerance=1e-08").
                         calcQuadraticArcLength per quadratic: a closed form (sqrt and asinh of the
                         tangent's slopes), with no tolerance, so both settings give the same value.
  peer_fonttools_approx  approximateCubicArcLength: one 5-point Gauss-Lobatto rule on |B'(t)| (its
                         docstring shows the collinear cusp of length 150 measured as 136.93);
                         approximateQuadraticArcLength: one 3-point Gauss-Legendre rule. No setting.
All in Python floats (double), points as complex numbers. A line segment is its exact distance
(math.hypot; fontTools measures no lines: a pen sums them itself). fontTools has no arc segment
(its pens turn arcs into Beziers of their own choosing): a case with an SVG arc is skipped. It has
no point at arc length either: "points" and "spaced" are null. A path's length is the sum over its
segments and subpaths, as a user of these functions sums them.

Times: ns_length is one whole-path length (every segment's call plus the sum), timed with
time.perf_counter_ns: a warm-up call, then the loop count doubled until one pass takes at least
--pass-ms (default 2 ms; Python calls cost microseconds), then the best of 5 passes (2 passes when a
single call takes over 20 ms: calcCubicArcLength at 1e-8 splits thousands of times per segment),
divided by the count. ns_point and ns_build are null (no point call, nothing built).
"""
import argparse
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import peer_io  # noqa: E402
from peer_io import DriverError, cpu_model, load_request, read_cpu  # noqa: E402,F401

DRIVER = "fonttools"
FORMAT = "curvebench-shipped-driver-1"
CALC_SETTINGS = (("", None), ("tolerance=1e-08", 1e-8))  # None: the function's own default (0.005)
DEFAULT_TOLERANCE = 0.005
PASS_NS = 2_000_000
PASSES = 5
SLOW_CALL_NS = 20_000_000


def segment_list(case):
    """[(kind, points as complex)] of every segment of every subpath, in order; DriverError for a
    kind this driver does not know or a wrong count of points."""
    counts = {"line": 2, "quadratic": 3, "cubic": 4, "arc": 2}
    out = []
    for sub in case["segments"]:
        for seg in sub["segments"]:
            kind, pts = seg.get("kind"), seg.get("points")
            if kind not in counts or not isinstance(pts, list) or len(pts) != counts[kind]:
                raise DriverError(f"{case['case']}: a segment {kind!r} with {len(pts or [])} points")
            out.append((kind, [complex(float(x), float(y)) for x, y in pts]))
    return out


def path_length_function(segments, peer, tolerance, bt):
    """A function of no argument returning the path's length as `peer` computes it (bt: the
    bezierTools module); lines by their distance."""
    calls = []
    for kind, p in segments:
        if kind == "line":
            calls.append((abs, (p[1] - p[0],)))
        elif kind == "quadratic":
            f = bt.calcQuadraticArcLengthC if peer == "peer_fonttools_calc" else bt.approximateQuadraticArcLengthC
            calls.append((f, tuple(p)))
        elif peer == "peer_fonttools_calc":
            args = tuple(p) + (() if tolerance is None else (tolerance,))
            calls.append((bt.calcCubicArcLengthC, args))
        else:
            calls.append((bt.approximateCubicArcLengthC, tuple(p)))

    def length():
        total = 0.0
        for f, args in calls:
            total += f(*args)
        return total
    return length


def peer_settings():
    """[(peer, setting, tolerance)] in the order the runs are written."""
    return ([("peer_fonttools_calc", s, tol) for s, tol in CALC_SETTINGS]
            + [("peer_fonttools_approx", "", None)])


def note_of(peer, setting, segments):
    kinds = {k for k, _ in segments}
    parts = []
    if peer == "peer_fonttools_calc":
        tol = DEFAULT_TOLERANCE if not setting else float(setting.split("=", 1)[1])
        if "cubic" in kinds:
            parts.append(f"cubics by calcCubicArcLength(tolerance={tol!r})")
        if "quadratic" in kinds:
            parts.append("quadratics by calcQuadraticArcLength (closed form, no tolerance)")
    else:
        if "cubic" in kinds:
            parts.append("cubics by approximateCubicArcLength (5-point Gauss-Lobatto)")
        if "quadratic" in kinds:
            parts.append("quadratics by approximateQuadraticArcLength (3-point Gauss-Legendre)")
    if "line" in kinds:
        parts.append("lines by their exact distance (fontTools has no line length)")
    return ("Length only (fontTools has no point at arc length): " + ", ".join(parts)
            + "; ns_length: one whole-path length, the sum of the segments' calls")


def run_case(case, bt, pass_ns=PASS_NS, passes=PASSES):
    """(runs, skipped) of one request case."""
    segments = segment_list(case)
    if any(k == "arc" for k, _ in segments):
        return [], skipped_arc(case["case"])
    runs, skipped = [], []
    for peer, setting, tol in peer_settings():
        try:
            length, ns = peer_io.best_ns(path_length_function(segments, peer, tol, bt), pass_ns, passes, SLOW_CALL_NS)
        except (ArithmeticError, RecursionError) as e:
            skipped.append({"peer": peer, "case": case["case"], "setting": setting,
                            "reason": f"fontTools raised {type(e).__name__}: {e}"})
            continue
        if not math.isfinite(length):
            skipped.append({"peer": peer, "case": case["case"], "setting": setting,
                            "reason": f"fontTools returned {length!r}"})
            continue
        runs.append({"peer": peer, "case": case["case"], "setting": setting, "length": length,
                     "points": None, "spaced": None, "ns_length": ns, "ns_point": None, "ns_build": None,
                     "note": note_of(peer, setting, segments)})
    return runs, skipped


def skipped_arc(case):
    return [{"peer": p, "case": case,
             "reason": "fontTools has no elliptical arc segment (its pens approximate arcs by Beziers of their "
                       "own choosing)"} for p in ("peer_fonttools_calc", "peer_fonttools_approx")]


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--request", required=True)
    ap.add_argument("--out", required=True)
    ap.add_argument("--quick", action="store_true", help="shorter timing passes (0.5 ms, best of 3)")
    ap.add_argument("--only", help="comma-separated case names")
    a = ap.parse_args(argv)
    try:
        import fontTools
        import fontTools.misc.bezierTools as bt
    except ImportError as e:
        raise DriverError(f"fontTools is not importable ({e}): apt-get install python3-fonttools") from e
    only = [n for n in a.only.split(",") if n] if a.only else None
    request, cases = load_request(a.request, only)
    pass_ns, passes = (500_000, 3) if a.quick else (PASS_NS, PASSES)
    runs, skipped = [], []
    for case in cases:
        r, k = run_case(case, bt, pass_ns, passes)
        runs += r
        skipped += k
    doc = {"driver": DRIVER, "format": FORMAT, "versions": {"fontTools": fontTools.version},
           "cpu": read_cpu(), "runs": runs, "skipped": skipped}
    peer_io.write_json(a.out, doc)
    print(f"fonttools_driver.py: {len(runs)} runs, {len(skipped)} skipped -> {a.out}")
    return 0


if __name__ == "__main__":
    try:
        sys.exit(main())
    except (DriverError, OSError, ValueError, KeyError) as e:
        print(f"fonttools_driver.py: {e}", file=sys.stderr)
        sys.exit(1)
