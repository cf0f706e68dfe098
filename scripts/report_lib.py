"""The pure part of scripts/report.py: the vocabulary, benchmark rows checked against it, times per
operation, peers, error targets, the Pareto front and the join of accuracy records with per-case
timings. No plotting here (matplotlib is imported by report.py only), so tests/python runs these
with Debian's python3 alone.

The vocabulary is the JSON of `curvebench list vocabulary --json` (bench/harness/vocabulary.hpp):
  {"quantities": [{"id", "doc"}], "methods": [{"id", "quantities", "settings", "theory", "doc"}],
   "peers": [{"id", "library", "doc"}], "operations": [{"id", "doc"}],
   "counters": [{"name", "kind", "doc"}], "algorithms": [{"id", "settings", "doc"}],
   "variant_keys": [{"id", "values", "doc"}],
   "tools": [{"id", "storage_bits", "default_solver", "settings", "doc", "rules", "verification"}]}
A benchmark name is family/algorithm[/key:value]..., the algorithm a method, a peer, an algorithm
or a tool id; the per-case arc-length benchmarks are arclength_case/<case>/<method>/<setting>. Every
benchmark labels the operation it times and sets items processed, so its time per operation is
1e9 / items_per_second ns, whatever the number of operations per iteration.
"""
import json
import math
from collections import defaultdict

CASE_FAMILY = "arclength_case"
TARGETS = (1e-6, 1e-10, 1e-14)
# Google Benchmark's own fields in a benchmark entry; every other field is a counter.
BENCHMARK_FIELDS = frozenset((
    "name", "run_name", "run_type", "repetitions", "repetition_index", "threads", "iterations",
    "real_time", "cpu_time", "time_unit", "aggregate_name", "aggregate_unit", "family_index",
    "per_family_instance_index", "label", "items_per_second", "bytes_per_second", "error_occurred",
    "error_message", "big_o", "rms"))


def fmt(x, digits=3):
    """The one number format of the generated pages: `digits` significant digits, exponent form
    outside [1e-3, 1e4)."""
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
    """A Markdown table; cells through fmt."""
    out = ["| " + " | ".join(headers) + " |", "|" + "|".join("---" for _ in headers) + "|"]
    for r in rows:
        out.append("| " + " | ".join(fmt(c) for c in r) + " |")
    return "\n".join(out)


class ReportError(Exception):
    """A benchmark or record the vocabulary does not describe; the message names it."""


class Vocabulary:
    def __init__(self, data):
        try:
            self.quantities = {q["id"]: q for q in data["quantities"]}
            self.methods = {m["id"]: m for m in data["methods"]}
            self.peers = {p["id"]: p for p in data["peers"]}
            self.operations = {o["id"]: o for o in data["operations"]}
            self.counters = {c["name"]: c for c in data["counters"]}
            self.algorithms = {a["id"]: a for a in data.get("algorithms", [])}
            self.variant_keys = {k["id"]: set(k["values"]) for k in data.get("variant_keys", [])}
            self.tools = {t["id"]: t for t in data.get("tools", [])}
        except (KeyError, TypeError) as e:
            raise ReportError(f"vocabulary: malformed ({e!r} missing or wrong)") from e
        for p in self.peers:
            if not p.startswith("peer_"):
                raise ReportError(f"vocabulary: peer id '{p}' does not start with 'peer_'")
        # Keys naming a method's or an algorithm's setting: rows differing only in these (and in
        # variant keys) are ranked together; the remaining keys describe the data.
        self.setting_keys = set()
        for x in list(self.methods.values()) + list(self.algorithms.values()) + list(self.tools.values()):
            self.setting_keys.update(x.get("settings", []))

    def error_counters(self):
        return {n for n, c in self.counters.items() if c["kind"] == "error"}

    def target_counters(self):
        """Error counters relative to a length (targets 1e-6...): those not in eps units (*_eps)."""
        return {n for n in self.error_counters() if not n.endswith("_eps")}

    def is_peer(self, algorithm):
        return algorithm in self.peers


