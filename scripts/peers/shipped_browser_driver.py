#!/usr/bin/python3
"""SVG arc length as real browsers ship it: getTotalLength() and
getPointAtLength() of headless Chromium and Firefox ESR on the cases of a shipped-peer request,
written as JSON (format curvebench-shipped-driver-1) for scripts/peers/shipped_results.py to measure.

  shipped_browser_driver.py --request FILE --out FILE [--work DIR] [--chromium PATH]
                            [--firefox PATH] [--timeout SECONDS] [--pass-ms MS] [--passes N]

The request (format curvebench-shipped-request-1) lists cases, each with its SVG path data "d",
optionally the equivalent basic shape ({"element": "circle" | "ellipse" | "rect", "attributes"}),
the arc lengths "s" at which to ask for the point at length, and "spaced" (n points at k / (n - 1)
times the browser's own getTotalLength(), k = 0 .. n - 1, computed in the page as
(k / (n - 1)) * length in doubles).

Peers, per browser: peer_<browser>_path measures a <path d=...>; peer_<browser>_shape (only cases
with a shape) the <circle>, <ellipse> or <rect> itself, whose geometry an engine may measure by
another route (Chromium: a shape's path through Skia's contour measure, a <path> through Blink's
own traversal of its path data). Every element sits in a small rendered <svg> of the page, so
each call includes the engine's check that style and layout are up to date (about 1.5 us in
Chromium 156, against a detached <path>). Values: the doubles JavaScript returns, recorded as
they come (Chromium 156 and Firefox 153 compute lengths and DOMPoints in float32: every recorded
value is a float32).

Timing, in the page with performance.now(): a loop of many calls, its count doubled until one pass
takes at least --pass-ms (default 25 ms), then the best of --passes (default 5) passes at that
count, divided by the count; every result is added to a sink the page reports, so no call is dead.
Browsers coarsen performance.now() (Chromium: 100 us for a page that is not cross-origin isolated;
Firefox: 1 ms, 20 us with privacy.reduceTimerPrecision off, as the profile this driver writes sets
it): with passes of 25 ms the coarsening costs at most 0.4 % (Chromium). The observed timer step is
recorded per browser and in each run's note. What is timed:
  ns_length  getTotalLength() on the unchanged element: what a caller asking again pays (an
             engine may keep what it built between calls: Firefox 153 answers a basic shape's
             length in about 50 ns, a cache hit; its <path>s and Chromium's are measured anew);
  ns_point   getPointAtLength(s) on the unchanged element, s cycling through the request's s;
  ns_build   setAttribute() then getTotalLength(), the attribute alternating between two spellings
             of the same value (a <path>'s d and d + " "; a shape's first attribute as written and
             with a trailing space): every call parses the new string and measures a new geometry,
             with the style and layout update the engine needs between the two. Null (with a note)
             where the second spelling does not give the same length.

Chromium runs as chromium_driver.py runs it: `chromium --headless=new --dump-dom file://page.html`
with a fresh profile; the page writes its JSON into <pre id=RESULT_ID>. Firefox cannot dump the
DOM: `firefox-esr --headless --no-remote --profile DIR URL` with a fresh profile (a user.js turning
off first-run pages, telemetry, updates and other background requests) loads the page from a
listener the driver runs on 127.0.0.1 (an ephemeral port, loopback only), and the page POSTs its
JSON back to it; the driver then stops the listener and Firefox (its process group). A browser
that is not installed is listed in "skipped" for each of its runs; a browser that fails or times
out (--timeout, default 120 s + 2 s per run, for each browser) is an error: its runs are listed in
"skipped" with the reason, the output is still written (with "errors"), and the driver exits 1.

The page, the Firefox profile, the parsing and checking of a browser's result and the run records
are pure functions (tested with plain Python by tests/python/test_shipped_browser_driver.py on a
recorded result); only main() starts browsers.
"""
import argparse
import http.server
import json
import math
import os
import queue
import re
import shutil
import subprocess
import sys
import tempfile
import threading
import time

import peer_io

DRIVER = "shipped_browser"
FORMAT = "curvebench-shipped-driver-1"
REQUEST_FORMAT = "curvebench-shipped-request-1"
RESULT_ID = peer_io.RESULT_ID
BROWSERS = ("chromium", "firefox")
SHAPES = {"circle": ("cx", "cy", "r"), "ellipse": ("cx", "cy", "rx", "ry"),
          "rect": ("x", "y", "width", "height", "rx", "ry")}
