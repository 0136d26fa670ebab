"""The command line of scripts/write_report.py:

    write_report.py BENCH HARD CONFIG [PLANES OCCLUDERS LIGHTS_SCALING LIGHTS FLICKER ERRORS TREES SEED]
        the whole page, on stdout (scripts/make-report.sh runs it; an empty folder argument leaves
        its section out)
    write_report.py --NAME-section DIR... [PAGE.md]
        one section alone, on stdout, or spliced into PAGE.md in place (the rest of the page is
        left as it is); --slices-section is --planes-section's former name"""
import argparse
from pathlib import Path

from . import flicker
from .common import splice_section, with_kept_sections
from .froxels import FROXELS_HEADING, froxels_section
from .froxels_motion import FROXELS_MOTION_HEADING, froxels_motion_section
from .froxels_near import FROXELS_NEAR_HEADING, froxels_near_section
from . import families
from .seeds import (SEED000_HEADING, SEED002_HEADING, SEED003_HEADING, SEED004_HEADING, seed000_section,
                    seed002_section, seed003_section, seed004_section)
from .gpu import GPU_HEADING, gpu_section
from .lights import LIGHTS_HEADING, lights_section
from .occluders import OCCLUDERS_HEADING, occluders_section
from .page import page_lines
from .planes import FORMER_HEADING, PLANES_HEADING, planes_section
from .reference import REFERENCE_HEADING, reference_section
from .runs import with_runs


def flicker_lines(dirs, page):
    # Its heat maps go beside the page.
    image_dir = page.parent / "performance" if page else None
    return flicker.flicker_section(dirs[0], image_dir), flicker.FLICKER_HEADING


def planes_lines(dirs, page):
    lines = planes_section(dirs[0])
    heading = lines[0].rstrip("\n")
    # A page written before the rename has the section under its former heading.
    return lines, (heading, heading.replace(PLANES_HEADING, FORMER_HEADING))


# --NAME-section: (its result folders, what they are, the section's lines and heading, or its
# headings: common.splice_section).
SECTIONS = {
    "gpu": (("GPU_DIR",), "scripts/gpu-bench.sh run's OUT",
            lambda dirs, page: (gpu_section(dirs[0]), GPU_HEADING)),
    "flicker": (("FLICKER_DIR",), "a bench run of bench/flicker.json", flicker_lines),
    "occluders": (("OCCLUDERS_DIR",), "a bench run of bench/occluders.json",
                  lambda dirs, page: (occluders_section(dirs[0]), OCCLUDERS_HEADING)),
    "lights": (("SCALING_DIR", "LIGHTS_DIR"), "bench runs of bench/lights_scaling.json and bench/lights.json",
               lambda dirs, page: (lights_section(dirs[0], dirs[1]), LIGHTS_HEADING)),
    "planes": (("PLANES_DIR",), "a bench run of bench/planes.json", planes_lines),
    "froxels": (("FROXELS_DIR", "SCALING_DIR"),
                "bench runs of bench/froxels.json (with budget-*.json beside) and bench/lights_scaling.json",
                lambda dirs, page: (froxels_section(dirs[0], dirs[1]), FROXELS_HEADING)),
    "froxels-motion": (("MOTION_DIR",), "a bench run of bench/froxels_flicker.json",
                       lambda dirs, page: (froxels_motion_section(dirs[0]), FROXELS_MOTION_HEADING)),
    "families": (("FAMILIES_DIR",), "a bench run of bench/froxels_families.json (its plot goes beside the page)",
                 lambda dirs, page: (families.families_section(dirs[0], page.parent / "performance" if page else None),
                                     families.FAMILIES_HEADING)),
    "froxels-near": (("NEAR_DIR",), "a bench run of bench/froxels_near_light.json",
                     lambda dirs, page: (froxels_near_section(dirs[0]), FROXELS_NEAR_HEADING)),
    "seed000": (("GTX680_DIR", "QUADRO_DIR", "INTEL_DIR", "DIRECTIONAL_DIR", "TREES_DIR"),
                "bench runs of bench/seed000_{gtx680,quadro,intel,directional,trees}.json (budget-*.json beside)",
                lambda dirs, page: (seed000_section(dict(zip(
                    ("gtx680", "quadro", "intel", "directional", "trees"), dirs))), SEED000_HEADING)),
    "seed002": (("SEED002_DIR",), "a bench run of bench/seed002.json (its strips are copied beside the page)",
                lambda dirs, page: (seed002_section(dirs[0], page.parent / "performance" if page else None),
                                    SEED002_HEADING)),
    "seed004": (("SEED004_DIR",), "a bench run of bench/seed004.json",
                lambda dirs, page: (seed004_section(dirs[0]), SEED004_HEADING)),
    "reference": (("REFERENCE_DIR",), "a run of tools/reference_timing (scripts/make-report.sh --reference-only)",
                  lambda dirs, page: (reference_section(dirs[0]), REFERENCE_HEADING)),
    "seed003": (("SMALL_DIR", "LARGE_DIR"), "bench runs of bench/seed003_1280x720.json and _2560x1440.json",
                lambda dirs, page: (seed003_section({"1280x720": dirs[0], "2560x1440": dirs[1]}),
                                    SEED003_HEADING)),
}

