#pragma once
// Every engine image of a frame in the role the engine gave it (depth, color, each light's shadow
// map and light color, the outputs, the noise), for the rules that look at the roles together:
// one VkImage in two roles, and each role's format against what the device can do with it.
#include <string>
#include <vector>

#include <lightscatter/lightscatter.h>
#include "frame_setup.h"

namespace lightscatter::detail {

struct ImageRole {
    // How the plugin uses it: Sampled with the nearest texel (depth, shadow maps), Filtered
    // linearly (a light color, the noise), written as Storage (the outputs, a float color) or
    // blended into as an Attachment (any other color).
    enum class Use { Sampled, Filtered, Storage, Attachment };
    std::string field;  // "color", "lights[2].lightColor"
    const ImageInput* image = nullptr;
    Use use = Use::Sampled;
    bool written() const { return use == Use::Storage || use == Use::Attachment; }
};

// The frame's images in the order of FrameDescription's fields, lights in the engine's order; the
// color only where the frame has one (format not UNDEFINED).
std::vector<ImageRole> imageRoles(const FrameDescription& frame, const ValidatedFrame& v);

// One VkImage given in two roles: refused where the plugin writes either (it would read what it
// is writing, or write one image twice), where the two give different layouts, or a layout other
// than SHADER_READ_ONLY_OPTIMAL (each role's barriers would move the image out of the layout the
// other believes it in), or where one is a depth the plugin may depth-test. Names both fields.
void checkSharedImages(const std::vector<ImageRole>& roles);

}  // namespace lightscatter::detail
