#!/usr/bin/python3
"""Arc length, the point at arc length and keyframe easing as Godot 3.2 computes them:
Curve2D's baked length and interpolate_baked() on the cases of a shipped-peer request, and
Animation's bezier tracks on the CSS cubic-bezier() channel cases, run headless in Debian's
godot3-server through scripts/peers/godot_driver.gd.

  godot_driver.py --request FILE --out FILE [--quick] [--only CASE,...]   (curves, the default mode)
  godot_driver.py easing --cases DIR --out FILE [--quick]                 (the channel solver table)
  common options: [--godot PATH] [--timeout SECONDS] [--keep DIR]

Runs `godot3-server --no-window -s godot_driver.gd -- IN.bin OUT.bin` once per mode under a time
limit (--timeout, default 300 s); a missing program is an error naming the package. Numbers go both
ways as binary doubles (GDScript prints floats with 6 digits, and its JSON parser is not the place to
trust the last bit): the times and s Godot reads are exactly the doubles written here.

What Godot 3.2 computes (from its sources): Curve2D bakes points every bake_interval
along each segment, placing each by 10 bisections on t, and takes the length as (N - 1) x interval
plus the rest; Vector2 and the baked arrays are float32 (real_t), so every length and point is a
float32. interpolate_baked(offset, cubic = false) (the default, measured here) interpolates
linearly between the baked points; an offset past the end gives the last point.
bezier_track_interpolate bisects t 10 times on the key pair's Bezier x(t), then interpolates
linearly, in float32.

Curves: peer peer_godot_curve2d, settings "" (bake_interval 5, Godot's default), "bake_interval=1"
and "bake_interval=0.1". A subpath's segments become Curve2D points with relative handles
(add_point(position, in, out)): a cubic's handles as is, a quadratic raised exactly to a cubic, a
line with zero handles (Godot's straight segment; baking places points by distance, so its speed
does not matter); a closed subpath's closing segment is already its last segment, ending on its
first point. An elliptical arc has no exact Bezier form: the case is skipped, and so is a path of
several subpaths (a Curve2D is one connected curve). Points: interpolate_baked(min(s, L)), L Godot's
baked length; spaced at k L / (n - 1). Times (OS.get_ticks_usec around a loop whose count doubles
until a pass lasts 2 ms, best of 5 passes; quick: 0.2 ms, best of 3): ns_build the bake
(bake_interval set, which marks the cache dirty, then get_baked_length()), ns_length
get_baked_length() of a baked curve (its stored value, what a caller asking again pays), ns_point
one interpolate_baked() averaged over the s.

Easing: peer peer_godot_bezier_track, for every bench/cases channel case with "tool": "css" and a
cubic-bezier(x1, y1, x2, y2) easing: key (0, 0) with out handle (x1, y1), key (1, 1) with in handle
(x2 - 1, y2 - 1), evaluated at the accuracy runner's sample fractions (257; 65 with --quick);
ns_per_op one call averaged over the times. Written in the format of
scripts/peers/easing_driver.mjs's output, for scripts/peers/easing_results.py.
"""
import argparse
import json
import os
import re
import shutil
import struct
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import peer_io  # noqa: E402
from peer_io import DriverError, cubic_of, load_request, read_cpu  # noqa: E402

DRIVER = "godot"
EASING_DRIVER = "godot_easing"
FORMAT = "curvebench-shipped-driver-1"
PEER = "peer_godot_curve2d"
EASING_PEER = "peer_godot_bezier_track"
INTERVALS = ((5.0, ""), (1.0, "bake_interval=1"), (0.1, "bake_interval=0.1"))
SCRIPT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "godot_driver.gd")
MAGIC = 0x44474243
TIMEOUT_S = 300.0
PROGRAM = "godot3-server"


