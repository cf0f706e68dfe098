#!/usr/bin/python3
"""Generates reports/REPORT.md and reports/plots/*.png from the results of scripts/bench.sh.

Inputs (all in the reports directory, all produced by scripts):
  bench_*.json     Google Benchmark output (names family/algorithm/arg:value; algorithms whose
                   name starts with "peer_" are peers from other libraries)
  accuracy.json    the accuracy runner's output: context, records, orders, properties
Every file is written under a temporary name and renamed, so an interrupted run never leaves a
half-written report. Uses Debian's python3-matplotlib (run with /usr/bin/python3).
"""
import argparse
import glob
import json
import math
import os
import sys
from collections import defaultdict

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

TARGETS = (1e-6, 1e-10, 1e-14)
PEER_PREFIXES = ("peer_", "boost_", "eigen_")
# Seed 001's property table as printed (EECS 487 lecture notes); data to show beside the measured one.
SEED_001_TABLE = [
    ["Hermite", "yes", "yes", "C1", "yes", "n/a", "n/a"],
    ["Cardinal (Catmull-Rom)", "except endpoints", "yes", "C1", "yes", "no", "no"],
    ["Bezier", "endpoints", "no", "C1", "yes", "yes", "yes"],
    ["natural", "yes", "no", "C2", "yes", "n/a", "n/a"],
    ["B-Splines", "no", "yes", "C2", "yes", "yes", "yes"],
]
ERROR_COUNTERS = ("rel_error", "max_ds_rel", "max_err_eps")


def is_peer(algorithm):
    return algorithm.startswith(PEER_PREFIXES)


def peer_name(algorithm):
    return algorithm[5:] if algorithm.startswith("peer_") else algorithm


def computes(algorithm):
    """What a benchmark computes, for pairing with peers: an inversion u(s), or anything else."""
    return "u_of_s" if algorithm.startswith("u_of_s") else "other"


def error_of(row):
    for k in ERROR_COUNTERS:
        if k in row["counters"]:
            return k, row["counters"][k]
    return None, None


def atomic_write(path, text):
    tmp = path + ".tmp"
    with open(tmp, "w", encoding="utf-8") as f:
        f.write(text)
    os.replace(tmp, path)


def atomic_savefig(fig, path):
    tmp = path + ".tmp.png"
    fig.savefig(tmp, dpi=110, bbox_inches="tight")
    plt.close(fig)
    os.replace(tmp, path)


def fmt(x, digits=3):
    if x is None:
        return "-"
    if isinstance(x, bool):
        return "yes" if x else "no"
    if isinstance(x, (int,)) and not isinstance(x, bool):
        return str(x)
    if isinstance(x, float):
        if x != x:
            return "nan"
        if x == 0:
            return "0"
        if abs(x) >= 1e4 or abs(x) < 1e-3:
            return f"{x:.{digits - 1}e}"
        return f"{x:.{digits}g}"
    return str(x)


def table(headers, rows):
    out = ["| " + " | ".join(headers) + " |", "|" + "|".join("---" for _ in headers) + "|"]
    for r in rows:
        out.append("| " + " | ".join(fmt(c) for c in r) + " |")
    return "\n".join(out)


def natural_key(s):
    """Sort key that orders embedded numbers by value: degree:3 before degree:20."""
    import re
    return [(0, float(t), "") if re.fullmatch(r"[0-9.eE+-]+", t) and t not in ("e", "E", "+", "-", ".")
            else (1, 0.0, t) for t in re.split(r"([0-9][0-9.eE+-]*)", s) if t]


def slug(s):
    return "".join(c if c.isalnum() else "_" for c in s).strip("_")


# ---------------------------------------------------------------------------------------------
# Benchmarks


