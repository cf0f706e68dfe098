#!/usr/bin/python3
"""Measures the arc-length peers' answers (issue 35) against the 50-digit reference of each case.

  shipped_results.py --driver FILE --request FILE --cases DIR --tool CURVEBENCH --work DIR --out FILE

The driver's runs (shipped_node_driver.mjs, shipped_browser_driver.py: per peer, case and setting
its length, its points at the request's arc lengths s, n points it spaces equally by its own length,
and its times) are written as CSV and measured by `curvebench check CASE --at-length CSV`, which
finds each point's distance from the exact point at s, and the arc length s(u*) of the curve's
point nearest it, all at 50 digits. Per run:

  length_error   |L_peer - L| / L
  point_error    max over the request's s of |P_peer(s) - P(s)| / L (its distance from the true point)
  s_error        max over the same of |s(u*) - s| / L (how far along the curve the point is off)
  off_curve      max distance of any returned point from the curve, / L
  spacing_cv     the coefficient of variation (population standard deviation / mean) of the true arc
                 lengths between the n equally spaced points (0 for a perfect spacing)
  ns_length, ns_point, ns_build   as the driver timed them (null where it did not)

Written to --out as {"driver", "versions", "cpu", "request_tool", "rows": [...], "skipped": [...]};
scripts/report_shipped.py makes REPORT.md's "Arc length in shipped software" from these files.
The joining is pure (rows_of, spacing_cv) and tested on recorded outputs by
tests/python/test_shipped_results.py; only measure() runs the tool.
"""
import argparse
import csv
import json
import math
import os
import re
import subprocess
import sys
from concurrent.futures import ThreadPoolExecutor

import peer_io

DRIVER_FORMAT = "curvebench-shipped-driver-1"
REQUEST_FORMAT = "curvebench-shipped-request-1"


class ShippedError(Exception):
    pass


def _finite_points(points, what):
    if not isinstance(points, list):
        raise ShippedError(f"{what}: expected a list of [x, y], got {points!r}"[:200])
    for i, p in enumerate(points):
        if not (isinstance(p, list) and len(p) == 2 and all(isinstance(v, (int, float)) and math.isfinite(v)
                                                            for v in p)):
            raise ShippedError(f"{what}[{i}]: expected [x, y] of finite numbers, got {p!r}"[:200])
    return points


def validate(driver, request):
    """Both documents' formats, and every run naming a case of the request with the right count of
    points; ShippedError naming the run otherwise."""
    if driver.get("format") != DRIVER_FORMAT:
        raise ShippedError(f"driver output: format {driver.get('format')!r}, expected {DRIVER_FORMAT!r}")
    if request.get("format") != REQUEST_FORMAT:
        raise ShippedError(f"request: format {request.get('format')!r}, expected {REQUEST_FORMAT!r}")
    cases = {c["case"]: c for c in request["cases"]}
    for i, run in enumerate(driver.get("runs", [])):
        where = f"runs[{i}] ({run.get('peer')}, {run.get('case')})"
        case = cases.get(run.get("case"))
        if case is None:
            raise ShippedError(f"{where}: the case is not in the request")
        if run.get("length") is not None and not (isinstance(run["length"], (int, float))
                                                  and math.isfinite(run["length"])):
            raise ShippedError(f"{where}: length {run['length']!r} is not a finite number")
        if run.get("points") is not None:
            _finite_points(run["points"], where + ".points")
            if len(run["points"]) != len(case["s"]):
                raise ShippedError(f"{where}: {len(run['points'])} points for the request's {len(case['s'])} s")
        if run.get("spaced") is not None:
            _finite_points(run["spaced"], where + ".spaced")
    return cases


def file_stem(run):
    """A file name for a run: peer, setting and case, with anything but [A-Za-z0-9_.=-] as '_'."""
    return re.sub(r"[^A-Za-z0-9_.=-]", "_", f"{run['peer']}.{run.get('setting') or 'default'}.{run['case']}")


def write_csvs(run, case, work):
    """The run's points (s,x,y) and spaced points (x,y) as CSV files in work: {kind: path}."""
    out = {}
    stem = os.path.join(work, file_stem(run))
    if run.get("points"):
        out["points"] = stem + ".points.csv"
        with open(out["points"], "w", newline="", encoding="utf-8") as f:
            w = csv.writer(f)
            w.writerow(["s", "x", "y"])
            for s, (x, y) in zip(case["s"], run["points"]):
                w.writerow([repr(float(s)), repr(float(x)), repr(float(y))])
    if run.get("spaced") and len(run["spaced"]) >= 2:
        # Each spaced point is where the k-th of n should be, s = k L / (n - 1) (L the true length):
        # its error is its distance from there, and where the curve passes it twice (a cusp folds
        # back on itself) its s_true is the branch nearest that s.
        out["spaced"] = stem + ".spaced.csv"
        n = len(run["spaced"])
        with open(out["spaced"], "w", newline="", encoding="utf-8") as f:
            w = csv.writer(f)
            w.writerow(["s", "x", "y"])
            for k, (x, y) in enumerate(run["spaced"]):
                s = case["length"] if k == n - 1 else case["length"] * k / (n - 1)
                w.writerow([repr(float(s)), repr(float(x)), repr(float(y))])
    return out


