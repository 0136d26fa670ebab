#!/usr/bin/env python3
"""The profile-order table of a `lightscatter bench` run with "profileOrder" (docs/performance.md,
"Profiles in order"): each scene and size's epipolar profiles, each at the median of its rounds'
medians, as the bench's own check takes them (host_example/bench/profile_order.cpp), in ms.

    tools/profile_order_table.py OUT/bench.json
"""
import json
import sys
from collections import defaultdict

PROFILES = ["high-quality", "balanced", "high-performance", "low-high-quality", "low-balanced",
            "low-high-performance"]


def middle(values):
    """The median as the bench takes it (host_example/bench/metrics.cpp, spreadOf): the value at
    rank (n - 1) / 2 rounded up."""
    v = sorted(values)
    return v[int(0.5 * (len(v) - 1) + 0.5)]


def table(bench):
    rounds = defaultdict(lambda: defaultdict(list))
    for r in bench["runs"]:
        if r.get("family") != "profiles" or r.get("method") != "epipolar":
            continue
        rounds[(r["scene"], r["size"][0], r["size"][1])][r["profile"]].append(r["time"]["median"])
    lines = ["| scene | size | " + " | ".join(PROFILES) + " |",
             "|---|---|" + "---|" * len(PROFILES)]
    for (scene, w, h), times in sorted(rounds.items()):
        cells = [f"{middle(times[p]):.1f}" if times[p] else "-" for p in PROFILES]
        lines.append(f"| {scene} | {w}x{h} | " + " | ".join(cells) + " |")
    return "\n".join(lines)


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    with open(sys.argv[1]) as f:
        print(table(json.load(f)))


if __name__ == "__main__":
    main()
