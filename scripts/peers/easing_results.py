#!/usr/bin/python3
"""Measures the easing driver's values (scripts/peers/easing_driver.mjs) and curvebench's own CSS
evaluation of the same cases at the same times against a 50-digit truth, into the peer records
REPORT.md reads (reports/peers_easing.json, scripts/report_peers.py).

  easing_results.py --driver easing_driver.json --cases bench/cases --curvebench-dir DIR --out FILE

The truth of CSS cubic-bezier(x1, y1, x2, y2) at progress t in [0, 1] is its definition: the
Bezier curve from (0, 0) to (1, 1) with inner points (x1, y1), (x2, y2); x(u) = t is solved for u
in [0, 1] (x is non-decreasing there since CSS requires x1, x2 in [0, 1]) by bisection in mpmath at
60 significant digits to |du| < 2^-200, and y(u) is the value. The query time is the double the
driver evaluated at, taken exactly. curvebench's own values come from `curvebench sample CASE
--at-file TIMES --derivatives 0` (DIR/<case>.csv, written by scripts/peers.sh), the tool's CSS
channel in double with the time solver "exact" (curvebench's most accurate; the case spec with
"solver": "exact" added), measured against the same truth as the peers' counterpart; and, when
DIR/<case>.table_newton.csv exists, the case as written (the CSS tool's default table_newton
solver, the WebKit / Chromium scheme curvebench models), reported in the notes.
A run with "steps": [n, position] instead of "easing" (scripts/peers/chromium_driver.py's steps()
easings, which need no case file) is measured against CSS steps() as CSS Easing Functions Level 1
defines it (before flag unset: the active phase): step = floor(x n), plus 1 for jump-start and
jump-both; at least 0 for x >= 0; at most the number of jumps (n + 1 for jump-both, n - 1 for
jump-none, else n); the value is step / jumps, computed in exact rationals from the double x.
Errors: max over the times of |v - y(t)| / (eps(double) x size), size = max |y(t)| over the times
(the unit of curvebench's eval records), and the absolute max |v - y(t)| as "abs_error"; a peer
that documents its solver's precision (@mapbox/unitbezier: epsilon 1e-6) carries it as
"documented_tolerance". A value the driver wrote as null (a NaN or infinity, named in the run's
"non_finite": Babylon's BezierCurve.Interpolate divides by x'(u), 0 where cubic-bezier(0, 4, 1, -3)
reaches x = 1) has no error: the record's error is over the other times, its "non_finite" counts
those values, its peer_status says so and a note names their fractions (every value non-finite: no
error, and the record is listed as a refusal).
"""
import argparse
import fractions
import math
import json
import os
import sys

import mpmath

import peer_io

EPS = 2.0 ** -52


class EasingResultError(Exception):
    pass


def cubic_bezier_truth(p, t):
    """y at progress t of cubic-bezier(p) (mpf, 60 digits); t a double in [0, 1]."""
    with mpmath.workdps(60):
        x1, y1, x2, y2 = (mpmath.mpf(v) for v in p)
        t = mpmath.mpf(t)
        if t <= 0:
            return mpmath.mpf(0)
        if t >= 1:
            return mpmath.mpf(1)

        def bez(a, b, u):
            v = 1 - u
            return 3 * v * v * u * a + 3 * v * u * u * b + u ** 3

        lo, hi = mpmath.mpf(0), mpmath.mpf(1)
        for _ in range(200):
            mid = (lo + hi) / 2
            if bez(x1, x2, mid) < t:
                lo = mid
            else:
                hi = mid
        return bez(y1, y2, (lo + hi) / 2)


def steps_truth(n, position, x):
    """CSS steps(n, position) at progress x (a double in [0, 1]), exactly (a Fraction)."""
    if position not in ("jump-start", "jump-end", "jump-none", "jump-both"):
        raise EasingResultError(f"steps(): unknown position {position!r}")
    jumps = {"jump-both": n + 1, "jump-none": n - 1}.get(position, n)
    if n < 1 or jumps < 1:
        raise EasingResultError(f"steps({n}, {position}): not a valid CSS easing")
    x = fractions.Fraction(x)
    step = math.floor(x * n) + (1 if position in ("jump-start", "jump-both") else 0)
    if x >= 0 and step < 0:
        step = 0
    if x <= 1 and step > jumps:
        step = jumps
    return fractions.Fraction(step, jumps)


