#pragma once
// Each engine image's format against what the device does with it in its role (its
// vkGetPhysicalDeviceFormatProperties): sampled, filtered linearly, written as storage. Vulkan
// leaves the result of a use the format does not support undefined, and the validation layer
// reports it only at the draw.
#include <vector>

#include "image_roles.h"
#include "rendergraph/device_caps.h"

namespace lightscatter::detail {

void checkImageFormats(const std::vector<ImageRole>& roles, const rg::DeviceCaps& caps);

}  // namespace lightscatter::detail
