#!/usr/bin/env bash
# Rewrites the golden images in tests/goldens from the current renderer, on purpose only.
# Review the new PNGs before committing them. Usage: tools/update-goldens.sh [build-dir]
set -euo pipefail
cd "$(dirname "$0")/.."
build="${1:-build}"
cmake --build "$build" -j"$(nproc)" --target ispm_image_tests
ISPM_UPDATE_GOLDENS=1 "$build/tests/ispm_image_tests" --gtest_filter='*Golden*'
git status --short tests/goldens
