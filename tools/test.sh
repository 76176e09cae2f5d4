#!/usr/bin/env bash
# README command 2: install what is missing, build with tests, run the whole suite through ctest.
# In CI (CI=true) warnings are errors.
set -euo pipefail
cd "$(dirname "$0")/.."
bash tools/install-deps.sh --test
werror=OFF
if [[ "${CI:-}" == "true" ]]; then werror=ON; fi
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DISPM_BUILD_TESTS=ON -DISPM_WERROR="$werror" > /dev/null
cmake --build build -j"$(nproc)"
ctest --test-dir build --output-on-failure -j"$(nproc)" --timeout 600
