#!/usr/bin/python3
"""Writes docs/performance.md (to stdout) from a `lightscatter bench` run of the shipped scenes, one
of the hard-case suite, and `lightscatter budget --json`. Every figure on the page is read from
those files; nothing is typed in except the seed's published numbers."""
import json
import os
import re
import sys
from datetime import date
from pathlib import Path

# Seed 000, "Performance": GeForce GTX 680 at 2560x1600, spot light (time ms, memory MB).
SEED = {"brute-force": (91.18, None), "high-quality": (5.986, 88.0), "balanced": (3.269, 44.0),
        "high-performance": (2.267, 18.0)}


def fmt(x, digits=3):
    if x is None:
        return "-"
    if x == 0:
        return "0"
    if abs(x) >= 100:
        return f"{x:.0f}"
    return f"{x:.{digits}g}"


OCCLUDERS_HEADING = "## Beam tree against scene complexity"


def occluders_section(occ_dir):
    """The section on seed 004's beam tree against the number of boxes, from a bench run of
    bench/occluders.json (scripts/plot_occluders.py draws its plot). Lines of Markdown."""
    sys.path.insert(0, str(Path(__file__).resolve().parent))
    import plot_occluders as po

    runs = po.load(occ_dir)
    table = po.occluder_rows(runs)
    ref, ref_label = po.reference_ms(table)
    methods = po.beam_methods(table)
    r0 = runs[0]
    w, h = r0["size"]
    kind = ("lavapipe CPU timings: the 'GPU' time is the CPU running Vulkan, on the same two cores as the tree"
            if r0["cpuDevice"] else "GPU timestamps")
    out = []
    p = out.append
    p(OCCLUDERS_HEADING + "\n")
    p(f"Seed 004 says its beam tree cannot cope with highly tessellated scenes. `scenes/occluders_N` "
      f"(`scripts/make_occluder_scenes.py`) are N boxes (pillars and crates, varied heights, turned, on a "
      f"jittered grid over the same 16 m square) on a floor under a spot light shining down across them; the "
      f"host hands the plugin one oriented box per connected part of each glTF primitive (here each box and "
      f"the floor), so the tree gets N + 1 occluders. Measured "
      f"on {date.today().isoformat()} with `./build/host_example/lightscatter bench --config bench/occluders.json "
      f"--out build/bench-occluders` (`scripts/make-report.sh --occluders-only` runs it, draws the plot and "
      f"splices this section into the page) "
      f"at {w}x{h}, balanced settings, the median of {r0['frames']} frames after warm-up, on "
      f"**{r0['device']}** ({kind}). CPU ms is the tree's build (`FrameReport::cpuWork`: the tree, the lit "
      f"pyramids and the sampling planes' partition), GPU ms the plugin's passes; no error is measured here "
      f"(`measureError: false`: a float64 reference at this size takes too long).\n")
    note = load_note(occ_dir)
    if note:
        p(note + "\n")
    p("![beam tree against scene complexity](performance/occluders_scaling.png)\n")
    head = "| boxes | occluders given |"
    rule = "|---|---|"
    for m in methods:
        head += f" {m} CPU ms | {m} GPU ms | {m} CPU + GPU ms |"
        rule += "---|---|---|"
    head += f" {ref_label or 'epipolar'} GPU ms |"
    rule += "---|"
    p(head)
    p(rule)
    counts = sorted({r[0] for rows in table.values() for r in rows})
    for n in counts:
        given = next((r[1] for rows in table.values() for r in rows if r[0] == n and r[1] is not None), None)
        line = f"| {n} | {given if given is not None else '-'} |"
        for m in methods:
            row = next((r for r in table[m] if r[0] == n), None)
            line += (f" {fmt(row[2])} | {fmt(row[3])} | {fmt(row[2] + row[3])} |" if row else " - | - | - |")
        epi = next((r for r in table.get(ref_label, []) if r[0] == n), None)
        line += f" {fmt(epi[3]) if epi else '-'} |"
        p(line)
    p("")
    if ref is not None:
        for m in methods:
            n, how = po.crossover(table[m], ref)
            cpu_n, cpu_how = po.crossover([(c, g, cpu, 0.0) for c, g, cpu, _ in table[m]], ref)
            if how == "interpolated":
                text = (f"**Crossover ({m}): about {n:.0f} boxes.** Below it the tree's CPU build plus its GPU "
                        f"time is less than epipolar's GPU time ({fmt(ref)} ms, the median over these scenes); "
                        f"above it epipolar is cheaper. This is interpolated (linearly in log boxes and log ms) "
                        f"between the two measured counts around it, not measured at that count.")
            elif how == "below":
                text = (f"**Crossover ({m}): at or below {n} box(es).** Already at the smallest measured count "
                        f"the tree's CPU build plus its GPU time ({fmt(table[m][0][2] + table[m][0][3])} ms) is "
                        f"more than epipolar's GPU time ({fmt(ref)} ms) on this device.")
            else:
                text = (f"**Crossover ({m}): above {n} boxes.** Up to the largest measured count the tree's CPU "
                        f"build plus its GPU time stays below epipolar's GPU time ({fmt(ref)} ms).")
            p(text)
            if cpu_how == "interpolated":
                p(f"The CPU build alone reaches epipolar's GPU time at about {cpu_n:.0f} boxes (interpolated the "
                  f"same way).")
            elif cpu_how == "below":
                p(f"The CPU build alone already exceeds epipolar's GPU time at {cpu_n} box(es).")
            else:
                p(f"The CPU build alone stays below epipolar's GPU time up to {cpu_n} boxes.")
            p("")
        for m in methods:
            last = max((r for r in runs if r["method"] == m), key=po.boxes)
            top = max(last["passes"], key=lambda x: x["median"])
            first = min((r for r in runs if r["method"] == m), key=po.boxes)
            top_first = next((x for x in first["passes"] if x["name"] == top["name"]), None)
            p(f"Where {m}'s GPU time goes: at {po.boxes(last)} boxes its largest pass is '{top['name']}', "
              f"{fmt(top['median'])} of {fmt(last['time']['median'])} ms"
              + (f" ({fmt(top_first['median'])} ms at {po.boxes(first)} "
                 f"{'box' if po.boxes(first) == 1 else 'boxes'})" if top_first else "")
              + (". More boxes give more pyramids, and each of their faces is rasterised over the screen area "
                 "it covers, so this pass grows with the pyramids' overlapping screen area, not with the pixel "
                 "count alone." if "pyramid" in top["name"] else
                 ". More boxes cut the sampling planes into more parts, each drawn over the screen area it "
                 "covers." if "plane" in top["name"] else ".") + "\n")
    if ref is not None and r0["cpuDevice"]:
        text = ("On lavapipe both columns are CPU time, so the crossover above compares like with like only on "
                "this machine. On a GPU the passes take a small fraction of these milliseconds while the tree's "
                "build stays what it is (it runs on the CPU either way), so there the tree's build alone against "
                "epipolar's GPU time is the comparison that matters, and the crossover moves to fewer boxes.")
        seed_ms = SEED["balanced"][0]
        counts = []
        for m in methods:
            n, how = po.crossover([(c, g, cpu, 0.0) for c, g, cpu, _ in table[m]], seed_ms)
            if how == "interpolated":
                counts.append(f"about {n:.0f} boxes for {m}")
            elif how == "below":
                counts.append(f"at or below {n} box(es) for {m}")
        if counts:
            text += (f" Not measured here (no GPU machine), but for scale: seed 000's balanced epipolar frame is "
                     f"{seed_ms} ms on its GPU (GTX 680, 2560x1600), and this machine's tree build alone reaches "
                     f"that at {' and '.join(counts)} (interpolated as above); with the beam tree's own GPU passes "
                     f"on top, a GPU's crossover would lie at or below that count.")
        p(text + "\n")
    return out


