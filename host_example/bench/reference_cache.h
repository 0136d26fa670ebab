#pragma once
// The float64 reference images a benchmark judges against, cached on disk: one takes minutes on a
// CPU, and a rerun of the benchmark (or of the report) should not pay for it again.
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include <vulkan/vulkan.h>

#include "scene/scene.h"

namespace host::bench {

// `s` with every character but letters, digits, '-' and '.' replaced by '_'.
[[nodiscard]] std::string fileSafe(std::string s);

// A hash, in hex, of everything the reference image depends on: the scene file's text, the
// camera, lights and medium as they are now (a motion moves them), the triangles, the size, and
// the reference renderer's own sources (hashed at build time). A change to any of them misses the
// cache instead of judging against a stale image.
[[nodiscard]] std::string referenceKey(const SceneDesc& scene, const MeshData& mesh,
                                       VkExtent2D size);

// The reference for the scene as it is now, read from `folder` or rendered and written there
// (RGB, 3 per pixel), with the seconds it took in a JSON file beside it. Values are rounded to
// float either way (the cache is a float EXR), so a rerun from the cache reproduces a first run's
// figures exactly.
[[nodiscard]] std::vector<double> loadOrRenderReference(
    const SceneDesc& scene, const MeshData& mesh, VkExtent2D size,
    const std::filesystem::path& folder, const std::function<void(double)>& progress);

}  // namespace host::bench
