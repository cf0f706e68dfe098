"""The keyframe-channel section of REPORT.md (scripts/report.py calls channel_section).

Inputs: the accuracy runner's channel records (quantities channel_value, channel_keys,
channel_monotone, channel_time; one method per time solver; setting bits=32 or bits=64), the
"channel" summary of each channel case (value range, picture, the tools' models and their
disagreement) and the bench_channel rows (family channel_value: ns per value, error counter
max_err_range_eps). The tools are the vocabulary's ("tools" of `curvebench list vocabulary --json`,
io::all_tools): their names are the disagreement table's columns and the algorithms of their
benchmark rows. The pure functions (tables) are tested by tests/python/test_report_channel.py;
the plots need matplotlib.
"""
import math
import os
from collections import defaultdict

import report_lib as lib

CHANNEL_QUANTITIES = ("channel_value", "channel_keys", "channel_monotone", "channel_time")
BENCH_FAMILY = "channel_value"
REFERENCE_TOOL = "exact"  # the keys as given: the disagreement table's reference, not a column


def tool_names(vocab):
    """The tools of the vocabulary (a report_lib.Vocabulary or its JSON), in its order."""
    tools = vocab.get("tools", []) if isinstance(vocab, dict) else getattr(vocab, "tools", {}).values()
    return [t["id"] for t in tools]


def channel_records(records):
    return [r for r in records if r.get("quantity") in CHANNEL_QUANTITIES]


def bits_of(setting):
    for k, v in (item.partition("=")[::2] for item in setting.split(",") if item):
        if k == "bits":
            return int(v)
    return None


def solver_order(records):
    """The solvers in the order the runner wrote them (channel::all_time_solvers)."""
    seen = []
    for r in records:
        if r["method"] not in seen:
            seen.append(r["method"])
    return seen


def worst(records, quantity, solver, bits, field="error"):
    """(max value, case) over the corpus of one quantity, solver and precision; (None, None) if none."""
    best = (None, None)
    for r in records:
        if r["quantity"] == quantity and r["method"] == solver and bits_of(r["setting"]) == bits:
            v = r.get(field)
            if v is None:
                continue
            if best[0] is None or v > best[0]:
                best = (v, r["case"])
    return best


def total(records, quantity, solver, bits):
    return sum(r["error"] or 0 for r in records
               if r["quantity"] == quantity and r["method"] == solver and bits_of(r["setting"]) == bits)


def bench_times(bench_rows):
    """{(solver or model, keys, bits, calls): ns per value} of the channel benchmarks."""
    out = {}
    for r in bench_rows:
        if r.get("family") != BENCH_FAMILY:
            continue
        args = dict(r["args"])
        out[(r["algorithm"], args.get("keys"), int(args.get("bits", 0)), args.get("calls"))] = r["ns_per_op"]
    return out


def solver_rows(records, times):
    """One row per solver: the corpus' worst figures in double and float, and the times."""
    rows = []
    for s in solver_order(records):
        v64, c64 = worst(records, "channel_value", s, 64)
        rms64, _ = worst(records, "channel_value", s, 64, "rms")
        v32, c32 = worst(records, "channel_value", s, 32)
        k64, _ = worst(records, "channel_keys", s, 64)
        t64, _ = worst(records, "channel_time", s, 64)
        it, _ = worst(records, "channel_time", s, 64, "iterations_mean")
        nc = sum(r.get("not_converged") or 0 for r in records
                 if r["quantity"] == "channel_time" and r["method"] == s)
        rows.append([s, v64, c64 or "-", rms64, v32, k64, t64,
                     f"{total(records, 'channel_monotone', s, 64):g} / {total(records, 'channel_monotone', s, 32):g}",
                     it, f"{nc:g}",
                     times.get((s, "64", 64, "single")), times.get((s, "64", 64, "sorted")),
                     times.get((s, "64", 32, "single")), times.get((s, "2", 64, "single"))])
    return rows


