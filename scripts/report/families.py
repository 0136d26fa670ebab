"""The 'Froxels against epipolar: the two families' section: per scene, each family's time-against-error
curve (the froxel grid swept over its column size and slice count, epipolar over its six profiles),
from a `lightscatter bench` run of bench/froxels_families.json, and the figures users ask for read off
the curves: the time each family needs to reach the other's error, and the error each gives at the
other's time. A family's curve is its Pareto front (no configuration both faster and more accurate),
read between its points on log-log axes."""
import json
import math
from datetime import date
from pathlib import Path

from .common import fmt, load_note
from .runs import commit_note

FAMILIES_HEADING = "## Froxels against epipolar: the two families"

# Each family's usual configuration, the point the other family is read against.
EPIPOLAR_DEFAULT = "epipolar balanced"
FROXELS_DEFAULT = "froxels 8 px x 64"  # froxels-hdrp's grid


def family_of(label):
    return "froxels" if label.startswith("froxels") else "epipolar"


def front(points):
    """The Pareto front of (time, error, label) points, by increasing time and decreasing error."""
    out = []
    for p in sorted(points):
        if not out or p[1] < out[-1][1]:
            out.append(p)
    return out


def _lerp_log(x, x0, x1, y0, y1):
    t = (math.log(x) - math.log(x0)) / (math.log(x1) - math.log(x0))
    return math.exp(math.log(y0) + t * (math.log(y1) - math.log(y0)))


def time_at_error(curve, error):
    """The time the front needs to reach `error`, or None where no point of it does."""
    if curve[0][1] <= error:
        return curve[0][0]
    for (t0, e0, _), (t1, e1, _) in zip(curve, curve[1:]):
        if e1 <= error:
            return _lerp_log(error, e0, e1, t0, t1)
    return None


def error_at_time(curve, time):
    """The front's error at `time`, or None where its cheapest point costs more."""
    if time < curve[0][0]:
        return None
    for (t0, e0, _), (t1, e1, _) in zip(curve, curve[1:]):
        if time <= t1:
            return _lerp_log(time, t0, t1, e0, e1)
    return curve[-1][1]


def read_offs(points):
    """The scene's fronts, and per family the read-off against its usual point: {family: (that point,
    the other's time at its error, the other's error at its time)}, each None where the other's front
    does not reach it."""
    curves = {f: front([p for p in points if family_of(p[2]) == f]) for f in ("froxels", "epipolar")}
    out = {}
    for mine, other, default in (("epipolar", "froxels", EPIPOLAR_DEFAULT), ("froxels", "epipolar", FROXELS_DEFAULT)):
        at = next((p for p in points if p[2] == default), None)
        if at is None or not curves[other]:
            continue
        out[mine] = (at, time_at_error(curves[other], at[1]), error_at_time(curves[other], at[0]))
    return out, curves


def _point(p):
    return f"{p[2]}: {fmt(p[0])} ms, {fmt(p[1])}"


