#!/usr/bin/env bash
# The sanitizer part of scripts/test.sh: a second build with AddressSanitizer and
# UndefinedBehaviorSanitizer (undefined behaviour is fatal), then the GPU-free suites with leak
# detection, and a few GPU tests on lavapipe. Leak detection is off for the GPU tests: the Vulkan
# loader unloads the driver and the validation layer before LeakSanitizer looks, so their own
# allocations at exit cannot be told from ours; leaked Vulkan objects are caught by the GPU tests'
# validation at teardown instead.
set -euo pipefail
cd "$(dirname "$0")/.."
# clang++ at -O1 (the level AddressSanitizer's documentation recommends): GCC 12 took 1250 s of CPU
# to build these programs with both sanitizers at -O3 (87 s for gltf_test.cpp alone), clang 14 at
# -O1 470 s, and the suites then ran in 32 s. Its warnings are errors too, so the code is
# held to both compilers' warnings. A build folder configured with another compiler is started over.
# LS_FUZZ too: the libraries carry libFuzzer's coverage as well, and scripts/fuzz.sh --build
# build-asan builds its targets on them instead of compiling the libraries a third time.
cache=build-asan/CMakeCache.txt
if [[ -f $cache ]] && ! grep -q '^CMAKE_CXX_COMPILER:[A-Z]*=.*clang++' "$cache"; then
    rm -rf build-asan
fi
cmake -S . -B build-asan -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_BUILD_TYPE=Release \
    -DCMAKE_CXX_FLAGS_RELEASE="-O1 -DNDEBUG" -DLS_WERROR=ON -DLS_SANITIZE=ON -DLS_FUZZ=ON
cmake --build build-asan -j"$(nproc)" --target test_rendergraph_compile test_float64_model test_plugin_budget \
    test_host_scene test_host_camera test_host_bench test_rendergraph_gpu test_plugin_gpu_sanitized fuzzers
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
cd build-asan
for suite in tests/test_rendergraph_compile tests/float64_model/test_float64_model tests/plugin/test_plugin_budget \
             tests/host/test_host_scene tests/host/test_host_camera tests/host/test_host_bench; do
    echo "sanitizers: $suite"
    ASAN_OPTIONS=detect_leaks=1 "./$suite" --gtest_brief=1
done
echo "sanitizers: tests/test_rendergraph_gpu"
ASAN_OPTIONS=detect_leaks=0 ./tests/test_rendergraph_gpu --gtest_brief=1
echo "sanitizers: tests/plugin/test_plugin_gpu_sanitized (a few of test_plugin_gpu's tests)"
ASAN_OPTIONS=detect_leaks=0 ./tests/plugin/test_plugin_gpu_sanitized --gtest_brief=1 \
    --gtest_filter='EpipolarGpu.SpotLightMatchesBruteForce:EpipolarGpu.TinyShadowMapsAreMarchedWithoutTrees:PoisonedTransientsGpu.*:OutOfMemoryGpu.AFailedConstructionLeavesNothingBehind:ReadmeExampleGpu.*'
echo "sanitizers: clean"
