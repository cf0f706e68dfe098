// d3-ease as a peer: its Penner easing functions evaluated on a grid of normalized
// times, written as JSON for scripts/peers/penner_results.py to measure against the definitions d3
// documents, at 50 digits. scripts/peers.sh copies this file beside the pinned packages
// (build-peers/node, from scripts/peers/node/package.json) and runs it there:
//   node penner_driver.mjs --out FILE [--quick]
// Functions: every d3 In / Out / InOut of the families quad, cubic, poly (exponents 4 and 5, the
// quart and quint of other tools), sin, exp, circle, back, bounce and elastic, with d3's default
// parameters (poly exponent 3, back overshoot 1.70158, elastic amplitude 1 and period 0.3), named
// by d3's export. Times: the accuracy runner's sample fractions (0, 1 and frac(j / phi); 65 with
// --quick, else 257) and the fractions next to 0, 1/2 and 1 where the exponential and elastic
// families switch branches (2^-k from them, k = 6, 12, 24). Time per evaluation: one call per
// time, the best of 200 passes (the first ones warm V8 up) divided by the number of times.
import fs from "node:fs";
import path from "node:path";
import * as d3 from "d3-ease";
import { bestNs, driverArgs, sampleFractions } from "./node_driver.mjs";

function times(n) {
  const out = new Set(sampleFractions(n));
  for (const k of [6, 12, 24]) {
    const h = 2 ** -k;
    for (const t of [h, 0.5 - h, 0.5, 0.5 + h, 1 - h]) out.add(t);
  }
  return [...out].sort((a, b) => a - b);
}

// [function name, family, mode, parameters, the d3 function]
const functions = [];
for (const [fam, base, params] of [["quad", "Quad", {}], ["cubic", "Cubic", {}], ["poly", "Poly", { exponent: 4 }],
                                   ["poly", "Poly", { exponent: 5 }], ["sin", "Sin", {}], ["exp", "Exp", {}],
                                   ["circle", "Circle", {}], ["back", "Back", { overshoot: 1.70158 }],
                                   ["bounce", "Bounce", {}], ["elastic", "Elastic", { amplitude: 1, period: 0.3 }]]) {
  for (const mode of ["In", "Out", "InOut"]) {
    let f = d3[`ease${base}${mode}`];
    if (!f) throw new Error(`penner_driver: d3-ease has no ease${base}${mode}`);
    if (params.exponent !== undefined) f = f.exponent(params.exponent);
    const name = `ease${base}${mode}` + (params.exponent !== undefined ? `.exponent(${params.exponent})` : "");
    functions.push([name, fam, mode.replace("InOut", "in_out").toLowerCase(), params, f]);
  }
}

const a = driverArgs("penner_driver", process.argv.slice(2), false);
const ts = times(a.quick ? 65 : 257);
const pkg = JSON.parse(fs.readFileSync(path.join("node_modules", "d3-ease", "package.json"), "utf8"));
const runs = functions.map(([name, family, mode, params, f]) => (
  { function: name, family, mode, params, times: ts, values: ts.map((t) => f(t)),
    ns_per_op: bestNs(f, ts, "penner_driver: NaN from d3-ease") }));
const doc = { driver: "penner", quick: a.quick, versions: { Node: process.version.replace(/^v/, ""), "d3-ease": pkg.version },
              notes: [], runs };
fs.writeFileSync(a.out + ".tmp", JSON.stringify(doc, null, 1));
fs.renameSync(a.out + ".tmp", a.out);
console.log(`penner_driver: ${runs.length} d3-ease functions at ${ts.length} times -> ${a.out}`);
