#!/usr/bin/python3
"""Measures the Qt driver's TCB output (`curvebench_peer_qt tcb`, bench/peers/qt) into the peer
records REPORT.md reads (reports/peers_qt_tcb.json, scripts/report_peers.py):

  tcb_results.py --driver qt_tcb.json --cases bench/cases [--spec FILE]... --tool CURVEBENCH --out FILE

A run is QEasingCurve's TCB spline through a kochanek_bartels spec's keys mapped into the unit
square (x' = (x - x0) / dx, y' = (y - y0) / dy, the run's "map"), given as toCubicSpline()'s
Bezier points: segment i runs from the previous segment's end ((0, 0) for the first) through
bezier[3i], bezier[3i + 1] to bezier[3i + 2]. Two records per run:

- curve identity (quantity "eval", setting "tcb curve"): Qt's Bezier segment i at w = k / 8,
  k = 0..7 (and w = 1 on the last segment), evaluated exactly (rationals from Qt's doubles), mapped
  back into the spec's coordinates exactly and rounded once to double, is the point of curvebench's
  uniform Kochanek-Bartels spline at u = knot_0 + (i + w) h: `curvebench check SPEC --values CSV
  --unit ulp-double` against the 50-digit reference gives its error in eps(double) x the curve's
  size. The same check on `curvebench sample SPEC --at-file` at those u is the counterpart (the
  tool's own evaluation of the spline). A same-curve peer is a few ulps off (its control points
  are rounded doubles); a different tangent rule is many orders more.
- valueForProgress (quantity "eval", setting "tcb", as easing_results measures CSS easings): the
  truth at progress x is Qt's own spline, exactly: the segment whose x range holds x, x(t) = x
  solved by bisection in mpmath at 60 digits (x must be non-decreasing on the segment: checked
  exactly from its derivative's Bernstein form and its vertex; a segment where it is not is named
  in the notes and measured all the same, on the first root found by bisection of the bracket),
  y(t). error = max |value - y| / (eps(double) x max |y|), abs_error = max |value - y| (unit
  square). The values at the keys' own x ("key_values") are measured likewise into
  "key_abs_error" and a note.
"""
import argparse
import csv
import fractions
import json
import os
import subprocess
import sys
import tempfile

import mpmath

import easing_results
import peer_io

PEER = "peer_qt_easing_curve"
STEPS = 8  # curve identity: points per segment


class TcbResultError(Exception):
    pass


def segments(bezier):
    """[(p0, p1, p2, p3)] of toCubicSpline()'s points (3 per segment, the first starting at (0, 0))."""
    if len(bezier) % 3 or not bezier:
        raise TcbResultError(f"bezier: {len(bezier)} points, not 3 per segment")
    out, start = [], (0.0, 0.0)
    for i in range(0, len(bezier), 3):
        seg = (tuple(start), tuple(bezier[i]), tuple(bezier[i + 1]), tuple(bezier[i + 2]))
        out.append(seg)
        start = bezier[i + 2]
    return out


def bezier_at(seg, w, coord):
    """Coordinate `coord` of a cubic Bezier at w (exact for Fractions, else in w's arithmetic)."""
    a, b, c, d = (p[coord] for p in seg)
    v = 1 - w
    return v * v * v * a + 3 * v * v * w * b + 3 * v * w * w * c + w * w * w * d


def x_monotone(seg):
    """Whether x(w) is non-decreasing on [0, 1], exactly: x' is a quadratic with Bernstein
    coefficients d0, d1, d2 (the differences of the x's); its minimum on [0, 1] is at an end or at
    its vertex."""
    x = [fractions.Fraction(p[0]) for p in seg]
    d0, d1, d2 = x[1] - x[0], x[2] - x[1], x[3] - x[2]
    candidates = [d0, d2]
    den = d0 - 2 * d1 + d2
    if den != 0:
        w = (d0 - d1) / den
        if 0 < w < 1:
            candidates.append((1 - w) ** 2 * d0 + 2 * w * (1 - w) * d1 + w * w * d2)
    return min(candidates) >= 0


def truth_at(segs, x):
    """y of Qt's own spline at progress x (mpf, 60 digits): the first segment whose x range holds x,
    x(w) = x by 200 bisections of [0, 1]."""
    with mpmath.workdps(60):
        x = mpmath.mpf(x)
        for seg in segs:
            if seg[0][0] <= x <= seg[3][0]:
                break
        else:
            raise TcbResultError(f"progress {x} outside the spline's x range")
        mseg = [(mpmath.mpf(p[0]), mpmath.mpf(p[1])) for p in seg]
        lo, hi = mpmath.mpf(0), mpmath.mpf(1)
        for _ in range(200):
            mid = (lo + hi) / 2
            if bezier_at(mseg, mid, 0) < x:
                lo = mid
            else:
                hi = mid
        return bezier_at(mseg, (lo + hi) / 2, 1)


