"""Unit tests of scripts/report_summary.py (REPORT.md's summary and contents) on small
synthetic records whose answers are known by hand: the cheapest method reaching each target on every
case of a group, by time where the benchmarks join and by evaluations otherwise; "none reaches it";
the best peer of a group; the peers' worst findings; the tool models' fidelity; the contents' links.
Run by ctest (report_py) with the other tests of tests/python:
  /usr/bin/python3 -m unittest discover -s tests/python -p 'test_report*.py'"""
import importlib.util
import os
import re
import sys
import unittest

HERE = os.path.dirname(os.path.abspath(__file__))
SCRIPTS = os.path.join(HERE, "..", "..", "scripts")
sys.path.insert(0, SCRIPTS)
import report_summary as rs  # noqa: E402
import report_fixture  # noqa: E402


def rec(case, method, setting, error, evaluations=10.0, quantity="length", group="g", **extra):
    """A record whose estimate bounds its error (converged); pass status="not_guaranteed",
    estimate=None, bounded=None for one without a bound."""
    r = {"case": case, "group": group, "quantity": quantity, "method": method, "setting": setting, "error": error,
         "estimate": None if error is None else 2 * error, "bounded": True, "evaluations": evaluations,
         "status": "converged"}
    r.update(extra)
    return r


def peer(case, method, setting, error, ns, quantity="length", group="g", **extra):
    r = rec(case, method, setting, error, 15.0, quantity, group, peer=True, library="Lib 1.0", ns_per_op=ns,
            peer_status="success")
    r.update(extra)
    return r


# One group "g" of two cases. Hand-known answers (errors relative to L):
#   gauss n=2        1e-7, 5e-7     reaches 1e-6             10 evals, 500 ns
#   gauss n=8        1e-11, 2e-11   reaches 1e-6 and 1e-10   40 evals, 300 ns
#   adaptive_gk ...  1e-15, 3e-15   reaches all three        100 evals, 900 ns
#   gauss n=4        1e-8, 2e-6     misses 1e-6 on c2        5 evals, 1 ns
#   richardson ...   1e-16 on c1 only (no record on c2)      1 eval, 1 ns
CANDIDATES = [("gauss", "n=2", (1e-7, 5e-7), 10.0, 500.0), ("gauss", "n=8", (1e-11, 2e-11), 40.0, 300.0),
              ("adaptive_gk", "tol=1e-14", (1e-15, 3e-15), 100.0, 900.0), ("gauss", "n=4", (1e-8, 2e-6), 5.0, 1.0)]


def length_records():
    out = [rec(c, m, s, e, ev) for m, s, errors, ev, _ in CANDIDATES for c, e in zip(("c1", "c2"), errors)]
    return out + [rec("c1", "richardson", "steps=8", 1e-16, 1.0)]


def length_times():
    times = {(c, m, s): ns for m, s, _, _, ns in CANDIDATES for c in ("c1", "c2")}
    times[("c1", "richardson", "steps=8")] = 1.0
    return times


def cells(rows, quantity="length", group="g"):
    row = next(r for r in rows if r["quantity"] == quantity and r["group"] == group)
    return row["cells"]


def chosen(cell, who="ours"):
    p = cell[who]
    return None if p is None else (p["method"], p["setting"], p["unit"], p["cost"])


