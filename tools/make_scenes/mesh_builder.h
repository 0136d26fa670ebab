#pragma once
// Procedural geometry for the shipped scenes: boxes, N-gon cylinders, extruded "curtain" profiles
// (arch spandrels), grouped by material into glTF primitives. Everything is in metres, world space,
// right-handed with +Y up; triangles are counter-clockwise seen from outside (glTF's front face).
#include <cstdint>
#include <functional>
#include <glm/glm.hpp>
#include <string>
#include <vector>

namespace make_scenes {

struct TextureImage {
    std::string fileName;  // written next to the .gltf
    uint32_t width = 0, height = 0;
    std::vector<uint8_t> rgba;  // RGBA8, sRGB-encoded, row 0 on top
};

struct MaterialDef {
    std::string name;
    glm::vec4 baseColorFactor{1.0f};  // linear
    int baseColorTexture = -1;        // index into MeshBuilder::textures()
    float roughness = 0.9f;
    float metallic = 0.0f;
};

// One primitive: the triangles of one material.
struct PrimitiveData {
    int material = 0;
    std::vector<glm::vec3> positions, normals;
    std::vector<glm::vec2> uvs;
    std::vector<uint32_t> indices;
};

class MeshBuilder {
  public:
    int addTexture(TextureImage image);
    // Adds a material; `uvPerMetre` scales the planar texture coordinates of everything drawn with
    // it.
    int addMaterial(MaterialDef material, float uvPerMetre = 1.0f);
    void use(int material);  // the material the following shapes are drawn with
    int current() const { return current_; }
    // A rigid placement applied to the following shapes (default: identity).
    void place(const glm::mat4& transform);

    // A box with half extents `half` around `center`, its axes rotated by `rotation`.
    void box(const glm::vec3& center, const glm::vec3& half,
             const glm::mat3& rotation = glm::mat3(1.0f));
    // An axis-aligned box from its two corners.
    void boxMinMax(const glm::vec3& lo, const glm::vec3& hi);
    // A vertical cylinder approximated by a `sides`-gon: smooth side normals, flat caps.
    void cylinder(const glm::vec3& baseCenter, float radius, float height, int sides);
    // A vertical cone approximated by a `sides`-gon: smooth side normals, a flat base.
    void cone(const glm::vec3& baseCenter, float radius, float height, int sides);
    // A terrain: a grid of `nx` x `nz` cells over [lo.x, hi.x] x [lo.y, hi.y] in (x, z), its
    // vertices at y = height(x, z), smooth normals from central differences, facing up. A single
    // surface: no skirt and no underside.
    void heightfield(const glm::vec2& lo, const glm::vec2& hi, int nx, int nz,
                     const std::function<float(float, float)>& height);
    // A solid between a lower curve y = bottom[i] and an upper curve y = top[i] at x = xs[i]
    // (xs increasing, bottom <= top), extruded along z over [z0, z1]. Flat-shaded.
    void curtain(const std::vector<float>& xs, const std::vector<float>& bottom,
                 const std::vector<float>& top, float z0, float z1);
    // A single quad (p0..p3 in order around it), turned to face along `normal`.
    void quad(const glm::vec3& p0, const glm::vec3& p1, const glm::vec3& p2, const glm::vec3& p3,
              const glm::vec3& normal);

    const std::vector<TextureImage>& textures() const { return textures_; }
    const std::vector<MaterialDef>& materials() const { return materials_; }
    // Non-empty primitives, in material order.
    std::vector<const PrimitiveData*> primitives() const;
    size_t triangleCount() const;

  private:
    uint32_t vertex(const glm::vec3& p, const glm::vec3& n, const glm::vec2& uv);
    glm::vec2 planarUv(const glm::vec3& p, const glm::vec3& n) const;
    void triangle(uint32_t a, uint32_t b, uint32_t c, const glm::vec3& facing);

    std::vector<TextureImage> textures_;
    std::vector<MaterialDef> materials_;
    std::vector<float> uvScale_;
    std::vector<PrimitiveData> prims_;  // one per material
    int current_ = -1;
    glm::mat4 transform_{1.0f};
    glm::mat3 normalMatrix_{1.0f};
};

}  // namespace make_scenes
