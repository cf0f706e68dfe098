// Arc length and point at length as shipped npm libraries compute them: each
// case of a request (scripts/peers/shipped_request.py: SVG path data, the Bezier when the case is
// one, the arc lengths s to ask for) is handed to each library through its own API; the lengths and
// points it returns are written as JSON for scripts/peers/shipped_results.py to measure against
// curvebench's 50-digit truth. scripts/peers.sh copies this file beside the pinned packages
// (build-peers/node, from scripts/peers/node/package.json) and runs it there:
//   node shipped_node_driver.mjs --request FILE --out FILE [--quick]
// Output: {"driver": "shipped_node", "format": "curvebench-shipped-driver-1", versions, cpu, runs,
// skipped}; a run holds the peer's length, its points at the request's s (in order), n points
// equally spaced along its own length (k/(n-1) of it), and the times below. Every peer reads the
// case's path data "d" (for a shape case, the shape's equivalent path) except where it has only a
// Bezier API ("bezier": one quadratic or cubic). An s beyond the peer's own length is asked at its
// own length (several peers return nothing or extrapolate there); the note counts such s. A peer
// that throws, or returns a NaN or an infinity, is listed in "skipped" with the reason.
//
// What each peer computes (read from the pinned versions' sources and docs):
// - bezier-js 6.1.4 (peer_bezier_js; "bezier" cases): Bezier.length() integrates |B'(t)| over
//   [0, 1] by one 24-point Gauss-Legendre rule, recomputed per call. It has no point at length (its
//   getLUT is uniform in t), so points and spaced are null.
// - svg-path-properties 2.1.0 (peer_svg_path_properties; its package declares
//   node >= 22 but runs under Node 20): the constructor parses d and sums segment lengths: cubic by
//   one 20-point Gauss-Legendre rule, quadratic in closed form, an arc as a polyline of 300 chords.
//   getPointAtLength: a cubic's or quadratic's t by a step-halving search that stops once the
//   length at t is within 1e-3 of the segment's length from s; an arc's angle is taken linear in the
//   length fraction (exact on a circle, not on an ellipse).
// - paper 0.12.20 (peer_paper; dist/paper-core.js, headless, no canvas): PathItem.create(d)
//   gives a Path (a CompoundPath for several subpaths, walked here by its children's lengths) of
//   cubic Beziers (quadratics raised exactly; an arc split into ceil(sweep / 90 deg) cubics).
//   Curve length: Gauss-Legendre with 16 nodes, cached per curve; getPointAt(offset): the curve by
//   cumulative lengths, then its t by Newton steps on the length (each increment integrated by
//   Gauss-Legendre with 2 to 16 nodes) kept inside a bisection bracket, until a step is below 1e-12.
// - svg-path-commander 2.3.3 (peer_svg_path_commander): the util functions
//   getTotalLength / getPointAtLength on the parsed PathArray (parsePathString): cubic and quadratic
//   by one 24-point Gauss-Legendre rule in t, an arc by 24-point rules in angle over <= 90 deg spans;
//   point at length: t (or the arc's fraction) by 25 bisection steps on that length, the path
//   normalized again on every call.
// - three 0.187.0: peer_three_curve on "bezier" cases (CubicBezierCurve / QuadraticBezierCurve of
//   Vector2); Curve.getLength() is a polyline through arcLengthDivisions + 1 points equally spaced in
//   t (setting "": three's default 200; "divisions=1000"), cached until updateArcLengths();
//   getPointAt(u) takes u as a fraction of its own length (asked here at s / getLength()), finds t
//   by binary search in that table and linear interpolation; spaced is getSpacedPoints(n - 1).
//   peer_three_svgloader on the other cases: SVGLoader.parse of an <svg> holding <path d>, whose
//   subPaths are CurvePaths of LineCurve / CubicBezierCurve / QuadraticBezierCurve / EllipseCurve
//   (an arc is an EllipseCurve, preceded by a short LineCurve where the ellipse's computed start
//   differs from the current point). SVGLoader needs a DOMParser: @xmldom/xmldom 0.9.12's, with
//   querySelectorAll answering no elements (SVGLoader asks only for gradients; the document has
//   none). Z sets the subpath's autoClose without adding the closing line to its curves, so
//   getLength() and getPointAt() leave that line out; setting "closePath=1" calls the subpath's
//   closePath() first (three's way to add it). CurvePath.getLength() sums its curves' lengths;
//   CurvePath.getPointAt(u) maps u through the CurvePath's own table of chords between getPoint()
//   samples (getPoint being already by length along the curves); several subpaths are walked by
//   their lengths; spaced: getSpacedPoints(n - 1) of a single subpath (without the first point
//   that it appends again when autoClose), else the point at k/(n-1) of the length.
// - canvaskit-wasm 0.42.0 (peer_skia_contour_measure; Skia's SkContourMeasure): Path.
//   MakeFromSVGString(d) (arcs become conics), ContourMeasureIter(path, false, resScale) for resScale
//   1, 10, 100: each contour is cut into line pieces until a cheap estimate of each piece's distance
//   from the curve is within 0.5 / resScale (in the path's units: with small coordinates resScale 1
//   measures near the chords; coordinates are float32, so far from the origin it measures their
//   rounding); the length is the sum of the pieces, in float32; getPosTan(d) takes the piece holding
//   d, the t linear within it, and evaluates the curve there. Length: the sum of the contours'
//   length(); a point: the contour holding s and getPosTan(s - its start).
// - @babylonjs/core 9.37.1 (peer_babylon_curve3; "bezier" cases, only Maths/math.path.js and
//   math.vector.js loaded, no engine): Curve3.CreateCubicBezier / CreateQuadraticBezier (z = 0)
//   samples nbPoints + 1 points equally spaced in t (settings nbPoints=100, its docs' typical, and
//   nbPoints=1000); length() is that polyline's length. Points: Path3D over the curve's points,
//   getPointAt(fraction of its own length), walking the polyline from its start on each call and
//   interpolating linearly between its points (so on the chords).
// - three 0.187.0 CatmullRomCurve3 (peer_three_catmull_rom) on the request's "catmull_rom" cases
//   (points, with three's curveType matching the case's alpha: "catmullrom" (tension 0.5) for 0,
//   "centripetal" for 1/2, "chordal" for 1; closed as the case): getPoint(t) takes segment
//   floor((n - 1) t) (n t when closed) at weight w, extrapolating P_-1 = 2 P_0 - P_1 at an open
//   end, and evaluates the cubic Hermite of the nonuniform Catmull-Rom tangents (intervals
//   |P_i+1 - P_i|^alpha as pow(squared distance, alpha / 2); an interval below 1e-4 is replaced, for
//   repeated points) at w. Curve.getLength(): the polyline through getPoint at arcLengthDivisions + 1
//   equally spaced t (200 by default: 200 chords whatever the number of segments; setting
//   "divisions=1000" and, for long splines, 10 per segment); getUtoTmapping(u): t for a fraction u of
//   that length by binary search and linear interpolation in the table; getPointAt(u) =
//   getPoint(getUtoTmapping(u)); getSpacedPoints(n - 1). Each run also carries "t_at_s" (getUtoTmapping
//   at the request's s) and "values": getPoint at the request's t grid, both measured against
//   curvebench's Catmull-Rom through the same points (shipped_results.py).
// Shape cases use "d" for every peer: the libraries' own shape helpers start elsewhere (paper's
// Path.Ellipse at the left end, svg-path-commander's shapeToPath at (cx - r, cy)), so their points
// at s would not be the SVG shape's.
//
// Times (ns, on this machine's CPU, recorded in "cpu"), in the style of node_driver.mjs's bestNs:
// the calls first run for at least 10 ms (V8 compiles them), then the best of up to 200 passes
// (within about 50 ms; 20 passes with --quick) of a loop of k calls, k making a pass about 20 us,
// divided by k; a sum of the results is kept so the calls are not optimized away. ns_build:
// constructing the peer's object from the case (parse, tables; wasm objects deleted inside the
// loop). ns_length: one length call as a user makes it on a fresh object: where the library caches
// lengths the cache is rebuilt or a new object made, as each run's note says. ns_point: one point
// at length on the built object, averaged over the request's s. A run of about 30 cases takes
// about 30 s (10 s with --quick) on this project's 2-core machine.
import fs from "node:fs";
import os from "node:os";
import path from "node:path";
import { fileURLToPath } from "node:url";
import { createRequire } from "node:module";

