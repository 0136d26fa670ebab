"""The sections 'Seed 000's results beside ours' and 'Seed 003's results beside ours': each of the
seeds' published tables reproduced at the seed's size, settings and shadow-map sizes by a bench
configuration checked into bench/ (seed000_*.json, seed003_*.json), with the seed's figures in a
column beside ours and a verdict per row. Times on lavapipe are CPU times, so what is compared is
what carries over between devices: ratios between rows of one table, memory, and the order of the
rows. `scripts/make-report.sh --seeds-only` runs the configurations and splices the sections."""
import json
from datetime import date
from pathlib import Path

from . import speed as rs
from .common import fmt

SEED000_HEADING = "## Seed 000's results beside ours"
SEED003_HEADING = "## Seed 003's results beside ours"

# Seed 000's three "Performance" tables: (row, slices, samples, shadow map, ms, MB), and the label
# of our run of that row in the table's configuration.
SEED000_TABLES = [
    ("gtx680", "NVIDIA GeForce GTX 680", "2560x1600", [
        ("brute force", None, None, 4096, 91.18, None, "brute-force"),
        ("high quality", 2048, 1024, 4096, 5.986, 88.0, "epipolar high-quality"),
        ("balanced", 1024, 1024, 2048, 3.269, 44.0, "epipolar balanced"),
        ("high performance", 1024, 512, 1024, 2.267, 18.0, "epipolar high-performance"),
    ]),
    ("quadro", "NVIDIA Quadro 1000M", "1366x768", [
        ("brute force", None, None, 2048, 164.0, None, "brute-force"),
        ("high quality", 1024, 1024, 2048, 18.9, 44.0, "seed high quality"),
        ("balanced", 512, 512, 1024, 8.37, 11.0, "seed balanced"),
        ("high performance", 512, 256, 512, 5.38, 4.5, "seed high performance"),
    ]),
    ("intel", "Intel 3rd-generation HD Graphics", "1024x768", [
        ("brute force", None, None, 2048, 184.79, None, "brute-force"),
        ("high quality", 1024, 1024, 2048, 28.83, 44.0, "seed high quality"),
        ("balanced", 512, 512, 1024, 12.85, 11.0, "seed balanced"),
        ("high performance", 512, 256, 512, 8.85, 4.5, "seed high performance"),
    ]),
]

# Seed 003's two tables: (row, [(GPU, mean, SD, max)]); the HD 4600 has no max.
SEED003_TABLES = {
    "2560x1440": [
        ("baseline", [("980Ti", 1.5, 0.1, 1.9), ("970M", 7.9, 5.3, 20), ("HD 4600", 27.1, 2, None)]),
        ("naive marching", [("980Ti", 5.6, 1.8, 9.6), ("970M", 18.5, 5.6, 30.8), ("HD 4600", 102, 35, None)]),
        ("test - no sampling", [("980Ti", 1.9, 0.3, 2.7), ("970M", 8.7, 5.3, 20.6), ("HD 4600", 33.3, 5, None)]),
        ("test - naive marching", [("980Ti", 5.3, 2, 11.4), ("970M", 17.5, 6, 49), ("HD 4600", 101, 41.5, None)]),
    ],
    "1280x720": [
        ("baseline", [("980Ti", 1.5, 0.1, 1.9), ("970M", 7.9, 5.4, 20.4), ("HD 4600", 24.5, 2.4, None)]),
        ("naive marching", [("980Ti", 2.6, 0.6, 4.3), ("970M", 10.5, 5.1, 41.2), ("HD 4600", 43.7, 9.8, None)]),
        ("test - no sampling", [("980Ti", 1.6, 0.1, 2.3), ("970M", 8.1, 5.4, 34.5), ("HD 4600", 26.2, 2.5, None)]),
        ("test - naive marching", [("980Ti", 2.5, 0.6, 11.2), ("970M", 10.3, 5.2, 21.2), ("HD 4600", 44.2, 11.6, None)]),
    ],
}


