#include "tiling_noise.h"

#include "plane_nodes.h"
#include "rendergraph/compile.h"
#include "rendergraph/device_caps_vulkan.h"
#include "rendergraph/executor.h"

namespace ls {

TilingNoise::TilingNoise(const rg::Device& device)
    : device_(device),
      image_(device, kNoiseFormat, kNoiseExtent,
             VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_SAMPLED_BIT, "tiling noise") {}

bool TilingNoise::ensure(const Shared& shared) {
    if (made_) return false;
    rg::RenderGraph g;
    rg::ImportedImage desc;
    desc.image = image_.image();
    desc.format = kNoiseFormat;
    desc.extent = kNoiseExtent;
    desc.usage = VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_SAMPLED_BIT;
    desc.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
    desc.finalLayout = VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;
    desc.finalStages = VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT;
    desc.finalAccess = VK_ACCESS_2_SHADER_SAMPLED_READ_BIT;
    addTilingNoise(g, {shared, g.importImage("tiling noise", desc)});
    const rg::VulkanDeviceCaps caps(device_);
    rg::GraphExecutor exec(device_, g, rg::compile(g, caps));
    exec.run();
    made_ = true;
    return true;
}

}  // namespace ls
