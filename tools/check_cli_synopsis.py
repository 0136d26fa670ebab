#!/usr/bin/env python3
"""Checks docs/cli.md's synopsis against the program it describes: the block that follows the line
`<!-- synopsis: ... -->` must say what `lightscatter --help` says, and each command's line in it
what `lightscatter COMMAND --help` says of that command.

    tools/check_cli_synopsis.py LIGHTSCATTER [REPO_ROOT]   exit 0: they agree; 1: one line per difference
    tools/check_cli_synopsis.py --self-test                 checks the checker on made-up texts

What is compared, whitespace aside (the block is indented as Markdown code and its lines are
wrapped where the page likes):
- every command of `--help` has its synopsis in the block, word for word, and the block names no
  other command;
- the lines after the commands (`common options: ...`, the methods and the profiles) are the same;
- each command's own `--help` opens with the same synopsis, and every option its help explains
  (a line starting with `  --`) appears in that synopsis (a command's help need not explain every
  option: `--method` and `--profile` are the methods and profiles its last lines list).
"""
import os
import re
import subprocess
import sys

MARKER = re.compile(r"^<!-- synopsis:.*-->\s*$")


def words(text):
    return " ".join(text.split())


def help_parts(text):
    """(commands {name: synopsis words}, footer words) of `lightscatter --help`."""
    lines = text.rstrip("\n").split("\n")[1:]  # the first line is "usage: ..."
    commands, footer, current = {}, [], None
    for line in lines:
        if line.startswith("  ") and not line.startswith("   "):
            current = line.split()[0]
            commands[current] = line.strip()
        elif line.startswith("   ") and current is not None and not footer:
            commands[current] += " " + line.strip()
        else:
            current = None
            footer.append(line)
    return {k: words(v) for k, v in commands.items()}, words("\n".join(footer))


def block_parts(block):
    """(commands {name: synopsis words}, footer words) of the page's block, whose command lines
    start with `lightscatter NAME` and whose continuation lines are indented further."""
    commands, footer, current = {}, [], None
    for line in block:
        m = re.match(r"^lightscatter (\S+)", line.strip())
        if m and not footer:
            current = m.group(1)
            commands[current] = line.strip()[len("lightscatter "):]
        elif current is not None and not footer and line.startswith(" " * 8):
            commands[current] += " " + line.strip()
        else:
            current = None
            footer.append(line.strip())
    return {k: words(v) for k, v in commands.items()}, words("\n".join(footer))


def page_block(page):
    lines = page.split("\n")
    at = next((i for i, l in enumerate(lines) if MARKER.match(l)), None)
    if at is None:
        return None
    i = at + 1
    while i < len(lines) and not lines[i].strip():
        i += 1
    block = []
    while i < len(lines) and (lines[i].startswith("    ") or not lines[i].strip()):
        if lines[i].strip():
            block.append(lines[i][4:])
        elif block and i + 1 < len(lines) and not lines[i + 1].startswith("    "):
            break
        i += 1
    return block


def options(synopsis):
    return set(re.findall(r"--[a-z][a-z-]*", synopsis))


def command_help(text, name):
    """(synopsis words, options explained) of `lightscatter NAME --help`."""
    lines = text.rstrip("\n").split("\n")
    first = lines[0]
    prefix = f"usage: lightscatter {name}"
    if not first.startswith(prefix):
        return None, set()
    synopsis = [first[len("usage: lightscatter "):]]
    i = 1
    while i < len(lines) and lines[i].startswith("   ") and lines[i].strip().startswith("["):
        synopsis.append(lines[i].strip())
        i += 1
    explained = set()
    for line in lines[i:]:
        if line.startswith("common options:"):
            break
        # "  --resize-at N --resize-to WxH  resize ...": the options of the column before the text.
        if re.match(r"^  --[a-z]", line):
            explained |= options(re.split(r"\s{2,}", line.strip(), maxsplit=1)[0])
    return words(" ".join(synopsis)), explained


