#!/usr/bin/python3
"""Measures the arc-length peers' answers against the 50-digit reference of each case.

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
  documented_tolerance, outside_tolerance   where the run carries "documented_length_tolerance"
                   (the error bound its library documents, absolute, in path units: lib2geom's
                   Curve::length), that bound and whether |L_peer - L| exceeds it

Runs on the request's "catmull_rom" cases (three's CatmullRomCurve3) carry 2D or 3D points as the
case is, and two more outputs, measured against curvebench's Catmull-Rom through the same points:
  map_s_error      max over s of |s(u) - s| / L where u is curvebench's parameter at the peer's
                   getUtoTmapping t (`check --inverse`): its u(s) alone, without evaluation
  eval_error       max over the request's t grid of |getPoint(t) - P(u(t))| in ulps of double x the
                   curve's size (`check --values --unit ulp-double`), beside
  curvebench_eval_error   the same of curvebench's own double evaluation (`curvebench sample`) at the
                   same u
  eval_floor       max over the grid of |P'(u)| ulp(u) / (eps(double) x size): what rounding the
                   parameter to a double alone moves the point by (0 on uniform knots, where
                   u = (n - 1) t exactly). three's t becomes curvebench's u = u_i + w (u_i+1 - u_i), rounded;
                   the exact point of that rounded u is the reference, so a getPoint error below
                   eval_floor is not distinguishable from that rounding (curvebench's own is
                   evaluated at the rounded u itself, and does not carry it)

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
import safe_output
import shipped_request

DRIVER_FORMAT = "curvebench-shipped-driver-1"
REQUEST_FORMAT = "curvebench-shipped-request-1"


class ShippedError(Exception):
    pass


def _finite(v):
    return isinstance(v, (int, float)) and not isinstance(v, bool) and math.isfinite(v)


def _finite_points(points, what, dim=2):
    shape = "[x, y]" if dim == 2 else "[x, y, z]"
    if not isinstance(points, list):
        raise ShippedError(f"{what}: expected a list of {shape}, got {points!r}"[:200])
    for i, p in enumerate(points):
        if not (isinstance(p, list) and len(p) == dim and all(_finite(v) for v in p)):
            raise ShippedError(f"{what}[{i}]: expected {shape} of finite numbers, got {p!r}"[:200])
    return points


def request_cases(request):
    """{case name: request entry} of both the path cases and the Catmull-Rom cases."""
    return {c["case"]: c for c in request["cases"] + request.get("catmull_rom", []) + request.get("splines", [])}


TIMINGS = ("ns_length", "ns_point", "ns_build")


def validate(driver, request):
    """Both documents' formats, and every run naming a case of the request with the right count of
    points, finite non-negative timings and tolerance; ShippedError naming the run otherwise."""
    for what, doc in (("driver output", driver), ("request", request)):
        if not isinstance(doc, dict):
            raise ShippedError(f"{what}: expected a JSON object, got {type(doc).__name__} {doc!r}"[:200])
    if not isinstance(driver.get("runs", []), list):
        raise ShippedError(f"driver output: runs: expected a list, got {driver['runs']!r}"[:200])
    for key in ("cases", "catmull_rom", "splines"):
        if not isinstance(request.get(key, []), list) or not all(isinstance(c, dict) and "case" in c
                                                                 for c in request.get(key, [])):
            raise ShippedError(f"request: {key}: expected a list of objects with a case"[:200])
    for i, run in enumerate(driver.get("runs", [])):
        if not isinstance(run, dict):
            raise ShippedError(f"driver output: runs[{i}]: expected an object, got {run!r}"[:200])
    if driver.get("format") != DRIVER_FORMAT:
        raise ShippedError(f"driver output: format {driver.get('format')!r}, expected {DRIVER_FORMAT!r}")
    if request.get("format") != REQUEST_FORMAT:
        raise ShippedError(f"request: format {request.get('format')!r}, expected {REQUEST_FORMAT!r}")
    cases = request_cases(request)
    for i, run in enumerate(driver.get("runs", [])):
        where = f"runs[{i}] ({run.get('peer')}, {run.get('case')})"
        case = cases.get(run.get("case"))
        if case is None:
            raise ShippedError(f"{where}: the case is not in the request")
        dim = case.get("dim", 2)
        if run.get("length") is not None and not _finite(run["length"]):
            raise ShippedError(f"{where}: length {run['length']!r} is not a finite number")
        for key in TIMINGS:
            if run.get(key) is not None and not (_finite(run[key]) and run[key] >= 0):
                raise ShippedError(f"{where}: {key} {run[key]!r} is not a finite number of ns >= 0")
        tol = run.get("documented_length_tolerance")
        if tol is not None and not (_finite(tol) and tol >= 0):
            raise ShippedError(f"{where}: documented_length_tolerance {tol!r} is not a finite number >= 0")
        if run.get("points") is not None:
            _finite_points(run["points"], where + ".points", dim)
            if len(run["points"]) != len(case["s"]):
                raise ShippedError(f"{where}: {len(run['points'])} points for the request's {len(case['s'])} s")
        if run.get("spaced") is not None:
            _finite_points(run["spaced"], where + ".spaced", dim)
        if run.get("values") is not None:
            _finite_points(run["values"], where + ".values", dim)
            if len(run["values"]) != len(case.get("t", [])):
                raise ShippedError(f"{where}: {len(run['values'])} values for the request's {len(case.get('t', []))} t")
        if run.get("t_at_s") is not None:
            t = run["t_at_s"]
            if not (isinstance(t, list) and len(t) == len(case["s"]) and all(_finite(v) and 0 <= v <= 1 for v in t)):
                raise ShippedError(f"{where}: t_at_s must hold one t in [0, 1] per request s, got {t!r}"[:200])
    return cases


def file_stem(run, index):
    """A file name for the index-th run: "r<index>." then peer, setting and case with anything but
    [A-Za-z0-9_.=-] as '_' (readable; the index alone keeps it unique: two runs of one peer,
    setting and case, or settings "a/b" and "a_b", would otherwise share the name and each other's
    measurement)."""
    clean = re.sub(r"[^A-Za-z0-9_.=-]", "_", f"{run['peer']}.{run.get('setting') or 'default'}.{run['case']}")
    return f"r{index}.{clean}"


def _write_file(path, write):
    """write(f) into a new file at path, through safe_output (a link or device there is refused)."""
    def fill(tmp):
        with open(tmp, "w", newline="", encoding="utf-8") as f:
            write(f)
    try:
        safe_output.write_with(path, fill)
    except safe_output.OutputError as e:
        raise ShippedError(f"--work: {e}")


def _axes(case):
    return ["x", "y", "z"][:case.get("dim", 2)]


def write_csvs(run, case, work, index=0):
    """The run's points (s,x,y[,z]) and spaced points as CSV files in work, and for a Catmull-Rom
    run its values (u,x,y[,z]) and t_at_s (s,u): {kind: path}. index: the run's in the driver's runs."""
    out = {}
    stem = os.path.join(work, file_stem(run, index))
    axes = _axes(case)

    def write(kind, header, rows):
        out[kind] = f"{stem}.{kind}.csv"

        def fill(f):
            w = csv.writer(f)
            w.writerow(header)
            for row in rows:
                w.writerow([repr(float(v)) for v in row])
        _write_file(out[kind], fill)
    if run.get("points"):
        write("points", ["s"] + axes, ([s] + p for s, p in zip(case["s"], run["points"])))
    if run.get("values"):
        write("values", ["u"] + axes, ([u] + p for u, p in zip(case["u"], run["values"])))
    if run.get("t_at_s"):
        end = case["knots"][-1]
        u_of = [min(shipped_request.three_parameter(t, case["knots"], case["closed"]), end) for t in run["t_at_s"]]
        write("inverse", ["s", "u"], zip(case["s"], u_of))
    if run.get("spaced") and len(run["spaced"]) >= 2:
        # Each spaced point is where the k-th of n should be, s = k L / (n - 1) (L the true length):
        # its error is its distance from there, and where the curve passes it twice (a cusp folds
        # back on itself) its s_true is the branch nearest that s.
        n = len(run["spaced"])
        write("spaced", ["s"] + axes, ([case["length"] if k == n - 1 else case["length"] * k / (n - 1)] + p
                                       for k, p in enumerate(run["spaced"])))
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


def is_loop(case):
    """Whether the request case is one closed subpath (or a closed Catmull-Rom or periodic B-spline)."""
    if "segments" in case:
        return len(case["segments"]) == 1 and bool(case["segments"][0].get("closed"))
    return bool(case.get("closed")) or case.get("knot_vector") == "periodic"


def row_of(run, checks, true_length=None, ours_eval=None, loop=False):
    """One result row from a run and the `check --json` outputs of its CSVs ({kind: parsed json});
    true_length: the case's L from another run's check, for a run with a length only (bezier-js);
    ours_eval: curvebench's own evaluation error at the case's u grid (Catmull-Rom cases); loop:
    the case is one closed loop (is_loop), whose spaced points' arc lengths count modulo L."""
    row = {k: run.get(k) for k in ("peer", "case", "setting", "ns_length", "ns_point", "ns_build", "note")}
    row["setting"] = row["setting"] or ""
    row["length"] = run.get("length")
    L = true_length
    for kind in ("points", "spaced"):
        if kind in checks:
            L = checks[kind]["checks"][0]["length"]
    row["true_length"] = L
    row["length_error"] = (abs(run["length"] - L) / L if run.get("length") is not None and L else None)
    if run.get("documented_length_tolerance") is not None and run.get("length") is not None and L:
        # The peer documents its length's error bound (absolute, path units): outside it is a finding.
        row["documented_tolerance"] = run["documented_length_tolerance"]
        row["outside_tolerance"] = abs(run["length"] - L) > run["documented_length_tolerance"]
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
        s_true = [r["s_true"] for r in rows]
        if loop and L:
            # A closed loop's start and end are one point: a spaced point a rounding past the end
            # is nearest the start (s_true about 0 for s = L). Arc lengths count modulo L there.
            s_true = [t + L * round((r["s"] - t) / L) for r, t in zip(rows, s_true)]
        row["spacing_cv"] = spacing_cv(s_true)
        off = max(r["off_curve"] for r in rows)
        row["off_curve"] = off if row["off_curve"] is None else max(row["off_curve"], off)
    else:
        row["spacing_cv"] = None
    if "values" in checks or "inverse" in checks:
        row["eval_error"] = checks["values"]["checks"][0]["summary"]["max"] if "values" in checks else None
        row["map_s_error"] = checks["inverse"]["checks"][0]["summary"]["max"] if "inverse" in checks else None
        row["curvebench_eval_error"] = ours_eval
    return row


