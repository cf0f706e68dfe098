#!/usr/bin/python3
"""Generates reports/REPORT.md, reports/REPORT.html and reports/plots/*.png from the results of
scripts/bench.sh.

Inputs (all in the reports directory, all produced by scripts):
  vocabulary.json  `curvebench list vocabulary --json`: methods, peers, algorithms, operations and
                   counters (bench/harness/vocabulary.hpp); every benchmark must use only these
  bench_*.json     Google Benchmark output (names family/algorithm/key:value; each benchmark labels
                   the operation it times and sets items processed: times are shown per operation)
  accuracy.json    the accuracy runner's output: context, records, orders, properties; records
                   marked "subject": true (a user's implementation: `curvebench check`, the subject
                   API) are shown in their own section beside curvebench's methods; its
                   "peer_records" (GSL, always run) and any peers_*.json of scripts/peers.sh make
                   the Peers section (report_peers.py; an accuracy.json without them is accepted)
  fidelity.json    optional, `curvebench fidelity --json` of tests/data/recorded/*.json: the tool models
                   against the real tools
REPORT.md opens with a summary built from these figures (per quantity, kind and size of curve the
cheapest method reaching each error target, each peer's worst finding, each tool model's fidelity) and a table
of contents (report_summary.py), then the sections. REPORT.html is the same Markdown rendered as one
page (report_html.py): sortable, filterable tables, the plots it shows embedded as PNG and the
per-case galleries linked to their files under plots/.
Exits 1, naming the benchmark, on a benchmark the vocabulary does not describe. Every file is
written under a temporary name and renamed, so an interrupted run never leaves a half-written
report. Needs matplotlib (Debian's python3-matplotlib: /usr/bin/python3, the shebang's); under a
python3 without it, it exits 1 naming the module and the interpreters that have it. The pure
helpers are in report_lib.py (tested by tests/python).
"""
import argparse
import glob
import io
import json
import os
import sys
from collections import defaultdict

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))


def interpreters_with(module):
    """The other python3 interpreters of this machine (/usr/bin/python3 and every python3 on PATH)
    that can import `module`, each once: told apart by their real executable and sys.prefix, so a
    venv (a link to the system's python3 with its own prefix) is not the system's interpreter."""
    import shutil
    import subprocess
    seen, out = {(os.path.realpath(sys.executable), sys.prefix)}, []
    dirs = os.environ.get("PATH", "").split(os.pathsep)
    for candidate in ["/usr/bin/python3"] + [shutil.which("python3", path=d) for d in dirs]:
        if not candidate or not os.path.exists(candidate):
            continue
        # -E: PYTHONPATH and the like are this process's, not the candidate's own setting.
        try:
            ask = f"import sys, {module}; print(sys.executable); print(sys.prefix)"
            p = subprocess.run([candidate, "-E", "-c", ask], capture_output=True, text=True, timeout=60)
        except (OSError, subprocess.SubprocessError):
            continue
        said = p.stdout.split("\n")
        if p.returncode != 0 or len(said) < 2:
            continue
        key = (os.path.realpath(said[0]), said[1])
        if key not in seen:
            seen.add(key)
            out.append(candidate)
    return out


def require(module, why):
    """Imports `module`, or exits 1 naming it, this interpreter and the interpreters that have it:
    `python3 scripts/report.py` under a python3 without it (a pyenv or venv one) says what to run."""
    import importlib
    try:
        return importlib.import_module(module)
    except ImportError as e:
        others = interpreters_with(module)
        fix = (f"run it with {others[0]} (which has it): {others[0]} {' '.join(sys.argv)}" if others
               else f"install it for this interpreter ({sys.executable} -m pip install {module}) or Debian's "
                    f"python3-{module} and run /usr/bin/python3 {' '.join(sys.argv)}")
        print(f"report.py: this python3 ({sys.executable}, Python {sys.version.split()[0]}) cannot import "
              f"'{module}' ({why}): {e}; {fix}", file=sys.stderr)
        sys.exit(1)


# The one module beyond the standard library (numpy comes with it); Pillow is optional (png_bytes).
require("matplotlib", "the report's plots")
import report_lib as lib  # noqa: E402
import safe_output  # noqa: E402
import report_peers  # noqa: E402
import report_shipped  # noqa: E402
import report_channel  # noqa: E402
import report_summary  # noqa: E402
import report_checks  # noqa: E402
import report_history  # noqa: E402
import report_html  # noqa: E402
import publish  # noqa: E402
from report_lib import TARGETS, pareto_front  # noqa: E402

