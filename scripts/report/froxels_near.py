"""The 'Froxels near the light' section: the froxel grid's error on scenes with a point or spot light
on or beside the screen, from a `lightscatter bench` run of bench/froxels_near_light.json, against the
float64 reference, beside epipolar balanced and brute force on the same frames."""
import json
from datetime import date
from pathlib import Path

from .common import fmt
from .runs import commit_note

FROXELS_NEAR_HEADING = "## Froxels near the light"

# The shipped scene the grid must hold within TARGET at the bench's size with froxels-hdrp.
TARGET_SCENE, TARGET_LABEL, TARGET = "spot_near_edge", "froxels-hdrp", 0.10

COLUMNS = ("froxels-hdrp", "froxels-unreal", "epipolar balanced", "brute-force")


def froxels_near_section(bench_dir):
    runs = json.loads((Path(bench_dir) / "bench.json").read_text())["runs"]
    out = []
    p = out.append
    p(FROXELS_NEAR_HEADING + "\n")
    if not runs:
        return out
    w, h = runs[0]["size"]
    err = {(r["scene"], r["label"]): r["error"]["meanRelative"] for r in runs if r.get("error")}
    scenes = list(dict.fromkeys(r["scene"] for r in runs))
    p("A point or spot light's froxel takes its slice of the column's ray in closed form, bounded in the "
      "slice that holds the light (docs/methods.md, froxels): where the light is on or beside the screen, "
      "one point sample per froxel lands near the inverse square's peak and spreads it over the froxel. "
      "Mean relative error against the float64 reference, one frame per configuration, `froxels-hdrp` "
      "(8-pixel columns, 64 slices) and `froxels-unreal` (16-pixel columns) beside epipolar balanced and "
      "brute force on the same frame.\n")
    p(f"Measured on {date.today().isoformat()}{commit_note()} with `./build/host_example/lightscatter bench --config "
      f"bench/froxels_near_light.json --out build/bench-froxels-near` (`scripts/make-report.sh "
      f"--froxels-near-only` runs it and splices this section) at {w}x{h}, on **{runs[0]['device']}** "
      "(errors do not depend on the device's speed; the grid's cost is in "
      "[Against froxel fog](#against-froxel-fog)).\n")
    p("| scene | " + " | ".join(COLUMNS) + " |")
    p("|---" * (len(COLUMNS) + 1) + "|")
    for scene in scenes:
        p(f"| {scene} | " + " | ".join(fmt(err.get((scene, c))) for c in COLUMNS) + " |")
    p("")
    got = err.get((TARGET_SCENE, TARGET_LABEL))
    if got is not None:
        verdict = "within" if got <= TARGET else "over"
        p(f"`{TARGET_SCENE}` (a spot on screen near the edge) with `{TARGET_LABEL}` at {w}x{h}: "
          f"{fmt(got)}, {verdict} the {TARGET:.0%} asked of the grid there. `FroxelsNearLight` in "
          "`test_hard_suite` holds it at a size the suite affords, where a point sample per froxel "
          "fails the same bound.\n")
    return out
