#!/usr/bin/python3
"""SciPy as a peer: reads curvebench case specs, builds the same curve with SciPy where
SciPy has it, evaluates it at the accuracy runner's parameters and integrates its arc length, and
writes what it computed for `curvebench check` to measure against the 50-digit reference.

  scipy_driver.py --cases bench/cases --out DIR [--quick]

Curves SciPy represents (one coordinate array per point, as the spec gives them):
  natural_cubic, end natural / clamped / not_a_knot / periodic
      peer_scipy_cubic_spline        CubicSpline(knots, points, bc_type=...)
      peer_scipy_make_interp_spline  make_interp_spline(knots, points, k=3, bc_type=...)
  bspline with explicit knots, or knot_vector clamped (the default) or uniform
      peer_scipy_bspline             BSpline(t, points, degree), the knot vector computed as the
                                     spec's field documentation describes it (clamped: degree + 1
                                     copies of 0 and 1 around uniform interior knots; uniform: 0,
                                     1, 2, ...)
  and for each of those curves
      peer_scipy_quad                quad(|P'(u)|, lo, hi, epsabs=0, epsrel=tol) with P' SciPy's own
                                     derivative of the spline above (CubicSpline / BSpline), at the
                                     accuracy runner's adaptive_gk tolerances; quad's other
                                     arguments at their defaults (limit=50), as users call it
      peer_scipy_quad_brentq         u(s) as arc-length code built on SciPy computes it: the length
                                     L by quad first, then brentq(s(u) - s, lo, hi) with each s(u)
                                     a quad from lo (epsabs=0, epsrel=tol), xtol = tol (hi - lo)
                                     (the tolerance scaled to the domain), at the accuracy runner's
                                     Newton u(s) tolerances and its interior u(s) targets (the
                                     fractions of harness/sweeps.hpp sample_fractions strictly
                                     between 0 and 1, times SciPy's L); the s, u pairs go to
                                     `curvebench check --inverse`
PchipInterpolator has no curvebench spec type (curvebench's monotone cubic is a scalar helper of
motion/, not a curve family), so no 50-digit reference: it is timed only, on the natural_cubic
cases' x coordinates, and says so in the notes.

Parameters: the accuracy runner's eval parameters (harness/sweeps.hpp sample_parameters: 0, 1 and
frac(j / phi) in between, 65 of them, or 257 without --quick). Times: per evaluation from one
vectorised call over all the parameters (best of 5, divided by their number), since a Python call
per point would measure the interpreter; per length from one quad call (best of 3).

Output in DIR: <case>.<peer>.values.csv (u, x[, y[, z]], dx[, dy[, dz]]) and <case>.<peer>.lengths.csv
(u0, u1, length; one row per tolerance, in the order of the run's "rows"),
<case>.peer_scipy_quad_brentq.tol=<tol>.inverse.csv (s, u) and scipy_driver.json:
{"driver": "scipy", "versions": {...}, "notes": [...], "runs": [{"case", "spec", "peer", "kind":
"values" | "lengths" | "inverse", "csv", "ns_per_op", "counterpart": {"method", "setting"}, "rows": [...]}]}.
scripts/peers.sh measures each CSV with `curvebench check` and scripts/peers/peer_results.py
joins the two into reports/peers_scipy.json.
"""
import argparse
import glob
import json
import math
import os
import sys
import time
import warnings

import numpy as np
import scipy
from scipy.integrate import IntegrationWarning, quad
from scipy.optimize import brentq
from scipy.interpolate import BSpline, CubicSpline, PchipInterpolator, make_interp_spline

import peer_io

# The peer ids this driver writes (each declared in bench/harness/vocabulary.hpp).
PEERS = ("peer_scipy_cubic_spline", "peer_scipy_make_interp_spline", "peer_scipy_bspline", "peer_scipy_quad",
         "peer_scipy_quad_brentq")
