#include "render_graph.h"

#include <algorithm>
#include <atomic>
#include <cmath>

#include "graph_error.h"

namespace rg {
namespace {

std::atomic<uint32_t> gNextGraphId{1};

VkExtent2D scaled(VkExtent2D screen, float sx, float sy) {
    auto dim = [](uint32_t s, float k) {
        const double v = std::ceil(static_cast<double>(s) * static_cast<double>(k));
        return v < 1.0 ? 1u : static_cast<uint32_t>(v);
    };
    return {dim(screen.width, sx), dim(screen.height, sy)};
}

}  // namespace

RenderGraph::RenderGraph() : id_(gNextGraphId.fetch_add(1)) {}

ImageRef RenderGraph::createImage(std::string name, const ImageDesc& desc) {
    ResourceDecl r;
    r.name = std::move(name) + nameSuffix_;
    r.image = desc;
    resources_.push_back(std::move(r));
    return ImageRef{id_, static_cast<uint32_t>(resources_.size() - 1), 0};
}

BufferRef RenderGraph::createBuffer(std::string name, const BufferDesc& desc) {
    ResourceDecl r;
    r.name = std::move(name) + nameSuffix_;
    r.buffer = true;
    r.bufferDesc = desc;
    resources_.push_back(std::move(r));
    return BufferRef{id_, static_cast<uint32_t>(resources_.size() - 1), 0};
}

ImageRef RenderGraph::importImage(std::string name, const ImportedImage& image, bool extentVaries) {
    ResourceDecl r;
    r.name = std::move(name) + nameSuffix_;
    r.imported = true;
    r.importedImage = image;
    r.declaredLayout = image.initialLayout;
    r.declaredExtent = image.extent;
    r.extentVaries = extentVaries;
    r.image = ImageDesc::absolute(image.format, image.extent.width, image.extent.height);
    r.image.mipLevels = image.mipLevels;
    r.image.arrayLayers = image.arrayLayers;
    r.image.depth = image.depth;
    resources_.push_back(std::move(r));
    return ImageRef{id_, static_cast<uint32_t>(resources_.size() - 1), 0};
}

namespace {

ImportedImage persistentImport(const PersistentImageDesc& d) {
    ImportedImage i;
    i.format = d.format;
    i.extent = d.extent;
    i.depth = d.depth;
    i.usage = d.usage;
    i.initialLayout = i.finalLayout = d.layout;
    i.initialStages = i.finalStages = d.stages;
    i.initialAccess = d.waitAccess;
    i.finalAccess = d.handAccess;
    return i;
}

}  // namespace

ImageRef RenderGraph::persistentImage(std::string name, const PersistentImageDesc& desc,
                                      HostDataRef<PersistentKey> key) {
    const ImageRef ref = importImage(name, persistentImport(desc));
    resources_[ref.id].persistent = ResourceDecl::Persistent{std::move(name), key, desc, 0};
    return ref;
}

RenderGraph::HistoryImages RenderGraph::historyImages(std::string name,
                                                      const PersistentImageDesc& desc,
                                                      HostDataRef<PersistentKey> key) {
    HistoryImages h;
    h.previous = importImage(name, persistentImport(desc));
    resources_[h.previous.id].persistent = ResourceDecl::Persistent{name, key, desc, 1};
    h.current = importImage(name + " (next)", persistentImport(desc));
    resources_[h.current.id].persistent = ResourceDecl::Persistent{std::move(name), key, desc, 2};
    return h;
}

BufferRef RenderGraph::importBuffer(std::string name, const ImportedBuffer& buffer) {
    ResourceDecl r;
    r.name = std::move(name) + nameSuffix_;
    r.buffer = true;
    r.imported = true;
    r.importedBuffer = buffer;
    r.bufferDesc.size = buffer.size;
    resources_.push_back(std::move(r));
    return BufferRef{id_, static_cast<uint32_t>(resources_.size() - 1), 0};
}

PassBuilder RenderGraph::addPass(std::string name, PassType type) {
    PassDecl p;
    p.name = std::move(name) + nameSuffix_;
    p.type = type;
    passes_.push_back(std::move(p));
    return PassBuilder(*this, static_cast<uint32_t>(passes_.size() - 1));
}

void RenderGraph::markOutput(ImageRef image) {
    if (image.graph == id_ && image.id < resources_.size()) resources_[image.id].output = true;
}

void RenderGraph::markOutput(BufferRef buffer) {
    if (buffer.graph == id_ && buffer.id < resources_.size()) resources_[buffer.id].output = true;
}

void RenderGraph::updateImport(ImageRef image, const ImportedImage& desc) {
    if (image.graph != id_ || image.id >= resources_.size() || !resources_[image.id].imported ||
        resources_[image.id].buffer)
        throw GraphError(Rule::UnknownResource, "updateImport: handle is not an imported image");
    auto& r = resources_[image.id];
    const auto& old = r.importedImage;
    const bool extentFits = r.extentVaries ? desc.extent.width <= r.declaredExtent.width &&
                                                 desc.extent.height <= r.declaredExtent.height
                                           : desc.extent.width == r.declaredExtent.width &&
                                                 desc.extent.height == r.declaredExtent.height;
    if (old.format != desc.format || !extentFits || old.usage != desc.usage ||
        old.mipLevels != desc.mipLevels || old.arrayLayers != desc.arrayLayers ||
        old.depth != desc.depth ||
        (desc.initialLayout != r.declaredLayout &&
         desc.initialLayout != VK_IMAGE_LAYOUT_UNDEFINED) ||
        old.finalLayout != desc.finalLayout)
        throw GraphError(
            Rule::ImportChanged,
            "imported image '" + r.name +
                "': format, extent, levels, usage or layouts changed; build a new graph");
    r.importedImage = desc;
}

void RenderGraph::updateImport(BufferRef buffer, const ImportedBuffer& desc) {
    if (buffer.graph != id_ || buffer.id >= resources_.size() || !resources_[buffer.id].imported ||
        !resources_[buffer.id].buffer)
        throw GraphError(Rule::UnknownResource, "updateImport: handle is not an imported buffer");
    auto& r = resources_[buffer.id];
    if (r.importedBuffer.size != desc.size || r.importedBuffer.usage != desc.usage)
        throw GraphError(Rule::ImportChanged, "imported buffer '" + r.name +
                                                  "': size or usage changed; build a new graph");
    r.importedBuffer = desc;
}

VkExtent2D RenderGraph::imageExtent(uint32_t resource) const {
    return imageExtent(resource, screen_);
}

VkExtent2D RenderGraph::imageExtent(uint32_t resource, VkExtent2D screen) const {
    const auto& r = resources_.at(resource);
    if (r.image.sizeMode == SizeMode::ScreenRelative)
        return scaled(screen, r.image.scaleX, r.image.scaleY);
    return {r.image.width, r.image.height};
}

// ---------------------------------------------------------------------------------------------
// PassBuilder

ResourceUse& PassBuilder::add(UseKind kind, bool buffer, uint32_t graph, uint32_t id,
                              uint32_t version) {
    ResourceUse u;
    u.kind = kind;
    u.buffer = buffer;
    u.graph = graph;
    u.resource = id;
    u.inVersion = version;
    auto& uses = graph_->passes_[pass_].uses;
    uses.push_back(u);
    return uses.back();
}

// One pass produces at most one new version of a resource, however many aspects it writes.
uint32_t PassBuilder::writeVersion(ResourceUse& use) {
    const auto& uses = graph_->passes_[pass_].uses;
    for (const auto& other : uses) {
        if (&other == &use) continue;
        if (other.resource == use.resource && other.graph == use.graph &&
            other.buffer == use.buffer && other.outVersion != kInvalidIndex &&
            other.inVersion == use.inVersion) {
            use.outVersion = other.outVersion;
            return use.outVersion;
        }
    }
    if (use.graph == graph_->id_ && use.resource < graph_->resources_.size())
        use.outVersion = graph_->resources_[use.resource].versionCount++;
    else
        use.outVersion = use.inVersion + 1;  // unknown handle: reported by the compiler
    return use.outVersion;
}

void PassBuilder::sampled(ImageRef image, VkPipelineStageFlags2 stages, VkImageAspectFlags aspect) {
    auto& u = add(UseKind::Sampled, false, image.graph, image.id, image.version);
    u.shaderStages = stages;
    u.aspect = aspect;
}

void PassBuilder::storageRead(ImageRef image, VkPipelineStageFlags2 stages) {
    add(UseKind::StorageRead, false, image.graph, image.id, image.version).shaderStages = stages;
}

ImageRef PassBuilder::storageWrite(ImageRef image, VkPipelineStageFlags2 stages) {
    auto& u = add(UseKind::StorageWrite, false, image.graph, image.id, image.version);
    u.shaderStages = stages;
    return {image.graph, image.id, writeVersion(u)};
}

ImageRef PassBuilder::storageReadWrite(ImageRef image, VkPipelineStageFlags2 stages) {
    auto& u = add(UseKind::StorageReadWrite, false, image.graph, image.id, image.version);
    u.shaderStages = stages;
    return {image.graph, image.id, writeVersion(u)};
}

ImageRef PassBuilder::colorAttachment(ImageRef image, LoadOp load, VkClearColorValue clear) {
    auto& u = add(UseKind::ColorAttachment, false, image.graph, image.id, image.version);
    u.load = load;
    u.clear.color = clear;
    return {image.graph, image.id, writeVersion(u)};
}

void PassBuilder::depthTest(ImageRef image) {
    add(UseKind::DepthTest, false, image.graph, image.id, image.version);
}

ImageRef PassBuilder::depthWrite(ImageRef image, LoadOp load, float clearDepth) {
    auto& u = add(UseKind::DepthWrite, false, image.graph, image.id, image.version);
    u.load = load;
    u.clear.depthStencil.depth = clearDepth;
    return {image.graph, image.id, writeVersion(u)};
}

void PassBuilder::stencilTest(ImageRef image) {
    add(UseKind::StencilTest, false, image.graph, image.id, image.version);
}

ImageRef PassBuilder::stencilWrite(ImageRef image, LoadOp load, uint32_t clearStencil) {
    auto& u = add(UseKind::StencilWrite, false, image.graph, image.id, image.version);
    u.load = load;
    u.clear.depthStencil.stencil = clearStencil;
    return {image.graph, image.id, writeVersion(u)};
}

void PassBuilder::transferSrc(ImageRef image) {
    add(UseKind::TransferSrc, false, image.graph, image.id, image.version);
}

ImageRef PassBuilder::transferDst(ImageRef image) {
    auto& u = add(UseKind::TransferDst, false, image.graph, image.id, image.version);
    return {image.graph, image.id, writeVersion(u)};
}

void PassBuilder::uniformBuffer(BufferRef buffer, VkPipelineStageFlags2 stages) {
    add(UseKind::UniformBuffer, true, buffer.graph, buffer.id, buffer.version).shaderStages =
        stages;
}

void PassBuilder::storageBufferRead(BufferRef buffer, VkPipelineStageFlags2 stages) {
    add(UseKind::StorageBufferRead, true, buffer.graph, buffer.id, buffer.version).shaderStages =
        stages;
}

BufferRef PassBuilder::storageBufferWrite(BufferRef buffer, VkPipelineStageFlags2 stages) {
    auto& u = add(UseKind::StorageBufferWrite, true, buffer.graph, buffer.id, buffer.version);
    u.shaderStages = stages;
    return {buffer.graph, buffer.id, writeVersion(u)};
}

BufferRef PassBuilder::storageBufferReadWrite(BufferRef buffer, VkPipelineStageFlags2 stages) {
    auto& u = add(UseKind::StorageBufferReadWrite, true, buffer.graph, buffer.id, buffer.version);
    u.shaderStages = stages;
    return {buffer.graph, buffer.id, writeVersion(u)};
}

void PassBuilder::transferSrc(BufferRef buffer) {
    add(UseKind::TransferSrc, true, buffer.graph, buffer.id, buffer.version);
}

BufferRef PassBuilder::transferDst(BufferRef buffer) {
    auto& u = add(UseKind::TransferDst, true, buffer.graph, buffer.id, buffer.version);
    return {buffer.graph, buffer.id, writeVersion(u)};
}

PassBuilder& PassBuilder::execute(std::function<void(PassContext&)> fn) {
    graph_->passes_[pass_].execute = std::move(fn);
    return *this;
}

PassBuilder& PassBuilder::sideEffect() {
    graph_->passes_[pass_].sideEffect = true;
    return *this;
}

PassBuilder& PassBuilder::countSamples() {
    graph_->passes_[pass_].countSamples = true;
    return *this;
}

PassBuilder& PassBuilder::renderArea(VkExtent2D extent) {
    graph_->passes_[pass_].renderArea = extent;
    return *this;
}

}  // namespace rg
