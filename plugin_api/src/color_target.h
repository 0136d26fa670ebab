#pragma once
// How the composite reaches the engine's color (FrameDescription::color): read-modify-written in
// place where it is a storage image the shaders can write, or split into two textures of the
// plugin's that a last pass blends into it (passes/shared/composite_target.h), and the rules the
// color, inscatterOut and transmittanceOut follow.
#include <vulkan/vulkan.h>

#include <lightscatter/lightscatter.h>
#include "rendergraph/device_caps.h"

namespace lightscatter::detail {

// R16G16B16A16_SFLOAT or R32G32B32A32_SFLOAT with STORAGE usage: the passes write it in place.
bool storageColor(VkFormat format, VkImageUsageFlags usage);
// The composite is split: the color is absent or no storage color, or the frame asks for the
// transmittance (transmittanceFormat not UNDEFINED).
bool splitComposite(VkFormat color, VkImageUsageFlags usage, VkFormat transmittanceFormat);
// The split textures' format: float32 for a float32 color (or, without one, a float32
// transmittance output), else float16 (every other color format holds less).
VkFormat splitFormat(VkFormat color, VkFormat transmittanceFormat);
// The device blends into `format` as a color attachment (COLOR_ATTACHMENT_BLEND).
bool formatBlends(VkFormat format, const rg::DeviceCaps& caps);
// A composite that is not split may blend into the color rather than read-modify-write it
// (ls::CompositeTarget::blend): the color also has COLOR_ATTACHMENT usage, its format blends
// (formatBlends) and the device has dual-source blending.
bool blendComposite(VkFormat color, VkImageUsageFlags usage, VkFormat transmittanceFormat,
                    bool colorBlends, bool dualSource);

// The rules of color, inscatterOut and transmittanceOut that need no device: the usage each way
// needs, formats, extents equal to `screen` (depth.extent), and that a frame without a color gives
// both outputs.
void checkColorTargets(const FrameDescription& frame, VkExtent2D screen);
// A color the plugin blends into: the device blends into its format as a color attachment.
void checkColorBlend(const FrameDescription& frame, const rg::DeviceCaps& caps);

}  // namespace lightscatter::detail