const here = path.dirname(fileURLToPath(import.meta.url));
const require = createRequire(import.meta.url);

function args(argv) {
  const a = { quick: false };
  for (let i = 0; i < argv.length; ++i) {
    if (argv[i] === "--request") a.request = argv[++i];
    else if (argv[i] === "--out") a.out = argv[++i];
    else if (argv[i] === "--quick") a.quick = true;
    else throw new Error(`shipped_node_driver: unknown argument ${argv[i]}`);
  }
  if (!a.request || !a.out) throw new Error("shipped_node_driver: --request FILE and --out FILE are required");
  return a;
}

// ns per call of fn (returning a number): after a warm-up (calls for at least 10 ms, 5 with
// --quick, so that V8 has compiled them), the best of passes of k calls, k making a pass about
// 20 us, passes up to 200 within about 50 ms (20 with --quick), divided by k. A NaN sum throws.
let QUICK = false;
function timeNs(fn) {
  let sink = 0;
  const warm = process.hrtime.bigint() + BigInt(QUICK ? 5e6 : 1e7);
  for (let calls = 0; calls < 200 || process.hrtime.bigint() < warm; ++calls) {
    sink += fn();
    if (calls >= 3 && process.hrtime.bigint() > warm + 40000000n) break;  // a slow call: enough
  }
  let one = Infinity;
  for (let i = 0; i < 3; ++i) {
    const t0 = process.hrtime.bigint();
    sink += fn();
    one = Math.min(one, Number(process.hrtime.bigint() - t0));
  }
  const k = Math.max(1, Math.min(100000, Math.ceil(20000 / Math.max(one, 1))));
  const passes = QUICK ? 20 : Math.max(10, Math.min(200, Math.floor(5e7 / (one * k + 1))));
  let best = Infinity;
  for (let pass = 0; pass < passes; ++pass) {
    const t0 = process.hrtime.bigint();
    for (let i = 0; i < k; ++i) sink += fn();
    best = Math.min(best, Number(process.hrtime.bigint() - t0));
  }
  if (Number.isNaN(sink)) throw new Error("NaN in a timed call");
  return best / k;
}