import matplotlib  # noqa: E402

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

# Seed 001's property table as printed (EECS 487 lecture notes); data to show beside the measured one.
SEED_001_TABLE = [
    ["Hermite", "yes", "yes", "C1", "yes", "n/a", "n/a"],
    ["Cardinal (Catmull-Rom)", "except endpoints", "yes", "C1", "yes", "no", "no"],
    ["Bezier", "endpoints", "no", "C1", "yes", "yes", "yes"],
    ["natural", "yes", "no", "C2", "yes", "n/a", "n/a"],
    ["B-Splines", "no", "yes", "C2", "yes", "yes", "yes"],
]


def atomic_write(path, text):
    safe_output.write_text(path, text)


# Every figure of the run as PNG bytes, by its link in the Markdown ('plots/NAME.png'): REPORT.html
# embeds those the Markdown shows and links the galleries' files (report_html.py).
PLOTS = {}


def png_bytes(fig):
    """The figure as a PNG of at most 256 colours where Pillow is there (matplotlib's own dependency):
    the plots are lines and text on white, which a palette keeps as they look, at a third of the
    bytes (the published full run's convergence plot: 816 kB in RGBA, 265 kB in a palette)."""
    buf = io.BytesIO()
    fig.savefig(buf, format="png", dpi=110, bbox_inches="tight")
    try:
        from PIL import Image
    except ImportError:
        return buf.getvalue()
    buf.seek(0)
    out = io.BytesIO()
    palette = Image.open(buf).convert("RGB").quantize(colors=256, method=Image.Quantize.MEDIANCUT)
    palette.save(out, format="png", optimize=True)
    return out.getvalue()


def atomic_savefig(fig, path):
    data = png_bytes(fig)

    def write(tmp):
        with open(tmp, "wb") as f:
            f.write(data)
    safe_output.write_with(path, write)
    PLOTS[f"plots/{os.path.basename(path)}"] = data
    plt.close(fig)


fmt, table = lib.fmt, lib.table


def natural_key(s):
    """Sort key that orders embedded numbers by value: degree:3 before degree:20."""
    import re
    return [(0, float(t), "") if re.fullmatch(r"[0-9.eE+-]+", t) and t not in ("e", "E", "+", "-", ".")
            else (1, 0.0, t) for t in re.split(r"([0-9][0-9.eE+-]*)", s) if t]


def slug(s):
    return "".join(c if c.isalnum() else "_" for c in s).strip("_")


# ---------------------------------------------------------------------------------------------
# Benchmarks


def per_op(operation):
    return f"ns per {operation}"


def speed_section(rows, vocab):
    """Per family and operation: every row's time per operation, ratio to the fastest row on the
    same data, ratio to each peer with the same settings, and its error counter."""
    lines = []
    by_family = defaultdict(list)
    for (family, operation, data), rs in lib.speed_groups(rows, vocab).items():
        by_family[(family, operation)].append((data, rs))
    pairs = defaultdict(list)
    for ours, peer in lib.peer_pairs(rows, vocab):
        pairs[ours["name"]].append(peer)
    for (family, operation), entries in sorted(by_family.items()):
        lines.append(f"\n#### {family}: {per_op(operation)}\n")
        body = []
        for data, rs in sorted(entries, key=lambda e: natural_key(lib.args_text(e[0]))):
            fastest = min(r["ns_per_op"] for r in rs)
            for r in sorted(rs, key=lambda r: r["ns_per_op"]):
                ratios = ", ".join(f"{p['algorithm']}: {fmt(r['ns_per_op'] / p['ns_per_op'])}"
                                   for p in pairs[r["name"]])
                kind, err = lib.error_of(r, vocab)
                body.append([lib.args_text(data) or "-", lib.display_algorithm(r, vocab), r["ns_per_op"],
                             r["ns_per_op"] / fastest, ratios or "-", f"{kind} {fmt(err)}" if kind else "-"])
        lines.append(table(["data", "algorithm", per_op(operation), "x fastest", "x peer (same settings)",
                            "error (counter)"], body))
    return "\n".join(lines)


