#!/usr/bin/python3
"""Publishes a full scripts/bench.sh run: docs/results.md, docs/results/ (headline.json and at
most a dozen plots) and the README's generated figures, between its `results:begin`/`results:end`
markers. Run by `scripts/bench.sh --publish` after a full run; by hand:
  /usr/bin/python3 scripts/publish.py --reports reports --docs docs --readme README.md
Refuses a quick run (its figures are not the ones to publish) unless --allow-quick, and a run in
which an optional peer of scripts/peers.sh did not run unless --allow-missing-peers (the page then
names the missing ones). docs/results.md carries REPORT.md's Summary and Peers sections of the
run (peers' accuracy, grouped findings, versions), rendered by the same code.

Nothing here is typed by hand: every figure comes from the run's files (accuracy.json,
bench_*.json, vocabulary.json, run.json) through headline(), which is pure; docs/results/
headline.json keeps that data, and the README block is rendered from it alone (render_readme), so
tests/python can check that the README says what headline.json says.
Each publish also appends the run's headline figures to docs/results/history.jsonl
(report_history.py; one line per revision), which the report plots over revisions.
Budget: the plots copied under docs/results/ stay under MAX_PLOT_BYTES together (the history stays
small); publishing fails otherwise.
"""
import argparse
import glob
import json
import math
import os
import shutil
import statistics
import sys
from collections import defaultdict

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import report_channel as rc  # noqa: E402
import report_history  # noqa: E402
import report_lib as lib  # noqa: E402
import report_peers  # noqa: E402
import report_shipped  # noqa: E402
import report_summary  # noqa: E402
import safe_output  # noqa: E402

MAX_PLOTS = 12
MAX_PLOT_BYTES = 2_000_000
BEGIN, END = "<!-- results:begin -->", "<!-- results:end -->"
# The fidelity of the tool models (`curvebench fidelity --json`, reports/fidelity.json) depends on the
# recordings and the models only, not on the timing run: its block of docs/results.md can be
# refreshed alone (--fidelity) and names the curvebench revision it measured.
FIDELITY_BEGIN, FIDELITY_END = "<!-- fidelity:begin -->", "<!-- fidelity:end -->"
# The cases whose error-vs-time plots are published are those where the methods differ most at
# equal cost (report_lib.method_spread over the joined lengths and times: the largest ratio of the
# methods' errors within one decade of time); the rest of the dozen is filled by name order.


class PublishError(Exception):
    pass


fmt, table = lib.fmt, lib.table


# ---------------------------------------------------------------------------------------------
# The data: pure functions of the run's files


def eval_spread(records, cases):
    """Per case with more than one evaluation algorithm: each algorithm's max error (eps x size),
    worst first by the ratio of the worst algorithm to the best."""
    family = {c["name"]: c.get("family", "-") for c in cases}
    per_case = defaultdict(dict)
    for r in records:
        if r["quantity"] == "eval" and r["method"] != "default" and isinstance(r.get("error"), (int, float)):
            per_case[r["case"]][r["method"]] = r["error"]
    out = []
    for case, algs in per_case.items():
        if len(algs) < 2:
            continue
        lo, hi = min(algs.values()), max(algs.values())
        out.append({"case": case, "family": family.get(case, "-"), "errors": dict(sorted(algs.items())),
                    "spread": hi / lo if lo > 0 else math.inf})
    out.sort(key=lambda e: (-e["spread"], e["case"]))
    return out


def peer_ratios(bench_rows, vocab):
    return [{"family": o["family"], "data": lib.args_text(lib.data_args(o, vocab)),
             "ours": lib.display_algorithm(o, vocab), "ours_ns": o["ns_per_op"],
             "peer": lib.display_algorithm(p, vocab), "peer_ns": p["ns_per_op"], "ratio": ratio,
             "operation": o["operation"]}
            for o, p, ratio in lib.headline_ratios(bench_rows, vocab)]


