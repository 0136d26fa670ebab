#include "model_bounds.h"

#include <tiny_gltf.h>
#include <cctype>
#include <cstring>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <stdexcept>
#include <vector>

namespace make_scenes {
namespace {

glm::mat4 nodeMatrix(const tinygltf::Node& node) {
    if (node.matrix.size() == 16) {
        glm::mat4 m;
        for (int i = 0; i < 16; ++i)
            glm::value_ptr(m)[i] = static_cast<float>(node.matrix[static_cast<size_t>(i)]);
        return m;  // glTF and glm are both column-major
    }
    glm::mat4 m(1.0f);
    if (node.translation.size() == 3)
        m[3] = glm::vec4(static_cast<float>(node.translation[0]),
                         static_cast<float>(node.translation[1]),
                         static_cast<float>(node.translation[2]), 1.0f);
    if (node.rotation.size() == 4) {
        const glm::quat q(
            static_cast<float>(node.rotation[3]), static_cast<float>(node.rotation[0]),
            static_cast<float>(node.rotation[1]), static_cast<float>(node.rotation[2]));
        m = m * glm::mat4_cast(q);
    }
    if (node.scale.size() == 3)
        m = m * glm::mat4(glm::vec4(static_cast<float>(node.scale[0]), 0, 0, 0),
                          glm::vec4(0, static_cast<float>(node.scale[1]), 0, 0),
                          glm::vec4(0, 0, static_cast<float>(node.scale[2]), 0),
                          glm::vec4(0, 0, 0, 1));
    return m;
}

void visit(const tinygltf::Model& model, int nodeIndex, const glm::mat4& parent, ModelPoints& out,
           const std::string& path) {
    const tinygltf::Node& node = model.nodes.at(static_cast<size_t>(nodeIndex));
    const glm::mat4 world = parent * nodeMatrix(node);
    if (node.mesh >= 0) {
        for (const tinygltf::Primitive& prim :
             model.meshes.at(static_cast<size_t>(node.mesh)).primitives) {
            if (prim.mode != TINYGLTF_MODE_TRIANGLES && prim.mode != -1) continue;
            const auto it = prim.attributes.find("POSITION");
            if (it == prim.attributes.end()) continue;
            const tinygltf::Accessor& acc = model.accessors.at(static_cast<size_t>(it->second));
            if (acc.componentType != TINYGLTF_COMPONENT_TYPE_FLOAT ||
                acc.type != TINYGLTF_TYPE_VEC3 || acc.bufferView < 0)
                throw std::runtime_error(path + ": unsupported POSITION accessor");
            const tinygltf::BufferView& view =
                model.bufferViews.at(static_cast<size_t>(acc.bufferView));
            const tinygltf::Buffer& buf = model.buffers.at(static_cast<size_t>(view.buffer));
            const size_t stride = acc.ByteStride(view) > 0
                                      ? static_cast<size_t>(acc.ByteStride(view))
                                      : sizeof(float) * 3;
            const size_t base = view.byteOffset + acc.byteOffset;
            if (base + stride * (acc.count - 1) + sizeof(float) * 3 > buf.data.size())
                throw std::runtime_error(path + ": POSITION accessor runs past its buffer");
            for (size_t i = 0; i < acc.count; ++i) {
                float p[3];
                std::memcpy(p, buf.data.data() + base + i * stride, sizeof p);
                out.points.push_back(glm::vec3(world * glm::vec4(p[0], p[1], p[2], 1.0f)));
            }
            out.triangles +=
                (prim.indices >= 0 ? model.accessors.at(static_cast<size_t>(prim.indices)).count
                                   : acc.count) /
                3;
        }
    }
    for (int child : node.children) visit(model, child, world, out, path);
}

}  // namespace

ModelPoints loadModelPoints(const std::string& path) {
    tinygltf::TinyGLTF loader;
    tinygltf::Model model;
    std::string err, warn;
    const bool binary = path.size() >= 4 && path.compare(path.size() - 4, 4, ".glb") == 0;
    const bool ok = binary ? loader.LoadBinaryFromFile(&model, &err, &warn, path)
                           : loader.LoadASCIIFromFile(&model, &err, &warn, path);
    while (!err.empty() && std::isspace(static_cast<unsigned char>(err.back()))) err.pop_back();
    if (!ok) throw std::runtime_error(path + ": " + (err.empty() ? "cannot be read" : err));
    ModelPoints out;
    std::vector<int> roots;
    if (!model.scenes.empty()) {
        const int sceneIndex = model.defaultScene >= 0 ? model.defaultScene : 0;
        roots = model.scenes.at(static_cast<size_t>(sceneIndex)).nodes;
    } else {  // no scene: every node that is nobody's child
        std::vector<bool> isChild(model.nodes.size(), false);
        for (const tinygltf::Node& node : model.nodes)
            for (int child : node.children) isChild.at(static_cast<size_t>(child)) = true;
        for (size_t i = 0; i < model.nodes.size(); ++i)
            if (!isChild[i]) roots.push_back(static_cast<int>(i));
    }
    for (int root : roots) visit(model, root, glm::mat4(1.0f), out, path);
    if (out.points.empty()) throw std::runtime_error(path + ": no triangle positions");
    return out;
}

}  // namespace make_scenes
