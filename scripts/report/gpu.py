"""The 'GPU timings' section: the GPU machine's run of scripts/gpu-bench.sh."""
import json

from .common import fmt

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

