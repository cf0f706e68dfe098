#!/usr/bin/python3
"""Measures three.js's glTF interpolants (scripts/peers/gltf_driver.mjs: the suite's glTF channel
cases loaded by three's GLTFLoader and evaluated by their track's interpolant) against the glTF 2.0
specification's sampler at 60 digits, and beside curvebench's own glTF model, into the peer
records REPORT.md reads (reports/peers_three.json, scripts/report_peers.py).

  gltf_results.py --driver three_driver.json --cases DIR --out FILE [--tool CURVEBENCH --work DIR]

The truth, in mpmath at 60 significant digits, of the case's keys as written (the doubles its
JSON holds, taken exactly: not rounded to float32, since three's float32 storage is part of what
is measured), from the specification's Appendix C (animation sampler interpolation). With keys
t_0 < ... < t_n, a time t in [t_k, t_k+1), td = t_k+1 - t_k and s = (t - t_k) / td:
  STEP         v_k (at t = t_k+1 the next key's value);
  LINEAR       (1 - s) v_k + s v_k+1; for a rotation the spherical interpolation: a = arccos |d|,
               d = v_k . v_k+1, v = sin(a (1 - s)) / sin(a) v_k + sign(d) sin(a s) / sin(a) v_k+1
               (the short path; its limit (1 - s) v_k + sign(d) s v_k+1 when a = 0);
  CUBICSPLINE  per key the in-tangent a_k, the value v_k and the out-tangent b_k:
               (2s^3 - 3s^2 + 1) v_k + td (s^3 - 2s^2 + s) b_k + (-2s^3 + 3s^2) v_k+1
               + td (s^3 - s^2) a_k+1; a rotation is then divided by its length.
Before the first key and after the last the sampler holds the end key's value (clamped).
The same truth of the keys rounded to float32 (the times too: what three holds after loading)
separates three's evaluation from its storage: "vs_float32_keys".

Errors, at every time the driver evaluated (three's values are float32 numbers, taken exactly):
  scalar    |three - truth| over the case (three's translation.x; y and z must stay 0), in units
            of eps(float32) = 2^-23 x size and of eps(double) = 2^-52 x size, size = max |truth|
            over the times;
  rotation  the angle of the rotation taking three's quaternion to the truth: twice the angle
            between them as 4-vectors, phi = 2 atan2(|q - p|, |q + p|) for unit p and q after
            flipping p when q . p < 0 (q and -q are one rotation), so 2 phi with both divided by
            their lengths first (curvebench's rotation measure, channel/gltf.hpp); in radians
            and in eps(float32) (radians / 2^-23).
curvebench's model: `curvebench sample SPEC --at-file TIMES --derivatives 0 --quiet` of the case
itself (double; t,value or t,x,y,z,w), measured against the same truth ("counterpart_error"), and
the largest difference from three ("vs_model": |three - model| for a scalar, the rotation angle
between them in radians for a rotation).
The peer record's "error" is in eps(double) x size (size 1 for a rotation's angle) like every eval
record, with "unit_eps" 2^-23: three evaluates float32 data, so the report's findings count its
own ulps.
"""
import argparse
import json
import os
import struct
import subprocess
import sys

import mpmath

import peer_io

PEER = "peer_three_gltf"
EPS32 = 2.0 ** -23
EPS64 = 2.0 ** -52
DPS = 60


class GltfResultError(Exception):
    pass


def f32(x):
    """The float32 nearest to the double x, as a double (what a Float32Array stores)."""
    return struct.unpack("<f", struct.pack("<f", x))[0]


def keys_of(spec, rounding=None):
    """(times, elements) of a gltf case: elements are numbers (scalar) or 4-tuples (rotation), per
    key, or in-tangent, value, out-tangent per key for cubicspline; exact mpf of the doubles, or of
    rounding(double) when given."""
    r = rounding or (lambda x: x)
    with mpmath.workdps(DPS):
        times = [mpmath.mpf(r(float(t))) for t in spec["times"]]
        vals = [mpmath.mpf(r(float(v))) for v in spec["values"]]
    if spec.get("path") == "rotation":
        if len(vals) % 4:
            raise GltfResultError(f"{len(vals)} rotation numbers: not quaternions")
        vals = [tuple(vals[i:i + 4]) for i in range(0, len(vals), 4)]
    per_key = 3 if spec["interpolation"] == "cubicspline" else 1
    if len(vals) != per_key * len(times):
        raise GltfResultError(f"{len(vals)} output elements for {len(times)} keys ({spec['interpolation']})")
    if any(b <= a for a, b in zip(times, times[1:])):
        raise GltfResultError("key times must increase")
    return times, vals


def _add(a, b):
    return tuple(x + y for x, y in zip(a, b)) if isinstance(a, tuple) else a + b


def _scale(c, a):
    return tuple(c * x for x in a) if isinstance(a, tuple) else c * a


def _dot(a, b):
    return sum(x * y for x, y in zip(a, b))


def _norm(a):
    return mpmath.sqrt(_dot(a, a))


