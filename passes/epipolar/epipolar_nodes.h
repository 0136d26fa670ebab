#pragma once
// Seed 000's method as render-graph nodes, one function per node. Each declares the auxiliary
// textures of the seed's table with their formats (the stencil textures with the depth-stencil
// format the device offers) and the stencil writes and tests as uses, so the runtime orders the
// passes, derives their barriers and aliases what it can.
#include "shared/node_inputs.h"

namespace ls {

struct EpipolarSizes {
    uint32_t slices = 1024;
    uint32_t samples = 1024;
    uint32_t shadowMapSize = 2048;
};

// The textures of one epipolar frame, as the nodes pass them along.
struct EpipolarTextures {
    rg::ImageRef cameraZ;              // R32F, screen
    rg::ImageRef sliceEndPoints;       // RGBA32F, slices x 1
    rg::ImageRef coordinates;          // RG32F, samples x slices
    rg::ImageRef epipolarZ;            // R32F, samples x slices
    rg::ImageRef epipolarStencil;      // depth-stencil, samples x slices
    rg::ImageRef interpolationSource;  // RG16UI, samples x slices
    rg::ImageRef sliceUvFrame;         // RGBA32F, slices x 1
    rg::ImageRef treeOdd, treeEven;    // RG16F, shadow-map size x slices
    rg::ImageRef marched;              // RGBA16F, samples x slices (in-scattering 1)
    rg::ImageRef interpolated;         // RGBA16F, samples x slices (in-scattering 2)
    rg::ImageRef cameraStencil;        // depth-stencil, screen
    rg::ImageRef screenInscatter;      // RGBA16F, screen
};

void addSliceEndPoints(rg::RenderGraph& g, const NodeInputs& in, const EpipolarSizes& s,
                       EpipolarTextures& t);
void addEpipolarCoordinates(rg::RenderGraph& g, const NodeInputs& in, const EpipolarSizes& s,
                            EpipolarTextures& t);
void addRefineSamples(rg::RenderGraph& g, const NodeInputs& in, const EpipolarSizes& s,
                      EpipolarTextures& t);
void addSliceUvFrame(rg::RenderGraph& g, const NodeInputs& in, const EpipolarSizes& s,
                     EpipolarTextures& t);
void addMinMaxTrees(rg::RenderGraph& g, const NodeInputs& in, const EpipolarSizes& s,
                    EpipolarTextures& t);
void addMarkRayMarchSamples(rg::RenderGraph& g, const NodeInputs& in, EpipolarTextures& t);
void addEpipolarRayMarch(rg::RenderGraph& g, const NodeInputs& in, const EpipolarSizes& s,
                         EpipolarTextures& t);
void addInterpolate(rg::RenderGraph& g, const NodeInputs& in, const EpipolarSizes& s,
                    EpipolarTextures& t);
void addUnwarp(rg::RenderGraph& g, const NodeInputs& in, bool markForFixup, EpipolarTextures& t);
void addFixup(rg::RenderGraph& g, const NodeInputs& in, EpipolarTextures& t);

// The whole chain, from camera-space z to the screen's in-scattering (before compositing).
struct EpipolarOptions {
    bool minMaxTrees = true;
    bool fixup = true;
};
EpipolarTextures addEpipolarNodes(rg::RenderGraph& g, const NodeInputs& in,
                                  const EpipolarSizes& sizes, const EpipolarOptions& options,
                                  rg::ImageRef cameraZ);

}  // namespace ls
