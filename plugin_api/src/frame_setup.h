#pragma once
// An engine's frame description, checked and translated into what the nodes take. Every rule
// broken is an InvalidInput naming the field; nothing is recorded before this passes.
#include <vulkan/vulkan.h>

#include <string>
#include <vector>

#include <lightscatter/lightscatter.h>
#include "shared/light_setup.h"
#include "shared/scattering_params.h"
#include "shared/view_reach.h"

namespace lightscatter::detail {

// How the engine named a light's fields: `light`, `shadowMap`, `lightColor` and `custom` for a
// frame that gave `light`, lights[i].light ... lights[i].settings (or `custom` without own
// settings) for the list; `about` ("lights[i]", or empty) leads a refusal about the light.
struct LightPaths {
    std::string light = "light", shadowMap = "shadowMap", lightColor = "lightColor",
                settings = "custom", about;
};

// One light as the engine gave it: FrameDescription::light (with shadowMap and lightColor), the
// one light of a frame that gives no list, or lights[i]. From here on nothing tells the two apart:
// a frame is a list of lights, in the order of their ids.
struct EdgeLight {
    LightInput input;
    LightPaths paths;  // its fields' names, for refusals
    size_t given = 0;  // its position in the engine's list
    uint64_t id = 0;   // LightInput::id, or its position
};
// The frame's lights in the order of their ids. Refuses a frame that gives both the list and the
// single light's fields, more than kMaxLights, or one id twice.
std::vector<EdgeLight> edgeLights(const FrameDescription& frame);

// A refusal about a light, saying which light it is (paths.about) before naming the field.
InvalidInput aboutLight(const InvalidInput& e, const LightPaths& paths);

// A frame, checked: each light as given and its setup, in the order of their ids.
struct ValidatedFrame {
    std::vector<EdgeLight> given;
    std::vector<ls::LightSetup> lights;
    std::vector<bool> touchesView;  // each light's volume reaches a view ray
};

// Checks everything: the frame's part once, then each light (errors name lights[i].field, or
// light.field); `withImages` false skips the image handles (the budget has none).
ValidatedFrame validateFrame(const FrameDescription& frame, bool withImages = true);
// The frame's part (settings, time, camera, medium, the engine's depth, color, noise and output),
// checked; setupLight (light_checks.h) adds a light's part to it.
ls::LightSetup setupFramePart(const FrameDescription& frame, bool withImages = true);

}  // namespace lightscatter::detail
