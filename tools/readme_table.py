#!/usr/bin/env python3
"""Writes the README's table of which method for which scene from docs/performance.md's figures, so
that a later measurement updates it and the two cannot disagree.

    tools/readme_table.py [REPO_ROOT]            prints the table (with its opening line)
    tools/readme_table.py --write [REPO_ROOT]    puts it into README.md between its markers
    tools/readme_table.py --check [REPO_ROOT]    exit 1 if README.md's table is not what it writes
    tools/readme_table.py --self-test            checks the rules on a small made-up page

The second table, when the page has it, is the section "Froxels against epipolar: the two families":
per scene, the grid's error at epipolar balanced's time and epipolar's time at the grid's error.

The figures are the section "Against froxel fog" of docs/performance.md: one run of
bench/froxels.json at 1920x1080 (every scene timed and measured against the float64 reference in
the same run), and its table of the cost of N shadowed spots. The rules:

- each scene of that section gets the cheapest configuration, brute force aside, whose mean
  relative error is within ERROR_BOUND times brute force's on that scene (brute force is the
  baseline every time is divided by, and the most accurate of the plugin's methods);
- a last row is the many-lights case with blurred shafts accepted: the cheapest configuration at the
  largest light count of the N-spots table, with its error as a multiple of epipolar balanced's on
  the scene of several shadowed lights that was measured (atrium_lights).
"""
import os
import re
import sys

ERROR_BOUND = 1.10
SECTION = "## Against froxel fog"
BEGIN = "<!-- BEGIN tools/readme_table.py: generated from docs/performance.md; do not edit by hand -->"
END = "<!-- END tools/readme_table.py -->"
SEVERAL = "atrium_lights"
BASE = "epipolar balanced"
# What each scene shows, for the reader (no figures here).
SCENES = {
    "window_room": "shafts through a grille (`window_room`)",
    "engine_spot": "a spot behind an engine block (`engine_spot`)",
    "atrium": "a low sun between columns (`atrium`)",
    "atrium_lights": "a sun and two shadowed spots (`atrium_lights`)",
    "point_cage": "a point light in bars, cube map (`point_cage`)",
    "point_fog": "an unshadowed point light in fog (`point_fog`)",
    "spot_near_edge": "a spot on screen near the edge (`spot_near_edge`)",
}


def section(page):
    lines = page.split("\n")
    if SECTION not in lines:
        raise SystemExit(f"docs/performance.md has no section '{SECTION}'")
    start = lines.index(SECTION)
    end = next((i for i in range(start + 1, len(lines)) if lines[i].startswith("## ")), len(lines))
    return lines[start:end]


def tables(lines):
    """Each Markdown table of the lines: (header cells, [row cells])."""
    out, i = [], 0
    while i < len(lines):
        if lines[i].startswith("|") and i + 1 < len(lines) and re.match(r"^\|[-|: ]+\|$", lines[i + 1]):
            header = [c.strip() for c in lines[i].strip("|").split("|")]
            rows, i = [], i + 2
            while i < len(lines) and lines[i].startswith("|"):
                rows.append([c.strip() for c in lines[i].strip("|").split("|")])
                i += 1
            out.append((header, rows))
        else:
            i += 1
    return out


def number(cell):
    m = re.match(r"^\s*([\d.]+(?:e[-+]?\d+)?)", cell)
    return float(m.group(1)) if m else None


def ms(x):
    if x >= 1000:
        return f"{x / 1000:.2g} s" if x < 10000 else f"{x / 1000:.0f} s"
    return f"{x:.3g} ms"


def ratio(x):
    return f"{x:.3g}x"


def rows_of(page):
    """(the run's sentence, the table's rows, the run's date) from the page's text."""
    lines = section(page)
    run = next((l for l in lines if l.startswith("Measured on ")), None)
    if run is None:
        raise SystemExit(f"'{SECTION}' says no 'Measured on ...' line")
    date = re.match(r"Measured on (\d{4}-\d{2}-\d{2})", run).group(1)
    found = tables(lines)
    main = next((t for t in found if t[0][:3] == ["scene", "configuration", "median ms (p10-p90)"]), None)
    spots = next((t for t in found if t[0][0] == "lights" and t[0][1] == "brute-force ms"), None)
    if main is None or spots is None:
        raise SystemExit(f"'{SECTION}' lacks its table of scenes or of N spots")
    return run, date, main, spots


