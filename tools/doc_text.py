"""What the documents' checkers share: the repository's files, and a page's text with its code
blocks blanked (line numbers kept), so that what they check is the prose."""
import os
import re
import subprocess

FENCE = re.compile(r"^\s{0,3}(```+|~~~+)")


def repository_files(root, pattern=None, skip_dir=lambda d: d.startswith(".")):
    """The files git tracks or would track under root (matching the git pathspec `pattern` when
    given); without git, a walk that skips folders `skip_dir` names."""
    try:
        out = subprocess.run(["git", "-C", root, "ls-files", "--cached", "--others", "--exclude-standard"]
                             + ([pattern] if pattern else []), check=True, capture_output=True, text=True).stdout
        files = [f for f in out.splitlines() if f]
    except (OSError, subprocess.CalledProcessError):
        files = []
        suffix = pattern.lstrip("*") if pattern else ""
        for base, dirs, names in os.walk(root):
            dirs[:] = [d for d in dirs if not skip_dir(d)]
            files += [os.path.relpath(os.path.join(base, n), root) for n in names if n.endswith(suffix)]
    return sorted(f for f in files if os.path.exists(os.path.join(root, f)))


def without_code(text, indented=False):
    """The text with fenced code blocks blanked, and with `indented` the indented ones too."""
    lines, fence = [], None
    for line in text.split("\n"):
        m = FENCE.match(line)
        if fence:
            if m and m.group(1)[0] == fence[0] and len(m.group(1)) >= len(fence):
                fence = None
            lines.append("")
        elif m:
            fence = m.group(1)
            lines.append("")
        elif indented and line.startswith("    ") and (not lines or not lines[-1].strip()
                                                     or lines[-1].startswith("    ")):
            lines.append("")  # an indented code block: commands, not prose
        else:
            lines.append(line)
    return "\n".join(lines)
