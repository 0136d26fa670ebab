"""The 'Froxels under motion' section: the froxel grid's flicker and its temporal mode's ghosting
under bench/flicker.json's motions, from a `lightscatter bench` run of bench/froxels_flicker.json
(rows with "motion" and "flicker"; docs/performance.md, "Temporal stability", defines the
figures)."""
import json
from datetime import date
from pathlib import Path

from .common import fmt
from .runs import commit_note

FROXELS_MOTION_HEADING = "## Froxels under motion"


def pct(x):
    return "-" if x is None else f"{fmt(100 * x)}%"


def mean(v):
    v = [x for x in v if x is not None]
    return sum(v) / len(v) if v else None


MOVING = ("light", "camera")
PRESETS = ("froxels-hdrp", "froxels-unreal")
# The temporal modes, by the suffix of their labels after a preset's name: the temporal mode, and
# with the per-pixel history (configurations labelled "<preset>-pixels").
MODES = (("-temporal", "the temporal mode"), ("-pixels", "the temporal mode with `pixelHistory`"))
# The temporal mode's goals against the plain grid of the same size: in motion its error and its
# excess flicker no higher (within 2%), on still frames its error at most 0.7 times.
MOVING_TOLERANCE = 1.02
STILL_GOAL = 0.7


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
    warmup = r0.get("warmup", 16)
    motions = []
    for r in runs:
        if r["motion"]["what"] not in motions:
            motions.append(r["motion"]["what"])
    p("Engines run their froxel grids with temporal reprojection, and what their users report is its cost "
      "in motion: ghosting (a shaft that trails where the light or the camera was) and flicker. This is "
      "`froxels` at HDRP's and Unreal's sizes, plain and in the temporal mode (docs/methods.md, \"The "
      "temporal mode\"; `-pixels`: with its still frames refined per pixel, \"Still frames refined per "
      "pixel\"), " + ("on still frames and " if "still" in motions else "") +
      "under bench/flicker.json's two motions (the light turning slowly, then the camera moving), beside "
      "epipolar balanced and brute force, every frame judged against the float64 reference at its own pose "
      "(\"Temporal stability\" above defines the figures). Each pass starts from the scene's own pose as a "
      f"camera cut (`resetHistory`) and {warmup} still warm-up frames, so that the temporal mode's history is "
      "settled before the frames are judged" + (": the still pass (`\"still\"` in the configuration's "
      "motions) then judges what it settles on" if "still" in motions else "") + ".\n")
    p(f"Measured on {date.today().isoformat()}{commit_note()} with `./build/host_example/lightscatter bench --config "
      f"bench/froxels_flicker.json --out build/bench-froxels-flicker` (`scripts/make-report.sh "
      f"--froxels-motion-only` runs it and splices this section) at {w}x{h}, {frames} frames per pass, on "
      f"**{r0['device']}** (flicker and error do not depend on the device's speed). At this size "
      f"`froxels-hdrp`'s grid is {-(-w // 8)}x{-(-h // 8)}x64 and `froxels-unreal`'s "
      f"{-(-w // 16)}x{-(-h // 16)}x64: the same froxels per pixel as at 1920x1080, so a shaft a froxel "
      "wide at this size is one at that size too.\n")
    p("| scene | motion | configuration | mean rel. error | mean excess flicker | p99 excess | "
      "error change |")
    p("|---|---|---|---|---|---|---|")
    for r in runs:
        f = r["flicker"]
        p(f"| {r['scene']} | {r['motion']['what']} | {r['label']} | {fmt(f['meanRelativeError'])} | "
          f"{pct(f['meanExcess'])} | {pct(f['p99Excess'])} | {pct(f['meanErrorChange'])} |")
    p("")

    by = {(r["scene"], r["motion"]["what"], r["label"]): r["flicker"] for r in runs}
    scenes = []
    for r in runs:
        if r["scene"] not in scenes:
            scenes.append(r["scene"])
    keys = [(s, m) for s in scenes for m in motions if any((s, m, l) in by for l in PRESETS)]

    def ratio(scene, what, preset, suffix, field):
        plain, temporal = by.get((scene, what, preset)), by.get((scene, what, preset + suffix))
        if not plain or not temporal or not plain[field]:
            return None
        return temporal[field] / plain[field]

    moving, still, misses, still_misses = {}, {}, {}, {}
    for suffix, name in MODES:
        if not any(label == pr + suffix for (_, _, label) in by for pr in PRESETS):
            continue
        p(f"{name[0].upper() + name[1:]} against the plain grid of the same size, per scene and motion (ratios; "
          "below 1 it is better; on still frames the plain grid renders the same image every frame, so its "
          "excess flicker is 0 and the mode's stands alone in the table above).\n")
        p("| scene | motion | hdrp: error | hdrp: flicker | unreal: error | unreal: flicker |")
        p("|---|---|---|---|---|---|")
        misses[suffix], still_misses[suffix] = [], []
        for scene, what in keys:
            cells = []
            for preset in PRESETS:
                mode = preset + suffix
                e = ratio(scene, what, preset, suffix, "meanRelativeError")
                x = ratio(scene, what, preset, suffix, "meanExcess")
                cells += ["-" if e is None else f"{fmt(e)}x", "-" if x is None else f"{fmt(x)}x"]
                if what in MOVING and e is not None and x is not None:
                    moving.setdefault(mode, ([], []))
                    moving[mode][0].append(e)
                    moving[mode][1].append(x)
                    over = [n for n, v in (("error", e), ("flicker", x)) if v > MOVING_TOLERANCE]
                    if over:
                        misses[suffix].append(f"`{scene}` ({what}, {preset}: " + ", ".join(
                            f"{n} {fmt(v)}x" for n, v in (("error", e), ("flicker", x)) if n in over) + ")")
                if what == "still" and e is not None:
                    still.setdefault(mode, []).append(e)
                    if e > STILL_GOAL:
                        still_misses[suffix].append(f"`{scene}` ({preset}, {fmt(e)}x)")
            p(f"| {scene} | {what} | " + " | ".join(cells) + " |")
        p("")

    # Against epipolar balanced in motion, per scene and motion.
    moving_keys = [k for k in keys if k[1] in MOVING]
    epi = {k: by.get(k + ("epipolar balanced",)) for k in moving_keys}
    lines = []
    for preset in PRESETS + tuple(x + suffix for suffix, _ in MODES for x in PRESETS):
        err = [by[k + (preset,)]["meanRelativeError"] / epi[k]["meanRelativeError"]
               for k in moving_keys if by.get(k + (preset,)) and epi[k] and epi[k]["meanRelativeError"]]
        flick = [by[k + (preset,)]["meanExcess"] / epi[k]["meanExcess"]
                 for k in moving_keys if by.get(k + (preset,)) and epi[k] and epi[k]["meanExcess"]]
        if err:
            lines.append(f"`{preset}` {fmt(min(err))}x to {fmt(max(err))}x epipolar balanced's moving error and "
                         f"{fmt(min(flick))}x to {fmt(max(flick))}x its excess flicker" if flick else
                         f"`{preset}` {fmt(min(err))}x to {fmt(max(err))}x epipolar balanced's moving error")
    if lines:
        p("Against epipolar balanced in the same motions: " + "; ".join(lines) + ".\n")
    for mode, (e, x) in moving.items():
        plain = next(pr for pr in PRESETS if mode.startswith(pr + "-"))
        p(f"`{mode}` against `{plain}` in motion: error {fmt(min(e))}x to {fmt(max(e))}x (mean "
          f"{fmt(mean(e))}x), excess flicker {fmt(min(x))}x to {fmt(max(x))}x (mean {fmt(mean(x))}x)" +
          (f"; on still frames error {fmt(min(still[mode]))}x to {fmt(max(still[mode]))}x (mean "
           f"{fmt(mean(still[mode]))}x)" if still.get(mode) else "") + ".\n")
    for suffix, name in MODES:
        cases = [(e, x) for mode, (es, xs) in moving.items() if mode.endswith(suffix) for e, x in zip(es, xs)]
        stills = [v for mode, vs in still.items() if mode.endswith(suffix) for v in vs]
        n, n_still = len(cases), len(stills)
        if not n:
            continue
        worse_e = sum(1 for e, _ in cases if e > MOVING_TOLERANCE)
        worse_x = sum(1 for _, x in cases if x > MOVING_TOLERANCE)
        met = sum(1 for e, x in cases if e <= MOVING_TOLERANCE and x <= MOVING_TOLERANCE)
        p(f"The goals for {name}: in each of the {n} scene, motion and size cases, its moving error and excess "
          f"flicker no higher than the plain grid's within 2%; and on still frames its error at most "
          f"{STILL_GOAL} times the plain grid's. It meets both in {met} of the {n} moving cases (its error is "
          f"higher by more than 2% in {worse_e}, its excess flicker in {worse_x})" +
          (f"; its still error is within {STILL_GOAL}x in {n_still - len(still_misses[suffix])} of {n_still}"
           if n_still else "") + ". " +
          ("Where it misses in motion: " + "; ".join(misses[suffix]) + ". " if misses[suffix] else
           "It meets both in motion. ") +
          ("On still frames: " + "; ".join(still_misses[suffix]) + "." if still_misses[suffix] else "") + "\n")
    # Epipolar balanced against brute force, the worst case of each figure.
    epi_e = [by[k + ("epipolar balanced",)]["meanRelativeError"] / by[k + ("brute-force",)]["meanRelativeError"]
             for k in moving_keys if by.get(k + ("epipolar balanced",)) and by.get(k + ("brute-force",))]
    epi_x = [by[k + ("epipolar balanced",)]["meanExcess"] / by[k + ("brute-force",)]["meanExcess"]
             for k in moving_keys if by.get(k + ("epipolar balanced",)) and by.get(k + ("brute-force",))
             and by[k + ("brute-force",)]["meanExcess"]]
    if epi_e and epi_x:
        p(f"Epipolar balanced, which keeps no history, stays within {fmt(max(epi_e))}x of brute force's moving "
          f"error and {fmt(max(epi_x))}x of its excess flicker in every moving case above.\n")
    return out