def families_section(bench_dir, image_dir=None):
    runs = json.loads((Path(bench_dir) / "bench.json").read_text())["runs"]
    out = []
    p = out.append
    p(FAMILIES_HEADING + "\n")
    runs = [r for r in runs if r.get("error") and r.get("time")]
    if not runs:
        return out
    w, h = runs[0]["size"]
    scenes = list(dict.fromkeys(r["scene"] for r in runs))
    points = {s: [(r["time"]["median"], r["error"]["meanRelative"], r["label"]) for r in runs if r["scene"] == s]
              for s in scenes}
    p("What users ask of the two families: what each costs at the other's error, and what error each gives at "
      "the other's cost. The froxel grid is swept over its column size (4, 8 and 16 pixels) and its slice "
      "count (64, 128, 256), epipolar over its six profiles, on the same frames; each configuration's time "
      "(the plugin's GPU time, median of its frames) against its mean relative error to the float64 "
      "reference. Each family's curve is its Pareto front, read between its points on log-log axes.\n")
    note = load_note(bench_dir)
    p(f"Measured on {date.today().isoformat()}{commit_note()} with `./build/host_example/lightscatter bench --config "
      f"bench/froxels_families.json --out build/bench-froxels-families` (`scripts/make-report.sh "
      f"--families-only` runs it, plots it and splices this section) at {w}x{h}, on **{runs[0]['device']}** "
      f"(lavapipe CPU timings: only ratios within this run carry over)." + (f" {note}" if note else "") + "\n")
    if image_dir:
        p("![time against error, per scene, the two families](performance/froxels_families.png)\n")
    p("Read off the curves, against each family's usual configuration (`epipolar balanced`; `froxels-hdrp`'s "
      "grid, 8-pixel columns and 64 slices). Where the other family's curve does not reach the point, the "
      "cell says so and gives that family's nearest point: its most accurate for an error, its cheapest for "
      "a time.\n")
    p("| scene | epipolar balanced | froxels' time at its error | froxels' error at its time | froxels 8 px x 64 | "
      "epipolar's time at its error | epipolar's error at its time |")
    p("|---|---|---|---|---|---|---|")
    apart = []
    for scene in scenes:
        offs, curves = read_offs(points[scene])
        cells = []
        for fam, other in (("epipolar", "froxels"), ("froxels", "epipolar")):
            if fam not in offs:
                cells += ["-", "-", "-"]
                continue
            at, t, e = offs[fam]
            cells.append(f"{fmt(at[0])} ms, {fmt(at[1])}")
            # Where the other front does not reach the point, its nearest: the most accurate point
            # for an error, the cheapest for a time (a front's first point is its cheapest).
            cheapest_other = curves[other][0]
            if t is None:
                cells.append(f"not reached (best {_point(min(curves[other], key=lambda q: q[1]))})")
            elif t == cheapest_other[0] and cheapest_other[1] < at[1]:
                # Its cheapest point is already more accurate: it needs no more than that.
                cells.append(f"under {fmt(t)} ms ({fmt(t / at[0])}x; its cheapest, {fmt(cheapest_other[1])})")
            else:
                cells.append(f"{fmt(t)} ms ({fmt(t / at[0])}x)")
            cells.append(f"{fmt(e)} ({fmt(e / at[1])}x)" if e is not None
                         else f"not reached (cheapest {_point(cheapest_other)})")
        p(f"| {scene} | " + " | ".join(cells) + " |")
        ep, fx = curves["epipolar"], curves["froxels"]
        # A front's last point is its most accurate, its first its cheapest and least accurate.
        if fx[-1][1] > ep[0][1]:
            apart.append((scene, fx[-1], ep[0]))
    p("")
    if apart:
        p("Where the curves do not overlap (the grid's most accurate point is still less accurate than "
          "epipolar's least accurate), the nearest point of each: " + "; ".join(
              f"{s}: the grid's most accurate, {_point(b)}; epipolar's cheapest, {_point(c)}" for s, b, c in apart) + ".\n")
    return out


def plot(bench_dir, out_dir):
    """docs/performance/froxels_families.png: one panel per scene, each family's points and front."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    runs = [r for r in json.loads((Path(bench_dir) / "bench.json").read_text())["runs"]
            if r.get("error") and r.get("time")]
    scenes = list(dict.fromkeys(r["scene"] for r in runs))
    cols = 3
    rows = -(-len(scenes) // cols)
    fig, axes = plt.subplots(rows, cols, figsize=(4.2 * cols, 3.4 * rows), squeeze=False)
    for ax, scene in zip(axes.flat, scenes):
        pts = [(r["time"]["median"], r["error"]["meanRelative"], r["label"]) for r in runs if r["scene"] == scene]
        for fam, color in (("froxels", "tab:orange"), ("epipolar", "tab:blue")):
            mine = [q for q in pts if family_of(q[2]) == fam]
            ax.scatter([q[0] for q in mine], [q[1] for q in mine], color=color, s=14, label=fam)
            f = front(mine)
            ax.plot([q[0] for q in f], [q[1] for q in f], color=color, linewidth=1.2)
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_title(scene, fontsize=10)
        ax.set_xlabel("plugin time (ms, lavapipe)", fontsize=8)
        ax.set_ylabel("mean relative error", fontsize=8)
        ax.tick_params(labelsize=7)
        ax.legend(fontsize=7)
    for ax in list(axes.flat)[len(scenes):]:
        ax.axis("off")
    fig.tight_layout()
    Path(out_dir).mkdir(parents=True, exist_ok=True)
    fig.savefig(Path(out_dir) / "froxels_families.png", dpi=90)
