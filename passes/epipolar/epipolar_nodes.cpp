#include "epipolar_nodes.h"

#include <array>
#include <string>

#include "shared/shared_nodes.h"

namespace ls {

EpipolarOutputs addEpipolarNodes(rg::RenderGraph& g, const NodeInputs& in,
                                 const EpipolarSizes& sizes, const EpipolarOptions& options,
                                 const CompositeTarget& target) {
    const rg::ImageRef endPoints = addSliceEndPoints(g, in, sizes);
    const EpipolarCoordinates samples = addEpipolarCoordinates(g, in, sizes, endPoints);
    rg::ImageRef sources = addRefineSamples(g, in, sizes, samples.epipolarZ);
    rg::ImageRef marking = addMarkRayMarchSamples(g, in, sources, samples.epipolarStencil);
    // The shadow map's part: the line of every slice in it, the trees along those lines and the
    // march. A point light's cube map repeats it per face, each face adding its part of every ray
    // to the same samples; the faces' lines and trees die with their march, so they alias.
    rg::BufferRef counts = options.stepCounts;
    struct Lines {
        rg::ImageRef uvFrame, trees;
    };
    auto lines = [&](const NodeInputs& light) {
        const rg::ImageRef uvFrame = addSliceUvFrame(g, light, sizes, endPoints);
        return Lines{uvFrame, options.minMaxTrees ? addMinMaxTrees(g, light, sizes, uvFrame)
                                                  : rg::ImageRef{}};
    };
    auto march = [&](const NodeInputs& light, const Lines& l, rg::ImageRef accumulate,
                     bool overwrite) {
        const EpipolarRayMarch m =
            addEpipolarRayMarch(g, light, sizes,
                                {samples.coordinates, samples.epipolarZ, l.uvFrame, marking,
                                 l.trees, accumulate, counts, overwrite});
        counts = m.stepCounts;
        return m.marched;
    };
    rg::ImageRef marched;
    Lines single;
    std::array<NodeInputs, 6> faces;
    const std::string suffix = g.nameSuffix();
    if (!options.cubeShadow) {
        single = lines(in);
        marched = march(in, single, {}, false);
    } else {
        for (uint32_t face = 0; face < 6; ++face) {
            g.setNameSuffix(suffix + " (cube face " + cubeFaceName(static_cast<int>(face)) + ")");
            faces[face] = in;
            faces[face].shared = in.shared ? in.shared->cubeFaces[face] : nullptr;
            faces[face].constants = addUploadConstants(g, faces[face].shared);
            marched = march(faces[face], lines(faces[face]), marched, false);
        }
        g.setNameSuffix(suffix);
    }
    if (options.inscatterRefinement) {
        // The samples between two marched ones that differ are marched too, before interpolation.
        // A spot's or the sun's lines and trees live on to this march; a cube's faces build theirs
        // again, so that the six faces' trees still alias (the second build costs the trees' time
        // again, not their memory).
        const RefinedSamples refined = addRefineOnInscattering(g, in, sources, marched, marking);
        sources = refined.interpolationSource;
        marking = refined.epipolarStencil;
        if (!options.cubeShadow) {
            g.setNameSuffix(suffix + " (refinement)");
            marched = march(in, single, marched, true);
        } else {
            for (uint32_t face = 0; face < 6; ++face) {
                g.setNameSuffix(suffix + " (refinement, cube face " +
                                cubeFaceName(static_cast<int>(face)) + ")");
                marched = march(faces[face], lines(faces[face]), marched, face == 0);
            }
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