class Recommendation(unittest.TestCase):
    def test_cheapest_by_evaluations_without_times(self):
        cs = cells(rs.recommendation_rows(length_records(), []))
        self.assertEqual([chosen(c) for c in cs], [("gauss", "n=2", "evals", 10.0), ("gauss", "n=8", "evals", 40.0),
                                                   ("adaptive_gk", "tol=1e-14", "evals", 100.0)])
        self.assertEqual([c["ours"]["max_error"] for c in cs], [5e-7, 2e-11, 3e-15])
        self.assertEqual(rs.cell_text(cs[0]), "gauss n=2 (10 evals)")  # no peer ran: no "peer:"

    def test_cheapest_by_time_where_every_candidate_is_timed(self):
        cs = cells(rs.recommendation_rows(length_records(), [], length_times()))
        # gauss n=8 (300 ns) is faster than gauss n=2 (500 ns) and reaches 1e-6 too
        self.assertEqual([chosen(c) for c in cs], [("gauss", "n=8", "ns", 300.0), ("gauss", "n=8", "ns", 300.0),
                                                   ("adaptive_gk", "tol=1e-14", "ns", 900.0)])
        self.assertEqual(rs.cell_text(cs[0]), "gauss n=8 (300 ns)")

    def test_mean_time_over_the_cases(self):
        times = length_times()
        times[("c2", "gauss", "n=8")] = 900.0  # mean 600 ns: now gauss n=2 (500 ns) is the cheapest at 1e-6
        cs = cells(rs.recommendation_rows(length_records(), [], times))
        self.assertEqual(chosen(cs[0]), ("gauss", "n=2", "ns", 500.0))
        self.assertEqual(chosen(cs[1]), ("gauss", "n=8", "ns", 600.0))

    def test_evaluations_when_a_candidate_has_no_time(self):
        times = length_times()
        del times[("c2", "adaptive_gk", "tol=1e-14")]  # reaches every target, untimed on c2
        cs = cells(rs.recommendation_rows(length_records(), [], times))
        self.assertEqual([chosen(c) for c in cs], [("gauss", "n=2", "evals", 10.0), ("gauss", "n=8", "evals", 40.0),
                                                   ("adaptive_gk", "tol=1e-14", "evals", 100.0)])

    def test_a_choice_without_an_error_bound_says_so(self):
        # gauss n=2 reaches 1e-6 by the suite's measured error, with no estimate on c2: the user's own
        # curve would get no bound from it. eval records carry no estimate by nature: not said there.
        records = length_records()
        records[1].update(status="not_guaranteed", estimate=None, bounded=None)
        self.assertEqual(rs.cell_text(cells(rs.recommendation_rows(records, []))[0]),
                         "gauss n=2 (10 evals, no error bound)")
        evals = [rec(c, "default", "", 1.0, quantity="eval", status="not_guaranteed") for c in ("c1", "c2")]
        self.assertEqual(rs.cell_text(cells(rs.recommendation_rows(evals, []), "eval")[0]), "default (max 2.22e-16)")

    def test_none_reaches_it(self):
        records = [rec(c, "gauss", "n=2", 1e-7) for c in ("c1", "c2")] + [rec("c1", "gauss", "n=8", 1e-12, 40.0),
                                                                          rec("c2", "gauss", "n=8", 2e-10, 40.0)]
        cs = cells(rs.recommendation_rows(records, []))
        self.assertEqual(chosen(cs[0]), ("gauss", "n=2", "evals", 10.0))
        self.assertIsNone(cs[1]["ours"])  # gauss n=8 misses 1e-10 on c2
        self.assertIsNone(cs[2]["ours"])
        self.assertEqual(rs.cell_text(cs[2]), "none reaches it")

    def test_equal_costs_go_to_the_smaller_error(self):
        records = [rec(c, "gauss", "n=2", 1e-7) for c in ("c1", "c2")] + [rec(c, "gauss", "n=8", 1e-9)
                                                                          for c in ("c1", "c2")]
        self.assertEqual(chosen(cells(rs.recommendation_rows(records, []))[0]), ("gauss", "n=8", "evals", 10.0))

    def test_a_method_without_a_record_on_every_case_does_not_reach(self):
        # without adaptive_gk only richardson steps=8 reaches 1e-14, on c1: it has no record on c2
        records = [r for r in length_records() if r["method"] != "adaptive_gk"]
        self.assertIsNone(cells(rs.recommendation_rows(records, [], length_times()))[2]["ours"])

    def test_a_record_without_a_numeric_error_does_not_reach(self):
        records = [rec("c1", "gauss", "n=2", 1e-7), rec("c2", "gauss", "n=2", None)]
        self.assertIsNone(cells(rs.recommendation_rows(records, []))[0]["ours"])

    def test_groups_apart_most_cases_first(self):
        records = length_records() + [rec(c, "gauss", "n=2", 1e-3, group="h") for c in ("d1", "d2", "d3")]
        rows = rs.recommendation_rows(records, [])
        self.assertEqual([(r["group"], r["cases"]) for r in rows], [("h", 3), ("g", 2)])
        self.assertEqual([c["ours"] for c in rows[0]["cells"]], [None, None, None])
        self.assertEqual(chosen(rows[1]["cells"][0]), ("gauss", "n=2", "evals", 10.0))

    def test_a_group_with_a_peer_gets_the_peer(self):
        peers = [peer("c1", "peer_p", "tol=1e-06", 1e-7, 1000.0), peer("c2", "peer_p", "tol=1e-06", 2e-7, 3000.0),
                 # ran on c1 only: reaches 1e-10 there, faster, but on fewer cases
                 peer("c1", "peer_q", "tol=1e-10", 1e-11, 10.0),
                 # reaches 1e-6 on both cases but slower than peer_p
                 peer("c1", "peer_r", "tol=1e-06", 1e-9, 5000.0), peer("c2", "peer_r", "tol=1e-06", 1e-9, 5000.0),
                 # another group: never beside g
                 peer("x1", "peer_s", "tol=1e-06", 1e-16, 1.0, group="h")]
        cs = cells(rs.recommendation_rows(length_records(), peers))
        self.assertEqual(chosen(cs[0], "peer"), ("peer_p", "tol=1e-06", "ns", 2000.0))
        self.assertEqual(chosen(cs[1], "peer"), ("peer_q", "tol=1e-10", "ns", 10.0))
        self.assertEqual((cs[1]["peer"]["covered"], cs[1]["peer"]["of"]), (1, 2))
        self.assertIsNone(cs[2]["peer"])
        self.assertEqual(rs.cell_text(cs[0]), "gauss n=2 (10 evals); peer: peer_p tol=1e-06 (2e+03 ns)")
        self.assertEqual(rs.cell_text(cs[1]), "gauss n=8 (40 evals); peer: peer_q tol=1e-10 (10 ns, 1 of 2 cases)")
        self.assertEqual(rs.cell_text(cs[2]), "adaptive_gk tol=1e-14 (100 evals); peer: none reaches it")

    def test_eval_errors_scaled_by_eps_and_the_most_accurate_named(self):
        # eps(double) x size: 30 eps is 6.66e-15 (reaches 1e-14), 50 eps 1.11e-14 (misses it)
        records = [rec(c, "default", "", 30.0, 65.0, "eval") for c in ("c1", "c2")]
        records += [rec(c, "power", "", e, 65.0, "eval") for c, e in (("c1", 0.5), ("c2", 50.0))]
        peers = [peer("c1", "peer_e", "", 0.9, 20.0, "eval"),
                 peer("c1", "peer_d", "derivative=1", 0.1, 1.0, "eval")]  # a derivative: left out
        cs = cells(rs.recommendation_rows(records, peers), "eval")
        # 1e-6: both reach it, no cost: the smaller max error (power's 50 eps > default's 30 eps)
        self.assertEqual(chosen(cs[0]), ("default", "", None, None))
        self.assertAlmostEqual(cs[0]["ours"]["max_error"], 30 * 2.0 ** -52)
        self.assertEqual(chosen(cs[2]), ("default", "", None, None))
        self.assertEqual(rs.cell_text(cs[2]), "default (max 6.66e-15); peer: peer_e (20 ns, 1 of 2 cases)")

    def test_channel_values_in_ulps_of_their_precision(self):
        # 4 ulps in float: 4.77e-7 of the range (reaches 1e-6 only); 2 ulps in double: 4.4e-16
        records = []
        for c in ("k1", "k2"):
            records += [rec(c, "solver", "bits=32", 4.0, 600.0, "channel_value", "channel"),
                        rec(c, "solver", "bits=64", 2.0, 600.0, "channel_value", "channel"),
                        rec(c, "solver", "bits=32", 1.0, 3.0, "channel_time", "channel"),
                        rec(c, "solver", "bits=64", 1.0, 2.0, "channel_time", "channel")]
        cs = cells(rs.recommendation_rows(records, []), "channel_value", "channel")
        # no bench_channel time: the time solver's evaluations per value (channel_time), not the 600 samples
        self.assertEqual([chosen(c) for c in cs], [("solver", "bits=64", "evals", 2.0)] * 3)
        times = {("solver", "64", 32, "single"): 5.0, ("solver", "64", 64, "single"): 8.0}
        cs = cells(rs.recommendation_rows(records, [], channel_times=times), "channel_value", "channel")
        self.assertEqual([chosen(c) for c in cs], [("solver", "bits=32", "ns", 5.0), ("solver", "bits=64", "ns", 8.0),
                                                   ("solver", "bits=64", "ns", 8.0)])
        self.assertAlmostEqual(cs[0]["ours"]["max_error"], 4 * 2.0 ** -23)

    def test_only_the_quantities_present_and_summarized(self):
        records = length_records() + [rec("k1", "solver", "bits=64", 3.0, 0.0, "channel_monotone", "channel")]
        self.assertEqual({r["quantity"] for r in rs.recommendation_rows(records, [])}, {"length"})

    def test_group_from_the_cases_when_a_record_has_none(self):
        records = [dict(r, group=None) for r in length_records()]
        rows = rs.recommendation_rows(records, [], case_groups={"c1": "g", "c2": "g"})
        self.assertEqual(chosen(cells(rows)[0]), ("gauss", "n=2", "evals", 10.0))

    def test_rows_per_size_class_of_the_segment_counts(self):
        # c1 has 1 segment, c2 1000: each size gets its own row, its own cheapest choice
        records = length_records()
        rows = rs.recommendation_rows(records, [], case_segments={"c1": 1, "c2": 1000})
        self.assertEqual([(r["group"], r["size"], r["cases"]) for r in rows],
                         [("g", "1 segment", 1), ("g", "100+ segments", 1)])
        # c1 alone is its size's group: richardson steps=8 (1 eval, record on c1 only) reaches 1e-14 there;
        # on c2 gauss n=4 misses 1e-6 (2e-6) and richardson has no record: gauss n=2
        self.assertEqual(chosen(rows[0]["cells"][2]), ("richardson", "steps=8", "evals", 1.0))
        self.assertEqual(chosen(rows[1]["cells"][0]), ("gauss", "n=2", "evals", 10.0))
        self.assertIn("| `length` | g | 100+ segments | 1 |", rs.recommendation_table(rows))
        self.assertEqual([rs.size_class(n) for n in (1, 2, 99, 100, 10000, None)],
                         ["1 segment", "2-99 segments", "2-99 segments", "100+ segments", "100+ segments", None])

    def test_a_tolerance_looser_than_the_target_says_why_it_reaches_it(self):
        records = [rec(c, "adaptive_gk", "tol=1e-06", 1e-15, 50.0) for c in ("c1", "c2")]
        cs = cells(rs.recommendation_rows(records, []))
        self.assertEqual(rs.cell_text(cs[0]), "adaptive_gk tol=1e-06 (50 evals)")  # tol = target: nothing said
        self.assertEqual(rs.cell_text(cs[2]), "adaptive_gk tol=1e-06 (50 evals, reaches it at its loosest setting)")
        # a looser setting exists in the run: its measured max error is said instead
        records += [rec(c, "adaptive_gk", "tol=1e-04", 1e-5, 20.0) for c in ("c1", "c2")]
        cs = cells(rs.recommendation_rows(records, []))
        self.assertEqual(rs.cell_text(cs[2]),
                         "adaptive_gk tol=1e-06 (50 evals, tol looser than the target, measured max error 1.00e-15)")

    def test_target_text(self):
        self.assertEqual([rs.target_text(t) for t in (1e-6, 1e-10, 1e-14)], ["1e-6", "1e-10", "1e-14"])


