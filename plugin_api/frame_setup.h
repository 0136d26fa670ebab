#pragma once
// An engine's frame description, checked and translated into what the nodes take. Every rule
// broken is an InvalidInput naming the field; nothing is recorded before this passes.
#include <vulkan/vulkan.h>

#include <string>
#include <vector>

#include "beam_tree/occluders.h"
#include "shared/scattering_params.h"
#include "lightscatter.h"

namespace lightscatter::detail {

struct FrameSetup {
    ls::CameraParams camera;
    ls::LightParams light;
    ls::MediumParams medium;
    ls::EpipolarSettings epipolar;
    Settings settings;
    VkExtent2D screen{0, 0};
    bool shadowed = false;
    bool lightColor = false;
    bool inscatterOut = false;
    bool noise = false;        // Settings::noiseAmplitude > 0
    bool engineNoise = false;  // FrameDescription::noise given
    bool simplified = false;   // Settings::lightModel == Simplified (seed 004's light model)
    bool depthAttachment = false;  // depth.usage allows a depth attachment (slices)
    double timeSeconds = 0.0;
    size_t occluders = 0;  // FrameDescription::occluders.size()
    // FrameDescription::occluders in double, checked: filled (beamOccluders()) only when the
    // frame's method reads them.
    std::vector<ls::beam::Occluder> beamOccluders;
};

// Checks everything; `withImages` false skips the image handles (the budget has none).
FrameSetup setupFrame(const FrameDescription& frame, bool withImages = true);

// Several lights (FrameDescription::lights): refuses a frame that gives both the list and the single
// light's fields, checks the frame without its lights, then each light as the frame's one light
// (errors name lights[i].field). Returns each light's setup, in order.
std::vector<FrameSetup> setupLights(const FrameDescription& frame, bool withImages = true);
// The frame with lights[i] as its single light (light, shadowMap, lightColor) and no list.
FrameDescription withLight(const FrameDescription& frame, size_t i);
// A message about the frame's single light, retold about lights[i]: "light.x" becomes
// "lights[i].light.x", "shadowMap" and "lightColor" become "lights[i].shadowMap" and so on, and
// the message says which light it is about.
std::string lightMessage(const std::string& message, size_t i, bool ownSettings = false);

void checkSettings(const Settings& s);
void checkOccluders(const std::vector<Occluder>& occluders);
// The occluders checked (at most kMaxOccluders, each box valid) and in double, for the beam tree.
std::vector<ls::beam::Occluder> beamOccluders(const std::vector<Occluder>& occluders);

// Throws InvalidInput naming every feature the plugin needs that `enabled` (the chain an engine
// created its device with) does not turn on.
void checkEnabledFeatures(const VkPhysicalDeviceFeatures2* enabled);

// Whether any light can scatter towards the camera (conservative): false when nothing is emitted,
// nothing scatters, or a spot's cone (within its range, or within the reach of the view) misses
// the view frustum.
bool lightTouchesView(const ls::CameraParams& camera, const ls::LightParams& light,
                      const ls::MediumParams& medium);
// Whether cube face `face` (+X, -X, +Y, -Y, +Z, -Z) of a point light reaches a view ray: its
// square pyramid against the view frustum, each bounded by how far the view reaches (conservative:
// true when unsure).
bool cubeFaceTouchesView(const ls::CameraParams& camera, const ls::LightParams& light,
                         const ls::MediumParams& medium, int face);

}  // namespace lightscatter::detail
