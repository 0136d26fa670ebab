"""The 'Several lights' section: frames of several lights and the shadowed point light."""
import json
import sys
from datetime import date
from pathlib import Path

from .common import fmt, load_note
from .runs import commit_note

LIGHTS_HEADING = "## Several lights"


def lights_section(scaling_dir, rows_dir):
    """The section on frames of several lights and the shadowed point light: time and error of each
    method that takes them (a bench run of bench/lights.json) and the cost of N lights (a run of
    bench/lights_scaling.json, plotted by scripts/plot_lights.py). Lines of Markdown."""
    # The plot scripts beside this package compute the numbers their plots show.
    sys.path.insert(0, str(Path(__file__).resolve().parents[1]))
    import plot_lights as pl

    out = []
    p = out.append
    p(LIGHTS_HEADING + "\n")
    p("`FrameDescription::lights` gives the plugin several lights; it builds a chain per light that reaches the "
      "view and composites once (docs/model.md: `color * exp(-betaT S)` plus the sum of every light's Lin). The "
      "float64 reference sums the lights' Lin in the same way, each light with its own exact visibility. Every "
      "method takes a list of lights, and every method but analytic a point light's cube map (docs/methods.md); "
      "`auto` chooses per light. `bench/lights.json` lists the methods measured here, and each table row is one "
      "of them (`ran`: the method `auto` picked; froxels are measured in \"Against froxel fog\"). "
      "`scripts/make-report.sh --lights-only` reruns both benchmarks below, draws the plot and splices this "
      "section into the page.\n")
    rows_file = Path(rows_dir) / "bench.json" if rows_dir else None
    if rows_file and rows_file.exists():
        runs = json.loads(rows_file.read_text())["runs"]
        r0 = runs[0]
        w, h = r0["size"]
        kind = "lavapipe CPU timings" if r0["cpuDevice"] else "GPU timestamps"
        p(f"Time and error at {w}x{h} (`./build/host_example/lightscatter bench --config bench/lights.json --out "
          f"build/bench-lights`, measured on {date.today().isoformat()}{commit_note()}, the median of {r0['frames']} frames after "
          f"warm-up, on **{r0['device']}**, {kind}): `atrium_lights`, the atrium under its sun and two shadowed "
          f"spots, and `point_cage`, one point light with a cube shadow map in a cage of bars.\n")
        p("| scene | lights | configuration | ran | median ms (p10-p90) | mean rel. error | p99 | over 5% | PSNR dB "
          "| non-finite |")
        p("|---|---|---|---|---|---|---|---|---|---|")
        for r in runs:
            t, e = r["time"], r.get("error", {})
            p(f"| {r['scene']} | {r['lights']} | {r['label']} | {r['methodRan']} | {fmt(t['median'])} "
              f"({fmt(t['p10'])}-{fmt(t['p90'])}) | {fmt(e.get('meanRelative'))} | {fmt(e.get('p99'))} | "
              f"{fmt(100 * e['fractionOver5pct']) + '%' if e else '-'} | {fmt(e.get('psnrDb'))} | "
              f"{r['nonFinite']} |")
        p("")
        for name in sorted(Path("docs/performance").glob("strip_lights_*.png")):
            what = name.stem.replace("strip_lights_", "")
            p(f"Reference, {what.replace('_', ' ')} and error heat map (black 0, white 10% of the reference's "
              f"p99):\n\n![{what}](performance/{name.name})\n")
    scaling_file = Path(scaling_dir) / "bench.json" if scaling_dir else None
    if scaling_file and scaling_file.exists():
        runs = pl.load(scaling_dir)
        table = pl.light_rows(runs)
        r0 = runs[0]
        w, h = r0["size"]
        kind = ("lavapipe CPU timings: the 'GPU' time is the CPU running Vulkan" if r0["cpuDevice"]
                else "GPU timestamps")
        p("### The cost of N lights\n")
        p(f"The atrium under N = 1, 2, 4, 8 and 16 shadowed spots and nothing else (`scenes/atrium_spots_N`, "
          f"`tools/make_scenes/make_lights_scenes.py`; every spot's cone reaches the court in view, so every light costs its "
          f"chain), at {w}x{h}, balanced settings, the median of {r0['frames']} frames after warm-up, on "
          f"**{r0['device']}** ({kind}). Measured on {date.today().isoformat()}{commit_note()} with `./build/host_example/lightscatter "
          f"bench --config bench/lights_scaling.json --out build/bench-lights-scaling`; no error is measured "
          f"(`measureError: false`: a float64 reference at this size takes too long). The plugin's passes only: "
          f"the engine's shadow maps and shading per light are not included.\n")
        note = load_note(scaling_dir)
        if note:
            p(note + "\n")
        p("![time against the number of lights](performance/lights_scaling.png)\n")
        methods = sorted(table)
        p("| lights | " + " | ".join(f"{m} ms | {m} ms per light" for m in methods) + " |")
        p("|---|" + "---|---|" * len(methods))
        for n in sorted({r[0] for rows in table.values() for r in rows}):
            line = f"| {n} |"
            for m in methods:
                row = next((r for r in table[m] if r[0] == n), None)
                line += f" {fmt(row[1])} | {fmt(row[1] / n)} |" if row else " - | - |"
            p(line)
        p("")
        for m in methods:
            rows = table[m]
            if len(rows) > 1 and rows[0][1] > 0:
                n0, t0 = rows[0][0], rows[0][1]
                # 8 lights (the figure the issues compare) and the most measured.
                for n1, t1, _, _ in [r for r in rows[1:] if r[0] == 8 or r is rows[-1]]:
                    p(f"- {m}: {n1} lights take {fmt(t1 / t0)}x the time of {n0} "
                      f"({fmt((t1 - t0) / (n1 - n0))} ms for each light beyond the first).")
        p("")
    return out

