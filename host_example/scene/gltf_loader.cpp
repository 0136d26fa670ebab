// glTF 2.0 loading with Debian's tinygltf shared library (no TINYGLTF_IMPLEMENTATION here: the
// implementation lives in libtinygltf.so). tinygltf parses the JSON and the buffers, and hands each
// image's bytes to this loader, which decodes them with Debian's stb_image; everything tinygltf
// does not check (buffer view and accessor bounds, indices, node references, the node tree) is
// checked here before a byte is read or anything is allocated for it, so a malformed file ends in
// a SceneError.
#include <stb/stb_image.h>
#include <tiny_gltf.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <iterator>
#include <limits>
#include <map>
#include <memory>
#include <optional>

#include "scene/glb_bytes.h"
#include "scene/gltf_json.h"
#include "scene/input_file.h"
#include "scene/json_input.h"
#include "scene/scene.h"

namespace host {
namespace {

// The node's axes made orthonormal (Gram-Schmidt from the first column; a degenerate column falls
// back to the world axis), right-handed.
glm::mat3 orthonormalAxes(const glm::mat3& m) {
    auto unit = [](glm::vec3 v, glm::vec3 fallback) {
        const float l = glm::length(v);
        return l > 1e-12f && std::isfinite(l) ? v / l : fallback;
    };
    const glm::vec3 x = unit(m[0], {1, 0, 0});
    glm::vec3 y = unit(m[1] - glm::dot(m[1], x) * x, {0, 0, 0});
    if (glm::length(y) < 0.5f)
        y = unit(glm::cross(x, std::fabs(x.y) < 0.9f ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 0)),
                 {0, 1, 0});
    return glm::mat3(x, y, glm::cross(x, y));
}

// Every count is checked against the bytes that hold it before anything is allocated for it, so
// that the memory a file costs follows the data it holds. Beyond this an accessor is refused even
// when its data is there.
constexpr size_t kMaxElements = size_t{1} << 28;
// An accessor without a buffer view is zeros (sparse substitutes aside): data the file does not
// hold, so its count alone would decide the allocation (2^28 VEC3s: 3 GiB from 300 bytes).
constexpr size_t kMaxZeroFilledElements = size_t{1} << 20;
// What a file's nodes place in all, with what the mesh held before: 1 GiB of vertices, 512 MiB of
// indices (the largest model of the shipped scenes, 2CylinderEngine, has 84,657 vertices).
constexpr size_t kMaxPlacedVertices = size_t{1} << 25;
constexpr size_t kMaxPlacedIndices = size_t{1} << 27;
// Vulkan's maxImageDimension2D on lavapipe and on most GPUs: a larger image could not be uploaded,
// and is refused before it is decoded.
constexpr int kMaxTextureSide = 16384;
// tinygltf's report holds a line per failure and names from the file; a message keeps this much.
constexpr size_t kMaxReportChars = 1024;

[[noreturn]] void fail(const std::string& path, const std::string& what) {
    throw SceneError(path + ": " + what);
}

// tinygltf's messages end in newlines and may hold several; a SceneError is one line.
std::string joinLines(const std::string& text) {
    std::string out;
    size_t start = 0;
    while (start <= text.size()) {
        size_t end = text.find('\n', start);
        if (end == std::string::npos) end = text.size();
        std::string line = text.substr(start, end - start);
        while (!line.empty() && (line.back() == ' ' || line.back() == '\r')) line.pop_back();
        if (!line.empty()) out += (out.empty() ? "" : "; ") + line;
        start = end + 1;
    }
    return out;
}
std::string oneLine(const std::string& text) {
    return echoText(joinLines(text), kMaxReportChars);
}

std::string plural(size_t n, const std::string& noun, const std::string& nouns = "") {
    return std::to_string(n) + " " + (n == 1 ? noun : nouns.empty() ? noun + "s" : nouns);
}

std::vector<unsigned char> readFile(const std::string& path) {
    try {
        return readInputBytes(path, "glTF file", glb::kFileCap);
    } catch (const InputFileError& e) {
        throw SceneError(e.what());
    }
}

bool isGlb(const std::vector<unsigned char>& bytes) {
    return bytes.size() >= 4 && glb::readU32(bytes, 0) == glb::kMagic;
}

// tinygltf 2.7 compares the BIN chunk's length with the file without counting the chunk's 8-byte
// header, so a crafted length makes it read past the end: the layout is checked here first.
void checkGlbLayout(const std::string& path, const std::vector<unsigned char>& bytes) {
    if (bytes.size() < 20) fail(path, "truncated GLB header");
    const uint32_t version = glb::readU32(bytes, 4);
    if (version != 2) fail(path, "GLB version " + std::to_string(version) + " is not 2");
    const uint64_t length = glb::readU32(bytes, 8);
    if (length > bytes.size()) {
        fail(path, "GLB header says " + std::to_string(length) + " bytes but the file has " +
                       std::to_string(bytes.size()));
    }
    const uint64_t jsonEnd = 20ull + glb::readU32(bytes, 12);
    if (glb::readU32(bytes, 16) != glb::kJsonChunk) fail(path, "the first GLB chunk is not JSON");
    if (jsonEnd > length) fail(path, "the GLB JSON chunk runs past the end of the file");
    if (jsonEnd == length) return;
    if (jsonEnd + 8 > length) fail(path, "truncated GLB BIN chunk header");
    const uint64_t binEnd = jsonEnd + 8 + glb::readU32(bytes, jsonEnd);
    if (glb::readU32(bytes, jsonEnd + 4) != glb::kBinChunk)
        fail(path, "the second GLB chunk is not BIN");
    if (binEnd > length) fail(path, "the GLB BIN chunk runs past the end of the file");
}

// Images tinygltf could not decode are recorded here instead of failing the whole file: a
// material whose texture is unreadable still renders with its base color factor. The files it
// reads for buffers and images go through readInputFile, so they obey the same rules as the glTF.
struct ImageLoadContext {
    const tinygltf::Model* model = nullptr;
    std::map<int, Texture> decoded;       // image index -> its pixels (held here, not in the model)
    std::map<int, std::string> failures;  // image index -> why it has no pixels
    std::vector<std::string> files;       // every external file read
    std::string readFailure;              // the first external file that could not be read
    std::string baseDir;                  // the glTF's folder, which tinygltf joins URIs to
};

// Whatever exists is reported as existing, so that the read below says why it cannot be used
// (a directory, a device) instead of tinygltf's "file not found".
bool anythingExists(const std::string& path, void*) {
    std::error_code ec;
    return std::filesystem::exists(path, ec);
}

// tinygltf's default expands "~" and shell variables (wordexp); a URI is a path, nothing more.
// tinygltf joins even an absolute path to the glTF's folder and to "." ("DIR//abs/b.bin"), where
// it is found by no name: such a path is taken as written, as a URI's absolute path resolves.
std::string pathAsWritten(const std::string& path, void* user) {
    const auto& context = *static_cast<const ImageLoadContext*>(user);
    for (const std::string& base : {context.baseDir, std::string(".")}) {
        if (base.empty()) continue;  // joined to nothing: the path is as written
        const std::string joined = base.back() == '/' ? base : base + "/";
        if (path.size() > joined.size() && path.compare(0, joined.size(), joined) == 0 &&
            path[joined.size()] == '/')
            return path.substr(joined.size());
    }
    return path;
}

bool readReferencedFile(std::vector<unsigned char>* out, std::string* err, const std::string& path,
                        void* user) {
    auto& context = *static_cast<ImageLoadContext*>(user);
    try {
        *out = readInputBytes(path, "file referenced by the glTF", glb::kFileCap);
        context.files.push_back(path);
        return true;
    } catch (const InputFileError& e) {
        if (context.readFailure.empty()) context.readFailure = e.what();
        if (err) *err = e.what();
        return false;
    }
}

bool refuseToWrite(std::string*, const std::string&, const std::vector<unsigned char>&, void*) {
    return false;
}

// Extensions whose data this loader reads. Any other listed in extensionsRequired changes what
// the file means in a way it would get wrong, so the file is refused.
bool implemented(const std::string& extension) {
    return extension == "KHR_mesh_quantization";
}

// Extensions on a primitive that replace its geometry: without them its accessors may be empty
// (Draco) or hold something else, so they are refused even when not listed as required.
bool replacesGeometry(const std::string& extension) {
    return extension == "KHR_draco_mesh_compression";
}

std::string extensionLabel(const std::string& extension) {
    return extension == "KHR_draco_mesh_compression" ? extension + " (Draco mesh compression)"
                                                     : extension;
}

// Checked on the JSON itself before tinygltf parses it: tinygltf fails on a Draco file's
// accessors with "accessor[0] invalid bufferView", and reads glTF 1.0 as a broken 2.0 file.
// The nesting cap applies here too, before tinygltf walks the document recursively (its "extras"
// become nested tinygltf::Values, one call per level).
void checkDocument(const std::string& path, const unsigned char* text, size_t size) {
    const auto* begin = reinterpret_cast<const char*>(text);
    std::shared_ptr<const nlohmann::json> parsed;
    try {
        // The document the lights' reader parsed, when it read this text (gltf_json.h).
        parsed = gltfJson(path, begin, begin + size,
                          {.refuseDuplicateKeys = false, .malformedIsDiscarded = true}, false);
    } catch (const JsonInputError& e) {
        throw SceneError(e.what());
    }
    const nlohmann::json& doc = *parsed;
    if (doc.is_discarded() || !doc.is_object()) return;  // tinygltf names the JSON error
    if (auto asset = doc.find("asset"); asset != doc.end() && asset->is_object()) {
        if (auto version = asset->find("version"); version != asset->end()) {
            const std::string v =
                version->is_string() ? version->get<std::string>() : echo(*version);
            if (v.rfind("2.", 0) != 0 && v != "2") {
                fail(path, "glTF version " + echoText(v) + ": this loader reads glTF 2.0 only");
            }
        }
    }
    if (auto required = doc.find("extensionsRequired");
        required != doc.end() && required->is_array()) {
        for (const auto& name : *required) {
            if (name.is_string() && !implemented(name.get<std::string>())) {
                fail(path, "requires glTF extension " +
                               extensionLabel(echoText(name.get<std::string>())) +
                               ", which this loader does not implement");
            }
        }
    }
    auto meshes = doc.find("meshes");
    if (meshes == doc.end() || !meshes->is_array()) return;
    for (size_t m = 0; m < meshes->size(); ++m) {
        const auto& mesh = (*meshes)[m];
        auto primitives = mesh.is_object() ? mesh.find("primitives") : mesh.end();
        if (!mesh.is_object() || primitives == mesh.end() || !primitives->is_array()) continue;
        for (size_t p = 0; p < primitives->size(); ++p) {
            const auto& primitive = (*primitives)[p];
            auto extensions =
                primitive.is_object() ? primitive.find("extensions") : primitive.end();
            if (!primitive.is_object() || extensions == primitive.end() ||
                !extensions->is_object()) {
                continue;
            }
            for (const auto& item : extensions->items()) {
                if (replacesGeometry(item.key())) {
                    fail(path, "mesh " + std::to_string(m) + " primitive " + std::to_string(p) +
                                   " uses glTF extension " + extensionLabel(echoText(item.key())) +
                                   ", which this loader does not implement");
                }
            }
        }
    }
}

bool bufferViewInBounds(const tinygltf::Model& model, int view) {
    if (view < 0 || size_t(view) >= model.bufferViews.size()) return false;
    const tinygltf::BufferView& v = model.bufferViews[size_t(view)];
    if (v.buffer < 0 || size_t(v.buffer) >= model.buffers.size()) return false;
    const size_t size = model.buffers[size_t(v.buffer)].data.size();
    return v.byteLength <= size && v.byteOffset <= size - v.byteLength &&
           v.byteLength <= size_t(std::numeric_limits<int>::max());
}

struct StbFree {
    void operator()(void* pixels) const { stbi_image_free(pixels); }
};

// stb_image's reason for its last failure. It can quote bytes of the file (an unknown PNG chunk's
// four-letter type, newline and all), so it is echoed like any text from a file.
std::string stbReason() {
    const char* why = stbi_failure_reason();
    return echoText(why ? why : "no reason given");
}

// A PNG's size from its IHDR chunk. stb_image's info refuses a PNG of more than 2^30 bytes of
// pixels ("too large") and then reports the last format it tried, "unknown image type"; the size
// read here says what is wrong with it.
bool pngSize(const unsigned char* bytes, int size, int& width, int& height) {
    static const unsigned char kSignature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
    if (size < 24 || std::memcmp(bytes, kSignature, 8) != 0 || std::memcmp(bytes + 12, "IHDR", 4))
        return false;
    auto u32 = [&](int at) {
        return uint32_t(bytes[at]) << 24 | uint32_t(bytes[at + 1]) << 16 |
               uint32_t(bytes[at + 2]) << 8 | uint32_t(bytes[at + 3]);
    };
    const uint32_t w = u32(16), h = u32(20);
    if (w > uint32_t(std::numeric_limits<int>::max()) ||
        h > uint32_t(std::numeric_limits<int>::max()))
        return false;
    width = int(w);
    height = int(h);
    return true;
}

// The image's size as its header gives it, by stb_image or, for a PNG it refuses, by pngSize.
bool imageSize(const unsigned char* bytes, int size, int& width, int& height) {
    int channels = 0;
    return (size > 0 && stbi_info_from_memory(bytes, size, &width, &height, &channels)) ||
           pngSize(bytes, size, width, height);
}

// Decodes an image file's bytes to RGBA8 in `texture`, or says why not. The pixels are held once,
// plus stb_image's own buffer while they are copied out of it (tinygltf's LoadImageData held them
// twice, and the RGBA8 conversion made a third copy next to the model's).
std::string decodeImage(const unsigned char* bytes, int size, int wantWidth, int wantHeight,
                        Texture& texture) {
    int width = 0, height = 0, channels = 0;
    if (size <= 0 || !stbi_info_from_memory(bytes, size, &width, &height, &channels)) {
        const std::string why = stbReason();
        if (!pngSize(bytes, size, width, height) ||
            (width <= kMaxTextureSide && height <= kMaxTextureSide))
            return "not an image stb_image reads: " + why;
    }
    if (width < 1 || height < 1 || width > kMaxTextureSide || height > kMaxTextureSide) {
        return std::to_string(width) + "x" + std::to_string(height) +
               " pixels: a texture has 1 to " + std::to_string(kMaxTextureSide) + " a side";
    }
    if ((wantWidth > 0 && wantWidth != width) || (wantHeight > 0 && wantHeight != height)) {
        return "the image is " + std::to_string(width) + "x" + std::to_string(height) +
               ", the glTF says " + std::to_string(wantWidth) + "x" + std::to_string(wantHeight);
    }
    const size_t values = size_t(width) * size_t(height) * 4;
    int w = 0, h = 0;
    if (stbi_is_16_bit_from_memory(bytes, size)) {
        const std::unique_ptr<stbi_us, StbFree> wide(
            stbi_load_16_from_memory(bytes, size, &w, &h, &channels, 4));
        if (!wide || w != width || h != height) return "stb_image cannot decode it: " + stbReason();
        texture.rgba.resize(values);
        for (size_t i = 0; i < values; ++i)  // rounded, 65535 -> 255
            texture.rgba[i] = uint8_t((uint32_t{wide.get()[i]} * 255u + 32767u) / 65535u);
    } else {
        const std::unique_ptr<stbi_uc, StbFree> pixels(
            stbi_load_from_memory(bytes, size, &w, &h, &channels, 4));
        if (!pixels || w != width || h != height)
            return "stb_image cannot decode it: " + stbReason();
        texture.rgba.assign(pixels.get(), pixels.get() + values);
    }
    texture.width = uint32_t(width);
    texture.height = uint32_t(height);
    return "";
}

bool loadImageLeniently(tinygltf::Image* image, int index, std::string* /*err*/,
                        std::string* /*warn*/, int width, int height, const unsigned char* bytes,
                        int size, void* user) {
    auto& context = *static_cast<ImageLoadContext*>(user);
    // tinygltf hands over bufferView images without checking the view against its buffer.
    if (image->bufferView >= 0 && !bufferViewInBounds(*context.model, image->bufferView)) {
        context.failures[index] =
            "buffer view " + std::to_string(image->bufferView) + " lies outside its buffer";
        return true;
    }
    Texture texture;
    const std::string why = decodeImage(bytes, size, width, height, texture);
    if (why.empty())
        context.decoded[index] = std::move(texture);
    else
        context.failures[index] = why;
    return true;
}

glm::mat4 nodeTransform(const std::string& path, const tinygltf::Node& node, size_t index) {
    const std::string where = "node " + std::to_string(index);
    auto finite = [&](const std::vector<double>& values, size_t want, const char* field) {
        if (!values.empty() && values.size() != want) {
            fail(path, where + " " + field + " must have " + std::to_string(want) + " numbers");
        }
        for (double v : values) {
            if (!std::isfinite(v)) fail(path, where + " " + field + " is not finite");
        }
        return !values.empty();
    };
    if (finite(node.matrix, 16, "matrix")) {
        glm::dmat4 m;
        std::copy(node.matrix.begin(), node.matrix.end(), glm::value_ptr(m));  // column-major
        return glm::mat4(m);
    }
    glm::mat4 result(1.0f);
    if (finite(node.translation, 3, "translation")) {
        result = glm::translate(result, glm::vec3(glm::make_vec3(node.translation.data())));
    }
    if (finite(node.rotation, 4, "rotation")) {
        const auto& r = node.rotation;
        glm::dquat q(r[3], r[0], r[1], r[2]);  // glTF stores x, y, z, w
        // Exporters write rotations rounded to a few digits; unnormalized they would scale too.
        if (glm::length(q) > 0.0) result *= glm::mat4_cast(glm::quat(glm::normalize(q)));
    }
    if (finite(node.scale, 3, "scale")) {
        result = glm::scale(result, glm::vec3(glm::make_vec3(node.scale.data())));
    }
    return result;
}

float readComponent(const unsigned char* p, int type, bool normalized) {
    switch (type) {
        case TINYGLTF_COMPONENT_TYPE_BYTE: {
            int8_t v;
            std::memcpy(&v, p, 1);
            return normalized ? std::max(float(v) / 127.0f, -1.0f) : float(v);
        }
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
            return normalized ? float(p[0]) / 255.0f : float(p[0]);
        case TINYGLTF_COMPONENT_TYPE_SHORT: {
            int16_t v;
            std::memcpy(&v, p, 2);
            return normalized ? std::max(float(v) / 32767.0f, -1.0f) : float(v);
        }
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
            uint16_t v;
            std::memcpy(&v, p, 2);
            return normalized ? float(v) / 65535.0f : float(v);
        }
        case TINYGLTF_COMPONENT_TYPE_INT: {
            int32_t v;
            std::memcpy(&v, p, 4);
            return normalized ? float(std::max(double(v) / 2147483647.0, -1.0)) : float(v);
        }
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: {
            uint32_t v;
            std::memcpy(&v, p, 4);
            return normalized ? float(double(v) / 4294967295.0) : float(v);
        }
        case TINYGLTF_COMPONENT_TYPE_FLOAT: {
            float v;
            std::memcpy(&v, p, 4);
            return v;
        }
        default: {
            double v;
            std::memcpy(&v, p, 8);
            return float(v);
        }
    }
}

