// reference_timing: times the float64 reference renderer on shipped scenes with the default
// options (a measurement, not a test: ctest does not run it). Each line ends with a hash of the
// image's doubles, so that the two traversals can be shown to give the same image bit for bit.
//   build/tools/reference_timing/reference_timing [--size WxH] [--traversal embree|own|both]
//                                                 [--json FILE] [SCENE.json ...]
// Without scenes it times scenes/window_room.json and scenes/atrium.json of the source tree; the
// default size is 96x54 and the default traversal Embree's. --json writes every figure for
// scripts/report/reference.py ("The reference renderer's time" in docs/performance.md).
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <exception>
#include <fstream>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include <nlohmann/json.hpp>

#include "exact_renderer/bvh.h"
#include "exact_renderer/reference_renderer.h"
#include "scene/scene.h"

namespace {

using host::reference::Bvh;

// FNV-1a over the image's bytes: equal hashes mean equal images (up to a 2^-64 chance).
std::string imageHash(const std::vector<double>& values) {
    uint64_t h = 0xcbf29ce484222325ull;
    const auto* p = reinterpret_cast<const unsigned char*>(values.data());
    for (size_t i = 0; i < values.size() * sizeof(double); ++i) h = (h ^ p[i]) * 0x100000001b3ull;
    char text[17];
    std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(h));
    return text;
}

// What the reference traces against: every primitive's whole triangles (as Bvh::fromMesh takes
// them), counted without building a BVH.
std::size_t triangleCount(const host::MeshData& mesh) {
    std::size_t n = 0;
    for (const host::Primitive& p : mesh.primitives) n += p.indexCount / 3;
    return n;
}

const char* name(Bvh::Traversal t) {
    return t == Bvh::Traversal::Embree ? "embree" : "own";
}

}  // namespace

int main(int argc, char** argv) {
    uint32_t width = 96, height = 54;
    std::vector<Bvh::Traversal> traversals{Bvh::Traversal::Embree};
    std::string jsonPath;
    std::vector<std::string> files;
    try {
        for (int i = 1; i < argc; ++i) {
            const std::string arg = argv[i];
            const bool hasValue = i + 1 < argc;
            if (arg == "--size") {
                if (!hasValue || std::sscanf(argv[i + 1], "%ux%u", &width, &height) != 2 ||
                    width == 0 || height == 0)
                    throw std::invalid_argument("--size takes WxH, both above 0");
                ++i;
            } else if (arg == "--traversal") {
                const std::string v = hasValue ? argv[++i] : "";
                if (v == "embree") {
                    traversals = {Bvh::Traversal::Embree};
                } else if (v == "own") {
                    traversals = {Bvh::Traversal::Own};
                } else if (v == "both") {
                    traversals = {Bvh::Traversal::Own, Bvh::Traversal::Embree};
                } else {
                    throw std::invalid_argument("--traversal takes embree, own or both, not '" + v +
                                                "'");
                }
            } else if (arg == "--json") {
                if (!hasValue) throw std::invalid_argument("--json takes a file name");
                jsonPath = argv[++i];
            } else {
                files.push_back(arg);
            }
        }
        if (files.empty())
            for (const char* scene : {"window_room", "atrium"})
                files.push_back(std::string(LS_SOURCE_DIR) + "/scenes/" + scene + ".json");
        nlohmann::json report{
            {"size", std::to_string(width) + "x" + std::to_string(height)},
            {"threads", std::thread::hardware_concurrency()},
            {"embreeBuilt",
             Bvh(std::vector<host::reference::Triangle>{{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}})
                 .usesEmbree()},
            {"scenes", nlohmann::json::array()}};
        std::vector<double> totals(traversals.size(), 0.0);
        for (const std::string& file : files) {
            const host::SceneDesc scene = host::loadSceneFile(file);
            const host::MeshData mesh = host::loadSceneMeshes(scene);
            nlohmann::json row{{"scene", file}, {"triangles", triangleCount(mesh)}};
            for (std::size_t t = 0; t < traversals.size(); ++t) {
                host::reference::ReferenceOptions options;
                options.traversal = traversals[t];
                const auto start = std::chrono::steady_clock::now();
                const host::reference::ReferenceImage image =
                    host::reference::renderReference(scene, mesh, width, height, options);
                const double seconds =
                    std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
                totals[t] += seconds;
                const std::string hash = imageHash(image.rgb);
                std::printf("%s: %ux%u, %s traversal, %.2f s (%zu triangles, image %s)\n",
                            file.c_str(), width, height, name(traversals[t]), seconds,
                            row["triangles"].get<std::size_t>(), hash.c_str());
                std::fflush(stdout);
                row[name(traversals[t])] = {{"seconds", seconds}, {"image", hash}};
            }
            report["scenes"].push_back(row);
        }
        for (std::size_t t = 0; t < traversals.size(); ++t) {
            std::printf("total, %s traversal: %.2f s\n", name(traversals[t]), totals[t]);
            report["total"][name(traversals[t])] = totals[t];
        }
        if (!jsonPath.empty()) {
            std::ofstream out(jsonPath);
            out << report.dump(2) << "\n";
            if (!out) throw std::runtime_error("could not write " + jsonPath);
        }
    } catch (const std::exception& e) {
        std::fprintf(stderr, "reference_timing: %s\n", e.what());
        return 1;
    }
    return 0;
}
