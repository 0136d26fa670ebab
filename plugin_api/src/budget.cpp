// The memory budget of the epipolar method for a profile, computed without a GPU: the frame graph
// is built and compiled against the offline device model, so the numbers are the compiler's own
// (per-resource sizes, the sum without aliasing, the peak with it).
#include <string>
#include <vector>

#include <lightscatter/lightscatter.h>
#include "graph_config.h"
#include "method_choice.h"
#include "method_units.h"
#include "planes/tiling_noise.h"
#include "registry/method_registry.h"
#include "rendergraph/compile.h"
#include "rendergraph/format_info.h"
#include "settings_checks.h"
#include "shared/point_table.h"

namespace lightscatter {
namespace {

// Seed 000's memory column: 2560x1600 (GTX 680) for the three main profiles, 1366x768 for the
// weaker-device set (the Intel HD table at 1024x768 repeats the same figures).
std::optional<SeedFigure> seedFigure(Profile p) {
    switch (p) {
        case Profile::HighQuality:
            return SeedFigure{2560, 1600, 88.0, 5.986};
        case Profile::Balanced:
            return SeedFigure{2560, 1600, 44.0, 3.269};
        case Profile::HighPerformance:
            return SeedFigure{2560, 1600, 18.0, 2.267};
        case Profile::LowHighQuality:
            return SeedFigure{1366, 768, 44.0, 18.9};
        case Profile::LowBalanced:
            return SeedFigure{1366, 768, 11.0, 8.37};
        case Profile::LowHighPerformance:
            return SeedFigure{1366, 768, 4.5, 5.38};
        default:
            return std::nullopt;
    }
}

// The engine's images as a typical engine hands them over (D32 depth, RGBA16F color).
void describeEngineImages(detail::FrameImports& f, VkExtent2D screen) {
    const VkImageLayout ro = VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;
    f.depth = {VK_FORMAT_D32_SFLOAT, screen,
               VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT, ro, ro};
    f.color = {VK_FORMAT_R16G16B16A16_SFLOAT, screen, VK_IMAGE_USAGE_STORAGE_BIT,
               VK_IMAGE_LAYOUT_GENERAL, VK_IMAGE_LAYOUT_GENERAL};
}

// The methods whose caps say `which`, by name ("epipolar, planes and beam-tree-analytic").
template <typename F>
std::string methodsWhere(F which) {
    std::vector<std::string> names;
    for (const ls::MethodUnit* m : ls::methodRegistry())
        if (which(m->caps())) names.push_back(m->name());
    std::string s;
    for (size_t i = 0; i < names.size(); ++i)
        s += (i == 0 ? "" : i + 1 == names.size() ? " and " : ", ") + names[i];
    return s;
}

uint64_t persistentBytes(const rg::OfflineDeviceCaps& caps, VkFormat format, VkExtent2D extent,
                         uint32_t depth = 1) {
    VkImageCreateInfo info{VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO};
    info.format = format;
    info.extent = {extent.width, extent.height, depth};
    info.mipLevels = info.arrayLayers = 1;
    return caps.imageRequirements(info).size;
}

Budget setBudget(Profile profile, uint32_t screenWidth, uint32_t screenHeight,
                 uint32_t shadowMapSize, const std::vector<BudgetLight>& lights,
                 const Settings* custom, bool refusals);

// Auto for a light of a budgeted set, which has no geometry or medium: as a frame's Auto for a
// light that covers the screen in a medium that needs the point-light table.
Method budgetAuto(const detail::FrameSetup& l) {
    if (!l.shadowed) return Method::Epipolar;  // its closed form per pixel
    const uint64_t pixels = uint64_t{l.screen.width} * l.screen.height;
    const uint64_t samples = uint64_t{l.epipolar.slices} * l.epipolar.samples;
    return pixels * detail::kEpipolarSamplesPerPixel >= samples ? Method::Epipolar
                                                                : Method::BruteForce;
}

}  // namespace

Budget budget(Profile profile, uint32_t screenWidth, uint32_t screenHeight, uint32_t shadowMapSize,
              LightType light, const Settings* custom, Method method) {
    return budget(profile, screenWidth, screenHeight, shadowMapSize, std::vector<LightType>{light},
                  custom, method);
}

Budget budget(Profile profile, uint32_t screenWidth, uint32_t screenHeight, uint32_t shadowMapSize,
              const std::vector<LightType>& lights, const Settings* custom, Method method) {
    const ls::MethodUnit* unit = detail::methodUnit(method);
    if (!unit || !unit->caps().budgeted)
        throw InvalidInput(std::string("lightscatter: budget method ") + methodName(method) +
                           ": only " +
                           methodsWhere([](const ls::MethodCaps& c) { return c.budgeted; }) +
                           " have textures that depend on the profile");
    const ls::MethodCaps caps = unit->caps();
    std::vector<BudgetLight> set;
    for (LightType light : lights) {
        if (light == LightType::Directional && !caps.directional)
            throw InvalidInput(std::string("lightscatter: budget method ") + methodName(method) +
                               ": needs a point or spot light");
        // A point light is budgeted with its cube map where the method samples one.
        set.push_back({light, light != LightType::Point || caps.cubeShadow, method});
    }
    // One method for every light, as before a light had its own: a setting the method does not
    // honour (noise for epipolar) is budgeted as if it did, not refused.
    return setBudget(profile, screenWidth, screenHeight, shadowMapSize, set, custom, false);
}

Budget budget(Profile profile, uint32_t screenWidth, uint32_t screenHeight, uint32_t shadowMapSize,
              const std::vector<BudgetLight>& lights, const Settings* custom) {
    return setBudget(profile, screenWidth, screenHeight, shadowMapSize, lights, custom, true);
}

namespace {

Budget setBudget(Profile profile, uint32_t screenWidth, uint32_t screenHeight,
                 uint32_t shadowMapSize, const std::vector<BudgetLight>& lights,
                 const Settings* custom, bool refusals) {
    if (lights.empty()) throw InvalidInput("lightscatter: budget lights: the list is empty");
    if (lights.size() > kMaxLights)
        throw InvalidInput("lightscatter: budget lights: " + std::to_string(lights.size()) +
                           " lights: at most " + std::to_string(kMaxLights) +
                           " (kMaxLights, as FrameDescription::lights)");
    if (screenWidth == 0 || screenHeight == 0 || screenWidth > 16384 || screenHeight > 16384)
        throw InvalidInput("lightscatter: budget screen " + std::to_string(screenWidth) + "x" +
                           std::to_string(screenHeight) + ": each side must be in [1, 16384]");
    if (shadowMapSize < 1 || shadowMapSize > 16384)
        throw InvalidInput("lightscatter: budget shadow-map size " + std::to_string(shadowMapSize) +
                           ": must be in [1, 16384]");
    Settings s =
        profile == Profile::Custom ? (custom ? *custom : Settings{}) : profileSettings(profile);
    // Read from custom with every profile, as a frame does: it adds the refinement's passes.
    if (custom) s.inscatterRefinementThreshold = custom->inscatterRefinementThreshold;
    // So is the froxel grid (its presets are settings, not profiles).
    if (custom) {
        s.froxelTile = custom->froxelTile;
        s.froxelSlices = custom->froxelSlices;
        s.froxelFarDistance = custom->froxelFarDistance;
        s.froxelTemporal = custom->froxelTemporal;
        s.froxelHistoryWeight = custom->froxelHistoryWeight;
    }
    detail::checkSettings(s);

    // The frame budget() describes: each light reaching the view, with a shadow map of
    // shadowMapSize (a point light's a cube of six faces, where the method samples one).
    const VkExtent2D screen{screenWidth, screenHeight};
    detail::ValidatedFrame frame;
    detail::FrameImports images;
    describeEngineImages(images, screen);
    std::vector<const ls::MethodUnit*> methods;
    for (size_t i = 0; i < lights.size(); ++i) {
        const LightType type = lights[i].type;
        detail::FrameSetup l;
        l.light.kind = type;
        l.shadowed = lights[i].shadowed;
        l.light.shadowMapSize = l.shadowed ? shadowMapSize : 0;
        detail::applySettings(l, s, l.light.shadowMapSize);
        // Read from custom with every profile, as a frame does: it adds the plugin's tiling noise.
        l.noise = custom && custom->noiseAmplitude > 0.0f;
        l.screen = screen;
        l.depthAttachment = true;
        l.settings = s;
        const Method method = lights[i].method == Method::Auto ? budgetAuto(l) : lights[i].method;
        const ls::MethodUnit* unit = detail::methodUnit(method);
        if (!unit)
            throw InvalidInput("lightscatter: budget lights[" + std::to_string(i) +
                               "].method is not a Method value");
        if (const std::string r = refusals ? unit->refusal(l) : ""; !r.empty())
            throw InvalidInput("lightscatter: budget lights[" + std::to_string(i) + "]: " + r);
        methods.push_back(unit);
        frame.lights.push_back(l);
        frame.touchesView.push_back(true);
        const VkImageLayout ro = VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;
        images.shadowMaps.push_back(l.shadowed
                                        ? detail::ImportState{VK_FORMAT_D32_SFLOAT,
                                                              {shadowMapSize, shadowMapSize},
                                                              VK_IMAGE_USAGE_SAMPLED_BIT,
                                                              ro,
                                                              ro,
                                                              type == LightType::Point ? 6u : 1u}
                                        : detail::ImportState{});
        images.lightColors.push_back({});
    }
    // A frame-wide method (froxels) takes every light, as in a frame.
    for (size_t i = 0; i < methods.size(); ++i)
        if (methods[i]->caps().frameWide && methods != std::vector(methods.size(), methods[i]))
            throw InvalidInput("lightscatter: budget lights[" + std::to_string(i) +
                               "].method = " + methods[i]->name() +
                               " takes every light of the frame into one grid: give it to every "
                               "light, or to none");
    const rg::OfflineDeviceCaps device;
    detail::GraphOptions options;
    options.depthStencil = detail::stencilFormat(device);
    options.coordinates = detail::coordinateFormat(device);
    const detail::GraphConfig c = detail::graphConfig(frame, methods, images, options);
    const detail::FrameGraph fg = detail::buildFrameGraph(c);
    const rg::CompiledGraph compiled = rg::compile(*fg.graph, device);

    Budget b;
    b.profile = profile;
    b.settings = s;
    b.settings.shadowMapSize = shadowMapSize;
    b.screenWidth = screenWidth;
    b.screenHeight = screenHeight;
    b.estimated = !compiled.exactSizes;
    b.depthStencilFormat = rg::formatName(c.depthStencil);
    if (lights.size() == 1) b.seed = seedFigure(profile);  // seed 000's figures are for one light
    for (const ls::MethodUnit* m : methods) b.lightMethods.push_back(m->name());
    for (uint32_t id = 0; id < fg.graph->resources().size(); ++id) {
        const auto& r = fg.graph->resource(id);
        const auto& p = compiled.resources[id];
        if (r.imported || !p.used) continue;
        b.entries.push_back({r.name, r.buffer ? "buffer" : rg::formatName(r.image.format),
                             p.extent.width, p.extent.height, p.memory.size, true,
                             r.buffer ? 1u : r.image.depth});
    }
    b.totalBytes = compiled.unaliasedBytes;
    b.peakBytes = compiled.aliasedBytes;
    // What lives across frames, outside the graph's aliased memory: the plugin's own tiling noise
    // (an engine's noise image replaces it) and each point or spot light's table.
    auto persistent = [&](const std::string& name, VkFormat format, VkExtent2D extent,
                          uint32_t depth = 1) {
        const uint64_t bytes = persistentBytes(device, format, extent, depth);
        b.entries.push_back(
            {name, rg::formatName(format), extent.width, extent.height, bytes, false, depth});
        b.totalBytes += bytes;
        b.peakBytes += bytes;
    };
    if (c.ownNoise) persistent("tiling noise", ls::kNoiseFormat, ls::kNoiseExtent);
    // The frame-wide method's history: two images, alternated (froxels' temporal mode).
    if (c.history.given())
        for (const char* name : {"frame history A", "frame history B"})
            persistent(name, c.history.format, c.history.extent, c.history.depth);
    for (size_t i = 0; i < c.lights.size(); ++i)
        if (c.lights[i].table.given())
            persistent(lights.size() == 1 ? "point-light table"
                                          : "point-light table (light " + std::to_string(i) + ")",
                       VK_FORMAT_R32G32B32A32_SFLOAT, {ls::kTableWidth, ls::kTableHeight});
    return b;
}

}  // namespace

}  // namespace lightscatter
