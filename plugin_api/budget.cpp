// The memory budget of the epipolar method for a profile, computed without a GPU: the frame graph
// is built and compiled against the offline device model, so the numbers are the compiler's own
// (per-resource sizes, the sum without aliasing, the peak with it).
#include <string>
#include <vector>

#include "frame_graph.h"
#include "frame_setup.h"
#include "lightscatter.h"
#include "rendergraph/compile.h"
#include "rendergraph/format_info.h"

namespace lightscatter {
namespace {

// Seed 000's memory column: 2560x1600 (GTX 680) for the three main profiles, 1366x768 for the
// weaker-device set (the Intel HD table at 1024x768 repeats the same figures).
std::optional<SeedFigure> seedFigure(Profile p) {
    switch (p) {
        case Profile::HighQuality: return SeedFigure{2560, 1600, 88.0, 5.986};
        case Profile::Balanced: return SeedFigure{2560, 1600, 44.0, 3.269};
        case Profile::HighPerformance: return SeedFigure{2560, 1600, 18.0, 2.267};
        case Profile::LowHighQuality: return SeedFigure{1366, 768, 44.0, 18.9};
        case Profile::LowBalanced: return SeedFigure{1366, 768, 11.0, 8.37};
        case Profile::LowHighPerformance: return SeedFigure{1366, 768, 4.5, 5.38};
        default: return std::nullopt;
    }
}

// The engine's images as a typical engine hands them over (D32 depth, RGBA16F color), and the
// camera depth-stencil format the device would give, for a budget computed without a device.
void describeEngineImages(detail::GraphConfig& c, const rg::OfflineDeviceCaps& caps) {
    c.depthStencil = detail::stencilFormat(caps);
    c.coordinates = detail::coordinateFormat(caps);
    const VkImageLayout ro = VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;
    c.depth = {VK_FORMAT_D32_SFLOAT, c.screen,
               VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT, ro, ro};
    c.color = {VK_FORMAT_R16G16B16A16_SFLOAT, c.screen, VK_IMAGE_USAGE_STORAGE_BIT, VK_IMAGE_LAYOUT_GENERAL,
               VK_IMAGE_LAYOUT_GENERAL};
}

// The engine's shadow map: D32, one layer, or six for a point light's cube map.
detail::ImportState engineShadowMap(LightType light, uint32_t size) {
    const VkImageLayout ro = VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;
    return {VK_FORMAT_D32_SFLOAT, {size, size}, VK_IMAGE_USAGE_SAMPLED_BIT, ro, ro, light == LightType::Point ? 6u : 1u};
}

}  // namespace

Budget budget(Profile profile, uint32_t screenWidth, uint32_t screenHeight, uint32_t shadowMapSize,
              LightType light, const Settings* custom, Method method) {
    const bool beamTree = method == Method::BeamTreeAnalytic || method == Method::BeamTreeSampling;
    if (method != Method::Epipolar && method != Method::Slices && !beamTree)
        throw InvalidInput(std::string("lightscatter: budget method ") + methodName(method) +
                           ": only epipolar, slices, beam-tree-analytic and beam-tree-sampling have textures that "
                           "depend on the profile");
    if (beamTree && light == LightType::Directional)
        throw InvalidInput(std::string("lightscatter: budget method ") + methodName(method) +
                           ": needs a point or spot light");
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
    detail::checkSettings(s);

    detail::GraphConfig c;
    c.method = method;
    c.sliceTarget = detail::sliceAccumulation(s.sliceTarget);
    c.sliceBlur = s.sliceBlur;
    c.beamCapacity = 3 * 4096;  // the triangle buffer's first size; it doubles when a frame needs more
    c.light = static_cast<ls::LightKind>(static_cast<int>(light));
    // Epipolar budgets a point light with its cube shadow map; slices and the beam trees refuse one.
    c.shadowed = light != LightType::Point || method == Method::Epipolar;
    c.minMaxTrees = s.minMaxTrees && ls::treesFit(shadowMapSize);
    c.fixup = s.fixup;
    c.inscatterRefinement = s.inscatterRefinementThreshold > 0.0f;
    c.slices = s.slices;
    c.samples = s.samplesPerSlice;
    c.shadowMapSize = shadowMapSize;
    c.screen = {screenWidth, screenHeight};
    const rg::OfflineDeviceCaps caps;
    describeEngineImages(c, caps);
    const VkImageLayout ro = VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;
    if (c.shadowed) c.shadowMap = engineShadowMap(light, shadowMapSize);
    // The point-light table: read by epipolar and beam-tree-analytic's closed form.
    const bool table = light != LightType::Directional && method != Method::Slices && method != Method::BeamTreeSampling;
    if (table)
        c.table = {VK_FORMAT_R32G32B32A32_SFLOAT, {512, 256},
                   VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_SAMPLED_BIT, ro, ro};

    const detail::FrameGraph fg = detail::buildFrameGraph(c, nullptr);
    const rg::CompiledGraph compiled = rg::compile(*fg.graph, caps);

    Budget b;
    b.profile = profile;
    b.settings = s;
    b.settings.shadowMapSize = shadowMapSize;
    b.screenWidth = screenWidth;
    b.screenHeight = screenHeight;
    b.estimated = !compiled.exactSizes;
    b.depthStencilFormat = rg::formatName(c.depthStencil);
    b.seed = seedFigure(profile);
    for (uint32_t id = 0; id < fg.graph->resources().size(); ++id) {
        const auto& r = fg.graph->resource(id);
        const auto& p = compiled.resources[id];
        if (r.imported || !p.used) continue;
        BudgetEntry e;
        e.name = r.name;
        e.format = r.buffer ? "buffer" : rg::formatName(r.image.format);
        e.width = p.extent.width;
        e.height = p.extent.height;
        e.bytes = p.memory.size;
        b.entries.push_back(e);
    }
    b.totalBytes = compiled.unaliasedBytes;
    b.peakBytes = compiled.aliasedBytes;
    const bool noise = custom && custom->noiseAmplitude > 0.0f;  // read from custom with every profile
    if (method == Method::Slices && noise) {
        // The plugin's own tiling noise lives across frames (an engine's noise image replaces it).
        VkImageCreateInfo info{VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO};
        info.format = detail::kNoiseFormat;
        info.extent = {detail::kNoiseExtent.width, detail::kNoiseExtent.height, 1};
        info.mipLevels = info.arrayLayers = 1;
        const uint64_t bytes = caps.imageRequirements(info).size;
        b.entries.push_back({"tiling noise", rg::formatName(detail::kNoiseFormat), detail::kNoiseExtent.width,
                             detail::kNoiseExtent.height, bytes, false});
        b.totalBytes += bytes;
        b.peakBytes += bytes;
    }
    if (table) {
        // The table lives across frames, outside the graph's aliased memory.
        VkImageCreateInfo info{VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO};
        info.format = VK_FORMAT_R32G32B32A32_SFLOAT;
        info.extent = {512, 256, 1};
        info.mipLevels = info.arrayLayers = 1;
        const uint64_t bytes = caps.imageRequirements(info).size;
        b.entries.push_back({"point-light table", "R32G32B32A32_SFLOAT", 512, 256, bytes, false});
        b.totalBytes += bytes;
        b.peakBytes += bytes;
    }
    return b;
}

Budget budget(Profile profile, uint32_t screenWidth, uint32_t screenHeight, uint32_t shadowMapSize,
              const std::vector<LightType>& lights, const Settings* custom, Method method) {
    if (lights.empty()) throw InvalidInput("lightscatter: budget lights: the list is empty");
    if (lights.size() > kMaxLights)
        throw InvalidInput("lightscatter: budget lights: " + std::to_string(lights.size()) + " lights: at most " +
                           std::to_string(kMaxLights) + " (kMaxLights, as FrameDescription::lights)");
    if (lights.size() == 1) return budget(profile, screenWidth, screenHeight, shadowMapSize, lights[0], custom, method);
    if (method != Method::Epipolar)
        throw InvalidInput(std::string("lightscatter: budget method ") + methodName(method) +
                           ": several lights are budgeted for epipolar only");
    // The single light's checks (screen, shadow-map size, settings) and the textures it does not
    // repeat per light come from the first light's budget.
    Budget b = budget(profile, screenWidth, screenHeight, shadowMapSize, lights[0], custom, method);
    const Settings& s = b.settings;

    detail::GraphConfig c;
    c.method = method;
    c.fixup = s.fixup;
    c.inscatterRefinement = s.inscatterRefinementThreshold > 0.0f;
    c.slices = s.slices;
    c.samples = s.samplesPerSlice;
    c.screen = {screenWidth, screenHeight};
    const rg::OfflineDeviceCaps caps;
    describeEngineImages(c, caps);
    const VkImageLayout ro = VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;
    std::vector<size_t> tables;  // the lights with a point-light table
    for (LightType type : lights) {
        detail::LightChainConfig l;
        l.light = static_cast<ls::LightKind>(static_cast<int>(type));
        l.shadowed = true;  // a point light with its cube map
        l.minMaxTrees = s.minMaxTrees && ls::treesFit(shadowMapSize);
        l.fixup = s.fixup;
        l.inscatterRefinement = s.inscatterRefinementThreshold > 0.0f;
        l.slices = s.slices;
        l.samples = s.samplesPerSlice;
        l.shadowMapSize = shadowMapSize;
        l.shadowMap = engineShadowMap(type, shadowMapSize);
        if (type != LightType::Directional) {
            l.table = {VK_FORMAT_R32G32B32A32_SFLOAT, {512, 256}, VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_SAMPLED_BIT,
                       ro, ro};
            tables.push_back(c.lights.size());
        }
        c.lights.push_back(l);
    }
    const detail::FrameGraph fg = detail::buildFrameGraph(c, nullptr);
    const rg::CompiledGraph compiled = rg::compile(*fg.graph, caps);
    b.estimated = !compiled.exactSizes;
    b.seed.reset();  // seed 000's figures are for one light
    b.entries.clear();
    for (uint32_t id = 0; id < fg.graph->resources().size(); ++id) {
        const auto& r = fg.graph->resource(id);
        const auto& p = compiled.resources[id];
        if (r.imported || !p.used) continue;
        b.entries.push_back({r.name, r.buffer ? "buffer" : rg::formatName(r.image.format), p.extent.width,
                             p.extent.height, p.memory.size, true});
    }
    b.totalBytes = compiled.unaliasedBytes;
    b.peakBytes = compiled.aliasedBytes;
    // Each point or spot light's table lives across frames, outside the graph's aliased memory.
    VkImageCreateInfo info{VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO};
    info.format = VK_FORMAT_R32G32B32A32_SFLOAT;
    info.extent = {512, 256, 1};
    info.mipLevels = info.arrayLayers = 1;
    const uint64_t bytes = caps.imageRequirements(info).size;
    for (size_t i : tables) {
        b.entries.push_back({"point-light table (light " + std::to_string(i) + ")", "R32G32B32A32_SFLOAT", 512, 256,
                             bytes, false});
        b.totalBytes += bytes;
        b.peakBytes += bytes;
    }
    return b;
}

}  // namespace lightscatter
