#include "color_target.h"

#include <string>

#include "field_checks.h"
#include "image_checks.h"
#include "rendergraph/format_info.h"

namespace lightscatter::detail {
namespace {

bool floatRgba(VkFormat f) {
    return f == VK_FORMAT_R16G16B16A16_SFLOAT || f == VK_FORMAT_R32G32B32A32_SFLOAT;
}

std::string extentText(VkExtent2D e) {
    return std::to_string(e.width) + "x" + std::to_string(e.height);
}

void sameExtent(const ImageInput& img, const std::string& field, VkExtent2D screen) {
    if (img.extent.width != screen.width || img.extent.height != screen.height)
        fail(field + ".extent " + extentText(img.extent) + " differs from depth.extent " +
             extentText(screen));
}

}  // namespace

bool storageColor(VkFormat format, VkImageUsageFlags usage) {
    return floatRgba(format) && (usage & VK_IMAGE_USAGE_STORAGE_BIT) != 0;
}

bool splitComposite(VkFormat color, VkImageUsageFlags usage, VkFormat transmittanceFormat) {
    return !storageColor(color, usage) || transmittanceFormat != VK_FORMAT_UNDEFINED;
}

VkFormat splitFormat(VkFormat color, VkFormat transmittanceFormat) {
    const VkFormat decides = color != VK_FORMAT_UNDEFINED ? color : transmittanceFormat;
    return decides == VK_FORMAT_R32G32B32A32_SFLOAT ? VK_FORMAT_R32G32B32A32_SFLOAT
                                                    : VK_FORMAT_R16G16B16A16_SFLOAT;
}

bool formatBlends(VkFormat format, const rg::DeviceCaps& caps) {
    return (caps.optimalFeatures(format) & VK_FORMAT_FEATURE_2_COLOR_ATTACHMENT_BLEND_BIT) != 0;
}

bool blendComposite(VkFormat color, VkImageUsageFlags usage, VkFormat transmittanceFormat,
                    bool colorBlends, bool dualSource) {
    return !splitComposite(color, usage, transmittanceFormat) && colorBlends && dualSource &&
           (usage & VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT) != 0;
}

void checkColorTargets(const FrameDescription& f, VkExtent2D screen) {
    if (f.color.format == VK_FORMAT_UNDEFINED) {
        if (!f.inscatterOut || !f.transmittanceOut)
            fail(std::string("color.format is UNDEFINED (no color: the engine composites itself) "
                             "and ") +
                 (!f.inscatterOut ? "inscatterOut" : "transmittanceOut") +
                 " is not given: without a color the frame's result is inscatterOut and "
                 "transmittanceOut, both required");
    } else {
        const bool storage = storageColor(f.color.format, f.color.usage);
        if (!storage && (f.color.usage & VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT) == 0)
            fail("color.usage lacks COLOR_ATTACHMENT: the plugin blends into a " +
                 rg::formatName(f.color.format) +
                 " color as an attachment (only an R16G16B16A16_SFLOAT or R32G32B32A32_SFLOAT "
                 "color with STORAGE usage is written in place instead)");
        checkImage(f.color, "color",
                   storage ? VK_IMAGE_USAGE_STORAGE_BIT : VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT);
        sameExtent(f.color, "color", screen);
        oneLayer(&f.color, "color");
    }
    if (f.inscatterOut) {
        oneLayer(&*f.inscatterOut, "inscatterOut");
        checkImage(*f.inscatterOut, "inscatterOut", VK_IMAGE_USAGE_STORAGE_BIT, false);
        if (f.inscatterOut->format != VK_FORMAT_R32G32B32A32_SFLOAT)
            fail("inscatterOut.format " + rg::formatName(f.inscatterOut->format) +
                 ": must be R32G32B32A32_SFLOAT");
        sameExtent(*f.inscatterOut, "inscatterOut", screen);
    }
    if (f.transmittanceOut) {
        oneLayer(&*f.transmittanceOut, "transmittanceOut");
        checkImage(*f.transmittanceOut, "transmittanceOut", VK_IMAGE_USAGE_STORAGE_BIT, false);
        if (!floatRgba(f.transmittanceOut->format))
            fail("transmittanceOut.format " + rg::formatName(f.transmittanceOut->format) +
                 ": must be R16G16B16A16_SFLOAT or R32G32B32A32_SFLOAT");
        sameExtent(*f.transmittanceOut, "transmittanceOut", screen);
    }
}

void checkColorBlend(const FrameDescription& f, const rg::DeviceCaps& caps) {
    if (f.color.format == VK_FORMAT_UNDEFINED || storageColor(f.color.format, f.color.usage))
        return;
    if (!formatBlends(f.color.format, caps))
        fail("color.format " + rg::formatName(f.color.format) +
             ": this device cannot blend into it as a color attachment "
             "(VK_FORMAT_FEATURE_COLOR_ATTACHMENT_BLEND_BIT), which the composite into a color "
             "without STORAGE needs");
}

}  // namespace lightscatter::detail
