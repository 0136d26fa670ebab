#!/usr/bin/env bash
# Regenerates docs/performance.md and its plots: the benchmark of the shipped scenes (bench/report.json,
# or the file given), the hard-case suite, the memory budget, then the plots and the page.
#   scripts/make-report.sh                 # bench/report.json at 1920x1080 in two runs: the timings
#                                          # (measureError false; about 45 minutes on 2 cores, run it on
#                                          # a quiet machine) and the errors (one frame per configuration
#                                          # against the float64 references, which build/bench-report-error
#                                          # /references keeps: 5 minutes of references the first time,
#                                          # 19 before Embree, "The reference renderer's time"); then
#                                          # bench/trees.json and
#                                          # bench/seed_size.json (about 10 minutes, timings), the hard
#                                          # cases; and about 20 more for bench/planes.json at 1920x1080;
#                                          # LS_REPORT_PLANES=0 skips it; bench/occluders.json, the beam
#                                          # tree against 1 to 1000 boxes at 1920x1080, is about 10 more:
#                                          # LS_REPORT_OCCLUDERS=0 skips it; both then reuse
#                                          # an earlier run's results where build/ has them)
#   scripts/make-report.sh --planes-only   # bench/planes.json alone (seed 002 against epipolar and
#                                          # brute force at 1920x1080; timings: a quiet machine), its
#                                          # plot and strips, its section spliced into the page
#                                          # (--slices-only and LS_REPORT_SLICES, the former names,
#                                          # still work)
#   scripts/make-report.sh --occluders-only  # that benchmark alone, its plot, and its section spliced
#                                          # into the existing docs/performance.md
#   scripts/make-report.sh --lights-only   # the same for "Several lights": bench/lights.json (time and
#                                          # error at 240x135) and bench/lights_scaling.json (1 to 16
#                                          # shadowed spots at 1920x1080, timings only: run it on a quiet
#                                          # machine); LS_REPORT_LIGHTS=0 skips both in a full run and
#                                          # reuses an earlier run's results, as above
#   LS_REPORT_GPU=DIR scripts/make-report.sh # with the GPU section from scripts/gpu-bench.sh's results
#   scripts/make-report.sh --froxels-only  # bench/froxels.json (froxels at HDRP's and Unreal's sizes,
#                                          # plain and temporal, beside epipolar's profiles and brute
#                                          # force at 1920x1080: a quiet machine; about 40 minutes the
#                                          # first time before Embree, most of it the references, which
#                                          # build/bench-froxels/references keeps), the budgets, its
#                                          # plot, and "Against froxel fog" spliced into the page (its
#                                          # N-lights table from --lights-only's run)
#   scripts/make-report.sh --seeds-only    # bench/seed000_*.json, seed002.json, seed003_*.json, seed004.json: each seed's
#                                          # tables at the seed's size, settings and shadow maps, with the
#                                          # seed's figures and a verdict per row ("Seed 000's results beside
#                                          # ours", "Seed 003's ..."); timings only: a quiet machine
#   scripts/make-report.sh --families-only # bench/froxels_families.json (the froxel grid's sweep and
#                                          # epipolar's six profiles at 1920x1080, timed and measured:
#                                          # a quiet machine), its plot, and "Froxels against epipolar:
#                                          # the two families" spliced into the page
#   scripts/make-report.sh --froxels-near-only # bench/froxels_near_light.json (froxels on lights on or
#                                          # beside the screen at 1280x720 against the float64
#                                          # reference; errors only, any machine) and "Froxels near
#                                          # the light" spliced into the page
#   scripts/make-report.sh --froxels-motion-only # bench/froxels_flicker.json (froxels plain and temporal
#                                          # under bench/flicker.json's motions at 160x90, beside epipolar
#                                          # balanced and brute force; about 40 minutes on 2 cores the first
#                                          # time before Embree, most of it the references, which
#                                          # build/bench-froxels-flicker/references keeps) and "Froxels under
#                                          # motion" spliced into the page
#   scripts/make-report.sh --reference-only # the float64 reference over bench/report.json's scenes at
#                                          # 1920x1080 through its double BVH alone and through Embree
#                                          # (about half an hour; a quiet machine), and "The reference
#                                          # renderer's time" spliced into the page
#   scripts/make-report.sh --flicker-only  # bench/flicker.json alone (temporal stability: 60 frames of a
#                                          # moving light, then camera, per scene and method at 160x90;
#                                          # about an hour on 2 cores the first time before Embree, most of it the float64
#                                          # references, which build/bench-flicker/references keeps for
#                                          # the next run) and its section spliced into the page; a full
#                                          # run does the same unless LS_REPORT_FLICKER=0, which reuses
#                                          # an earlier run's results
set -euo pipefail
cd "$(dirname "$0")/.."
config="${1:-bench/report.json}"
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release > /dev/null
cmake --build build -j"$(nproc)" --target lightscatter > /dev/null
out=docs/performance
mkdir -p "$out"
# The load average recorded before a timing run: the 1-minute average still counts a step that has
# just ended (this script's own previous benchmark, or a build), so wait for it to fall below half
# the cores, for at most 90 s, and the figure on the page is then other work's.
load_before() {
  local half i
  half=$(( $(nproc) / 2 ))
  for i in $(seq 18); do
    awk -v h="$half" '{ exit !($1 > h) }' /proc/loadavg || break
    sleep 5
  done
  uptime > "$1"
}
occluders() {
  # The load average around the run goes on the page: the tree and lavapipe share the CPU with
  # whatever else runs.
  mkdir -p build/bench-occluders
  load_before build/bench-occluders/load-before.txt
  ./build/host_example/lightscatter bench --config bench/occluders.json --out build/bench-occluders
  uptime > build/bench-occluders/load-after.txt
  /usr/bin/python3 scripts/plot_occluders.py build/bench-occluders "$out"
}
lights() {
  mkdir -p build/bench-lights-scaling
  load_before build/bench-lights-scaling/load-before.txt
  ./build/host_example/lightscatter bench --config bench/lights_scaling.json --out build/bench-lights-scaling
  uptime > build/bench-lights-scaling/load-after.txt
  ./build/host_example/lightscatter bench --config bench/lights.json --out build/bench-lights
  /usr/bin/python3 scripts/plot_lights.py build/bench-lights-scaling "$out"
  rm -f "$out"/strip_lights_*.png
  for s in build/bench-lights/strips/atrium_lights_epipolar_balanced.png \
           build/bench-lights/strips/point_cage_brute-force.png; do
    if [[ -f "$s" ]]; then cp "$s" "$out/strip_lights_$(basename "$s")"; fi
  done
}
if [[ "$config" == --lights-only ]]; then
  lights
  /usr/bin/python3 scripts/write_report.py --lights-section build/bench-lights-scaling build/bench-lights \
    docs/performance.md
  echo "docs/performance.md: section 'Several lights' replaced"
  exit 0