def case_matrix(records, bits=64):
    """(solvers, rows): per case, the max value error of each solver in ulps of the value range."""
    solvers = solver_order(records)
    cells = defaultdict(dict)
    for r in records:
        if r["quantity"] == "channel_value" and bits_of(r["setting"]) == bits:
            cells[r["case"]][r["method"]] = r["error"]
    return solvers, [[case] + [cells[case].get(s) for s in solvers] for case in sorted(cells)]


def disagreement_rows(cases, tools):
    """Per exact-tool case: each tool's largest difference from the exact keys (one column per tool
    of `tools` but the reference), the largest between two tools, and the tools that cannot hold
    the keys (with the reason)."""
    columns = [t for t in tools if t != REFERENCE_TOOL]
    rows, notes = [], []
    for c in cases:
        m = (c.get("channel") or {}).get("models")
        if not m:
            continue
        vs_exact = {d["b"]: d["max"] for d in m["disagreement"] if d["a"] == "exact"}
        among = [d for d in m["disagreement"] if d["a"] != "exact"]
        top = max(among, key=lambda d: d["max"]) if among else None
        rows.append([c["name"]] + [vs_exact.get(t, "n/a") for t in columns] +
                    [f"{top['a']} vs {top['b']}: {lib.fmt(top['max'])}" if top else "-"])
        for tool, why in sorted(m.get("skipped", {}).items()):
            notes.append(f"{c['name']}, {tool}: {why}")
    return rows, notes


def rotation_rows(records):
    """Per glTF rotation case and method (rotation_step, _slerp, _nlerp, _cubicspline): the angle
    error in double and float (eps radians), its RMS and the largest departure from unit length."""
    cells = defaultdict(dict)
    for r in records:
        if r.get("quantity") == "channel_rotation":
            cells[(r["case"], r["method"])][bits_of(r["setting"])] = r
    rows = []
    for (case, method), by_bits in sorted(cells.items()):
        d, f = by_bits.get(64, {}), by_bits.get(32, {})
        rows.append([case, method, d.get("error"), d.get("rms"), d.get("norm"), f.get("error"), f.get("norm")])
    return rows


def goal_line(records):
    """The curvebench solver's goal: <= 4 ulps of the value range in double on the whole
    corpus, no monotonicity violation, faster than every other solver reaching that accuracy."""
    v, case = worst(records, "channel_value", "curvebench", 64)
    if v is None:
        return None
    mono = total(records, "channel_monotone", "curvebench", 64)
    accurate = [s for s in solver_order(records)
                if s != "curvebench" and (worst(records, "channel_value", s, 64)[0] or math.inf) <= 4]
    return v, case, mono, accurate


# The benchmark configurations the speed goal is judged on: (keys, calls, what they are).
SPEED_CONFIGS = (("64", "single", "64 keys, random times"), ("64", "sorted", "64 keys, sorted times"),
                 ("2", "single", "CSS ease"))


def speed_goal(times, accurate):
    """The speed half of the goal: [(configuration, curvebench ns, [(solver, ns, curvebench / solver)])]
    in double for every configuration bench_channel timed, and whether curvebench is faster than
    every accurate solver in all of them (None when a time is missing)."""
    out, met = [], True
    for keys, calls, what in SPEED_CONFIGS:
        ours = times.get(("curvebench", keys, 64, calls))
        theirs = [(s, times.get((s, keys, 64, calls))) for s in accurate]
        if ours is None or any(ns is None for _, ns in theirs):
            met = None if met is not False else met
            continue
        ratios = [(s, ns, ours / ns) for s, ns in theirs]
        met = met if all(r < 1 for _, _, r in ratios) else False
        out.append((what, ours, ratios))
    return out, (met if out else None)


# The machine epsilon of each precision: the records' value errors are in ulps of their own
# precision (eps x value range), so a plot of both precisions converts them to one unit first.
EPS = {64: 2.0 ** -52, 32: 2.0 ** -23}


