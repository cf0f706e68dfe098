"""What the optional peers' Python scripts share (scripts/peers/*.py, run from this directory or
imported with it on sys.path): the accuracy runner's sample fractions, the all-or-nothing write of
a result file, `curvebench sample`'s command and CSV for the tool models beside the peers, the
timing loop and the running of a peer program. Also imported inside Blender's Python
(blender_length.py): only the standard library and scripts/safe_output.py."""
import contextlib
import csv
import html
import json
import os
import re
import shutil
import signal
import subprocess
import sys
import tempfile
import time

sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
import safe_output  # noqa: E402

# The element a browser peer's page writes its JSON into (chromium --dump-dom prints it).
RESULT_ID = "curvebench-result"
INV_PHI = 0.6180339887498949  # 1 / golden ratio, as bench/harness/sweeps.hpp


def sample_fractions(n):
    """harness/sweeps.hpp sample_fractions: 0, 1 and frac(j / phi) in between, the same doubles."""
    return [0.0 if j == 0 else 1.0 if j + 1 == n else (j * INV_PHI) % 1.0 for j in range(n)]


def write_json(path, doc):
    """doc as indented JSON at path through scripts/safe_output.py: only a regular file or a new
    path is replaced, and an interrupted run never leaves a half-written file."""
    safe_output.write_text(path, json.dumps(doc, indent=1))


def best_ns(fn, pass_ns, passes, slow_call_ns=None):
    """(fn's value, its best ns per call) by time.perf_counter_ns: a warm-up call (its value
    returned), then the call count doubled (up to 2**20) until one pass of that many calls lasts
    pass_ns, then the best of `passes` further passes of that count, per call. slow_call_ns: a
    warm-up call slower than that skips the doubling and times 2 passes of one call."""
    t0 = time.perf_counter_ns()
    value = fn()
    if slow_call_ns is not None and time.perf_counter_ns() - t0 > slow_call_ns:
        passes, count = 2, 1
    else:
        count = 1
        while True:
            t0 = time.perf_counter_ns()
            for _ in range(count):
                fn()
            if time.perf_counter_ns() - t0 >= pass_ns or count >= 1 << 20:
                break
            count *= 2
    best = None
    for _ in range(passes):
        t0 = time.perf_counter_ns()
        for _ in range(count):
            fn()
        dt = (time.perf_counter_ns() - t0) / count
        best = dt if best is None else min(best, dt)
    return value, best


def sample_command(tool, spec_path, times_path, as_tool=True):
    """`curvebench sample` of a channel spec at the times listed in times_path, values only. as_tool:
    the tool model's own evaluation (`--as-tool`: Blender's in float as Blender stores it, the CSS
    model with its solver), what the peers are compared beside; without it `sample` prints the
    channel's 50-digit truth rounded to double (a glTF rotation has only its sampler's evaluation
    and refuses --as-tool)."""
    return ([tool, "sample", spec_path, "--at-file", times_path, "--derivatives", "0", "--quiet"]
            + (["--as-tool"] if as_tool else []))


def read_sample(path, times, columns=("value",), error=ValueError, exact_times=True):
    """The values of a `curvebench sample` CSV at `times`: its first lines starting with '#' (what
    was sampled) skipped, then the header t and `columns`, then one row per time. exact_times: each
    row's t must be the time asked for (a float32 model prints t to 9 digits: not exact). Returns a
    float per row for one column, else a tuple per row; raises `error` naming the file otherwise."""
    with open(path, encoding="utf-8") as f:
        rows = [r for r in csv.reader(line for line in f if not line.startswith("#")) if r]
    header = ["t", *columns]
    if not rows or rows[0] != header:
        raise error(f"{path}: expected the header {','.join(header)}"
                    + (f", not {','.join(rows[0])}" if rows else ", the file has no rows"))
    body = rows[1:]
    if len(body) != len(times):
        raise error(f"{path}: {len(body)} rows for {len(times)} times")
    for i, (r, t) in enumerate(zip(body, times)):
        if exact_times and float(r[0]) != t:
            raise error(f"{path}: row {i + 2} is at t = {r[0]}, the driver's time is {t!r}")
    if len(columns) == 1:
        return [float(r[1]) for r in body]
    return [tuple(float(x) for x in r[1:1 + len(columns)]) for r in body]


def page_result(text, error):
    """The JSON object a browser peer's page produced (its text, as posted or unescaped from a dump);
    error(message) is raised when it is not a JSON object or names the error its script hit."""
    try:
        doc = json.loads(text)
    except json.JSONDecodeError as e:
        raise error(f"the page's result is not JSON: {e}") from e
    if not isinstance(doc, dict):
        raise error("the page's result is not a JSON object")
    if "error" in doc:
        raise error(f"the page's script failed: {doc['error']}")
    return doc


def dump_result(dom, error):
    """page_result of the <pre id=RESULT_ID> in chromium --dump-dom's output."""
    m = re.search(rf'<pre id="{RESULT_ID}">(.*?)</pre>', dom, re.S)
    if not m or not m.group(1).strip():
        raise error("the dumped DOM holds no result (did the page's script run?)")
    return page_result(html.unescape(m.group(1)), error)


