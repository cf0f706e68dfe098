"""The "Peers" section of REPORT.md: the libraries users would pick instead of
curvebench, measured on the same cases against the same 50-digit references, error and time
beside curvebench's own, and the findings where a peer does not do what its documentation says.

Inputs:
  accuracy.json      "peer_records" (the C++ peers the accuracy runner always runs: GSL,
                     Boost.Math and Eigen, by bench/harness/sweep_peers*.cpp) and context.peers (their versions); an
                     accuracy.json without peer records (older runs) gives a section saying so
  peers_*.json       one per optional peer driver (scripts/peers.sh): {"driver", "versions":
                     {library: version}, "notes": [text], "peer_records": [...]}, built by
                     scripts/peers/peer_results.py from the driver's output and `curvebench check`
  bench_*.json rows  Google Benchmark rows (report_lib.load_benchmark_files): the peers' speed
                     ratios measured in the same benchmark run as curvebench's
A peer record has the accuracy record's fields (case, group, quantity, method = the peer id,
setting, error, estimate, bounded, evaluations, status) plus "peer": true, "library",
"peer_status" (the library's own word for how it ended), "ns_per_op" and, where measured,
"counterpart" {"method", "setting"} (curvebench's record of the same computation) and
"counterpart_ns_per_op" (timed back to back with the peer). Pure functions but peers_section's
file reading; no plotting, so tests/python runs them with Debian's python3 alone.
"""
import glob
import json
import math
import os
import re
from collections import defaultdict

import report_lib as lib

# An evaluation finding: a peer interpolating the case's own data in double whose values (or
# derivatives) are this many eps(double) x size away from the exact curve has lost digits to its
# algorithm, not to rounding: curvebench's default evaluation and GSL's cspline stay below 1 on
# every case of the suite (a quick run), and SciPy's CubicSpline below 6.
EVAL_FINDING_ULPS = 100.0
EPS_DOUBLE = 2.0 ** -52

# The optional peers scripts/peers.sh runs, by the driver name their peers_<driver>.json carries.
OPTIONAL_DRIVERS = {"scipy": "SciPy (scripts/peers/scipy_driver.py)",
                    "easing": ("bezier-easing 3.2.0 / 2.1.0, @mapbox/unitbezier, Babylon.js's "
                               "BezierCurve.Interpolate and lottie-web's BezierEaser "
                               "(scripts/peers/easing_driver.mjs)"),
                    "chromium": ("headless Chromium, CSS easing through the Web Animations API "
                                 "(scripts/peers/chromium_driver.py)"),
                    "penner": "d3-ease's Penner easings (scripts/peers/penner_driver.mjs)",
                    "blender": "real Blender F-curves (scripts/peers/blender_channels.py; needs blender on PATH)",
                    "three": "three.js's glTF interpolants (scripts/peers/gltf_driver.mjs)",
                    "shipped_node": ("arc length in npm libraries: bezier-js, svg-path-properties, paper, "
                                     "svg-path-commander, three.js curves, canvaskit-wasm (Skia), Babylon.js "
                                     "(scripts/peers/shipped_node_driver.mjs)"),
                    "shipped_browser": ("SVG getTotalLength / getPointAtLength in headless Chromium and Firefox ESR "
                                        "(scripts/peers/shipped_browser_driver.py)"),
                    "lottie": ("lottie-web's position along a spatial Bezier with eased timing, in headless Chromium "
                               "(scripts/peers/lottie_driver.py)"),
                    "qt": ("Qt 5's QPainterPath length / percentAtLength / pointAtPercent and QEasingCurve "
                           "(bench/peers/qt, CURVEBENCH_PEER_QT)"),
                    "occt": "OpenCASCADE's GCPnts length and abscissa (bench/peers/occt, CURVEBENCH_PEER_OCCT)",
                    "lib2geom": ("lib2geom's bezier_length, SBasis length and arc_length_parametrization "
                                 "(bench/peers/lib2geom, CURVEBENCH_PEER_2GEOM)"),
                    "fonttools": ("fontTools' calcCubicArcLength and approximateCubicArcLength "
                                  "(scripts/peers/fonttools_driver.py)"),
                    "blender_length": ("Blender's Spline.calc_length and Follow Path "
                                       "(scripts/peers/blender_length_driver.py; needs blender on PATH)"),
                    "godot": ("Godot 3's Curve2D baked length and points, and bezier tracks "
                              "(scripts/peers/godot_driver.py; needs godot3-server)")}