uint32_t readIndex(const unsigned char* p, int type) {
    if (type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE) return p[0];
    if (type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT) {
        uint16_t v;
        std::memcpy(&v, p, 2);
        return v;
    }
    uint32_t v;
    std::memcpy(&v, p, 4);
    return v;
}

bool isUnsignedIndexType(int type) {
    return type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE ||
           type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT ||
           type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT;
}

// Do `count` elements of `elementSize` bytes, `stride` apart from `offset`, fit in `length` bytes?
// Written without products that could overflow.
bool fits(size_t offset, size_t count, size_t stride, size_t elementSize, size_t length) {
    if (offset > length) return false;
    if (count == 0) return true;
    if (elementSize > length - offset) return false;
    return count - 1 <= (length - offset - elementSize) / stride;
}

const char* typeName(int type) {
    switch (type) {
        case TINYGLTF_TYPE_SCALAR:
            return "SCALAR";
        case TINYGLTF_TYPE_VEC2:
            return "VEC2";
        case TINYGLTF_TYPE_VEC3:
            return "VEC3";
        case TINYGLTF_TYPE_VEC4:
            return "VEC4";
        default:
            return "a matrix";
    }
}

// What a MeshData held before an append, so that a failed append can be undone.
struct AppendMark {
    explicit AppendMark(const MeshData& m)
        : vertices(m.vertices.size()),
          indices(m.indices.size()),
          primitives(m.primitives.size()),
          materials(m.materials.size()),
          textures(m.textures.size()),
          warnings(m.warnings.size()),
          files(m.files.size()),
          bounds(m.bounds) {}
    void undo(MeshData& m) const {
        m.vertices.resize(vertices);
        m.indices.resize(indices);
        m.primitives.resize(primitives);
        m.materials.resize(materials);
        m.textures.resize(textures);
        m.warnings.resize(warnings);
        m.files.resize(files);
        m.bounds = bounds;
    }
    size_t vertices, indices, primitives, materials, textures, warnings, files;
    Bounds bounds;
};

