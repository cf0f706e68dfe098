"""The summary at the top of REPORT.md and its table of contents ("the answers first").

Built from the run's figures alone, with no name or number written in here:
  - per quantity, kind of curve (the records' "group") and size class (the case's segment count:
    1, 2-99, 100+), curvebench's cheapest method and setting whose error is at most 1e-6, 1e-10 and
    1e-14 on every case of the group of that size, and the best peer reaching the same on every case
    it ran on (recommendation_rows); a choice whose tol is looser than the target says why it
    reaches it (tolerance_note);
  - per peer, its worst finding (report_peers.grouped_findings; peer_lines);
  - per tool model, how it agrees with the recordings of the real tool (fidelity.json; fidelity_lines);
  - the table of contents: a link to every "## " section (toc).
Pure functions: tests/python/test_report_summary.py runs them with Debian's python3 alone.
"""
import math
import re
from collections import defaultdict

import report_channel
import report_lib as lib
import report_peers

EPS64 = 2.0 ** -52

# The quantities summarized, in this order, each with what its error is relative to. The targets
# are relative errors: eval records are in eps(double) x the curve's size, channel_value records in
# eps of their precision (setting bits=64 or bits=32) x the value range, so both are scaled first.
QUANTITIES = {
    "length": "the length L",
    "s_of_u": "L",
    "u_of_s": "L",
    "eval": "the curve's size",
    "channel_value": "the value range",
}
# Quantities whose records' evaluations are the cost of one result (amortized over the queries for
# s(u) and u(s)); eval's and channel_value's count the sample points, the same for every method.
EVALUATIONS_ARE_COSTS = ("length", "s_of_u", "u_of_s")


def _number(x):
    return isinstance(x, (int, float)) and not isinstance(x, bool) and math.isfinite(x)


def relative_error(r):
    """The record's error relative to what QUANTITIES says, or None (no numeric error, or a
    quantity the summary does not hold)."""
    q, e = r.get("quantity"), r.get("error")
    if q not in QUANTITIES or not _number(e):
        return None
    if q == "eval":
        return e * EPS64
    if q == "channel_value":
        bits = report_channel.bits_of(r.get("setting") or "")
        return report_channel.relative_to_range(e, bits) if bits in report_channel.EPS else None
    return e


def _derivative(r):
    """A peer's eval record of a derivative (setting derivative=k, k > 0): curvebench's eval records
    are of values, so these are left out of the comparison."""
    for item in (r.get("setting") or "").split(","):
        k, _, v = item.partition("=")
        if k == "derivative" and v not in ("", "0"):
            return True
    return False


def own_cost_tiers(quantity, records, times, channel_times):
    """[(unit, cost of a record)] in order of preference for curvebench's records of `quantity`:
    the measured time where the benchmarks join the record (length: bench_arclength_cases by case,
    method and setting; channel_value: bench_channel's 64 keys, single calls, by solver and bits),
    then evaluations (channel_value: the time solver's, from the channel_time record of the same
    case, solver and bits). eval has none: its records count sample points, not a cost."""
    def evals(r):
        return r.get("evaluations")
    if quantity == "length":
        return [("ns", lambda r: times.get((r["case"], r["method"], r.get("setting") or ""))), ("evals", evals)]
    if quantity in EVALUATIONS_ARE_COSTS:
        return [("evals", evals)]
    if quantity == "channel_value":
        solver = {(r["case"], r["method"], r.get("setting") or ""): r.get("evaluations")
                  for r in records if r.get("quantity") == "channel_time"}
        return [("ns", lambda r: channel_times.get((r["method"], "64", report_channel.bits_of(r.get("setting") or ""),
                                                    "single"))),
                ("evals", lambda r: solver.get((r["case"], r["method"], r.get("setting") or "")))]
    return []


def peer_cost_tiers(quantity):
    """A peer's own time per operation (the accuracy runner's or its driver's), then evaluations."""
    tiers = [("ns", lambda r: r.get("ns_per_op"))]
    if quantity in EVALUATIONS_ARE_COSTS:
        tiers.append(("evals", lambda r: r.get("evaluations")))
    return tiers


