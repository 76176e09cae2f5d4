#!/usr/bin/env bash
# README command 2: install what is missing, check the C++ layout against .clang-format, build
# with tests, run the whole suite through ctest. In CI (CI=true) warnings are errors.
set -euo pipefail
cd "$(dirname "$0")/.."
bash tools/install-deps.sh --test
# Every C++ source and header (the shaders' shared headers included) as clang-format lays it out;
# the first difference fails the run with its file and line.
find app gl tests shaders/shared \( -name '*.cpp' -o -name '*.h' \) -print0 |
    xargs -0 clang-format --dry-run --Werror
werror=OFF
if [[ "${CI:-}" == "true" ]]; then werror=ON; fi
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DISPM_BUILD_TESTS=ON -DISPM_WERROR="$werror" > /dev/null
cmake --build build -j"$(nproc)"
ctest --test-dir build --output-on-failure -j"$(nproc)" --timeout 600
