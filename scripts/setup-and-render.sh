#!/usr/bin/env bash
# First command of the README: install, build, and run the main job.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release
cmake --build build -j"$(nproc)"
mkdir -p out
./build/host_example/lightscatter pattern --out out/pattern.png --size 512x512 \
    --report out/pattern-report.json --dot out/pattern-graph.dot
echo "image: out/pattern.png"
