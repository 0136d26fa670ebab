#pragma once
// The builds of the shared nodes' shaders they ask for (the builds: shaders/CMakeLists.txt).
#include <vulkan/vulkan.h>

#include "composite_variant.h"
#include "rendergraph/pipeline.h"
#include "shared_state.h"

namespace ls {

// shadowMap false: an unshadowed light marched for its light color (spec.lightColor).
rg::ShaderCode pixelMarchShader(const ScatterSpec& spec, bool shadowMap = true);
// The march compositing into the engine's color (epipolar's fix-up).
rg::ShaderCode fixupShader(const ScatterSpec& spec, const CompositeVariant& target);
// withLin: a Lin image is read (else only the extinction is applied); addOnly: a frame's later
// light, adding Lin only (its build reads Lin).
rg::ShaderCode compositeShader(bool addOnly, bool withLin, const CompositeVariant& target);
// The split composite's last passes (addSplitComposite, addTransmittanceExport).
rg::ShaderCode compositeBlendShader(bool dualSource);
rg::ShaderCode compositeApplyShader(VkFormat color);
rg::ShaderCode transmittanceExportShader(VkFormat out);
rg::ShaderCode unshadowedShader(const ScatterSpec& spec);

}  // namespace ls
