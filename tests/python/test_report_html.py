"""Unit tests of scripts/report_html.py (REPORT.html from the report's Markdown) and of the anchors and
summary links of scripts/report_summary.py it relies on; the page itself in headless Chromium is
check_report_html.py (ctest report_html_chromium). Run by ctest (report_py)."""
import base64
import html
import os
import re
import shutil
import sys
import tempfile
import unittest
from html.parser import HTMLParser

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "..", "scripts"))
import report_html  # noqa: E402
import report_summary  # noqa: E402
import report_fixture  # noqa: E402

PNG = b"\x89PNG\r\n\x1a\n not decoded by the renderer"  # the bytes are only base64-encoded


class Elements(HTMLParser):
    """Every start tag with its attributes, and the text of each <td>/<th> row."""

    def __init__(self):
        super().__init__(convert_charrefs=True)
        self.tags, self.rows, self._row, self._cell = [], [], None, None

    def handle_starttag(self, tag, attrs):
        self.tags.append((tag, dict(attrs)))
        if tag == "tr":
            self._row = []
        elif tag in ("td", "th") and self._row is not None:
            self._cell = []

    def handle_endtag(self, tag):
        if tag in ("td", "th") and self._cell is not None:
            self._row.append("".join(self._cell).strip())
            self._cell = None
        elif tag == "tr" and self._row is not None:
            self.rows.append(self._row)
            self._row = None

    def handle_data(self, data):
        if self._cell is not None:
            self._cell.append(data)


def parse(page):
    p = Elements()
    p.feed(page)
    return p


class Anchors(unittest.TestCase):
    def test_repeated_headings_get_githubs_suffixes_whatever_their_level(self):
        lines = ["# R", "## Summary", "### Tool models against the real tools", "```", "## not a heading", "```",
                 "## Tool models against the real tools", "## Peers: x (y)"]
        self.assertEqual(report_summary.heading_anchors(lines),
                         ["r", "summary", "tool-models-against-the-real-tools", "tool-models-against-the-real-tools-1",
                          "peers-x-y"])

    def test_contents_link_the_sections_not_the_summarys_subsection_of_the_same_name(self):
        # Before headings() counted every level, the contents linked "## Tool models..." to the
        # summary's "### Tool models..." (the first heading with that anchor on GitHub).
        before = ["## Summary", "### Tool models against the real tools"]
        after = ["## Tool models against the real tools"]
        self.assertIn("- [Tool models against the real tools](#tool-models-against-the-real-tools-1)",
                      report_summary.toc(before, after))

    def test_the_summary_links_the_sections_that_hold_its_figures_and_only_those(self):
        page = ["## Summary", "", "### The method to use for an error target", "", "| a |", "|---|", "| 1 |", "",
                "### Peers: the worst finding of each", "", "- p: none", "", "## Contents", "",
                "## Arc length: error vs cost", "", "## Peers: the libraries users would pick instead", ""]
        out = report_summary.link_details(page)
        details = [line for line in out if line.startswith("Details:")]
        self.assertEqual(details, ["Details: [Arc length: error vs cost](#arc-length-error-vs-cost).",
                                   "Details: [Peers: the libraries users would pick instead]"
                                   "(#peers-the-libraries-users-would-pick-instead)."])
        # Inserted inside the summary, before the next subsection and before the next section.
        self.assertLess(out.index(details[0]), out.index("### Peers: the worst finding of each"))
        self.assertLess(out.index(details[1]), out.index("## Contents"))
        self.assertEqual(report_summary.heading_anchors(out), report_summary.heading_anchors(page))


