#!/usr/bin/env bash
# Soak test: the `view` window under Xvfb for many frames, the light moving every frame and the
# window resized again and again, under the validation layer. Host memory (resident set) and the
# device memory the render graphs hold are sampled every 100 frames; after a warm-up that has shown
# every window size, neither may grow by more than 2%, and the layer must report nothing.
#
#   scripts/soak.sh [--frames N] [--resizes N] [--scene FILE] [--out DIR] [--binary PATH]
#
# Defaults: 10000 frames, 50 resizes, scenes/window_room.json, out/soak, build/host_example/lightscatter.
set -euo pipefail
cd "$(dirname "$0")/.."
frames=10000
resizes=50
scene=scenes/window_room.json
out=out/soak
binary=build/host_example/lightscatter
while [ $# -gt 0 ]; do
    case "$1" in
        --frames) frames=$2; shift 2 ;;
        --resizes) resizes=$2; shift 2 ;;
        --scene) scene=$2; shift 2 ;;
        --out) out=$2; shift 2 ;;
        --binary) binary=$2; shift 2 ;;
        *) echo "soak.sh: unknown option '$1'" >&2; exit 2 ;;
    esac
done
mkdir -p "$out"
log="$out/memory.csv"
start=$(date +%s)
status=0
# The X authority file in $out, not in xvfb-run's temporary folder, whose removal once failed a
# run that had passed (tests/host/cli_runner.h).
xvfb-run -a -f "$out/.xvfb-authority" "$binary" view "$scene" --size 160x90 --profile low-high-performance --frames "$frames" \
    --animate-light --resizes "$resizes" --memory-log "$log" --validation >"$out/view.log" 2>&1 || status=$?
seconds=$(( $(date +%s) - start ))
if [ "$status" -ne 0 ]; then
    echo "soak.sh: lightscatter view exited with $status after ${seconds} s (3: validation messages); see $out/view.log" >&2
    tail -n 5 "$out/view.log" >&2
    exit 1
fi
# The warm-up ends once three resizes have shown the three window sizes (and at 10% of the run at
# the earliest); later samples must stay within 2% of the highest sample until then.
python3 - "$log" "$frames" "$resizes" "$seconds" <<'PY'
import csv, math, sys
path, frames, resizes, seconds = sys.argv[1], int(sys.argv[2]), int(sys.argv[3]), int(sys.argv[4])
rows = [(int(r["frame"]), int(r["rss_kib"]), int(r["device_bytes"])) for r in csv.DictReader(open(path))]
period = frames // (resizes + 1) if resizes else frames
warm = max(3 * period if resizes >= 3 else 0, frames // 10)
warm = int(math.ceil(warm / 100.0) * 100)
base = [r for r in rows if r[0] <= warm]
after = [r for r in rows if r[0] > warm]
if not base or not after:
    sys.exit(f"soak: {len(rows)} samples do not reach past the warm-up (frame {warm}); run more frames")
ok = True
for name, i, scale in (("host resident memory", 1, 1024.0), ("device memory", 2, 1048576.0)):
    limit = max(r[i] for r in base)
    worst = max(r[i] for r in after)
    growth = (worst - limit) / limit * 100.0
    print(f"soak: {name}: {limit / scale:.1f} MiB after the warm-up (frame {warm}), at most {worst / scale:.1f} MiB "
          f"over frames {after[0][0]}-{after[-1][0]} ({growth:+.2f}%)")
    if growth > 2.0:
        ok = False
print(f"soak: {frames} frames, {resizes} resizes, {seconds} s, no validation message")
sys.exit(0 if ok else "soak: memory grew by more than 2% after the warm-up")
PY
