// libFuzzer target: the glTF loader on any bytes, as a .gltf or (with the magic) a .glb. Debian's
// tinygltf parses them (it is not instrumented: coverage and sanitizers see the project's code),
// then the loader's own checks and flattening run over what it parsed. URIs resolve against a
// folder that links the shipped scenes' files, so the seeds' buffers and images load. An input is
// loaded or refused with one SceneError line, and every warning is one line; any other outcome is a
// finding (see scene_fuzzer.cpp). The same bytes then go through the KHR_lights_punctual reader of
// "lightsFromGltf" (a file of its own: it reads the glTF's JSON by path).
#include "fuzz_input.h"
#include "scene/gltf_lights.h"
#include "scene/scene.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    // The path only names the input and gives the folder for its URIs: the bytes go in directly.
    static const std::string path = fuzz::inputFolder() + "/input.gltf";
    host::MeshData mesh;
    try {
        host::appendGltfBytes(mesh, path, std::vector<unsigned char>(data, data + size));
    } catch (const host::SceneError& e) {
        fuzz::checkRefusal(e.what(), path);
    }
    for (const std::string& warning : mesh.warnings) fuzz::checkRefusal(warning, path);
    const std::string& lights = fuzz::writeInput(data, size, "lights.gltf");
    try {
        (void)host::readGltfLights(lights, 1.0);
    } catch (const host::SceneError& e) {
        fuzz::checkRefusal(e.what(), lights);
    }
    return 0;
}