def identity_points(run, spec):
    """[(u, x, y)] of Qt's Bezier segments at w = k / STEPS mapped back into the spec's coordinates,
    each exact until one rounding to double."""
    m = run["map"]
    knots = spec.get("knots")
    k0 = fractions.Fraction(knots[0]) if knots else fractions.Fraction(0)
    h = fractions.Fraction(knots[1]) - k0 if knots else fractions.Fraction(1)
    segs = segments(run["bezier"])
    x0, y0, dx, dy = (fractions.Fraction(m[k]) for k in ("x0", "y0", "dx", "dy"))
    out = []
    for i, seg in enumerate(segs):
        fseg = [(fractions.Fraction(p[0]), fractions.Fraction(p[1])) for p in seg]
        for k in range(STEPS + (1 if i == len(segs) - 1 else 0)):
            w = fractions.Fraction(k, STEPS)
            out.append((float(k0 + (i + w) * h), float(x0 + bezier_at(fseg, w, 0) * dx),
                        float(y0 + bezier_at(fseg, w, 1) * dy)))
    return out


def check_values(tool, spec_path, rows, work, name):
    """`curvebench check --values` of [(u, x, y)] at ulp-double: (error, the check's JSON summary)."""
    path = os.path.join(work, name + ".csv")
    with open(path, "w", encoding="utf-8", newline="") as f:
        w = csv.writer(f)
        w.writerow(["u", "x", "y"])
        for row in rows:
            w.writerow([repr(v) for v in row])
    out = subprocess.run([tool, "check", spec_path, "--values", path, "--unit", "ulp-double", "--json", "--quiet",
                          "--name", name], capture_output=True, text=True)
    if out.returncode not in (0, 1):
        raise TcbResultError(f"curvebench check {spec_path}: {out.stderr.strip()}")
    checks = [c for c in json.loads(out.stdout)["checks"] if c["kind"] == "values"]
    return checks[0]["summary"]["max"], checks[0]


def sample_at(tool, spec_path, us, work):
    """curvebench's own spline at us: [(u, x, y)] from `curvebench sample --at-file`."""
    path = os.path.join(work, "at.txt")
    with open(path, "w", encoding="utf-8") as f:
        f.write("\n".join(repr(u) for u in us) + "\n")
    out = subprocess.run([tool, "sample", spec_path, "--at-file", path, "--derivatives", "0", "--quiet"],
                         capture_output=True, text=True)
    if out.returncode != 0:
        raise TcbResultError(f"curvebench sample {spec_path}: {out.stderr.strip()}")
    rows = list(csv.DictReader(out.stdout.splitlines()))
    return [(float(r["u"]), float(r["x"]), float(r["y"])) for r in rows]


def _library(versions):
    return f"Qt {versions.get('Qt', '?')}"


def _base(run, spec, versions, setting):
    return {"case": run["case"], "group": spec.get("group", ""), "quantity": "eval", "method": PEER,
            "setting": setting, "estimate": None, "bounded": None, "status": "not_guaranteed", "peer": True,
            "library": _library(versions), "counterpart_ns_per_op": None}


