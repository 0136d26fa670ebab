#pragma once
// The host example's scene: what SCENE.json says (camera, light, medium, which glTF files) and the
// triangles of its glTF models, flattened to world space. Nothing here touches Vulkan or the
// plugin.
#include <cstdint>
#include <glm/glm.hpp>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include <lightscatter/lightscatter.h>  // the light types and phase functions, one enum each with the plugin

namespace host {

// Every failure to read a scene: one line naming the file, the field or value, and the rule broken.
class SceneError : public std::runtime_error {
  public:
    using std::runtime_error::runtime_error;
};

struct Texture {
    std::string name;
    uint32_t width = 0, height = 0;
    std::vector<uint8_t> rgba;  // RGBA8, sRGB-encoded color as stored in the file, row 0 on top
};

struct Material {
    glm::vec4 baseColorFactor{1.0f};  // linear
    int baseColorTexture = -1;        // index into MeshData::textures, -1: none
};

struct Vertex {
    glm::vec3 position{0.0f};  // world space
    glm::vec3 normal{0.0f, 1.0f, 0.0f};
    glm::vec2 uv{0.0f};
};

struct Primitive {
    uint32_t firstIndex = 0;  // into MeshData::indices
    uint32_t indexCount = 0;  // a multiple of 3: triangle lists (strips and fans are converted)
    int material = -1;        // index into MeshData::materials, -1: default white
    uint32_t firstVertex = 0, vertexCount = 0;  // into MeshData::vertices
    glm::mat3 axes{1.0f};  // its node's world axes, orthonormalised (for an oriented bounding box)
};

struct Bounds {
    glm::vec3 min{1e30f}, max{-1e30f};
    bool empty() const { return min.x > max.x; }
    void add(const glm::vec3& p) {
        min = glm::min(min, p);
        max = glm::max(max, p);
    }
};

struct MeshData {
    std::vector<Vertex> vertices;
    std::vector<uint32_t> indices;
    std::vector<Primitive> primitives;
    std::vector<Material> materials;
    std::vector<Texture> textures;
    Bounds bounds;
    std::vector<std::string> warnings;  // e.g. a missing texture that fell back to its factor
    std::vector<std::string> files;     // every file read: each glTF and its buffers and images
};

// Appends the default scene of a .gltf or .glb file (node hierarchy and transforms applied, then
// `transform`) to `mesh`. Throws SceneError naming the file and what is wrong.
void appendGltf(MeshData& mesh, const std::string& path,
                const glm::mat4& transform = glm::mat4(1.0f));

// appendGltf of a file's bytes already in memory: `path` names it in messages, and the URIs it
// references resolve against its folder. The fuzzer's way in (tests/fuzz/gltf_fuzzer.cpp).
void appendGltfBytes(MeshData& mesh, const std::string& path, std::vector<unsigned char> bytes,
                     const glm::mat4& transform = glm::mat4(1.0f));

// Decodes an image file's bytes (whatever stb_image reads: PNG, JPEG, ...) to RGBA8 in `texture`,
// at most `maxSide` pixels a side; returns why not, or "".
std::string decodeImageFile(const std::vector<unsigned char>& bytes, int maxSide, Texture& texture);

struct CameraDesc {
    glm::vec3 position{0.0f, 1.7f, 5.0f};
    glm::vec3 target{0.0f, 1.0f, 0.0f};
    glm::vec3 up{0.0f, 1.0f, 0.0f};
    float fovYDegrees = 60.0f;
    float nearPlane = 0.1f;
    float farPlane = 1000.0f;
    bool reversedZ = false;
    bool infiniteFar = false;
};

struct LightDesc {
    lightscatter::LightType type = lightscatter::LightType::Directional;
    glm::vec3 position{0.0f};
    glm::vec3 direction{0.0f, -1.0f, 0.0f};  // unit; the way light travels (directional), spot axis
    glm::vec3 intensity{1.0f};               // W/m^2 (directional) or W/sr
    // A spot's cone (lightscatter::Light's): inner = outer, a hard edge.
    float innerConeAngleDegrees = 30.0f;
    float outerConeAngleDegrees = 30.0f;
    float range = 1e30f;  // point and spot
    lightscatter::RangeFalloff rangeFalloff = lightscatter::RangeFalloff::Cut;
    float radius = 0.05f;
    uint32_t shadowMapSize = 2048;  // 0: no shadow map; point lights: 0 unless given (a
                                    // cube map of six faces this size)
    // "cookie": the light's color image (a spot's or a directional light's, projected with its
    // shadow map's matrix, with a shadow map or without), decoded to RGBA8 as stored (sRGB); null:
    // none. Shared: a light is copied by value, its image is not.
    std::shared_ptr<const Texture> cookie;
};

struct MediumDesc {
    glm::vec3 betaR{5.8e-6f, 13.5e-6f, 33.1e-6f};
    glm::vec3 betaM{2e-5f, 2e-5f, 2e-5f};
    float g = 0.76f;
    glm::vec3 sigmaA{0.0f};
    lightscatter::MiePhase phase = lightscatter::MiePhase::CornetteShanks;
    float maxDistance = 1000.0f;
    // docs/model.md's non-uniform medium ("density", "heightFog", "fogVolumes"): absent, the
    // medium is homogeneous.
    float density = 1.0f;
    std::optional<lightscatter::HeightFog> heightFog;
    std::vector<lightscatter::FogVolume> fogVolumes;
    bool nonUniform() const { return heightFog.has_value() || !fogVolumes.empty(); }
};

struct ModelInstance {
    std::string path;  // absolute, resolved against the scene file's folder
    glm::mat4 transform{1.0f};
};

struct SceneDesc {
    std::string path;                   // the SCENE.json itself
    std::vector<ModelInstance> models;  // "gltf" first (identity), then "models" in order
    CameraDesc camera;
    LightDesc light;                    // "light", or the first of "lights"
    std::vector<LightDesc> moreLights;  // the rest of "lights"
    bool lightList = false;             // the scene gave "lights" (its fields are named lights[i])
    size_t lightCount() const { return 1 + moreLights.size(); }
    LightDesc& lightAt(size_t i) { return i == 0 ? light : moreLights.at(i - 1); }
    const LightDesc& lightAt(size_t i) const { return i == 0 ? light : moreLights.at(i - 1); }
    MediumDesc medium;
    glm::vec3 skyColor{0.0f};  // radiance of the sky behind everything (linear)
    glm::vec3 ambient{0.0f};   // irradiance added to every surface, W/m^2 (linear)
    float exposure = 1.0f;     // display only: multiplies radiance before tone mapping
};

// Reads and checks SCENE.json. Throws SceneError naming the file and the field.
SceneDesc loadSceneFile(const std::string& path);

// All models of a scene, loaded.
MeshData loadSceneMeshes(const SceneDesc& scene);

}  // namespace host
