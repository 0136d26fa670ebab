#pragma once
// Seed 002 (Mitchell, "Light Shaft Rendering") as nodes: view-aligned planes across the light's
// volume, additively blended into an accumulation target and depth-tested against the engine's
// depth, then resolved into Lin. And the plugin's own tiling noise, made once.
#include <memory>

#include "plane_geometry.h"
#include "shared/chain_context.h"

namespace ls {

// Where this frame's planes go (the method's LightData), placed on the CPU before each frame is
// recorded; the nodes read it from the frame's LightFrame when they record.
struct PlaneData final : LightData {
    PlanePlacement placement;
};
const PlanePlacement& placementOf(const LightFrame& frame);

struct PlanesInputs {
    ChainContext chain;  // its constants, and the depth: a read-only depth attachment
    // light.shadowMap invalid: no shadow-map sampling; light.lightColor: the cookie, projected with
    // the light's shadowViewProjection (with a shadow map or without), invalid without one. The
    // table is not read.
    LightImages light;
    rg::ImageRef noise;  // tiling noise (red, green layers); invalid: no noise
};

struct PlanesOptions {
    PlaneTarget target = PlaneTarget::Float16;
    bool dither = false;     // Rgba8Channels: stochastic rounding of each plane's share
    bool reversedZ = false;  // the engine's depth convention, for the depth test's direction
};

// Returns the planes' sum: R16G16B16A16_SFLOAT or R32G32B32A32_SFLOAT (Lin, rgb), or R8G8B8A8_UNORM
// (luminance, one quarter of the planes per channel), screen-sized.
rg::ImageRef addPlanes(rg::RenderGraph& graph, const PlanesInputs& in,
                       const PlanesOptions& options);

struct PlaneResolveInputs {
    ChainContext chain;     // its constants, and the depth: where each pixel's ray ends
    rg::ImageRef planeSum;  // addPlanes' result
};

struct PlaneResolveOptions {
    PlaneTarget target = PlaneTarget::Float16;
    uint32_t blurRadius = 0;  // pixels; 0: no blur
    bool closedFormOutsideSlab =
        false;  // directional lights: add the rays' parts outside the planes
};

// Whether the planes' sum needs resolving, or already is Lin.
bool planeResolveNeeded(const PlaneResolveOptions& options);

// Returns Lin (R16G16B16A16_SFLOAT, screen).
rg::ImageRef addPlaneResolve(rg::RenderGraph& graph, const PlaneResolveInputs& in,
                             const PlaneResolveOptions& options);

}  // namespace ls