def table(page):
    run, date, (header, rows), (sheader, srows) = rows_of(page)
    col = {name: i for i, name in enumerate(header)}
    by_scene = {}
    for r in rows:
        by_scene.setdefault(r[col["scene"]], []).append(
            {"label": r[col["configuration"]], "ms": number(r[col["median ms (p10-p90)"]]),
             "speed": number(r[col["x brute force"]]), "error": number(r[col["mean rel. error"]])})
    out = [BEGIN, "",
           f"| scene | method | time | x brute force | mean error (brute force's) |",
           "|---|---|---|---|---|"]
    for scene, configs in by_scene.items():
        brute = next((c for c in configs if c["label"] == "brute-force"), None)
        if brute is None or brute["error"] is None:
            continue
        fit = [c for c in configs if c["label"] != "brute-force" and c["error"] is not None
               and c["error"] <= ERROR_BOUND * brute["error"]]
        if not fit:
            out.append(f"| {SCENES.get(scene, f'`{scene}`')} | `brute-force` (none within {ERROR_BOUND}x its "
                       f"error) | {ms(brute['ms'])} | 1x | {brute['error']:.3g} |")
            continue
        best = min(fit, key=lambda c: c["ms"])
        method, _, profile = best["label"].partition(" ")
        name = f"`{method}`" + (f", {profile}" if profile else "")
        note = " (no faster than brute force here)" if best["speed"] is not None and best["speed"] < 1 else ""
        out.append(f"| {SCENES.get(scene, f'`{scene}`')} | {name}{note} | {ms(best['ms'])} | "
                   f"{ratio(best['speed'])} | {best['error']:.3g} ({brute['error']:.3g}) |")
    # Many lights, blurred shafts accepted: the cheapest at the largest count.
    last = srows[-1]
    lights = last[0]
    times = {sheader[i][:-len(" ms")]: number(last[i]) for i in range(1, len(sheader))}
    brute_ms = times.pop("brute-force")
    label, t = min(times.items(), key=lambda kv: kv[1])
    several = {c["label"]: c for c in by_scene.get(SEVERAL, [])}
    if label in several and BASE in several:
        err = (f"not measured at {lights} lights; {several[label]['error'] / several[BASE]['error']:.3g}x "
               f"{BASE}'s on `{SEVERAL}`")
    else:
        err = "not measured"
    out.append(f"| {lights} shadowed spots (`atrium_spots_{lights}`), blurred shafts accepted | `{label}` | "
               f"{ms(t)} | {ratio(brute_ms / t)} | {err} |")
    out += ["",
            f"Each row is the cheapest configuration whose mean relative error (of `Lin`, against the float64 "
            f"reference) is within {ERROR_BOUND}x brute force's on that scene, brute force aside; the last row "
            f"takes the cheapest at any error. Figures: [docs/performance.md](docs/performance.md#against-froxel-fog), "
            f"\"Against froxel fog\", one run at 1920x1080 on {date} on lavapipe (a CPU: the times are CPU "
            f"figures, and only ratios within that run carry over), "
            f"`lightscatter bench --config bench/froxels.json`, with `bench/lights_scaling.json` for the last "
            f"row. `tools/readme_table.py` writes this table from that section; CTest `docs.readme_table` "
            f"checks that it is what the section gives."]
    out += families_table(page)
    out += ["", END]
    return out


FAMILIES = "## Froxels against epipolar: the two families"
FAMILIES_HEADER = ["scene", "epipolar balanced", "froxels' time at its error", "froxels' error at its time",
                   "froxels 8 px x 64", "epipolar's time at its error", "epipolar's error at its time"]


def ratio_in(cell):
    """The first 'N.NNx' of a cell, or None."""
    m = re.search(r"([\d.]+(?:e[-+]?\d+)?)x", cell)
    return float(m.group(1)) if m else None


def families_table(page):
    """The lines of the two families' table (which family wins where, and by how much), read from the
    section FAMILIES; none when the page has no such section or it has no read-off table yet."""
    lines = page.split("\n")
    if FAMILIES not in lines:
        return []
    start = lines.index(FAMILIES)
    end = next((i for i in range(start + 1, len(lines)) if lines[i].startswith("## ")), len(lines))
    found = [t for t in tables(lines[start:end]) if t[0] == FAMILIES_HEADER]
    run = next((l for l in lines[start:end] if l.startswith("Measured on ")), None)
    if not found or run is None:
        return []
    date = re.match(r"Measured on (\d{4}-\d{2}-\d{2})", run).group(1)
    out = ["", "| scene | epipolar balanced | the grid at that time | froxels-hdrp's grid | epipolar at that error |",
           "|---|---|---|---|---|"]
    for r in found[0][1]:
        out.append(f"| {SCENES.get(r[0], f'`{r[0]}`')} | {r[1]} | {r[3]} | {r[4]} | {r[5]} |")
    errors = [(r[0], ratio_in(r[3])) for r in found[0][1] if ratio_in(r[3]) is not None]
    times = [(r[0], ratio_in(r[5])) for r in found[0][1] if ratio_in(r[5]) is not None]
    summary = ""
    if errors and times:
        e = [x for _, x in errors]
        t = [x for _, x in times]
        grid = [f"`{n}`" for n, x in times if x > 1]
        both = [f"`{n}`" for n, x in times if x <= 1]
        summary = (f" At epipolar balanced's time the grid's error is {min(e):.3g}x to {max(e):.3g}x epipolar's. "
                   f"At the grid's error epipolar takes {min(t):.3g}x to {max(t):.3g}x the grid's time ('its "
                   f"cheapest': epipolar's cheapest profile, already more accurate than the grid)"
                   + (f"; the grid is the cheaper on {', '.join(grid)}" if grid else "")
                   + (f"; epipolar is both cheaper and more accurate on {', '.join(both)}" if both else "") + ".")
    out += ["", "Which family wins where: each family's time-against-error curve on the same frames, read off at "
            "the other's usual configuration (epipolar balanced; `froxels-hdrp`'s grid, 8-pixel columns and 64 "
            "slices)." + summary + f" Figures: [docs/performance.md](docs/performance.md#froxels-against-"
            f"epipolar-the-two-families), one run at 1920x1080 on {date} on lavapipe (CPU timings), "
            "`lightscatter bench --config bench/froxels_families.json`."]
    return out


