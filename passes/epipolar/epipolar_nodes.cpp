#include "epipolar_nodes.h"

#include <array>
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
    rg::ImageRef sources = addRefineSamples(g, {chain, epipolar, samples.epipolarZ}, sizes);
    rg::ImageRef marking =
        addMarkRayMarchSamples(g, {chain, epipolar, sources, samples.epipolarZ, {}}, sizes);
    // The shadow map's part: the line of every slice in it, the trees along those lines and the
    // march. A point light's cube map repeats it per face, each face adding its part of every ray
    // to the same samples; the faces' lines and trees die with their march, so they alias.
    rg::BufferRef counts = in.stepCounts;
    struct Lines {
        rg::ImageRef uvFrame, trees;
    };
    // Each takes the light's epipolar constants, or a cube face's.
    auto lines = [&](const EpipolarContext& e) {
        const rg::ImageRef uvFrame = addSliceUvFrame(g, {chain, e, endPoints}, sizes);
        return Lines{uvFrame, options.minMaxTrees
                                  ? addMinMaxTrees(g, {chain, e, in.light, uvFrame}, sizes)
                                  : rg::ImageRef{}};
    };
    auto march = [&](const EpipolarContext& e, const Lines& l, rg::ImageRef accumulate,
                     bool overwrite, uint32_t marks) {
        const EpipolarRayMarch m =
            addEpipolarRayMarch(g,
                                {chain, e, in.light, samples.coordinates, samples.epipolarZ,
                                 l.uvFrame, marking, l.trees, accumulate, counts},
                                {sizes, overwrite, marks});
        counts = m.stepCounts;
        return m.marched;
    };
    rg::ImageRef marched;
    Lines single;
    std::array<EpipolarContext, 6> faces;
    const std::string suffix = g.nameSuffix();
    if (!options.cubeShadow) {
        single = lines(epipolar);
        marched = march(epipolar, single, {}, false, kFirstMarch);
    } else {
        for (uint32_t face = 0; face < 6; ++face) {
            g.setNameSuffix(suffix + " (cube face " + cubeFaceName(static_cast<int>(face)) + ")");
            faces[face] = addUploadEpipolarConstants(g, {chain.values, static_cast<int>(face)});
            marched = march(faces[face], lines(faces[face]), marched, false, kFirstMarch);
        }
        g.setNameSuffix(suffix);
    }
    if (options.inscatterRefinement) {
        // The samples between two marched ones that differ are marched too, before interpolation.
        // A spot's or the sun's lines and trees live on to this march; a cube's faces build theirs
        // again, so that the six faces' trees still alias (the second build costs the trees' time
        // again, not their memory).
        sources = addRefineOnInscattering(g, {chain, epipolar, sources, marched, samples.epipolarZ},
                                          sizes);
        g.setNameSuffix(suffix + " (refinement)");
        marking = addMarkRayMarchSamples(g, {chain, epipolar, sources, samples.epipolarZ, marking},
                                         sizes);
        if (!options.cubeShadow) {
            marched = march(epipolar, single, marched, true, kRefinementMarch);
        } else {
            for (uint32_t face = 0; face < 6; ++face) {
                g.setNameSuffix(suffix + " (refinement, cube face " +
                                cubeFaceName(static_cast<int>(face)) + ")");
                marched =
                    march(faces[face], lines(faces[face]), marched, face == 0, kRefinementMarch);
            }
        }
        g.setNameSuffix(suffix);
    }
    const rg::ImageRef interpolated =
        addInterpolate(g, {chain, epipolar, sources, marched, samples.epipolarZ}, sizes);
    const UnwarpOutputs screen = addUnwarp(
        g, {chain, epipolar, in.light, endPoints, samples.epipolarZ, interpolated, in.target},
        {options.fixup});
    if (!options.fixup) return {screen.composited, counts};
    return {addFixup(g, {chain, in.light, screen.cameraStencil,
                         targetAfter(screen.composited, in.target.addOnly)}),
            counts};
}

}  // namespace ls