def slerp(p, q, s):
    """The specification's spherical interpolation from p to q at s (the short path)."""
    d = _dot(p, q)
    sign = -1 if d < 0 else 1
    a = mpmath.acos(min(abs(d), mpmath.mpf(1)))
    if a == 0:
        return _add(_scale(1 - s, p), _scale(sign * s, q))
    return _add(_scale(mpmath.sin(a * (1 - s)) / mpmath.sin(a), p),
                _scale(sign * mpmath.sin(a * s) / mpmath.sin(a), q))


def hermite(v0, b0, v1, a1, td, s):
    """The specification's cubic Hermite of a CUBICSPLINE segment: tangents times the interval td."""
    s2, s3 = s * s, s * s * s
    out = _scale(2 * s3 - 3 * s2 + 1, v0)
    out = _add(out, _scale(td * (s3 - 2 * s2 + s), b0))
    out = _add(out, _scale(-2 * s3 + 3 * s2, v1))
    return _add(out, _scale(td * (s3 - s2), a1))


def sample(interpolation, times, vals, t, rotation=False):
    """The glTF sampler of exact keys at the time t (a double or mpf), at 60 digits: a number, or
    a quaternion tuple for a rotation (normalized after a cubicspline)."""
    with mpmath.workdps(DPS):
        t = mpmath.mpf(t)
        cubic = interpolation == "cubicspline"

        def value(k):
            return vals[3 * k + 1] if cubic else vals[k]
        if t <= times[0]:
            return value(0)
        if t >= times[-1]:
            return value(len(times) - 1)
        k = max(i for i in range(len(times) - 1) if times[i] <= t)
        if interpolation == "step":
            return value(k)
        td = times[k + 1] - times[k]
        s = (t - times[k]) / td
        if interpolation == "linear":
            if rotation:
                return slerp(vals[k], vals[k + 1], s)
            return (1 - s) * vals[k] + s * vals[k + 1]
        if cubic:
            h = hermite(vals[3 * k + 1], vals[3 * k + 2], vals[3 * k + 4], vals[3 * k + 3], td, s)
            if rotation:
                n = _norm(h)
                if n == 0:
                    raise GltfResultError(f"t = {t}: the cubicspline quaternion vanishes")
                h = _scale(1 / n, h)
            return h
        raise GltfResultError(f"interpolation {interpolation!r}: not step, linear or cubicspline")


def rotation_angle(q, p):
    """The angle (radians, mpf) of the rotation taking p to q, quaternions of any nonzero length:
    2 phi with phi = 2 atan2(|q' - p'|, |q' + p'|), q' and p' the unit quaternions, p' flipped when
    q . p < 0 (see the module doc)."""
    with mpmath.workdps(DPS):
        q = tuple(mpmath.mpf(x) for x in q)
        p = tuple(mpmath.mpf(x) for x in p)
        nq, np_ = _norm(q), _norm(p)
        if nq == 0 or np_ == 0:
            raise GltfResultError("the angle needs nonzero quaternions")
        q, p = _scale(1 / nq, q), _scale(1 / np_, p)
        if _dot(q, p) < 0:
            p = _scale(-1, p)
        diff, summ = _add(q, _scale(-1, p)), _add(q, p)
        return 4 * mpmath.atan2(_norm(diff), _norm(summ))


def read_sample(path, times, rotation):
    """`curvebench sample` CSV at exactly `times`: values (scalar) or (x, y, z, w) tuples."""
    return peer_io.read_sample(path, times, ("x", "y", "z", "w") if rotation else ("value",), GltfResultError)