// A mesh primitive read from the file, in the mesh's own space, with only the vertices its
// triangles use. Read once per primitive, placed once per node that references the mesh.
struct LocalPrimitive {
    std::vector<glm::vec3> positions;
    std::vector<glm::vec3> normals;
    std::vector<glm::vec2> uvs;
    std::vector<uint32_t> triangles;  // a list, into the arrays above
    int material = -1;                // glTF material index
};

class GltfFlattener {
  public:
    GltfFlattener(MeshData& mesh, const std::string& path, const tinygltf::Model& model,
                  ImageLoadContext& images)
        : mesh_(mesh), path_(path), model_(model), images_(images) {}

    void run(const glm::mat4& transform) {
        materialBase_ = mesh_.materials.size();
        for (size_t i = 0; i < model_.materials.size(); ++i) addMaterial(i);
        meshes_.resize(model_.meshes.size());
        placeNodes(transform);
    }

  private:
    void addMaterial(size_t index) {
        const tinygltf::Material& source = model_.materials[index];
        const std::string where = "material " + std::to_string(index);
        const auto& pbr = source.pbrMetallicRoughness;
        Material material;
        if (pbr.baseColorFactor.size() != 4)
            fail(path_, where + " baseColorFactor needs 4 numbers");
        for (int c = 0; c < 4; ++c) {
            const double v = pbr.baseColorFactor[size_t(c)];
            if (!std::isfinite(v)) fail(path_, where + " baseColorFactor is not finite");
            material.baseColorFactor[c] = float(v);
        }
        if (pbr.baseColorTexture.index >= 0) {
            material.baseColorTexture = textureFor(pbr.baseColorTexture.index, where);
            if (pbr.baseColorTexture.texCoord != 0 && material.baseColorTexture >= 0) {
                mesh_.warnings.push_back(path_ + ": " + where +
                                         " reads its base color through TEXCOORD_" +
                                         std::to_string(pbr.baseColorTexture.texCoord) +
                                         ", which is not loaded; TEXCOORD_0 is used");
            }
        }
        mesh_.materials.push_back(material);
    }