def load_peer_files(report_dir):
    """[(path, data)] of every reports/peers_*.json, sorted by name. A file that is not a JSON
    object with a "peer_records" array raises lib.ReportError naming it."""
    out = []
    for path in sorted(glob.glob(os.path.join(report_dir, "peers_*.json"))):
        with open(path, encoding="utf-8") as f:
            try:
                data = json.load(f)
            except json.JSONDecodeError as e:
                raise lib.ReportError(f"{path}: not JSON ({e})") from e
        if not isinstance(data, dict) or not isinstance(data.get("peer_records"), list):
            raise lib.ReportError(f"{path}: expected an object with a \"peer_records\" array")
        for i, r in enumerate(data["peer_records"]):
            for key in ("case", "quantity", "method"):
                if not isinstance(r, dict) or not isinstance(r.get(key), str):
                    raise lib.ReportError(f"{path}: peer_records[{i}].{key}: expected a string")
        out.append((path, data))
    return out


def all_peer_records(acc, peer_files):
    """The accuracy runner's peer records followed by those of every peers_*.json."""
    records = list(acc.get("peer_records", []))
    for _, data in peer_files:
        records += data["peer_records"]
    return records


def version_rows(acc, peer_files):
    """[[libraries with versions, where they ran, records]]: one row per peer library the runner
    ran, one per driver file (its versions in the driver's order: the peers first)."""
    counts = defaultdict(int)
    for r in acc.get("peer_records", []):
        counts[r.get("library", "").split(" ")[0]] += 1
    rows = [[lib.versions_text({lib_name: version}), "accuracy runner (always)", counts.get(lib_name, 0)]
            for lib_name, version in sorted(acc.get("context", {}).get("peers", {}).items())]
    for path, data in peer_files:
        versions = lib.versions_text(data.get("versions"))
        # The shipped-software drivers' measurements are rows of their own section (report_shipped.py).
        rows.append([versions, f"{os.path.basename(path)} (scripts/peers.sh)",
                     len(data["peer_records"]) + len(data.get("rows", []))])
    return rows


def missing_drivers(peer_files):
    """The optional drivers with no peers_<driver>.json."""
    ran = {data.get("driver") for _, data in peer_files}
    return [doc for name, doc in sorted(OPTIONAL_DRIVERS.items()) if name not in ran]


def _key(r):
    return (r["case"], r["quantity"], r["method"], r.get("setting") or "")


def _counterpart(r, own):
    c = r.get("counterpart")
    if not c:
        return None
    return own.get((r["case"], r["quantity"], c["method"], c.get("setting") or ""))


def _own_index(records):
    return {_key(r): r for r in records if not r.get("subject")}


def _ratio(ours, theirs):
    if isinstance(ours, (int, float)) and isinstance(theirs, (int, float)) and theirs > 0:
        return ours / theirs
    return None


def _ns_of_counterparts(peer_records):
    """{(case, quantity, method, setting): ns} of curvebench's counterparts timed by any peer record
    (the accuracy runner times them back to back with its peers), for peers timed elsewhere."""
    out = {}
    for r in peer_records:
        c = r.get("counterpart")
        if c and isinstance(r.get("counterpart_ns_per_op"), (int, float)):
            out.setdefault((r["case"], r["quantity"], c["method"], c.get("setting") or ""), r["counterpart_ns_per_op"])
    return out


def eval_rows(records, peer_records):
    """[case, peer (setting), peer's error, curvebench's counterpart, its error, peer ns, ours ns,
    ours / peer] for every eval peer record; errors in eps(double) x the curve's size."""
    own = _own_index(records)
    timed = _ns_of_counterparts(peer_records)
    rows = []
    for r in sorted((r for r in peer_records if r["quantity"] == "eval"), key=_key):
        c = _counterpart(r, own)
        ours_ns = r.get("counterpart_ns_per_op")
        if not isinstance(ours_ns, (int, float)) and r.get("counterpart"):
            k = r["counterpart"]
            ours_ns = timed.get((r["case"], "eval", k["method"], k.get("setting") or ""))
        label = f"{r['method']} {r.get('setting') or ''}".strip()
        if c is None and r.get("counterpart") and "counterpart_error" in r:  # measured by the driver's join
            k = r["counterpart"]
            c = {"method": f"{k['method']} {k.get('setting') or ''}".strip(), "error": r["counterpart_error"]}
        rows.append([r["case"], label, r.get("error"), c["method"] if c else "-", c.get("error") if c else None,
                     r.get("ns_per_op"), ours_ns, _ratio(ours_ns, r.get("ns_per_op"))])
    return rows