fi
froxels() {
  # Timings: run it on a quiet machine. The 1920x1080 references stay in build/bench-froxels. The
  # cost of N lights comes from the lights() run's folder (bench/lights_scaling.json lists froxels).
  local dir=build/bench-froxels
  mkdir -p "$dir"
  load_before "$dir/load-before.txt"
  ./build/host_example/lightscatter bench --config bench/froxels.json --out "$dir"
  uptime > "$dir/load-after.txt"
  for m in froxels-hdrp froxels-unreal froxels-hdrp-temporal froxels-unreal-temporal; do
    ./build/host_example/lightscatter budget --method "$m" --profile balanced --size 1920x1080 --json \
      > "$dir/budget-$m.json"
  done
  for p in high-quality balanced high-performance; do
    ./build/host_example/lightscatter budget --method epipolar --profile "$p" --size 1920x1080 --json \
      > "$dir/budget-epipolar-$p.json"
  done
  /usr/bin/python3 scripts/plot_froxels.py "$dir" "$out"
}
if [[ "$config" == --froxels-only ]]; then
  froxels
  /usr/bin/python3 scripts/write_report.py --froxels-section build/bench-froxels \
    build/bench-lights-scaling docs/performance.md
  echo "docs/performance.md: section 'Against froxel fog' replaced"
  exit 0
