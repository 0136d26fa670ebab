#include "gltf_writer.h"

#include <cstring>
#include <fstream>
#include <stdexcept>

#include "json_types.h"
#include "png_writer.h"

namespace make_scenes {
namespace {

constexpr int kFloat = 5126, kUnsignedShort = 5123, kUnsignedInt = 5125;
constexpr int kArrayBuffer = 34962, kElementArrayBuffer = 34963;
constexpr int kLinear = 9729, kLinearMipmapLinear = 9987, kRepeat = 10497;

void writeFile(const std::filesystem::path& path, const std::vector<uint8_t>& bytes) {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(bytes.data()),
              static_cast<std::streamsize>(bytes.size()));
    if (!out) throw std::runtime_error("cannot write " + path.string());
}

class BufferBuilder {
  public:
    // Appends `bytes` as a new buffer view (4-byte aligned) and returns its index.
    int view(const void* data, size_t bytes, int target) {
        while (bin_.size() % 4 != 0) bin_.push_back(0);
        const size_t offset = bin_.size();
        bin_.resize(offset + bytes);
        std::memcpy(bin_.data() + offset, data, bytes);
        Json v = {{"buffer", 0}, {"byteOffset", offset}, {"byteLength", bytes}};
        v["target"] = target;
        views_.push_back(std::move(v));
        return static_cast<int>(views_.size()) - 1;
    }
    std::vector<uint8_t>& bin() { return bin_; }
    Json& views() { return views_; }

  private:
    std::vector<uint8_t> bin_;
    Json views_ = Json::array();
};

Json vec(const glm::vec3& v) {
    return Json::array({v.x, v.y, v.z});
}

}  // namespace

void writeGltf(const MeshBuilder& mesh, const std::filesystem::path& folder,
               const std::string& name) {
    BufferBuilder buffer;
    Json accessors = Json::array();
    Json primitives = Json::array();

    for (const PrimitiveData* prim : mesh.primitives()) {
        const size_t count = prim->positions.size();
        glm::vec3 lo(1e30f), hi(-1e30f);
        for (const glm::vec3& p : prim->positions) {
            lo = glm::min(lo, p);
            hi = glm::max(hi, p);
        }
        Json attributes;
        const int posView =
            buffer.view(prim->positions.data(), count * sizeof(glm::vec3), kArrayBuffer);
        accessors.push_back({{"bufferView", posView},
                             {"componentType", kFloat},
                             {"count", count},
                             {"type", "VEC3"},
                             {"min", vec(lo)},
                             {"max", vec(hi)}});
        attributes["POSITION"] = accessors.size() - 1;
        const int nrmView =
            buffer.view(prim->normals.data(), count * sizeof(glm::vec3), kArrayBuffer);
        accessors.push_back({{"bufferView", nrmView},
                             {"componentType", kFloat},
                             {"count", count},
                             {"type", "VEC3"}});
        attributes["NORMAL"] = accessors.size() - 1;
        const int uvView = buffer.view(prim->uvs.data(), count * sizeof(glm::vec2), kArrayBuffer);
        accessors.push_back({{"bufferView", uvView},
                             {"componentType", kFloat},
                             {"count", count},
                             {"type", "VEC2"}});
        attributes["TEXCOORD_0"] = accessors.size() - 1;

        // 16-bit indices where they fit, 32-bit otherwise (the loader must take both).
        int indexView = 0, indexType = kUnsignedInt;
        if (count <= 65535) {
            std::vector<uint16_t> small(prim->indices.begin(), prim->indices.end());
            indexView =
                buffer.view(small.data(), small.size() * sizeof(uint16_t), kElementArrayBuffer);
            indexType = kUnsignedShort;
        } else {
            indexView = buffer.view(prim->indices.data(), prim->indices.size() * sizeof(uint32_t),
                                    kElementArrayBuffer);
        }
        accessors.push_back({{"bufferView", indexView},
                             {"componentType", indexType},
                             {"count", prim->indices.size()},
                             {"type", "SCALAR"}});
        primitives.push_back({{"attributes", attributes},
                              {"indices", accessors.size() - 1},
                              {"material", prim->material},
                              {"mode", 4}});
    }

    Json materials = Json::array();
    for (const MaterialDef& m : mesh.materials()) {
        Json pbr = {{"baseColorFactor", Json::array({m.baseColorFactor.r, m.baseColorFactor.g,
                                                     m.baseColorFactor.b, m.baseColorFactor.a})}};
        if (m.baseColorTexture >= 0) pbr["baseColorTexture"] = {{"index", m.baseColorTexture}};
        pbr["metallicFactor"] = m.metallic;
        pbr["roughnessFactor"] = m.roughness;
        materials.push_back({{"name", m.name}, {"pbrMetallicRoughness", pbr}});
    }

    Json gltf;
    gltf["asset"] = {{"version", "2.0"}, {"generator", "lightscatter make_scenes"}};
    gltf["scene"] = 0;
    gltf["scenes"] = Json::array({{{"name", name}, {"nodes", Json::array({0})}}});
    gltf["nodes"] = Json::array({{{"name", name}, {"mesh", 0}}});
    gltf["meshes"] = Json::array({{{"name", name}, {"primitives", primitives}}});
    gltf["materials"] = materials;
    if (!mesh.textures().empty()) {
        Json images = Json::array(), textures = Json::array();
        for (size_t i = 0; i < mesh.textures().size(); ++i) {
            const TextureImage& t = mesh.textures()[i];
            writeFile(folder / t.fileName, encodePng(t.width, t.height, t.rgba));
            images.push_back({{"uri", t.fileName}, {"mimeType", "image/png"}});
            textures.push_back({{"sampler", 0}, {"source", i}});
        }
        gltf["images"] = images;
        gltf["samplers"] = Json::array({{{"magFilter", kLinear},
                                         {"minFilter", kLinearMipmapLinear},
                                         {"wrapS", kRepeat},
                                         {"wrapT", kRepeat}}});
        gltf["textures"] = textures;
    }
    gltf["accessors"] = accessors;
    gltf["bufferViews"] = buffer.views();
    gltf["buffers"] = Json::array({{{"uri", name + ".bin"}, {"byteLength", buffer.bin().size()}}});

    writeFile(folder / (name + ".bin"), buffer.bin());
    const std::string text = gltf.dump(1) + "\n";
    writeFile(folder / (name + ".gltf"), std::vector<uint8_t>(text.begin(), text.end()));
}

}  // namespace make_scenes