def length_rows(records, peer_records, quantity="length"):
    """[case, setting, peer, its error, estimate, bounded, evaluations, status (library's words),
    curvebench's counterpart error, its evaluations, peer ns, ours ns, ours / peer] per peer record
    of `quantity` ("length", or "u_of_s": the same columns) with a value (refused settings are
    listed by refusals); errors relative to the reference length."""
    own = _own_index(records)
    timed = _ns_of_counterparts(peer_records)
    rows = []
    for r in sorted((r for r in peer_records if r["quantity"] == quantity and r.get("error") is not None),
                    key=lambda r: (r["case"], r["method"], _tol(r) or 0)):
        c = _counterpart(r, own)
        ours_ns = r.get("counterpart_ns_per_op")
        if not isinstance(ours_ns, (int, float)) and r.get("counterpart"):  # a driver's peer: the runner's time
            k = r["counterpart"]
            ours_ns = timed.get((r["case"], quantity, k["method"], k.get("setting") or ""))
        rows.append([r["case"], r.get("setting") or "-", r["method"], r.get("error"), r.get("estimate"),
                     r.get("bounded"), r.get("evaluations"), r.get("peer_status") or r.get("status"),
                     c.get("error") if c else None, c.get("evaluations") if c else None,
                     r.get("ns_per_op"), ours_ns, _ratio(ours_ns, r.get("ns_per_op"))])
    return rows


def _tol(r):
    m = re.search(r"(?:^|,)tol=([^,]+)", r.get("setting") or "")
    try:
        return float(m.group(1)) if m else None
    except ValueError:
        return None


