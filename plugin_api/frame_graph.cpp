#include "frame_graph.h"

#include <algorithm>

#include "analytic/analytic_node.h"
#include "brute_force/brute_force_node.h"
#include "cone_march/cone_march_node.h"
#include "epipolar/epipolar_nodes.h"
#include "epipolar/step_counts.h"
#include "shared/composite_target.h"
#include "shared/shared_nodes.h"

namespace lightscatter::detail {

bool GraphConfig::operator==(const GraphConfig& o) const {
    return method == o.method && light == o.light && shadowed == o.shadowed &&
           touchesView == o.touchesView && minMaxTrees == o.minMaxTrees && fixup == o.fixup &&
           inscatterRefinement == o.inscatterRefinement && slices == o.slices &&
           samples == o.samples && shadowMapSize == o.shadowMapSize &&
           screen.width == o.screen.width && screen.height == o.screen.height &&
           depthStencil == o.depthStencil && coordinates == o.coordinates && depth == o.depth &&
           color == o.color && shadowMap == o.shadowMap && lightColor == o.lightColor &&
           inscatterOut == o.inscatterOut && table == o.table && extinction == o.extinction &&
           coneSamples == o.coneSamples && coneLimited == o.coneLimited &&
           coneJitter == o.coneJitter && shadowSampling == o.shadowSampling &&
           sliceTarget == o.sliceTarget && sliceBlur == o.sliceBlur &&
           sliceDither == o.sliceDither && beamCapacity == o.beamCapacity &&
           reversedZ == o.reversedZ && noise == o.noise && engineNoise == o.engineNoise &&
           poisonTransients == o.poisonTransients && countSteps == o.countSteps &&
           lights == o.lights;
}

ls::SliceAccumulation sliceAccumulation(SliceTarget target) {
    switch (target) {
        case SliceTarget::Float32: return ls::SliceAccumulation::Float32;
        case SliceTarget::Rgba8Channels: return ls::SliceAccumulation::Rgba8Channels;
        case SliceTarget::Float16: break;
    }
    return ls::SliceAccumulation::Float16;
}

VkFormat stencilFormat(const rg::DeviceCaps& caps) {
    return rg::firstSupported(caps, {VK_FORMAT_S8_UINT, VK_FORMAT_D24_UNORM_S8_UINT, VK_FORMAT_D32_SFLOAT_S8_UINT},
                              VK_FORMAT_FEATURE_2_DEPTH_STENCIL_ATTACHMENT_BIT);
}

VkFormat coordinateFormat(const rg::DeviceCaps& caps) {
    const VkFormat f = rg::firstSupported(caps, {VK_FORMAT_R16G16_UNORM, VK_FORMAT_R32G32_SFLOAT},
                                          VK_FORMAT_FEATURE_2_COLOR_ATTACHMENT_BIT);
    return f == VK_FORMAT_UNDEFINED ? VK_FORMAT_R32G32_SFLOAT : f;
}

rg::ImportedBuffer stepCountImport(VkBuffer buffer, uint32_t slices) {
    rg::ImportedBuffer b;
    b.buffer = buffer;
    b.size = ls::stepCountBytes(slices);
    b.usage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT;
    b.initialStages = b.finalStages = VK_PIPELINE_STAGE_2_HOST_BIT;
    b.initialAccess = b.finalAccess = VK_ACCESS_2_HOST_READ_BIT;
    return b;
}

rg::ImportedImage importDescription(const ImageInput& in) {
    rg::ImportedImage d;
    d.image = in.image;
    d.format = in.format;
    d.extent = in.extent;
    d.arrayLayers = in.arrayLayers;
    d.usage = in.usage;
    d.initialLayout = in.layout;
    d.initialStages = in.stages;
    d.initialAccess = in.access;
    d.finalLayout = in.finalLayout;
    d.finalStages = in.finalStages;
    d.finalAccess = in.finalAccess;
    return d;
}

rg::ImportedImage persistentImport(const ImportState& s, VkImage image) {
    rg::ImportedImage d = importDescription(s);
    d.image = image;
    d.initialStages = d.finalStages = VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT | VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT;
    d.initialAccess = VK_ACCESS_2_NONE;
    d.finalAccess = VK_ACCESS_2_SHADER_SAMPLED_READ_BIT;
    return d;
}

ImportState ownNoiseState() {
    return {kNoiseFormat, kNoiseExtent, VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_STORAGE_BIT,
            VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
}

rg::ImportedImage importDescription(const ImportState& s) {
    rg::ImportedImage d;
    d.format = s.format;
    d.extent = s.extent;
    d.arrayLayers = s.arrayLayers;
    d.usage = s.usage;
    d.initialLayout = s.layout;
    d.finalLayout = s.finalLayout;
    return d;
}

namespace {

// The step counter, imported and cleared when the frame counts; invalid otherwise.
rg::BufferRef clearedStepCounter(rg::RenderGraph& g, const GraphConfig& c, FrameGraph& fg) {
    if (!c.countSteps) return {};
    fg.stepCounts =
        g.importBuffer("ray-march step counts", stepCountImport(VK_NULL_HANDLE, c.slices));
    return ls::addClearStepCounts(g, fg.stepCounts);
}

// Every frame's graph, one light or several: the engine's depth, color and optional Lin output
// imported, and the node inputs that follow from the configuration (screen, formats).
ls::NodeInputs importEngineImages(rg::RenderGraph& g, const GraphConfig& c, FrameGraph& fg, ls::Shared shared) {
    ls::NodeInputs in;
    in.shared = std::move(shared);
    in.screen = c.screen;
    in.depthStencil = c.depthStencil;
    in.coordinateFormat = c.coordinates;
    fg.depth = in.depth = g.importImage("engine depth", importDescription(c.depth));
    fg.color = g.importImage("engine color", importDescription(c.color));
    if (c.inscatterOut.format != VK_FORMAT_UNDEFINED)
        fg.inscatterOut = g.importImage("in-scattering output", importDescription(c.inscatterOut));
    return in;
}

// Several lights: one chain per light whose volume reaches the view, one after the other. The first
// chain's composite applies the extinction and adds its Lin; each later chain adds its Lin to the
// color (and to inscatterOut) as soon as it is done, so that its transients are dead before the
// next chain starts and the next one may reuse their memory: no sum image is kept.
FrameGraph buildLightsGraph(const GraphConfig& c, const std::vector<ls::Shared>& lightShared) {
    FrameGraph fg;
    fg.graph = std::make_unique<rg::RenderGraph>();
    rg::RenderGraph& g = *fg.graph;
    g.setScreenExtent(c.screen);
    auto sharedOf = [&](size_t i) { return i < lightShared.size() ? lightShared[i] : ls::Shared{}; };

    ls::NodeInputs base = importEngineImages(g, c, fg, sharedOf(0));
    fg.lights.resize(c.lights.size());
    bool anyTouches = false;
    for (size_t i = 0; i < c.lights.size(); ++i) {
        const LightChainConfig& l = c.lights[i];
        const std::string which = " (light " + std::to_string(i) + ")";
        if (l.shadowMap.format != VK_FORMAT_UNDEFINED)
            fg.lights[i].shadowMap = g.importImage("engine shadow map" + which, importDescription(l.shadowMap));
        if (l.lightColor.format != VK_FORMAT_UNDEFINED)
            fg.lights[i].lightColor = g.importImage("light color" + which, importDescription(l.lightColor));
        anyTouches = anyTouches || l.touchesView;
    }
    if (!anyTouches && !c.extinction && !fg.inscatterOut.valid()) {
        fg.summary = "no light scatters and nothing absorbs: no pass at all";
        return fg;
    }
    // The camera and the medium are every light's: light 0's constants serve the composite.
    base.constants = ls::addUploadConstants(g, base.shared);

    rg::ImageRef color = fg.color, linOut = fg.inscatterOut;
    rg::BufferRef counts =
        c.method == Method::Epipolar ? clearedStepCounter(g, c, fg) : rg::BufferRef{};
    size_t chains = 0;
    for (size_t i = 0; i < c.lights.size(); ++i) {
        const LightChainConfig& l = c.lights[i];
        if (!l.touchesView) continue;  // a light whose volume misses the view costs nothing
        // Each chain's resources and passes are named for its light.
        g.setNameSuffix(" (light " + std::to_string(i) + ")");
        ls::NodeInputs in = base;
        in.shared = sharedOf(i);
        in.constants = i == 0 ? base.constants : ls::addUploadConstants(g, in.shared);
        in.shadowMapSize = l.shadowMapSize;
        if (l.light != ls::LightKind::Directional)
            fg.lights[i].table = in.table = g.importImage("point-light table", importDescription(l.table));
        if (l.shadowed) {
            in.shadowMap = fg.lights[i].shadowMap;
            in.lightColor = fg.lights[i].lightColor;
        }
        // The first chain's composite applies the extinction; the others add their Lin. Epipolar
        // composites in its own unwarp and fix-up; the others leave a screen Lin to a composite.
        const ls::CompositeTarget target{color, linOut, chains != 0};
        ls::CompositeOutputs o;
        if (l.shadowed && c.method == Method::Epipolar) {
            ls::EpipolarSizes sizes{l.slices, l.samples, l.shadowMapSize};
            ls::EpipolarOptions options{l.minMaxTrees, l.fixup, l.light == ls::LightKind::Point,
                                        counts, l.inscatterRefinement};
            const ls::EpipolarOutputs e = ls::addEpipolarNodes(g, in, sizes, options, target);
            o = e.composited;
            counts = e.stepCounts;
        } else {
            const rg::ImageRef lin = l.shadowed ? ls::addBruteForce(g, in) : ls::addUnshadowed(g, in);
            o = chains == 0 ? ls::addComposite(g, in, color, lin, linOut) : ls::addInscatter(g, in, color, lin, linOut);
        }
        color = o.color;
        linOut = o.inscatterOut;
        ++chains;
    }
    g.setNameSuffix({});
    if (chains == 0) ls::addComposite(g, base, color, {}, linOut);  // extinction only
    const bool anyFixup = std::any_of(c.lights.begin(), c.lights.end(),
                                      [](const LightChainConfig& l) { return l.fixup; });
    const bool anyRefined = std::any_of(c.lights.begin(), c.lights.end(),
                                        [](const LightChainConfig& l) { return l.inscatterRefinement; });
    // Cleared even when no chain marches, so that the frame's counts are its own.
    if (counts.valid()) g.markOutput(counts);
    fg.summary =
        std::to_string(c.lights.size()) + " lights, " + std::to_string(chains) +
        " reaching the view: " +
        (c.method == Method::BruteForce
             ? "brute-force ray marching"
             : std::string("epipolar sampling") +
                   (anyRefined ? ", refined on in-scattering differences" : "") +
                   (anyFixup ? ", fix-up" : "")) +
        " per shadowed light, closed form per unshadowed one; the first composite applies the "
        "extinction, each light's Lin is added to the color as its chain ends";
    return fg;
}

}  // namespace

FrameGraph buildFrameGraph(const GraphConfig& c, const ls::Shared& shared, ls::SlicePlacementRef slices,
                           ls::BeamTreeFrameRef beams, const std::vector<ls::Shared>& lightShared) {
    if (!c.lights.empty()) return buildLightsGraph(c, lightShared);
    FrameGraph fg;
    fg.graph = std::make_unique<rg::RenderGraph>();
    rg::RenderGraph& g = *fg.graph;
    g.setScreenExtent(c.screen);

    ls::NodeInputs in = importEngineImages(g, c, fg, shared);
    in.shadowMapSize = c.shadowMapSize;
    // The engine's shadow map and light color are imported whenever given, so that they are left
    // in the layouts the engine asked for even where no node reads them.
    if (c.shadowMap.format != VK_FORMAT_UNDEFINED)
        fg.shadowMap = g.importImage("engine shadow map", importDescription(c.shadowMap));
    if (c.lightColor.format != VK_FORMAT_UNDEFINED)
        fg.lightColor = g.importImage("light color", importDescription(c.lightColor));
    if (!c.touchesView && !c.extinction && !fg.inscatterOut.valid()) {
        fg.summary = "no light scatters and nothing absorbs: no pass at all";
        return fg;
    }
    in.constants = ls::addUploadConstants(g, shared);

    rg::ImageRef lin;
    if (!c.touchesView) {
        fg.summary = "the light reaches no view ray (or nothing scatters): extinction only";
    } else if (c.method == Method::Analytic) {
        lin = ls::addAnalytic(g, shared, {in.constants, in.depth});
        fg.summary = "seed 001's arctangent closed form per pixel";
    } else if (c.method == Method::BeamTreeAnalytic) {
        fg.table = g.importImage("point-light table", importDescription(c.table));
        ls::BeamTreeInputs beam{in.constants, in.depth, fg.table, {}, {}};
        if (c.shadowed) {
            beam.shadowMap = fg.shadowMap;
            beam.lightColor = fg.lightColor;
        }
        lin = ls::addBeamTreeHybrid(g, shared, beams, beam, {c.beamCapacity, c.reversedZ});
        fg.summary = std::string("seed 004's beam tree: lit pyramids in closed form") +
                     (c.shadowed ? ", uncertain space sampled by planes with the shadow map"
                                 : ", uncertain space sampled by planes as lit (no shadow map)");
    } else if (c.method == Method::BeamTreeSampling) {
        ls::BeamTreeSamplingInputs beam{in.constants, in.depth, {}, {}};
        if (c.shadowed) {
            beam.shadowMap = fg.shadowMap;
            beam.lightColor = fg.lightColor;
        }
        lin = ls::addBeamTreeSampling(g, shared, beams, beam, {c.beamCapacity, c.reversedZ});
        fg.summary = std::string("seed 004's beam tree clipping slices' planes: lit parts without shadow look-ups") +
                     (c.shadowed ? ", uncertain parts with the shadow map"
                                 : ", uncertain parts as lit (no shadow map)");
    } else if (c.method == Method::Slices) {
        ls::SlicePlanesInputs planes{in.constants, in.depth, {}, {}, {}};
        if (c.shadowed && c.shadowSampling) planes.shadowMap = fg.shadowMap;
        if (c.shadowed) planes.lightColor = fg.lightColor;
        if (c.noise) {
            fg.noise = g.importImage(c.engineNoise.format != VK_FORMAT_UNDEFINED ? "engine noise" : "tiling noise",
                                     importDescription(c.engineNoise.format != VK_FORMAT_UNDEFINED ? c.engineNoise
                                                                                                 : ownNoiseState()));
            planes.noise = fg.noise;
        }
        ls::SlicePlanesOptions planeOptions;
        planeOptions.target = c.sliceTarget;
        planeOptions.dither = c.sliceDither;
        planeOptions.reversedZ = c.reversedZ;
        const rg::ImageRef sum = ls::addSlicePlanes(g, shared, slices, planes, planeOptions);
        const ls::SliceResolveOptions resolve{c.sliceTarget, c.sliceBlur, c.light == ls::LightKind::Directional};
        lin = ls::sliceResolveNeeded(resolve) ? ls::addSliceResolve(g, shared, slices, {in.constants, in.depth, sum}, resolve)
                                              : sum;
        fg.summary = std::string("seed 002's view-aligned slice planes") +
                     (c.sliceTarget == ls::SliceAccumulation::Rgba8Channels ? " into 8-bit channels"
                      : c.sliceTarget == ls::SliceAccumulation::Float32 ? " into a float32 target" : "") +
                     (c.shadowed && !c.shadowSampling ? ", no shadow-map sampling" : "") +
                     (c.noise ? ", scrolling noise" : "") + (c.sliceBlur ? ", blurred" : "");
    } else if (c.method == Method::ConeMarch) {
        ls::ConeMarchInputs cone{in.constants, in.depth, {}, fg.lightColor};
        if (c.shadowed && c.shadowSampling) cone.shadowMap = fg.shadowMap;
        lin = ls::addConeMarch(g, shared, cone, {c.coneSamples, c.coneLimited, c.coneJitter});
        fg.summary = std::string(c.coneLimited ? "cone-limited" : "naive full-ray") + " march, " +
                     std::to_string(c.coneSamples) + " samples per pixel" +
                     (c.shadowed && !c.shadowSampling ? ", no shadow-map sampling" : "") +
                     (c.coneJitter ? ", jittered" : "");
    } else {
        if (c.light != ls::LightKind::Directional)
            fg.table = in.table = g.importImage("point-light table", importDescription(c.table));
        if (c.shadowed) {
            in.shadowMap = fg.shadowMap;
            in.lightColor = fg.lightColor;
        }
        if (!c.shadowed) {
            lin = ls::addUnshadowed(g, in);
            fg.summary = c.light == ls::LightKind::Directional
                             ? "unshadowed directional light: closed form per pixel"
                             : "unshadowed light: the point-light table in closed form per pixel";
        } else if (c.method == Method::BruteForce) {
            lin = ls::addBruteForce(g, in);
            fg.summary = "brute-force ray marching";
        } else {
            ls::EpipolarSizes sizes{c.slices, c.samples, c.shadowMapSize};
            const bool cube = c.light == ls::LightKind::Point;  // a shadowed point light's cube map
            ls::EpipolarOptions options{c.minMaxTrees, c.fixup, cube, clearedStepCounter(g, c, fg),
                                        c.inscatterRefinement};
            // Composited in the chain's unwarp and fix-up: no composite pass.
            const ls::EpipolarOutputs e =
                ls::addEpipolarNodes(g, in, sizes, options, {fg.color, fg.inscatterOut, false});
            if (e.stepCounts.valid()) g.markOutput(e.stepCounts);
            fg.summary = std::string("epipolar sampling") +
                         (c.minMaxTrees ? " with min/max trees" : "") +
                         (cube ? " per cube face" : "") +
                         (c.inscatterRefinement ? ", refined on in-scattering differences" : "") +
                         (c.fixup ? ", fix-up" : "") + ", composited in the unwarp";
            return fg;
        }
    }
    ls::addComposite(g, in, fg.color, lin, fg.inscatterOut);
    return fg;
}

}  // namespace lightscatter::detail