def floor_section(rows, vocab):
    """Each row beside the floors timed in the same run on the same data (algorithm ids starting with
    "floor_" in the vocabulary: the simplest correct hand-written kernel for the same work) with the
    same call pattern and timing (calls:, timing:): time per operation, its ratio to each floor,
    FLOPs per operation (the flops counter, per evaluation, never per batch) and the FLOP rate."""
    floor_ids = {a for a in vocab.algorithms if a.startswith("floor_")}
    body = []

    def group_order(kv):
        return (kv[0][0], kv[0][1], natural_key(lib.args_text(kv[0][2])))
    for (family, operation, data), rs in sorted(lib.speed_groups(rows, vocab).items(), key=group_order):
        floors = [r for r in rs if r["algorithm"] in floor_ids]
        for r in sorted(rs, key=lambda r: (r["algorithm"] in floor_ids, natural_key(lib.display_algorithm(r, vocab)))):
            mine = [f for f in floors if f is not r and lib.variant_args(f, vocab) == lib.variant_args(r, vocab)]
            if not mine:
                continue
            ratios = ", ".join(f"{f['algorithm']}: {fmt(r['ns_per_op'] / f['ns_per_op'])}"
                               for f in sorted(mine, key=lambda f: f["algorithm"]))
            flops = r["counters"].get("flops")
            rate = f"{fmt(flops / r['ns_per_op'])}" if isinstance(flops, (int, float)) and flops > 0 else "-"
            body.append([family, lib.args_text(data) or "-", lib.display_algorithm(r, vocab), r["ns_per_op"],
                         ratios, flops if flops is not None else "-", rate])
    if not body:
        return "No benchmark has a floor row."
    return ("Each row against the floors timed in the same run on the same data with the same call pattern "
            "and timing (throughput: independent evaluations; latency: a dependent chain). A ratio near 1 "
            "means the kernel runs at the speed of the simplest hand-written code for the same work.\n\n"
            + table(["family", "data", "algorithm", "ns per operation", "x floor", "FLOPs per operation",
                     "GFLOP/s"], body))


def fastest_at_target(rows, vocab):
    out = []
    for t in lib.fastest_at_targets(rows, vocab):
        head = [t["family"], t["counter"], f"{t['target']:g}"]
        if t["best"] is None:
            out.append(head + ["none reached", "-", "-"])
            continue
        b, p = t["best"], t["best_peer"]
        vs = f"{lib.display_algorithm(p, vocab)} {fmt(p['ns_per_op'])} ns" if p else "no peer reached it"
        out.append(head + [f"{lib.display_algorithm(b, vocab)} {lib.args_text(lib.data_args(b, vocab))}".strip(),
                           f"{fmt(b['ns_per_op'])} ns per {b['operation']}", vs])
    return table(["family", "error measure", "target", "fastest reaching it", "time", "fastest peer reaching it"], out)


# ---------------------------------------------------------------------------------------------
# Accuracy


def cheapest_at(records, quantity, segments=None):
    """Per case: the method+setting with the fewest evaluations reaching each target error, beside
    the case's segment count (segments: {case: count})."""
    segments = segments or {}
    per_case = defaultdict(list)
    for r in records:
        if r["quantity"] == quantity and isinstance(r.get("error"), (int, float)):
            per_case[r["case"]].append(r)
    rows = []
    for case, rs in sorted(per_case.items()):
        row = [case, segments.get(case, "-")]
        for t in TARGETS:
            ok = [r for r in rs if r["error"] <= t and r.get("evaluations")]
            if ok:
                best = min(ok, key=lambda r: r["evaluations"])
                row.append(f"{best['method']} {best['setting']} ({best['evaluations']} evals)")
            else:
                row.append("none reached")
        rows.append(row)
    return table(["case", "segments"] + [f"cheapest at {t:g}" for t in TARGETS], rows)


# How many per-case error-vs-time plots are featured first (publish.py publishes the same rule's).
FEATURED_CASES = 6


