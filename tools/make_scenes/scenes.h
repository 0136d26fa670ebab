#pragma once
// The shipped scenes. Each writer puts <name>.gltf, <name>.bin (and any texture) and the scene file
// <name>.json into `folder` and returns what it wrote.
#include <filesystem>
#include <string>

namespace make_scenes {

struct SceneSummary {
    std::string name;
    size_t triangles = 0;  // of the generated glTF (referenced models not counted)
    std::string note;      // one line for the log
};

SceneSummary writeAtrium(const std::filesystem::path& folder);
SceneSummary writeWindowRoom(const std::filesystem::path& folder);
// `engineGlb`: the Khronos 2CylinderEngine sample (Debian package assimp-testmodels).
SceneSummary writeEngineSpot(const std::filesystem::path& folder, const std::string& engineGlb);
SceneSummary writePointFog(const std::filesystem::path& folder);
SceneSummary writeValleyFog(const std::filesystem::path& folder);

}  // namespace make_scenes
