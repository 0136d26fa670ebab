"""The 'Scaling' section: epipolar against brute force as the screen grows, and the plots."""
from pathlib import Path

from . import speed as rs
from .common import fmt


def scaling_section(runs, scenes):
    out = []
    p = out.append
    p("## Scaling\n")
    size_tables = [(scene, rs.crossover(runs, scene)[0]) for scene in scenes]
    if any(t for _, t in size_tables):
        p("Epipolar (balanced settings) against brute force as the screen grows, same run (median ms; the "
          "largest size is the tables' own run):\n")
        p("| scene | screen | epipolar ms | brute force ms | speed-up |")
        p("|---|---|---|---|---|")
        for scene, table in size_tables:
            for _, size, ratio, epipolar_ms, brute_ms in table:
                p(f"| {scene} | {size[0]}x{size[1]} | {fmt(epipolar_ms)} | {fmt(brute_ms)} | {fmt(ratio)}x |")
        p("")
    for name, what in (("scaling_screen", "screen size"), ("scaling_shadow_map", "shadow-map size"),
                       ("scaling_slices_samples", "slices x samples")):
        if Path("docs/performance", f"{name}.png").exists():
            p(f"Time against {what}:\n\n![{what}](performance/{name}.png)\n")
    return out
