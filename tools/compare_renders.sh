#!/usr/bin/env bash
# Renders every shipped scene with every method (and the auto choice), small and one frame, with two
# builds of lightscatter, and compares the images byte for byte: a redesign that claims to change no
# image runs this against the commit before it.
#
#   tools/compare_renders.sh BASE_COMMIT            builds BASE_COMMIT in a temporary worktree
#   tools/compare_renders.sh --base-binary FILE     uses an already built base lightscatter
#   optional: --binary FILE (default build/host_example/lightscatter),
#             --base-renders DIR (the base's renders: reused when DIR exists, else made there)
#
# A method that refuses a scene must refuse it in both builds with the same message. Prints one line
# per difference and exits 1 when there is any.
set -euo pipefail
cd "$(dirname "$0")/.."
root=$PWD
base_commit="" base_bin="" new_bin="$root/build/host_example/lightscatter" base_dir=""
while [ $# -gt 0 ]; do
  case "$1" in
    --base-binary) base_bin=$2; shift 2 ;;
    --binary) new_bin=$2; shift 2 ;;
    --base-renders) base_dir=$2; shift 2 ;;
    -*) echo "compare_renders: unknown option $1" >&2; exit 2 ;;
    *) base_commit=$1; shift ;;
  esac
done
if [ -z "$base_bin" ] && [ -z "$base_commit" ] && { [ -z "$base_dir" ] || [ ! -d "$base_dir" ]; }; then
  echo "usage: tools/compare_renders.sh BASE_COMMIT | --base-binary FILE | --base-renders DIR" \
       "[--binary FILE]" >&2
  exit 2
fi
work=$(mktemp -d "${TMPDIR:-/tmp}/compare-renders.XXXXXX")
trap 'rm -rf "$work"; git -C "$root" worktree prune' EXIT
[ -n "$base_dir" ] || base_dir="$work/base"
have_base=0
[ -d "$base_dir" ] && have_base=1
if [ "$have_base" = 0 ] && [ -z "$base_bin" ]; then
  git -C "$root" worktree add --detach "$work/src" "$base_commit" >/dev/null
  cmake -S "$work/src" -B "$work/build" -DCMAKE_BUILD_TYPE=Release -DLS_BUILD_TESTS=OFF >/dev/null
  cmake --build "$work/build" -j"$(nproc)" --target lightscatter >/dev/null
  base_bin="$work/build/host_example/lightscatter"
fi
[ -x "$new_bin" ] || { echo "compare_renders: $new_bin is not built" >&2; exit 2; }

# The scenes render from a copy, so that nothing is written beside the repository's own files.
cp -r "$root/scenes" "$work/scenes"
# "slices" is the planes method's former name, which both builds accept: base renders made before
# the rename carry it in their file names.
methods="auto epipolar brute-force analytic cone-march slices beam-tree-analytic beam-tree-sampling froxels"
profiles="balanced high-quality low-high-performance"
render() {  # BINARY OUTDIR SCENE METHOD PROFILE
  local stem
  stem="$2/$(basename "$3" .json)-$4-$5"
  if LS_DEVICE=llvmpipe "$1" render "$3" --method "$4" --profile "$5" --size 64x36 \
        --out "$stem.exr" --inscatter "$stem-lin.exr" >"$stem.log" 2>&1; then
    : >"$stem.log"  # a success's chatter (timings) may differ; its images may not
  else
    sed -i "s#$2#OUT#g; s#$work#WORK#g" "$stem.log"  # a refusal's words are compared, not its paths
  fi
}
differences=0 renders=0
mkdir -p "$base_dir" "$work/new"
for scene in "$work"/scenes/*.json "$work"/scenes/hard/*.json; do
  grep -q '"camera"' "$scene" || continue  # settings and bench files are not scenes
  for method in $methods; do
    for profile in $profiles; do
      [ "$have_base" = 1 ] || render "$base_bin" "$base_dir" "$scene" "$method" "$profile"
      render "$new_bin" "$work/new" "$scene" "$method" "$profile"
      renders=$((renders + 1))
    done
  done
done
for f in "$base_dir"/*; do
  n="$work/new/$(basename "$f")"
  if [ ! -e "$n" ] || ! cmp -s "$f" "$n"; then
    echo "differs: $(basename "$f")"
    differences=$((differences + 1))
  fi
done
for n in "$work"/new/*; do
  [ -e "$base_dir/$(basename "$n")" ] || { echo "only in the new build: $(basename "$n")"; differences=$((differences + 1)); }
done
echo "compare_renders: $renders scene x method x profile renders, $(ls "$base_dir" | grep -c 'lin.exr$' || true) images each way, $differences differences"
[ "$differences" -eq 0 ]
