#!/usr/bin/python3
"""Measures d3-ease (scripts/peers/penner_driver.mjs) against the definitions its documentation
gives, at 50 digits, and beside curvebench's Blender model of the same Penner equations, into the
peer records REPORT.md reads (reports/peers_penner.json, scripts/report_peers.py).

  penner_results.py --driver penner_driver.json --out FILE [--tool CURVEBENCH --work DIR]

The truth of each function at a time t (the double d3 evaluated at, taken exactly), in mpmath at
60 significant digits. d3-ease documents its functions as Penner's easing equations of normalized
time (begin 0, change 1, duration 1) with these definitions and defaults:
  in        quad t^2; cubic t^3; poly t^e (e the exponent); sin 1 - cos(t pi / 2); exp 2^(10 (t - 1))
            (d3's words: "raises 2 to the exponent 10 x (t - 1)"); circle 1 - sqrt(1 - t^2); back
            t^2 ((s + 1) t - s) with overshoot s = 1.70158; elastic (amplitude a = 1, period p =
            0.3) -a 2^(10 (t - 1)) sin((t - 1 - s) 2 pi / p) with s = p / (2 pi) asin(1 / a);
            bounce 1 - out(1 - t)
  out       1 - in(1 - t) ("reverse" easing); bounce out is Penner's four parabolas: 121/16 t^2 on
            [0, 4/11), then 121/16 (t - c)^2 + k with (c, k) = (6/11, 3/4) to 8/11, (9/11, 15/16)
            to 10/11, (21/22, 63/64) to 1
  in_out    in(2 t) / 2 for t < 1/2, else (2 - in(2 - 2 t)) / 2 ("symmetric" easing)
and, as in Penner's equations, exp and elastic are exactly 0 at t = 0 and 1 at t = 1 (his formulas
do not reach the ends by themselves: 2^(10 (t - 1)) is 2^-10 at t = 0).
Errors: max over the times of |v - f(t)| / (eps(double) x size), size = max |f(t)| over the
times (the unit of the other easing peers), and the absolute max as "abs_error".

curvebench's Blender model (the counterpart): `curvebench sample` of a blender channel with keys
(0, 0) and (1, 1) whose first key holds the matching interpolation and easing (BLENDER_FAMILY,
BLENDER_MODE; back with its back 1.70158; elastic with amplitude 1 and period 0.3, Blender's
fields in frames and value units, which for a unit segment are d3's normalized ones), measured
against the same truth; when it is given, the largest difference between d3 and the model is
recorded as "vs_blender_model".
"""
import argparse
import json
import os
import subprocess
import sys

import mpmath

import peer_io

EPS = 2.0 ** -52
PEER = "peer_d3_ease"
BLENDER_FAMILY = {"quad": "quad", "cubic": "cubic", "poly4": "quart", "poly5": "quint", "sin": "sine", "exp": "expo",
                  "circle": "circ", "back": "back", "bounce": "bounce", "elastic": "elastic"}
BLENDER_MODE = {"in": "in", "out": "out", "in_out": "in_out"}


# d3 and the Blender model "agree" on a function when no time shows a larger difference: both
# evaluate the same closed forms in double, a few eps apart.
MODEL_AGREES = 1e-12


class PennerResultError(Exception):
    pass


def _family_key(run):
    fam = run["family"]
    if fam == "poly":
        return f"poly{int(run['params']['exponent'])}"
    return fam


def _bounce_out(t):
    k = mpmath.mpf(121) / 16
    for edge, c, off in ((mpmath.mpf(4) / 11, 0, 0), (mpmath.mpf(8) / 11, mpmath.mpf(6) / 11, mpmath.mpf(3) / 4),
                         (mpmath.mpf(10) / 11, mpmath.mpf(9) / 11, mpmath.mpf(15) / 16)):
        if t < edge:
            return k * (t - c) ** 2 + off
    return k * (t - mpmath.mpf(21) / 22) ** 2 + mpmath.mpf(63) / 64


def ease_in(family, params, t):
    """The documented in-function of a family at t (mpf)."""
    if family == "quad":
        return t ** 2
    if family == "cubic":
        return t ** 3
    if family == "poly":
        return t ** mpmath.mpf(params["exponent"])
    if family == "sin":
        return 1 - mpmath.cos(t * mpmath.pi / 2)
    if family == "exp":
        return mpmath.power(2, 10 * (t - 1))
    if family == "circle":
        return 1 - mpmath.sqrt(1 - t * t)
    if family == "back":
        s = mpmath.mpf(params.get("overshoot", 1.70158))
        return t * t * ((s + 1) * t - s)
    if family == "elastic":
        a, p = mpmath.mpf(params.get("amplitude", 1)), mpmath.mpf(params.get("period", 0.3))
        s = p / (2 * mpmath.pi) * mpmath.asin(1 / a)
        return -a * mpmath.power(2, 10 * (t - 1)) * mpmath.sin((t - 1 - s) * 2 * mpmath.pi / p)
    if family == "bounce":
        return 1 - _bounce_out(1 - t)
    raise PennerResultError(f"unknown family {family!r}")