def targets(bench_rows, vocab):
    out = []
    for t in lib.fastest_at_targets(bench_rows, vocab):
        b, p = t["best"], t["best_peer"]
        out.append({"family": t["family"], "operation": t["operation"], "counter": t["counter"],
                    "target": t["target"],
                    "best": (None if b is None else
                             f"{lib.display_algorithm(b, vocab)} {lib.args_text(lib.data_args(b, vocab))}".strip()),
                    "best_ns": None if b is None else b["ns_per_op"],
                    "best_is_peer": None if b is None else vocab.is_peer(b["algorithm"]),
                    "peer": None if p is None else lib.display_algorithm(p, vocab),
                    "peer_ns": None if p is None else p["ns_per_op"]})
    return out


def orders_summary(orders):
    """Per (quantity, method): the median observed order over the cases, its range and theory, and
    the points excluded from the fits as at the rounding floor (the orders' "excluded", summed;
    None when the run's orders do not say)."""
    by = defaultdict(list)
    theory, excluded = {}, {}
    for o in orders:
        if isinstance(o.get("observed"), (int, float)):
            key = (o["quantity"], o["method"])
            by[key].append(o["observed"])
            theory[key] = o.get("theory")
            if isinstance(o.get("excluded"), int):
                excluded[key] = excluded.get(key, 0) + o["excluded"]
    return [{"quantity": q, "method": m, "median": statistics.median(v), "min": min(v), "max": max(v),
             "cases": len(v), "theory": theory[(q, m)], "excluded": excluded.get((q, m))}
            for (q, m), v in sorted(by.items())]


def honesty(records):
    """Records with an estimate (a bool "bounded"), how many bound their error, and those that do not."""
    with_estimate = [r for r in records if isinstance(r.get("bounded"), bool)]
    dishonest = [{"case": r["case"], "quantity": r["quantity"], "method": r["method"], "setting": r["setting"],
                  "status": r.get("status"), "error": r.get("error"), "estimate": r.get("estimate")}
                 for r in with_estimate if not r["bounded"]]
    return {"records": len(records), "with_estimate": len(with_estimate),
            "bounded": len(with_estimate) - len(dishonest), "dishonest": dishonest}


def pareto_fastest(records, times, cases=()):
    """Per case and target: the fastest length method reaching it (ns per length), from the join of
    the sweep's errors with the per-case timings, with the case's segment count (cases: the
    accuracy document's cases list; None where it has none)."""
    joined, *_ = lib.join_lengths(records, times)
    segments = {c["name"]: c.get("segments") for c in cases if "name" in c}
    out = []
    for case, pts in sorted(joined.items()):
        row = {"case": case, "segments": segments.get(case)}
        for t in lib.TARGETS:
            ok = [p for p in pts if p[1] <= t]
            best = min(ok) if ok else None
            row[f"{t:g}"] = None if best is None else {"method": f"{best[2]} {best[3]}".strip(), "ns": best[0]}
        out.append(row)
    return out


def featured(records, times):
    """The cases whose error-vs-time plots are published first: report_lib.featured_cases over the
    joined lengths and times, [{"case", "spread"}], at most MAX_PLOTS - 1 (the convergence plot is one)."""
    joined, *_ = lib.join_lengths(records, times)
    points = {case: [(ns, e, m) for ns, e, m, _ in pts] for case, pts in joined.items()}
    return [{"case": c, "spread": sp} for c, sp in lib.featured_cases(points, MAX_PLOTS - 1)]


def channel_summary(records, bench_rows):
    """The keyframe-channel figures: per time solver its worst value error over the corpus
    in double (ulps of the value range, and the case) and float, monotonicity violations, ns per
    value (64 keys, random and sorted, double); curvebench's goal line; per glTF rotation method the
    worst angle error in double. None when the run has no channel records."""
    records_c = rc.channel_records(records)
    if not records_c:
        return None
    times = rc.bench_times(bench_rows)
    solvers = []
    for s in rc.solver_order(records_c):
        v64, case = rc.worst(records_c, "channel_value", s, 64)
        solvers.append({"solver": s, "max64": v64, "case": case,
                        "max32": rc.worst(records_c, "channel_value", s, 32)[0],
                        "monotone": (rc.total(records_c, "channel_monotone", s, 64)
                                     + rc.total(records_c, "channel_monotone", s, 32)),
                        "ns": times.get((s, "64", 64, "single")), "ns_sorted": times.get((s, "64", 64, "sorted"))})
    goal = rc.goal_line(records_c)
    rotation = {}
    for row in rc.rotation_rows(records):
        if row[2] is not None and row[2] > rotation.get(row[1], -1.0):
            rotation[row[1]] = row[2]
    return {"solvers": solvers, "rotation": rotation,
            "goal": None if goal is None else {"max64": goal[0], "case": goal[1], "monotone": goal[2],
                                               "accurate_others": goal[3]}}


