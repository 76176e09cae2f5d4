#!/usr/bin/env bash
# README command 1: install what is missing, build Release, render the default scene (box city).
set -euo pipefail
cd "$(dirname "$0")/.."
bash tools/install-deps.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release > /dev/null
cmake --build build -j"$(nproc)" --target ispm
./build/ispm render assets/scenes/box_city.json -o box_city.png
