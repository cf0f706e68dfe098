#!/usr/bin/env bash
# Installs the Debian packages curvebench needs, only those that are missing; non-interactive,
# idempotent, and quiet when everything is already present.
#   scripts/setup.sh [PACKAGE...]   the packages given are needed too (fuzz.sh: clang, libFuzzer)
set -euo pipefail

packages=(g++ cmake make ninja-build ccache libeigen3-dev libboost-dev libboost-math-dev libbenchmark-dev libgtest-dev libgmock-dev
          nlohmann-json3-dev libcli11-dev libgsl-dev libpugixml-dev python3-matplotlib python3-numpy "$@")

missing=()
for p in "${packages[@]}"; do
  status=$(dpkg-query -W -f='${Status}' "$p" 2>/dev/null || true)
  [[ "$status" == "install ok installed" ]] || missing+=("$p")
done
[[ ${#missing[@]} -eq 0 ]] && exit 0

echo "setup: installing ${missing[*]}"
sudo=""
[[ $(id -u) -eq 0 ]] || sudo="sudo"
export DEBIAN_FRONTEND=noninteractive
$sudo apt-get update -qq
$sudo apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
