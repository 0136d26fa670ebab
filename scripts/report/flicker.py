#!/usr/bin/python3
"""The 'Temporal stability' section of docs/performance.md, from a `lightscatter bench` run of
bench/flicker.json (rows with "motion" and "flicker"). `scripts/write_report.py --flicker-section
BENCH_DIR [PAGE.md]` prints it or splices it into the page; with the page, the flicker heat maps of
epipolar (balanced) and brute force are copied beside it (docs/performance)."""
import json
import math
import os
import re
import shutil
from datetime import date
from pathlib import Path

from .common import FORMER_SWEEPS, fmt
from .runs import commit_note

FLICKER_HEADING = "## Temporal stability"


def pct(x):
    return "-" if x is None else f"{fmt(100 * x)}%"


def load(bench_dir):
    return [r for r in json.loads((Path(bench_dir) / "bench.json").read_text())["runs"] if "flicker" in r]


# Sweep families that start from epipolar's balanced profile (bench_config.cpp: balanced()), under
# their current names and those of runs recorded before (common.FORMER_SWEEPS).
EPIPOLAR_SWEEPS = ("slices", "samplesPerSlice", "initialSampleStep", "refinementThreshold", "minMaxTrees",
                   *FORMER_SWEEPS)


def label(r):
    if r["family"] in EPIPOLAR_SWEEPS:
        return f"epipolar balanced, {r['label']}"
    if r["method"] == "cone-march":
        return f"cone-march ({r.get('coneSamples', 32)} samples)"
    if r["method"] == "auto" and r.get("methodRan"):
        return f"auto (ran {r['methodRan']})"
    return r["label"]


def strip_name(r):
    """The strip's file name as `lightscatter bench` writes it (bench::fileSafe of scene_label_motion-what)."""
    name = f"{r['scene']}_{r['label']}_motion-{r['motion']['what']}"
    return re.sub(r"[^A-Za-z0-9.\-]", "_", name) + "_flicker.png"


def reference_seconds(bench_dir):
    """{scene: (mean seconds per reference frame, frames timed, threads)} from the cache's sidecars
    (references/*.json, written when a reference is rendered; a cached one keeps its first time)."""
    per = {}
    for f in sorted((Path(bench_dir) / "references").glob("*.json")):
        info = json.loads(f.read_text())
        per.setdefault(info["scene"], []).append((info["seconds"], info["threads"], tuple(info["size"])))
    return {s: (sum(x[0] for x in v) / len(v), len(v), v[0][1], v[0][2]) for s, v in per.items()}


def excess(runs, scene, lab, what):
    r = next((r for r in runs if r["scene"] == scene and r["label"] == lab and r["motion"]["what"] == what), None)
    return r["flicker"]["meanExcess"] if r else None


