#!/usr/bin/python3
"""lottie-web as a peer: a layer moving along a spatial Bezier with eased timing, played
by lottie-web in headless Chromium and measured against the exact motion at 50 digits.

  lottie_driver.py --lottie PACKAGE --tool CURVEBENCH [--work DIR] --out FILE [--chromium PATH]

PACKAGE is the installed npm package (build-peers/node/node_modules/lottie-web, pinned in
scripts/peers/node/package.json); DIR keeps the page, the dump, the specs and the CSVs.
The motion: an After Effects position keyframe A with spatial tangents ("to" from A, "ti" from the
next key B) moves along the cubic Bezier A, A + to, B + ti, B, and its temporal ease ("o", "i": a
cubic-bezier(o.x, o.y, i.x, i.y) easing) gives the fraction of that Bezier's ARC LENGTH reached: at
f = (frame - frame_A) / (frame_B - frame_A) the layer is at the point at arc length s = L E(f), L
the Bezier's length, E the CSS cubic-bezier easing of the handles.
(lottie-web 5.13.0 walks a table of 150 points on the curve by their chords, and solves the easing
with a float32 11-sample table and Newton or bisection; its positions are float32.)

What runs: animation(), one shape layer (a small square) whose position has a key every
SEGMENT_FRAMES frames, one segment per SEGMENTS entry (an arch with seed 002's at-rest-at-both-ends
ease, the common easeInOutBack that backs up and overshoots, an S curve with AE's easy ease, an S
curve with linear timing). The page (renderer "svg", autoplay off, lottie-web's
build/player/lottie_svg.min.js copied beside it) calls anim.goToAndStop(frame, true) at the frames
of 65 fractions of every segment (0, 1 and frac(j / phi): mostly non-integer frames) and reads the
layer's <g transform="matrix(1,0,0,1,x,y)"> from the rendered SVG (the layer's "ln" makes it the
element's id; lottie prints the float32 matrix entries as JavaScript numbers: exact), in two orders:
  seek      each frame reached from the animation's last frame (as a scrub or a jump does; lottie
            restarts its walk along the curve)
  playback  the frames in increasing order (as a player plays; lottie continues its walk from the
            chord where the previous frame stopped, within a segment)
It also compares the attribute with lottie's own finalTransform.mProp.p.v and counts disagreements.

Measured: per segment, E(f) is the 50-digit truth of `curvebench sample` of the channel spec
{"type": "channel", "tool": "css", "easing": "cubic-bezier(o.x, o.y, i.x, i.y)"} at the f (rounded
to double); L the length `curvebench check` reports for the segment's spec {"type": "bezier",
"points": [A, A + to, B + ti, B]}; the points with E(f) in [0, 1] are checked by `curvebench check
SPEC --at-length CSV` (columns s, x, y with s = L E(f)): point_error max |P_lottie - P(s)| / L,
s_error max |s(u*) - s| / L (u* the curve's point nearest lottie's), off_curve max distance / L.
Where E(f) is outside [0, 1] the exact motion leaves the curve's arc-length range (no point of the
Bezier is at s < 0 or s > L); the row's note and the file's notes say where lottie put the layer
there (its distance from A and from B, / L).

Written to --out (reports/peers_lottie.json) as {"driver": "lottie", "versions", "user_agent",
"peer_records": [] (the key every peers_*.json reader expects), "rows": [...] (the row format of
scripts/report_shipped.py, one per segment and order), "notes", "segments"}. The page, the dump's
parsing and the joining are pure functions (tests/python/test_lottie_driver.py, on a recorded dump);
main() starts Chromium and the tool.
"""
import argparse
import csv
import html
import json
import math
import os
import re
import shutil
import struct
import subprocess
import sys
import tempfile

import peer_io
from chromium_driver import chromium_version

