#include "scene_inputs.h"

namespace host {

void addSceneInputs(OutputSet& outputs, const std::string& scenePath, const SceneDesc& scene,
                    const MeshData& mesh, const std::string& whose) {
    outputs.addInput(whose == "the scene" ? "the scene file" : whose, scenePath);
    for (const std::string& f : mesh.files) outputs.addInput("a file " + whose + " reads", f);
    for (size_t i = 0; i < scene.lightCount(); ++i)
        if (const auto& cookie = scene.lightAt(i).cookie)
            outputs.addInput("a file " + whose + " reads", cookie->name);
}

}  // namespace host
