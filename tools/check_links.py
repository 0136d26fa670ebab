#!/usr/bin/env python3
"""Checks that the project's Markdown stands alone: every relative link and image in README.md,
docs/ and the other .md files of the repository resolves to a file inside the repository (and to a
heading, for links with an #anchor), no path climbs out of the repository, and every document a
page names (a word ending in .md) exists in it.

    tools/check_links.py [REPO_ROOT]     exit 0: all good; 1: one line per broken reference
    tools/check_links.py --self-test     checks the checker on a small made-up repository
"""
import os
import re
import sys

sys.dont_write_bytecode = True  # the checkers run from the tests: they write nothing here
from doc_text import repository_files, without_code  # noqa: E402

LINK = re.compile(r"!?\[(?:[^\[\]]|\[[^\]]*\])*\]\(\s*<?([^)\s>]+)>?(?:\s+\"[^\"]*\")?\s*\)")
REFERENCE = re.compile(r"^\s{0,3}\[[^\]]+\]:\s*<?(\S+?)>?(?:\s+.*)?$", re.M)
HTML = re.compile(r"<(?:a|img)\b[^>]*?\b(?:href|src)\s*=\s*\"([^\"]+)\"", re.I)
NAMED_DOC = re.compile(r"(?<![\w/.-])(/?(?:\.{1,2}/)*[\w.-]+(?:/[\w.-]+)*\.md)\b")
CLIMBING = re.compile(r"(?<![\w/.-])((?:\.\./)+[\w.-][\w./-]*)")
SCHEME = re.compile(r"^[a-zA-Z][a-zA-Z0-9+.-]*:")


def markdown_files(root):
    return sorted(f for f in repository_files(root, "*.md", lambda d: d.startswith(".") or d.startswith("build"))
                  if os.path.isfile(os.path.join(root, f)))


def slug(heading):
    s = re.sub(r"[`*_]", "", heading.strip().lower())
    s = re.sub(r"[^\w\- ]", "", s)
    return s.replace(" ", "-")


def anchors(path):
    with open(path, encoding="utf-8") as f:
        text = without_code(f.read())
    seen, out = {}, set()
    for m in re.finditer(r"^\s{0,3}#{1,6}\s+(.*?)\s*#*\s*$", text, re.M):
        s = slug(m.group(1))
        n = seen.get(s, 0)
        seen[s] = n + 1
        out.add(s if n == 0 else f"{s}-{n}")
    return out


def inside(root, path):
    root, path = os.path.realpath(root), os.path.realpath(path)
    return path == root or path.startswith(root + os.sep)


def check(root):
    problems = []
    files = markdown_files(root)
    basenames = {os.path.basename(f) for f in files}
    for rel in files:
        path = os.path.join(root, rel)
        with open(path, encoding="utf-8") as f:
            raw = f.read()
        text = without_code(raw)
        here = os.path.dirname(path)

        def line_of(pos, source=text):
            return source.count("\n", 0, pos) + 1

        targets = [(m.group(1), m.start()) for m in LINK.finditer(text)]
        targets += [(m.group(1), m.start()) for m in REFERENCE.finditer(text)]
        targets += [(m.group(1), m.start()) for m in HTML.finditer(text)]
        for target, pos in targets:
            where = f"{rel}:{line_of(pos)}"
            if SCHEME.match(target):
                continue  # http(s), mailto: not the repository's business
            file_part, _, anchor = target.partition("#")
            dest = path if not file_part else os.path.normpath(os.path.join(here, file_part))
            if not inside(root, dest):
                problems.append(f"{where}: link '{target}' points outside the repository")
            elif not os.path.exists(dest):
                problems.append(f"{where}: link '{target}': no such file in the repository")
            elif anchor and dest.endswith(".md") and anchor not in anchors(dest):
                problems.append(f"{where}: link '{target}': {os.path.relpath(dest, root)} has no "
                                f"heading #{anchor}")

        # Documents named in the prose or in code: they must be the repository's own.
        for m in NAMED_DOC.finditer(raw):
            name = m.group(1)
            where = f"{rel}:{line_of(m.start(), raw)}"
            candidates = [os.path.normpath(os.path.join(here, name)),
                          os.path.normpath(os.path.join(root, name.lstrip("/")))]
            if name.startswith("/"):
                candidates = []  # an absolute path: on the writer's machine, not the reader's
            if any(inside(root, c) and os.path.exists(c) for c in candidates):
                continue
            if "/" not in name and name in basenames:
                continue  # e.g. README.md of another folder, named by its file name
            problems.append(f"{where}: names '{name}', which is not in the repository")
        for m in CLIMBING.finditer(raw):
            dest = os.path.normpath(os.path.join(here, m.group(1)))
            if not inside(root, dest):
                problems.append(f"{rel}:{line_of(m.start(), raw)}: path '{m.group(1)}' leaves the repository")
    return files, problems


def self_test():
    import tempfile
    with tempfile.TemporaryDirectory() as root:
        os.makedirs(os.path.join(root, "docs"))
        with open(os.path.join(root, "docs", "a.md"), "w") as f:
            f.write("# A page\n\n## Some heading\n\nBack to [the README](../README.md).\n")
        with open(os.path.join(root, "README.md"), "w") as f:
            f.write("# Top\n\n"
                    "[fine](docs/a.md), [fine too](docs/a.md#some-heading), [here](#top), "
                    "[web](https://example.com/x.md)\n"
                    "[no such heading](docs/a.md#nothing)\n"
                    "![missing image](docs/missing.png)\n"
                    "[outside](../../elsewhere.md)\n"
                    "as MODEL.md says, and `/work/shared/DESIGN.md`\n"
                    "```\n[in code](nowhere.md) is not a link\n```\n"
                    "[ref]: docs/gone.md\n")
        _, problems = check(root)
    expected = ["has no heading #nothing", "docs/missing.png': no such file", "points outside the repository",
                "names 'MODEL.md'", "names '/work/shared/DESIGN.md'", "link 'docs/gone.md': no such file",
                "names '../../elsewhere.md'", "path '../../elsewhere.md' leaves the repository",
                "names 'nowhere.md'", "names 'docs/gone.md'"]
    missing = [e for e in expected if not any(e in p for p in problems)]
    extra = [p for p in problems if not any(e in p for e in expected)]
    for m in missing:
        print(f"self-test: not reported: {m}")
    for x in extra:
        print(f"self-test: reported wrongly: {x}")
    print(f"self-test: {len(problems)} problems found, {len(missing)} missed, {len(extra)} wrong")
    return 1 if missing or extra else 0


def main():
    if sys.argv[1:] == ["--self-test"]:
        return self_test()
    root = os.path.abspath(sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), ".."))
    files, problems = check(root)
    for p in problems:
        print(p)
    print(f"{len(files)} Markdown files checked, {len(problems)} broken reference(s)")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