def pareto_section(records, times, plot_dir, segments=None):
    """Length error (accuracy runner) joined with time (per-case benchmarks): the fastest method at
    each target per case (beside its segment count, segments: {case: count}), and one error-vs-time
    plot per case with its Pareto front."""
    segments = segments or {}
    joined, unmatched_records, unmatched_times, without_error = lib.join_lengths(records, times)
    per_case = {case: [(ns, max(e, 1e-18), f"{m} {st}", m) for ns, e, m, st in pts] for case, pts in joined.items()}
    notes = join_notes(unmatched_records, unmatched_times, without_error)
    if not per_case:
        return ["No per-case timings (bench_arclength_cases) joined with the errors.", ""] + notes
    md = ["Time per length (bench_arclength_cases, median ns per length; the curve behind the same "
          "type-erased interface for every method) joined with the accuracy runner's error for the same "
          "(case, method, setting). Fastest reaching each relative error:", ""]
    rows, links = [], []
    for case, pts in sorted(per_case.items()):
        row = [case, segments.get(case, "-")]
        for t in TARGETS:
            ok = [p for p in pts if p[1] <= t]
            if ok:
                best = min(ok)
                row.append(f"{best[2]} ({fmt(best[0])} ns)")
            else:
                row.append("none reached")
        rows.append(row)
        fig, ax = plt.subplots(figsize=(6.4, 4.2))
        by_method = defaultdict(list)
        for ns, e, _, method in pts:
            by_method[method].append((ns, e))
        for method, mp in sorted(by_method.items()):
            mp.sort()
            ax.loglog([q[0] for q in mp], [q[1] for q in mp], marker="o", ms=3, lw=0.8, label=method)
        front = pareto_front([(ns, e, label) for ns, e, label, _ in pts])
        xs, ys = [], []
        for ns, e, _ in front:  # a staircase: the best error reachable within a time budget
            if xs:
                xs.append(ns)
                ys.append(ys[-1])
            xs.append(ns)
            ys.append(e)
        ax.loglog(xs, ys, color="black", lw=1.6, alpha=0.5, label="Pareto front")
        ax.set_xlabel("ns per length")
        ax.set_ylabel("relative error of the length")
        ax.set_title(f"{case}: error vs time")
        ax.grid(True, which="both", alpha=0.3)
        ax.legend(fontsize=7)
        name = f"pareto_length_{slug(case)}.png"
        atomic_savefig(fig, os.path.join(plot_dir, name))
        links.append(f"- [{case}](plots/{name})")
    md.append(table(["case", "segments"] + [f"fastest at {t:g}" for t in TARGETS], rows))
    featured = lib.featured_cases({case: [(ns, e, m) for ns, e, _, m in pts] for case, pts in per_case.items()},
                                  FEATURED_CASES)
    md += ["", "Error-vs-time plots, Pareto front in black (errors below 1e-18 drawn at 1e-18). First the "
           f"{len(featured)} cases where the methods differ most at equal cost (per case, the largest ratio "
           "between two methods' smallest errors within one decade of time, errors below eps(double) taken as eps, "
           "in brackets; docs/results.md "
           "publishes these), then the others:", ""]
    first = {case for case, _ in featured}
    md += [f"- [{case}](plots/pareto_length_{slug(case)}.png) ({fmt(spread)})" for case, spread in featured]
    md += [link for link, case in zip(links, sorted(per_case)) if case not in first]
    return md + [""] + notes


def join_notes(unmatched_records, unmatched_times, without_error):
    """What the join left out, said in the report (and on stderr): never dropped silently."""
    md = []
    if unmatched_records:
        by = defaultdict(set)
        for case, method, setting in unmatched_records:
            by[(method, setting)].add(case)
        md += [f"{len(unmatched_records)} length records have no per-case timing (settings the timed sweep "
               "does not run, or cases it skipped):", ""]
        md.append(table(["method", "setting", "cases without a timing"],
                        [[m, st, len(cs)]
                         for (m, st), cs in sorted(by.items(), key=lambda kv: (kv[0][0], natural_key(kv[0][1])))]))
        md.append("")
    if unmatched_times:
        md += [f"{len(unmatched_times)} per-case timings have no length record:", ""]
        md.append(table(["case", "method", "setting"], [list(k) for k in unmatched_times]))
        md.append("")
    if without_error:
        md += [f"{len(without_error)} length records have no numeric error (not plotted): "
               + ", ".join(f"{c} {m} {st}" for c, m, st in without_error[:20])
               + (" ..." if len(without_error) > 20 else ""), ""]
    if unmatched_records or unmatched_times or without_error:
        print(f"report.py: join of lengths and timings: {len(unmatched_records)} records without timing, "
              f"{len(unmatched_times)} timings without record, {len(without_error)} records without error",
              file=sys.stderr)
    return md


def error_cost_plots(records, quantity, plot_dir, prefix):
    """One log-log plot of error vs evaluations per case, one series per method. Returns paths."""
    per_case = defaultdict(lambda: defaultdict(list))
    for r in records:
        if r["quantity"] != quantity or not isinstance(r.get("error"), (int, float)) or not r.get("evaluations"):
            continue
        per_case[r["case"]][r["method"]].append((r["evaluations"], max(r["error"], 1e-40)))
    paths = []
    for case, methods in sorted(per_case.items()):
        fig, ax = plt.subplots(figsize=(6.4, 4.2))
        for method, pts in sorted(methods.items()):
            pts.sort()
            ax.loglog([p[0] for p in pts], [p[1] for p in pts], marker="o", ms=3, label=method)
        ax.set_xlabel("curve-derivative evaluations")
        ax.set_ylabel(f"relative error ({quantity})")
        ax.set_title(f"{case}: {quantity} error vs cost")
        ax.grid(True, which="both", alpha=0.3)
        ax.legend(fontsize=7)
        name = f"{prefix}_{slug(case)}.png"
        atomic_savefig(fig, os.path.join(plot_dir, name))
        paths.append((case, f"plots/{name}"))
    return paths


