#!/usr/bin/env python3
"""The cost of a non-uniform medium (docs/performance.md, "Media").

Renders each shipped media scene and its homogeneous twin (the same scene with density 1, no height
fog and no fog volumes: the uniform medium of the scene's coefficients) with the methods given, in
alternation, RUNS times each, and prints the median of the plugin's GPU time per scene, method and
medium as a Markdown table with the ratio of the two. The twins are written to a temporary folder,
never beside the repository's scenes.

    tools/media_timing.py [--binary build/host_example/lightscatter] [--size 1920x1080]
                          [--runs 3] [--methods epipolar,froxels] [--scenes valley_fog,...]

On lavapipe only ratios measured in one run on a quiet machine mean anything.
"""
import argparse
import json
import os
import statistics
import sys
import tempfile

from render_timing import render_report

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
SCENES = ["valley_fog", "room_fog_box", "point_fog_volume", "media_mix"]


def twin(scene_path, folder):
    """The scene with a uniform medium of its own coefficients, its paths made absolute."""
    with open(scene_path) as f:
        scene = json.load(f)
    base = os.path.dirname(os.path.abspath(scene_path))
    if "gltf" in scene:
        scene["gltf"] = os.path.join(base, scene["gltf"])
    for model in scene.get("models", []):
        model["gltf"] = os.path.join(base, model["gltf"])
    for light in ([scene["light"]] if "light" in scene else []) + scene.get("lights", []):
        if "cookie" in light:
            light["cookie"] = os.path.join(base, light["cookie"])
    medium = scene.setdefault("medium", {})
    for key in ("density", "heightFog", "fogVolumes"):
        medium.pop(key, None)
    out = os.path.join(folder, os.path.basename(scene_path).replace(".json", "_homogeneous.json"))
    with open(out, "w") as f:
        json.dump(scene, f)
    return out


def plugin_ms(binary, scene, method, size, folder):
    report = render_report(binary, scene, method, size, folder)
    return report["totalMilliseconds"], report.get("method", method)


def main():
    p = argparse.ArgumentParser()
    p.add_argument("--binary", default=os.path.join(ROOT, "build/host_example/lightscatter"))
    p.add_argument("--size", default="1920x1080")
    p.add_argument("--runs", type=int, default=3)
    p.add_argument("--methods", default="epipolar,brute-force,cone-march,planes,froxels")
    p.add_argument("--scenes", default=",".join(SCENES))
    args = p.parse_args()
    methods = args.methods.split(",")
    with tempfile.TemporaryDirectory() as folder:
        print(f"| scene | method | media (ms) | homogeneous (ms) | ratio |")
        print(f"|---|---|---|---|---|")
        for name in args.scenes.split(","):
            scene = os.path.join(ROOT, "scenes", name + ".json")
            uniform = twin(scene, folder)
            for method in methods:
                media, hom = [], []
                for _ in range(args.runs):
                    media.append(plugin_ms(args.binary, scene, method, args.size, folder)[0])
                    hom.append(plugin_ms(args.binary, uniform, method, args.size, folder)[0])
                m, h = statistics.median(media), statistics.median(hom)
                print(f"| {name} | {method} | {m:.0f} | {h:.0f} | {m / h:.2f} |", flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