def headline(acc, bench_context, bench_rows, vocab, run):
    """Everything the published pages say, as plain data (JSON-serialisable)."""
    ctx = acc.get("context", {})
    records = acc.get("records", [])
    times = lib.case_times(bench_rows)
    rows = [r for r in bench_rows if r["family"] != lib.CASE_FAMILY]
    suite = acc.get("suite", {})
    return {
        "run": {"revision": ctx.get("revision") or bench_context.get("git_revision", "unknown"),
                "date": bench_context.get("date", "-"), "host": bench_context.get("host_name", "-"),
                "cpus": bench_context.get("num_cpus"), "mhz": bench_context.get("mhz_per_cpu"),
                "compiler": ctx.get("compiler", "-"), "flags": bench_context.get("flags", ctx.get("flags", "-")),
                "quick": bool(ctx.get("quick")), "suite": suite.get("name", "-"),
                "suite_version": suite.get("version"), "cases": len(acc.get("cases", [])),
                "records": len(records), "seconds_after_build": run.get("seconds_after_build"),
                "accuracy_seconds": ctx.get("seconds")},
        "eval": eval_spread(records, acc.get("cases", [])),
        "peers": peer_ratios(rows, vocab),
        "targets": targets(rows, vocab),
        "pareto": pareto_fastest(records, times, acc.get("cases", [])),
        "featured": featured(records, times),
        "orders": orders_summary(acc.get("orders", [])),
        "honesty": honesty(records),
        "channel": channel_summary(records, bench_rows),
        # The recommendations, as the summary of REPORT.md and docs/results.md makes them (one function).
        "recommendations": report_summary.run_recommendations(acc, bench_rows),
    }


# ---------------------------------------------------------------------------------------------
# The pages


def run_line(h):
    r = h["run"]
    return (f"revision {r['revision']}, {r['date'][:10]}, host `{r['host']}` ({r['cpus']} CPUs at {r['mhz']} MHz), "
            f"{r['compiler']}, `{r['flags'].strip()}`; suite {r['suite']} v{r['suite_version']}, {r['cases']} cases, "
            f"{r['records']} accuracy records" + (" (QUICK run)" if r["quick"] else ""))


def describe_peer(p):
    data = f" ({p['data']})" if p["data"] else ""
    faster = "faster" if p["ratio"] < 1 else "slower"
    factor = 1 / p["ratio"] if p["ratio"] < 1 else p["ratio"]
    return (f"{p['family']}{data}: ours `{p['ours']}` {fmt(p['ours_ns'])} ns vs `{p['peer']}` "
            f"{fmt(p['peer_ns'])} ns per {p['operation']} ({fmt(factor)}x {faster})")


def readme_peers(peers):
    """One row per (family, peer): random queries where the data names an order (sorted queries and
    the other settings are in docs/results.md)."""
    chosen = {}
    for p in peers:
        key = (p["family"], p["peer"].split(" ")[0])
        if key not in chosen or ("random" in p["data"] and "random" not in chosen[key]["data"]):
            chosen[key] = p
    return [chosen[k] for k in sorted(chosen)]


