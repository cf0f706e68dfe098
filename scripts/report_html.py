"""REPORT.html: the report's Markdown (the lines report.py builds for REPORT.md) rendered as one
self-contained page.

One source, two renderings: report.py builds the Markdown once; this module turns the same lines
into HTML, so the page can say nothing the Markdown does not. What the page adds:
  - every table sortable (click a column's heading; numbers sort by value, "1.2e-10 (3 evals)" by
    its leading number) and filterable (a text box over all cells, and a list of the values of each
    column named case, family, method, algorithm, peer, tool, group or quantity);
  - the plots: an image the Markdown shows (![alt](plots/NAME.png): the convergence panels, the
    history, the shipped-software sweeps) is embedded as its PNG (a data: URI, so the page shows it
    alone); a list item that is only a link to a plot of the run (the per-case galleries, a few
    hundred plots in a full run) becomes a closed <details> whose image is the file plots/NAME.png
    beside the page, loaded lazily when opened. Every plot inline as SVG made the quick run's page
    10.6 MB, 94 % of it the 237 SVGs; with the galleries linked it is about 1 MB (docs/DESIGN.md);
  - headings carry GitHub's anchors (report_summary.heading_anchors), so the summary's and the
    contents' links work the same on GitHub and in the page.
No network and no server: no external script, style sheet or font, and no image but the run's own
plots/ files; the page's script and style are inline. The grammar rendered is the one report.py,
report_summary.py, report_peers.py, report_channel.py and report_history.py write: headings, pipe
tables, "- " lists (two levels), paragraphs, ``` fences, and inline `code`, **bold**, [text](link)
and ![alt](image).
Pure functions: tests/python/test_report_html.py, and tests/python/check_report_html.py in headless
Chromium (the page loads without a console error, sorting reorders, the summary's numbers are the
JSON's; a screenshot is kept).
"""
import base64
import html
import re

import report_summary

# Columns offered as a list of their values beside the text filter (headings compared lowercased).
FILTER_COLUMNS = ("case", "family", "method", "algorithm", "peer", "tool", "group", "quantity",
                  "kind of curve (group)", "case (family)")
# A column with more distinct values than this keeps only the text filter.
MAX_CHOICES = 300

_INLINE = re.compile(r"`([^`]*)`|!\[([^\]]*)\]\(([^)\s]*)\)|\[([^\]]*)\]\(([^)\s]*)\)|\*\*(.+?)\*\*")
_SEPARATOR = re.compile(r"^\|(\s*:?-{3,}:?\s*\|)+\s*$")


def plot_key(link):
    """'plots/x.png' for a link to a plot of the report ('plots/x.png' or './plots/x.png'), else None."""
    m = re.fullmatch(r"(?:\./)?(plots/[^/]+)\.png", link)
    return m.group(1) + ".png" if m else None


def shown_text(cell):
    """A Markdown cell's text as the page shows it (the value a filter list offers and matches)."""
    text = re.sub(r"!?\[([^\]]*)\]\([^)\s]*\)", r"\1", cell)
    return re.sub(r"\*\*(.+?)\*\*", r"\1", re.sub(r"`([^`]*)`", r"\1", text)).strip()


class _Page:
    def __init__(self, plots):
        self.plots = plots
        self.out = []
        self.figures = 0
        self.tables = 0

    def figure(self, key, caption, embedded=True):
        """The plot `key` ('plots/NAME.png'): embedded as its PNG bytes, or the file beside the page,
        loaded when shown (a closed <details> is not shown until opened)."""
        self.figures += 1
        alt = html.escape(caption, quote=True)
        if embedded:
            data = base64.b64encode(self.plots[key]).decode("ascii")
            img = f'<img src="data:image/png;base64,{data}" alt="{alt}">'
        else:
            img = f'<img src="{html.escape(key, quote=True)}" loading="lazy" alt="{alt}">'
        return (f'<figure class="plot">{img}<figcaption>{html.escape(caption)} '
                f'(<a href="{html.escape(key, quote=True)}">{html.escape(key)}</a>)</figcaption></figure>')

    def inline(self, text):
        """Inline Markdown to HTML; everything else escaped."""
        parts, pos = [], 0
        for m in _INLINE.finditer(text):
            parts.append(html.escape(text[pos:m.start()]))
            pos = m.end()
            code, alt, image, label, link, bold = m.groups()
            if code is not None:
                parts.append(f"<code>{html.escape(code)}</code>")
            elif image is not None:
                key = plot_key(image)
                if key in self.plots:
                    parts.append(self.figure(key, alt))
                else:  # not a figure of this run: named, never loaded (no network, no file)
                    parts.append(f"<em>[image: {html.escape(alt)} ({html.escape(image)})]</em>")
            elif link is not None:
                parts.append(f'<a href="{html.escape(link, quote=True)}">{self.inline(label)}</a>')
            else:
                parts.append(f"<strong>{self.inline(bold)}</strong>")
        parts.append(html.escape(text[pos:]))
        return "".join(parts)

    def table(self, rows):
        self.tables += 1
        head, body = rows[0], rows[1:]
        filters = []
        for i, h in enumerate(head):
            values = sorted({shown_text(r[i]) for r in body if i < len(r)})
            if h.strip("`").lower() in FILTER_COLUMNS and 1 < len(values) <= MAX_CHOICES:
                options = "".join(f'<option value="{html.escape(v, quote=True)}">{html.escape(v)}</option>'
                                  for v in values)
                filters.append(f'<label>{html.escape(h)} <select data-column="{i}"><option value="">all</option>'
                               f"{options}</select></label>")
        out = [f'<div class="table" id="table-{self.tables}"><div class="filters">'
               f'<input type="search" placeholder="filter rows" aria-label="filter rows">{"".join(filters)}'
               f'<span class="count"></span></div><table class="data"><thead><tr>']
        out += [f'<th title="sort">{self.inline(h)}</th>' for h in head]
        out.append("</tr></thead><tbody>")
        for r in body:
            out.append("<tr>" + "".join(f"<td>{self.inline(c)}</td>" for c in r) + "</tr>")
        out.append("</tbody></table></div>")
        return "".join(out)