def load(d):
    f = Path(d) / "bench.json"
    return json.loads(f.read_text())["runs"] if f.exists() else []


def budget_mib(d, label):
    """Peak MiB of a configuration at its table's size (budget-LABEL.json beside the run), or None."""
    f = Path(d) / f"budget-{label.replace(' ', '-')}.json"
    if not f.exists():
        return None
    return json.loads(f.read_text())[0]["peakBytes"] / 2**20


def budget_args(size, label, slices, samples, shadow_map):
    """The `lightscatter budget` options that give a row's memory (scripts/make-report.sh's), as the
    page's comment after each figure says them for tools/check_budget_figures.py."""
    if label.startswith("epipolar "):
        return f"--method epipolar --profile {label.split(' ', 1)[1]} --size {size}"
    settings = json.dumps({"epipolar": {"slices": slices, "samplesPerSlice": samples}, "shadowMapSize": shadow_map})
    return f"--profile custom --settings-json '{settings}' --shadow-map {shadow_map} --size {size}"


def row_of(runs, scene, label):
    return next((r for r in runs if r["scene"] == scene and r["label"] == label), None)


def device_line(runs):
    r0 = runs[0]
    kind = "lavapipe, a CPU Vulkan driver: compare ratios, not milliseconds" if r0["cpuDevice"] else "GPU timestamps"
    return f"**{r0['device']}** ({kind})"


def seed000_table(out, d, key, gpu, size, rows):
    p = out.append
    runs = load(d)
    if not runs:
        return
    scenes = sorted({r["scene"] for r in runs})
    p(f"### {gpu}, {size}, spot light\n")
    p(f"`bench/seed000_{key}.json`: the seed's rows at the seed's size and shadow maps "
      f"({runs[0]['frames']} frames after warm-up, median), on {device_line(runs)}; memory from "
      "`lightscatter budget` at this size with each row's settings (the plugin's textures, the shadow map "
      "excluded, as in the seed's column).\n")
    p("| row | slices x samples | shadow map | seed ms | seed speed-up over brute force | "
      + " | ".join(f"ours, {s}: ms (speed-up)" for s in scenes) + " | seed MB | ours: peak MiB | verdict |")
    p("|---|---|---|---|---|" + "---|" * len(scenes) + "---|---|---|")
    seed_brute = rows[0][4]
    for name, slices, samples, sm, ms, mb, label in rows:
        cells, verdicts = [], []
        seed_speed = seed_brute / ms
        for s in scenes:
            r, b = row_of(runs, s, label), row_of(runs, s, "brute-force")
            if not r:
                cells.append("-")
                continue
            t = r["time"]["median"]
            speed = b["time"]["median"] / t if b and t else None
            sm_ours = r.get("shadowMapSize")
            note = "" if sm_ours == sm else f", map {sm_ours}"
            cells.append(f"{fmt(t)} ({fmt(speed)}x{note})" if label != "brute-force" else f"{fmt(t)}{note and ' (' + note[2:] + ')'}")
            if label != "brute-force" and speed is not None:
                verdicts.append((s, speed, r))
        mib = budget_mib(d, label) if label != "brute-force" else None
        source = f"<!-- budget {budget_args(size, label, slices, samples, sm)}: peak -->" if mib is not None else ""
        if label == "brute-force":
            verdict = "the reference row"
        else:
            held = [s for s, x, _ in verdicts if x >= seed_speed]
            missed = [(s, x, r) for s, x, r in verdicts if x < seed_speed]
            parts = []
            if held and not missed:
                parts.append("speed-up holds on every scene")
            elif held:
                parts.append("speed-up holds on " + ", ".join(held))
            for s, x, r in missed:
                rest = r["time"]["median"] - rs.march_ms(r)
                free = (row_of(runs, s, "brute-force")["time"]["median"] / rest) if rest > 0 else None
                why = (f"its ray march is {fmt(100 * rs.march_ms(r) / r['time']['median'], 2)}% of the frame; "
                       f"a free one would give {fmt(free)}x") if free else "the ray march is the whole frame"
                parts.append(f"below on {s} ({fmt(x)}x against {seed_speed:.1f}x: {why})")
            if mib is not None and mb:
                parts.append(f"memory {'holds' if mib <= mb * 1.05 else 'above the seed'} "
                             f"({fmt(mib)} MiB{source} against {mb} MB)")
            verdict = "; ".join(parts)
        p(f"| {name} | {f'{slices} x {samples}' if slices else '-'} | {sm}^2 | {ms} | "
          f"{'-' if label == 'brute-force' else f'{seed_speed:.1f}x'} | " + " | ".join(cells) +
          f" | {mb if mb else '-'} | {fmt(mib)}{source} | {verdict} |")
    p("")


