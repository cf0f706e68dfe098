// three.js as a glTF peer: every glTF channel case of the suite (bench/cases/*.json with
// "type": "channel", "tool": "gltf") written into a GLB held in memory, loaded by three's own
// GLTFLoader and evaluated by the interpolant of the animation track the loader builds, at the
// query times; written as JSON for scripts/peers/gltf_results.py to measure against the glTF 2.0
// specification at 60 digits. scripts/peers.sh copies this file beside the pinned packages
// (build-peers/node, from scripts/peers/node/package.json) and runs it there:
//   node gltf_driver.mjs --cases DIR --out FILE [--quick]
// The GLB: one node, one animation with one sampler whose input accessor holds the key times and
// whose output accessor holds the values, both FLOAT (float32, as glTF stores them: rounding the
// case's keys to float32 is part of what is measured). A scalar case (path "weights", the
// default) animates the node's translation with its value in x and 0 in y and z (a VEC3 output:
// per key, or in-tangent, value, out-tangent per key for CUBICSPLINE); a rotation case
// ("path": "rotation") animates the node's rotation with the case's quaternions (VEC4, x y z w).
// GLTFLoader.parse needs no fetch and no image for such a file, so it runs under Node as it runs
// in a browser; the AnimationClip's only track is evaluated through track.createInterpolant(),
// which for CUBICSPLINE is the loader's own factory (GLTFCubicSplineInterpolant, or the quaternion
// one that normalizes), for LINEAR rotations QuaternionLinearInterpolant and for STEP the discrete
// interpolant. The result buffer is the track's Float32Array, so every value comes back in float.
// A rotation case with "blend": "nlerp" has no three.js counterpart (three slerps linear
// rotations): it is skipped with the reason in "notes".
// Query times: the accuracy runner's sample fractions mapped onto the key range (0, 1 and
// frac(j / phi) in between; 65 with --quick, else 257), the key times themselves, and 16 times on
// each side beyond the keys over a tenth of the range (glTF clamps there), sorted and distinct.
// Time per evaluation: one evaluate() per time, the best of 200 passes divided by their number.
import fs from "node:fs";
import path from "node:path";
import { GLTFLoader } from "three/examples/jsm/loaders/GLTFLoader.js";
import { bestNs, driverArgs, sampleFractions } from "./node_driver.mjs";

function queryTimes(t0, t1, keyTimes, n) {
  const span = t1 - t0;
  const out = new Set(keyTimes);
  for (const f of sampleFractions(n)) out.add(f === 1 ? t1 : t0 + span * f);
  for (let i = 0; i < 16; ++i) {
    out.add(t0 - span * 0.1 * (16 - i) / 16);
    out.add(t1 + span * 0.1 * (i + 1) / 16);
  }
  return [...out].sort((a, b) => a - b);
}

// The sampler of a case as glTF stores it: [interpolation (upper case), path, times, output
// components per element, output elements] or a reason it is not run.
function samplerOf(spec) {
  const interp = spec.interpolation;
  if (!["step", "linear", "cubicspline"].includes(interp)) return { skip: `interpolation ${interp}` };
  const times = spec.times, values = spec.values;
  const perKey = interp === "cubicspline" ? 3 : 1;
  const rotation = spec.path === "rotation";
  if (!rotation && spec.path !== undefined && spec.path !== "weights") return { skip: `path ${spec.path}` };
  if (rotation && (spec.blend ?? "slerp") !== "slerp")
    return { skip: `blend ${spec.blend}: three.js interpolates linear rotations by slerp only` };
  const width = rotation ? 4 : 1;
  if (values.length !== times.length * perKey * width)
    throw new Error(`${spec.name}: ${values.length} values for ${times.length} keys`);
  const out = [];
  for (let e = 0; e < times.length * perKey; ++e) {
    if (rotation) out.push(values.slice(4 * e, 4 * e + 4));
    else out.push([values[e], 0, 0]);  // the scalar in translation.x
  }
  return { interpolation: interp.toUpperCase(), path: rotation ? "rotation" : "translation", times, out,
           components: rotation ? 4 : 3 };
}

function pad4(bytes, fill) {
  const n = (4 - (bytes.length % 4)) % 4;
  const out = new Uint8Array(bytes.length + n);
  out.set(bytes);
  out.fill(fill, bytes.length);
  return out;
}