def epipolar_findings(runs, scenes, w, h):
    """Where epipolar's flicker beyond brute force's comes from, from the sweep rows of the run."""
    out = []
    p = out.append
    # Marching every sample: "initialStep=1" in runs recorded before the sweep took the field's name.
    every = next((s for s in ("initialSampleStep=1", "initialStep=1") if any(r["label"] == s for r in runs)),
                 "initialSampleStep=1")
    sweeps = [every, "refinementThreshold=0.01", "refinementThreshold=0.003", "slices=128"]
    have = [s for s in sweeps if any(r["label"] == s for r in runs)]
    if not any(r["label"] == "epipolar balanced" for r in runs) or not have or \
            not any(r["method"] == "brute-force" for r in runs):
        return out
    p("**Epipolar's own part.** Brute force marches every pixel through the same shadow map as epipolar, so "
      "its excess is what the shadow map adds (its texels against exact visibility; for a sun under camera "
      "motion, a map refitted to the view every frame); epipolar's excess above brute force's is its "
      "sampling's. The sweeps from the balanced profile show where that part comes from (mean excess; "
      "scenes whose light the plugin does not shadow are left out, as both methods compute the same closed "
      "form there):\n")
    head = "| scene | motion | brute force | epipolar balanced |" + "".join(f" {s} |" for s in have)
    p(head)
    p("|---" * (4 + len(have)) + "|")
    gaps, closed = [], {s: [] for s in have}
    for scene in scenes:
        for what in ("light", "camera"):
            bf, epi = excess(runs, scene, "brute-force", what), excess(runs, scene, "epipolar balanced", what)
            if bf is None or epi is None or epi == bf:
                continue  # an unshadowed light: both compute the same closed form, nothing is sampled
            line = f"| {scene} | {what} | {pct(bf)} | {pct(epi)} |"
            for sw in have:
                v = excess(runs, scene, sw, what)
                line += f" {pct(v)} |"
                if v is not None and epi - bf > 0:
                    closed[sw].append((epi - v) / (epi - bf))
            if epi - bf > 0:
                gaps.append(epi - bf)
            p(line)
    p("")
    mean = lambda v: sum(v) / len(v) if v else None
    share = {sw: mean(v) for sw, v in closed.items()}
    if share.get(every) is not None:
        p(f"Marching every sample ({every}, no interpolation along the lines) removes on average "
          f"{fmt(100 * share[every], 2)}% of epipolar's part (the gap to brute force), so most of it is "
          "interpolation between ray-marching samples. The cause: depth-break refinement looks at camera depth "
          "alone. Where a shadow edge crosses an epipolar line without a depth step above `refinementThreshold` "
          "(3% by default), in the open medium or on a surface whose depth steps a little (a window's recess, "
          "a wall seen at a grazing angle), no sample is added there, and the pixels between two ray-marching "
          "samples (`initialSampleStep` samples apart) take a shadowed fraction interpolated across the edge. "
          "As the light's or the camera's screen position moves, every slice's line turns and its samples "
          "slide along it, so the ray-marching samples land elsewhere on the edge each frame and the "
          "interpolated edge jumps: flicker along the epipolar lines (the streaks in the heat maps below).")
        for sw in ("refinementThreshold=0.01", "refinementThreshold=0.003"):
            if share.get(sw) is not None:
                p(f"A lower threshold, {sw.split('=')[1]}, marches the small steps too and removes "
                  f"{fmt(100 * share[sw], 2)}% of it on average.")
        p(f"At {w}x{h} the lines are short, so every profile places one sample per pixel along them and the "
          "threshold is crossed by a pixel's depth step; on a larger screen a surface's step per sample is "
          "smaller and fewer samples are marched at the same threshold. Refinement on in-scattering "
          "differences (`Settings::epipolar.inscatterRefinementThreshold`, off by default: samples are added where two "
          "marched neighbours disagree in what they carry, not only in depth) adds samples at these edges "
          "whatever their depth; on the atrium under a moving light it removes 43% of epipolar's excess over "
          "brute force at 0.05 ([epipolar.md](epipolar.md)), and `refinementThreshold` trades ray-marching "
          "samples for stability too. The defaults are unchanged here: every profile already meets the goal "
          "on these scenes.")
    ratios = [excess(runs, sc, "slices=128", wh) / excess(runs, sc, "epipolar balanced", wh)
              for sc in scenes for wh in ("light", "camera")
              if excess(runs, sc, "slices=128", wh) is not None and excess(runs, sc, "epipolar balanced", wh)]
    if ratios:
        balanced = next(r for r in runs if r["label"] == "epipolar balanced")
        here = 2 * (w + h) / 128
        full_hd = 2 * (1920 + 1080) / balanced["slices"]
        p(f"Fewer slices add flicker across the lines instead: with 128 slices (one per {fmt(here, 2)} boundary "
          f"pixels here, nearer to balanced's density at 1920x1080, one per {fmt(full_hd, 2)}) epipolar's excess "
          f"is {fmt(mean(ratios))} times balanced's on average, as the unwarp interpolates between slices that "
          "turn with the light. At real screen sizes, with fewer slices per pixel, epipolar may therefore "
          "flicker more than these figures show.")
    p("")
    return out


