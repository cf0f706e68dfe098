"""Checks a baseline for `scripts/bench.sh --baseline DIR` before the build and the long run: the
files `curvebench compare` reads from a results directory (accuracy.json, bench_*.json) are there,
each is whole JSON (no NaN or Infinity, which JSON does not have) holding a "records" or a
"benchmarks" array of objects. `curvebench compare DIR DIR` after the build then reads it with the
tool's own reader, before the run.

  python3 scripts/baseline_check.py DIR [--quick | --full]

With --quick or --full, the baseline's accuracy.json must be a run of that kind too (compare
refuses a quick run against a full one: a quick run measures each key on fewer samples).

Exits 0 when the baseline can be compared, 1 with a message naming the file and what is wrong
(for a file cut short: the line and column where the JSON stops)."""
import json
import os
import sys


class BaselineError(ValueError):
    """The baseline cannot be compared; the message names the file."""


def _no_constant(name):
    raise ValueError(f"{name} is not JSON")


def check_file(path):
    try:
        with open(path, encoding="utf-8") as f:
            data = json.load(f, parse_constant=_no_constant)
    except json.JSONDecodeError as e:
        raise BaselineError(f"{path}: not whole JSON: {e.msg} at line {e.lineno}, column {e.colno} "
                            "(a file cut short?)") from None
    except (ValueError, UnicodeDecodeError) as e:
        raise BaselineError(f"{path}: {e}") from None
    if not isinstance(data, dict) or not ("records" in data or "benchmarks" in data):
        raise BaselineError(f"{path}: holds neither \"records\" (accuracy.json) nor \"benchmarks\" "
                            "(Google Benchmark JSON)")
    for key in ("records", "peer_records", "benchmarks"):
        if key not in data:
            continue
        entries = data[key]
        if not isinstance(entries, list):
            raise BaselineError(f"{path}: \"{key}\" is not an array")
        for i, entry in enumerate(entries):
            if not isinstance(entry, dict):
                raise BaselineError(f"{path}: {key}[{i}] is not an object")
    return data


def check_baseline(directory, mode=None):
    if not os.path.isdir(directory):
        raise BaselineError(f"{directory}: not a directory")
    names = sorted(n for n in os.listdir(directory)
                   if n == "accuracy.json" or (n.startswith("bench_") and n.endswith(".json")))
    if not names:
        raise BaselineError(f"{directory}: no accuracy.json and no bench_*.json (a copy of an earlier reports/)")
    for name in names:
        data = check_file(os.path.join(directory, name))
        if name == "accuracy.json" and mode is not None:
            quick = data.get("context", {}).get("quick") if isinstance(data.get("context"), dict) else None
            if quick is not (mode == "quick"):
                raise BaselineError(f"{os.path.join(directory, name)}: a {'quick' if quick else 'full'} run "
                                    f"(context.quick is {json.dumps(quick)}), and this run is {mode}: compare "
                                    "compares two quick or two full runs")
    return names


def main(argv):
    if argv and argv[0] in ("-h", "--help"):
        print(__doc__)
        return 0
    if len(argv) not in (1, 2) or (len(argv) == 2 and argv[1] not in ("--quick", "--full")):
        print("usage: baseline_check.py DIR [--quick | --full]", file=sys.stderr)
        return 2
    try:
        check_baseline(argv[0], argv[1][2:] if len(argv) == 2 else None)
    except BaselineError as e:
        print(f"baseline_check.py: {e}", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
