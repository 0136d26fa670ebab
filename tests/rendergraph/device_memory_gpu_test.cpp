// Device memory that cannot be had is reported in the terms of what needed it (issue #22: "
// vkAllocateMemory(...) failed: VK_ERROR_OUT_OF_DEVICE_MEMORY" named neither the image nor its
// size), and images beyond the device's limits never reach vkCreateImage.
#include <gtest/gtest.h>

#include "rendergraph/compile.h"
#include "rendergraph/device_caps_vulkan.h"
#include "rendergraph/device_memory.h"
#include "rendergraph/executor.h"
#include "rendergraph/host_buffer.h"
#include "rendergraph/owned_image.h"
#include "rendergraph/vk_error.h"
#include "support/gpu_test.h"

using testing_support::GpuTest;

class DeviceMemoryGpu : public GpuTest {
  protected:
    VkDeviceSize largestHeap() {
        VkDeviceSize largest = 0;
        for (uint32_t i = 0; i < dev().memoryProperties().memoryHeapCount; ++i)
            largest = std::max(largest, dev().memoryProperties().memoryHeaps[i].size);
        return largest;
    }
};

TEST(DeviceMemory, SizesAreSaidInTheirUnits) {
    EXPECT_EQ(rg::bytesText(12), "12 bytes");
    EXPECT_EQ(rg::bytesText(2048), "2 KiB");
    EXPECT_EQ(rg::bytesText(VkDeviceSize{3} << 29), "1.5 GiB");
    EXPECT_EQ(rg::bytesText(VkDeviceSize{4} << 30), "4 GiB");
}

TEST_F(DeviceMemoryGpu, AnImageWiderThanTheDeviceTakesIsRefusedBeforeVulkanSeesIt) {
    const uint32_t limit = dev().properties().limits.maxImageDimension2D;
    try {
        rg::OwnedImage image(dev(), VK_FORMAT_R8G8B8A8_UNORM, {limit + 1, 1},
                             VK_IMAGE_USAGE_SAMPLED_BIT, "too wide");
        ADD_FAILURE() << "made an image of " << limit + 1 << "x1";
    } catch (const rg::VulkanError& e) {
        EXPECT_EQ(std::string(e.what()), "image 'too wide' is " + std::to_string(limit + 1) +
                                             "x1: the device takes at most " +
                                             std::to_string(limit) +
                                             " per side (maxImageDimension2D)");
    }
}

// maxResourceSize is the format's and usage's (vkGetPhysicalDeviceImageFormatProperties), not a
// device limit: an image past it was created, and the validation layer warned
// (InvalidFormatLimitsViolation), before memory ran out (issue #42).
TEST_F(DeviceMemoryGpu, AnImageLargerThanItsFormatTakesIsRefusedBeforeVulkanSeesIt) {
    const uint32_t side = dev().properties().limits.maxImageDimension2D;
    VkImageFormatProperties p{};
    ASSERT_EQ(dev().vk().GetPhysicalDeviceImageFormatProperties(
                  dev().physical(), VK_FORMAT_R32G32B32A32_SFLOAT, VK_IMAGE_TYPE_2D,
                  VK_IMAGE_TILING_OPTIMAL, VK_IMAGE_USAGE_STORAGE_BIT, 0, &p),
              VK_SUCCESS);
    const VkDeviceSize bytes = VkDeviceSize{side} * side * 16;
    if (bytes <= p.maxResourceSize)
        GTEST_SKIP() << "the device takes " << p.maxResourceSize << " bytes in one image";
    try {
        rg::OwnedImage image(dev(), VK_FORMAT_R32G32B32A32_SFLOAT, {side, side},
                             VK_IMAGE_USAGE_STORAGE_BIT, "too large");
        ADD_FAILURE() << "made an image of " << bytes << " bytes";
    } catch (const rg::VulkanError& e) {
        const std::string s = std::to_string(side);
        EXPECT_EQ(std::string(e.what()),
                  "image 'too large' (" + s + "x" + s + " R32G32B32A32_SFLOAT) needs " +
                      std::to_string(bytes) + " bytes (" + rg::bytesText(bytes) +
                      "): the device takes at most " + std::to_string(p.maxResourceSize) +
                      " bytes for one image of this format and usage (maxResourceSize, "
                      "vkGetPhysicalDeviceImageFormatProperties)");
    }
}

