#!/usr/bin/env bash
# Fuzzes the project's own input readers (tests/fuzz/: the scene reader, the --settings reader, the
# benchmark configuration reader, the glTF loader's checks over what tinygltf parsed).
#
#   scripts/fuzz.sh [--build DIR] [SECONDS] [TARGET...]
#
# Builds build-fuzz/ with clang++ (libFuzzer, AddressSanitizer, UndefinedBehaviorSanitizer; only
# the fuzz targets and what they link) and runs each target for SECONDS (default 30; CI runs 30),
# one after the other. With --build DIR the targets are built in DIR instead, a folder configured
# with -DLS_FUZZ=ON (scripts/test.sh passes build-asan/, whose libraries are then compiled once
# for both); corpora, logs and findings stay in build-fuzz/. Each starts from a working copy of its
# corpus in build-fuzz/corpus/TARGET: the shipped files (scenes, benchmark configurations, glTF) and
# tests/fuzz/corpus/TARGET/, which holds the settings examples and every input a fuzzer ever found a
# fault with; tests/fuzz/TARGET.dict gives it the format's words (keys, methods, glTF's types).
# Nothing is written into the repository: a new finding is left in build-fuzz/findings/ and its
# input is added to tests/fuzz/corpus/TARGET/ by hand, with the fix and a test. A crash, a
# sanitizer report, an input that runs longer than 10 s or a process above 2 GB counts as a finding
# and fails the script.
set -euo pipefail
cd "$(dirname "$0")/.."
root=$PWD
build=""
if [[ ${1:-} == --build ]]; then
    build=${2:?"fuzz: --build needs a build folder"}
    shift 2
fi
seconds=${1:-30}
shift $(($# > 0 ? 1 : 0))
targets=("$@")
[ ${#targets[@]} -gt 0 ] || targets=(scene settings bench gltf)
out=$root/build-fuzz

# -O0 for build-fuzz/ alone: the build is most of a short run (88 s of CPU at -O0, 137 s at -O1,
# which runs each input several times as fast: LS_FUZZ_FLAGS="-O1 -gline-tables-only" for long
# runs). scripts/test.sh's build-asan/ is at -O1 already.
flags=${LS_FUZZ_FLAGS:--O0 -gline-tables-only}
mkdir -p "$out"
if [[ -n $build ]]; then
    if ! grep -qx 'LS_FUZZ:BOOL=ON' "$build/CMakeCache.txt" 2> /dev/null; then
        echo "fuzz: --build $build: not a build folder configured with -DLS_FUZZ=ON" >&2
        exit 1
    fi
else
    build=$out
    cmake -S . -B "$build" --log-level=WARNING -DCMAKE_CXX_COMPILER=clang++ -DLS_FUZZ=ON \
        -DLS_BUILD_TESTS=OFF -DLS_BUILD_HOST_EXAMPLE=OFF -DLS_INSTALL=OFF \
        -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_FLAGS_RELEASE="$flags"
fi
cmake --build "$build" -j"$(nproc)" --target "${targets[@]/%/_fuzzer}" > "$out/build.log" 2>&1 ||
    { tail -n 40 "$out/build.log"; exit 1; }

# The seeds of each target, besides tests/fuzz/corpus/TARGET/. Files above the inputs' length cap
# (occluders_1000.gltf) would only be cut short.
max_len=65536
seeds() {
    case $1 in
        scene) ls scenes/*.json scenes/hard/*.json ;;
        bench) ls bench/*.json ;;
        gltf) ls scenes/*.gltf scenes/hard/*.gltf ;;
        settings) ;;
    esac
    ls "tests/fuzz/corpus/$1"/* 2> /dev/null || true
}

export TMPDIR=$out/tmp  # the targets' scratch files
export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1:symbolize=1
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
failed=()
for t in "${targets[@]}"; do
    corpus=$out/corpus/$t
    mkdir -p "$corpus" "$out/findings" "$out/logs"
    rm -rf "$TMPDIR" && mkdir -p "$TMPDIR"
    for f in $(seeds "$t"); do
        [ "$(stat -c %s "$f")" -le $max_len ] && cp "$f" "$corpus/seed-$(basename "$f")"
    done
    log=$out/logs/$t.log
    if "$build/tests/fuzz/${t}_fuzzer" "$corpus" -dict="tests/fuzz/$t.dict" -max_len=$max_len \
        -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 -print_final_stats=1 \
        -artifact_prefix="$out/findings/$t-" > "$log" 2>&1; then
        runs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log")
        echo "fuzz: $t: ${runs:-?} inputs in ${seconds} s, $(grep -o 'cov: [0-9]*' "$log" | tail -n 1), no finding"
    else
        failed+=("$t")
        echo "fuzz: $t: FINDING (log: $log)"
        grep -E "ERROR|SUMMARY|fuzz: the refusal|Test unit written|==[0-9]+==" "$log" | head -n 20
    fi
done
rm -rf "$TMPDIR"
if [ ${#failed[@]} -gt 0 ]; then
    echo "fuzz: findings in ${failed[*]}: see build-fuzz/findings/"
    exit 1
fi