def relative_to_range(ulps, bits):
    """A value error in ulps of the precision `bits` (eps x value range) as a fraction of the range."""
    return ulps * EPS[bits]


def error_time_plot(records, times, plot_dir, plt, save):
    """Error vs time per solver (max over the corpus against ns per value on keys:64, single calls),
    double and float on one axis in one unit: the error as a fraction of the value range."""
    fig, ax = plt.subplots(figsize=(6.5, 4.2))
    plotted = False
    floor = 1e-2 * EPS[64]  # an error of 0 drawn at 1 % of a double ulp
    for bits, marker in ((64, "o"), (32, "s")):
        for s in solver_order(records):
            v, _ = worst(records, "channel_value", s, bits)
            ns = times.get((s, "64", bits, "single"))
            if v is None or ns is None:
                continue
            y = max(relative_to_range(v, bits), floor)
            ax.scatter([ns], [y], marker=marker, label=f"{s} ({'double' if bits == 64 else 'float'})")
            ax.annotate(s, (ns, y), fontsize=6, xytext=(3, 3), textcoords="offset points")
            plotted = True
    if not plotted:
        plt.close(fig)
        return None
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("ns per value (64 bezier keys, random times)")
    ax.set_ylabel("max error over the corpus / value range")
    ax.set_title("Keyframe channels: time solvers, error vs time")
    ax.legend(fontsize=6, ncol=2)
    path = os.path.join(plot_dir, "channel_solvers_error_time.png")
    save(fig, path)
    return os.path.relpath(path, os.path.dirname(plot_dir))


def pictures_plot(cases, plot_dir, plt, save):
    """One panel per channel case: the value over the sampled window, the keys and their handles."""
    shown = [c for c in cases if (c.get("channel") or {}).get("picture")]
    if not shown:
        return None
    cols = 3
    rows = (len(shown) + cols - 1) // cols
    fig, axes = plt.subplots(rows, cols, figsize=(4.0 * cols, 2.6 * rows), squeeze=False)
    for ax, c in zip([a for row in axes for a in row], shown):
        p = c["channel"]["picture"]
        ax.plot(p["t"], p["v"], lw=1)
        for k in p["keys"]:
            ax.plot([k["t"]], [k["v"]], "ko", ms=3)
            for side in ("in", "out"):
                if side in k:
                    ax.plot([k["t"], k[side][0]], [k["v"], k[side][1]], "r-", lw=0.7)
                    ax.plot([k[side][0]], [k[side][1]], "rs", ms=2)
        ax.set_title(f"{c['name']} ({c['channel']['tool']})", fontsize=7)
        ax.tick_params(labelsize=6)
    for ax in [a for row in axes for a in row][len(shown):]:
        ax.axis("off")
    fig.tight_layout()
    path = os.path.join(plot_dir, "channel_cases.png")
    save(fig, path)
    return os.path.relpath(path, os.path.dirname(plot_dir))


