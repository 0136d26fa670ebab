#include "referenced_files.h"

#include <sys/stat.h>

#include <cctype>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <optional>

namespace host {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

// A folder's scan reads its files' text: larger files are not scenes or glTF JSON worth reading,
// and a folder of a million entries is not a scene folder.
constexpr std::uintmax_t kTextCap = 16u << 20;
constexpr size_t kEntryCap = 10000;

std::optional<std::string> smallRegularFile(const fs::path& path) {
    struct stat st {};
    if (::stat(path.c_str(), &st) != 0 || !S_ISREG(st.st_mode) ||
        static_cast<std::uintmax_t>(st.st_size) > kTextCap)
        return std::nullopt;
    std::ifstream in(path, std::ios::binary);
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (!in && !in.eof()) return std::nullopt;
    return text;
}

// glTF URIs are URI references: "my%20floor.png" is the file "my floor.png".
std::string percentDecoded(const std::string& uri) {
    std::string out;
    for (size_t i = 0; i < uri.size(); ++i) {
        if (uri[i] == '%' && i + 2 < uri.size() &&
            std::isxdigit(static_cast<unsigned char>(uri[i + 1])) &&
            std::isxdigit(static_cast<unsigned char>(uri[i + 2]))) {
            out += static_cast<char>(std::stoi(uri.substr(i + 1, 2), nullptr, 16));
            i += 2;
        } else {
            out += uri[i];
        }
    }
    return out;
}

// The JSON chunk of a binary glTF (12-byte header, then a chunk of type "JSON").
std::optional<std::string> glbJson(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    unsigned char head[20];
    if (!in.read(reinterpret_cast<char*>(head), sizeof head)) return std::nullopt;
    uint32_t magic, length, type;
    std::memcpy(&magic, head, 4);
    std::memcpy(&length, head + 12, 4);
    std::memcpy(&type, head + 16, 4);
    if (magic != 0x46546C67u || type != 0x4E4F534Au || length > kTextCap) return std::nullopt;
    std::string text(length, '\0');
    if (!in.read(text.data(), length)) return std::nullopt;
    return text;
}

std::optional<json> parsed(const std::optional<std::string>& text) {
    if (!text) return std::nullopt;
    json j = json::parse(*text, nullptr, false);
    if (j.is_discarded() || !j.is_object()) return std::nullopt;
    return j;
}

void addGltfFiles(const fs::path& gltf, std::vector<ReferencedFile>& out) {
    const bool binary = gltf.extension() == ".glb";
    const std::optional<json> j = parsed(binary ? glbJson(gltf) : smallRegularFile(gltf));
    if (!j) return;
    for (const char* list : {"buffers", "images"}) {
        const auto it = j->find(list);
        if (it == j->end() || !it->is_array()) continue;
        for (const json& entry : *it) {
            if (!entry.is_object()) continue;
            const auto uri = entry.find("uri");
            if (uri == entry.end() || !uri->is_string()) continue;
            const std::string u = uri->get<std::string>();
            if (u.rfind("data:", 0) == 0 || u.empty()) continue;
            out.push_back({(gltf.parent_path() / percentDecoded(u)).lexically_normal().string(),
                           gltf.lexically_normal().string()});
        }
    }
}

void addSceneFiles(const fs::path& scene, std::vector<ReferencedFile>& out) {
    const std::optional<json> j = parsed(smallRegularFile(scene));
    if (!j) return;
    std::vector<std::string> models;
    if (const auto g = j->find("gltf"); g != j->end() && g->is_string())
        models.push_back(g->get<std::string>());
    if (const auto m = j->find("models"); m != j->end() && m->is_array())
        for (const json& model : *m)
            if (model.is_object())
                if (const auto g = model.find("gltf"); g != model.end() && g->is_string())
                    models.push_back(g->get<std::string>());
    for (const std::string& model : models) {
        const fs::path p = (scene.parent_path() / model).lexically_normal();
        out.push_back({p.string(), scene.lexically_normal().string()});
        addGltfFiles(p, out);
    }
    // A light's cookie image ("light" or each of "lights").
    std::vector<const json*> lights;
    if (const auto l = j->find("light"); l != j->end()) lights.push_back(&*l);
    if (const auto l = j->find("lights"); l != j->end() && l->is_array())
        for (const json& light : *l) lights.push_back(&light);
    for (const json* light : lights)
        if (light->is_object())
            if (const auto c = light->find("cookie"); c != light->end() && c->is_string())
                out.push_back(
                    {(scene.parent_path() / c->get<std::string>()).lexically_normal().string(),
                     scene.lexically_normal().string()});
}

}  // namespace

std::vector<ReferencedFile> filesReferencedFrom(const std::string& folder) {
    std::vector<ReferencedFile> out;
    std::error_code ec;
    fs::directory_iterator it(folder.empty() ? "." : folder, ec), end;
    for (size_t n = 0; !ec && it != end && n < kEntryCap; it.increment(ec), ++n) {
        const fs::path& p = it->path();
        const std::string ext = p.extension().string();
        if (ext == ".json")
            addSceneFiles(p, out);
        else if (ext == ".gltf" || ext == ".glb")
            addGltfFiles(p, out);
    }
    return out;
}

}  // namespace host
