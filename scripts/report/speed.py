"""The speed side of docs/performance.md at a real screen size: the timing run's rows with the error
run's errors merged in, where epipolar's time goes (per pass), the screen size where it overtakes
brute force, the min/max trees on and off at high quality, and seed 000's own size. Every figure is
read from `lightscatter bench` results; page.py places the sections."""
import json
import math
from pathlib import Path

# Passes that run once per screen pixel; everything else of epipolar runs per sample or per slice.
FULL_SCREEN = ("unwarp epipolar to screen", "fix-up ray march", "composite", "reconstruct camera-space z")
RAY_MARCH = "ray march with min/max trees"
RAY_MARCH_NO_TREES = "ray march"


def load_runs(bench_dir):
    path = Path(bench_dir) / "bench.json"
    return json.loads(path.read_text())["runs"] if path.exists() else []


def run_key(r):
    return (r["scene"], r["label"], tuple(r["size"]))


def merge_errors(timed, errored):
    """`timed` (measureError false: the quiet machine's run) with each row's error, nonFinite and
    methodRan taken from the same configuration in `errored` (one frame each, any load: the error
    does not depend on the device's speed)."""
    by_key = {run_key(r): r for r in errored}
    out = []
    for r in timed:
        e = by_key.get(run_key(r))
        if e and "error" in e:
            r = dict(r, error=e["error"], nonFinite=e["nonFinite"])
        out.append(r)
    return out


def pass_times(r):
    return {p["name"]: p["median"] for p in r.get("passes", [])}


def shares(r):
    """(ray-march share, full-screen share, the full-screen passes' names with their ms) of a run."""
    t = pass_times(r)
    total = sum(t.values())
    if total <= 0:
        return None
    march = march_ms(r)
    full = {name: ms for name, ms in t.items() if name in FULL_SCREEN}
    return march / total, sum(full.values()) / total, full, total


def speedup(runs, scene, label, size=None):
    rs = [r for r in runs if r["scene"] == scene and (size is None or tuple(r["size"]) == tuple(size))]
    b = next((r for r in rs if r["method"] == "brute-force" and r["family"] in ("profiles", "size")), None)
    e = next((r for r in rs if r["label"] == label), None)
    if not b or not e or e["time"]["median"] <= 0:
        return None, b, e
    return b["time"]["median"] / e["time"]["median"], b, e


def crossover(runs, scene):
    """The screen sizes measured for `scene` with epipolar (balanced settings) and brute force's
    time at each, as (pixels, size, speed-up, epipolar ms, brute force ms), and the pixel count where their ratio crosses 1, interpolated in log-log between
    the two measured sizes around it (None when it never crosses within the sizes measured)."""
    points = {}
    for r in runs:
        if r["scene"] != scene:
            continue
        size = tuple(r["size"])
        if r["family"] == "size" or (r["family"] == "profiles" and r["label"] in ("epipolar balanced", "brute-force")):
            which = "brute" if r["method"] == "brute-force" else ("epipolar" if r["method"] == "epipolar" else None)
            if which:
                points.setdefault(size, {})[which] = r["time"]["median"]
    table = sorted((s[0] * s[1], s, v["brute"] / v["epipolar"], v["epipolar"], v["brute"]) for s, v in points.items()
                   if "brute" in v and "epipolar" in v and v["epipolar"] > 0)
    if not table or table[-1][2] < 1:
        return table, None  # behind at the largest size measured
    if all(row[2] >= 1 for row in table):
        return table, 0  # ahead at every size measured
    # The last crossing from behind to ahead, interpolated in log-log.
    cross = None
    for (n0, _, r0, *_), (n1, _, r1, *_) in zip(table, table[1:]):
        if r0 < 1 <= r1:
            f = (0 - math.log(r0)) / (math.log(r1) - math.log(r0))
            cross = math.exp(math.log(n0) + f * (math.log(n1) - math.log(n0)))
    return table, cross


def side_of(pixels):
    """A 16:9 screen with `pixels` pixels, as WxH."""
    w = math.sqrt(pixels * 16 / 9)
    return f"{w:.0f}x{w * 9 / 16:.0f}"


def march_ms(r):
    return sum(ms for name, ms in pass_times(r).items() if name.startswith("ray march"))


def tree_pairs(runs):
    """[(scene, trees-on run, trees-off run)] of a bench/trees.json run, scenes in order."""
    pairs = []
    for scene in sorted({r["scene"] for r in runs}):
        on = next((r for r in runs if r["scene"] == scene and r["label"] == "minMaxTrees=on"), None)
        off = next((r for r in runs if r["scene"] == scene and r["label"] == "minMaxTrees=off"), None)
        if on and off:
            pairs.append((scene, on, off))
    return pairs


def trees_section(trees_dir, fmt):
    runs = load_runs(trees_dir)
    if not runs:
        return []
    out = []
    p = out.append
    w, h = runs[0]["size"]
    p("### The min/max trees at high quality\n")
    p(f"`bench/trees.json`: epipolar's high-quality profile with the trees on and off (the sweep starts from "
      f"high-quality: `sweepProfile`), {w}x{h}, the median of {runs[0]['frames']} frames after warm-up, "
      "timings only. The ray march alone is the pass the trees act on; the total includes the trees' own "
      "construction.\n")
    p("| scene | ray march, trees on (ms) | ray march, trees off (ms) | ray march speed-up | trees' build (ms) | "
      "total on | total off | total speed-up |")
    p("|---|---|---|---|---|---|---|---|")
    for scene, on, off in tree_pairs(runs):
        m_on, m_off = march_ms(on), march_ms(off)
        build = sum(ms for n, ms in pass_times(on).items() if n.startswith("min/max trees"))
        p(f"| {scene} | {fmt(m_on)} | {fmt(m_off)} | {fmt(m_off / m_on) + 'x' if m_on > 0 else '-'} | "
          f"{fmt(build)} | {fmt(on['time']['median'])} | {fmt(off['time']['median'])} | "
          f"{fmt(off['time']['median'] / on['time']['median'])}x |")
    p("")
    return out


def seed_size_rows(seed_dir):
    """{profile: [(scene, speed-up over brute force, the best a free ray march would give)]} at seed
    000's size; the last is brute force over everything but epipolar's ray march (None when the
    march is all of it)."""
    runs = load_runs(seed_dir)
    rows = {}
    for scene in sorted({r["scene"] for r in runs}):
        brute = next((r for r in runs if r["scene"] == scene and r["method"] == "brute-force"), None)
        for r in runs:
            if r["scene"] == scene and r["method"] == "epipolar" and brute:
                prof = r["label"].split(" ", 1)[1]
                rest = r["time"]["median"] - march_ms(r)
                rows.setdefault(prof, []).append(
                    (scene, brute["time"]["median"] / r["time"]["median"],
                     brute["time"]["median"] / rest if rest > 0 else None))
    return rows, (runs[0] if runs else None)


def pass_breakdown_lines(r, fmt):
    s = shares(r)
    if not s:
        return []
    march, full, full_passes, total = s
    names = ", ".join(f"{n} {fmt(ms)} ms" for n, ms in full_passes.items())
    return [f"Where epipolar balanced's {fmt(total)} ms go (per-pass GPU timestamps): the ray march "
            f"{100 * march:.0f}%, the full-screen passes {100 * full:.0f}% ({names}), everything else "
            f"(coordinates, refinement, trees, interpolation) {100 * (1 - march - full):.0f}%.\n"]