TEST_F(DeviceMemoryGpu, AnImageOfAUsageItsFormatHasNotIsRefusedBeforeVulkanSeesIt) {
    VkImageFormatProperties p{};
    if (dev().vk().GetPhysicalDeviceImageFormatProperties(
            dev().physical(), VK_FORMAT_D32_SFLOAT, VK_IMAGE_TYPE_2D, VK_IMAGE_TILING_OPTIMAL,
            VK_IMAGE_USAGE_STORAGE_BIT, 0, &p) != VK_ERROR_FORMAT_NOT_SUPPORTED)
        GTEST_SKIP() << "the device makes D32_SFLOAT storage images";
    try {
        rg::OwnedImage image(dev(), VK_FORMAT_D32_SFLOAT, {4, 4}, VK_IMAGE_USAGE_STORAGE_BIT,
                             "depth storage");
        ADD_FAILURE() << "made a D32_SFLOAT storage image";
    } catch (const rg::VulkanError& e) {
        EXPECT_EQ(std::string(e.what()),
                  "image 'depth storage' (4x4 D32_SFLOAT): the device makes no image of this "
                  "format, type, tiling, usage and flags "
                  "(vkGetPhysicalDeviceImageFormatProperties)");
    }
}

TEST_F(DeviceMemoryGpu, MoreThanTheHeapHoldsNamesTheObjectItsSizeAndTheHeap) {
    const VkDeviceSize bytes = largestHeap() + (VkDeviceSize{1} << 30);
    try {
        rg::HostBuffer buffer(dev(), bytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT, "far too large");
        ADD_FAILURE() << "allocated " << bytes << " bytes";
    } catch (const rg::OutOfDeviceMemory& e) {
        const std::string m = e.what();
        EXPECT_EQ(m.rfind("out of device memory: host-visible buffer 'far too large' needs " +
                              rg::bytesText(bytes) + "; the device has ",
                          0),
                  0u)
            << m;
        EXPECT_NE(m.find("more than the whole heap"), std::string::npos) << m;
    }
}

// A transient block too large for the device names the graph's largest resources in it. Each
// image of half-floats stays within maxResourceSize (lavapipe's: 4 GiB), which is checked first.
TEST_F(DeviceMemoryGpu, ATransientBlockNamesItsLargestResources) {
    const uint32_t side = dev().properties().limits.maxImageDimension2D;
    rg::RenderGraph g;
    rg::ImageRef a =
        g.createImage("huge a", rg::ImageDesc::absolute(VK_FORMAT_R16G16B16A16_SFLOAT, side, side));
    rg::ImageRef b =
        g.createImage("huge b", rg::ImageDesc::absolute(VK_FORMAT_R16G16B16A16_SFLOAT, side, side));
    auto p = g.addPass("fill both", rg::PassType::Compute);
    a = p.storageWrite(a);
    b = p.storageWrite(b);
    p.execute([](rg::PassContext&) {});
    g.markOutput(a);
    g.markOutput(b);
    const VkDeviceSize needed = VkDeviceSize{2} * side * side * 8;
    if (needed <= largestHeap()) GTEST_SKIP() << "the device's heap holds " << needed << " bytes";
    const rg::VulkanDeviceCaps caps(dev());
    try {
        rg::GraphExecutor executor(dev(), g, rg::compile(g, caps));
        ADD_FAILURE() << "allocated the block";
    } catch (const rg::OutOfDeviceMemory& e) {
        const std::string m = e.what();
        EXPECT_NE(
            m.find("the render graph's transient memory block 0 (2 resources; the largest 'huge"),
            std::string::npos)
            << m;
        EXPECT_NE(
            m.find(std::to_string(side) + "x" + std::to_string(side) + " R16G16B16A16_SFLOAT"),
            std::string::npos)
            << m;
    }
}
