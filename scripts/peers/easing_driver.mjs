// The JavaScript easing evaluators as peers: every CSS cubic-bezier() case of the suite
// (bench/cases/*.json with "type": "channel", "tool": "css") evaluated by each package at the
// query times, written as JSON for scripts/peers/easing_results.py to measure against a 50-digit
// truth. scripts/peers.sh copies this file beside the pinned packages (build-peers/node, from
// scripts/peers/node/package.json) and runs it there:
//   node easing_driver.mjs --cases DIR --out FILE [--quick]
// Peers: bezier-easing 3.2.0 (peer_bezier_easing_3), bezier-easing 2.1.0 (peer_bezier_easing_2),
// @mapbox/unitbezier 1.0.0 (peer_mapbox_unitbezier, solve(x) with its default epsilon) and
// @babylonjs/core 9.37.1 (peer_babylon_bezier_interpolate: BezierCurve.Interpolate(x, x1, y1, x2,
// y2), what Babylon's BezierCurveEase evaluates; five Newton steps on x(u) = x from u = x, each
// clamped to [0, 1], no convergence test; only Maths/math.path.js is loaded, no engine).
// lottie-web 5.13.0 (peer_lottie_bezier_easing): the BezierFactory of its player
// (player/js/3rd_party/BezierEaser.js, the module its bundles build in; loaded here from the pinned
// package as an ES module, no page): a bezier-easing variant with an 11-entry sample table of x(u)
// in a Float32Array (so the table's x are float32), 4 Newton steps when the slope is at least
// 1e-3, else at most 10 bisection steps to 1e-7; what lottie's keyframes evaluate for their
// temporal easing (its "o" and "i" tangents).
// Query times: the accuracy runner's sample fractions (0, 1 and frac(j / phi) in between; 65, or
// 257 without --quick). Time per evaluation: one call per time, as an animation loop calls them,
// the best of 200 passes over all the times (the first ones warm V8 up) divided by their number;
// a peer's NaN or infinite values (Babylon's Newton step divides by x'(u), 0 where x(u) = x lands
// on a flat point: cubic-bezier(0, 4, 1, -3) at x = 1) are written as null and listed in the run's
// "non_finite", and its time is over the other times.
import fs from "node:fs";
import path from "node:path";
import { createRequire } from "node:module";
import bezier3 from "bezier-easing-3";
import unitBezier from "@mapbox/unitbezier";
import { BezierCurve } from "@babylonjs/core/Maths/math.path.js";
import { bestNs, driverArgs, sampleFractions } from "./node_driver.mjs";

const require = createRequire(import.meta.url);
const bezier2 = require("bezier-easing");

function version(pkg) {
  return JSON.parse(fs.readFileSync(path.join("node_modules", pkg, "package.json"), "utf8")).version;
}

function cubicBezier(easing) {
  const m = /^\s*cubic-bezier\(([^)]*)\)\s*$/.exec(easing);
  if (!m) return null;
  const v = m[1].split(",").map(Number);
  return v.length === 4 && v.every(Number.isFinite) ? v : null;
}

// lottie's BezierEaser.js is an ES module inside a CommonJS package: imported from its text.
const lottieEaser = (
  await import(
    "data:text/javascript," +
      encodeURIComponent(fs.readFileSync(path.join("node_modules", "lottie-web", "player", "js", "3rd_party",
                                                   "BezierEaser.js"), "utf8"))
  )
).default;

const a = driverArgs("easing_driver", process.argv.slice(2), true);
const times = sampleFractions(a.quick ? 65 : 257);
const peers = {
  peer_bezier_easing_3: (p) => bezier3(...p),
  peer_bezier_easing_2: (p) => bezier2(...p),
  peer_mapbox_unitbezier: (p) => {
    const solve = unitBezier(...p);
    return (t) => solve(t);
  },
  peer_babylon_bezier_interpolate: ([x1, y1, x2, y2]) => (t) => BezierCurve.Interpolate(t, x1, y1, x2, y2),
  peer_lottie_bezier_easing: (p) => {
    const e = lottieEaser.getBezierEasing(...p);
    return (t) => e.get(t);
  },
};
const runs = [];
const notes = [];
for (const file of fs.readdirSync(a.cases).filter((f) => f.endsWith(".json")).sort()) {
  const spec = JSON.parse(fs.readFileSync(path.join(a.cases, file), "utf8"));
  if (spec.type !== "channel" || spec.tool !== "css") continue;
  const name = path.basename(file, ".json");
  const p = cubicBezier(spec.easing || "");
  if (!p) {
    notes.push(`${name}: easing ${JSON.stringify(spec.easing)} is not cubic-bezier(); these peers evaluate only that`);
    continue;
  }
  for (const [peer, make] of Object.entries(peers)) {
    let f;
    try {
      f = make(p);
    } catch (e) {
      runs.push({ case: name, peer, easing: p, refused: String(e.message || e) });
      continue;
    }
    const values = times.map(f);
    // A NaN or infinite value (JSON null) is recorded with its fraction as "non_finite" [[x, "NaN"]]
    // for easing_results.py to report; the time per evaluation is then over the other fractions.
    const bad = times.flatMap((t, i) => (Number.isFinite(values[i]) ? [] : [[t, String(values[i])]]));
    const timed = bad.length ? times.filter((t, i) => Number.isFinite(values[i])) : times;
    const run = { case: name, peer, easing: p, times, values,
                  ns_per_op: timed.length ? bestNs(f, timed, "easing_driver: NaN from a peer") : null };
    if (bad.length) run.non_finite = bad;
    // @mapbox/unitbezier documents solve(x, epsilon) with epsilon 1e-6 by default: its precision.
    if (peer === "peer_mapbox_unitbezier") run.documented_tolerance = 1e-6;
    runs.push(run);
  }
}
const doc = {
  driver: "easing",
  quick: a.quick,
  versions: {
    Node: process.version.replace(/^v/, ""),
    "bezier-easing 3": version("bezier-easing-3"),
    "bezier-easing 2": version("bezier-easing"),
    "@mapbox/unitbezier": version("@mapbox/unitbezier"),
    "@babylonjs/core": version("@babylonjs/core"),
    "lottie-web": version("lottie-web"),
  },
  notes,
  runs,
};
fs.writeFileSync(a.out + ".tmp", JSON.stringify(doc, null, 1));
fs.renameSync(a.out + ".tmp", a.out);
console.log(`easing_driver: ${runs.length} runs on ${new Set(runs.map((r) => r.case)).size} cases -> ${a.out}`);
