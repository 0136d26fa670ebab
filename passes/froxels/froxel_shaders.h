#pragma once
// The builds of froxels' shaders its nodes ask for (the builds: shaders/CMakeLists.txt).
#include <vulkan/vulkan.h>

#include "rendergraph/pipeline.h"
#include "shared/composite_variant.h"

namespace ls {

// A light's injection: its shadow map (a point light's cube) and light color, where it has them;
// `slab`, a point or spot light's slices in closed form (its point-light table bound); `noise`, the
// temporal mode's, each froxel (each column, with `slab`) jittered by the blue-noise tile.
rg::ShaderCode froxelInjectShader(bool shadowMap, bool lightColor, bool cube, bool slab,
                                  bool noise);
// The integration; `samples`, the per-pixel history's, which integrates this frame's unblended
// samples in its still frames.
rg::ShaderCode froxelIntegrateShader(bool samples);
// The apply pass, compositing into an engine color of `color`'s format, and into the Lin output.
rg::ShaderCode froxelApplyShader(const CompositeVariant& target, bool pixelHistory);

}  // namespace ls