PEER = "peer_lottie_web_position"
RESULT_ID = peer_io.RESULT_ID
LAYER_ID = "curvebench-mover"
LOTTIE_FILE = "lottie_svg.min.js"  # lottie-web's SVG player, build/player/ in the package
SEGMENT_FRAMES = 64  # a power of two: f = (frame - frame_A) / 64 is exact
FRACTIONS = 65  # per segment: the accuracy runner's sample fractions (peer_io.sample_fractions)
ORDERS = ("seek", "playback")
# The keys' positions (integers: exact in float32 and double), then per segment from key k to k + 1:
# case name, out tangent "to" (from A), in tangent "ti" (from B), temporal ease (o.x, o.y, i.x, i.y).
KEYS = ((56, 256), (456, 256), (256, 456), (256, 56), (56, 456))
SEGMENTS = (
    ("lottie_arch_ease_in_out", (120, -160), (-120, -160), (0.8, 0, 0.2, 1)),
    ("lottie_overshoot", (0, 150), (150, 0), (0.68, -0.55, 0.265, 1.55)),
    ("lottie_s_curve_easy_ease", (300, -100), (-300, 100), (0.33, 0, 0.67, 1)),
    ("lottie_s_curve_linear", (200, 150), (-200, -150), (0, 0, 1, 1)),
)
WHY = {"lottie_arch_ease_in_out": "seed 002's motion on a cubic arch: at rest at both ends, a strong ease-in-out",
       "lottie_overshoot": "easeInOutBack (easings.net): backs up (E < 0) early and overshoots (E > 1) late",
       "lottie_s_curve_easy_ease": "an S-shaped path (one inflection) with After Effects' easy ease",
       "lottie_s_curve_linear": "an S-shaped path with linear timing (lottie's easing returns f itself): "
                                "the chord table alone"}


class LottieDriverError(Exception):
    pass


def bezier_points(k):
    """The control points of segment k: A, A + to, B + ti, B."""
    (ax, ay), (bx, by) = KEYS[k], KEYS[k + 1]
    _, to, ti, _ = SEGMENTS[k]
    return [[ax, ay], [ax + to[0], ay + to[1]], [bx + ti[0], by + ti[1]], [bx, by]]


def easing_text(k):
    return "cubic-bezier({}, {}, {}, {})".format(*SEGMENTS[k][3])


def animation():
    """The Lottie document: one shape layer whose position has a key every SEGMENT_FRAMES frames."""
    keys = []
    for k, (_, to, ti, ease) in enumerate(SEGMENTS):
        keys.append({"t": k * SEGMENT_FRAMES, "s": [*KEYS[k], 0], "to": [*to, 0], "ti": [*ti, 0],
                     "o": {"x": ease[0], "y": ease[1]}, "i": {"x": ease[2], "y": ease[3]}})
    end = len(SEGMENTS) * SEGMENT_FRAMES
    keys.append({"t": end, "s": [*KEYS[-1], 0]})
    static = lambda v: {"a": 0, "k": v}  # noqa: E731
    square = {"ty": "gr", "nm": "square", "it": [
        {"ty": "rc", "nm": "rect", "d": 1, "s": static([8, 8]), "p": static([0, 0]), "r": static(0)},
        {"ty": "fl", "nm": "fill", "c": static([1, 0, 0, 1]), "o": static(100), "r": 1},
        {"ty": "tr", "p": static([0, 0]), "a": static([0, 0]), "s": static([100, 100]), "r": static(0),
         "o": static(100)}]}
    layer = {"ddd": 0, "ind": 1, "ty": 4, "nm": "mover", "ln": LAYER_ID, "sr": 1, "ao": 0, "ip": 0, "op": end + 1,
             "st": 0, "bm": 0, "shapes": [square],
             "ks": {"o": static(100), "r": static(0), "a": static([0, 0, 0]), "s": static([100, 100, 100]),
                    "p": {"a": 1, "k": keys}}}
    return {"v": "5.7.4", "fr": 60, "ip": 0, "op": end + 1, "w": 512, "h": 512, "nm": "curvebench lottie peer",
            "ddd": 0, "assets": [], "layers": [layer]}


def queries():
    """[(segment, f, frame)]: per segment the FRACTIONS sample fractions x, frame = frame_A + 64 x
    rounded to double, and f = (frame - frame_A) / 64 (exact) the fraction lottie evaluates."""
    out = []
    for k in range(len(SEGMENTS)):
        a = k * SEGMENT_FRAMES
        for x in peer_io.sample_fractions(FRACTIONS):
            frame = a + SEGMENT_FRAMES * x
            out.append((k, (frame - a) / SEGMENT_FRAMES, frame))
    return out


def page_frames(qs):
    """The distinct frames the page visits, increasing (the playback order)."""
    return sorted({frame for _, _, frame in qs})