CHECK_OPTION = {"points": ["--at-length"], "spaced": ["--at-length"], "values": ["--unit", "ulp-double", "--values"],
                "inverse": ["--inverse"]}


def check_command(tool, spec, csv_path, peer, kind="points"):
    return [tool, "check", spec] + CHECK_OPTION[kind] + [csv_path, "--name", peer, "--json", "--quiet"]


def sample_to(tool, spec, at_file, derivatives, out_csv):
    """`curvebench sample SPEC --at-file AT --derivatives K` into out_csv; ShippedError on a failure."""
    try:
        safe_output.check_output_path(out_csv)
    except safe_output.OutputError as e:
        raise ShippedError(f"--work: {e}")
    with open(out_csv, "w", encoding="utf-8") as f:
        p = subprocess.run([tool, "sample", spec, "--at-file", at_file, "--derivatives", str(derivatives), "--quiet"],
                           stdout=f, stderr=subprocess.PIPE, text=True)
    if p.returncode != 0:
        raise ShippedError(f"curvebench sample {spec}: exit {p.returncode}: {p.stderr.strip()[:500]}")


def _case_stem(index, case):
    """The index-th request case's name as a file name (the index keeps names that clean alike apart)."""
    return f"c{index}." + re.sub(r"[^A-Za-z0-9_.=-]", "_", case["case"])


