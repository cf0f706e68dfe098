"""The user's own check results in the report: `scripts/report.py --checks FILE...`, FILE the JSON
`curvebench check ... --json` prints (bench/tool/check.cpp):
  {"spec", "name", "checks": [{"kind", "file", "unit", "summary": {"rows", "max", "rms", ...},
   "worst": [rows], "rows": [{"line", "error", ... "scale" (times)}], "records", "unit_id", ...}],
   "records", "failures", "passed", and the limits given: "max_error", "max_value_error",
   "max_length_error", "max_inverse_error", "max_at_length_error"}.
Every figure is shown in the check's own unit ("unit": ulps of double x size, relative to L, ...),
the unit the tool printed it in. A check is over its gate when its largest error exceeds the limit
the tool applied to its kind (its own --max-KIND-error, else --max-error; a non-finite error is
over too, as the tool counts it); a file failed when the tool said so ("passed": false, which also
counts --thresholds breaches). The files' "records" (subject records) join the report's section on
the user's implementations. Pure functions; tests/python/test_report_checks.py.
"""
import json
import math
import os

import report_lib as lib

# The option that limits each kind's rows, as `curvebench check` reads them (limit_of in check.cpp).
OWN_LIMIT = {"values": "max_value_error", "times": "max_value_error", "lengths": "max_length_error",
             "inverse": "max_inverse_error", "at_length": "max_at_length_error"}
SECTION = "Your checks (curvebench check --json)"


class ChecksError(Exception):
    pass


def load(paths):
    """[(path, document)] of the check result files; ChecksError naming a file that is not one."""
    out = []
    for path in paths:
        try:
            with open(path, encoding="utf-8") as f:
                doc = json.load(f)
        except OSError as e:
            raise ChecksError(f"{path}: {e.strerror or e}") from e
        except json.JSONDecodeError as e:
            raise ChecksError(f"{path}: not JSON ({e}); --checks takes what `curvebench check ... --json` "
                              "prints") from e
        if not isinstance(doc, dict) or not isinstance(doc.get("checks"), list) or "passed" not in doc:
            raise ChecksError(f"{path}: not a `curvebench check --json` result (an object with \"checks\" and "
                              "\"passed\")")
        for i, c in enumerate(doc["checks"]):
            if not isinstance(c, dict) or not isinstance(c.get("summary"), dict) or "unit" not in c:
                raise ChecksError(f"{path}: checks[{i}]: expected an object with \"kind\", \"unit\" and \"summary\"")
        out.append((path, doc))
    return out


def limit(doc, kind):
    """The limit the tool applied to a check of `kind` in `doc`, or None (no gate given)."""
    for key in (OWN_LIMIT.get(kind), "max_error"):
        if key and isinstance(doc.get(key), (int, float)):
            return doc[key]
    return None


def verdict(doc, check):
    """"passed", "over" or "no gate" of one check of a file."""
    gate = limit(doc, check.get("kind"))
    if gate is None:
        return "no gate"
    worst = check["summary"].get("max")
    finite = isinstance(worst, (int, float)) and math.isfinite(worst)
    return "passed" if finite and worst <= gate else "over"


def records(files):
    """The subject records of every file (each check's, as the tool lists them in "records")."""
    return [r for _, doc in files for r in doc.get("records", []) if isinstance(r, dict)]


def counts(files):
    """{"files", "passed", "failed", "checks", "over", "no_gate"}: files by the tool's own verdict
    (a file with no gate at all counts as neither passed nor failed), checks by verdict()."""
    out = {"files": len(files), "passed": 0, "failed": 0, "ungated_files": 0, "checks": 0, "over": 0,
           "no_gate": 0}
    for _, doc in files:
        verdicts = [verdict(doc, c) for c in doc["checks"]]
        out["checks"] += len(verdicts)
        out["over"] += verdicts.count("over")
        out["no_gate"] += verdicts.count("no gate")
        if doc.get("passed") is False:
            out["failed"] += 1
        elif all(v == "no gate" for v in verdicts) and not doc.get("failures"):
            out["ungated_files"] += 1
        else:
            out["passed"] += 1
    return out


def _scale_text(check):
    """The size its unit is taken of: the values' size, or the range of the rows' scales (times)."""
    scales = [r["scale"] for r in check.get("rows", []) if isinstance(r.get("scale"), (int, float))]
    if scales:
        lo, hi = min(scales), max(scales)
        return f"row scale {lib.fmt(lo)}" + (f" to {lib.fmt(hi)}" if hi != lo else "")
    if isinstance(check.get("size"), (int, float)):
        return f"size {lib.fmt(check['size'])}"
    if isinstance(check.get("length"), (int, float)):
        return f"L {lib.fmt(check['length'])}"
    return "-"


def rows(files):
    """One row per check: [result file, spec, name, kind, rows, max, rms, unit, scale, worst row,
    gate, verdict]."""
    out = []
    for path, doc in files:
        for c in doc["checks"]:
            s = c["summary"]
            worst = (c.get("worst") or [None])[0]
            gate = limit(doc, c.get("kind"))
            out.append([os.path.basename(path), doc.get("spec", "-"), doc.get("name", "-"), c.get("kind", "-"),
                        s.get("rows", "-"), lib.fmt(s.get("max")), lib.fmt(s.get("rms")), c["unit"], _scale_text(c),
                        f"line {worst['line']} of {c.get('file', '-')}" if isinstance(worst, dict) else "-",
                        lib.fmt(gate) if gate is not None else "none", verdict(doc, c)])
    return out


def summary_text(files):
    """The summary's sentence on the files: how many passed and how many are over their gate."""
    n = counts(files)
    over = [f"{os.path.basename(p)} {c.get('kind')}: max {lib.fmt(c['summary'].get('max'))} {c['unit']} "
            f"> {lib.fmt(limit(doc, c.get('kind')))}"
            for p, doc in files for c in doc["checks"] if verdict(doc, c) == "over"]
    text = (f"{n['files']} check result file{'s' if n['files'] != 1 else ''} ({n['checks']} "
            f"check{'s' if n['checks'] != 1 else ''}): {n['passed']} passed, {n['failed']} failed")
    if n["ungated_files"]:
        text += f", {n['ungated_files']} without a gate (no --max-error)"
    text += f"; {n['over']} check{'s' if n['over'] != 1 else ''} over {'their' if n['over'] != 1 else 'its'} gate"
    return text + (": " + "; ".join(over) if over else "") + "."


def section(files):
    """The markdown lines of the section (none without files)."""
    if not files:
        return []
    md = ["", f"## {SECTION}", "",
          "Each check result file as `curvebench check --json` wrote it: per check its rows, its largest and rms "
          "error in the check's own unit (the unit the tool printed; the size or the rows' scale it is taken of), "
          "its worst row, the limit the tool applied (the kind's own --max-KIND-error, else --max-error) and the "
          "verdict; a file failed when the tool said so (its --thresholds breaches included).", "",
          summary_text(files), ""]
    md.append(lib.table(["result file", "spec", "name", "kind", "rows", "max", "rms", "unit", "of", "worst row",
                         "gate", "verdict"], rows(files)))
    failures = [(os.path.basename(p), f) for p, doc in files for f in doc.get("failures", [])]
    if failures:
        md += ["", "The tool's failure lines:", ""]
        md += [f"- {p}: `{f}`" for p, f in failures[:40]]
        if len(failures) > 40:
            md.append(f"- and {len(failures) - 40} more")
    return md + [""]
