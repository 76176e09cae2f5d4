#!/usr/bin/env bash
# README command 2: install what is missing, check the C++ layout against .clang-format, build
# with tests, run the whole suite through ctest. In CI (CI=true) warnings are errors, and a
# sanitizer stage follows (ISPM_SANITIZE=1 asks for it outside CI).
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
start=$SECONDS
cmake --build build -j"$(nproc)"
echo "tools/test.sh: Release build $((SECONDS - start)) s"
ctest --test-dir build --output-on-failure -j"$(nproc)" --timeout 600

# Sanitizer stage: the asan preset (-O1 with asserts, AddressSanitizer, LeakSanitizer and UBSan,
# every report fatal) builds ispm, the unit and CLI suites and the viewer's leak check, and runs
# them (the CLI tests run the sanitized ispm, so its leaks and errors fail them too). The GL,
# image and viewer suites run in the Release build only, to keep the stage within CI's time.
if [[ "${CI:-}" == "true" || "${ISPM_SANITIZE:-}" == "1" ]]; then
    cmake --preset asan > /dev/null
    start=$SECONDS
    cmake --build build-asan -j"$(nproc)" \
        --target ispm ispm_unit_tests ispm_cli_tests ispm_keep_gl_drivers
    echo "tools/test.sh: sanitizer build $((SECONDS - start)) s"
    UBSAN_OPTIONS=print_stacktrace=1 ctest --test-dir build-asan --output-on-failure \
        -j"$(nproc)" --timeout 600 -L '^(unit|cli|sanitize)$'
fi
