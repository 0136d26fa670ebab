#pragma once
#include <vulkan/vulkan.h>

namespace ls {

// How a shader that composites (shaders/shared/composite_into.glsl) writes its target: the format
// of the image it read-modify-writes (the engine's color, or the split composite's Lin), whether
// the Lin output image is written, and whether the composite is split (composite_target.h).
struct CompositeVariant {
    VkFormat color = VK_FORMAT_R16G16B16A16_SFLOAT;
    bool output = false;
    bool split = false;
};

}  // namespace ls