// A GLB (glTF 2.0 binary: 12-byte header, a JSON chunk, a BIN chunk) with one animated node.
function glbOf(s) {
  const input = Float32Array.from(s.times);
  const output = Float32Array.from(s.out.flat());
  const bin = new Uint8Array(input.byteLength + output.byteLength);
  bin.set(new Uint8Array(input.buffer), 0);
  bin.set(new Uint8Array(output.buffer), input.byteLength);
  const gltf = {
    asset: { version: "2.0", generator: "curvebench scripts/peers/gltf_driver.mjs" },
    scene: 0,
    scenes: [{ nodes: [0] }],
    nodes: [{ name: "animated" }],
    buffers: [{ byteLength: bin.byteLength }],
    bufferViews: [{ buffer: 0, byteOffset: 0, byteLength: input.byteLength },
                  { buffer: 0, byteOffset: input.byteLength, byteLength: output.byteLength }],
    accessors: [
      { bufferView: 0, componentType: 5126, count: input.length, type: "SCALAR",
        min: [Math.min(...input)], max: [Math.max(...input)] },
      { bufferView: 1, componentType: 5126, count: s.out.length, type: s.components === 4 ? "VEC4" : "VEC3" }],
    animations: [{ name: "case", samplers: [{ input: 0, output: 1, interpolation: s.interpolation }],
                   channels: [{ sampler: 0, target: { node: 0, path: s.path } }] }],
  };
  const json = pad4(new TextEncoder().encode(JSON.stringify(gltf)), 0x20);
  const body = pad4(bin, 0);
  const total = 12 + 8 + json.length + 8 + body.length;
  const glb = new ArrayBuffer(total);
  const view = new DataView(glb);
  view.setUint32(0, 0x46546c67, true);  // "glTF"
  view.setUint32(4, 2, true);
  view.setUint32(8, total, true);
  view.setUint32(12, json.length, true);
  view.setUint32(16, 0x4e4f534a, true);  // "JSON"
  new Uint8Array(glb, 20, json.length).set(json);
  view.setUint32(20 + json.length, body.length, true);
  view.setUint32(24 + json.length, 0x004e4942, true);  // "BIN\0"
  new Uint8Array(glb, 28 + json.length, body.length).set(body);
  return glb;
}

function load(glb) {
  return new Promise((resolve, reject) => new GLTFLoader().parse(glb, "", resolve, reject));
}

async function main() {
  const a = driverArgs("gltf_driver", process.argv.slice(2), true);
  const notes = [], runs = [];
  for (const file of fs.readdirSync(a.cases).filter((f) => f.endsWith(".json")).sort()) {
    const spec = JSON.parse(fs.readFileSync(path.join(a.cases, file), "utf8"));
    if (spec.type !== "channel" || spec.tool !== "gltf") continue;
    const name = file.slice(0, -5);
    const s = samplerOf({ ...spec, name });
    if (s.skip) {
      notes.push(`${name}: not run (${s.skip})`);
      continue;
    }
    const gltf = await load(glbOf(s));
    const clip = gltf.animations[0];
    if (!clip || clip.tracks.length !== 1)
      throw new Error(`${name}: the loader made ${clip ? clip.tracks.length : 0} tracks, not 1`);
    const track = clip.tracks[0];
    const interpolant = track.createInterpolant();
    const ts = queryTimes(s.times[0], s.times[s.times.length - 1], s.times, a.quick ? 65 : 257);
    const values = ts.map((t) => Array.from(interpolant.evaluate(t)));
    runs.push({ case: name, path: spec.path === "rotation" ? "rotation" : "weights", interpolation: spec.interpolation,
                track: track.constructor.name, interpolant: interpolant.constructor.name, target: track.name,
                times: ts, values,
                ns_per_op: bestNs((t) => interpolant.evaluate(t)[0], ts, "gltf_driver: NaN from three") });
  }
  const pkg = JSON.parse(fs.readFileSync(path.join("node_modules", "three", "package.json"), "utf8"));
  const versions = { three: pkg.version, Node: process.version.replace(/^v/, "") };
  const doc = { driver: "three", quick: a.quick, versions, notes, runs };
  fs.writeFileSync(a.out + ".tmp", JSON.stringify(doc, null, 1));
  fs.renameSync(a.out + ".tmp", a.out);
  console.log(`gltf_driver: ${runs.length} glTF cases through three ${pkg.version}'s GLTFLoader -> ${a.out}`);
}

await main();
