#!/usr/bin/env python3
"""Writes scenes/atrium_gltf_lights.gltf and .json: the atrium lit by KHR_lights_punctual lights.

The glTF is scenes/atrium.gltf (its mesh, materials and texture, the same atrium.bin and
atrium_floor.png) with three lights placed by nodes: the low sun of atrium_lights (a directional
light, in lux) and two spots (in candela) hung from a "Lamps" node 6 m over the court, each spot
node placed relative to it and turned so that its -Z axis is the spot's axis. The warm spot has a
soft cone (15 to 20 degrees) and KHR's windowed range of 30 m; the cold one gives only its outer
cone (20 degrees, the inner one KHR's default 0) and no range. Intensities are atrium_lights' W/sr
and W/m^2 times 683 lm/W, their colours apart. The SCENE.json takes its camera, medium, sky,
ambient and exposure from scenes/atrium_lights.json and its lights from the glTF
("lightsFromGltf"), with a shadow-map size per light by light name or node name.
Deterministic; standard library only.

    python3 tools/make_scenes/make_gltf_lights_scene.py [OUT_DIR]

OUT_DIR defaults to the repository's scenes/. The buffer and texture are the atrium's (not
copied: OUT_DIR must hold atrium.bin and atrium_floor.png for the scene to load). Do not edit the
generated files by hand.
"""
import argparse
import json
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from cube_scenes import compact, write_scene_json  # noqa: E402

NAME = "atrium_gltf_lights"
LUMENS_PER_WATT = 683.0
LAMPS = [0.0, 6.0, 3.5]  # the parent node of both spots


def toward(direction):
    """The unit quaternion (x, y, z, w) turning -Z onto `direction` by the shortest arc."""
    length = math.sqrt(sum(c * c for c in direction))
    bx, by, bz = (c / length for c in direction)
    # -Z x b = (by, -bx, 0); -Z . b = -bz.
    q = [by, -bx, 0.0, 1.0 - bz]
    norm = math.sqrt(sum(c * c for c in q))
    return [c / norm for c in q]


# (light, node); KHR's intensity: candela for the spots, lux for the sun.
LIGHTS = [
    ({"name": "Sun", "type": "directional", "color": [1.0, 0.9, 0.75],
      "intensity": 20.0 * LUMENS_PER_WATT},
     {"name": "Sun", "rotation": toward([-0.31, -0.4226, -0.8517])}),
    ({"name": "Warm spot", "type": "spot", "color": [1.0, 0.625, 0.3],
      "intensity": 400.0 * LUMENS_PER_WATT, "range": 30.0,
      "spot": {"innerConeAngle": math.radians(15.0), "outerConeAngle": math.radians(20.0)}},
     {"name": "Warm lamp", "translation": [-3.0, 0.0, -1.5], "rotation": toward([0.3, -1.0, 0.2])}),
    ({"name": "Cold spot", "type": "spot", "color": [0.3, 0.625, 1.0],
      "intensity": 400.0 * LUMENS_PER_WATT, "spot": {"outerConeAngle": math.radians(20.0)}},
     {"name": "Cold lamp", "translation": [3.0, 0.0, 1.5], "rotation": toward([-0.2, -1.0, -0.1])}),
]
# By the KHR light's name (Sun, Warm spot) or its node's (Cold lamp).
SHADOWS = {"Sun": 2048, "Warm spot": 1024, "Cold lamp": 1024}


def gltf_document(atrium):
    doc = dict(atrium)
    doc["asset"] = dict(atrium["asset"], generator="lightscatter make_gltf_lights_scene.py")
    nodes = list(atrium["nodes"])
    light_nodes = []
    for index, (_, node) in enumerate(LIGHTS):
        light_nodes.append(len(nodes))
        nodes.append(dict(node, extensions={"KHR_lights_punctual": {"light": index}}))
    # The spots hang from one node: their positions are the parent's and their own together.
    lamps = len(nodes)
    nodes.append({"name": "Lamps", "translation": LAMPS, "children": light_nodes[1:]})
    doc["nodes"] = nodes
    doc["scenes"] = [dict(atrium["scenes"][0], nodes=atrium["scenes"][0]["nodes"] +
                          [light_nodes[0], lamps])]
    doc["extensionsUsed"] = ["KHR_lights_punctual"]
    doc["extensions"] = {"KHR_lights_punctual": {"lights": [light for light, _ in LIGHTS]}}
    return doc


def scene_document(atrium_lights):
    scene = {"gltf": NAME + ".gltf", "camera": atrium_lights["camera"], "lightsFromGltf": True,
             "gltfLightScale": 1.0, "gltfLightShadows": SHADOWS}
    for key in ("medium", "sky", "ambient", "exposure"):
        scene[key] = atrium_lights[key]
    return scene


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    scenes = os.path.join(here, "..", "..", "scenes")
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("out", nargs="?", default=scenes)
    args = parser.parse_args()
    with open(os.path.join(scenes, "atrium.gltf")) as f:
        atrium = json.load(f)
    with open(os.path.join(scenes, "atrium_lights.json")) as f:
        atrium_lights = json.load(f)
    os.makedirs(args.out, exist_ok=True)
    with open(os.path.join(args.out, NAME + ".gltf"), "w") as f:
        f.write(compact(json.dumps(gltf_document(atrium), indent=1)) + "\n")
    write_scene_json(args.out, NAME, scene_document(atrium_lights))
    print("wrote %s.gltf and .json: %d KHR_lights_punctual lights" %
          (os.path.join(args.out, NAME), len(LIGHTS)))


if __name__ == "__main__":
    main()
