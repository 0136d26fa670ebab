#!/usr/bin/python3
"""The cost of N lights, from a `lightscatter bench` run of bench/lights_scaling.json (the atrium
under N = 1, 2, 4, 8 shadowed spots, tools/make_scenes/make_lights_scenes.py): the plugin's median frame time
(p10 to p90 as bars) against the number of lights for each method, and the time per light. Lines
are told apart in a legend (no labels on the plot). Uses Debian's python3-matplotlib.

    scripts/plot_lights.py BENCH_DIR OUT_DIR      # writes OUT_DIR/lights_scaling.png

The numbers behind it are computed by light_rows() here, which scripts/report/lights.py imports
for docs/performance.md."""
import json
import sys
from pathlib import Path


def load(bench_dir):
    return json.loads((Path(bench_dir) / "bench.json").read_text())["runs"]


def light_rows(runs):
    """{method label: [(lights, median ms, p10 ms, p90 ms), ...] sorted by lights}. Epipolar and
    froxels are keyed by their labels ('epipolar balanced', 'froxels-hdrp'), the others by method
    name."""
    out = {}
    for r in runs:
        key = r["label"] if r["method"] in ("epipolar", "froxels") else r["method"]
        t = r["time"]
        out.setdefault(key, []).append((r["lights"], t["median"], t["p10"], t["p90"]))
    for rows in out.values():
        rows.sort()
    return out


def main():
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    runs = load(sys.argv[1])
    out = Path(sys.argv[2])
    out.mkdir(parents=True, exist_ok=True)
    table = light_rows(runs)
    colors = {"brute-force": "tab:red"}
    fig, (total, per) = plt.subplots(1, 2, figsize=(11, 4.8))
    for k, (method, rows) in enumerate(sorted(table.items())):
        color = colors.get(method, ["tab:blue", "tab:green", "tab:purple", "tab:orange"][k % 4])
        n = [r[0] for r in rows]
        median = [r[1] for r in rows]
        below = [r[1] - r[2] for r in rows]
        above = [r[3] - r[1] for r in rows]
        total.errorbar(n, median, yerr=[below, above], color=color, marker="o", capsize=3, label=method)
        per.plot(n, [m / c for m, c in zip(median, n)], color=color, marker="o", label=method)
    for ax, what in ((total, "ms per frame (median, p10-p90)"), (per, "ms per frame and light")):
        ax.set_xscale("log", base=2)
        ax.set_xticks(sorted({r[0] for rows in table.values() for r in rows}))
        ax.get_xaxis().set_major_formatter(matplotlib.ticker.ScalarFormatter())
        ax.set_xlabel("shadowed spot lights in the frame")
        ax.set_ylabel(what)
        ax.set_ylim(bottom=0)
        ax.grid(True, which="both", alpha=0.3)
    r0 = runs[0]
    w, h = r0["size"]
    kind = "CPU timings: lavapipe runs the 'GPU' on the CPU" if r0["cpuDevice"] else "GPU timestamps"
    fig.suptitle(f"The cost of N lights, atrium, {w}x{h}\n{r0['device']} ({kind})", fontsize=9)
    handles, labels = total.get_legend_handles_labels()
    fig.legend(handles, labels, loc="lower center", ncol=len(labels), fontsize=8, frameon=False)
    fig.tight_layout(rect=(0, 0.07, 1, 0.93))
    path = out / "lights_scaling.png"
    fig.savefig(path, dpi=110)
    print(path)


if __name__ == "__main__":
    main()
