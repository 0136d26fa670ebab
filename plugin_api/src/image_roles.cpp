#include "image_roles.h"

#include <algorithm>
#include <tuple>

#include "color_target.h"
#include "field_checks.h"
#include "rendergraph/layout_rules.h"

namespace lightscatter::detail {
namespace {

std::string layoutText(VkImageLayout layout) {
    const char* name = rg::layoutName(layout);
    return name ? std::string(name) : "#" + std::to_string(static_cast<int64_t>(layout));
}

}  // namespace

std::vector<ImageRole> imageRoles(const FrameDescription& f, const ValidatedFrame& v) {
    std::vector<ImageRole> roles;
    using Use = ImageRole::Use;
    roles.push_back({"depth", &f.depth, Use::Sampled});
    if (f.color.format != VK_FORMAT_UNDEFINED)
        roles.push_back(
            {"color", &f.color,
             storageColor(f.color.format, f.color.usage) ? Use::Storage : Use::Attachment});
    std::vector<const EdgeLight*> lights;
    for (const EdgeLight& l : v.given) lights.push_back(&l);
    std::sort(lights.begin(), lights.end(),
              [](const EdgeLight* a, const EdgeLight* b) { return a->given < b->given; });
    for (const EdgeLight* l : lights) {
        if (l->input.shadowMap)
            roles.push_back({l->paths.shadowMap, &*l->input.shadowMap, Use::Sampled});
        if (l->input.lightColor)
            roles.push_back({l->paths.lightColor, &*l->input.lightColor, Use::Filtered});
    }
    if (f.inscatterOut) roles.push_back({"inscatterOut", &*f.inscatterOut, Use::Storage});
    if (f.transmittanceOut)
        roles.push_back({"transmittanceOut", &*f.transmittanceOut, Use::Storage});
    if (f.volumeOut) roles.push_back({"volumeOut", &*f.volumeOut, Use::Storage});
    if (f.noise) roles.push_back({"noise", &*f.noise, Use::Filtered});
    return roles;
}

void checkSharedImages(const std::vector<ImageRole>& roles) {
    for (size_t i = 0; i < roles.size(); ++i)
        for (size_t j = i + 1; j < roles.size(); ++j) {
            const ImageRole& a = roles[i];
            const ImageRole& b = roles[j];
            if (a.image->image == VK_NULL_HANDLE || a.image->image != b.image->image) continue;
            const std::string both = a.field + ".image and " + b.field + ".image are one VkImage";
            if (a.written() || b.written()) {
                const std::string writer = a.written() && b.written()
                                               ? a.field + " and " + b.field
                                               : (a.written() ? a.field : b.field);
                fail(both + ": the plugin writes " + writer +
                     ", and an image it writes can have no other role (give each its own image)");
            }
            for (const auto& [which, first, second] :
                 {std::tuple{"layout", a.image->layout, b.image->layout},
                  std::tuple{"finalLayout", a.image->finalLayout, b.image->finalLayout}})
                if (first != second)
                    fail(both + " in two layouts (" + a.field + "." + which + " " +
                         layoutText(first) + ", " + b.field + "." + which + " " +
                         layoutText(second) +
                         "): an image the plugin reads in two roles is in "
                         "one layout, at the start and at the end");
            // Each role's import moves the image into the layout its passes sample in and back:
            // from any other layout, the second role's barriers would start from one the image
            // has left.
            const VkImageLayout sampled = VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;
            if (a.image->layout != sampled || a.image->finalLayout != sampled)
                fail(both + " in " +
                     layoutText(a.image->layout != sampled ? a.image->layout
                                                           : a.image->finalLayout) +
                     ": an image the plugin reads in two roles must be in "
                     "SHADER_READ_ONLY_OPTIMAL (layout and finalLayout), the layout it samples in, "
                     "which neither role then changes");
            // The planes and beam-tree methods depth-test against the depth, in a depth layout.
            if (a.field == "depth" &&
                (a.image->usage & VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT) != 0)
                fail(both +
                     ": with DEPTH_STENCIL_ATTACHMENT usage the depth may be depth-tested "
                     "in DEPTH_STENCIL_READ_ONLY_OPTIMAL, so it can have no other role");
        }
}

}  // namespace lightscatter::detail
