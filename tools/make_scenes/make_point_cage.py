#!/usr/bin/env python3
"""Writes scenes/point_cage.json (+ .gltf, .bin): a shadowed point light in a cage, in fog.

A point light hangs 2 m above a floor inside a cubic cage of square bars (1.2 m across, bars 8 cm
thick, 22 cm gaps) with bars on all six sides, so shafts leave the cage in every direction: up,
down onto the floor, sideways and towards the camera, which stands outside. The light has a cube
shadow map (shadowMapSize), which brute-force samples face by face; the cage's bars cross every
face of the cube and the seams between faces. Deterministic; standard library only.

    python3 tools/make_scenes/make_point_cage.py [OUT_DIR]

OUT_DIR defaults to the repository's scenes/. Do not edit the generated files by hand.
"""
import argparse
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from cube_scenes import cube_buffer, cube_gltf, floor_node, material, r6, write_scene  # noqa: E402

LIGHT = (0.0, 2.0, 0.0)
HALF = 0.6     # the cage's half-size, metres
BAR = 0.08     # the bars' thickness
STEPS = (-0.3, 0.0, 0.3)  # inner bar positions along a side
FLOOR_HALF = 15.0
FLOOR_THICK = 0.2


def bars():
    """(centre, size) of every bar of the cage, in world space."""
    lx, ly, lz = LIGHT
    out = []
    # Vertical bars on the four walls, corner posts included once.
    posts = set()
    for s in (-HALF, HALF):
        for t in (-HALF,) + STEPS + (HALF,):
            posts.add((t, s))
            posts.add((s, t))
    for (x, z) in sorted(posts):
        out.append(((lx + x, ly, lz + z), (BAR, 2 * HALF + BAR, BAR)))
    # Roof and base: bars along x over z, and a frame along z at the edges.
    for y in (-HALF, HALF):
        for z in STEPS:
            out.append(((lx, ly + y, lz + z), (2 * HALF, BAR, BAR)))
        for x in (-HALF, HALF):
            out.append(((lx + x, ly + y, lz), (BAR, BAR, 2 * HALF)))
        for z in (-HALF, HALF):
            out.append(((lx, ly + y, lz + z), (2 * HALF, BAR, BAR)))
    return out


def gltf_document(bin_name, bin_bytes, vertex_count, index_count):
    nodes = [floor_node(FLOOR_HALF, FLOOR_THICK)]
    for k, (c, size) in enumerate(bars()):
        nodes.append({"name": "bar%d" % k, "mesh": 1, "translation": [r6(x) for x in c],
                      "scale": [r6(x) for x in size]})
    meshes = [("floor", material("stone", (0.35, 0.33, 0.3), 0.9)),
              ("bar", material("iron", (0.12, 0.11, 0.1), 0.7))]
    return cube_gltf("point_cage", "scripts/make_point_cage.py", bin_name, len(bin_bytes), vertex_count,
                     index_count, meshes, nodes), len(nodes)


def scene_document():
    return {
        "gltf": "point_cage.gltf",
        "camera": {"position": [2.2, 2.6, 6.5], "target": [0.0, 1.7, 0.0], "up": [0.0, 1.0, 0.0],
                   "fovYDegrees": 60.0, "near": 0.1, "far": 100.0, "reversedZ": False, "infiniteFar": False},
        "light": {"type": "point", "position": list(LIGHT), "intensity": [60.0, 52.0, 40.0],
                  "radius": 0.05, "shadowMapSize": 512},
        "medium": {"betaR": [0.0, 0.0, 0.0], "betaM": [0.1, 0.1, 0.1], "g": 0.0,
                   "sigmaA": [0.0, 0.0, 0.0], "phase": "isotropic", "maxDistance": 100.0},
        "sky": {"color": [0.0, 0.0, 0.0]},
        "ambient": [0.01, 0.01, 0.012],
        "exposure": 1.0,
    }


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("out", nargs="?", default=os.path.join(here, "..", "..", "scenes"))
    args = parser.parse_args()
    os.makedirs(args.out, exist_ok=True)
    data, vertex_count, index_count = cube_buffer()
    text, count = gltf_document("point_cage.bin", data, vertex_count, index_count)
    write_scene(args.out, "point_cage", data, text, scene_document())
    print("wrote %s (.json, .gltf, .bin): %d nodes" % (os.path.join(args.out, "point_cage"), count))


if __name__ == "__main__":
    main()
