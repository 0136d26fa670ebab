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

// A frame, checked: one setup per light (a frame that gives `light` has one, lights[0]), and what
// of the engine's images decides the frame's graph.
struct ValidatedFrame {
    std::vector<ls::LightSetup> lights;
    std::vector<bool> touchesView;  // each light's volume reaches a view ray
    bool list = false;              // the engine gave FrameDescription::lights
};

// Checks everything (setupFrame for a frame of one light, setupLights for the list); `withImages`
// false skips the image handles (the budget has none).
ValidatedFrame validateFrame(const FrameDescription& frame, bool withImages = true);

// The frame's lights as a list: `light`, `shadowMap` and `lightColor` as lights[0] when the frame
// gives no list.
std::vector<LightInput> lightInputs(const FrameDescription& frame);

// A refusal of lights[i] of the list (`list`), saying which light it is about before naming the
// field.
InvalidInput aboutLight(const InvalidInput& e, size_t i, const std::string& list = "lights");

// Checks everything; `withImages` false skips the image handles (the budget has none).
ls::LightSetup setupFrame(const FrameDescription& frame, bool withImages = true);

// Several lights (FrameDescription::lights): refuses a frame that gives both the list and the
// single light's fields, checks the frame's part once, then each light (errors name
// lights[i].field). Returns each light's setup, in order.
std::vector<ls::LightSetup> setupLights(const FrameDescription& frame, bool withImages = true);
// The frame's part (settings, time, camera, medium, the engine's depth, color, noise and output),
// checked; setupLight (light_checks.h) adds a light's part to it.
ls::LightSetup setupFrameWide(const FrameDescription& frame, bool withImages = true);

// Throws InvalidInput naming every feature the plugin needs that `enabled` (the chain an engine
// created its device with) does not turn on.
void checkEnabledFeatures(const VkPhysicalDeviceFeatures2* enabled);

}  // namespace lightscatter::detail
