#!/usr/bin/python3
"""REPORT.html in headless Chromium (Debian's `chromium`):
  - the page loads without a console error, an uncaught exception or a failed resource;
  - it loads nothing but its own plots (the page's resource timing lists no script, style or font, and
    no image but a data: URI or a file under the report's plots/);
  - the summary's table shows, cell for cell, the table report_summary.py builds from the accuracy
    JSON the report came from (recomputed here from that JSON, not read back from REPORT.md);
  - clicking a column's heading sorts the rows by it (numbers by value), a second click reverses,
    and the text filter hides the rows that do not match;
  - screenshots of the page's top (the summary) and of a deep link (REPORT.html#DEEP_ANCHOR, the
    shipped-software section, far down the page) are written (the test's artifacts), neither blank
    and not the same picture (the link scrolled): not_blank() says what blank is;
  - a control run (the page without its script, a console error planted) must fail those checks.
  check_report_html.py --reports DIR --screenshot PNG [--chromium PATH] [--work DIR]
(the deep link's screenshot is PNG with "-deep" before its extension)
  check_report_html.py --tool CURVEBENCH --only TEXT --reports DIR --screenshot PNG ...
DIR holds REPORT.html and the inputs report.py read (accuracy.json, vocabulary.json, bench_*.json).
With --tool, DIR is made first: the tool's quick accuracy run of the cases named by --only, its
vocabulary, and scripts/report.py over them (ctest report_html_chromium).
Exits 0 when every check passes, 1 naming each failure, 2 when Chromium is missing.
"""
import argparse
import glob
import html
import json
import os
import re
import shutil
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "..", "scripts"))
import report_lib as lib  # noqa: E402
import report_html  # noqa: E402
import report_summary  # noqa: E402

# Installed first in <head>: every console.error, uncaught exception and failed resource is kept.
PROBE_HEAD = """<script>
window.__problems = [];
(function () {
  var error = console.error;
  console.error = function () {
    window.__problems.push("console.error: " + Array.prototype.join.call(arguments, " "));
    return error.apply(console, arguments);
  };
  window.addEventListener("error", function (e) {
    window.__problems.push(e.message ? "uncaught: " + e.message
                                     : "resource failed: " + (e.target.src || e.target.href));
  }, true);
  window.addEventListener("unhandledrejection", function (e) { window.__problems.push("rejection: " + e.reason); });
})();
</script>"""

# Run after the page's own script: drives the first sortable table with a numeric column and reads
# the summary; the result goes into the DOM as JSON, which --dump-dom prints.
PROBE_TAIL = r"""<script>
(function () {
  var out = { problems: window.__problems, tables: document.querySelectorAll("div.table").length,
              resources: performance.getEntriesByType("resource").map(function (e) { return e.name; }) };
  function cellTexts(table, column) {
    return Array.prototype.map.call(table.tBodies[0].rows, function (r) { return r.cells[column].textContent.trim(); });
  }
  // The summary first, as loaded: the sorting below may pick its table.
  var summary = document.getElementById("summary");
  var table = null;
  for (var n = summary; n && !table; n = n.nextElementSibling) {
    if (n !== summary && /^H2$/.test(n.tagName)) break;
    if (n.matches && n.matches("div.table")) table = n.querySelector("table.data");
  }
  if (table) {
    out.summary_head = Array.prototype.map.call(table.tHead.rows[0].cells, function (c) { return c.textContent; });
    out.summary_rows = Array.prototype.map.call(table.tBodies[0].rows, function (r) {
      return Array.prototype.map.call(r.cells, function (c) { return c.textContent; });
    });
  }
  out.summary_links = summary ? (function () {
    var links = [];
    for (var n = summary.nextElementSibling; n && n.tagName !== "H2"; n = n.nextElementSibling) {
      Array.prototype.forEach.call(n.querySelectorAll ? n.querySelectorAll("a[href^='#']") : [], function (a) {
        var id = a.getAttribute("href").slice(1);
        links.push({ href: a.getAttribute("href"), target: !!document.getElementById(id) });
      });
    }
    return links;
  })() : [];
  var NUMBER = /^\s*([-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?)/;
  var chosen = null;
  Array.prototype.some.call(document.querySelectorAll("table.data"), function (table) {
    var body = table.tBodies[0];
    if (body.rows.length < 3) return false;
    var heads = table.tHead.rows[0].cells;
    for (var c = 0; c < heads.length; c++) {
      var texts = cellTexts(table, c);
      var numeric = texts.filter(function (t) { return NUMBER.test(t); });
      var sorted = numeric.map(function (t) { return parseFloat(NUMBER.exec(t)[1]); });
      var ordered = sorted.every(function (v, i) { return i === 0 || sorted[i - 1] <= v; });
      if (numeric.length === texts.length && !ordered) { chosen = { table: table, column: c }; return true; }
    }
    return false;
  });
  if (chosen) {
    var th = chosen.table.tHead.rows[0].cells[chosen.column];
    out.sorted_heading = th.textContent;
    out.before = cellTexts(chosen.table, chosen.column);
    th.click();
    out.ascending = cellTexts(chosen.table, chosen.column);
    out.aria_ascending = th.getAttribute("aria-sort");
    th.click();
    out.descending = cellTexts(chosen.table, chosen.column);
    out.aria_descending = th.getAttribute("aria-sort");
    var box = chosen.table.closest("div.table");
    var input = box.querySelector("div.filters input");
    var term = out.before[0];
    input.value = term;
    input.dispatchEvent(new Event("input"));
    out.filter_term = term;
    out.filter_rows = Array.prototype.map.call(chosen.table.tBodies[0].rows, function (r) {
      return { hidden: r.hidden, text: r.textContent };
    });
    out.filter_count = box.querySelector("span.count").textContent;
  }
  var pre = document.createElement("pre");
  pre.id = "check-report-html";
  pre.textContent = JSON.stringify(out);
  document.body.appendChild(pre);
})();
</script>"""


