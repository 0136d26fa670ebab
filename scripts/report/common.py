"""Pieces every section of docs/performance.md shares: the number format, seed 000's published
figures, the load-average note, and splicing a section into the page."""
import os
import re
from pathlib import Path

# Seed 000, "Performance": GeForce GTX 680 at 2560x1600, spot light (time ms, memory MB).
SEED = {"brute-force": (91.18, None), "high-quality": (5.986, 88.0), "balanced": (3.269, 44.0),
        "high-performance": (2.267, 18.0)}


# Sweeps named after the settings field they set since the benchmark's sweeps take any field
# (bench_config.cpp): runs recorded before carry the family on the left (and "samples=512",
# "initialStep=8" as labels); the trees' labels were already "minMaxTrees=on" and "=off".
FORMER_SWEEPS = {"samples": "samplesPerSlice", "initialStep": "initialSampleStep", "trees": "minMaxTrees"}


def sweep_family(r):
    """A run's sweep family under its current name, whenever the run was recorded."""
    return FORMER_SWEEPS.get(r["family"], r["family"])


def fmt(x, digits=3):
    if x is None:
        return "-"
    if x == 0:
        return "0"
    if abs(x) >= 100:
        return f"{x:.0f}"
    return f"{x:.{digits}g}"



def load_note(bench_dir):
    """A sentence on the machine's load average around a timing run (load-before.txt and
    load-after.txt, `uptime` written by scripts/make-report.sh), or None without them: on a CPU
    device the timings share the cores with whatever else runs."""
    loads, worst = [], 0.0
    for when in ("before", "after"):
        f = Path(bench_dir) / f"load-{when}.txt"
        m = re.search(r"load average: ([\d.]+), ([\d.]+), ([\d.]+)", f.read_text()) if f.exists() else None
        if m:
            loads.append(f"{m.group(1)} {when} the run" + (" (the run's own threads included)" if when == "after" else ""))
            if when == "before":
                worst = float(m.group(1))
    if not loads:
        return None
    cores = os.cpu_count() or 1
    busy = ("other work shared the CPU, so treat single figures as rough; the trend over the counts is "
            "what to read" if worst > 0.5 * cores else "little else ran")
    return f"The machine's load average (1 minute) was {' and '.join(loads)}, on {cores} cores: {busy}."



def splice_section(page, heading, lines, before="## Scaling"):
    """`page` (Markdown) with the section starting at `heading` replaced by `lines`, up to the next
    '## ' heading; inserted before the `before` heading if the page has none yet. `heading` may be a
    tuple: the section's heading, then the ones it had on pages written before it was renamed."""
    text = page.split("\n")
    section = "\n".join(lines).rstrip("\n").split("\n") + [""]
    heading = next((h for h in ((heading,) if isinstance(heading, str) else heading) if h in text), None)
    if heading:
        start = text.index(heading)
        end = next((i for i in range(start + 1, len(text)) if text[i].startswith("## ")), len(text))
        return "\n".join(text[:start] + section + text[end:])
    at = text.index(before) if before in text else len(text)
    return "\n".join(text[:at] + section + text[at:])



def sections(text):
    """[(heading, lines)] of Markdown text cut at each '## ' heading; the part before the first has
    the heading None."""
    out = [(None, [])]
    for line in text.split("\n"):
        if line.startswith("## "):
            out.append((line, []))
        out[-1][1].append(line)
    return out


def with_kept_sections(old_page, new_text):
    """`new_text` with every section of `old_page` it does not write (a hand-written one such as
    'Cookies', or one another run splices in, such as 'Against froxel fog') kept, after the section
    it followed on the old page: regenerating the page loses none of them."""
    new = sections(new_text)
    written = {h for h, _ in new}
    previous = None
    after = {}  # a written heading (None: the top) -> the old sections that followed it
    for heading, lines in sections(old_page)[1:]:
        if heading in written:
            previous = heading
        else:
            after.setdefault(previous, []).append(lines)
    out = []
    for heading, lines in new:
        out += lines
        for kept in after.get(heading, []):
            out += kept
    return "\n".join(out)


def kept_section(page_text, heading):
    """The section at `heading` of the page as it was (up to the next '## '), for a section whose
    results this run does not have: it stays as last measured, with its own date and command."""
    text = page_text.split("\n")
    if heading not in text:
        return []
    start = text.index(heading)
    end = next((i for i in range(start + 1, len(text)) if text[i].startswith("## ")), len(text))
    return text[start:end]