def readme_parts(readme):
    if BEGIN not in readme or END not in readme:
        raise SystemExit(f"README.md lacks the markers {BEGIN} ... {END}")
    a = readme.index(BEGIN)
    b = readme.index(END) + len(END)
    return readme[:a], readme[a:b], readme[b:]


def self_test():
    page = "\n".join([
        "# P", "", SECTION, "", "Measured on 2030-01-02 with `x`.", "",
        "| scene | configuration | median ms (p10-p90) | x brute force | mean rel. error | p99 | PSNR dB | memory MiB |",
        "|---|---|---|---|---|---|---|---|",
        "| s1 | epipolar balanced | 100 (90-110) | 10 | 0.0105 | 0 | 0 | 1 |",
        "| s1 | epipolar high-performance | 50 (40-60) | 20 | 0.012 | 0 | 0 | 1 |",
        "| s1 | brute-force | 1000 (900-1100) | 1 | 0.01 | 0 | 0 | - |",
        "| s1 | froxels-unreal | 10 (9-11) | 100 | 0.05 | 0 | 0 | 1 |",
        "| atrium_lights | epipolar balanced | 100 (90-110) | 10 | 0.01 | 0 | 0 | 1 |",
        "| atrium_lights | brute-force | 2000 (1900-2100) | 1 | 0.01 | 0 | 0 | - |",
        "| atrium_lights | froxels-unreal | 20 (9-11) | 100 | 0.05 | 0 | 0 | 1 |",
        "", "| lights | brute-force ms | epipolar balanced ms | froxels-unreal ms |", "|---|---|---|---|",
        "| 1 | 100 | 50 | 10 |", "| 8 | 800 | 400 | 40 |", "", FAMILIES, "", "Measured on 2030-01-03 with `y`.", "",
        "| " + " | ".join(FAMILIES_HEADER) + " |", "|---|---|---|---|---|---|---|",
        "| s1 | 300 ms, 0.01 | not reached (best g: 70 ms, 0.08) | 0.08 (8x) | 20 ms, 0.3 | "
        "under 150 ms (7.5x; its cheapest, 0.012) | not reached (cheapest e: 150 ms, 0.012) |",
        "", "## Next", ""])
    out = "\n".join(table(page))
    expected = ["| `s1` | `epipolar`, balanced | 100 ms | 10x | 0.0105 (0.01) |",
                "| a sun and two shadowed spots (`atrium_lights`) | `epipolar`, balanced | 100 ms | 10x | 0.01 (0.01) |",
                "| 8 shadowed spots (`atrium_spots_8`), blurred shafts accepted | `froxels-unreal` | 40 ms | 20x | "
                "not measured at 8 lights; 5x epipolar balanced's on `atrium_lights` |", "on 2030-01-02",
                "| `s1` | 300 ms, 0.01 | 0.08 (8x) | 20 ms, 0.3 | under 150 ms (7.5x; its cheapest, 0.012) |",
                "the grid's error is 8x to 8x epipolar's", "the grid is the cheaper on `s1`",
                "one run at 1920x1080 on 2030-01-03"]
    missing = [e for e in expected if e not in out]
    for m in missing:
        print(f"self-test: expected {m!r} in:\n{out}")
    print(f"self-test: {len(expected) - len(missing)} of {len(expected)} expectations met")
    return 1 if missing else 0


def main(argv):
    if argv == ["--self-test"]:
        return self_test()
    mode = argv[0] if argv and argv[0] in ("--write", "--check") else None
    rest = argv[1:] if mode else argv
    root = os.path.abspath(rest[0] if rest else os.path.join(os.path.dirname(__file__), ".."))
    with open(os.path.join(root, "docs", "performance.md"), encoding="utf-8") as f:
        text = "\n".join(table(f.read()))
    if mode is None:
        print(text)
        return 0
    path = os.path.join(root, "README.md")
    with open(path, encoding="utf-8") as f:
        readme = f.read()
    before, current, after = readme_parts(readme)
    if mode == "--write":
        with open(path, "w", encoding="utf-8") as f:
            f.write(before + text + after)
        return 0
    if current != text:
        print("README.md's table of which method for which scene is not what docs/performance.md gives; "
              "run tools/readme_table.py --write. It should read:\n" + text)
        return 1
    print("README.md's table matches docs/performance.md")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
