#!/usr/bin/env bash
# Builds OpenUSD's Ts library (the `ts` target and what it links: arch, tf, gf, pegtl, js, trace,
# work, plug, vt) and the recorder scripts/peers/usd_ts_record.cpp, in /tmp/usd, for
# tests/data/recorded/usd_ts_splines.json. Nothing is downloaded: OpenUSD's source comes from a local git
# clone (USD_GIT_DIR, a bare or ordinary git directory holding commit USD_COMMIT) and TBB from
# Debian (apt-get install libtbb-dev). Only pxr/base, pxr/external and cmake/ are extracted; the
# top-level CMakeLists.txt's `extras` and pxr/CMakeLists.txt's `usd` subdirectories, which are not
# extracted, are skipped by editing the extracted copy. About 40 CPU-minutes on 2 cores.
#   USD_GIT_DIR=/path/to/OpenUSD/.git bash scripts/peers/usd_ts_build.sh
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
: "${USD_GIT_DIR:?set USD_GIT_DIR to a local git clone of PixarAnimationStudios/OpenUSD}"
commit=${USD_COMMIT:-899c19efdc20786bc6cfc2c8202b8d32c3a5c794}
work=${USD_WORK:-/tmp/usd}
src=$work/src
build=$work/build
if [[ ! -f $src/pxr/base/ts/spline.h ]]; then
  mkdir -p "$src"
  for p in cmake pxr/base pxr/external; do
    git --git-dir="$USD_GIT_DIR" archive --prefix="$p/" "$commit:$p" | tar -x -C "$src"
  done
  for f in CMakeLists.txt pxr/CMakeLists.txt pxr/pxr.h.in pxr/pxrConfig.cmake.in LICENSE.txt NOTICE.txt; do
    git --git-dir="$USD_GIT_DIR" show "$commit:$f" > "$src/$f"
  done
  sed -i 's|^add_subdirectory(extras)|#add_subdirectory(extras)|' "$src/CMakeLists.txt"
  sed -i 's|^add_subdirectory(usd)$|if (EXISTS "${CMAKE_CURRENT_SOURCE_DIR}/usd")\n  add_subdirectory(usd)\nendif()|' \
    "$src/pxr/CMakeLists.txt"
fi
cmake -S "$src" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DPXR_ENABLE_PYTHON_SUPPORT=OFF \
  -DPXR_BUILD_IMAGING=OFF -DPXR_BUILD_USD_IMAGING=OFF -DPXR_BUILD_TESTS=OFF -DPXR_BUILD_EXAMPLES=OFF \
  -DPXR_BUILD_TUTORIALS=OFF -DPXR_BUILD_USD_TOOLS=OFF -DPXR_ENABLE_GL_SUPPORT=OFF -DPXR_BUILD_USDVIEW=OFF \
  -DPXR_ENABLE_PRECOMPILED_HEADERS=OFF -DPXR_BUILD_DOCUMENTATION=OFF >/dev/null
nice -n 19 ninja -C "$build" -j2 ts
libs=()
rpath=()
for lib in ts vt gf tf trace js arch; do
  libs+=("-L$build/pxr/base/$lib" "-lusd_$lib")
  rpath+=("$build/pxr/base/$lib")
done
nice -n 19 g++ -std=c++17 -O2 -I"$build/include" -I"$src" \
  "$root/scripts/peers/usd_ts_record.cpp" -o "$work/usd_ts_record" "${libs[@]}" \
  -Wl,-rpath,"$(IFS=:; echo "${rpath[*]}")" -ltbb -lpthread -ldl
echo "$work/usd_ts_record"
