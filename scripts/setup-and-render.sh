#!/usr/bin/env bash
# First command of the README: install, build, and run the main job.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
# The program alone (the tests are scripts/test.sh's to build), in the configuration scripts/test.sh
# uses, so that it rebuilds none of it.
scripts/build.sh lightscatter
mkdir -p out
./build/host_example/lightscatter render scenes/atrium.json --size 960x540 --out out/atrium.png \
    --inscatter out/atrium-inscatter.exr --timings out/atrium-timings.json
echo "image: out/atrium.png (Lin alone: out/atrium-inscatter.exr, per-pass times: out/atrium-timings.json)"
