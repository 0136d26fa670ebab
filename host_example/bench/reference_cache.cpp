#include "reference_cache.h"

#include <cctype>
#include <chrono>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <thread>

#include "exact_renderer/reference_renderer.h"
#include "image_io.h"
#include "reference_code_hash.h"
#include "scene/input_file.h"

namespace host::bench {
namespace {

namespace fs = std::filesystem;

// FNV-1a, 64 bits: stable across compilers and runs, unlike std::hash, which a cache on disk
// outlives.
class Fnv {
  public:
    void bytes(const void* data, size_t n) {
        const auto* p = static_cast<const unsigned char*>(data);
        for (size_t i = 0; i < n; ++i) h_ = (h_ ^ p[i]) * 0x100000001b3ull;
    }
    template <typename... T>
    void values(const T&... v) {
        (bytes(&v, sizeof v), ...);
    }
    void text(const std::string& s) {
        values(s.size());
        bytes(s.data(), s.size());
    }
    [[nodiscard]] std::string hex() const {
        char buf[17];
        std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(h_));
        return buf;
    }

  private:
    uint64_t h_ = 0xcbf29ce484222325ull;
};

void light(Fnv& f, const LightDesc& l) {
    // Not the shadow map's size: the reference traces exact visibility.
    f.values(l.type, l.position, l.direction, l.intensity, l.innerConeAngleDegrees,
             l.outerConeAngleDegrees, l.range, l.rangeFalloff, l.radius);
    // The cookie's pixels, not its path: the reference colours the light with them.
    if (l.cookie) {
        f.values(l.cookie->width, l.cookie->height);
        f.bytes(l.cookie->rgba.data(), l.cookie->rgba.size());
    }
}

}  // namespace

std::string fileSafe(std::string s) {
    for (char& c : s)
        if (!std::isalnum(static_cast<unsigned char>(c)) && c != '-' && c != '.') c = '_';
    return s;
}

std::string referenceKey(const SceneDesc& scene, const MeshData& mesh, VkExtent2D size) {
    Fnv f;
    f.text(LS_REFERENCE_CODE_HASH);
    f.text(readInputFile(scene.path, "scene file", 16 * kMiB));
    f.values(size.width, size.height);
    const CameraDesc& c = scene.camera;
    f.values(c.position, c.target, c.up, c.fovYDegrees, c.nearPlane, c.farPlane, c.reversedZ,
             c.infiniteFar);
    for (size_t i = 0; i < scene.lightCount(); ++i) light(f, scene.lightAt(i));
    const MediumDesc& m = scene.medium;
    f.values(m.betaR, m.betaM, m.g, m.sigmaA, m.phase, m.maxDistance);
    // The non-uniform medium (a motion may move a volume, in memory, not in the file).
    f.values(m.density, m.heightFog.has_value(), m.fogVolumes.size());
    if (m.heightFog) f.values(m.heightFog->baseHeight, m.heightFog->falloff);
    for (const lightscatter::FogVolume& v : m.fogVolumes)
        f.values(v.center, v.halfExtents, v.axes, v.density, v.fade);
    for (const Vertex& v : mesh.vertices) f.values(v.position);
    f.bytes(mesh.indices.data(), mesh.indices.size() * sizeof(uint32_t));
    return f.hex();
}

std::vector<double> loadOrRenderReference(const SceneDesc& scene, const MeshData& mesh,
                                          VkExtent2D size, const fs::path& folder,
                                          const std::function<void(double)>& progress) {
    const fs::path cache =
        folder /
        (fileSafe(fs::path(scene.path).stem().string()) + "_" + std::to_string(size.width) + "x" +
         std::to_string(size.height) + "_" + referenceKey(scene, mesh, size) + ".exr");
    std::vector<double> rgb(size_t{size.width} * size.height * 3);
    if (fs::exists(cache)) {
        const FloatImage img = readExr(cache.string());
        if (img.width == size.width && img.height == size.height) {
            for (size_t p = 0; p < rgb.size() / 3; ++p)
                for (size_t c = 0; c < 3; ++c) rgb[p * 3 + c] = img.rgba[p * 4 + c];
            return rgb;
        }
    }
    const auto start = std::chrono::steady_clock::now();
    const reference::ReferenceImage ref =
        reference::renderReference(scene, mesh, size.width, size.height, {}, progress);
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::vector<float> rgba(size_t{size.width} * size.height * 4, 1.0f);
    for (size_t p = 0; p < rgb.size() / 3; ++p)
        for (size_t c = 0; c < 3; ++c) {
            rgba[p * 4 + c] = static_cast<float>(ref.rgb[p * 3 + c]);
            rgb[p * 3 + c] = rgba[p * 4 + c];
        }
    writeExr(cache.string(), size.width, size.height, rgba);
    // What it cost, beside it: the report says why its references are as small as they are.
    writeTextFile(fs::path(cache).replace_extension(".json").string(),
                  nlohmann::json{{"scene", fs::path(scene.path).stem().string()},
                                 {"size", {size.width, size.height}},
                                 {"seconds", seconds},
                                 {"threads", std::thread::hardware_concurrency()}}
                          .dump() +
                      "\n");
    return rgb;
}

}  // namespace host::bench