PASS_MS = 25.0
PASSES = 5
TIMEOUT_S = 120.0  # per browser, plus TIMEOUT_PER_JOB_S per job of the page
TIMEOUT_PER_JOB_S = 2.0

NOTE_PATH = ("ns_length: getTotalLength() on the unchanged <path>; ns_point: getPointAtLength() on it, s "
             "cycling through the request's s; ns_build: setAttribute('d') alternating between d and d + ' ' "
             "(the same path, another string: parsed again), then getTotalLength(), with the engine's style and "
             "layout update between them")
NOTE_SHAPE = ("ns_length: getTotalLength() on the unchanged <{element}>; ns_point: getPointAtLength() on it, s "
              "cycling through the request's s; ns_build: setAttribute('{attribute}') alternating between its "
              "value as written and with a trailing space (the same geometry, another string), then "
              "getTotalLength(), with the engine's style and layout update between them")


class DriverError(Exception):
    pass


def peer_id(browser, kind):
    """peer_chromium_path, peer_firefox_shape, ..."""
    return f"peer_{browser}_{kind}"


def _number(v):
    return isinstance(v, (int, float)) and not isinstance(v, bool) and math.isfinite(v)


def jobs_of(request):
    """The page's jobs from a request: per case a "path" job and, for a case with a shape, a
    "shape" job: {"case", "kind", "element", "attributes" (name -> string, in order), "s",
    "spaced"}. A request that is not the expected format or holds a malformed case raises
    DriverError."""
    if not isinstance(request, dict) or request.get("format") != REQUEST_FORMAT:
        raise DriverError(f"the request is not {REQUEST_FORMAT}")
    cases = request.get("cases")
    if not isinstance(cases, list):
        raise DriverError("the request holds no list of cases")
    jobs, seen = [], set()
    for c in cases:
        name = c.get("case") if isinstance(c, dict) else None
        if not isinstance(name, str) or not name or name in seen:
            raise DriverError(f"a case without a name, or named twice: {name!r}")
        seen.add(name)
        d, s, n = c.get("d"), c.get("s"), c.get("spaced")
        if not isinstance(d, str) or not d.strip():
            raise DriverError(f"{name}: no path data d")
        if not isinstance(s, list) or not all(_number(x) for x in s):
            raise DriverError(f"{name}: s is not a list of finite numbers")
        if not isinstance(n, int) or isinstance(n, bool) or n < 0 or n == 1:
            raise DriverError(f"{name}: spaced must be 0 or a count of at least 2, not {n!r}")
        base = {"case": name, "s": [float(x) for x in s], "spaced": n}
        jobs.append(dict(base, kind="path", element="path", attributes={"d": d}))
        shape = c.get("shape")
        if shape is None:
            continue
        element = shape.get("element") if isinstance(shape, dict) else None
        attrs = shape.get("attributes") if isinstance(shape, dict) else None
        if element not in SHAPES or not isinstance(attrs, dict) or not attrs:
            raise DriverError(f"{name}: a shape must be a circle, ellipse or rect with attributes: {shape!r}")
        for k, v in attrs.items():
            if k not in SHAPES[element] or not _number(v):
                raise DriverError(f"{name}: <{element}> attribute {k}={v!r} (allowed: {', '.join(SHAPES[element])})")
        jobs.append(dict(base, kind="shape", element=element,
                         attributes={k: _attribute_text(v) for k, v in attrs.items()}))
    return jobs


def _attribute_text(v):
    """A number as an attribute value: integers without a fraction, others as repr (shortest
    round-trip; SVG and CSS read an exponent)."""
    if float(v).is_integer() and abs(v) < 2 ** 53:
        return str(int(v))
    return repr(float(v))