def spacing_cv(s_true):
    """Coefficient of variation of the gaps between consecutive arc lengths (population standard
    deviation over the mean); None for fewer than two gaps' worth of points or a zero mean."""
    gaps = [b - a for a, b in zip(s_true, s_true[1:])]
    if len(gaps) < 2:
        return None
    mean = sum(gaps) / len(gaps)
    if mean <= 0:
        return None
    return math.sqrt(sum((g - mean) ** 2 for g in gaps) / len(gaps)) / mean


def row_of(run, checks, true_length=None):
    """One result row from a run and the `check --json` outputs of its CSVs ({kind: parsed json});
    true_length: the case's L from another run's check, for a run with a length only (bezier-js)."""
    row = {k: run.get(k) for k in ("peer", "case", "setting", "ns_length", "ns_point", "ns_build", "note")}
    row["setting"] = row["setting"] or ""
    row["length"] = run.get("length")
    L = true_length
    for kind in ("points", "spaced"):
        if kind in checks:
            L = checks[kind]["checks"][0]["length"]
    row["true_length"] = L
    row["length_error"] = (abs(run["length"] - L) / L if run.get("length") is not None and L else None)
    if "points" in checks:
        rows = checks["points"]["checks"][0]["rows"]
        row["point_error"] = max(r["error"] for r in rows)
        row["point_error_at"] = max(rows, key=lambda r: r["error"])["s"]
        row["s_error"] = max(r["s_error"] for r in rows)
        row["off_curve"] = max(r["off_curve"] for r in rows)
    else:
        row["point_error"] = row["point_error_at"] = row["s_error"] = row["off_curve"] = None
    if "spaced" in checks:
        rows = checks["spaced"]["checks"][0]["rows"]
        row["spacing_cv"] = spacing_cv([r["s_true"] for r in rows])
        off = max(r["off_curve"] for r in rows)
        row["off_curve"] = off if row["off_curve"] is None else max(row["off_curve"], off)
    else:
        row["spacing_cv"] = None
    return row


def check_command(tool, spec, csv_path, peer):
    return [tool, "check", spec, "--at-length", csv_path, "--name", peer, "--json", "--quiet"]


def measure(driver, request, cases_dir, tool, work, jobs=2):
    """Every run's CSVs checked by the tool (jobs at a time); the rows and the driver's skips."""
    cases = validate(driver, request)
    os.makedirs(work, exist_ok=True)
    jobs_list = []
    for run in driver.get("runs", []):
        files = write_csvs(run, cases[run["case"]], work)
        spec = os.path.join(cases_dir, run["case"] + ".json")
        for kind, path in files.items():
            jobs_list.append((run, kind, check_command(tool, spec, path, run["peer"])))

    def one(job):
        run, kind, cmd = job
        p = subprocess.run(cmd, capture_output=True, text=True)
        if p.returncode != 0:
            raise ShippedError(f"{' '.join(cmd)}: exit {p.returncode}: {p.stderr.strip()[:500]}")
        return id(run), kind, json.loads(p.stdout)

    checks = {}
    with ThreadPoolExecutor(max_workers=jobs) as pool:
        for key, kind, out in pool.map(one, jobs_list):
            checks.setdefault(key, {})[kind] = out
    # The case's L (the reference rounded to double, as check prints it) from any of its checks.
    lengths = {}
    for run in driver.get("runs", []):
        for out in checks.get(id(run), {}).values():
            lengths[run["case"]] = out["checks"][0]["length"]
    rows = [row_of(run, checks.get(id(run), {}), lengths.get(run["case"])) for run in driver.get("runs", [])]
    # "peer_records" (none): the file sits beside the other peers_*.json, whose readers expect the key;
    # its measurements are "rows", the section of scripts/report_shipped.py.
    return {"driver": driver.get("driver"), "versions": driver.get("versions", {}), "cpu": driver.get("cpu"),
            "request_tool": request.get("tool"), "peer_records": [], "rows": rows,
            "skipped": driver.get("skipped", [])}


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    for name in ("--driver", "--request", "--cases", "--tool", "--work", "--out"):
        ap.add_argument(name, required=True)
    a = ap.parse_args()
    with open(a.driver, encoding="utf-8") as f:
        driver = json.load(f)
    with open(a.request, encoding="utf-8") as f:
        request = json.load(f)
    result = measure(driver, request, a.cases, a.tool, a.work)
    peer_io.write_json(a.out, result)
    print(f"shipped_results.py: {len(result['rows'])} runs measured, {len(result['skipped'])} skipped -> {a.out}")
    return 0


if __name__ == "__main__":
    try:
        sys.exit(main())
    except (ShippedError, OSError, ValueError, KeyError) as e:
        print(f"shipped_results.py: {e}", file=sys.stderr)
        sys.exit(1)