def load_vocabulary(path):
    with open(path, encoding="utf-8") as f:
        return Vocabulary(json.load(f))


def parse_args(name, parts):
    args = []
    for p in parts:
        key, sep, value = p.partition(":")
        if not sep or not key or not value:
            raise ReportError(f"benchmark {name}: '{p}' is not key:value")
        args.append((key, value))
    return args


def parse_benchmark_name(name, vocab):
    """{family, algorithm, args} (and case, setting for the per-case benchmarks) of a benchmark
    name, checked against the vocabulary: ReportError naming the benchmark otherwise."""
    parts = name.split("/")
    if len(parts) < 2:
        raise ReportError(f"benchmark {name}: not family/algorithm[/key:value]...")
    family = parts[0]
    row = {"family": family}
    if family == CASE_FAMILY:
        if len(parts) != 4:
            raise ReportError(f"benchmark {name}: not {CASE_FAMILY}/<case>/<method>/<setting>")
        row.update(case=parts[1], algorithm=parts[2], setting=parts[3], args=[])
        if parts[2] not in vocab.methods:
            raise ReportError(f"benchmark {name}: method '{parts[2]}' is not in the vocabulary")
    else:
        algorithm = parts[1]
        if (algorithm not in vocab.methods and algorithm not in vocab.peers and algorithm not in vocab.algorithms
                and algorithm not in vocab.tools):
            raise ReportError(f"benchmark {name}: algorithm '{algorithm}' is neither a method, a peer, an "
                              "algorithm nor a tool of the vocabulary")
        row.update(algorithm=algorithm, args=parse_args(name, parts[2:]))
        for key, value in row["args"]:
            if key in vocab.variant_keys and value not in vocab.variant_keys[key]:
                raise ReportError(f"benchmark {name}: {key}:{value} is not a variant of the vocabulary "
                                  f"(allowed: {' '.join(sorted(vocab.variant_keys[key]))})")
    return row


def benchmark_row(entry, vocab, program=""):
    """One Google Benchmark entry as a row, checked against the vocabulary (ReportError naming the
    benchmark otherwise), or None for an aggregate other than the median and for one repetition of
    a repeated benchmark (its median aggregate stands for them; `curvebench compare` reads them)."""
    if entry.get("run_type") == "aggregate" and entry.get("aggregate_name") != "median":
        return None
    if entry.get("run_type") == "iteration" and entry.get("repetitions", 1) > 1:
        return None
    name = entry.get("run_name", entry.get("name", "?"))
    if entry.get("error_occurred"):
        raise ReportError(f"benchmark {name}: failed: {entry.get('error_message', '')}")
    row = {"program": program, "name": name}
    row.update(parse_benchmark_name(name, vocab))
    label = entry.get("label", "")
    if label not in vocab.operations:
        raise ReportError(f"benchmark {name}: label '{label}' is not an operation of the vocabulary "
                          f"({', '.join(sorted(vocab.operations))})")
    rate = entry.get("items_per_second")
    if not isinstance(rate, (int, float)) or not rate > 0 or math.isinf(rate):
        raise ReportError(f"benchmark {name}: no items processed (per_operation not called)")
    counters = {}
    for k, v in entry.items():
        if k in BENCHMARK_FIELDS:
            continue
        if k not in vocab.counters:
            raise ReportError(f"benchmark {name}: counter '{k}' is not in the vocabulary")
        counters[k] = v
    unit = {"ns": 1.0, "us": 1e3, "ms": 1e6, "s": 1e9}[entry.get("time_unit", "ns")]
    row.update(operation=label, ns_per_op=1e9 / rate, ns_per_iteration=entry["cpu_time"] * unit,
               counters=counters)
    return row


def benchmark_rows(data, vocab, program=""):
    rows = []
    for entry in data.get("benchmarks", []):
        row = benchmark_row(entry, vocab, program)
        if row is not None:
            rows.append(row)
    return rows


