#!/usr/bin/env bash
# Regenerates docs/performance.md and its plots: the benchmark of the shipped scenes (bench/report.json,
# or the file given), the hard-case suite, the memory budget, then the plots and the page.
#   scripts/make-report.sh                 # lavapipe-sized configuration (about 15 minutes on 2 cores)
#   scripts/make-report.sh bench/full.json # the GPU machine's configuration
set -euo pipefail
cd "$(dirname "$0")/.."
config="${1:-bench/report.json}"
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release > /dev/null
cmake --build build -j"$(nproc)" --target lightscatter > /dev/null
out=docs/performance
mkdir -p "$out"
./build/host_example/lightscatter bench --config "$config" --out build/bench-report
./build/host_example/lightscatter bench --config bench/hard.json --out build/bench-hard
./build/host_example/lightscatter budget --json > build/bench-report/budget.json
/usr/bin/python3 scripts/plot_bench.py build/bench-report "$out"
rm -f "$out"/strip_*.png
for s in build/bench-report/strips/*_epipolar_balanced.png build/bench-report/strips/*_brute-force.png; do
  cp "$s" "$out/strip_$(basename "$s")"
done
/usr/bin/python3 scripts/write_report.py build/bench-report build/bench-hard "$config" > docs/performance.md
echo "docs/performance.md regenerated"