def load_note(bench_dir):
    """A sentence on the machine's load average around a timing run (load-before.txt and
    load-after.txt, `uptime` written by scripts/make-report.sh), or None without them: on a CPU
    device the timings share the cores with whatever else runs."""
    loads, worst = [], 0.0
    for when in ("before", "after"):
        f = Path(bench_dir) / f"load-{when}.txt"
        m = re.search(r"load average: ([\d.]+), ([\d.]+), ([\d.]+)", f.read_text()) if f.exists() else None
        if m:
            loads.append(f"{m.group(1)} {when} the run" + (" (the run's own threads included)" if when == "after" else ""))
            if when == "before":
                worst = float(m.group(1))
    if not loads:
        return None
    cores = os.cpu_count() or 1
    busy = ("other work shared the CPU, so treat single figures as rough; the trend over the counts is "
            "what to read" if worst > 0.5 * cores else "little else ran")
    return f"The machine's load average (1 minute) was {' and '.join(loads)}, on {cores} cores: {busy}."


LIGHTS_HEADING = "## Several lights"


def lights_section(scaling_dir, rows_dir):
    """The section on frames of several lights and the shadowed point light: time and error of each
    method that takes them (a bench run of bench/lights.json) and the cost of N lights (a run of
    bench/lights_scaling.json, plotted by scripts/plot_lights.py). Lines of Markdown."""
    sys.path.insert(0, str(Path(__file__).resolve().parent))
    import plot_lights as pl

    out = []
    p = out.append
    p(LIGHTS_HEADING + "\n")
    p("`FrameDescription::lights` gives the plugin several lights; it builds a chain per light that reaches the "
      "view and composites once (docs/model.md: `color * exp(-betaT S)` plus the sum of every light's Lin). The "
      "float64 reference sums the lights' Lin in the same way, each light with its own exact visibility. Not "
      "every method takes several lights, nor a point light's cube shadow map: `bench/lights.json` lists, per "
      "scene, the methods that do, and each table row is one of them (`ran`: the method `auto` picked). "
      "`scripts/make-report.sh --lights-only` reruns both benchmarks below, draws the plot and splices this "
      "section into the page.\n")
    rows_file = Path(rows_dir) / "bench.json" if rows_dir else None
    if rows_file and rows_file.exists():
        runs = json.loads(rows_file.read_text())["runs"]
        r0 = runs[0]
        w, h = r0["size"]
        kind = "lavapipe CPU timings" if r0["cpuDevice"] else "GPU timestamps"
        p(f"Time and error at {w}x{h} (`./build/host_example/lightscatter bench --config bench/lights.json --out "
          f"build/bench-lights`, measured on {date.today().isoformat()}, the median of {r0['frames']} frames after "
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
        p(f"The atrium under N = 1, 2, 4 and 8 shadowed spots and nothing else (`scenes/atrium_spots_N`, "
          f"`scripts/make_lights_scenes.py`; every spot's cone reaches the court in view, so every light costs its "
          f"chain), at {w}x{h}, balanced settings, the median of {r0['frames']} frames after warm-up, on "
          f"**{r0['device']}** ({kind}). Measured on {date.today().isoformat()} with `./build/host_example/lightscatter "
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
                (n0, t0, _, _), (n1, t1, _, _) = rows[0], rows[-1]
                p(f"- {m}: {n1} lights take {fmt(t1 / t0)}x the time of {n0} "
                  f"({fmt((t1 - t0) / (n1 - n0))} ms for each light beyond the first).")
        p("")
    return out


def splice_section(page, heading, lines, before="## Scaling"):
    """`page` (Markdown) with the section starting at `heading` replaced by `lines`, up to the next
    '## ' heading; inserted before the `before` heading if the page has none yet."""
    text = page.split("\n")
    section = "\n".join(lines).rstrip("\n").split("\n") + [""]
    if heading in text:
        start = text.index(heading)
        end = next((i for i in range(start + 1, len(text)) if text[i].startswith("## ")), len(text))
        return "\n".join(text[:start] + section + text[end:])
    at = text.index(before) if before in text else len(text)
    return "\n".join(text[:at] + section + text[at:])


GPU_HEADING = "## GPU timings"


def gpu_section(gpu_dir):
    """The GPU machine's run of bench/full.json (scripts/gpu-bench.sh): per scene, every run's median
    frame time and its speed-up over brute force in the same run, and the per-pass times of epipolar
    balanced; without that run, a line saying so."""
    out = [GPU_HEADING, ""]
    p = out.append
    path = gpu_dir / "bench.json" if gpu_dir else None
    if not path or not path.exists():
        p("No GPU machine has been lent to a session since this section was added, so it has no figures. On one, "
          "`scripts/gpu-bench.sh prepare` (here) and `scripts/gpu-bench.sh run OUT` (there, with `.gl` and "
          "`build-gpu/stage` carried) run `bench/full.json` in under 10 minutes, and "
          "`scripts/write_report.py --gpu-section OUT docs/performance.md` fills this section.\n")
        return out
    runs = [r for r in json.loads(path.read_text())["runs"] if not r["cpuDevice"]]
    if not runs:
        p(f"`{path}` holds CPU timings only: not a GPU run.\n")
        return out
    first = runs[0]
    p(f"Device **{first['device']}**, driver {first['driver']}: GPU timestamps, median of {first['frames']} frames "
      "after warm-up (`scripts/gpu-bench.sh run`, bench/full.json). Speed-up is brute force's median over the "
      "run's, same scene and size, same run. Errors are not measured there (they do not depend on the device; "
      "the tables above give them).\n")
    for scene in sorted({r["scene"] for r in runs}):
        rows = [r for r in runs if r["scene"] == scene and r["family"] == "profiles"]
        brute = {tuple(r["size"]): r["time"]["median"] for r in runs
                 if r["scene"] == scene and r["method"] == "brute-force"}
        if not rows:
            continue
        p(f"### {scene}\n")
        p("| run | size | median ms | p90 ms | speed-up over brute force |")
        p("|---|---|---|---|---|")
        for r in rows:
            b = brute.get(tuple(r["size"]))
            t = r["time"]
            p(f"| {r['label']} | {r['size'][0]}x{r['size'][1]} | {fmt(t['median'])} | {fmt(t['p90'])} | "
              f"{fmt(b / t['median']) + 'x' if b and t['median'] > 0 else '-'} |")
        p("")
        balanced = next((r for r in rows if r["method"] == "epipolar" and r.get("profile") == "balanced"), None)
        if balanced:
            total = sum(x["median"] for x in balanced["passes"]) or 1.0
            p(f"Epipolar balanced, per pass ({scene}):\n")
            p("| pass | median ms | share |")
            p("|---|---|---|")
            for x in balanced["passes"]:
                p(f"| {x['name']} | {fmt(x['median'])} | {100.0 * x['median'] / total:.1f}% |")
            p("")
    return out


def summary_lines(runs, rs, trees_dir, seed_dir):
    """The page's first section: epipolar balanced against brute force on every scene at the run's
    size, where the time goes, the screen size where epipolar overtakes, the trees at high quality
    and seed 000's own size, each against the target we hold the method to."""
    out = []
    p = out.append
    w, h = runs[0]["size"]
    p(f"## At a glance ({w}x{h})\n")
    p("Epipolar (balanced) against brute force, same scene, size and run. Targets: at least 30x brute force's "
      "speed with a mean error no more than brute force's plus 0.5 percentage points; the full-screen passes "
      "(unwarp and fix-up, which run per pixel) under 10% of the total.\n")
    p("| scene | epipolar balanced ms | brute force ms | speed-up | epipolar error | brute-force error | "
      "ray march share | full-screen share |")
    p("|---|---|---|---|---|---|---|---|")
    for scene in sorted({r["scene"] for r in runs}):
        speed, b, e = rs.speedup(runs, scene, "epipolar balanced", (w, h))
        if not speed:
            continue
        sh = rs.shares(e)
        ee, be = e.get("error", {}).get("meanRelative"), b.get("error", {}).get("meanRelative")
        p(f"| {scene} | {fmt(e['time']['median'])} | {fmt(b['time']['median'])} | {fmt(speed)}x | "
          f"{fmt(ee)} | {fmt(be)} | {f'{100 * sh[0]:.0f}%' if sh else '-'} | {f'{100 * sh[1]:.0f}%' if sh else '-'} |")
    p("")
    floors = [t for r in runs if r["family"] == "profiles" and r["method"] == "cone-march" and tuple(r["size"]) == (w, h)
              for n, t in rs.pass_times(r).items() if n == "composite"]
    if floors:
        p(f"For scale: a full-screen pass that only composites (cone-march's composite: read its Lin and the depth, "
          f"read-modify-write the engine's color) takes {fmt(min(floors))} to {fmt(max(floors))} ms here, so on this "
          "device no per-pixel pass costs less; the unwarp does that and the bilateral search of four samples, "
          "and the fix-up marches the pixels the unwarp could not serve. Where the unwarp's time goes, part by "
          "part, and why 10% is below this device's floor: [epipolar.md](epipolar.md#where-the-unwarps-time-goes).\n")
    # Where a scene misses the 30x target: what the rest of the frame costs, that is the best a free
    # ray march could give.
    short = []
    for scene in sorted({r["scene"] for r in runs}):
        speed, b, e = rs.speedup(runs, scene, "epipolar balanced", (w, h))
        sh = rs.shares(e) if speed else None
        if not sh or speed >= 30 or sh[0] <= 0:
            continue
        rest = sh[3] * (1 - sh[0])
        unwarp = sh[2].get("unwarp epipolar to screen")
        short.append(f"{scene} ({fmt(speed)}x): everything but the ray march takes {fmt(rest)} ms"
                     + (f", the unwarp {fmt(unwarp)} of them" if unwarp else "")
                     + f", so even a free ray march would give at most {fmt(b['time']['median'] / rest)}x")
    if short:
        p("Where the 30x target is missed, the floor: " + "; ".join(short) + ". Brute force is cheap on these "
          "scenes (short rays through the light's volume), and on this device every per-pixel pass costs its "
          "share (below).\n")
    crossings = []
    for scene in sorted({r["scene"] for r in runs}):
        table, cross = rs.crossover(runs, scene)
        _, _, e = rs.speedup(runs, scene, "epipolar balanced", (w, h))
        if not table or not e or not any(n.startswith("ray march") for n in rs.pass_times(e)):
            continue  # no shadow map: both methods compute the same closed form
        if cross is None:
            crossings.append(f"{scene}: not within the sizes measured")
        elif cross == 0:
            crossings.append(f"{scene}: ahead at every size measured, from {table[0][1][0]}x{table[0][1][1]}")
        else:
            crossings.append(f"{scene}: about {rs.side_of(cross)} ({cross / 1e6:.2g} million pixels)")
    if crossings:
        p("Where epipolar (balanced settings) overtakes brute force, interpolated between the screen sizes "
          "measured ([Scaling](#scaling) has the times): " + "; ".join(crossings) + ".\n")
    trees = rs.load_runs(trees_dir) if trees_dir else []
    if trees:
        parts = [f"{scene} {fmt(rs.march_ms(off) / rs.march_ms(on))}x"
                 for scene, on, off in rs.tree_pairs(trees) if rs.march_ms(on) > 0]
        p("The min/max trees at high quality, on the ray march alone (target 8x, seed 000's 8.6x): "
          + ", ".join(parts) + " ([the trees](#the-minmax-trees-at-high-quality)).\n")
    seed_rows, first = rs.seed_size_rows(seed_dir) if seed_dir else ({}, None)
    if seed_rows:
        sw, sh_ = first["size"]
        parts = []
        for prof in ("high-quality", "balanced", "high-performance"):
            if prof in seed_rows:
                ours = ", ".join(f"{sc} {fmt(x)}x" for sc, x, _ in seed_rows[prof])
                parts.append(f"{prof} {ours} (seed {SEED['brute-force'][0] / SEED[prof][0]:.1f}x)")
        p(f"At seed 000's size, {sw}x{sh_}, the speed-ups over brute force: " + "; ".join(parts) +
          " ([Beside seed 000](#beside-seed-000)).\n")
    return out


def kept_section(page_text, heading):
    """The section at `heading` of the page as it was (up to the next '## '), for a section whose
    results this run does not have: it stays as last measured, with its own date and command."""
    text = page_text.split("\n")
    if heading not in text:
        return []
    start = text.index(heading)
    end = next((i for i in range(start + 1, len(text)) if text[i].startswith("## ")), len(text))
    return text[start:end]


SLICES_HEADING = "## Seed 002: slice planes"


def slices_section(slices_dir):
    """Seed 002's slice planes against epipolar and brute force (bench/slices.json), per scene, with
    the 8-bit targets' banding strips."""
    out = []
    p = out.append
    slice_runs = json.loads((slices_dir / "bench.json").read_text())["runs"]
    w, h = slice_runs[0]["size"]
    p(f"{SLICES_HEADING} at {w}x{h}\n")
    p(f"`slices` against epipolar (balanced) and brute force on the spot and directional scenes at {w}x{h} "
      f"(`bench/slices.json`, measured on {date.fromtimestamp((slices_dir / 'bench.json').stat().st_mtime).isoformat()}: {slice_runs[0]['frames']} frame after "
      f"{slice_runs[0].get('warmup', 1)} of warm-up per row, on {slice_runs[0]['device']}; at this size brute "
      "force takes seconds per frame on a CPU; `scripts/make-report.sh --slices-only` reruns it and replaces this "
      "section). Each "
      "slices row is a plane count and an accumulation target (docs/methods.md): float16, float32, rgba8 "
      "(seed 002's four 8-bit channels, rounded to nearest) and rgba8-dither (the same with stochastic "
      "rounding). Speed-up and error of every row are against brute force in the same run.\n")
    p(f"![slices against epipolar and brute force](performance/slices_{w}x{h}.png)\n")
    for scene in sorted({r["scene"] for r in slice_runs}):
        rows = [r for r in slice_runs if r["scene"] == scene]
        brute = next((r for r in rows if r["method"] == "brute-force"), None)
        p(f"### {scene}\n")
        p("| configuration | median ms | speed-up over brute force | mean rel. error | brute force's error | "
          "over 5% |")
        p("|---|---|---|---|---|---|")
        for r in rows:
            t, e = r["time"], r.get("error", {})
            speed = brute["time"]["median"] / t["median"] if brute and t["median"] > 0 else None
            label = "slices balanced (128 planes, float16)" if r["method"] == "slices" and \
                r["family"] == "profiles" else r["label"]
            p(f"| {label} | {fmt(t['median'])} | {fmt(speed) + 'x' if speed else '-'} | "
              f"{fmt(e.get('meanRelative'))} | {fmt(brute['error']['meanRelative']) if brute else '-'} | "
              f"{fmt(100 * e['fractionOver5pct']) + '%' if e else '-'} |")
        p("")
    banding = [r for r in slice_runs if r["method"] == "slices" and "rgba8" in r["label"]]
    if banding:
        p("The 8-bit targets' banding, window_room at 256 planes, seed 002's rounding and stochastic rounding "
          "(reference, result, error heat map):\n")
        for r in banding:
            if r["scene"] == "window_room" and "256" in r["label"]:
                name = f"strip_slices_{r['label'].replace(' ', '_')}.png"
                p(f"{r['label']}:\n\n![{r['label']}](performance/{name})\n")
    return out


def slices_lines(slices_dir):
    lines = slices_section(slices_dir)
    return lines, lines[0].rstrip("\n")


def flicker_lines(bench_dir, page):
    sys.path.insert(0, str(Path(__file__).resolve().parent))
    import report_flicker as rf
    # Its heat maps go beside the page.
    return rf.flicker_section(bench_dir, page.parent / "performance" if page else None), rf.FLICKER_HEADING


# write_report.py --NAME-section DIR... [PAGE.md]: one section alone, or spliced into the page in
# place (the rest of the page is left as it is). NAME: its result folders, and how to make it.
SECTIONS = {
    "--gpu-section": (1, lambda dirs, page: (gpu_section(dirs[0]), GPU_HEADING)),
    "--flicker-section": (1, lambda dirs, page: flicker_lines(dirs[0], page)),
    "--occluders-section": (1, lambda dirs, page: (occluders_section(dirs[0]), OCCLUDERS_HEADING)),
    "--lights-section": (2, lambda dirs, page: (lights_section(dirs[0], dirs[1]), LIGHTS_HEADING)),
    "--slices-section": (1, lambda dirs, page: slices_lines(dirs[0])),
}


def main():
    if len(sys.argv) > 1 and sys.argv[1] in SECTIONS:
        count, make = SECTIONS[sys.argv[1]]
        dirs = [Path(d) for d in sys.argv[2:2 + count]]
        page = Path(sys.argv[2 + count]) if len(sys.argv) > 2 + count else None
        lines, heading = make(dirs, page)
        if page:
            page.write_text(splice_section(page.read_text(), heading, lines))
        else:
            print("\n".join(lines))
        return
    bench_dir, hard_dir, config = Path(sys.argv[1]), Path(sys.argv[2]), sys.argv[3]
    slices_dir = Path(sys.argv[4]) if len(sys.argv) > 4 and sys.argv[4] else None
    occluders_dir = Path(sys.argv[5]) if len(sys.argv) > 5 and sys.argv[5] else None
    lights_scaling_dir = Path(sys.argv[6]) if len(sys.argv) > 6 and sys.argv[6] else None
    lights_dir = Path(sys.argv[7]) if len(sys.argv) > 7 and sys.argv[7] else None
    flicker_dir = Path(sys.argv[8]) if len(sys.argv) > 8 and sys.argv[8] else None
    # The timing run (measureError false, on a quiet machine) and the same configurations' errors
    # from a run of one frame each; then min/max trees at high quality, and seed 000's screen size.
    errors_dir = Path(sys.argv[9]) if len(sys.argv) > 9 and sys.argv[9] else None
    trees_dir = Path(sys.argv[10]) if len(sys.argv) > 10 and sys.argv[10] else None
    seed_dir = Path(sys.argv[11]) if len(sys.argv) > 11 and sys.argv[11] else None
    old_page = Path("docs/performance.md").read_text() if Path("docs/performance.md").exists() else ""
    sys.path.insert(0, str(Path(__file__).resolve().parent))
    import report_speed as rs
    runs = json.loads((bench_dir / "bench.json").read_text())["runs"]
    if errors_dir:
        runs = rs.merge_errors(runs, rs.load_runs(errors_dir))
    hard = json.loads((hard_dir / "bench.json").read_text())["runs"]
    budget = json.loads((bench_dir / "budget.json").read_text())
    first = runs[0]
    cpu = first["cpuDevice"]
    kind = "CPU timings (lavapipe is a CPU Vulkan driver: never compare these with GPU milliseconds)" if cpu \
        else "GPU timestamps"
    out = []
    p = out.append
    p("# Performance: time against error\n")
    p(f"Generated by `scripts/make-report.sh {config}` on {date.today().isoformat()}. Device: "
      f"**{first['device']}**, driver {first['driver']}; {kind}. Every time is the median of "
      f"{first['frames']} frames after warm-up, per-pass GPU timestamps summed over the plugin's passes "
      "(the engine's own shadow map and shading are not included). Every error is Lin against the float64 "
      "reference renderer (exact visibility against the scene's triangles through a BVH, adaptive quadrature; "
      "`host_example/exact_renderer`), at the same pixel centres: mean relative error = sum |a - b| / sum |b| over "
      "every pixel and channel; p99 and max are of |a - b| divided by the reference's 99th percentile; "
      "'over 5%' counts pixels off by more than 5% of that percentile; PSNR is of the tone-mapped 8-bit "
      "images.\n")
    if errors_dir:
        p("The times come from a run with `measureError: false` on a quiet machine; the errors from a second run "
          "of the same configurations, one frame each, matched row by row (an error does not depend on how "
          "fast the device is, so that run need not be quiet).\n")
    if cpu:
        p("> No GPU figures on this page's tables: they are lavapipe's. The section [GPU timings](#gpu-timings) "
          "holds a GPU machine's run of bench/full.json when one was lent (`scripts/gpu-bench.sh`).\n")
    out += summary_lines(runs, rs, trees_dir, seed_dir)

    scenes = sorted({r["scene"] for r in runs})
    for scene in scenes:
        rows = [r for r in runs if r["scene"] == scene and r["family"] == "profiles"]
        brute = next((r for r in rows if r["method"] == "brute-force"), None)
        w, h = rows[0]["size"]
        p(f"## {scene} ({w}x{h})\n")
        scene_file = Path("scenes") / f"{scene}.json"
        light = json.loads(scene_file.read_text()).get("light", {}) if scene_file.exists() else {}
        if light.get("type") == "point" and not light.get("shadowMapSize"):
            p("This scene's point light has no shadow map (the scene gives it none; `scenes/point_cage` is the "
              "one with a cube map, in [Several lights](#several-lights)): epipolar and brute force compute the "
              "same closed form (the point-light table), analytic seed 001's arctangent (which ignores the "
              "phase function's shape and extinction), cone-march samples the same integrand; the error is "
              "mostly the shadows the reference has and the plugin lacks.\n")
        p(f"![time against error, {scene}](performance/time_vs_error_{scene}.png)\n")
        p("| configuration | slices x samples | median ms (p10-p90) | speed-up over brute force | mean rel. error | "
          "p99 | max | over 5% | PSNR dB | non-finite |")
        p("|---|---|---|---|---|---|---|---|---|---|")
        for r in rows:
            if r["method"] == "auto" and r.get("methodRan"):
                r = dict(r, label=f"auto (ran {r['methodRan']})")
            if r["method"] == "cone-march":
                r = dict(r, label=f"cone-march ({r.get('coneSamples', 32)} samples)")
            t = r["time"]
            e = r.get("error", {})
            speed = brute["time"]["median"] / t["median"] if brute and t["median"] > 0 else None
            ss = f"{r['slices']} x {r['samples']}" if r["method"] == "epipolar" else "-"
            p(f"| {r['label']} | {ss} | {fmt(t['median'])} ({fmt(t['p10'])}-{fmt(t['p90'])}) | "
              f"{fmt(speed) + 'x' if speed else '-'} | {fmt(e.get('meanRelative'))} | {fmt(e.get('p99'))} | "
              f"{fmt(e.get('max'))} | {fmt(100 * e['fractionOver5pct']) + '%' if e else '-'} | "
              f"{fmt(e.get('psnrDb'))} | {r['nonFinite']} |")
        p("")
        balanced = next((r for r in rows if r["label"] == "epipolar balanced"), None)
        if balanced:
            out += rs.pass_breakdown_lines(balanced, fmt)
        sweeps = [r for r in runs if r["scene"] == scene and r["family"] not in ("profiles", "cone")]
        if sweeps:
            p("Sweeps from the balanced profile (one parameter at a time; the speed-up is over brute force at the "
              "same screen and shadow-map size, same run):\n")
            p("| sweep | median ms | speed-up over brute force | mean rel. error | over 5% |")
            p("|---|---|---|---|---|")
            for r in sweeps:
                e = r.get("error")
                b = next((x for x in runs if x["scene"] == scene and x["method"] == "brute-force"
                          and tuple(x["size"]) == tuple(r["size"]) and x["shadowMapSize"] == r["shadowMapSize"]
                          and x["family"] in ("profiles", "size", "shadowMapSize")), None)
                speed = b["time"]["median"] / r["time"]["median"] if b and r["time"]["median"] > 0 else None
                p(f"| {r['label']} | {fmt(r['time']['median'])} | {fmt(speed) + 'x' if speed else '-'} | "
                  f"{fmt(e['meanRelative']) if e else '(timing only)'} | "
                  f"{fmt(100 * e['fractionOver5pct']) + '%' if e else '-'} |")
            p("")
        p(f"Reference, epipolar (balanced) and error heat map (black 0, white 10% of the reference's p99):\n")
        p(f"![strip](performance/strip_{scene}_epipolar_balanced.png)\n")
        p(f"Brute force:\n\n![strip](performance/strip_{scene}_brute-force.png)\n")

    cone = [r for r in runs if r["family"] == "cone"]
    if cone:
        p("## Seed 003: marching only inside the cone\n")
        p("Seed 003's comparison on each scene: the same fixed number of samples per pixel over the whole ray "
          "(naive), over the part inside the spot's cone and range (cone), and inside the cone without "
          "shadow-map look-ups (no-shadow-sampling, the seed's low-end mode: no shadows at all). A "
          "directional or point light has no cone, so there cone and naive march the same interval. Same "
          "scene, size and settings for every row; time and error as above.\n")
        for scene in scenes:
            rows = [r for r in cone if r["scene"] == scene]
            if not rows:
                continue
            brute = next((r for r in runs if r["scene"] == scene and r["method"] == "brute-force"
                          and r["family"] == "profiles"), None)
            p(f"### {scene}\n")
            p("| mode | samples per pixel | median ms | speed-up over brute force | mean rel. error | over 5% |")
            p("|---|---|---|---|---|---|")
            for r in sorted(rows, key=lambda r: (r["label"].split()[0], r["coneSamples"])):
                t, e = r["time"], r.get("error", {})
                speed = brute["time"]["median"] / t["median"] if brute and t["median"] > 0 else None
                p(f"| {r['label'].split()[0]} | {r['coneSamples']} | {fmt(t['median'])} | "
                  f"{fmt(speed) + 'x' if speed else '-'} | {fmt(e.get('meanRelative'))} | "
                  f"{fmt(100 * e['fractionOver5pct']) + '%' if e else '-'} |")
            p("")

    if slices_dir and (slices_dir / "bench.json").exists():
        out += slices_section(slices_dir)

    if occluders_dir and (occluders_dir / "bench.json").exists():
        out += occluders_section(occluders_dir)
    if lights_scaling_dir or lights_dir:
        out += lights_section(lights_scaling_dir, lights_dir)

    if flicker_dir and (flicker_dir / "bench.json").exists():
        sys.path.insert(0, str(Path(__file__).resolve().parent))
        import report_flicker as rf
        out += rf.flicker_section(flicker_dir, "docs/performance")
    else:
        out += kept_section(old_page, "## Temporal stability")

    p("## Scaling\n")
    size_tables = [(scene, rs.crossover(runs, scene)[0]) for scene in scenes]
    if any(t for _, t in size_tables):
        p("Epipolar (balanced settings) against brute force as the screen grows, same run (median ms; the "
          "largest size is the tables' own run):\n")
        p("| scene | screen | epipolar ms | brute force ms | speed-up |")
        p("|---|---|---|---|---|")
        for scene, table in size_tables:
            for _, size, ratio, epipolar_ms, brute_ms in table:
                p(f"| {scene} | {size[0]}x{size[1]} | {fmt(epipolar_ms)} | {fmt(brute_ms)} | {fmt(ratio)}x |")
        p("")
    for name, what in (("scaling_screen", "screen size"), ("scaling_shadow_map", "shadow-map size"),
                       ("scaling_slices_samples", "slices x samples")):
        if Path("docs/performance", f"{name}.png").exists():
            p(f"Time against {what}:\n\n![{what}](performance/{name}.png)\n")

    if trees_dir:
        out += rs.trees_section(trees_dir, fmt)
    p("## Beside seed 000\n")
    seed_rows, seed_first = rs.seed_size_rows(seed_dir) if seed_dir else ({}, None)
    if seed_rows:
        sw, sh_ = seed_first["size"]
        p(f"The seed's figures are a GeForce GTX 680 at 2560x1600 with a spot light. Ours: `bench/seed_size.json`, "
          f"the same profiles and brute force at {sw}x{sh_} on the device above ({seed_first['frames']} frames after "
          "warm-up each, timings only), so the ratios can be set side by side; the milliseconds cannot (a CPU "
          "device runs the per-pixel passes far slower, relative to the rest, than a GPU).\n")
        p(f"| profile | seed ms | seed speed-up over brute force | ours at {sw}x{sh_}: speed-up over brute force, "
          "per scene | seed memory MB | ours: peak MiB at 2560x1600 (aliased) | ours: total MiB |")
    else:
        p("The seed's figures are a GeForce GTX 680 at 2560x1600 with a spot light; ours are the device above at "
          "the size above, so only the ratios can be set side by side.\n")
        p("| profile | seed ms | seed speed-up over brute force | ours: speed-up over brute force (mean over "
          "scenes) | seed memory MB | ours: peak MiB at 2560x1600 (aliased) | ours: total MiB |")
    p("|---|---|---|---|---|---|---|")
    for prof in ("high-quality", "balanced", "high-performance"):
        ms, mb = SEED[prof]
        if seed_rows:
            ours = ", ".join(f"{sc} {fmt(x)}x" for sc, x, _ in seed_rows.get(prof, [])) or "-"
        else:
            ratios = []
            for scene in scenes:
                b = next((r for r in runs if r["scene"] == scene and r["method"] == "brute-force" and r["family"] == "profiles"), None)
                e = next((r for r in runs if r["scene"] == scene and r["label"] == f"epipolar {prof}"), None)
                if b and e:
                    ratios.append(b["time"]["median"] / e["time"]["median"])
            ours = fmt(sum(ratios) / len(ratios)) + "x" if ratios else "-"
        bud = next((x for x in budget if x["profile"] == prof), None)
        p(f"| {prof} | {ms} | {SEED['brute-force'][0] / ms:.1f}x | {ours} | {mb} | "
          f"{bud['peakBytes'] / 2**20:.1f} | {bud['totalBytes'] / 2**20:.1f} |")
    p("\nMemory sizes come from `lightscatter budget` (estimated without a device: texels packed, 64 KiB "
      "alignment); docs/epipolar.md says what brought them to the seed's column.\n")
    if seed_rows:
        # Where a scene falls short of the seed's ratio, and whether a free ray march would close it.
        misses, march_bound = [], True
        for prof, rows in seed_rows.items():
            seed_speed = SEED["brute-force"][0] / SEED[prof][0]
            for scene, speed, floor in rows:
                if speed < seed_speed and floor is not None:
                    misses.append(f"{scene} {prof} {fmt(speed)}x against {seed_speed:.1f}x (a free ray march "
                                  f"would give at most {fmt(floor)}x)")
                    march_bound = march_bound and floor >= seed_speed
        if misses:
            p("Where ours falls short of the seed's ratio: " + "; ".join(misses) + ". " +
              ("A free ray march would reach the seed's ratio in each, so it is the ray march that keeps them "
               "below ([where its steps go](epipolar.md#where-the-ray-marchs-steps-go))."
               if march_bound else
               "Even a free ray march would not reach the seed's ratio there: the rest of the frame sets the "
               "floor ([the unwarp's share](epipolar.md#where-the-unwarps-time-goes)).") + "\n")

    p("## The hard-case suite\n")
    bounds = {}
    test = Path("tests/host/hard_suite_test.cpp").read_text()
    # Bound{epipolar, bruteForce, ...}: the first two fields are this table's.
    for name, fields in re.findall(r'\{"(\w+)", \{([\d., ]+)\}\}', test):
        bounds[name] = tuple(float(x) for x in fields.split(","))[:2]
    default = tuple(float(x) for x in re.search(r"kDefault\{([\d., ]+)\}", test).group(1).split(","))[:2]
    w, h = hard[0]["size"]
    p(f"Every hard case of [model.md](model.md#hard-cases) as a scene (`scenes/hard`, from `tools/make_hard_cases.py`), {w}x{h}, balanced "
      "profile. `test_hard_suite` asserts finite pixels and the bound below for each (mean relative error); thin "
      "media must stay within 1% of float64. A point light without a cube shadow map is unshadowed in the "
      "plugin but shadowed in the reference, so its cases count the missing shadows as error.\n")
    def named_bounds(start, end):
        block = test.split(start)[1].split(end)[0]
        return ({n: float(v) for n, v in re.findall(r'\{"(\w+)", ([\d.]+)\}', block)},
                float(re.search(end + r" = ([\d.]+)", test).group(1)))
    # The methods beside epipolar and brute force, each with its bounds in the test.
    others = [("slices", *named_bounds("kSlicesBounds", "kSlicesDefault")),
              ("beam-tree-analytic", *named_bounds("kBeamTreeBounds", "kBeamTreeDefault")),
              ("beam-tree-sampling", *named_bounds("kBeamTreeSamplingBounds", "kBeamTreeSamplingDefault"))]
    header = "| case | epipolar error | bound | brute-force error | bound |"
    for name, _, _ in others:
        header += f" {name} error | bound |"
    p(header + " non-finite |")
    p("|---" * (5 + 2 * len(others) + 1) + "|")
    for scene in sorted({r["scene"] for r in hard}):
        epi = next(r for r in hard if r["scene"] == scene and r["method"] == "epipolar")
        bf = next(r for r in hard if r["scene"] == scene and r["method"] == "brute-force")
        b = bounds.get(scene, default)
        nonfinite = epi['nonFinite'] + bf['nonFinite']
        line = (f"| {scene.replace('_', ' ')} | {fmt(epi['error']['meanRelative'])} | {b[0]} | "
                f"{fmt(bf['error']['meanRelative'])} | {b[1]} |")
        for name, table, fallback in others:
            r = next((r for r in hard if r["scene"] == scene and r["method"] == name), None)
            if r:
                nonfinite += r['nonFinite']
                line += f" {fmt(r['error']['meanRelative'])} | {table.get(scene, fallback)} |"
            else:
                line += " - | - |"  # not run: a directional light (beam tree), a cube map (slices, beam tree)
        p(line + f" {nonfinite} |")
    p("\nThe beam-tree methods run on the point and spot cases only (\"-\": a directional light). The host "
      "gives them one box per connected part of the scene's glTF primitives. A point light's cube shadow map "
      "(point in cage) is sampled by epipolar and brute force only.\n")

    p("## Which profile for which budget\n")
    for scene in scenes:
        rows = [r for r in runs if r["scene"] == scene and r["family"] == "profiles" and r["method"] == "epipolar"
                and "error" in r]
        rows.sort(key=lambda r: r["time"]["median"])
        front, best = [], float("inf")
        for r in rows:
            if r["error"]["meanRelative"] < best:
                front.append(r)
                best = r["error"]["meanRelative"]
        names = ", ".join(f"{r['label'].replace('epipolar ', '')} ({fmt(r['time']['median'])} ms, "
                          f"{fmt(100 * r['error']['meanRelative'])}%)" for r in front)
        p(f"- {scene}: the profiles on the Pareto front, cheapest first: {names}.")
    p("\nPick the cheapest profile on the front whose error you can accept; a profile off the front is beaten "
      "on both counts by one on it.\n")
    p("How far each one-parameter sweep moves the error (largest minus smallest mean relative error over the "
      "sweep, averaged over the scenes), largest first:\n")
    spans = {}
    for family in ("slices", "samples", "initialStep", "shadowMapSize", "trees"):
        per_scene = []
        for scene in scenes:
            errs = [r["error"]["meanRelative"] for r in runs if r["scene"] == scene and r["family"] == family
                    and r["method"] == "epipolar" and "error" in r]
            if len(errs) > 1:
                per_scene.append(max(errs) - min(errs))
        if per_scene:
            spans[family] = sum(per_scene) / len(per_scene)
    for family, span in sorted(spans.items(), key=lambda kv: -kv[1]):
        p(f"- {family}: {100 * span:.2f} percentage points")
    if any(r["family"] == "size" for r in runs):
        p("\nThe epipolar method's cost grows with slices x samples and the shadow map, hardly with the screen; "
          "brute force's grows with every pixel ([Scaling](#scaling): where brute force is ahead, the screen is "
          "too small for the fixed cost to pay off on this device).\n")
    # The GPU machine's run, kept where scripts/gpu-bench.sh's results were copied (LS_REPORT_GPU).
    gpu_dir = os.environ.get("LS_REPORT_GPU", "")
    out += gpu_section(Path(gpu_dir) if gpu_dir else None)
    print("\n".join(out))


if __name__ == "__main__":
    main()
