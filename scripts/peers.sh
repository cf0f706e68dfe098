#!/usr/bin/env bash
# The optional peers: installs what they need (Debian packages by name, npm at exact versions, non-interactive)
# and runs their drivers on the case suite, writing reports/peers_<driver>.json, which
# scripts/report.py joins into REPORT.md's Peers section when present. The C++ peers (GSL,
# Boost.Math, Eigen) need nothing from here: the accuracy runner runs them in every
# scripts/bench.sh.
#   scripts/peers.sh               install, then run every driver (the full sweep's parameters)
#   scripts/peers.sh --quick       the quick sweep's parameters and tolerances
#   scripts/peers.sh --no-install  run only the drivers whose packages are already installed
#                                  (scripts/bench.sh calls it so)
#   scripts/peers.sh --check       install and run nothing: name each driver that would be skipped
#                                  and exit 1 if any would (scripts/bench.sh --publish asks first)
# Drivers: scripts/peers/scipy_driver.py (SciPy: CubicSpline, make_interp_spline, BSpline, quad);
# scripts/peers/easing_driver.mjs (Node: bezier-easing 3.2.0 and 2.1.0, @mapbox/unitbezier 1.0.0,
# @babylonjs/core's BezierCurve.Interpolate, pinned in scripts/peers/node/package.json and installed
# into build-peers/node), measured by
# scripts/peers/easing_results.py against a 50-digit truth of the CSS cubic-bezier definition;
# scripts/peers/chromium_driver.py (headless Chromium, Debian's chromium, major >= 112: Blink's CSS
# cubic-bezier() and steps() through the Web Animations API), measured the same way;
# scripts/peers/penner_driver.mjs (Node: d3-ease 3.0.2, pinned in the same package.json), measured
# by scripts/peers/penner_results.py against the Penner definitions d3 documents, at 50 digits,
# beside curvebench's Blender model of the same equations; real Blender (Debian's blender, major 3,
# about 770 MB, installed here like the others; run when `blender` is on PATH): scripts/peers/blender_channels.py turns
# the channel cases an F-curve can hold into a request for scripts/peers/blender_fcurves.py, run
# by `blender -b`, and compares Blender's values with curvebench's Blender model and the exact keys;
# scripts/peers/gltf_driver.mjs (Node: three 0.187.0, pinned in the same package.json) loads each
# glTF channel case as a GLB through three's GLTFLoader and evaluates the track's interpolant
# (float32 keys and results), measured by scripts/peers/gltf_results.py against the glTF 2.0
# sampler of the case's keys at 60 digits, beside curvebench's gltf model (`curvebench sample`).
# scripts/peers/shipped_browser_driver.py (headless Chromium and Debian's firefox-esr, whichever is
# installed): SVG getTotalLength() and getPointAtLength() of a <path> and of the basic shape, on the
# request of scripts/peers/shipped_request.py, measured by scripts/peers/shipped_results.py.
# scripts/peers/shipped_node_driver.mjs (Node: bezier-js, svg-path-properties, paper, svg-path-commander,
# three's curves and SVGLoader, canvaskit-wasm, @babylonjs/core, pinned in the same package.json): their
# arc lengths and points at length on the same request, measured by scripts/peers/shipped_results.py.
# scripts/peers/lottie_driver.py (lottie-web, pinned in the same package.json, played in headless Chromium):
# a layer's position along a spatial Bezier with eased timing, against s = L E(f) by `curvebench check --at-length`.
# The Node drivers share scripts/peers/node_driver.mjs (command line, sample times, ns per call).
# Each driver's values are measured by `curvebench check` against the 50-digit reference of the
# case's spec (scripts/peers/peer_results.py joins them), so the truth is never a double
# evaluation of curvebench's own code. The tool is $CURVEBENCH_TOOL, or build-bench's (built here
# with scripts/bench.sh's configuration when missing).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)

