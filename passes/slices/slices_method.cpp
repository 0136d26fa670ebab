#include "slices_method.h"

#include "shared/chain_inputs.h"
#include "shared/refusals.h"
#include "slice_nodes.h"

namespace ls {

MethodCaps SlicesMethod::caps() const {
    MethodCaps c;
    c.budgeted = true;
    return c;
}

std::string SlicesMethod::refusal(const LightSetup& s) const {
    return firstRefusal(
        {refuseCubeShadow(s, name()),
         refuseNoDepthAttachment(s, "method slices (seed 002) depth-tests its planes"),
         refuseSimplified(s, name())});
}

std::unique_ptr<LightData> SlicesMethod::makeData() const {
    return std::make_unique<SliceData>();
}

std::vector<CpuWork> SlicesMethod::prepare(LightData* data, LightFrame&,
                                           const LightSetup& s) const {
    static_cast<SliceData*>(data)->placement =
        placeSlices(s.camera, s.light, s.medium, s.planes, s.timeSeconds);
    return {};
}

ChainOptions SlicesMethod::options(const LightSetup& s, const LightData*,
                                   const ChainOptions*) const {
    return ChainOptions(Options{s.sliceTarget, s.sliceBlur, s.sliceDither, s.noise,
                                s.shadowSampling, s.camera.reversedZ});
}

ChainOutputs SlicesMethod::addChain(rg::RenderGraph& g, const ChainInputs& in, const ChainConfig& c,
                                    const CompositeTarget&) const {
    const Options& o = *c.options.get<Options>();
    const FrameContext frame = frameContext(in, c);
    SlicePlanesInputs planes{frame, {}, {}};
    if (c.shadowed && o.shadowSampling) planes.light.shadowMap = in.shadowMap;
    if (c.shadowed) planes.light.lightColor = in.lightColor;
    planes.light.shadowMapSize = c.shadowMapSize;
    if (o.noise) planes.noise = in.noise;
    SlicePlanesOptions planeOptions;
    planeOptions.target = o.target;
    planeOptions.dither = o.dither;
    planeOptions.reversedZ = o.reversedZ;
    const rg::ImageRef sum = addSlicePlanes(g, planes, planeOptions);
    const SliceResolveOptions resolve{o.target, o.blur, c.light == LightType::Directional};
    ChainOutputs out;
    out.lin = sliceResolveNeeded(resolve) ? addSliceResolve(g, {frame, sum}, resolve) : sum;
    return out;
}

std::string SlicesMethod::summary(const ChainConfig& c) const {
    const Options& o = *c.options.get<Options>();
    return std::string("seed 002's view-aligned slice planes") +
           (o.target == SliceTarget::Rgba8Channels ? " into 8-bit channels"
            : o.target == SliceTarget::Float32     ? " into a float32 target"
                                                   : "") +
           (c.shadowed && !o.shadowSampling ? ", no shadow-map sampling" : "") +
           (o.noise ? ", scrolling noise" : "") + (o.blur ? ", blurred" : "");
}

}  // namespace ls
