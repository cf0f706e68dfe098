#!/usr/bin/env bash
# Fuzzing: builds the libFuzzer targets of tests/fuzz/ (spec, gate, csv, times, svg, compare,
# fidelity) with clang, AddressSanitizer and UndefinedBehaviorSanitizer in build-fuzz/, then runs
# each for SECONDS.
#   scripts/fuzz.sh [SECONDS] [TARGET...]   default 600 s per target, every target
# Installs clang and libFuzzer when missing (non-interactive apt-get, as scripts/setup.sh does).
# Each target starts from its seed corpus: tests/fuzz/seeds/<target>, tests/fuzz/regressions/<target>,
# bench/cases for the spec target (the regressions hold the extreme values: 1e200,
# 1e-170, a 1e-300 knot span, far and one-ulp domains, zero length), and inputs larger than
# libFuzzer's default length limit (JSON nested 100000 levels, a 100 kB string, a CSV header of
# 20000 columns, SVG elements nested 20000 levels, 2000 paths, path data of 5000 commands) written
# here, with -max_len 200000 so that mutations reach that size too; -use_value_profile=1 steers mutations by the values compared.
# Runs keep going after a finding (-fork=1 -ignore_crashes=1 -ignore_timeouts=1 -ignore_ooms=1), so
# a known defect does not hide the others; -timeout 60 s and -rss_limit_mb 4096 per input.
# Each finding is saved under build-fuzz/findings/<target>/ (crash-*, timeout-*, oom-*), replayed
# (the first 20) and summarized by the property it broke ("fuzz spec: property violated: bounded
# work: ...") or the sanitizer's first line; in runs of 120 s or more the first crash of each class
# is minimized beside it (.min, -minimize_crash for 30 s). A finding becomes a test:
# copy its input to tests/fuzz/regressions/<target>/ (the fuzz_replay_<target> ctest replays it).
# Runs of 120 s or more also check that bench/harness and bench/tool compile with clang.
# Exits 1 when any target found anything (or a source does not compile with clang), 0 otherwise, 2 on
# a usage error.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)

seconds=600
targets=()
for arg in "$@"; do
  case "$arg" in
    -h|--help) awk 'NR == 1 { next } /^#/ { sub(/^# ?/, ""); print; next } { exit }' "$0"; exit 0 ;;
    spec|gate|csv|times|svg|compare|fidelity) targets+=("$arg") ;;
    *)
      if [[ "$arg" =~ ^[0-9]+$ && "$arg" -gt 0 ]]; then seconds=$arg
      else echo "fuzz.sh: '$arg' is neither a number of seconds nor a target (spec, gate, csv, times, svg, compare, fidelity)" >&2; exit 2; fi ;;
  esac
