"""REPORT.md's "Arc length in shipped software": the arc length, point at length and
spacing of the SVG engines and JavaScript libraries people's paths actually go through, measured by
scripts/peers/shipped_results.py against the same 50-digit reference as curvebench's own methods.

Inputs: the reports/peers_*.json files that carry "rows" (peers_shipped_<driver>.json, one per
driver, and peers_lottie.json: "rows" of peer, case, setting,
length and its error, point error, s error, spacing CV and times) and accuracy.json's records of the
same cases (curvebench's length and u(s) methods). Every sentence of the findings is built from
these figures. Pure functions but the plot writer; tested by tests/python/test_report_shipped.py.
"""
import math
import os
import re
import statistics

import report_lib as lib
import report_peers

fmt, table = lib.fmt, lib.table

# curvebench's rows beside the peers: its default length method at the tolerance a user would
# choose for 1e-10, and its u(s) table (the quantity a point at length needs), from accuracy.json.
OURS_LENGTH = ("adaptive_gk", "tol=1e-10")
FEATURED = ("svg_every_command", "svg_cusp_fonttools", "svg_thin_ellipse", "svg_cubic_offset_1e6")
# Plots' floor: an error of 0 (a peer exact to the last bit) is drawn here, and the text says so.
FLOOR = 1e-17
SWEEPS = (("extent", r"svg_cubic_extent_1e(-?\d+)", "the cubic's extent (scale sweep)"),
          ("offset", r"svg_cubic_offset_1e(-?\d+)", "the cubic's offset from the origin (offset sweep)"))


class ShippedReportError(Exception):
    pass


def load(report_dir):
    """[(path, data)] of the peers_*.json files with "rows" (the shipped-software drivers' and
    lottie's), read by report_peers.load_peer_files; ShippedReportError naming a malformed one."""
    out = []
    for path, data in report_peers.load_peer_files(report_dir):
        if "rows" not in data and os.path.basename(path).startswith("peers_shipped_"):
            raise ShippedReportError(f"{path}: expected an object with a \"rows\" array")
        if "rows" not in data:
            continue  # another peer's file (its records are the Peers section's)
        if not isinstance(data["rows"], list):
            raise ShippedReportError(f"{path}: \"rows\" is not an array")
        for i, r in enumerate(data["rows"]):
            for key in ("peer", "case"):
                if not isinstance(r, dict) or not isinstance(r.get(key), str):
                    raise ShippedReportError(f"{path}: rows[{i}].{key}: expected a string")
        out.append((path, data))
    return out


def label(row):
    """The peer's name as the report shows it: peer id without "peer_", with its setting."""
    name = row["peer"][5:] if row["peer"].startswith("peer_") else row["peer"]
    return name + (f" ({row['setting']})" if row.get("setting") else "")


def ours(records, cases):
    """curvebench's rows on the same cases, in the peers' row format: the length method of
    OURS_LENGTH and, per case, the most accurate u(s) record (its error is |s(u) - s| / L, the
    peers' s_error)."""
    rows = []
    for case in sorted(cases):
        length = [r for r in records if r.get("case") == case and r.get("quantity") == "length"
                  and (r.get("method"), r.get("setting")) == OURS_LENGTH and not r.get("subject")]
        inv = [r for r in records if r.get("case") == case and r.get("quantity") == "u_of_s"
               and isinstance(r.get("error"), (int, float)) and not r.get("subject")]
        if not length and not inv:
            continue
        best_inv = min(inv, key=lambda r: r["error"]) if inv else None
        rows.append({"peer": "curvebench", "case": case, "setting": "",
                     "length_error": length[0]["error"] if length else None,
                     "s_error": best_inv["error"] if best_inv else None,
                     "s_method": f"{best_inv['method']} {best_inv['setting']}".strip() if best_inv else None,
                     "point_error": None, "spacing_cv": None, "ns_length": None, "ns_point": None, "ns_build": None})
    return rows


def _worst(rows, key):
    """(value, case) of the largest finite `key` over rows; None when no row has one."""
    have = [(r[key], r["case"]) for r in rows if isinstance(r.get(key), (int, float)) and math.isfinite(r[key])]
    return max(have) if have else None


