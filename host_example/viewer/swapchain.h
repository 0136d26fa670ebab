#pragma once
// The window's swapchain: FIFO presentation, sRGB color when offered, recreated on resize.
#include <vulkan/vulkan.h>

#include <vector>

#include "rendergraph/device.h"

namespace host {

class Swapchain {
  public:
    Swapchain(const rg::Device& device, VkSurfaceKHR surface, VkExtent2D wanted);
    ~Swapchain();
    Swapchain(const Swapchain&) = delete;
    Swapchain& operator=(const Swapchain&) = delete;

    void recreate(VkExtent2D wanted);
    VkSwapchainKHR handle() const { return swapchain_; }
    VkFormat format() const { return format_; }
    VkExtent2D extent() const { return extent_; }
    VkImage image(uint32_t i) const { return images_[i]; }
    uint32_t imageCount() const { return static_cast<uint32_t>(images_.size()); }
    VkImageUsageFlags usage() const { return usage_; }

  private:
    void create(VkExtent2D wanted, VkSwapchainKHR old);
    const rg::Device& device_;
    VkSurfaceKHR surface_;
    VkSwapchainKHR swapchain_ = VK_NULL_HANDLE;
    VkFormat format_ = VK_FORMAT_UNDEFINED;
    VkExtent2D extent_{0, 0};
    VkImageUsageFlags usage_ = 0;
    std::vector<VkImage> images_;
};

}  // namespace host