def expected_summary(report_dir):
    """The summary table (head, rows) as report_summary.py builds it from the run's own JSON files."""
    with open(os.path.join(report_dir, "accuracy.json"), encoding="utf-8") as f:
        acc = json.load(f)
    vocab = lib.load_vocabulary(os.path.join(report_dir, "vocabulary.json"))
    _, rows = lib.load_benchmark_files(sorted(glob.glob(os.path.join(report_dir, "bench_*.json"))), vocab)
    fidelity = None
    if os.path.exists(os.path.join(report_dir, "fidelity.json")):
        with open(os.path.join(report_dir, "fidelity.json"), encoding="utf-8") as f:
            fidelity = json.load(f)
    lines = report_summary.flat(report_summary.summary_of_run(acc, report_dir, rows, vocab, fidelity))
    start = next(i for i, line in enumerate(lines) if line.startswith("| quantity"))
    table = []
    for line in lines[start:]:
        if not line.startswith("|"):
            break
        table.append(line)
    cells = [[report_html.shown_text(c) for c in report_html.split_row(row)] for row in table]
    return cells[0], cells[2:]


def key(text):
    m = re.match(r"\s*([-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?)", text)
    return float(m.group(1))


# The section a deep link is checked on: on every report (it says "Not run" without the drivers' files),
# and far down the page.
DEEP_ANCHOR = "arc-length-in-shipped-software"
# A screenshot is blank below these: a page of white (or of one colour) has 1 colour and no ink; a
# heading and a line of anti-aliased text already make dozens of grey levels and well over 0.2 % of
# the pixels non-white (a 1400 x 2200 window: 6160 pixels, about two lines of 12 px text).
MIN_COLOURS = 16
MIN_INK = 0.002


def not_blank(png_path):
    """None when the screenshot shows something (more than MIN_COLOURS colours and MIN_INK of its
    pixels not white), else why it is blank."""
    from PIL import Image
    with Image.open(png_path) as im:
        rgb = im.convert("RGB")
        colours = rgb.getcolors(maxcolors=1 << 24)
        n = rgb.width * rgb.height
    white = sum(c for c, v in colours if v == (255, 255, 255))
    ink = (n - white) / n
    if len(colours) <= MIN_COLOURS or ink < MIN_INK:
        return f"{png_path} is blank: {len(colours)} colours, {100 * ink:.3f} % of its pixels not white"
    return None


# Headless Chromium's --screenshot of a scrolled page is blank: it paints the document's first
# window-height of pixels and shows the scrolled-to part of the viewport (a plain page of 200
# headings, file.html#h150, is one white colour; #h10 shows ink only below the scroll offset), so
# REPORT.html#anchor itself cannot be photographed. The deep link's screenshot is of a copy whose
# script, once the browser has found the link's target, drops what precedes the target's section
# and scrolls back to the top: the section the link opens, drawn as the page draws it.
ISOLATE_TARGET = """<script>
window.addEventListener("load", function () {
  var id = decodeURIComponent(location.hash.slice(1)), t = id && document.getElementById(id);
  if (!t) { document.body.textContent = ""; return; }  // no target: a blank screenshot, a failure
  while (t.parentNode !== document.body) t = t.parentNode;
  var b = document.body;
  while (b.firstChild && b.firstChild !== t) b.removeChild(b.firstChild);
  window.scrollTo(0, 0);
});
</script>"""


