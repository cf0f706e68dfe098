#!/usr/bin/python3
"""curvebench's own evaluation of the CSS easings an easing driver ran, at the driver's times: per
case, DIR/<case>.csv with the time solver "exact" (the peers' counterpart) and
DIR/<case>.table_newton.csv as written (the CSS tool's default solver), for
scripts/peers/easing_results.py --curvebench-dir DIR.

  sample_css_runs.py --driver DRIVER.json --cases bench/cases --tool CURVEBENCH --out DIR

A run's spec is its case file; a steps() run of scripts/peers/chromium_driver.py without a case
file (its "easing_text") gets the spec {"type": "channel", "tool": "css", "easing": TEXT}.
"""
import argparse
import json
import os
import subprocess
import sys

import peer_io


def spec_of(run, cases):
    """The CSS channel spec of a driver run."""
    path = os.path.join(cases, run["case"] + ".json")
    if os.path.exists(path):
        with open(path, encoding="utf-8") as f:
            return json.load(f)
    if "easing_text" in run:
        return {"type": "channel", "tool": "css", "easing": run["easing_text"]}
    raise FileNotFoundError(f"{path}: no case file for run {run['case']!r}")


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--driver", required=True)
    ap.add_argument("--cases", required=True)
    ap.add_argument("--tool", required=True)
    ap.add_argument("--out", required=True)
    a = ap.parse_args()
    with open(a.driver, encoding="utf-8") as f:
        driver = json.load(f)
    os.makedirs(a.out, exist_ok=True)
    done = set()
    for run in driver["runs"]:
        if run["case"] in done or "times" not in run:
            continue
        done.add(run["case"])
        times = os.path.join(a.out, run["case"] + ".times")
        with open(times, "w", encoding="utf-8") as f:
            f.write("".join(repr(t) + "\n" for t in run["times"]))
        spec = spec_of(run, a.cases)
        written = os.path.join(a.out, run["case"] + ".spec.json")
        exact = os.path.join(a.out, run["case"] + ".exact.json")
        for path, s in ((written, spec), (exact, dict(spec, solver="exact"))):
            with open(path, "w", encoding="utf-8") as f:
                json.dump(s, f)
        for spec_path, csv in ((exact, run["case"] + ".csv"), (written, run["case"] + ".table_newton.csv")):
            with open(os.path.join(a.out, csv), "w", encoding="utf-8") as f:
                subprocess.run(peer_io.sample_command(a.tool, spec_path, times), stdout=f, check=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
