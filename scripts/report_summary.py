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
import report_checks
import report_lib as lib
import report_peers
import report_shipped

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


def _mean(values):
    return sum(values) / len(values) if values and all(_number(v) for v in values) else None


def reaching(candidates, cases, target, tiers, whole_group=True):
    """Every candidate reaching `target` on its cases, as `pick` describes them, each with its mean
    "query_evaluations" and "build_evaluations" over the cases (None unless every record carries
    both: the accuracy runner's u_of_s and s_of_u records, the cost of one query and of the set-up
    apart), cheapest first."""
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
                   "query_evaluations": _mean([r.get("query_evaluations") for r in recs]),
                   "build_evaluations": _mean([r.get("build_evaluations") for r in recs]),
                   # no estimate on some case: the target is met by the suite's measured error, not by
                   # a bound the method would report on the user's own curve
                   "unbounded": any(r.get("status") == "not_guaranteed" for r in recs)})
    for unit, cost in tiers:
        costs = [[cost(r) for r in c["_records"]] for c in ok]
        if ok and all(_number(x) for cs in costs for x in cs):
            for c, cs in zip(ok, costs):
                c["cost"], c["unit"] = sum(cs) / len(cs), unit
            break
    for c in ok:
        del c["_records"]
    return sorted(ok, key=lambda c: (-c["covered"], c["cost"] if c["cost"] is not None else 0.0, c["max_error"],
                                     c["method"], c["setting"]))


def pick(candidates, cases, target, tiers, whole_group=True):
    """The candidate reaching `target` on its cases, cheapest by the first tier of `tiers` that
    gives every such candidate a cost on every case, else the most accurate.

    candidates: {(method, setting): {case: record}}; cases: the group's cases. A candidate reaches
    the target when its relative error is at most the target on every case of the group it has a
    record of, and has one for every case (whole_group; a peer, whole_group=False, needs at least
    one: more cases covered rank first). Its cost is the mean over those cases. Returns None or
    {"method", "setting", "covered", "of", "max_error", "cost", "unit", "query_evaluations",
    "build_evaluations"} (cost and unit None when no tier applied); ties go to the smaller error,
    then the name."""
    ok = reaching(candidates, cases, target, tiers, whole_group)
    return ok[0] if ok else None


def by_query_count(choices):
    """Where a method built once (a table) competes with one that pays per query: the cheapest of
    `choices` (reaching's) in evaluations for N queries, build + N x query, as ranges of N:
    [{"from": N0, "choice": c}, ...] from N = 1 on, each choice cheapest from its "from" (the
    break-even query count: the build's extra evaluations over the per-query saving) to the next
    one's. None when some choice's records do not split the cost; one range when one choice is the
    cheapest whatever the count."""
    if not choices or any(not _number(c.get("build_evaluations")) or not _number(c.get("query_evaluations"))
                          for c in choices):
        return None

    def name(c):
        return (c["method"], c["setting"])
    n = 1.0
    current = min(choices, key=lambda c: (c["build_evaluations"] + n * c["query_evaluations"],
                                          c["query_evaluations"], name(c)))
    out = [{"from": n, "choice": current}]
    while True:
        nxt = None
        for c in choices:
            if c["query_evaluations"] < current["query_evaluations"]:
                at = max(n, (c["build_evaluations"] - current["build_evaluations"])
                         / (current["query_evaluations"] - c["query_evaluations"]))
                if nxt is None or (at, c["query_evaluations"], name(c)) < (nxt[0], nxt[1]["query_evaluations"],
                                                                           name(nxt[1])):
                    nxt = (at, c)
        if nxt is None:
            return out
        n, current = nxt
        out.append({"from": n, "choice": current})


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
    {"quantity", "group", "size", "cases", "cells": [{"target", "ours", "peer", "peers_ran",
    "by_queries", "split"}]}, ours and peer as `pick` returns them (None: none reaches it; ours with
    "note": tolerance_note), by_queries by_query_count's ranges over ours and the other methods
    reaching the target when more than one method is the cheapest for some query count (None
    otherwise), split whether the records carry the cost's two parts (query, build) at all, size
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
                all_mine = reaching(ours[key], cases, t, tiers)
                mine = all_mine[0] if all_mine else None
                for p in [peer] + all_mine:  # eval and channel records carry no estimate by nature: not said
                    if p and quantity not in EVALUATIONS_ARE_COSTS:
                        p["unbounded"] = False
                for p in all_mine:
                    p["note"] = tolerance_note(p, ours[key], t)
                ranges = by_query_count(all_mine) if quantity in EVALUATIONS_ARE_COSTS else None
                cells.append({"target": t, "ours": mine, "peer": peer, "peers_ran": key in theirs,
                              "by_queries": ranges if ranges and len(ranges) > 1 else None,
                              "split": ranges is not None})
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