def _median(rows, key):
    have = [r[key] for r in rows if isinstance(r.get(key), (int, float)) and math.isfinite(r[key])]
    return statistics.median(have) if have else None


def by_peer(rows):
    """{label: [rows]} in the order the peers first appear."""
    out = {}
    for r in rows:
        out.setdefault(label(r), []).append(r)
    return out


def summary_rows(rows):
    """Per peer and setting: cases, worst and median length error, worst point and s error, worst
    spacing CV, median times."""
    out = []
    for name, rs in by_peer(rows).items():
        def worst(key):
            w = _worst(rs, key)
            return f"{fmt(w[0])} ({w[1]})" if w else "-"
        build, point = _median(rs, "ns_build"), _median(rs, "ns_point")
        out.append([name, len(rs), worst("length_error"), fmt(_median(rs, "length_error")), worst("point_error"),
                    worst("s_error"), worst("spacing_cv"), fmt(_median(rs, "ns_length")), fmt(point), fmt(build),
                    fmt(build / point) if build and point else "-"])
    return out


def featured_table(rows, case):
    """[[engine, length, relative error]] of one case, the truth first."""
    rs = [r for r in rows if r["case"] == case and r.get("length") is not None]
    if not rs:
        return None
    truth = next((r["true_length"] for r in rs if r.get("true_length")), None)
    out = [["50-digit truth", f"{truth:.17g}" if truth else "-", "0"]]
    for r in sorted(rs, key=lambda r: (r.get("length_error") is None, r.get("length_error") or 0)):
        out.append([label(r), f"{r['length']:.10g}", fmt(r.get("length_error"))])
    return out


def sweep_series(rows, pattern):
    """{label: [(x, error)]} of the length errors on the sweep's cases (x = 10^k from the name)."""
    out = {}
    for r in rows:
        m = re.fullmatch(pattern, r["case"])
        if m and isinstance(r.get("length_error"), (int, float)):
            out.setdefault(label(r), []).append((10.0 ** int(m.group(1)), max(r["length_error"], FLOOR)))
    return {k: sorted(v) for k, v in out.items() if len(v) >= 2}


def findings(rows, ours_rows):
    """Sentences from the figures: each peer's worst length and point error with its case, the
    spread of the engines on the featured path, and curvebench's worst on the same cases."""
    out = []
    for name, rs in by_peer(rows).items():
        parts = []
        w = _worst(rs, "length_error")
        if w:
            parts.append(f"its worst length error is {fmt(w[0])} of L on {w[1]}")
        p = _worst(rs, "point_error")
        if p:
            parts.append(f"its worst point at length is {fmt(p[0])} of L from the true point, on {p[1]}")
        c = _worst(rs, "spacing_cv")
        if c:
            parts.append(f"its equally spaced points vary by a CV of {fmt(c[0])} (on {c[1]})")
        if parts:
            out.append(f"- **{name}** ({len(rs)} cases): " + "; ".join(parts) + ".")
    for case in FEATURED:
        lengths = [r["length"] for r in rows if r["case"] == case and r.get("length") is not None]
        truth = next((r["true_length"] for r in rows if r["case"] == case and r.get("true_length")), None)
        if len(lengths) >= 2 and truth:
            out.append(f"- On {case} (true length {truth:.10g}) the engines answer between {min(lengths):.10g} and "
                       f"{max(lengths):.10g}: a spread of {fmt((max(lengths) - min(lengths)) / truth)} of L.")
    wl, ws = _worst(ours_rows, "length_error"), _worst(ours_rows, "s_error")
    if wl or ws:
        out.append("- curvebench on the same cases: " + "; ".join(
            s for s in (f"adaptive_gk at tol 1e-10 is at most {fmt(wl[0])} off ({wl[1]})" if wl else "",
                        f"its most accurate u(s) at most {fmt(ws[0])} of L ({ws[1]})" if ws else "") if s) + ".")
    return out


def base_peer(row):
    """(the peer as the report names it, with a mode: a setting's first comma-separated part without
    "=" (three's "centripetal", lib2geom's "sbasis"), the rest of the setting)."""
    name = row["peer"][5:] if row["peer"].startswith("peer_") else row["peer"]
    parts = [p.strip() for p in (row.get("setting") or "").split(",") if p.strip()]
    if parts and "=" not in parts[0]:
        return f"{name} ({parts[0]})", ", ".join(parts[1:])
    return name, ", ".join(parts)


