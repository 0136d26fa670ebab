#pragma once
// The builds of epipolar's shaders its nodes ask for (the builds: shaders/CMakeLists.txt).
#include <vulkan/vulkan.h>

#include "rendergraph/pipeline.h"
#include "shared/composite_variant.h"
#include "shared/shared_state.h"

namespace ls {

// trees: the min/max trees are read; countSteps: the step-count buffer's build.
rg::ShaderCode rayMarchShader(const ScatterSpec& spec, bool trees, bool countSteps);
// table: the point-light table is read (any light but a directional one); blend: the target is
// blended into as an attachment (addBlendedCompositeTarget), never with a split target.
rg::ShaderCode unwarpShader(bool table, const CompositeVariant& target, bool blend);
rg::ShaderCode minMaxTreesShader(bool cubeShadow);
rg::ShaderCode sliceUvFrameShader(bool cubeShadow);
// What a frame's later light's unwarp and fix-up draw (shaders/epipolar/window_wedge.vert):
// kWedgeVertices vertices, the wedge of a windowed light's lines or the whole viewport.
rg::ShaderCode windowWedgeShader();
inline constexpr uint32_t kWedgeVertices = 15;
// What the first marking and the first march draw with the march list
// (shaders/epipolar/march_cover.vert): marchCoverVertices(P) vertices for P march phases, the
// march-order texels that can hold a ray-marching sample.
rg::ShaderCode marchCoverShader();
inline constexpr uint32_t marchCoverVertices(uint32_t phases) {
    return 6 * (2 * phases - 1);
}

}  // namespace ls
