#!/usr/bin/env python3
"""Writes the light-count scaling scenes scenes/atrium_spots_<N>.json for N in 1, 2, 4, 8, 16, and
scenes/atrium_sun_small_spots.json.

Each is the atrium (scenes/atrium.json's glTF, camera, medium, sky, ambient and exposure) lit by N
shadowed spots and nothing else, given as a "lights" array: the first N of eight spots hung 6 m
up over the court, each pointing down and a little askew, in turn warm and cold. Every spot's cone
reaches the court the camera looks at, so every light reaches the view and costs its chain: the
scenes measure the cost of N lights (bench/lights_scaling.json). Each spot is as bright whatever N
(400/250/120 or 120/250/400 W/sr, atrium_lights' two spots), so scene N + 1 adds a light to scene N.
atrium_sun_small_spots is the atrium's own sun (shadowed) and four small shadowed spots hung 4.5 m
up, soft-edged (inner 8, outer 11 degrees) with a 6 m windowed range, each covering a few percent of
a 1920x1080 screen: the frame of a method chosen per light (bench/lights_per_light.json), where a
small spot's chain costs its share of the screen rather than a full-screen pass.
Deterministic; standard library only.

    python3 tools/make_scenes/make_lights_scenes.py [OUT_DIR] [--counts 1,2,4,8,16]

OUT_DIR defaults to the repository's scenes/. The glTF is the atrium's (not copied: OUT_DIR must
hold atrium.gltf for the scenes to load). Do not edit the generated files by hand.
"""
import argparse
import json
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from cube_scenes import write_scene_json  # noqa: E402

COUNTS = (1, 2, 4, 8, 16)
# (x, z) over the court, and where each spot's axis leans (x, z per metre down).
SPOTS = [((-3.0, 2.0), (0.3, 0.2)), ((3.0, 5.0), (-0.2, -0.1)), ((0.0, 8.0), (0.1, -0.3)),
         ((-2.0, 6.5), (0.25, -0.15)), ((2.5, 1.0), (-0.3, 0.25)), ((-4.0, 4.0), (0.35, 0.0)),
         ((4.0, 8.5), (-0.3, -0.2)), ((0.5, 3.5), (0.0, 0.3)), ((-1.0, 1.0), (0.2, 0.2)),
         ((1.5, 2.5), (-0.1, 0.2)), ((-3.0, 7.5), (0.2, -0.2)), ((3.0, 6.5), (-0.25, 0.1)),
         ((-1.5, 5.0), (0.1, 0.1)), ((1.0, 6.0), (0.2, -0.1)), ((-2.5, 3.0), (0.15, 0.25)),
         ((2.0, 8.0), (-0.15, -0.25))]
HEIGHT = 6.0
WARM, COLD = (400.0, 250.0, 120.0), (120.0, 250.0, 400.0)


def spot(k):
    (x, z), (dx, dz) = SPOTS[k]
    color = WARM if k % 2 == 0 else COLD
    return {"type": "spot", "position": [x, HEIGHT, z], "direction": [dx, -1.0, dz],
            "intensity": list(color), "halfAngleDegrees": 20.0, "range": 30.0,
            "shadowMapSize": 1024}


# Small spots: (x, z), axis lean (x, z per metre down), warm or cold.
SMALL_SPOTS = [((-2.0, 4.0), (0.1, 0.05)), ((1.5, 7.0), (-0.05, 0.1)), ((-4.0, 8.0), (0.1, -0.1)),
               ((3.5, 3.0), (-0.1, 0.0))]
SMALL_HEIGHT = 4.5


def small_spot(k):
    (x, z), (dx, dz) = SMALL_SPOTS[k]
    color = (300.0, 220.0, 140.0) if k % 2 == 0 else (140.0, 220.0, 300.0)
    return {"type": "spot", "position": [x, SMALL_HEIGHT, z], "direction": [dx, -1.0, dz],
            "intensity": list(color), "innerConeAngleDegrees": 8.0, "outerConeAngleDegrees": 11.0,
            "range": 6.0, "rangeFalloff": "window", "shadowMapSize": 512}


def sun_and_small_spots(atrium):
    scene = {key: atrium[key] for key in ("gltf", "camera")}
    scene["lights"] = [atrium["light"]] + [small_spot(k) for k in range(len(SMALL_SPOTS))]
    for key in ("medium", "sky", "ambient", "exposure"):
        scene[key] = atrium[key]
    return scene


def scene_document(atrium, count):
    scene = {key: atrium[key] for key in ("gltf", "camera")}
    scene["lights"] = [spot(k) for k in range(count)]
    for key in ("medium", "sky", "ambient", "exposure"):
        scene[key] = atrium[key]
    return scene


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    scenes = os.path.join(here, "..", "..", "scenes")
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("out", nargs="?", default=scenes)
    parser.add_argument("--counts", default=",".join(str(c) for c in COUNTS),
                        help="comma-separated light counts (default 1,2,4,8,16)")
    args = parser.parse_args()
    counts = [int(c) for c in args.counts.split(",") if c]
    if any(c < 1 or c > len(SPOTS) for c in counts):
        parser.error("--counts: each count must be from 1 to %d" % len(SPOTS))
    with open(os.path.join(scenes, "atrium.json")) as f:
        atrium = json.load(f)
    os.makedirs(args.out, exist_ok=True)
    for count in counts:
        name = "atrium_spots_%d" % count
        write_scene_json(args.out, name, scene_document(atrium, count))
        print("wrote %s: %d shadowed spot(s)" % (os.path.join(args.out, name + ".json"), count))
    write_scene_json(args.out, "atrium_sun_small_spots", sun_and_small_spots(atrium))
    print("wrote %s: the sun and %d small spots" %
          (os.path.join(args.out, "atrium_sun_small_spots.json"), len(SMALL_SPOTS)))


if __name__ == "__main__":
    main()