def pick(candidates, cases, target, tiers, whole_group=True):
    """The candidate reaching `target` on its cases, cheapest by the first tier of `tiers` that
    gives every such candidate a cost on every case, else the most accurate.

    candidates: {(method, setting): {case: record}}; cases: the group's cases. A candidate reaches
    the target when its relative error is at most the target on every case of the group it has a
    record of, and has one for every case (whole_group; a peer, whole_group=False, needs at least
    one: more cases covered rank first). Its cost is the mean over those cases. Returns None or
    {"method", "setting", "covered", "of", "max_error", "cost", "unit"} (cost and unit None when no
    tier applied); ties go to the smaller error, then the name."""
    ok = []
    for (method, setting), by_case in candidates.items():
        covered = [c for c in cases if c in by_case]
        if not covered or (whole_group and len(covered) < len(cases)):
            continue
        errors = [relative_error(by_case[c]) for c in covered]
        if any(e is None or not e <= target for e in errors):
            continue
        recs = [by_case[c] for c in covered]
        ok.append({"method": method, "setting": setting, "covered": len(covered), "of": len(cases),
                   "max_error": max(errors), "cost": None, "unit": None, "_records": recs,
                   # no estimate on some case: the target is met by the suite's measured error, not by
                   # a bound the method would report on the user's own curve
                   "unbounded": any(r.get("status") == "not_guaranteed" for r in recs)})
    if not ok:
        return None
    for unit, cost in tiers:
        costs = [[cost(r) for r in c["_records"]] for c in ok]
        if all(_number(x) for cs in costs for x in cs):
            for c, cs in zip(ok, costs):
                c["cost"], c["unit"] = sum(cs) / len(cs), unit
            break
    best = min(ok, key=lambda c: (-c["covered"], c["cost"] if c["cost"] is not None else 0.0, c["max_error"],
                                  c["method"], c["setting"]))
    del best["_records"]
    return best


# The sizes of curve the recommendations are given for, by the case's segment count, so that a user
# with a 1000-segment spline reads the answer for curves of that size.
SIZE_CLASSES = ("1 segment", "2-99 segments", "100+ segments")


def size_class(segments):
    """The SIZE_CLASSES entry of a segment count, or None (no count)."""
    if not _number(segments) or segments < 1:
        return None
    return SIZE_CLASSES[0] if segments < 2 else SIZE_CLASSES[1] if segments < 100 else SIZE_CLASSES[2]


def _size_rank(size):
    return SIZE_CLASSES.index(size) if size in SIZE_CLASSES else len(SIZE_CLASSES)


def _by_group(records, quantity, case_groups, case_segments=None):
    """{(group, size class): {(method, setting): {case: record}}} of the records of `quantity`; the
    size class from case_segments ({case: segment count}; None where it has none)."""
    case_segments = case_segments or {}
    out = defaultdict(lambda: defaultdict(dict))
    for r in records:
        if r.get("quantity") != quantity:
            continue
        group = r.get("group") or case_groups.get(r["case"])
        if group:
            key = (group, size_class(case_segments.get(r["case"])))
            out[key][(r["method"], r.get("setting") or "")][r["case"]] = r
    return out


def _tolerance(setting):
    """The value of a setting's tol key ("tol=1e-06" -> 1e-06), or None."""
    for item in (setting or "").split(","):
        k, _, v = item.partition("=")
        if k == "tol":
            try:
                return float(v)
            except ValueError:
                return None
    return None


def tolerance_note(choice, candidates, target):
    """Why a choice whose tolerance is looser than the target reaches it, from the figures alone:
    "reaches it at its loosest setting" when no setting of the method in `candidates` ({(method,
    setting): ...}) asks for less, else its measured max error; None when its setting has no tol or
    one at most the target."""
    tol = _tolerance(choice["setting"])
    if tol is None or not tol > target:
        return None
    loosest = max((t for t in (_tolerance(st) for m, st in candidates if m == choice["method"]) if t is not None),
                  default=tol)
    if tol >= loosest:
        return "reaches it at its loosest setting"
    return f"tol looser than the target, measured max error {lib.fmt(choice['max_error'])}"


