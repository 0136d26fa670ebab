#pragma once
// What the scattering nodes need to know about a frame, in docs/model.md's units. The plugin API
// translates an engine's description into these; the nodes never see the engine's types.
#include <vulkan/vulkan.h>

#include <cstdint>
#include <glm/glm.hpp>
#include <vector>

#include "frame_constants.h"
#include "lightscatter/vocabulary.h"
#include "shaders/shared/bindings.h"

namespace ls {

// The vocabulary's words (lightscatter/vocabulary.h), as the API and the shaders name them.
using lightscatter::LightType;
using lightscatter::MiePhase;
using lightscatter::PlaneTarget;
using lightscatter::RangeFalloff;

struct CameraParams {
    glm::mat4 view{1.0f};
    glm::mat4 projection{1.0f};
    float nearPlane = 0.1f;
    float farPlane = 1000.0f;
    bool reversedZ = false;
    bool infiniteFar = false;
};

struct LightParams {
    LightType kind = LightType::Directional;
    glm::vec3 position{0.0f};
    glm::vec3 direction{0.0f, -1.0f, 0.0f};  // unit
    glm::vec3 intensity{1.0f};
    // A spot's cone (KHR_lights_punctual): cos of the outer angle, where the light ends, and of the
    // inner one, where its falloff begins (equal: a hard edge).
    float cosOuter = 0.5f;
    float cosInner = 0.5f;
    float range = 1e30f;         // point and spot
    bool windowedRange = false;  // RangeFalloff::Window: KHR's smooth window to 0 at range
    float radius = 0.05f;
    glm::mat4 shadowViewProj{1.0f};
    glm::mat4 cubeFaceViewProj[6]{};  // point light with a shadow map: world -> clip per face
    uint32_t shadowMapSize = 0;       // 0: unshadowed
    // The light color's larger side (0: none): an unshadowed light's march takes one step per
    // texel of it, as a shadowed one takes one per shadow-map texel.
    uint32_t lightColorSize = 0;
    bool shadowReversedZ = false;
    float shadowDepthBias = 0.0f;  // added to the ray's light-space depth before comparing
};

// A local fog volume (docs/model.md): an oriented box of added density.
struct FogVolumeParams {
    glm::vec3 center{0.0f};
    glm::vec3 halfExtents{1.0f};
    glm::mat3 axes{1.0f};  // columns: the box's local x, y, z in world space (orthonormal)
    float density = 1.0f;
    float fade = 0.0f;  // metres; 0: a hard edge
};

// The medium of docs/model.md. The coefficients are those of density factor 1: a homogeneous
// medium's whole density is folded into them, a non-uniform one's factor m(x) multiplies them at
// each point (shaders/shared/medium.glsl).
struct MediumParams {
    glm::vec3 betaR{0.0f};
    glm::vec3 betaM{0.0f};
    glm::vec3 sigmaA{0.0f};
    float g = 0.0f;
    MiePhase phase = MiePhase::CornetteShanks;
    float maxDistance = 1000.0f;
    // m(x) = density h(y) + sum over volumes, h(y) = exp(-falloff max(0, y - baseHeight)) with
    // heightFog, 1 without.
    float density = 1.0f;
    bool heightFog = false;
    float baseHeight = 0.0f, falloff = 0.0f;
    std::vector<FogVolumeParams> volumes;
    glm::vec3 betaT() const { return betaR + betaM + sigmaA; }
    bool nonUniform() const { return heightFog || !volumes.empty(); }
    // The largest m anywhere: density plus every volume's.
    float maxDensity() const;
};

// The look-up table's shape and scale (shaders/shared/lut.glsl).
// Rows are uniform in log(hEff / r0) from 0 (a ray through the light) to logRange, where
// extinction has made the table negligible (or, without extinction, far beyond where it changes).
struct TableLayout {
    uint32_t width = 512;   // phi
    uint32_t height = 256;  // log(hEff / r0)
    float logRange = 10.0f;
};
TableLayout tableLayoutFor(const MediumParams& medium, float lightRadius, uint32_t width = 512,
                           uint32_t height = 256);

// Where the light (or, behind the camera, the point its shafts converge to) lands in NDC.
struct LightOnScreen {
    glm::vec2 ndc{0.0f};
    float wSign = 1.0f;
    bool onScreen = false;
};
LightOnScreen projectLight(const CameraParams& camera, const LightParams& light);

// What the frame constants hold besides the camera, the light, the medium and the table, as plain
// values the plugin has: the screen and its textures' size, and how Lin is stored and scaled.
struct FrameParams {
    VkExtent2D screen{0, 0};
    // The size of the screen-sized textures, the plugin's maxRenderSize; 0: the screen's.
    VkExtent2D maxScreen{0, 0};
    // Seed 004's simplified light model, I / (a1 r^2 + a0) (read with kSimplifiedModel only).
    float simplifiedA0 = 0.0f;
    float simplifiedA1 = 1.0f;
    float linStorage = 1.0f;   // the power of two Lin is stored with (plugin_api/src/lin_storage.h)
    float preExposure = 1.0f;  // the engine's: the composite adds preExposure Lin to its color
};

FrameConstants makeFrameConstants(const CameraParams& camera, const LightParams& light,
                                  const MediumParams& medium, const FrameParams& params,
                                  const TableLayout& table);

// A point light's cube face by its layer (Vulkan's order +X, -X, +Y, -Y, +Z, -Z), for names.
const char* cubeFaceName(int face);

}  // namespace ls
