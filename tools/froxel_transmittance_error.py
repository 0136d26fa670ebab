#!/usr/bin/env python3
"""How far froxels' composite transmittance is from the model's exp(-betaT S), per shipped scene.

The froxel grid keeps one transmittance per froxel, the mean of the three channels, at each slice's
far end; the apply pass interpolates it linearly in the slice coordinate (within the first slice,
linearly in z from 1 at the camera). This walks every camera-space z of the 64 exponential slices (near plane
to the smaller of maxDistance and the far plane) and prints the largest |grid - exp(-betaT_c z)|
over the channels, for a ray along the view axis (S = z), beyond the first slice and within it.

    tools/froxel_transmittance_error.py [SCENE.json ...]   (default: scenes/*.json)
"""
import glob
import json
import math
import sys


def channels(value):
    return value if isinstance(value, list) else [value] * 3


def worst(scene, slices=64, steps=32):
    m, cam = scene["medium"], scene.get("camera", {})
    beta_t = [r + s + a for r, s, a in zip(channels(m.get("betaR", 0.0)),
                                           channels(m.get("betaM", 0.0)),
                                           channels(m.get("sigmaA", 0.0)))]
    near = cam.get("near", 0.1)
    far = min(m.get("maxDistance", 1000.0), cam.get("far", 1000.0))
    z = [near * (far / near) ** (k / slices) for k in range(slices + 1)]
    exact = lambda d: [math.exp(-b * d) for b in beta_t]
    grid = [1.0] + [sum(exact(d)) / 3 for d in z[1:]]  # grid[k]: T at slice k's start
    first, out = (0.0, near), (0.0, near)  # within the first slice; beyond it
    for k in range(slices):
        for t in range(steps + 1):
            f = t / steps
            d = z[k] * (z[k + 1] / z[k]) ** f
            # Within the first slice the apply blends linearly in z from the camera (T = 1).
            g = grid[k] + (grid[k + 1] - grid[k]) * f if k else 1 + (grid[1] - 1) * d / z[1]
            e = max(abs(g - x) for x in exact(d))
            if k == 0:
                first = max(first, (e, d))
            else:
                out = max(out, (e, d))
    return first, out


def main():
    files = sys.argv[1:] or sorted(glob.glob("scenes/*.json"))
    for path in files:
        with open(path) as f:
            scene = json.load(f)
        if "medium" not in scene:
            continue
        (e0, d0), (e, d) = worst(scene)
        print(f"{path}: largest |T_grid - exp(-betaT S)| = {e:.4f} (at {d:.1f} m); "
              f"in the first slice {e0:.4f} (at {d0:.2f} m)")


if __name__ == "__main__":
    main()