def page(jobs, post_url=None, pass_ms=PASS_MS, passes=PASSES):
    """The HTML page measuring `jobs`; its script writes JSON into <pre id=RESULT_ID> and, with
    post_url, also POSTs it there: {"userAgent", "timer_step_ms", "pass_ms", "passes", "sink",
    "results": [{"case", "kind", "length", "points", "spaced", "ns_length", "ns_point",
    "ns_build", "build_same", "calls"} or {"case", "kind", "error"}]} or {"error"}."""
    data = json.dumps([{k: j[k] for k in ("case", "kind", "element", "attributes", "s", "spaced")} for j in jobs])
    # "</" never appears inside the script element's text.
    data = data.replace("</", "<\\/")
    post = json.dumps(post_url)
    return f"""<!doctype html>
<html><head><meta charset="utf-8"><title>curvebench shipped SVG length peer</title></head>
<body><svg id="stage" xmlns="http://www.w3.org/2000/svg" width="8" height="8" viewBox="0 0 8 8"></svg>
<pre id="{RESULT_ID}"></pre>
<script>
"use strict";
const jobs = {data};
const POST = {post};
const PASS_MS = {float(pass_ms)!r};
const PASSES = {int(passes)};
const SVGNS = "http://www.w3.org/2000/svg";
let sink = 0;

// The smallest step performance.now() takes, over 50 ms.
function timerStep() {{
  let step = Infinity;
  let last = performance.now();
  const end = last + 50;
  for (;;) {{
    const t = performance.now();
    if (t !== last) {{ step = Math.min(step, t - last); last = t; }}
    if (t > end) break;
  }}
  return step;
}}

// ns per call of body(count): the count doubled until a pass takes PASS_MS, then the best of PASSES.
function timed(body) {{
  let count = 1, ms = 0;
  for (;;) {{
    const t0 = performance.now();
    body(count);
    ms = performance.now() - t0;
    if (ms >= PASS_MS || count >= 1 << 30) break;
    count *= ms < PASS_MS / 16 ? 8 : 2;
  }}
  let best = Infinity;
  for (let p = 0; p < PASSES; p++) {{
    const t0 = performance.now();
    body(count);
    best = Math.min(best, performance.now() - t0);
  }}
  return {{ns: best * 1e6 / count, count: count}};
}}

function measure(job, stage) {{
  const el = document.createElementNS(SVGNS, job.element);
  const names = Object.keys(job.attributes);
  for (const k of names) el.setAttribute(k, job.attributes[k]);
  stage.appendChild(el);
  try {{
    const length = el.getTotalLength();
    const xy = (s) => {{ const p = el.getPointAtLength(s); return [p.x, p.y]; }};
    const points = job.s.map(xy);
    const spaced = [];
    for (let k = 0; k < job.spaced; k++) spaced.push(xy(k / (job.spaced - 1) * length));
    const tl = timed((count) => {{ for (let i = 0; i < count; i++) sink += el.getTotalLength(); }});
    const ss = job.s.length ? job.s : [0.5 * length];
    const m = ss.length;
    const tp = timed((count) => {{
      for (let i = 0; i < count; i++) {{ const p = el.getPointAtLength(ss[i % m]); sink += p.x + p.y; }}
    }});
    // Two spellings of the same value: the engine parses and measures anew at every call.
    const name = names[0];
    const a = job.attributes[name], b = a + " ";
    el.setAttribute(name, b);
    const lengthB = el.getTotalLength();
    el.setAttribute(name, a);
    const lengthA = el.getTotalLength();
    const buildSame = lengthA === length && lengthB === length;
    const tb = timed((count) => {{
      for (let i = 0; i < count; i++) {{ el.setAttribute(name, i & 1 ? b : a); sink += el.getTotalLength(); }}
    }});
    el.setAttribute(name, a);
    return {{case: job.case, kind: job.kind, length: length, points: points, spaced: spaced,
             ns_length: tl.ns, ns_point: tp.ns, ns_build: buildSame ? tb.ns : null, build_same: buildSame,
             build_lengths: [lengthA, lengthB], calls: [tl.count, tp.count, tb.count]}};
  }} finally {{
    el.remove();
  }}
}}

function deliver(out) {{
  const text = JSON.stringify(out);
  document.getElementById("{RESULT_ID}").textContent = text;
  if (POST) fetch(POST, {{method: "POST", headers: {{"Content-Type": "application/json"}}, body: text}});
}}

let out = {{userAgent: navigator.userAgent, pass_ms: PASS_MS, passes: PASSES, results: []}};
try {{
  out.timer_step_ms = timerStep();
  const stage = document.getElementById("stage");
  for (const job of jobs) {{
    try {{
      out.results.push(measure(job, stage));
    }} catch (e) {{
      out.results.push({{case: job.case, kind: job.kind, error: String(e)}});
    }}
  }}
  out.sink = sink;
}} catch (e) {{
  out = {{error: String(e)}};
}}
deliver(out);
</script></body></html>
"""