def seed000_section(dirs):
    """dirs: {gtx680, quadro, intel, directional, trees: folder}."""
    out = []
    p = out.append
    p(SEED000_HEADING + "\n")
    p("Each of seed 000's performance results (its \"Performance\" slides), run again here at the seed's "
      "screen size, settings and shadow-map sizes, with the seed's figures beside ours. The seed measured "
      "GPUs; this page's device is lavapipe, which runs per-pixel work far slower relative to the rest than "
      "a GPU does, so milliseconds do not carry over: the verdicts compare ratios between rows of one table "
      "(each profile's speed-up over brute force, the trees' factor), memory, and the order of the rows. "
      f"Generated on {date.today().isoformat()} by `scripts/make-report.sh --seeds-only`; the scenes are "
      "the spot-lit `engine_spot` and `window_room` (the seed's scene is not available).\n")
    for key, gpu, size, rows in SEED000_TABLES:
        if dirs.get(key):
            seed000_table(out, dirs[key], key, gpu, size, rows)

    runs = load(dirs["directional"]) if dirs.get("directional") else []
    r = runs and row_of(runs, runs[0]["scene"], "seed directional")
    if r:
        b = row_of(runs, r["scene"], "brute-force")
        p("### Directional light, 1280x960, 1024 slices x 512 samples, 4096^2 shadow map\n")
        p(f"`bench/seed000_directional.json` on `{r['scene']}` (its sun), on {device_line(runs)}. The seed "
          "gives one figure, \"just above 4 ms\" on a GeForce GTX 480 (the per-pass split is a chart without "
          "numbers), so what can be set beside it is where our time goes and the speed-up over brute force "
          "at the scene's map, which the seed does not give.\n")
        total = r["time"]["median"]
        parts = ", ".join(f"{n} {fmt(ms)} ms" for n, ms in sorted(rs.pass_times(r).items(), key=lambda x: -x[1])[:5])
        p(f"Ours: {fmt(total)} ms in all (ray march {fmt(100 * rs.march_ms(r) / total, 2)}%; the largest passes: "
          f"{parts})" + (f"; brute force at its {b['shadowMapSize']}^2 map {fmt(b['time']['median'])} ms, "
                         f"{fmt(b['time']['median'] / total)}x as long" if b else "") +
          ". Verdict: not comparable in milliseconds; the split is the device's.\n")

    runs = load(dirs["trees"]) if dirs.get("trees") else []
    if runs:
        p("### The min/max trees on a spot light, coloured shafts, and epipolar alone against brute force\n")
        p(f"`bench/seed000_trees.json` at 1280x960 with the balanced profile, trees on and off, on "
          f"{device_line(runs)}. The seed (slide 76, GeForce GTX 480): for a spot light, without the trees "
          "the ray march alone takes 3.3x as long and the whole frame 2x (\"for higher quality settings the "
          "speedup is much higher\"); with coloured shafts the trees skip far less (slide 77: the ray march "
          "1.67 ms plain against 5.49 ms coloured, 3.29x; the frame 3.36 against 6.86 ms, 2.04x).\n")
        p("| scene | ray march, trees on ms | trees off ms | trees' factor on the march (seed 3.3x) | frame "
          "on / off ms | on the frame (seed 2x) | epipolar (trees on) against brute force |")
        p("|---|---|---|---|---|---|---|")
        facts = {}
        for s in sorted({r["scene"] for r in runs}):
            on, off, b = row_of(runs, s, "trees on"), row_of(runs, s, "trees off"), row_of(runs, s, "brute-force")
            if not on or not off:
                continue
            m_on, m_off = rs.march_ms(on), rs.march_ms(off)
            t_on, t_off = on["time"]["median"], off["time"]["median"]
            facts[s] = (m_on, t_on)
            p(f"| {s} | {fmt(m_on)} | {fmt(m_off)} | {fmt(m_off / m_on) if m_on else '-'}x | {fmt(t_on)} / "
              f"{fmt(t_off)} | {fmt(t_off / t_on)}x | "
              f"{fmt(b['time']['median'] / t_on) + 'x' if b else '-'} |")
        p("")
        if "stained_glass" in facts and "window_room" in facts:
            (mc, tc), (mp, tp) = facts["stained_glass"], facts["window_room"]
            p(f"Coloured against plain (trees on; `stained_glass` is `window_room`'s light through a stained-glass "
              f"cookie): the ray march {fmt(mp)} ms plain against {fmt(mc)} ms coloured, {fmt(mc / mp)}x (seed "
              f"3.29x); the frame {fmt(tp)} against {fmt(tc)} ms, {fmt(tc / tp)}x (seed 2.04x). Our coloured march "
              "takes no lit node of a tree whole, as the seed's cannot (the colour changes along it: "
              "`shaders/epipolar/ray_march.frag`), and steps through lit runs one texel at a time; only shadowed "
              "runs are still skipped. The factor is that lost skipping on this scene's light.\n")
    return out