def load_benchmarks(report_dir):
    """(context, rows): rows are dicts with family, algorithm, args, ns (median cpu time per iteration)."""
    context, rows = {}, []
    for path in sorted(glob.glob(os.path.join(report_dir, "bench_*.json"))):
        with open(path, encoding="utf-8") as f:
            data = json.load(f)
        context = context or data.get("context", {})
        for b in data.get("benchmarks", []):
            if b.get("run_type") == "aggregate" and b.get("aggregate_name") != "median":
                continue
            name = b.get("run_name", b["name"])
            parts = name.split("/")
            if len(parts) < 2:
                continue
            unit = {"ns": 1.0, "us": 1e3, "ms": 1e6, "s": 1e9}[b.get("time_unit", "ns")]
            counters = {k: v for k, v in b.items() if k not in ("name", "run_name", "run_type", "repetitions",
                                                                 "repetition_index", "threads", "iterations",
                                                                 "real_time", "cpu_time", "time_unit",
                                                                 "aggregate_name", "aggregate_unit",
                                                                 "family_index", "per_family_instance_index")}
            rows.append({"program": os.path.basename(path)[:-5], "family": parts[0], "algorithm": parts[1],
                         "args": "/".join(parts[2:]), "ns": b["cpu_time"] * unit, "counters": counters})
    return context, rows


def speed_section(rows):
    """Per family and argument set: time per call, ratio to the fastest, ratio to each peer."""
    lines = []
    groups = defaultdict(list)
    for r in rows:
        groups[(r["family"], r["args"])].append(r)
    by_family = defaultdict(list)
    for (family, args), rs in sorted(groups.items(), key=lambda kv: (kv[0][0], natural_key(kv[0][1]))):
        by_family[family].append((args, rs))
    headlines = []
    for family, entries in by_family.items():
        lines.append(f"\n#### {family}\n")
        body = []
        for args, rs in entries:
            fastest = min(r["ns"] for r in rs)
            peers = [r for r in rs if is_peer(r["algorithm"])]
            for r in sorted(rs, key=lambda r: r["ns"]):
                peer_ratios = ", ".join(f"{peer_name(p['algorithm'])}: {r['ns'] / p['ns']:.2f}" for p in peers if p is not r)
                kind, err = error_of(r)
                body.append([args or "-", r["algorithm"], r["ns"], r["ns"] / fastest, peer_ratios or "-",
                             f"{kind} {fmt(err)}" if kind else "-"])
            for p in peers:
                # Peers compute lengths or evaluate curves; a u(s) inversion beside them is not a peer's rival.
                ours = [r for r in rs if not is_peer(r["algorithm"]) and computes(r["algorithm"]) == computes(p["algorithm"])]
                if ours:
                    best = min(ours, key=lambda r: r["ns"])
                    headlines.append((family, args, best["algorithm"], peer_name(p["algorithm"]), best["ns"] / p["ns"]))
        lines.append(table(["args", "algorithm", "ns per call", "x fastest", "x each peer", "error (counter)"], body))
    return "\n".join(lines), headlines


def fastest_at_target(rows):
    """Per family with error counters: the fastest benchmark (ours or a peer) reaching each target."""
    fams = defaultdict(list)
    for r in rows:
        kind, err = error_of(r)
        if kind in ("rel_error", "max_ds_rel") and isinstance(err, (int, float)):
            fams[(r["family"], kind)].append((r, err))
    out = []
    for (family, kind), rs in sorted(fams.items()):
        for t in TARGETS:
            ok = [(r, e) for r, e in rs if e <= t]
            if not ok:
                out.append([family, kind, f"{t:g}", "none reached", "-", "-"])
                continue
            r, e = min(ok, key=lambda x: x[0]["ns"])
            peers = [(p, pe) for p, pe in ok if is_peer(p["algorithm"])]
            best_peer = min(peers, key=lambda x: x[0]["ns"]) if peers else None
            vs = (f"{peer_name(best_peer[0]['algorithm'])}/{best_peer[0]['args']} {fmt(best_peer[0]['ns'])} ns"
                  if best_peer else "no peer reached it")
            out.append([family, kind, f"{t:g}", f"{r['algorithm']}/{r['args']}", r["ns"], vs])
    return table(["family", "error measure", "target", "fastest reaching it", "ns", "fastest peer reaching it"], out)


# ---------------------------------------------------------------------------------------------
# Accuracy