def user_js():
    """The fresh Firefox profile's user.js: no first-run or welcome pages, no default-browser check,
    no telemetry or health report, no update checks (application, add-ons), no Normandy studies,
    safe-browsing lists, captive-portal or connectivity probes, no proxy (the page is on
    127.0.0.1), no slow-script interruption of the measuring page, and performance.now() at full
    resolution (privacy.reduceTimerPrecision off)."""
    prefs = [
        ("browser.shell.checkDefaultBrowser", False),
        ("browser.startup.homepage_override.mstone", "ignore"),
        ("startup.homepage_welcome_url", ""),
        ("startup.homepage_welcome_url.additional", ""),
        ("browser.aboutwelcome.enabled", False),
        ("browser.startup.page", 0),
        ("browser.newtabpage.enabled", False),
        ("browser.sessionstore.resume_from_crash", False),
        ("toolkit.startup.max_resumed_crashes", -1),
        ("datareporting.policy.dataSubmissionEnabled", False),
        ("datareporting.healthreport.uploadEnabled", False),
        ("toolkit.telemetry.enabled", False),
        ("toolkit.telemetry.unified", False),
        ("toolkit.telemetry.archive.enabled", False),
        ("toolkit.telemetry.server", ""),
        ("app.normandy.enabled", False),
        ("app.shield.optoutstudies.enabled", False),
        ("app.update.auto", False),
        ("app.update.checkInstallTime", False),
        ("extensions.update.enabled", False),
        ("extensions.getAddons.cache.enabled", False),
        ("browser.safebrowsing.malware.enabled", False),
        ("browser.safebrowsing.phishing.enabled", False),
        ("browser.safebrowsing.downloads.enabled", False),
        ("browser.safebrowsing.downloads.remote.enabled", False),
        ("network.captive-portal-service.enabled", False),
        ("network.connectivity-service.enabled", False),
        ("network.proxy.type", 0),
        ("dom.max_script_run_time", 0),
        ("privacy.reduceTimerPrecision", False),
    ]
    return "".join(f"user_pref({json.dumps(k)}, {json.dumps(v)});\n" for k, v in prefs)


def parse_dump(dom):
    """The JSON the page wrote, from chromium --dump-dom's output."""
    return peer_io.dump_result(dom, DriverError)


def parse_result(text):
    """The page's JSON (as posted to the listener or unescaped from the dump); a page whose script
    failed raises DriverError naming the error."""
    return peer_io.page_result(text, DriverError)


def _points(v, n, what):
    if not isinstance(v, list) or len(v) != n:
        raise DriverError(f"{what}: expected {n} points, got {len(v) if isinstance(v, list) else v!r}")
    out = []
    for i, p in enumerate(v):
        if not (isinstance(p, list) and len(p) == 2 and all(_number(x) for x in p)):
            raise DriverError(f"{what}: point {i} is {p!r}")
        out.append([float(p[0]), float(p[1])])
    return out


def _ns(v, what):
    if v is None:
        return None
    if not _number(v) or v <= 0:
        raise DriverError(f"{what}: {v!r} is not a positive time")
    return float(v)


def runs_of(doc, jobs, browser):
    """(runs, skipped) from a page's result for `jobs`, measured by `browser` ("chromium" or
    "firefox"): one run record per job, or a skipped entry for a job the page's script could not
    run. A result whose jobs, counts or values do not match the request raises DriverError."""
    results = doc.get("results")
    if not isinstance(results, list) or len(results) != len(jobs):
        raise DriverError(f"expected {len(jobs)} results, got {len(results) if isinstance(results, list) else 0}")
    step = doc.get("timer_step_ms")
    runs, skipped = [], []
    for job, r in zip(jobs, results):
        case, kind = job["case"], job["kind"]
        peer = peer_id(browser, kind)
        if not isinstance(r, dict) or r.get("case") != case or r.get("kind") != kind:
            got = (r.get("case"), r.get("kind")) if isinstance(r, dict) else r
            raise DriverError(f"result for {got!r} where {(case, kind)!r} was asked")
        what = f"{peer} on {case}"
        if "error" in r:
            skipped.append({"peer": peer, "case": case, "reason": f"the page's script failed: {r['error']}"})
            continue
        length = r.get("length")
        if not _number(length) or length < 0:
            raise DriverError(f"{what}: getTotalLength() gave {length!r}")
        run = {"peer": peer, "case": case, "setting": "", "length": float(length),
               "points": _points(r.get("points"), len(job["s"]), what + ": points"),
               "spaced": _points(r.get("spaced"), job["spaced"], what + ": spaced") if job["spaced"] else None,
               "ns_length": _ns(r.get("ns_length"), what + ": ns_length"),
               "ns_point": _ns(r.get("ns_point"), what + ": ns_point") if job["s"] else None,
               "ns_build": _ns(r.get("ns_build"), what + ": ns_build")}
        if kind == "path":
            note = NOTE_PATH
        else:
            note = NOTE_SHAPE.format(element=job["element"], attribute=next(iter(job["attributes"])))
        if r.get("build_same") is not True:
            run["ns_build"] = None
            note += (f"; ns_build not recorded: the second spelling gave the lengths "
                     f"{r.get('build_lengths')!r}, not {length!r} twice")
        if _number(step):
            note += f"; performance.now() step {step:.6g} ms"
        run["note"] = note
        runs.append(run)
    return runs, skipped


