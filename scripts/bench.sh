#!/usr/bin/env bash
# The main job: build optimized, run the accuracy sweep against 50-digit references and every
# benchmark, and write reports/ (REPORT.md, REPORT.html, accuracy.json/.csv, bench_*.json,
# vocabulary.json, fidelity.json, plots/*.png).
#   scripts/bench.sh           full run (all cases and settings, 3 benchmark repetitions; < 20 min on 2 cores)
#   scripts/bench.sh --quick   the quick suite and short benchmarks (a few minutes)
#   scripts/bench.sh --publish full run, then docs/results.md, docs/results/ and the README's figures
#                              (scripts/publish.py; commit them with the revision they name); refused
#                              before the build when an optional peer is not installed (peers.sh
#                              --check; install them: scripts/peers.sh), and after the run when one
#                              did not run, unless --allow-missing-peers is also given
#   scripts/bench.sh --baseline DIR   then `curvebench compare DIR reports` (DIR: a copy of an
#                              earlier reports/); every benchmark repeated 5 times, so that a
#                              slowdown can be told from noise; exits 1 on a confident regression;
#                              a baseline that cannot be compared is refused (exit 2) before the
#                              build (scripts/baseline_check.py) and again, by the tool, before the run
# Every output is written under a temporary name and renamed, so an interrupted run never leaves a
# half-written file. Progress is printed as cases and benchmarks finish.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)

quick=0
publish=0
allow_missing_peers=0
baseline=""
while [[ $# -gt 0 ]]; do
  case "$1" in
    --quick) quick=1 ;;
    --publish) publish=1 ;;
    --allow-missing-peers) allow_missing_peers=1 ;;
    --baseline)
      if [[ $# -lt 2 || -z "$2" ]]; then echo "bench.sh: --baseline needs a directory" >&2; exit 2; fi
      baseline="$2"
      shift ;;
    # The usage is the comment block under the shebang, printed without its "# ".
    -h|--help) awk 'NR == 1 { next } /^#/ { sub(/^# ?/, ""); print; next } { exit }' "$0"; exit 0 ;;
    *) echo "bench.sh: unknown argument '$1' (allowed: --quick, --publish, --allow-missing-peers, --baseline DIR)" >&2; exit 2 ;;
  esac
  shift
done
if [[ $allow_missing_peers -eq 1 && $publish -eq 0 ]]; then
  echo "bench.sh: --allow-missing-peers goes with --publish" >&2
  exit 2
fi
if [[ $quick -eq 1 && $publish -eq 1 ]]; then
  echo "bench.sh: --publish needs the full run; drop --quick" >&2
  exit 2
fi

if [[ -n "$baseline" ]]; then
  # The run rewrites reports/: a baseline there would be compared with itself, after being replaced.
  if [[ ! -d "$baseline" ]]; then echo "bench.sh: --baseline $baseline: not a directory" >&2; exit 2; fi
  if [[ "$(cd "$baseline" && pwd -P)" == "$(mkdir -p "$root/reports" && cd "$root/reports" && pwd -P)" ]]; then
    echo "bench.sh: --baseline $baseline is reports/ itself, which this run replaces: copy it first" \
         "(cp -r reports /tmp/base; scripts/bench.sh --baseline /tmp/base)" >&2
    exit 2
  fi
  # A baseline cut short or of another kind is refused now, not after the build and the run.
  if ! python3 "$root/scripts/baseline_check.py" "$baseline" "$([[ $quick -eq 1 ]] && echo --quick || echo --full)"; then
    echo "bench.sh: --baseline $baseline cannot be compared (above)" >&2
    exit 2
  fi
fi

# A run to publish needs every optional peer (publish.py refuses it otherwise): said now, not after
# the long run.
if [[ $publish -eq 1 && $allow_missing_peers -eq 0 ]] && ! bash "$root/scripts/peers.sh" --check; then
  echo "bench.sh: --publish: the optional peers above are not installed; install them (scripts/peers.sh)" \
       "or publish without them (--allow-missing-peers)" >&2
  exit 2
