#include "epipolar_nodes.h"

namespace ls {

EpipolarResult addEpipolarNodes(rg::RenderGraph& g, const NodeInputs& in,
                                const EpipolarSizes& sizes, const EpipolarOptions& options,
                                rg::ImageRef cameraZ) {
    const rg::ImageRef endPoints = addSliceEndPoints(g, in, sizes);
    const EpipolarCoordinates samples = addEpipolarCoordinates(g, in, sizes, endPoints, cameraZ);
    const rg::ImageRef sources = addRefineSamples(g, in, sizes, samples.epipolarZ);
    const rg::ImageRef uvFrame = addSliceUvFrame(g, in, sizes, endPoints);
    const MinMaxTrees trees =
        options.minMaxTrees ? addMinMaxTrees(g, in, sizes, uvFrame) : MinMaxTrees{};
    const rg::ImageRef marking = addMarkRayMarchSamples(g, in, sources, samples.epipolarStencil);
    const rg::ImageRef marched = addEpipolarRayMarch(
        g, in, sizes, {samples.coordinates, samples.epipolarZ, uvFrame, marking, trees});
    const rg::ImageRef interpolated = addInterpolate(g, in, sizes, sources, marched, marking);
    const UnwarpOutputs screen =
        addUnwarp(g, in, {endPoints, samples.epipolarZ, interpolated, cameraZ}, options.fixup);
    if (!options.fixup) return {screen.screenInscatter};
    return {addFixup(g, in, cameraZ, screen.cameraStencil, screen.screenInscatter)};
}

}  // namespace ls