def skipped_all(jobs, browser, reason):
    """Every run of `browser` over `jobs` as skipped, with `reason`."""
    return [{"peer": peer_id(browser, j["kind"]), "case": j["case"], "reason": reason} for j in jobs]


def cpu_model(cpuinfo):
    """The first "model name" of /proc/cpuinfo's text, or None."""
    m = re.search(r"^model name\s*:\s*(.+?)\s*$", cpuinfo, re.M)
    return m.group(1) if m else None


def assemble(versions, cpu, outcomes, page_info=None):
    """The driver's output from {browser: (runs, skipped)} in BROWSERS order; page_info: {browser:
    {"user_agent", "timer_step_ms", "pass_ms", "passes"}} of the pages that ran."""
    runs, skipped = [], []
    for b in BROWSERS:
        if b in outcomes:
            runs += outcomes[b][0]
            skipped += outcomes[b][1]
    out = {"driver": DRIVER, "format": FORMAT, "versions": {b: versions.get(b) for b in BROWSERS},
           "cpu": cpu, "runs": runs, "skipped": skipped}
    if page_info:
        out["pages"] = {b: page_info[b] for b in BROWSERS if b in page_info}
    return out


def page_info_of(doc):
    return {"user_agent": doc.get("userAgent"), "timer_step_ms": doc.get("timer_step_ms"),
            "pass_ms": doc.get("pass_ms"), "passes": doc.get("passes")}


# --- What starts browsers (main() only) ---

def _version(program):
    return subprocess.run([program, "--version"], capture_output=True, text=True, check=True,
                          timeout=60).stdout.strip().splitlines()[0]


def run_chromium(program, text, work, timeout):
    """The page's result from `chromium --headless=new --dump-dom` on the page written to work."""
    page_path = os.path.abspath(os.path.join(work, "chromium_page.html"))
    with open(page_path, "w", encoding="utf-8") as f:
        f.write(text)
    dom = peer_io.chromium_dump(program, page_path, os.path.join(work, "chromium_profile"), timeout, DriverError)
    with open(os.path.join(work, "chromium_dump.html"), "w", encoding="utf-8") as f:
        f.write(dom)
    return parse_dump(dom)


class _Listener(http.server.HTTPServer):
    """127.0.0.1 only, on an ephemeral port: serves the page, takes the page's POST."""

    def __init__(self, page_bytes):
        self.page_bytes = page_bytes
        self.results = queue.Queue()
        super().__init__(("127.0.0.1", 0), _Handler)


class _Handler(http.server.BaseHTTPRequestHandler):
    def log_message(self, *args):
        pass

    def _send(self, code, body=b"", kind="text/plain"):
        self.send_response(code)
        self.send_header("Content-Type", kind)
        self.send_header("Content-Length", str(len(body)))
        self.send_header("Cache-Control", "no-store")
        self.end_headers()
        self.wfile.write(body)

    def do_GET(self):
        if self.path == "/page.html":
            self._send(200, self.server.page_bytes, "text/html; charset=utf-8")
        else:
            self._send(404)

    def do_POST(self):
        if self.path != "/result":
            self._send(404)
            return
        n = int(self.headers.get("Content-Length") or 0)
        body = self.rfile.read(n)
        self._send(204)
        self.server.results.put(body.decode("utf-8", "replace"))