fi

bash "$root/scripts/setup.sh"
# ccache keys on absolute paths unless told the checkout's root: with it, a fresh clone anywhere
# (CI's) reuses the objects of an earlier build of the same sources.
export CCACHE_BASEDIR="$root"
build="$root/build-bench"
flags="-O3 -march=native -fno-math-errno -DNDEBUG"
# Warnings are errors in the test build (scripts/test.sh); here a compiler's false positive at -O3
# (GCC 12 has several in its own headers with -march=native) must not stop the main job.
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_FLAGS_RELEASE="$flags" \
      -DCURVEBENCH_WERROR=OFF -DCURVEBENCH_BUILD_TESTS=OFF -DCURVEBENCH_BUILD_BENCH=ON >/dev/null
echo "bench.sh: building (optimized: $flags)"
# The full log goes to a file (a stale executable from an earlier build must not be run after a
# failed one); progress is one line per finished target.
log="$build/build.log"
{ cmake --build "$build" --parallel "$(nproc)" 2>&1; echo $? >"$build/build.status"; } |
  tee "$log" | grep --line-buffered -E "Built target" || true
if [[ "$(cat "$build/build.status")" != 0 ]]; then
  grep -E -A3 "error|Error" "$log" | head -n 60 >&2
  echo "bench.sh: the build failed; the whole log is $log" >&2
  exit 1
fi

# The tool's own reader on the baseline (what compare will do after the run), before the run.
if [[ -n "$baseline" ]] && ! "$build/bench/curvebench" compare "$baseline" "$baseline" >/dev/null; then
  echo "bench.sh: --baseline $baseline cannot be compared (curvebench compare above)" >&2
  exit 2
fi

reports="$root/reports"
mkdir -p "$reports"
revision=$(git -C "$root" rev-parse --short HEAD 2>/dev/null || echo unknown)
export CURVEBENCH_REVISION="$revision"
start=$SECONDS

echo "bench.sh: accuracy sweep$([[ $quick -eq 1 ]] && echo ' (quick)')"
accuracy_args=(accuracy --out "$reports/accuracy.json")
[[ $quick -eq 1 ]] && accuracy_args+=(--quick)
"$build/bench/curvebench" "${accuracy_args[@]}"

