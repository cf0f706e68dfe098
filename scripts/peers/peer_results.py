#!/usr/bin/python3
"""Joins an optional peer driver's output with `curvebench check`'s measurement of it into the
peer records REPORT.md reads (reports/peers_<driver>.json, scripts/report_peers.py).

  peer_results.py --driver DIR/scipy_driver.json --out reports/peers_scipy.json

The driver (scripts/peers/scipy_driver.py) writes what the peer computed as CSV files beside its
JSON; scripts/peers.sh measures each CSV with `curvebench check SPEC --values|--lengths CSV --name
PEER --json` into CSV + ".check.json". The truth is therefore the 50-digit reference of the case's
spec (harness/check.hpp), never a double evaluation of curvebench's own code. This module turns the
pair into records of the accuracy format with "peer": true (see report_peers.py):
  values   each check record (eval "" for the points, eval "derivative=1" for the first
           derivative; errors in eps(double) x size), the driver's time per evaluation on the
           points' record, counterpart curvebench's default evaluation of the case
  lengths  one record per tolerance the driver ran, in the driver's row order: error = the check
           row's |L_peer - L| / L, estimate = quad's abserr / L, bounded, evaluations = quad's
           neval, status from quad's message (success: converged; the subdivision limit: cap_hit;
           roundoff: rounding_limited; other warnings: not_guaranteed), and a refused tolerance as
           a record without a value whose peer_status is the library's message
  inverse  one u_of_s record per run (a tolerance): error = the check's worst |s(u) - s| / L,
           estimate = the driver's own account (max over the targets of quad's residual plus its
           abserr) / L, evaluations = speed evaluations per query, status from the warnings as
           for lengths, counterpart curvebench's Newton u(s) at the same tolerance; a run brentq
           or quad refused is a record without a value
Errors name the file and the field.
"""
import argparse
import json
import os
import sys

import peer_io


class PeerResultError(Exception):
    pass


def _load(path):
    try:
        with open(path, encoding="utf-8") as f:
            return json.load(f)
    except (OSError, json.JSONDecodeError) as e:
        raise PeerResultError(f"{path}: {e}") from e


def quad_status(message, warned):
    """A result_status name for quad's outcome (its message's first line)."""
    m = message.lower()
    if not warned and m == "success":
        return "converged"
    if "maximum number of subdivisions" in m:
        return "cap_hit"
    if "roundoff" in m:
        return "rounding_limited"
    return "not_guaranteed"


def _base(check_record, library):
    r = dict(check_record)
    r.pop("subject", None)
    r.update({"peer": True, "library": library})
    return r


def values_records(run, check, library):
    """The peer records of a values run from its check JSON."""
    checks = check.get("checks")
    if not isinstance(checks, list) or len(checks) != 1 or checks[0].get("kind") != "values":
        raise PeerResultError(f"{run['csv']}.check.json: expected one check of kind values")
    out = []
    for rec in checks[0].get("records", []):
        if rec.get("quantity") != "eval" or rec.get("method") != run["peer"]:
            raise PeerResultError(f"{run['csv']}.check.json: record {rec.get('quantity')}/{rec.get('method')} is not "
                                  f"an eval record of {run['peer']}")
        r = _base(rec, library)
        r["peer_status"] = "success"
        points = (rec.get("setting") or "") == ""
        r["ns_per_op"] = run.get("ns_per_op") if points else None
        if points:
            r["counterpart"] = run.get("counterpart")
        out.append(r)
    return out


def _refused(message):
    """The fields of a record the library refused to compute: no value, its message kept."""
    return {"error": None, "estimate": None, "bounded": None, "evaluations": 0, "status": "not_guaranteed",
            "peer_status": message, "ns_per_op": None}


