#!/usr/bin/env python3
"""Before and after: the plugin's GPU time of two builds of lightscatter on the same scenes.

Renders each scene with the base build and the new one in alternation, RUNS times each, and prints
the median of the plugin's total time and of the passes whose names start with each --pass prefix,
as a Markdown table with the ratio after / before. Images go to a temporary folder.

    tools/ab_timing.py --base-binary OLD/lightscatter [--binary build/host_example/lightscatter]
                       [--method epipolar] [--profile balanced] [--size 1920x1080] [--runs 3]
                       [--pass "ray march" --pass unwarp] SCENE.json...

On lavapipe only ratios measured in one run on a quiet machine mean anything.
"""
import argparse
import os
import statistics
import sys
import tempfile

from render_timing import render_report

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def timed(binary, scene, args, folder):
    """The total and each pass prefix's milliseconds of one render."""
    report = render_report(binary, scene, args.method, args.size, folder, args.profile)
    passes = report.get("passes", [])
    return [report["totalMilliseconds"]] + [
        sum(p["milliseconds"] for p in passes if p["name"].startswith(prefix)) for prefix in args.passes]


def main():
    p = argparse.ArgumentParser()
    p.add_argument("--base-binary", required=True)
    p.add_argument("--binary", default=os.path.join(ROOT, "build/host_example/lightscatter"))
    p.add_argument("--method", default="epipolar")
    p.add_argument("--profile", default="balanced")
    p.add_argument("--size", default="1920x1080")
    p.add_argument("--runs", type=int, default=3)
    p.add_argument("--pass", dest="passes", action="append", default=[])
    p.add_argument("scenes", nargs="+")
    args = p.parse_args()
    columns = ["total"] + args.passes
    print("| scene | " + " | ".join(f"{c} before (ms) | {c} after (ms) | ratio" for c in columns) + " |")
    print("|---|" + "---|---|---|" * len(columns))
    with tempfile.TemporaryDirectory() as folder:
        for scene in args.scenes:
            before, after = [], []
            for _ in range(args.runs):
                before.append(timed(args.base_binary, scene, args, folder))
                after.append(timed(args.binary, scene, args, folder))
            cells = []
            for k in range(len(columns)):
                b = statistics.median(r[k] for r in before)
                a = statistics.median(r[k] for r in after)
                cells.append(f"{b:.0f} | {a:.0f} | {a / b:.2f}" if b > 0 else f"{b:.0f} | {a:.0f} | -")
            print(f"| {os.path.basename(scene)} | " + " | ".join(cells) + " |", flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
