#!/bin/bash
# The thesis preset's per-pass table on this machine's GPU, beside the thesis's own (McLaughlin,
# GTX 560 Ti): builds ispm (Release, no tests) into BUILD_DIR, shows the GL context it gets
# (hardware EGL device first; ISPM_GL=egl-device insists on one), runs `ispm bench --preset
# thesis` (box city, 1280x1024, 50,000 photons, 3 bounces; timer queries on a GPU, read frames
# later without stalling) and prints the per-pass medians with the thesis's figures beside the
# passes they correspond to. On a software renderer it says so: its times are CPU-clock times.
# Usage: tools/gpu-bench.sh [BUILD_DIR] [BENCH-ARGS...]   (default build-gpu; e.g. --frames 50)
# ISPM_BIN=path runs that binary instead of building one (a GPU machine without the build's
# dependencies; BUILD_DIR is then ignored).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-build-gpu}
[ $# -gt 0 ] && shift
if [ -n "${ISPM_BIN:-}" ]; then
    ispm=$ISPM_BIN
else
    # A new build folder is configured Release without tests; an existing one keeps its options.
    if [ -f "$build/CMakeCache.txt" ]; then
        cmake -S "$root" -B "$build" > /dev/null
    else
        cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release -DISPM_BUILD_TESTS=OFF > /dev/null
    fi
    cmake --build "$build" -j"$(nproc)" --target ispm > /dev/null
    ispm="$build/ispm"
fi
"$ispm" info | sed -n '1,4p'
json=$(mktemp)
trap 'rm -f "$json"' EXIT
# 30 timed frames after 5 untimed ones unless the arguments say otherwise.
defaults=()
[[ " $* " == *" --frames "* ]] || defaults+=(--frames 30)
[[ " $* " == *" --warmup "* ]] || defaults+=(--warmup 5)
"$ispm" bench --preset thesis "${defaults[@]}" "$@" --json > "$json"
python3 - "$json" <<'PY'
import json, sys

d = json.load(open(sys.argv[1]))
ms = {p["name"]: p["median_ms"] for p in d["passes"]}
# The thesis's frame on a GTX 560 Ti (section 6.2): G-buffers 3 ms, bounce buffer 0.1 ms,
# tracing 10-30 ms, 40-50 ms a frame. Its G-buffer figure covers the viewer's and the lights'.
thesis = {"gbuffer + light_views": "3", "emit": "0.1", "trace": "10-30", "frame": "40-50"}
rows = []
gbuffers = ms.get("gbuffer", 0.0) + ms.get("light_views", 0.0)
for name, value in ms.items():
    rows.append((name, value, thesis.get(name, "")))
rows.append(("gbuffer + light_views", gbuffers, thesis["gbuffer + light_views"]))
rows.append(("frame", d["total_median_ms"], thesis["frame"]))
print(f"renderer: {d['renderer']}; timing: {d['timing_method']}; "
      f"{d['width']}x{d['height']}, {d['frames']} frames; photons stored: "
      f"{d['photons']['stored']}")
if not d["timing_method"].startswith("GPU timer queries"):
    print("note: no GPU timer queries here (software renderer): CPU-clock times, not a GPU's")
print(f"{'pass':<24} {'ispm median ms':>15} {'thesis ms (GTX 560 Ti)':>24}")
for name, value, ref in rows:
    print(f"{name:<24} {value:>15.2f} {ref:>24}")
PY
