#!/usr/bin/env bash
# The format check CI runs: every tracked C++ file (or the files given, paths from the repository
# root) against .clang-format, with `clang-format --dry-run --Werror`. It changes nothing; it lists
# each line clang-format would change and fails if there is one. To fix a file: clang-format -i FILE.
#   scripts/check-format.sh [FILE...]
set -euo pipefail
cd "$(dirname "$0")/.."
if [[ $# -gt 0 ]]; then
  files=("$@")
else
  mapfile -t files < <(git ls-files -- '*.cpp' '*.h' '*.hpp' '*.cc')
fi
[[ ${#files[@]} -gt 0 ]] || { echo "check-format: no C++ files to check" >&2; exit 2; }
for f in "${files[@]}"; do
  [[ -f "$f" ]] || { echo "check-format: $f: no such file" >&2; exit 2; }
done
command -v clang-format > /dev/null || { echo "check-format: clang-format is not installed" >&2; exit 2; }
log=$(mktemp)
trap 'rm -f "$log"' EXIT
status=0
clang-format --dry-run --Werror --style=file "${files[@]}" 2> "$log" || status=$?
# One diagnostic per replacement: FILE:LINE:COLUMN: error: code should be clang-formatted.
places=$(grep -oE '^[^: ]+:[0-9]+:[0-9]+: error: code should be clang-formatted' "$log" | cut -d: -f1,2 | sort -u -t: -k1,1 -k2,2n || true)
if [[ $status -eq 0 && -z "$places" ]]; then
  echo "check-format: ${#files[@]} files match .clang-format"
  exit 0
fi
if [[ -z "$places" ]]; then
  # clang-format failed for another reason (a missing file, a bad .clang-format).
  echo "check-format: clang-format failed: $(head -1 "$log")" >&2
  exit "$status"
fi
echo "$places"
bad_files=$(cut -d: -f1 <<< "$places" | sort -u | wc -l)
bad_lines=$(wc -l <<< "$places")
echo "check-format: $bad_files of ${#files[@]} files differ from .clang-format, on $bad_lines lines" \
  "(clang-format -i FILE fixes one)" >&2
exit 1
