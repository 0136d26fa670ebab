// appendGltf on small glTF files written by the tests (JSON with base64 buffers, and GLB), and on
// Khronos models from Debian's assimp-testmodels. Expected values are worked out by hand in the
// comments, never by calling the loader's own helpers.
#include <gtest/gtest.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <glm/glm.hpp>
#include <new>
#include <nlohmann/json.hpp>

#include "host_test_helpers.h"
#include "scene/scene.h"

namespace {

namespace fs = std::filesystem;
using nlohmann::json;

constexpr int kUByte = 5121, kShort = 5122, kUShort = 5123, kUInt = 5125, kFloat = 5126;
const std::string kModels = "/usr/share/assimp/models/glTF2/";

std::string base64(const std::vector<uint8_t>& bytes) {
    static const char* digits = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    for (size_t i = 0; i < bytes.size(); i += 3) {
        const uint32_t n = uint32_t{bytes[i]} << 16 |
                           (i + 1 < bytes.size() ? uint32_t{bytes[i + 1]} << 8 : 0u) |
                           (i + 2 < bytes.size() ? uint32_t{bytes[i + 2]} : 0u);
        out += digits[n >> 18 & 63];
        out += digits[n >> 12 & 63];
        out += i + 1 < bytes.size() ? digits[n >> 6 & 63] : '=';
        out += i + 2 < bytes.size() ? digits[n & 63] : '=';
    }
    return out;
}

void writeBytes(const std::string& path, const std::string& bytes) {
    std::ofstream out(path, std::ios::binary);
    out << bytes;
}

// A PNG with stored (uncompressed) deflate blocks: enough for stb_image, no zlib needed.
std::string png(uint32_t width, uint32_t height, uint8_t bitDepth, uint8_t colorType,
                const std::vector<uint8_t>& pixels) {
    auto be32 = [](uint32_t v) {
        return std::string{char(v >> 24), char(v >> 16 & 0xff), char(v >> 8 & 0xff),
                           char(v & 0xff)};
    };
    auto crc32 = [](const std::string& bytes) {
        uint32_t crc = 0xffffffffu;
        for (unsigned char c : bytes) {
            crc ^= c;
            for (int k = 0; k < 8; ++k) crc = (crc >> 1) ^ (0xedb88320u & (0u - (crc & 1u)));
        }
        return ~crc;
    };
    auto chunk = [&](const std::string& type, const std::string& data) {
        return be32(uint32_t(data.size())) + type + data + be32(crc32(type + data));
    };
    const size_t rowBytes = pixels.size() / height;
    std::string raw;
    for (uint32_t y = 0; y < height; ++y) {
        raw += '\0';  // filter: none
        raw.append(reinterpret_cast<const char*>(pixels.data() + y * rowBytes), rowBytes);
    }
    uint32_t a = 1, b = 0;
    for (unsigned char c : raw) {
        a = (a + c) % 65521;
        b = (b + a) % 65521;
    }
    std::string zlib = "\x78\x01";
    zlib += '\x01';  // final stored block (raw is far below 65535 bytes here)
    const auto n = uint16_t(raw.size());
    zlib += {char(n & 0xff), char(n >> 8), char(~n & 0xff), char((~n >> 8) & 0xff)};
    zlib += raw + be32(b << 16 | a);
    const std::string header =
        be32(width) + be32(height) + std::string{char(bitDepth), char(colorType), 0, 0, 0};
    return "\x89PNG\r\n\x1a\n" + chunk("IHDR", header) + chunk("IDAT", zlib) + chunk("IEND", "");
}

// Builds a glTF document and its single binary buffer.
class GltfBuilder {
  public:
    json doc = {{"asset", {{"version", "2.0"}}}};
    std::vector<uint8_t> bin;

    template <class T>
    int view(const std::vector<T>& values, size_t stride = 0) {
        while (bin.size() % 4 != 0) bin.push_back(0);
        const size_t offset = bin.size();
        bin.resize(offset + values.size() * sizeof(T));
        std::memcpy(bin.data() + offset, values.data(), values.size() * sizeof(T));
        json v = {{"buffer", 0}, {"byteOffset", offset}, {"byteLength", values.size() * sizeof(T)}};
        if (stride != 0) v["byteStride"] = stride;
        doc["bufferViews"].push_back(v);
        return int(doc["bufferViews"].size()) - 1;
    }

    int accessor(int view, int componentType, size_t count, const char* type, size_t offset = 0,
                 bool normalized = false) {
        json a = {{"bufferView", view},
                  {"byteOffset", offset},
                  {"componentType", componentType},
                  {"count", count},
                  {"type", type}};
        if (normalized) a["normalized"] = true;
        doc["accessors"].push_back(a);
        return int(doc["accessors"].size()) - 1;
    }

    int vec3s(const std::vector<glm::vec3>& v) {
        return accessor(view(v), kFloat, v.size(), "VEC3");
    }
    template <class T>
    int indices(const std::vector<T>& v, int componentType) {
        return accessor(view(v), componentType, v.size(), "SCALAR");
    }

    // One mesh with one primitive; returns the mesh index.
    int mesh(json attributes, int indices = -1, int mode = 4, int material = -1) {
        json p = {{"attributes", attributes}, {"mode", mode}};
        if (indices >= 0) p["indices"] = indices;
        if (material >= 0) p["material"] = material;
        doc["meshes"].push_back({{"primitives", {p}}});
        return int(doc["meshes"].size()) - 1;
    }

    int node(json n) {
        doc["nodes"].push_back(n);
        return int(doc["nodes"].size()) - 1;
    }

    void scene(json roots) {
        doc["scenes"] = {{{"nodes", roots}}};
        doc["scene"] = 0;
    }

    std::string writeGltf(const std::string& path) {
        json d = doc;
        if (!bin.empty()) {
            d["buffers"] = {{{"byteLength", bin.size()},
                             {"uri", "data:application/octet-stream;base64," + base64(bin)}}};
        }
        writeBytes(path, d.dump());
        return path;
    }

    std::string writeGlb(const std::string& path) {
        json d = doc;
        if (!bin.empty()) d["buffers"] = {{{"byteLength", bin.size()}}};
        std::string text = d.dump();
        while (text.size() % 4 != 0) text += ' ';
        std::string payload(bin.begin(), bin.end());
        while (payload.size() % 4 != 0) payload += '\0';
        std::string out = "glTF";
        auto u32 = [&](size_t v) {
            for (int i = 0; i < 4; ++i) out += char((v >> (8 * i)) & 0xff);
        };
        u32(2);
        u32(12 + 8 + text.size() + (payload.empty() ? 0 : 8 + payload.size()));
        u32(text.size());
        out += "JSON" + text;
        if (!payload.empty()) {
            u32(payload.size());
            out += std::string("BIN\0", 4) + payload;
        }
        writeBytes(path, out);
        return path;
    }
};

const std::vector<glm::vec3> kTriangle = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};

using host_test::expectVec3;

glm::vec3 triangleNormal(const host::MeshData& mesh, size_t firstIndex) {
    const glm::vec3 a = mesh.vertices[mesh.indices[firstIndex]].position;
    const glm::vec3 b = mesh.vertices[mesh.indices[firstIndex + 1]].position;
    const glm::vec3 c = mesh.vertices[mesh.indices[firstIndex + 2]].position;
    return glm::normalize(glm::cross(b - a, c - a));
}