def series_without_order(records, orders, vocab):
    """{(quantity, method): [cases]} of the series of a method with a theory order (vocabulary) that
    have records but no observed order: too few points before the rounding plateau."""
    theory = {m for m, d in vocab.methods.items() if (d.get("theory") or 0) > 0}
    have = {(o["case"], o["quantity"], o["method"]) for o in orders}
    out = defaultdict(set)
    for r in records:
        if r.get("method") in theory and (r["case"], r["quantity"], r["method"]) not in have:
            out[(r["quantity"], r["method"])].add(r["case"])
    return {k: sorted(v) for k, v in sorted(out.items())}


# At most this many cases are drawn in colour and named in each panel of the convergence plot.
LABELLED_PER_PANEL = 10


def convergence_panels(orders, records):
    """{(quantity, method): {case: {"points": [(evaluations, error)] sorted, "order": the order}}} of
    every (case, quantity, method) with an observed order, and, per panel, the cases named in colour:
    the LABELLED_PER_PANEL cases of extreme observed order (half the lowest, half the highest),
    the rest drawn grey. Returns (panels, labelled)."""
    order_of = {(o["case"], o["quantity"], o["method"]): o.get("observed") for o in orders}
    panels = defaultdict(dict)
    for r in records:
        k = (r["case"], r["quantity"], r["method"])
        if k in order_of and isinstance(r.get("error"), (int, float)) and r.get("evaluations") and r["error"] > 0:
            series = panels[(k[1], k[2])].setdefault(k[0], {"points": [], "order": order_of[k]})
            series["points"].append((r["evaluations"], r["error"]))
    labelled = {}
    for key, by_case in panels.items():
        for series in by_case.values():
            series["points"].sort()
        ranked = sorted(by_case, key=lambda c: (by_case[c]["order"] if isinstance(by_case[c]["order"], (int, float))
                                                else 0.0, c))
        if len(ranked) <= LABELLED_PER_PANEL:
            labelled[key] = ranked
        else:
            low = LABELLED_PER_PANEL // 2
            labelled[key] = ranked[:low] + ranked[len(ranked) - (LABELLED_PER_PANEL - low):]
    return dict(panels), labelled


def convergence_plot(orders, records, plot_dir):
    """Small multiples of error vs cost: one log-log panel per quantity and method with an observed
    order, one line per case; at most LABELLED_PER_PANEL cases named in colour per panel (those of
    the lowest and highest observed orders), the others grey. Returns (path, panels) or (None, {})."""
    panels, labelled = convergence_panels(orders, records)
    if not panels:
        return None, {}
    keys = sorted(panels)
    cols = min(3, len(keys))
    rows = (len(keys) + cols - 1) // cols
    fig, axes = plt.subplots(rows, cols, figsize=(5.2 * cols, 3.9 * rows), squeeze=False)
    for ax, key in zip(axes.flat, keys):
        by_case = panels[key]
        named = labelled[key]
        grey = [c for c in sorted(by_case) if c not in named]
        for case in grey:
            pts = by_case[case]["points"]
            ax.loglog([p[0] for p in pts], [p[1] for p in pts], color="0.75", lw=0.6, marker=".", ms=2)
        for case in named:
            pts, order = by_case[case]["points"], by_case[case]["order"]
            ax.loglog([p[0] for p in pts], [p[1] for p in pts], lw=0.9, marker=".", ms=3,
                      label=f"{case} ({fmt(order)})")
        if grey:
            ax.plot([], [], color="0.75", lw=0.6, label=f"{len(grey)} other cases")
        ax.set_title(f"{key[0]}: {key[1]}", fontsize=9)
        ax.set_xlabel("curve-derivative evaluations", fontsize=8)
        ax.set_ylabel(f"relative error ({key[0]})", fontsize=8)
        ax.tick_params(labelsize=7)
        ax.grid(True, which="both", alpha=0.3)
        ax.legend(fontsize=5.5, loc="lower left")
    for ax in list(axes.flat)[len(keys):]:
        ax.set_visible(False)
    fig.tight_layout()
    atomic_savefig(fig, os.path.join(plot_dir, "convergence.png"))
    return "plots/convergence.png", panels