def load_benchmark_files(paths, vocab):
    """(context, rows) of the bench_*.json files; ReportError on the first unknown name."""
    import os
    context, rows = {}, []
    for path in paths:
        with open(path, encoding="utf-8") as f:
            data = json.load(f)
        context = context or data.get("context", {})
        program = os.path.basename(path)[:-len(".json")] if path.endswith(".json") else os.path.basename(path)
        try:
            rows += benchmark_rows(data, vocab, program)
        except ReportError as e:
            raise ReportError(f"{os.path.basename(path)}: {e}") from e
    return context, rows


def args_text(args):
    return "/".join(f"{k}:{v}" for k, v in args)


def data_args(row, vocab):
    """The keys that describe the data (points, segments, ...): neither settings nor variants."""
    return tuple((k, v) for k, v in row["args"] if k not in vocab.setting_keys and k not in vocab.variant_keys)


def setting_args(row, vocab):
    """The method's or algorithm's own settings (n, tol, ...), without variants."""
    return tuple((k, v) for k, v in row["args"] if k in vocab.setting_keys)


def variant_args(row, vocab):
    return tuple((k, v) for k, v in row["args"] if k in vocab.variant_keys)


def display_algorithm(row, vocab):
    """The algorithm with its settings and variants: 'power calls:sorted', 'gauss n:8 estimate:none'."""
    extra = setting_args(row, vocab) + variant_args(row, vocab)
    return row["algorithm"] + ("" if not extra else " " + " ".join(f"{k}:{v}" for k, v in extra))


def speed_groups(rows, vocab):
    """{(family, operation, data args): rows}: the rows ranked together, all timing one operation."""
    groups = defaultdict(list)
    for r in rows:
        if r["family"] == CASE_FAMILY:
            continue
        groups[(r["family"], r["operation"], data_args(r, vocab))].append(r)
    return groups


def peer_pairs(rows, vocab):
    """[(ours, peer)]: each of our rows with each peer row of the same family, operation and data
    and the same settings (gauss n:10 with peer_boost_gauss n:10); rows of different operations are
    never paired."""
    pairs = []
    for _, rs in sorted(speed_groups(rows, vocab).items()):
        peers = [r for r in rs if vocab.is_peer(r["algorithm"])]
        for r in rs:
            if vocab.is_peer(r["algorithm"]):
                continue
            for p in peers:
                if setting_args(p, vocab) == setting_args(r, vocab):
                    pairs.append((r, p))
    return pairs


def headline_ratios(rows, vocab):
    """Per peer row: our fastest paired row and the ratio of times per operation (< 1: ours faster)."""
    best = {}
    for ours, peer in peer_pairs(rows, vocab):
        key = peer["name"]
        if key not in best or ours["ns_per_op"] < best[key][0]["ns_per_op"]:
            best[key] = (ours, peer)
    return [(o, p, o["ns_per_op"] / p["ns_per_op"]) for o, p in sorted(best.values(), key=lambda x: x[1]["name"])]


def error_of(row, vocab):
    """(counter, value) of the row's error counter (kind "error"), or (None, None)."""
    for k in sorted(vocab.error_counters()):
        if k in row["counters"]:
            return k, row["counters"][k]
    return None, None


def fastest_at_targets(rows, vocab, targets=TARGETS):
    """Per (family, operation, error counter) and target: the fastest row per operation reaching it
    and the fastest peer reaching it. Only relative error counters (not *_eps)."""
    fams = defaultdict(list)
    for r in rows:
        if r["family"] == CASE_FAMILY:
            continue
        kind, err = error_of(r, vocab)
        if kind in vocab.target_counters() and isinstance(err, (int, float)):
            fams[(r["family"], r["operation"], kind)].append((r, err))
    out = []
    for (family, operation, kind), rs in sorted(fams.items()):
        for t in targets:
            ok = [(r, e) for r, e in rs if e <= t]
            best = min(ok, key=lambda x: x[0]["ns_per_op"])[0] if ok else None
            peers = [r for r, _ in ok if vocab.is_peer(r["algorithm"])]
            best_peer = min(peers, key=lambda r: r["ns_per_op"]) if peers else None
            out.append({"family": family, "operation": operation, "counter": kind, "target": t,
                        "best": best, "best_peer": best_peer})
    return out