def split_row(line):
    """The cells of a pipe-table row ('| a | b |'); '\\|' is a literal bar."""
    inner = line.strip()
    inner = inner[1:] if inner.startswith("|") else inner
    inner = inner[:-1] if inner.endswith("|") and not inner.endswith("\\|") else inner
    return [c.strip().replace("\\|", "|") for c in re.split(r"(?<!\\)\|", inner)]


def body_html(lines, plots):
    """The HTML of the Markdown lines (headings with their anchors, tables, lists, paragraphs);
    plots: {'plots/NAME.png': its PNG bytes} of the run's figures."""
    page = _Page(plots)
    lines = report_summary.flat(lines)
    found = {index: (level, text, anchor) for index, level, text, anchor in report_summary.headings(lines)}
    out, para, i = page.out, [], 0

    def flush():
        if para:
            out.append(f"<p>{page.inline(' '.join(para))}</p>")
            para.clear()
    while i < len(lines):
        line = lines[i]
        if line.startswith("```"):
            flush()
            j = i + 1
            while j < len(lines) and not lines[j].startswith("```"):
                j += 1
            out.append(f"<pre><code>{html.escape(chr(10).join(lines[i + 1:j]))}</code></pre>")
            i = j + 1
            continue
        if i in found:  # headings as report_summary reads them (their anchors are the links')
            flush()
            level, text, anchor = found[i]
            out.append(f'<h{level} id="{html.escape(anchor, quote=True)}">{page.inline(text)}'
                       f'<a class="self" href="#{html.escape(anchor, quote=True)}">#</a></h{level}>')
            i += 1
            continue
        if line.startswith("|") and i + 1 < len(lines) and _SEPARATOR.match(lines[i + 1]):
            flush()
            rows = [split_row(line)]
            i += 2
            while i < len(lines) and lines[i].startswith("|"):
                rows.append(split_row(lines[i]))
                i += 1
            out.append(page.table(rows))
            continue
        if re.match(r"^ {0,3}- ", line):
            flush()
            i = list_html(lines, i, page)
            continue
        if not line.strip():
            flush()
        else:
            para.append(line.strip())
        i += 1
    flush()
    return "\n".join(out), page


def list_html(lines, i, page):
    """A "- " list from lines[i] on (items indented by 2 or more nest one level); returns the next
    line's index. An item that is only a link to a plot becomes the plot in a closed <details>."""
    out = page.out
    items = []  # (nested, text)
    while i < len(lines):
        m = re.match(r"^( *)- (.*)$", lines[i])
        if m:
            items.append((len(m.group(1)) >= 2, m.group(2)))
        elif lines[i].strip() and lines[i].startswith("  ") and items:
            items[-1] = (items[-1][0], items[-1][1] + " " + lines[i].strip())  # a continuation line
        else:
            break
        i += 1
    html_items, nested = [], []

    def item(text):
        only = re.fullmatch(r"\[([^\]]*)\]\(([^)\s]*)\)", text.strip())
        key = plot_key(only.group(2)) if only else None
        if key in page.plots:
            return (f'<li><details><summary>{html.escape(only.group(1))}</summary>'
                    f"{page.figure(key, only.group(1), embedded=False)}</details></li>")
        return f"<li>{page.inline(text)}</li>"
    for is_nested, text in items:
        if is_nested and html_items:
            nested.append(item(text))
            continue
        if nested:
            html_items[-1] = html_items[-1][:-len("</li>")] + "<ul>" + "".join(nested) + "</ul></li>"
            nested = []
        html_items.append(item(text))
    if nested:
        html_items[-1] = html_items[-1][:-len("</li>")] + "<ul>" + "".join(nested) + "</ul></li>"
    out.append("<ul>" + "".join(html_items) + "</ul>")
    return i


