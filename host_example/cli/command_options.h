#pragma once
// Options shared by the commands that render a scene.
#include <string>

#include "cli_args.h"
#include "engine_renderer.h"
#include "options_as_run.h"
#include "rendergraph/device.h"

namespace host {

struct SceneOptions {
    std::string scenePath;
    std::string settingsPath;  // --settings, "" when not given
    RenderOptions render;
    std::optional<VkExtent2D> size;
    rg::DeviceOptions device;
};

// --method, --profile, --settings, --size, --device, --validation; names, numbers, the settings
// file and its noise against the method are checked before any device exists.
SceneOptions takeSceneOptions(Args& args, const char* defaultSize);
VkExtent2D sceneSize(const SceneOptions& o, VkExtent2D fallback);

// The profile named by --profile and --settings together: --settings overlays the file's fields
// on the profile's settings and makes the custom profile; --profile custom needs --settings.
// `settingsPath` is "" when --settings was not given.
RenderOptions profileOptions(const std::string& profile, const std::string& settingsPath);

// The names of the methods that honour it, with auto last where `andAuto`: "a, b and c".
std::string methodsHonouring(bool lightscatter::MethodInfo::*what, bool andAuto = false);
// Names joined by ", ".
std::string joined(const std::vector<std::string>& names);
// Every method's name and every preset's (MethodInfo::presets), as --method takes them.
std::vector<std::string> methodAndPresetNames();

}  // namespace host
