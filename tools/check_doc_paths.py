#!/usr/bin/env python3
"""Checks that the paths the documents name in backticks exist in the repository.

    tools/check_doc_paths.py [REPO_ROOT]     exit 0: all good; 1: one line per path that is not there
    tools/check_doc_paths.py --self-test     checks the checker on a small made-up repository

The documents are the Markdown files check_links.py reads (README.md, docs/, every other .md file
of the repository). Every word of an inline code span (`...`, outside code blocks) that looks like a
repository path is checked: a word ending in an extension the repository's files have (.md, .json,
.cpp, .h, .py, .sh, ...), a folder (a word ending in `/`), or a word with a `/` that starts at one of
the repository's top-level entries (`scenes/...`, `docs/...`); `1/w` or `storageBufferRead/Write`
are not paths. It must name a file or folder of the repository:

- from the repository's root, or from the document's folder;
- or as the last part of a path in the repository: an include path (`lightscatter/lightscatter.h`
  is plugin_api/include/lightscatter/lightscatter.h) or a path relative to a folder the text named
  just before (`epipolar/unwarp.frag` in a table of shaders/); a word without a `/` (a file's name)
  matches a file or folder of that name anywhere;
- or without its extension (`scenes/point_cage` for scenes/point_cage.json);
- or as a file tests/new_method/null_method.patch adds (the example method docs/methods.md walks
  through: `passes/null/`).

Not checked, by rule:

- what a build or a run makes, not the repository: a path under `build/`, a `build-*/` folder,
  `out/` (scripts/setup-and-render.sh's images) or `bench-results/` (bench's default output); an
  installed tree's `lib/` and `share/`;
- absolute paths (`/usr/share/...`, `/dev/zero`): the reader's system, not the repository;
- placeholders: a part in capitals (`SCENE.json`, `DIR/references/`, `FILE.png`), `WxH`, `_N`,
  `<...>`, `*`, `{...}` or `...`;
- what a command writes: the word after an output option (`--out`, `--timings`, `--inscatter`,
  `--screenshot`, `--report`, `--dot`, `--memory-log`, `--report-log`, `-o`) in the same span;
- the example files the documents define themselves, listed in EXAMPLES below with where each is
  shown (a settings file whose text a page gives, a file a command is shown writing).
"""
import os
import re
import sys

sys.dont_write_bytecode = True  # the checkers run from the tests: they write nothing here
from doc_text import repository_files, without_code  # noqa: E402

EXTENSIONS = ("md", "json", "cpp", "h", "hpp", "py", "sh", "cmake", "glsl", "frag", "comp", "vert", "inc",
              "gltf", "glb", "bin", "png", "exr", "csv", "patch", "dict", "txt", "pc", "in", "dot")
OUTPUT_OPTIONS = {"--out", "--timings", "--inscatter", "--screenshot", "--report", "--dot", "--memory-log",
                  "--report-log", "-o", ">"}
BUILD = re.compile(r"^(?:\./)?(?:build(?:-[\w.-]+)?|out|bench-results)(?:/|$)")
INSTALLED = re.compile(r"^(?:lib|share)/")
# Files the documents show rather than ship: (name, where it is shown).
EXAMPLES = {
    "fast-no-trees.json": "docs/host_example.md gives its text (--settings FILE.json)",
    "settings.json": "docs/host_example.md: a settings file of the reader's",
    "lightscatter-settings.json": "the viewer's default name for 'save settings'",
    "t.json": "docs/host_example.md: the timings file a command is shown writing",
    "glass.png": "docs/host_example.md: a cookie named in an error message",
    "big.glb": "docs/host_example.md: a glTF named in an error message",
    "f.json": "docs/host_example.md, docs/reliability.md: a file named in an error message",
    "a.png": "docs/host_example.md: an output named in an example",
    "graph.png": "docs/rendergraph.md: what Graphviz writes",
    "viewer.png": "docs/cli.md: what the screenshot command writes",
    "s.json": "docs/host_example.md, docs/reliability.md: a file named in an example",
    "bench.csv": "what lightscatter bench writes into its --out folder",
    "bench.json": "what lightscatter bench writes into its --out folder",
    "lightscatterConfig.cmake": "what the install writes (from cmake/lightscatterConfig.cmake.in)",
}
# The example method's files, which tests/new_method/null_method.patch adds (docs/methods.md).
PATCH = "tests/new_method/null_method.patch"


def spans(text):
    """(offset, content) of each inline code span."""
    for m in re.finditer(r"(?<!`)(`+)(?!`)(.+?)(?<!`)\1(?!`)", text, re.S):
        yield m.start(), m.group(2)


