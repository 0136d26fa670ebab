#include "point_table.h"

#include "methods/method_nodes.h"
#include "rendergraph/compile.h"
#include "rendergraph/device_caps_vulkan.h"
#include "rendergraph/executor.h"
#include "rendergraph/vk_error.h"

namespace lightscatter::detail {

PointTable::PointTable(const rg::Device& device, uint32_t width, uint32_t height)
    : device_(device), width_(width), height_(height) {
    VkImageCreateInfo info{VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO};
    info.imageType = VK_IMAGE_TYPE_2D;
    info.format = VK_FORMAT_R32G32B32A32_SFLOAT;
    info.extent = {width, height, 1};
    info.mipLevels = 1;
    info.arrayLayers = 1;
    info.samples = VK_SAMPLE_COUNT_1_BIT;
    info.tiling = VK_IMAGE_TILING_OPTIMAL;
    info.usage = VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_SAMPLED_BIT;
    RG_VK(vkCreateImage(device.device(), &info, nullptr, &image_));
    device.setName(image_, VK_OBJECT_TYPE_IMAGE, "point-light table");
    VkMemoryRequirements req;
    vkGetImageMemoryRequirements(device.device(), image_, &req);
    VkMemoryAllocateInfo alloc{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
    alloc.allocationSize = req.size;
    try {
        alloc.memoryTypeIndex = device.findMemoryType(req.memoryTypeBits, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
        RG_VK(vkAllocateMemory(device.device(), &alloc, nullptr, &memory_));
        device.setName(memory_, VK_OBJECT_TYPE_DEVICE_MEMORY, "point-light table memory");
        RG_VK(vkBindImageMemory(device.device(), image_, memory_, 0));
    } catch (...) {
        if (memory_) vkFreeMemory(device.device(), memory_, nullptr);
        vkDestroyImage(device.device(), image_, nullptr);
        throw;
    }
}

PointTable::~PointTable() {
    vkDestroyImage(device_.device(), image_, nullptr);
    vkFreeMemory(device_.device(), memory_, nullptr);
}

bool PointTable::update(const ls::Shared& shared) {
    const ls::FrameConstants& c = shared->constants;
    const std::array<float, 16> key{c.betaR.x, c.betaR.y, c.betaR.z, c.betaR.w,  // w: g
                                    c.betaM.x, c.betaM.y, c.betaM.z,
                                    c.betaT.x, c.betaT.y, c.betaT.z, c.betaT.w,  // w: r0
                                    c.lutInfo.x, c.lutInfo.y, c.lutInfo.z,
                                    shared->spec.isotropicMie ? 1.0f : 0.0f, 0.0f};
    if (filled_ && key == key_) return false;

    rg::RenderGraph g;
    rg::ImportedImage desc;
    desc.image = image_;
    desc.format = VK_FORMAT_R32G32B32A32_SFLOAT;
    desc.extent = {width_, height_};
    desc.usage = VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_SAMPLED_BIT;
    desc.initialLayout = filled_ ? VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL : VK_IMAGE_LAYOUT_UNDEFINED;
    desc.initialStages = VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT | VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT;
    desc.initialAccess = VK_ACCESS_2_NONE;
    desc.finalLayout = VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;
    desc.finalStages = VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT | VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT;
    desc.finalAccess = VK_ACCESS_2_SHADER_SAMPLED_READ_BIT;
    const rg::ImageRef table = g.importImage("point-light table", desc);
    const rg::BufferRef constants = ls::addUploadConstants(g, shared);
    ls::addPointTable(g, shared, constants, table);
    const rg::VulkanDeviceCaps caps(device_);
    rg::GraphExecutor exec(device_, g, rg::compile(g, caps));
    exec.run();
    key_ = key;
    filled_ = true;
    return true;
}

}  // namespace lightscatter::detail