std::string errorOf(const std::string& path) {
    try {
        host::MeshData mesh;
        host::appendGltf(mesh, path);
    } catch (const host::SceneError& e) {
        return e.what();
    }
    return "(no error)";
}

// appendGltf of `file` in a child process whose address space may grow by at most `headroom`
// bytes: its SceneError message, "(no error)", or "(out of memory)" when an allocation failed.
std::string errorWithin(const std::string& file, uint64_t headroom) {
    int fds[2];
    if (::pipe(fds) != 0) return "(no pipe)";
    const pid_t child = ::fork();
    if (child == 0) {
        ::close(fds[0]);
        std::string result = "(no error)";
        {
            long pages = 0;
            std::ifstream("/proc/self/statm") >> pages;
            const rlim_t limit = rlim_t(pages) * rlim_t(::sysconf(_SC_PAGESIZE)) + headroom;
            const rlimit l{limit, limit};
            ::setrlimit(RLIMIT_AS, &l);
            try {
                host::MeshData mesh;
                host::appendGltf(mesh, file);
            } catch (const host::SceneError& e) {
                result = e.what();
            } catch (const std::bad_alloc&) {
                result = "(out of memory)";
            }
        }
        (void)!::write(fds[1], result.data(), result.size());
        ::_exit(0);
    }
    ::close(fds[1]);
    std::string out;
    char buffer[4096];
    for (ssize_t n; (n = ::read(fds[0], buffer, sizeof buffer)) > 0;) out.append(buffer, size_t(n));
    ::close(fds[0]);
    int status = 0;
    ::waitpid(child, &status, 0);
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) out += " (the child died)";
    return out;
}

