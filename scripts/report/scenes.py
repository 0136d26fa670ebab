"""One section per scene of the main run: its profiles' time and error against brute force, its
sweeps and its strips."""
import json
from pathlib import Path

from . import speed as rs
from .common import fmt


def scene_sections(runs, scenes):
    out = []
    p = out.append
    for scene in scenes:
        rows = [r for r in runs if r["scene"] == scene and r["family"] == "profiles"]
        brute = next((r for r in rows if r["method"] == "brute-force"), None)
        w, h = rows[0]["size"]
        p(f"## {scene} ({w}x{h})\n")
        scene_file = Path("scenes") / f"{scene}.json"
        light = json.loads(scene_file.read_text()).get("light", {}) if scene_file.exists() else {}
        if light.get("type") == "point" and not light.get("shadowMapSize"):
            p("This scene's point light has no shadow map (the scene gives it none; `scenes/point_cage` is the "
              "one with a cube map, in [Several lights](#several-lights)): epipolar and brute force compute the "
              "same closed form (the point-light table), analytic seed 001's arctangent (which ignores the "
              "phase function's shape and extinction), cone-march samples the same integrand; the error is "
              "mostly the shadows the reference has and the plugin lacks. Epipolar's rows time the same per-pixel "
              "computation as brute force's, so their speed-up over brute force is 1 within the run's noise (the "
              "p10-p90 spread): below 1 in one run, above in another, it measures the run, not the method.\n")
        p(f"![time against error, {scene}](performance/time_vs_error_{scene}.png)\n")
        p("| configuration | slices x samples | median ms (p10-p90) | speed-up over brute force | mean rel. error | "
          "p99 | max | over 5% | PSNR dB | non-finite |")
        p("|---|---|---|---|---|---|---|---|---|---|")
        for r in rows:
            if r["method"] == "auto" and r.get("methodRan"):
                r = dict(r, label=f"auto (ran {r['methodRan']})")
            if r["method"] == "cone-march":
                r = dict(r, label=f"cone-march ({r.get('coneSamples', 32)} samples)")
            t = r["time"]
            e = r.get("error", {})
            speed = brute["time"]["median"] / t["median"] if brute and t["median"] > 0 else None
            ss = f"{r['slices']} x {r['samples']}" if r["method"] == "epipolar" else "-"
            p(f"| {r['label']} | {ss} | {fmt(t['median'])} ({fmt(t['p10'])}-{fmt(t['p90'])}) | "
              f"{fmt(speed) + 'x' if speed else '-'} | {fmt(e.get('meanRelative'))} | {fmt(e.get('p99'))} | "
              f"{fmt(e.get('max'))} | {fmt(100 * e['fractionOver5pct']) + '%' if e else '-'} | "
              f"{fmt(e.get('psnrDb'))} | {r['nonFinite']} |")
        p("")
        balanced = next((r for r in rows if r["label"] == "epipolar balanced"), None)
        if balanced:
            out += rs.pass_breakdown_lines(balanced, fmt)
        sweeps = [r for r in runs if r["scene"] == scene and r["family"] not in ("profiles", "cone")]
        if sweeps:
            p("Sweeps from the balanced profile (one parameter at a time; the speed-up is over brute force at the "
              "same screen and shadow-map size, same run):\n")
            p("| sweep | median ms | speed-up over brute force | mean rel. error | over 5% |")
            p("|---|---|---|---|---|")
            for r in sweeps:
                e = r.get("error")
                b = next((x for x in runs if x["scene"] == scene and x["method"] == "brute-force"
                          and tuple(x["size"]) == tuple(r["size"]) and x["shadowMapSize"] == r["shadowMapSize"]
                          and x["family"] in ("profiles", "size", "shadowMapSize")), None)
                speed = b["time"]["median"] / r["time"]["median"] if b and r["time"]["median"] > 0 else None
                p(f"| {r['label']} | {fmt(r['time']['median'])} | {fmt(speed) + 'x' if speed else '-'} | "
                  f"{fmt(e['meanRelative']) if e else '(timing only)'} | "
                  f"{fmt(100 * e['fractionOver5pct']) + '%' if e else '-'} |")
            p("")
        p(f"Reference, epipolar (balanced) and error heat map (black 0, white 10% of the reference's p99):\n")
        p(f"![strip](performance/strip_{scene}_epipolar_balanced.png)\n")
        p(f"Brute force:\n\n![strip](performance/strip_{scene}_brute-force.png)\n")
    return out
