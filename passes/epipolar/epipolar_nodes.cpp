#include "epipolar_nodes.h"

namespace ls {

EpipolarTextures addEpipolarNodes(rg::RenderGraph& g, const NodeInputs& in,
                                  const EpipolarSizes& sizes, const EpipolarOptions& options,
                                  rg::ImageRef cameraZ) {
    EpipolarTextures t;
    t.cameraZ = cameraZ;
    addSliceEndPoints(g, in, sizes, t);
    addEpipolarCoordinates(g, in, sizes, t);
    addRefineSamples(g, in, sizes, t);
    addSliceUvFrame(g, in, sizes, t);
    if (options.minMaxTrees) addMinMaxTrees(g, in, sizes, t);
    addMarkRayMarchSamples(g, in, t);
    addEpipolarRayMarch(g, in, sizes, t);
    addInterpolate(g, in, sizes, t);
    addUnwarp(g, in, options.fixup, t);
    if (options.fixup) addFixup(g, in, t);
    return t;
}

}  // namespace ls
