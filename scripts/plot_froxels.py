#!/usr/bin/python3
"""Time against error for froxels and the seeds' methods, from a `lightscatter bench` run of
bench/froxels.json: one point per scene and configuration, the froxel configurations in one colour
family and epipolar's profiles and brute force in another, time relative to brute force on the same
scene (so scenes of different cost share the axes). Uses Debian's python3-matplotlib.

    scripts/plot_froxels.py BENCH_DIR OUT_DIR      # writes OUT_DIR/froxels.png"""
import json
import sys
from pathlib import Path


def main():
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    runs = json.loads((Path(sys.argv[1]) / "bench.json").read_text())["runs"]
    out = Path(sys.argv[2])
    out.mkdir(parents=True, exist_ok=True)
    brute = {r["scene"]: r["time"]["median"] for r in runs if r["label"] == "brute-force"}
    labels = sorted({r["label"] for r in runs})
    froxel_colors = iter(["tab:orange", "tab:red", "tab:brown", "tab:pink"])
    seed_colors = iter(["tab:blue", "tab:green", "tab:cyan", "tab:purple", "tab:olive"])
    markers = {s: m for s, m in zip(sorted(brute), "osD^vP<>")}
    fig, ax = plt.subplots(figsize=(8, 5.5))
    for label in labels:
        color = next(froxel_colors if label.startswith("froxels") else seed_colors)
        for r in runs:
            e = r.get("error", {}).get("meanRelative")
            if r["label"] != label or e is None or not brute.get(r["scene"]):
                continue
            ax.scatter(r["time"]["median"] / brute[r["scene"]], e, color=color,
                       marker=markers.get(r["scene"], "o"),
                       label=label if r["scene"] == sorted(brute)[0] else None)
    for scene, marker in markers.items():
        ax.scatter([], [], color="grey", marker=marker, label=scene)
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("time relative to brute force on the same scene (median)")
    ax.set_ylabel("mean relative error against the float64 reference")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=7, ncol=2)
    fig.tight_layout()
    fig.savefig(out / "froxels.png", dpi=110)


if __name__ == "__main__":
    main()