def queries_text(n):
    """A query count as the answers say it: whole queries (2149.2 -> '2150') up to a million, lib.fmt's
    figures beyond."""
    return str(math.ceil(n)) if n < 1e6 else lib.fmt(float(n))


def ranges_text(ranges):
    """'newton tol=1e-12 (1e+03 evals a query, 5.00e+04 to build) up to 2150 queries, then
    hermite_table_sized tol=1e-12 (0 evals a query, 2.20e+06 to build)': by_query_count's ranges said."""
    parts = []
    for i, r in enumerate(ranges):
        c = r["choice"]
        label = f"{c['method']} {c['setting']}".strip()
        cost = f"{lib.fmt(c['query_evaluations'])} evals a query, {lib.fmt(c['build_evaluations'])} to build"
        until = f" up to {queries_text(ranges[i + 1]['from'])} queries" if i + 1 < len(ranges) else ""
        parts.append(f"{label} ({cost}){until}")
    return ", then ".join(parts)


def cell_text(cell):
    text = choice_text(cell["ours"]) if cell["ours"] else "none reaches it"
    if cell.get("by_queries"):
        text += "; by query count: " + ranges_text(cell["by_queries"])
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


# The sections the answers link to, by title (a link is dropped, its text kept, where the page has
# no such section: docs/results.md carries some of REPORT.md's).
SECTIONS = {"method": "The method to use for an error target", "shipped": "Arc length in shipped software",
            "peers": "Peers: the libraries users would pick instead", "fidelity": "Tool models against the real tools",
            "subjects": "Your implementations (subjects) beside curvebench's methods",
            "checks": report_checks.SECTION, "many": "u(s) on many segments"}
# The quantities of the shipped-software rows, by their column: what the engines are asked for.
SHIPPED_QUANTITIES = (("length", "length_error", "of L"), ("point at length", "point_error", "of L"),
                      ("s at length (how far along the returned point is)", "s_error", "of L"),
                      ("equal spacing", "spacing_cv", "coefficient of variation"))
PEER_QUANTITY_NAMES = {"length": "length", "s_of_u": "s(u)", "u_of_s": "u(s)", "eval": "evaluation",
                       "channel_value": "easing and keyframe values", "channel_time": "keyframe times"}
ANSWER_TARGET = 1e-10


def section_link(text, key):
    """A link to the section SECTIONS[key], resolved against the page by link_details."""
    return f"[{text}](#={key})"


def answer_lines(rows, target=ANSWER_TARGET):
    """One line per quantity and size class of recommendation_rows' rows: the answer at `target`
    for the kind of curve (group) with the most cases of that size, with the ranges by query count
    where a table competes with a per-query method. The README's headline and the summary's first
    answer both say these lines."""
    best = {}
    for r in rows:
        key = (r["quantity"], r.get("size"))
        if key not in best or r["cases"] > best[key]["cases"]:
            best[key] = r
    out = []
    for (quantity, size), r in best.items():
        cell = next((c for c in r["cells"] if c["target"] == target), None)
        if cell is None:
            continue
        text = choice_text(cell["ours"]) if cell["ours"] else "none reaches it"
        if cell.get("by_queries"):
            text += "; by query count: " + ranges_text(cell["by_queries"])
        cases = f"{r['cases']} case{'s' if r['cases'] != 1 else ''}"
        out.append(f"`{quantity}`, {size or 'any size'} ({r['group']}, {cases}): {text}")
    return out