    // Index into MeshData::textures, or -1 (with a warning) when the image has no usable pixels.
    int textureFor(int textureIndex, const std::string& where) {
        if (size_t(textureIndex) >= model_.textures.size()) {
            fail(path_, where + " references texture " + std::to_string(textureIndex) +
                            ", but the file has " + plural(model_.textures.size(), "texture"));
        }
        const int source = model_.textures[size_t(textureIndex)].source;
        if (source < 0) {
            mesh_.warnings.push_back(path_ + ": texture " + std::to_string(textureIndex) +
                                     " has no image it can read; " + where +
                                     " uses its base color factor");
            return -1;
        }
        if (size_t(source) >= model_.images.size()) {
            fail(path_, "texture " + std::to_string(textureIndex) + " references image " +
                            std::to_string(source) + ", but the file has " +
                            plural(model_.images.size(), "image"));
        }
        if (auto known = textureOfImage_.find(source); known != textureOfImage_.end()) {
            return known->second;
        }
        const tinygltf::Image& image = model_.images[size_t(source)];
        std::string name =
            !image.name.empty() ? echoText(image.name) : echoText(image.uri, kMaxPathChars);
        if (name.empty()) name = "image " + std::to_string(source);
        int result = -1;
        if (auto decoded = images_.decoded.find(source); decoded != images_.decoded.end()) {
            Texture texture = std::move(decoded->second);
            images_.decoded.erase(decoded);
            texture.name = name;
            result = int(mesh_.textures.size());
            mesh_.textures.push_back(std::move(texture));
        } else {
            auto failure = images_.failures.find(source);
            const std::string why =
                failure != images_.failures.end() ? failure->second : "the file could not be read";
            mesh_.warnings.push_back(path_ + ": image " + std::to_string(source) + " '" + name +
                                     "' could not be decoded (" + why +
                                     "); materials using it fall back to their base color factor");
        }
        textureOfImage_[source] = result;
        return result;
    }