def compare(page, general, per_command):
    """Problems, one line each. general: `--help`'s text; per_command: {name: its --help text}."""
    problems = []
    block = page_block(page)
    if block is None:
        return ["docs/cli.md has no '<!-- synopsis: ... -->' line followed by the synopsis block"]
    helped, help_footer = help_parts(general)
    paged, page_footer = block_parts(block)
    for name, syn in helped.items():
        if name not in paged:
            problems.append(f"docs/cli.md's synopsis lacks the command '{name}' (--help: lightscatter {syn})")
        elif paged[name] != syn:
            problems.append(f"docs/cli.md's synopsis of '{name}' differs from --help:\n  page: lightscatter "
                            f"{paged[name]}\n  help: lightscatter {syn}")
    for name in paged:
        if name not in helped:
            problems.append(f"docs/cli.md's synopsis names '{name}', which --help does not list")
    if page_footer != help_footer:
        problems.append(f"docs/cli.md's lines after the commands differ from --help's:\n  page: {page_footer}\n"
                        f"  help: {help_footer}")
    for name, text in per_command.items():
        syn, explained = command_help(text, name)
        if syn is None:
            problems.append(f"'lightscatter {name} --help' does not open with 'usage: lightscatter {name}'")
            continue
        if syn != helped.get(name):
            problems.append(f"'lightscatter {name} --help' opens with another synopsis than --help's:\n"
                            f"  {name} --help: {syn}\n  --help: {helped.get(name)}")
        named = options(paged.get(name, ""))
        for o in sorted(explained - named):
            problems.append(f"'lightscatter {name} --help' explains {o}, which docs/cli.md's synopsis of "
                            f"'{name}' lacks")
    return problems


def run(program, *args):
    out = subprocess.run([program, *args], capture_output=True, text=True)
    if out.returncode != 0:
        raise SystemExit(f"{program} {' '.join(args)} exited {out.returncode}: {out.stderr.strip()}")
    return out.stdout


def self_test():
    general = ("usage: lightscatter <command> [options]\n"
               "  render SCENE.json [--out FILE] [--size WxH]\n"
               "                    [--frames N]\n"
               "  pattern [--out FILE.png]\n"
               "common options: --device NAME, --help (-h)\n")
    render = ("usage: lightscatter render SCENE.json [--out FILE] [--size WxH]\n"
              "                    [--frames N]\nRenders.\n  --out FILE   the image\n  --size WxH   size\n"
              "  --frames N   frames\n  --settings FILE.json  JSON object\ncommon options: --device NAME\n")
    pattern = "usage: lightscatter pattern [--out FILE.png]\nPattern.\ncommon options: --device NAME\n"
    good = ("# CLI\n\n<!-- synopsis: x -->\n\n    lightscatter render SCENE.json [--out FILE]\n"
            "                        [--size WxH] [--frames N]\n    lightscatter pattern [--out FILE.png]\n"
            "    common options: --device NAME, --help (-h)\n\nAfter.\n")
    bad = good.replace(" [--frames N]", "").replace("--help (-h)", "--help")
    bad += "\n"
    found = compare(good, general, {"render": render, "pattern": pattern})
    expected_good = ["explains --settings"]
    wrong = [p for p in found if not any(e in p for e in expected_good)]
    missed_good = [e for e in expected_good if not any(e in p for p in found)]
    found_bad = compare(bad, general, {"render": render, "pattern": pattern})
    expected_bad = ["synopsis of 'render' differs", "lines after the commands differ", "explains --frames"]
    missed_bad = [e for e in expected_bad if not any(e in p for p in found_bad)]
    for p in wrong:
        print(f"self-test: reported wrongly: {p}")
    for e in missed_good + missed_bad:
        print(f"self-test: not reported: {e}")
    print(f"self-test: {len(found) + len(found_bad)} problems found, {len(missed_good + missed_bad)} missed, "
          f"{len(wrong)} wrong")
    return 1 if wrong or missed_good or missed_bad else 0


def main(argv):
    if argv == ["--self-test"]:
        return self_test()
    if not argv:
        print(__doc__)
        return 2
    program = argv[0]
    root = os.path.abspath(argv[1] if len(argv) > 1 else os.path.join(os.path.dirname(__file__), ".."))
    with open(os.path.join(root, "docs", "cli.md"), encoding="utf-8") as f:
        page = f.read()
    general = run(program, "--help")
    names, _ = help_parts(general)
    problems = compare(page, general, {name: run(program, name, "--help") for name in names})
    for p in problems:
        print(p)
    print(f"docs/cli.md's synopsis against {len(names)} commands' --help: {len(problems)} difference(s)")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
