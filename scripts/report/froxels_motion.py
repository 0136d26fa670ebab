"""The 'Froxels under motion' section: the froxel grid's flicker and its temporal mode's ghosting
under bench/flicker.json's motions, from a `lightscatter bench` run of bench/froxels_flicker.json
(rows with "motion" and "flicker"; docs/performance.md, "Temporal stability", defines the
figures)."""
import json
from datetime import date
from pathlib import Path

from .common import fmt

FROXELS_MOTION_HEADING = "## Froxels under motion"


def pct(x):
    return "-" if x is None else f"{fmt(100 * x)}%"


def mean(v):
    v = [x for x in v if x is not None]
    return sum(v) / len(v) if v else None


def froxels_motion_section(bench_dir):
    bench = json.loads((Path(bench_dir) / "bench.json").read_text())
    runs = [r for r in bench["runs"] if "flicker" in r]
    out = []
    p = out.append
    p(FROXELS_MOTION_HEADING + "\n")
    if not runs:
        return out
    r0 = runs[0]
    w, h = r0["size"]
    frames = r0["frames"]
    p("Engines run their froxel grids with temporal reprojection, and what their users report is its cost "
      "in motion: ghosting (a shaft that trails where the light or the camera was) and flicker. This is "
      "`froxels` at HDRP's and Unreal's sizes, plain and in the temporal mode, under bench/flicker.json's "
      "two motions (the light turning slowly, then the camera moving), beside epipolar balanced and brute "
      "force, every frame judged against the float64 reference at its own pose (\"Temporal stability\" above "
      "defines the figures). Each motion starts from the scene's own pose as a camera cut "
      "(`resetHistory`) after 16 still frames, so that the temporal mode's history has seen its whole "
      "jitter sequence before the motion begins.\n")
    p(f"Measured on {date.today().isoformat()} with `./build/host_example/lightscatter bench --config "
      f"bench/froxels_flicker.json --out build/bench-froxels-flicker` (`scripts/make-report.sh "
      f"--froxels-motion-only` runs it and splices this section) at {w}x{h}, {frames} frames per motion, on "
      f"**{r0['device']}** (flicker and error do not depend on the device's speed). At this size "
      f"`froxels-hdrp`'s grid is {-(-w // 8)}x{-(-h // 8)}x64 and `froxels-unreal`'s "
      f"{-(-w // 16)}x{-(-h // 16)}x64: the same froxels per pixel as at 1920x1080, so a shaft a froxel "
      "wide at this size is one at that size too.\n")
    p("| scene | motion | configuration | mean rel. error (moving) | mean excess flicker | p99 excess | "
      "error change |")
    p("|---|---|---|---|---|---|---|")
    for r in runs:
        f = r["flicker"]
        p(f"| {r['scene']} | {r['motion']['what']} | {r['label']} | {fmt(f['meanRelativeError'])} | "
          f"{pct(f['meanExcess'])} | {pct(f['p99Excess'])} | {pct(f['meanErrorChange'])} |")
    p("")

    by = {(r["scene"], r["motion"]["what"], r["label"]): r["flicker"] for r in runs}
    keys = sorted({(r["scene"], r["motion"]["what"]) for r in runs})
    p("The temporal mode against the plain grid of the same size, per scene and motion (ratios; below 1 the "
      "temporal mode is better): the moving error shows the ghosting, a history that lags the scene, against "
      "what the jittered average gains; the excess flicker shows what the blend smooths.\n")
    p("| scene | motion | hdrp: error | hdrp: flicker | unreal: error | unreal: flicker |")
    p("|---|---|---|---|---|---|")
    ratios = {"froxels-hdrp": ([], []), "froxels-unreal": ([], [])}
    for scene, what in keys:
        cells = []
        for preset in ("froxels-hdrp", "froxels-unreal"):
            plain, temporal = by.get((scene, what, preset)), by.get((scene, what, preset + "-temporal"))
            if not plain or not temporal or not plain["meanRelativeError"] or not plain["meanExcess"]:
                cells += ["-", "-"]
                continue
            e = temporal["meanRelativeError"] / plain["meanRelativeError"]
            x = temporal["meanExcess"] / plain["meanExcess"]
            ratios[preset][0].append(e)
            ratios[preset][1].append(x)
            cells += [f"{fmt(e)}x", f"{fmt(x)}x"]
        p(f"| {scene} | {what} | " + " | ".join(cells) + " |")
    p("")

    # Against epipolar balanced in motion, per scene and motion.
    epi = {k: by.get(k + ("epipolar balanced",)) for k in keys}
    lines = []
    for preset in ("froxels-hdrp", "froxels-unreal", "froxels-hdrp-temporal", "froxels-unreal-temporal"):
        err = [by[k + (preset,)]["meanRelativeError"] / epi[k]["meanRelativeError"]
               for k in keys if by.get(k + (preset,)) and epi[k] and epi[k]["meanRelativeError"]]
        flick = [by[k + (preset,)]["meanExcess"] / epi[k]["meanExcess"]
                 for k in keys if by.get(k + (preset,)) and epi[k] and epi[k]["meanExcess"]]
        if err:
            lines.append(f"`{preset}` {fmt(min(err))}x to {fmt(max(err))}x epipolar balanced's moving error and "
                         f"{fmt(min(flick))}x to {fmt(max(flick))}x its excess flicker" if flick else
                         f"`{preset}` {fmt(min(err))}x to {fmt(max(err))}x epipolar balanced's moving error")
    if lines:
        p("Against epipolar balanced in the same motions: " + "; ".join(lines) + ".\n")
    for preset, (e, x) in ratios.items():
        if e:
            p(f"`{preset}-temporal` against `{preset}`: moving error {fmt(min(e))}x to {fmt(max(e))}x (mean "
              f"{fmt(mean(e))}x), excess flicker {fmt(min(x))}x to {fmt(max(x))}x (mean {fmt(mean(x))}x).\n")
    worse_e = sum(1 for e, _ in ratios.values() for v in e if v > 1)
    worse_x = sum(1 for _, x in ratios.values() for v in x if v > 1)
    n = sum(len(e) for e, _ in ratios.values())
    # The cases where the temporal mode beats the plain grid on both counts.
    helps = []
    for scene, what in keys:
        for preset in ("froxels-hdrp", "froxels-unreal"):
            plain, temporal = by.get((scene, what, preset)), by.get((scene, what, preset + "-temporal"))
            if plain and temporal and temporal["meanRelativeError"] < plain["meanRelativeError"] and \
                    temporal["meanExcess"] < plain["meanExcess"]:
                helps.append(f"`{scene}` ({what}, {preset})")
    # Epipolar balanced against brute force, the worst case of each figure.
    epi_e = [by[k + ("epipolar balanced",)]["meanRelativeError"] / by[k + ("brute-force",)]["meanRelativeError"]
             for k in keys if by.get(k + ("epipolar balanced",)) and by.get(k + ("brute-force",))]
    epi_x = [by[k + ("epipolar balanced",)]["meanExcess"] / by[k + ("brute-force",)]["meanExcess"]
             for k in keys if by.get(k + ("epipolar balanced",)) and by.get(k + ("brute-force",))
             and by[k + ("brute-force",)]["meanExcess"]]
    if n:
        p(f"In motion the temporal mode gives back what it gains on a still scene (\"Against froxel fog\": 7% to 33% "
          f"less error after the same warm-up frames): its moving error is above the plain grid's in {worse_e} of "
          f"the {n} scene, motion and size cases, the history lagging the scene (ghosting: each froxel keeps "
          f"`froxels.historyWeight`, 0.9 here, of where the shafts were), and its excess flicker above the plain "
          f"grid's in {worse_x} of them: the plain grid samples each froxel at its fixed centre, which moves "
          f"little from one frame to the next under a slow motion, while the jitter moves every sample each frame "
          f"and the blend lets a tenth of that through. "
          + (f"It beats the plain grid on both counts only in {', '.join(helps)}, where the plain grid's columns "
             f"are coarser than the shafts and its every frame differs already (its own excess flicker above). "
             if helps else "It never beats the plain grid on both counts. ")
          + (f"Epipolar balanced, which keeps no history, stays within {fmt(max(epi_e))}x of brute force's moving "
             f"error and {fmt(max(epi_x))}x of its excess flicker in every case above.\n" if epi_e and epi_x else "\n"))
    return out
