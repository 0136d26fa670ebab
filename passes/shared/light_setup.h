#pragma once
// One light of a frame as the methods see it, checked by the plugin API: the camera, the light, the
// medium and the settings in the passes' own terms (the API translates its Settings into these;
// no method sees an engine's types), and what the frame holds around the light.
#include <vulkan/vulkan.h>

#include <string>
#include <vector>

#include "beam_tree/occluders.h"
#include "lightscatter/settings.h"
#include "shared/scattering_params.h"

namespace ls {

struct LightSetup {
    CameraParams camera;
    LightParams light;
    MediumParams medium;
    // The light's settings, checked: the profile's values over the frame's custom (or the light's
    // own). Each method reads its own group (settings.epipolar, ...) and Settings' shared fields.
    lightscatter::Settings settings;
    VkExtent2D screen{0, 0};
    // The pixels whose rays may cross the light's volume (lightScreenRect); the whole screen
    // where it is not known (the budget).
    VkRect2D screenRect{{0, 0}, {0, 0}};
    bool shadowed = false;
    bool lightColor = false;
    bool inscatterOut = false;
    bool engineNoise = false;      // the engine gives the noise image
    bool depthAttachment = false;  // the engine's depth may be a depth attachment
    double timeSeconds = 0.0;
    float preExposure = 1.0f;  // the factor the composite scales Lin by in the engine's color
    size_t occluders = 0;      // the frame's occluders, counted
    // The occluders in double, checked: filled only when the frame's method reads them.
    std::vector<beam::Occluder> beamOccluders;
    // How the engine named this light's fields and settings ("light" and "custom", or
    // "lights[1].light" and "lights[1].settings"), for a refusal to name what the engine set.
    std::string lightPath = "light";
    std::string settingsPath = "custom";
};

// Settings the light's frame asks of its method beyond docs/model.md.
inline bool noisy(const LightSetup& s) {
    return s.settings.noiseAmplitude > 0.0f;  // seed 002's scrolling noise
}
inline bool simplifiedModel(const LightSetup& s) {
    return s.settings.lightModel == lightscatter::LightModel::Simplified;  // seed 004's
}

}  // namespace ls