def seed003_section(dirs):
    """dirs: {size: folder} for 1280x720 and 2560x1440."""
    out = []
    p = out.append
    p(SEED003_HEADING + "\n")
    p("Seed 003 times whole frames, mean, SD and max over frames, on three GPUs: the scene alone (baseline), "
      "with its naive full-ray march, with the cone-limited march without shadow look-ups (16 samples), and "
      "with the cone-limited march. Ours: `bench/seed003_WxH.json`, the host's frame (its shadow map and "
      "shading) alone as the baseline and with `cone-march` in each mode, at the seed's two sizes (each "
      "row's ratio is to the host's own frames timed in the same run), "
      f"generated on {date.today().isoformat()} by `scripts/make-report.sh --seeds-only`. The seed's claims: the "
      "cone-limited march is as fast as or faster than the naive one, and the no-sampling mode costs little "
      "over the baseline. Milliseconds do not carry over from its GPUs to lavapipe; the ratios to the "
      "baseline and the order of the rows do.\n")
    for size in ("1280x720", "2560x1440"):
        runs = load(dirs[size]) if dirs.get(size) else []
        if not runs:
            continue
        seed = SEED003_TABLES[size]
        p(f"### {size}\n")
        p(f"On {device_line(runs)}, {runs[0]['frames']} frames after {runs[0]['warmup']} warm-up.\n")
        scenes = sorted({r["scene"] for r in runs})
        p("| row | seed 980Ti mean / SD / max (x baseline) | seed 970M | seed HD 4600 | "
          + " | ".join(f"ours, {s}: mean / SD / max ms (x baseline)" for s in scenes) + " |")
        p("|---|---|---|---|" + "---|" * len(scenes))
        base_seed = {g: m for g, m, _, _ in seed[0][1]}
        ours = {}
        for name, figures in seed:
            cells = [f"{m} / {sd} / {mx if mx is not None else '-'} ({fmt(m / base_seed[g])}x)"
                     for g, m, sd, mx in figures]
            for s in scenes:
                # Each run times the host's frame beside its own: a row's ratio is to the baseline
                # measured in the same frames; the baseline row shows the first run's.
                r = next((x for x in runs if x["scene"] == s), None) if name == "baseline" \
                    else row_of(runs, s, name)
                base = r and r.get("engineTime")
                t = base if name == "baseline" else r and r.get("frameTime")
                if not t or not base:
                    cells.append("-")
                    continue
                ours[(s, name)] = t["mean"] / base["mean"]
                cells.append(f"{fmt(t['mean'])} / {fmt(t['sd'])} / {fmt(t['max'])} "
                             f"({fmt(t['mean'] / base['mean'])}x)")
            p(f"| {name} | " + " | ".join(cells) + " |")
        p("")
        verdicts = []
        for s in scenes:
            naive, cone, nos = (ours.get((s, k)) for k in ("naive marching", "test - naive marching",
                                                           "test - no sampling"))
            if None in (naive, cone, nos):
                continue
            held = "holds: as fast or faster, as the seed found"
            missed = "does not hold: slower here, where the seed found it as fast or faster"
            verdicts.append(
                f"{s}: the cone-limited march {fmt(cone)}x the baseline against the naive one's {fmt(naive)}x "
                f"({held if cone <= naive * 1.02 else missed}); no sampling "
                f"{fmt(nos)}x ({'cheap beside the marches, as the seed found' if nos < min(cone, naive) else 'not cheaper than the marches'})")
        if verdicts:
            p("Verdict: " + "; ".join(verdicts) + ".\n")
    return out


