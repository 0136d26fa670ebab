"""The 'Against froxel fog' section: the froxel grid engines ship beside the seeds' methods, from a
bench run of bench/froxels.json (time and error at 1920x1080), the budget of each configuration
(budget-*.json in the same folder, `lightscatter budget --json`), and the cost of N lights
(a run of bench/lights_scaling.json)."""
import json
import sys
from datetime import date
from pathlib import Path

from .common import fmt, load_note
from .runs import commit_note

FROXELS_HEADING = "## Against froxel fog"


def family(label):
    return "froxels" if label.startswith("froxels") else "seeds"


def memory_mib(bench_dir, label):
    """Peak MiB of a configuration at the run's size, from budget-LABEL.json (None without it)."""
    f = Path(bench_dir) / f"budget-{label.replace(' ', '-')}.json"
    if not f.exists():
        return None
    b = json.loads(f.read_text())[0]
    return b["peakBytes"] / (1024.0 * 1024.0)


def memory_cell(bench_dir, label, w, h):
    """A configuration's peak MiB, followed by the `lightscatter budget` options that give it
    (scripts/make-report.sh's) for tools/check_budget_figures.py; '-' without a budget."""
    mib = memory_mib(bench_dir, label)
    if mib is None:
        return "-"
    method, _, profile = label.partition(" ")
    return f"{fmt(mib)}<!-- budget --method {method} --profile {profile or 'balanced'} --size {w}x{h}: peak -->"


def froxels_section(bench_dir, scaling_dir=None):
    sys.path.insert(0, str(Path(__file__).resolve().parents[1]))
    import plot_lights as pl

    out = []
    p = out.append
    p(FROXELS_HEADING + "\n")
    p("What engines ship for volumetric light is a froxel grid (Unreal's volumetric fog, Frostbite's unified "
      "volumetrics, HDRP, Godot 4): `froxels` is that method in the same graph (docs/methods.md, \"froxels\"), "
      "at HDRP's size (`froxels-hdrp`, 8-pixel columns) and Unreal's (`froxels-unreal`, 16), each plain and in "
      "the temporal mode, beside epipolar's three main profiles and brute force on the same frames, against the "
      "same float64 reference. `scripts/make-report.sh --froxels-only` reruns it and splices this section.\n")
    runs = json.loads((Path(bench_dir) / "bench.json").read_text())["runs"]
    r0 = runs[0]
    w, h = r0["size"]
    kind = "lavapipe CPU timings: compare ratios, not milliseconds" if r0["cpuDevice"] else "GPU timestamps"
    p(f"Measured on {date.today().isoformat()}{commit_note()} with `./build/host_example/lightscatter bench --config "
      f"bench/froxels.json`, at {w}x{h}, the median of {r0['frames']} frames after warm-up (the temporal mode "
      f"after the same frames, the scene still), on **{r0['device']}** ({kind}); memory is the plugin's peak "
      f"with aliasing at this size (`lightscatter budget`, estimated without a device; the temporal mode's two "
      f"history grids included).\n")
    p("Its epipolar and brute-force rows repeat configurations of the page's main run on another day and code "
      "(the index of runs above). Errors carry over; times, and their ratios to brute force, move from one run to "
      "another, so compare a row with this section's rows, not with the main run's.\n")
    note = load_note(bench_dir)
    if note:
        p(note + "\n")
    p("![time against error, froxels and the seeds' methods](performance/froxels.png)\n")
    p("| scene | configuration | median ms (p10-p90) | x brute force | mean rel. error | p99 | PSNR dB | "
      "memory MiB |")
    p("|---|---|---|---|---|---|---|---|")
    brute = {r["scene"]: r["time"]["median"] for r in runs if r["label"] == "brute-force"}
    for r in runs:
        t, e = r["time"], r.get("error", {})
        speed = brute.get(r["scene"], 0) / t["median"] if t["median"] else None
        p(f"| {r['scene']} | {r['label']} | {fmt(t['median'])} ({fmt(t['p10'])}-{fmt(t['p90'])}) | "
          f"{fmt(speed)} | {fmt(e.get('meanRelative'))} | {fmt(e.get('p99'))} | {fmt(e.get('psnrDb'))} | "
          f"{memory_cell(bench_dir, r['label'], w, h)} |")
    p("")
    # Where each family wins: each froxel configuration against epipolar balanced on each scene.
    by = {(r["scene"], r["label"]): r for r in runs}
    base = "epipolar balanced"
    p(f"Each froxel configuration against `{base}` on the same scene (time ratio, error ratio; below 1 "
      f"the froxels are faster or more accurate):\n")
    froxel_labels = sorted({r["label"] for r in runs if family(r["label"]) == "froxels"})
    scenes = sorted({r["scene"] for r in runs})
    p("| scene | " + " | ".join(froxel_labels) + " |")
    p("|---|" + "---|" * len(froxel_labels))
    for scene in scenes:
        b = by.get((scene, base))
        cells = []
        for label in froxel_labels:
            f = by.get((scene, label))
            be, fe = (b or {}).get("error", {}).get("meanRelative"), (f or {}).get("error", {}).get("meanRelative")
            if not b or not f or not b["time"]["median"] or not be:
                cells.append("-")
                continue
            cells.append(f"{fmt(f['time']['median'] / b['time']['median'])}x time, "
                         f"{fmt(fe / be) if fe is not None else '-'}x error")
        p(f"| {scene} | " + " | ".join(cells) + " |")
    p("")
    table = None
    if scaling_dir and (Path(scaling_dir) / "bench.json").exists():
        table = pl.light_rows(pl.load(scaling_dir))
        p("The cost of N shadowed spots (the atrium's `scenes/atrium_spots_N`, bench/lights_scaling.json, the "
          "same run as \"The cost of N lights\" above):\n")
        methods = sorted(table)
        p("| lights | " + " | ".join(f"{m} ms" for m in methods) + " |")
        p("|---|" + "---|" * len(methods))
        for n in sorted({r[0] for rows in table.values() for r in rows}):
            row = [next((x for x in table[m] if x[0] == n), None) for m in methods]
            p(f"| {n} | " + " | ".join(fmt(x[1]) if x else "-" for x in row) + " |")
        p("")
    out += where_each_wins(runs, base, table)
    return out