class Rendering(unittest.TestCase):
    def test_text_is_escaped_and_inline_markdown_rendered(self):
        body, _ = report_html.body_html(["a <script>alert(1)</script> & `x<y>` **b** [l](#t) ![i](x.png)"], {})
        self.assertIn("a &lt;script&gt;alert(1)&lt;/script&gt; &amp; <code>x&lt;y&gt;</code> <strong>b</strong> "
                      '<a href="#t">l</a> <em>[image: i (x.png)]</em>', body)
        self.assertNotIn("<script>", body)

    def test_a_table_keeps_its_cells_and_offers_the_values_of_its_case_column(self):
        md = ["| case | `error` | note |", "|---|---|---|", "| b | 2 | x\\|y |", "| `a` | 1e-3 | - |"]
        body, page = report_html.body_html(md, {})
        p = parse(body)
        self.assertEqual(p.rows, [["case", "error", "note"], ["b", "2", "x|y"], ["a", "1e-3", "-"]])
        options = [a["value"] for t, a in p.tags if t == "option"]
        self.assertEqual(options, ["", "a", "b"])  # the shown text, not the Markdown's `a`
        self.assertEqual(page.tables, 1)

    def test_every_heading_has_the_anchor_its_links_use(self):
        lines = ["## Summary", "", "- [B](#b-1)", "", "## B", "### B", ""]
        body, _ = report_html.body_html(lines, {})
        ids = [a["id"] for t, a in parse(body).tags if t in ("h2", "h3")]
        self.assertEqual(ids, ["summary", "b", "b-1"])

    def test_shown_plots_are_embedded_and_gallery_plots_link_their_files(self):
        md = ["- [case one](plots/one.png)", "- [no plot](plots/missing.png)", "", "![conv](plots/two.png)"]
        body, page = report_html.body_html(md, {"plots/one.png": PNG, "plots/two.png": PNG})
        self.assertEqual(page.figures, 2)
        imgs = [a for t, a in parse(body).tags if t == "img"]
        self.assertEqual(len(imgs), 2)
        # The gallery's plot: the file beside the page, fetched when its <details> is opened.
        self.assertEqual((imgs[0]["src"], imgs[0]["loading"], imgs[0]["alt"]), ("plots/one.png", "lazy", "case one"))
        self.assertIn("<details><summary>case one</summary><figure", body)
        # The image the Markdown shows: its own bytes, so the page shows it without the file.
        self.assertEqual(imgs[1]["src"], "data:image/png;base64," + base64.b64encode(PNG).decode())
        self.assertIn('<a href="plots/missing.png">no plot</a>', body)  # a link, not an embedded file

    def test_lists_nest_and_continue(self):
        body, _ = report_html.body_html(["- a", "  - b", "  more", "- c"], {})
        self.assertEqual(body, "<ul><li>a<ul><li>b more</li></ul></li><li>c</li></ul>")

    def test_the_page_loads_nothing_but_its_own_plots(self):
        page = report_html.render(["# R", "- [x](plots/one.png)", "", "![y](plots/two.png)"],
                                  {"plots/one.png": PNG, "plots/two.png": PNG})
        p = parse(page)
        for tag, attrs in p.tags:
            self.assertNotIn(tag, ("link", "iframe", "object", "embed"))
            if tag == "img":
                self.assertRegex(attrs["src"], r"^(data:image/png;base64,|plots/[^/]+\.png$)")
            else:
                self.assertNotIn("src", attrs, tag)
        self.assertNotRegex(page, r"@import|url\(\s*['\"]?(?:https?:|//)")