def under(case, method, setting, error, estimate):
    return peer(case, method, setting, error, 1.0, estimate=estimate, bounded=False, status="rounding_limited",
                peer_status="roundoff error")


class PeerLines(unittest.TestCase):
    def test_worst_finding_per_peer_and_the_clean_ones(self):
        records = [under("c", "peer_x", "tol=1e-6", 2e-9, 1e-9), under("c", "peer_x", "tol=1e-10", 1e-7, 1e-9),
                   under("d", "peer_x", "tol=1e-6", 5e-9, 1e-9),
                   peer("c", "peer_y", "tol=1e-6", 1e-9, 1.0, estimate=1e-8, bounded=True),
                   # an estimate of 0 under an error below eps(double): counted, but not the worst
                   under("e", "peer_z", "tol=1e-14", 1e-17, 0.0), under("f", "peer_z", "tol=1e-6", 3e-6, 1e-6)]
        lines = rs.peer_lines(records)
        self.assertEqual(lines[0], "- peer_x (Lib 1.0): 2 findings on 2 cases; the worst on c (tol=1e-10): its error "
                                   "estimate 1.00e-09 does not bound its true error 1.00e-07 (under by 100x; status "
                                   "\"roundoff error\").")
        self.assertEqual(lines[1], "- peer_y (Lib 1.0): no finding in this run.")
        self.assertTrue(lines[2].startswith("- peer_z (Lib 1.0): 2 findings on 2 cases; the worst on f (tol=1e-6): "),
                        lines[2])
        self.assertEqual(len(lines), 3)