def flicker_section(bench_dir, image_dir=None):
    """Lines of Markdown."""
    runs = load(bench_dir)
    out = []
    p = out.append
    p(FLICKER_HEADING + "\n")
    if not runs:
        p(f"No motion rows in {bench_dir}/bench.json.\n")
        return out
    r0 = runs[0]
    w, h = r0["size"]
    m = r0["motion"]
    kind = ("lavapipe, a CPU driver" if r0["cpuDevice"] else "GPU")
    p("Flicker is a method's image changing from one frame to the next by more than the scene does. "
      f"`bench/flicker.json` renders {m['frames']} frames while the light moves slowly, then {m['frames']} "
      "while the camera does, and judges every frame against the float64 reference at the same pose. "
      f"Measured on {date.today().isoformat()}{commit_note()} with `./build/host_example/lightscatter bench --config "
      "bench/flicker.json --out build/bench-flicker` (`scripts/make-report.sh --flicker-only` runs it and "
      f"splices this section into the page) at {w}x{h} on **{r0['device']}** ({kind}; flicker and error "
      "do not depend on the device's speed, so these figures need no quiet machine).\n")
    p(f"- **The motions.** Light: a sun turns {fmt(m['lightDegreesPerFrame'])} degree a frame towards the "
      f"camera's right ({fmt(m['lightDegreesPerFrame'] * (m['frames'] - 1))} degrees in all), a spot or point "
      f"light moves {fmt(100 * m['lightMetresPerFrame'])} cm a frame to the camera's right. Camera: "
      f"{fmt(100 * m['cameraMetresPerFrame'])} cm to its right and a turn of {fmt(m['cameraDegreesPerFrame'])} "
      "degree to the right about its up vector, each frame. Only the scene's first light moves.")
    p("- **Excess flicker**, per pixel and channel and each pair of consecutive frames: "
      "`max(0, |L_k - L_(k-1)| - |R_k - R_(k-1)|)`, L the method's Lin and R the reference's. Whatever "
      "the reference itself changes by is the motion, not flicker. **Mean**: the sum of the excess over "
      "the sum of `|R_k|`, the same normalisation as the mean relative error, so that the two compare "
      "directly. **p99**: the 99th percentile of the excess over the reference's mean `|R_k|`.")
    p("- **Error change**: `|(L_k - R_k) - (L_(k-1) - R_(k-1))|`, normalised as the mean. It is never below "
      "the excess (triangle inequality) and also counts a method that moves differently from the "
      "reference without changing more (a shaft that lags or slides); where the two agree, the change "
      "is flicker.")
    p("- **Reference change**: the reference's own mean change per frame (how much the motion moves).")
    p("- **Mean error**: the mean relative error over all the frames of the motion (the goal: mean "
      "excess no larger than it). Rows over the goal are marked **over**.")
    secs = reference_seconds(bench_dir)
    if secs:
        parts = [f"{s} {fmt(v[0])} s" for s, v in sorted(secs.items())]
        threads = next(iter(secs.values()))[2]
        total = sum(v[0] * v[1] for v in secs.values())
        motions = {r["motion"]["what"] for r in runs}
        poses = len(motions) * (m["frames"] - 1) + 1
        p(f"- **The reference** is rendered once per pose ({poses} poses a scene"
          f"{': the first is shared by both motions' if len(motions) > 1 else ''}) and cached in `build/bench-flicker/references`, "
          "keyed by a hash of the scene file, the pose, the triangles, the size and the reference code's "
          f"sources, so a rerun renders none. At {w}x{h} one took, on {threads} threads of this machine "
          f"(while other work shared its cores): {', '.join(parts)}; "
          f"{fmt(total / 60)} minutes for the poses timed. That cost is why the size is {w}x{h}.")
    p("")
    goal_misses = []
    scenes = sorted({r["scene"] for r in runs})
    profile_rows = [r for r in runs if r["family"] == "profiles" and r["method"] == "epipolar"]
    if profile_rows and all(r["slices"] >= 2 * (w + h) and r["samples"] >= math.hypot(w, h) for r in profile_rows):
        p(f"Epipolar's profiles sample alike at {w}x{h}: each has more slices than the screen has boundary pixels "
          f"({2 * (w + h)}) and more samples per slice than the longest line has pixels (lines are then stretched "
          "to one sample per pixel), so their rows differ little.\n")
    for scene in scenes:
        rows = [r for r in runs if r["scene"] == scene]
        p(f"### {scene}\n")
        p("| configuration | light: mean excess | p99 excess | error change | mean error | camera: mean excess "
          "| p99 excess | error change | mean error |")
        p("|---|---|---|---|---|---|---|---|---|")
        seen = []
        for r in rows:
            if r["label"] not in seen:
                seen.append(r["label"])
        for lab in seen:
            line = f"| {label(next(r for r in rows if r['label'] == lab))} |"
            for what in ("light", "camera"):
                r = next((r for r in rows if r["label"] == lab and r["motion"]["what"] == what), None)
                if not r:
                    line += " - | - | - | - |"
                    continue
                f = r["flicker"]
                over = f["meanExcess"] > f["meanRelativeError"]
                if over:
                    goal_misses.append((scene, lab, what, f))
                line += (f" {pct(f['meanExcess'])}{' **over**' if over else ''} | {pct(f['p99Excess'])} | "
                         f"{pct(f['meanErrorChange'])} | {pct(f['meanRelativeError'])} |")
            p(line)
        refs = {what: next((r["flicker"]["referenceChange"] for r in rows if r["motion"]["what"] == what), None)
                for what in ("light", "camera")}
        p(f"\nThe reference changes by {pct(refs['light'])} a frame as the light moves and {pct(refs['camera'])} "
          "as the camera does.\n")
    out += epipolar_findings(runs, scenes, w, h)
    if goal_misses:
        p("Over the goal (mean excess above the mean error): " + "; ".join(
            f"{s} {lab} ({what}: {pct(f['meanExcess'])} against {pct(f['meanRelativeError'])})"
            for s, lab, what, f in goal_misses) + ".\n")
    else:
        p("Every configuration meets the goal: its mean excess flicker is below its mean error.\n")
    if image_dir:
        for old in Path(image_dir).glob("flicker_*.png"):
            old.unlink()  # an earlier run's, perhaps of configurations no longer run
        shown = []
        for r in runs:
            if r["label"] in ("epipolar balanced", "brute-force"):
                src = Path(bench_dir) / "strips" / strip_name(r)
                if src.exists():
                    os.makedirs(image_dir, exist_ok=True)
                    shutil.copy(src, Path(image_dir) / f"flicker_{strip_name(r)}")
                    shown.append(r)
        if shown:
            p("Where the flicker is, per pixel: the reference's own mean change (left) and the method's mean "
              "excess over it (right), on one scale (white at the larger 99th percentile of the two).\n")
            p("| scene | motion | epipolar balanced | brute force |")
            p("|---|---|---|---|")
            for scene in scenes:
                for what in ("light", "camera"):
                    cells = []
                    for lab in ("epipolar balanced", "brute-force"):
                        r = next((r for r in shown if r["scene"] == scene and r["label"] == lab
                                  and r["motion"]["what"] == what), None)
                        cells.append(f"![{lab}, {what}](performance/flicker_{strip_name(r)})" if r else "-")
                    p(f"| {scene} | {what} | {cells[0]} | {cells[1]} |")
            p("")
    return out