def measure(run, spec, model=None):
    """(summary row, peer record) of one driver run against the truth of its case's keys."""
    rotation = spec.get("path") == "rotation"
    interp = spec["interpolation"]
    times, values = run["times"], run["values"]
    if len(values) != len(times):
        raise GltfResultError(f"{run['case']}: {len(values)} values for {len(times)} times")
    exact = keys_of(spec)
    rounded = keys_of(spec, f32)
    truths = [sample(interp, *exact, t, rotation) for t in times]
    truths32 = [sample(interp, *rounded, t, rotation) for t in times]
    row = {"case": run["case"], "path": "rotation" if rotation else "weights", "interpolation": interp,
           "interpolant": run.get("interpolant"), "times": len(times),
           "in_key_range": sum(1 for t in times if exact[0][0] <= t <= exact[0][-1])}
    with mpmath.workdps(DPS):
        if rotation:
            if any(len(v) != 4 for v in values):
                raise GltfResultError(f"{run['case']}: a rotation's values are 4 numbers each")
            angles = [rotation_angle(v, y) for v, y in zip(values, truths)]
            worst = max(angles)
            worst_at = times[angles.index(worst)]
            row.update({"max_angle_rad": float(worst), "error_eps32": float(worst / EPS32), "worst_time": worst_at,
                        "vs_float32_keys_eps32": float(max(rotation_angle(v, y) for v, y in zip(values, truths32))
                                                       / EPS32)})
            size, abs_err = mpmath.mpf(1), worst
        else:
            if any(len(v) != 3 for v in values):
                raise GltfResultError(f"{run['case']}: a scalar case's values are translations (x, y, z)")
            row["max_abs_yz"] = max(max(abs(v[1]), abs(v[2])) for v in values)
            size = max(abs(y) for y in truths) or mpmath.mpf(1)
            diffs = [abs(mpmath.mpf(v[0]) - y) for v, y in zip(values, truths)]
            abs_err = max(diffs)
            size32 = max(abs(y) for y in truths32) or mpmath.mpf(1)
            row.update({"max_abs_error": float(abs_err), "error_eps32": float(abs_err / (EPS32 * size)),
                        "error_eps64": float(abs_err / (EPS64 * size)), "worst_time": times[diffs.index(abs_err)],
                        "vs_float32_keys_eps32": float(max(abs(mpmath.mpf(v[0]) - y) for v, y in zip(values, truths32))
                                                       / (EPS32 * size32))})
        rec = {"case": run["case"], "group": "channel", "quantity": "eval", "method": PEER, "setting": "",
               "error": float(abs_err / (EPS64 * size)), "abs_error": float(abs_err), "estimate": None,
               "bounded": None, "status": "not_guaranteed", "peer": True, "peer_status": "success",
               "library": f"three {run.get('three_version', '?')}", "evaluations": len(times),
               "ns_per_op": run.get("ns_per_op"), "counterpart_ns_per_op": None, "unit_eps": EPS32,
               "definition": "the glTF 2.0 sampler of the case's keys" + (" (the rotation angle)" if rotation else "")}
        if model is not None:
            if len(model) != len(times):
                raise GltfResultError(f"{run['case']}: {len(model)} model values for {len(times)} times")
            if rotation:
                row["vs_model"] = float(max(rotation_angle(v, m) for v, m in zip(values, model)))
                model_err = max(rotation_angle(m, y) for m, y in zip(model, truths))
            else:
                row["vs_model"] = max(abs(v[0] - m) for v, m in zip(values, model))
                model_err = max(abs(mpmath.mpf(m) - y) for m, y in zip(model, truths))
            row["model_error_eps64"] = float(model_err / (EPS64 * size))
            rec.update({"vs_model": row["vs_model"],
                        "counterpart": {"method": "curvebench gltf model (double)", "setting": ""},
                        "counterpart_error": row["model_error_eps64"]})
    return row, rec


def assemble(driver, specs, model_values=lambda run, spec: None):
    """The peers_three.json document; model_values(run, spec) -> curvebench's values at run["times"]
    (numbers, or (x, y, z, w) for a rotation) or None."""
    for key in ("driver", "versions", "runs"):
        if key not in driver:
            raise GltfResultError(f"driver output: no \"{key}\"")
    version = driver["versions"].get("three", "?")
    rows, records = [], []
    for run in driver["runs"]:
        if run["case"] not in specs:
            raise GltfResultError(f"{run['case']}: no such case")
        spec = specs[run["case"]]
        row, rec = measure(dict(run, three_version=version), spec, model_values(run, spec))
        rows.append(row)
        records.append(rec)
    return {"driver": driver["driver"], "versions": driver["versions"], "quick": driver.get("quick"),
            "notes": list(driver.get("notes", [])), "cases": rows, "peer_records": records}


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--driver", required=True)
    ap.add_argument("--cases", required=True)
    ap.add_argument("--out", required=True)
    ap.add_argument("--tool", help="the curvebench tool: also sample its glTF model at the same times")
    ap.add_argument("--work", help="where the model's times and samples go (with --tool)")
    a = ap.parse_args()
    try:
        with open(a.driver, encoding="utf-8") as f:
            driver = json.load(f)
        specs = {}
        for run in driver.get("runs", []):
            with open(os.path.join(a.cases, run["case"] + ".json"), encoding="utf-8") as f:
                specs[run["case"]] = json.load(f)

        def model(run, spec):
            if not a.tool:
                return None
            os.makedirs(a.work, exist_ok=True)
            stem = os.path.join(a.work, run["case"])
            with open(stem + ".times", "w", encoding="utf-8") as f:
                f.write("".join(repr(t) + "\n" for t in run["times"]))
            with open(stem + ".csv", "w", encoding="utf-8") as f:
                p = subprocess.run(peer_io.sample_command(a.tool, os.path.join(a.cases, run["case"] + ".json"),
                                                          stem + ".times", as_tool=spec.get("path") != "rotation"),
                                   stdout=f, stderr=subprocess.PIPE, text=True)
            if p.returncode != 0:  # a tool older than the case (e.g. before rotation channels): said, not fatal
                refused.append(f"{run['case']}: curvebench's model not compared (`curvebench sample` refused the "
                               f"case: {p.stderr.strip()})")
                return None
            return read_sample(stem + ".csv", run["times"], spec.get("path") == "rotation")
        refused = []
        doc = assemble(driver, specs, model)
        doc["notes"] += refused
    except (OSError, KeyError, json.JSONDecodeError, subprocess.SubprocessError, GltfResultError) as e:
        print(f"gltf_results: {e}", file=sys.stderr)
        return 1
    peer_io.write_json(a.out, doc)
    print(f"gltf_results: {len(doc['peer_records'])} glTF cases -> {a.out}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