SEED002_HEADING = "## Seed 002's results beside ours"


def strip_name(r):
    """The strip's file name as `lightscatter bench` writes it (bench::fileSafe of scene_label)."""
    import re
    return re.sub(r"[^A-Za-z0-9.\-]", "_", f"{r['scene']}_{r['label']}") + ".png"


def seed002_section(d, image_dir=None):
    """Seed 002's Figure 8.1.11 (25, 50, 100 planes, and 100 blurred) from a run of
    bench/seed002.json; with image_dir, each row's strip is copied there for the page."""
    import shutil
    out = []
    p = out.append
    p(SEED002_HEADING + "\n")
    runs = load(d)
    if not runs:
        return out
    w, h = runs[0]["size"]
    p("Seed 002's Figure 8.1.11 shows its scene with 25, 50 and 100 sampling planes and with 100 planes "
      "blurred at composite, into its 8-bit target (a quarter of the planes in each of four 8-bit channels, "
      "pick-nearest shadow look-ups). Its text claims: with 25 and 50 planes the shadow edges show stair "
      "steps; with 100 they are \"essentially gone\"; the blur \"softens the look of the light shafts and "
      "further reduces aliasing\". It gives images, no numbers, so ours are images and errors: "
      f"`bench/seed002.json` at {w}x{h} on `{runs[0]['scene']}` (a spot through a window, as the seed's scene), "
      f"on {device_line(runs)}, each row against the float64 reference, beside our float16 default at the same "
      f"counts. Generated on {date.today().isoformat()} by `scripts/make-report.sh --seeds-only`.\n")
    p("| row | median ms | mean rel. error | p99 | pixels over 5% | PSNR dB | image (reference, ours, error) |")
    p("|---|---|---|---|---|---|---|")
    for r in runs:
        e = r.get("error", {})
        image = "-"
        if image_dir:
            src = Path(d) / "strips" / strip_name(r)
            if src.exists():
                name = "seed002_" + strip_name(r)
                Path(image_dir).mkdir(parents=True, exist_ok=True)
                shutil.copyfile(src, Path(image_dir) / name)
                image = f"![{r['label']}](performance/{name})"
        p(f"| {r['label']} | {fmt(r['time']['median'])} | {fmt(e.get('meanRelative'))} | {fmt(e.get('p99'))} | "
          f"{fmt(100 * e['fractionOver5pct']) + '%' if 'fractionOver5pct' in e else '-'} | "
          f"{fmt(e.get('psnrDb'))} | {image} |")
    p("")
    by = {r["label"]: r.get("error", {}) for r in runs}
    verdicts = []
    for target in ("8-bit", "float16"):
        errs = [by.get(f"{n} planes, {target}", {}).get("meanRelative") for n in (25, 50, 100)]
        over = [by.get(f"{n} planes, {target}", {}).get("fractionOver5pct") for n in (25, 50, 100)]
        blur = by.get(f"100 planes, {target}, blurred", {})
        if None in errs:
            continue
        falls = errs[0] > errs[1] > errs[2]
        verdicts.append(
            f"{target}: the error {'falls' if falls else 'does not fall'} with the planes ({fmt(errs[0])}, "
            f"{fmt(errs[1])}, {fmt(errs[2])}; pixels over 5%: "
            + ", ".join(f"{fmt(100 * o)}%" for o in over if o is not None) + ")"
            + (f"; blurred at 100, {fmt(blur.get('meanRelative'))} and "
               f"{fmt(100 * blur['fractionOver5pct'])}% over 5%" if "meanRelative" in blur else ""))
    if verdicts:
        p("Verdict: " + "; ".join(verdicts) + ". Whether the stair steps are \"essentially gone\" at 100 planes "
          "is a matter of the images above; the error columns say how much of the shafts each count misses.\n")
    return out