def curvebench_eval_jobs(request, cases_dir, tool, work):
    """For each Catmull-Rom case: curvebench's own double evaluation at the case's u grid (`curvebench
    sample`), as a values CSV to check like the peers': [(case, check command)]."""
    jobs = []
    for i, c in enumerate(request.get("catmull_rom", [])):
        spec = os.path.join(cases_dir, c["case"] + ".json")
        at = os.path.join(work, f"curvebench.{_case_stem(i, c)}.u.txt")
        _write_file(at, lambda f: f.write("".join(repr(float(u)) + "\n" for u in c["u"])))
        values = os.path.join(work, f"curvebench.{_case_stem(i, c)}.values.csv")
        sample_to(tool, spec, at, 0, values)
        jobs.append((c["case"], check_command(tool, spec, values, "curvebench", "values")))
    return jobs


def reference_length(case, spec, tool, work):
    """The 50-digit length L of a request case (as check prints it), from `check --at-length` of the
    curve's start point at s = 0."""
    start = case["segments"][0]["start"] if "segments" in case else case["points"][0][:case.get("dim", 2)]
    path = os.path.join(work, f"start.{re.sub(r'[^A-Za-z0-9_.=-]', '_', case['case'])}.csv")
    _write_file(path, lambda f: csv.writer(f).writerows([["s"] + _axes(case), [0.0] + [repr(float(v)) for v in start]]))
    p = subprocess.run(check_command(tool, spec, path, "start"), capture_output=True, text=True)
    if p.returncode != 0:
        raise ShippedError(f"curvebench check {spec} (its length): exit {p.returncode}: {p.stderr.strip()[:500]}")
    return json.loads(p.stdout)["checks"][0]["length"]


