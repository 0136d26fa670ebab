#!/usr/bin/env python3
"""Checks that every memory figure the documents take from `lightscatter budget` is what the
program prints today. A figure says where it comes from with an HTML comment right after it, which
Markdown does not show:

    15.9 MiB<!-- budget --method planes --profile balanced --size 1920x1080: peak -->

The comment holds `budget`'s options, then after the last colon what the figure is: `peak` (the
peak with aliasing), `total` (without aliasing), or a resource's name in quotes ("point-light table",
its bytes). The figure is the number before the comment, with its unit when one follows it (KiB, MiB
or GiB; none: MiB); it must equal budget's to the digits it is written with. `--settings-json
'{...}'` stands for `--settings FILE` with that JSON in a temporary file.

    tools/check_budget_figures.py LIGHTSCATTER [REPO_ROOT]          exit 0: every figure holds
    tools/check_budget_figures.py --fix LIGHTSCATTER [REPO_ROOT]    rewrites the figures that moved
    tools/check_budget_figures.py --self-test                       checks the checker without the program

The documents are README.md and every .md file under docs/ and scenes/. The memory figures they
give without such a comment are not budget's: a seed's published megabytes, a texture's size worked
out in the text, what a run measured on a device (resident memory, `--memory-log`), or what a
texture used to cost before a change; each says which it is where it stands.
"""
import json
import os
import re
import shlex
import subprocess
import sys
import tempfile
from decimal import Decimal

ANNOTATED = re.compile(
    r"(?P<figure>\d[\d,]*(?:\.\d+)?)(?P<space>\s*)(?P<unit>KiB|MiB|GiB)?(?P<after>[^<\n|]{0,3}?)"
    r"<!--\s*budget\s+(?P<args>.*?):\s*(?P<what>peak|total|\"[^\"]+\")\s*-->")
UNITS = {"KiB": 1024.0, "MiB": 1024.0 ** 2, "GiB": 1024.0 ** 3}


def documents(root):
    out = [os.path.join(root, "README.md")]
    for folder in ("docs", "scenes"):
        for base, _, names in os.walk(os.path.join(root, folder)):
            out += [os.path.join(base, n) for n in sorted(names) if n.endswith(".md")]
    return [p for p in out if os.path.isfile(p)]


class Budget:
    """Runs `LIGHTSCATTER budget ARGS --json` once per distinct ARGS."""

    def __init__(self, program):
        self.program, self.cache = program, {}

    def __call__(self, args):
        if args not in self.cache:
            words, temps = shlex.split(args), []
            try:
                if "--settings-json" in words:
                    i = words.index("--settings-json")
                    f = tempfile.NamedTemporaryFile("w", suffix=".json", delete=False)
                    f.write(words[i + 1])
                    f.close()
                    temps.append(f.name)
                    words[i:i + 2] = ["--settings", f.name]
                out = subprocess.run([self.program, "budget", *words, "--json"], capture_output=True, text=True)
            finally:
                for t in temps:
                    os.unlink(t)
            if out.returncode != 0:
                self.cache[args] = f"lightscatter budget {args} failed: {out.stderr.strip()}"
            else:
                self.cache[args] = json.loads(out.stdout)
        return self.cache[args]


def value(result, what):
    """Bytes of `what` in budget's JSON (a list of one profile's result), or an error string."""
    if isinstance(result, str):
        return result
    if len(result) != 1:
        return f"budget printed {len(result)} results; name one profile (--profile NAME)"
    r = result[0]
    if what == "peak":
        return float(r["peakBytes"])
    if what == "total":
        return float(r["totalBytes"])
    name = what.strip('"')
    found = [x["bytes"] for x in r["resources"] if x["name"] == name]
    if not found:
        return f"budget lists no resource '{name}' (it lists: {', '.join(x['name'] for x in r['resources'])})"
    return float(sum(found))


def written(figure, number):
    """`number` written with as many decimals as `figure`."""
    decimals = len(figure.split(".")[1]) if "." in figure else 0
    return f"{Decimal(repr(number)).quantize(Decimal(1).scaleb(-decimals), rounding='ROUND_HALF_UP'):f}"


