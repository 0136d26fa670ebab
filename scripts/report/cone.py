"""The 'Seed 003: marching only inside the cone' section, from the main run's cone rows."""
from .common import fmt


def cone_section(runs, scenes):
    out = []
    p = out.append
    cone = [r for r in runs if r["family"] == "cone"]
    if cone:
        p("## Seed 003: marching only inside the cone\n")
        p("Seed 003's comparison on each scene: the same fixed number of samples per pixel over the whole ray "
          "(naive), over the part inside the spot's cone and range (cone), and inside the cone without "
          "shadow-map look-ups (no-shadow-sampling, the seed's low-end mode: no shadows at all). A "
          "directional or point light has no cone, so there cone and naive march the same interval. Same "
          "scene, size and settings for every row; time and error as above.\n")
        for scene in scenes:
            rows = [r for r in cone if r["scene"] == scene]
            if not rows:
                continue
            brute = next((r for r in runs if r["scene"] == scene and r["method"] == "brute-force"
                          and r["family"] == "profiles"), None)
            p(f"### {scene}\n")
            p("| mode | samples per pixel | median ms | speed-up over brute force | mean rel. error | over 5% |")
            p("|---|---|---|---|---|---|")
            for r in sorted(rows, key=lambda r: (r["label"].split()[0], r["coneSamples"])):
                t, e = r["time"], r.get("error", {})
                speed = brute["time"]["median"] / t["median"] if brute and t["median"] > 0 else None
                p(f"| {r['label'].split()[0]} | {r['coneSamples']} | {fmt(t['median'])} | "
                  f"{fmt(speed) + 'x' if speed else '-'} | {fmt(e.get('meanRelative'))} | "
                  f"{fmt(100 * e['fractionOver5pct']) + '%' if e else '-'} |")
            p("")
    return out