def render_readme(h):
    """The README's generated block: a few lines per topic, every figure from h."""
    r = h["run"]
    lines = [BEGIN, "<!-- generated by scripts/publish.py from docs/results/headline.json; do not edit -->", "",
             f"From a full `scripts/bench.sh` ({run_line(h)}). The run took "
             f"{fmt(r['seconds_after_build'])} s after the build. Shared 2-core VM: compare ratios, "
             "not absolute times. All tables and plots: [docs/results.md](docs/results.md).", ""]
    spread = [e for e in h["eval"] if e["spread"] >= 10]
    if spread:
        lines.append("- **Evaluation algorithms** (max error in eps(double) x the curve's size, against 50 digits), "
                     "largest spreads between algorithms on the same data:")
        for e in spread[:3]:
            algs = ", ".join(f"{a} {fmt(v)}" for a, v in sorted(e["errors"].items(), key=lambda kv: kv[1]))
            lines.append(f"  {e['case']} ({e['family']}): {algs}.")
    peers = readme_peers(h["peers"])
    if peers:
        lines.append("- **Against peers, same data and settings** (time per operation; random queries where "
                     "the data has an order):")
        lines += [f"  {describe_peer(p)};" for p in peers]
        lines[-1] = lines[-1][:-1] + "."
    uos = [t for t in h["targets"] if t["family"] == "u_of_s" and t["best"] is not None]
    if "recommendations" in h:
        answers = report_summary.answer_lines(h["recommendations"])
        if answers:
            lines.append(f"- **The method for an error target** (the answer of docs/results.md's Summary at "
                         f"{report_summary.target_text(report_summary.ANSWER_TARGET)}, for the kind of curve with "
                         "the most cases of each size; every kind, size and target is there):")
            lines += [f"  {a};" for a in answers]
            lines[-1] = lines[-1][:-1] + "."
    elif uos:  # a headline.json published before the recommendations were in it renders as it was published
        lines.append("- **u(s), fastest reaching |ds| / L** (one curve, benchmarks): " + "; ".join(
            f"{t['target']:g}: `{t['best']}` {fmt(t['best_ns'])} ns"
            + (f" (`{t['peer']}` {fmt(t['peer_ns'])} ns)" if t["peer"] else "")
            for t in uos) + ".")
    if h["orders"]:
        lines.append("- **Observed convergence orders** (median over cases, theory in brackets): " + ", ".join(
            f"{o['quantity']} {o['method']} {fmt(o['median'])}" + (f" [{fmt(o['theory'])}]" if o["theory"] else "")
            for o in h["orders"]) + ".")
    ch = h.get("channel")
    if ch and ch.get("goal"):
        g = ch["goal"]
        by = {x["solver"]: x for x in ch["solvers"]}
        own = by.get("curvebench", {})
        others = ", ".join(f"`{x['solver']}` {fmt(x['max64'])} ulps" + (f" {fmt(x['ns'])} ns" if x["ns"] else "")
                           for x in ch["solvers"] if x["solver"] != "curvebench")
        lines.append(f"- **Keyframe channels** (time solvers on the stress corpus, double, max error in ulps of the "
                     f"value range against the 50-digit inversion): curvebench's solver {fmt(g['max64'])} ulps "
                     f"(goal <= 4), {g['monotone']:g} monotonicity violations"
                     + (f", {fmt(own['ns'])} ns per value" if own.get("ns") else "") + f"; {others}.")
    ho = h["honesty"]
    lines.append(f"- **Honest estimates**: {ho['bounded']} of the {ho['with_estimate']} records that carry an "
                 f"error estimate bound their true error ({len(ho['dishonest'])} do not"
                 + (": " + ", ".join(f"{d['case']} {d['method']} {d['setting']}".strip() for d in ho["dishonest"][:5])
                    + (" ..." if len(ho["dishonest"]) > 5 else "") if ho["dishonest"] else "") + ").")
    lines += ["", END]
    return "\n".join(lines)


def render_fidelity(fidelity, tools):
    """The fidelity block of docs/results.md: report_channel's section with its markers."""
    lines = [FIDELITY_BEGIN, "<!-- generated by scripts/publish.py from `curvebench fidelity --json`; do not edit -->"]
    lines += rc.fidelity_section(fidelity, tools)
    if fidelity:
        lines += ["", f"Measured by {fidelity.get('curvebench', 'curvebench')}."]
    return "\n".join(lines + ["", FIDELITY_END])


