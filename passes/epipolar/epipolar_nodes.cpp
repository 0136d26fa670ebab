#include "epipolar_nodes.h"

#include <string>

namespace ls {

EpipolarOutputs addEpipolarNodes(rg::RenderGraph& g, const EpipolarInputs& in,
                                 const EpipolarOptions& options) {
    const EpipolarSizes& sizes = options.sizes;
    const ChainContext& chain = in.chain;
    const EpipolarContext epipolar = addUploadEpipolarConstants(g, {chain.values});
    const rg::ImageRef endPoints = addSliceEndPoints(g, {chain, epipolar}, sizes);
    const EpipolarCoordinates samples =
        addEpipolarCoordinates(g, {chain, epipolar, endPoints}, sizes);
    const RefinedSamples refined = addRefineSamples(
        g, {chain, epipolar, samples.epipolarZ, addClearMarchList(g, sizes)}, sizes);
    rg::ImageRef sources = refined.sources;
    const rg::BufferRef list = refined.marchList;
    rg::ImageRef marking =
        addMarkRayMarchSamples(g, {chain, epipolar, sources, samples.epipolarZ, list, {}}, sizes);
    // The shadow map's part: the line of every slice in it, the trees along those lines and the
    // march (a point light's cube map: the six faces' in each pass). Both marches read the same
    // lines and trees.
    const rg::ImageRef uvFrame = addSliceUvFrame(g, {chain, epipolar, endPoints}, sizes);
    const rg::ImageRef trees = options.minMaxTrees
                                   ? addMinMaxTrees(g, {chain, epipolar, in.light, uvFrame}, sizes)
                                   : rg::ImageRef{};
    rg::BufferRef counts = in.stepCounts;
    auto march = [&](rg::ImageRef accumulate, uint32_t marks) {
        const EpipolarRayMarch m =
            addEpipolarRayMarch(g,
                                {chain, epipolar, in.light, samples.coordinates, samples.epipolarZ,
                                 uvFrame, endPoints, marking, list, trees, accumulate, counts},
                                {sizes, marks});
        counts = m.stepCounts;
        return m.marched;
    };
    rg::ImageRef marched = march({}, kFirstMarch);
    if (options.inscatterRefinement) {
        // The samples between two marched ones that differ are marched too, before interpolation.
        sources = addRefineOnInscattering(g, {chain, epipolar, sources, marched, samples.epipolarZ},
                                          sizes);
        const std::string suffix = g.nameSuffix();
        g.setNameSuffix(suffix + " (refinement)");
        marking = addMarkRayMarchSamples(
            g, {chain, epipolar, sources, samples.epipolarZ, list, marking}, sizes);
        marched = march(marched, kRefinementMarch);
        g.setNameSuffix(suffix);
    }
    const rg::ImageRef interpolated =
        addInterpolate(g, {chain, epipolar, sources, marched, samples.epipolarZ}, sizes);
    const UnwarpOutputs screen = addUnwarp(
        g, {chain, epipolar, in.light, endPoints, samples.epipolarZ, interpolated, in.target},
        {options.fixup});
    if (!options.fixup) return {screen.composited, counts};
    return {addFixup(g, {chain, epipolar, in.light, screen.cameraStencil,
                         targetAfter(screen.composited, in.target.addOnly)}),
            counts};
}

}  // namespace ls