def page(frames, lottie_src=LOTTIE_FILE):
    """The HTML page: loads lottie-web from lottie_src (beside the page), plays ANIMATION's frames
    in both ORDERS and writes JSON into <pre id=RESULT_ID>: {"userAgent", "lottie" (its version),
    "loaded", "frames", "orders": {order: [transform attribute per frame]}, "internal_mismatches"
    (frames whose attribute is not lottie's own position value)} or {"error"}."""
    data = json.dumps(animation())
    end = len(SEGMENTS) * SEGMENT_FRAMES
    return f"""<!doctype html>
<html><head><meta charset="utf-8"><title>curvebench lottie-web peer</title>
<script src="{html.escape(lottie_src)}"></script></head>
<body><div id="stage" style="width:512px;height:512px"></div><pre id="{RESULT_ID}"></pre>
<script>
const frames = {json.dumps(frames)};
const out = {{userAgent: navigator.userAgent, frames: frames, orders: {{}}, internal_mismatches: 0}};
try {{
  out.lottie = lottie.version;
  const anim = lottie.loadAnimation({{container: document.getElementById("stage"), renderer: "svg", loop: false,
                                     autoplay: false, animationData: {data}}});
  out.loaded = anim.isLoaded;
  const read = () => {{
    const t = document.getElementById("{LAYER_ID}").getAttribute("transform");
    const m = /matrix\\(([^)]*)\\)/.exec(t || "");
    const v = anim.renderer.elements[0].finalTransform.mProp.p.v;
    if (!m || Number(m[1].split(",")[4]) !== v[0] || Number(m[1].split(",")[5]) !== v[1]) out.internal_mismatches += 1;
    return t;
  }};
  for (const order of {json.dumps(list(ORDERS))}) {{
    const got = [];
    for (const f of frames) {{
      if (order === "seek") anim.goToAndStop({end}, true);
      anim.goToAndStop(f, true);
      got.push(read());
    }}
    out.orders[order] = got;
    anim.goToAndStop({end}, true);
  }}
}} catch (e) {{
  out.error = String(e);
}}
document.getElementById("{RESULT_ID}").textContent = JSON.stringify(out);
</script></body></html>
"""


def parse_dump(dom):
    """The JSON the page wrote, from chromium --dump-dom's output."""
    return peer_io.dump_result(dom, LottieDriverError)


def translation(transform):
    """(x, y) of lottie's layer transform "matrix(1,0,0,1,x,y)" (no rotation, scale or skew here)."""
    m = re.fullmatch(r"\s*matrix\(([^)]*)\)\s*", transform or "")
    try:
        v = [float(s) for s in m.group(1).split(",")] if m else []
    except ValueError:
        v = []
    if len(v) != 6 or v[:4] != [1, 0, 0, 1]:
        raise LottieDriverError(f"layer transform {transform!r}: expected matrix(1,0,0,1,x,y)")
    return v[4], v[5]


def positions(doc, qs):
    """{order: [(x, y) per query of qs]} from the page's result; LottieDriverError when its frames,
    orders or counts are not the request's, or lottie's attribute and its own value disagree."""
    frames = page_frames(qs)
    if doc.get("frames") != frames:
        raise LottieDriverError("the page's frames are not the request's")
    if doc.get("internal_mismatches"):
        raise LottieDriverError(f"{doc['internal_mismatches']} layer transforms differ from lottie's own "
                                "position value")
    out = {}
    for order in ORDERS:
        got = (doc.get("orders") or {}).get(order)
        if not isinstance(got, list) or len(got) != len(frames):
            raise LottieDriverError(f"order {order}: expected {len(frames)} transforms")
        at = {}
        for frame, t in zip(frames, got):
            try:
                at[frame] = translation(t)
            except LottieDriverError as e:
                raise LottieDriverError(f"order {order}, frame {frame!r}: {e}") from e
        out[order] = [at[frame] for _, _, frame in qs]
    return out


def float32_half_ulp(v):
    """Half the spacing of float32 at |v| (the rounding of a float32 position)."""
    a = abs(float(struct.unpack("f", struct.pack("f", v))[0]))
    bits = struct.unpack("I", struct.pack("f", a))[0]
    return (struct.unpack("f", struct.pack("I", bits + 1))[0] - a) / 2


def _dist(p, q):
    return ((p[0] - q[0]) ** 2 + (p[1] - q[1]) ** 2) ** 0.5