def pareto_front(points):
    """The (time, error, label) points no other point beats in both: by time, error strictly falling."""
    front, best = [], float("inf")
    for t, e, label in sorted(points):
        if e < best:
            front.append((t, e, label))
            best = e
    return front


def case_times(rows):
    """{(case, method, setting): ns per length} from the per-case benchmarks."""
    out = {}
    for r in rows:
        if r["family"] == CASE_FAMILY:
            if r["operation"] != "length":
                raise ReportError(f"benchmark {r['name']}: times '{r['operation']}', the join needs 'length'")
            out[(r["case"], r["algorithm"], r["setting"])] = r["ns_per_op"]
    return out


def join_lengths(records, times):
    """Length records (numeric error) joined with per-case times by (case, method, setting).
    Returns (joined, unmatched_records, unmatched_times, records_without_error): joined is
    {case: [(ns, error, method, setting)]}; nothing is dropped without being returned."""
    joined = defaultdict(list)
    unmatched_records, without_error = [], []
    used = set()
    for r in records:
        if r.get("quantity") != "length":
            continue
        key = (r["case"], r["method"], r["setting"])
        if not isinstance(r.get("error"), (int, float)):
            without_error.append(key)
            used.add(key)
            continue
        if key in times:
            joined[r["case"]].append((times[key], r["error"], r["method"], r["setting"]))
            used.add(key)
        else:
            unmatched_records.append(key)
    unmatched_times = sorted(k for k in times if k not in used)
    return dict(joined), sorted(unmatched_records), unmatched_times, sorted(without_error)


def validate_files(vocabulary_path, bench_paths):
    """Checks benchmark JSON files against the vocabulary; returns the number of rows checked."""
    vocab = load_vocabulary(vocabulary_path)
    _, rows = load_benchmark_files(bench_paths, vocab)
    if not rows:
        raise ReportError(f"no benchmarks in {', '.join(bench_paths)}")
    return len(rows)


def split_subjects(records):
    """(curvebench's own records, subject records): a subject is a user's implementation measured
    by `curvebench check` or the subject API (harness/subject.hpp), its records marked "subject": true."""
    own = [r for r in records if not r.get("subject")]
    return own, [r for r in records if r.get("subject")]


def subject_rows(own, subjects):
    """One row per subject record, beside curvebench's own records of the same case and quantity:
    [case, quantity, subject (method and setting), its error, curvebench's most accurate record
    (method setting), its error, curvebench's cheapest record at least as accurate as the subject
    (method setting, evaluations) or "none"]. Without own records of that case and quantity
    (a subject measured alone) the last three cells are "-"."""
    def label(r):
        return f"{r['method']} {r.get('setting') or ''}".strip()

    by_key = defaultdict(list)
    for r in own:
        if r.get("error") is not None:
            by_key[(r["case"], r["quantity"])].append(r)
    rows = []
    for s in sorted(subjects, key=lambda r: (r["case"], r["quantity"], r["method"], r.get("setting") or "")):
        err = s.get("error")
        mine = by_key.get((s["case"], s["quantity"]), [])
        if not mine:
            rows.append([s["case"], s["quantity"], label(s), err if err is not None else "-", "-", "-", "-"])
            continue
        best = min(mine, key=lambda r: r["error"])
        as_good = [r for r in mine if err is not None and r["error"] <= err]
        cheapest = min(as_good, key=lambda r: (r["evaluations"], r["error"])) if as_good else None
        rows.append([s["case"], s["quantity"], label(s), err if err is not None else "-", label(best), best["error"],
                     f"{label(cheapest)} ({cheapest['evaluations']:g} evals)" if cheapest else "none"])
    return rows


SPREAD_FLOOR = 2.0 ** -52  # errors below eps(double) are rounding: compared at eps


