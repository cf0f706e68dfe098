"""Unit tests of report_channel (the keyframe-channel section of REPORT.md): the corpus' worst
figures per solver and precision, the goal line of curvebench's solver, the tools' disagreement
table and the join with the channel benchmarks. Run by ctest (report_py)."""
import os
import sys
import unittest

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "..", "scripts"))
import report_channel as rc  # noqa: E402


def rec(case, quantity, method, bits, error, **extra):
    r = {"case": case, "group": "channel", "quantity": quantity, "method": method, "setting": f"bits={bits}",
         "error": error, "estimate": None, "bounded": None, "evaluations": 600, "status": "not_guaranteed"}
    r.update(extra)
    return r


RECORDS = [
    rec("s", "channel_value", "closed_form", 64, 17.0, rms=3.0),
    rec("s", "channel_value", "closed_form", 32, 40.0, rms=5.0),
    rec("s", "channel_value", "curvebench", 64, 1.0, rms=0.4),
    rec("s", "channel_value", "curvebench", 32, 2.0, rms=0.5),
    rec("t", "channel_value", "curvebench", 64, 3.5, rms=0.2),
    rec("t", "channel_value", "exact", 64, 2.0, rms=0.3),
    rec("s", "channel_monotone", "curvebench", 64, 0),
    rec("s", "channel_monotone", "closed_form", 64, 2),
    rec("t", "channel_monotone", "closed_form", 64, 1),
    rec("s", "channel_time", "curvebench", 64, 1.5, iterations_mean=3.0, iterations_max=5, not_converged=0),
    rec("s", "eval", "default", 64, 1.0),  # not a channel record: ignored
]


class ChannelSection(unittest.TestCase):
    def test_worst_is_over_cases_per_precision(self):
        recs = rc.channel_records(RECORDS)
        self.assertEqual(rc.worst(recs, "channel_value", "curvebench", 64), (3.5, "t"))
        self.assertEqual(rc.worst(recs, "channel_value", "curvebench", 32), (2.0, "s"))
        self.assertEqual(rc.worst(recs, "channel_value", "curvebench", 64, "rms"), (0.4, "s"))
        self.assertEqual(rc.worst(recs, "channel_value", "bisection12", 64), (None, None))
        self.assertEqual(rc.total(recs, "channel_monotone", "closed_form", 64), 3)

    def test_goal_line_names_the_other_accurate_solvers(self):
        v, case, mono, accurate = rc.goal_line(rc.channel_records(RECORDS))
        self.assertEqual((v, case, mono), (3.5, "t", 0))
        self.assertEqual(accurate, ["exact"])  # closed_form's 17 ulps miss the 4-ulp goal

    def test_speed_goal_compares_each_configuration_with_the_accurate_solvers(self):
        t = {("curvebench", "64", 64, "single"): 70.0, ("exact", "64", 64, "single"): 80.0,
             ("curvebench", "64", 64, "sorted"): 72.0, ("exact", "64", 64, "sorted"): 78.0,
             ("curvebench", "2", 64, "single"): 71.0, ("exact", "2", 64, "single"): 85.0}
        configs, met = rc.speed_goal(t, ["exact"])
        self.assertTrue(met)
        self.assertEqual([c[0] for c in configs], ["64 keys, random times", "64 keys, sorted times", "CSS ease"])
        self.assertAlmostEqual(configs[0][2][0][2], 70.0 / 80.0)
        t[("exact", "64", 64, "sorted")] = 71.0  # slower than exact in one configuration: missed
        self.assertFalse(rc.speed_goal(t, ["exact"])[1])
        del t[("exact", "2", 64, "single")]
        self.assertFalse(rc.speed_goal(t, ["exact"])[1])  # a missing time does not hide a miss
        t[("exact", "64", 64, "sorted")] = 78.0
        self.assertIsNone(rc.speed_goal(t, ["exact"])[1])  # nor passes unjudged
        self.assertIsNone(rc.speed_goal({}, ["exact"])[1])

    def test_solver_rows_join_the_benchmark_times(self):
        bench = [{"family": "channel_value", "algorithm": "curvebench", "ns_per_op": 70.0,
                  "args": [("keys", "64"), ("bits", "64"), ("calls", "single")]},
                 {"family": "channel_value", "algorithm": "curvebench", "ns_per_op": 60.0,
                  "args": [("keys", "64"), ("bits", "32"), ("calls", "single")]},
                 {"family": "other", "algorithm": "curvebench", "ns_per_op": 1.0, "args": []}]
        times = rc.bench_times(bench)
        rows = {r[0]: r for r in rc.solver_rows(rc.channel_records(RECORDS), times)}
        self.assertEqual(set(rows), {"closed_form", "curvebench", "exact"})
        cb = rows["curvebench"]
        self.assertEqual(cb[1:4], [3.5, "t", 0.4])
        self.assertEqual(cb[7], "0 / 0")
        self.assertEqual(cb[8], 3.0)
        self.assertEqual((cb[10], cb[12]), (70.0, 60.0))
        self.assertIsNone(cb[11])  # no sorted benchmark given

    def test_case_matrix_has_a_column_per_solver(self):
        solvers, rows = rc.case_matrix(rc.channel_records(RECORDS))
        self.assertEqual(solvers, ["closed_form", "curvebench", "exact"])
        self.assertEqual(rows, [["s", 17.0, 1.0, None], ["t", None, 3.5, 2.0]])

    def test_disagreement_rows(self):
        cases = [{"name": "s", "channel": {"models": {
            "disagreement": [{"a": "exact", "b": "maya", "max": 0.2}, {"a": "exact", "b": "usd", "max": 1e-16},
                             {"a": "maya", "b": "usd", "max": 0.2}, {"a": "maya", "b": "blender", "max": 0.3}],
            "skipped": {"gltf": "a vertical handle"}}}},
            {"name": "css", "channel": {"tool": "css"}}]
        rows, notes = rc.disagreement_rows(cases, ["exact", "maya", "usd", "blender", "gltf"])
        self.assertEqual(rows, [["s", 0.2, 1e-16, "n/a", "n/a", "maya vs blender: 0.3"]])
        self.assertEqual(notes, ["s, gltf: a vertical handle"])
        # The columns are the tools given, in their order, the reference (exact) left out.
        rows, _ = rc.disagreement_rows(cases, ["exact", "usd", "css", "maya"])
        self.assertEqual(rows, [["s", 1e-16, "n/a", 0.2, "maya vs blender: 0.3"]])

    def test_tool_names_come_from_the_vocabulary(self):
        data = {"tools": [{"id": "exact"}, {"id": "gltf"}, {"id": "maya"}]}
        self.assertEqual(rc.tool_names(data), ["exact", "gltf", "maya"])
        self.assertEqual(rc.tool_names({}), [])

    def test_rotation_rows_pair_the_precisions_per_case_and_method(self):
        records = RECORDS + [
            rec("r", "channel_rotation", "rotation_slerp", 64, 3.0, rms=1.0, norm=0.5),
            rec("r", "channel_rotation", "rotation_slerp", 32, 2.5, rms=0.7, norm=1.5),
            rec("r", "channel_rotation", "rotation_nlerp", 64, 4.0, rms=2.0, norm=1.0),
        ]
        self.assertEqual(rc.rotation_rows(records), [["r", "rotation_nlerp", 4.0, 2.0, 1.0, None, None],
                                                     ["r", "rotation_slerp", 3.0, 1.0, 0.5, 2.5, 1.5]])
        self.assertEqual(rc.rotation_rows(RECORDS), [])
        # Rotation records are not time-solver records: the solver tables do not list them.
        self.assertNotIn("rotation_slerp", rc.solver_order(rc.channel_records(records)))

    def test_the_error_time_plot_puts_both_precisions_in_one_unit(self):
        # 4 ulps of double and 4 ulps of float are not the same error; as a
        # fraction of the value range they are 4 x 2^-52 and 4 x 2^-23.
        self.assertEqual(rc.relative_to_range(4, 64), 4 * 2.0 ** -52)
        self.assertEqual(rc.relative_to_range(4, 32), 4 * 2.0 ** -23)