def measure(values, truths, size_of=None):
    """(error in eps x size, absolute error) of doubles against the truths; size the largest |truth|
    of size_of (default: the truths)."""
    with mpmath.workdps(60):
        size = max((abs(y) for y in (truths if size_of is None else size_of)), default=mpmath.mpf(0))
        if size == 0:
            size = mpmath.mpf(1)
        worst = max(abs(mpmath.mpf(v) - y) for v, y in zip(values, truths))
        return float(worst / (EPS * size)), float(worst)


def read_curvebench(path, times):
    """curvebench sample's values at `times` (its CSV: t,value), checked to be those times."""
    return peer_io.read_sample(path, times, error=EasingResultError)


def assemble(driver, specs, curvebench_values, tool_model_values=lambda case, times: None):
    """The peers_easing.json document. specs: {case: spec}; curvebench_values(case, times) -> the
    tool's values at those times (solver exact), or None when absent; tool_model_values likewise
    with the case's own (table_newton) solver."""
    for key in ("driver", "versions", "runs"):
        if key not in driver:
            raise EasingResultError(f"driver output: no \"{key}\"")
    records, truths, ours = [], {}, {}
    notes = list(driver.get("notes", []))
    for run in driver["runs"]:
        case = run["case"]
        spec = specs.get(case)
        if spec is None and "steps" not in run:
            raise EasingResultError(f"driver output: case {case} is not in the cases")
        rec = {"case": case, "group": spec.get("group", "") if spec else "css steps", "quantity": "eval",
               "method": run["peer"], "setting": "",
               "estimate": None, "bounded": None, "status": "not_guaranteed", "peer": True,
               "library": _library(run["peer"], driver["versions"]),
               "counterpart": {"method": "curvebench css channel, solver exact", "setting": ""},
               "counterpart_ns_per_op": None}
        if "refused" in run:
            rec.update({"error": None, "evaluations": 0, "peer_status": run["refused"], "ns_per_op": None})
            records.append(rec)
            continue
        times = run["times"]
        if len(run["values"]) != len(times):
            raise EasingResultError(f"driver output: {case} {run['peer']}: {len(run['values'])} values for "
                                    f"{len(times)} times")
        key = (case, tuple(times))
        if key not in truths:
            if "steps" in run:
                with mpmath.workdps(60):
                    truths[key] = [mpmath.mpf(steps_truth(run["steps"][0], run["steps"][1], t).numerator) /
                                   steps_truth(run["steps"][0], run["steps"][1], t).denominator for t in times]
            else:
                truths[key] = [cubic_bezier_truth(run["easing"], t) for t in times]
            vals = curvebench_values(case, times)
            ours[key] = measure(vals, truths[key]) if vals is not None else (None, None)
            model = tool_model_values(case, times)
            if model is not None:
                e, ae = measure(model, truths[key])
                notes.append(f"{case}: curvebench's CSS model with its default table_newton solver (the WebKit / "
                             f"Chromium scheme) is {e:.3g} eps x size ({ae:.3g} absolute) from the truth; with the "
                             f"exact solver {ours[key][0]:.3g}" if ours[key][0] is not None else
                             f"{case}: curvebench table_newton {e:.3g} eps x size")
        if "steps" in run:
            notes += _steps_notes(run)
            rec["definition"] = f"CSS steps({run['steps'][0]}, {run['steps'][1]}) as CSS Easing defines it,"
        finite = [i for i, v in enumerate(run["values"]) if _finite(v, case, run["peer"], i)]
        status = "success"
        if len(finite) < len(times):
            status, note = _non_finite(run, truths[key], finite)
            notes.append(note)
            rec["non_finite"] = len(times) - len(finite)
        err, abs_err = (measure([run["values"][i] for i in finite], [truths[key][i] for i in finite], truths[key])
                        if finite else (None, None))
        rec.update({"error": err, "abs_error": abs_err, "evaluations": len(times), "peer_status": status,
                    "ns_per_op": run.get("ns_per_op"), "counterpart_error": ours[key][0],
                    "counterpart_abs_error": ours[key][1]})
        if "documented_tolerance" in run:
            rec["documented_tolerance"] = run["documented_tolerance"]
        records.append(rec)
    return {"driver": driver["driver"], "versions": driver["versions"], "notes": notes,
            "quick": driver.get("quick"), "peer_records": records}


