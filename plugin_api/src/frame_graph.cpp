#include "frame_graph.h"

#include "color_target.h"
#include "rendergraph/format_info.h"

#include <algorithm>

#include "shared/clear_counters_node.h"
#include "shared/shared_nodes.h"
#include "shared/tiling_noise.h"

namespace lightscatter::detail {

ImportState importState(const ImageInput& in) {
    return {in.format, in.extent, in.usage, in.layout, in.finalLayout, in.arrayLayers, in.depth};
}

VkFormat stencilFormat(const rg::DeviceCaps& caps) {
    return rg::firstSupported(
        caps, {VK_FORMAT_S8_UINT, VK_FORMAT_D24_UNORM_S8_UINT, VK_FORMAT_D32_SFLOAT_S8_UINT},
        VK_FORMAT_FEATURE_2_DEPTH_STENCIL_ATTACHMENT_BIT);
}

VkFormat coordinateFormat(const rg::DeviceCaps& caps) {
    const VkFormat f = rg::firstSupported(caps, {VK_FORMAT_R16G16_UNORM, VK_FORMAT_R32G32_SFLOAT},
                                          VK_FORMAT_FEATURE_2_COLOR_ATTACHMENT_BIT);
    return f == VK_FORMAT_UNDEFINED ? VK_FORMAT_R32G32_SFLOAT : f;
}

rg::ImportedBuffer stepCountImport(VkBuffer buffer, uint64_t bytes) {
    rg::ImportedBuffer b;
    b.buffer = buffer;
    b.size = bytes;
    b.usage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT;
    b.initialStages = b.finalStages = VK_PIPELINE_STAGE_2_HOST_BIT;
    b.initialAccess = b.finalAccess = VK_ACCESS_2_HOST_READ_BIT;
    return b;
}

rg::ImportedImage importDescription(const ImageInput& in) {
    rg::ImportedImage d = importDescription(importState(in));
    d.image = in.image;
    d.initialStages = in.stages;
    d.initialAccess = in.access;
    d.finalStages = in.finalStages;
    d.finalAccess = in.finalAccess;
    return d;
}

rg::ImportedImage importDescription(const ImportState& s) {
    rg::ImportedImage d;
    d.format = s.format;
    d.extent = s.extent;
    d.arrayLayers = s.arrayLayers;
    d.depth = s.depth;
    d.usage = s.usage;
    d.initialLayout = s.layout;
    d.finalLayout = s.finalLayout;
    return d;
}

namespace {

// The frame's summary: the one light's chain, or every light's.
std::string frameSummary(const GraphConfig& c, size_t chains) {
    if (c.lights.size() == 1)
        return c.lights[0].touchesView
                   ? c.lights[0].method->summary(c.lights[0].chain)
                   : "the light reaches no view ray (or nothing scatters): extinction only";
    std::string s = std::to_string(c.lights.size()) + " lights, " + std::to_string(chains) +
                    " reaching the view";
    if (c.lights[0].method->caps().onePerFrame)
        return s + ", in one chain (" + c.lights[0].method->name() +
               "): " + c.lights[0].method->summary(c.lights[0].chain);
    for (size_t i = 0; i < c.lights.size(); ++i)
        if (c.lights[i].touchesView)
            s += "; light " + std::to_string(i) + " (" + c.lights[i].method->name() +
                 "): " + c.lights[i].method->summary(c.lights[i].chain);
    return s +
           "; the first composite applies the extinction, each light's Lin is added to the "
           "color as its chain ends";
}

}  // namespace

// One chain per light whose volume reaches the view, one after the other. The first chain's
// composite applies the extinction and adds its Lin; each later chain adds its Lin to the color
// (and to inscatterOut) as soon as it is done, so that its transients are dead before the next
// chain starts and the next one may reuse their memory: no sum image is kept.
FrameGraph buildFrameGraph(const GraphConfig& c, const ls::Shared& shared) {
    FrameGraph fg;
    fg.graph = std::make_unique<rg::RenderGraph>();
    rg::RenderGraph& g = *fg.graph;
    g.setScreenExtent(c.screen);
    // A frame of several lights names each chain's resources and passes for its light.
    const bool several = c.lights.size() > 1;
    auto which = [&](size_t i) {
        return several ? " (light " + std::to_string(i) + ")" : std::string();
    };

    fg.depth = g.importImage("engine depth", importDescription(c.depth), c.dynamicScreen);
    if (c.color.given())
        fg.color = g.importImage("engine color", importDescription(c.color), c.dynamicScreen);
    if (c.inscatterOut.given())
        fg.inscatterOut = g.importImage("in-scattering output", importDescription(c.inscatterOut),
                                        c.dynamicScreen);
    if (c.transmittanceOut.given())
        fg.transmittanceOut = g.importImage("transmittance output",
                                            importDescription(c.transmittanceOut), c.dynamicScreen);
    // A light's shadow map and color are imported whenever given, so that they are left in the
    // layouts the engine asked for even where no node reads them.
    fg.lights.resize(c.lights.size());
    fg.frameKey = g.hostData<rg::PersistentKey>("frame key");
    fg.previous = g.hostData<ls::PreviousFrame>("previous frame constants");
    bool anyTouches = false;
    for (size_t i = 0; i < c.lights.size(); ++i) {
        const LightGraphConfig& l = c.lights[i];
        fg.lights[i].values = g.hostData<ls::LightFrame>("light values" + which(i));
        fg.lights[i].key = g.hostData<rg::PersistentKey>("light key" + which(i));
        if (l.shadowMap.given())
            fg.lights[i].shadowMap =
                g.importImage("engine shadow map" + which(i), importDescription(l.shadowMap));
        if (l.lightColor.given())
            fg.lights[i].lightColor =
                g.importImage("light color" + which(i), importDescription(l.lightColor));
        anyTouches = anyTouches || l.touchesView;
    }
    if (!anyTouches && !c.extinction && !fg.inscatterOut.valid() && !fg.transmittanceOut.valid()) {
        fg.summary = "no light scatters and nothing absorbs: no pass at all";
        return fg;
    }
    // The camera and the medium are every light's: light 0's constants serve the composite.
    ls::ChainContext frame;
    frame.shared = shared;
    frame.spec = c.lights[0].chain.spec;
    frame.values = fg.lights[0].values;
    frame.constants = ls::addUploadConstants(g, {frame.values});
    frame.depth = fg.depth;
    frame.screen = c.screen;
    frame.depthStencil = c.depthStencil;
    frame.coordinateFormat = c.coordinates;

    // The composite's target: the engine's color, or the split's two textures (color_target.h).
    rg::ImageRef color = fg.color, linOut = fg.inscatterOut, transmittance;
    const bool split = splitComposite(c.color.format, c.color.usage, c.transmittanceOut.format);
    const bool blend = blendComposite(c.color.format, c.color.usage, c.transmittanceOut.format,
                                      c.colorBlends, c.dualSourceBlend);
    if (split) {
        const VkFormat f = splitFormat(c.color.format, c.transmittanceOut.format);
        color = g.createImage("split composite in-scattering", rg::ImageDesc::screen(f));
        transmittance = g.createImage("split composite transmittance", rg::ImageDesc::screen(f));
    }
    rg::ImageRef noise;  // the noise as the chains read it (made first, when it is the plugin's)
    rg::BufferRef counts;
    size_t chains = 0;
    std::vector<ls::ChainLight> onePerFrame;  // the lights of a one-per-frame method
    for (size_t i = 0; i < c.lights.size(); ++i) {
        const LightGraphConfig& l = c.lights[i];
        if (!l.touchesView) continue;  // a light whose volume misses the view costs nothing
        g.setNameSuffix(which(i));
        ls::ChainInputs in;
        in.shared = shared;
        in.values = fg.lights[i].values;
        in.constants = i == 0 ? frame.constants : ls::addUploadConstants(g, {in.values});
        in.depth = fg.depth;
        in.shadowMap = fg.lights[i].shadowMap;
        in.lightColor = fg.lights[i].lightColor;
        in.key = fg.lights[i].key;
        in.frameKey = fg.frameKey;
        in.previous = fg.previous;
        if (l.table)
            in.table = ls::addPointTable(
                g, {shared, l.chain.spec, in.values, in.constants, fg.lights[i].key});
        if (l.noise && !noise.valid()) {
            // The engine's, or the plugin's own, made once and kept by the graph.
            if (c.ownNoise) {
                noise = ls::addTilingNoise(g, {shared, fg.frameKey});
            } else {
                fg.noise = noise = g.importImage("engine noise", importDescription(c.noise));
            }
        }
        if (l.noise) in.noise = noise;
        in.screen = c.screen;
        in.depthStencil = c.depthStencil;
        in.coordinateFormat = c.coordinates;
        if (c.countSteps && l.chain.shadowed && !counts.valid()) {
            // Imported and cleared once, before the first chain that marches.
            fg.stepCounts = g.importBuffer("ray-march step counts",
                                           stepCountImport(VK_NULL_HANDLE, c.stepCountBytes));
            counts = ls::addClearCounters(g, {fg.stepCounts});
        }
        in.stepCounts = counts;
        if (l.method->caps().onePerFrame) {
            // Its lights go into one chain, added once they are all known.
            onePerFrame.push_back({in, l.chain});
            continue;
        }
        // The first chain's composite applies the extinction; the others add their Lin.
        const ls::CompositeTarget target{color, linOut, chains != 0, transmittance, blend};
        const ls::ChainLight light{in, l.chain};
        const ls::ChainOutputs o = l.method->addChain(g, {&light, 1}, target);
        if (o.stepCounts.valid()) counts = o.stepCounts;
        ls::CompositeOutputs written = o.target;
        if (!o.composited) {
            ls::ChainContext composite = frame;
            composite.spec = l.chain.spec;
            composite.values = in.values;
            composite.constants = in.constants;
            const ls::CompositeInputs into{composite, color, o.lin, linOut, transmittance};
            written = chains == 0 ? ls::addComposite(g, into) : ls::addInscatter(g, into);
        }
        color = written.color;
        linOut = written.inscatterOut;
        transmittance = written.transmittance;
        ++chains;
    }
    g.setNameSuffix({});
    if (!onePerFrame.empty()) {
        if (c.volumeOut.given()) {
            fg.volumeOut = g.importImage("engine volume output", importDescription(c.volumeOut));
            onePerFrame[0].in.volumeOut = fg.volumeOut;
        }
        // A one-per-frame method takes every light (the method choice mixes it with no other).
        const ls::ChainOutputs o = c.lights[0].method->addChain(
            g, onePerFrame, {color, linOut, false, transmittance, blend});
        color = o.target.color;
        linOut = o.target.inscatterOut;
        transmittance = o.target.transmittance;
        chains = onePerFrame.size();
    }
    if (chains == 0) {  // extinction only
        const ls::CompositeOutputs o =
            ls::addComposite(g, {frame, color, {}, linOut, transmittance});
        color = o.color;
        transmittance = o.transmittance;
    }
    if (split) {
        if (fg.color.valid())
            ls::addSplitComposite(g, {.chain = frame,
                                      .lin = color,
                                      .transmittance = transmittance,
                                      .color = fg.color,
                                      .storage = storageColor(c.color.format, c.color.usage),
                                      .dualSource = c.dualSourceBlend});
        if (fg.transmittanceOut.valid())
            ls::addTransmittanceExport(g, {frame, transmittance, fg.transmittanceOut});
    }
    if (counts.valid()) g.markOutput(counts);
    fg.summary = frameSummary(c, chains);
    if (blend)
        fg.summary += "; the color takes dual-source blending: fragment passes may blend into it";
    if (split)
        fg.summary += !c.color.given() ? "; no color: Lin and the transmittance out"
                      : storageColor(c.color.format, c.color.usage)
                          ? "; composited through two textures, for the transmittance output"
                          : "; composited through two textures, blended into the " +
                                rg::formatName(c.color.format) + " color" +
                                (c.dualSourceBlend ? " in one dual-source draw"
                                                   : " in two draws (no dualSrcBlend)");
    return fg;
}

}  // namespace lightscatter::detail
