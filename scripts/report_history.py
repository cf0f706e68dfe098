"""The history of published runs: docs/results/history.jsonl holds one line per
published revision, the headline figures of its run; `scripts/bench.sh --publish` (publish.py)
appends the run it publishes (replacing the line of a revision published again), and the report
(report.py, REPORT.md's "History" section) tables and plots those figures over the revisions, with
the current run as the last point.

Every figure comes from publish.headline() of a run's files, never typed by hand. A figure a run
did not measure (a benchmark missing from it) is absent from that line and left out of its series.
"""
import json
import math
import os

import report_lib as lib
import safe_output

HISTORY = os.path.join("docs", "results", "history.jsonl")
VERSION = 1
TABLE_RUNS = 8


def _target_figures(h):
    """The fastest benchmark (ours or a peer's, named in methods) per error target of each
    benchmarked family: 'u_of_s query: fastest at 1e-10 (ns)'."""
    figures, methods = {}, {}
    for t in h.get("targets", []):
        if t.get("best") is None or not isinstance(t.get("best_ns"), (int, float)):
            continue
        key = f"{t['family']} {t['operation']}: fastest at {t['target']:g} (ns)"
        figures[key] = t["best_ns"]
        methods[key] = t["best"]
    return figures, methods


def entry(h):
    """The history line of a run from its headline data (publish.headline)."""
    run = h["run"]
    figures, methods = _target_figures(h)
    ho = h.get("honesty", {})
    if ho.get("with_estimate"):
        figures["estimates that bound their error (share)"] = ho["bounded"] / ho["with_estimate"]
        figures["estimates that do not (count)"] = len(ho.get("dishonest", []))
    goal = (h.get("channel") or {}).get("goal")
    if goal and isinstance(goal.get("max64"), (int, float)):
        figures["channel time solver max error (ulps)"] = goal["max64"]
    if isinstance(run.get("accuracy_seconds"), (int, float)):
        figures["accuracy run (s)"] = run["accuracy_seconds"]
    return {"version": VERSION, "revision": run["revision"], "date": run["date"], "host": run.get("host"),
            "cpus": run.get("cpus"), "mhz": run.get("mhz"), "compiler": run.get("compiler"),
            "quick": bool(run.get("quick")), "figures": figures, "methods": methods}


def _checked(e, where):
    if not isinstance(e, dict):
        raise lib.ReportError(f"{where}: not a JSON object")
    if e.get("version") != VERSION:
        raise lib.ReportError(f"{where}: version {e.get('version')!r}, this script reads version {VERSION}")
    for key in ("revision", "date"):
        if not isinstance(e.get(key), str) or not e[key]:
            raise lib.ReportError(f"{where}: {key} must be a non-empty string")
    figures = e.get("figures")
    if not isinstance(figures, dict):
        raise lib.ReportError(f"{where}: figures must be an object")
    for name, value in figures.items():
        if isinstance(value, bool) or not isinstance(value, (int, float)) or not math.isfinite(value):
            raise lib.ReportError(f"{where}: figure {name[:80]!r} = {str(value)[:80]} is not a finite number")
    return e


def load(path):
    """The history's entries in file order ([] when the file does not exist)."""
    if not os.path.exists(path):
        return []
    out = []
    with open(path, encoding="utf-8") as f:
        for n, line in enumerate(f, 1):
            if not line.strip():
                continue
            try:
                e = json.loads(line)
            except ValueError as err:
                raise lib.ReportError(f"{path}: line {n}: not JSON ({err})") from err
            out.append(_checked(e, f"{path}: line {n}"))
    return out


def appended(history, e):
    """history with e as its last line; an earlier line of the same revision is dropped."""
    return [x for x in history if x["revision"] != e["revision"]] + [e]


def write(path, history):
    safe_output.write_text(path, "".join(json.dumps(x, sort_keys=True) + "\n" for x in history))


def record(path, h):
    """Appends the run of headline data h (publish.headline) to the history file at path, replacing
    an earlier line of the same revision; returns the line."""
    e = entry(h)
    write(path, appended(load(path), e))
    return e


def series(history):
    """{figure: [(index, value)]} over the entries, in order; a figure an entry lacks is skipped."""
    out = {}
    for i, e in enumerate(history):
        for name, value in e["figures"].items():
            out.setdefault(name, []).append((i, value))
    return out


def section(history, current, plot_dir, plt, savefig):
    """REPORT.md's History section: the published revisions (docs/results/history.jsonl) and this
    run (`current`, not published: marked), a table of the figures and one plot of each over them."""
    md = ["", "## History", ""]
    runs = list(history) + ([dict(current, revision=current["revision"] + " (this run)")] if current else [])
    if not runs:
        return md + ["No published run yet (`scripts/bench.sh --publish` appends one to "
                     f"`{HISTORY}`)."]
    md += [f"The headline figures of each published run (`{HISTORY}`, one line per revision, appended by "
           "`scripts/bench.sh --publish`) and of this run. Times are from different runs, possibly on "
           "different machines (the host is shown), and a quick run (marked) measures less: compare full "
           "runs within a machine.", ""]
    data = series(runs)
    names = sorted(data)
    shown = runs[-TABLE_RUNS:]  # the plot has them all
    if len(runs) > len(shown):
        md += [f"The table shows the last {len(shown)} of {len(runs)} runs; the plot shows all.", ""]
    md.append(lib.table(["figure"] + [f"{r['revision']} ({r['date'][:10]}, {r.get('host') or '-'}"
                                      + (", quick run" if r.get("quick") else "") + ")" for r in shown],
                        [[n] + [r["figures"].get(n, "-") for r in shown] for n in names]))
    if plt is None or len(runs) < 2 or not names:
        return md
    cols = 2
    rows = (len(names) + cols - 1) // cols
    fig, axes = plt.subplots(rows, cols, figsize=(11, 2.6 * rows), squeeze=False)
    labels = [r["revision"].replace(" (this run)", "*") for r in runs]
    for k, name in enumerate(names):
        ax = axes[k // cols][k % cols]
        xs, ys = zip(*data[name])
        ax.plot(xs, ys, marker="o")
        ax.set_title(name, fontsize=9)
        ax.set_xticks(range(len(runs)))
        ax.set_xticklabels(labels, fontsize=7, rotation=30)
        if all(y > 0 for y in ys) and max(ys) / min(ys) > 100:
            ax.set_yscale("log")
    for k in range(len(names), rows * cols):
        axes[k // cols][k % cols].axis("off")
    fig.tight_layout()
    path = os.path.join(plot_dir, "history.png")
    savefig(fig, path)
    plt.close(fig)
    return md + ["", "![history](plots/history.png)", "",
                 "(* this run, not published.)"]