def honesty_section(records):
    stats = defaultdict(lambda: [0, 0])
    for r in records:
        if isinstance(r.get("bounded"), bool):
            s = stats[(r["quantity"], r["method"])]
            s[0] += 1
            s[1] += 1 if r["bounded"] else 0
    rows = [[q, m, n, b, f"{100.0 * b / n:.1f}%"] for (q, m), (n, b) in sorted(stats.items())]
    return table(["quantity", "method", "results with estimate", "estimate >= true error", "honest"], rows)


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--reports", default=os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "reports"))
    ap.add_argument("--vocabulary", help="the vocabulary JSON (default: REPORTS/vocabulary.json)")
    ap.add_argument("--history", default=os.path.join(os.path.dirname(os.path.abspath(__file__)), "..",
                                                      report_history.HISTORY),
                    help="the published runs' history (default: the checkout's docs/results/history.jsonl)")
    ap.add_argument("--checks", nargs="+", metavar="FILE", default=[],
                    help="your own `curvebench check ... --json` result files: the report's section \"Your checks\" "
                         "lists each check in its own unit with its gate and verdict, the summary counts them (passed, "
                         "over their gate), and their records join \"Your implementations\"; with only these (no "
                         "accuracy.json, benchmarks or vocabulary.json in REPORTS) the report is of them alone")
    args = ap.parse_args()
    report_dir = os.path.abspath(args.reports)
    plot_dir = os.path.join(report_dir, "plots")
    os.makedirs(plot_dir, exist_ok=True)

    vocab_path = args.vocabulary or os.path.join(report_dir, "vocabulary.json")
    bench_files = sorted(glob.glob(os.path.join(report_dir, "bench_*.json")))
    try:
        checks = report_checks.load(args.checks)
        if args.checks and not args.vocabulary and not bench_files and not os.path.exists(vocab_path):
            # A report of the user's checks alone: no benchmark to describe, no vocabulary needed.
            vocab = lib.Vocabulary({"quantities": [], "methods": [], "peers": [], "operations": [], "counters": []})
        else:
            vocab = lib.load_vocabulary(vocab_path)
        bench_context, bench_rows = lib.load_benchmark_files(bench_files, vocab)
        times = lib.case_times(bench_rows)
        history = report_history.load(args.history)
    except (OSError, lib.ReportError, report_checks.ChecksError) as e:
        print(f"report.py: {e}", file=sys.stderr)
        return 1
    acc_path = os.path.join(report_dir, "accuracy.json")
    acc = {}
    if os.path.exists(acc_path):
        with open(acc_path, encoding="utf-8") as f:
            acc = json.load(f)
    records, orders = acc.get("records", []), acc.get("orders", [])
    # A user's own implementations (subject records) get their own section, beside ours.
    records, subjects = lib.split_subjects(records)
    subjects += report_checks.records(checks)
    ctx = acc.get("context", {})
    segments = lib.segment_counts(acc)

    head = ["# curvebench report", "",
            "Generated by `scripts/bench.sh` (scripts/report.py); do not edit by hand.", ""]
    # The summary and the contents go between the head and the sections, built last from the same
    # inputs (every benchmark row: the per-case length times, the channel benchmarks' times).
    all_rows = bench_rows
    # This run's history line, from the same headline data --publish would append (all benchmark rows).
    current = report_history.entry(publish.headline(acc, bench_context, bench_rows, vocab, {})) if acc else None
    md = ["## Machine and build", ""]
    md.append(table(["item", "value"], [
        ["revision", ctx.get("revision", bench_context.get("git_revision", "-"))],
        ["date", bench_context.get("date", ctx.get("date", "-"))],
        ["host", bench_context.get("host_name", "-")],
        ["CPUs", f"{bench_context.get('num_cpus', '-')} x {bench_context.get('mhz_per_cpu', '-')} MHz"],
        ["compiler", ctx.get("compiler", "-")],
        ["flags", bench_context.get("flags", ctx.get("flags", "-"))],
        ["suite", f"{acc.get('suite', {}).get('name', '-')} v{acc.get('suite', {}).get('version', '-')}, "
                  f"{acc.get('suite', {}).get('cases', '-')} cases" + (" (quick)" if ctx.get("quick") else "")],
    ]))
    md += ["", "Absolute times on a shared machine are noisy; compare the ratios, measured in the same run.", ""]

    # The sections in the order of the summary's answers that are not the method table's (whose
    # figures are the long sections below): the user's own results, what shipped software and the
    # peers get wrong, the tool models' fidelity.
    md += report_checks.section(checks)
    if subjects:
        md += ["", "## Your implementations (subjects) beside curvebench's methods", ""]
        md.append("Records of a user's own implementation (`curvebench check`, or the subject API "
                  "harness/subject.hpp) against the same 50-digit reference, beside curvebench's own records of "
                  "the same case and quantity (eval in eps x size, the others relative to L):")
        md.append("")
        md.append(table(["case", "quantity", "subject", "error", "curvebench's most accurate", "its error",
                         "curvebench's cheapest at least as accurate"],
                        lib.subject_rows(records, subjects)))
    md += report_shipped.section(acc, report_dir, plot_dir, plt, atomic_savefig)
    md += report_peers.peers_section(acc, report_dir, [r for r in bench_rows if r["family"] != lib.CASE_FAMILY],
                                     vocab)
    fidelity_path = os.path.join(report_dir, "fidelity.json")
    fidelity = None
    if os.path.exists(fidelity_path):
        with open(fidelity_path, encoding="utf-8") as f:
            fidelity = json.load(f)
    md += report_channel.fidelity_section(fidelity, list(vocab.tools.values()))

    md += ["", "## Speed per operation", ""]
    bench_rows = [r for r in bench_rows if r["family"] != lib.CASE_FAMILY]
    if bench_rows:
        ops = sorted({r["operation"] for r in bench_rows})
        md += ["Every time is CPU time per operation (the benchmark's label), whatever it does per "
               "iteration: a batch of 1024 evaluations is divided by 1024, so single calls, batches and "
               "sorted batches compare directly. Rows are ranked only against rows timing the same "
               "operation on the same data. Operations:", ""]
        md += [f"- **{o}**: {vocab.operations[o]['doc']}" for o in ops] + [""]
        headlines = lib.headline_ratios(bench_rows, vocab)
        if headlines:
            md += ["Headline ratios (our fastest with the peer's settings on the same data / the peer, per "
                   "operation; < 1 means faster than the peer):", ""]
            md.append(table(["family", "data", "ours", "peer", "ns per op (ours)", "ratio"],
                            [[o["family"], lib.args_text(lib.data_args(o, vocab)) or "-",
                              lib.display_algorithm(o, vocab), lib.display_algorithm(p, vocab), o["ns_per_op"], ratio]
                             for o, p, ratio in headlines]))
            md.append("")
        md += ["", "### Fastest at an error target (benchmarks with a relative error counter)", "",
               "One benchmark curve per family, timed: a measurement, not a recommendation (the Summary's table "
               "answers per kind and size of curve).", ""]
        md.append(fastest_at_target(bench_rows, vocab))
        md += ["", "### Against the floor (hand-written kernels for the same work)", ""]
        md.append(floor_section(bench_rows, vocab))
        md += ["", "### All benchmarks", ""]
        md.append(speed_section(bench_rows, vocab))
    else:
        md.append("No benchmark results found.")

    for quantity, title in (("length", "Arc length: error vs cost"), ("s_of_u", "s(u): error vs cost"),
                            ("u_of_s", "Inversion u(s): error vs cost")):
        md += ["", f"## {title}", ""]
        if quantity == "length":
            md += ["### Error vs time (Pareto)", ""] + pareto_section(records, times, plot_dir, segments)
            md += ["", "### Error vs evaluations", ""]
        if any(r["quantity"] == quantity for r in records):
            md.append(cheapest_at(records, quantity, segments))
            md.append("")
            for case, path in error_cost_plots(records, quantity, plot_dir, quantity):
                md.append(f"- [{case}]({path})")
        else:
            md.append("No results.")
        if quantity == "u_of_s":
            md += [""] + report_summary.with_many_segments_answer(lib.table_per_segments(all_rows, segments),
                                                                  report_summary.run_recommendations(acc, all_rows))

    md += ["", "## Evaluation-algorithm accuracy", ""]
    ev = [r for r in records if r["quantity"] == "eval"]
    if ev:
        family = {c["name"]: c.get("family", "-") for c in acc.get("cases", [])}
        md.append(table(["case", "segments", "family", "algorithm", "max error (eps x size)"],
                        [[r["case"], segments.get(r["case"], "-"), family.get(r["case"], "-"), r["method"],
                          r["error"]] for r in ev]))
    else:
        md.append("No results.")

    md += report_channel.channel_section(acc, bench_rows, plot_dir, plt, atomic_savefig,
                                         report_channel.tool_names(vocab))

    md += ["", "## Convergence orders", ""]
    if orders:
        excluded = sum(o.get("excluded", 0) or 0 for o in orders)
        md.append("The observed order is the least-squares slope of log error against log evaluations over the "
                  "points where the error still falls: by increasing cost, the first point whose error is not at "
                  "least 10 % below the best so far (or is below 1e-12) starts the rounding plateau, and it and "
                  "every costlier point are excluded; points above 1e-2 are pre-asymptotic and skipped. An order "
                  "needs 3 points spanning a factor 4 in cost, else the case has none. "
                  f"{excluded} points were excluded over the {len(orders)} orders of this run "
                  "(column \"excluded\"; \"points\" were fitted).")
        md.append("")
        md.append(table(["case", "segments", "quantity", "method", "observed", "theory", "points", "excluded"],
                        [[o["case"], segments.get(o["case"], "-"), o["quantity"], o["method"], o["observed"],
                          o.get("theory"), o.get("points", "-"), o.get("excluded", "-")] for o in orders]))
        missing = series_without_order(records, orders, vocab)
        if missing:
            md += ["", "No observed order (fewer than 3 points spanning a factor 4 in cost between 1e-2 and the "
                   "rounding plateau): " + "; ".join(
                       f"{q} {m} on {len(cs)} case{'s' if len(cs) > 1 else ''} ({', '.join(cs[:5])}"
                       + (", ..." if len(cs) > 5 else "") + ")" for (q, m), cs in missing.items()) + "."]
        path, panels = convergence_plot(orders, records, plot_dir)
        if path:
            md += ["", f"One panel per quantity and method ({len(panels)} panels), one line per case; in each panel "
                   f"at most {LABELLED_PER_PANEL} cases are named in colour, those of the lowest and the highest "
                   "observed orders (in brackets), and the others are grey.", "", f"![convergence]({path})"]
    else:
        md.append("No results.")

    md += ["", "## Curve properties (measured) beside seed 001's table", ""]
    rows = [c["properties"] for c in acc.get("cases", []) if c.get("properties")]
    if rows:
        md.append("Seed 001's table, as printed in the lecture notes (transcribed data, not a result):")
        md.append("")
        md.append(table(["Cubic", "Interpolate?", "Local?", "Continuity", "Affine?", "Convex hull?", "VD?"],
                        SEED_001_TABLE))
        md += ["", "Measured by `curvebench::analysis::audit_properties` on each 2D case of the suite "
               "(the family rebuilt from perturbed control data; see docs/properties.md for how each column is "
               "measured and why the answers differ from the seed's):", ""]
        md.append("| Case (family) | Interpolates | Local control | Continuity | Affine invariant | Convex hull | "
                  "Variation diminishing |")
        md.append("|---|---|---|---|---|---|---|")
        md += [r.rstrip("\n") for r in rows]
    else:
        md.append("No results.")

    md += ["", "## References", ""]
    cases = acc.get("cases", [])
    if cases:
        md.append("The 50-digit reference of each case (the same spec at 50 digits, integrated by Boost.Math "
                  "split at breakpoints and speed minima) and its own error estimate, relative:")
        md.append("")
        md.append(table(["case", "group", "family", "segments", "length", "reference error", "speed minima", "seconds"],
                        [[c["name"], c["group"], c["family"], c["segments"], str(c.get("reference_length", "-"))[:22],
                          c.get("reference_error", "-"), c.get("speed_minima", "-"), c.get("seconds", "-")]
                         for c in cases]))
    else:
        md.append("No results.")

    md += ["", "## Error-estimate honesty", ""]
    md.append(honesty_section(records) if records else "No results.")
    md += report_history.section(history, current, plot_dir, plt, atomic_savefig)
    md.append("")
    summary = report_summary.summary_of_run(acc, report_dir, all_rows, vocab, fidelity, checks)
    md = report_summary.link_details(head + summary + report_summary.toc(summary, md) + md)
    atomic_write(os.path.join(report_dir, "REPORT.md"), "\n".join(md) + "\n")
    atomic_write(os.path.join(report_dir, "REPORT.html"), report_html.render(md, PLOTS))
    print(f"report.py: wrote {os.path.join(report_dir, 'REPORT.md')} and REPORT.html")
    return 0


if __name__ == "__main__":
    try:
        sys.exit(main())
    except safe_output.OutputError as e:  # REPORT.md or a plot over a FIFO, a link, a device
        print(f"report.py: {e}", file=sys.stderr)
        sys.exit(1)