def _default_rows(rows):
    """The shipped rows at a peer's defaults (no setting beyond its mode): what a user gets."""
    return [r for r in rows if not report_shipped.base_peer(r)[1]]


def engine_answer(shipped_rows, peer_records, own_records, drivers_ran):
    """The sentence on what the browsers, engines and libraries get wrong: per quantity the worst
    engine (its defaults) and by how much, from the shipped-software rows; per quantity the peer
    finding furthest past its promise; or that none were measured."""
    parts = []
    rows = _default_rows(shipped_rows) or shipped_rows
    for name, key, unit in SHIPPED_QUANTITIES:
        have = [r for r in rows if _number(r.get(key))]
        if have:
            w = max(have, key=lambda r: r[key])
            parts.append(f"{name}: worst {report_shipped.label(w)}, {lib.fmt(w[key])} {unit} on {w['case']}")
    worst = {}
    for g in report_peers.grouped_findings(peer_records, own_records):
        if g["quantity"] not in worst or g["worst"]["excess"] > worst[g["quantity"]]["worst"]["excess"]:
            worst[g["quantity"]] = g
    for quantity, g in sorted(worst.items()):
        where = g["case"] + (f" ({g['worst']['setting']})" if g["worst"]["setting"] else "")
        parts.append(f"{PEER_QUANTITY_NAMES.get(quantity, quantity)}: worst {g['peer']} on {where}: "
                     f"{g['worst']['text'].rstrip('.')}")
    if parts:
        text = "; ".join(parts) + "."
    elif shipped_rows or peer_records:
        text = "nothing past what each promised in this run."
    else:
        text = "none were measured in this run (no peer records and no reports/peers_*.json: scripts/peers.sh)."
    if not shipped_rows:
        text += " No browser or shipped engine was measured (no reports/peers_shipped_*.json)."
    if drivers_ran is not None and not drivers_ran and peer_records:
        text += " Only the accuracy runner's library peers ran."
    return text


def fidelity_answer(fidelity, tools):
    """Which tool models agree with every evaluated recording of the real tool, which do not (how
    many channels disagree, the largest error), which have none."""
    recordings = (fidelity or {}).get("recordings") or []
    if not recordings:
        return "none measured in this run (no reports/fidelity.json: `curvebench fidelity --json`)."
    by_tool = defaultdict(lambda: [0, 0, 0.0])
    for r in recordings:
        t = by_tool[r["tool"]]
        t[0] += r["agree"]
        t[1] += r["channels"] - r["refused"] - r.get("unverified", 0)
        t[2] = max(t[2], r["max_error"]) if _number(r.get("max_error")) else t[2]
    verified = [f"{tool} ({a} of {n} channels)" for tool, (a, n, _) in sorted(by_tool.items()) if n and a == n]
    off = [f"{tool} ({n - a} of {n} channels disagree, largest error {lib.fmt(e)} x scale)"
           for tool, (a, n, e) in sorted(by_tool.items()) if a < n]
    missing = [t for t in tools if t not in by_tool and t != report_channel.REFERENCE_TOOL]
    parts = [("verified against every recording: " + ", ".join(verified)) if verified else "none verified"]
    if off:
        parts.append("not verified: " + ", ".join(off))
    if missing:
        parts.append("no recording of the real tool: " + ", ".join(missing))
    return "; ".join(parts) + "."


def subjects_answer(subjects):
    """Per implementation (the records' method) its records and its largest error per quantity, in
    the unit the check printed it in where the record says ("unit", "error_in_unit": a values or
    times check's), else the record's own (eval in ulps of double x size, the others / L)."""
    by = defaultdict(lambda: defaultdict(list))
    for r in subjects:
        if isinstance(r.get("unit"), str) and _number(r.get("error_in_unit")):
            by[r["method"]][f"{r['quantity']} ({r['unit']})"].append(r["error_in_unit"])
        elif _number(r.get("error")):
            by[r["method"]][r["quantity"]].append(r["error"])

    def worst(q, es):
        return f"{q} max {lib.fmt(max(es))} ({len(es)} record{'s' if len(es) > 1 else ''})"
    return "; ".join(f"{m}: " + ", ".join(worst(q, es) for q, es in sorted(qs.items()))
                     for m, qs in sorted(by.items())) + "."