def finding_items(peer_records, own_records=()):
    """Where a peer disagrees with its documentation, one item per record and defect: a length (or
    u(s)) reported as successful (status converged) whose true error exceeds the relative tolerance it
    was asked for (QUADPACK's documented target |result - L| <= epsrel L with epsabs 0; kind
    "beyond_tolerance"); an error estimate that does not bound the true error ("estimate_under"); an
    evaluation (value or derivative) at least EVAL_FINDING_ULPS eps(double) x size from the exact
    curve ("eval_error"), with curvebench's default evaluation of the same case beside it when
    own_records has it; a value beyond the precision the peer documents ("beyond_documented"); NaN or
    infinite values among an evaluation's ("non_finite": the record's count, excess infinite).
    Each item: {"peer", "case", "quantity", "setting", "kind", "text" (the sentence after
    "<peer> on <case> (<setting>): "), "excess" (how many times the defect exceeds what the peer
    promised: the tolerance, its own estimate, EVAL_FINDING_ULPS, its documented precision; the
    measure of "worst"; an estimate below eps(double) counts as eps(double), as a relative error
    below the result's rounding says nothing of the method)}. Sorted by case, quantity, peer and
    setting."""
    out = []

    def add(r, kind, text, excess):
        out.append({"peer": r["method"], "case": r["case"], "quantity": r["quantity"],
                    "setting": r.get("setting") or "", "kind": kind, "text": text, "excess": excess})
    for r in sorted(peer_records, key=_key):
        err, est, tol = r.get("error"), r.get("estimate"), _tol(r)
        if r["quantity"] in ("length", "u_of_s") and tol is not None and isinstance(err, (int, float)):
            if r.get("status") == "converged" and err > tol:
                add(r, "beyond_tolerance", f"reported success, but its true relative error {lib.fmt(err)} is "
                    f"{lib.fmt(err / tol)} times the requested tolerance {lib.fmt(tol)}.", err / tol)
        doc_tol, abs_err = r.get("documented_tolerance"), r.get("abs_error")
        # a peer evaluating in float ("unit_eps": 2^-23) is held to as many of its own ulps
        own_ulps = err * 2.0 ** -52 / r["unit_eps"] if isinstance(err, (int, float)) and r.get("unit_eps") else err
        if (r["quantity"] == "eval" and isinstance(err, (int, float)) and own_ulps >= EVAL_FINDING_ULPS
                and doc_tol is None):  # a peer with a documented precision is held to that instead
            what = f"derivative of order {r['setting'].split('=')[-1]}" if r.get("setting") else "values"
            against = f"{r['definition']} at 50 digits" if r.get("definition") else "the exact curve of the same data"
            if isinstance(r.get("counterpart_error"), (int, float)):
                beside = f" ({r['counterpart']['method']}: {lib.fmt(r['counterpart_error'])})"
            else:  # curvebench's eval records are of values only: no figure beside a derivative
                own = [o for o in own_records if not r.get("setting") and o["case"] == r["case"]
                       and o["quantity"] == "eval" and o["method"] == "default"]
                beside = f" (curvebench's default evaluation: {lib.fmt(own[0]['error'])})" if own else ""
            absolute = f", {lib.fmt(abs_err)} absolute" if isinstance(abs_err, (int, float)) else ""
            add(r, "eval_error", f"error {lib.fmt(err)} eps(double) x size{absolute} in its {what} against "
                f"{against}{beside}.", own_ulps / EVAL_FINDING_ULPS)
        if isinstance(doc_tol, (int, float)) and isinstance(abs_err, (int, float)) and abs_err > doc_tol:
            add(r, "beyond_documented", f"absolute error {lib.fmt(abs_err)} in its value ({lib.fmt(err)} eps(double) "
                f"x size), beyond the {lib.fmt(doc_tol)} it documents as its solver's precision.",
                abs_err / doc_tol if doc_tol > 0 else math.inf)
        if isinstance(r.get("non_finite"), int) and r["non_finite"] > 0:  # a NaN or infinity among its values
            measured = (f"; its error {lib.fmt(err)} eps(double) x size is over the others"
                        if isinstance(err, (int, float)) else "")
            add(r, "non_finite", f"{r['non_finite']} of {r.get('evaluations')} values not finite (NaN or infinity)"
                f"{measured}.", math.inf)
        if r.get("bounded") is False and isinstance(err, (int, float)) and isinstance(est, (int, float)):
            under = f"under by {lib.fmt(err / est)}x; " if est > 0 else ""  # not "under by infx" for an estimate 0
            add(r, "estimate_under", f"its error estimate {lib.fmt(est)} does not bound its true error {lib.fmt(err)} "
                f"({under}status \"{r.get('peer_status') or r.get('status')}\").", err / max(est, EPS_DOUBLE))
    return out


def _where(item, settings=None):
    return f"{item['peer']} on {item['case']}" + (f" ({settings})" if settings else "")


def findings(peer_records, own_records=()):
    """finding_items as sentences, one per record and defect: "<peer> on <case> (<setting>): <text>"."""
    return [f"{_where(i, i['setting'])}: {i['text']}" for i in finding_items(peer_records, own_records)]


def settings_text(settings):
    """The settings a grouped finding holds for, in the order given (the sweep's): the one setting;
    "tol=1e-06, 1e-10" or "tol=1e-06 .. 1e-14, 5 settings" when every setting is key=value with the
    same key (a range from three on); otherwise the settings themselves ("no setting" for ""), the
    first and last of them from three on."""
    if len(settings) == 1:
        return settings[0]
    parts = [s.split("=", 1) if "=" in s and "," not in s else None for s in settings]
    same_key = all(p is not None and p[0] == parts[0][0] for p in parts)
    shown = [p[1] for p in parts] if same_key else [s or "no setting" for s in settings]
    prefix = f"{parts[0][0]}=" if same_key else ""
    sep = ", " if same_key else "; "
    if len(settings) == 2:
        return prefix + sep.join(shown)
    return f"{prefix}{shown[0]} .. {shown[-1]}, {len(settings)} settings"


