#pragma once
// Resource declarations: what a graph's images and buffers are, and the handles passes use to name
// one version of their contents.
#include <vulkan/vulkan.h>

#include <cstdint>
#include <limits>
#include <string>

namespace rg {

inline constexpr uint32_t kInvalidIndex = std::numeric_limits<uint32_t>::max();

// A handle names one version of a resource. Every write yields the next version, so the order of
// passes follows from which version each one reads; two passes writing the same version are
// unordered and rejected at compile time.
struct ImageRef {
    uint32_t graph = 0;
    uint32_t id = kInvalidIndex;
    uint32_t version = 0;
    bool valid() const { return id != kInvalidIndex; }
};

struct BufferRef {
    uint32_t graph = 0;
    uint32_t id = kInvalidIndex;
    uint32_t version = 0;
    bool valid() const { return id != kInvalidIndex; }
};

enum class SizeMode : uint8_t { Absolute, ScreenRelative };

struct ImageDesc {
    VkFormat format = VK_FORMAT_UNDEFINED;
    SizeMode sizeMode = SizeMode::Absolute;
    uint32_t width = 0;  // Absolute
    uint32_t height = 0;
    float scaleX = 1.0f;  // ScreenRelative: rounded up, never below 1
    float scaleY = 1.0f;
    uint32_t mipLevels = 1;
    uint32_t arrayLayers = 1;
    // Above 1: a 3D image of this many slices (one layer, one level; never an attachment), its
    // view VK_IMAGE_VIEW_TYPE_3D. Absolute size only.
    uint32_t depth = 1;

    static ImageDesc absolute(VkFormat f, uint32_t w, uint32_t h) {
        ImageDesc d;
        d.format = f;
        d.width = w;
        d.height = h;
        return d;
    }
    static ImageDesc volume(VkFormat f, uint32_t w, uint32_t h, uint32_t d) {
        ImageDesc v = absolute(f, w, h);
        v.depth = d;
        return v;
    }
    static ImageDesc screen(VkFormat f, float sx = 1.0f, float sy = 1.0f) {
        ImageDesc d;
        d.format = f;
        d.sizeMode = SizeMode::ScreenRelative;
        d.scaleX = sx;
        d.scaleY = sy;
        return d;
    }
};

struct BufferDesc {
    VkDeviceSize size = 0;
};

// Where an engine-owned resource stands when the frame starts and where it must be left. The
// runtime waits on `initial*` before its first use and makes its last use available to `final*`.
struct ImportedImage {
    VkImage image = VK_NULL_HANDLE;  // may be null when a graph is only compiled, never executed
    VkFormat format = VK_FORMAT_UNDEFINED;
    VkExtent2D extent{};
    uint32_t mipLevels = 1;
    uint32_t arrayLayers = 1;
    uint32_t depth = 1;           // above 1: a 3D image (ImageDesc::depth)
    VkImageUsageFlags usage = 0;  // what the engine created it with; checked against the uses
    VkImageLayout initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
    VkPipelineStageFlags2 initialStages = VK_PIPELINE_STAGE_2_NONE;
    VkAccessFlags2 initialAccess = VK_ACCESS_2_NONE;
    VkImageLayout finalLayout = VK_IMAGE_LAYOUT_UNDEFINED;
    VkPipelineStageFlags2 finalStages = VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT;
    VkAccessFlags2 finalAccess = VK_ACCESS_2_MEMORY_READ_BIT | VK_ACCESS_2_MEMORY_WRITE_BIT;
};

struct ImportedBuffer {
    VkBuffer buffer = VK_NULL_HANDLE;
    VkDeviceSize size = 0;
    VkBufferUsageFlags usage = 0;
    VkPipelineStageFlags2 initialStages = VK_PIPELINE_STAGE_2_NONE;
    VkAccessFlags2 initialAccess = VK_ACCESS_2_NONE;
    VkPipelineStageFlags2 finalStages = VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT;
    VkAccessFlags2 finalAccess = VK_ACCESS_2_MEMORY_READ_BIT | VK_ACCESS_2_MEMORY_WRITE_BIT;
};

}  // namespace rg
