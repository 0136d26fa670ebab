// libFuzzer target: the scene reader (SCENE.json) on any bytes. An input is read or refused with
// one SceneError line; a crash, a sanitizer report, another exception, a hang (-timeout) or a huge
// allocation (-rss_limit_mb, -malloc_limit_mb) is a finding. The glTF files a scene names are not
// loaded here (gltf_fuzzer does that), except for their KHR_lights_punctual lights with
// "lightsFromGltf".
#include "fuzz_input.h"
#include "scene/scene.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const std::string& path = fuzz::writeInput(data, size, "scene.json");
    try {
        (void)host::loadSceneFile(path);
    } catch (const host::SceneError& e) {
        fuzz::checkRefusal(e.what(), path);
    }
    return 0;
}
