#pragma once
// Dear ImGui over the window's swapchain image: the context, its GLFW and Vulkan back ends
// (Debian's libimgui-dev 1.86), and the render pass the Vulkan back end needs. The window's own
// graph leaves the swapchain image as a color attachment; this pass draws the interface over it and
// hands it on for presentation, or for a screenshot graph that reads it first.
#include <vulkan/vulkan.h>

#include <vector>

#include "rendergraph/device.h"

struct GLFWwindow;

namespace host {

class Swapchain;

class UiOverlay {
  public:
    UiOverlay(const rg::Device& device, GLFWwindow* window, const Swapchain& swapchain);
    ~UiOverlay();
    UiOverlay(const UiOverlay&) = delete;
    UiOverlay& operator=(const UiOverlay&) = delete;

    // After the swapchain was recreated: framebuffers for its images.
    void swapchainChanged(const Swapchain& swapchain);
    // Starts the interface's frame (ImGui::NewFrame); the panel draws after it.
    void beginFrame();
    // Draws the interface over swapchain image `index` (in COLOR_ATTACHMENT_OPTIMAL after the
    // window's graph). `keep` leaves it there for a later graph (the screenshot); otherwise it ends
    // in PRESENT_SRC_KHR.
    void record(VkCommandBuffer cmd, uint32_t index, bool keep);
    // The interface has the mouse or the keyboard: the viewer's own controls leave them alone.
    bool wantsMouse() const;
    bool wantsKeyboard() const;

  private:
    VkRenderPass makePass(VkImageLayout finalLayout, const char* name) const;
    void destroyFramebuffers();
    void uploadFonts();

    const rg::Device& device_;
    VkFormat format_;
    VkDescriptorPool pool_ = VK_NULL_HANDLE;
    VkRenderPass present_ = VK_NULL_HANDLE, keep_ = VK_NULL_HANDLE;  // compatible: one format
    std::vector<VkImageView> views_;
    std::vector<VkFramebuffer> framebuffers_;
    VkExtent2D extent_{0, 0};
};

}  // namespace host