class GltfTest : public ::testing::Test {
  protected:
    void SetUp() override {
        dir_ = fs::temp_directory_path() /
               ("host_gltf_" + std::to_string(getpid()) + "_" +
                ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::remove_all(dir_);
        fs::create_directories(dir_);
    }
    void TearDown() override { fs::remove_all(dir_); }
    std::string path(const std::string& name) const { return (dir_ / name).string(); }

    fs::path dir_;
};

TEST_F(GltfTest, HierarchyAppliesTrsThenMatrixThenTheCallersTransform) {
    GltfBuilder b;
    const int position = b.vec3s(kTriangle);
    const int normal = b.vec3s({{0, 0, 1}, {0, 0, 1}, {0, 0, 1}});
    const int mesh = b.mesh({{"POSITION", position}, {"NORMAL", normal}});
    const float h = std::sqrt(0.5f);  // quaternion of 90 degrees about +Y: (0, sin 45, 0, cos 45)
    b.node({{"translation", {1, 2, 3}},
            {"rotation", {0, h, 0, h}},
            {"scale", {2, 2, 2}},
            {"children", {1}}});
    b.node({{"matrix", {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 5, 1}}, {"mesh", mesh}});
    b.node({{"translation", {0, 0, -7}}, {"mesh", mesh}});
    b.scene({0, 2});
    host::MeshData m;
    host::appendGltf(m, b.writeGltf(path("h.gltf")),
                     glm::mat4(1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 100, 0, 0, 1));
    ASSERT_EQ(m.vertices.size(), 6u);
    ASSERT_EQ(m.primitives.size(), 2u);
    // Node 1: (x, y, z + 5); node 0: scale 2, then Ry(90): (x, y, z) -> (z, y, -x), then +(1, 2,
    // 3); the caller adds (100, 0, 0). (0,0,0) -> (0,0,10) -> (10,0,0) -> (111,2,3).
    expectVec3(m.vertices[0].position, {111, 2, 3});
    expectVec3(m.vertices[1].position, {111, 2, 1});  // (1,0,5) -> (2,0,10) -> (10,0,-2)
    expectVec3(m.vertices[2].position, {111, 4, 3});  // (0,1,5) -> (0,2,10) -> (10,2,0)
    expectVec3(m.vertices[0].normal, {1, 0, 0});      // +Z turned 90 degrees about +Y
    // Node 2, a second copy of the same mesh: (x, y, z - 7) + (100, 0, 0).
    expectVec3(m.vertices[3].position, {100, 0, -7});
    expectVec3(m.vertices[4].position, {101, 0, -7});
    expectVec3(m.vertices[5].position, {100, 1, -7});
    EXPECT_EQ(m.indices, (std::vector<uint32_t>{0, 1, 2, 3, 4, 5}));
    EXPECT_EQ(m.primitives[1].firstIndex, 3u);
    EXPECT_EQ(m.primitives[1].indexCount, 3u);
    expectVec3(m.bounds.min, {100, 0, -7});
    expectVec3(m.bounds.max, {111, 4, 3});
    EXPECT_TRUE(m.warnings.empty());
}

TEST_F(GltfTest, DefaultSceneIsTheOneLoaded) {
    GltfBuilder b;
    const int mesh = b.mesh({{"POSITION", b.vec3s(kTriangle)}});
    b.node({{"mesh", mesh}});
    b.node({{"mesh", mesh}, {"translation", {5, 0, 0}}});
    b.doc["scenes"] = {{{"nodes", {0}}}, {{"nodes", {1}}}};
    b.doc["scene"] = 1;
    host::MeshData m;
    host::appendGltf(m, b.writeGltf(path("s.gltf")));
    ASSERT_EQ(m.vertices.size(), 3u);
    expectVec3(m.vertices[1].position, {6, 0, 0});
}

TEST_F(GltfTest, WithoutScenesEveryRootNodeIsLoaded) {
    GltfBuilder b;
    const int mesh = b.mesh({{"POSITION", b.vec3s(kTriangle)}});
    b.node({{"children", {1}}, {"translation", {0, 10, 0}}});
    b.node({{"mesh", mesh}});
    b.node({{"mesh", mesh}, {"translation", {0, 0, 4}}});
    host::MeshData m;
    host::appendGltf(m, b.writeGltf(path("r.gltf")));
    ASSERT_EQ(m.vertices.size(), 6u);
    expectVec3(m.vertices[0].position, {0, 10, 0});  // node 1 under node 0
    expectVec3(m.vertices[3].position, {0, 0, 4});   // node 2, the other root
}

TEST_F(GltfTest, IndicesOfEveryUnsignedWidthAreRead) {
    const std::vector<glm::vec3> quad = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
    const std::vector<uint32_t> expected = {0, 1, 2, 2, 3, 0};
    for (int type : {kUByte, kUShort, kUInt}) {
        GltfBuilder b;
        const int position = b.vec3s(quad);
        int index = -1;
        if (type == kUByte) index = b.indices(std::vector<uint8_t>{0, 1, 2, 2, 3, 0}, type);
        if (type == kUShort) index = b.indices(std::vector<uint16_t>{0, 1, 2, 2, 3, 0}, type);
        if (type == kUInt) index = b.indices(std::vector<uint32_t>{0, 1, 2, 2, 3, 0}, type);
        b.node({{"mesh", b.mesh({{"POSITION", position}}, index)}});
        b.scene({0});
        host::MeshData m;
        host::appendGltf(m, b.writeGltf(path("i" + std::to_string(type) + ".gltf")));
        EXPECT_EQ(m.indices, expected) << "componentType " << type;
        ASSERT_EQ(m.vertices.size(), 4u);
        expectVec3(m.vertices[2].position, {1, 1, 0});
        expectVec3(triangleNormal(m, 3), {0, 0, 1});
    }
}

TEST_F(GltfTest, NonIndexedPrimitivesUseTheirVerticesInOrder) {
    GltfBuilder b;
    const int position =
        b.vec3s({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {5, 0, 0}, {6, 0, 0}, {5, 1, 0}});
    b.node({{"mesh", b.mesh({{"POSITION", position}})}});
    b.scene({0});
    host::MeshData m;
    host::appendGltf(m, b.writeGltf(path("n.gltf")));
    EXPECT_EQ(m.indices, (std::vector<uint32_t>{0, 1, 2, 3, 4, 5}));
    expectVec3(m.vertices[4].position, {6, 0, 0});
}

TEST_F(GltfTest, StripsAndFansBecomeListsAndPointsAndLinesAreSkipped) {
    GltfBuilder b;
    // A strip whose every triangle faces +Z when the glTF order is kept.
    const int strip = b.vec3s({{0, 1, 0}, {0, 0, 0}, {1, 1, 0}, {1, 0, 0}, {2, 1, 0}});
    const int fan = b.vec3s({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {-1, 1, 0}});
    json primitives = {{{"attributes", {{"POSITION", strip}}}, {"mode", 5}},
                       {{"attributes", {{"POSITION", fan}}}, {"mode", 6}},
                       {{"attributes", {{"POSITION", fan}}}, {"mode", 0}},
                       {{"attributes", {{"POSITION", fan}}}, {"mode", 3}}};
    b.doc["meshes"] = {{{"primitives", primitives}}};
    b.node({{"mesh", 0}});
    b.scene({0});
    host::MeshData m;
    const std::string file = b.writeGltf(path("sf.gltf"));
    host::appendGltf(m, file);
    ASSERT_EQ(m.primitives.size(), 2u);
    // glTF strip triangle i: (i, i+1, i+2) for even i, (i, i+2, i+1) for odd i.
    EXPECT_EQ(m.primitives[0].indexCount, 9u);
    EXPECT_EQ(std::vector<uint32_t>(m.indices.begin(), m.indices.begin() + 9),
              (std::vector<uint32_t>{0, 1, 2, 1, 3, 2, 2, 3, 4}));
    // glTF fan triangle i: (i+1, i+2, 0); the fan's vertices follow the strip's five.
    EXPECT_EQ(std::vector<uint32_t>(m.indices.begin() + 9, m.indices.end()),
              (std::vector<uint32_t>{6, 7, 5, 7, 8, 5, 8, 9, 5}));
    for (size_t t = 0; t < m.indices.size(); t += 3) expectVec3(triangleNormal(m, t), {0, 0, 1});
    ASSERT_EQ(m.warnings.size(), 2u);
    EXPECT_EQ(m.warnings[0], file + ": mesh 0 primitive 2 draws points and is skipped");
    EXPECT_EQ(m.warnings[1], file + ": mesh 0 primitive 3 draws lines and is skipped");
}

TEST_F(GltfTest, StripTrianglesWithRepeatedIndicesAreDropped) {
    GltfBuilder b;
    const int position = b.vec3s({{0, 1, 0}, {0, 0, 0}, {1, 1, 0}, {1, 0, 0}});
    // Triangles (0,1,2), (1,2,2) and (2,2,3): only the first has an area.
    const int index = b.indices(std::vector<uint16_t>{0, 1, 2, 2, 3}, kUShort);
    b.node({{"mesh", b.mesh({{"POSITION", position}}, index, 5)}});
    b.scene({0});
    host::MeshData m;
    host::appendGltf(m, b.writeGltf(path("d.gltf")));
    EXPECT_EQ(m.indices, (std::vector<uint32_t>{0, 1, 2}));
    EXPECT_EQ(m.vertices.size(), 3u);  // vertex 3 is used by no triangle
}

TEST_F(GltfTest, InterleavedAttributesFollowByteStride) {
    GltfBuilder b;
    // 3 vertices of position (12 bytes), normal (12), uv (8), padding (4): stride 36.
    std::vector<float> data = {0, 0, 0, 0, 0, 1, 0.25f, 0.5f, -1,  //
                               2, 0, 0, 0, 0, 1, 1,     0,    -1,  //
                               0, 3, 0, 0, 0, 1, 0,     1,    -1};
    const int view = b.view(data, 36);
    const int position = b.accessor(view, kFloat, 3, "VEC3", 0);
    const int normal = b.accessor(view, kFloat, 3, "VEC3", 12);
    const int uv = b.accessor(view, kFloat, 3, "VEC2", 24);
    b.node({{"mesh", b.mesh({{"POSITION", position}, {"NORMAL", normal}, {"TEXCOORD_0", uv}})}});
    b.scene({0});
    host::MeshData m;
    host::appendGltf(m, b.writeGlb(path("stride.glb")));
    ASSERT_EQ(m.vertices.size(), 3u);
    expectVec3(m.vertices[1].position, {2, 0, 0});
    expectVec3(m.vertices[2].position, {0, 3, 0});
    expectVec3(m.vertices[2].normal, {0, 0, 1});
    EXPECT_EQ(m.vertices[0].uv, glm::vec2(0.25f, 0.5f));
    EXPECT_EQ(m.vertices[2].uv, glm::vec2(0.0f, 1.0f));
}

TEST_F(GltfTest, MissingNormalsAreAveragedOverTheFacesAroundEachVertex) {
    GltfBuilder b;
    // A roof: ridge (x = 0, y = 1) along z, eaves at x = -1 and x = 1. Each slope is two
    // triangles of equal area; the left faces (-1, 1, 0), the right (1, 1, 0).
    const int position =
        b.vec3s({{-1, 0, 0}, {-1, 0, 1}, {0, 1, 0}, {0, 1, 1}, {1, 0, 0}, {1, 0, 1}});
    const int index = b.indices(std::vector<uint16_t>{0, 1, 3, 0, 3, 2, 2, 3, 5, 2, 5, 4}, kUShort);
    b.node({{"mesh", b.mesh({{"POSITION", position}}, index)}});
    b.scene({0});
    host::MeshData m;
    host::appendGltf(m, b.writeGltf(path("roof.gltf")));
    ASSERT_EQ(m.vertices.size(), 6u);
    const float r2 = std::sqrt(2.0f), r10 = std::sqrt(10.0f);
    expectVec3(m.vertices[0].normal, {-1 / r2, 1 / r2, 0});  // left faces only
    expectVec3(m.vertices[5].normal, {1 / r2, 1 / r2, 0});   // right faces only
    // Vertex 2 is in one left and two right triangles: -1*(1,-1) + 2*(1,1) = (1, 3).
    expectVec3(m.vertices[2].normal, {1 / r10, 3 / r10, 0});
    // Vertex 3 is in two left and one right triangles: (-1, 3).
    expectVec3(m.vertices[3].normal, {-1 / r10, 3 / r10, 0});
}

TEST_F(GltfTest, NormalsGoThroughTheInverseTranspose) {
    GltfBuilder b;
    const float h = std::sqrt(0.5f);
    const int position = b.vec3s(kTriangle);
    const int normal = b.vec3s({{0, h, h}, {0, h, h}, {0, h, h}});
    const int mesh = b.mesh({{"POSITION", position}, {"NORMAL", normal}});
    b.node({{"mesh", mesh}, {"scale", {1, 2, 1}}});
    b.scene({0});
    host::MeshData m;
    host::appendGltf(m, b.writeGltf(path("it.gltf")));
    // diag(1, 2, 1)^-T = diag(1, 1/2, 1): (0, 1, 1) -> (0, 1/2, 1) ~ (0, 1, 2) / sqrt 5. The plain
    // matrix would give (0, 2, 1) / sqrt 5.
    const float r5 = std::sqrt(5.0f);
    expectVec3(m.vertices[0].normal, {0, 1 / r5, 2 / r5});
}

TEST_F(GltfTest, MirroringKeepsTrianglesFacingTheirNormals) {
    GltfBuilder b;
    const int position = b.vec3s(kTriangle);
    const int normal = b.vec3s({{0, 0, 1}, {0, 0, 1}, {0, 0, 1}});
    b.node({{"mesh", b.mesh({{"POSITION", position}, {"NORMAL", normal}})}, {"scale", {-1, 1, 1}}});
    b.scene({0});
    host::MeshData m;
    host::appendGltf(m, b.writeGltf(path("mirror.gltf")));
    // Mirroring x keeps the +Z normal; the triangle, counter-clockwise in the file, would turn
    // clockwise (facing -Z) unless two of its corners are swapped.
    expectVec3(m.vertices[0].normal, {0, 0, 1});
    expectVec3(triangleNormal(m, 0), {0, 0, 1});
    EXPECT_EQ(m.indices, (std::vector<uint32_t>{0, 2, 1}));
}

TEST_F(GltfTest, NormalizedIntegerAttributesAreScaled) {
    GltfBuilder b;
    b.doc["extensionsUsed"] = {"KHR_mesh_quantization"};
    b.doc["extensionsRequired"] = {"KHR_mesh_quantization"};
    // Signed shorts, 8-byte stride (6 bytes of data, 2 of padding).
    const std::vector<int16_t> positions = {32767, 0, 0, 0, 0, -32768, 0, 0, 0, -16384, 0, 0};
    const int position = b.accessor(b.view(positions, 8), kShort, 3, "VEC3", 0, true);
    const std::vector<uint8_t> uvs = {255, 0, 0, 128, 51, 255};
    const int uv = b.accessor(b.view(uvs), kUByte, 3, "VEC2", 0, true);
    b.node({{"mesh", b.mesh({{"POSITION", position}, {"TEXCOORD_0", uv}})}});
    b.scene({0});
    host::MeshData m;
    host::appendGltf(m, b.writeGltf(path("q.gltf")));
    ASSERT_EQ(m.vertices.size(), 3u);
    expectVec3(m.vertices[0].position, {1, 0, 0});
    expectVec3(m.vertices[1].position, {0, -1, 0});  // -32768 clamps to -1
    expectVec3(m.vertices[2].position, {0, -16384.0f / 32767.0f, 0});
    EXPECT_FLOAT_EQ(m.vertices[0].uv.x, 1.0f);
    EXPECT_FLOAT_EQ(m.vertices[1].uv.y, 128.0f / 255.0f);
    EXPECT_FLOAT_EQ(m.vertices[2].uv.x, 0.2f);
}

TEST_F(GltfTest, SparseAccessorsReplaceTheListedElements) {
    GltfBuilder b;
    const int base = b.view(kTriangle);
    const int sparseIndices = b.view(std::vector<uint16_t>{2, 0});
    const int sparseValues = b.view(std::vector<glm::vec3>{{7, 8, 9}});
    b.accessor(base, kFloat, 3, "VEC3");
    b.doc["accessors"][0]["sparse"] = {
        {"count", 1},
        {"indices", {{"bufferView", sparseIndices}, {"componentType", kUShort}}},
        {"values", {{"bufferView", sparseValues}}}};
    b.node({{"mesh", b.mesh({{"POSITION", 0}})}});
    b.scene({0});
    host::MeshData m;
    host::appendGltf(m, b.writeGltf(path("sparse.gltf")));
    ASSERT_EQ(m.vertices.size(), 3u);
    expectVec3(m.vertices[0].position, {0, 0, 0});
    expectVec3(m.vertices[2].position, {7, 8, 9});  // element 2 replaced, the rest kept
}

TEST_F(GltfTest, MaterialsKeepTheirFactorsAndAreOffsetWhenAppending) {
    GltfBuilder b;
    b.doc["materials"] = {{{"name", "white"}},
                          {{"pbrMetallicRoughness", {{"baseColorFactor", {0.5, 0.25, 1, 0.75}}}}}};
    b.node({{"mesh", b.mesh({{"POSITION", b.vec3s(kTriangle)}}, -1, 4, 1)}});
    b.scene({0});
    const std::string file = b.writeGltf(path("mat.gltf"));
    host::MeshData m;
    host::appendGltf(m, file);
    host::appendGltf(m, file);
    ASSERT_EQ(m.materials.size(), 4u);
    EXPECT_EQ(m.materials[0].baseColorFactor, glm::vec4(1.0f));
    EXPECT_EQ(m.materials[1].baseColorFactor, glm::vec4(0.5f, 0.25f, 1.0f, 0.75f));
    EXPECT_EQ(m.materials[1].baseColorTexture, -1);
    ASSERT_EQ(m.primitives.size(), 2u);
    EXPECT_EQ(m.primitives[0].material, 1);
    EXPECT_EQ(m.primitives[1].material, 3);  // the second file's material 1
    EXPECT_EQ(m.primitives[1].firstIndex, 3u);
    EXPECT_EQ(m.indices[3], 3u);  // indices address the whole vertex array
}

// Three materials, each with one texture, each with one image file.
GltfBuilder texturedTriangle(const std::vector<std::string>& uris) {
    GltfBuilder b;
    b.doc["materials"] = json::array();
    for (size_t i = 0; i < uris.size(); ++i) {
        b.doc["images"].push_back({{"uri", uris[i]}});
        b.doc["textures"].push_back({{"source", i}});
        b.doc["materials"].push_back(
            {{"pbrMetallicRoughness",
              {{"baseColorFactor", {0.5, 0.5, 0.5, 1}}, {"baseColorTexture", {{"index", i}}}}}});
    }
    b.node({{"mesh", b.mesh({{"POSITION", b.vec3s(kTriangle)}}, -1, 4, 0)}});
    b.scene({0});
    return b;
}

TEST_F(GltfTest, TexturesAreDecodedToRgba8) {
    writeBytes(path("rgb.png"), png(2, 1, 8, 2, {255, 0, 0, 0, 255, 0}));
    writeBytes(path("gray.pgm"), std::string("P5\n1 1\n255\n") + std::string("\x4d", 1));
    // 16-bit gray and alpha, big-endian as PNG stores them: (65535, 0) and (1000, 32768).
    writeBytes(path("ga16.png"), png(2, 1, 16, 4, {0xff, 0xff, 0, 0, 0x03, 0xe8, 0x80, 0}));
    GltfBuilder b = texturedTriangle({"rgb.png", "gray.pgm", "ga16.png"});
    host::MeshData m;
    host::appendGltf(m, b.writeGltf(path("tex.gltf")));
    EXPECT_TRUE(m.warnings.empty()) << m.warnings.front();
    ASSERT_EQ(m.textures.size(), 3u);
    ASSERT_EQ(m.materials.size(), 3u);
    EXPECT_EQ(m.materials[0].baseColorTexture, 0);
    EXPECT_EQ(m.materials[2].baseColorTexture, 2);
    EXPECT_EQ(m.textures[0].name, "rgb.png");
    EXPECT_EQ(m.textures[0].width, 2u);
    EXPECT_EQ(m.textures[0].height, 1u);
    EXPECT_EQ(m.textures[0].rgba, (std::vector<uint8_t>{255, 0, 0, 255, 0, 255, 0, 255}));
    EXPECT_EQ(m.textures[1].rgba, (std::vector<uint8_t>{77, 77, 77, 255}));
    // 16 bits to 8, rounded: 1000 * 255 / 65535 = 3.89 -> 4, 32768 * 255 / 65535 = 127.5 -> 128.
    EXPECT_EQ(m.textures[2].rgba, (std::vector<uint8_t>{255, 255, 255, 0, 4, 4, 4, 128}));
}

TEST_F(GltfTest, MissingOrUnreadableTexturesFallBackToTheFactor) {
    writeBytes(path("broken.png"), "this is not an image");
    writeBytes(path("ok.pgm"), std::string("P5\n1 1\n255\n") + std::string("\x10", 1));
    GltfBuilder b = texturedTriangle({"missing.png", "broken.png", "ok.pgm"});
    host::MeshData m;
    const std::string file = b.writeGltf(path("fallback.gltf"));
    host::appendGltf(m, file);
    ASSERT_EQ(m.materials.size(), 3u);
    EXPECT_EQ(m.materials[0].baseColorTexture, -1);
    EXPECT_EQ(m.materials[1].baseColorTexture, -1);
    EXPECT_EQ(m.materials[2].baseColorTexture, 0);
    EXPECT_EQ(m.materials[0].baseColorFactor, glm::vec4(0.5f, 0.5f, 0.5f, 1.0f));
    ASSERT_EQ(m.textures.size(), 1u);
    auto warned = [&](const std::string& image) {
        for (const std::string& w : m.warnings) {
            if (w.rfind(file + ": ", 0) == 0 && w.find(image) != std::string::npos &&
                w.find("base color factor") != std::string::npos) {
                return true;
            }
        }
        return false;
    };
    EXPECT_TRUE(warned("image 0 'missing.png'"));
    EXPECT_TRUE(warned("image 1 'broken.png'"));
    EXPECT_FALSE(warned("ok.pgm"));
}

TEST_F(GltfTest, AnImageViewOutsideItsBufferFallsBackToo) {
    GltfBuilder b = texturedTriangle({});
    const int view = b.view(std::vector<uint8_t>{1, 2, 3, 4});
    b.doc["bufferViews"][size_t(view)]["byteLength"] = 4000;
    b.doc["images"] = {{{"bufferView", view}, {"mimeType", "image/png"}}};
    b.doc["textures"] = {{{"source", 0}}};
    b.doc["materials"] = {{{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}}}}};
    host::MeshData m;
    const std::string file = b.writeGlb(path("view.glb"));
    host::appendGltf(m, file);
    EXPECT_EQ(m.materials.at(0).baseColorTexture, -1);
    ASSERT_EQ(m.warnings.size(), 1u);
    EXPECT_EQ(m.warnings[0], file + ": image 0 'image 0' could not be decoded (buffer view " +
                                 std::to_string(view) +
                                 " lies outside its buffer); materials using it fall back to "
                                 "their base color factor");
}