def run_firefox(program, page_of_url, work, timeout):
    """The page's result from headless Firefox: a listener on 127.0.0.1 serves the page (built by
    page_of_url(post_url)) and takes its POST; Firefox is stopped once it arrives or at the timeout."""
    profile = os.path.join(work, "firefox_profile")
    shutil.rmtree(profile, ignore_errors=True)
    os.makedirs(profile)
    with open(os.path.join(profile, "user.js"), "w", encoding="utf-8") as f:
        f.write(user_js())
    text = page_of_url("/result")
    with open(os.path.join(work, "firefox_page.html"), "w", encoding="utf-8") as f:
        f.write(text)
    server = _Listener(text.encode("utf-8"))
    thread = threading.Thread(target=server.serve_forever, daemon=True)
    thread.start()
    url = f"http://127.0.0.1:{server.server_address[1]}/page.html"
    home = os.path.join(work, "firefox_home")  # what Firefox writes outside its profile (Downloads, caches)
    os.makedirs(home, exist_ok=True)
    env = dict(os.environ, HOME=home, MOZ_HEADLESS="1")
    log = open(os.path.join(work, "firefox.log"), "w", encoding="utf-8")
    proc = subprocess.Popen([program, "--headless", "--no-remote", "--profile", profile, url],
                            stdout=log, stderr=subprocess.STDOUT, env=env, start_new_session=True)
    try:
        deadline = time.monotonic() + timeout
        while True:
            try:
                body = server.results.get(timeout=0.5)
                break
            except queue.Empty:
                pass
            if proc.poll() is not None:
                raise DriverError(f"firefox exited with status {proc.returncode} before the page posted its "
                                  f"result (see {os.path.join(work, 'firefox.log')})")
            if time.monotonic() > deadline:
                raise DriverError(f"firefox timed out after {timeout:g} s: the page posted no result")
    finally:
        peer_io.stop_group(proc)
        log.close()
        server.shutdown()
        server.server_close()
    with open(os.path.join(work, "firefox_result.json"), "w", encoding="utf-8") as f:
        f.write(body)
    return parse_result(body)


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--request", required=True)
    ap.add_argument("--out", required=True)
    ap.add_argument("--work", help="where the pages and raw results are kept (default: a temporary directory)")
    ap.add_argument("--chromium", default="chromium")
    ap.add_argument("--firefox", default="firefox-esr")
    ap.add_argument("--timeout", type=float, help="seconds per browser (default: 120 + 2 per run)")
    ap.add_argument("--pass-ms", type=float, default=PASS_MS)
    ap.add_argument("--passes", type=int, default=PASSES)
    a = ap.parse_args()
    try:
        with open(a.request, encoding="utf-8") as f:
            jobs = jobs_of(json.load(f))
    except (OSError, json.JSONDecodeError, DriverError) as e:
        print(f"shipped_browser_driver: {a.request}: {e}", file=sys.stderr)
        return 2
    try:
        with open("/proc/cpuinfo", encoding="utf-8") as f:
            cpu = cpu_model(f.read())
    except OSError:
        cpu = None
    programs = {"chromium": a.chromium, "firefox": a.firefox}
    timeout = a.timeout if a.timeout is not None else TIMEOUT_S + TIMEOUT_PER_JOB_S * len(jobs)
    versions, outcomes, info, errors = {}, {}, {}, []
    with tempfile.TemporaryDirectory() as tmp:
        work = os.path.abspath(a.work or tmp)
        os.makedirs(work, exist_ok=True)
        for b in BROWSERS:
            program = shutil.which(programs[b])
            if not program:
                versions[b] = None
                outcomes[b] = ([], skipped_all(jobs, b, f"{programs[b]} is not on PATH"))
                print(f"shipped_browser_driver: {programs[b]} is not on PATH; its runs are skipped", file=sys.stderr)
                continue
            try:
                versions[b] = _version(program)
                if b == "chromium":
                    doc = run_chromium(program, page(jobs, None, a.pass_ms, a.passes), work, timeout)
                else:
                    doc = run_firefox(program, lambda url: page(jobs, url, a.pass_ms, a.passes), work, timeout)
                outcomes[b] = runs_of(doc, jobs, b)
                info[b] = page_info_of(doc)
            except (OSError, subprocess.SubprocessError, DriverError) as e:
                errors.append(f"{b}: {e}")
                print(f"shipped_browser_driver: error: {b}: {e}", file=sys.stderr)
                outcomes[b] = ([], skipped_all(jobs, b, f"error: {e}"))
            finally:
                for d in ("chromium_profile", "firefox_profile", "firefox_home"):
                    shutil.rmtree(os.path.join(work, d), ignore_errors=True)
    out = assemble(versions, cpu, outcomes, info)
    if errors:
        out["errors"] = errors
    peer_io.write_json(a.out, out)
    print(f"shipped_browser_driver: {len(out['runs'])} runs, {len(out['skipped'])} skipped -> {a.out}")
    return 1 if errors else 0


if __name__ == "__main__":
    sys.exit(main())