def replace_fidelity(text, block):
    """text with its fidelity block replaced by `block` (appended when it has none)."""
    i, j = text.find(FIDELITY_BEGIN), text.find(FIDELITY_END)
    if i < 0 or j < i:
        return text.rstrip("\n") + "\n\n" + block + "\n"
    return text[:i] + block + text[j + len(FIDELITY_END):]


def load_fidelity(report_dir):
    path = os.path.join(report_dir, "fidelity.json")
    if not os.path.exists(path):
        return None
    with open(path, encoding="utf-8") as f:
        return json.load(f)


def render_results(h, plots):
    r = h["run"]
    head = ["# curvebench results", "",
            "Generated by `scripts/bench.sh --publish` (scripts/publish.py) from one full run; do not edit by hand. "
            "The complete report of a run is `reports/REPORT.md` (and `reports/REPORT.html`).", ""]
    md = ["## Machine and run", ""]
    md.append(table(["item", "value"], [
        ["revision", r["revision"]], ["date", r["date"]], ["host", r["host"]],
        ["CPUs", f"{r['cpus']} x {r['mhz']} MHz"], ["compiler", r["compiler"]], ["flags", r["flags"].strip()],
        ["suite", f"{r['suite']} v{r['suite_version']}, {r['cases']} cases, {r['records']} records"
                  + (" (quick)" if r["quick"] else "")],
        ["seconds after the build", r["seconds_after_build"]], ["accuracy sweep seconds", r["accuracy_seconds"]]]))
    md += ["", "Absolute times on a shared machine are noisy; the ratios are measured in the same run.", ""]
    if h.get("peers_missing"):
        md += ["Optional peers missing from this run (published with --allow-missing-peers): "
               + ", ".join(h["peers_missing"]) + ".", ""]

    md += ["## Against peers", "", "Our fastest row with the peer's settings on the same data, time per operation "
           "(ratio < 1: ours faster).", ""]
    md.append(table(["family", "data", "ours", "ns", "peer", "ns", "ours / peer"],
                    [[p["family"], p["data"] or "-", p["ours"], p["ours_ns"], p["peer"], p["peer_ns"], p["ratio"]]
                     for p in h["peers"]]) if h["peers"] else "No peer benchmarks in this run.")
    if h.get("peers_section"):  # REPORT.md's Peers section: accuracy, findings, versions (report_peers.py)
        md += h["peers_section"]
    if h.get("shipped_section"):  # REPORT.md's "Arc length in shipped software" (report_shipped.py)
        md += h["shipped_section"]
    md += ["", "## Fastest reaching an error target (benchmarks)", ""]
    if "recommendations" in h:  # a headline.json published before them renders as it was published
        md += ["One benchmark curve per family, timed: a measurement, not a recommendation (the Summary's table "
               "answers per kind and size of curve).", ""]
    md.append(table(["family", "error counter", "target", "fastest", "ns per op", "fastest peer", "ns per op"],
                    [[t["family"], t["counter"], f"{t['target']:g}", t["best"] or "none reached", t["best_ns"],
                      t["peer"] or "-", t["peer_ns"]] for t in h["targets"]]))
    md += ["", "## Arc length per case: fastest method reaching each relative error", "",
           "Per-case timings (`bench_arclength_cases`) joined with the accuracy sweep's errors.", ""]

    def fastest(p, t):
        best = p[f"{t:g}"]
        return f"{best['method']} ({fmt(best['ns'])} ns)" if best else "none reached"
    # A headline.json published before the segment counts and the excluded points renders
    # as it was published: the columns appear when the run's data carry them.
    with_segments = any("segments" in p for p in h["pareto"])
    md.append(table(["case"] + (["segments"] if with_segments else []) + [f"at {t:g}" for t in lib.TARGETS],
                    [[p["case"]] + ([p["segments"] if p.get("segments") is not None else "-"] if with_segments else [])
                     + [fastest(p, t) for t in lib.TARGETS] for p in h["pareto"]])
              if h["pareto"] else "No per-case timings.")
    if h.get("u_of_s_many"):  # REPORT.md's "u(s) on many segments" (report_lib.table_per_segments), a section here
        md += ["", "## " + h["u_of_s_many"][0].lstrip("# ")] + h["u_of_s_many"][1:]
    md += ["", "## Evaluation algorithms", "", "Max error in eps(double) x the curve's size against the 50-digit "
           "evaluation of the same data; cases with more than one algorithm, largest spread first.", ""]
    md.append(table(["case", "family", "errors per algorithm", "worst / best"],
                    [[e["case"], e["family"], ", ".join(f"{a} {fmt(v)}" for a, v in e["errors"].items()), e["spread"]]
                     for e in h["eval"]]))
    md += ["", "## Convergence orders", ""]
    with_excluded = any(o.get("excluded") is not None for o in h["orders"])
    if with_excluded:
        md += ["Fitted only where the error still falls: the points at the rounding plateau (from the first whose "
               "error is not 10 % below the best at a lower cost on) are excluded, and a case with fewer than 3 "
               "points spanning a factor 4 in cost left has no order.", ""]
    md.append(table(["quantity", "method", "median observed", "min", "max", "cases", "theory"]
                    + (["excluded points"] if with_excluded else []),
                    [[o["quantity"], o["method"], o["median"], o["min"], o["max"], o["cases"], o["theory"]]
                     + ([o["excluded"] if o.get("excluded") is not None else "-"] if with_excluded else [])
                     for o in h["orders"]]))
    ho = h["honesty"]
    ch = h.get("channel")
    if ch:
        md += ["", "## Keyframe channels", "", "Each time solver on the channel stress corpus against the 50-digit "
               "inversion: max value error in ulps of the channel's value range (double, its worst case, float), "
               "monotonicity violations (double and float), ns per value on 64 keys (random and sorted times, "
               "double). The complete tables are in REPORT.md's section \"Keyframe channels\".", ""]
        md.append(table(["solver", "max error, double", "worst case", "max error, float", "monotonicity violations",
                         "ns/value", "ns/value sorted"],
                        [[x["solver"], x["max64"], x["case"] or "-", x["max32"], f"{x['monotone']:g}", x["ns"],
                          x["ns_sorted"]] for x in ch["solvers"]]))
        if ch.get("rotation"):
            md += ["", "glTF rotation channels, max angle error in eps(double) radians: " +
                   ", ".join(f"`{m}` {fmt(v)}" for m, v in sorted(ch["rotation"].items())) + "."]
    md += ["", "## Error-estimate honesty", "",
           f"{ho['bounded']} of {ho['with_estimate']} records with an estimate bound their error "
           f"({ho['records']} records in all).", ""]
    if ho["dishonest"]:
        md.append(table(["case", "quantity", "method", "setting", "status", "error", "estimate"],
                        [[d["case"], d["quantity"], d["method"], d["setting"], d["status"], d["error"], d["estimate"]]
                         for d in ho["dishonest"]]))
        md.append("")
    if plots:
        md += ["## Plots", ""]
        if h.get("featured"):
            md += ["The error-vs-time plots shown are of the cases where the methods differ most at equal cost: "
                   "per case, the largest ratio between two methods' smallest errors within one decade of time, errors "
                   "below eps(double) taken as eps "
                   "(" + ", ".join(f"{f['case']} {fmt(f['spread'])}" for f in h["featured"]) + ").", ""]
        md += [f"![{name}](results/{name})" for name in plots] + [""]
    # The page opens with REPORT.md's summary of the same run (report_summary.py) and the contents,
    # as REPORT.md does; the summary's "Details:" link this page's sections that hold its figures.
    summary = (h.get("summary") or []) + [""]
    # The fidelity block is appended after (replace_fidelity): its section is linked as the page will have it.
    page = report_summary.link_details(head + summary + report_summary.toc(summary, md) + md,
                                       later=rc.fidelity_section(None, [])[:2])
    return "\n".join(page)


