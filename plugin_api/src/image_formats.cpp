#include "image_formats.h"

#include <string>

#include "field_checks.h"
#include "rendergraph/format_info.h"

namespace lightscatter::detail {

void checkImageFormats(const std::vector<ImageRole>& roles, const rg::DeviceCaps& caps) {
    using Use = ImageRole::Use;
    for (const ImageRole& r : roles) {
        // The color the plugin blends into is checkColorBlend's.
        if (r.use == Use::Attachment) continue;
        const VkFormat format = r.image->format;
        const std::string at = r.field + ".format " + rg::formatName(format);
        // A light color or the noise is read for its colors: a view of a depth image would take
        // a color aspect it does not have.
        if (r.use == Use::Filtered && rg::isDepthStencil(format))
            fail(at + " is a depth/stencil format: " + r.field +
                 " is sampled for its colors, so it must be a color format");
        struct Need {
            bool needed;
            VkFormatFeatureFlags2 feature;
            const char* name;
            const char* use;
        };
        const Need needs[] = {
            {r.use == Use::Storage, VK_FORMAT_FEATURE_2_STORAGE_IMAGE_BIT, "STORAGE_IMAGE",
             "writes it as a storage image"},
            {!r.written(), VK_FORMAT_FEATURE_2_SAMPLED_IMAGE_BIT, "SAMPLED_IMAGE", "samples it"},
            {r.use == Use::Filtered, VK_FORMAT_FEATURE_2_SAMPLED_IMAGE_FILTER_LINEAR_BIT,
             "SAMPLED_IMAGE_FILTER_LINEAR", "samples it with a linear filter"},
        };
        const VkFormatFeatureFlags2 has = caps.optimalFeatures(format);
        for (const Need& n : needs)
            if (n.needed && (has & n.feature) == 0)
                fail(at + ": the plugin " + n.use +
                     ", and this device's format properties "
                     "(optimal tiling) lack " +
                     n.name + " for it");
    }
}

}  // namespace lightscatter::detail
