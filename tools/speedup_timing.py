#!/usr/bin/env python3
"""Speed-up over brute force: epipolar's profiles against brute force on the same scenes.

Renders each scene with brute force and with epipolar at each --profile in alternation, RUNS times
each (and with --base-binary an older build's brute force and epipolar too, in the same rounds:
a change that speeds up the shared shadow-map look-ups speeds up brute force as well), and prints
the median of the plugin's GPU time of each and its speed-up (its own build's brute-force median
over its own) as a Markdown table. Images go to a temporary folder.

    tools/speedup_timing.py [--binary build/host_example/lightscatter] [--base-binary OLD]
                            [--profile balanced ...] [--size 1920x1080] [--runs 3] SCENE.json...

On lavapipe only ratios measured in one run on a quiet machine mean anything.
"""
import argparse
import os
import statistics
import sys
import tempfile

from render_timing import render_report

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def main():
    p = argparse.ArgumentParser()
    p.add_argument("--binary", default=os.path.join(ROOT, "build/host_example/lightscatter"))
    p.add_argument("--base-binary")
    p.add_argument("--profile", dest="profiles", action="append", default=[])
    p.add_argument("--size", default="1920x1080")
    p.add_argument("--runs", type=int, default=3)
    p.add_argument("scenes", nargs="+")
    args = p.parse_args()
    profiles = args.profiles or ["balanced"]
    # (label, binary, profile) of each epipolar configuration, in the order of each round.
    configs = []
    for profile in profiles:
        if args.base_binary:
            configs.append((f"{profile} before", args.base_binary, profile))
        configs.append((profile, args.binary, profile))
    # The brute-force builds: the base's first where there is one.
    brutes = ([("brute force before", args.base_binary)] if args.base_binary else []) + \
        [("brute force", args.binary)]
    print("| scene | " + " | ".join(f"{label} (ms)" for label, _ in brutes) + " | " +
          " | ".join(f"{label} (ms) | speed-up" for label, _, _ in configs) + " |")
    print("|---|" + "---|" * len(brutes) + "---|---|" * len(configs))
    with tempfile.TemporaryDirectory() as folder:
        for scene in args.scenes:
            brute, times = [[] for _ in brutes], [[] for _ in configs]
            for _ in range(args.runs):
                for k, (_, binary) in enumerate(brutes):
                    brute[k].append(render_report(binary, scene, "brute-force", args.size,
                                                  folder)["totalMilliseconds"])
                for k, (_, binary, profile) in enumerate(configs):
                    times[k].append(render_report(binary, scene, "epipolar", args.size, folder,
                                                  profile)["totalMilliseconds"])
            medians = {binary: statistics.median(t) for (_, binary), t in zip(brutes, brute)}
            cells = [f"{statistics.median(t):.0f} | {medians[binary] / statistics.median(t):.1f}x"
                     for t, (_, binary, _) in zip(times, configs)]
            print(f"| {os.path.basename(scene)} | " +
                  " | ".join(f"{statistics.median(t):.0f}" for t in brute) + " | " +
                  " | ".join(cells) + " |", flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