def recommendation_rows(records, peer_records, times=None, channel_times=None, case_groups=None,
                        targets=lib.TARGETS, case_segments=None):
    """One row per quantity (QUANTITIES, those the records carry), group and size class:
    {"quantity", "group", "size", "cases", "cells": [{"target", "ours", "peer", "peers_ran"}]}, ours
    and peer as `pick` returns them (None: none reaches it; ours with "note": tolerance_note), size
    the SIZE_CLASSES entry of the cases' segment counts (None without counts), peers_ran whether any
    peer has a record of that quantity, group and size. records: curvebench's own (subjects split
    off); peer_records: the accuracy runner's and the drivers'; times: report_lib.case_times;
    channel_times: report_channel.bench_times; case_groups: {case: group} for records without one;
    case_segments: {case: segment count} (the accuracy document's cases)."""
    times, channel_times, case_groups = times or {}, channel_times or {}, case_groups or {}
    present = {r.get("quantity") for r in records}
    comparable_peers = [r for r in peer_records if not (r.get("quantity") == "eval" and _derivative(r))]
    rows = []
    for quantity in (q for q in QUANTITIES if q in present):
        ours = _by_group(records, quantity, case_groups, case_segments)
        theirs = _by_group(comparable_peers, quantity, case_groups, case_segments)
        tiers = own_cost_tiers(quantity, records, times, channel_times)
        group_cases = defaultdict(set)
        for (group, _), by_setting in ours.items():
            group_cases[group] |= {c for by_case in by_setting.values() for c in by_case}
        # the groups with the most cases first: the kinds of curve the suite holds most of; then sizes
        for key in sorted(ours, key=lambda k: (-len(group_cases[k[0]]), k[0], _size_rank(k[1]))):
            cases = sorted({c for by_case in ours[key].values() for c in by_case})
            peer_cases = sorted(set(cases) | {c for by_case in theirs.get(key, {}).values() for c in by_case})
            cells = []
            for t in targets:
                peer = pick(theirs[key], peer_cases, t, peer_cost_tiers(quantity), whole_group=False) \
                    if key in theirs else None
                mine = pick(ours[key], cases, t, tiers)
                for p in (mine, peer):  # eval and channel records carry no estimate by nature: not said
                    if p and quantity not in EVALUATIONS_ARE_COSTS:
                        p["unbounded"] = False
                if mine:
                    mine["note"] = tolerance_note(mine, ours[key], t)
                cells.append({"target": t, "ours": mine, "peer": peer, "peers_ran": key in theirs})
            rows.append({"quantity": quantity, "group": key[0], "size": key[1], "cases": len(cases), "cells": cells})
    return rows


def target_text(t):
    """1e-06 as 1e-6: the targets as the issue and the docs write them."""
    mantissa, _, exponent = f"{t:.0e}".partition("e")
    return f"{mantissa}e{int(exponent)}"


def choice_text(p):
    """'gauss n=8 (312 ns)', 'default (max 1.1e-16)', 'peer_x tol=1e-06 (4.1e3 ns, 3 of 19 cases)'."""
    label = f"{p['method']} {p['setting']}".strip()
    extra = [f"{lib.fmt(p['cost'])} {p['unit']}" if p["cost"] is not None else f"max {lib.fmt(p['max_error'])}"]
    if p["covered"] < p["of"]:
        extra.append(f"{p['covered']} of {p['of']} cases")
    if p.get("unbounded"):
        extra.append("no error bound")
    if p.get("note"):
        extra.append(p["note"])
    return f"{label} ({', '.join(extra)})"


def cell_text(cell):
    text = choice_text(cell["ours"]) if cell["ours"] else "none reaches it"
    if cell["peers_ran"]:
        text += "; peer: " + (choice_text(cell["peer"]) if cell["peer"] else "none reaches it")
    return text


def recommendation_table(rows, targets=lib.TARGETS):
    return lib.table(["quantity", "kind of curve (group)", "size", "cases"]
                     + [f"error <= {target_text(t)}" for t in targets],
                     [[f"`{r['quantity']}`", r["group"], r.get("size") or "-", r["cases"]]
                      + [cell_text(c) for c in r["cells"]] for r in rows])


def peer_lines(peer_records, own_records=()):
    """One line per peer that has records: its library, how many grouped findings on how many
    cases, and the worst of them (the largest excess: furthest past what the peer promised), or
    that it has none."""
    groups = report_peers.grouped_findings(peer_records, own_records)
    library = {}
    for r in peer_records:
        library.setdefault(r["method"], r.get("library") or "")
    lines = []
    for peer in sorted(library, key=lambda p: (library[p], p)):
        mine = [g for g in groups if g["peer"] == peer]
        head = f"- {peer}" + (f" ({library[peer]})" if library[peer] else "")
        if not mine:
            lines.append(f"{head}: no finding in this run.")
            continue
        worst = max(mine, key=lambda g: g["worst"]["excess"])["worst"]
        cases = len({g["case"] for g in mine})
        where = f"{worst['case']}" + (f" ({worst['setting']})" if worst["setting"] else "")
        lines.append(f"{head}: {len(mine)} finding{'s' if len(mine) > 1 else ''} on {cases} "
                     f"case{'s' if cases > 1 else ''}; the worst on {where}: {worst['text']}")
    return lines