def segment_row(k, order, fs, easing, points, length, check):
    """One result row (scripts/report_shipped.py's format) and its note, for segment k in `order`:
    fs the fractions, easing E(f) (the truth), points lottie's (x, y), length L, check the parsed
    `check --json` of the points with E in [0, 1] (in their order; None when there are none)."""
    name = SEGMENTS[k][0]
    ctrl = bezier_points(k)
    a, b = ctrl[0], ctrl[3]
    inside = [i for i, e in enumerate(easing) if 0 <= e <= 1]
    outside = [i for i, e in enumerate(easing) if not 0 <= e <= 1]
    rows = check["checks"][0]["rows"] if check else []
    if len(rows) != len(inside):
        raise LottieDriverError(f"{name} ({order}): {len(rows)} checked rows for {len(inside)} points")
    row = {"peer": PEER, "case": name, "setting": order, "length": None, "true_length": length,
           "length_error": None, "point_error": None, "point_error_at": None, "s_error": None, "off_curve": None,
           "spacing_cv": None, "ns_length": None, "ns_point": None, "ns_build": None}
    if rows:
        worst = max(range(len(rows)), key=lambda j: rows[j]["error"])
        row.update({"point_error": rows[worst]["error"], "point_error_at": rows[worst]["s"],
                    "s_error": max(r["s_error"] for r in rows), "off_curve": max(r["off_curve"] for r in rows)})
        worst_f = fs[inside[worst]]
    floor = max(float32_half_ulp(c) for p in ctrl for c in p) / length
    parts = [f"{len(fs)} fractions f of the segment (frames {k * SEGMENT_FRAMES} to {(k + 1) * SEGMENT_FRAMES}), "
             f"easing {easing_text(k)} ({WHY[name]}), reached in {order} order; float32 rounding of a position "
             f"alone is up to {floor:.2g} L"]
    if rows:
        parts.append(f"worst point error {row['point_error']:.3g} L at f = {worst_f!r} (s = {row['point_error_at']!r})")
        at_end = sorted((i for i in inside if easing[i] < 1 and tuple(points[i]) == tuple(b)), key=lambda i: fs[i])
        if at_end:
            parts.append(f"{len(at_end)} of the {len(inside)} fractions with E(f) in [0, 1) show the segment's end B "
                         f"exactly (the smallest f = {fs[at_end[0]]!r}, E = {easing[at_end[0]]:.4g})")
    if outside:
        lo, hi = min(easing[i] for i in outside), max(easing[i] for i in outside)
        d_b = max(_dist(points[i], b) for i in outside) / length
        d_a = min(_dist(points[i], a) for i in outside) / length
        parts.append(f"E(f) outside [0, 1] at {len(outside)} fractions (E from {lo:.4g} to {hi:.4g}; no point of the "
                     f"curve is at s = L E there): lottie's point is at most {d_b:.3g} L from B and at least "
                     f"{d_a:.3g} L from A" + (" (B exactly, also where E < 0)" if d_b == 0 and lo < 0 else ""))
    row["note"] = "; ".join(parts)
    return row


def at_length_csv(path, points, easing, length):
    """The check's CSV: s = L E(f), x, y for the points whose E(f) is in [0, 1]; returns their count.
    L is the check's length, the 50-digit L rounded to double, which can lie above L itself, where
    the check refuses s: an s from L up is written as the double below L (1 ulp of L at most)."""
    n = 0
    with open(path, "w", newline="", encoding="utf-8") as f:
        w = csv.writer(f)
        w.writerow(["s", "x", "y"])
        for (x, y), e in zip(points, easing):
            if 0 <= e <= 1:
                s = length * e
                w.writerow([repr(s if s < length else math.nextafter(length, 0)), repr(float(x)), repr(float(y))])
                n += 1
    return n


def _run_json(cmd):
    p = subprocess.run(cmd, capture_output=True, text=True, timeout=600)
    if p.returncode != 0:
        raise LottieDriverError(f"{' '.join(cmd)}: exit {p.returncode}: {p.stderr.strip()[:500]}")
    return json.loads(p.stdout)


