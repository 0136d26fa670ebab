// The memory budget of a frame's methods for a profile, computed without a GPU: the frame graph
// is built and compiled against the offline device model, so the numbers are the compiler's own
// (per-resource sizes, the sum without aliasing, the peak with it).
#include <string>
#include <vector>

#include <lightscatter/lightscatter.h>
#include "color_target.h"
#include "enum_checks.h"
#include "graph_config.h"
#include "method_choice.h"
#include "method_units.h"
#include "rendergraph/compile.h"
#include "rendergraph/format_info.h"

namespace lightscatter {
namespace {

// The engine's images as a typical engine hands them over: a D32 depth, and its color, a storage
// image where its format allows, else a color attachment.
void describeEngineImages(detail::FrameImports& f, VkExtent2D screen, VkFormat color) {
    const VkImageLayout ro = VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;
    f.depth = {VK_FORMAT_D32_SFLOAT, screen,
               VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT, ro, ro};
    if (detail::storageColor(color, VK_IMAGE_USAGE_STORAGE_BIT))
        f.color = {color, screen, VK_IMAGE_USAGE_STORAGE_BIT, VK_IMAGE_LAYOUT_GENERAL,
                   VK_IMAGE_LAYOUT_GENERAL};
    else
        f.color = {color, screen, VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT,
                   VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                   VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL};
}

uint64_t persistentBytes(const rg::OfflineDeviceCaps& caps, VkFormat format, VkExtent2D extent,
                         uint32_t depth = 1) {
    VkImageCreateInfo info{VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO};
    info.format = format;
    info.extent = {extent.width, extent.height, depth};
    info.mipLevels = info.arrayLayers = 1;
    return caps.imageRequirements(info).size;
}

}  // namespace

Budget budget(Profile profile, uint32_t screenWidth, uint32_t screenHeight, uint32_t shadowMapSize,
              const std::vector<BudgetLight>& lights, const Settings* custom,
              VkFormat colorFormat) {
    detail::checkProfile(profile, "budget profile");
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
    for (size_t i = 0; i < lights.size(); ++i) {
        const std::string at = "budget lights[" + std::to_string(i) + "]";
        detail::checkLightType(lights[i].type, at + ".type");
        detail::checkMethod(lights[i].method, at + ".method");
    }
    const rg::OfflineDeviceCaps model;
    if (!detail::storageColor(colorFormat, VK_IMAGE_USAGE_STORAGE_BIT) &&
        !detail::formatBlends(colorFormat, model))
        throw InvalidInput("lightscatter: budget color format " + rg::formatName(colorFormat) +
                           ": not one a device blends into as a color attachment");
    // The settings a frame of this profile and custom runs with.
    const Settings s = profileSettings(profile, custom ? *custom : Settings{});
    checkSettings(s);

    // The frame budget() describes: each light reaching the view, with a shadow map of
    // shadowMapSize (a point light's a cube of six faces, where the method samples one).
    const VkExtent2D screen{screenWidth, screenHeight};
    detail::ValidatedFrame frame;
    detail::FrameImports images;
    describeEngineImages(images, screen, colorFormat);
    std::vector<const ls::MethodUnit*> methods;
    for (size_t i = 0; i < lights.size(); ++i) {
        const LightType type = lights[i].type;
        ls::LightSetup l;
        l.light.kind = type;
        l.shadowed = lights[i].shadowed;
        l.light.shadowMapSize = l.shadowed ? shadowMapSize : 0;
        l.screen = screen;
        l.depthAttachment = true;
        l.settings = s;
        // No geometry: the light's screen rectangle is unknown (empty), so auto weighs the screen.
        detail::LightPaths paths;
        paths.about = "budget lights[" + std::to_string(i) + "]";
        const detail::MethodChoice choice = [&] {
            try {
                return detail::chooseMethod(lights[i].method, l, true);
            } catch (const InvalidInput& e) {
                throw detail::aboutLight(e, paths);
            }
        }();
        methods.push_back(&choice.unit());
        frame.given.push_back({LightInput{}, paths, i, i});
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
    // A one-per-frame method (froxels) takes every light, as in a frame.
    for (size_t i = 0; i < methods.size(); ++i)
        if (methods[i]->caps().onePerFrame && methods != std::vector(methods.size(), methods[i]))
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
    // Seed 000's figures are for one light.
    if (lights.size() == 1) b.seed = methods[0]->seedFigure(profile);
    for (const ls::MethodUnit* m : methods) b.lightMethods.push_back(m->name());
    b.totalBytes = compiled.unaliasedBytes;
    b.peakBytes = compiled.aliasedBytes;
    for (uint32_t id = 0; id < fg.graph->resources().size(); ++id) {
        const auto& r = fg.graph->resource(id);
        const auto& p = compiled.resources[id];
        if (r.persistent) {
            // What the graph keeps across frames, outside its aliased memory: each point or spot
            // light's table, the plugin's own tiling noise, a history's two images.
            const rg::PersistentImageDesc& d = r.persistent->desc;
            const uint64_t bytes = persistentBytes(device, d.format, d.extent, d.depth);
            b.entries.push_back({r.name, rg::formatName(d.format), d.extent.width, d.extent.height,
                                 bytes, false, d.depth});
            b.totalBytes += bytes;
            b.peakBytes += bytes;
            continue;
        }
        if (r.imported || !p.used) continue;
        b.entries.push_back({r.name, r.buffer ? "buffer" : rg::formatName(r.image.format),
                             p.extent.width, p.extent.height, p.memory.size, true,
                             r.buffer ? 1u : r.image.depth});
    }
    return b;
}

}  // namespace lightscatter