def grouped_findings(peer_records, own_records=()):
    """finding_items grouped: one per (peer, quantity, defect kind, case), whatever the settings it
    holds for. Each: {"peer", "case", "quantity", "kind", "settings" (in the order of the peer's
    records: the sweep's), "worst" (the item of the largest excess; the first of equals), "line"}.
    A line reads as the one finding's when it holds for one setting; otherwise it names the settings
    and the worst one, with the worst one's figures. Sorted by case, quantity, peer, kind."""
    order = {}
    for i, r in enumerate(peer_records):
        order.setdefault((r["method"], r.get("setting") or ""), i)
    groups = {}
    for item in finding_items(peer_records, own_records):
        g = groups.setdefault((item["case"], item["quantity"], item["peer"], item["kind"]), [])
        g.append(item)
    out = []
    for (case, quantity, peer, kind), items in sorted(groups.items()):
        items.sort(key=lambda i: order.get((i["peer"], i["setting"]), len(order)))
        settings = list(dict.fromkeys(i["setting"] for i in items))
        worst = max(items, key=lambda i: i["excess"])  # max returns the first of equals
        if len(settings) == 1:
            where = settings[0]
        else:
            where = f"{settings_text(settings)}; worst at {worst['setting'] or 'no setting'}"
        out.append({"peer": peer, "case": case, "quantity": quantity, "kind": kind, "settings": settings,
                    "worst": worst, "where": where, "line": f"{_where(worst, where)}: {worst['text']}"})
    return out


def refusals(peer_records):
    """Settings a peer refused to compute (no value, the library's status kept), one line per peer
    and status with the cases: documented behaviour, listed so that a missing row is explained."""
    by = defaultdict(set)
    for r in peer_records:
        if r.get("error") is None and r.get("peer_status"):
            by[(r["method"], r.get("setting") or "", r["peer_status"])].add(r["case"])
    return [f"{m}{' ' + st if st else ''}: \"{status}\" on {len(cases)} case(s)"
            for (m, st, status), cases in sorted(by.items())]


def honesty_rows(peer_records):
    """[peer, quantity, results with an estimate, estimates >= true error, share] per peer."""
    stats = defaultdict(lambda: [0, 0])
    for r in peer_records:
        if isinstance(r.get("bounded"), bool):
            s = stats[(r["method"], r["quantity"])]
            s[0] += 1
            s[1] += 1 if r["bounded"] else 0
    return [[m, q, n, b, f"{100.0 * b / n:.1f}%"] for (m, q), (n, b) in sorted(stats.items())]


def speed_rows(bench_rows, vocab, libraries):
    """Headline ratios (report_lib.headline_ratios) of the benchmark rows whose peer belongs to one
    of `libraries` (the vocabulary's library names, "GSL"): [family, data, ours, peer, ours ns per
    op, peer ns per op, ours / peer]. Peers timed without an accuracy record (GSL's akima and
    steffen, which no curvebench family equals) are listed too."""
    rows = []
    for o, p, ratio in lib.headline_ratios(bench_rows, vocab):
        if vocab.peers.get(p["algorithm"], {}).get("library") in libraries:
            rows.append([o["family"], lib.args_text(lib.data_args(o, vocab)) or "-", lib.display_algorithm(o, vocab),
                         lib.display_algorithm(p, vocab), o["ns_per_op"], p["ns_per_op"], ratio])
    return rows


def blender_rows(data):
    """[case, Blender version, times, of them compared with the exact keys, max |Blender - model|,
    max |Blender - exact keys|] per channel of a peers_blender.json (scripts/peers/blender_channels.py)."""
    version = data.get("versions", {}).get("Blender", "?")
    return [[c["case"], version, c.get("times"), c.get("compared_with_exact"), c.get("vs_model"), c.get("vs_exact")]
            for c in data.get("channels", [])]