def channel_section(acc, bench_rows, plot_dir, plt, save, tools):
    """The markdown lines of the keyframe-channel section; `tools` the vocabulary's tool names."""
    records = channel_records(acc.get("records", []))
    cases = [c for c in acc.get("cases", []) if c.get("channel")]
    md = ["", "## Keyframe channels: time solvers and tool models", ""]
    if not records:
        return md + ["No results."]
    times = bench_times(bench_rows)
    md += ["Each channel case of the corpus (group `channel`) is evaluated at sorted times over its keyed range "
           "widened by a quarter on each side, with every time solver, in double (bits=64) and in float "
           "(bits=32: the keys rounded to float as a float runtime holds them), against the same spec at "
           "50 digits with the exact inversion, taken at the same (rounded) times. Value errors are in ulps of "
           "the channel's value range (eps of the precision x the range); the time residual |x(u) - t| in ulps "
           "of the segment's duration; monotonicity violations count consecutive samples where the value "
           "moves against the exact value's direction (double / float). Times come from bench_channel "
           "(ns per value; 64 bezier keys with random handles, 1024 random or sorted times; and the CSS "
           "keyword `ease`, keys:2).", ""]
    goal = goal_line(records)
    if goal:
        v, case, mono, accurate = goal
        ok = v <= 4 and mono == 0
        md.append(f"curvebench's solver in double: at most {lib.fmt(v)} ulps of the value range over the corpus "
                  f"(worst {case}), {mono:g} monotonicity violations: the goal (<= 4 ulps, none) is "
                  f"{'met' if ok else 'missed'}. Other solvers within 4 ulps on the whole corpus: "
                  f"{', '.join(accurate) if accurate else 'none'}.")
        configs, fast = speed_goal(times, accurate)
        if configs:
            parts = [f"{what}: {lib.fmt(ours)} ns per value"
                     + "".join(f", {s} {lib.fmt(ns)} (ratio {r:.2f})" for s, ns, r in ratios)
                     for what, ours, ratios in configs]
            verdict = {True: "faster than every other solver within 4 ulps: the speed goal is met",
                       False: "not faster than every other solver within 4 ulps: the speed goal is missed",
                       None: "some times are missing: the speed goal is not judged"}[fast]
            md.append(f"Speed in double (bench_channel, same run; ratio curvebench / solver): {'; '.join(parts)}; "
                      f"{verdict}.")
        md.append("")
    md.append(lib.table(["solver", "max value error, double", "worst case", "max RMS, double",
                         "max value error, float", "key error, double", "time residual, double",
                         "monotonicity violations", "mean iterations, double", "not converged",
                         "ns/value double", "ns/value double sorted", "ns/value float", "ns/value CSS ease"],
                        solver_rows(records, times)))
    path = error_time_plot(records, times, plot_dir, plt, save)
    if path:
        md += ["", f"![channel solvers, error vs time]({path})"]
    solvers, rows = case_matrix(records)
    md += ["", "### Per case: max value error in double (ulps of the value range)", ""]
    md.append(lib.table(["case"] + solvers, rows))
    refused = [(c["name"], s, why) for c in cases for s, why in sorted(c["channel"].get("refused", {}).items())]
    if refused:
        md += ["", "Refused in float (the keys rounded to float are no longer valid):", ""]
        md.append(lib.table(["case", "solver", "message"], [list(x) for x in refused]))
    rotations = rotation_rows(acc.get("records", []))
    if rotations:
        md += ["", "### glTF rotation channels", ""]
        md += ["Each rotation case (`\"path\": \"rotation\"`) under its interpolation's methods (linear both "
               "as the specification's slerp and as the nlerp players use), in double and in float, against the "
               "same formula at 50 digits at the same (rounded) times; the error is the rotation angle between "
               "the two quaternions in eps of the precision (radians), unit: the largest | |q| - 1 | in eps.", ""]
        md.append(lib.table(["case", "method", "max angle error, double", "RMS, double", "unit, double",
                             "max angle error, float", "unit, float"], rotations))
    md += ["", "### Where the tools disagree on the same keys", ""]
    md += ["The keys of each `exact` case imported into each tool's model (channel/tools/<tool>.hpp, from_keys: "
           "Maya's weighted fixed tangents with its correction of regressive handles, USD's keep_ratio "
           "anti-regression, Blender's float32 free handles with its per-handle limit, glTF's cubicspline slopes "
           "without the handle lengths, CSS's cubic-bezier or linear() on [0, 1]), each evaluated by its own solver; "
           "the largest difference of each pair over the keyed range, in value ranges (exact is the 50-digit truth "
           "of the keys as given):", ""]
    rows, notes = disagreement_rows(cases, tools)
    columns = [t for t in tools if t != REFERENCE_TOOL]
    md.append(lib.table(["case"] + [f"{t} vs exact" for t in columns] + ["largest between two tools"], rows)
              if rows else "No exact-tool cases.")
    if notes:
        md += ["", "n/a: the tool cannot hold these keys:", ""] + [f"- {n}" for n in notes]
    models = [[a, bits, ns] for (a, keys, bits, calls), ns in sorted(times.items())
              if keys == "64" and a in tools and a != REFERENCE_TOOL]
    if models:
        md += ["", "The tools' models of the 64 benchmark keys, timed in the same run (ns per value):", ""]
        md.append(lib.table(["model", "bits", "ns/value"], models))
    path = pictures_plot(cases, plot_dir, plt, save)
    if path:
        md += ["", "The stress cases, with their keys (black) and handles (red):", "", f"![channel cases]({path})"]
    return md


