#pragma once
// Equality of the plain Vulkan structures that configurations hold, so that a configuration can
// compare with `= default` and no field is left out of the comparison.
#include <vulkan/vulkan.h>

inline bool operator==(const VkExtent2D& a, const VkExtent2D& b) {
    return a.width == b.width && a.height == b.height;
}