def eval_floor(sample_csv, size):
    """max |P'(u)| ulp(u) / (eps x size) over the rows of `curvebench sample --derivatives 1` output."""
    eps = 2.0 ** -52
    worst = 0.0
    with open(sample_csv, encoding="utf-8") as f:
        for row in csv.DictReader(f):
            speed = math.sqrt(sum(float(row[k]) ** 2 for k in row if k.startswith("d") and len(k) == 2))
            worst = max(worst, speed * math.ulp(float(row["u"])))
    return worst / (eps * size) if size else None


def eval_floors(request, cases_dir, tool, work, sizes):
    """{case: eval_floor} of the Catmull-Rom cases, from their u grid's derivatives."""
    out = {}
    for i, c in enumerate(request.get("catmull_rom", [])):
        if c["case"] not in sizes:
            continue
        spec = os.path.join(cases_dir, c["case"] + ".json")
        at = os.path.join(work, f"curvebench.{_case_stem(i, c)}.u.txt")
        sample = os.path.join(work, f"curvebench.{_case_stem(i, c)}.derivatives.csv")
        sample_to(tool, spec, at, 1, sample)
        out[c["case"]] = eval_floor(sample, sizes[c["case"]])
    return out


def measure(driver, request, cases_dir, tool, work, jobs=2):
    """Every run's CSVs checked by the tool (jobs at a time); the rows and the driver's skips."""
    cases = validate(driver, request)
    os.makedirs(work, exist_ok=True)
    jobs_list = []
    for i, run in enumerate(driver.get("runs", [])):
        files = write_csvs(run, cases[run["case"]], work, i)
        spec = os.path.join(cases_dir, run["case"] + ".json")
        for kind, path in files.items():
            jobs_list.append((id(run), kind, check_command(tool, spec, path, run["peer"], kind)))
    if any(run["case"] in {c["case"] for c in request.get("catmull_rom", [])} for run in driver.get("runs", [])):
        jobs_list += [(case, "curvebench_values", cmd)
                      for case, cmd in curvebench_eval_jobs(request, cases_dir, tool, work)]

    def one(job):
        key, kind, cmd = job
        p = subprocess.run(cmd, capture_output=True, text=True)
        if p.returncode != 0:
            raise ShippedError(f"{' '.join(cmd)}: exit {p.returncode}: {p.stderr.strip()[:500]}")
        return key, kind, json.loads(p.stdout)

    checks = {}
    with ThreadPoolExecutor(max_workers=jobs) as pool:
        for key, kind, out in pool.map(one, jobs_list):
            checks.setdefault(key, {})[kind] = out
    ours_eval = {case: out["curvebench_values"]["checks"][0]["summary"]["max"]
                 for case, out in checks.items() if isinstance(case, str)}
    floors = eval_floors(request, cases_dir, tool, work,
                         {case: out["curvebench_values"]["checks"][0]["size"]
                          for case, out in checks.items() if isinstance(case, str)})
    # The case's L (the reference rounded to double, as check prints it) from any of its checks; a
    # case whose runs have lengths only (fontTools, bezier-js alone) gets a check of its start point.
    lengths = {}
    for run in driver.get("runs", []):
        for out in checks.get(id(run), {}).values():
            lengths[run["case"]] = out["checks"][0]["length"]
    for case in sorted({run["case"] for run in driver.get("runs", [])} - set(lengths)):
        lengths[case] = reference_length(cases[case], os.path.join(cases_dir, case + ".json"), tool, work)
    rows = [row_of(run, checks.get(id(run), {}), lengths.get(run["case"]), ours_eval.get(run["case"]),
                   is_loop(cases[run["case"]])) for run in driver.get("runs", [])]
    uniform = {c["case"] for c in request.get("catmull_rom", []) if c["curve_type"] == "catmullrom"}
    for row in rows:
        if "eval_error" in row:
            # Uniform knots: u = u_i + w = (n - 1) t exactly (Sterbenz), nothing rounded.
            row["eval_floor"] = 0.0 if row["case"] in uniform else floors.get(row["case"])
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
