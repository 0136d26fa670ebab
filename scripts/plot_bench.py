#!/usr/bin/python3
"""Plots of a `lightscatter bench` run (bench.json): time against error with the Pareto front, and
time against screen size, shadow-map size and slices x samples. Uses Debian's python3-matplotlib."""
import json
import math
import sys
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

# A sweep's colour under its family's current name and the one of runs recorded before ("samples",
# "initialStep", "trees").
COLORS = {"brute-force": "tab:red", "profiles": "tab:blue", "slices": "tab:green", "samplesPerSlice": "tab:olive",
          "samples": "tab:olive", "initialSampleStep": "tab:purple", "initialStep": "tab:purple",
          "minMaxTrees": "tab:orange", "trees": "tab:orange", "shadowMapSize": "tab:brown", "size": "tab:gray",
          "planes": "tab:cyan"}


def device_note(runs):
    r = runs[0]
    return f"{r['device']} ({'CPU timings' if r['cpuDevice'] else 'GPU timings'})"


def pareto(points):
    front, best = [], math.inf
    for t, e in sorted(points):
        if e < best:
            front.append((t, e))
            best = e
    return front


MARKERS = "osD^vP*Xhp<>8"


def time_vs_error(runs, scene, out):
    """Every configuration of the scene's table (the methods and epipolar's profiles) as its own marker
    in a legend beside the plot, so no label overlaps another; the one-parameter sweeps as small grey
    dots (their figures are in the tables), and the Pareto front over everything."""
    rows = [r for r in runs if r["scene"] == scene and "error" in r and r["error"]["meanRelative"] > 0]
    if not rows:
        return None
    fig, ax = plt.subplots(figsize=(9.5, 5))
    named = [r for r in rows if r["family"] == "profiles"]
    swept = [r for r in rows if r["family"] != "profiles"]
    if swept:
        ax.scatter([r["time"]["median"] for r in swept], [r["error"]["meanRelative"] for r in swept],
                   color="0.7", s=12, zorder=2, label="one-parameter sweeps (tables)")
    cmap = plt.get_cmap("tab20")
    for k, r in enumerate(named):
        label = r["label"]
        if r["method"] == "auto" and r.get("methodRan"):
            label = f"auto (ran {r['methodRan']})"
        ax.scatter(r["time"]["median"], r["error"]["meanRelative"], color=cmap(k % 20),
                   marker=MARKERS[k % len(MARKERS)], s=46, zorder=3, edgecolors="black", linewidths=0.4,
                   label=label)
    front = pareto([(r["time"]["median"], r["error"]["meanRelative"]) for r in rows])
    ax.plot([p[0] for p in front], [p[1] for p in front], "k--", lw=1, label="Pareto front", zorder=1)
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("median frame time of the plugin (ms)")
    ax.set_ylabel("mean relative error of Lin against float64 reference")
    w, h = rows[0]["size"]
    ax.set_title(f"{scene}, {w}x{h}\n{device_note(rows)}", fontsize=9)
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=7.5, loc="upper left", bbox_to_anchor=(1.01, 1.0), borderaxespad=0.0)
    path = out / f"time_vs_error_{scene}.png"
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)
    return path


def scaling(runs, family, x_of, xlabel, name, out):
    rows = [r for r in runs if r["family"] == family]
    if not rows:
        return None
    fig, ax = plt.subplots(figsize=(6.5, 4.5))
    groups = {}
    for r in rows:
        groups.setdefault((r["scene"], r["method"]), []).append(r)
    for (scene, method), rs in sorted(groups.items()):
        rs.sort(key=x_of)
        ax.errorbar([x_of(r) for r in rs], [r["time"]["median"] for r in rs],
                    yerr=[[r["time"]["median"] - r["time"]["p10"] for r in rs],
                          [r["time"]["p90"] - r["time"]["median"] for r in rs]],
                    marker="o", ms=4, capsize=2, label=f"{scene} {method}")
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel(xlabel)
    ax.set_ylabel("median plugin time (ms), p10-p90 bars")
    ax.set_title(device_note(rows), fontsize=9)
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=7, loc="upper left", bbox_to_anchor=(1.01, 1.0), borderaxespad=0.0)
    path = out / name
    fig.tight_layout()
    fig.savefig(path, dpi=110, bbox_inches="tight")
    plt.close(fig)
    return path


def screen_scaling(runs, out):
    """Time against screen size, a panel per scene and a line per method: the size sweep (balanced
    settings) and the configuration's own size (the methods' rows and epipolar balanced)."""
    rows = [r for r in runs if r["family"] == "size" or
            (r["family"] == "profiles" and (r["method"] != "epipolar" or r["label"] == "epipolar balanced"))]
    if not any(r["family"] == "size" for r in rows):
        return None
    scenes = sorted({r["scene"] for r in rows})
    cols = 2
    fig, axes = plt.subplots((len(scenes) + cols - 1) // cols, cols, figsize=(11, 3.6 * ((len(scenes) + 1) // 2)),
                             squeeze=False)
    methods = sorted({r["method"] for r in rows})
    cmap = plt.get_cmap("tab10")
    for ax, scene in zip(axes.flat, scenes):
        for k, m in enumerate(methods):
            rs = sorted((r for r in rows if r["scene"] == scene and r["method"] == m),
                        key=lambda r: r["size"][0] * r["size"][1])
            if rs:
                ax.plot([r["size"][0] * r["size"][1] for r in rs], [r["time"]["median"] for r in rs],
                        marker=MARKERS[k % len(MARKERS)], ms=4, color=cmap(k % 10), label=m)
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_title(scene, fontsize=9)
        ax.set_xlabel("pixels", fontsize=8)
        ax.set_ylabel("median plugin time (ms)", fontsize=8)
        ax.grid(True, which="both", alpha=0.3)
    for ax in list(axes.flat)[len(scenes):]:
        ax.axis("off")
    legend = {}  # every method once, whichever panel has it (not every method takes every light)
    for ax in axes.flat:
        for handle, label in zip(*ax.get_legend_handles_labels()):
            legend.setdefault(label, handle)
    fig.legend(list(legend.values()), list(legend.keys()), fontsize=8, loc="center left",
               bbox_to_anchor=(1.0, 0.5))
    fig.suptitle(device_note(rows), fontsize=9)
    fig.tight_layout()
    path = out / "scaling_screen.png"
    fig.savefig(path, dpi=110, bbox_inches="tight")
    plt.close(fig)
    return path


def main():
    if len(sys.argv) != 3:
        sys.exit("usage: plot_bench.py BENCH_DIR OUTPUT_DIR")
    runs = json.loads((Path(sys.argv[1]) / "bench.json").read_text())["runs"]
    out = Path(sys.argv[2])
    out.mkdir(parents=True, exist_ok=True)
    made = []
    for scene in sorted({r["scene"] for r in runs}):
        made.append(time_vs_error(runs, scene, out))
    made.append(screen_scaling(runs, out))
    made.append(scaling(runs, "shadowMapSize", lambda r: r["shadowMapSize"], "shadow-map size (texels per side)",
                        "scaling_shadow_map.png", out))
    # "samples": samplesPerSlice's family in runs recorded before it took the field's name.
    ss = [dict(r, family="ss") for r in runs if r["family"] in ("slices", "samplesPerSlice", "samples")]
    made.append(scaling(ss, "ss", lambda r: r["slices"] * r["samples"], "slices x samples",
                        "scaling_slices_samples.png", out))
    for m in made:
        if m:
            print(m)


if __name__ == "__main__":
    main()
