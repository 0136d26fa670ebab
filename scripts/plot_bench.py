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

COLORS = {"brute-force": "tab:red", "profiles": "tab:blue", "slices": "tab:green", "samples": "tab:olive",
          "initialStep": "tab:purple", "trees": "tab:orange", "shadowMapSize": "tab:brown", "size": "tab:gray",
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


def time_vs_error(runs, scene, out):
    rows = [r for r in runs if r["scene"] == scene and "error" in r and r["error"]["meanRelative"] > 0]
    if not rows:
        return None
    fig, ax = plt.subplots(figsize=(7.5, 5))
    for r in rows:
        key = "brute-force" if r["method"] == "brute-force" else r["family"]
        ax.scatter(r["time"]["median"], r["error"]["meanRelative"], color=COLORS.get(key, "black"), s=28, zorder=3)
        ax.annotate(r["label"], (r["time"]["median"], r["error"]["meanRelative"]), fontsize=7,
                    xytext=(4, 3), textcoords="offset points")
    front = pareto([(r["time"]["median"], r["error"]["meanRelative"]) for r in rows])
    ax.plot([p[0] for p in front], [p[1] for p in front], "k--", lw=1, label="Pareto front", zorder=2)
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("median frame time of the plugin (ms)")
    ax.set_ylabel("mean relative error of Lin against float64 reference")
    w, h = rows[0]["size"]
    ax.set_title(f"{scene}, {w}x{h}\n{device_note(rows)}", fontsize=9)
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=8)
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
    ax.legend(fontsize=7)
    path = out / name
    fig.tight_layout()
    fig.savefig(path, dpi=110)
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
    made.append(scaling(runs, "size", lambda r: r["size"][0] * r["size"][1], "pixels", "scaling_screen.png", out))
    made.append(scaling(runs, "shadowMapSize", lambda r: r["shadowMapSize"], "shadow-map size (texels per side)",
                        "scaling_shadow_map.png", out))
    made.append(scaling([dict(r, family="ss") for r in runs if r["family"] in ("slices", "samples")], "ss",
                        lambda r: r["slices"] * r["samples"], "slices x samples", "scaling_slices_samples.png", out))
    for m in made:
        if m:
            print(m)


if __name__ == "__main__":
    main()