def stop_group(proc):
    """Ends the process group a driver started for one browser (start_new_session), then reaps it."""
    if proc.poll() is None:
        try:
            os.killpg(proc.pid, signal.SIGTERM)
            proc.wait(timeout=10)
        except (ProcessLookupError, subprocess.TimeoutExpired):
            pass
    try:
        os.killpg(proc.pid, signal.SIGKILL)
    except ProcessLookupError:
        pass
    proc.wait()


def chromium_dump(program, page_path, profile, timeout, error):
    """The DOM `chromium --headless=new --dump-dom` prints for the page at page_path, with a fresh
    profile directory; the browser's whole process group is ended on return. error(message) for a
    timeout or an empty dump."""
    # --no-sandbox: the driver may run as root (containers, CI), where Chromium's sandbox refuses.
    cmd = [program, "--headless=new", "--no-sandbox", "--disable-gpu", "--no-first-run",
           f"--user-data-dir={profile}", "--dump-dom", "file://" + os.path.abspath(page_path)]
    proc = subprocess.Popen(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, start_new_session=True)
    try:
        dom, err = proc.communicate(timeout=timeout)
    except subprocess.TimeoutExpired:
        stop_group(proc)
        raise error(f"chromium timed out after {timeout:g} s without dumping the page") from None
    finally:
        stop_group(proc)
    if not dom.strip():
        raise error(f"chromium exited with status {proc.returncode} and dumped nothing: {err.strip()[-400:]}")
    return dom


@contextlib.contextmanager
def work_dir(keep, prefix):
    """The directory a driver's peer program reads and writes its files in: `keep` (created if need
    be and left in place) or a new temporary one, removed with its files on leaving."""
    work = keep or tempfile.mkdtemp(prefix=prefix)
    os.makedirs(work, exist_ok=True)
    try:
        yield work
    finally:
        if not keep:
            shutil.rmtree(work, ignore_errors=True)


def run_batch(cmd, out, timeout, name, **popen_args):
    """Runs a peer program that writes its answer to the file `out` (cmd, in a session of its own,
    stdout and stderr in one log; popen_args such as cwd and env passed on) and returns its log.
    DriverError naming it as `name` when it runs past `timeout` seconds (its process group is ended),
    exits with a non-zero status or writes no `out`."""
    proc = subprocess.Popen(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, start_new_session=True,
                            **popen_args)
    try:
        log, _ = proc.communicate(timeout=timeout)
    except subprocess.TimeoutExpired:
        stop_group(proc)
        raise DriverError(f"{name} did not finish within {timeout:g} s") from None
    if proc.returncode != 0 or not os.path.exists(out):
        raise DriverError(f"{name} exited with status {proc.returncode}: {log.strip()[-600:]}")
    return log


# The arc-length peers' request (scripts/peers/shipped_request.py) as the Python drivers read it.
SHIPPED_REQUEST_FORMAT = "curvebench-shipped-request-1"


class DriverError(Exception):
    """A driver's input or its peer's answer is unusable; the message names which and why."""


def cpu_model(text):
    """The first "model name" of /proc/cpuinfo's text, or None."""
    for line in text.splitlines():
        if line.startswith("model name") and ":" in line:
            return line.split(":", 1)[1].strip()
    return None


def read_cpu():
    """This machine's CPU model (recorded with every timed run), or None."""
    try:
        with open("/proc/cpuinfo", encoding="utf-8") as f:
            return cpu_model(f.read())
    except OSError:
        return None


def load_request(path, only=None):
    """(request, its cases: all, or those named in `only`, which must all exist); DriverError
    naming the file or the missing names otherwise."""
    with open(path, encoding="utf-8") as f:
        request = json.load(f)
    if not isinstance(request, dict) or request.get("format") != SHIPPED_REQUEST_FORMAT:
        raise DriverError(f"{path}: not a {SHIPPED_REQUEST_FORMAT} document")
    cases = request.get("cases")
    if not isinstance(cases, list):
        raise DriverError(f"{path}: no list of cases")
    if only:
        names = {c.get("case") for c in cases}
        missing = [n for n in only if n not in names]
        if missing:
            raise DriverError(f"--only names cases not in the request: {', '.join(missing)}")
        cases = [c for c in cases if c.get("case") in only]
    return request, cases


def _lerp(a, b, t):
    return [a[0] + (b[0] - a[0]) * t, a[1] + (b[1] - a[1]) * t]


def cubic_of(segment):
    """The four control points of a request segment as a cubic Bezier: a line with its inner points
    at one and two thirds, a quadratic raised (p0, p0 + 2/3 (q - p0), p2 + 2/3 (q - p2), p2), a cubic
    as is. DriverError for an arc (no exact Bezier) or an unknown kind."""
    kind, p = segment.get("kind"), [[float(v) for v in q] for q in segment.get("points", [])]
    if kind == "line" and len(p) == 2:
        return [p[0], _lerp(p[0], p[1], 1 / 3), _lerp(p[0], p[1], 2 / 3), p[1]]
    if kind == "quadratic" and len(p) == 3:
        return [p[0], _lerp(p[0], p[1], 2 / 3), _lerp(p[2], p[1], 2 / 3), p[2]]
    if kind == "cubic" and len(p) == 4:
        return p
    if kind == "arc":
        raise DriverError("an elliptical arc has no exact Bezier form")
    raise DriverError(f"a {kind!r} segment with {len(p)} points")
