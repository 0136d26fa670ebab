#pragma once
// Reads the vertex positions of a glTF/GLB file's default scene (node transforms applied) with
// tinygltf, so that a scene can size and place a model it references.
#include <glm/glm.hpp>
#include <string>
#include <vector>

namespace make_scenes {

struct ModelPoints {
    std::vector<glm::vec3> points;  // every POSITION of every triangle primitive, in model space
    size_t triangles = 0;
};

// Throws std::runtime_error naming the file when it cannot be read.
ModelPoints loadModelPoints(const std::string& path);

}  // namespace make_scenes