function versionOf(pkg) {
  const file = path.join(here, "node_modules", ...pkg.split("/"), "package.json");
  return JSON.parse(fs.readFileSync(file, "utf8")).version;
}

const finite = (v) => typeof v === "number" && Number.isFinite(v);
const xy = (p) => [p.x, p.y];

// The s asked of a peer whose own length is L: s clamped to [0, L].
function askedS(c, L) {
  const s = c.s.map((v) => Math.min(Math.max(v, 0), L));
  const beyond = c.s.filter((v) => v > L).length;
  return { s, note: beyond ? `${beyond} of ${c.s.length} s beyond its length ${L}: asked at ${L}` : "" };
}

// One run: spec = {setting, build() -> object, length(o), point(o, s) -> [x, y] or null (no API),
// spaced(o, n, L) -> points (default: point at k/(n-1) L), lengthFresh(o) -> the timed length
// call, dispose(o), note}.
function measure(peer, c, spec, out) {
  const o = spec.build();
  try {
    const L = spec.length(o);
    const notes = [spec.note];
    let points = null, spaced = null, nsPoint = null, asked = null;
    if (spec.point) {
      asked = askedS(c, L);
      notes.push(asked.note);
      points = asked.s.map((s) => spec.point(o, s));
      const n = c.spaced;
      spaced = !(n >= 2) ? null : spec.spaced ? spec.spaced(o, n, L)
        : Array.from({ length: n }, (_, k) => spec.point(o, k === n - 1 ? L : (k / (n - 1)) * L));
    }
    // Extra outputs of a run (CatmullRomCurve3: t_at_s, values): {key: list of numbers or points}.
    const extra = spec.extra ? spec.extra(o, L, asked ? asked.s : c.s) : {};
    const bad = [];
    if (!finite(L)) bad.push(`length ${L}`);
    const okPoint = (p) => Array.isArray(p) && p.length >= 2 && p.every(finite);
    for (const [what, list] of [["point", points], ["spaced point", spaced], ...Object.entries(extra)])
      if (list) list.forEach((p, i) => { if (!(typeof p === "number" ? finite(p) : okPoint(p))) bad.push(`${what} ${i}: ${JSON.stringify(p)}`); });
    if (bad.length) {
      out.skipped.push({ peer, case: c.case, reason: (spec.setting ? `[${spec.setting}] ` : "") + `not finite: ${bad.slice(0, 3).join("; ")}` });
      return;
    }
    const nsBuild = timeNs(() => { const x = spec.build(); spec.dispose(x); return 1; });
    const nsLength = timeNs(() => spec.lengthFresh(o));
    if (spec.point) {
      const ss = asked.s;
      nsPoint = timeNs(() => { let sum = 0; for (const s of ss) sum += spec.point(o, s)[0]; return sum; }) / ss.length;
    }
    const run = { peer, case: c.case, setting: spec.setting, length: L, points, spaced,
                  ns_length: nsLength, ns_point: nsPoint, ns_build: nsBuild, ...extra };
    const note = notes.filter((x) => x).join("; ");
    if (note) run.note = note;
    for (const k of ["ns_length", "ns_point", "ns_build"]) if (run[k] !== null && !finite(run[k])) run[k] = null;
    out.runs.push(run);
  } finally {
    spec.dispose(o);
  }
}