class Fidelity(unittest.TestCase):
    def recording(self, tool, name, channels, agree, refused=0, unverified=0, max_error=1e-16):
        return {"tool": tool, "file": f"/x/tests/data/recorded/{name}", "channels": channels, "agree": agree,
                "refused": refused, "unverified": unverified, "max_error": max_error}

    def test_per_tool_over_its_recordings(self):
        fidelity = {"agree_ulps": 64, "recordings": [
            self.recording("blender", "a.json", 10, 10, max_error=2e-7),
            self.recording("usd", "u.json", 20, 15, refused=1, unverified=2, max_error=0.5),
            self.recording("blender", "b.json", 5, 4, max_error=3e-6)]}
        self.assertEqual(rs.fidelity_lines(fidelity, ["exact", "css", "blender", "usd"]),
                         ["- blender: 14 of 15 channels agree, largest error 3.00e-06 x scale (a.json, b.json)",
                          "- usd: 15 of 17 channels agree (1 refused, 2 unverified), largest error 0.5 x scale "
                          "(u.json)",
                          "- no recording of the real tool in this run: css"])

    def test_absent(self):
        self.assertEqual(rs.fidelity_lines(None, ["css"]),
                         ["No recordings of the real tools were measured in this run (no fidelity.json)."])


class Contents(unittest.TestCase):
    def test_github_anchors(self):
        self.assertEqual(rs.anchor("s(u): error vs cost"), "su-error-vs-cost")
        self.assertEqual(rs.anchor("Curve properties (measured) beside seed 001's table"),
                         "curve-properties-measured-beside-seed-001s-table")
        self.assertEqual(rs.anchor("Peers: the libraries users would pick instead"),
                         "peers-the-libraries-users-would-pick-instead")
        self.assertEqual(rs.anchor("Evaluation-algorithm accuracy"), "evaluation-algorithm-accuracy")
        self.assertEqual(rs.anchor("snake_case `code` x"), "snake_case-code-x")

    def test_links_to_every_section_repeats_numbered(self):
        before = ["## Summary", "### Sub", "text ## not a heading"]
        after = ["## Machine and build", "```", "## in a fence", "```", "## Contents", "## Notes", "## Notes"]
        self.assertEqual(rs.toc(before, after),
                         ["## Contents", "", "- [Summary](#summary)", "- [Machine and build](#machine-and-build)",
                          "- [Contents](#contents-1)", "- [Notes](#notes)", "- [Notes](#notes-1)", ""])


