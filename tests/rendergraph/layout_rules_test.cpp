// The layout table the runtime's import checks and the plugin's image checks share: each kind of
// fault, and the usages a refusal names, in the order it names them.
#include <gtest/gtest.h>

#include <string>

#include "rendergraph/layout_rules.h"

using namespace rg;

namespace {

constexpr VkImageUsageFlags kStorage = VK_IMAGE_USAGE_STORAGE_BIT;

LayoutFault fault(VkImageLayout layout, VkFormat format, VkImageUsageFlags usage,
                  LayoutEnd end = LayoutEnd::Initial, bool read = false) {
    return layoutVerdict(layout, format, usage, end, read).fault;
}

}  // namespace

TEST(LayoutRules, Names) {
    EXPECT_STREQ(layoutName(VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL), "SHADER_READ_ONLY_OPTIMAL");
    EXPECT_STREQ(layoutName(VK_IMAGE_LAYOUT_PRESENT_SRC_KHR), "PRESENT_SRC_KHR");
    EXPECT_EQ(layoutName(VK_IMAGE_LAYOUT_SHARED_PRESENT_KHR), nullptr);
    EXPECT_STREQ(usageName(VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT),
                 "DEPTH_STENCIL_ATTACHMENT");
    EXPECT_EQ(fault(VK_IMAGE_LAYOUT_SHARED_PRESENT_KHR, VK_FORMAT_R8G8B8A8_UNORM, kStorage),
              LayoutFault::Unknown);
}

// UNDEFINED leaves the image's whereabouts unsaid at the end, and its contents undefined at the
// start; PREINITIALIZED is a host-written linear color image's first layout, never a last one.
TEST(LayoutRules, StartOnlyLayouts) {
    const VkFormat rgba = VK_FORMAT_R8G8B8A8_UNORM;
    EXPECT_EQ(fault(VK_IMAGE_LAYOUT_UNDEFINED, rgba, kStorage, LayoutEnd::Final),
              LayoutFault::NoFinalLayout);
    EXPECT_EQ(fault(VK_IMAGE_LAYOUT_PREINITIALIZED, rgba, kStorage, LayoutEnd::Final),
              LayoutFault::NotFinal);
    EXPECT_EQ(fault(VK_IMAGE_LAYOUT_UNDEFINED, rgba, kStorage, LayoutEnd::Initial, true),
              LayoutFault::Discards);
    EXPECT_EQ(fault(VK_IMAGE_LAYOUT_UNDEFINED, rgba, kStorage, LayoutEnd::Initial, false),
              LayoutFault::None);
    EXPECT_EQ(fault(VK_IMAGE_LAYOUT_PREINITIALIZED, rgba, kStorage), LayoutFault::None);
    EXPECT_EQ(fault(VK_IMAGE_LAYOUT_PREINITIALIZED, VK_FORMAT_D32_SFLOAT, kStorage),
              LayoutFault::HostColorOnly);
}

TEST(LayoutRules, LayoutsOfOneAspect) {
    const VkImageUsageFlags all = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT |
                                  VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT |
                                  VK_IMAGE_USAGE_SAMPLED_BIT;
    EXPECT_EQ(fault(VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, VK_FORMAT_D32_SFLOAT, all),
              LayoutFault::ColorOnly);
    EXPECT_EQ(fault(VK_IMAGE_LAYOUT_PRESENT_SRC_KHR, VK_FORMAT_D16_UNORM, all),
              LayoutFault::SwapchainOnly);
    EXPECT_EQ(fault(VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL, VK_FORMAT_R16G16B16A16_SFLOAT, all),
              LayoutFault::DepthOnly);
    EXPECT_EQ(fault(VK_IMAGE_LAYOUT_DEPTH_STENCIL_READ_ONLY_OPTIMAL, VK_FORMAT_S8_UINT, all),
              LayoutFault::DepthOnly);
    EXPECT_EQ(fault(VK_IMAGE_LAYOUT_STENCIL_ATTACHMENT_OPTIMAL, VK_FORMAT_D24_UNORM_S8_UINT, all),
              LayoutFault::StencilAlone);
    EXPECT_EQ(fault(VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL, VK_FORMAT_D24_UNORM_S8_UINT, all),
              LayoutFault::None);
}

TEST(LayoutRules, MissingUsageNamesEveryUsageThatWouldDo) {
    auto needed = [](VkImageLayout layout, VkFormat format) {
        const LayoutVerdict v = layoutVerdict(layout, format, kStorage, LayoutEnd::Final, false);
        EXPECT_EQ(v.fault, LayoutFault::MissingUsage);
        return v.neededUsage;
    };
    EXPECT_EQ(needed(VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_FORMAT_R32_SFLOAT), "TRANSFER_DST");
    EXPECT_EQ(needed(VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, VK_FORMAT_D32_SFLOAT),
              "SAMPLED or INPUT_ATTACHMENT");
    EXPECT_EQ(needed(VK_IMAGE_LAYOUT_DEPTH_READ_ONLY_OPTIMAL, VK_FORMAT_D32_SFLOAT),
              "DEPTH_STENCIL_ATTACHMENT, SAMPLED or INPUT_ATTACHMENT");
    // ATTACHMENT_OPTIMAL is either kind of attachment: the format says which.
    EXPECT_EQ(needed(VK_IMAGE_LAYOUT_ATTACHMENT_OPTIMAL, VK_FORMAT_R8G8B8A8_UNORM),
              "COLOR_ATTACHMENT");
    EXPECT_EQ(needed(VK_IMAGE_LAYOUT_ATTACHMENT_OPTIMAL, VK_FORMAT_D16_UNORM),
              "DEPTH_STENCIL_ATTACHMENT");
    // One of the usages is enough; GENERAL needs none.
    EXPECT_EQ(fault(VK_IMAGE_LAYOUT_READ_ONLY_OPTIMAL, VK_FORMAT_R8G8B8A8_UNORM,
                    VK_IMAGE_USAGE_INPUT_ATTACHMENT_BIT),
              LayoutFault::None);
    EXPECT_EQ(fault(VK_IMAGE_LAYOUT_GENERAL, VK_FORMAT_D32_SFLOAT, 0), LayoutFault::None);
}
