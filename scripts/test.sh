#!/usr/bin/env bash
# The test command: set-up, configure, build and run every test with ctest.
#   scripts/test.sh             tests (warnings are errors), benchmarks and tool compiled too
#   scripts/test.sh --sanitize  the same tests under AddressSanitizer + UndefinedBehaviorSanitizer
#   scripts/test.sh --sanitize --light   CI's phase: under the sanitizers, the tests of the code that
#                               reads users' input (tests/CMakeLists.txt: curvebench_sanitizer_ci)
# Exits non-zero on any failure.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)

sanitize=0
light=0
for arg in "$@"; do
  case "$arg" in
    --sanitize) sanitize=1 ;;
    --light) light=1 ;;
    -h|--help) sed -n '2,7p' "$0"; exit 0 ;;
    *) echo "test.sh: unknown argument '$arg' (allowed: --sanitize, --light)" >&2; exit 2 ;;
  esac
done
if [[ $light -eq 1 && $sanitize -eq 0 ]]; then
  echo "test.sh: --light goes with --sanitize" >&2
  exit 2
fi

# Debian's Chromium (by name: a security update replaces its revision) for the test of REPORT.html in
# a headless browser (tests/python/check_report_html.py); the sanitizer build does not run it.
extra=()
[[ $sanitize -eq 1 ]] || extra=(chromium fonts-dejavu-core)
bash "$root/scripts/setup.sh" "${extra[@]}"
# ccache keys on absolute paths unless told the checkout's root: with it, a fresh clone anywhere
# (CI's) reuses the objects of an earlier build of the same sources.
export CCACHE_BASEDIR="$root"
jobs=$(nproc)
# A new build tree uses Ninja (scripts/setup.sh installs it): it compiles a target's sources while
# the libraries it links are still building, where Make's generator waits for them; measured on CI's
# cold build with 2 cores. A tree configured earlier keeps its generator (CMake refuses a change).
generator=()
configure_generator() { [[ -f "$1/CMakeCache.txt" ]] || generator=(-G Ninja); }

if [[ $sanitize -eq 1 ]]; then
  build="$root/build-sanitize"
  configure_generator "$build"
  # -Og -g1 (line tables, enough for the sanitizers' stack traces): measured on test_motion.cpp,
  # 46 s to compile against 145 s with -O1 -g (full debug info of the 50-digit templates made the
  # assembler alone take 1.8 GB), and test_inversion runs as fast (53 s against 56 s; -O0 took 340 s).
  cmake -S "$root" -B "$build" "${generator[@]}" -DCMAKE_BUILD_TYPE=Debug -DCMAKE_CXX_FLAGS_DEBUG="-Og -g1" \
        -DCURVEBENCH_SANITIZE=ON -DCURVEBENCH_BUILD_BENCH=OFF -DCURVEBENCH_BUILD_TESTS=ON -DCURVEBENCH_WERROR=ON >/dev/null
  export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1
  export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
else
  build="$root/build-test"
  configure_generator "$build"
  # -O2 without NDEBUG: optimized enough for 50-digit references, assertions (Eigen's too) kept.
  cmake -S "$root" -B "$build" "${generator[@]}" -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_FLAGS_RELEASE="-O2" \
        -DCURVEBENCH_BUILD_BENCH=ON -DCURVEBENCH_BUILD_TESTS=ON -DCURVEBENCH_WERROR=ON >/dev/null
fi

if [[ $light -eq 1 ]]; then
  cmake --build "$build" --parallel "$jobs" --target curvebench_sanitizer_light
  ctest --test-dir "$build" --output-on-failure --parallel "$jobs" --label-regex sanitizer_ci
else
  cmake --build "$build" --parallel "$jobs"
  ctest --test-dir "$build" --output-on-failure --parallel "$jobs"
fi
