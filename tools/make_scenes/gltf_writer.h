#pragma once
// Writes a MeshBuilder as glTF 2.0: <name>.gltf (JSON), <name>.bin (one buffer) and its textures
// as PNG files, all in one folder. Output is deterministic.
#include <filesystem>
#include <string>

#include "mesh_builder.h"

namespace make_scenes {

// Throws std::runtime_error when a file cannot be written.
void writeGltf(const MeshBuilder& mesh, const std::filesystem::path& folder,
               const std::string& name);

}  // namespace make_scenes
