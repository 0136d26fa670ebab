#!/usr/bin/env bash
# Second command of the README: build with warnings as errors (scripts/build.sh, shared with the
# first command) and run every test.
set -euo pipefail
cd "$(dirname "$0")/.."
# Every tracked C++ file as .clang-format writes it (the style holds by itself, not by review).
scripts/check-format.sh
scripts/build.sh
ctest --test-dir build --output-on-failure -j"$(nproc)"
# The same code under AddressSanitizer and UndefinedBehaviorSanitizer (build-asan/).
scripts/test-sanitizers.sh
# The input readers under libFuzzer, 30 s each, built in build-asan/ (configured with LS_FUZZ too,
# so the libraries are compiled once for both).
scripts/fuzz.sh --build build-asan 30
