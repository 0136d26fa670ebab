#!/usr/bin/env bash
# First command of the README: install, build, and run the main job.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
scripts/build.sh  # the same configuration as scripts/test.sh, which then rebuilds nothing
mkdir -p out
./build/host_example/lightscatter render scenes/atrium.json --size 960x540 --out out/atrium.png \
    --inscatter out/atrium-inscatter.exr --timings out/atrium-timings.json
echo "image: out/atrium.png (Lin alone: out/atrium-inscatter.exr, per-pass times: out/atrium-timings.json)"