def choose_plots(plot_dir, ranked=()):
    """At most MAX_PLOTS of the run's plots: the convergence plot, then the per-case error-vs-time
    plots of the cases `ranked` (featured(): where the methods differ most), then the rest by name."""
    pareto = sorted(os.path.basename(p) for p in glob.glob(os.path.join(plot_dir, "pareto_length_*.png")))
    chosen = [n for n in ("convergence.png", "shipped_length_vs_extent.png", "shipped_length_vs_offset.png")
              if os.path.exists(os.path.join(plot_dir, n))]
    for case in ranked:
        name = f"pareto_length_{''.join(c if c.isalnum() else '_' for c in case).strip('_')}.png"
        if name in pareto and name not in chosen:
            chosen.append(name)
    chosen += [n for n in pareto if n not in chosen]
    return chosen[:MAX_PLOTS]


def replace_block(text, block, path):
    i, j = text.find(BEGIN), text.find(END)
    if i < 0 or j < i:
        raise PublishError(f"{path}: no {BEGIN} ... {END} block to replace")
    return text[:i] + block + text[j + len(END):]


def atomic_write(path, text):
    safe_output.write_text(path, text)


def load_run(report_dir):
    vocab = lib.load_vocabulary(os.path.join(report_dir, "vocabulary.json"))
    bench_files = sorted(glob.glob(os.path.join(report_dir, "bench_*.json")))
    bench_context, bench_rows = lib.load_benchmark_files(bench_files, vocab)
    with open(os.path.join(report_dir, "accuracy.json"), encoding="utf-8") as f:
        acc = json.load(f)
    run = {}
    if os.path.exists(os.path.join(report_dir, "run.json")):
        with open(os.path.join(report_dir, "run.json"), encoding="utf-8") as f:
            run = json.load(f)
    return acc, bench_context, bench_rows, vocab, run