class ByQueryCount(unittest.TestCase):
    """The cheapest u(s) method for N queries, build + N x query evaluations, known by hand."""

    def rows(self, table_build):
        # newton: 100 a query, 1e3 to build; polished table: 10 a query, 2e4; sized table: 0, table_build
        out = []
        for case in ("r1", "r2"):
            for m, st, q, b in (("newton", "tol=1e-12", 100.0, 1e3), ("hermite_table_polished", "M=512", 10.0, 2e4),
                                ("hermite_table_sized", "tol=1e-12", 0.0, table_build)):
                out.append(rec(case, m, st, 1e-13, q + b / 1000, quantity="u_of_s", query_evaluations=q,
                               build_evaluations=b))
        return rs.recommendation_rows(out, [], targets=(1e-10,))

    def test_each_method_is_cheapest_from_its_break_even_count_on(self):
        (cell,) = cells(self.rows(1e6), "u_of_s")
        ranges = [(round(r["from"], 6), r["choice"]["method"]) for r in cell["by_queries"]]
        # newton until (2e4 - 1e3) / (100 - 10) = 211.1 queries, the polished table until
        # (1e6 - 2e4) / (10 - 0) = 98000, then the sized table
        self.assertEqual(ranges, [(1.0, "newton"), (round(19000 / 90, 6), "hermite_table_polished"),
                                  (98000.0, "hermite_table_sized")])
        self.assertIn("newton tol=1e-12 (100 evals a query, 1e+03 to build) up to 212 queries, then "
                      "hermite_table_polished M=512 (10 evals a query, 2.00e+04 to build) up to 98000 queries, then "
                      "hermite_table_sized tol=1e-12 (0 evals a query, 1.00e+06 to build)", rs.cell_text(cell))
        # at the records' 1000 queries the polished table is the cheapest: the pick agrees with the ranges
        self.assertEqual(cell["ours"]["method"], "hermite_table_polished")

    def test_a_cheap_enough_table_is_the_answer_whatever_the_count(self):
        # a sized table built for less than newton's prefix and free per query dominates: no ranges
        (cell,) = cells(self.rows(500.0), "u_of_s")
        self.assertIsNone(cell["by_queries"])
        self.assertTrue(cell["split"])
        self.assertEqual(cell["ours"]["method"], "hermite_table_sized")