def cheapest_at(records, quantity):
    """Per case: the method+setting with the fewest evaluations reaching each target error."""
    per_case = defaultdict(list)
    for r in records:
        if r["quantity"] == quantity and isinstance(r.get("error"), (int, float)):
            per_case[r["case"]].append(r)
    rows = []
    for case, rs in sorted(per_case.items()):
        row = [case]
        for t in TARGETS:
            ok = [r for r in rs if r["error"] <= t and r.get("evaluations")]
            if ok:
                best = min(ok, key=lambda r: r["evaluations"])
                row.append(f"{best['method']} {best['setting']} ({best['evaluations']} evals)")
            else:
                row.append("none reached")
        rows.append(row)
    return table(["case"] + [f"cheapest at {t:g}" for t in TARGETS], rows)


def case_times(rows):
    """(case, method, setting) -> ns per call, from bench_arclength_cases (arclength_case/case/method/setting)."""
    out = {}
    for r in rows:
        if r["program"] == "bench_arclength_cases":
            method, _, setting = r["args"].partition("/")
            out[(r["algorithm"], method, setting)] = r["ns"]
    return out


def pareto_front(points):
    """The (time, error) points no other point beats in both: sorted by time, error strictly falling."""
    front, best = [], float("inf")
    for t, e, label in sorted(points):
        if e < best:
            front.append((t, e, label))
            best = e
    return front


def pareto_section(records, times, plot_dir):
    """Length error (accuracy runner) joined with time (per-case benchmarks): the fastest method at
    each target per case, and one error-vs-time plot per case with its Pareto front."""
    per_case = defaultdict(list)
    for r in records:
        if r["quantity"] != "length" or not isinstance(r.get("error"), (int, float)):
            continue
        ns = times.get((r["case"], r["method"], r["setting"]))
        if ns is not None:
            per_case[r["case"]].append((ns, max(r["error"], 1e-18), f"{r['method']} {r['setting']}", r["method"]))
    if not per_case:
        return ["No per-case timings (bench_arclength_cases) to join with the errors."]
    md = ["Time per length computation (bench_arclength_cases, median ns; the curve behind the same "
          "type-erased interface for every method) joined with the accuracy runner's error for the same "
          "(case, method, setting). Fastest reaching each relative error:", ""]
    rows, links = [], []
    for case, pts in sorted(per_case.items()):
        row = [case]
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
        ax.set_xlabel("time per length computation (ns)")
        ax.set_ylabel("relative error of the length")
        ax.set_title(f"{case}: error vs time")
        ax.grid(True, which="both", alpha=0.3)
        ax.legend(fontsize=7)
        name = f"pareto_length_{slug(case)}.png"
        atomic_savefig(fig, os.path.join(plot_dir, name))
        links.append(f"- [{case}](plots/{name})")
    md.append(table(["case"] + [f"fastest at {t:g}" for t in TARGETS], rows))
    md += ["", "Error-vs-time plots, Pareto front in black (errors below 1e-18 drawn at 1e-18):", ""]
    md += links
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