def lengths_records(run, check, library, group):
    """The peer records of a lengths run: one per driver row, measured rows joined in order."""
    rows = run.get("rows", [])
    measured = [row for row in rows if "refused" not in row]
    check_rows = []
    length = None
    if measured:
        checks = check.get("checks") if check else None
        if not isinstance(checks, list) or len(checks) != 1 or checks[0].get("kind") != "lengths":
            raise PeerResultError(f"{run['csv']}.check.json: expected one check of kind lengths")
        check_rows = checks[0].get("rows", [])
        length = checks[0].get("length")
        if len(check_rows) != len(measured):
            raise PeerResultError(f"{run['csv']}.check.json: {len(check_rows)} rows measured, the driver ran "
                                  f"{len(measured)} tolerances")
        if not isinstance(length, (int, float)) or length <= 0:
            raise PeerResultError(f"{run['csv']}.check.json: length {length!r} is not a positive number")
    out, k = [], 0
    for row in rows:
        r = {"case": run["case"], "group": group, "quantity": "length", "method": run["peer"],
             "setting": row["setting"], "peer": True, "library": library,
             "counterpart": {"method": run["counterpart"]["method"], "setting": row["setting"]}}
        if "refused" in row:
            r.update(_refused(row["refused"]))
        else:
            err = check_rows[k]["error"]
            k += 1
            est = row["abserr"] / length
            r.update({"error": err, "estimate": est, "bounded": est >= err, "evaluations": row["neval"],
                      "status": quad_status(row["message"], row.get("warned", False)),
                      "peer_status": row["message"], "ns_per_op": row.get("ns_per_op")})
        out.append(r)
    return out


def inverse_record(run, check, library, group):
    """The u_of_s peer record of an inverse run (one tolerance)."""
    r = {"case": run["case"], "group": group, "quantity": "u_of_s", "method": run["peer"],
         "setting": run["setting"], "peer": True, "library": library, "counterpart": run["counterpart"]}
    if "refused" in run:
        r.update(_refused(run["refused"]))
        return r
    checks = check.get("checks") if check else None
    if not isinstance(checks, list) or len(checks) != 1 or checks[0].get("kind") != "inverse":
        raise PeerResultError(f"{run['csv']}.check.json: expected one check of kind inverse")
    recs = [x for x in checks[0].get("records", []) if x.get("quantity") == "u_of_s"]
    length = checks[0].get("length")
    if len(recs) != 1 or not isinstance(recs[0].get("error"), (int, float)):
        raise PeerResultError(f"{run['csv']}.check.json: expected one u_of_s record with an error")
    if not isinstance(length, (int, float)) or length <= 0:
        raise PeerResultError(f"{run['csv']}.check.json: length {length!r} is not a positive number")
    err = recs[0]["error"]
    est = run["estimate_abs"] / length
    r.update({"error": err, "estimate": est, "bounded": est >= err, "evaluations": run["evaluations_per_query"],
              "status": quad_status(run["message"], run.get("warned", False)), "peer_status": run["message"],
              "ns_per_op": run.get("ns_per_op")})
    return r


def assemble(driver, read_check, library_name="SciPy"):
    """The peers_<driver>.json document. read_check(csv) returns the check JSON of a CSV."""
    for key in ("driver", "versions", "runs"):
        if key not in driver:
            raise PeerResultError(f"driver output: no \"{key}\"")
    library = f"{library_name} {driver['versions'].get(library_name, '?')}"
    records = []
    groups = {}
    for run in driver["runs"]:
        check = read_check(run["csv"]) if run.get("csv") else None
        if run["kind"] == "values":
            recs = values_records(run, check, library)
            groups[run["case"]] = recs[0]["group"] if recs else groups.get(run["case"], "")
            records += recs
        elif run["kind"] == "lengths":
            group = groups.get(run["case"], "")
            if check and check.get("records"):
                group = check["records"][0].get("group", group)
            records += lengths_records(run, check, library, group)
        elif run["kind"] == "inverse":
            records.append(inverse_record(run, check, library, groups.get(run["case"], "")))
        else:
            raise PeerResultError(f"driver output: run kind {run['kind']!r} is not values, lengths or inverse")
    return {"driver": driver["driver"], "versions": driver["versions"], "notes": driver.get("notes", []),
            "quick": driver.get("quick"), "peer_records": records}


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--driver", required=True, help="the driver's JSON (its CSVs and .check.json files beside it)")
    ap.add_argument("--out", required=True)
    a = ap.parse_args()
    base = os.path.dirname(os.path.abspath(a.driver))
    try:
        doc = assemble(_load(a.driver), lambda csv: _load(os.path.join(base, csv + ".check.json")))
    except PeerResultError as e:
        print(f"peer_results: {e}", file=sys.stderr)
        return 1
    peer_io.write_json(a.out, doc)
    print(f"peer_results: {len(doc['peer_records'])} peer records -> {a.out}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