def curve_points(subpath):
    """[(position, in handle, out handle)] (each (x, y), the handles relative to the position) of
    a subpath's segments as Curve2D points: one per segment start, then the last segment's end."""
    cubics = [cubic_of(s) for s in subpath["segments"]]
    if not cubics:
        raise DriverError("a subpath without segments")

    def rel(a, b):
        return (a[0] - b[0], a[1] - b[1])
    pts = []
    for i, c in enumerate(cubics):
        p = tuple(c[0])
        into = rel(cubics[i - 1][2], p) if i > 0 else (0.0, 0.0)
        pts.append((p, into, rel(c[1], p)))
    end = tuple(cubics[-1][3])
    pts.append((end, rel(cubics[-1][2], end), (0.0, 0.0)))
    if any(s.get("kind") == "line" for s in subpath["segments"]):
        # Godot's own straight segment: zero handles on both of its ends.
        for i, s in enumerate(subpath["segments"]):
            if s.get("kind") == "line":
                pts[i] = (pts[i][0], pts[i][1], (0.0, 0.0))
                pts[i + 1] = (pts[i + 1][0], (0.0, 0.0), pts[i + 1][2])
    return pts


class Writer:
    def __init__(self):
        self.parts = []

    def u32(self, v):
        self.parts.append(struct.pack("<I", v))

    def f64(self, *vs):
        self.parts.append(struct.pack(f"<{len(vs)}d", *vs))

    def data(self):
        return b"".join(self.parts)


class Reader:
    def __init__(self, data):
        self.data, self.at = data, 0

    def u32(self):
        v, = struct.unpack_from("<I", self.data, self.at)
        self.at += 4
        return v

    def f64(self, n=1):
        v = struct.unpack_from(f"<{n}d", self.data, self.at)
        self.at += 8 * n
        return list(v)

    def pascal(self):
        n = self.u32()
        s = self.data[self.at:self.at + n].decode("utf-8")
        self.at += n
        return s

    def end(self):
        if self.at != len(self.data):
            raise DriverError(f"Godot's output has {len(self.data) - self.at} bytes more than expected")


def timing(quick):
    return (200.0, 3) if quick else (2000.0, 5)


def curve_jobs(cases):
    """([(case, points, s, spaced)], skipped) of the request's cases."""
    jobs, skipped = [], []
    for c in cases:
        if len(c["segments"]) != 1:
            skipped.append({"peer": PEER, "case": c["case"], "reason": f"{len(c['segments'])} subpaths: a Curve2D is "
                            "one connected curve"})
            continue
        try:
            pts = curve_points(c["segments"][0])
        except DriverError as e:
            skipped.append({"peer": PEER, "case": c["case"], "reason": f"{e}: Curve2D has Bezier segments only"
                            if "arc" in str(e) else str(e)})
            continue
        jobs.append((c["case"], pts, [float(x) for x in c["s"]], int(c["spaced"])))
    return jobs, skipped


def input_writer(mode, cases, quick):
    """A Writer holding the input's header: magic, mode (1 = Curve2D, 2 = bezier track), the timing
    and the number of cases."""
    w = Writer()
    pass_usec, passes = timing(quick)
    w.u32(MAGIC)
    w.u32(mode)
    w.f64(pass_usec)
    w.u32(passes)
    w.u32(cases)
    return w


def curve_input(jobs, quick=False):
    w = input_writer(1, len(jobs), quick)
    for _, pts, s, n in jobs:
        w.u32(len(pts))
        for p, i, o in pts:
            w.f64(*p, *i, *o)
        w.u32(len(INTERVALS))
        w.f64(*[v for v, _ in INTERVALS])
        w.u32(len(s))
        w.f64(*s)
        w.u32(n)
    return w.data()


def _finite(vals):
    import math
    return all(math.isfinite(v) for v in vals)


