#include "method_unit.h"

#include <stdexcept>

#include "refusals.h"

namespace ls {

ScatterSpec scatterSpec(const LightSetup& light) {
    ScatterSpec spec;
    spec.light = light.light.kind;
    spec.phase = light.medium.phase;
    spec.lightColor = light.lightColor;
    spec.bilinearShadow = light.settings.shadowFilter == lightscatter::ShadowFilter::Bilinear;
    spec.simplifiedModel = simplifiedModel(light);
    spec.cubeShadow = cubeShadowed(light);
    spec.media = (light.medium.heightFog ? LS_MEDIA_HEIGHT_FOG : 0) |
                 (light.medium.volumes.empty() ? 0 : LS_MEDIA_VOLUMES);
    for (const FogVolumeParams& v : light.medium.volumes)
        if (v.fade > 0.0f) spec.media |= LS_MEDIA_FADES;
    return spec;
}

void MethodUnit::readStepCounts(const void*, uint64_t, lightscatter::StepCounts&) const {
    throw std::logic_error(std::string(name()) + " counts no steps");
}

VolumeLayout MethodUnit::exportedVolume(const LightSetup&, VkExtent2D) const {
    throw std::logic_error(std::string(name()) + " exports no volume");
}

const ChainLight& onlyLight(ChainLights lights, const char* method) {
    if (lights.size() != 1)
        throw std::logic_error(std::string(method) + ": a per-light chain was given " +
                               std::to_string(lights.size()) + " lights");
    return lights[0];
}

}  // namespace ls
