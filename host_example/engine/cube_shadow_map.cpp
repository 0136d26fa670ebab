#include "cube_shadow_map.h"

#include "rendergraph/vk_error.h"

namespace host {

CubeShadowMap::CubeShadowMap(const rg::Device& device, uint32_t size, const std::string& name)
    : device_(device),
      name_(name),
      image_(device, VK_FORMAT_D32_SFLOAT, VkExtent2D{size, size},
             VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT, name, 6,
             VK_IMAGE_CREATE_CUBE_COMPATIBLE_BIT) {
    static const char* kFaces[6] = {"+X", "-X", "+Y", "-Y", "+Z", "-Z"};
    try {
        for (uint32_t i = 0; i < 6; ++i) {
            VkImageViewCreateInfo info{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
            info.image = image_.image();
            info.viewType = VK_IMAGE_VIEW_TYPE_2D;
            info.format = VK_FORMAT_D32_SFLOAT;
            info.subresourceRange = {VK_IMAGE_ASPECT_DEPTH_BIT, 0, 1, i, 1};
            RG_VK(vkCreateImageView(device.device(), &info, nullptr, &faceViews_[i]));
            device.setName(faceViews_[i], VK_OBJECT_TYPE_IMAGE_VIEW, name + " face " + kFaces[i]);
        }
    } catch (...) {
        // The destructor does not run for a constructor that throws (out of memory).
        destroyViews();
        throw;
    }
}

CubeShadowMap::~CubeShadowMap() {
    destroyViews();
}

void CubeShadowMap::destroyViews() {
    for (VkImageView& v : faceViews_) {
        if (v) vkDestroyImageView(device_.device(), v, nullptr);
        v = VK_NULL_HANDLE;
    }
}

void CubeShadowMap::record(
    VkCommandBuffer cmd, const std::array<glm::mat4, 6>& faces,
    const std::function<void(VkCommandBuffer, const glm::mat4&)>& draw) const {
    device_.beginLabel(cmd, name_);
    // The previous frame's plugin read the faces last (its final barrier made that visible to the
    // fragment tests); they are redrawn from scratch.
    VkImageMemoryBarrier2 b{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER_2};
    b.srcStageMask =
        VK_PIPELINE_STAGE_2_EARLY_FRAGMENT_TESTS_BIT | VK_PIPELINE_STAGE_2_LATE_FRAGMENT_TESTS_BIT;
    b.srcAccessMask = VK_ACCESS_2_NONE;
    b.dstStageMask =
        VK_PIPELINE_STAGE_2_EARLY_FRAGMENT_TESTS_BIT | VK_PIPELINE_STAGE_2_LATE_FRAGMENT_TESTS_BIT;
    b.dstAccessMask = VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_READ_BIT |
                      VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT;
    b.oldLayout = VK_IMAGE_LAYOUT_UNDEFINED;
    b.newLayout = VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL;
    b.srcQueueFamilyIndex = b.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    b.image = image_.image();
    b.subresourceRange = {VK_IMAGE_ASPECT_DEPTH_BIT, 0, 1, 0, 6};
    VkDependencyInfo dep{VK_STRUCTURE_TYPE_DEPENDENCY_INFO};
    dep.imageMemoryBarrierCount = 1;
    dep.pImageMemoryBarriers = &b;
    vkCmdPipelineBarrier2(cmd, &dep);

    const VkExtent2D extent = image_.extent();
    for (size_t i = 0; i < 6; ++i) {
        VkRenderingAttachmentInfo depth{VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO};
        depth.imageView = faceViews_[i];
        depth.imageLayout = VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL;
        depth.loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
        depth.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
        depth.clearValue.depthStencil = {1.0f, 0};
        VkRenderingInfo info{VK_STRUCTURE_TYPE_RENDERING_INFO};
        info.renderArea = {{0, 0}, extent};
        info.layerCount = 1;
        info.pDepthAttachment = &depth;
        vkCmdBeginRendering(cmd, &info);
        const VkViewport viewport{
            0.0f, 0.0f, static_cast<float>(extent.width), static_cast<float>(extent.height),
            0.0f, 1.0f};
        const VkRect2D scissor{{0, 0}, extent};
        vkCmdSetViewport(cmd, 0, 1, &viewport);
        vkCmdSetScissor(cmd, 0, 1, &scissor);
        draw(cmd, faces[i]);
        vkCmdEndRendering(cmd);
    }
    device_.endLabel(cmd);
}

}  // namespace host