# Options under the names they had before: the planes section was "slices" until the word came to
# mean only an epipolar line.
FORMER_OPTIONS = {"planes": ("--slices-section",)}

# The whole page's optional result folders, in their order on the command line.
PAGE_FOLDERS = (("planes", "bench/planes.json"), ("occluders", "bench/occluders.json"),
                ("lights_scaling", "bench/lights_scaling.json"), ("lights", "bench/lights.json"),
                ("flicker", "bench/flicker.json"),
                ("errors", "the main configuration's error run (one frame each), merged into BENCH's rows"),
                ("trees", "bench/trees.json"), ("seed", "bench/seed_size.json"))


def parser():
    p = argparse.ArgumentParser(prog="scripts/write_report.py", description=__doc__,
                                formatter_class=argparse.RawDescriptionHelpFormatter)
    one = p.add_mutually_exclusive_group()
    for name, (folders, what, _) in SECTIONS.items():
        one.add_argument(f"--{name}-section", *FORMER_OPTIONS.get(name, ()), nargs="+", metavar="DIR",
                         help=f"{' '.join(folders)} [PAGE.md]: {what}")
    p.add_argument("bench", nargs="?", metavar="BENCH",
                   help="the main bench run (bench.json and budget.json; scripts/make-report.sh)")
    p.add_argument("hard", nargs="?", metavar="HARD", help="a bench run of bench/hard.json")
    p.add_argument("config", nargs="?", metavar="CONFIG", help="the main run's configuration, as named on the page")
    for name, what in PAGE_FOLDERS:
        p.add_argument(name, nargs="?", default="", metavar=name.upper(), help=f"{what} (empty: none)")
    return p


def main(argv=None):
    p = parser()
    args = p.parse_args(argv)
    for name, (folders, _, make) in SECTIONS.items():
        given = getattr(args, f"{name.replace('-', '_')}_section")
        if given is None:
            continue
        if args.bench is not None:
            p.error(f"--{name}-section takes no other folders")
        if not len(folders) <= len(given) <= len(folders) + 1:
            p.error(f"--{name}-section takes {' '.join(folders)} [PAGE.md]")
        dirs = [Path(d) for d in given[:len(folders)]]
        page = Path(given[len(folders)]) if len(given) > len(folders) else None
        lines, heading = make(dirs, page)
        if page:
            page.write_text(with_runs(splice_section(page.read_text(), heading, lines)))
        else:
            print("\n".join(lines))
        return 0
    if args.config is None:
        p.error("the whole page needs BENCH, HARD and CONFIG (or one --NAME-section)")
    folders = {name: Path(getattr(args, name)) if getattr(args, name) else None for name, _ in PAGE_FOLDERS}
    text = "\n".join(page_lines(Path(args.bench), Path(args.hard), args.config,
                                **{f"{name}_dir": d for name, d in folders.items()}))
    # The sections this run does not write stay as they were (page_lines reads the same page).
    old = Path("docs/performance.md")
    print(with_runs(with_kept_sections(old.read_text(), text) if old.exists() else text))
    return 0

