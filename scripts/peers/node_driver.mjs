// What the Node peer drivers (easing_driver.mjs, penner_driver.mjs, gltf_driver.mjs) share:
// their command line, the accuracy runner's sample fractions and the time per evaluation.
// scripts/peers.sh copies this file beside each driver in build-peers/node.

const INV_PHI = 0.6180339887498949;  // 1 / golden ratio, as bench/harness/sweeps.hpp

/// The accuracy runner's n sample fractions (harness/sweeps.hpp sample_fractions): 0, 1 and
/// frac(j / phi) in between, the same doubles.
export function sampleFractions(n) {
  const out = [];
  for (let j = 0; j < n; ++j) out.push(j === 0 ? 0 : j + 1 === n ? 1 : (j * INV_PHI) % 1);
  return out;
}

/// {quick, out[, cases]} from argv: --out FILE, --quick, and --cases DIR when withCases; any other
/// argument or a missing required one throws, naming the driver.
export function driverArgs(name, argv, withCases) {
  const a = { quick: false };
  for (let i = 0; i < argv.length; ++i) {
    if (withCases && argv[i] === "--cases") a.cases = argv[++i];
    else if (argv[i] === "--out") a.out = argv[++i];
    else if (argv[i] === "--quick") a.quick = true;
    else throw new Error(`${name}: unknown argument ${argv[i]}`);
  }
  if (withCases && (!a.cases || !a.out)) throw new Error(`${name}: --cases DIR and --out FILE are required`);
  if (!a.out) throw new Error(`${name}: --out FILE is required`);
  return a;
}

/// ns per evaluation of fn (a number per time): one call per time, as an animation loop calls it;
/// the best of 200 passes over all the times (the first ones run before V8 has compiled fn; the
/// best pass is compiled code) divided by their number. A NaN among the results throws nanMessage.
export function bestNs(fn, times, nanMessage) {
  let best = Infinity;
  for (let pass = 0; pass < 200; ++pass) {
    let sink = 0;
    const t0 = process.hrtime.bigint();
    for (const t of times) sink += fn(t);
    const ns = Number(process.hrtime.bigint() - t0);
    if (Number.isNaN(sink)) throw new Error(nanMessage);
    best = Math.min(best, ns);
  }
  return best / times.length;
}