// An image larger than a Vulkan image may be is refused from its header, before its pixels are
// decoded (a 16384^2 image is 1 GiB of them).
TEST_F(GltfTest, ImagesTooLargeToUploadAreRefusedBeforeDecoding) {
    writeBytes(path("wide.png"), png(16385, 1, 8, 0, std::vector<uint8_t>(16385, 7)));
    host::MeshData m;
    const std::string file = texturedTriangle({"wide.png"}).writeGltf(path("wide.gltf"));
    host::appendGltf(m, file);
    EXPECT_EQ(m.materials.at(0).baseColorTexture, -1);
    ASSERT_EQ(m.warnings.size(), 1u);
    EXPECT_EQ(m.warnings[0], file +
                                 ": image 0 'wide.png' could not be decoded (16385x1 pixels: a "
                                 "texture has 1 to 16384 a side); materials using it fall back "
                                 "to their base color factor");
}

// stb_image names an unknown PNG chunk by its four bytes from the file: a newline among them made
// a two-line warning (found by tests/fuzz/gltf_fuzzer; tests/fuzz/corpus/gltf/png-chunk-newline).
TEST_F(GltfTest, AnImagesFailureIsOneLineWhateverItsBytes) {
    std::string bytes = png(1, 1, 8, 0, {7});
    bytes.insert(33, std::string("\0\0\0\0\nBCD\0\0\0\0", 12));  // after IHDR
    writeBytes(path("chunk.png"), bytes);
    host::MeshData m;
    const std::string file = texturedTriangle({"chunk.png"}).writeGltf(path("chunk.gltf"));
    host::appendGltf(m, file);
    ASSERT_EQ(m.warnings.size(), 1u);
    EXPECT_EQ(m.warnings[0], file +
                                 ": image 0 'chunk.png' could not be decoded (stb_image cannot "
                                 "decode it: \\nBCD PNG chunk not known); materials using it fall "
                                 "back to their base color factor");
}