    std::vector<int> sceneRoots() const {
        if (!model_.scenes.empty()) {
            if (size_t(model_.defaultScene) >= model_.scenes.size() && model_.defaultScene >= 0) {
                fail(path_, "default scene " + std::to_string(model_.defaultScene) +
                                " does not exist: the file has " +
                                plural(model_.scenes.size(), "scene"));
            }
            return model_.scenes[size_t(std::max(model_.defaultScene, 0))].nodes;
        }
        // No scene at all: every node that is nobody's child is a root.
        std::vector<bool> isChild(model_.nodes.size(), false);
        for (const tinygltf::Node& node : model_.nodes) {
            for (int child : node.children) {
                if (child >= 0 && size_t(child) < isChild.size()) isChild[size_t(child)] = true;
            }
        }
        std::vector<int> roots;
        for (size_t i = 0; i < isChild.size(); ++i) {
            if (!isChild[i]) roots.push_back(int(i));
        }
        return roots;
    }

    // Depth-first with an explicit stack: a deep hierarchy must not overflow the call stack, and
    // a node reached twice (a cycle, or a node with two parents) is refused, so the work is
    // bounded by the node count. Meshes are read as their nodes are reached, and placed once the
    // whole tree has been walked and the totals checked.
    struct Placement {
        size_t mesh;
        glm::mat4 world;
    };

    void placeNodes(const glm::mat4& transform) {
        struct Pending {
            int node;
            glm::mat4 parent;
        };
        std::vector<Pending> stack;
        std::vector<Placement> placements;
        const std::vector<int> roots = sceneRoots();
        for (auto it = roots.rbegin(); it != roots.rend(); ++it) stack.push_back({*it, transform});
        std::vector<bool> reached(model_.nodes.size(), false);
        while (!stack.empty()) {
            const Pending pending = stack.back();
            stack.pop_back();
            if (pending.node < 0 || size_t(pending.node) >= model_.nodes.size()) {
                fail(path_, "node " + std::to_string(pending.node) +
                                " does not exist: the file has " +
                                plural(model_.nodes.size(), "node"));
            }
            const size_t index = size_t(pending.node);
            if (reached[index]) {
                fail(path_, "node " + std::to_string(index) +
                                " is reached twice: the node hierarchy must be a tree");
            }
            reached[index] = true;
            const tinygltf::Node& node = model_.nodes[index];
            const glm::mat4 world = pending.parent * nodeTransform(path_, node, index);
            if (node.mesh >= 0) {
                if (size_t(node.mesh) >= model_.meshes.size()) {
                    fail(path_, "node " + std::to_string(index) + " references mesh " +
                                    std::to_string(node.mesh) + ", but the file has " +
                                    plural(model_.meshes.size(), "mesh", "meshes"));
                }
                readMesh(size_t(node.mesh));
                placements.push_back({size_t(node.mesh), world});
            }
            for (auto it = node.children.rbegin(); it != node.children.rend(); ++it) {
                stack.push_back({*it, world});
            }
        }
        checkPlacedTotals(placements);
        for (const Placement& p : placements) {
            for (const LocalPrimitive& primitive : *meshes_[p.mesh]) place(primitive, p.world);
        }
    }

    // Each node places its mesh once more: a mesh read once can become any number of copies (ten
    // thousand nodes of a 24,000-vertex mesh are 60 KB of JSON and 8 GB of vertices), so the
    // totals are checked before anything is placed.
    void checkPlacedTotals(const std::vector<Placement>& placements) const {
        size_t vertices = mesh_.vertices.size(), indices = mesh_.indices.size();
        for (const Placement& p : placements) {
            for (const LocalPrimitive& primitive : *meshes_[p.mesh]) {
                if (primitive.triangles.empty()) continue;
                vertices += primitive.positions.size();
                indices += primitive.triangles.size();
            }
            if (vertices > kMaxPlacedVertices || indices > kMaxPlacedIndices) {
                fail(path_, "its nodes place more than " +
                                std::to_string(vertices > kMaxPlacedVertices ? kMaxPlacedVertices
                                                                             : kMaxPlacedIndices) +
                                (vertices > kMaxPlacedVertices ? " vertices" : " indices") +
                                " in all (each node places its mesh once more), the most this "
                                "loader accepts");
            }
        }
    }

    void readMesh(size_t meshIndex) {
        if (!meshes_[meshIndex]) {
            std::vector<LocalPrimitive> primitives;
            const auto& source = model_.meshes[meshIndex].primitives;
            for (size_t p = 0; p < source.size(); ++p) {
                if (auto local = readPrimitive(meshIndex, p))
                    primitives.push_back(std::move(*local));
            }
            meshes_[meshIndex] = std::move(primitives);
        }
    }

    // Appends one placed copy of a primitive in world space.
    void place(const LocalPrimitive& local, const glm::mat4& world) {
        if (local.triangles.empty()) return;
        const size_t base = mesh_.vertices.size();  // below 2^32: checkPlacedTotals
        const glm::mat3 linear(world);
        const float det = glm::determinant(linear);
        // Normals go through the inverse-transpose; its direction is the cofactor matrix's
        // (det times it), which needs no division, so a zero scale cannot make infinities.
        const float side = det < 0.0f ? -1.0f : 1.0f;
        const glm::mat3 normalMatrix(side * glm::cross(linear[1], linear[2]),
                                     side * glm::cross(linear[2], linear[0]),
                                     side * glm::cross(linear[0], linear[1]));
        for (size_t i = 0; i < local.positions.size(); ++i) {
            Vertex v;
            v.position = glm::vec3(world * glm::vec4(local.positions[i], 1.0f));
            const glm::vec3 n = normalMatrix * local.normals[i];
            const float length = glm::length(n);
            v.normal = length > 0.0f && std::isfinite(length) ? n / length : glm::vec3(0, 1, 0);
            if (!local.uvs.empty()) v.uv = local.uvs[i];
            mesh_.vertices.push_back(v);
            mesh_.bounds.add(v.position);
        }
        Primitive primitive;
        primitive.firstIndex = uint32_t(mesh_.indices.size());
        primitive.indexCount = uint32_t(local.triangles.size());
        primitive.material = local.material < 0 ? -1 : int(materialBase_) + local.material;
        primitive.firstVertex = uint32_t(base);
        primitive.vertexCount = uint32_t(local.positions.size());
        primitive.axes = orthonormalAxes(linear);
        // A mirroring transform turns counter-clockwise triangles clockwise; swapping two corners
        // keeps the world-space front faces counter-clockwise, as the normals say.
        const bool mirrored = det < 0.0f;
        for (size_t t = 0; t < local.triangles.size(); t += 3) {
            const uint32_t a = local.triangles[t], b = local.triangles[t + 1],
                           c = local.triangles[t + 2];
            mesh_.indices.push_back(uint32_t(base) + a);
            mesh_.indices.push_back(uint32_t(base) + (mirrored ? c : b));
            mesh_.indices.push_back(uint32_t(base) + (mirrored ? b : c));
        }
        mesh_.primitives.push_back(primitive);
    }