QUICK_TOLS = (1e-6, 1e-10, 1e-14)
FULL_TOLS = (1e-4, 1e-6, 1e-8, 1e-10, 1e-12, 1e-14)
# u(s): the accuracy runner's Newton tolerances and target counts (harness/sweep.hpp).
QUICK_INVERSE = ((1e-8, 1e-12), 9)
FULL_INVERSE = ((1e-6, 1e-9, 1e-12, 1e-14), 33)
BRENTQ_MAXITER = 100


def sample_parameters(lo, hi, n):
    """The accuracy runner's eval parameters (harness/sweeps.hpp), the same doubles."""
    return np.array([hi if f == 1.0 else lo + (hi - lo) * f for f in peer_io.sample_fractions(n)])


def best_ns(fn, repeats):
    best = math.inf
    for _ in range(repeats):
        t0 = time.perf_counter_ns()
        fn()
        best = min(best, time.perf_counter_ns() - t0)
    return float(best)


def clamped_knots(count, degree):
    """The spec's clamped knot vector on [0, 1] (the field's documentation): degree + 1 copies of
    each end around count - degree - 1 uniform interior knots, computed as lo + (hi - lo) j / n."""
    segments = count - degree
    breaks = [0.0 + (1.0 - 0.0) * j / segments for j in range(segments + 1)]
    breaks[-1] = 1.0
    return np.array([breaks[0]] * (degree + 1) + breaks[1:-1] + [breaks[-1]] * (degree + 1))


def curves(spec):
    """[(peer id, callable P(u) -> (n, dim), derivative P'(u) -> (n, dim), domain, counterpart
    eval algorithm)] SciPy builds for the spec, and a reason when it builds none."""
    kind = spec.get("type")
    if isinstance(spec.get("points"), dict):
        return [], f"generated points ({spec['points'].get('generate')}) are not read by this driver"
    if kind == "natural_cubic":
        y = np.array(spec["points"], dtype=float)
        x = np.array(spec["knots"], dtype=float) if "knots" in spec else np.arange(len(y), dtype=float)
        end = spec.get("end", "natural")
        if end == "clamped":
            s0, s1 = np.array(spec["start_slope"], dtype=float), np.array(spec["end_slope"], dtype=float)
            bc_cs, bc_mis = ((1, s0), (1, s1)), ([(1, s0)], [(1, s1)])
        else:
            bc_cs = {"natural": "natural", "not_a_knot": "not-a-knot", "periodic": "periodic"}[end]
            bc_mis = {"natural": "natural", "not_a_knot": None, "periodic": "periodic"}[end]
        cs = CubicSpline(x, y, bc_type=bc_cs)
        mis = make_interp_spline(x, y, k=3, bc_type=bc_mis)
        dom = (x[0], x[-1])
        return [("peer_scipy_cubic_spline", cs, cs.derivative(), dom),
                ("peer_scipy_make_interp_spline", mis, mis.derivative(), dom)], None
    if kind == "bspline":
        c = np.array(spec["points"], dtype=float)
        k = int(spec["degree"])
        if "knots" in spec:
            t = np.array(spec["knots"], dtype=float)
        else:
            kv = spec.get("knot_vector", "clamped")
            if kv == "clamped":
                t = clamped_knots(len(c), k)
            elif kv == "uniform":
                t = np.arange(len(c) + k + 1, dtype=float)
            else:
                return [], f"knot_vector {kv}: curvebench wraps the control loop itself; SciPy has no such constructor"
        b = BSpline(t, c, k, extrapolate=False)
        return [("peer_scipy_bspline", b, b.derivative(), (t[k], t[len(c)]))], None
    return [], None


def write_csv(path, header, rows):
    with open(path, "w", encoding="utf-8") as f:
        f.write(",".join(header) + "\n")
        for r in rows:
            f.write(",".join(repr(float(v)) for v in r) + "\n")


