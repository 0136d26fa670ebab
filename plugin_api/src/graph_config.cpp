#include "graph_config.h"

#include <algorithm>

namespace lightscatter::detail {

FrameImports frameImports(const FrameDescription& frame, const ValidatedFrame& v) {
    FrameImports f;
    f.depth = importState(frame.depth);
    if (frame.color.format != VK_FORMAT_UNDEFINED) f.color = importState(frame.color);
    if (frame.inscatterOut) f.inscatterOut = importState(*frame.inscatterOut);
    if (frame.transmittanceOut) f.transmittanceOut = importState(*frame.transmittanceOut);
    if (frame.noise) f.noise = importState(*frame.noise);
    if (frame.volumeOut) f.volumeOut = importState(*frame.volumeOut);
    for (const EdgeLight& e : v.given) {
        const LightInput& l = e.input;
        f.shadowMaps.push_back(l.shadowMap ? importState(*l.shadowMap) : ImportState{});
        f.lightColors.push_back(l.lightColor ? importState(*l.lightColor) : ImportState{});
    }
    return f;
}

GraphConfig graphConfig(const ValidatedFrame& frame,
                        const std::vector<const ls::MethodUnit*>& methods,
                        const FrameImports& images, const GraphOptions& options,
                        const std::vector<const ls::LightData*>& data,
                        const std::vector<const ls::ChainOptions*>& previous) {
    const ls::LightSetup& first = frame.lights[0];
    GraphConfig c;
    c.screen = first.screen;
    c.depthStencil = options.depthStencil;
    c.coordinates = options.coordinates;
    c.depth = images.depth;
    c.color = images.color;
    c.inscatterOut = images.inscatterOut;
    c.transmittanceOut = images.transmittanceOut;
    c.dualSourceBlend = options.dualSourceBlend;
    c.colorBlends = options.colorBlends;
    if (options.maxScreen.width != 0) {
        // Dynamic resolution: the graph is the maximum's, whatever this frame's size.
        c.screen = options.maxScreen;
        c.dynamicScreen = true;
        for (ImportState* s : {&c.depth, &c.color, &c.inscatterOut, &c.transmittanceOut})
            if (s->given()) s->extent = options.maxScreen;
    }
    c.extinction = glm::any(glm::greaterThan(first.medium.betaT(), glm::vec3(0.0f)));
    c.poisonTransients = options.poisonTransients;
    bool noise = false;
    for (size_t i = 0; i < frame.lights.size(); ++i) {
        const ls::LightSetup& s = frame.lights[i];
        const bool touches = frame.touchesView[i];
        const ls::MethodUnit& method = *methods[i];
        LightGraphConfig l;
        l.method = &method;
        l.chain.light = s.light.kind;
        l.chain.shadowed = s.shadowed;
        l.chain.shadowMapSize = s.light.shadowMapSize;
        l.chain.spec = ls::scatterSpec(s);
        l.chain.options = method.options(s, i < data.size() ? data[i] : nullptr,
                                         i < previous.size() ? previous[i] : nullptr);
        l.touchesView = touches;
        l.noise = touches && method.readsNoise(s);
        l.shadowMap = images.shadowMaps[i];
        l.lightColor = images.lightColors[i];
        l.table = touches && method.readsTable(s);
        noise = noise || l.noise;
        // The step counter holds what the most demanding light that counts adds into.
        if (options.countSteps && method.caps().countsSteps && touches && s.shadowed) {
            c.countSteps = true;
            c.stepCountBytes = std::max(c.stepCountBytes, method.stepCountBytes(s));
            c.stepCounter = &method;
        }
        c.lights.push_back(l);
    }
    // The engine's 3D image for a one-per-frame method's result (it takes every light, so the
    // first light reaching the view names it).
    for (size_t i = 0; i < c.lights.size(); ++i)
        if (c.lights[i].touchesView) {
            const ls::MethodCaps caps = c.lights[i].method->caps();
            if (caps.onePerFrame && caps.exportsVolume) c.volumeOut = images.volumeOut;
            break;
        }
    if (noise) {
        c.ownNoise = !images.noise.given();
        if (!c.ownNoise) c.noise = images.noise;
    }
    return c;
}

}  // namespace lightscatter::detail
