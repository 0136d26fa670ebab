#include "gpu_images.h"

#include <cmath>
#include <cstring>
#include <limits>

#include "rendergraph/format_info.h"
#include "rendergraph/host_buffer.h"
#include "rendergraph/image_readback.h"
#include "rendergraph/vk_error.h"

namespace plugin_test {

TestImage::TestImage(const rg::Device& device, VkFormat format, VkExtent2D extent,
                     VkImageUsageFlags usage, VkImageLayout restingLayout, const std::string& name)
    : device_(device),
      format_(format),
      extent_(extent),
      usage_(usage | VK_IMAGE_USAGE_TRANSFER_DST_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT),
      resting_(restingLayout),
      image_(device, format, extent, usage_, name) {
    device.submitAndWait(
        [&](VkCommandBuffer cmd) { transition(cmd, VK_IMAGE_LAYOUT_UNDEFINED, resting_); });
}

void TestImage::transition(VkCommandBuffer cmd, VkImageLayout from, VkImageLayout to) const {
    VkImageMemoryBarrier2 b{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER_2};
    b.srcStageMask = VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT;
    b.srcAccessMask = VK_ACCESS_2_MEMORY_WRITE_BIT;
    b.dstStageMask = VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT;
    b.dstAccessMask = VK_ACCESS_2_MEMORY_READ_BIT | VK_ACCESS_2_MEMORY_WRITE_BIT;
    b.oldLayout = from;
    b.newLayout = to;
    b.srcQueueFamilyIndex = b.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    b.image = image_.image();
    b.subresourceRange = {rg::fullAspect(format_), 0, 1, 0, 1};
    VkDependencyInfo dep{VK_STRUCTURE_TYPE_DEPENDENCY_INFO};
    dep.imageMemoryBarrierCount = 1;
    dep.pImageMemoryBarriers = &b;
    vkCmdPipelineBarrier2(cmd, &dep);
}

void TestImage::upload(const std::vector<float>& texels) {
    std::vector<uint8_t> bytes(texels.size() * sizeof(float));
    std::memcpy(bytes.data(), texels.data(), bytes.size());
    uploadBytes(bytes);
}

void TestImage::uploadBytes(const std::vector<uint8_t>& texels) {
    const VkDeviceSize bytes = texels.size();
    rg::HostBuffer staging(device_, bytes, VK_BUFFER_USAGE_TRANSFER_SRC_BIT, "test upload");
    std::memcpy(staging.data(), texels.data(), bytes);
    device_.submitAndWait([&](VkCommandBuffer cmd) {
        transition(cmd, resting_, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL);
        VkBufferImageCopy region{};
        region.imageSubresource = {rg::hasDepth(format_)
                                       ? VkImageAspectFlags{VK_IMAGE_ASPECT_DEPTH_BIT}
                                       : VkImageAspectFlags{VK_IMAGE_ASPECT_COLOR_BIT},
                                   0, 0, 1};
        region.imageExtent = {extent_.width, extent_.height, 1};
        vkCmdCopyBufferToImage(cmd, staging.buffer(), image_.image(),
                               VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region);
        transition(cmd, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, resting_);
    });
}

namespace {

float halfToFloat(uint16_t h) {
    const uint32_t sign = (h >> 15) & 1u, exponent = (h >> 10) & 0x1fu, mantissa = h & 0x3ffu;
    float v;
    if (exponent == 0)
        v = std::ldexp(static_cast<float>(mantissa), -24);
    else if (exponent == 31)
        v = mantissa ? std::numeric_limits<float>::quiet_NaN()
                     : std::numeric_limits<float>::infinity();
    else
        v = std::ldexp(static_cast<float>(mantissa | 0x400u), static_cast<int>(exponent) - 25);
    return sign ? -v : v;
}

}  // namespace

void TestImage::clear(float value) {
    device_.submitAndWait([&](VkCommandBuffer cmd) {
        transition(cmd, resting_, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL);
        VkClearColorValue c{{value, value, value, value}};
        VkImageSubresourceRange range{VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
        vkCmdClearColorImage(cmd, image_.image(), VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, &c, 1,
                             &range);
        transition(cmd, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, resting_);
    });
}

std::vector<uint8_t> TestImage::downloadBytes() {
    const VkDeviceSize bytes = size_t{extent_.width} * extent_.height * rg::texelBytes(format_);
    rg::HostBuffer staging(device_, bytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT, "test download");
    device_.submitAndWait([&](VkCommandBuffer cmd) {
        transition(cmd, resting_, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL);
        rg::recordReadback(device_, cmd, image_.image(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                           extent_, staging.buffer(),
                           rg::hasDepth(format_) ? VkImageAspectFlags{VK_IMAGE_ASPECT_DEPTH_BIT}
                                                 : VkImageAspectFlags{VK_IMAGE_ASPECT_COLOR_BIT});
        transition(cmd, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, resting_);
    });
    std::vector<uint8_t> out(bytes);
    std::memcpy(out.data(), staging.data(), bytes);
    return out;
}

std::vector<float> TestImage::download() {
    const bool half = format_ == VK_FORMAT_R16G16B16A16_SFLOAT;
    const size_t channels = half ? 4 : rg::texelBytes(format_) / 4;
    const std::vector<uint8_t> bytes = downloadBytes();
    std::vector<float> out(size_t{extent_.width} * extent_.height * channels);
    if (half) {
        const auto* h = reinterpret_cast<const uint16_t*>(bytes.data());
        for (size_t i = 0; i < out.size(); ++i) out[i] = halfToFloat(h[i]);
    } else {
        std::memcpy(out.data(), bytes.data(), bytes.size());
    }
    return out;
}

lightscatter::ImageInput TestImage::input() const {
    lightscatter::ImageInput in;
    in.image = image_.image();
    in.format = format_;
    in.extent = extent_;
    in.usage = usage_;
    in.layout = resting_;
    in.finalLayout = resting_;
    return in;
}

}  // namespace plugin_test
