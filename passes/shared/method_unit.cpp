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

}  // namespace ls