def where_each_wins(runs, base, lights_table=None):
    """The plain statement the section ends with: where each family won on this device and by how
    much, from the rows themselves (each froxel configuration against `base` on the same scenes,
    and each light's cost from the N-lights table), with the reason the method's design gives."""
    by = {(r["scene"], r["label"]): r for r in runs}
    scenes = sorted({r["scene"] for r in runs})
    labels = sorted({r["label"] for r in runs if family(r["label"]) == "froxels"})

    def err(r):
        return (r or {}).get("error", {}).get("meanRelative")

    out = ["Where each wins, on this device:\n"]
    for label in labels:
        pairs = []
        for scene in scenes:
            b, f = by.get((scene, base)), by.get((scene, label))
            if b and f and b["time"]["median"] and err(b) and err(f) is not None:
                pairs.append((scene, f["time"]["median"] / b["time"]["median"], err(f) / err(b)))
        if not pairs:
            continue
        faster = [x for x in pairs if x[1] < 1]
        worse = [x for x in pairs if x[2] > 1]
        t = sorted(x[1] for x in pairs)
        e = sorted(x[2] for x in pairs)
        worst = max(pairs, key=lambda x: x[2])
        out.append(f"- `{label}` took {fmt(t[0])}x to {fmt(t[-1])}x the time of `{base}` (faster on "
                   f"{len(faster)} of {len(pairs)} scenes) at {fmt(e[0])}x to {fmt(e[-1])}x its mean error "
                   f"(worse on {len(worse)} of {len(pairs)}; most on {worst[0]}, {fmt(worst[2])}x).")
    brute_pairs = []
    for scene in scenes:
        b, r = by.get((scene, base)), by.get((scene, "brute-force"))
        if b and r and err(b) and err(r):
            brute_pairs.append(err(b) / err(r))
    if brute_pairs:
        out.append(f"- `{base}` stayed within {fmt(max(brute_pairs))}x of brute force's mean error on every "
                   f"scene: its error is the shadow map's and the reference's, not its sampling's.")
    if lights_table:
        per = []
        for m, rows in sorted(lights_table.items()):
            if len(rows) > 1 and rows[-1][0] > rows[0][0]:
                per.append(f"`{m}` {fmt((rows[-1][1] - rows[0][1]) / (rows[-1][0] - rows[0][0]))} ms")
        if per:
            out.append("- Each shadowed spot beyond the first added " + ", ".join(per) + ": a light costs the "
                       "grid one injection pass, not a full-screen chain of its own.")
    out.append("")
    out.append("Why: the grid takes each light along its columns' centre rays only (a point or spot light's "
               "slice in closed form with its shadow at one point, a sun at the froxel's centre) and spreads "
               "that over the froxel, so a shaft narrower than a column (a grille, bars, struts) is blurred "
               "or lost; epipolar sampling and brute force march each pixel's own ray through the shadow "
               "map. What the grid costs grows with its froxels "
               "and its lights' injections, not with the screen's rays, which is where it wins; and it gives "
               "the volume itself (docs/methods.md, \"The exported volume\"), which fogs forward transparents "
               "and particles as no screen-space method can. `auto` never picks it, as it keeps to methods "
               "that hold the reference's accuracy (docs/methods.md, \"auto\").\n")
    return out
