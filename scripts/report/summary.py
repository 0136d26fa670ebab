"""The page's first section, 'At a glance'."""
from . import speed as rs
from .common import SEED, fmt

def summary_lines(runs, trees_dir, seed_dir):
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
        p("The min/max trees at high quality, on the ray march alone (target 8x; seed 000, for a spot light: "
          "without the trees the ray march alone takes 3.3x as long and the whole frame 2x, and \"for higher "
          "quality settings the speedup is much higher\"): " + ", ".join(parts) + " ([the trees](#the-minmax-trees-at-high-quality)).\n")
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