// --- Errors: one line naming the file and the problem. ---

// tinygltf turns "extras" into nested values one call per level: the nesting cap of the project's
// other JSON readers is applied before tinygltf sees the document.
TEST_F(GltfTest, DeepNestingIsRefusedBeforeTinygltfWalksIt) {
    const std::string file = path("deep.gltf");
    for (size_t levels : {size_t{65}, size_t{100000}}) {
        writeBytes(file, R"({"asset": {"version": "2.0", "extras": )" + std::string(levels, '[') +
                             std::string(levels, ']') + "}}");
        EXPECT_EQ(errorOf(file).rfind(file + ": asset.extras[0][0][0]", 0), 0u) << levels;
        EXPECT_NE(errorOf(file).find("arrays and objects nest more than 64 deep here"),
                  std::string::npos);
    }
    writeBytes(file, R"({"asset": {"version": "2.0", "extras": )" + std::string(62, '[') +
                         std::string(62, ']') + "}}");
    EXPECT_EQ(errorOf(file), "(no error)");
}

TEST_F(GltfTest, MissingFile) {
    const std::string file = path("nope.gltf");
    EXPECT_EQ(errorOf(file), file + ": glTF file does not exist");
}

// A glTF, or a buffer it references, that never ends (a device, a FIFO) used to hang and eat
// memory; a directory used to be "not found".
TEST_F(GltfTest, OnlyRegularFilesUpToTheCapAreRead) {
    EXPECT_EQ(errorOf("/dev/zero"),
              "/dev/zero: glTF file is a character device, not a regular file");
    EXPECT_EQ(errorOf(dir_.string()), dir_.string() + ": glTF file is a directory");
    const std::string huge = path("huge.glb");
    writeBytes(huge, "glTF");
    fs::resize_file(huge, (uintmax_t{2} << 30) + 1);  // sparse: nothing is written to disk
    EXPECT_EQ(errorOf(huge), huge + ": glTF file is larger than the 2 GiB read for a glTF file");

    fs::create_symlink("/dev/zero", dir_ / "zero.bin");
    ASSERT_EQ(::mkfifo(path("fifo.bin").c_str(), 0600), 0);
    for (const char* uri : {"zero.bin", "fifo.bin"}) {
        SCOPED_TRACE(uri);
        GltfBuilder b;
        b.node({{"mesh", b.mesh({{"POSITION", b.vec3s(kTriangle)}})}});
        b.scene({0});
        json d = b.doc;
        d["buffers"] = {{{"byteLength", b.bin.size()}, {"uri", uri}}};
        const std::string file = path("external.gltf");
        writeBytes(file, d.dump());
        const std::string error = errorOf(file);
        EXPECT_EQ(error.rfind(file + ": " + path(uri) + ": file referenced by the glTF is a ", 0),
                  0u)
            << error;
        EXPECT_NE(error.find("not a regular file"), std::string::npos) << error;
    }
}

