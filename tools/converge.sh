#!/bin/bash
# Error against accumulated frames: renders SCENE's indirect light with --accumulate N for each N
# and compares it with a reference's indirect light (REF3 minus REF0, `ispm render --mode
# reference` with --bounces 3 and 0), printing CSV rows "label,frames,energy,rel_rmse4".
# Usage: tools/converge.sh ISPM LABEL SCENE CAMERA REF3 REF0 [N...] [-- RENDER-ARGS...]
# (CAMERA "" for the default; N defaults to 1 2 4 ... 64; RENDER-ARGS go to every `ispm render`,
# e.g. --set photons=20000.)
set -euo pipefail
if [ $# -lt 6 ]; then
    echo "usage: tools/converge.sh ISPM LABEL SCENE CAMERA REF3 REF0 [N...] [-- RENDER-ARGS...]" >&2
    exit 2
fi
ispm=$1 label=$2 scene=$3 camera=$4 ref3=$5 ref0=$6
shift 6
frames=()
while [ $# -gt 0 ] && [ "$1" != "--" ]; do
    if ! [[ $1 =~ ^[1-9][0-9]*$ ]]; then
        echo "tools/converge.sh: frame count '$1': expected a whole number of frames >= 1" >&2
        exit 2
    fi
    frames+=("$1")
    shift
done
[ $# -gt 0 ] && shift # the "--"
extra=("$@")
[ ${#frames[@]} -gt 0 ] || frames=(1 2 4 8 16 32 64)
size=$(head -2 "$ref3" | tail -1) # PFM: "W H"
width=${size% *} height=${size#* }
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
camera_args=()
[ -n "$camera" ] && camera_args=(--camera "$camera")
for n in "${frames[@]}"; do
    "$ispm" render "$scene" "${camera_args[@]}" --width "$width" --height "$height" \
        --aov indirect --accumulate "$n" "${extra[@]}" -o "$tmp/ispm.pfm" >/dev/null
    report=$("$ispm" compare "$tmp/ispm.pfm" "$ref3" --minus "$ref0")
    energy=$(awk '$1 == "energy" { print $2 }' <<<"$report")
    rel=$(awk '$1 == "rel" && $3 == "4x4" { print $4 }' <<<"$report")
    echo "$label,$n,$energy,$rel"
done