def check_text(text, budget):
    """(problems [(offset, message)], the text with every moved figure rewritten)."""
    problems, pieces, last = [], [], 0
    for m in ANNOTATED.finditer(text):
        unit = m.group("unit") or "MiB"
        got = value(budget(m.group("args").strip()), m.group("what"))
        if isinstance(got, str):
            problems.append((m.start(), got))
            continue
        figure = m.group("figure").replace(",", "")
        should = written(figure, got / UNITS[unit])
        # Within half a unit of the figure's last digit (either way of rounding a tie).
        half = Decimal(5).scaleb(-len(figure.split(".")[1]) - 1 if "." in figure else -1)
        if abs(Decimal(figure) - Decimal(repr(got / UNITS[unit]))) > half:
            problems.append((m.start(), f"{m.group('figure')} {unit} should be {should} {unit} "
                                        f"(lightscatter budget {m.group('args').strip()}: {m.group('what')})"))
            pieces.append(text[last:m.start("figure")] + should)
            last = m.end("figure")
    pieces.append(text[last:])
    return problems, "".join(pieces)


def self_test():
    fake = {"--size 8x8 --profile balanced": [{"peakBytes": 3 * 1024 ** 2 + 400 * 1024, "totalBytes": 5 * 1024 ** 2,
                                                "resources": [{"name": "point-light table", "bytes": 2097152}]}]}
    budget = lambda args: fake.get(args, f"lightscatter budget {args} failed: unknown")  # noqa: E731
    text = ("peak 3.4 MiB<!-- budget --size 8x8 --profile balanced: peak -->, total 5<!-- budget --size 8x8 "
            "--profile balanced: total --> MiB, table 2048 KiB<!-- budget --size 8x8 --profile balanced: "
            "\"point-light table\" -->; wrong 3.3 MiB<!-- budget --size 8x8 --profile balanced: peak -->, "
            "| 4.00 <!-- budget --size 8x8 --profile balanced: total --> |, missing 1 MiB<!-- budget --size 9x9: "
            "peak -->, no such 1 MiB<!-- budget --size 8x8 --profile balanced: \"nothing\" -->")
    problems, fixed = check_text(text, budget)
    expected = ["3.3 MiB should be 3.4 MiB", "4.00 MiB should be 5.00 MiB", "budget --size 9x9 failed",
                "lists no resource 'nothing'"]
    messages = [p for _, p in problems]
    missed = [e for e in expected if not any(e in p for p in messages)]
    wrong = [p for p in messages if not any(e in p for e in expected)]
    if "wrong 3.4 MiB<!--" not in fixed or "| 5.00 <!--" not in fixed:
        wrong.append(f"--fix wrote: {fixed}")
    for m in missed:
        print(f"self-test: not reported: {m}")
    for w in wrong:
        print(f"self-test: reported wrongly: {w}")
    print(f"self-test: {len(problems)} problems found, {len(missed)} missed, {len(wrong)} wrong")
    return 1 if missed or wrong else 0


def main(argv):
    if argv == ["--self-test"]:
        return self_test()
    fix = bool(argv) and argv[0] == "--fix"
    argv = argv[1:] if fix else argv
    if not argv:
        print(__doc__)
        return 2
    root = os.path.abspath(argv[1] if len(argv) > 1 else os.path.join(os.path.dirname(__file__), ".."))
    budget = Budget(argv[0])
    count, problems = 0, 0
    for path in documents(root):
        with open(path, encoding="utf-8") as f:
            text = f.read()
        found, fixed = check_text(text, budget)
        count += len(ANNOTATED.findall(text))
        for offset, message in found:
            print(f"{os.path.relpath(path, root)}:{text.count(chr(10), 0, offset) + 1}: {message}")
        problems += len(found)
        if fix and fixed != text:
            with open(path, "w", encoding="utf-8") as f:
                f.write(fixed)
    print(f"{count} memory figures checked against lightscatter budget, {problems} problem(s)"
          + (" (the figures that moved were rewritten)" if fix and problems else ""))
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