class Answers(unittest.TestCase):
    def test_the_worst_engine_per_quantity_and_none_measured(self):
        shipped = [{"peer": "peer_chromium", "case": "a", "setting": "", "length_error": 1e-3, "point_error": 2e-5},
                   {"peer": "peer_firefox", "case": "b", "setting": "", "length_error": 4e-2, "point_error": 1e-6},
                   {"peer": "peer_skia", "case": "a", "setting": "tolerance=1e-9", "length_error": 9.0}]
        text = rs.engine_answer(shipped, [], [], ["shipped_browser"])
        # Skia's 9 is at a setting, not its defaults: the defaults' worst are named
        self.assertIn("length: worst firefox, 0.04 of L on b", text)
        self.assertIn("point at length: worst chromium, 2.00e-05 of L on a", text)
        self.assertNotIn("skia", text)
        self.assertEqual(rs.engine_answer([], [], [], []),
                         "none were measured in this run (no peer records and no reports/peers_*.json: "
                         "scripts/peers.sh). No browser or shipped engine was measured (no "
                         "reports/peers_shipped_*.json).")

    def test_fidelity_names_the_verified_the_disagreeing_and_the_unrecorded(self):
        fid = {"recordings": [{"tool": "blender", "channels": 10, "refused": 0, "unverified": 0, "agree": 10,
                               "max_error": 0.1, "file": "b.json"},
                              {"tool": "maya", "channels": 8, "refused": 1, "unverified": 1, "agree": 4,
                               "max_error": 30.0, "file": "m.json"}]}
        self.assertEqual(rs.fidelity_answer(fid, ["exact", "blender", "maya", "usd"]),
                         "verified against every recording: blender (10 of 10 channels); not verified: maya (2 of 6 "
                         "channels disagree, largest error 30 x scale); no recording of the real tool: usd.")
        self.assertIn("none measured", rs.fidelity_answer(None, ["blender"]))

    def test_section_links_resolve_to_the_section_not_the_summarys_subsection(self):
        page = ["## Summary", "- " + rs.section_link("fidelity", "fidelity") + " " + rs.section_link("x", "shipped"),
                "### Tool models against the real tools", "## Tool models against the real tools"]
        self.assertEqual(rs.resolve_section_links(page)[1],
                         "- [fidelity](#tool-models-against-the-real-tools-1) x")  # no shipped section: text