TEST_F(GltfTest, TheFilesReadAreListed) {
    host::MeshData m;
    host::appendGltf(m, kModels + "BoxTextured-glTF/BoxTextured.gltf");
    ASSERT_EQ(m.files.size(), 3u);
    EXPECT_EQ(m.files[0], kModels + "BoxTextured-glTF/BoxTextured.gltf");
    EXPECT_NE(m.files[1].find("BoxTextured0.bin"), std::string::npos) << m.files[1];
    EXPECT_NE(m.files[2].find("CesiumLogoFlat.png"), std::string::npos) << m.files[2];
}

// Draco-compressed primitives have accessors without data; tinygltf used to fail on them with
// "accessor[0] invalid bufferView" before the extension was looked at.
TEST_F(GltfTest, UnimplementedExtensionsAreRefusedByName) {
    GltfBuilder b;
    b.doc["accessors"] = {{{"componentType", kFloat}, {"count", 3}, {"type", "VEC3"}},
                          {{"componentType", kUShort}, {"count", 3}, {"type", "SCALAR"}}};
    json primitive = {
        {"attributes", {{"POSITION", 0}}},
        {"indices", 1},
        {"mode", 4},
        {"extensions",
         {{"KHR_draco_mesh_compression", {{"bufferView", 0}, {"attributes", {{"POSITION", 0}}}}}}}};
    b.doc["meshes"] = {{{"primitives", {primitive}}}};
    b.doc["bufferViews"] = {{{"buffer", 0}, {"byteLength", 4}}};
    b.bin = {0, 0, 0, 0};
    b.node({{"mesh", 0}});
    b.scene({0});
    b.doc["extensionsUsed"] = {"KHR_draco_mesh_compression"};
    const std::string used = b.writeGltf(path("used.gltf"));
    EXPECT_EQ(errorOf(used), used +
                                 ": mesh 0 primitive 0 uses glTF extension "
                                 "KHR_draco_mesh_compression (Draco mesh compression), which "
                                 "this loader does not implement");
    b.doc["extensionsRequired"] = {"KHR_draco_mesh_compression"};
    const std::string required = b.writeGlb(path("required.glb"));
    EXPECT_EQ(errorOf(required), required +
                                     ": requires glTF extension KHR_draco_mesh_compression "
                                     "(Draco mesh compression), which this loader does not "
                                     "implement");

    GltfBuilder other;
    other.node({{"mesh", other.mesh({{"POSITION", other.vec3s(kTriangle)}})}});
    other.scene({0});
    other.doc["extensionsUsed"] = {"KHR_texture_transform", "EXT_made_up"};
    const std::string usedOnly = other.writeGltf(path("used-only.gltf"));
    EXPECT_EQ(errorOf(usedOnly), "(no error)");  // used but not required: may be ignored
    other.doc["extensionsRequired"] = {"EXT_made_up"};
    const std::string madeUp = other.writeGltf(path("made-up.gltf"));
    EXPECT_EQ(errorOf(madeUp), madeUp +
                                   ": requires glTF extension EXT_made_up, which this loader "
                                   "does not implement");

    const std::string corpus = kModels + "draco/2CylinderEngine.gltf";
    if (fs::exists(corpus)) {
        EXPECT_EQ(errorOf(corpus), corpus +
                                       ": requires glTF extension KHR_draco_mesh_compression "
                                       "(Draco mesh compression), which this loader does not "
                                       "implement");
    }
}

TEST_F(GltfTest, GltfOneIsRefusedByVersion) {
    const std::string file = path("old.gltf");
    writeBytes(file, R"({"asset": {"version": "1.0"}, "meshes": {}})");
    EXPECT_EQ(errorOf(file), file + ": glTF version 1.0: this loader reads glTF 2.0 only");
}

TEST_F(GltfTest, MalformedJson) {
    const std::string file = path("bad.gltf");
    writeBytes(file, "{ \"asset\": { \"version\": \"2.0\" }, \"nodes\": [ ");
    const std::string error = errorOf(file);
    EXPECT_EQ(error.rfind(file + ": invalid glTF: ", 0), 0u) << error;
    EXPECT_NE(error.find("parse error"), std::string::npos) << error;
    EXPECT_EQ(error.find('\n'), std::string::npos) << error;
}

TEST_F(GltfTest, MalformedGlb) {
    GltfBuilder b;
    b.node({{"mesh", b.mesh({{"POSITION", b.vec3s(kTriangle)}})}});
    b.scene({0});
    const std::string good = b.writeGlb(path("good.glb"));
    const std::string bytes = host_test::readAll(good);

    const std::string version = path("version.glb");
    writeBytes(version, bytes.substr(0, 4) + std::string("\x01\0\0\0", 4) + bytes.substr(8));
    EXPECT_EQ(errorOf(version), version + ": GLB version 1 is not 2");

    const std::string truncated = path("truncated.glb");
    writeBytes(truncated, bytes.substr(0, 12));
    EXPECT_EQ(errorOf(truncated), truncated + ": truncated GLB header");

    // The BIN chunk claims 4 bytes more than the file holds (its header is not counted).
    const std::string longBin = path("longbin.glb");
    std::string changed = bytes;
    uint32_t jsonLength, binLength;
    std::memcpy(&jsonLength, changed.data() + 12, 4);
    std::memcpy(&binLength, changed.data() + 20 + jsonLength, 4);
    binLength += 4;
    std::memcpy(changed.data() + 20 + jsonLength, &binLength, 4);
    writeBytes(longBin, changed);
    EXPECT_EQ(errorOf(longBin), longBin + ": the GLB BIN chunk runs past the end of the file");

    const std::string text = path("text.glb");
    writeBytes(text, "{}");
    EXPECT_EQ(errorOf(text), text + ": not a GLB file (no glTF magic)");
}

TEST_F(GltfTest, IndexOutOfRange) {
    GltfBuilder b;
    const int position = b.vec3s(kTriangle);
    const int index = b.indices(std::vector<uint16_t>{0, 1, 3}, kUShort);
    b.node({{"mesh", b.mesh({{"POSITION", position}}, index)}});
    b.scene({0});
    const std::string file = b.writeGltf(path("range.gltf"));
    EXPECT_EQ(errorOf(file), file +
                                 ": mesh 0 primitive 0: index 3 (element 2 of accessor 1) is "
                                 "out of range for 3 vertices");
}

