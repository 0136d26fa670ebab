#!/usr/bin/env bash
# Regenerates the image-regression references (tests/host/references) from the shipped scenes, on
# lavapipe. Run after a deliberate change of the output, and say why in the commit.
set -euo pipefail
cd "$(dirname "$0")/.."
mkdir -p tests/host/references
for scene in atrium window_room engine_spot point_fog; do
  LS_DEVICE=llvmpipe ./build/host_example/lightscatter render "scenes/$scene.json" --size 96x54 \
      --out "/tmp/$scene.png" --inscatter "tests/host/references/${scene}_lin.exr"
done