def _finite(v, case, peer, i):
    """Whether the driver's value i is a number (null: the peer's NaN or infinity); anything else
    raises EasingResultError."""
    if v is None:
        return False
    if isinstance(v, bool) or not isinstance(v, (int, float)) or not math.isfinite(v):
        raise EasingResultError(f"driver output: {case} {peer}: value {i} is {v!r}, not a number or null")
    return True


def _non_finite(run, truths, finite):
    """(peer_status, note) of a run with null values: how many, and the first fractions with what the
    peer returned there (the run's "non_finite" names NaN or Infinity) and the definition's value."""
    said = {t: v for t, v in run.get("non_finite", [])}
    kept = set(finite)
    n, bad = len(run["times"]), [i for i in range(len(run["times"])) if i not in kept]
    shown = "; ".join(f"x = {run['times'][i]!r}: {said.get(run['times'][i], 'non-finite')} where the definition "
                      f"gives {float(truths[i])!r}" for i in bad[:3])
    status = f"non-finite value at {len(bad)} of {n} fractions"
    rest = f"its error is over the other {len(finite)}" if finite else "no value to measure"
    return status, (f"{run['case']} ({run['peer']}): {status} ({shown}" + ("; ..." if len(bad) > 3 else "")
                    + f"); {rest}")


def _steps_notes(run):
    """A sentence naming the fractions where a steps() run is not the definition's value: the
    doubles just below a step boundary k / n whose product x n rounds up to k are the usual ones."""
    n, pos = run["steps"]
    bad = [(x, v, steps_truth(n, pos, x)) for x, v in zip(run["times"], run["values"])
           if v != float(steps_truth(n, pos, x))]
    if not bad:
        return []
    shown = "; ".join(f"x = {x!r} (x n = {fractions.Fraction(x) * n} exactly, {x * n!r} in double): {v!r} where "
                      f"the definition gives {float(t)!r}" for x, v, t in bad[:3])
    return [f"{run['case']} ({run['peer']}): {len(bad)} of {len(run['times'])} fractions off the steps({n}, {pos}) "
            f"definition by a whole step: {shown}" + ("; ..." if len(bad) > 3 else "")]


def _library(peer, versions):
    names = {"peer_bezier_easing_3": "bezier-easing 3", "peer_bezier_easing_2": "bezier-easing 2",
             "peer_mapbox_unitbezier": "@mapbox/unitbezier", "peer_babylon_bezier_interpolate": "@babylonjs/core",
             "peer_chromium_waapi": "Chromium", "peer_lottie_bezier_easing": "lottie-web",
             "peer_qt_easing_curve": "Qt", "peer_godot_bezier_track": "Godot"}
    name = names.get(peer, peer)
    return f"{name.split(' ')[0]} {versions.get(name, '?')}"


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--driver", required=True)
    ap.add_argument("--cases", required=True)
    ap.add_argument("--curvebench-dir", required=True, help="DIR/<case>.csv: curvebench sample at the driver's times")
    ap.add_argument("--out", required=True)
    a = ap.parse_args()
    try:
        with open(a.driver, encoding="utf-8") as f:
            driver = json.load(f)
        specs = {}
        for run in driver.get("runs", []):
            if "steps" in run and not os.path.exists(os.path.join(a.cases, run["case"] + ".json")):
                continue  # a steps() easing of the driver's own, no case file
            with open(os.path.join(a.cases, run["case"] + ".json"), encoding="utf-8") as f:
                specs[run["case"]] = json.load(f)

        def reader(suffix):
            def read(case, times):
                path = os.path.join(a.curvebench_dir, case + suffix)
                return read_curvebench(path, times) if os.path.exists(path) else None
            return read
        doc = assemble(driver, specs, reader(".csv"), reader(".table_newton.csv"))
    except (OSError, json.JSONDecodeError, EasingResultError) as e:
        print(f"easing_results: {e}", file=sys.stderr)
        return 1
    peer_io.write_json(a.out, doc)
    print(f"easing_results: {len(doc['peer_records'])} peer records -> {a.out}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