def blender_lines(peer_files):
    """The "Real Blender" subsection: per channel case, real Blender against curvebench's Blender
    model and against the 50-digit evaluation of the same keys; "not run" without the file."""
    md = ["", "### Real Blender F-curves", ""]
    data = next((d for _, d in peer_files if d.get("driver") == "blender"), None)
    if data is None:
        return md + ["Not run: no reports/peers_blender.json "
                     "(scripts/peers.sh runs Blender when `blender` is on PATH)."]
    md += ["The channel cases a Blender F-curve can hold, evaluated by Blender itself (fcurve.evaluate, float) at the "
           "same times as curvebench's Blender model (float, `curvebench sample`); the exact keys are the keys and "
           "handles Blender reports, their Bezier segments evaluated at 50 digits inside the key range (Blender "
           "corrects overreaching handles before it evaluates; the exact keys do not, so a correction shows there). "
           "Absolute value differences.", ""]
    md.append(lib.table(["case", "Blender", "times", "compared with exact keys", "max |Blender - curvebench model|",
                         "max |Blender - exact keys|"], blender_rows(data)))
    return md


# three evaluates from the float32 keys it holds into a float32 result: an error within one
# eps(float32) of the truth of those keys is the result's rounding plus a few double roundings.
THREE_STORAGE_ONLY = 1.0


def three_rows(data):
    """[case, interpolation, three's interpolant, times, max error vs truth in eps(float32), in
    radians (rotations; None for a scalar), vs the truth of the float32 keys in eps(float32), max
    |three - curvebench model|] per case of a peers_three.json (scripts/peers/gltf_results.py)."""
    return [[c["case"] + (" (rotation)" if c.get("path") == "rotation" else ""), c.get("interpolation"),
             c.get("interpolant"), c.get("times"), c.get("error_eps32"), c.get("max_angle_rad"),
             c.get("vs_float32_keys_eps32"), c.get("vs_model")] for c in data.get("cases", [])]


def three_lines(peer_files):
    """The "three.js glTF interpolants" subsection: per glTF case, three's values against the glTF
    2.0 sampler at 60 digits and against curvebench's gltf model; "not run" without the file."""
    md = ["", "### three.js glTF interpolants", ""]
    data = next((d for _, d in peer_files if d.get("driver") == "three"), None)
    if data is None:
        return md + ["Not run: no reports/peers_three.json (scripts/peers.sh runs it when build-peers/node has three)."]
    rows = three_rows(data)
    version = data.get("versions", {}).get("three", "?")
    md += [f"The glTF channel cases written as GLBs (float32 accessors) and loaded by three {version}'s "
           "GLTFLoader, each track evaluated by its own interpolant (float32 results), against the glTF 2.0 sampler of "
           "the case's keys at 60 digits (clamped outside them). Error: a scalar's in eps(float32) x the largest "
           "|value|, a rotation's as the angle between the rotations (radians, and in eps(float32)); the same against "
           "the truth of the keys rounded to float32 separates evaluation from storage; the difference from "
           "curvebench's model (double; a scalar's absolute, a rotation's angle in radians)."
           + _three_finding(rows), ""]
    md.append(lib.table(["case", "interpolation", "three interpolant", "times", "max error (eps float32)",
                         "max angle (rad)", "vs float32 keys (eps float32)",
                         "max difference from curvebench model"], rows))
    return md


def _three_finding(rows):
    """The run's largest errors in one sentence, with what they show when the evaluation from the
    float32 keys three holds stays within THREE_STORAGE_ONLY eps(float32); "" without figures."""
    errs = [(r[4], r[6]) for r in rows]
    if not errs or any(not isinstance(e, (int, float)) or not isinstance(k, (int, float)) for e, k in errs):
        return ""
    worst, worst32 = max(e for e, _ in errs), max(k for _, k in errs)
    text = (f" In this run the largest error is {lib.fmt(worst)} eps(float32) against the keys as written and "
            f"{lib.fmt(worst32)} against the keys rounded to float32")
    if worst32 <= THREE_STORAGE_ONLY:
        return text + (": three's interpolants are the specification's sampler up to float32 storage of the keys "
                       "and of the result.")
    return text + "."