def fidelity_lines(fidelity, tools=()):
    """One line per tool recorded in fidelity.json (`curvebench fidelity --json`): channels that
    agree of those evaluated, refused and unverified ones, the largest error and the recordings;
    then the tools of `tools` (vocabulary ids, the reference "exact" left out) with no recording."""
    recordings = (fidelity or {}).get("recordings") or []
    if not recordings:
        return ["No recordings of the real tools were measured in this run (no fidelity.json)."]
    by_tool = defaultdict(list)
    for r in recordings:
        by_tool[r["tool"]].append(r)
    order = [t for t in tools if t in by_tool] + sorted(t for t in by_tool if t not in tools)
    lines = []
    for tool in order:
        rs = by_tool[tool]
        channels = sum(r["channels"] for r in rs)
        refused = sum(r["refused"] for r in rs)
        unverified = sum(r.get("unverified", 0) for r in rs)
        agree = sum(r["agree"] for r in rs)
        worst = max(r["max_error"] for r in rs)
        notes = [f"{n} {what}" for n, what in ((refused, "refused"), (unverified, "unverified")) if n]
        files = ", ".join(r["file"].replace("\\", "/").rsplit("/", 1)[-1] for r in rs)
        lines.append(f"- {tool}: {agree} of {channels - refused - unverified} channels agree"
                     + (f" ({', '.join(notes)})" if notes else "")
                     + f", largest error {lib.fmt(worst)} x scale ({files})")
    missing = [t for t in tools if t not in by_tool and t != report_channel.REFERENCE_TOOL]
    if missing:
        lines.append(f"- no recording of the real tool in this run: {', '.join(missing)}")
    return lines


def summary_of_run(acc, report_dir, bench_rows, vocab, fidelity):
    """The Summary section of a run's files (REPORT.md and docs/results.md alike): acc the accuracy
    document, bench_rows every benchmark row (the per-case timings included), fidelity
    reports/fidelity.json's document or None."""
    records, _ = lib.split_subjects(acc.get("records", []))
    try:
        peer_records = report_peers.all_peer_records(acc, report_peers.load_peer_files(report_dir))
    except (OSError, lib.ReportError):  # the Peers section says why
        peer_records = list(acc.get("peer_records", []))
    return summary_section(records, peer_records, lib.case_times(bench_rows), report_channel.bench_times(bench_rows),
                           {c["name"]: c.get("group") for c in acc.get("cases", [])}, fidelity,
                           report_channel.tool_names(vocab),
                           {c["name"]: c.get("segments") for c in acc.get("cases", []) if "name" in c})


def summary_section(records, peer_records, times, channel_times, case_groups, fidelity, tools, case_segments=None):
    """The markdown lines of the "Summary" section."""
    md = ["## Summary", "",
          "The answers of this run, from its own figures; the sections below hold every figure behind them.", "",
          "### The method to use for an error target", "",
          "Per quantity, kind of curve (the cases' group) and size (the cases' segment count: "
          + ", ".join(f"{c}" for c in SIZE_CLASSES) + "), curvebench's cheapest method and setting whose error "
          "is at most the target on every case of the group of that size; after \"peer:\", the best peer reaching "
          "it on every case it ran on. Read the row of your kind and size of curve: the answer for one segment "
          "need not hold for a thousand.", "",
          "- Errors are relative: " + "; ".join(f"`{q}` to {what}" for q, what in QUANTITIES.items())
          + " (`eval` records are in eps(double) x size, `channel_value` records in eps x range of their precision, "
          "`bits=64` double or `bits=32` float: both are multiplied by that eps).",
          "- Cheapest is the lowest mean cost over the group's cases, and the unit says which cost: ns, measured, "
          "when every method reaching the target has a time on every case (`length`: bench_arclength_cases, "
          "joined by case, method and setting; `channel_value`: bench_channel's 64 keys, single calls, one time "
          "for every case); otherwise evals, curve evaluations per length or per query (tables amortized), for "
          "`channel_value` the time solver's per value. `eval` records have no cost per method (their "
          "evaluations count the sample points): the most accurate is named, with its max error.",
          "- A peer that ran on fewer cases than the group has says on how many; more cases rank first, then its "
          "own time per operation (the accuracy runner's or its driver's clock, not the benchmarks': compare "
          "peers with each other), else evaluations. Its derivative records are left out (curvebench's `eval` "
          "records are of values).",
          "- A choice whose tolerance (`tol`) is looser than the target says so: \"reaches it at its loosest "
          "setting\" when the run has no looser setting of that method, else its measured max error.", ""]
    rows = recommendation_rows(records, peer_records, times, channel_times, case_groups,
                               case_segments=case_segments)
    md.append(recommendation_table(rows) if rows else "No accuracy records.")
    left = sorted({r.get("quantity") for r in records} - set(QUANTITIES) - {None})
    if left:
        md += ["", "Not in this table (no relative error to hold to a target): "
               + ", ".join(f"`{q}`" for q in left) + "; see their sections."]
    md += ["", "### Peers: the worst finding of each", ""]
    if peer_records:
        md += ["Findings counted as the Peers section groups them (one per peer, defect and case, whatever the "
               "settings); the worst is the one furthest past what the peer promised: the tolerance asked for, its own "
               "error estimate (at least eps(double)), the precision it documents, or "
               f"{lib.fmt(report_peers.EVAL_FINDING_ULPS)} eps(double) x size for an evaluation.", ""]
        md += peer_lines(peer_records, records)
    else:
        md.append("No peer records in this run.")
    md += ["", "### Tool models against the real tools", ""]
    md += fidelity_lines(fidelity, tools)
    return md + [""]