def run_sections(report_dir, acc, bench_rows, vocab, allow_missing_peers):
    """REPORT.md's Summary and Peers sections of the run (the same code renders both pages) and
    the optional peers that did not run, which refuse the publish unless allow_missing_peers."""
    try:
        missing = report_peers.missing_drivers(report_peers.load_peer_files(report_dir))
    except (OSError, lib.ReportError) as e:
        raise PublishError(f"the optional peers' results could not be read: {e}") from e
    if missing and not allow_missing_peers:
        raise PublishError("optional peers did not run (no reports/peers_<driver>.json): " + ", ".join(missing)
                           + "; install them with scripts/peers.sh and run again, or publish without them "
                             "(scripts/bench.sh --publish --allow-missing-peers; docs/results.md then names them)")
    rows = [r for r in bench_rows if r["family"] != lib.CASE_FAMILY]
    many = report_summary.with_many_segments_answer(lib.table_per_segments(bench_rows, lib.segment_counts(acc)),
                                                    report_summary.run_recommendations(acc, bench_rows))
    return {"summary": report_summary.summary_of_run(acc, report_dir, bench_rows, vocab, load_fidelity(report_dir)),
            "peers_section": report_peers.peers_section(acc, report_dir, rows, vocab), "peers_missing": missing,
            "u_of_s_many": many}