def peers_section(acc, report_dir, bench_rows, vocab):
    """The markdown lines of the "Peers" section."""
    md = ["", "## Peers: the libraries users would pick instead", ""]
    try:
        peer_files = load_peer_files(report_dir)
    except (OSError, lib.ReportError) as e:
        return md + [f"The optional peers' results could not be read: {e}", ""]
    peer_records = all_peer_records(acc, peer_files)
    versions = version_rows(acc, peer_files)
    if not peer_records and not versions:
        return md + ["No peer results (this accuracy.json has no peer_records: it predates the peer sweep).", ""]
    md += ["Each peer runs on every case it can represent and is measured against the same 50-digit "
           "reference as curvebench's methods; curvebench's counterpart is the record of the same "
           "computation (the default evaluation of the case, adaptive_gk at the same relative tolerance). "
           "A peer that represents only part of the case's domain says which in its setting (Boost's "
           "catmull_rom wraps its end tangents: segments=interior) and is compared with curvebench's error "
           "on the same parameters.", ""]
    md.append(lib.table(["peers and versions", "ran by", "records"], versions))
    missing = missing_drivers(peer_files)
    if missing:
        md += ["", "Optional peers that did not run (no reports/peers_<driver>.json; run scripts/peers.sh): "
               + ", ".join(missing) + "."]
    for _, data in peer_files:
        for note in data.get("notes", []):
            md += ["", f"- {data.get('driver', '?')}: {note}"]
    records = [r for r in acc.get("records", []) if not r.get("subject")]

    md += ["", "### Evaluation", "",
           "Error in eps(double) x the curve's size (as curvebench's eval records). Times per evaluation: "
           "the accuracy runner's (each peer and curvebench's counterpart timed back to back on one thread, "
           "curvebench through its type-erased any_curve; compare the ratio), or the driver's for the "
           "optional peers (SciPy: one vectorised call over all the parameters, divided by their number).", ""]
    ev = eval_rows(records, peer_records)
    md.append(lib.table(["case", "peer", "peer error", "curvebench", "curvebench error", "peer ns/eval",
                         "curvebench ns/eval", "curvebench / peer"], ev) if ev else "No evaluation peer records.")

    md += ["", "### Arc length", "",
           "Relative error |L_peer - L| / L, the peer's own estimate / L and whether it bounds the error, the "
           "integrand evaluations, the library's status in its own words, beside curvebench's adaptive_gk at the "
           "same relative tolerance; times per length as above.", ""]
    lr = length_rows(records, peer_records)
    md.append(lib.table(["case", "setting", "peer", "peer error", "peer estimate", "bounds?", "evals", "peer status",
                         "adaptive_gk error", "adaptive_gk evals", "peer ns", "curvebench ns", "curvebench / peer"], lr)
              if lr else "No arc-length peer records.")
    md += ["", "### Arc-length inversion u(s)", "",
           "The anchored |s(u) - s| / L of the peer's u over the sweep's targets (as curvebench's u(s) records), "
           "the peer's own account of it / L and whether it bounds the error, integrand evaluations per query, "
           "beside curvebench's Newton u(s) at the same relative tolerance; times per query.", ""]
    ur = length_rows(records, peer_records, "u_of_s")
    md.append(lib.table(["case", "setting", "peer", "peer error", "peer estimate", "bounds?", "evals", "peer status",
                         "newton error", "newton evals", "peer ns", "curvebench ns", "curvebench / peer"], ur)
              if ur else "No u(s) peer records.")
    hon = honesty_rows(peer_records)
    if hon:
        md += ["", "Do the peers' error estimates bound their errors?", ""]
        md.append(lib.table(["peer", "quantity", "results with estimate", "estimate >= true error", "honest"], hon))

    libraries = {vocab.peers[r["method"]]["library"] for r in peer_records if r["method"] in vocab.peers}
    sp = speed_rows(bench_rows, vocab, libraries)
    if sp:
        md += ["", "### Speed in the benchmarks (same run, same data)", ""]
        md.append(lib.table(["family", "data", "curvebench", "peer", "curvebench ns/op", "peer ns/op",
                             "curvebench / peer"], sp))

    md += blender_lines(peer_files)
    md += three_lines(peer_files)

    md += ["", "### Findings: where a peer does less than its documentation says or the same data allow", ""]
    fs = grouped_findings(peer_records, records)
    if fs:
        md += ["One line per peer, defect and case, whatever the settings it holds for: their range, and the "
               "figures of the worst of them (the one furthest past what the peer promised).", ""]
        md += [f"- {g['line']}" for g in fs]
    else:
        md.append("None in this run.")
    rf = refusals(peer_records)
    if rf:
        md += ["", "Settings the peers refused (as documented; no value to measure):", ""]
        md += [f"- {x}" for x in rf]
    md.append("")
    return md