quick=0
install=1
check=0
for arg in "$@"; do
  case "$arg" in
    --quick) quick=1 ;;
    --no-install) install=0 ;;
    --check) check=1; install=0 ;;
    -h|--help) awk 'NR == 1 { next } /^#/ { sub(/^# ?/, ""); print; next } { exit }' "$0"; exit 0 ;;
    *) echo "peers.sh: unknown argument '$arg' (allowed: --quick, --no-install, --check)" >&2; exit 2 ;;
  esac
done

# Debian 12 (bookworm) packages by name, never by revision: Debian's security suite replaces a
# revision when it updates a package (Chromium 156.0.8078.79-1~deb12u1 stopped installing that
# way), so an exact pin breaks the next fresh install. Comparability comes from the record instead:
# every driver writes the version it ran (Chromium's, SciPy's, Blender's, Node's) into its result,
# and the report shows it. Where a driver depends on a major version it is checked below.
apt_packages=(python3-scipy python3-numpy python3-mpmath chromium chromium-common firefox-esr blender
              qtbase5-dev libocct-foundation-dev libocct-modeling-data-dev libocct-modeling-algorithms-dev
              lib2geom-dev python3-fonttools godot3-server)

installed() {  # package -> 0 when installed (any version)
  [[ "$(dpkg-query -W -f='${Status}' "$1" 2>/dev/null || true)" == "install ok installed" ]]
}

