#pragma once
// Options shared by the commands that render a scene.
#include <string>

#include "cli_args.h"
#include "engine_renderer.h"
#include "rendergraph/device.h"

namespace host {

struct SceneOptions {
    std::string scenePath;
    RenderOptions render;
    std::optional<VkExtent2D> size;
    rg::DeviceOptions device;
};

// --method, --profile, --size, --device, --validation; names are checked before any device exists.
SceneOptions takeSceneOptions(Args& args, const char* defaultSize);
VkExtent2D sceneSize(const SceneOptions& o, VkExtent2D fallback);

}  // namespace host
