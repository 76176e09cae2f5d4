#!/bin/bash
# Trace and frame cost as the scene grows: three box cities on the same ground, seen from the same
# camera under the same lights with the same photon budget, with about 1x, 10x and 100x the
# default city's triangles (more and smaller lots). Prints one row per city: triangles, photons
# stored (more surfaces keep more photons in the scene: more bounces to trace), then the `ispm
# bench` medians of the trace pass and of the frame, and the trace time per stored photon against
# the smallest city's.
# Usage: tools/scaling-bench.sh ISPM [BENCH-ARGS...]   (e.g. --width 256 --height 256 --frames 5)
set -euo pipefail
if [ $# -lt 1 ]; then
    echo "usage: tools/scaling-bench.sh ISPM [BENCH-ARGS...]" >&2
    exit 2
fi
ispm=$1
shift
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT

# name, lots per block, alley width (m), building inset range (m): lots shrink as they multiply.
cities=("1x:[2, 2]:4:[1, 3]" "10x:[6, 7]:1:[0.3, 1]" "100x:[20, 20]:0.4:[0.1, 0.3]")
base=""
printf "%-6s %10s %8s %10s %10s %22s\n" city triangles stored trace_ms frame_ms trace_per_photon_ratio
for city in "${cities[@]}"; do
    IFS=: read -r name lots alley inset <<< "$city"
    scene="$dir/city_$name.json"
    cat > "$scene" <<JSON
{
  "camera": {"position": [-170.0, 110.0, -190.0], "target": [0.0, 0.0, 0.0], "fov_y_deg": 45},
  "objects": [{"type": "box_city", "seed": 7, "lots_per_block": $lots, "alley_width": $alley,
               "building_inset": $inset}],
  "lights": [{"type": "sun", "direction": [0.77, -0.34, -0.54], "irradiance": [1000.0, 960.0, 900.0]}]
}
JSON
    triangles=$("$ispm" export "$scene" -o "$dir/city_$name.obj" | sed -n 's/.*(\([0-9]*\) triangles).*/\1/p')
    read -r trace frame stored < <("$ispm" bench "$scene" --json "$@" | python3 -c '
import json, sys
d = json.load(sys.stdin)
trace = next(p["median_ms"] for p in d["passes"] if p["name"] == "trace")
print(trace, d["total_median_ms"], d["photons"]["stored"])')
    perPhoton=$(python3 -c "print($trace / max($stored, 1))")
    [ -z "$base" ] && base=$perPhoton
    ratio=$(python3 -c "print('%.2f' % ($perPhoton / $base))")
    printf "%-6s %10s %8s %10.3f %10.2f %22s\n" "$name" "$triangles" "$stored" "$trace" "$frame" "$ratio"
done