# package, least major version, why: fails (naming all three) when an installed package is older.
require_major() {
  local version major
  version=$(dpkg-query -W -f='${Version}' "$1" 2>/dev/null || true)
  [[ -n "$version" ]] || return 0  # not installed: its driver reports it missing
  major=${version#*:}
  major=${major%%[.+~-]*}
  if [[ ! "$major" =~ ^[0-9]+$ ]] || ((major < $2)); then
    echo "peers.sh: $1 $version is installed; its driver needs major version >= $2 ($3)" >&2
    exit 1
  fi
}

node_dir="$root/build-peers/node"
if [[ $install -eq 1 ]]; then
  # Debian's nodejs and npm when absent (their version is recorded in REPORT.md); mpmath: the truth.
  { command -v node && command -v npm; } >/dev/null || apt_packages+=(nodejs npm)
  missing=()
  for p in "${apt_packages[@]}"; do installed "$p" || missing+=("$p"); done
  if [[ ${#missing[@]} -gt 0 ]]; then
    echo "peers.sh: installing ${missing[*]}"
    sudo=""
    [[ $(id -u) -eq 0 ]] || sudo="sudo"
    export DEBIAN_FRONTEND=noninteractive
    $sudo apt-get update -qq
    $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
  fi
  # chromium_driver.py loads pages with --headless=new (Chromium 112 and later); scipy_driver.py
  # uses SciPy 1.x's integrate and interpolate interfaces.
  require_major chromium 112 "the driver runs --headless=new"
  require_major firefox-esr 60 "shipped_browser_driver.py runs --headless, privacy.reduceTimerPrecision off"
  require_major python3-scipy 1 "scipy_driver.py uses SciPy 1's interfaces"
  # blender_fcurves.py was written and its recordings made against Debian's Blender 3.4.
  require_major blender 3 "blender_fcurves.py uses Blender 3's F-curve API"
  require_major qtbase5-dev 5 "bench/peers/qt is written against Qt 5's QPainterPath and QEasingCurve"
  require_major libocct-foundation-dev 7 "bench/peers/occt uses OpenCASCADE 7's GCPnts"
  # Godot 3's Curve2D and Animation APIs (Godot 4 renamed them); the report says these are Godot 3.2's.
  require_major godot3-server 3 "scripts/peers/godot_driver.gd is GDScript for Godot 3"
  for p in "${apt_packages[@]}"; do
    echo "peers.sh: $p $(dpkg-query -W -f='${Version}' "$p" 2>/dev/null || echo 'not installed')"
  done
  # The npm packages at the exact versions of package.json (no ranges), without install scripts.
  mkdir -p "$node_dir"
  cp "$root/scripts/peers/node/package.json" "$node_dir/package.json"
  (cd "$node_dir" && npm install --no-audit --no-fund --ignore-scripts --loglevel=error >/dev/null)
fi

tool=${CURVEBENCH_TOOL:-$root/build-bench/bench/curvebench}
if [[ $check -eq 0 && ! -x "$tool" ]]; then
  bash "$root/scripts/setup.sh"
  export CCACHE_BASEDIR="$root"
  build="$root/build-bench"
  # scripts/bench.sh's configuration, so that its build reuses this one.
  cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_FLAGS_RELEASE="-O3 -march=native -fno-math-errno -DNDEBUG" \
        -DCURVEBENCH_WERROR=OFF -DCURVEBENCH_BUILD_TESTS=OFF -DCURVEBENCH_BUILD_BENCH=ON >/dev/null
  echo "peers.sh: building the curvebench tool"
  cmake --build "$build" --parallel "$(nproc)" --target curvebench_tool >/dev/null
  tool="$build/bench/curvebench"
fi

reports="$root/reports"
[[ $check -eq 1 ]] || mkdir -p "$reports"
quick_args=()
[[ $quick -eq 1 ]] && quick_args=(--quick)

# run_NAME: driver NAME, writing reports/peers_NAME.json; `optional` (below) calls it with $work a
# fresh reports/peers/NAME.
run_scipy() {
  /usr/bin/python3 "$root/scripts/peers/scipy_driver.py" --cases "$root/bench/cases" --out "$work" "${quick_args[@]}"
  # Measure every CSV the driver wrote against the 50-digit reference of its case.
  /usr/bin/python3 - "$work/scipy_driver.json" "$tool" "$root/bench/cases" <<'EOF'
import json, os, subprocess, sys
driver_path, tool, cases = sys.argv[1:4]
work = os.path.dirname(driver_path)
with open(driver_path, encoding="utf-8") as f:
    driver = json.load(f)
for run in driver["runs"]:
    if not run.get("csv"):
        continue
    csv = os.path.join(work, run["csv"])
    option = {"values": "--values", "lengths": "--lengths", "inverse": "--inverse"}[run["kind"]]
    with open(csv + ".check.json", "w", encoding="utf-8") as out:
        subprocess.run([tool, "check", os.path.join(cases, run["case"] + ".json"), option, csv,
                        "--name", run["peer"], "--json", "--quiet"], stdout=out, check=True)
EOF
  /usr/bin/python3 "$root/scripts/peers/peer_results.py" --driver "$work/scipy_driver.json" \
                   --out "$reports/peers_scipy.json"
}

# node_driver DRIVER ARGS...: scripts/peers/DRIVER.mjs run beside the pinned packages
# (build-peers/node) with the module the Node drivers share, at this run's parameters.
node_driver() {
  local driver=$1
  shift
  cp "$root/scripts/peers/$driver.mjs" "$root/scripts/peers/node_driver.mjs" "$node_dir/"
  (cd "$node_dir" && node "$driver.mjs" "$@" "${quick_args[@]}")
}

run_easing() {
  mkdir -p "$work/curvebench"
  node_driver easing_driver --cases "$root/bench/cases" --out "$work/easing_driver.json"
  # curvebench's own CSS evaluation at the driver's times: the case with the exact time solver
  # (the peers' counterpart) and as written (the tool's table_newton model).
  /usr/bin/python3 "$root/scripts/peers/sample_css_runs.py" --driver "$work/easing_driver.json" \
                   --cases "$root/bench/cases" --tool "$tool" --out "$work/curvebench"
  /usr/bin/python3 "$root/scripts/peers/easing_results.py" --driver "$work/easing_driver.json" \
                   --cases "$root/bench/cases" --curvebench-dir "$work/curvebench" --out "$reports/peers_easing.json"
}

run_penner() {
  node_driver penner_driver --out "$work/penner_driver.json"
  /usr/bin/python3 "$root/scripts/peers/penner_results.py" --driver "$work/penner_driver.json" \
                   --tool "$tool" --work "$work/blender_model" --out "$reports/peers_penner.json"
}

run_blender() {
  /usr/bin/python3 "$root/scripts/peers/blender_channels.py" request --cases "$root/bench/cases" \
                   --out "$work/request.json" --model-dir "$work/model" "${quick_args[@]}"
  blender -b --factory-startup --python "$root/scripts/peers/blender_fcurves.py" -- \
          "$work/request.json" "$work/blender.json" >"$work/blender.log" 2>&1 ||
    { echo "peers.sh: Blender failed; see $work/blender.log" >&2; return 1; }
  local spec
  for spec in "$work"/model/*.json; do
    # The Blender model as Blender evaluates it (float; without --as-tool: the truth of its keys).
    "$tool" sample "$spec" --at-file "${spec%.json}.times" --derivatives 0 --quiet --as-tool >"${spec%.json}.csv"
  done
  /usr/bin/python3 "$root/scripts/peers/blender_channels.py" results --cases "$root/bench/cases" \
                   --blender "$work/blender.json" --model-dir "$work/model" --out "$reports/peers_blender.json"
}

run_three() {
  node_driver gltf_driver --cases "$root/bench/cases" --out "$work/three_driver.json"
  /usr/bin/python3 "$root/scripts/peers/gltf_results.py" --driver "$work/three_driver.json" --cases "$root/bench/cases" \
                   --tool "$tool" --work "$work/model" --out "$reports/peers_three.json"
}

# Arc length and point at length in npm libraries, on shipped_request.py's request.
run_shipped_node() {
  /usr/bin/python3 "$root/scripts/peers/shipped_request.py" --tool "$tool" --cases "$root/bench/cases" --out "$work/request.json"
  node_driver shipped_node_driver --request "$work/request.json" --out "$work/shipped_node_driver.json"
  /usr/bin/python3 "$root/scripts/peers/shipped_results.py" --driver "$work/shipped_node_driver.json" \
                   --request "$work/request.json" --cases "$root/bench/cases" --tool "$tool" --work "$work/check" \
                   --out "$reports/peers_shipped_node.json"
}

run_chromium() {
  mkdir -p "$work/curvebench"
  /usr/bin/python3 "$root/scripts/peers/chromium_driver.py" --cases "$root/bench/cases" \
                   --out "$work/chromium_driver.json" --work "$work/page" "${quick_args[@]}"
  rm -rf "$work/page/profile"  # the browser profile of the run: nothing to keep
  /usr/bin/python3 "$root/scripts/peers/sample_css_runs.py" --driver "$work/chromium_driver.json" \
                   --cases "$root/bench/cases" --tool "$tool" --out "$work/curvebench"
  /usr/bin/python3 "$root/scripts/peers/easing_results.py" --driver "$work/chromium_driver.json" \
                   --cases "$root/bench/cases" --curvebench-dir "$work/curvebench" --out "$reports/peers_chromium.json"
}

# SVG lengths in the browsers that are installed (the driver lists a missing one's runs as skipped).
run_shipped_browser() {
  /usr/bin/python3 "$root/scripts/peers/shipped_request.py" --tool "$tool" --cases "$root/bench/cases" --out "$work/request.json"
  /usr/bin/python3 "$root/scripts/peers/shipped_browser_driver.py" --request "$work/request.json" \
                   --out "$work/shipped_browser_driver.json" --work "$work/browsers"
  /usr/bin/python3 "$root/scripts/peers/shipped_results.py" --driver "$work/shipped_browser_driver.json" \
                   --request "$work/request.json" --cases "$root/bench/cases" --tool "$tool" --work "$work/check" \
                   --out "$reports/peers_shipped_browser.json"
}

# lottie-web's layer position on a spatial Bezier with eased timing, in headless Chromium.
run_lottie() {
  /usr/bin/python3 "$root/scripts/peers/lottie_driver.py" --lottie "$node_dir/node_modules/lottie-web" \
                   --tool "$tool" --work "$work" --out "$reports/peers_lottie.json"
}

# The native peers: C++ drivers under bench/peers/, built once into build-peers/native
# with the CMake switch of each whose Debian package is installed (the project's compiler flags and
# ccache). native_tool NAME prints the program's path when it is built.
native_dir="$root/build-peers/native"
native_built=0
build_native() {
  [[ $native_built -eq 0 ]] || return 0
  native_built=1
  local options=() targets=() t
  installed qtbase5-dev && options+=(-DCURVEBENCH_PEER_QT=ON) && targets+=(curvebench_peer_qt)
  installed libocct-modeling-algorithms-dev && options+=(-DCURVEBENCH_PEER_OCCT=ON) && targets+=(curvebench_peer_occt)
  installed lib2geom-dev && options+=(-DCURVEBENCH_PEER_2GEOM=ON) && targets+=(curvebench_peer_2geom)
  [[ ${#options[@]} -gt 0 ]] || return 0
  echo "peers.sh: building the native peer drivers (${options[*]})" >&2
  mkdir -p "$native_dir"
  # A driver that does not build is reported (its peer then says it is skipped), not fatal.
  if cmake -S "$root" -B "$native_dir" -DCMAKE_BUILD_TYPE=Release -DCURVEBENCH_BUILD_TESTS=OFF \
           -DCURVEBENCH_BUILD_BENCH=OFF "${options[@]}" >"$native_dir/build.log" 2>&1; then
    for t in "${targets[@]}"; do
      cmake --build "$native_dir" --parallel "$(nproc)" --target "$t" >>"$native_dir/build.log" 2>&1 ||
        echo "peers.sh: $t did not build; see $native_dir/build.log" >&2
    done
  else
    echo "peers.sh: the native peer drivers did not configure; see $native_dir/build.log" >&2
  fi
}
[[ $check -eq 1 ]] || build_native
native_tool() {
  build_native
  local exe="$native_dir/bench/peers/$1/curvebench_peer_${1/lib2geom/2geom}"
  [[ -x "$exe" ]] && echo "$exe"
}

# shipped_native NAME DRIVER ARGS...: the shipped request answered by DRIVER ARGS... --request REQ
# --out OUT and measured into reports/peers_shipped_NAME.json.
shipped_run() {
  local name=$1
  shift
  /usr/bin/python3 "$root/scripts/peers/shipped_request.py" --tool "$tool" --cases "$root/bench/cases" --out "$work/request.json"
  "$@" --request "$work/request.json" --out "$work/${name}_driver.json" "${quick_args[@]}"
  /usr/bin/python3 "$root/scripts/peers/shipped_results.py" --driver "$work/${name}_driver.json" \
                   --request "$work/request.json" --cases "$root/bench/cases" --tool "$tool" --work "$work/check" \
                   --out "$reports/peers_shipped_$name.json"
}

# easing_run NAME DRIVER ARGS...: the CSS cubic-bezier cases evaluated by DRIVER ARGS... --cases DIR
# --out OUT, measured with curvebench's own evaluation at the same times (the channel solver table
# of the Peers section) into reports/peers_NAME.json.
easing_run() {
  local name=$1
  shift
  "$@" --cases "$root/bench/cases" --out "$work/${name}_easing.json" "${quick_args[@]}"
  mkdir -p "$work/curvebench"
  /usr/bin/python3 "$root/scripts/peers/sample_css_runs.py" --driver "$work/${name}_easing.json" \
                   --cases "$root/bench/cases" --tool "$tool" --out "$work/curvebench"
  /usr/bin/python3 "$root/scripts/peers/easing_results.py" --driver "$work/${name}_easing.json" \
                   --cases "$root/bench/cases" --curvebench-dir "$work/curvebench" --out "$reports/peers_$name.json"
}

# Qt 5: QPainterPath on the shipped request, QEasingCurve on the CSS cases (the channel
# solver table, beside the easing peers).
run_qt() {
  local exe spec specs=()
  exe=$(native_tool qt)
  shipped_run qt "$exe" paths
  easing_run qt "$exe" easing
  # QEasingCurve's TCB spline beside curvebench's Kochanek-Bartels through the same keys: the
  # driver's own easing specs (no bench case is a uniform Kochanek-Bartels easing).
  for spec in "$root"/bench/peers/qt/specs/*.json; do specs+=(--spec "$spec"); done
  "$exe" tcb --cases "$root/bench/cases" "${specs[@]}" --out "$work/qt_tcb.json" "${quick_args[@]}"
  /usr/bin/python3 "$root/scripts/peers/tcb_results.py" --driver "$work/qt_tcb.json" --cases "$root/bench/cases" \
                   "${specs[@]}" --tool "$tool" --out "$reports/peers_qt_tcb.json"
}

# OpenCASCADE's GCPnts and lib2geom's lengths on the shipped request.
run_occt() { shipped_run occt "$(native_tool occt)"; }
run_lib2geom() { shipped_run lib2geom "$(native_tool lib2geom)"; }
# fontTools' two cubic length functions, Blender's Spline.calc_length and Follow Path, Godot 3's
# Curve2D on the same request; Godot's bezier tracks in the channel solver table.
run_fonttools() { shipped_run fonttools /usr/bin/python3 "$root/scripts/peers/fonttools_driver.py"; }
run_blender_length() { shipped_run blender_length /usr/bin/python3 "$root/scripts/peers/blender_length_driver.py"; }
run_godot() {
  shipped_run godot /usr/bin/python3 "$root/scripts/peers/godot_driver.py"
  easing_run godot /usr/bin/python3 "$root/scripts/peers/godot_driver.py" easing
}

# Whether the drivers' requirements are there: a Python module; a pinned npm package in
# build-peers/node (with node and mpmath, the truth of every Node peer); a program on PATH (with mpmath).
python_has() { /usr/bin/python3 -c "import $1" 2>/dev/null; }
node_has() { command -v node >/dev/null && [[ -d "$node_dir/node_modules/$1" ]] && python_has mpmath; }
on_path() { command -v "$1" >/dev/null && python_has mpmath; }
node_version=$(node --version 2>/dev/null || echo "not installed")

ran=0
absent=0
# optional NAME LABEL MISSING CHECK...: removes an earlier reports/peers_NAME.json (no stale results
# from another run, whatever happens next); then, when the command CHECK... succeeds, runs run_NAME
# with $work a fresh reports/peers/NAME and prints LABEL, otherwise prints MISSING. With --check it
# only prints MISSING (and counts it) where CHECK... fails.
optional() {
  local name=$1 label=$2 missing=$3
  shift 3
  if [[ $check -eq 1 ]]; then
    "$@" || { echo "peers.sh: $name: $missing" >&2; absent=$((absent + 1)); }
    return 0
  fi
  rm -f "$reports/peers_$name".json "$reports/peers_$name"_*.json "$reports/peers_shipped_$name.json"
  if "$@"; then
    echo "peers.sh: $label"
    work="$reports/peers/$name"
    rm -rf "$work"
    mkdir -p "$work"
    "run_$name"
    ran=$((ran + 1))
  else
    echo "peers.sh: $missing" >&2
  fi
}
optional scipy "SciPy" "SciPy not installed (python3-scipy); skipped" python_has "scipy, numpy"
optional easing "easing (Node $node_version)" \
  "the easing peers are not installed (node, build-peers/node, python3-mpmath); skipped" node_has bezier-easing-3
optional penner "d3-ease (Node $node_version)" \
  "d3-ease is not installed (node, build-peers/node, python3-mpmath); skipped" node_has d3-ease
optional three "three.js glTF interpolants (Node $node_version)" \
  "three is not installed (node, build-peers/node, python3-mpmath); skipped" node_has three
optional shipped_node "arc length in npm libraries (Node $node_version)" \
  "the arc-length npm peers are not installed (node, build-peers/node, python3-mpmath); skipped" node_has canvaskit-wasm
optional blender "real Blender ($(blender --version 2>/dev/null | head -n 1))" \
  "blender is not on PATH (or python3-mpmath is missing); the real-Blender comparison is not run" on_path blender
optional chromium "$(chromium --version 2>/dev/null | head -n 1)" \
  "Chromium is not installed (chromium, python3-mpmath); skipped" on_path chromium
browser_on_path() { command -v chromium >/dev/null || command -v firefox-esr >/dev/null; }
optional shipped_browser "SVG lengths in $(chromium --version 2>/dev/null | head -n 1) $(firefox-esr --version 2>/dev/null | head -n 1)" \
  "neither chromium nor firefox-esr is installed; the browsers' SVG lengths are skipped" browser_on_path
# lottie's truth is the tool's (its 50-digit CSS easing and Bezier): no node, no mpmath.
lottie_ready() { command -v chromium >/dev/null && [[ -f "$node_dir/node_modules/lottie-web/build/player/lottie_svg.min.js" ]]; }
optional lottie "lottie-web in $(chromium --version 2>/dev/null | head -n 1)" \
  "chromium or lottie-web (build-peers/node) is not installed; lottie's motion is skipped" lottie_ready
# native_ready PACKAGE NAME: the package and mpmath installed, and (unless --check) its driver built.
native_ready() {
  installed "$1" && python_has mpmath || return 1
  [[ $check -eq 1 ]] || [[ -n "$(native_tool "$2")" ]]
}
optional qt "Qt $(dpkg-query -W -f='${Version}' qtbase5-dev 2>/dev/null) (QPainterPath, QEasingCurve)" \
  "Qt 5 is not installed (qtbase5-dev, python3-mpmath) or its driver did not build; skipped" native_ready qtbase5-dev qt
optional occt "OpenCASCADE $(dpkg-query -W -f='${Version}' libocct-foundation-dev 2>/dev/null) (GCPnts)" \
  "OpenCASCADE is not installed (libocct-*-dev, python3-mpmath) or its driver did not build; skipped" \
  native_ready libocct-modeling-algorithms-dev occt
optional lib2geom "lib2geom $(dpkg-query -W -f='${Version}' lib2geom-dev 2>/dev/null)" \
  "lib2geom is not installed (lib2geom-dev, python3-mpmath) or its driver did not build; skipped" \
  native_ready lib2geom-dev lib2geom
optional fonttools "fontTools $(dpkg-query -W -f='${Version}' python3-fonttools 2>/dev/null)" \
  "fontTools is not installed (python3-fonttools, python3-mpmath); skipped" python_has "fontTools.misc.bezierTools, mpmath"
optional blender_length "Blender's calc_length and Follow Path ($(blender --version 2>/dev/null | head -n 1))" \
  "blender is not on PATH (or python3-mpmath is missing); Blender's curve lengths are skipped" on_path blender
optional godot "Godot $(dpkg-query -W -f='${Version}' godot3-server 2>/dev/null) (Curve2D, bezier tracks)" \
  "godot3-server is not installed (or python3-mpmath is missing); Godot is skipped" on_path godot3-server
if [[ $check -eq 1 ]]; then
  [[ $absent -eq 0 ]] && echo "peers.sh: every optional peer is installed"
  [[ $absent -eq 0 ]]
  exit
fi
echo "peers.sh: $ran optional peer driver(s) ran; results in $reports/peers_*.json"
