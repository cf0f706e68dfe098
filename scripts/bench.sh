#!/usr/bin/env bash
# The main job: build optimized (-O3 -march=native -fno-math-errno), run every benchmark program,
# and write the results to reports/ (JSON, Google Benchmark format). Files are written under a
# temporary name and renamed, so an interrupted run never leaves a half-written result.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)

bash "$root/scripts/setup.sh"
build="$root/build-bench"
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release \
      -DCMAKE_CXX_FLAGS_RELEASE="-O3 -march=native -fno-math-errno -DNDEBUG" \
      -DCURVEBENCH_BUILD_TESTS=OFF -DCURVEBENCH_BUILD_BENCH=ON >/dev/null
cmake --build "$build" --parallel "$(nproc)"

mkdir -p "$root/reports"
revision=$(git -C "$root" rev-parse --short HEAD 2>/dev/null || echo unknown)
for exe in "$build"/bench/bench_*; do
  [[ -x "$exe" && -f "$exe" ]] || continue
  name=$(basename "$exe")
  echo "bench.sh: running $name"
  out="$root/reports/$name.json"
  "$exe" --benchmark_out="$out.tmp" --benchmark_out_format=json --benchmark_repetitions=3 \
         --benchmark_report_aggregates_only=true --benchmark_context=git_revision="$revision" \
         --benchmark_context=flags="-O3 -march=native -fno-math-errno"
  mv "$out.tmp" "$out"
done
echo "bench.sh: results in reports/"
