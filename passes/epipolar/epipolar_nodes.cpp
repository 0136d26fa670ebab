#include "epipolar_nodes.h"

#include "shared/shared_nodes.h"

namespace ls {

EpipolarOutputs addEpipolarNodes(rg::RenderGraph& g, const NodeInputs& in,
                                 const EpipolarSizes& sizes, const EpipolarOptions& options,
                                 const CompositeTarget& target) {
    const rg::ImageRef endPoints = addSliceEndPoints(g, in, sizes);
    const EpipolarCoordinates samples = addEpipolarCoordinates(g, in, sizes, endPoints);
    const rg::ImageRef sources = addRefineSamples(g, in, sizes, samples.epipolarZ);
    const rg::ImageRef marking = addMarkRayMarchSamples(g, in, sources, samples.epipolarStencil);
    // The shadow map's part: the line of every slice in it, the trees along those lines and the
    // march. A point light's cube map repeats it per face, each face adding its part of every ray
    // to the same samples; the faces' lines and trees die with their march, so they alias.
    rg::BufferRef counts = options.stepCounts;
    auto march = [&](const NodeInputs& light, rg::ImageRef accumulate) {
        const rg::ImageRef uvFrame = addSliceUvFrame(g, light, sizes, endPoints);
        const rg::ImageRef trees =
            options.minMaxTrees ? addMinMaxTrees(g, light, sizes, uvFrame) : rg::ImageRef{};
        const EpipolarRayMarch m = addEpipolarRayMarch(
            g, light, sizes,
            {samples.coordinates, samples.epipolarZ, uvFrame, marking, trees, accumulate, counts});
        counts = m.stepCounts;
        return m.marched;
    };
    rg::ImageRef marched;
    if (!options.cubeShadow) {
        marched = march(in, {});
    } else {
        const std::string suffix = g.nameSuffix();
        for (uint32_t face = 0; face < 6; ++face) {
            g.setNameSuffix(suffix + " (cube face " + cubeFaceName(static_cast<int>(face)) + ")");
            NodeInputs f = in;
            f.shared = in.shared ? in.shared->cubeFaces[face] : nullptr;
            f.constants = addUploadConstants(g, f.shared);
            marched = march(f, marched);
        }
        g.setNameSuffix(suffix);
    }
    const rg::ImageRef interpolated = addInterpolate(g, in, sizes, sources, marched, marking);
    const UnwarpOutputs screen =
        addUnwarp(g, in, {endPoints, samples.epipolarZ, interpolated}, target, options.fixup);
    if (!options.fixup) return {screen.composited, counts};
    return {addFixup(g, in, screen.cameraStencil,
                     {screen.composited.color, screen.composited.inscatterOut, target.addOnly}),
            counts};
}

}  // namespace ls