SEED004_HEADING = "## Seed 004's results beside ours"

# Table 6.1 (frames per second): {(dz, scene): (planes, {size: (beam tree, sampling, method 1,
# method 2)})}.
SEED004_TABLE = {
    (0.5, "Parallel"): (71, {64: (850, 924, 204, 174), 256: (311, 325, 204, 180), 512: (102, 100, 100, 146),
                             1024: (28, 34, 27, 44)}),
    (0.5, "Toplight"): (17, {64: (879, 985, 563, 515), 256: (342, 567, 339, 515), 512: (117, 240, 116, 269),
                             1024: (32, 73, 32, 85)}),
    (0.5, "Multiple"): (47, {64: (79, 440, 223, 206), 256: (79, 440, 224, 200), 512: (79, 257, 175, 200),
                             1024: (57, 80, 54, 89)}),
    (0.1, "Parallel"): (356, {64: (850, 556, 53, 45), 256: (311, 80, 50, 45), 512: (102, 24, 53, 21),
                              1024: (28, 7, 27, 6)}),
    (0.1, "Toplight"): (88, {64: (879, 719, 288, 229), 256: (342, 172, 288, 150), 512: (117, 50, 111, 47),
                             1024: (32, 13, 31, 13)}),
    (0.1, "Multiple"): (239, {64: (79, 407, 100, 83), 256: (79, 164, 100, 83), 512: (79, 64, 102, 50),
                              1024: (57, 13, 47, 15)}),
}
SEED004_SCENES = {"Parallel": "seed004_parallel", "Toplight": "seed004_toplight", "Multiple": "occluders_100"}


def planes_of(r):
    import re
    m = re.search(r"(\d+) sampling planes", r.get("reason", ""))
    return int(m.group(1)) if m else None