def truth(family, mode, params, t):
    """The documented value of family / mode at the double t, at 60 digits."""
    with mpmath.workdps(60):
        t = mpmath.mpf(t)
        if family in ("exp", "elastic") and t in (0, 1):
            return t  # Penner's own end cases of these two families
        if family == "bounce" and mode == "out":
            return _bounce_out(t)
        if mode == "in":
            return ease_in(family, params, t)
        if mode == "out":
            return 1 - ease_in(family, params, 1 - t)
        if mode == "in_out":
            if t < mpmath.mpf(1) / 2:
                return ease_in(family, params, 2 * t) / 2
            return (2 - ease_in(family, params, 2 - 2 * t)) / 2
        raise PennerResultError(f"unknown mode {mode!r}")


def measure(values, truths):
    with mpmath.workdps(60):
        size = max((abs(y) for y in truths), default=mpmath.mpf(0)) or mpmath.mpf(1)
        worst = max(abs(mpmath.mpf(v) - y) for v, y in zip(values, truths))
        return float(worst / (EPS * size)), float(worst)


def blender_spec(run):
    """The blender channel spec of curvebench's model of a d3 function (see the module doc)."""
    fam = BLENDER_FAMILY.get(_family_key(run))
    if fam is None:
        raise PennerResultError(f"{run['function']}: no Blender family")
    key = {"time": 0, "value": 0, "interpolation": fam, "easing": BLENDER_MODE[run["mode"]]}
    if fam == "back":
        key["back"] = run["params"].get("overshoot", 1.70158)
    if fam == "elastic":
        key["amplitude"] = run["params"].get("amplitude", 1)
        key["period"] = run["params"].get("period", 0.3)
    return {"type": "channel", "tool": "blender", "keys": [key, {"time": 1, "value": 1}]}


def read_sample(path, times):
    """`curvebench sample` CSV (t,value) at exactly `times`."""
    return peer_io.read_sample(path, times, error=PennerResultError, exact_times=False)


def assemble(driver, blender_values=lambda run: None):
    """The peers_penner.json document; blender_values(run) -> the model's values at run["times"] or None."""
    for key in ("driver", "versions", "runs"):
        if key not in driver:
            raise PennerResultError(f"driver output: no \"{key}\"")
    records, notes = [], list(driver.get("notes", []))
    for run in driver["runs"]:
        times, values = run["times"], run["values"]
        if len(values) != len(times):
            raise PennerResultError(f"{run['function']}: {len(values)} values for {len(times)} times")
        truths = [truth(run["family"], run["mode"], run["params"], t) for t in times]
        err, abs_err = measure(values, truths)
        rec = {"case": run["function"], "group": "penner", "quantity": "eval", "method": PEER, "setting": "",
               "error": err, "abs_error": abs_err, "estimate": None, "bounded": None, "status": "not_guaranteed",
               "peer": True, "peer_status": "success", "library": f"d3-ease {driver['versions'].get('d3-ease', '?')}",
               "evaluations": len(times), "ns_per_op": run.get("ns_per_op"), "counterpart_ns_per_op": None,
               "definition": f"d3's documented {_family_key(run)} {run['mode']}"}
        model = blender_values(run)
        if model is not None:
            if len(model) != len(times):
                raise PennerResultError(f"{run['function']}: {len(model)} model values for {len(times)} times")
            ce, cae = measure(model, truths)
            rec.update({"counterpart": {"method": "curvebench blender " + blender_spec(run)["keys"][0]["interpolation"]
                                        + " " + run["mode"], "setting": ""},
                        "counterpart_error": ce, "counterpart_abs_error": cae,
                        "vs_blender_model": max(abs(a - b) for a, b in zip(values, model))})
        records.append(rec)
    apart = [r for r in records if (r.get("vs_blender_model") or 0) > MODEL_AGREES]
    if apart:
        notes.append("d3-ease and curvebench's Blender model of the same Penner equation differ by more than "
                     f"{MODEL_AGREES:g} on: " + "; ".join(
                         f"{r['case']} (max {r['vs_blender_model']:.3g}; d3 {r['abs_error']:.3g} and the model "
                         f"{r['counterpart_abs_error']:.3g} from d3's documented definition)" for r in apart))
    return {"driver": driver["driver"], "versions": driver["versions"], "notes": notes, "quick": driver.get("quick"),
            "peer_records": records}


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--driver", required=True)
    ap.add_argument("--out", required=True)
    ap.add_argument("--tool", help="the curvebench tool: also measure its Blender model at the same times")
    ap.add_argument("--work", help="where the model's specs and samples go (with --tool)")
    a = ap.parse_args()
    try:
        with open(a.driver, encoding="utf-8") as f:
            driver = json.load(f)

        def model(run):
            if not a.tool:
                return None
            os.makedirs(a.work, exist_ok=True)
            stem = os.path.join(a.work, run["function"].replace("(", "_").replace(")", "").replace(".", "_"))
            with open(stem + ".json", "w", encoding="utf-8") as f:
                json.dump(blender_spec(run), f)
            with open(stem + ".times", "w", encoding="utf-8") as f:
                f.write("".join(repr(t) + "\n" for t in run["times"]))
            with open(stem + ".csv", "w", encoding="utf-8") as f:
                subprocess.run(peer_io.sample_command(a.tool, stem + ".json", stem + ".times"), stdout=f, check=True)
            return read_sample(stem + ".csv", run["times"])
        doc = assemble(driver, model)
    except (OSError, json.JSONDecodeError, subprocess.SubprocessError, PennerResultError) as e:
        print(f"penner_results: {e}", file=sys.stderr)
        return 1
    peer_io.write_json(a.out, doc)
    print(f"penner_results: {len(doc['peer_records'])} peer records -> {a.out}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