def measure(pos, qs, tool, work):
    """The rows and notes from the page's positions ({order: [(x, y) per query]}), measured by the
    tool in work (the specs, times and CSVs are kept there)."""
    os.makedirs(work, exist_ok=True)
    rows, notes = [], []
    for k, (name, _, _, _) in enumerate(SEGMENTS):
        idx = [i for i, q in enumerate(qs) if q[0] == k]
        fs = [qs[i][1] for i in idx]
        spec, ease_spec = os.path.join(work, name + ".json"), os.path.join(work, name + ".easing.json")
        peer_io.write_json(spec, {"name": name, "type": "bezier", "points": bezier_points(k)})
        peer_io.write_json(ease_spec, {"name": name + "_easing", "type": "channel", "tool": "css",
                                       "easing": easing_text(k)})
        times = os.path.join(work, name + ".times")
        with open(times, "w", encoding="utf-8") as f:
            f.write("".join(repr(x) + "\n" for x in fs))
        sample = os.path.join(work, name + ".easing.csv")
        with open(sample, "w", encoding="utf-8") as f:
            subprocess.run(peer_io.sample_command(tool, ease_spec, times, as_tool=False), stdout=f, check=True,
                           timeout=600)
        easing = peer_io.read_sample(sample, fs, error=LottieDriverError)
        start = os.path.join(work, name + ".start.csv")
        with open(start, "w", encoding="utf-8") as f:
            f.write("s,x,y\n0,{},{}\n".format(*bezier_points(k)[0]))
        length = _run_json([tool, "check", spec, "--at-length", start, "--json", "--quiet"])["checks"][0]["length"]
        for order in ORDERS:
            pts = [pos[order][i] for i in idx]
            path = os.path.join(work, f"{name}.{order}.csv")
            check = None
            if at_length_csv(path, pts, easing, length):
                check = _run_json([tool, "check", spec, "--at-length", path, "--name", PEER, "--json", "--quiet"])
            row = segment_row(k, order, fs, easing, pts, length, check)
            rows.append(row)
            if any(not 0 <= e <= 1 for e in easing) or "show the segment's end B" in row["note"]:
                notes.append(f"{PEER} on {name} ({order}): {row['note']}")
    return rows, notes


def package_version(lottie_dir):
    with open(os.path.join(lottie_dir, "package.json"), encoding="utf-8") as f:
        return json.load(f)["version"]


def run_chromium(chromium, work, frames, lottie_dir):
    """The page's result from `chromium --headless=new --dump-dom`, the page and lottie in work."""
    os.makedirs(work, exist_ok=True)
    shutil.copy(os.path.join(lottie_dir, "build", "player", LOTTIE_FILE), os.path.join(work, LOTTIE_FILE))
    page_path = os.path.abspath(os.path.join(work, "lottie_peer.html"))
    with open(page_path, "w", encoding="utf-8") as f:
        f.write(page(frames))
    try:
        dom = peer_io.chromium_dump(chromium, page_path, os.path.join(work, "profile"), 300, LottieDriverError)
    finally:
        shutil.rmtree(os.path.join(work, "profile"), ignore_errors=True)
    with open(os.path.join(work, "dump.html"), "w", encoding="utf-8") as f:
        f.write(dom)
    return parse_dump(dom)


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--lottie", required=True, help="the installed lottie-web package (node_modules/lottie-web)")
    ap.add_argument("--tool", required=True)
    ap.add_argument("--work", help="page, dump, specs and CSVs (default: a temporary directory)")
    ap.add_argument("--out", required=True)
    ap.add_argument("--chromium", default="chromium")
    a = ap.parse_args()
    qs = queries()
    try:
        version = package_version(a.lottie)
        browser = chromium_version(subprocess.run([a.chromium, "--version"], capture_output=True, text=True,
                                                  check=True).stdout)
        with tempfile.TemporaryDirectory() as tmp:
            work = a.work or tmp
            doc = run_chromium(a.chromium, os.path.join(work, "page"), page_frames(qs), a.lottie)
            if doc.get("lottie") != version:
                raise LottieDriverError(f"the page ran lottie {doc.get('lottie')!r}, the package is {version}")
            rows, notes = measure(positions(doc, qs), qs, a.tool, os.path.join(work, "check"))
    except (OSError, ValueError, subprocess.SubprocessError, LottieDriverError) as e:
        print(f"lottie_driver: {e}", file=sys.stderr)
        return 1
    out = {"driver": "lottie", "versions": {"lottie-web": version, "Chromium": browser},
           "user_agent": doc.get("userAgent"), "peer_records": [], "rows": rows, "notes": notes,
           "segments": [{"case": name, "points": bezier_points(k), "easing": easing_text(k),
                         "frames": [k * SEGMENT_FRAMES, (k + 1) * SEGMENT_FRAMES]}
                        for k, (name, _, _, _) in enumerate(SEGMENTS)]}
    peer_io.write_json(a.out, out)
    print(f"lottie_driver: {len(rows)} rows -> {a.out}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