    std::optional<LocalPrimitive> readPrimitive(size_t meshIndex, size_t primitiveIndex) {
        const tinygltf::Primitive& source = model_.meshes[meshIndex].primitives[primitiveIndex];
        const std::string where =
            "mesh " + std::to_string(meshIndex) + " primitive " + std::to_string(primitiveIndex);
        const int mode = source.mode < 0 ? TINYGLTF_MODE_TRIANGLES : source.mode;
        if (mode < TINYGLTF_MODE_POINTS || mode > TINYGLTF_MODE_TRIANGLE_FAN) {
            fail(path_, where + " has mode " + std::to_string(mode) + ", which is not a glTF mode");
        }
        if (mode < TINYGLTF_MODE_TRIANGLES) {
            mesh_.warnings.push_back(path_ + ": " + where + " draws " +
                                     (mode == TINYGLTF_MODE_POINTS ? "points" : "lines") +
                                     " and is skipped");
            return std::nullopt;
        }
        const auto position = source.attributes.find("POSITION");
        if (position == source.attributes.end()) fail(path_, where + " has no POSITION attribute");
        if (source.material >= 0 && size_t(source.material) >= model_.materials.size()) {
            fail(path_, where + " references material " + std::to_string(source.material) +
                            ", but the file has " + plural(model_.materials.size(), "material"));
        }
        const std::vector<float> positions = readFloats(position->second, 3, "POSITION");
        const size_t vertexCount = positions.size() / 3;
        std::vector<float> normals, uvs;
        if (auto it = source.attributes.find("NORMAL"); it != source.attributes.end()) {
            normals = readFloats(it->second, 3, "NORMAL");
            checkSameCount(it->second, normals.size() / 3, vertexCount, "NORMAL", where);
        }
        if (auto it = source.attributes.find("TEXCOORD_0"); it != source.attributes.end()) {
            uvs = readFloats(it->second, 2, "TEXCOORD_0");
            checkSameCount(it->second, uvs.size() / 2, vertexCount, "TEXCOORD_0", where);
        }
        std::vector<uint32_t> indices;
        if (source.indices >= 0) {
            indices = readIndices(source.indices);
            for (size_t i = 0; i < indices.size(); ++i) {
                if (indices[i] >= vertexCount) {
                    fail(path_, where + ": index " + std::to_string(indices[i]) + " (element " +
                                    std::to_string(i) + " of accessor " +
                                    std::to_string(source.indices) + ") is out of range for " +
                                    plural(vertexCount, "vertex", "vertices"));
                }
            }
        } else {
            indices.resize(vertexCount);
            for (size_t i = 0; i < vertexCount; ++i) indices[i] = uint32_t(i);
        }
        std::vector<uint32_t> triangles = toTriangleList(mode, indices, where);
        return compact(positions, normals, uvs, triangles, source.material);
    }

    void checkSameCount(int accessor, size_t count, size_t vertexCount, const char* role,
                        const std::string& where) const {
        if (count != vertexCount) {
            fail(path_, where + ": accessor " + std::to_string(accessor) + " (" + role + ") has " +
                            std::to_string(count) + " elements but POSITION has " +
                            std::to_string(vertexCount));
        }
    }

    std::vector<uint32_t> toTriangleList(int mode, const std::vector<uint32_t>& in,
                                         const std::string& where) {
        std::vector<uint32_t> out;
        auto add = [&](uint32_t a, uint32_t b, uint32_t c) {
            // Strips restart through repeated indices; those triangles have no area.
            if (mode != TINYGLTF_MODE_TRIANGLES && (a == b || b == c || a == c)) return;
            out.insert(out.end(), {a, b, c});
        };
        if (mode == TINYGLTF_MODE_TRIANGLES) {
            if (in.size() % 3 != 0) {
                mesh_.warnings.push_back(path_ + ": " + where + " has " +
                                         std::to_string(in.size()) +
                                         " indices, not a multiple of 3; the last are ignored");
            }
            for (size_t i = 0; i + 2 < in.size(); i += 3) add(in[i], in[i + 1], in[i + 2]);
        } else if (mode == TINYGLTF_MODE_TRIANGLE_STRIP) {
            // The glTF spec's order: every other triangle swaps two corners to keep the winding.
            for (size_t i = 0; i + 2 < in.size(); ++i) {
                const bool odd = (i % 2) != 0;
                add(in[i], in[i + (odd ? 2 : 1)], in[i + (odd ? 1 : 2)]);
            }
        } else {
            for (size_t i = 1; i + 1 < in.size(); ++i) add(in[i], in[i + 1], in[0]);
        }
        return out;
    }