# The tool models against the values recorded from the real tools (Blender, AnimX, OpenUSD's Ts):
# reports/fidelity.json, the report's "Tool models against the real tools".
shopt -s nullglob
recordings=("$root"/tests/data/recorded/*.json)
shopt -u nullglob
if [[ ${#recordings[@]} -gt 0 ]]; then
  echo "bench.sh: tool models against ${#recordings[@]} recordings of the real tools"
  "$build/bench/curvebench" fidelity --json "${recordings[@]}" >"$reports/fidelity.json.tmp"
  mv "$reports/fidelity.json.tmp" "$reports/fidelity.json"
fi

# The optional peers (scripts/peers.sh installs them) when installed: reports/peers_*.json, which
# the report joins; the C++ peers (GSL, Boost.Math, Eigen) ran inside the accuracy sweep above.
peers_args=(--no-install)
[[ $quick -eq 1 ]] && peers_args+=(--quick)
CURVEBENCH_TOOL="$build/bench/curvebench" bash "$root/scripts/peers.sh" "${peers_args[@]}" ||
  echo "bench.sh: an optional peer driver failed (above); REPORT.md goes without it" >&2

if [[ $quick -eq 1 ]]; then
  bench_args=(--benchmark_min_time=0.05)
  # ~900 (case, method, setting) timings, each joined with its error: short runs, the quick suite.
  case_args=(--quick-suite --benchmark_min_time=0.01)
  repetitions=1
else
  bench_args=(--benchmark_min_time=0.2)
  case_args=(--benchmark_min_time=0.03)
  repetitions=3
fi
# Against a baseline, 5 repetitions of every benchmark: the U test of `curvebench compare` needs 4 a
# side to reach p < 0.05 (3 against 3 never goes below 0.1). Repetitions stay in the JSON (the
# console shows their aggregates): the report takes their median, compare the repetitions.
if [[ -n "$baseline" ]]; then
  repetitions=5
  case_args+=(--benchmark_repetitions=5 --benchmark_display_aggregates_only=true
              --benchmark_enable_random_interleaving=true)
fi
# Interleaved at random, so that a burst of load on a shared machine spreads over every benchmark's
# repetitions instead of shifting one benchmark's (tests/data/compare/README.md).
if [[ $repetitions -gt 1 ]]; then
  bench_args+=(--benchmark_repetitions=$repetitions --benchmark_display_aggregates_only=true
               --benchmark_enable_random_interleaving=true)
fi
for exe in "$build"/bench/bench_*; do
  [[ -x "$exe" && -f "$exe" ]] || continue
  name=$(basename "$exe")
  echo "bench.sh: running $name"
  out="$reports/$name.json"
  args=("${bench_args[@]}")
  [[ $name == bench_arclength_cases ]] && args=("${case_args[@]}")
  "$exe" "${args[@]}" --benchmark_out="$out.tmp" --benchmark_out_format=json \
         --benchmark_context=git_revision="$revision"
  # Google Benchmark's --benchmark_context takes no '=' or ',' in a value (-march=native has one):
  # the flags and the compiler go into the JSON's context afterwards.
  /usr/bin/python3 - "$out.tmp" "$flags" "$(c++ --version | head -n 1)" <<'EOF'
import json, os, sys
path, flags, compiler = sys.argv[1:4]
with open(path, encoding="utf-8") as f:
    data = json.load(f)
data.setdefault("context", {}).update({"flags": flags, "compiler": compiler})
with open(path + ".ctx", "w", encoding="utf-8") as f:
    json.dump(data, f, indent=1)
os.replace(path + ".ctx", path)
EOF
  mv "$out.tmp" "$out"
done

echo "bench.sh: writing the report"
# The ids every benchmark name, label and counter must use (report.py fails on any other).
"$build/bench/curvebench" list vocabulary --json >"$reports/vocabulary.json.tmp"
mv "$reports/vocabulary.json.tmp" "$reports/vocabulary.json"
/usr/bin/python3 "$root/scripts/report.py" --reports "$reports"
# The gate's verdict on these results: thresholds.json's max_error and min_order rules were set on
# the quick suite, so on a full run they are information; thresholds_full.json (every estimate
# bounds its error) holds on every run, and a breach fails bench.sh (after the reports are written).
"$build/bench/curvebench" gate --results "$reports/accuracy.json" --thresholds "$reports/thresholds.json" || true
honest=0
"$build/bench/curvebench" gate --results "$reports/accuracy.json" --thresholds "$reports/thresholds_full.json" || honest=$?
printf '{"quick": %s, "seconds_after_build": %d}\n' "$([[ $quick -eq 1 ]] && echo true || echo false)" \
       "$((SECONDS - start))" >"$reports/run.json"
if [[ $publish -eq 1 ]]; then
  publish_args=()
  [[ $allow_missing_peers -eq 1 ]] && publish_args+=(--allow-missing-peers)
  /usr/bin/python3 "$root/scripts/publish.py" --reports "$reports" --docs "$root/docs" --readme "$root/README.md" \
                   "${publish_args[@]}"
fi
echo "bench.sh: done in $((SECONDS - start)) s after the build; see reports/REPORT.md (or REPORT.html in a browser)"
regressed=0
if [[ -n "$baseline" ]]; then
  echo "bench.sh: compared with the baseline $baseline"
  "$build/bench/curvebench" compare "$baseline" "$reports" || regressed=$?
fi
if [[ $honest -ne 0 ]]; then
  echo "bench.sh: an error estimate does not bound its error (gate on reports/thresholds_full.json above)" >&2
  exit 1
fi
if [[ $regressed -ne 0 ]]; then
  echo "bench.sh: a confident regression against $baseline (curvebench compare above)" >&2
  exit 1
fi
