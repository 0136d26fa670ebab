"""The 'Which profile for which budget' section: the profiles on the Pareto front and the sweeps'
reach."""
from .common import fmt, sweep_family


def profiles_section(runs, scenes):
    out = []
    p = out.append
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
    for family in ("slices", "samplesPerSlice", "initialSampleStep", "shadowMapSize", "minMaxTrees"):
        per_scene, named = [], family
        for scene in scenes:
            rows = [r for r in runs if r["scene"] == scene and sweep_family(r) == family
                    and r["method"] == "epipolar" and "error" in r]
            errs = [r["error"]["meanRelative"] for r in rows]
            if len(errs) > 1:
                per_scene.append(max(errs) - min(errs))
                named = rows[0]["family"]  # as the run recorded it ("samples" before samplesPerSlice)
        if per_scene:
            spans[named] = sum(per_scene) / len(per_scene)
    for family, span in sorted(spans.items(), key=lambda kv: -kv[1]):
        p(f"- {family}: {100 * span:.2f} percentage points")
    if any(r["family"] == "size" for r in runs):
        p("\nThe epipolar method's cost grows with slices x samples and the shadow map, hardly with the screen; "
          "brute force's grows with every pixel ([Scaling](#scaling): where brute force is ahead, the screen is "
          "too small for the fixed cost to pay off on this device).\n")
    return out