def own_plot(url, report_dir):
    """Whether a resource the page loaded is one of the run's plots: a PNG under report_dir/plots."""
    if url.startswith("data:image/png;base64,"):
        return True
    m = re.fullmatch(r"file://(/.*/plots/[^/]+\.png)", url)
    plots = os.path.realpath(os.path.join(report_dir, "plots"))
    return bool(m) and os.path.dirname(os.path.realpath(m.group(1))) == plots


def check(result, head, rows, report_dir="."):
    """The failures (strings) of the probe's result against the expected summary."""
    bad = [f"page: {p}" for p in result.get("problems", [])]
    bad += [f"the page loaded {u}" for u in result.get("resources", []) if not own_plot(u, report_dir)]
    if not result.get("tables"):
        bad.append("no table on the page")
    if "sorted_heading" not in result:
        bad.append("no table with an unsorted numeric column to sort")
    else:
        values = [key(t) for t in result["ascending"]]
        if values != sorted(values) or sorted(result["ascending"]) != sorted(result["before"]):
            bad.append(f"a click on '{result['sorted_heading']}' did not sort ascending: {result['ascending'][:8]}")
        values = [key(t) for t in result["descending"]]
        if values != sorted(values, reverse=True):
            bad.append(f"a second click did not sort descending: {result['descending'][:8]}")
        if (result.get("aria_ascending"), result.get("aria_descending")) != ("ascending", "descending"):
            bad.append(f"aria-sort {result.get('aria_ascending')}, {result.get('aria_descending')}")
        term = result["filter_term"].lower()
        words = term.split()  # the page's filter: every word of the box somewhere in the row
        for r in result["filter_rows"]:
            if r["hidden"] == all(w in r["text"].lower() for w in words):
                bad.append(f"filter '{term}': row {'hidden' if r['hidden'] else 'shown'} wrongly: {r['text'][:80]}")
                break
        shown = sum(1 for r in result["filter_rows"] if not r["hidden"])
        if not result["filter_count"].startswith(f"{shown} "):
            bad.append(f"filter count '{result['filter_count']}' but {shown} rows shown")
    if result.get("summary_head") != head:
        bad.append(f"summary table head {result.get('summary_head')} != {head}")
    if result.get("summary_rows") != rows:
        got = result.get("summary_rows") or []
        diff = next((i for i, (a, b) in enumerate(zip(got, rows)) if a != b), min(len(got), len(rows)))
        bad.append(f"summary table row {diff} shows {got[diff] if diff < len(got) else None}, "
                   f"the JSON gives {rows[diff] if diff < len(rows) else None}")
    if not result.get("summary_links"):
        bad.append("the summary links to no section")
    bad += [f"summary link {a['href']} has no target" for a in result.get("summary_links", []) if not a["target"]]
    return bad


def make_reports(tool, only, report_dir):
    """A report of a real (small) run in report_dir; returns None, or what failed."""
    os.makedirs(report_dir, exist_ok=True)
    scripts = os.path.join(HERE, "..", "..", "scripts")
    steps = [[tool, "accuracy", "--quick", "--quiet", "--out", os.path.join(report_dir, "accuracy.json")]
             + (["--only", only] if only else []),
             [tool, "list", "vocabulary", "--json"],
             ["/usr/bin/python3", os.path.join(scripts, "report.py"), "--reports", report_dir]]
    for step in steps:
        p = subprocess.run(step, capture_output=True, text=True, timeout=900)
        if p.returncode != 0:
            return f"{' '.join(step)}: exit {p.returncode}: {p.stderr[-2000:]}"
        if step[1:3] == ["list", "vocabulary"]:
            with open(os.path.join(report_dir, "vocabulary.json"), "w", encoding="utf-8") as f:
                f.write(p.stdout)
    return None


def chromium_command(chromium, work, *args):
    # --no-sandbox: the check may run as root (containers, CI), where Chromium's sandbox refuses.
    return [chromium, "--headless=new", "--no-sandbox", "--disable-gpu", "--no-first-run", "--hide-scrollbars",
            f"--user-data-dir={os.path.join(work, 'profile')}", *args]