fi
seeds() {
  # Timings: run it on a quiet machine. Seed 000's tables at the seed's sizes, settings and shadow
  # maps, each configuration's memory beside it, then seed 003's at its two sizes.
  local c p size
  for c in gtx680 quadro intel directional trees; do
    mkdir -p "build/bench-seed000-$c"
    ./build/host_example/lightscatter bench --config "bench/seed000_$c.json" --out "build/bench-seed000-$c"
  done
  for p in high-quality balanced high-performance; do
    ./build/host_example/lightscatter budget --method epipolar --profile "$p" --size 2560x1600 --json \
      > "build/bench-seed000-gtx680/budget-epipolar-$p.json"
  done
  # The smaller GPUs' profiles: (label, slices, samples, shadow map), as bench/seed000_quadro.json.
  for c in quadro:1366x768 intel:1024x768; do
    size=${c#*:}
    while read -r label slices samples map; do
      printf '{"slices": %s, "samplesPerSlice": %s, "shadowMapSize": %s}\n' "$slices" "$samples" "$map" \
        > "build/bench-seed000-${c%%:*}/settings-$label.json"
      ./build/host_example/lightscatter budget --method epipolar --profile custom \
        --settings "build/bench-seed000-${c%%:*}/settings-$label.json" --shadow-map "$map" --size "$size" \
        --json > "build/bench-seed000-${c%%:*}/budget-$label.json"
    done <<'ROWS'
seed-high-quality 1024 1024 2048
seed-balanced 512 512 1024
seed-high-performance 512 256 512
ROWS
  done
  mkdir -p build/bench-seed002
  ./build/host_example/lightscatter bench --config bench/seed002.json --out build/bench-seed002
  mkdir -p build/bench-seed004
  ./build/host_example/lightscatter bench --config bench/seed004.json --out build/bench-seed004
  for size in 1280x720 2560x1440; do
    mkdir -p "build/bench-seed003-$size"
    ./build/host_example/lightscatter bench --config "bench/seed003_$size.json" --out "build/bench-seed003-$size"
  done
}
if [[ "$config" == --seeds-only ]]; then
  load_before build/seeds-load-before.txt
  seeds
  uptime > build/seeds-load-after.txt
  /usr/bin/python3 scripts/write_report.py --seed000-section build/bench-seed000-gtx680 build/bench-seed000-quadro \
    build/bench-seed000-intel build/bench-seed000-directional build/bench-seed000-trees docs/performance.md
  /usr/bin/python3 scripts/write_report.py --seed002-section build/bench-seed002 docs/performance.md
  /usr/bin/python3 scripts/write_report.py --seed004-section build/bench-seed004 docs/performance.md
  /usr/bin/python3 scripts/write_report.py --seed003-section build/bench-seed003-1280x720 \
    build/bench-seed003-2560x1440 docs/performance.md
  echo "docs/performance.md: sections 'Seed 000/002/003/004's results beside ours' replaced"
  exit 0
fi
if [[ "$config" == --reference-only ]]; then
  # The float64 reference over the report's scenes at 1920x1080, through the double BVH alone and
  # through Embree (about half an hour on 2 cores): a quiet machine.
  cmake --build build -j"$(nproc)" --target reference_timing > /dev/null
  dir=build/reference-timing
  mkdir -p "$dir"
  load_before "$dir/load-before.txt"
  date -u +%Y-%m-%d > "$dir/date.txt"
  lscpu | sed -n 's/^Model name: *//p' | head -n 1 > "$dir/cpu.txt"
  mapfile -t scenes < <(/usr/bin/python3 -c 'import json, sys; print("\n".join(json.load(open(sys.argv[1]))["scenes"]))' bench/report.json)
  ./build/tools/reference_timing/reference_timing --size 1920x1080 --traversal both \
    --json "$dir/reference_timing.json" "${scenes[@]}"
  /usr/bin/python3 scripts/write_report.py --reference-section "$dir" docs/performance.md
  echo "docs/performance.md: section 'The reference renderer's time' replaced"
  exit 0
fi
if [[ "$config" == --families-only ]]; then
  # Timings: run it on a quiet machine. The 1920x1080 references stay in build/bench-froxels-families.
  dir=build/bench-froxels-families
  mkdir -p "$dir"
  load_before "$dir/load-before.txt"
  ./build/host_example/lightscatter bench --config bench/froxels_families.json --out "$dir"
  uptime > "$dir/load-after.txt"
  /usr/bin/python3 -c "import sys; sys.path.insert(0, 'scripts'); from report import families; families.plot('$dir', '$out')"
  /usr/bin/python3 scripts/write_report.py --families-section "$dir" docs/performance.md
  echo "docs/performance.md: section 'Froxels against epipolar: the two families' replaced"
  exit 0
fi
if [[ "$config" == --froxels-near-only ]]; then
  ./build/host_example/lightscatter bench --config bench/froxels_near_light.json --out build/bench-froxels-near
  /usr/bin/python3 scripts/write_report.py --froxels-near-section build/bench-froxels-near docs/performance.md
  echo "docs/performance.md: section 'Froxels near the light' replaced"
  exit 0
fi
if [[ "$config" == --froxels-motion-only ]]; then
  ./build/host_example/lightscatter bench --config bench/froxels_flicker.json --out build/bench-froxels-flicker
  /usr/bin/python3 scripts/write_report.py --froxels-motion-section build/bench-froxels-flicker docs/performance.md
  echo "docs/performance.md: section 'Froxels under motion' replaced"
  exit 0
fi
flicker() {
  # Flicker and error do not depend on the machine's speed: no quiet machine needed.
  ./build/host_example/lightscatter bench --config bench/flicker.json --out build/bench-flicker
}
if [[ "$config" == --flicker-only ]]; then
  flicker
  /usr/bin/python3 scripts/write_report.py --flicker-section build/bench-flicker docs/performance.md
  echo "docs/performance.md: section 'Temporal stability' replaced"
  exit 0
fi
# The planes method was "slices" until the word came to mean only an epipolar line: the former
# option and variable still work, and an earlier run's results under the former folder are read.
if [[ "$config" == --slices-only ]]; then config=--planes-only; fi
report_planes="${LS_REPORT_PLANES:-${LS_REPORT_SLICES:-1}}"
planes_dir=build/bench-planes
if [[ ! -f "$planes_dir/bench.json" && -f build/bench-slices/bench.json && "$config" != --planes-only &&
      "$report_planes" == 0 ]]; then
  planes_dir=build/bench-slices
fi
planes_plots() {
  /usr/bin/python3 scripts/plot_planes.py "$planes_dir" "$out"
  rm -f "$out"/strip_planes_*.png "$out"/strip_slices_*.png "$out"/slices_1920x1080.png
  for s in "$planes_dir"/strips/window_room_{planes,slices}_256_rgba8*.png; do
    # A third of the size: a 1920x1080 strip of noise is megabytes otherwise. (An "if": a pattern
    # that matches nothing must not end the function with a failure under set -e.)
    if [[ -f "$s" ]]; then
      /usr/bin/python3 -c 'import sys, matplotlib.image as m; m.imsave(sys.argv[2], m.imread(sys.argv[1])[::3, ::3])' \
        "$s" "$out/strip_planes_$(basename "$s" | sed 's/^window_room_//')"
    fi
  done
}
if [[ "$config" == --planes-only ]]; then
  # Timings: run it on a quiet machine. The 1920x1080 references stay in build/bench-planes.
  ./build/host_example/lightscatter bench --config bench/planes.json --out "$planes_dir"
  planes_plots
  /usr/bin/python3 scripts/write_report.py --planes-section "$planes_dir" docs/performance.md
  echo "docs/performance.md: section 'Seed 002: view-aligned planes' replaced"
  exit 0
fi
if [[ "$config" == --occluders-only ]]; then
  occluders
  /usr/bin/python3 scripts/write_report.py --occluders-section build/bench-occluders docs/performance.md
  echo "docs/performance.md: section 'Beam tree against scene complexity' replaced"
  exit 0
fi
# One configuration, two runs: the timings on their own (no reference rendered between frames, the
# CPU left to the runs) and the errors, one frame each, which do not depend on the machine's load.
mkdir -p build/bench-report build/bench-report-error build/bench-trees build/bench-seed-size
/usr/bin/python3 - "$config" <<'PY'
import json, sys
c = json.load(open(sys.argv[1]))
json.dump(dict(c, measureError=False), open("build/bench-report/config.json", "w"), indent=1)
json.dump(dict(c, frames=1, warmup=0), open("build/bench-report-error/config.json", "w"), indent=1)
PY
timed() {  # CONFIG DIR: a timing run, with the load average around it for the page
  load_before "$2/load-before.txt"
  ./build/host_example/lightscatter bench --config "$1" --out "$2"
  uptime > "$2/load-after.txt"
}
timed build/bench-report/config.json build/bench-report
timed bench/trees.json build/bench-trees
timed bench/seed_size.json build/bench-seed-size
./build/host_example/lightscatter bench --config build/bench-report-error/config.json --out build/bench-report-error
./build/host_example/lightscatter bench --config bench/hard.json --out build/bench-hard
if [[ "$report_planes" != 0 ]]; then
  ./build/host_example/lightscatter bench --config bench/planes.json --out "$planes_dir"
fi
./build/host_example/lightscatter budget --json > build/bench-report/budget.json
/usr/bin/python3 - <<'PY'
# The plots need both halves: the timing run's rows with the error run's errors.
import json, sys
sys.path.insert(0, "scripts")
from report import speed as rs
runs = rs.merge_errors(rs.load_runs("build/bench-report"), rs.load_runs("build/bench-report-error"))
json.dump({"runs": runs}, open("build/bench-report/merged.json", "w"))
PY
mkdir -p build/bench-report/merged && cp build/bench-report/merged.json build/bench-report/merged/bench.json
/usr/bin/python3 scripts/plot_bench.py build/bench-report/merged "$out"
for f in "$out"/strip_*.png; do  # the report's own strips; the lights', planes' and cookies' are their sections'
  case "$(basename "$f")" in strip_lights_* | strip_planes_* | strip_slices_* | strip_cookies_*) ;; *) rm -f "$f" ;; esac