def seed004_section(d):
    out = []
    p = out.append
    p(SEED004_HEADING + "\n")
    runs = load(d)
    if not runs:
        return out
    p("Seed 004's Table 6.1 gives frames per second for its sampling planes alone (\"Sampling\", Dobashi's planes), "
      "its method 1 (sampling with aggressive clipping: `beam-tree-sampling`) and method 2 (lit space in closed "
      "form: `beam-tree-analytic`), and the beam tree's own part (\"a partial solution\"), with the planes "
      "`dz` = 0.5 and 0.1 apart, at 64 to 1024 pixels, on three scenes: Parallel (a light parallel to the view), "
      "Toplight (a light orthogonal to it) and Multiple (many objects). The thesis describes its scenes in one "
      "line each and shows two pictures; ours are approximations built from those lines, labelled so: "
      "`scenes/seed004_parallel.json` (occluders_10's boxes, a spot behind the camera shining along the view), "
      "`scenes/seed004_toplight.json` (the same boxes, a spot straight above them, seen from the side) and "
      "`scenes/occluders_100.json` for Multiple (100 boxes). `Settings::planes.spacing` is the seed's `dz`. "
      f"`bench/seed004.json` on {device_line(runs)}, generated on {date.today().isoformat()} by "
      "`scripts/make-report.sh --seeds-only`. Ours are frame rates of the plugin's passes alone (1000 / median ms; "
      "the beam tree's CPU build is not in them, as the seed's GPU figures do not say it is), the beam tree's part "
      "being method 2's lit-pyramid pass. What carries over from the seed's GPU to lavapipe is each row's order "
      "of the columns and how they fall with size, not the rates.\n")
    p("| dz | scene | size | seed: planes; beam tree / sampling / method 1 / method 2 fps | ours: planes; "
      "beam tree / sampling / method 1 / method 2 fps | fastest, seed / ours |")
    p("|---|---|---|---|---|---|")
    names = ("beam tree", "sampling", "method 1", "method 2")
    agree = total = 0
    # Where a beam-tree method beats the sampling planes alone, in the seed and here.
    tree_wins = {"seed": [], "ours": []}
    for (dz, scene), (seed_planes, by_size) in SEED004_TABLE.items():
        ours_scene = SEED004_SCENES[scene]
        for size, seed_fps in by_size.items():
            tag = f"{size}x{size}"
            rows = {k: row_of(runs, ours_scene, f"{k}, dz {dz} {tag}") for k in ("sampling", "method 1", "method 2")}
            if not all(rows.values()):
                continue
            pyramids = next((q["median"] for q in rows["method 2"].get("passes", [])
                             if q["name"].startswith("lit pyramids")), None)
            ms = [pyramids] + [rows[k]["time"]["median"] for k in ("sampling", "method 1", "method 2")]
            fps = [1000.0 / x if x else None for x in ms]
            seed_best = names[1 + max(range(3), key=lambda i: seed_fps[1 + i])]
            ours_best = names[1 + max(range(3), key=lambda i: fps[1 + i] or 0)]
            total += 1
            agree += seed_best == ours_best
            case = f"{scene} {size} (dz {dz})"
            if max(seed_fps[2], seed_fps[3]) > seed_fps[1]:
                tree_wins["seed"].append(case)
            if max(fps[2] or 0, fps[3] or 0) > (fps[1] or 0):
                tree_wins["ours"].append(case)
            p(f"| {dz} | {scene} | {size} | {seed_planes}; " + " / ".join(str(x) for x in seed_fps) +
              f" | {planes_of(rows['sampling']) or '-'}; " + " / ".join(fmt(x) for x in fps) +
              f" | {seed_best} / {ours_best} |")
    p("")
    if total:
        both = [c for c in tree_wins["seed"] if c in tree_wins["ours"]]
        p(f"Of the {total} rows, the fastest of sampling, method 1 and method 2 is the seed's in {agree}. A beam-tree "
          f"method beats the sampling planes alone in {len(tree_wins['seed'])} of the seed's rows and "
          f"{len(tree_wins['ours'])} of ours, {len(both)} of them the same"
          + (f" ({', '.join(both)})" if both else "") + ". The seed's conclusion is that the beam-tree methods pay "
          "\"for simple scenes rendered in high resolutions\": "
          + ("here too they win mostly at the larger sizes" if sum(1 for c in tree_wins["ours"] if " 512 " in c
                                                                   or " 1024 " in c) * 2 >= len(tree_wins["ours"])
             and tree_wins["ours"] else "here their wins do not follow the size")
          + ".\n")
    return out