TEST_F(GltfTest, AccessorPastTheEndOfItsBufferView) {
    GltfBuilder b;
    const int view = b.view(kTriangle);
    b.accessor(view, kFloat, 4, "VEC3");  // 48 bytes from a 36-byte view
    b.node({{"mesh", b.mesh({{"POSITION", 0}})}});
    b.scene({0});
    const std::string file = b.writeGltf(path("past.gltf"));
    EXPECT_EQ(errorOf(file), file +
                                 ": accessor 0 reads past the end of buffer view 0: 4 elements of "
                                 "12 bytes, 12 apart from byte 0, in a view of 36 bytes");

    // The same with an offset: 12 + 36 > 36.
    b.doc["accessors"][0]["count"] = 3;
    b.doc["accessors"][0]["byteOffset"] = 12;
    b.writeGltf(file);
    EXPECT_EQ(errorOf(file), file +
                                 ": accessor 0 reads past the end of buffer view 0: 3 elements of "
                                 "12 bytes, 12 apart from byte 12, in a view of 36 bytes");

    // A stride larger than the view allows for the count.
    b.doc["accessors"][0]["byteOffset"] = 0;
    b.doc["bufferViews"][0]["byteStride"] = 16;
    b.writeGltf(file);
    EXPECT_EQ(errorOf(file), file +
                                 ": accessor 0 reads past the end of buffer view 0: 3 elements of "
                                 "12 bytes, 16 apart from byte 0, in a view of 36 bytes");
}

// A count was allocated for before it was checked against its buffer view: a 430-byte file with
// 2^28 VEC3s took 3.2 GB and 5.5 s to be told it reads past the view, 4294967295 was "out of host
// memory". Checked first now, within 64 MiB of memory.
TEST_F(GltfTest, HugeCountsAreRefusedBeforeAnyAllocation) {
    constexpr uint64_t kHeadroom = 64ull << 20;
    for (uint64_t count : {268435456ull, 536870912ull, 4294967295ull}) {
        SCOPED_TRACE(count);
        GltfBuilder b;
        b.accessor(b.view(kTriangle), kFloat, size_t(count), "VEC3");
        b.node({{"mesh", b.mesh({{"POSITION", 0}})}});
        b.scene({0});
        const std::string file = b.writeGltf(path("count.gltf"));
        EXPECT_LT(fs::file_size(file), 500u);
        EXPECT_EQ(errorWithin(file, kHeadroom),
                  file +
                      ": accessor 0 reads past the end of buffer view 0: " + std::to_string(count) +
                      " elements of 12 bytes, 12 apart from byte 0, in a view of 36 bytes");
    }
    // Indices, and sparse substitutes, the same.
    GltfBuilder b;
    const int position = b.vec3s(kTriangle);
    const int index =
        b.accessor(b.view(std::vector<uint16_t>{0, 1, 2}), kUShort, 4294967295u, "SCALAR");
    b.node({{"mesh", b.mesh({{"POSITION", position}}, index)}});
    b.scene({0});
    const std::string file = b.writeGltf(path("indices.gltf"));
    EXPECT_EQ(errorWithin(file, kHeadroom),
              file +
                  ": accessor 1 reads past the end of buffer view 1: 4294967295 elements of 2 "
                  "bytes, 2 apart from byte 0, in a view of 6 bytes");
    // tinygltf wants a buffer view for indices; sparse substitutes go into the positions.
    b.doc["meshes"][0]["primitives"][0].erase("indices");
    b.doc["accessors"][0] = {{"componentType", kFloat},
                             {"count", 3},
                             {"type", "VEC3"},
                             {"sparse",
                              {{"count", 2147483647},
                               {"indices", {{"bufferView", 1}, {"componentType", kUShort}}},
                               {"values", {{"bufferView", 0}}}}}};
    b.writeGltf(file);
    EXPECT_EQ(errorWithin(file, kHeadroom),
              file + ": accessor 0 has a sparse count or offset out of range");
}

// Zeros the file does not hold (an accessor without a buffer view) are capped: 2^28 of them took
// 3 GiB from 300 bytes.
TEST_F(GltfTest, AccessorsWithoutDataAreCapped) {
    GltfBuilder b;
    b.accessor(-1, kFloat, 268435456, "VEC3");
    b.doc["accessors"][0].erase("bufferView");
    b.node({{"mesh", b.mesh({{"POSITION", 0}})}});
    b.scene({0});
    const std::string file = b.writeGltf(path("zeros.gltf"));
    EXPECT_EQ(errorWithin(file, 64ull << 20),
              file +
                  ": accessor 0 has 268435456 elements and no buffer view (zeros the file does "
                  "not hold), more than the 1048576 this loader accepts");
    b.doc["accessors"][0]["count"] = 3;
    b.writeGltf(file);
    host::MeshData m;
    host::appendGltf(m, file);  // three zeros: one degenerate triangle, placed
    EXPECT_EQ(m.vertices.size(), 3u);
}

// Each node places its mesh once more, so a few bytes of nodes multiply a mesh: the totals are
// checked before anything is placed (40 copies of 2^20 vertices would be 1.25 GiB of them).
TEST_F(GltfTest, WhatTheNodesPlaceIsCappedBeforePlacing) {
    GltfBuilder b;
    b.accessor(-1, kFloat, size_t{1} << 20, "VEC3");  // zeros: 2^20 vertices for 20 bytes
    b.doc["accessors"][0].erase("bufferView");
    b.mesh({{"POSITION", 0}});
    json roots = json::array();
    for (int i = 0; i < 40; ++i) roots.push_back(b.node({{"mesh", 0}}));
    b.scene(roots);
    const std::string file = b.writeGltf(path("copies.gltf"));
    EXPECT_EQ(errorWithin(file, 256ull << 20),
              file +
                  ": its nodes place more than 33554432 vertices in all (each node places its "
                  "mesh once more), the most this loader accepts");
}

// A buffer read from its .bin was held three times on its way (a string grown to twice its size by
// copying, then a copy into the buffer): a 1 GiB .bin peaked at 3.2 GB. It is read once now.
TEST_F(GltfTest, AnExternalBufferIsHeldOnce) {
    constexpr uint64_t kBin = 256ull << 20;
    const std::string bin = path("big.bin");
    writeBytes(bin, std::string(reinterpret_cast<const char*>(kTriangle.data()), 36));
    fs::resize_file(bin, kBin);  // sparse: no disk space
    GltfBuilder b;
    b.doc["bufferViews"] = {{{"buffer", 0}, {"byteLength", 36}}};
    b.accessor(0, kFloat, 3, "VEC3");
    b.node({{"mesh", b.mesh({{"POSITION", 0}})}});
    b.scene({0});
    b.doc["buffers"] = {{{"byteLength", kBin}, {"uri", "big.bin"}}};
    const std::string file = path("big.gltf");
    writeBytes(file, b.doc.dump());
    EXPECT_EQ(errorWithin(file, kBin + (96ull << 20)), "(no error)");
}

TEST_F(GltfTest, BufferViewPastTheEndOfItsBuffer) {
    GltfBuilder b;
    const int position = b.vec3s(kTriangle);
    b.doc["bufferViews"][0]["byteLength"] = 40;
    b.node({{"mesh", b.mesh({{"POSITION", position}})}});
    b.scene({0});
    const std::string file = b.writeGltf(path("view.gltf"));
    EXPECT_EQ(errorOf(file), file + ": buffer view 0 reads past the end of buffer 0");
}

