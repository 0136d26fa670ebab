#include "method_unit.h"

#include "refusals.h"

namespace ls {

ScatterSpec scatterSpec(const LightSetup& light) {
    ScatterSpec spec;
    spec.light = light.light.kind;
    spec.phase = light.medium.phase;
    spec.minMaxTrees = light.epipolar.minMaxTrees;
    spec.lightColor = light.lightColor;
    spec.bilinearShadow = light.epipolar.bilinearShadow;
    spec.simplifiedModel = light.simplified;
    spec.cubeShadow = cubeShadowed(light);
    return spec;
}

ChainOutputs MethodUnit::addFrameChain(rg::RenderGraph& graph, const std::vector<ChainInputs>& in,
                                       const std::vector<ChainConfig>& configs,
                                       const CompositeTarget& target) const {
    // Only a frame-wide method is asked for one; one light is its own chain otherwise.
    return addChain(graph, in.at(0), configs.at(0), target);
}

}  // namespace ls
