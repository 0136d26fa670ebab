#include "method_unit.h"

#include "refusals.h"

namespace ls {

ScatterSpec scatterSpec(const LightSetup& light) {
    ScatterSpec spec;
    spec.light = light.light.kind;
    spec.phase = light.medium.phase;
    // Trees need a shadow map of 4 texels or more (treesFit).
    spec.minMaxTrees = light.settings.epipolar.minMaxTrees && treesFit(light.light.shadowMapSize);
    spec.lightColor = light.lightColor;
    spec.bilinearShadow = light.settings.shadowFilter == lightscatter::ShadowFilter::Bilinear;
    spec.simplifiedModel = simplifiedModel(light);
    spec.cubeShadow = cubeShadowed(light);
    return spec;
}

ChainOutputs MethodUnit::addFrameChain(rg::RenderGraph& graph, const std::vector<ChainInputs>& in,
                                       const std::vector<ChainConfig>& configs,
                                       const CompositeTarget& target) const {
    // Only a one-per-frame method is asked for one; one light is its own chain otherwise.
    return addChain(graph, in.at(0), configs.at(0), target);
}

}  // namespace ls
