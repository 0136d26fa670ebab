#include "swapchain.h"

#include <algorithm>

#include "rendergraph/vk_error.h"

namespace host {

Swapchain::Swapchain(const rg::Device& device, VkSurfaceKHR surface, VkExtent2D wanted)
    : device_(device), surface_(surface) {
    VkBool32 present = VK_FALSE;
    vkGetPhysicalDeviceSurfaceSupportKHR(device.physical(), device.queueFamily(), surface,
                                         &present);
    if (!present) throw rg::VulkanError("the device's queue cannot present to this window");
    create(wanted, VK_NULL_HANDLE);
}

Swapchain::~Swapchain() {
    if (swapchain_) vkDestroySwapchainKHR(device_.device(), swapchain_, nullptr);
}

void Swapchain::recreate(VkExtent2D wanted) {
    vkDeviceWaitIdle(device_.device());
    const VkSwapchainKHR old = swapchain_;
    create(wanted, old);
    vkDestroySwapchainKHR(device_.device(), old, nullptr);
}

void Swapchain::create(VkExtent2D wanted, VkSwapchainKHR old) {
    const VkPhysicalDevice pd = device_.physical();
    VkSurfaceCapabilitiesKHR caps;
    RG_VK(vkGetPhysicalDeviceSurfaceCapabilitiesKHR(pd, surface_, &caps));
    uint32_t n = 0;
    vkGetPhysicalDeviceSurfaceFormatsKHR(pd, surface_, &n, nullptr);
    std::vector<VkSurfaceFormatKHR> formats(n);
    vkGetPhysicalDeviceSurfaceFormatsKHR(pd, surface_, &n, formats.data());
    if (formats.empty()) throw rg::VulkanError("the window offers no surface format");
    VkSurfaceFormatKHR chosen = formats[0];
    for (const auto& f : formats)
        if ((f.format == VK_FORMAT_B8G8R8A8_SRGB || f.format == VK_FORMAT_R8G8B8A8_SRGB) &&
            f.colorSpace == VK_COLOR_SPACE_SRGB_NONLINEAR_KHR)
            chosen = f;
    format_ = chosen.format;
    extent_ = caps.currentExtent.width != UINT32_MAX
                  ? caps.currentExtent
                  : VkExtent2D{std::clamp(wanted.width, caps.minImageExtent.width,
                                          caps.maxImageExtent.width),
                               std::clamp(wanted.height, caps.minImageExtent.height,
                                          caps.maxImageExtent.height)};
    usage_ = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT |
             (caps.supportedUsageFlags & VK_IMAGE_USAGE_TRANSFER_SRC_BIT);  // screenshots
    VkSwapchainCreateInfoKHR info{VK_STRUCTURE_TYPE_SWAPCHAIN_CREATE_INFO_KHR};
    info.surface = surface_;
    info.minImageCount = caps.maxImageCount ? std::min(caps.minImageCount + 1, caps.maxImageCount)
                                            : caps.minImageCount + 1;
    info.imageFormat = chosen.format;
    info.imageColorSpace = chosen.colorSpace;
    info.imageExtent = extent_;
    info.imageArrayLayers = 1;
    info.imageUsage = usage_;
    info.imageSharingMode = VK_SHARING_MODE_EXCLUSIVE;
    info.preTransform = caps.currentTransform;
    info.compositeAlpha = VK_COMPOSITE_ALPHA_OPAQUE_BIT_KHR;
    info.presentMode = VK_PRESENT_MODE_FIFO_KHR;
    info.clipped = VK_TRUE;
    info.oldSwapchain = old;
    RG_VK(vkCreateSwapchainKHR(device_.device(), &info, nullptr, &swapchain_));
    vkGetSwapchainImagesKHR(device_.device(), swapchain_, &n, nullptr);
    images_.resize(n);
    vkGetSwapchainImagesKHR(device_.device(), swapchain_, &n, images_.data());
    for (uint32_t i = 0; i < n; ++i)
        device_.setName(images_[i], VK_OBJECT_TYPE_IMAGE, "swapchain image " + std::to_string(i));
}

}  // namespace host
