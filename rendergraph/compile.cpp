#include "compile.h"

#include "format_info.h"
#include "memory_placement.h"

namespace rg {
namespace {

VkImageCreateInfo imageInfo(const ResourceDecl& r, const ResourcePlan& plan) {
    VkImageCreateInfo info{VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO};
    info.imageType = r.image.depth > 1 ? VK_IMAGE_TYPE_3D : VK_IMAGE_TYPE_2D;
    info.format = r.image.format;
    info.extent = {plan.extent.width, plan.extent.height, r.image.depth};
    info.mipLevels = r.image.mipLevels;
    info.arrayLayers = r.image.arrayLayers;
    info.samples = VK_SAMPLE_COUNT_1_BIT;
    info.tiling = VK_IMAGE_TILING_OPTIMAL;
    info.usage = plan.imageUsage;
    info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
    info.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
    return info;
}

}  // namespace

VkImageCreateInfo transientImageInfo(const ResourceDecl& r, const ResourcePlan& plan) {
    return imageInfo(r, plan);
}

CompiledGraph compile(const RenderGraph& graph, const DeviceCaps& caps,
                      const CompileOptions& options) {
    detail::validate(graph, caps);
    const detail::Schedule sched = detail::schedule(graph);

    CompiledGraph out;
    out.screen = graph.screenExtent();
    out.culled = sched.culled;
    out.exactSizes = caps.exact();
    out.resources.resize(graph.resources().size());
    for (uint32_t id = 0; id < graph.resources().size(); ++id) {
        const auto& r = graph.resource(id);
        auto& plan = out.resources[id];
        plan.buffer = r.buffer;
        plan.imported = r.imported;
        if (!r.buffer) plan.extent = graph.imageExtent(id);
    }

    // Lifetimes and the usage flags transient resources are created with.
    for (uint32_t pos = 0; pos < sched.order.size(); ++pos) {
        PassPlan pp;
        pp.pass = sched.order[pos];
        out.passes.push_back(pp);
        for (const auto& u : graph.passes()[pp.pass].uses) {
            auto& plan = out.resources[u.resource];
            if (!plan.used) plan.firstPass = pos;
            plan.used = true;
            plan.lastPass = pos;
            if (plan.buffer)
                plan.bufferUsage |= bufferUsageFor(u.kind);
            else
                plan.imageUsage |= imageUsageFor(u.kind);
        }
    }

    out.poisonTransients = options.poisonTransients;
    if (options.poisonTransients)
        for (auto& plan : out.resources) {
            if (!plan.used || plan.imported) continue;
            if (plan.buffer)
                plan.bufferUsage |= VK_BUFFER_USAGE_TRANSFER_DST_BIT;
            else
                plan.imageUsage |= VK_IMAGE_USAGE_TRANSFER_DST_BIT;
        }

    // Memory: requirements from the device (or the estimate), then placement.
    std::vector<PlacementItem> items;
    std::vector<uint32_t> itemResource;
    for (uint32_t id = 0; id < graph.resources().size(); ++id) {
        auto& plan = out.resources[id];
        const auto& r = graph.resource(id);
        if (!plan.used || plan.imported) continue;
        if (plan.buffer) {
            VkBufferCreateInfo info{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
            info.size = r.bufferDesc.size;
            info.usage = plan.bufferUsage;
            info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
            plan.memory = caps.bufferRequirements(info);
        } else {
            plan.memory = caps.imageRequirements(imageInfo(r, plan));
        }
        plan.memoryType = caps.memoryTypeFor(plan.memory.memoryTypeBits);
        items.push_back({plan.memory.size, plan.memory.alignment, plan.firstPass, plan.lastPass,
                         plan.memoryType, plan.buffer});
        itemResource.push_back(id);
        out.unaliasedBytes += plan.memory.size;
    }
    const PlacementResult placed =
        placeResources(items, caps.bufferImageGranularity(), options.aliasing);
    for (size_t i = 0; i < items.size(); ++i) {
        auto& plan = out.resources[itemResource[i]];
        plan.block = placed.placements[i].block;
        plan.offset = placed.placements[i].offset;
    }
    out.blocks = placed.blocks;
    for (const auto& b : out.blocks) out.aliasedBytes += b.size;

    detail::deriveSync(graph, out);
    return out;
}

}  // namespace rg