def measure_run(run, spec, spec_path, tool, work, versions):
    """(records, notes) of one driver run."""
    notes = []
    segs = segments(run["bezier"])
    n = len(spec["points"])
    if len(segs) != n - 1:
        raise TcbResultError(f"{run['case']}: {len(segs)} Bezier segments for {n} keys")
    # (a) curve identity
    pts = identity_points(run, spec)
    err, check = check_values(tool, spec_path, pts, work, run["case"] + ".qt")
    own = sample_at(tool, spec_path, [p[0] for p in pts], work)
    own_err, _ = check_values(tool, spec_path, own, work, run["case"] + ".curvebench")
    worst = check["worst"][0] if check.get("worst") else {}
    ident = _base(run, spec, versions, "tcb curve")
    ident.update({"error": err, "abs_error": check["summary"].get("max_absolute"), "evaluations": len(pts),
                  "peer_status": "success", "ns_per_op": None,
                  "counterpart": {"method": "curvebench kochanek_bartels", "setting": ""},
                  "counterpart_error": own_err,
                  "definition": ("QEasingCurve TCB spline's toCubicSpline() Bezier segments, mapped back, against "
                                 "curvebench's uniform Kochanek-Bartels spline through the same keys")})
    notes.append(f"{run['case']}: Qt's TCB Bezier segments (toCubicSpline, {len(segs)} segments x {STEPS} points) "
                 f"are {err:.3g} eps(double) x size from curvebench's Kochanek-Bartels reference (worst at u = "
                 f"{worst.get('u')!r}, {check['summary'].get('max_absolute', float('nan')):.3g} absolute); "
                 f"curvebench's own evaluation {own_err:.3g}")
    # (b) valueForProgress
    bad = [i for i, s in enumerate(segs) if not x_monotone(s)]
    if bad:
        notes.append(f"{run['case']}: x is not monotone on Qt's Bezier segment(s) {bad}: the truth there is the "
                     f"first root bisection finds")
    times, values = run["times"], run["values"]
    if len(times) != len(values):
        raise TcbResultError(f"{run['case']}: {len(values)} values for {len(times)} times")
    truths = [truth_at(segs, t) for t in times]
    finite = [i for i, v in enumerate(values) if v is not None]
    e, ae = (easing_results.measure([values[i] for i in finite], [truths[i] for i in finite], truths)
             if finite else (None, None))
    rec = _base(run, spec, versions, "tcb")
    rec.update({"error": e, "abs_error": ae, "evaluations": len(times),
                "peer_status": "success" if len(finite) == len(times) else
                f"non-finite value at {len(times) - len(finite)} of {len(times)} fractions",
                "ns_per_op": run.get("ns_per_op"),
                "definition": "y of Qt's own toCubicSpline() Bezier spline at progress x, x(t) = x solved exactly"})
    if len(finite) < len(times):
        rec["non_finite"] = len(times) - len(finite)
    keys = [k[0] for k in run.get("keys", [])]
    kv = run.get("key_values")
    if keys and kv and len(kv) == len(keys) and all(v is not None for v in kv):
        kt = [truth_at(segs, x) for x in keys]
        _, kae = easing_results.measure(kv, kt)
        worst_key = max(range(len(keys)), key=lambda i: abs(mpmath.mpf(kv[i]) - kt[i]))
        rec["key_abs_error"] = kae
        notes.append(f"{run['case']}: Qt's valueForProgress (its approximate x(t) = x solve) is up to {ae:.3g} "
                     f"from its own spline at {len(times)} fractions ({e:.3g} eps(double) x size) and up to "
                     f"{kae:.3g} at the keys' own x (worst x = {keys[worst_key]!r}: {kv[worst_key]!r} where the "
                     f"key's y is {float(kt[worst_key])!r})")
    return [ident, rec], notes


def assemble(driver, specs, tool, work):
    """The peers_qt_tcb.json document. specs: {case: (spec, path)}."""
    for key in ("driver", "versions", "runs"):
        if key not in driver:
            raise TcbResultError(f"driver output: no \"{key}\"")
    records, notes = [], list(driver.get("notes", []))
    for run in driver["runs"]:
        if run["case"] not in specs:
            raise TcbResultError(f"driver output: case {run['case']} is not among the specs")
        spec, path = specs[run["case"]]
        r, n = measure_run(run, spec, path, tool, work, driver["versions"])
        records += r
        notes += n
    return {"driver": driver["driver"], "versions": driver["versions"], "cpu": driver.get("cpu"),
            "quick": driver.get("quick"), "notes": notes, "peer_records": records}


def load_specs(cases_dir, spec_files):
    """{case (the file's stem): (spec, path)} of the cases directory's JSON files and the --spec files."""
    paths = []
    if cases_dir:
        paths += [os.path.join(cases_dir, f) for f in sorted(os.listdir(cases_dir)) if f.endswith(".json")]
    paths += list(spec_files or [])
    out = {}
    for p in paths:
        with open(p, encoding="utf-8") as f:
            spec = json.load(f)
        if isinstance(spec, dict) and spec.get("type") == "kochanek_bartels":
            out[os.path.splitext(os.path.basename(p))[0]] = (spec, p)
    return out


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--driver", required=True)
    ap.add_argument("--cases", required=True)
    ap.add_argument("--spec", action="append", default=[])
    ap.add_argument("--tool", required=True, help="the curvebench executable")
    ap.add_argument("--out", required=True)
    a = ap.parse_args()
    try:
        with open(a.driver, encoding="utf-8") as f:
            driver = json.load(f)
        with tempfile.TemporaryDirectory(prefix="tcb_results_") as work:
            doc = assemble(driver, load_specs(a.cases, a.spec), a.tool, work)
    except (OSError, json.JSONDecodeError, KeyError, TcbResultError) as e:
        print(f"tcb_results: {e}", file=sys.stderr)
        return 1
    peer_io.write_json(a.out, doc)
    for r in doc["peer_records"]:
        extra = f", abs {r['abs_error']:.3g}" if isinstance(r.get("abs_error"), float) else ""
        print(f"tcb_results: {r['case']} {r['setting']}: {r['error']:.3g} eps x size{extra}")
    print(f"tcb_results: {len(doc['peer_records'])} peer records -> {a.out}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
