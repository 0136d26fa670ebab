"""The 'Beside seed 000' section: our speed-ups and memory beside the seed's published figures."""
from . import speed as rs
from .common import SEED, fmt


def seed_section(runs, scenes, budget, seed_dir):
    out = []
    p = out.append
    p("## Beside seed 000\n")
    seed_rows, seed_first = rs.seed_size_rows(seed_dir) if seed_dir else ({}, None)
    if seed_rows:
        sw, sh_ = seed_first["size"]
        maps = sorted({r.get("shadowMapSize") for r in rs.load_runs(seed_dir)} - {None})
        p(f"The seed's figures are a GeForce GTX 680 at 2560x1600 with a spot light. Ours: `bench/seed_size.json`, "
          f"the same profiles and brute force at {sw}x{sh_} on the device above ({seed_first['frames']} frames after "
          "warm-up each, timings only), so the ratios can be set side by side; the milliseconds cannot (a CPU "
          "device runs the per-pixel passes far slower, relative to the rest, than a GPU). Every run here keeps "
          f"its scene's shadow map ({', '.join(f'{m}^2' for m in maps)}), brute force's included, where the seed "
          "gave each profile its own (4096^2, 2048^2, 1024^2) and ran brute force at 4096^2: "
          "[Seed 000's results beside ours](#seed-000s-results-beside-ours) runs the seed's maps.\n")
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
        # Each figure names its budget (tools/check_budget_figures.py runs it again).
        args = f"--profile {prof} --size 2560x1600"
        p(f"| {prof} | {ms} | {SEED['brute-force'][0] / ms:.1f}x | {ours} | {mb} | "
          f"{bud['peakBytes'] / 2**20:.1f}<!-- budget {args}: peak --> | "
          f"{bud['totalBytes'] / 2**20:.1f}<!-- budget {args}: total --> |")
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
    return out