def looks_like_path(word, top):
    """A word with an extension the repository's files have, or a folder (a trailing /), or one
    starting at a top-level entry of the repository (`scenes/point_cage`); `1/w` and
    `storageBufferRead/Write` are not."""
    if "://" in word or word.startswith(("-", "$", "%", "@", "#", "/")):
        return False
    if not re.fullmatch(r"[\w.@+\-/<>*{}~]+", word) or re.fullmatch(r"\.\w+", word):
        return False  # not a path's characters, or a file type (`.glb`)
    if re.search(r"\.(?:" + "|".join(EXTENSIONS) + r")$", word):
        return True
    return "/" in word and (word.endswith("/") or word.removeprefix("./").split("/")[0] in top)


def placeholder(word):
    if any(c in word for c in "<>*{}") or "..." in word or "WxH" in word:
        return True
    for part in word.strip("/").split("/"):
        stem = part.split(".")[0]
        if re.fullmatch(r"[A-Z][A-Z0-9_-]*", stem) or re.search(r"_N$", stem) or stem == "N":
            return True
    return False


def check(root):
    files = repository_files(root, skip_dir=lambda d: d.startswith(".") or bool(BUILD.match(d)))
    paths = set(files)
    for f in files:  # every folder too
        parts = f.split("/")
        for i in range(1, len(parts)):
            paths.add("/".join(parts[:i]))
    try:
        with open(os.path.join(root, PATCH), encoding="utf-8") as f:
            patched = re.findall(r"^\+\+\+ b/(\S+)", f.read(), re.M)
    except OSError:
        patched = []
    for f in patched:
        parts = f.split("/")
        for i in range(1, len(parts) + 1):
            paths.add("/".join(parts[:i]))
    names = {p.split("/")[-1] for p in paths}
    top = {p.split("/")[0] for p in paths}
    problems, checked = [], 0
    for rel in (f for f in files if f.endswith(".md")):
        with open(os.path.join(root, rel), encoding="utf-8") as f:
            text = without_code(f.read(), indented=True)
        here = os.path.dirname(rel)
        for offset, span in spans(text):
            words = span.split()
            for i, raw in enumerate(words):
                word = raw.strip("\"'(),;:[]")
                word = re.sub(r"[.,;:]$", "", word) if not re.search(r"\.(?:" + "|".join(EXTENSIONS) + ")$", word) \
                    else word
                if not word or not looks_like_path(word, top):
                    continue
                if BUILD.match(word) or INSTALLED.match(word) or placeholder(word):
                    continue
                if i > 0 and words[i - 1] in OUTPUT_OPTIONS:
                    continue
                if word in EXAMPLES:
                    continue
                checked += 1
                bare = word.rstrip("/").removeprefix("./")
                if bare in paths or os.path.normpath(os.path.join(here, bare)) in paths:
                    continue
                if "/" in bare and any(p == bare or p.endswith("/" + bare) for p in paths):
                    continue
                if "/" not in bare and bare in names:
                    continue
                if any(p.startswith(bare + ".") for p in paths):
                    continue  # a scene or configuration named without its .json
                line = text.count("\n", 0, offset) + 1
                problems.append(f"{rel}:{line}: `{word}` is not in the repository")
    return checked, problems


def self_test():
    import tempfile
    with tempfile.TemporaryDirectory() as root:
        for f in ("README.md", "docs/a.md", "scripts/run.sh", "lib/include/pkg/api.h", "passes/epi/node.cpp"):
            os.makedirs(os.path.join(root, os.path.dirname(f)), exist_ok=True)
            open(os.path.join(root, f), "w").close()
        with open(os.path.join(root, "docs", "a.md"), "w") as f:
            f.write("Run `scripts/run.sh --out out/x.png` and `lightscatter render scenes/gone.json`; "
                    "include `<pkg/api.h>` as `pkg/api.h`; the node `epi/node.cpp`; `build/bin/x`; "
                    "`SCENE.json`; `bench/seed_WxH.json`; `/usr/share/x`; `missing.cpp`; `docs/a.md`; "
                    "`../scripts/run.sh`; `scripts/`; `tools/nowhere/`; `render x --timings t2.json`; "
                    "`fast-no-trees.json`.\n\n```\n`in/a/fence.json`\n```\n")
        _, problems = check(root)
    expected = ["`scenes/gone.json` is not", "`missing.cpp` is not", "`tools/nowhere/` is not"]
    missed = [e for e in expected if not any(e in p for p in problems)]
    wrong = [p for p in problems if not any(e in p for e in expected)]
    for m in missed:
        print(f"self-test: not reported: {m}")
    for w in wrong:
        print(f"self-test: reported wrongly: {w}")
    print(f"self-test: {len(problems)} problems found, {len(missed)} missed, {len(wrong)} wrong")
    return 1 if missed or wrong else 0


def main():
    if sys.argv[1:] == ["--self-test"]:
        return self_test()
    root = os.path.abspath(sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), ".."))
    checked, problems = check(root)
    for p in problems:
        print(p)
    print(f"{checked} paths in backticks checked, {len(problems)} not in the repository")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