// ---- the peers: each {peer, pkg, load() -> api, specs(api, case) -> [spec] or a string (skip reason)}

const PEERS = [
  {
    peer: "peer_bezier_js", pkgs: ["bezier-js"],
    load: async () => (await import("bezier-js")).Bezier,
    specs: (Bezier, c) => {
      if (!c.bezier) return "not one quadratic or cubic Bezier (bezier-js takes only a Bezier)";
      const pts = c.bezier.map(([x, y]) => ({ x, y }));
      return [{ setting: "", build: () => new Bezier(pts), length: (b) => b.length(), point: null,
                lengthFresh: (b) => b.length(), dispose: () => {},
                note: "no point-at-length API (getLUT is uniform in t): points and spaced null; length() is not cached: ns_length is one call on the built object" }];
    },
  },
  {
    peer: "peer_svg_path_properties", pkgs: ["svg-path-properties"],
    load: async () => (await import("svg-path-properties")).svgPathProperties,
    specs: (Props, c) => [{
      setting: "", build: () => new Props(c.d), length: (p) => p.getTotalLength(),
      point: (p, s) => xy(p.getPointAtLength(s)),
      lengthFresh: () => new Props(c.d).getTotalLength(), dispose: () => {},
      note: "lengths are computed in the constructor: ns_length is new svgPathProperties(d).getTotalLength() (parse included)",
    }],
  },
  {
    peer: "peer_paper", pkgs: ["paper"],
    load: async () => {
      const paper = require("paper/dist/paper-core.js");
      paper.setup(new paper.Size(1, 1));
      paper.settings.insertItems = false;  // items made here stay out of the project
      return paper;
    },
    specs: (paper, c) => {
      const build = () => {
        const item = paper.PathItem.create(c.d);
        const parts = item.children ? item.children.slice() : [item];
        return { item, parts };
      };
      const point = (o, s) => {
        let start = 0;
        for (let i = 0; i < o.parts.length; ++i) {
          const len = o.parts[i].length;
          if (s <= start + len || i === o.parts.length - 1) {
            const p = o.parts[i].getPointAt(Math.min(Math.max(s - start, 0), len));
            return p ? [p.x, p.y] : null;
          }
          start += len;
        }
        return null;
      };
      return [{ setting: "", build, length: (o) => o.item.length, point,
                lengthFresh: (o) => o.item.clone({ insert: false }).length, dispose: () => {},
                note: "paper caches each curve's length: ns_length is item.clone({insert: false}).length (the clone's curves measured anew)" +
                      (c.d.match(/[Mm]/g).length > 1 ? "; a CompoundPath: walked by its children's lengths" : "") }];
    },
  },
  {
    peer: "peer_svg_path_commander", pkgs: ["svg-path-commander"],
    load: async () => import("svg-path-commander/util"),
    specs: (u, c) => [{
      setting: "", build: () => u.parsePathString(c.d), length: (pa) => u.getTotalLength(pa),
      point: (pa, s) => xy(u.getPointAtLength(pa, s)),
      lengthFresh: (pa) => u.getTotalLength(pa), dispose: () => {},
      note: "util getTotalLength / getPointAtLength on parsePathString(d), nothing cached: ns_length is one call on the PathArray",
    }],
  },
  {
    peer: "peer_three_curve", pkgs: ["three"],
    load: async () => import("three"),
    specs: (THREE, c) => {
      if (!c.bezier) return "not one Bezier: three's SVGLoader route is peer_three_svgloader";
      const v = c.bezier.map(([x, y]) => new THREE.Vector2(x, y));
      const make = (div) => () => {
        const curve = v.length === 4 ? new THREE.CubicBezierCurve(...v) : new THREE.QuadraticBezierCurve(...v);
        if (div) curve.arcLengthDivisions = div;
        return curve;
      };
      return [["", 0], ["divisions=1000", 1000]].map(([setting, div]) => ({
        setting, build: make(div), length: (k) => k.getLength(),
        point: (k, s) => xy(k.getPointAt(s / k.getLength())),
        spaced: (k, n) => k.getSpacedPoints(n - 1).map(xy),
        lengthFresh: (k) => { k.updateArcLengths(); return k.getLength(); }, dispose: () => {},
        note: `${v.length === 4 ? "CubicBezierCurve" : "QuadraticBezierCurve"}, arcLengthDivisions ${div || 200}; ` +
              "getPointAt(u) takes u as a fraction of its own length: asked at u = s / getLength(); spaced: getSpacedPoints(n-1); " +
              "three caches the arc-length table: ns_length is updateArcLengths() + getLength()",
      }));
    },
  },
  {
    peer: "peer_three_svgloader", pkgs: ["three", "@xmldom/xmldom"],
    load: async () => {
      const { DOMParser } = await import("@xmldom/xmldom");
      // SVGLoader.parse asks the document for gradients by querySelectorAll, which xmldom lacks;
      // the documents made here hold one <path> and no gradient.
      globalThis.DOMParser = class extends DOMParser {
        parseFromString(text, type) {
          const doc = super.parseFromString(text, type);
          doc.querySelectorAll = () => [];
          return doc;
        }
      };
      return (await import("three/examples/jsm/loaders/SVGLoader.js")).SVGLoader;
    },
    specs: (SVGLoader, c) => {
      if (c.bezier) return "one Bezier: three's curve classes are peer_three_curve";
      const svg = `<svg xmlns="http://www.w3.org/2000/svg"><path d="${c.d}"/></svg>`;
      const make = (div, close) => () => {
        const subs = [];
        for (const sp of new SVGLoader().parse(svg).paths) for (const p of sp.subPaths) if (p.curves.length) subs.push(p);
        if (!subs.length) throw new Error("SVGLoader made no curve of the path");
        for (const p of subs) {
          if (close && p.autoClose) p.closePath();
          if (div) for (const k of [p, ...p.curves]) k.arcLengthDivisions = div;
        }
        return subs;
      };
      const probe = make(0, false)();
      // Subpaths closed by Z whose ends are apart (more than rounding): their closing line is missing.
      const open = probe.filter((p) => p.autoClose &&
        p.curves[0].getPoint(0).distanceTo(p.curves[p.curves.length - 1].getPoint(1)) > 1e-9 * Math.max(1, p.getLength())).length;
      const length = (subs) => subs.reduce((sum, p) => sum + p.getLength(), 0);
      const point = (subs, s) => {
        let start = 0;
        for (let i = 0; i < subs.length; ++i) {
          const len = subs[i].getLength();
          if (s <= start + len || i === subs.length - 1) {
            const p = subs[i].getPointAt(Math.min(Math.max((s - start) / len, 0), 1));
            return p ? [p.x, p.y] : null;
          }
          start += len;
        }
        return null;
      };
      const spaced = (subs, n, L) => subs.length === 1 ? subs[0].getSpacedPoints(n - 1).slice(0, n).map(xy)
        : Array.from({ length: n }, (_, k) => point(subs, k === n - 1 ? L : (k / (n - 1)) * L));
      const lengthFresh = (subs) => {
        let sum = 0;
        for (const p of subs) {
          for (const k of p.curves) k.updateArcLengths();
          p.updateArcLengths();
          sum += p.getLength();
        }
        return sum;
      };
      const settings = [["", 0, false], ["divisions=1000", 1000, false]];
      if (open) settings.push(["closePath=1", 0, true]);
      const curves = probe.map((p) => p.curves.map((k) => k.type).join(" ")).join(" | ");
      return settings.map(([setting, div, close]) => ({
        setting, build: make(div, close), length, point, spaced, lengthFresh, dispose: () => {},
        note: `SVGLoader subPaths: ${curves}; arcLengthDivisions ${div || 200}; ` +
              (open ? (close ? "closePath() added the closing line of the Z subpath(s); "
                             : `${open} subpath(s) closed by Z (autoClose): the closing line is not among the curves, so not in the length or points; `) : "") +
              "point: CurvePath.getPointAt(s_local / its getLength()); spaced: " +
              (probe.length === 1 ? "getSpacedPoints(n-1) (by getPoint)" : "point at k/(n-1) of the length") +
              "; ns_build includes the XML parse; ns_length: updateArcLengths() of each curve and CurvePath + getLength()",
      }));
    },
  },
  {
    peer: "peer_skia_contour_measure", pkgs: ["canvaskit-wasm"],
    load: async () => {
      const init = (await import("canvaskit-wasm")).default;
      const bin = path.join(here, "node_modules", "canvaskit-wasm", "bin");
      return init({ locateFile: (f) => path.join(bin, f) });
    },
    specs: (CK, c) => {
      const walk = (p, rs) => {
        const it = new CK.ContourMeasureIter(p, false, rs);
        const contours = [], starts = [];
        let total = 0, m;
        while ((m = it.next())) { starts.push(total); contours.push(m); total += m.length(); }
        it.delete();
        return { contours, starts, total };
      };
      const parse = () => {
        const p = CK.Path.MakeFromSVGString(c.d);
        if (!p) throw new Error("Path.MakeFromSVGString returned null");
        return p;
      };
      return [1, 10, 100].map((rs) => ({
        setting: `resScale=${rs}`,
        build: () => { const p = parse(); return { path: p, ...walk(p, rs) }; },
        length: (o) => o.total,
        point: (o, s) => {
          if (!o.contours.length) throw new Error("no contour (ContourMeasureIter skips zero-length contours)");
          let i = 0;
          while (i + 1 < o.contours.length && s > o.starts[i] + o.contours[i].length()) ++i;
          const pt = o.contours[i].getPosTan(s - o.starts[i]);
          return [pt[0], pt[1]];
        },
        lengthFresh: (o) => {
          const it = new CK.ContourMeasureIter(o.path, false, rs);
          let sum = 0, m;
          while ((m = it.next())) { sum += m.length(); m.delete(); }
          it.delete();
          return sum;
        },
        dispose: (o) => { for (const m of o.contours) m.delete(); o.path.delete(); },
        note: "float32 lengths and points; ns_build: MakeFromSVGString + ContourMeasureIter walk (+ delete); " +
              "ns_length: a new ContourMeasureIter over the parsed path, summing the contours' length()",
      }));
    },
  },
  {
    peer: "peer_babylon_curve3", pkgs: ["@babylonjs/core"],
    load: async () => {
      const { Curve3, Path3D } = await import("@babylonjs/core/Maths/math.path.js");
      const { Vector3 } = await import("@babylonjs/core/Maths/math.vector.js");
      return { Curve3, Path3D, Vector3 };
    },
    specs: (B, c) => {
      if (!c.bezier) return "not one quadratic or cubic Bezier (Curve3.CreateCubicBezier / CreateQuadraticBezier)";
      const v = c.bezier.map(([x, y]) => new B.Vector3(x, y, 0));
      const curve = (n) => v.length === 4 ? B.Curve3.CreateCubicBezier(v[0], v[1], v[2], v[3], n)
                                          : B.Curve3.CreateQuadraticBezier(v[0], v[1], v[2], n);
      return [100, 1000].map((n) => ({
        setting: `nbPoints=${n}`,
        build: () => { const k = curve(n); return { k, p3: new B.Path3D(k.getPoints()) }; },
        length: (o) => o.k.length(),
        point: (o, s) => { const p = o.p3.getPointAt(s / o.p3.length()); return [p.x, p.y]; },
        spaced: (o, m) => Array.from({ length: m }, (_, i) => { const p = o.p3.getPointAt(i / (m - 1)); return [p.x, p.y]; }),
        lengthFresh: () => curve(n).length(), dispose: () => {},
        note: `Curve3.Create${v.length === 4 ? "Cubic" : "Quadratic"}Bezier; points: Path3D(curve.getPoints()).getPointAt(fraction of its own length), ` +
              "asked at s / length(); the length is computed when the Curve3 is made: ns_length is Create...Bezier(...).length(); ns_build adds the Path3D",
      }));
    },
  },
  {
    peer: "peer_three_catmull_rom", pkgs: ["three"], input: "catmull_rom",
    load: async () => import("three"),
    specs: (THREE, c) => {
      const pts = c.points.map(([x, y, z]) => new THREE.Vector3(x, y, z));
      const dims = (p) => c.dim === 3 ? [p.x, p.y, p.z] : [p.x, p.y];
      const segments = c.closed ? pts.length : pts.length - 1;
      const divisions = [[200, ""], [1000, "divisions=1000"]];
      if (10 * segments > 1000) divisions.push([10 * segments, `divisions=${10 * segments}`]);
      return divisions.map(([div, tag]) => ({
        setting: [c.curve_type, tag].filter((x) => x).join(", "),
        build: () => {
          const k = new THREE.CatmullRomCurve3(pts, c.closed, c.curve_type, 0.5);
          k.arcLengthDivisions = div;
          k.getLengths();
          return k;
        },
        length: (k) => k.getLength(),
        point: (k, s) => dims(k.getPointAt(Math.min(Math.max(s / k.getLength(), 0), 1))),
        spaced: (k, n) => k.getSpacedPoints(n - 1).map(dims),
        extra: (k, L, ss) => ({
          t_at_s: ss.map((s) => k.getUtoTmapping(Math.min(Math.max(s / L, 0), 1))),
          values: c.t.map((t) => dims(k.getPoint(t))),
        }),
        lengthFresh: (k) => { k.updateArcLengths(); return k.getLength(); },
        dispose: () => {},
        note: `CatmullRomCurve3(points, closed=${c.closed}, "${c.curve_type}", tension 0.5), arcLengthDivisions ${div} ` +
              `(${segments} segments); points: getPointAt(s / getLength()); t_at_s: getUtoTmapping(s / getLength()); ` +
              "ns_build: the constructor and its length table (getLengths); ns_length: updateArcLengths() + getLength()",
      }));
    },
  },
];