@unittest.skipUnless(importlib.util.find_spec("matplotlib"), "report.py plots with matplotlib")
class ReportScript(unittest.TestCase):
    """report.py puts the summary and the contents right after the title and the "generated" line."""

    def test_summary_then_contents_then_sections(self):
        # both cases of 2-99 segments: one row, its size said; the per-case table gives each count
        acc = {"context": {}, "records": length_records(), "orders": [],
               "cases": [{"name": "c1", "group": "g", "family": "f", "segments": 2},
                         {"name": "c2", "group": "g", "family": "f", "segments": 40}],
               "peer_records": [peer("c1", "peer_p", "tol=1e-06", 1e-7, 1000.0),
                                peer("c2", "peer_p", "tol=1e-06", 2e-7, 3000.0)]}
        lines = report_fixture.run_report(self, acc).splitlines()
        self.assertEqual(lines[0], "# curvebench report")
        self.assertTrue(lines[2].startswith("Generated by"))
        self.assertEqual(lines[4], "## Summary")
        headings = [x for x in lines if x.startswith("## ")]
        self.assertEqual(headings[:3], ["## Summary", "## Contents", "## Machine and build"])
        self.assertIn("| `length` | g | 2-99 segments | 2 | gauss n=2 (10 evals); peer: peer_p tol=1e-06 (2e+03 ns) | "
                      "gauss n=8 (40 evals); peer: none reaches it | "
                      "adaptive_gk tol=1e-14 (100 evals); peer: none reaches it |", lines)
        self.assertIn("| c2 | 40 | gauss n=2 (10.0 evals) | gauss n=8 (40.0 evals) | "
                      "adaptive_gk tol=1e-14 (100.0 evals) |", lines)
        start = lines.index("## Contents")
        links = []
        for x in lines[start + 2:]:
            if not x.startswith("- ["):
                break
            links.append(re.fullmatch(r"- \[(.*)\]\(#(.*)\)", x).groups())
        self.assertEqual([t for t, _ in links], [h[3:] for h in headings if h != "## Contents"])
        self.assertIn(("Inversion u(s): error vs cost", "inversion-us-error-vs-cost"), links)
        self.assertIn(("Peers: the libraries users would pick instead", "peers-the-libraries-users-would-pick-instead"),
                      links)


if __name__ == "__main__":
    unittest.main()