def non_finite_reason(interval, L, s_list, pts_flat, spaced_flat):
    """Why a run is skipped: which of Godot's answers were not finite numbers."""
    import math
    if not math.isfinite(L):
        return f"bake_interval {interval:g}: get_baked_length() gave {L!r}"

    def bad(flat):
        return sum(1 for i in range(0, len(flat), 2) if not _finite(flat[i:i + 2]))
    multiple = math.fmod(L, interval) == 0
    return (f"bake_interval {interval:g}: interpolate_baked() gave inf/NaN coordinates at {bad(pts_flat)} of "
            f"{len(s_list)} s and {bad(spaced_flat)} of {len(spaced_flat) // 2} spaced points; the baked length "
            f"{L!r}" + (" is a whole multiple of bake_interval" if multiple else ""))


def curve_runs(data, jobs):
    """(version, runs, skipped) from Godot's output for the jobs."""
    r = Reader(data)
    if r.u32() != MAGIC:
        raise DriverError("Godot's output does not start with the driver's magic number")
    version = r.pascal()
    runs, skipped = [], []
    for case, pts, s_list, n in jobs:
        for interval, setting in INTERVALS:
            L, = r.f64()
            pts_flat = r.f64(2 * len(s_list))
            spaced_flat = r.f64(2 * n)
            ns_build, ns_length, ns_point = r.f64(3)
            if not _finite([L] + pts_flat + spaced_flat):
                skipped.append({"peer": PEER, "case": case, "setting": setting,
                                "reason": non_finite_reason(interval, L, s_list, pts_flat, spaced_flat)})
                continue
            beyond = sum(1 for s in s_list if s > L)
            note = (f"Curve2D with bake_interval {interval:g}: get_baked_length(), interpolate_baked(s) (cubic=false, "
                    "linear between baked points)"
                    + (f"; {beyond} s beyond Godot's own length asked at its length" if beyond else "")
                    + "; spaced at k L/(n-1); ns_build: bake_interval set + get_baked_length() (one bake), "
                    "ns_length: get_baked_length() of the baked curve (its stored value)")
            runs.append({"peer": PEER, "case": case, "setting": setting, "length": L,
                         "points": [pts_flat[i:i + 2] for i in range(0, len(pts_flat), 2)],
                         "spaced": [spaced_flat[i:i + 2] for i in range(0, len(spaced_flat), 2)] or None,
                         "ns_length": ns_length, "ns_point": ns_point, "ns_build": ns_build, "note": note})
    r.end()
    return version, runs, skipped


CUBIC_BEZIER = re.compile(r"^\s*cubic-bezier\(([^)]*)\)\s*$")


def cubic_bezier(easing):
    """[x1, y1, x2, y2] of a CSS cubic-bezier() easing text, or None."""
    m = CUBIC_BEZIER.match(easing or "")
    if not m:
        return None
    try:
        v = [float(x) for x in m.group(1).split(",")]
    except ValueError:
        return None
    return v if len(v) == 4 else None


def easing_cases(cases_dir):
    """([(case, [x1, y1, x2, y2])], notes) of the directory's CSS channel cases, sorted by file."""
    out, notes = [], []
    for name in sorted(f for f in os.listdir(cases_dir) if f.endswith(".json")):
        with open(os.path.join(cases_dir, name), encoding="utf-8") as f:
            spec = json.load(f)
        if not isinstance(spec, dict) or spec.get("type") != "channel" or spec.get("tool") != "css":
            continue
        case = name[:-len(".json")]
        p = cubic_bezier(spec.get("easing"))
        if p is None:
            notes.append(f"{case}: easing {json.dumps(spec.get('easing'))} is not cubic-bezier(); a Godot bezier "
                         "track evaluates only that")
            continue
        out.append((case, p))
    return out, notes


def easing_input(cases, times, quick=False):
    w = input_writer(2, len(cases), quick)
    for _, p in cases:
        w.f64(*p)
        w.u32(len(times))
        w.f64(*times)
    return w.data()


