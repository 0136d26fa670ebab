#!/usr/bin/env python3
"""Writes the occluder-scaling scenes scenes/occluders_<N>.json (+ .gltf, .bin) for N in 1, 10, 100, 1000.

Each scene is a field of N boxes (pillars and crates of varied heights, turned about the vertical, on
a jittered grid) standing on a floor, under a spot light shining down across it at an angle, seen
by a camera looking across the field. Seed 004's beam tree gets one occluder per glTF primitive:
the N boxes and the floor, N + 1 in all. The field covers the same 16 m x 16 m for every N, so the
boxes get smaller as N grows. Deterministic (a fixed seed); standard library only.

    python3 tools/make_scenes/make_occluder_scenes.py [OUT_DIR] [--counts 1,10,100,1000]

OUT_DIR defaults to the repository's scenes/. Do not edit the generated files by hand.
"""
import argparse
import math
import os
import random
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from cube_scenes import cube_buffer, cube_gltf, floor_node, material, r6, write_scene  # noqa: E402

FIELD = 16.0        # metres, the side of the square the boxes stand in
FLOOR_HALF = 20.0   # the floor is 40 m x 40 m
FLOOR_THICK = 0.2
# Boxes stand this far above the floor's top, and each box's world bounds stay inside its grid cell:
# no two occluders touch or overlap, which is what seed 004 assumes of its boxes (the plugin's BSP
# ordering of faces also takes overlapping ones, but the field should be the seed's case).
LIFT = 0.005
COUNTS = (1, 10, 100, 1000)


def boxes(count, rng):
    """(x, z, half-width, height, yaw) for `count` boxes on a jittered grid over the field."""
    cols = math.ceil(math.sqrt(count))
    rows = math.ceil(count / cols)
    cell = FIELD / max(cols, rows)
    cells = [(i, j) for j in range(rows) for i in range(cols)]
    rng.shuffle(cells)
    out = []
    for (i, j) in sorted(cells[:count], key=lambda c: (c[1], c[0])):
        half = min(0.6, 0.22 * cell) * rng.uniform(0.75, 1.0)
        yaw = rng.uniform(0.0, math.pi / 2)
        # The box's world bounds stay inside its cell, with a gap.
        reach = half * (abs(math.cos(yaw)) + abs(math.sin(yaw)))
        slack = max(0.0, 0.5 * cell - reach - 0.02 * cell)
        x = (i + 0.5) * cell - 0.5 * FIELD + rng.uniform(-slack, slack)
        z = (j + 0.5) * cell - 0.5 * FIELD + rng.uniform(-slack, slack)
        # Pillars and crates: a third low and wide-ish, the rest tall.
        height = rng.uniform(0.4, 1.0) if rng.random() < 0.33 else rng.uniform(1.5, 3.5)
        out.append((x, z, half, height, yaw))
    return out


def gltf_document(name, bin_name, bin_bytes, vertex_count, index_count, field):
    nodes = [floor_node(FLOOR_HALF, FLOOR_THICK)]
    for k, (x, z, half, height, yaw) in enumerate(field):
        nodes.append({"name": "box%d" % k, "mesh": 1,
                      "translation": [r6(x), r6(LIFT + 0.5 * height), r6(z)],
                      "rotation": [0.0, r6(math.sin(0.5 * yaw)), 0.0, r6(math.cos(0.5 * yaw))],
                      "scale": [r6(2 * half), r6(height), r6(2 * half)]})
    meshes = [("floor", material("concrete", (0.32, 0.31, 0.29), 0.9)),
              ("box", material("painted_wood", (0.55, 0.42, 0.3), 0.8))]
    return cube_gltf(name, "scripts/make_occluder_scenes.py", bin_name, len(bin_bytes), vertex_count,
                     index_count, meshes, nodes)


LIGHT = (-9.0, 13.0, -4.0)
LIGHT_TARGET = (0.5, 0.0, 0.5)


def scene_document(name):
    d = [t - l for t, l in zip(LIGHT_TARGET, LIGHT)]
    length = math.sqrt(sum(c * c for c in d))
    return {
        "gltf": name + ".gltf",
        "camera": {"position": [13.0, 3.2, 12.5], "target": [-1.0, 0.8, -1.5], "up": [0.0, 1.0, 0.0],
                   "fovYDegrees": 55.0, "near": 0.1, "far": 200.0, "reversedZ": False, "infiniteFar": False},
        "light": {"type": "spot", "position": list(LIGHT),
                  "direction": [r6(c / length) for c in d],
                  "intensity": [5200.0, 4900.0, 4300.0], "halfAngleDegrees": 32.0, "range": 40.0,
                  "radius": 0.05, "shadowMapSize": 2048},
        "medium": {"betaR": [0.0, 0.0, 0.0], "betaM": [0.04, 0.04, 0.04], "g": 0.5,
                   "sigmaA": [0.0, 0.0, 0.0], "phase": "cornette-shanks", "maxDistance": 200.0},
        "sky": {"color": [0.0, 0.0, 0.0]},
        "ambient": [0.08, 0.08, 0.09],
        "exposure": 0.32,
    }


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("out", nargs="?", default=os.path.join(here, "..", "..", "scenes"))
    parser.add_argument("--counts", default=",".join(str(c) for c in COUNTS),
                        help="comma-separated box counts (default 1,10,100,1000)")
    args = parser.parse_args()
    counts = [int(c) for c in args.counts.split(",") if c]
    if any(c < 1 or c > 4000 for c in counts):
        parser.error("--counts: each count must be from 1 to 4000 (the plugin takes 4096 occluders)")
    os.makedirs(args.out, exist_ok=True)
    data, vertex_count, index_count = cube_buffer()
    for count in counts:
        name = "occluders_%d" % count
        field = boxes(count, random.Random(4000 + count))
        write_scene(args.out, name, data,
                    gltf_document(name, name + ".bin", data, vertex_count, index_count, field),
                    scene_document(name))
        print("wrote %s (.json, .gltf, .bin): %d boxes and the floor" % (os.path.join(args.out, name), count))


if __name__ == "__main__":
    main()