def answers(rows, shipped_rows, peer_records, own_records, fidelity, tools, subjects=(), checks=(),
            drivers_ran=None):
    """The summary's opening: one short answer per question a user brings, each linking to the
    section that holds its figures."""
    md = ["### The answers", ""]
    if rows:
        md.append(f"- **Which method for my error target?** At {target_text(ANSWER_TARGET)}, for the kind of curve "
                  "with the most cases of each size: every kind, size and target is in "
                  + section_link("the table below", "method") + " (and " + section_link("u(s) on many segments",
                                                                                        "many") + ").")
        md += [f"  - {line}" for line in answer_lines(rows)]
    else:
        md.append("- **Which method for my error target?** This run has no records of curvebench's own methods (no "
                  "accuracy.json, or one without records): nothing to recommend.")
    md.append("- **What does each browser, engine and library get wrong, and by how much?** "
              + engine_answer(shipped_rows, peer_records, own_records, drivers_ran) + " See "
              + section_link("Arc length in shipped software", "shipped") + " and "
              + section_link("Peers", "peers") + ".")
    md.append("- **Which tool models are verified against the real tools?** " + fidelity_answer(fidelity, tools)
              + " See " + section_link("Tool models against the real tools", "fidelity") + ".")
    if subjects or checks:
        text = []
        if checks:
            text.append(report_checks.summary_text(checks) + " See " + section_link("your checks", "checks") + ".")
        if subjects:
            text.append(f"{len(subjects)} records of your implementations: " + subjects_answer(subjects) + " See "
                        + section_link("your implementations beside curvebench's", "subjects") + ".")
        md.append("- **How did my own implementations do?** " + " ".join(text))
    return md + [""]


def many_segments_answer(rows):
    """The answer for u(s) on curves of 100+ segments, per kind of curve and target, from
    recommendation_rows' rows (the summary's): the lines the "u(s) on many segments" section opens
    with, so that it cannot name another method than the summary does."""
    mine = [r for r in rows if r["quantity"] == "u_of_s" and r.get("size") == SIZE_CLASSES[2]]
    if not mine:
        return ["No `u_of_s` accuracy records of curves with 100+ segments in this run: the timings below are of "
                "the sized Hermite table alone, not a recommendation."]
    out = [f"The method to use on {SIZE_CLASSES[2]}, as the Summary answers it (the accuracy records; the "
           "timings below are of one method, the sized Hermite table):", ""]
    for r in mine:
        for c in r["cells"]:
            out.append(f"- {r['group']} ({r['cases']} case{'s' if r['cases'] != 1 else ''}), error <= "
                       f"{target_text(c['target'])}: {cell_text(dict(c, peers_ran=False))}")
    return out + [""]


def with_many_segments_answer(section, rows):
    """report_lib.table_per_segments' lines (its "### " heading first) with many_segments_answer
    after the heading; none when the section has none (no such benchmarks)."""
    if not section:
        return []
    return section[:2] + many_segments_answer(rows) + section[2:]


def resolve_section_links(lines, page=None):
    """lines with each section_link [text](#=KEY) made a link to the anchor of the "## " section
    SECTIONS[KEY] of `page` (default: lines), or of its "### " heading for the summary's own table
    ("method"), or its text alone where the page has none."""
    found = {}
    for _, level, text, a in headings(flat(page if page is not None else lines)):
        found.setdefault((level, text), a)

    def resolve(m):
        key = m.group(2)
        a = found.get((3 if key == "method" else 2, SECTIONS.get(key)))
        return f"[{m.group(1)}](#{a})" if a else m.group(1)
    return [re.sub(r"\[([^\]]*)\]\(#=([a-z_]+)\)", resolve, line) for line in flat(lines)]


