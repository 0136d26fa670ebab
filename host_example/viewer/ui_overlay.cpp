#include "ui_overlay.h"

#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_vulkan.h>
#include <imgui.h>

#include <algorithm>
#include <stdexcept>
#include <string>

#include "rendergraph/vk_error.h"
#include "swapchain.h"

namespace host {
namespace {

void checkResult(VkResult r) {
    if (r < 0) rg::check(r, "the interface's Vulkan back end");
}

}  // namespace

UiOverlay::UiOverlay(const rg::Device& device, GLFWwindow* window, const Swapchain& swapchain)
    : device_(device), format_(swapchain.format()) {
    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    ImGui::GetIO().IniFilename = nullptr;  // no imgui.ini next to the user's files
    ImGui::StyleColorsDark();
    if (!ImGui_ImplGlfw_InitForVulkan(window, true))
        throw std::runtime_error("view: the interface cannot take the window's input");

    // The back end allocates one combined image sampler (the font); a few to spare.
    const VkDescriptorPoolSize size{VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 4};
    VkDescriptorPoolCreateInfo poolInfo{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
    poolInfo.flags = VK_DESCRIPTOR_POOL_CREATE_FREE_DESCRIPTOR_SET_BIT;
    poolInfo.maxSets = 4;
    poolInfo.poolSizeCount = 1;
    poolInfo.pPoolSizes = &size;
    RG_VK(vkCreateDescriptorPool(device.device(), &poolInfo, nullptr, &pool_));
    device.setName(pool_, VK_OBJECT_TYPE_DESCRIPTOR_POOL, "interface descriptors");
    present_ = makePass(VK_IMAGE_LAYOUT_PRESENT_SRC_KHR, "interface over the frame");
    keep_ = makePass(VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, "interface over the screenshot");

    ImGui_ImplVulkan_InitInfo info{};
    info.Instance = device.instance();
    info.PhysicalDevice = device.physical();
    info.Device = device.device();
    info.QueueFamily = device.queueFamily();
    info.Queue = device.queue();
    info.DescriptorPool = pool_;
    info.MinImageCount = std::max(2u, swapchain.imageCount());
    info.ImageCount = std::max(2u, swapchain.imageCount());
    info.MSAASamples = VK_SAMPLE_COUNT_1_BIT;
    info.CheckVkResultFn = checkResult;
    if (!ImGui_ImplVulkan_Init(&info, present_))
        throw std::runtime_error("view: the interface's Vulkan back end did not start");
    uploadFonts();
    swapchainChanged(swapchain);
}

UiOverlay::~UiOverlay() {
    vkDeviceWaitIdle(device_.device());
    destroyFramebuffers();
    ImGui_ImplVulkan_Shutdown();
    ImGui_ImplGlfw_Shutdown();
    ImGui::DestroyContext();
    vkDestroyRenderPass(device_.device(), keep_, nullptr);
    vkDestroyRenderPass(device_.device(), present_, nullptr);
    vkDestroyDescriptorPool(device_.device(), pool_, nullptr);
}

VkRenderPass UiOverlay::makePass(VkImageLayout finalLayout, const char* name) const {
    VkAttachmentDescription color{};
    color.format = format_;
    color.samples = VK_SAMPLE_COUNT_1_BIT;
    color.loadOp = VK_ATTACHMENT_LOAD_OP_LOAD;  // over the tone-mapped frame
    color.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
    color.stencilLoadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE;
    color.stencilStoreOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
    color.initialLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
    color.finalLayout = finalLayout;
    VkAttachmentReference ref{0, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL};
    VkSubpassDescription subpass{};
    subpass.pipelineBindPoint = VK_PIPELINE_BIND_POINT_GRAPHICS;
    subpass.colorAttachmentCount = 1;
    subpass.pColorAttachments = &ref;
    // In: after the window graph's tone map wrote the image. Out: before the present (whose
    // semaphore waits on all commands) or the screenshot graph (which waits on color output).
    VkSubpassDependency deps[2]{};
    deps[0].srcSubpass = VK_SUBPASS_EXTERNAL;
    deps[0].dstSubpass = 0;
    deps[0].srcStageMask = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT;
    deps[0].srcAccessMask = VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT;
    deps[0].dstStageMask = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT;
    deps[0].dstAccessMask =
        VK_ACCESS_COLOR_ATTACHMENT_READ_BIT | VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT;
    deps[1].srcSubpass = 0;
    deps[1].dstSubpass = VK_SUBPASS_EXTERNAL;
    deps[1].srcStageMask = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT;
    deps[1].srcAccessMask = VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT;
    deps[1].dstStageMask = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT;
    deps[1].dstAccessMask = 0;
    VkRenderPassCreateInfo info{VK_STRUCTURE_TYPE_RENDER_PASS_CREATE_INFO};
    info.attachmentCount = 1;
    info.pAttachments = &color;
    info.subpassCount = 1;
    info.pSubpasses = &subpass;
    info.dependencyCount = 2;
    info.pDependencies = deps;
    VkRenderPass pass = VK_NULL_HANDLE;
    RG_VK(vkCreateRenderPass(device_.device(), &info, nullptr, &pass));
    device_.setName(pass, VK_OBJECT_TYPE_RENDER_PASS, name);
    return pass;
}

void UiOverlay::uploadFonts() {
    VkCommandPoolCreateInfo poolInfo{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
    poolInfo.flags = VK_COMMAND_POOL_CREATE_TRANSIENT_BIT;
    poolInfo.queueFamilyIndex = device_.queueFamily();
    VkCommandPool pool = VK_NULL_HANDLE;
    RG_VK(vkCreateCommandPool(device_.device(), &poolInfo, nullptr, &pool));
    VkCommandBufferAllocateInfo alloc{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
    alloc.commandPool = pool;
    alloc.commandBufferCount = 1;
    VkCommandBuffer cmd = VK_NULL_HANDLE;
    RG_VK(vkAllocateCommandBuffers(device_.device(), &alloc, &cmd));
    VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
    begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
    RG_VK(vkBeginCommandBuffer(cmd, &begin));
    ImGui_ImplVulkan_CreateFontsTexture(cmd);
    RG_VK(vkEndCommandBuffer(cmd));
    VkSubmitInfo submit{VK_STRUCTURE_TYPE_SUBMIT_INFO};
    submit.commandBufferCount = 1;
    submit.pCommandBuffers = &cmd;
    RG_VK(vkQueueSubmit(device_.queue(), 1, &submit, VK_NULL_HANDLE));
    RG_VK(vkQueueWaitIdle(device_.queue()));
    ImGui_ImplVulkan_DestroyFontUploadObjects();
    vkDestroyCommandPool(device_.device(), pool, nullptr);
}

void UiOverlay::destroyFramebuffers() {
    for (VkFramebuffer f : framebuffers_) vkDestroyFramebuffer(device_.device(), f, nullptr);
    for (VkImageView v : views_) vkDestroyImageView(device_.device(), v, nullptr);
    framebuffers_.clear();
    views_.clear();
}

void UiOverlay::swapchainChanged(const Swapchain& swapchain) {
    destroyFramebuffers();
    extent_ = swapchain.extent();
    for (uint32_t i = 0; i < swapchain.imageCount(); ++i) {
        VkImageViewCreateInfo view{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
        view.image = swapchain.image(i);
        view.viewType = VK_IMAGE_VIEW_TYPE_2D;
        view.format = format_;
        view.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
        VkImageView v = VK_NULL_HANDLE;
        RG_VK(vkCreateImageView(device_.device(), &view, nullptr, &v));
        views_.push_back(v);
        VkFramebufferCreateInfo fb{VK_STRUCTURE_TYPE_FRAMEBUFFER_CREATE_INFO};
        fb.renderPass = present_;
        fb.attachmentCount = 1;
        fb.pAttachments = &v;
        fb.width = extent_.width;
        fb.height = extent_.height;
        fb.layers = 1;
        VkFramebuffer f = VK_NULL_HANDLE;
        RG_VK(vkCreateFramebuffer(device_.device(), &fb, nullptr, &f));
        framebuffers_.push_back(f);
        device_.setName(v, VK_OBJECT_TYPE_IMAGE_VIEW, "interface target " + std::to_string(i));
        device_.setName(f, VK_OBJECT_TYPE_FRAMEBUFFER, "interface target " + std::to_string(i));
    }
}

void UiOverlay::beginFrame() {
    ImGui_ImplVulkan_NewFrame();
    ImGui_ImplGlfw_NewFrame();
    ImGui::NewFrame();
}

void UiOverlay::record(VkCommandBuffer cmd, uint32_t index, bool keep) {
    ImGui::Render();
    VkRenderPassBeginInfo begin{VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO};
    begin.renderPass = keep ? keep_ : present_;
    begin.framebuffer = framebuffers_.at(index);
    begin.renderArea = {{0, 0}, extent_};
    device_.beginLabel(cmd, "interface");
    vkCmdBeginRenderPass(cmd, &begin, VK_SUBPASS_CONTENTS_INLINE);
    ImGui_ImplVulkan_RenderDrawData(ImGui::GetDrawData(), cmd);
    vkCmdEndRenderPass(cmd);
    device_.endLabel(cmd);
}

bool UiOverlay::wantsMouse() const {
    return ImGui::GetIO().WantCaptureMouse;
}
bool UiOverlay::wantsKeyboard() const {
    return ImGui::GetIO().WantCaptureKeyboard;
}

}  // namespace host
