"""The 'Seed 002: slice planes' section."""
import json
from datetime import date

from .common import fmt

SLICES_HEADING = "## Seed 002: slice planes"


def slices_section(slices_dir):
    """Seed 002's slice planes against epipolar and brute force (bench/slices.json), per scene, with
    the 8-bit targets' banding strips."""
    out = []
    p = out.append
    slice_runs = json.loads((slices_dir / "bench.json").read_text())["runs"]
    w, h = slice_runs[0]["size"]
    p(f"{SLICES_HEADING} at {w}x{h}\n")
    p(f"`slices` against epipolar (balanced) and brute force on the spot and directional scenes at {w}x{h} "
      f"(`bench/slices.json`, measured on {date.fromtimestamp((slices_dir / 'bench.json').stat().st_mtime).isoformat()}: {slice_runs[0]['frames']} frame after "
      f"{slice_runs[0].get('warmup', 1)} of warm-up per row, on {slice_runs[0]['device']}; at this size brute "
      "force takes seconds per frame on a CPU; `scripts/make-report.sh --slices-only` reruns it and replaces this "
      "section). Each "
      "slices row is a plane count and an accumulation target (docs/methods.md): float16, float32, rgba8 "
      "(seed 002's four 8-bit channels, rounded to nearest) and rgba8-dither (the same with stochastic "
      "rounding). Speed-up and error of every row are against brute force in the same run.\n")
    p(f"![slices against epipolar and brute force](performance/slices_{w}x{h}.png)\n")
    for scene in sorted({r["scene"] for r in slice_runs}):
        rows = [r for r in slice_runs if r["scene"] == scene]
        brute = next((r for r in rows if r["method"] == "brute-force"), None)
        p(f"### {scene}\n")
        p("| configuration | median ms | speed-up over brute force | mean rel. error | brute force's error | "
          "over 5% |")
        p("|---|---|---|---|---|---|")
        for r in rows:
            t, e = r["time"], r.get("error", {})
            speed = brute["time"]["median"] / t["median"] if brute and t["median"] > 0 else None
            label = "slices balanced (128 planes, float16)" if r["method"] == "slices" and \
                r["family"] == "profiles" else r["label"]
            p(f"| {label} | {fmt(t['median'])} | {fmt(speed) + 'x' if speed else '-'} | "
              f"{fmt(e.get('meanRelative'))} | {fmt(brute['error']['meanRelative']) if brute else '-'} | "
              f"{fmt(100 * e['fractionOver5pct']) + '%' if e else '-'} |")
        p("")
    banding = [r for r in slice_runs if r["method"] == "slices" and "rgba8" in r["label"]]
    if banding:
        p("The 8-bit targets' banding, window_room at 256 planes, seed 002's rounding and stochastic rounding "
          "(reference, result, error heat map):\n")
        for r in banding:
            if r["scene"] == "window_room" and "256" in r["label"]:
                name = f"strip_slices_{r['label'].replace(' ', '_')}.png"
                p(f"{r['label']}:\n\n![{r['label']}](performance/{name})\n")
    return out


def slices_lines(slices_dir):
    lines = slices_section(slices_dir)
    return lines, lines[0].rstrip("\n")