STYLE = """
body{font:14px/1.45 system-ui,-apple-system,"Segoe UI",sans-serif;margin:0 auto;max-width:1400px;
padding:0 1.5em 4em;color:#1d1d1f}
h1,h2,h3,h4{line-height:1.2;margin:1.4em 0 .5em}h2{border-bottom:1px solid #ddd;padding-bottom:.2em}
a.self{visibility:hidden;margin-left:.4em;color:#999;text-decoration:none}
h1:hover a.self,h2:hover a.self,h3:hover a.self,h4:hover a.self{visibility:visible}
code{font:12.5px ui-monospace,monospace;background:#f3f3f5;padding:0 .25em;border-radius:3px}
pre{background:#f3f3f5;padding:.8em;overflow:auto}
div.table{margin:.6em 0 1.2em;overflow-x:auto}
div.filters{display:flex;flex-wrap:wrap;gap:.5em;align-items:center;margin:.3em 0;font-size:12.5px}
div.filters input{padding:.15em .4em;min-width:14em}div.filters select{max-width:22em}span.count{color:#666}
table.data{border-collapse:collapse;font-size:12.5px}
table.data th,table.data td{border:1px solid #d8d8dc;padding:.2em .5em;vertical-align:top;text-align:left}
table.data th{background:#f0f0f4;cursor:pointer;user-select:none;position:sticky;top:0}
table.data th[aria-sort=ascending]::after{content:" \\25b2"}
table.data th[aria-sort=descending]::after{content:" \\25bc"}
table.data tbody tr:nth-child(even){background:#fafafc}
figure.plot{margin:.5em 0}figure.plot img{max-width:100%;height:auto}figcaption{font-size:12px;color:#555}
details{margin:.2em 0}details summary{cursor:pointer}
"""

# Sorting and filtering; no library. A cell's sort key is its leading number when it has one
# (1.2e-10, -3, 45%, "4.1 ns"), else its text; numbers sort before text, and "-" (no value) last.
SCRIPT = r"""
(function () {
  "use strict";
  var NUMBER = /^\s*([-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?)/;
  function key(text) {
    var t = text.trim();
    if (t === "-" || t === "") return [2, 0, ""];
    var m = NUMBER.exec(t);
    if (m) return [0, parseFloat(m[1]), t];
    return [1, 0, t.toLowerCase()];
  }
  function compare(a, b) {
    if (a[0] !== b[0]) return a[0] - b[0];
    if (a[0] === 0 && a[1] !== b[1]) return a[1] < b[1] ? -1 : 1;
    return a[2] < b[2] ? -1 : a[2] > b[2] ? 1 : 0;
  }
  function setUp(box) {
    var table = box.querySelector("table.data");
    var body = table.tBodies[0];
    var heads = table.tHead.rows[0].cells;
    var input = box.querySelector("div.filters input");
    var selects = box.querySelectorAll("div.filters select");
    var count = box.querySelector("span.count");
    var total = body.rows.length;
    function filter() {
      var terms = input.value.toLowerCase().split(/\s+/).filter(function (s) { return s.length > 0; });
      var shown = 0;
      Array.prototype.forEach.call(body.rows, function (row) {
        var text = row.textContent.toLowerCase();
        var ok = terms.every(function (term) { return text.indexOf(term) >= 0; });
        Array.prototype.forEach.call(selects, function (s) {
          if (ok && s.value !== "") ok = row.cells[+s.dataset.column].textContent.trim() === s.value;
        });
        row.hidden = !ok;
        if (ok) shown += 1;
      });
      count.textContent = (shown === total ? "" : shown + " of ") + total + (total === 1 ? " row" : " rows");
    }
    Array.prototype.forEach.call(heads, function (th, column) {
      th.addEventListener("click", function () {
        var descending = th.getAttribute("aria-sort") === "ascending";
        Array.prototype.forEach.call(heads, function (h) { h.removeAttribute("aria-sort"); });
        th.setAttribute("aria-sort", descending ? "descending" : "ascending");
        var rows = Array.prototype.map.call(body.rows, function (row, index) {
          return { row: row, key: key(row.cells[column] ? row.cells[column].textContent : ""), index: index };
        });
        rows.sort(function (a, b) {
          var c = compare(a.key, b.key);
          if (descending && a.key[0] === b.key[0]) c = -c;  // "-" stays last either way
          return c !== 0 ? c : a.index - b.index;
        });
        rows.forEach(function (r) { body.appendChild(r.row); });
      });
    });
    input.addEventListener("input", filter);
    Array.prototype.forEach.call(selects, function (s) { s.addEventListener("change", filter); });
    filter();
  }
  Array.prototype.forEach.call(document.querySelectorAll("div.table"), setUp);
})();
"""


def render(lines, plots, title="curvebench report"):
    """The whole page: lines the report's Markdown lines, plots {'plots/NAME.png': PNG bytes} of the
    figures the run wrote beside it (a link to a plot not among them stays a link)."""
    body, _ = body_html(lines, plots)
    return ("<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">"
            "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">"
            f"<title>{html.escape(title)}</title><style>{STYLE}</style></head>\n<body>\n{body}\n"
            f"<script>{SCRIPT}</script>\n</body></html>\n")