class FromTheReport(unittest.TestCase):
    """report.py writes REPORT.html beside REPORT.md from the same lines."""

    def test_report_py_writes_the_page_with_the_summary_of_the_markdown(self):
        d = tempfile.mkdtemp()
        self.addCleanup(shutil.rmtree, d)
        acc = {"context": {"revision": "r1"}, "suite": {"name": "s", "version": 1, "cases": 2},
               "cases": [{"name": c, "group": "bezier", "family": "bezier", "segments": 1} for c in ("c1", "c2")],
               "records": [{"case": c, "quantity": "length", "method": m, "setting": st, "error": e,
                            "evaluations": n, "estimate": 2 * e, "bounded": True}
                           for c in ("c1", "c2")
                           for m, st, e, n in (("gauss", "n=4", 3e-7, 4), ("gauss", "n=12", 2e-11, 12),
                                               ("adaptive_gk", "tol=1e-14", 4e-16, 45))]}
        md = report_fixture.run_report(self, acc, directory=d)
        with open(os.path.join(d, "REPORT.html"), encoding="utf-8") as f:
            page = f.read()
        rows = parse(page).rows
        md_rows = [[report_html.shown_text(c) for c in report_html.split_row(line)]
                   for line in md.splitlines() if line.startswith("| `length`")]
        self.assertTrue(md_rows)
        for r in md_rows:
            self.assertIn(r, rows)
        self.assertIn("gauss n=4 (4 evals)", html.unescape(page))
        self.assertIn('<h2 id="summary">', page)
        self.assertIn("Details: [", md)

    def test_the_page_stays_small_its_galleries_linked_not_embedded(self):
        # Every plot inline as SVG made the quick run's page 10.6 MB; the galleries' plots are now
        # the files beside it (1.26 MB on the quick run of 81 cases, docs/DESIGN.md).
        d = tempfile.mkdtemp()
        self.addCleanup(shutil.rmtree, d)
        acc = {"context": {"revision": "r1"}, "suite": {"name": "s", "version": 1, "cases": 30},
               "cases": [{"name": f"c{i}", "group": "bezier", "family": "bezier", "segments": 1} for i in range(30)],
               "records": [{"case": f"c{i}", "quantity": q, "method": m, "setting": st, "error": e * (1 + i),
                            "evaluations": n, "estimate": 2 * e, "bounded": True}
                           for i in range(30) for q in ("length", "u_of_s")
                           for m, st, e, n in (("gauss", "n=4", 3e-7, 4), ("gauss", "n=12", 2e-11, 12))]}
        report_fixture.run_report(self, acc, directory=d)
        size = os.path.getsize(os.path.join(d, "REPORT.html"))
        with open(os.path.join(d, "REPORT.html"), encoding="utf-8") as f:
            page = f.read()
        plots = os.listdir(os.path.join(d, "plots"))
        self.assertGreaterEqual(len(plots), 60)  # a plot per case and quantity
        linked = re.findall(r'<img src="(plots/[^"]+)" loading="lazy"', page)
        self.assertEqual(len(linked), len([p for p in plots if p.startswith(("length_", "u_of_s_"))]))
        self.assertLess(size, 3_000_000)
        self.assertLess(size, 200_000, "60 plots linked, not embedded: the page is its tables and text")

    def test_chromium_check_compares_the_page_with_the_json(self):
        # The comparison of check_report_html.py, without Chromium: a row the page shows differently
        # from the JSON's summary, an unsorted column and a console error are each named.
        import check_report_html as chk
        result = {"problems": ["console.error: x"], "tables": 1, "sorted_heading": "n", "before": ["2", "1"],
                  "ascending": ["2", "1"], "descending": ["1", "2"], "aria_ascending": "ascending",
                  "aria_descending": "descending", "filter_term": "2",
                  "filter_rows": [{"hidden": False, "text": "2"}, {"hidden": True, "text": "1"}],
                  "filter_count": "1 of 2 rows", "summary_head": ["quantity"], "summary_rows": [["length 1"]],
                  "summary_links": [{"href": "#a", "target": True}]}
        bad = chk.check(result, ["quantity"], [["length 2"]])
        self.assertEqual(len(bad), 4, bad)
        self.assertIn("page: console.error: x", bad)
        self.assertTrue(any("did not sort ascending" in b for b in bad))
        self.assertTrue(any("did not sort descending" in b for b in bad))
        self.assertTrue(any("summary table row 0 shows ['length 1'], the JSON gives ['length 2']" in b for b in bad))
        good = dict(result, problems=[], ascending=["1", "2"], descending=["2", "1"], summary_rows=[["length 2"]])
        self.assertEqual(chk.check(good, ["quantity"], [["length 2"]]), [])


if __name__ == "__main__":
    unittest.main()