    // Keeps only the vertices the triangles use, in their original order: primitives often share
    // one large vertex accessor, and each would otherwise copy all of it.
    LocalPrimitive compact(const std::vector<float>& positions, const std::vector<float>& normals,
                           const std::vector<float>& uvs, std::vector<uint32_t>& triangles,
                           int material) const {
        const size_t vertexCount = positions.size() / 3;
        constexpr uint32_t kUnused = std::numeric_limits<uint32_t>::max();
        std::vector<uint32_t> remap(vertexCount, kUnused);
        for (uint32_t i : triangles) remap[i] = 0;
        LocalPrimitive local;
        local.material = material;
        for (size_t i = 0; i < vertexCount; ++i) {
            if (remap[i] == kUnused) continue;
            remap[i] = uint32_t(local.positions.size());
            const glm::vec3 p = glm::make_vec3(&positions[i * 3]);
            if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) {
                fail(path_, "vertex " + std::to_string(i) + " has a non-finite POSITION");
            }
            local.positions.push_back(p);
            if (!normals.empty()) local.normals.push_back(glm::make_vec3(&normals[i * 3]));
            if (!uvs.empty()) local.uvs.push_back(glm::make_vec2(&uvs[i * 2]));
        }
        for (uint32_t& i : triangles) i = remap[i];
        local.triangles = std::move(triangles);
        if (normals.empty()) local.normals = faceAveragedNormals(local);
        return local;
    }

    // Area-weighted average of the normals of the faces around each vertex (the cross product's
    // length is twice the area), in the mesh's own space: the cofactor matrix used for placing
    // maps these sums exactly as it maps each face's cross product.
    static std::vector<glm::vec3> faceAveragedNormals(const LocalPrimitive& local) {
        std::vector<glm::vec3> sums(local.positions.size(), glm::vec3(0.0f));
        for (size_t t = 0; t < local.triangles.size(); t += 3) {
            const uint32_t a = local.triangles[t], b = local.triangles[t + 1],
                           c = local.triangles[t + 2];
            const glm::vec3 face = glm::cross(local.positions[b] - local.positions[a],
                                              local.positions[c] - local.positions[a]);
            sums[a] += face;
            sums[b] += face;
            sums[c] += face;
        }
        return sums;  // normalized when placed; a zero sum becomes +Y there
    }

    const tinygltf::Accessor& accessor(int index, const char* role) const {
        if (index < 0 || size_t(index) >= model_.accessors.size()) {
            fail(path_, std::string(role) + " accessor " + std::to_string(index) +
                            " does not exist: the file has " +
                            plural(model_.accessors.size(), "accessor"));
        }
        return model_.accessors[size_t(index)];
    }

    // The bytes of a buffer view, after checking it lies inside its buffer.
    std::pair<const unsigned char*, size_t> viewBytes(int view, const std::string& user) const {
        if (view < 0 || size_t(view) >= model_.bufferViews.size()) {
            fail(path_, user + " references buffer view " + std::to_string(view) +
                            ", but the file has " +
                            plural(model_.bufferViews.size(), "buffer view"));
        }
        const tinygltf::BufferView& v = model_.bufferViews[size_t(view)];
        if (v.buffer < 0 || size_t(v.buffer) >= model_.buffers.size()) {
            fail(path_, "buffer view " + std::to_string(view) + " references buffer " +
                            std::to_string(v.buffer) + ", but the file has " +
                            plural(model_.buffers.size(), "buffer"));
        }
        const std::vector<unsigned char>& data = model_.buffers[size_t(v.buffer)].data;
        if (!fits(v.byteOffset, 1, 1, v.byteLength, data.size())) {
            fail(path_, "buffer view " + std::to_string(view) + " reads past the end of buffer " +
                            std::to_string(v.buffer));
        }
        return {data.data() + v.byteOffset, v.byteLength};
    }

    // Everything that could make reading an accessor go wrong, before anything is allocated for
    // it: its elements (count x stride from its offset) inside its buffer view and the view inside
    // its buffer, its sparse indices and values inside theirs, every sparse index below the count.
    void checkAccessor(int index, const tinygltf::Accessor& a, size_t elementSize) const {
        const std::string name = "accessor " + std::to_string(index);
        if (a.bufferView >= 0) {
            const auto [bytes, length] = viewBytes(a.bufferView, name);
            const size_t stride = strideOf(a, elementSize);
            if (stride < elementSize) {
                fail(path_, "buffer view " + std::to_string(a.bufferView) + " has byteStride " +
                                std::to_string(stride) + ", less than the " +
                                std::to_string(elementSize) + "-byte elements of " + name);
            }
            if (!fits(a.byteOffset, a.count, stride, elementSize, length)) {
                fail(path_, name + " reads past the end of buffer view " +
                                std::to_string(a.bufferView) + ": " + std::to_string(a.count) +
                                " elements of " + std::to_string(elementSize) + " bytes, " +
                                std::to_string(stride) + " apart from byte " +
                                std::to_string(a.byteOffset) + ", in a view of " +
                                std::to_string(length) + " bytes");
            }
        }
        const size_t most = a.bufferView >= 0 ? kMaxElements : kMaxZeroFilledElements;
        if (a.count > most) {
            fail(path_,
                 name + " has " + std::to_string(a.count) + " elements" +
                     (a.bufferView >= 0 ? ""
                                        : " and no buffer view (zeros the file does not hold)") +
                     ", more than the " + std::to_string(most) + " this loader accepts");
        }
        if (!a.sparse.isSparse) return;
        const auto& sparse = a.sparse;
        const int indexType = sparse.indices.componentType;
        if (!isUnsignedIndexType(indexType)) {
            fail(path_, name + " has sparse indices that are not unsigned integers");
        }
        if (sparse.count < 0 || size_t(sparse.count) > a.count || sparse.indices.byteOffset < 0 ||
            sparse.values.byteOffset < 0) {
            fail(path_, name + " has a sparse count or offset out of range");
        }
        const size_t count = size_t(sparse.count);
        const size_t indexSize = size_t(tinygltf::GetComponentSizeInBytes(uint32_t(indexType)));
        const auto [indexBytes, indexLength] = viewBytes(sparse.indices.bufferView, name);
        const auto [valueBytes, valueLength] = viewBytes(sparse.values.bufferView, name);
        const size_t indexOffset = size_t(sparse.indices.byteOffset);
        const size_t valueOffset = size_t(sparse.values.byteOffset);
        if (!fits(indexOffset, count, indexSize, indexSize, indexLength) ||
            !fits(valueOffset, count, elementSize, elementSize, valueLength)) {
            fail(path_, name + " has sparse data past the end of its buffer views");
        }
        for (size_t i = 0; i < count; ++i) {
            const uint32_t target = readIndex(indexBytes + indexOffset + i * indexSize, indexType);
            if (target >= a.count) {
                fail(path_, name + " has sparse index " + std::to_string(target) +
                                ", out of range for " + plural(a.count, "element"));
            }
        }
    }

    size_t strideOf(const tinygltf::Accessor& a, size_t elementSize) const {
        const size_t byteStride = model_.bufferViews[size_t(a.bufferView)].byteStride;
        return byteStride != 0 ? byteStride : elementSize;
    }

    // Calls `visit(element, bytes)` for each element of an accessor that checkAccessor passed, and
    // then for each sparse substitute, so the last call for an element wins.
    template <class Visit>
    void forEachElement(const tinygltf::Accessor& a, size_t elementSize, Visit&& visit) const {
        if (a.bufferView >= 0) {
            const tinygltf::BufferView& view = model_.bufferViews[size_t(a.bufferView)];
            const unsigned char* bytes =
                model_.buffers[size_t(view.buffer)].data.data() + view.byteOffset + a.byteOffset;
            const size_t stride = strideOf(a, elementSize);
            for (size_t i = 0; i < a.count; ++i) visit(i, bytes + i * stride);
        }
        if (!a.sparse.isSparse) return;
        const auto& sparse = a.sparse;
        auto start = [&](int viewIndex, int offset) {
            const tinygltf::BufferView& view = model_.bufferViews[size_t(viewIndex)];
            return model_.buffers[size_t(view.buffer)].data.data() + view.byteOffset +
                   size_t(offset);
        };
        const int indexType = sparse.indices.componentType;
        const size_t indexSize = size_t(tinygltf::GetComponentSizeInBytes(uint32_t(indexType)));
        const unsigned char* indices = start(sparse.indices.bufferView, sparse.indices.byteOffset);
        const unsigned char* values = start(sparse.values.bufferView, sparse.values.byteOffset);
        for (size_t i = 0; i < size_t(sparse.count); ++i)
            visit(readIndex(indices + i * indexSize, indexType), values + i * elementSize);
    }

    std::vector<float> readFloats(int index, int components, const char* role) const {
        const tinygltf::Accessor& a = accessor(index, role);
        const std::string name = "accessor " + std::to_string(index);
        const int have = tinygltf::GetNumComponentsInType(uint32_t(a.type));
        if (have != components) {
            fail(path_, name + " (" + role + ") is " + typeName(a.type) + ", expected " +
                            typeName(components == 2 ? TINYGLTF_TYPE_VEC2 : TINYGLTF_TYPE_VEC3));
        }
        const int componentSize = tinygltf::GetComponentSizeInBytes(uint32_t(a.componentType));
        if (componentSize <= 0) {
            fail(path_, name + " has unknown componentType " + std::to_string(a.componentType));
        }
        const size_t c = size_t(components);
        checkAccessor(index, a, size_t(componentSize) * c);
        std::vector<float> out(a.count * c, 0.0f);  // no buffer view: zeros, as glTF says
        forEachElement(
            a, size_t(componentSize) * c, [&](size_t element, const unsigned char* bytes) {
                for (size_t k = 0; k < c; ++k) {
                    out[element * c + k] = readComponent(bytes + k * size_t(componentSize),
                                                         a.componentType, a.normalized);
                }
            });
        return out;
    }

    std::vector<uint32_t> readIndices(int index) const {
        const tinygltf::Accessor& a = accessor(index, "indices");
        if (a.type != TINYGLTF_TYPE_SCALAR || !isUnsignedIndexType(a.componentType)) {
            fail(path_, "accessor " + std::to_string(index) +
                            " (indices) must be SCALAR unsigned byte, short or int");
        }
        const size_t size = size_t(tinygltf::GetComponentSizeInBytes(uint32_t(a.componentType)));
        checkAccessor(index, a, size);
        std::vector<uint32_t> out(a.count, 0);
        forEachElement(a, size, [&](size_t element, const unsigned char* bytes) {
            out[element] = readIndex(bytes, a.componentType);
        });
        return out;
    }

    MeshData& mesh_;
    const std::string& path_;
    const tinygltf::Model& model_;
    ImageLoadContext& images_;  // its decoded pixels are moved into the mesh
    size_t materialBase_ = 0;
    std::map<int, int> textureOfImage_;  // glTF image -> MeshData texture, -1: unusable
    std::vector<std::optional<std::vector<LocalPrimitive>>> meshes_;
};

}  // namespace