def accurate_settings(rows, targets=(1e-6, 1e-10)):
    """Per peer (without setting): its default setting's worst length error, and for each target the
    cheapest of its settings (by median ns per length) whose worst length error over every case it
    measured is at most the target: [[peer, cases, default worst, (setting, ns) per target...]].
    A setting is compared on the cases the default measured, so a setting that skips the hard ones
    does not pass."""
    out = []
    peers = {}
    for r in rows:
        if isinstance(r.get("length_error"), (int, float)):
            name, setting = base_peer(r)
            peers.setdefault(name, {}).setdefault(setting, []).append(r)
    for peer, settings in peers.items():
        default = settings.get("", next(iter(settings.values())))
        cases = {r["case"] for r in default}
        line = [peer, len(cases), fmt(_worst(default, "length_error")[0])]
        for target in targets:
            ok = []
            for setting, rs in settings.items():
                by_case = {r["case"]: r for r in rs}
                if not cases <= set(by_case):
                    continue
                worst = max(by_case[c]["length_error"] for c in cases)
                if worst <= target:
                    ok.append((_median(list(by_case.values()), "ns_length") or math.inf, setting or "default", worst))
            best = min(ok) if ok else None
            line.append(f"{best[1]} ({fmt(best[0])} ns)" if best else "no measured setting")
        out.append(line)
    return out


def tolerance_findings(rows):
    """Sentences naming every run whose length is outside the error bound its library documents."""
    out = []
    for name, rs in by_peer([r for r in rows if r.get("outside_tolerance")]).items():
        worst = max(rs, key=lambda r: abs(r["length"] - r["true_length"]) / r["documented_tolerance"])
        out.append(f"- **{name}** is outside its documented length tolerance on {len(rs)} case(s): on {worst['case']} "
                   f"it is {fmt(abs(worst['length'] - worst['true_length']))} off (absolute) where its documentation "
                   f"bounds the error by {fmt(worst['documented_tolerance'])}.")
    return out


def catmull_rom_rows(rows):
    """The rows of runs on Catmull-Rom cases (three's CatmullRomCurve3): those with eval_error."""
    return [r for r in rows if "eval_error" in r]


def catmull_rom_table(rows):
    """[[case, mode and divisions, length error, point error, getUtoTmapping s error, spacing CV,
    getPoint ulps, curvebench ulps, parameter rounding ulps, ns / length, ns / point]]."""
    return [[r["case"], r.get("setting") or "-", fmt(r.get("length_error")), fmt(r.get("point_error")),
             fmt(r.get("map_s_error")), fmt(r.get("spacing_cv")), fmt(r.get("eval_error")),
             fmt(r.get("curvebench_eval_error")), fmt(r.get("eval_floor")), fmt(r.get("ns_length")),
             fmt(r.get("ns_point"))] for r in sorted(rows, key=lambda r: (r["case"], r.get("ns_length") or 0))]


def catmull_rom_findings(rows):
    """Sentences on three's CatmullRomCurve3: its worst length error at its defaults and with the
    most divisions measured, and its getPoint against curvebench's evaluation."""
    if not rows:
        return []
    out = []
    default = [r for r in rows if "divisions=" not in (r.get("setting") or "")]
    w = _worst(default, "length_error")
    if w:
        seg = next((r for r in default if r["case"] == w[1]), {})
        out.append(f"- **three's CatmullRomCurve3** at its default 200 length divisions: worst length error "
                   f"{fmt(w[0])} of L "
                   f"on {w[1]} ({seg.get('setting')}); worst point at length {fmt(_worst(default, 'point_error')[0])} "
                   f"of L, its getUtoTmapping alone {fmt(_worst(default, 'map_s_error')[0])} of L.")
    finest = {}
    for r in rows:
        div = re.search(r"divisions=(\d+)", r.get("setting") or "")
        n = int(div.group(1)) if div else 200
        if r["case"] not in finest or n > finest[r["case"]][0]:
            finest[r["case"]] = (n, r)
    wf = _worst([r for _, r in finest.values()], "length_error")
    if wf:
        out.append(f"- With the most divisions measured per case the worst is {fmt(wf[0])} ({wf[1]}, "
                   f"{finest[wf[1]][1].get('setting')}): the table's chords, not the curve, set the error.")
    over = [r for r in rows if isinstance(r.get("eval_error"), (int, float))
            and isinstance(r.get("eval_floor"), (int, float))
            and r["eval_error"] > max(r["eval_floor"], r.get("curvebench_eval_error") or 0) + 4]
    we, wc = _worst(rows, "eval_error"), _worst(rows, "curvebench_eval_error")
    if we and wc:
        out.append(f"- Its getPoint(t) is the same curve as curvebench's Catmull-Rom through the same points: at most "
                   f"{fmt(we[0])} ulps of the curve's size from the 50-digit point ({we[1]}), curvebench's own double "
                   f"evaluation at most {fmt(wc[0])} ulps; "
                   + (f"{len(over)} run(s) exceed both curvebench's and the parameter's rounding by more than 4 ulps."
                      if over else
                      "no run exceeds both curvebench's and the parameter's own rounding by more than 4 ulps."))
    return out


