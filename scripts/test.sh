#!/usr/bin/env bash
# Second command of the README: build with warnings as errors and run every test.
set -euo pipefail
cd "$(dirname "$0")/.."
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DLS_WERROR=ON
cmake --build build -j"$(nproc)"
ctest --test-dir build --output-on-failure -j"$(nproc)"
# The same code under AddressSanitizer and UndefinedBehaviorSanitizer (build-asan/).
scripts/test-sanitizers.sh
