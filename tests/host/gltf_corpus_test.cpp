// Every glTF of Debian's assimp-testmodels (valid files, broken ones, glTF 1.0, extensions): each
// either loads or is refused with one SceneError line naming the file. Nothing else may escape.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <iostream>
#include <map>
#include <typeinfo>

#include "scene/scene.h"

namespace {

namespace fs = std::filesystem;

const fs::path kCorpus = "/usr/share/assimp/models";

// The files of Debian 12's package that are broken or need what this loader does not implement,
// each with what its refusal must say. Every other glTF 2.0 file must load.
const std::map<std::string, std::string> kRefused = {
    {"glTF2/draco/2CylinderEngine.gltf", "requires glTF extension KHR_draco_mesh_compression"},
    {"glTF2/BoxTextured-glTF-techniqueWebGL/BoxTextured.gltf", "extension KHR_technique_webgl"},
    {"glTF2/BoxWithInfinites-glTF-Binary/BoxWithInfinites.glb", "non-finite POSITION"},
    {"glTF2/IndexOutOfRange/IndexOutOfRange.gltf", "is out of range"},
    {"glTF2/IndexOutOfRange/AllIndicesOutOfRange.gltf", "is out of range"},
    {"glTF2/MissingBin/BoxTextured.gltf", "BoxTextured0.bin"},
    {"glTF2/SchemaFailures/sceneWrongType.gltf", "BoxTextured0.bin"},
    {"glTF2/RecursiveNodes/RecursiveNodes.gltf", "reached twice"},
};

std::vector<std::string> corpusFiles() {
    std::vector<std::string> files;
    std::error_code ec;
    for (auto it = fs::recursive_directory_iterator(kCorpus, ec);
         !ec && it != fs::recursive_directory_iterator(); it.increment(ec)) {
        std::string ext = it->path().extension().string();
        std::transform(ext.begin(), ext.end(), ext.begin(),
                       [](unsigned char c) { return char(std::tolower(c)); });
        if ((ext == ".gltf" || ext == ".glb") && it->is_regular_file())
            files.push_back(it->path().string());
    }
    std::sort(files.begin(), files.end());
    return files;
}

struct Outcome {
    bool loaded = false;
    std::string message;  // the SceneError's, when refused
};

Outcome load(const std::string& file) {
    Outcome o;
    host::MeshData mesh;
    try {
        host::appendGltf(mesh, file);
        o.loaded = true;
    } catch (const host::SceneError& e) {
        o.message = e.what();
    } catch (const std::exception& e) {
        ADD_FAILURE() << file << ": " << typeid(e).name() << " escaped the loader: " << e.what();
    } catch (...) {
        ADD_FAILURE() << file << ": a non-std exception escaped the loader";
    }
    if (!o.loaded && !o.message.empty()) {
        EXPECT_EQ(o.message.rfind(file + ": ", 0), 0u) << o.message;
        EXPECT_EQ(o.message.find('\n'), std::string::npos) << o.message;
    }
    return o;
}

}  // namespace

TEST(GltfCorpus, EachFileLoadsOrIsRefusedWithOneLineNamingIt) {
    if (!fs::is_directory(kCorpus))
        GTEST_SKIP() << kCorpus << " is absent (Debian package assimp-testmodels)";
    const auto files = corpusFiles();
    ASSERT_FALSE(files.empty());
    size_t loaded = 0;
    for (const std::string& file : files) {
        const Outcome o = load(file);
        loaded += o.loaded ? 1 : 0;
        std::cout << (o.loaded ? "loaded   " : "refused  ") << (o.loaded ? file : o.message)
                  << "\n";
    }
    std::cout << loaded << " of " << files.size() << " loaded\n";
}
