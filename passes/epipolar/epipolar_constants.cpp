#include "epipolar_constants.h"

#include "min_max_trees.h"
#include "shaders/epipolar/epipolar_bindings.h"
#include "shared/pass_helpers.h"

namespace ls {

float inscatterRefinementOf(const lightscatter::EpipolarSettings& s, bool refinesByDefault) {
    if (s.inscatterRefinementThreshold > 0.0f || !refinesByDefault)
        return s.inscatterRefinementThreshold;
    return kDefaultInscatterRefinement;
}

EpipolarConstants makeEpipolarConstants(const lightscatter::EpipolarSettings& s,
                                        uint32_t shadowMapSize, bool interpolatesLin,
                                        bool refinesByDefault, const glm::vec4& bounds) {
    const bool fraction =
        s.interpolation == lightscatter::Interpolation::ShadowedFraction && !interpolatesLin;
    EpipolarConstants c{};
    c.sampling = {static_cast<float>(s.slices), static_cast<float>(s.samplesPerSlice),
                  static_cast<float>(s.initialSampleStep), s.refinementThreshold};
    c.marching = {static_cast<float>(treeLevels(shadowMapSize)), fraction ? 1.0f : 0.0f,
                  inscatterRefinementOf(s, refinesByDefault), static_cast<float>(s.fixupMaxSteps)};
    c.unwarp = {s.bilateralThreshold, 0.0f, 0.0f, 0.0f};
    c.cubeFaces = {static_cast<float>(kAllCubeFaces), 0.0f, 0.0f, 0.0f};
    c.bounds = bounds;
    const uint32_t phases = marchPhases(s);
    const bool list = marchesFromList(s, c.marching.z > 0.0f);
    c.march = {static_cast<float>(phases), static_cast<float>(marchBlocksPerRow(phases)),
               list ? 1.0f : 0.0f, 0.0f};
    c.window = {0.0f, static_cast<float>(s.slices), 0.0f, 0.0f};  // every slice of the border
    return c;
}

uint32_t marchPhases(const lightscatter::EpipolarSettings& s) {
    const uint32_t p = s.initialSampleStep;
    return p > 1 && s.samplesPerSlice % p == 0 && s.slices % 4 == 0 ? p : 1;
}

bool marchesFromList(const lightscatter::EpipolarSettings& s, bool inscatterRefinement) {
    const uint32_t phases = marchPhases(s);
    return phases > 1 && s.samplesPerSlice / phases >= 2 && s.slices % 16 == 0 &&
           !inscatterRefinement;
}

uint32_t marchBlocksPerRow(uint32_t phases) {
    uint32_t across = 1;
    while (across * across < phases) across *= 2;
    return across;
}

uint32_t EpipolarFrame::facesInView() const {
    uint32_t bits = 0;
    for (int f = 0; f < 6; ++f) bits |= faceInView[f] ? 1u << f : 0u;
    return bits;
}

const EpipolarFrame& epipolarFrameOf(const LightFrame& frame) {
    return static_cast<const EpipolarFrame&>(*frame.data);
}

rg::BindingTable epipolarTable(rg::PassBuilder& pass, const ChainContext& chain,
                               const EpipolarContext& epipolar, VkPipelineStageFlags2 stages) {
    rg::BindingTable table = frameTable(pass, chain.constants, stages);
    table.uniform(LS_BINDING_EPIPOLAR, epipolar.constants, stages);
    return table;
}

}  // namespace ls