done
[[ ${#targets[@]} -eq 0 ]] && targets=(spec gate csv times svg compare fidelity)

bash "$root/scripts/setup.sh" clang libfuzzer-14-dev

export CCACHE_BASEDIR="$root"
build="$root/build-fuzz"
# -O1 with line tables: the sanitizers' stack traces name the lines; warnings are the test build's
# business (clang's differ from g++'s on the library's headers), so they are not errors here.
cmake -S "$root" -B "$build" -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_BUILD_TYPE=RelWithDebInfo \
      -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -gline-tables-only" -DCURVEBENCH_FUZZ=ON \
      -DCURVEBENCH_BUILD_TESTS=OFF -DCURVEBENCH_BUILD_BENCH=OFF -DCURVEBENCH_WERROR=OFF >/dev/null
cmake --build "$build" --parallel "$(nproc)" --target "${targets[@]/#/fuzz_}"

# Seed corpora: copied, so that the fuzzer's additions stay out of the source tree.
corpus="$build/corpus"
rm -rf "$corpus"
for t in "${targets[@]}"; do
  mkdir -p "$corpus/$t"
  cp "$root/tests/fuzz/seeds/$t/"* "$root/tests/fuzz/regressions/$t/"* "$corpus/$t/" 2>/dev/null || true
done
python3 - "$corpus" "$root" <<'EOF'
import glob, json, os, shutil, sys
corpus, root = sys.argv[1], sys.argv[2]
def put(target, name, text):
    if os.path.isdir(os.path.join(corpus, target)):
        with open(os.path.join(corpus, target, name), "w") as f:
            f.write(text)
if os.path.isdir(os.path.join(corpus, "spec")):
    for case in glob.glob(os.path.join(root, "bench", "cases", "*.json")):
        shutil.copy(case, os.path.join(corpus, "spec", "case_" + os.path.basename(case)))
    put("spec", "big_deep_root.json", "[" * 100000 + "]" * 100000)
    put("spec", "big_deep_field.json", '{"type": "bezier", "reason": ' + "[" * 50000 + "]" * 50000 + ', "points": [[0,0],[1,1]]}')
    put("spec", "big_long_string.json", '{"type": "bezier", "points": [[0,0],[1,1]], "name": "' + "x" * 100000 + '"}')
    put("spec", "big_many_points.json", json.dumps({"type": "polyline", "points": [[i, (i * 7919) % 101] for i in range(4000)]}))
if os.path.isdir(os.path.join(corpus, "gate")):
    put("gate", "big_deep.json", '{"records": ' + "[" * 100000 + "]" * 100000 + ', "rules": []}')
    rules = [{"quantity": "length", "method": "gauss", "setting": "n=%d" % n, "max_error": 1e-3} for n in range(1, 400)]
    records = [{"case": "c", "group": "g", "quantity": "length", "method": "gauss", "setting": "n=%d" % n, "error": 1e-4}
               for n in range(1, 400)]
    put("gate", "big_many_rules.json", json.dumps({"records": records, "rules": rules}))
if os.path.isdir(os.path.join(corpus, "csv")):
    put("csv", "big_wide_header.csv", ",".join("c%d" % i for i in range(20000)) + "\n" + ",".join("1" for _ in range(20000)) + "\n")
    put("csv", "big_long_cell.csv", "u,x\n0," + "9" * 100000 + "\n")
if os.path.isdir(os.path.join(corpus, "svg")):
    ns = '<svg xmlns="http://www.w3.org/2000/svg">'
    put("svg", "big_deep.svg", ns + "<g>" * 20000 + '<path d="M0 0 L1 1"/>' + "</g>" * 20000 + "</svg>")
    put("svg", "big_many_paths.svg", ns + "".join('<path id="p%d" d="M%d 0 L1 1"/>' % (i, i) for i in range(2000)) + "</svg>")
    put("svg", "big_long_d.svg", ns + '<path d="M0 0' + "".join(" L%d %d" % (i, i % 7) for i in range(5000)) + '"/></svg>')
    put("svg", "big_long_path_data.txt", "d=M0 0" + "".join(" c1 2 3 4 5 %d" % (i % 9) for i in range(3000)))
EOF

# The first line that says what broke input $1 of target $t: the property, or a sanitizer's report.
what_broke() {
  local w
  w=$(cd "$build" && timeout 120 ./tests/fuzz/fuzz_$t "$1" -timeout=60 -rss_limit_mb=4096 2>&1 |
      grep -m1 -E 'property violated|ERROR: AddressSanitizer|ERROR: LeakSanitizer|runtime error|ERROR: libFuzzer|Sanitizer' ||
      true)
  printf '%s' "${w:-crash}"
}
# The class of a finding: the property's name, or the report without addresses and numbers.
class_of() { printf '%s' "$1" | sed -E 's/(property violated: [^:]*).*/\1/; s/0x[0-9a-f]+//g; s/[0-9]+//g'; }

# Minimizing costs up to a minute per class: runs of 120 s and more only (not CI's smoke).
minimize=$(( seconds >= 120 ? 1 : 0 ))
status=0
for t in "${targets[@]}"; do
  findings="$build/findings/$t"
  log="$build/fuzz_$t.log"
  rm -rf "$findings" "$build/fork_$t"
  mkdir -p "$findings"
  echo "fuzz.sh: $t for $seconds s (log $log)"
  # libFuzzer's own exit code is not the verdict in fork mode: the saved findings are.
  (cd "$build" && ./tests/fuzz/fuzz_$t "$corpus/$t" -dict="$root/tests/fuzz/$t.dict" -max_total_time="$seconds" \
      -max_len=200000 -use_value_profile=1 -timeout=60 -rss_limit_mb=4096 -fork=1 -ignore_crashes=1 -ignore_timeouts=1 -ignore_ooms=1 \
      -artifact_prefix="$findings/" -print_final_stats=1 -print_funcs=0 >"$log" 2>&1) || true
  shopt -s nullglob
  found=("$findings"/crash-* "$findings"/timeout-* "$findings"/oom-* "$findings"/leak-*)
  shopt -u nullglob
  if [[ ${#found[@]} -eq 0 ]]; then
    echo "fuzz.sh: $t: no finding ($(grep -oE '^#[0-9]+' "$log" | tail -1 | tr -d '#' || true) executions)"
    continue
  fi
  status=1
  echo "fuzz.sh: $t: ${#found[@]} finding(s) in $findings"
  classes=()
  declare -A minimized=()
  shown_count=0
  for f in "${found[@]}"; do
    kind=$(basename "$f" | cut -d- -f1)
    if [[ $shown_count -ge 20 ]]; then classes+=("$kind (not replayed: over 20 findings)"); continue; fi
    shown_count=$((shown_count + 1))
    what="$kind"
    [[ "$kind" == crash || "$kind" == leak ]] && what=$(what_broke "$f")
    class=$(class_of "$what")
    classes+=("$class")
    shown="$f"
    if [[ $minimize -eq 1 && "$kind" == crash && -z "${minimized[$class]:-}" ]]; then  # the first of each class
      minimized[$class]=1
      (cd "$build" && timeout 120 ./tests/fuzz/fuzz_$t "$f" -minimize_crash=1 -max_total_time=30 -timeout=60 \
          -exact_artifact_path="$f.min" >/dev/null 2>&1) || true
      # -minimize_crash keeps any crash: the smaller input counts only if it breaks the same property.
      if [[ -s "$f.min" && "$(class_of "$(what_broke "$f.min")")" == "$class" ]]; then shown="$f.min"; else rm -f "$f.min"; fi
    fi
    printf '  %s (%s bytes): %s\n' "$shown" "$(stat -c %s "$shown")" "$what"
  done
  echo "fuzz.sh: $t: findings by class:"
  printf '%s\n' "${classes[@]}" | sort | uniq -c | sed 's/^/  /'
done
# Runs of 120 s and more also check that the harness and the tool compile with clang (the fuzz
# build compiles neither; clang 14 once refused a structured binding captured by a lambda there, so
# a sanitizer build with clang failed): a syntax check, about 5 CPU-minutes.
if [[ $seconds -ge 120 ]]; then
  for f in "$root"/bench/harness/*.cpp "$root"/bench/tool/*.cpp; do
    [[ $(basename "$f") == common.cpp ]] && continue  # its version header is generated by the bench build
    if ! clang++ -std=c++20 -fsyntax-only -I"$root/lib/include" -I"$root/bench" -isystem /usr/include/eigen3 \
        -DCURVEBENCH_FLAGS='""' -DCURVEBENCH_CASES_DIR='""' "$f"; then
      echo "fuzz.sh: ${f#"$root"/} does not compile with clang" >&2
      status=1
    fi
  done
fi
exit $status
