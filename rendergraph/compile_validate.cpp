// Declaration rules: everything that can be judged from one pass's uses and the device's formats.
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <unordered_set>

#include "compile.h"
#include "format_info.h"
#include "layout_rules.h"

namespace rg::detail {
namespace {

std::string extentText(VkExtent2D e) {
    return std::to_string(e.width) + "x" + std::to_string(e.height);
}

VkFormatFeatureFlags2 requiredFeature(UseKind kind) {
    switch (kind) {
        case UseKind::Sampled:
            return VK_FORMAT_FEATURE_2_SAMPLED_IMAGE_BIT;
        case UseKind::StorageRead:
        case UseKind::StorageWrite:
        case UseKind::StorageReadWrite:
            return VK_FORMAT_FEATURE_2_STORAGE_IMAGE_BIT;
        case UseKind::ColorAttachment:
            return VK_FORMAT_FEATURE_2_COLOR_ATTACHMENT_BIT;
        case UseKind::DepthTest:
        case UseKind::DepthWrite:
        case UseKind::StencilTest:
        case UseKind::StencilWrite:
            return VK_FORMAT_FEATURE_2_DEPTH_STENCIL_ATTACHMENT_BIT;
        case UseKind::TransferSrc:
            return VK_FORMAT_FEATURE_2_TRANSFER_SRC_BIT;
        case UseKind::TransferDst:
            return VK_FORMAT_FEATURE_2_TRANSFER_DST_BIT;
        default:
            return 0;
    }
}

bool allowedIn(PassType type, UseKind kind) {
    if (isAttachment(kind)) return type == PassType::Graphics;
    if (kind == UseKind::TransferSrc || kind == UseKind::TransferDst)
        return type == PassType::Transfer;
    return type != PassType::Transfer;
}

// Depth and stencil are separate aspects: one pass may test or write each, and may sample the
// aspect it does not write. Anything else on one image in one pass is a feedback loop or a layout
// clash.
bool compatible(const ResourceUse& a, const ResourceUse& b, VkFormat format) {
    auto aspectOf = [&](const ResourceUse& u) -> VkImageAspectFlags {
        switch (u.kind) {
            case UseKind::DepthTest:
            case UseKind::DepthWrite:
                return VK_IMAGE_ASPECT_DEPTH_BIT;
            case UseKind::StencilTest:
            case UseKind::StencilWrite:
                return VK_IMAGE_ASPECT_STENCIL_BIT;
            case UseKind::Sampled:
                return u.aspect ? u.aspect : fullAspect(format);
            default:
                return 0;
        }
    };
    if (a.kind == b.kind && !isWrite(a.kind) && a.aspect == b.aspect) return true;  // repeated read
    const bool aDS = isAttachment(a.kind) && a.kind != UseKind::ColorAttachment;
    const bool bDS = isAttachment(b.kind) && b.kind != UseKind::ColorAttachment;
    if (aDS && bDS) return aspectOf(a) != aspectOf(b);
    if ((aDS && b.kind == UseKind::Sampled) || (bDS && a.kind == UseKind::Sampled)) {
        const ResourceUse& att = aDS ? a : b;
        const ResourceUse& smp = aDS ? b : a;
        if (!isWrite(att.kind)) return true;  // read-only attachment and sampler share a layout
        return (aspectOf(att) & aspectOf(smp)) == 0;
    }
    return false;
}

void checkDescriptions(const RenderGraph& graph) {
    std::unordered_set<std::string_view>
        names;  // a set, not every earlier name: linear in the graph
    for (uint32_t i = 0; i < graph.resources().size(); ++i) {
        const auto& r = graph.resource(i);
        const std::string name = quote(r.name);
        if (r.name.empty())
            throw GraphError(Rule::BadDescription,
                             "resource #" + std::to_string(i) + " has no name");
        if (!names.insert(r.name).second)
            throw GraphError(Rule::BadDescription,
                             "resource " + name + " is declared twice; names must be unique");
        if (r.buffer) {
            if (r.bufferDesc.size == 0)
                throw GraphError(Rule::BadDescription, "buffer " + name + " has size 0");
            continue;
        }
        if (r.image.format == VK_FORMAT_UNDEFINED)
            throw GraphError(Rule::BadDescription, "image " + name + " has no format");
        if (r.image.sizeMode == SizeMode::ScreenRelative &&
            (graph.screenExtent().width == 0 || graph.screenExtent().height == 0))
            throw GraphError(Rule::BadDescription, "image " + name +
                                                       " is sized relative to the screen, but the "
                                                       "graph's screen extent is not set");
        const VkExtent2D e = graph.imageExtent(i);
        if (e.width == 0 || e.height == 0)
            throw GraphError(Rule::BadDescription,
                             "image " + name + " has an empty extent " + extentText(e));
        if (r.image.mipLevels == 0 || r.image.arrayLayers == 0 || r.image.depth == 0)
            throw GraphError(Rule::BadDescription,
                             "image " + name + " needs at least one mip level, layer and slice");
        if (r.image.depth > 1 && (r.image.arrayLayers > 1 || r.image.mipLevels > 1 ||
                                  r.image.sizeMode != SizeMode::Absolute))
            throw GraphError(
                Rule::BadDescription,
                "image " + name + " is 3D: it takes one layer, one mip level and an absolute size");
        // Of the layout rules, the one the final barrier cannot do without: an import's layouts
        // are otherwise taken as its owner gives them.
        if (r.imported && layoutVerdict(r.importedImage.finalLayout, r.image.format,
                                        r.importedImage.usage, LayoutEnd::Final, false)
                                  .fault == LayoutFault::NoFinalLayout)
            throw GraphError(Rule::ImportWithoutFinalLayout,
                             "imported image " + name +
                                 " does not say the layout it must be left in (finalLayout is "
                                 "UNDEFINED)");
    }
}

void checkUse(const RenderGraph& graph, const DeviceCaps& caps, const PassDecl& pass,
              const ResourceUse& u) {
    const std::string where = "pass " + quote(pass.name);
    if (u.graph != graph.id() || u.resource >= graph.resources().size())
        throw GraphError(Rule::UnknownResource,
                         where + " uses a resource handle (#" +
                             (u.resource == kInvalidIndex ? std::string("invalid")
                                                          : std::to_string(u.resource)) +
                             ") that this graph did not declare");
    const auto& r = graph.resource(u.resource);
    const std::string res = quote(r.name);
    if (u.inVersion >= r.versionCount)
        throw GraphError(Rule::UnknownResource, where + " names version " +
                                                    std::to_string(u.inVersion) + " of " + res +
                                                    ", which no pass produces");
    if (u.buffer != r.buffer)
        throw GraphError(Rule::UnknownResource,
                         where + " uses " + res + " as " + (u.buffer ? "a buffer" : "an image") +
                             " but it is " + (r.buffer ? "a buffer" : "an image"));
    if (!allowedIn(pass.type, u.kind))
        throw GraphError(Rule::WrongPassType,
                         where + " declares a " + useKindName(u.kind) + " use of " + res +
                             ", which its pass type does not allow (attachments only in graphics "
                             "passes, transfers only in transfer passes)");
    if (r.buffer) {
        if (isImageOnly(u.kind))
            throw GraphError(Rule::UnknownResource,
                             where + " uses buffer " + res + " as " + useKindName(u.kind));
        if (r.imported) {
            const VkBufferUsageFlags need = bufferUsageFor(u.kind);
            if ((r.importedBuffer.usage & need) != need)
                throw GraphError(Rule::UsageNotDeclared,
                                 where + " uses imported buffer " + res + " as " +
                                     useKindName(u.kind) +
                                     " but it was not created with that usage");
        }
        return;
    }
    if (isBufferOnly(u.kind))
        throw GraphError(Rule::UnknownResource,
                         where + " uses image " + res + " as " + useKindName(u.kind));

    const VkFormat f = r.image.format;
    const std::string fmt = formatName(f);
    switch (u.kind) {
        case UseKind::StencilTest:
        case UseKind::StencilWrite:
            if (!hasStencil(f))
                throw GraphError(Rule::StencilWithoutStencilFormat,
                                 where + " declares a " + useKindName(u.kind) + " on " + res +
                                     ", whose format " + fmt + " has no stencil aspect");
            break;
        case UseKind::DepthTest:
        case UseKind::DepthWrite:
            if (!hasDepth(f))
                throw GraphError(Rule::DepthWithoutDepthFormat,
                                 where + " declares a " + useKindName(u.kind) + " on " + res +
                                     ", whose format " + fmt + " has no depth aspect");
            break;
        case UseKind::ColorAttachment:
        case UseKind::StorageRead:
        case UseKind::StorageWrite:
        case UseKind::StorageReadWrite:
            if (isDepthStencil(f))
                throw GraphError(Rule::ColorOnDepthFormat,
                                 where + " uses " + res + " (" + fmt + ") as " +
                                     useKindName(u.kind) +
                                     ", which a depth-stencil format cannot be");
            break;
        case UseKind::Sampled:
            if (u.aspect != 0 && (u.aspect & ~fullAspect(f)) != 0)
                throw GraphError(
                    Rule::StencilWithoutStencilFormat,
                    where + " samples an aspect of " + res + " that " + fmt + " does not have");
            if (isDepthStencil(f) && hasDepth(f) && hasStencil(f) && u.aspect != 0 &&
                u.aspect != VK_IMAGE_ASPECT_DEPTH_BIT && u.aspect != VK_IMAGE_ASPECT_STENCIL_BIT)
                throw GraphError(Rule::ConflictingUses,
                                 where + " samples " + res +
                                     " with both aspects at once; sample depth or stencil");
            break;
        default:
            break;
    }
    const VkFormatFeatureFlags2 need = requiredFeature(u.kind);
    if ((caps.optimalFeatures(f) & need) != need)
        throw GraphError(Rule::FormatUnsupported, where + " uses " + res + " as " +
                                                      useKindName(u.kind) + ", but " + caps.name() +
                                                      " does not support " + fmt + " for that");
    if (r.imported) {
        const VkImageUsageFlags needUsage = imageUsageFor(u.kind);
        if ((r.importedImage.usage & needUsage) != needUsage)
            throw GraphError(Rule::UsageNotDeclared,
                             where + " uses imported image " + res + " as " + useKindName(u.kind) +
                                 " but the engine did not create it with that usage");
    }
}

void checkPass(const RenderGraph& graph, const DeviceCaps& caps, const PassDecl& pass) {
    const std::string where = "pass " + quote(pass.name);
    if (pass.name.empty()) throw GraphError(Rule::BadDescription, "a pass has no name");
    bool hasAttachment = false;
    std::map<uint32_t, const ResourceUse*> firstUse;
    std::optional<std::pair<VkExtent2D, uint32_t>> attachmentExtent;
    for (const auto& u : pass.uses) {
        checkUse(graph, caps, pass, u);
        const auto& r = graph.resource(u.resource);
        if (auto it = firstUse.find(u.resource); it != firstUse.end()) {
            const ResourceUse& prev = *it->second;
            if (prev.inVersion != u.inVersion)
                throw GraphError(Rule::ConflictingUses, where + " uses versions " +
                                                            std::to_string(prev.inVersion) +
                                                            " and " + std::to_string(u.inVersion) +
                                                            " of " + quote(r.name) + " at once");
            if (r.buffer ? (isWrite(prev.kind) || isWrite(u.kind))
                         : !compatible(prev, u, r.image.format))
                throw GraphError(Rule::ConflictingUses, where + " uses " + quote(r.name) +
                                                            " both as " + useKindName(prev.kind) +
                                                            " and as " + useKindName(u.kind) +
                                                            "; no single layout serves both");
        } else {
            firstUse[u.resource] = &u;
        }
        if (isAttachment(u.kind)) {
            hasAttachment = true;
            const VkExtent2D e = graph.imageExtent(u.resource);
            if (!attachmentExtent) {
                attachmentExtent = {e, u.resource};
            } else if (attachmentExtent->first.width != e.width ||
                       attachmentExtent->first.height != e.height) {
                throw GraphError(
                    Rule::ExtentMismatch,
                    where + " renders to " + quote(graph.resource(attachmentExtent->second).name) +
                        " (" + extentText(attachmentExtent->first) + ") and " + quote(r.name) +
                        " (" + extentText(e) + "); attachments of one pass must share an extent");
            }
        }
    }
    const bool area = pass.renderArea.width > 0 && pass.renderArea.height > 0;
    if (pass.type == PassType::Graphics && !hasAttachment && !area)
        throw GraphError(Rule::WrongPassType,
                         where +
                             " is a graphics pass without attachments; make it a compute pass, "
                             "give it a render target or declare its render area");
    if (pass.type != PassType::Graphics &&
        (pass.renderArea.width > 0 || pass.renderArea.height > 0))
        throw GraphError(Rule::WrongPassType,
                         where + " declares a render area but is not a graphics pass");
    if (hasAttachment && (pass.renderArea.width > 0 || pass.renderArea.height > 0))
        throw GraphError(Rule::ExtentMismatch,
                         where +
                             " declares a render area and has attachments; it renders over the "
                             "attachments' extent, so declare one or the other");
}

}  // namespace

void validate(const RenderGraph& graph, const DeviceCaps& caps) {
    checkDescriptions(graph);
    for (const auto& pass : graph.passes()) checkPass(graph, caps, pass);
}

}  // namespace rg::detail
