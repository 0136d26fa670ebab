#!/usr/bin/env bash
# Configures and builds build/ the one way both README commands use (Release, warnings as errors),
# so that scripts/test.sh after scripts/setup-and-render.sh (or the other way round) finds what is
# built with the same flags and rebuilds none of it.
#   scripts/build.sh            everything, tests included
#   scripts/build.sh TARGET...  only those targets and what they need (the first command builds
#                               the lightscatter program alone, for a first image sooner)
set -euo pipefail
cd "$(dirname "$0")/.."
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DLS_WERROR=ON
if [[ $# -gt 0 ]]; then
  targets=()
  for t in "$@"; do targets+=(--target "$t"); done
  cmake --build build -j"$(nproc)" "${targets[@]}"
else
  cmake --build build -j"$(nproc)"
fi
