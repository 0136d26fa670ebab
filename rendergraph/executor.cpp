#include "executor.h"

#include <algorithm>
#include <bit>

#include "compile.h"
#include "device_memory.h"
#include "fault_injection.h"
#include "format_info.h"
#include "import_barriers.h"
#include "memory_counter.h"
#include "vk_error.h"

namespace rg {
namespace {

constexpr VkImageUsageFlags kViewUsages =
    VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT |
    VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT | VK_IMAGE_USAGE_INPUT_ATTACHMENT_BIT;

VkImageViewType viewType(const ImageDesc& d) {
    if (d.depth > 1) return VK_IMAGE_VIEW_TYPE_3D;
    return d.arrayLayers > 1 ? VK_IMAGE_VIEW_TYPE_2D_ARRAY : VK_IMAGE_VIEW_TYPE_2D;
}

// A named pool, every query reset from the host so that the first frame may read any slot.
VkQueryPool createQueryPool(const Device& device, VkQueryType type, uint32_t count,
                            const char* name) {
    VkQueryPoolCreateInfo info{VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO};
    info.queryType = type;
    info.queryCount = count;
    VkQueryPool pool = VK_NULL_HANDLE;
    RG_VK_CREATE(device.vk().CreateQueryPool(device.device(), &info, device.allocator(), &pool));
    device.setName(pool, VK_OBJECT_TYPE_QUERY_POOL, name);
    device.vk().ResetQueryPool(device.device(), pool, 0, count);
    return pool;
}

}  // namespace

GraphExecutor::GraphExecutor(const Device& device, RenderGraph& graph, CompiledGraph compiled,
                             const TransientHeap* heap, PersistentStore* store)
    : device_(device), graph_(graph), compiled_(std::move(compiled)), heap_(heap), store_(store) {
    const VkDevice dev = device_.device();
    images_.resize(graph_.resources().size());
    buffers_.resize(graph_.resources().size(), VK_NULL_HANDLE);
    importViews_.resize(kTimingSlots);
    for (const PassPlan& plan : compiled_.passes)
        for (const PassResourceState& s : plan.states) {
            if (graph_.resource(s.resource).imported) continue;
            transientScope_.stages |= s.stages;
            if (s.writes) transientScope_.writes |= s.access;
        }
    try {
        createMemory();

        formats_.resize(compiled_.passes.size());
        for (uint32_t pos = 0; pos < compiled_.passes.size(); ++pos) {
            const PassPlan& plan = compiled_.passes[pos];
            for (const auto& c : plan.colors)
                formats_[pos].colors.push_back(graph_.resource(c.resource).image.format);
            if (plan.depth)
                formats_[pos].depth = graph_.resource(plan.depth->resource).image.format;
            if (plan.stencil)
                formats_[pos].stencil = graph_.resource(plan.stencil->resource).image.format;
        }

        // Two timestamps per pass, in one slot per frame of the last kTimingSlots.
        queriesPerFrame_ =
            std::max<uint32_t>(2, 2 * static_cast<uint32_t>(compiled_.passes.size()));
        slotFrames_.assign(kTimingSlots, 0);
        queries_ = createQueryPool(device_, VK_QUERY_TYPE_TIMESTAMP,
                                   queriesPerFrame_ * kTimingSlots, "render graph pass timestamps");

        // One occlusion query per counting graphics pass, in one slot per frame like the stamps.
        countIndex_.assign(compiled_.passes.size(), -1);
        for (uint32_t pos = 0; pos < compiled_.passes.size(); ++pos) {
            const PassDecl& pass = graph_.passes()[compiled_.passes[pos].pass];
            if (pass.countSamples && pass.type == PassType::Graphics)
                countIndex_[pos] = static_cast<int32_t>(countedPerFrame_++);
        }
        if (countedPerFrame_)
            samples_ =
                createQueryPool(device_, VK_QUERY_TYPE_OCCLUSION, countedPerFrame_ * kTimingSlots,
                                "render graph pass sample counts");

        VkCommandPoolCreateInfo pool{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
        pool.flags = VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT;
        pool.queueFamilyIndex = device_.queueFamily();
        RG_VK_CREATE(device_.vk().CreateCommandPool(dev, &pool, device_.allocator(), &pool_));
        device_.setName(pool_, VK_OBJECT_TYPE_COMMAND_POOL, "render graph command pool");
        VkCommandBufferAllocateInfo alloc{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
        alloc.commandPool = pool_;
        alloc.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
        alloc.commandBufferCount = 1;
        RG_VK_CREATE(device_.vk().AllocateCommandBuffers(dev, &alloc, &cmd_));
        device_.setName(cmd_, VK_OBJECT_TYPE_COMMAND_BUFFER, "render graph frame");
        VkFenceCreateInfo fence{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
        RG_VK_CREATE(device_.vk().CreateFence(dev, &fence, device_.allocator(), &fence_));
        device_.setName(fence_, VK_OBJECT_TYPE_FENCE, "render graph frame fence");
    } catch (...) {
        destroy();
        throw;
    }
}

GraphExecutor::~GraphExecutor() {
    destroy();
}

void GraphExecutor::destroyViews(ImageObjects& o) {
    for (VkImageView v : {o.full, o.depth, o.stencil})
        if (v) device_.vk().DestroyImageView(device_.device(), v, device_.allocator());
    o.full = o.depth = o.stencil = VK_NULL_HANDLE;
}

// The owner has made sure the GPU is done with every frame recorded here (see the header).
void GraphExecutor::destroy() {
    const VkDevice dev = device_.device();
    if (!dev) return;
    for (uint32_t id = 0; id < images_.size(); ++id) {
        if (graph_.resource(id).imported) continue;
        destroyViews(images_[id]);
        if (images_[id].image)
            device_.vk().DestroyImage(dev, images_[id].image, device_.allocator());
        images_[id].image = VK_NULL_HANDLE;
    }
    for (auto& slot : importViews_) {
        for (ImageObjects& views : slot) destroyViews(views);
        slot.clear();
    }
    for (uint32_t id = 0; id < buffers_.size(); ++id)
        if (buffers_[id] && !graph_.resource(id).imported)
            device_.vk().DestroyBuffer(dev, buffers_[id], device_.allocator());
    buffers_.clear();
    for (size_t b = 0; b < blocks_.size() && !heap_; ++b) {
        detail::uncountDeviceMemory(std::max<VkDeviceSize>(compiled_.blocks[b].size, 1));
        device_.vk().FreeMemory(dev, blocks_[b], device_.allocator());
    }
    blocks_.clear();
    if (fence_) device_.vk().DestroyFence(dev, fence_, device_.allocator());
    if (pool_) device_.vk().DestroyCommandPool(dev, pool_, device_.allocator());
    if (queries_) device_.vk().DestroyQueryPool(dev, queries_, device_.allocator());
    if (samples_) device_.vk().DestroyQueryPool(dev, samples_, device_.allocator());
    fence_ = VK_NULL_HANDLE;
    pool_ = VK_NULL_HANDLE;
    queries_ = VK_NULL_HANDLE;
    samples_ = VK_NULL_HANDLE;
}

void GraphExecutor::createMemory() {
    if (heap_) heapGeneration_ = heap_->generation();
    for (uint32_t b = 0; b < compiled_.blocks.size(); ++b) {
        const VkDeviceSize bytes = std::max<VkDeviceSize>(compiled_.blocks[b].size, 1);
        if (heap_) {
            const uint32_t type = compiled_.blocks[b].memoryType;
            if (heap_->size(type) < bytes)
                throw VulkanError("the transient heap has no room for block " + std::to_string(b) +
                                  " (TransientHeap::reserve first)");
            blocks_.push_back(heap_->memory(type));
            continue;
        }
        blocks_.push_back(
            allocateDeviceMemory(device_, bytes, compiled_.blocks[b].memoryType, blockContents(b)));
        detail::countDeviceMemory(bytes);
        device_.setName(blocks_.back(), VK_OBJECT_TYPE_DEVICE_MEMORY,
                        "render graph transient block " + std::to_string(b));
    }
    for (uint32_t id = 0; id < graph_.resources().size(); ++id) {
        const ResourceDecl& r = graph_.resource(id);
        const ResourcePlan& plan = compiled_.resources[id];
        if (r.imported) {
            if (r.buffer) buffers_[id] = r.importedBuffer.buffer;
            continue;
        }
        if (!plan.used) continue;
        try {
            createResource(id);
        } catch (const OutOfDeviceMemory&) {
            throw;  // names the resource already
        } catch (const VulkanError& e) {
            throw VulkanError("render graph resource '" + r.name + "': " + e.what());
        }
    }
}

// A transient block as a message names it: its size comes with the message, the largest
// resources in it say what made it that large.
std::string GraphExecutor::blockContents(uint32_t block) const {
    std::vector<uint32_t> ids;
    for (uint32_t id = 0; id < graph_.resources().size(); ++id)
        if (!graph_.resource(id).imported && compiled_.resources[id].used &&
            compiled_.resources[id].block == block)
            ids.push_back(id);
    std::sort(ids.begin(), ids.end(), [&](uint32_t a, uint32_t b) {
        return compiled_.resources[a].memory.size > compiled_.resources[b].memory.size;
    });
    std::string largest;
    for (size_t i = 0; i < ids.size() && i < 3; ++i) {
        const ResourceDecl& r = graph_.resource(ids[i]);
        const ResourcePlan& p = compiled_.resources[ids[i]];
        largest +=
            std::string(i ? ", " : "") + "'" + r.name + "' " +
            (r.buffer ? "buffer"
                      : std::to_string(p.extent.width) + "x" + std::to_string(p.extent.height) +
                            " " + formatName(r.image.format)) +
            " " + bytesText(p.memory.size);
    }
    return "the render graph's transient memory block " + std::to_string(block) + " (" +
           std::to_string(ids.size()) + " resources; the largest " + largest + ")";
}

void GraphExecutor::createResource(uint32_t id) {
    const VkDevice dev = device_.device();
    const ResourceDecl& r = graph_.resource(id);
    const ResourcePlan& plan = compiled_.resources[id];
    VkMemoryRequirements req;
    if (r.buffer) {
        VkBufferCreateInfo info{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
        info.size = r.bufferDesc.size;
        info.usage = plan.bufferUsage;
        info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
        RG_VK_CREATE(device_.vk().CreateBuffer(dev, &info, device_.allocator(), &buffers_[id]));
        device_.setName(buffers_[id], VK_OBJECT_TYPE_BUFFER, r.name);
        device_.vk().GetBufferMemoryRequirements(dev, buffers_[id], &req);
    } else {
        const VkImageCreateInfo info = transientImageInfo(r, plan);
        checkImageLimits(device_, info, "render graph resource '" + r.name + "'");
        RG_VK_CREATE(device_.vk().CreateImage(dev, &info, device_.allocator(), &images_[id].image));
        device_.setName(images_[id].image, VK_OBJECT_TYPE_IMAGE, r.name);
        device_.vk().GetImageMemoryRequirements(dev, images_[id].image, &req);
    }
    // The plan used vkGetDevice*MemoryRequirements for the same create info; a driver that answers
    // differently for the real object would break the placement.
    if (req.size > plan.memory.size || plan.offset % req.alignment != 0 ||
        !(req.memoryTypeBits & (1u << plan.memoryType)))
        throw VulkanError("the driver's memory requirements differ from the compiled plan");
    // The message, and the scan of the block it names, only for a bind that failed: this runs for
    // every resource of every graph built.
    const VkResult bound = r.buffer ? device_.vk().BindBufferMemory(
                                          dev, buffers_[id], blocks_[plan.block], plan.offset)
                                    : device_.vk().BindImageMemory(
                                          dev, images_[id].image, blocks_[plan.block], plan.offset);
    if (bound != VK_SUCCESS)
        checkBind(device_, bound, r.buffer ? "vkBindBufferMemory" : "vkBindImageMemory",
                  compiled_.blocks[plan.block].size, plan.memoryType,
                  "render graph resource '" + r.name + "' in " + blockContents(plan.block));
    // An image only copied to and from has no view (Vulkan forbids one).
    if (!r.buffer && (plan.imageUsage & kViewUsages))
        images_[id] = makeViews(id, images_[id].image);
}

GraphExecutor::ImageObjects GraphExecutor::makeViews(uint32_t resource, VkImage image) {
    const ResourceDecl& r = graph_.resource(resource);
    ImageObjects o;
    o.image = image;
    VkImageViewCreateInfo info{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
    info.image = image;
    info.viewType = viewType(r.image);
    info.format = r.image.format;
    info.subresourceRange = {fullAspect(r.image.format), 0, r.image.mipLevels, 0,
                             r.image.arrayLayers};
    auto make = [&](VkImageAspectFlags aspect, const char* suffix) {
        info.subresourceRange.aspectMask = aspect;
        VkImageView v;
        RG_VK_CREATE(
            device_.vk().CreateImageView(device_.device(), &info, device_.allocator(), &v));
        device_.setName(v, VK_OBJECT_TYPE_IMAGE_VIEW, r.name + suffix);
        return v;
    };
    try {
        o.full = make(fullAspect(r.image.format), " view");
        if (hasDepth(r.image.format) && hasStencil(r.image.format)) {
            o.depth = make(VK_IMAGE_ASPECT_DEPTH_BIT, " depth view");
            o.stencil = make(VK_IMAGE_ASPECT_STENCIL_BIT, " stencil view");
        }
    } catch (...) {
        for (VkImageView v : {o.full, o.depth, o.stencil})
            if (v) device_.vk().DestroyImageView(device_.device(), v, device_.allocator());
        throw;
    }
    return o;
}

// Views of this frame's imported images, made afresh: a handle says nothing of whether the image
// behind it is the one seen before (an engine's allocator may give a destroyed image's handle to
// the next one). The slot's views from kTimingSlots frames ago are done with.
void GraphExecutor::refreshImports(uint32_t slot) {
    std::vector<ImageObjects>& views = importViews_[slot];
    for (ImageObjects& o : views) destroyViews(o);
    views.clear();
    for (uint32_t id = 0; id < graph_.resources().size(); ++id) {
        const ResourceDecl& r = graph_.resource(id);
        if (!r.imported) continue;
        if (r.buffer) {
            buffers_[id] = r.importedBuffer.buffer;
            continue;
        }
        const VkImage img = r.importedImage.image;
        if (!img) throw VulkanError("imported image '" + r.name + "' has no VkImage to run with");
        // The image and its debug name are the engine's; only the views are the runtime's, and an
        // image only copied to and from has none (Vulkan forbids one). A persistent image's view
        // is kept with it (persistent_store.h).
        ImageObjects o{img};
        if (r.persistent) {
            Bound& b = bound_[id];
            VkImageView& kept = b.entry->views[b.image];
            if (!kept) kept = makeViews(id, img).full;
            o.full = kept;
        } else if (r.importedImage.usage & kViewUsages) {
            o = makeViews(id, img);
            views.push_back(o);
        }
        images_[id] = o;
    }
}

void GraphExecutor::releaseCompleted(uint64_t completed) {
    for (uint32_t slot = 0; slot < kTimingSlots; ++slot) {
        if (slotFrames_[slot] > completed || importViews_[slot].empty()) continue;
        for (ImageObjects& o : importViews_[slot]) destroyViews(o);
        importViews_[slot].clear();
    }
}

void GraphExecutor::recordBarriers(VkCommandBuffer cmd, const std::vector<BarrierPlan>& barriers) {
    std::vector<VkImageMemoryBarrier2> imageBarriers;
    std::vector<VkBufferMemoryBarrier2> bufferBarriers;
    for (const BarrierPlan& b : barriers) {
        const ResourceDecl& r = graph_.resource(b.resource);
        if (b.buffer) {
            VkBufferMemoryBarrier2 bb{VK_STRUCTURE_TYPE_BUFFER_MEMORY_BARRIER_2};
            bb.srcStageMask = b.srcStages;
            bb.srcAccessMask = b.srcAccess;
            bb.dstStageMask = b.dstStages;
            bb.dstAccessMask = b.dstAccess;
            bb.srcQueueFamilyIndex = bb.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
            bb.buffer = buffers_[b.resource];
            bb.offset = 0;
            bb.size = VK_WHOLE_SIZE;
            bufferBarriers.push_back(bb);
        } else {
            VkImageMemoryBarrier2 ib{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER_2};
            ib.srcStageMask = b.srcStages;
            ib.srcAccessMask = b.srcAccess;
            ib.dstStageMask = b.dstStages;
            ib.dstAccessMask = b.dstAccess;
            ib.oldLayout = b.oldLayout;
            ib.newLayout = b.newLayout;
            ib.srcQueueFamilyIndex = ib.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
            ib.image = images_[b.resource].image;
            ib.subresourceRange = {fullAspect(r.image.format), 0, r.image.mipLevels, 0,
                                   r.image.arrayLayers};
            imageBarriers.push_back(ib);
        }
    }
    if (imageBarriers.empty() && bufferBarriers.empty()) return;
    VkDependencyInfo dep{VK_STRUCTURE_TYPE_DEPENDENCY_INFO};
    dep.imageMemoryBarrierCount = static_cast<uint32_t>(imageBarriers.size());
    dep.pImageMemoryBarriers = imageBarriers.data();
    dep.bufferMemoryBarrierCount = static_cast<uint32_t>(bufferBarriers.size());
    dep.pBufferMemoryBarriers = bufferBarriers.data();
    device_.vk().CmdPipelineBarrier2(cmd, &dep);
}

// Fills the transients this pass uses first with a signalling pattern, after whatever last used
// their memory, and returns the pass's barriers with those first uses now waiting on the fill.
std::vector<BarrierPlan> GraphExecutor::poisonFirstUses(VkCommandBuffer cmd,
                                                        const std::vector<BarrierPlan>& barriers) {
    std::vector<BarrierPlan> toFill, patched = barriers;
    for (BarrierPlan& b : patched) {
        if (!b.firstUse) continue;
        BarrierPlan fill = b;
        fill.dstStages =
            VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT;  // fills count as copies, clears as clears
        fill.dstAccess = VK_ACCESS_2_TRANSFER_WRITE_BIT;
        fill.newLayout =
            b.buffer ? VK_IMAGE_LAYOUT_UNDEFINED : VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL;
        toFill.push_back(fill);
        b.srcStages = VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT;
        b.srcAccess = VK_ACCESS_2_TRANSFER_WRITE_BIT;
        b.oldLayout = fill.newLayout;
    }
    if (toFill.empty()) return patched;
    recordBarriers(cmd, toFill);
    constexpr uint32_t kNaN = 0x7fc00000u;
    for (const BarrierPlan& b : toFill) {
        if (b.buffer) {
            device_.vk().CmdFillBuffer(cmd, buffers_[b.resource], 0, VK_WHOLE_SIZE, kNaN);
            continue;
        }
        const ResourceDecl& r = graph_.resource(b.resource);
        const VkImageSubresourceRange range{fullAspect(r.image.format), 0, r.image.mipLevels, 0,
                                            r.image.arrayLayers};
        if (isDepthStencil(r.image.format)) {
            // Depth must stay in [0, 1]; an odd depth and stencil stand in for NaN.
            const VkClearDepthStencilValue v{0.5f, 0xA5u};
            device_.vk().CmdClearDepthStencilImage(cmd, images_[b.resource].image,
                                                   VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, &v, 1,
                                                   &range);
        } else {
            VkClearColorValue v;
            if (isIntegerFormat(r.image.format)) {
                for (uint32_t& c : v.uint32) c = ~0u;
            } else {
                for (float& c : v.float32) c = std::bit_cast<float>(kNaN);
            }
            device_.vk().CmdClearColorImage(cmd, images_[b.resource].image,
                                            VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, &v, 1, &range);
        }
    }
    return patched;
}

void GraphExecutor::recordPass(VkCommandBuffer cmd, uint32_t position,
                               const TransientScope* before) {
    const PassPlan& plan = compiled_.passes[position];
    PassDecl& pass = graph_.passes()[plan.pass];
    device_.beginLabel(cmd, pass.name);
    device_.vk().CmdWriteTimestamp2(cmd, VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, queries_,
                                    firstQuery_ + 2 * position);
    std::vector<BarrierPlan> barriers = plan.barriers;
    // Another graph used this memory in the frame before: a first use waits on all it did.
    if (before)
        for (BarrierPlan& b : barriers) {
            if (!b.firstUse) continue;
            b.srcStages |= before->stages;
            b.srcAccess |= before->writes;
        }
    if (compiled_.poisonTransients)
        recordBarriers(cmd, poisonFirstUses(cmd, barriers));
    else
        recordBarriers(cmd, barriers);

    PassContext ctx(*this, position, cmd);
    if (pass.type == PassType::Graphics) {
        auto attachment = [&](const AttachmentPlan& a, VkImageView view) {
            VkRenderingAttachmentInfo info{VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO};
            info.imageView = view;
            info.imageLayout = a.layout;
            info.loadOp = a.load;
            info.storeOp = a.store;
            info.clearValue = a.clear;
            return info;
        };
        std::vector<VkRenderingAttachmentInfo> colors;
        for (const auto& c : plan.colors) colors.push_back(attachment(c, images_[c.resource].full));
        VkRenderingAttachmentInfo depth{}, stencil{};
        VkRenderingInfo info{VK_STRUCTURE_TYPE_RENDERING_INFO};
        const VkExtent2D extent = renderExtent(position);
        info.renderArea = {{0, 0}, extent};
        info.layerCount = 1;
        info.colorAttachmentCount = static_cast<uint32_t>(colors.size());
        info.pColorAttachments = colors.data();
        if (plan.depth) {
            depth = attachment(*plan.depth, images_[plan.depth->resource].full);
            info.pDepthAttachment = &depth;
        }
        if (plan.stencil) {
            stencil = attachment(*plan.stencil, images_[plan.stencil->resource].full);
            info.pStencilAttachment = &stencil;
        }
        const int32_t counted = countIndex_[position];
        if (counted >= 0)
            device_.vk().CmdBeginQuery(
                cmd, samples_, slot_ * countedPerFrame_ + static_cast<uint32_t>(counted), 0);
        device_.vk().CmdBeginRendering(cmd, &info);
        VkViewport viewport{
            0.0f, 0.0f, static_cast<float>(extent.width), static_cast<float>(extent.height),
            0.0f, 1.0f};
        VkRect2D scissor{{0, 0}, extent};
        device_.vk().CmdSetViewport(cmd, 0, 1, &viewport);
        device_.vk().CmdSetScissor(cmd, 0, 1, &scissor);
        if (pass.execute) pass.execute(ctx);
        device_.vk().CmdEndRendering(cmd);
        if (counted >= 0)
            device_.vk().CmdEndQuery(cmd, samples_,
                                     slot_ * countedPerFrame_ + static_cast<uint32_t>(counted));
    } else if (pass.execute) {
        pass.execute(ctx);
    }
    device_.vk().CmdWriteTimestamp2(cmd, VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, queries_,
                                    firstQuery_ + 2 * position + 1);
    device_.endLabel(cmd);
}

VkExtent2D GraphExecutor::renderExtent(uint32_t position) const {
    const PassPlan& plan = compiled_.passes[position];
    return plan.screenSized ? frameScreen_ : plan.renderExtent;
}

uint64_t GraphExecutor::record(VkCommandBuffer cmd, uint64_t frame, const FrameData& data,
                               const TransientScope* before, VkExtent2D screen) {
    const VkExtent2D full = graph_.screenExtent();
    if (screen.width == 0 || screen.height == 0) screen = full;
    if (screen.width > full.width || screen.height > full.height)
        throw VulkanError("a frame of " + std::to_string(screen.width) + "x" +
                          std::to_string(screen.height) + " on a graph built for " +
                          std::to_string(full.width) + "x" + std::to_string(full.height));
    frameScreen_ = screen;
    if (heap_ && heap_->generation() != heapGeneration_)
        throw VulkanError("the transient heap was replaced since this graph was placed in it");
    if (frame == 0) frame = lastFrame_ + 1;
    const uint32_t slot = static_cast<uint32_t>(frame % kTimingSlots);
    // Before any command: what it makes (a new persistent image) may fail, leaving `cmd` as given.
    bindPersistent(data, frame);
    refreshImports(slot);
    frameData_ = &data;
    firstQuery_ = slot * queriesPerFrame_;
    slot_ = slot;
    // Reset on the host, so the slot reads as not finished until this frame has run; and in the
    // command buffer too, so that it may be submitted again.
    device_.vk().ResetQueryPool(device_.device(), queries_, firstQuery_, queriesPerFrame_);
    slotFrames_[slot] = frame;
    lastFrame_ = frame;
    const uint32_t queryCount = 2 * static_cast<uint32_t>(compiled_.passes.size());
    if (queryCount) device_.vk().CmdResetQueryPool(cmd, queries_, firstQuery_, queryCount);
    if (countedPerFrame_) {
        device_.vk().ResetQueryPool(device_.device(), samples_, slot * countedPerFrame_,
                                    countedPerFrame_);
        device_.vk().CmdResetQueryPool(cmd, samples_, slot * countedPerFrame_, countedPerFrame_);
    }
    device_.beginLabel(cmd, "render graph");
    // Import stages and access may change per frame (layouts may not), so the barriers that
    // wait on or hand back an import are patched here.
    std::vector<bool> waited(graph_.resources().size(), false);
    for (uint32_t pos = 0; pos < compiled_.passes.size(); ++pos) {
        PassPlan& plan = compiled_.passes[pos];
        for (auto& b : plan.barriers) {
            const ResourceDecl& r = graph_.resource(b.resource);
            if (!r.imported || compiled_.resources[b.resource].firstPass != pos) continue;
            detail::waitOnImport(b, r);
            waited[b.resource] = true;
        }
    }
    // An image given UNDEFINED for this frame needs the first-use barrier that transitions it.
    for (uint32_t id = 0; id < graph_.resources().size(); ++id) {
        const ResourceDecl& r = graph_.resource(id);
        if (r.imported && !r.buffer && compiled_.resources[id].used && !waited[id] &&
            r.importedImage.initialLayout != r.declaredLayout)
            throw VulkanError("imported image '" + r.name +
                              "' is given UNDEFINED where the graph has no barrier before its "
                              "first use; build a graph for that layout");
    }
    try {
        for (uint32_t pos = 0; pos < compiled_.passes.size(); ++pos) recordPass(cmd, pos, before);
    } catch (...) {
        frameData_ = nullptr;
        throw;
    }
    frameData_ = nullptr;
    std::vector<BarrierPlan> finals = compiled_.finalBarriers;
    for (auto& b : finals) {
        const ResourceDecl& r = graph_.resource(b.resource);
        if (compiled_.resources[b.resource].used) {
            detail::handBackImport(b, r);
        } else if (!r.buffer) {
            detail::waitOnImport(b, r);
            b.newLayout = detail::importFinish(r).layout;
        }
    }
    recordBarriers(cmd, finals);
    device_.endLabel(cmd);
    if (!rehearsing_) commitPersistent(frame);
    return frame;
}

void GraphExecutor::rehearse(const FrameData& data, VkExtent2D screen) {
    // Nothing of it is submitted: the frame number and the timing slot it took are given back.
    const uint64_t lastFrame = lastFrame_;
    const std::vector<uint64_t> slotFrames = slotFrames_;
    auto restore = [&] {
        lastFrame_ = lastFrame;
        slotFrames_ = slotFrames;
    };
    RG_VK(device_.vk().ResetCommandBuffer(cmd_, 0));
    VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
    begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
    RG_VK(device_.vk().BeginCommandBuffer(cmd_, &begin));
    rehearsing_ = true;
    try {
        record(cmd_, 0, data, nullptr, screen);
    } catch (...) {
        rehearsing_ = false;
        device_.vk().ResetCommandBuffer(
            cmd_, 0);  // possibly inside a rendering scope: not ended, dropped
        restore();
        throw;
    }
    rehearsing_ = false;
    RG_VK(device_.vk().EndCommandBuffer(cmd_));
    RG_VK(device_.vk().ResetCommandBuffer(cmd_, 0));
    restore();
}

FrameTimings GraphExecutor::run(uint64_t frame, const FrameData& data, const TransientScope* before,
                                VkExtent2D screen) {
    RG_VK(device_.vk().ResetCommandBuffer(cmd_, 0));
    VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
    begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
    RG_VK(device_.vk().BeginCommandBuffer(cmd_, &begin));
    frame = record(cmd_, frame, data, before, screen);
    RG_VK(device_.vk().EndCommandBuffer(cmd_));
    device_.submitAndWait(cmd_, fence_);
    return readTimings(frame);
}

FrameTimings GraphExecutor::readTimings() {
    return readTimings(lastFrame_);
}

FrameTimings GraphExecutor::readTimings(uint64_t frame) {
    FrameTimings t;
    t.frame = frame;
    const uint32_t n = static_cast<uint32_t>(compiled_.passes.size());
    const uint32_t slot = static_cast<uint32_t>(frame % kTimingSlots);
    if (frame == 0 || n == 0 || slotFrames_[slot] != frame) return t;
    // Value and availability per query; never waits (a frame recorded but not submitted would
    // never become available).
    std::vector<uint64_t> results(4 * n);
    const VkResult r = device_.vk().GetQueryPoolResults(
        device_.device(), queries_, slot * queriesPerFrame_, 2 * n,
        results.size() * sizeof(uint64_t), results.data(), 2 * sizeof(uint64_t),
        VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WITH_AVAILABILITY_BIT);
    if (r == VK_NOT_READY) return t;
    check(r, "vkGetQueryPoolResults");
    std::vector<uint64_t> stamps(2 * n);
    for (uint32_t i = 0; i < 2 * n; ++i) {
        if (results[2 * i + 1] == 0) return t;
        stamps[i] = results[2 * i];
    }
    const uint32_t bits = device_.timestampValidBits();
    const uint64_t mask = bits >= 64 ? ~uint64_t{0} : ((uint64_t{1} << bits) - 1);
    const double toMs = device_.timestampPeriodNs() * 1e-6;
    std::vector<uint64_t> counts(2 * countedPerFrame_);
    if (countedPerFrame_) {
        const VkResult c = device_.vk().GetQueryPoolResults(
            device_.device(), samples_, slot * countedPerFrame_, countedPerFrame_,
            counts.size() * sizeof(uint64_t), counts.data(), 2 * sizeof(uint64_t),
            VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WITH_AVAILABILITY_BIT);
        if (c == VK_NOT_READY) return t;
        check(c, "vkGetQueryPoolResults");
        for (uint32_t i = 0; i < countedPerFrame_; ++i)
            if (counts[2 * i + 1] == 0) return t;
    }
    for (uint32_t pos = 0; pos < n; ++pos) {
        const uint64_t a = stamps[2 * pos] & mask, b = stamps[2 * pos + 1] & mask;
        const uint64_t ticks = (b - a) & mask;
        const int32_t counted = countIndex_[pos];
        t.passes.push_back(
            {graph_.passes()[compiled_.passes[pos].pass].name, static_cast<double>(ticks) * toMs,
             counted >= 0 ? static_cast<int64_t>(counts[2 * static_cast<uint32_t>(counted)]) : -1});
    }
    const uint64_t ticks = ((stamps[2 * n - 1] & mask) - (stamps[0] & mask)) & mask;
    t.totalMilliseconds = static_cast<double>(ticks) * toMs;
    t.valid = true;
    return t;
}

VkImage GraphExecutor::image(uint32_t resource) const {
    return images_.at(resource).image;
}

VkImageView GraphExecutor::view(uint32_t resource, VkImageAspectFlags aspect) const {
    const ImageObjects& o = images_.at(resource);
    if (aspect == VK_IMAGE_ASPECT_DEPTH_BIT && o.depth) return o.depth;
    if (aspect == VK_IMAGE_ASPECT_STENCIL_BIT && o.stencil) return o.stencil;
    return o.full;
}

VkBuffer GraphExecutor::buffer(uint32_t resource) const {
    return buffers_.at(resource);
}

// ---------------------------------------------------------------------------------------------

const void* PassContext::hostData(uint32_t graph, uint32_t id, const void* tag) const {
    const RenderGraph& g = executor_.graph_;
    const std::string name = graph == g.id() && id < g.hostDataDecls().size()
                                 ? "'" + g.hostDataDecls()[id].name + "'"
                                 : "host data of another graph";
    if (graph != g.id() || id >= g.hostDataDecls().size())
        throw VulkanError("pass '" + passName() + "' reads " + name);
    const void* v = executor_.frameData_ ? executor_.frameData_->find(graph, id, tag) : nullptr;
    if (!v)
        throw VulkanError("pass '" + passName() + "' reads host data " + name +
                          ", which this frame did not give (FrameData::set)");
    return v;
}

const Device& PassContext::device() const {
    return executor_.device_;
}

const std::string& PassContext::passName() const {
    return executor_.graph_.passes()[executor_.compiled_.passes[position_].pass].name;
}

VkImage PassContext::image(ImageRef ref) const {
    return executor_.image(ref.id);
}

const PassResourceState& PassContext::declared(ImageRef ref, const char* asking) const {
    for (const auto& s : executor_.compiled_.passes[position_].states)
        if (s.resource == ref.id) return s;
    throw VulkanError("pass '" + passName() + "' asks for " + asking + " of '" +
                      executor_.graph_.resource(ref.id).name + "', which it did not declare");
}

VkImageView PassContext::view(ImageRef ref, VkImageAspectFlags aspect) const {
    declared(ref, "a view");
    return executor_.view(ref.id, aspect);
}

VkImageLayout PassContext::layout(ImageRef ref) const {
    return declared(ref, "the layout").layout;
}

VkExtent2D PassContext::extent(ImageRef ref) const {
    const ResourceDecl& r = executor_.graph_.resource(ref.id);
    if (r.imported) return r.importedImage.extent;  // this frame's
    return executor_.graph_.imageExtent(ref.id, executor_.frameScreen_);
}

VkFormat PassContext::format(ImageRef ref) const {
    return executor_.graph_.resource(ref.id).image.format;
}

VkBuffer PassContext::buffer(BufferRef ref) const {
    return executor_.buffer(ref.id);
}

VkDeviceSize PassContext::size(BufferRef ref) const {
    return executor_.graph_.resource(ref.id).bufferDesc.size;
}

VkExtent2D PassContext::renderExtent() const {
    return executor_.renderExtent(position_);
}

const RenderingFormats& PassContext::renderingFormats() const {
    return executor_.formats_[position_];
}

}  // namespace rg
