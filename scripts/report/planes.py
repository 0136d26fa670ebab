"""The 'Seed 002: view-aligned planes' section."""
import json
from datetime import date

from .common import fmt

PLANES_HEADING = "## Seed 002: view-aligned planes"
# The section's heading on pages written before the planes method was renamed from "slices" (the
# word now means only an epipolar line): a section spliced in replaces it.
FORMER_HEADING = "## Seed 002: slice planes"
# The method's names in bench results: "slices" in runs made before the rename.
PLANES_METHOD = ("planes", "slices")


def planes_section(planes_dir):
    """Seed 002's planes against epipolar and brute force (bench/planes.json), per scene, with the
    8-bit targets' banding strips."""
    out = []
    p = out.append
    plane_runs = json.loads((planes_dir / "bench.json").read_text())["runs"]
    w, h = plane_runs[0]["size"]
    p(f"{PLANES_HEADING} at {w}x{h}\n")
    p(f"`planes` against epipolar (balanced) and brute force on the spot and directional scenes at {w}x{h} "
      f"(`bench/planes.json`, measured on {date.fromtimestamp((planes_dir / 'bench.json').stat().st_mtime).isoformat()}: {plane_runs[0]['frames']} frame after "
      f"{plane_runs[0].get('warmup', 1)} of warm-up per row, on {plane_runs[0]['device']}; at this size brute "
      "force takes seconds per frame on a CPU; `scripts/make-report.sh --planes-only` reruns it and replaces this "
      "section). Each "
      "planes row is a plane count and an accumulation target (docs/methods.md): float16, float32, rgba8 "
      "(seed 002's four 8-bit channels, rounded to nearest) and rgba8-dither (the same with stochastic "
      "rounding). Speed-up and error of every row are against brute force in the same run.\n")
    p(f"![planes against epipolar and brute force](performance/planes_{w}x{h}.png)\n")
    for scene in sorted({r["scene"] for r in plane_runs}):
        rows = [r for r in plane_runs if r["scene"] == scene]
        brute = next((r for r in rows if r["method"] == "brute-force"), None)
        p(f"### {scene}\n")
        p("| configuration | median ms | speed-up over brute force | mean rel. error | brute force's error | "
          "over 5% |")
        p("|---|---|---|---|---|---|")
        for r in rows:
            t, e = r["time"], r.get("error", {})
            speed = brute["time"]["median"] / t["median"] if brute and t["median"] > 0 else None
            label = "planes balanced (128 planes, float16)" if r["method"] in PLANES_METHOD and \
                r["family"] == "profiles" else r["label"]
            p(f"| {label} | {fmt(t['median'])} | {fmt(speed) + 'x' if speed else '-'} | "
              f"{fmt(e.get('meanRelative'))} | {fmt(brute['error']['meanRelative']) if brute else '-'} | "
              f"{fmt(100 * e['fractionOver5pct']) + '%' if e else '-'} |")
        p("")
    banding = [r for r in plane_runs if r["method"] in PLANES_METHOD and "rgba8" in r["label"]]
    if banding:
        p("The 8-bit targets' banding, window_room at 256 planes, seed 002's rounding and stochastic rounding "
          "(reference, result, error heat map):\n")
        for r in banding:
            if r["scene"] == "window_room" and "256" in r["label"]:
                name = f"strip_planes_{r['label'].replace(' ', '_')}.png"
                p(f"{r['label']}:\n\n![{r['label']}](performance/{name})\n")
    return out