def publish(report_dir, docs_dir, readme, allow_quick=False, allow_missing_peers=False):
    acc, bench_context, bench_rows, vocab, run = load_run(report_dir)
    h = headline(acc, bench_context, bench_rows, vocab, run)
    if h["run"]["quick"] and not allow_quick:
        raise PublishError(f"{report_dir}/accuracy.json is a quick run: publish a full `scripts/bench.sh` run")
    h.update(run_sections(report_dir, acc, bench_rows, vocab, allow_missing_peers))
    # The shipped-software section links its plots where docs/results.md finds them (results/).
    h["shipped_section"] = report_shipped.section(acc, report_dir, os.path.join(report_dir, "plots"),
                                                  link_prefix="results/")
    out = os.path.join(docs_dir, "results")
    os.makedirs(out, exist_ok=True)
    plots = choose_plots(os.path.join(report_dir, "plots"), [f["case"] for f in h.get("featured", [])])
    size = sum(os.path.getsize(os.path.join(report_dir, "plots", n)) for n in plots)
    if size > MAX_PLOT_BYTES:
        raise PublishError(f"the {len(plots)} chosen plots take {size} bytes, over the {MAX_PLOT_BYTES} budget")
    for old in glob.glob(os.path.join(out, "*.png")):
        if os.path.basename(old) not in plots:
            os.remove(old)
    for n in plots:
        shutil.copyfile(os.path.join(report_dir, "plots", n), os.path.join(out, n))
    atomic_write(os.path.join(out, "headline.json"), json.dumps(h, indent=1, sort_keys=True) + "\n")
    report_history.record(os.path.join(out, "history.jsonl"), h)
    results = render_results(h, plots) + "\n"
    results = replace_fidelity(results, render_fidelity(load_fidelity(report_dir), list(vocab.tools.values())))
    atomic_write(os.path.join(docs_dir, "results.md"), results)
    if readme:
        with open(readme, encoding="utf-8") as f:
            text = f.read()
        atomic_write(readme, replace_block(text, render_readme(h), readme))
    return h


def main():
    root = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..")
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--reports", default=os.path.join(root, "reports"))
    ap.add_argument("--docs", default=os.path.join(root, "docs"))
    ap.add_argument("--readme", default=os.path.join(root, "README.md"), help="README to update ('' for none)")
    ap.add_argument("--allow-quick", action="store_true", help="publish a quick run (for trying the script)")
    ap.add_argument("--allow-missing-peers", action="store_true",
                    help="publish although an optional peer (scripts/peers.sh) did not run; the page names it")
    ap.add_argument("--fidelity-only", action="store_true",
                    help="refresh only the tool-model fidelity block of RESULTS from REPORTS/fidelity.json and "
                         "REPORTS/vocabulary.json (what `curvebench fidelity --json` and `list vocabulary --json` "
                         "write); the rest of the published run stays")
    ap.add_argument("--history-only", action="store_true",
                    help="append the published run (DOCS/results/headline.json) to DOCS/results/history.jsonl, "
                         "for a run published before the history existed; the rest stays")
    args = ap.parse_args()
    if args.history_only:
        try:
            out = os.path.join(os.path.abspath(args.docs), "results")
            path = os.path.join(out, "history.jsonl")
            with open(os.path.join(out, "headline.json"), encoding="utf-8") as f:
                e = report_history.record(path, json.load(f))
        except (OSError, ValueError, KeyError, lib.ReportError) as err:
            print(f"publish.py: {err}", file=sys.stderr)
            return 1
        print(f"publish.py: {path}: revision {e['revision']} recorded")
        return 0
    if args.fidelity_only:
        try:
            report_dir = os.path.abspath(args.reports)
            fidelity = load_fidelity(report_dir)
            if fidelity is None:
                raise PublishError(f"{report_dir}/fidelity.json: not found (curvebench fidelity --json writes it)")
            vocab = lib.load_vocabulary(os.path.join(report_dir, "vocabulary.json"))
            path = os.path.join(os.path.abspath(args.docs), "results.md")
            with open(path, encoding="utf-8") as f:
                text = f.read()
            atomic_write(path, replace_fidelity(text, render_fidelity(fidelity, list(vocab.tools.values()))))
        except (OSError, ValueError, lib.ReportError, PublishError) as e:
            print(f"publish.py: {e}", file=sys.stderr)
            return 1
        print(f"publish.py: refreshed the fidelity block of {path}")
        return 0
    try:
        h = publish(os.path.abspath(args.reports), os.path.abspath(args.docs), args.readme, args.allow_quick,
                    args.allow_missing_peers)
    except (OSError, ValueError, lib.ReportError, PublishError) as e:
        print(f"publish.py: {e}", file=sys.stderr)
        return 1
    print(f"publish.py: wrote {args.docs}/results.md and results/ (revision {h['run']['revision']})")
    return 0


if __name__ == "__main__":
    sys.exit(main())
