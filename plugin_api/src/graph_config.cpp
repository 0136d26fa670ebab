#include "graph_config.h"

#include <algorithm>

namespace lightscatter::detail {

FrameImports frameImports(const FrameDescription& frame) {
    FrameImports f;
    f.depth = importState(frame.depth);
    f.color = importState(frame.color);
    if (frame.inscatterOut) f.inscatterOut = importState(*frame.inscatterOut);
    if (frame.noise) f.noise = importState(*frame.noise);
    if (frame.volumeOut) f.volumeOut = importState(*frame.volumeOut);
    for (const LightInput& l : lightInputs(frame)) {
        f.shadowMaps.push_back(l.shadowMap ? importState(*l.shadowMap) : ImportState{});
        f.lightColors.push_back(l.lightColor ? importState(*l.lightColor) : ImportState{});
    }
    return f;
}

GraphConfig graphConfig(const ValidatedFrame& frame,
                        const std::vector<const ls::MethodUnit*>& methods,
                        const FrameImports& images, const GraphOptions& options,
                        const std::vector<const ls::LightData*>& data,
                        const GraphConfig* previous) {
    const ls::LightSetup& first = frame.lights[0];
    GraphConfig c;
    c.screen = first.screen;
    c.depthStencil = options.depthStencil;
    c.coordinates = options.coordinates;
    c.depth = images.depth;
    c.color = images.color;
    c.inscatterOut = images.inscatterOut;
    if (options.maxScreen.width != 0) {
        // Dynamic resolution: the graph is the maximum's, whatever this frame's size.
        c.screen = options.maxScreen;
        c.dynamicScreen = true;
        for (ImportState* s : {&c.depth, &c.color, &c.inscatterOut})
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
        const bool sameMethod =
            previous && i < previous->lights.size() && previous->lights[i].method == &method;
        l.chain.options = method.options(s, i < data.size() ? data[i] : nullptr,
                                         sameMethod ? &previous->lights[i].chain.options : nullptr);
        l.touchesView = touches;
        l.noise = touches && method.readsNoise(s);
        l.shadowMap = images.shadowMaps[i];
        l.lightColor = images.lightColors[i];
        if (touches && method.readsTable(s)) l.table = tableState();
        noise = noise || l.noise;
        // The step counter holds the most slices of any light that marches.
        if (options.countSteps && method.caps().countsSteps && touches && s.shadowed) {
            c.countSteps = true;
            c.stepCountSlices = std::max(c.stepCountSlices, s.settings.epipolar.slices);
        }
        c.lights.push_back(l);
    }
    // A frame-wide method's history, for the graph's screen (the frame-wide method takes every
    // light, so the first light reaching the view names it).
    for (size_t i = 0; i < c.lights.size(); ++i)
        if (c.lights[i].touchesView) {
            const ls::MethodUnit& m = *c.lights[i].method;
            if (m.caps().onePerFrame) {
                const ls::HistoryShape shape = m.history(c.lights[i].chain, c.screen);
                if (shape.given()) c.history = historyState(shape);
                if (m.caps().exportsVolume) c.volumeOut = images.volumeOut;
            }
            break;
        }
    if (noise) {
        c.ownNoise = !images.noise.given();
        c.noise = c.ownNoise ? ownNoiseState() : images.noise;
    }
    return c;
}

}  // namespace lightscatter::detail
