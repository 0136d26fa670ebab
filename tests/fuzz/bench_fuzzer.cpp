// libFuzzer target: the benchmark configuration reader on any bytes, every run it expands to
// checked as `lightscatter bench` checks them before rendering. An input is read or refused with
// one std::runtime_error line; any other outcome is a finding (see scene_fuzzer.cpp).
#include <stdexcept>

#include "bench/bench_config.h"
#include "fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const std::string& path = fuzz::writeInput(data, size, "bench.json");
    try {
        (void)host::bench::loadBenchConfig(path, LS_SOURCE_DIR);
    } catch (const std::runtime_error& e) {
        fuzz::checkRefusal(e.what(), path);
    }
    return 0;
}
