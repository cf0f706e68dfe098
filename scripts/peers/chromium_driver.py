#!/usr/bin/python3
"""Headless Chromium as an easing peer: Blink's own CSS easing, reached through the Web
Animations API, at the query times of the CSS cases; written as JSON in the easing driver's format
for scripts/peers/easing_results.py to measure against the same 50-digit truth.

  chromium_driver.py --cases DIR --out FILE [--quick] [--chromium PATH] [--work DIR]

What runs: one file:// page per invocation, loaded by `chromium --headless=new --dump-dom`. For
each easing the page animates a <div>'s opacity with a paused Animation of duration 2^20 ms and
the easing as the effect's timing function, sets currentTime to x * 2^20 (exact: a power of two)
for every query fraction x, and reads effect.getComputedTiming(): "progress" is the eased progress
Blink computed, "localTime" the time it evaluated at (Blink converts times internally: localTime /
duration can differ from x in its last bits, so the query fraction recorded is the former). The page writes the
results as JSON into a
<pre>, which --dump-dom prints once the page's script has run. Blink treats local times within
0.001 ms of an interval's ends as the end (its time tolerance); with 2^20 ms that moves only
fractions within 1e-9 of 0 or 1. The truth is taken where Blink evaluated.

Easings: every CSS case of DIR ("type": "channel", "tool": "css") whose easing is cubic-bezier()
or steps(), and the steps() easings of STEPS (the suite has no steps() case; each jump position
once, named as steps_case() does: steps_4_jump_end), whose query fractions add every step boundary
k / n (as doubles) to the grid. Query
fractions: the accuracy runner's sample fractions (0, 1 and frac(j / phi); 65 with --quick, else
257), as scripts/peers/easing_driver.mjs. No time per evaluation: setting currentTime and reading
the computed timing costs far more than the easing, so a figure would not be Blink's solver's.

The page, the parsing of the dump and the runs are pure functions (tested with plain Python by
tests/python/test_chromium_driver.py on a recorded dump); only main() starts Chromium.
"""
import argparse
import json
import os
import re
import subprocess
import sys
import tempfile

import peer_io

DURATION_MS = 1048576.0  # 2^20: x * duration is exact for every double x in [0, 1]
PEER = "peer_chromium_waapi"
# steps() easings the driver adds (no case of the suite has one): every jump position.
STEPS = ("steps(4, jump-end)", "steps(4, jump-start)", "steps(5, jump-none)", "steps(3, jump-both)",
         "steps(10, jump-end)")
RESULT_ID = peer_io.RESULT_ID


class ChromiumDriverError(Exception):
    pass


def parse_cubic_bezier(easing):
    m = re.fullmatch(r"\s*cubic-bezier\(([^)]*)\)\s*", easing)
    if not m:
        return None
    try:
        v = [float(s) for s in m.group(1).split(",")]
    except ValueError:
        return None
    return v if len(v) == 4 else None


def parse_steps(easing):
    """(n, position) of steps(n[, position]); position one of jump-start, jump-end, jump-none,
    jump-both (start / end are CSS's aliases of jump-start / jump-end); None if not steps()."""
    m = re.fullmatch(r"\s*steps\(\s*(\d+)\s*(?:,\s*([a-z-]+)\s*)?\)\s*", easing)
    if not m:
        return None
    pos = {"start": "jump-start", "end": "jump-end", None: "jump-end"}.get(m.group(2), m.group(2))
    if pos not in ("jump-start", "jump-end", "jump-none", "jump-both"):
        return None
    return int(m.group(1)), pos


def easings_of(specs, grid):
    """[(case, easing text, times)] for the CSS specs ({case: spec}) Chromium can run and the
    driver's STEPS; a steps() easing's times are the grid plus its step boundaries k / n."""
    out = []
    for case, spec in sorted(specs.items()):
        if spec.get("type") != "channel" or spec.get("tool") != "css":
            continue
        e = spec.get("easing", "")
        if parse_cubic_bezier(e) or parse_steps(e):
            out.append((case, e, _times_for(e, grid)))
    for e in STEPS:
        out.append((steps_case(e), e, _times_for(e, grid)))
    return out


def steps_case(easing):
    """The case name of one of the driver's steps() easings: "steps(4, jump-end)" -> steps_4_jump_end."""
    return re.sub(r"[^a-z0-9]+", "_", easing).strip("_")


def _times_for(easing, grid):
    s = parse_steps(easing)
    if not s:
        return list(grid)
    return sorted(set(grid) | {k / s[0] for k in range(s[0] + 1)})