async function main() {
  const a = args(process.argv.slice(2));
  QUICK = a.quick;
  const request = JSON.parse(fs.readFileSync(a.request, "utf8"));
  if (request.format !== "curvebench-shipped-request-1")
    throw new Error(`shipped_node_driver: ${a.request}: format ${request.format}, not curvebench-shipped-request-1`);
  const out = { driver: "shipped_node", format: "curvebench-shipped-driver-1", versions: { node: process.version },
                cpu: os.cpus()[0]?.model ?? "unknown", runs: [], skipped: [] };
  const t0 = Date.now();
  for (const peer of PEERS) {
    let api;
    try {
      api = await peer.load();
      for (const p of peer.pkgs) out.versions[p] = versionOf(p);
    } catch (e) {
      for (const c of request[peer.input ?? "cases"] ?? [])
        out.skipped.push({ peer: peer.peer, case: c.case, reason: `not loaded: ${e.message}` });
      continue;
    }
    for (const c of request[peer.input ?? "cases"] ?? []) {
      let specs;
      try {
        specs = peer.specs(api, c);
      } catch (e) {
        out.skipped.push({ peer: peer.peer, case: c.case, reason: `threw: ${e.message}` });
        continue;
      }
      if (typeof specs === "string") {
        out.skipped.push({ peer: peer.peer, case: c.case, reason: specs });
        continue;
      }
      for (const spec of specs) {
        try {
          measure(peer.peer, c, spec, out);
        } catch (e) {
          out.skipped.push({ peer: peer.peer, case: c.case, reason: (spec.setting ? `[${spec.setting}] ` : "") + `threw: ${e.message}` });
        }
      }
    }
  }
  fs.writeFileSync(a.out + ".tmp", JSON.stringify(out, null, 1) + "\n");
  fs.renameSync(a.out + ".tmp", a.out);
  console.log(`shipped_node_driver: ${out.runs.length} runs, ${out.skipped.length} skipped, ${request.cases.length} cases, ` +
              `${((Date.now() - t0) / 1000).toFixed(1)} s -> ${a.out}`);
}

await main();
