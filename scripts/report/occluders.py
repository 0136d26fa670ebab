"""The 'Beam tree against scene complexity' section: seed 004's beam tree against the number of
boxes."""
import sys
from datetime import date
from pathlib import Path

from .common import SEED, fmt, load_note

OCCLUDERS_HEADING = "## Beam tree against scene complexity"


def occluders_section(occ_dir):
    """The section on seed 004's beam tree against the number of boxes, from a bench run of
    bench/occluders.json (scripts/plot_occluders.py draws its plot). Lines of Markdown."""
    # The plot scripts beside this package compute the numbers their plots show.
    sys.path.insert(0, str(Path(__file__).resolve().parents[1]))
    import plot_occluders as po

    runs = po.load(occ_dir)
    table = po.occluder_rows(runs)
    ref, ref_label = po.reference_ms(table)
    methods = po.beam_methods(table)
    r0 = runs[0]
    w, h = r0["size"]
    kind = ("lavapipe CPU timings: the 'GPU' time is the CPU running Vulkan, on the same two cores as the tree"
            if r0["cpuDevice"] else "GPU timestamps")
    out = []
    p = out.append
    p(OCCLUDERS_HEADING + "\n")
    p(f"Seed 004 says its beam tree cannot cope with highly tessellated scenes. `scenes/occluders_N` "
      f"(`tools/make_scenes/make_occluder_scenes.py`) are N boxes (pillars and crates, varied heights, turned, on a "
      f"jittered grid over the same 16 m square) on a floor under a spot light shining down across them; the "
      f"host hands the plugin one oriented box per connected part of each glTF primitive (here each box and "
      f"the floor), so the tree gets N + 1 occluders. Measured "
      f"on {date.today().isoformat()} with `./build/host_example/lightscatter bench --config bench/occluders.json "
      f"--out build/bench-occluders` (`scripts/make-report.sh --occluders-only` runs it, draws the plot and "
      f"splices this section into the page) "
      f"at {w}x{h}, balanced settings, the median of {r0['frames']} frames after warm-up, on "
      f"**{r0['device']}** ({kind}). CPU ms is the tree's build (`FrameReport::cpuWork`: the tree, the lit "
      f"pyramids and the sampling planes' partition), GPU ms the plugin's passes; no error is measured here "
      f"(`measureError: false`: a float64 reference at this size takes too long).\n")
    note = load_note(occ_dir)
    if note:
        p(note + "\n")
    p("![beam tree against scene complexity](performance/occluders_scaling.png)\n")
    head = "| boxes | occluders given |"
    rule = "|---|---|"
    for m in methods:
        head += f" {m} CPU ms | {m} GPU ms | {m} CPU + GPU ms |"
        rule += "---|---|---|"
    head += f" {ref_label or 'epipolar'} GPU ms |"
    rule += "---|"
    p(head)
    p(rule)
    counts = sorted({r[0] for rows in table.values() for r in rows})
    for n in counts:
        given = next((r[1] for rows in table.values() for r in rows if r[0] == n and r[1] is not None), None)
        line = f"| {n} | {given if given is not None else '-'} |"
        for m in methods:
            row = next((r for r in table[m] if r[0] == n), None)
            line += (f" {fmt(row[2])} | {fmt(row[3])} | {fmt(row[2] + row[3])} |" if row else " - | - | - |")
        epi = next((r for r in table.get(ref_label, []) if r[0] == n), None)
        line += f" {fmt(epi[3]) if epi else '-'} |"
        p(line)
    p("")
    if ref is not None:
        for m in methods:
            n, how = po.crossover(table[m], ref)
            cpu_n, cpu_how = po.crossover([(c, g, cpu, 0.0) for c, g, cpu, _ in table[m]], ref)
            if how == "interpolated":
                text = (f"**Crossover ({m}): about {n:.0f} boxes.** Below it the tree's CPU build plus its GPU "
                        f"time is less than epipolar's GPU time ({fmt(ref)} ms, the median over these scenes); "
                        f"above it epipolar is cheaper. This is interpolated (linearly in log boxes and log ms) "
                        f"between the two measured counts around it, not measured at that count.")
            elif how == "below":
                text = (f"**Crossover ({m}): at or below {n} box(es).** Already at the smallest measured count "
                        f"the tree's CPU build plus its GPU time ({fmt(table[m][0][2] + table[m][0][3])} ms) is "
                        f"more than epipolar's GPU time ({fmt(ref)} ms) on this device.")
            else:
                text = (f"**Crossover ({m}): above {n} boxes.** Up to the largest measured count the tree's CPU "
                        f"build plus its GPU time stays below epipolar's GPU time ({fmt(ref)} ms).")
            p(text)
            if cpu_how == "interpolated":
                p(f"The CPU build alone reaches epipolar's GPU time at about {cpu_n:.0f} boxes (interpolated the "
                  f"same way).")
            elif cpu_how == "below":
                p(f"The CPU build alone already exceeds epipolar's GPU time at {cpu_n} box(es).")
            else:
                p(f"The CPU build alone stays below epipolar's GPU time up to {cpu_n} boxes.")
            p("")
        for m in methods:
            last = max((r for r in runs if r["method"] == m), key=po.boxes)
            top = max(last["passes"], key=lambda x: x["median"])
            first = min((r for r in runs if r["method"] == m), key=po.boxes)
            top_first = next((x for x in first["passes"] if x["name"] == top["name"]), None)
            p(f"Where {m}'s GPU time goes: at {po.boxes(last)} boxes its largest pass is '{top['name']}', "
              f"{fmt(top['median'])} of {fmt(last['time']['median'])} ms"
              + (f" ({fmt(top_first['median'])} ms at {po.boxes(first)} "
                 f"{'box' if po.boxes(first) == 1 else 'boxes'})" if top_first else "")
              + (". More boxes give more pyramids, and each of their faces is rasterised over the screen area "
                 "it covers, so this pass grows with the pyramids' overlapping screen area, not with the pixel "
                 "count alone." if "pyramid" in top["name"] else
                 ". More boxes cut the sampling planes into more parts, each drawn over the screen area it "
                 "covers." if "plane" in top["name"] else ".") + "\n")
    if ref is not None and r0["cpuDevice"]:
        text = ("On lavapipe both columns are CPU time, so the crossover above compares like with like only on "
                "this machine. On a GPU the passes take a small fraction of these milliseconds while the tree's "
                "build stays what it is (it runs on the CPU either way), so there the tree's build alone against "
                "epipolar's GPU time is the comparison that matters, and the crossover moves to fewer boxes.")
        seed_ms = SEED["balanced"][0]
        counts = []
        for m in methods:
            n, how = po.crossover([(c, g, cpu, 0.0) for c, g, cpu, _ in table[m]], seed_ms)
            if how == "interpolated":
                counts.append(f"about {n:.0f} boxes for {m}")
            elif how == "below":
                counts.append(f"at or below {n} box(es) for {m}")
        if counts:
            text += (f" Not measured here (no GPU machine), but for scale: seed 000's balanced epipolar frame is "
                     f"{seed_ms} ms on its GPU (GTX 680, 2560x1600), and this machine's tree build alone reaches "
                     f"that at {' and '.join(counts)} (interpolated as above); with the beam tree's own GPU passes "
                     f"on top, a GPU's crossover would lie at or below that count.")
        p(text + "\n")
    return out

