#include "froxels_method.h"

#include "froxel_blue_noise.h"

#include "shared/chain_inputs.h"
#include "shared/refusals.h"

namespace ls {

const MethodUnit& methodUnitFroxels() {
    static const FroxelsMethod unit;
    return unit;
}

std::string FroxelsMethod::description() const {
    return "the froxel volumetric fog engines ship: every light injected into one view-frustum "
           "grid";
}

MethodCaps FroxelsMethod::caps() const {
    MethodCaps c;
    c.cubeShadow = true;
    c.profileSized = true;
    c.onePerFrame = true;
    c.exportsVolume = true;
    c.keepsHistory = true;  // the temporal mode
    c.media = true;         // each slice's optical depth along its column (integrate.comp)
    return c;
}

// The grids engines ship: Unity HDRP's (the screen / 8 on x and y, 64 slices; the default) and
// Unreal's volumetric fog (the screen / 16, 64 slices), each also in the temporal mode and in the
// temporal mode with still frames refined per pixel (`-pixels`: two screen-sized float32 images
// more, so a name of its own rather than the temporal presets' default).
std::vector<lightscatter::MethodPreset> FroxelsMethod::presets() const {
    struct Grid {
        const char* name;
        const char* engine;
        uint32_t tile, slices;
    };
    struct Mode {
        const char* suffix;
        const char* description;
        bool temporal, pixelHistory;
    };
    std::vector<lightscatter::MethodPreset> out;
    for (const Grid& g : {Grid{"froxels-hdrp", "Unity HDRP", 8, 64},
                          Grid{"froxels-unreal", "Unreal's volumetric fog", 16, 64}})
        for (const Mode& m :
             {Mode{"", "", false, false},
              Mode{"-temporal", ", blended with the frame before's", true, false},
              Mode{"-pixels", ", blended with the frame before's, still frames refined per pixel",
                   true, true}})
            out.push_back({std::string(g.name) + m.suffix,
                           std::string(g.engine) + "'s grid, " + std::to_string(g.tile) + "x" +
                               std::to_string(g.tile) + "-pixel columns and " +
                               std::to_string(g.slices) + " slices" + m.description,
                           [g, m](lightscatter::Settings& s) {
                               s.froxels.tile = g.tile;
                               s.froxels.slices = g.slices;
                               s.froxels.temporal = m.temporal;
                               s.froxels.pixelHistory = m.pixelHistory;
                           }});
    return out;
}

namespace {

// The slices run from the near plane to the far distance, within the medium's reach.
std::string refuseFarDistance(const LightSetup& s) {
    const float far = s.settings.froxels.farDistance;
    if (far == 0.0f) return {};
    const std::string field = s.settingsPath + ".froxels.farDistance = " + twoDigits(far);
    if (far > s.medium.maxDistance)
        return field + ": must be at most medium.maxDistance (" + twoDigits(s.medium.maxDistance) +
               "), where every ray ends";
    if (far <= s.camera.nearPlane)
        return field + ": must be beyond the camera's near plane (" +
               twoDigits(s.camera.nearPlane) + "), where the first slice starts";
    return {};
}

// The per-pixel history refines the temporal mode's still frames; alone it has no history to keep.
std::string refusePixelHistory(const LightSetup& s) {
    const lightscatter::FroxelsSettings& f = s.settings.froxels;
    if (!f.pixelHistory || f.temporal) return {};
    return s.settingsPath +
           ".froxels.pixelHistory = true: needs froxels.temporal = true (it gathers the temporal "
           "mode's still frames per pixel)";
}

}  // namespace

bool FroxelsMethod::readsTable(const LightSetup& s) const {
    // The closed form holds in a homogeneous medium under the full model; elsewhere the grid keeps
    // its point samples and builds no table.
    return pointLike(s) && !s.medium.nonUniform() && !simplifiedModel(s);
}

std::string FroxelsMethod::refusal(const LightSetup& s) const {
    if (std::string r = refuseFarDistance(s); !r.empty()) return r;
    return refusePixelHistory(s);
}

ChainOptions FroxelsMethod::options(const LightSetup& s, const LightData*,
                                    const ChainOptions*) const {
    return ChainOptions(Options{froxelSettings(s.settings.froxels)});
}

// One injection per light, in the frame's order, into one grid; then one integration and one
// apply, with the first light's constants (the camera and the medium are every light's).
ChainOutputs FroxelsMethod::addChain(rg::RenderGraph& g, ChainLights lights,
                                     const CompositeTarget& target) const {
    const ChainInputs& first = lights.front().in;
    const FroxelSettings& settings = lights.front().config.options.get<Options>()->grid;
    const FroxelGrid grid = froxelGrid(first.screen, settings);
    const bool temporal = settings.temporal;
    // The temporal mode's histories, kept by the graph under the frame's key: the frame before's
    // grid, read, and this frame's, written; and with the per-pixel history, the frame before's
    // pixels and this frame's.
    rg::RenderGraph::HistoryImages history, pixels;
    rg::ImageRef noise;
    if (temporal) {
        history = g.historyImages("froxel history", froxelHistoryDesc(grid), first.frameKey);
        noise = addFroxelBlueNoise(g, {first.shared, first.frameKey});
    }
    if (temporal && settings.pixelHistory)
        pixels = g.historyImages("froxel pixel history", froxelPixelHistoryDesc(first.screen),
                                 first.frameKey);
    const FroxelPixelClock clock{pixels.previous, first.previous};
    rg::ImageRef scattering = froxelScatteringImage(g, grid);
    std::vector<rg::HostDataRef<LightFrame>> values;
    for (size_t i = 0; i < lights.size(); ++i) {
        const ChainLight& l = lights[i];
        if (lights.size() > 1) g.setNameSuffix(" (light " + std::to_string(i) + ")");
        scattering = addFroxelInjection(g,
                                        {chainContext(l.in, l.config), lightImages(l.in, l.config),
                                         scattering, i == 0, history.previous, noise, clock},
                                        grid);
        values.push_back(l.in.values);
    }
    g.setNameSuffix({});
    const ChainContext chain = chainContext(first, lights.front().config);
    ChainOutputs out;
    // The per-pixel history's still frames apply this frame's samples, which it gathers per
    // pixel, while the blend keeps the grid of the last frame that moved: the exported volume, and
    // the history of the next frame that moves.
    const rg::ImageRef samples = pixels.current.valid() ? scattering : rg::ImageRef{};
    if (temporal) {
        scattering = addFroxelTemporalBlend(g,
                                            {chain, scattering, history.previous, history.current,
                                             first.previous, settings.historyWeight, clock},
                                            grid);
        g.markOutput(scattering);  // the next frame reads it
    }
    const rg::ImageRef integrated =
        addFroxelIntegration(g, {chain, scattering, values, clock, samples}, grid);
    // With the per-pixel history, the grid the blend keeps, integrated on its own: the exported
    // volume, and what the apply's pixels hold their detail against in a still frame (a frame that
    // moved integrates it only to export it).
    const FroxelPixelClock onlyStill = first.volumeOut.valid() ? FroxelPixelClock{} : clock;
    const rg::ImageRef kept =
        samples.valid()
            ? addFroxelIntegration(g, {chain, scattering, values, {}, {}, true, onlyStill}, grid)
            : integrated;
    if (first.volumeOut.valid())
        g.markOutput(addFroxelExport(g, {chain, kept, values, first.volumeOut}, grid));
    out.composited = true;
    out.target = addFroxelApply(g,
                                {chain,
                                 integrated,
                                 values,
                                 {target.color, target.inscatterOut, false, target.transmittance},
                                 clock,
                                 pixels.current,
                                 kept},
                                grid);
    return out;
}

VolumeLayout FroxelsMethod::exportedVolume(const LightSetup& s, VkExtent2D screen) const {
    const FroxelGrid grid = froxelGrid(screen, froxelSettings(s.settings.froxels));
    const FroxelDepthRange z =
        froxelDepthRange(s.camera.nearPlane, s.camera.farPlane, s.camera.infiniteFar,
                         s.medium.maxDistance, s.settings.froxels.farDistance);
    return {grid.columns,
            grid.rows,
            grid.slices,
            grid.tile,
            z.nearZ,
            z.farZ,
            "the screen over Settings::froxels.tile, and froxels.slices"};
}

std::string FroxelsMethod::summary(const ChainConfig& c) const {
    const FroxelSettings& s = c.options.get<Options>()->grid;
    return "froxel grid of " + std::to_string(s.tile) + "x" + std::to_string(s.tile) +
           "-pixel columns and " + std::to_string(s.slices) +
           " exponential depth slices: each light injected at the froxels' " +
           (s.temporal ? "jittered points, blended with the frame before's grid (weight " +
                             twoDigits(s.historyWeight) + "), "
                       : "centres, ") +
           "integrated front to back, applied at each pixel's depth" +
           (s.temporal && s.pixelHistory
                ? "; still frames step the columns across a froxel and each pixel gathers the "
                  "rays nearest it"
                : "");
}

}  // namespace ls
