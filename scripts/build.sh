#!/usr/bin/env bash
# Configures and builds build/ the one way both README commands use (Release, warnings as errors),
# so that scripts/test.sh after scripts/setup-and-render.sh (or the other way round) finds everything
# built with the same flags and rebuilds nothing.
set -euo pipefail
cd "$(dirname "$0")/.."
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DLS_WERROR=ON
cmake --build build -j"$(nproc)"