def method_spread(points):
    """How far apart the methods are at equal cost: points are (cost, error, method). The costs are
    put in bins of one decade (floor of log10 cost); in each bin each method counts with its smallest
    error (at least SPREAD_FLOOR); the spread of a bin is the largest of those errors over the
    smallest, and the case's is the largest over the bins holding at least two methods (1.0 when
    none does). The rule that picks the featured per-case plots (report.py, publish.py)."""
    bins = defaultdict(dict)
    for cost, error, method in points:
        if not (isinstance(cost, (int, float)) and cost > 0 and isinstance(error, (int, float))
                and math.isfinite(error)):
            continue
        b = bins[math.floor(math.log10(cost))]
        e = max(error, SPREAD_FLOOR)
        b[method] = min(e, b.get(method, math.inf))
    spreads = [max(b.values()) / min(b.values()) for b in bins.values() if len(b) >= 2]
    return max(spreads, default=1.0)


def featured_cases(per_case_points, count):
    """The `count` cases of {case: [(cost, error, method)]} with the largest method_spread, largest
    first (ties by name); [(case, spread)]."""
    ranked = sorted(((c, method_spread(p)) for c, p in per_case_points.items()), key=lambda cs: (-cs[1], cs[0]))
    return ranked[:count]


def versions_text(versions):
    """A driver's {library: version} as the report lists it ("chromium Chromium 156, firefox not
    run"): a null version is a peer the driver could not run (not installed), said so."""
    return ", ".join(f"{k} {v if v is not None else 'not run'}" for k, v in (versions or {}).items())


def segment_counts(acc):
    """{case: its segment count} from the accuracy document's cases list ("-" where one has none)."""
    return {c["name"]: c.get("segments", "-") for c in acc.get("cases", []) if "name" in c}


def table_per_segments(rows, segments):
    """u(s) on many segments: per case, the Hermite table sized per segment
    (bench_arclength_cases' u_of_s_build_case and u_of_s_case rows): its cells, build time and time
    per query, and the ratio of that time to the one-segment case's of the same run. Returns the
    Markdown lines (none when the run has no such rows)."""
    per_case = defaultdict(dict)
    for r in rows:
        if r["family"] not in ("u_of_s_case", "u_of_s_build_case"):
            continue
        args = dict(r["args"])
        per_case[args.get("case", "-")][r["family"]] = (r, args.get("tol", "-"))
    if not per_case:
        return []
    base = [c for c in sorted(per_case) if segments.get(c) == 1 and "u_of_s_case" in per_case[c]]
    base_ns = per_case[base[0]]["u_of_s_case"][0]["ns_per_op"] if base else None
    out = []
    for case in sorted(per_case, key=lambda c: (segments.get(c, 0) if isinstance(segments.get(c), int) else 0, c)):
        q = per_case[case].get("u_of_s_case")
        b = per_case[case].get("u_of_s_build_case")
        tol = (q or b)[1]
        cells = (q or b)[0]["counters"].get("table_intervals", "-")
        if isinstance(cells, float) and cells.is_integer():
            cells = int(cells)  # Google Benchmark writes counters as doubles
        ns = q[0]["ns_per_op"] if q else None
        out.append([case, segments.get(case, "-"), tol, cells, fmt(b[0]["ns_per_op"] / 1e6) if b else "-",
                    fmt(ns) if ns else "-", fmt(ns / base_ns) if ns and base_ns else "-"])
    md = ["### u(s) on many segments", "",
          "The Hermite table sized per segment to its target (tol, relative to L), per case: its cells, the time "
          "to build it and the time per query (1024 random targets, tables built beforehand), and that time over "
          + (f"the one-segment case {base[0]}'s in the same run." if base else
             "a one-segment case's (none in this run: no ratio).") + " The target is at most 2 on 1000 segments.",
          ""]
    md.append(table(["case", "segments", "tol", "cells", "build (ms)", "ns per query", "x one segment"], out))
    return md + [""]