def easing_doc(data, cases, times, notes, quick):
    """The easing driver document (easing_driver.mjs's format) from Godot's output."""
    import math
    r = Reader(data)
    if r.u32() != MAGIC:
        raise DriverError("Godot's output does not start with the driver's magic number")
    version = r.pascal()
    runs = []
    for case, p in cases:
        values = r.f64(len(times))
        ns, = r.f64()
        run = {"case": case, "peer": EASING_PEER, "easing": p, "times": times,
               "values": [v if math.isfinite(v) else None for v in values], "ns_per_op": ns}
        bad = [[t, repr(v)] for t, v in zip(times, values) if not math.isfinite(v)]
        if bad:
            run["non_finite"] = bad
        runs.append(run)
    r.end()
    notes = list(notes) + [
        "peer_godot_bezier_track: Godot " + version + " Animation bezier track, key (0, 0) with out handle (x1, y1) "
        "and key (1, 1) with in handle (x2 - 1, y2 - 1), bezier_track_interpolate(track, t) (10 bisections on t, then "
        "linear, in float32); times passed to Godot as binary doubles; ns_per_op: one call averaged over the times "
        "(OS.get_ticks_usec, best of passes, the GDScript loop included)"]
    return {"driver": EASING_DRIVER, "quick": quick, "versions": {"Godot": version}, "notes": notes, "runs": runs}


def run_godot(program, data, work, timeout):
    """Godot's output bytes for the input bytes; DriverError on a failure or a timeout."""
    inp, out = os.path.join(work, "godot_in.bin"), os.path.join(work, "godot_out.bin")
    with open(inp, "wb") as f:
        f.write(data)
    if os.path.exists(out):
        os.remove(out)
    cmd = [program, "--no-window", "-s", SCRIPT, "--", inp, out]
    # Godot refuses the C locale with an error line and falls back to English: harmless, quieted.
    env = dict(os.environ, LANG="en_US.UTF-8", LC_ALL="C.UTF-8")
    peer_io.run_batch(cmd, out, timeout, program, cwd=work, env=env)
    with open(out, "rb") as f:
        return f.read()


def main(argv=None):
    argv = list(sys.argv[1:] if argv is None else argv)
    mode = "easing" if argv[:1] == ["easing"] else "curves"
    if mode == "easing":
        argv = argv[1:]
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    if mode == "easing":
        ap.add_argument("--cases", required=True)
    else:
        ap.add_argument("--request", required=True)
        ap.add_argument("--only", help="comma-separated case names")
    ap.add_argument("--out", required=True)
    ap.add_argument("--quick", action="store_true")
    ap.add_argument("--godot", default=PROGRAM)
    ap.add_argument("--timeout", type=float, default=TIMEOUT_S)
    ap.add_argument("--keep", help="keep Godot's input and output in this directory")
    a = ap.parse_args(argv)
    program = shutil.which(a.godot)
    if program is None:
        raise DriverError(f"{a.godot!r} is not on PATH (Debian: apt-get install godot3-server); nothing measured")
    with peer_io.work_dir(a.keep, "cb_godot_") as work:
        if mode == "easing":
            cases, notes = easing_cases(a.cases)
            times = peer_io.sample_fractions(65 if a.quick else 257)
            data = run_godot(program, easing_input(cases, times, a.quick), work, a.timeout)
            doc = easing_doc(data, cases, times, notes, a.quick)
            msg = f"{len(doc['runs'])} runs"
        else:
            only = [n for n in a.only.split(",") if n] if a.only else None
            _, cases = load_request(a.request, only)
            jobs, skipped = curve_jobs(cases)
            data = run_godot(program, curve_input(jobs, a.quick), work, a.timeout)
            version, runs, more = curve_runs(data, jobs)
            doc = {"driver": DRIVER, "format": FORMAT, "versions": {"Godot": version}, "cpu": read_cpu(),
                   "runs": runs, "skipped": skipped + more}
            msg = f"{len(runs)} runs, {len(doc['skipped'])} skipped"
    peer_io.write_json(a.out, doc)
    print(f"godot_driver.py: {msg} -> {a.out}")
    return 0


if __name__ == "__main__":
    try:
        sys.exit(main())
    except (DriverError, OSError, ValueError, KeyError, struct.error) as e:
        print(f"godot_driver.py: {e}", file=sys.stderr)
        sys.exit(1)