def run_recommendations(acc, bench_rows):
    """recommendation_rows of a run's files: acc the accuracy document (its records, subjects left
    out, its peer records, its cases' groups and segment counts), bench_rows every benchmark row.
    The one source of every recommendation the pages make (REPORT.md's summary, docs/results.md,
    the README's headline through publish.py)."""
    records, _ = lib.split_subjects(acc.get("records", []))
    segments = {c["name"]: c.get("segments") for c in acc.get("cases", []) if "name" in c}
    return recommendation_rows(records, list(acc.get("peer_records", [])), lib.case_times(bench_rows),
                               report_channel.bench_times(bench_rows),
                               {c["name"]: c.get("group") for c in acc.get("cases", [])}, case_segments=segments)


def summary_of_run(acc, report_dir, bench_rows, vocab, fidelity, checks=()):
    """The Summary section of a run's files (REPORT.md and docs/results.md alike): acc the accuracy
    document, bench_rows every benchmark row (the per-case timings included), fidelity
    reports/fidelity.json's document or None, checks report_checks.load's files (--checks)."""
    records, subjects = lib.split_subjects(acc.get("records", []))
    subjects = subjects + report_checks.records(checks)
    drivers_ran = None
    try:
        files = report_peers.load_peer_files(report_dir)
        peer_records = report_peers.all_peer_records(acc, files)
        drivers_ran = [data.get("driver") for _, data in files]
    except (OSError, lib.ReportError):  # the Peers section says why
        peer_records = list(acc.get("peer_records", []))
    try:
        shipped = [r for _, data in report_shipped.load(report_dir) for r in data["rows"]]
    except (OSError, lib.ReportError, report_shipped.ShippedReportError):  # its section says why
        shipped = []
    return summary_section(records, peer_records, lib.case_times(bench_rows), report_channel.bench_times(bench_rows),
                           {c["name"]: c.get("group") for c in acc.get("cases", [])}, fidelity,
                           report_channel.tool_names(vocab),
                           {c["name"]: c.get("segments") for c in acc.get("cases", []) if "name" in c},
                           shipped_rows=shipped, subjects=subjects, checks=checks, drivers_ran=drivers_ran)


def summary_section(records, peer_records, times, channel_times, case_groups, fidelity, tools, case_segments=None,
                    shipped_rows=(), subjects=(), checks=(), drivers_ran=None):
    """The markdown lines of the "Summary" section: the answers (one per question), then the
    recommendation table, each peer's worst finding and each tool model's fidelity."""
    rows = recommendation_rows(records, peer_records, times, channel_times, case_groups,
                               case_segments=case_segments)
    md = ["## Summary", "",
          "The answers of this run, from its own figures; the sections below hold every figure behind them.", ""]
    md += answers(rows, shipped_rows, peer_records, records, fidelity, tools, subjects, checks, drivers_ran)
    md += ["### The method to use for an error target", "",
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
           "setting\" when the run has no looser setting of that method, else its measured max error.",
           "- Where a table built once competes with a method that pays per query (`s_of_u`, `u_of_s`), "
           "\"by query count\" gives the cheapest for N queries, build + N x query evaluations, as ranges: "
           "each switch is at the break-even count, the build's extra evaluations over the per-query saving "
           "(the records' `build_evaluations` and `query_evaluations`). The choice before it is the cheapest at "
           "the records' amortization of the build over 1000 queries.", ""]
    if rows:
        md.append(recommendation_table(rows))
        if any(r["quantity"] in ("s_of_u", "u_of_s") for r in rows) and \
                not any(c.get("split") for r in rows for c in r["cells"]):
            md += ["", "This run's `s_of_u` and `u_of_s` records do not carry `build_evaluations` and "
                   "`query_evaluations` apart (an accuracy run of an older curvebench): no break-even query count."]
    elif subjects or checks:
        md.append("No records of curvebench's own methods in this run: nothing to recommend; your own results are "
                  "answered above.")
    else:
        md.append("No accuracy records.")
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


def link_details(page, later=()):
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
    # later: headings the page will have after its end (docs/results.md's fidelity block)
    return resolve_section_links(out, out + list(later))
