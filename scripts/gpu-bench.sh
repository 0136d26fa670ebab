#!/usr/bin/env bash
# The benchmark on a machine with an NVIDIA GPU, in two halves.
#
#   scripts/gpu-bench.sh prepare
#       Here (Debian 12, x86-64, with network): a release build of `lightscatter` staged with every
#       shared library it loads (except glibc's) in build-gpu/stage/, and the Vulkan and GL loader
#       packages the GPU machine lacks in .gl/. Both are ignored by git; carry them to the machine
#       (build-gpu/stage is a few MiB).
#   scripts/gpu-bench.sh run OUT [CONFIG]
#       On the GPU machine, in a copy of the repository with .gl/ and build-gpu/stage/: unpacks the
#       loader packages, refuses to go on unless the Vulkan device is a GPU (a CPU driver's figures
#       would be taken for GPU ones), and runs CONFIG (default bench/full.json: 1920x1080, every
#       method and profile, 60 frames after 10 of warm-up, GPU timestamps, no float64 reference:
#       errors come from the lavapipe report, they do not depend on the device) into OUT, stopping
#       it before 9.5 minutes. OUT gets bench.json (per-run and per-pass medians) and run.log.
#   scripts/write_report.py --gpu-section OUT docs/performance.md
#       Back here: the page's "GPU timings" section from OUT/bench.json.
set -euo pipefail
cd "$(dirname "$0")/.."
stage=build-gpu/stage

prepare() {
  grep -qx '/.gl/' .git/info/exclude 2>/dev/null || echo '/.gl/' >> .git/info/exclude
  mkdir -p .gl /tmp/ls-apt-amd64/partial
  local o='-oAPT::Architecture=amd64 -oAPT::Architectures=amd64 -oDir::State::Lists=/tmp/ls-apt-amd64'
  # shellcheck disable=SC2086
  apt-get $o update > /dev/null
  # shellcheck disable=SC2086
  (cd .gl && apt-get $o download libvulkan1 libegl1 libglvnd0 libopengl0 libgl1 libglx0 libgles2 > /dev/null)
  cmake -S . -B build-gpu -DCMAKE_BUILD_TYPE=Release -DLS_BUILD_TESTS=OFF > /dev/null
  cmake --build build-gpu -j"$(nproc)" --target lightscatter > /dev/null
  rm -rf "$stage" && mkdir -p "$stage/bin" "$stage/lib"
  cp build-gpu/host_example/lightscatter "$stage/bin/"
  # Every library the binary loads but the C runtime, which the machine has in its own version.
  ldd "$stage/bin/lightscatter" | awk '$3 ~ /^\// {print $3}' | while read -r lib; do
    case "$(basename "$lib")" in
      libc.so*|libm.so*|libdl.so*|libpthread.so*|librt.so*|ld-linux*) ;;
      *) cp -L "$lib" "$stage/lib/" ;;
    esac
  done
  du -sh "$stage" .gl
  echo "carry .gl and $stage; on the machine: scripts/gpu-bench.sh run \$OUT"
}

run() {
  local out="$1" config="${2:-bench/full.json}"
  mkdir -p "$out"
  [[ -x "$stage/bin/lightscatter" ]] || { echo "$stage/bin/lightscatter is missing: run 'scripts/gpu-bench.sh prepare' first" >&2; exit 1; }
  for f in .gl/*.deb; do dpkg -x "$f" /; done
  ldconfig
  local icd=/usr/local/nvidia/share/vulkan/icd.d/nvidia_icd.json
  if [[ -z "${VK_DRIVER_FILES:-}" && -f "$icd" ]]; then export VK_DRIVER_FILES="$icd"; fi
  export LD_LIBRARY_PATH="$PWD/$stage/lib${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}"
  # The bench names the device it ran on in every row; a CPU driver here would be a wrong setup.
  ./"$stage"/bin/lightscatter pattern --out "$out/pattern.png" 2>&1 | tee "$out/run.log"
  if grep -q "(CPU" "$out/run.log"; then
    echo "the Vulkan device is a CPU driver, not the GPU: see $out/run.log" >&2
    exit 1
  fi
  local status=0
  timeout 570 ./"$stage"/bin/lightscatter bench --config "$config" --out /tmp/ls-gpu-bench 2>&1 | tee -a "$out/run.log" || status=$?
  cp /tmp/ls-gpu-bench/bench.json "$out/" 2>/dev/null || true
  rm -f "$out/pattern.png"
  return "$status"
}

case "${1:-}" in
  prepare) prepare ;;
  run) [[ $# -ge 2 ]] || { echo "usage: scripts/gpu-bench.sh run OUT [CONFIG]" >&2; exit 2; }; run "$2" "${3:-}" ;;
  *) echo "usage: scripts/gpu-bench.sh prepare | run OUT [CONFIG]" >&2; exit 2 ;;
esac