def run_case(name, spec, out_dir, n_params, tols, runs, notes, inverse=((), 0)):
    built, reason = curves(spec)
    if reason:
        notes.append(f"{name}: {reason}")
    coords = ["x", "y", "z"]
    for peer, p, dp, (lo, hi) in built:
        us = sample_parameters(float(lo), float(hi), n_params)
        values, d1 = p(us), dp(us)
        dim = values.shape[1]
        if not (np.all(np.isfinite(values)) and np.all(np.isfinite(d1))):
            notes.append(f"{name}: {peer} gave non-finite values at the sweep's parameters")
            continue
        ns = best_ns(lambda: p(us), 5) / len(us)
        csv = os.path.join(out_dir, f"{name}.{peer}.values.csv")
        write_csv(csv, ["u"] + coords[:dim] + ["d" + c for c in coords[:dim]],
                  [[u] + list(v) + list(d) for u, v, d in zip(us, values, d1)])
        runs.append({"case": name, "peer": peer, "kind": "values", "csv": os.path.basename(csv), "ns_per_op": ns,
                     "counterpart": {"method": "default", "setting": ""}})
        if peer == "peer_scipy_make_interp_spline":
            continue  # the same curve as CubicSpline's: one quad per curve
        rows, lengths = [], []
        for tol in tols:
            def speed(u):
                return float(np.linalg.norm(dp(u)))
            row = {"tol": tol, "setting": f"tol={tol:g}"}
            with warnings.catch_warnings(record=True) as caught:
                warnings.simplefilter("always", IntegrationWarning)
                try:
                    out = quad(speed, float(lo), float(hi), epsabs=0, epsrel=tol, full_output=1)
                except ValueError as e:  # quad refuses tolerances it cannot reach
                    row.update({"refused": str(e)})
                    rows.append(row)
                    continue
            value, abserr, info = out[0], out[1], out[2]
            row.update({"abserr": abserr, "neval": int(info["neval"]),
                        "message": out[3].strip().splitlines()[0] if len(out) > 3 else "success",
                        "warned": bool(caught)})
            row["ns_per_op"] = best_ns(lambda: quad(speed, float(lo), float(hi), epsabs=0, epsrel=tol), 3)
            rows.append(row)
            lengths.append([lo, hi, value])
        csv = os.path.join(out_dir, f"{name}.peer_scipy_quad.lengths.csv")
        if lengths:
            write_csv(csv, ["u0", "u1", "length"], lengths)
        runs.append({"case": name, "peer": "peer_scipy_quad", "kind": "lengths",
                     "csv": os.path.basename(csv) if lengths else None, "rows": rows,
                     "counterpart": {"method": "adaptive_gk"}, "curve": peer})
        for tol in inverse[0]:
            runs.append(inverse_run(name, peer, dp, float(lo), float(hi), tol, inverse[1], out_dir))