def probe(chromium, work, page, head, rows, report_dir):
    """(the probe's result or None, the failures) of page loaded in Chromium with the probes added;
    its relative links (the plots' files) resolve in report_dir, as REPORT.html's do."""
    path = os.path.abspath(os.path.join(work, "probe.html"))
    base = f'<base href="file://{html.escape(os.path.abspath(report_dir), quote=True)}/">'
    with open(path, "w", encoding="utf-8") as f:
        f.write(page.replace("<head>", "<head>" + base + PROBE_HEAD, 1)
                .replace("</body>", PROBE_TAIL + "</body>", 1))
    proc = subprocess.run(chromium_command(chromium, work, "--dump-dom", "file://" + path),
                          capture_output=True, text=True, timeout=300)
    m = re.search(r'<pre id="check-report-html">(.*?)</pre>', proc.stdout, re.S)
    if not m:
        return None, [f"the probe wrote no result (exit {proc.returncode}): {proc.stderr[-2000:]}"]
    result = json.loads(html.unescape(m.group(1)))
    return result, check(result, head, rows, report_dir)


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--reports", required=True)
    ap.add_argument("--screenshot", required=True)
    ap.add_argument("--chromium", default="chromium")
    ap.add_argument("--work")
    ap.add_argument("--tool", help="make DIR first: this curvebench's accuracy run and vocabulary, then report.py")
    ap.add_argument("--only", help="with --tool: the cases of the accuracy run (its --only)")
    a = ap.parse_args()
    chromium = shutil.which(a.chromium)
    if not chromium:
        print(f"check_report_html: {a.chromium} not found (Debian's chromium: scripts/test.sh installs it)",
              file=sys.stderr)
        return 2
    if a.tool:
        made = make_reports(a.tool, a.only, a.reports)
        if made:
            print(f"check_report_html: {made}", file=sys.stderr)
            return 1
    page_path = os.path.join(a.reports, "REPORT.html")
    with open(page_path, encoding="utf-8") as f:
        page = f.read()
    head, rows = expected_summary(a.reports)
    with tempfile.TemporaryDirectory() as tmp:
        work = a.work or tmp
        os.makedirs(work, exist_ok=True)
        result, bad = probe(chromium, work, page, head, rows, a.reports)
        # The control: the same page with its script replaced by a console error must fail the
        # console and the sorting checks, or this check could not see them.
        planted = page.replace(report_html.SCRIPT, 'console.error("planted by the control run");', 1)
        _, control = probe(chromium, work, planted, head, rows, a.reports)
        for must in ("page: console.error: planted by the control run", "did not sort ascending"):
            if not any(must in c for c in control):
                bad.append(f"the control run (no page script, a planted console error) did not report '{must}': "
                           f"{control}")
        if f'id="{DEEP_ANCHOR}"' not in page:
            bad.append(f"the page has no heading #{DEEP_ANCHOR}")
        os.makedirs(os.path.dirname(os.path.abspath(a.screenshot)), exist_ok=True)
        stem, ext = os.path.splitext(os.path.abspath(a.screenshot))
        deep_page = os.path.abspath(os.path.join(work, "deep.html"))
        base = f'<base href="file://{html.escape(os.path.abspath(a.reports), quote=True)}/">'
        with open(deep_page, "w", encoding="utf-8") as f:
            f.write(page.replace("<head>", "<head>" + base, 1).replace("</body>", ISOLATE_TARGET + "</body>", 1))
        shots = ((os.path.abspath(a.screenshot), "file://" + os.path.abspath(page_path)),
                 (f"{stem}-deep{ext or '.png'}", "file://" + deep_page + "#" + DEEP_ANCHOR))
        for shot_path, url in shots:
            fragment = url[url.find("#"):] if "#" in url else ""
            if os.path.exists(shot_path):
                os.remove(shot_path)
            command = chromium_command(chromium, work, f"--screenshot={shot_path}", "--window-size=1400,2200", url)
            shot = subprocess.run(command, capture_output=True, text=True, timeout=300)
            if not os.path.exists(shot_path) or os.path.getsize(shot_path) == 0:
                bad.append(f"no screenshot of REPORT.html{fragment} written (exit {shot.returncode}): "
                           f"{shot.stderr[-500:]}")
                continue
            blank = not_blank(shot_path)
            if blank:
                bad.append(f"the screenshot of REPORT.html{fragment}: {blank}")
        if all(os.path.exists(p) for p, _ in shots):
            with open(shots[0][0], "rb") as f, open(shots[1][0], "rb") as g:
                if f.read() == g.read():
                    bad.append(f"REPORT.html#{DEEP_ANCHOR} shows the same picture as the page's top: the link "
                               "did not scroll to its section")
    for b in bad:
        print(f"check_report_html: {b}", file=sys.stderr)
    if bad or result is None:
        return 1
    print(f"check_report_html: {result['tables']} tables; sorted '{result['sorted_heading']}'; summary {len(rows)} "
          f"rows as in the JSON; {len(result['summary_links'])} summary links; screenshots {a.screenshot} "
          f"and its -deep twin (#{DEEP_ANCHOR}), neither blank")
    return 0


if __name__ == "__main__":
    sys.exit(main())
