#!/usr/bin/python3
"""Seed 004's beam tree against scene complexity, from a `lightscatter bench` run of bench/occluders.json:
the CPU tree build (FrameReport::cpuWork), the GPU time and their sum for each beam-tree method in the
data (beam-tree-analytic, beam-tree-sampling, ...) against the number of boxes (log x), with epipolar's
GPU time as the horizontal reference. Everything is told apart in a legend (no labels on the plot).
Uses Debian's python3-matplotlib.

    scripts/plot_occluders.py BENCH_DIR OUT_DIR      # writes OUT_DIR/occluders_scaling.png

The numbers behind it (and the crossover) are computed by occluder_rows() and crossover() here, which
scripts/report/occluders.py imports for docs/performance.md."""
import json
import math
import re
import statistics
import sys
from pathlib import Path


def boxes(r):
    """The scene's box count: occluders_<N> is N boxes on a floor (tools/make_scenes/make_occluder_scenes.py)."""
    m = re.search(r"occluders_(\d+)$", r["scene"])
    return int(m.group(1)) if m else r.get("occluders", 0)


def load(bench_dir):
    return json.loads((Path(bench_dir) / "bench.json").read_text())["runs"]


def occluder_rows(runs):
    """{method label: [(boxes, occluders given, cpu ms, gpu ms), ...] sorted by boxes}. Beam-tree methods
    are keyed by method name, epipolar by its label ('epipolar balanced')."""
    out = {}
    for r in runs:
        key = r["label"] if r["method"] == "epipolar" else r["method"]
        cpu = r.get("cpuTime", {}).get("median", 0.0)
        out.setdefault(key, []).append((boxes(r), r.get("occluders"), cpu, r["time"]["median"]))
    for rows in out.values():
        rows.sort()
    return out


def beam_methods(table):
    return sorted(k for k in table if k.startswith("beam-tree"))


def crossover(rows, reference_ms):
    """Where CPU + GPU of a beam-tree method (rows from occluder_rows) first reaches `reference_ms`,
    interpolated linearly in log(boxes) and log(ms) between the two measured counts around it.
    Returns (count, kind): kind 'interpolated', 'below' (already slower at the smallest count, count is
    that count) or 'above' (still faster at the largest, count is that count)."""
    pts = [(n, cpu + gpu) for n, _, cpu, gpu in rows if n > 0]
    if not pts:
        return None, "none"
    if pts[0][1] >= reference_ms:
        return pts[0][0], "below"
    for (n0, t0), (n1, t1) in zip(pts, pts[1:]):
        if t0 < reference_ms <= t1:
            f = (math.log(reference_ms) - math.log(t0)) / (math.log(t1) - math.log(t0))
            return math.exp(math.log(n0) + f * (math.log(n1) - math.log(n0))), "interpolated"
    return pts[-1][0], "above"


def reference_ms(table):
    """Epipolar's GPU time, the median over the scenes (it hardly depends on the boxes)."""
    epi = next((v for k, v in sorted(table.items()) if k.startswith("epipolar")), None)
    if not epi:
        return None, None
    return statistics.median(gpu for _, _, _, gpu in epi), next(k for k in sorted(table) if k.startswith("epipolar"))


def main():
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    runs = load(sys.argv[1])
    out = Path(sys.argv[2])
    out.mkdir(parents=True, exist_ok=True)
    table = occluder_rows(runs)
    ref, ref_label = reference_ms(table)
    colors = ["tab:blue", "tab:green", "tab:purple", "tab:brown"]
    fig, ax = plt.subplots(figsize=(8.6, 6.4))
    for color, method in zip(colors, beam_methods(table)):
        rows = table[method]
        n = [r[0] for r in rows]
        cpu = [max(r[2], 1e-3) for r in rows]
        gpu = [max(r[3], 1e-3) for r in rows]
        ax.plot(n, cpu, color=color, marker="s", linestyle=":", label=f"{method}: CPU tree build")
        ax.plot(n, gpu, color=color, marker="o", linestyle="--", label=f"{method}: GPU")
        ax.plot(n, [c + g for c, g in zip(cpu, gpu)], color=color, marker="D", linestyle="-", linewidth=2,
                label=f"{method}: CPU + GPU")
        if ref is not None:
            n_cross, how = crossover(rows, ref)
            if how == "interpolated":
                ax.axvline(n_cross, color=color, linestyle=(0, (1, 4)), linewidth=1.2,
                           label=f"{method}: crossover, ~{n_cross:.0f} boxes (interpolated)")
    if ref is not None:
        ax.axhline(ref, color="tab:red", linestyle="-.", label=f"{ref_label}: GPU ({ref:.0f} ms, reference)")
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("boxes in the scene (each also has the floor as one more occluder)")
    ax.set_ylabel("ms per frame (median)")
    ax.grid(True, which="both", alpha=0.3)
    r0 = runs[0]
    w, h = r0["size"]
    kind = "CPU timings: lavapipe runs the 'GPU' on the CPU too" if r0["cpuDevice"] else "GPU timestamps"
    ax.set_title(f"Beam tree against scene complexity, {w}x{h}\n{r0['device']} ({kind})", fontsize=9)
    # Below the axes, so that it covers no line.
    ax.legend(loc="upper center", bbox_to_anchor=(0.5, -0.13), ncol=2, fontsize=8, frameon=False)
    fig.tight_layout()
    path = out / "occluders_scaling.png"
    fig.savefig(path, dpi=110, bbox_inches="tight")  # the legend below the axes is kept whole
    print(path)


if __name__ == "__main__":
    main()
