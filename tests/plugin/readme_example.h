#pragma once
#include <vulkan/vulkan.h>

#include <array>
#include <memory>

#include "lightscatter.h"

// The engine-side objects the README's integration example works with.
struct EngineFrame {
    lightscatter::VulkanContext context;
    VkCommandBuffer commandBuffer;
    VkExtent2D extent;
    VkImage depth, hdrColor, shadowMap;
    std::array<float, 16> view, projection, lightViewProjection;
    std::unique_ptr<lightscatter::Plugin> lightShafts;  // the engine destroys it before its device
};

// The README's example, verbatim (readme_example.cpp): records the light shafts into the engine's
// command buffer and returns the plugin, for its report once the engine has waited.
lightscatter::Plugin& recordLightShafts(EngineFrame& engine);
