#!/usr/bin/env bash
# Formatting and lint, as CI checks them (a phase of .ci/run):
#   scripts/lint.sh          check: clang-format (Debian's clang-format-14, .clang-format) on every
#                            tracked C++ file, and flake8 (.flake8) on every tracked Python file
#   scripts/lint.sh --fix    rewrite the C++ files in place with the same clang-format
# Exits 1 naming the files that differ; installs the two tools when missing (scripts/setup.sh).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
cd "$root"
fix=0
for arg in "$@"; do
  case "$arg" in
    --fix) fix=1 ;;
    -h|--help) sed -n '2,6p' "$0"; exit 0 ;;
    *) echo "lint.sh: unknown argument '$arg' (allowed: --fix)" >&2; exit 2 ;;
  esac
done
bash scripts/setup.sh clang-format-14 flake8
# One formatter version for everyone: another major version formats some constructs differently.
format=clang-format-14
"$format" --version | grep -q "version 14\." || { echo "lint.sh: $format is not version 14" >&2; exit 1; }
mapfile -t cxx < <(git ls-files '*.cpp' '*.hpp' '*.h')
mapfile -t py < <(git ls-files '*.py')
if [[ $fix -eq 1 ]]; then
  "$format" -i "${cxx[@]}"
  exit 0
fi
status=0
if ! "$format" --dry-run --Werror "${cxx[@]}" 2> /tmp/curvebench_format.$$; then
  echo "lint.sh: these files differ from .clang-format (scripts/lint.sh --fix rewrites them):" >&2
  grep -o '^[^:]*:[0-9]*:[0-9]*: error' /tmp/curvebench_format.$$ | cut -d: -f1 | sort -u | sed 's/^/  /' >&2
  status=1
fi
rm -f /tmp/curvebench_format.$$
flake8 "${py[@]}" || { echo "lint.sh: flake8 found the problems above" >&2; status=1; }
[[ $status -eq 0 ]] && echo "lint.sh: ${#cxx[@]} C++ files formatted, ${#py[@]} Python files clean"
exit $status