def fidelity_section(fidelity, tools):
    """The markdown lines of "Tool models against the real tools": `fidelity` the JSON of `curvebench
    fidelity --json` (None when the run has none), `tools` the vocabulary's tool dicts (id,
    verification)."""
    md = ["", "## Tool models against the real tools", ""]
    md += ["What each tool model is verified against, recorded from the real tool, and what it is not:", ""]
    md.append(lib.table(["tool", "verified"], [[t["id"], t.get("verification", "-")] for t in tools]))
    md.append("")
    if not fidelity or not fidelity.get("recordings"):
        return md + ["No recordings were measured in this run (`curvebench fidelity`)."]
    ulps = fidelity.get("agree_ulps")
    md += [f"Each recorded channel is read as a curvebench spec and evaluated as the tool evaluates it (its "
           f"time solver, its storage precision); it agrees when the largest |model - tool| over its recorded "
           f"times is at most {ulps:g} eps of the tool's precision times the channel's scale, its value range "
           f"plus |t V'(t)| (the reach of the time's own rounding, large for a cycle wrapped far out or a frame "
           f"near 1e5): the two programs' own roundings of the same operations stay well inside that; a "
           f"different rule does not. Errors are fractions of that scale. `curvebench fidelity FILE` prints "
           f"the same for a recording of your own.", ""]
    rows = []
    for r in fidelity["recordings"]:
        s = r.get("source", {})
        source = ", ".join(str(s[k]) for k in ("implementation", "version") if s.get(k))
        commit = str(s.get("commit", ""))
        if commit and commit != str(s.get("version", "")):
            # A git hash is shortened; anything else (a release name) is shown as written.
            short = commit[:12] if len(commit) == 40 and all(c in "0123456789abcdef" for c in commit) else commit
            source += f" (commit {short})"
        unverified = r.get("unverified", 0)
        evaluated = r["channels"] - r["refused"] - unverified
        rows.append([r["tool"], source or "-", os.path.basename(r["file"]), r["channels"],
                     f"{r['agree']} of {evaluated}", r["refused"], unverified, r["max_error"]])
    md.append(lib.table(["tool", "recorded from", "recording", "channels", "agree", "refused (not modelled)",
                         "unverified (no tool values)", "max error (x scale)"], rows))
    for r in fidelity["recordings"]:
        md += ["", f"### {r['tool']}: {os.path.basename(r['file'])}", ""]
        build = r.get("source", {}).get("build")
        if build:
            md += [f"Built: {build}.", ""]
        md.append(lib.table(["feature", "channels", "agree", "refused", "unverified", "max error (x scale)"],
                            [[f["feature"], f["channels"], f["agree"], f["refused"], f.get("unverified", 0),
                              f["max_error"]] for f in r["features"]]))
        if r["disagree"]:
            md += ["", "Channels that disagree (largest error, where):", ""]
            md.append(lib.table(["channel", "error (x scale)", "t", "model", "tool"],
                                [[d["name"], d["error"], d["t"], d["model"], d["recorded"]] for d in r["disagree"]]))
        if r["refused_channels"]:
            refused = "; ".join(f"{c['name']} ({c['reason']})" for c in r["refused_channels"])
            md += ["", "Refused (not modelled): " + refused]
        if r.get("unverified_channels"):
            md += ["", "Unverified (the tool gave no values): " + "; ".join(
                f"{c['name']} ({c['reason']})" for c in r["unverified_channels"])]
    return md
