#!/usr/bin/env bash
# Where the epipolar unwarp's time goes: builds `lightscatter` from the committed tree five times,
# each with a part of shaders/epipolar/unwarp.frag taken out, and times the unwarp pass of each on
# window_room (a spot) and atrium (a sun) at 1920x1080, balanced settings. The variants:
#   shipped         the shader as it is
#   no-ratio        without the ratio mode's per-pixel closed-form unshadowed Lin
#   no-search       without the search of the 2 x 2 nearest samples (one fetch instead)
#   composite-only  without both: reads the depth and the engine's color, writes the color
#   store-only      as composite-only, but writes the color without reading it
# The images of the variants are wrong by design: only the times mean anything. Each variant runs
# three times, in turn, and the table gives the fastest round with all three: a slow spell of the
# machine shows as a disagreement between the rounds. Run it on a quiet machine (about 5 minutes
# of building and 3 of timing on 2 cores).
#   scripts/unwarp-breakdown.sh [OUT]   # default build/unwarp-breakdown; OUT/breakdown.txt
set -euo pipefail
cd "$(dirname "$0")/.."
out=$(realpath -m "${1:-build/unwarp-breakdown}")
src="$out/src"
rm -rf "$src" && mkdir -p "$src" "$out/bin"
git archive HEAD | tar -x -C "$src"
shader="$src/shaders/epipolar/unwarp.frag"
cp "$shader" "$out/unwarp.frag.shipped"

# Each edit must match exactly once, or the variant would silently time the shipped shader.
edit() {
    local from="$1" to="$2"
    local n
    n=$(grep -cF -- "$from" "$shader" || true)
    if [ "$n" != 1 ]; then
        echo "unwarp-breakdown: '$from' occurs $n times in shaders/epipolar/unwarp.frag (want 1)" >&2
        exit 1
    fi
    python3 - "$shader" "$from" "$to" <<'PY'
import sys
p, a, b = sys.argv[1:]
s = open(p).read()
open(p, "w").write(s.replace(a, b))
PY
}
no_ratio() {
    edit 'value.rgb *= unshadowedInscatter(C, v, t0, t1);' 'value.rgb *= vec3(1.0);'
}
no_search() {
    edit 'for (int a = 0; a < 2; ++a) {' \
        'sum = texelFetch(inscatter, ivec2(gl_FragCoord.xy) % ivec2(512), 0); weight = 1.0; for (int a = 0; a < 0; ++a) {'
}
store_only() {
    edit 'compositeInto(pixel, value.rgb, S, pc.addOnly != 0);' \
        'imageStore(engineColor, pixel, vec4(value.rgb * S, 1.0));'
}

cmake -S "$src" -B "$out/build" -DCMAKE_BUILD_TYPE=Release >/dev/null
for v in shipped no-ratio no-search composite-only store-only; do
    cp "$out/unwarp.frag.shipped" "$shader"
    case $v in
        no-ratio) no_ratio ;;
        no-search) no_search ;;
        composite-only) no_ratio && no_search ;;
        store-only) no_ratio && no_search && store_only ;;
    esac
    echo "building $v"
    cmake --build "$out/build" --target lightscatter -j"$(nproc)" >"$out/build-$v.log" 2>&1
    cp "$out/build/host_example/lightscatter" "$out/bin/$v"
done

cat >"$out/config.json" <<'JSON'
{"name": "unwarp breakdown", "frames": 5, "warmup": 1, "size": "1920x1080",
 "scenes": ["scenes/window_room.json", "scenes/atrium.json"],
 "methods": ["epipolar"], "profiles": ["balanced"], "measureError": false}
JSON
for round in 1 2 3; do
    for v in shipped no-ratio no-search composite-only store-only; do
        echo "timing $v, round $round"
        "$out/bin/$v" bench --config "$out/config.json" --out "$out/runs/$v-$round" >"$out/runs-$v-$round.log" 2>&1
    done
done
python3 - "$out" <<'PY' | tee "$out/breakdown.txt"
import json, os, sys
out = sys.argv[1]
variants = ["shipped", "no-ratio", "no-search", "composite-only", "store-only"]
device = ""
rows = {}
for v in variants:
    for r in (1, 2, 3):
        bench = json.load(open(os.path.join(out, "runs", f"{v}-{r}", "bench.json")))
        for run in bench["runs"]:
            device = run["device"]
            passes = {p["name"]: p["median"] for p in run["passes"]}
            scene = os.path.basename(run["scene"]).split(".")[0]
            rows.setdefault((v, scene), []).append(passes["unwarp epipolar to screen"])
print(f"unwarp pass, median ms of 5 frames at 1920x1080, balanced, on {device}: fastest round (rounds 1 / 2 / 3)")
scenes = sorted({s for _, s in rows})
print("| variant | " + " | ".join(scenes) + " |")
print("|---|" + "---|" * len(scenes))
for v in variants:
    cells = [f"{min(rows[(v, s)]):.1f} (" + " / ".join(f"{t:.1f}" for t in rows[(v, s)]) + ")" for s in scenes]
    print(f"| {v} | " + " | ".join(cells) + " |")
PY