def page(easings):
    """The HTML page evaluating [(case, easing, times)]; its script writes JSON into
    <pre id=RESULT_ID>: {"userAgent", "results": [{"case", "easing", "local_times", "durations",
    "progress"}]} or {"error"}."""
    data = json.dumps([{"case": c, "easing": e, "times": t} for c, e, t in easings])
    return f"""<!doctype html>
<html><head><meta charset="utf-8"><title>curvebench chromium easing peer</title></head>
<body><div id="target"></div><pre id="{RESULT_ID}"></pre>
<script>
const jobs = {data};
const D = {DURATION_MS!r};
const out = {{userAgent: navigator.userAgent, results: []}};
try {{
  const el = document.getElementById("target");
  for (const job of jobs) {{
    const anim = el.animate([{{opacity: 0}}, {{opacity: 1}}], {{duration: D, easing: job.easing, fill: "both"}});
    anim.pause();
    const r = {{case: job.case, easing: job.easing, local_times: [], durations: [], progress: []}};
    for (const x of job.times) {{
      anim.currentTime = x * D;
      const c = anim.effect.getComputedTiming();
      r.local_times.push(c.localTime);
      r.durations.push(c.duration);
      r.progress.push(c.progress);
    }}
    anim.cancel();
    out.results.push(r);
  }}
}} catch (e) {{
  out.error = String(e);
}}
document.getElementById("{RESULT_ID}").textContent = JSON.stringify(out);
</script></body></html>
"""


def parse_dump(dom):
    """The JSON the page wrote, from chromium --dump-dom's output."""
    return peer_io.dump_result(dom, ChromiumDriverError)


def chromium_version(text):
    """'156.0.8078.79' from `chromium --version` ("Chromium 156.0.8078.79 built on Debian ...")."""
    m = re.search(r"Chromium\s+(\d+(?:\.\d+)+)", text)
    if not m:
        raise ChromiumDriverError(f"cannot read a version from {text.strip()!r}")
    return m.group(1)


def runs_of(doc, easings):
    """The easing driver's runs from the page's result: per easing the query fractions Blink
    evaluated (localTime / duration) and its progress; cubic-bezier runs carry "easing" [x1, y1,
    x2, y2], steps runs "steps" [n, position]. A result whose easings or lengths differ from the
    request raises ChromiumDriverError."""
    results = doc.get("results")
    if not isinstance(results, list) or len(results) != len(easings):
        raise ChromiumDriverError(f"expected {len(easings)} results, got {len(results or [])}")
    runs = []
    for (case, easing, times), r in zip(easings, results):
        if r.get("case") != case or r.get("easing") != easing:
            raise ChromiumDriverError(f"result for {r.get('case')!r} where {case!r} was asked")
        n = len(times)
        if not all(len(r.get(k) or []) == n for k in ("local_times", "durations", "progress")):
            raise ChromiumDriverError(f"{case}: expected {n} local times, durations and progress values")
        xs = []
        for i, (lt, d) in enumerate(zip(r["local_times"], r["durations"])):
            if not isinstance(lt, (int, float)) or not isinstance(d, (int, float)) or d <= 0:
                raise ChromiumDriverError(f"{case}: query {i}: localTime {lt!r}, duration {d!r}")
            xs.append(lt / d)
        for i, p in enumerate(r["progress"]):
            if not isinstance(p, (int, float)):
                raise ChromiumDriverError(f"{case}: query {i} (x = {times[i]!r}): progress {p!r}")
        run = {"case": case, "peer": PEER, "times": xs, "values": [float(p) for p in r["progress"]],
               "ns_per_op": None}
        cb, st = parse_cubic_bezier(easing), parse_steps(easing)
        if cb:
            run["easing"] = cb
        else:
            run["steps"] = [st[0], st[1]]
            run["easing_text"] = easing
        runs.append(run)
    return runs


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--cases", required=True)
    ap.add_argument("--out", required=True)
    ap.add_argument("--quick", action="store_true")
    ap.add_argument("--chromium", default="chromium")
    ap.add_argument("--work", help="where the page and the dump are kept (default: a temporary directory)")
    a = ap.parse_args()
    specs = {}
    for f in sorted(os.listdir(a.cases)):
        if f.endswith(".json"):
            with open(os.path.join(a.cases, f), encoding="utf-8") as fh:
                specs[f[:-5]] = json.load(fh)
    easings = easings_of(specs, peer_io.sample_fractions(65 if a.quick else 257))
    try:
        version = chromium_version(subprocess.run([a.chromium, "--version"], capture_output=True, text=True,
                                                  check=True).stdout)
        with tempfile.TemporaryDirectory() as tmp:
            work = a.work or tmp
            os.makedirs(work, exist_ok=True)
            page_path = os.path.abspath(os.path.join(work, "chromium_easing.html"))
            with open(page_path, "w", encoding="utf-8") as f:
                f.write(page(easings))
            dom = peer_io.chromium_dump(a.chromium, page_path, os.path.join(work, "profile"), 300, ChromiumDriverError)
            if a.work:
                with open(os.path.join(work, "dump.html"), "w", encoding="utf-8") as f:
                    f.write(dom)
            doc = parse_dump(dom)
        runs = runs_of(doc, easings)
    except (OSError, subprocess.SubprocessError, ChromiumDriverError) as e:
        print(f"chromium_driver: {e}", file=sys.stderr)
        return 1
    out = {"driver": "chromium", "quick": a.quick, "versions": {"Chromium": version},
           "user_agent": doc.get("userAgent"), "notes": [], "runs": runs}
    peer_io.write_json(a.out, out)
    print(f"chromium_driver: {len(runs)} easings -> {a.out}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