def plot_sweeps(rows, ours_rows, plot_dir, plt, savefig, link_prefix="plots/"):
    """One log-log plot per sweep (relative length error against extent or offset, one line per
    peer and curvebench); [(title, path)] of those written."""
    written = []
    for name, pattern, title in SWEEPS:
        series = sweep_series(rows, pattern)
        mine = sweep_series([dict(r, length=0) for r in ours_rows], pattern)
        if not series:
            continue
        fig, ax = plt.subplots(figsize=(8, 4.5))
        lines = list(series.items()) + [("curvebench adaptive_gk tol=1e-10", v) for v in mine.values()]
        for i, (lbl, pts) in enumerate(lines):
            # Colours repeat after ten lines: the line style and marker tell the next ten apart.
            ax.plot([x for x, _ in pts], [e for _, e in pts], marker="os^D"[i // 10 % 4],
                    linestyle=("-", "--", ":", "-.")[i // 10 % 4], label=lbl,
                    linewidth=2.5 if lbl.startswith("curvebench") else 1.2)
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_xlabel(title)
        ax.set_ylabel("|L_peer - L| / L")
        ax.grid(True, which="both", alpha=0.3)
        ax.legend(fontsize=7, ncol=2)
        path = os.path.join(plot_dir, f"shipped_length_vs_{name}.png")
        savefig(fig, path)
        written.append((title, link_prefix + os.path.basename(path)))
    return written


def section(acc, report_dir, plot_dir=None, plt=None, savefig=None, link_prefix="plots/"):
    """The markdown lines of the section. With plt, its plots are drawn into plot_dir (report.py);
    without, the ones plot_dir already holds are linked as link_prefix + name (publish.py)."""
    md = ["", "## Arc length in shipped software", ""]
    try:
        files = load(report_dir)
    except (OSError, ShippedReportError, lib.ReportError) as e:
        return md + [f"The shipped-software results could not be read: {e}", ""]
    if not files:
        return md + ["Not run: no reports/peers_shipped_*.json (scripts/peers.sh runs the drivers: "
                     "scripts/peers/shipped_node_driver.mjs and scripts/peers/shipped_browser_driver.py).", ""]
    rows = [r for _, data in files for r in data["rows"]]
    cases = {r["case"] for r in rows}
    ours_rows = ours(acc.get("records", []), cases)
    md += ["What SVG engines and JavaScript libraries compute for a path's length, its point at a given length "
           "and its equally spaced points, on the SVG corpus (bench/cases/svg_*.json and every case SVG path data "
           "holds exactly), against the 50-digit reference (`curvebench check --at-length`: the distance of each "
           "returned point from the true point at that s, and the arc length of the curve's point nearest it). "
           "Errors are relative to the true length L; times are the drivers' own (best of repeated passes, per "
           "call; a build is the parse or table construction, timed apart).", ""]
    versions = [[os.path.basename(p), data.get("driver", "-"),
                 lib.versions_text(data.get("versions")), data.get("cpu", "-")]
                for p, data in files]
    md.append(table(["file", "driver", "versions", "CPU"], versions))
    cr_rows = catmull_rom_rows(rows)
    md += ["", "### Findings", ""] + findings(rows, ours_rows) + tolerance_findings(rows) + \
        catmull_rom_findings(cr_rows)
    md += ["", "### Every peer, worst case first", "",
           "Length error |L_peer - L| / L; point error |P_peer(s) - P(s)| / L over s = k L / 16; s error: how far "
           "along the curve the returned point is from s, / L; spacing: the coefficient of variation of the true "
           "arc lengths between its equally spaced points (0 is perfect). ns: medians over the cases; "
           "timed on a shared machine, compare within a driver's rows.", ""]
    md.append(table(["peer", "cases", "worst length error", "median", "worst point error", "worst s error",
                     "worst spacing CV", "ns / length", "ns / point", "ns / build", "build = points"],
                    summary_rows(rows)))
    md += ["", "\"build = points\": how many point queries cost as much as one build (the parse and, where the "
           "peer keeps one, its length table): the number of queries over which the build amortises."]
    md += ["", "### The setting that reaches 1e-6 and 1e-10", "",
           "Per peer: its defaults' worst length error, and the cheapest of its measured settings (median ns per "
           "length call) whose worst length error is within the target on every case its defaults measured.", ""]
    md.append(table(["peer", "cases", "default: worst length error", "reaches 1e-6", "reaches 1e-10"],
                    accurate_settings(rows)))
    if ours_rows:
        md += ["", "curvebench on the same cases (accuracy.json): adaptive_gk at tol=1e-10 for the length, the most "
               "accurate u(s) method of the run for the s error:", ""]
        md.append(table(["case", "length error", "u(s) error", "u(s) method"],
                        [[r["case"], fmt(r["length_error"]), fmt(r["s_error"]), r["s_method"] or "-"]
                         for r in ours_rows]))
    if cr_rows:
        md += ["", "### three.js CatmullRomCurve3 beside curvebench's Catmull-Rom", "",
               "The catmull_rom cases three draws as the same curve (its curveType matching the case's alpha; "
               "phantom or closed ends) through the same points. Length, point at length (getPointAt) and spacing "
               "(getSpacedPoints) as above; getUtoTmapping: |s(u) - s| / L at curvebench's parameter of the t it "
               "returns; getPoint: its point at t = k/32 against the 50-digit point of curvebench's spline at the "
               "same parameter, in ulps of double x the curve's size, beside curvebench's own double evaluation "
               "there and what rounding that parameter to a double moves the point by (errors under it are not "
               "three's).", ""]
        md.append(table(["case", "mode, divisions", "length error", "point error", "getUtoTmapping", "spacing CV",
                         "getPoint ulps", "curvebench ulps", "parameter rounding ulps", "ns / length", "ns / point"],
                        catmull_rom_table(cr_rows)))
    for case in FEATURED:
        t = featured_table(rows, case)
        if t:
            md += ["", f"### The length of {case} in every engine", ""]
            md.append(table(["engine", "length", "relative error"], t))
    if plot_dir and plt is not None:
        written = plot_sweeps(rows, ours_rows, plot_dir, plt, savefig, link_prefix)
    else:
        written = [(title, link_prefix + f"shipped_length_vs_{name}.png") for name, _, title in SWEEPS
                   if plot_dir and os.path.exists(os.path.join(plot_dir, f"shipped_length_vs_{name}.png"))]
    if written:
        md += ["", "### Error against the curve's extent and offset", "",
               f"Log-log, one line per peer; an absolute tolerance shows as a slope of -1 against the extent, "
               f"float32 coordinates as a rise with the offset. An error of exactly 0 is drawn at {FLOOR:g}.", ""]
        # As list items: docs/results.md's own gallery is its lines that start with "![" (publish.py).
        md += [f"- ![length error against {t}]({p})" for t, p in written]
    skipped = [s for _, data in files for s in data.get("skipped", [])]
    if skipped:
        md += ["", "Not measured (the peer cannot represent the case, or threw): " + "; ".join(
            f"{s.get('peer')} on {s.get('case')}: {s.get('reason')}" for s in skipped[:40])
            + (f"; and {len(skipped) - 40} more" if len(skipped) > 40 else "") + "."]
    return md + [""]
