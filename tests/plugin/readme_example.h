#pragma once
#include <vulkan/vulkan.h>

#include <array>
#include <cstdint>
#include <memory>

#include <lightscatter/lightscatter.h>

// The engine-side objects docs/integration.md's example works with.
struct Engine {
    lightscatter::VulkanContext context;  // the engine's device, with its enabled feature chain
    std::unique_ptr<lightscatter::Plugin>
        lightShafts;  // made on first use; reset before the device
    VkCommandBuffer commandBuffer = VK_NULL_HANDLE;
    VkExtent2D extent{0, 0};
    VkImage depth = VK_NULL_HANDLE, hdrColor = VK_NULL_HANDLE, shadowMap = VK_NULL_HANDLE;
    std::array<float, 16> view{}, projection{}, lightViewProjection{};
};

// docs/integration.md's example, verbatim (readme_example.cpp): records the light shafts into the
// engine's command buffer and returns the frame's number, for the plugin's report once the engine
// has waited. Compiled by the plugin's tests and by the consumer projects (tests/consumer/).
uint64_t recordLightShafts(Engine& engine);
