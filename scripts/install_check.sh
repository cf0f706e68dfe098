#!/usr/bin/env bash
# The documented install, as a user runs it (a phase of .ci/run):
#   scripts/install_check.sh   runs the install block of docs/checking.md (between its
#                              `<!-- install:begin` and `<!-- install:end` markers, read by
#                              scripts/install_doc.py) as written, in a fresh copy of the checkout's
#                              HEAD (git archive: uncommitted changes are not in it) under
#                              build-install-check/, with <prefix> replaced by a scratch prefix there;
#                              then checks that the installed tool lists the installed cases, and
#                              builds and runs tests/consumer/ against the installed package.
#                              Fails when the install's build prints a compiler warning.
# ccache keeps a second run cheap: the copy is always at the same path, which is its CCACHE_BASEDIR.
# The build's log is build-install-check/install.log. Exits non-zero on any failure.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
for arg in "$@"; do
  case "$arg" in
    -h|--help) awk 'NR == 1 { next } /^#/ { sub(/^# ?/, ""); print; next } { exit }' "$0"; exit 0 ;;
    *) echo "install_check.sh: unknown argument '$arg' (it takes none)" >&2; exit 2 ;;
  esac
done
bash "$root/scripts/setup.sh"

work="$root/build-install-check"
src="$work/src"
prefix="$work/prefix"
log="$work/install.log"
rm -rf "$work"
mkdir -p "$src" "$work/run"
git -C "$root" archive --format=tar HEAD | tar -x -C "$src"
git -C "$root" diff --quiet HEAD -- || echo "install_check.sh: note: uncommitted changes are not in the copy (HEAD only)"

# The environment, not the commands: ccache for every compilation (the project's CMakeLists.txt
# uses it by itself; CMAKE_CXX_COMPILER_LAUNCHER is CMake's default for the consumer), with paths
# relative to the copy; CMAKE_BUILD_PARALLEL_LEVEL gives `cmake --build` the machine's cores (the
# default generator, Make, builds one file at a time without it).
export CCACHE_BASEDIR="$src"
export CMAKE_CXX_COMPILER_LAUNCHER=ccache
export CMAKE_BUILD_PARALLEL_LEVEL
CMAKE_BUILD_PARALLEL_LEVEL=$(nproc)

start=$SECONDS
python3 "$src/scripts/install_doc.py" "$src/docs/checking.md" --prefix "$prefix" > "$work/install.sh"
echo "install_check.sh: running docs/checking.md's install block in $src:"
grep -v '^set ' "$work/install.sh" | sed 's/^/  /'
if ! (cd "$src" && bash "$work/install.sh") > "$log" 2>&1; then
  echo "install_check.sh: the documented install failed after $((SECONDS - start)) s; the end of $log:" >&2
  tail -n 60 "$log" >&2
  exit 1
fi
# Without -Werror the build goes on past a warning; CI still wants none (the -O3 build is the one
# users get, and GCC 12 warns there where scripts/test.sh's -O2 build does not).
if grep -q 'warning:' "$log"; then
  echo "install_check.sh: the documented install built, but the compiler warned ($log):" >&2
  grep -B12 'warning:' "$log" | grep -E 'warning:|inlined from .*at (\.\./)+(lib|bench|tests)/|^(\.\./)+(lib|bench|tests)/' >&2
  exit 1
fi
echo "install_check.sh: documented install done in $((SECONDS - start)) s, no compiler warning"

# The installed tool finds its cases beside itself, from a directory with no bench/ or reports/.
cases=$(cd "$work/run" && "$prefix/bin/curvebench" list cases)
if ! grep -q -F "$prefix/share/curvebench/cases" <<<"$cases" || ! grep -q "arch_cubic_bezier" <<<"$cases"; then
  echo "install_check.sh: the installed curvebench did not list the installed cases ($prefix/share/curvebench/cases):" >&2
  echo "$cases" >&2
  exit 1
fi
echo "install_check.sh: $prefix/bin/curvebench lists $prefix/share/curvebench/cases"

# A downstream project against the installed package (as the package_consumer test does with the
# build tree's install).
step=$SECONDS
cmake -S "$src/tests/consumer" -B "$work/consumer" -DCMAKE_PREFIX_PATH="$prefix" >> "$log" 2>&1 \
  || { echo "install_check.sh: configuring tests/consumer against $prefix failed; the end of $log:" >&2; tail -n 40 "$log" >&2; exit 1; }
cmake --build "$work/consumer" >> "$log" 2>&1 \
  || { echo "install_check.sh: building tests/consumer against $prefix failed; the end of $log:" >&2; tail -n 40 "$log" >&2; exit 1; }
"$work/consumer/consumer"
echo "install_check.sh: tests/consumer built against $prefix and ran in $((SECONDS - step)) s; total $((SECONDS - start)) s"
