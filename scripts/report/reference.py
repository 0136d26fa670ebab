"""The 'The reference renderer's time' section: the float64 reference over the report's scenes,
through its own double BVH and through Embree, from a run of tools/reference_timing."""
import json
from datetime import date
from pathlib import Path

REFERENCE_HEADING = "## The reference renderer's time"

# Embree is kept only if it takes the report's references at least this many times sooner.
ADOPT_AT = 3.0


def _text(path):
    return path.read_text().strip() if path.exists() else ""


def reference_section(run_dir):
    """Lines of Markdown from DIR/reference_timing.json (reference_timing --traversal both --json),
    with DIR/cpu.txt and DIR/load-before.txt beside it (scripts/make-report.sh --reference-only)."""
    run_dir = Path(run_dir)
    data = json.loads((run_dir / "reference_timing.json").read_text())
    if not data.get("embreeBuilt"):
        raise SystemExit(f"{run_dir}: reference_timing was built without Embree; its 'embree' column "
                         "would be the double BVH's again")
    cpu = _text(run_dir / "cpu.txt") or "this machine's CPU"
    load = _text(run_dir / "load-before.txt")
    when = _text(run_dir / "date.txt") or date.today().isoformat()
    rows = data["scenes"]
    own = sum(r["own"]["seconds"] for r in rows)
    embree = sum(r["embree"]["seconds"] for r in rows)
    same = all(r["own"]["image"] == r["embree"]["image"] for r in rows)
    ratio = own / embree
    out = []
    p = out.append
    p(REFERENCE_HEADING + "\n")
    p(f"Every error on this page is against the float64 reference (`reference/exact_renderer`): Lin at each "
      f"pixel centre with exact visibility, each view ray's lit intervals from 512 shadow rays bisected to "
      f"1e-9 of its length. Its shadow rays go through Intel Embree's BVH (Debian's libembree-dev "
      f"3.13.5): Embree only finds candidate triangles, as boxes padded by 2^-14 of the scene's scale so "
      f"that float rounding cannot lose one, and every candidate is decided by the same double-precision "
      f"watertight test as before, so the image does not change by a bit. Measured on {when} with "
      f"`build/tools/reference_timing/reference_timing --size {data['size']} --traversal both` over the "
      f"report's scenes (`scripts/make-report.sh --reference-only` runs it and writes this section), default "
      f"options, {data['threads']} threads on **{cpu}**" + (f" (load before: {load})" if load else "") +
      "; wall-clock seconds including the BVH builds. 'Double BVH alone' is the renderer as it was before "
      "Embree (`ReferenceOptions::traversal = Own`; on 2026-12-03 the build before Embree took 12.4 s for "
      "these scenes at 192x108, this column's traversal 12.2 s).\n")
    p("| scene | triangles | double BVH alone, s | through Embree, s | sooner | same image |")
    p("|---|---|---|---|---|---|")
    for r in rows:
        name = Path(r["scene"]).stem
        o, e = r["own"], r["embree"]
        p(f"| {name} | {r['triangles']:,} | {o['seconds']:.0f} | {e['seconds']:.0f} | "
          f"{o['seconds'] / e['seconds']:.1f}x | {'yes' if o['image'] == e['image'] else '**no**'} |")
    p(f"| **all four** | | **{own:.0f}** | **{embree:.0f}** | **{ratio:.1f}x** | "
      f"{'yes' if same else '**no**'} |")
    p("")
    verdict = (f"Embree stays: it takes the four references {ratio:.1f}x sooner (the bar was {ADOPT_AT:.0f}x)"
               if ratio >= ADOPT_AT else
               f"Embree takes the four references only {ratio:.1f}x sooner, under the {ADOPT_AT:.0f}x that would "
               f"justify a dependency")
    p(f"{verdict}. The report's error run (`scripts/make-report.sh`'s second run over bench/report.json) "
      f"renders exactly these four references once and keeps them; the rest of that run does not change, so "
      f"generating the report is {own - embree:.0f} s ({(own - embree) / 60:.0f} minutes) shorter on this machine "
      f"the first time: {own / 60:.0f} minutes of references before, {embree / 60:.0f} after. What remains is "
      f"mostly the double triangle tests of the candidates and the quadrature (Embree's traversal itself was "
      f"about a fifth of the time under perf at 192x108 on 2026-12-03). Without libembree-dev the build falls back to the double BVH alone, "
      f"with the same images.\n")
    return out
