#!/usr/bin/python3
"""Time against error of seed 002's planes beside epipolar and brute force, one panel per scene,
from a `lightscatter bench` run of bench/planes.json. Points are told apart by marker and colour in a
legend (no labels on the plot). Uses Debian's python3-matplotlib."""
import json
import sys
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

STYLE = {"float16": ("tab:green", "o"), "float32": ("tab:olive", "s"), "rgba8": ("tab:purple", "v"),
         "rgba8-dither": ("tab:pink", "^")}
# The method's names in bench results: "slices" in runs made before it was renamed (the word now
# means only an epipolar line).
PLANES = ("planes", "slices")


def key(r):
    if r["method"] not in PLANES:
        return r["label"], ("tab:red" if r["method"] == "brute-force" else "tab:blue", "D")
    if r["family"] == "profiles":
        return "planes balanced (128 planes, float16)", ("tab:green", "*")
    target = r["label"].split()[-1]
    return r["label"], STYLE.get(target, ("black", "x"))


def main():
    runs = json.loads((Path(sys.argv[1]) / "bench.json").read_text())["runs"]
    out = Path(sys.argv[2])
    scenes = sorted({r["scene"] for r in runs})
    fig, axes = plt.subplots(1, len(scenes), figsize=(5 * len(scenes), 4.6), squeeze=False)
    handles = {}
    for ax, scene in zip(axes[0], scenes):
        for r in (r for r in runs if r["scene"] == scene and "error" in r):
            label, (color, marker) = key(r)
            size = 70 if r["method"] not in PLANES or r["family"] == "profiles" else 40
            alpha = 1.0 if "256" in label or r["method"] not in PLANES or r["family"] == "profiles" else 0.55
            h = ax.scatter(r["time"]["median"], max(r["error"]["meanRelative"], 1e-5), color=color, marker=marker,
                           s=size, alpha=alpha, zorder=3)
            handles.setdefault(label, h)
        w, h = runs[0]["size"]
        ax.set_title(f"{scene}, {w}x{h}", fontsize=10)
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_xlabel("median frame time of the plugin (ms)")
        ax.grid(True, which="both", alpha=0.3)
    axes[0][0].set_ylabel("mean relative error of Lin against float64")
    r0 = runs[0]
    fig.suptitle(f"{r0['device']} ({'CPU timings' if r0['cpuDevice'] else 'GPU timings'}); faint: 64 planes",
                 fontsize=9)
    fig.legend(handles.values(), handles.keys(), loc="lower center", ncol=4, fontsize=8, frameon=False)
    fig.tight_layout(rect=(0, 0.16, 1, 0.95))
    path = out / "planes_1920x1080.png"
    fig.savefig(path, dpi=110)
    print(path)


if __name__ == "__main__":
    main()