def inverse_run(name, curve_peer, dp, lo, hi, tol, n_targets, out_dir):
    """u(s) by quad + brentq at tol (see the module's doc): one run, its CSV of (s, u)."""
    calls = [0]

    def speed(u):
        calls[0] += 1
        return float(np.linalg.norm(dp(u)))

    def s_of(u):
        return quad(speed, lo, u, epsabs=0, epsrel=tol, full_output=1) if u > lo else (0.0, 0.0, {"neval": 0})

    def solve(s, total):
        if not s > 0:
            return lo
        if s >= total:
            return hi
        return brentq(lambda u: s_of(u)[0] - s, lo, hi, xtol=tol * (hi - lo), maxiter=BRENTQ_MAXITER)

    setting = f"tol={tol:g}"
    run = {"case": name, "peer": "peer_scipy_quad_brentq", "kind": "inverse", "curve": curve_peer,
           "setting": setting, "counterpart": {"method": "newton", "setting": setting}}
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always", IntegrationWarning)
        try:
            total = s_of(hi)[0]
            # The interior targets: the ends are u = lo and u = hi by definition, and s = L by SciPy's
            # own L may lie beyond the true L, which `curvebench check` refuses.
            targets = [total * f for f in peer_io.sample_fractions(n_targets) if 0 < f < 1]
            calls[0] = 0
            us = [solve(s, total) for s in targets]
            evals = calls[0] / len(targets)
            # The user's own account of |s(u) - s|: the residual by quad plus quad's abserr.
            estimate = max(abs(v - s) + e for s, (v, e) in zip(targets, (s_of(u)[:2] for u in us)))
        except (ValueError, RuntimeError) as e:  # quad's refusals; brentq's maxiter
            run.update({"csv": None, "refused": str(e).splitlines()[0]})
            return run
    csv = os.path.join(out_dir, f"{name}.peer_scipy_quad_brentq.{setting}.inverse.csv")
    write_csv(csv, ["s", "u"], list(zip(targets, us)))
    run.update({"csv": os.path.basename(csv), "total_length": total, "estimate_abs": estimate,
                "evaluations_per_query": evals, "warned": bool(caught),
                "message": str(caught[0].message).strip().splitlines()[0] if caught else "success",
                "ns_per_op": best_ns(lambda: [solve(s, total) for s in targets], 1) / len(targets)})
    return run


def pchip_timing(specs, n_params):
    """PCHIP's time per evaluation on each natural_cubic case's first coordinate (no reference)."""
    out = []
    for name, spec in specs:
        if spec.get("type") != "natural_cubic" or isinstance(spec.get("points"), dict):
            continue
        y = np.array(spec["points"], dtype=float)[:, 0]
        x = np.array(spec["knots"], dtype=float) if "knots" in spec else np.arange(len(y), dtype=float)
        p = PchipInterpolator(x, y)
        us = sample_parameters(x[0], x[-1], n_params)
        out.append(f"{name}: PchipInterpolator {best_ns(lambda: p(us), 5) / len(us):.3g} ns per evaluation "
                   f"(x coordinate, vectorised; no curvebench spec type is the same interpolant, so no error)")
    return out


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--cases", required=True, help="directory of curvebench case specs")
    ap.add_argument("--out", required=True, help="output directory")
    ap.add_argument("--quick", action="store_true", help="the quick sweep's parameters and tolerances")
    a = ap.parse_args()
    os.makedirs(a.out, exist_ok=True)
    n_params, tols = (65, QUICK_TOLS) if a.quick else (257, FULL_TOLS)
    inverse = QUICK_INVERSE if a.quick else FULL_INVERSE
    specs = []
    for path in sorted(glob.glob(os.path.join(a.cases, "*.json"))):
        with open(path, encoding="utf-8") as f:
            specs.append((os.path.splitext(os.path.basename(path))[0], json.load(f)))
    runs, notes = [], []
    for name, spec in specs:
        if spec.get("quick") is False and a.quick:
            continue
        run_case(name, spec, a.out, n_params, tols, runs, notes, inverse)
    notes += pchip_timing(specs, n_params)
    notes.append("quad is called as users call it: epsabs=0, epsrel=tol, limit=50 (its default), over the whole "
                 "domain without the breakpoints")
    notes.append(f"u(s) by brentq over quad: xtol = tol x the domain's width, maxiter {BRENTQ_MAXITER}, its other "
                 "arguments at their defaults; times per query include no length (L is computed once per tolerance)")
    doc = {"driver": "scipy", "quick": a.quick, "cases_dir": os.path.abspath(a.cases),
           "versions": {"SciPy": scipy.__version__, "NumPy": np.__version__,
                        "Python": sys.version.split()[0]},
           "notes": notes, "runs": runs}
    peer_io.write_json(os.path.join(a.out, "scipy_driver.json"), doc)
    print(f"scipy_driver: {len(runs)} runs on {len({r['case'] for r in runs})} cases -> {a.out}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