def convergence_plot(orders, records, plot_dir):
    """Log-log error vs cost for every (case, method) that has an observed order."""
    if not orders:
        return None
    fig, ax = plt.subplots(figsize=(7, 4.6))
    keys = {(o["case"], o["quantity"], o["method"]) for o in orders}
    series = defaultdict(list)
    for r in records:
        k = (r["case"], r["quantity"], r["method"])
        if k in keys and isinstance(r.get("error"), (int, float)) and r.get("evaluations") and r["error"] > 0:
            series[k].append((r["evaluations"], r["error"]))
    for k, pts in sorted(series.items()):
        pts.sort()
        ax.loglog([p[0] for p in pts], [p[1] for p in pts], marker=".", lw=0.8, label=f"{k[0]} {k[2]}")
    ax.set_xlabel("evaluations")
    ax.set_ylabel("relative error")
    ax.set_title("convergence")
    ax.grid(True, which="both", alpha=0.3)
    if len(series) <= 16:
        ax.legend(fontsize=6)
    atomic_savefig(fig, os.path.join(plot_dir, "convergence.png"))
    return "plots/convergence.png"


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
    args = ap.parse_args()
    report_dir = os.path.abspath(args.reports)
    plot_dir = os.path.join(report_dir, "plots")
    os.makedirs(plot_dir, exist_ok=True)

    bench_context, bench_rows = load_benchmarks(report_dir)
    acc_path = os.path.join(report_dir, "accuracy.json")
    acc = {}
    if os.path.exists(acc_path):
        with open(acc_path, encoding="utf-8") as f:
            acc = json.load(f)
    records, orders = acc.get("records", []), acc.get("orders", [])
    ctx = acc.get("context", {})

    md = ["# curvebench report", "",
          "Generated by `scripts/bench.sh` (scripts/report.py); do not edit by hand.", ""]
    md += ["## Machine and build", ""]
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

    md += ["## Evaluation speed", ""]
    times = case_times(bench_rows)
    bench_rows = [r for r in bench_rows if r["program"] != "bench_arclength_cases"]
    if bench_rows:
        text, headlines = speed_section(bench_rows)
        if headlines:
            md += ["Headline ratios (our fastest algorithm / peer; < 1 means faster than the peer):", ""]
            md.append(table(["family", "args", "ours", "peer", "ratio"], headlines))
            md.append("")
        md += ["", "### Fastest at an error target (benchmarks with an error counter)", ""]
        md.append(fastest_at_target(bench_rows))
        md += ["", "### All benchmarks", ""]
        md.append(text)
    else:
        md.append("No benchmark results found.")

    for quantity, title in (("length", "Arc length: error vs cost"), ("s_of_u", "s(u): error vs cost"),
                            ("u_of_s", "Inversion u(s): error vs cost")):
        md += ["", f"## {title}", ""]
        if quantity == "length":
            md += ["### Error vs time (Pareto)", ""] + pareto_section(records, times, plot_dir)
            md += ["", "### Error vs evaluations", ""]
        if any(r["quantity"] == quantity for r in records):
            md.append(cheapest_at(records, quantity))
            md.append("")
            for case, path in error_cost_plots(records, quantity, plot_dir, quantity):
                md.append(f"- [{case}]({path})")
        else:
            md.append("No results.")

    md += ["", "## Evaluation-algorithm accuracy", ""]
    ev = [r for r in records if r["quantity"] == "eval"]
    if ev:
        md.append(table(["case", "algorithm", "setting", "max error (x scale)"],
                        [[r["case"], r["method"], r["setting"], r["error"]] for r in ev]))
    else:
        md.append("No results.")

    md += ["", "## Convergence orders", ""]
    if orders:
        md.append(table(["case", "quantity", "method", "observed", "theory"],
                        [[o["case"], o["quantity"], o["method"], o["observed"], o.get("theory")] for o in orders]))
        path = convergence_plot(orders, records, plot_dir)
        if path:
            md += ["", f"![convergence]({path})"]
    else:
        md.append("No results.")

    md += ["", "## Curve properties (measured) beside seed 001's table", ""]
    rows = [c["properties"] for c in acc.get("cases", []) if c.get("properties")]
    if rows:
        md.append("Seed 001's table, as printed in the lecture notes (transcribed data, not a result):")
        md.append("")
        md.append(table(["Cubic", "Interpolate?", "Local?", "Continuity", "Affine?", "Convex hull?", "VD?"],
                        SEED_001_TABLE))
        md += ["", "Measured by `curvebench::audit_properties` on each 2D case of the suite (the family rebuilt "
               "from perturbed control data; see docs/properties.md for how each column is measured and why "
               "the answers differ from the seed's):", ""]
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
                        [[c["name"], c["group"], c["family"], c["segments"], c["reference_length"][:22],
                          c["reference_error"], c["speed_minima"], c["seconds"]] for c in cases]))
    else:
        md.append("No results.")

    md += ["", "## Error-estimate honesty", ""]
    md.append(honesty_section(records) if records else "No results.")
    md.append("")
    atomic_write(os.path.join(report_dir, "REPORT.md"), "\n".join(md) + "\n")
    print(f"report.py: wrote {os.path.join(report_dir, 'REPORT.md')}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
