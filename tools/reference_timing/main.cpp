// reference_timing: times the float64 reference renderer on shipped scenes at 96x54 with the
// default options (a measurement, not a test: ctest does not run it).
//   build/tools/reference_timing/reference_timing [SCENE.json ...]
// Without arguments it times scenes/window_room.json and scenes/atrium.json of the source tree.
#include <chrono>
#include <cstdio>
#include <exception>
#include <string>
#include <vector>

#include "exact_renderer/bvh.h"
#include "exact_renderer/reference_renderer.h"
#include "scene/scene.h"

int main(int argc, char** argv) {
    std::vector<std::string> files(argv + 1, argv + argc);
    if (files.empty())
        for (const char* name : {"window_room", "atrium"})
            files.push_back(std::string(LS_SOURCE_DIR) + "/scenes/" + name + ".json");
    try {
        for (const std::string& file : files) {
            const host::SceneDesc scene = host::loadSceneFile(file);
            const host::MeshData mesh = host::loadSceneMeshes(scene);
            const auto start = std::chrono::steady_clock::now();
            const host::reference::ReferenceImage image =
                host::reference::renderReference(scene, mesh, 96, 54);
            const double seconds =
                std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
            double sum = 0.0;
            for (double v : image.rgb) sum += v;
            std::printf("%s: 96x54 in %.2f s (%zu triangles, mean Lin %.6g)\n", file.c_str(),
                        seconds, host::reference::Bvh::fromMesh(mesh).triangles().size(),
                        sum / static_cast<double>(image.rgb.size()));
        }
    } catch (const std::exception& e) {
        std::fprintf(stderr, "reference_timing: %s\n", e.what());
        return 1;
    }
    return 0;
}
