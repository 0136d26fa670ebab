#include "point_table.h"

#include "rendergraph/compile.h"
#include "rendergraph/device_caps_vulkan.h"
#include "rendergraph/executor.h"
#include "rendergraph/vk_error.h"
#include "shared_nodes.h"

namespace ls {

PointTable::PointTable(const rg::Device& device, uint32_t width, uint32_t height)
    : device_(device),
      width_(width),
      height_(height),
      image_(device, VK_FORMAT_R32G32B32A32_SFLOAT, {width, height},
             VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_SAMPLED_BIT, "point-light table") {}

bool PointTable::update(const Shared& shared) {
    const FrameConstants& c = shared->constants;
    const std::array<float, 16> key{
        c.betaR.x,   c.betaR.y,   c.betaR.z,
        c.betaR.w,  // w: g
        c.betaM.x,   c.betaM.y,   c.betaM.z,   c.betaT.x,
        c.betaT.y,   c.betaT.z,
        c.betaT.w,  // w: r0
        c.lutInfo.x, c.lutInfo.y, c.lutInfo.z, static_cast<float>(shared->spec.phase),
        0.0f};
    if (filled_ && key == key_) return false;

    rg::RenderGraph g;
    rg::ImportedImage desc;
    desc.image = image_.image();
    desc.format = VK_FORMAT_R32G32B32A32_SFLOAT;
    desc.extent = {width_, height_};
    desc.usage = VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_SAMPLED_BIT;
    desc.initialLayout =
        filled_ ? VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL : VK_IMAGE_LAYOUT_UNDEFINED;
    desc.initialStages =
        VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT | VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT;
    desc.initialAccess = VK_ACCESS_2_NONE;
    desc.finalLayout = VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;
    desc.finalStages =
        VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT | VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT;
    desc.finalAccess = VK_ACCESS_2_SHADER_SAMPLED_READ_BIT;
    const rg::ImageRef table = g.importImage("point-light table", desc);
    const rg::BufferRef constants = addUploadConstants(g, {shared});
    addPointTable(g, {shared, constants, table});
    const rg::VulkanDeviceCaps caps(device_);
    rg::GraphExecutor exec(device_, g, rg::compile(g, caps));
    exec.run();
    key_ = key;
    filled_ = true;
    return true;
}

}  // namespace ls
