// libFuzzer target: the --settings reader on any bytes, over the balanced profile, the plugin's own
// rules (checkSettings) included. An input is read or refused with one std::runtime_error line; any
// other outcome is a finding (see scene_fuzzer.cpp).
#include <stdexcept>

#include "fuzz_input.h"
#include "settings_file.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const std::string& path = fuzz::writeInput(data, size, "settings.json");
    try {
        (void)host::loadSettingsFile(
            path, lightscatter::profileSettings(lightscatter::Profile::Balanced));
    } catch (const std::runtime_error& e) {
        fuzz::checkRefusal(e.what(), path);
    }
    return 0;
}
