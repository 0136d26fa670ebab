// make_scenes OUT_DIR [--engine-glb PATH]
// Writes the shipped scenes (glTF 2.0 + SCENE.json each) into OUT_DIR. Deterministic.
#include <cstdio>
#include <exception>
#include <filesystem>
#include <string>

#include "scenes.h"

namespace {

constexpr const char* kDefaultEngine =
    "/usr/share/assimp/models/glTF2/2CylinderEngine-glTF-Binary/2CylinderEngine.glb";

int usage() {
    std::fprintf(stderr,
                 "usage: make_scenes OUT_DIR [--engine-glb PATH]\n"
                 "  writes atrium, window_room, engine_spot, point_fog and valley_fog "
                 "(<name>.json, .gltf, .bin)\n"
                 "  engine_spot references PATH (default %s, Debian package assimp-testmodels)\n",
                 kDefaultEngine);
    return 2;
}

void report(const make_scenes::SceneSummary& s) {
    std::printf("%-12s %7zu triangles  %s\n", s.name.c_str(), s.triangles, s.note.c_str());
}

}  // namespace

int main(int argc, char** argv) {
    std::string outDir, engine = kDefaultEngine;
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        if (arg == "--engine-glb" && i + 1 < argc) {
            engine = argv[++i];
        } else if (arg == "-h" || arg == "--help") {
            usage();
            return 0;
        } else if (!arg.empty() && arg[0] != '-' && outDir.empty()) {
            outDir = arg;
        } else {
            return usage();
        }
    }
    if (outDir.empty()) return usage();

    int status = 0;
    try {
        std::filesystem::create_directories(outDir);
        report(make_scenes::writeAtrium(outDir));
        report(make_scenes::writeWindowRoom(outDir));
        report(make_scenes::writePointFog(outDir));
        report(make_scenes::writeValleyFog(outDir));
    } catch (const std::exception& e) {
        std::fprintf(stderr, "make_scenes: %s\n", e.what());
        return 1;
    }
    try {
        report(make_scenes::writeEngineSpot(outDir, engine));
    } catch (const std::exception& e) {
        std::fprintf(
            stderr,
            "make_scenes: engine_spot not written: %s (it needs the 2CylinderEngine sample "
            "of Debian's assimp-testmodels package, or --engine-glb PATH)\n",
            e.what());
        status = 1;
    }
    return status;
}