TEST_F(GltfTest, NoPosition) {
    GltfBuilder b;
    b.node({{"mesh", b.mesh({{"NORMAL", b.vec3s(kTriangle)}})}});
    b.scene({0});
    const std::string file = b.writeGltf(path("nopos.gltf"));
    EXPECT_EQ(errorOf(file), file + ": mesh 0 primitive 0 has no POSITION attribute");
}

TEST_F(GltfTest, StructuralErrors) {
    auto write = [&](GltfBuilder& b, const char* name) { return b.writeGltf(path(name)); };
    {
        GltfBuilder b;
        b.node({{"mesh", 4}});
        b.scene({0});
        const std::string file = write(b, "mesh.gltf");
        EXPECT_EQ(errorOf(file), file + ": node 0 references mesh 4, but the file has 0 meshes");
    }
    {
        GltfBuilder b;
        b.node({{"children", {1}}});
        b.node({{"children", {0}}});
        b.scene({0});
        const std::string file = write(b, "cycle.gltf");
        EXPECT_EQ(errorOf(file),
                  file + ": node 0 is reached twice: the node hierarchy must be a tree");
    }
    {
        GltfBuilder b;
        const int position = b.accessor(b.view(kTriangle), kFloat, 4, "VEC2");
        b.node({{"mesh", b.mesh({{"POSITION", position}})}});
        b.scene({0});
        const std::string file = write(b, "type.gltf");
        EXPECT_EQ(errorOf(file), file + ": accessor 0 (POSITION) is VEC2, expected VEC3");
    }
    {
        GltfBuilder b;
        const int position = b.accessor(b.view(kTriangle, 8), kFloat, 2, "VEC3");
        b.node({{"mesh", b.mesh({{"POSITION", position}})}});
        b.scene({0});
        const std::string file = write(b, "stride.gltf");
        EXPECT_EQ(errorOf(file), file +
                                     ": buffer view 0 has byteStride 8, less than the 12-byte "
                                     "elements of accessor 0");
    }
    {
        GltfBuilder b;
        const int position = b.vec3s(kTriangle);
        const int normal = b.vec3s({{0, 0, 1}, {0, 0, 1}});
        b.node({{"mesh", b.mesh({{"POSITION", position}, {"NORMAL", normal}})}});
        b.scene({0});
        const std::string file = write(b, "count.gltf");
        EXPECT_EQ(errorOf(file), file +
                                     ": mesh 0 primitive 0: accessor 1 (NORMAL) has 2 elements "
                                     "but POSITION has 3");
    }
}

TEST_F(GltfTest, AFailedAppendLeavesTheMeshAsItWas) {
    GltfBuilder good;
    good.node({{"mesh", good.mesh({{"POSITION", good.vec3s(kTriangle)}})}});
    good.scene({0});
    host::MeshData m;
    host::appendGltf(m, good.writeGltf(path("good.gltf")));

    // Node 0 places a triangle before node 1's bad mesh reference is found.
    GltfBuilder bad = good;
    bad.node({{"mesh", 9}});
    bad.doc["materials"] = {{{"name", "m"}}};
    bad.scene({0, 1});
    EXPECT_THROW(host::appendGltf(m, bad.writeGltf(path("bad.gltf"))), host::SceneError);
    EXPECT_EQ(m.vertices.size(), 3u);
    EXPECT_EQ(m.indices.size(), 3u);
    EXPECT_EQ(m.primitives.size(), 1u);
    EXPECT_TRUE(m.materials.empty());
    expectVec3(m.bounds.max, {1, 1, 0});
}

// --- Khronos sample models from Debian's assimp-testmodels. ---

TEST(KhronosModels, TwoCylinderEngine) {
    host::MeshData m;
    host::appendGltf(m, kModels + "2CylinderEngine-glTF-Binary/2CylinderEngine.glb");
    // Counted by a separate script that walks the file's scene, nodes and index accessors.
    EXPECT_EQ(m.indices.size() / 3, 121496u);
    EXPECT_EQ(m.primitives.size(), 115u);
    expectVec3(m.bounds.min, {-371.692f, -180.972f, -140.0f}, 0.01f);
    expectVec3(m.bounds.max, {371.692f, 92.0416f, 128.0f}, 0.01f);
    for (uint32_t i : m.indices) ASSERT_LT(i, m.vertices.size());
    for (const host::Vertex& v : m.vertices) ASSERT_NEAR(glm::length(v.normal), 1.0f, 1e-4f);
    EXPECT_TRUE(m.warnings.empty());
}

// Width and height from a PNG's IHDR chunk (big-endian, at bytes 16 and 20).
std::pair<uint32_t, uint32_t> pngSize(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    unsigned char header[24] = {};
    in.read(reinterpret_cast<char*>(header), 24);
    auto be = [&](int at) {
        return uint32_t{header[at]} << 24 | uint32_t{header[at + 1]} << 16 |
               uint32_t{header[at + 2]} << 8 | header[at + 3];
    };
    return {be(16), be(20)};
}

void expectBoxTextured(const host::MeshData& m) {
    ASSERT_EQ(m.vertices.size(), 24u);
    EXPECT_EQ(m.indices.size(), 36u);
    expectVec3(m.bounds.min, {-0.5f, -0.5f, -0.5f});
    expectVec3(m.bounds.max, {0.5f, 0.5f, 0.5f});
    for (const host::Vertex& v : m.vertices) {
        // Cube faces: every normal is an axis, pointing away from the centre.
        EXPECT_NEAR(glm::length(v.normal), 1.0f, 1e-5f);
        EXPECT_NEAR(std::max({std::fabs(v.normal.x), std::fabs(v.normal.y), std::fabs(v.normal.z)}),
                    1.0f, 1e-5f);
        EXPECT_NEAR(glm::dot(v.normal, v.position), 0.5f, 1e-5f);
    }
    ASSERT_EQ(m.materials.size(), 1u);
    ASSERT_EQ(m.materials[0].baseColorTexture, 0);
    ASSERT_EQ(m.textures.size(), 1u);
    const auto [width, height] = pngSize(kModels + "BoxTextured-glTF/CesiumLogoFlat.png");
    EXPECT_EQ(m.textures[0].width, width);
    EXPECT_EQ(m.textures[0].height, height);
    EXPECT_EQ(m.textures[0].rgba.size(), size_t(width) * height * 4);
    EXPECT_TRUE(m.warnings.empty());
}

TEST(KhronosModels, BoxTexturedGltfAndGlbAgree) {
    host::MeshData text, binary;
    host::appendGltf(text, kModels + "BoxTextured-glTF/BoxTextured.gltf");
    host::appendGltf(binary, kModels + "BoxTextured-glTF-Binary/BoxTextured.glb");
    expectBoxTextured(text);
    expectBoxTextured(binary);
    EXPECT_EQ(text.textures[0].name, "CesiumLogoFlat.png");
    ASSERT_EQ(text.vertices.size(), binary.vertices.size());
    for (size_t i = 0; i < text.vertices.size(); ++i) {
        EXPECT_EQ(text.vertices[i].position, binary.vertices[i].position);
        EXPECT_EQ(text.vertices[i].uv, binary.vertices[i].uv);
    }
    EXPECT_EQ(text.indices, binary.indices);
    EXPECT_EQ(text.textures[0].rgba, binary.textures[0].rgba);
}

}  // namespace