FIDELITY = {"agree_ulps": 128, "curvebench": "curvebench 0.1.0 (abc1234)", "recordings": [{
    "file": "tests/data/recorded/animx_curves.json", "tool": "maya",
    "source": {"implementation": "Autodesk AnimX", "commit": "0123456789abcdef0123456789abcdef01234567",
               "build": "64-bit time"},
    "channels": 4, "agree": 1, "refused": 1, "unverified": 1, "tolerance": 2.8e-14, "max_error": 0.25,
    "features": [{"feature": "tangent:auto", "channels": 2, "agree": 1, "refused": 0, "max_error": 0.25},
                 {"feature": "tangent:spline", "channels": 1, "agree": 0, "refused": 1, "max_error": 0}],
    "disagree": [{"name": "c2", "features": ["tangent:auto"], "error": 0.25, "t": 3.0, "model": 1.0,
                  "recorded": 1.5}],
    "refused_channels": [{"name": "c3", "reason": "not modelled"}],
    "unverified_channels": [{"name": "c4", "reason": "no hermite in Ts"}]}]}
TOOLS = [{"id": "maya", "verification": "against AnimX; spline tangents not verified"}]


class FidelitySection(unittest.TestCase):
    def test_counts_sources_disagreements_and_refusals(self):
        md = "\n".join(rc.fidelity_section(FIDELITY, TOOLS))
        self.assertIn("## Tool models against the real tools", md)
        self.assertIn("| maya | against AnimX; spline tangents not verified |", md)
        # One row per recording: evaluated channels are those neither refused nor unverified (4 - 1 - 1).
        self.assertIn("| maya | Autodesk AnimX (commit 0123456789ab) | animx_curves.json | 4 | 1 of 2 | 1 | 1 | 0.25 |",
                      md)
        self.assertIn("Unverified (the tool gave no values): c4 (no hermite in Ts)", md)
        self.assertIn("Built: 64-bit time.", md)
        self.assertIn("| tangent:auto | 2 | 1 | 0 | 0 | 0.25 |", md)
        self.assertIn("| c2 | 0.25 | 3 | 1 | 1.5 |", md)
        self.assertIn("Refused (not modelled): c3 (not modelled)", md)
        self.assertIn("at most 128 eps", md)

    def test_without_recordings_the_verification_table_stays(self):
        md = "\n".join(rc.fidelity_section(None, TOOLS))
        self.assertIn("| maya | against AnimX", md)
        self.assertIn("No recordings were measured", md)


if __name__ == "__main__":
    unittest.main()
