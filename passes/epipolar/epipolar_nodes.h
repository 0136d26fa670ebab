#pragma once
// Seed 000's method as render-graph nodes, one function per node. Each takes the handles it reads
// and returns the handles it writes, so a signature shows the node's place in the graph. Each
// declares the auxiliary textures of the seed's table with their formats (the stencil textures
// with the depth-stencil format the device offers) and the stencil writes and tests as uses, so
// the runtime orders the passes, derives their barriers and aliases what it can. Every node also
// reads its light's frame constants (ChainContext), and where it says so epipolar's own
// (EpipolarContext) and the light's images (LightImages).
#include "epipolar_constants.h"
#include "shared/chain_context.h"
#include "shared/composite_target.h"

namespace ls {

struct EpipolarSizes {
    uint32_t slices = 1024;
    uint32_t samples = 1024;
    uint32_t marchPhases = 1;  // the march's order (marchPhases in epipolar_constants.h)
    bool marchList = false;    // the tiles' samples marched from a list (marchesFromList)
    // The extent of the march's textures (the marched samples and the march's stencil): the
    // samples x slices, in the march's order (shaders/epipolar/epipolar_constants.glsl).
    VkExtent2D marchExtent() const {
        if (marchPhases <= 1) return {samples, slices};
        const uint32_t across = marchBlocksPerRow(marchPhases);
        return {across * (samples / marchPhases * 4), marchPhases / across * (slices / 4)};
    }
    // The march list's entries: an eighth of the samples the tiles hold ((P - 1)(S / P - 1) a
    // slice; marchListCapacity in shaders/epipolar/epipolar_constants.glsl); none without the list.
    uint32_t marchListCapacity() const {
        return marchList ? (marchPhases - 1) * (samples / marchPhases - 1) * slices / 8 : 0;
    }
};

// Copies this frame's epipolar constants (EpipolarFrame::constants) into a graph buffer
// (vkCmdUpdateBuffer, recorded per frame).
struct UploadEpipolarConstantsInputs {
    rg::HostDataRef<LightFrame> values;  // whose constants (its data: the EpipolarFrame)
};
EpipolarContext addUploadEpipolarConstants(rg::RenderGraph& g,
                                           const UploadEpipolarConstantsInputs& in);

// Entry and exit of each slice's line in NDC: RGBA32F, slices x 1.
struct SliceEndPointsInputs {
    ChainContext chain;
    EpipolarContext epipolar;
};
rg::ImageRef addSliceEndPoints(rg::RenderGraph& g, const SliceEndPointsInputs& in,
                               const EpipolarSizes& s);

// Each sample's NDC position and the camera-space z under it (from frame.depth); invalid samples
// (off the screen, on culled slices) keep z -1.
struct EpipolarCoordinatesInputs {
    ChainContext chain;
    EpipolarContext epipolar;
    rg::ImageRef sliceEndPoints;
};
struct EpipolarCoordinates {
    rg::ImageRef coordinates;  // frame.coordinateFormat (RG16 unorm or RG32F), samples x slices
    rg::ImageRef epipolarZ;    // R32F, samples x slices
};
EpipolarCoordinates addEpipolarCoordinates(rg::RenderGraph& g, const EpipolarCoordinatesInputs& in,
                                           const EpipolarSizes& s);

// The march list (EpipolarSizes::marchList): a storage buffer of a count and the entries of the
// tiles' samples the first march takes (k | slice << 16, shaders/epipolar/epipolar_constants.glsl),
// its count zeroed. Without the list, the count alone (the shaders that read it then never do).
rg::BufferRef addClearMarchList(rg::RenderGraph& g, const EpipolarSizes& s);

// Each sample's two interpolation sources: RG16UI, samples x slices; and the march list, the tiles'
// ray-marching samples appended.
struct RefineSamplesInputs {
    ChainContext chain;
    EpipolarContext epipolar;
    rg::ImageRef epipolarZ;
    rg::BufferRef marchList;  // cleared (addClearMarchList)
};
struct RefinedSamples {
    rg::ImageRef sources;
    rg::BufferRef marchList;
};
RefinedSamples addRefineSamples(rg::RenderGraph& g, const RefineSamplesInputs& in,
                                const EpipolarSizes& s);

// Each slice's line in the shadow map, origin and direction: RGBA32F, slices x 1; a point light's
// cube map: slices x 6, a row per face (zero for a face out of view, as for a slice off the map).
struct SliceUvFrameInputs {
    ChainContext chain;
    EpipolarContext epipolar;
    rg::ImageRef sliceEndPoints;
};
rg::ImageRef addSliceUvFrame(rg::RenderGraph& g, const SliceUvFrameInputs& in,
                             const EpipolarSizes& s);

// The 1D min/max trees of light.shadowMap along each slice's line, every level in one texture:
// RG16F, light.shadowMapSize x slices; a point light's cube map: 6 layers, one per face.
struct MinMaxTreesInputs {
    ChainContext chain;
    EpipolarContext epipolar;
    LightImages light;  // its shadow map and size
    rg::ImageRef sliceUvFrame;
};
rg::ImageRef addMinMaxTrees(rg::RenderGraph& g, const MinMaxTreesInputs& in,
                            const EpipolarSizes& s);

// The march's stencil values (depth-stencil, samples x slices in the march's order: marchTexel in
// shaders/epipolar/epipolar_constants.glsl): the first march's samples, and those the refinement
// on in-scattering differences added.
inline constexpr uint32_t kFirstMarch = 2;
inline constexpr uint32_t kRefinementMarch = 3;

// Marks the ray-marching samples (valid, and their own interpolation source) in the march's
// stencil: a new one with kFirstMarch, or with marchStencil (the refinement's marking) those not
// marked yet with kRefinementMarch. Returns the stencil's new version.
struct MarkRayMarchInputs {
    ChainContext chain;
    EpipolarContext epipolar;
    rg::ImageRef interpolationSource, epipolarZ;
    rg::BufferRef marchList;    // its count marks the tiles' first slots
    rg::ImageRef marchStencil;  // invalid: the first marking
};
rg::ImageRef addMarkRayMarchSamples(rg::RenderGraph& g, const MarkRayMarchInputs& in,
                                    const EpipolarSizes& s);

// Lin (or the shadowed fraction) of the ray-marching samples (options.marks in the march's
// stencil): RGBA16F, samples x slices in the march's order, stored (a storage image: a slot of the
// march list stores its sample's value at the sample's texel); texels of samples not marched are
// left undefined, and no pass reads them. Reads the light's images; without trees
// every sample is marched texel by texel. A point light's cube map is marched in the same pass,
// each ray's part in each face along that face's line and trees. The refinement march writes its
// samples into `accumulate`, keeping the first march's samples.
struct EpipolarRayMarchInputs {
    ChainContext chain;
    EpipolarContext epipolar;
    LightImages light;
    rg::ImageRef coordinates, epipolarZ, sliceUvFrame;
    rg::ImageRef sliceEndPoints;  // read with a point light's cube map only
    rg::ImageRef marchStencil;    // after the marking
    rg::BufferRef marchList;      // the samples the tiles' marked slots march
    rg::ImageRef trees;           // invalid: marched without trees
    rg::ImageRef accumulate;      // invalid: a new texture (the first march)
    // The step counter (step_counts.h), cleared; invalid: the plain variant, nothing counted.
    rg::BufferRef stepCounts;
};
struct EpipolarRayMarchOptions {
    EpipolarSizes sizes;
    uint32_t marks = kFirstMarch;  // the march stencil's value it marches
};
struct EpipolarRayMarch {
    rg::ImageRef marched;
    rg::BufferRef stepCounts;  // the counter's new version; invalid when not counted
};
EpipolarRayMarch addEpipolarRayMarch(rg::RenderGraph& g, const EpipolarRayMarchInputs& in,
                                     const EpipolarRayMarchOptions& options);

// Refinement on in-scattering differences: every sample whose two interpolation sources differ in
// `marched` by more than epipolar.marching.z (relative, per channel) or in validity becomes a
// ray-marching sample (its own source); the refinement's marking then gives the samples added,
// and only them, to a second march. Returns the sources' new version (rewritten in place).
struct RefineOnInscatteringInputs {
    ChainContext chain;
    EpipolarContext epipolar;
    rg::ImageRef interpolationSource, marched, epipolarZ;
};
rg::ImageRef addRefineOnInscattering(rg::RenderGraph& g, const RefineOnInscatteringInputs& in,
                                     const EpipolarSizes& s);

// Every valid sample, interpolated between its two sources: RGBA16F, samples x slices.
struct InterpolateInputs {
    ChainContext chain;
    EpipolarContext epipolar;
    rg::ImageRef interpolationSource, marched, epipolarZ;
};
rg::ImageRef addInterpolate(rg::RenderGraph& g, const InterpolateInputs& in,
                            const EpipolarSizes& s);

// The samples unwarped to the screen and composited into the target (no screen-sized Lin), and with
// markForFixup the pixels no sample could serve left to the fix-up: 0 in a camera stencil where
// every served pixel wrote 1.
struct UnwarpInputs {
    ChainContext chain;  // its constants and depth
    EpipolarContext epipolar;
    LightImages light;  // its table, where given
    rg::ImageRef sliceEndPoints, epipolarZ, interpolated;
    CompositeTarget target;
};
struct UnwarpOptions {
    bool markForFixup = false;
};
struct UnwarpOutputs {
    CompositeOutputs composited;  // the target's new versions
    rg::ImageRef cameraStencil;   // depth-stencil, screen; invalid without markForFixup
};
UnwarpOutputs addUnwarp(rg::RenderGraph& g, const UnwarpInputs& in, const UnwarpOptions& options);

// Marches the pixels marked in cameraStencil on their own and composites them into the target
// (the unwarp's new versions); returns the target's new versions. Reads the light's images.
struct FixupInputs {
    ChainContext chain;
    EpipolarContext epipolar;  // a later light's wedge (the unwarp's)
    LightImages light;
    rg::ImageRef cameraStencil;
    CompositeTarget target;
};
CompositeOutputs addFixup(rg::RenderGraph& g, const FixupInputs& in);

// The whole chain, from the engine's depth to the composited color. With cubeShadow (a point
// light's six-layer shadow map) each pass that reads the map reads its six faces at once: the line
// frames a row per face, the trees a layer per face, and the march each ray's part in each face;
// the fix-up marches the whole cube.
struct EpipolarInputs {
    ChainContext chain;
    LightImages light;
    CompositeTarget target;
    rg::BufferRef stepCounts;  // the step counter, cleared, that the marches add to; invalid: none
};
struct EpipolarOptions {
    EpipolarSizes sizes;
    bool minMaxTrees = true;
    bool fixup = true;
    bool cubeShadow = false;
    // A second, stencil-limited march of the samples between two marched ones that differ
    // (EpipolarConstants::marching.z), before interpolation.
    bool inscatterRefinement = false;
};
// The target's new versions (the chain composites its Lin where the unwarp and the fix-up make
// it), and the step counter's (invalid when not counted).
struct EpipolarOutputs {
    CompositeOutputs composited;
    rg::BufferRef stepCounts;
};
EpipolarOutputs addEpipolarNodes(rg::RenderGraph& g, const EpipolarInputs& in,
                                 const EpipolarOptions& options);

}  // namespace ls