done
for s in build/bench-report-error/strips/*_epipolar_balanced.png build/bench-report-error/strips/*_brute-force.png; do
  cp "$s" "$out/strip_$(basename "$s")"
done
if [[ -f "$planes_dir/bench.json" ]]; then
  planes_plots
fi
occluders_dir=""
if [[ "${LS_REPORT_OCCLUDERS:-1}" != 0 ]]; then
  occluders
  occluders_dir=build/bench-occluders
elif [[ -f build/bench-occluders/bench.json ]]; then
  occluders_dir=build/bench-occluders  # an earlier run's, as for the planes benchmark
fi
lights_dirs=("" "")
if [[ "${LS_REPORT_LIGHTS:-1}" != 0 ]]; then
  lights
  lights_dirs=(build/bench-lights-scaling build/bench-lights)
elif [[ -f build/bench-lights/bench.json ]]; then
  lights_dirs=(build/bench-lights-scaling build/bench-lights)  # an earlier run's
fi
flicker_dir=""
if [[ "${LS_REPORT_FLICKER:-1}" != 0 ]]; then
  flicker
  flicker_dir=build/bench-flicker
elif [[ -f build/bench-flicker/bench.json ]]; then
  flicker_dir=build/bench-flicker  # an earlier run's
fi
# Written beside the page, then moved over it: a section whose results this run lacks (the flicker's,
# say) is copied from the page as it was.
/usr/bin/python3 scripts/write_report.py build/bench-report build/bench-hard "$config" "$planes_dir" \
  "$occluders_dir" "${lights_dirs[@]}" "$flicker_dir" build/bench-report-error build/bench-trees \
  build/bench-seed-size > build/performance.md.new
mv build/performance.md.new docs/performance.md
echo "docs/performance.md regenerated"