std::string decodeImageFile(const std::vector<unsigned char>& bytes, int maxSide,
                            Texture& texture) {
    if (bytes.size() > size_t(std::numeric_limits<int>::max()))
        return "larger than the " + std::to_string(std::numeric_limits<int>::max()) +
               " bytes stb_image reads";
    int width = 0, height = 0;
    if (imageSize(bytes.data(), int(bytes.size()), width, height) &&
        (width > maxSide || height > maxSide))
        return std::to_string(width) + "x" + std::to_string(height) + " pixels: at most " +
               std::to_string(maxSide) + " a side";
    return decodeImage(bytes.data(), int(bytes.size()), 0, 0, texture);
}

void appendGltf(MeshData& mesh, const std::string& path, const glm::mat4& transform) {
    appendGltfBytes(mesh, path, readFile(path), transform);
}

void appendGltfBytes(MeshData& mesh, const std::string& path, std::vector<unsigned char> bytes,
                     const glm::mat4& transform) {
    const std::string baseDir = std::filesystem::path(path).parent_path().string();
    tinygltf::Model model;
    ImageLoadContext images;
    images.model = &model;
    images.baseDir = baseDir;
    tinygltf::TinyGLTF loader;
    loader.SetImageLoader(loadImageLeniently, &images);
    tinygltf::FsCallbacks files;
    files.FileExists = anythingExists;
    files.ExpandFilePath = pathAsWritten;
    files.ReadWholeFile = readReferencedFile;
    files.WriteWholeFile = refuseToWrite;
    files.user_data = &images;
    loader.SetFsCallbacks(files);
    std::string err, warn;
    bool ok;
    if (bytes.size() > std::numeric_limits<uint32_t>::max())
        fail(path, "is larger than the 4 GiB tinygltf reads");
    if (isGlb(bytes)) {
        checkGlbLayout(path, bytes);
        checkDocument(path, bytes.data() + 20, glb::readU32(bytes, 12));
        ok = loader.LoadBinaryFromMemory(&model, &err, &warn, bytes.data(), uint32_t(bytes.size()),
                                         baseDir);
    } else {
        if (std::filesystem::path(path).extension() == ".glb") {
            fail(path, "not a GLB file (no glTF magic)");
        }
        checkDocument(path, bytes.data(), bytes.size());
        ok = loader.LoadASCIIFromString(&model, &err, &warn,
                                        reinterpret_cast<const char*>(bytes.data()),
                                        uint32_t(bytes.size()), baseDir);
    }
    // tinygltf copied what it keeps (a GLB's BIN chunk into its buffer): the file's bytes go now,
    // before the geometry is read.
    std::vector<unsigned char>().swap(bytes);
    // A required buffer that could not be read: its own reason, not tinygltf's wrapping of it.
    if (!ok && !images.readFailure.empty()) fail(path, images.readFailure);
    if (!ok) fail(path, "invalid glTF: " + (err.empty() ? "unknown error" : oneLine(err)));

    // All or nothing: a file that fails halfway leaves `mesh` as it was.
    const AppendMark before(mesh);
    try {
        // What tinygltf reports while still succeeding (a missing image file, say).
        for (const std::string& text : {err, warn}) {
            if (!oneLine(text).empty()) mesh.warnings.push_back(path + ": " + oneLine(text));
        }
        GltfFlattener(mesh, path, model, images).run(transform);
        mesh.files.push_back(path);
        mesh.files.insert(mesh.files.end(), images.files.begin(), images.files.end());
    } catch (...) {
        before.undo(mesh);
        throw;
    }
}

}  // namespace host