def anchor(heading):
    """GitHub's anchor of a heading: lowercase, punctuation but '-' and '_' dropped, each space a '-'."""
    return "".join(c if c.isalnum() or c in "-_" else "-" if c == " " else "" for c in heading.strip().lower())


def flat(lines):
    """The report's lines one per line (an entry of the report's lists may hold a whole table)."""
    return "\n".join(lines).split("\n") if lines else []


def headings(lines):
    """(index, level, text, anchor) of every heading of lines (any level, outside ``` fences), in
    order; index counts the lines of flat(lines). GitHub's anchors: a repeated one gets -1, -2, ...
    in the order of the page, whatever the levels (so a "### X" in the summary and a later "## X"
    section get x and x-1). The one reading of headings: the contents, the summary's links and
    report_html.py's page all take them from here."""
    seen = defaultdict(int)
    out, fenced = [], False
    for index, line in enumerate(flat(lines)):
        if line.startswith("```"):
            fenced = not fenced
            continue
        m = None if fenced else re.match(r"^(#{1,6}) (.*)$", line)
        if not m:
            continue
        text = m.group(2).strip()
        a = anchor(text)
        n = seen[a]
        seen[a] += 1
        out.append((index, len(m.group(1)), text, f"{a}-{n}" if n else a))
    return out


def heading_anchors(lines):
    """The anchors of headings(lines), in order (report_html.py gives them to the page's headings)."""
    return [a for _, _, _, a in headings(lines)]


def toc(before, after, title="Contents"):
    """The "## Contents" section that goes between the lines `before` and `after`: a link to every
    "## " heading of both but its own, with the anchors GitHub gives them in the whole page."""
    found = headings(before + [f"## {title}"] + after)
    own = len(headings(before))  # the index of its own heading
    links = [f"- [{text}](#{a})" for i, (_, level, text, a) in enumerate(found) if level == 2 and i != own]
    return [f"## {title}", ""] + links + [""]


# Where the figures behind each subsection of the summary are: "### " subsection -> the "## "
# sections that hold them, linked when the page has them (REPORT.md has all, docs/results.md some).
DETAILS = {
    "The method to use for an error target": (
        "Arc length: error vs cost", "s(u): error vs cost", "Inversion u(s): error vs cost",
        "Evaluation-algorithm accuracy", "Keyframe channels: time solvers and tool models", "Speed per operation",
        "Arc length per case: fastest method reaching each relative error", "Evaluation algorithms"),
    "Peers: the worst finding of each": ("Peers: the libraries users would pick instead",),
    "Tool models against the real tools": ("Tool models against the real tools",),
}


def link_details(page):
    """The page's lines with a "Details:" line closing each subsection of its "## Summary": links to
    the sections (DETAILS) of the same page that hold the subsection's figures. Inserting lines that
    are not headings leaves every anchor as it was."""
    page = flat(page)
    found = headings(page)
    sections = {text: a for _, level, text, a in found if level == 2}
    at = {index: (level, text) for index, level, text, _ in found if level in (2, 3)}
    out, in_summary, pending = [], False, None

    def close():
        links = [f"[{t}](#{sections[t]})" for t in DETAILS.get(pending, ()) if t in sections]
        if links:
            if out and out[-1] != "":
                out.append("")
            out.extend(["Details: " + ", ".join(links) + ".", ""])
    for index, line in enumerate(page):
        level, text = at.get(index, (None, None))
        if level and in_summary:
            close()
            pending = None
            if level == 2:
                in_summary = False
            else:
                pending = text
        if level == 2 and text == "Summary":
            in_summary = True
        out.append(line)
    if in_summary:
        close()
    return out
