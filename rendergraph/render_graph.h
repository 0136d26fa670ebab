#pragma once
// The declarative front of the runtime: resources and passes are declared here, then compiled
// (compile.h) and executed (executor.h). Declaring never touches the GPU and never fails; every
// rule is checked by the compiler so that one message can name the pass, the resource and the rule.
#include <cstdint>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "host_data.h"
#include "pass_decl.h"
#include "persistent_store.h"
#include "resources.h"

namespace rg {

struct ResourceDecl {
    std::string name;
    bool buffer = false;
    bool imported = false;
    ImageDesc image;        // transient images
    BufferDesc bufferDesc;  // transient buffers
    ImportedImage importedImage;
    VkImageLayout declaredLayout = VK_IMAGE_LAYOUT_UNDEFINED;  // the import's initial layout
                                                               // when the graph was compiled
    VkExtent2D declaredExtent{0, 0};  // the import's extent when the graph was compiled
    bool extentVaries = false;        // a frame's image may be smaller (RenderGraph::importImage)
    ImportedBuffer importedBuffer;
    // An image the graph keeps across frames (RenderGraph::persistentImage, historyImages): an
    // import whose image the executor takes from its PersistentStore under `storeName` and this
    // frame's key. role: 0 a persistent image; 1 a history's image the frame reads (the frame
    // before's), 2 the one it writes.
    struct Persistent {
        std::string storeName;
        HostDataRef<PersistentKey> key;
        PersistentImageDesc desc;
        uint8_t role = 0;
    };
    std::optional<Persistent> persistent;
    bool output = false;  // marked as a result: its producers are never culled
    uint32_t versionCount = 1;
};

class RenderGraph;

// Returned by RenderGraph::addPass; records the pass's uses. Writes return the new version, which
// later readers must name.
class PassBuilder {
  public:
    PassBuilder(RenderGraph& graph, uint32_t pass) : graph_(&graph), pass_(pass) {}

    void sampled(ImageRef image, VkPipelineStageFlags2 stages = 0, VkImageAspectFlags aspect = 0);
    void storageRead(ImageRef image, VkPipelineStageFlags2 stages = 0);
    [[nodiscard]] ImageRef storageWrite(ImageRef image, VkPipelineStageFlags2 stages = 0);
    [[nodiscard]] ImageRef storageReadWrite(ImageRef image, VkPipelineStageFlags2 stages = 0);
    [[nodiscard]] ImageRef colorAttachment(ImageRef image, LoadOp load,
                                           VkClearColorValue clear = {});
    void depthTest(ImageRef image);
    [[nodiscard]] ImageRef depthWrite(ImageRef image, LoadOp load, float clearDepth = 1.0f);
    void stencilTest(ImageRef image);
    [[nodiscard]] ImageRef stencilWrite(ImageRef image, LoadOp load, uint32_t clearStencil = 0);
    void transferSrc(ImageRef image);
    [[nodiscard]] ImageRef transferDst(ImageRef image);

    void uniformBuffer(BufferRef buffer, VkPipelineStageFlags2 stages = 0);
    void storageBufferRead(BufferRef buffer, VkPipelineStageFlags2 stages = 0);
    [[nodiscard]] BufferRef storageBufferWrite(BufferRef buffer, VkPipelineStageFlags2 stages = 0);
    [[nodiscard]] BufferRef storageBufferReadWrite(BufferRef buffer,
                                                   VkPipelineStageFlags2 stages = 0);
    void transferSrc(BufferRef buffer);
    [[nodiscard]] BufferRef transferDst(BufferRef buffer);

    PassBuilder& execute(std::function<void(PassContext&)> fn);
    PassBuilder& sideEffect();
    // Graphics: count the samples that pass the pass's tests (PassTiming::samples), a cheap way to
    // read back how much work a stencil- or depth-limited pass did.
    PassBuilder& countSamples();
    // A graphics pass with no attachment renders over `extent` (its fragments write storage
    // images); a pass with attachments renders over theirs.
    PassBuilder& renderArea(VkExtent2D extent);
    uint32_t index() const { return pass_; }

  private:
    ResourceUse& add(UseKind kind, bool buffer, uint32_t graph, uint32_t id, uint32_t version);
    uint32_t writeVersion(ResourceUse& use);

    RenderGraph* graph_;
    uint32_t pass_;
};

class RenderGraph {
  public:
    RenderGraph();

    ImageRef createImage(std::string name, const ImageDesc& desc);
    BufferRef createBuffer(std::string name, const BufferDesc& desc);
    // `extentVaries`: a frame's image may be any size up to this one (dynamic resolution); the
    // passes that render over the screen then render over the frame's screen (GraphExecutor::
    // record's `screen`).
    ImageRef importImage(std::string name, const ImportedImage& image, bool extentVaries = false);
    BufferRef importBuffer(std::string name, const ImportedBuffer& buffer);
    PassBuilder addPass(std::string name, PassType type);
    // Host data the passes read when they are recorded; its value is given to each record()
    // (FrameData), and a frame that lacks it fails with the pass and the data named.
    template <typename T>
    HostDataRef<T> hostData(std::string name) {
        hostData_.push_back({std::move(name) + nameSuffix_, detail::hostDataTag<T>()});
        return {id_, static_cast<uint32_t>(hostData_.size() - 1)};
    }
    const std::vector<HostDataDecl>& hostDataDecls() const { return hostData_; }

    // An image the graph keeps across frames and graphs (persistent_store.h), one per name and
    // key: `key` is given to each record(). Its first frame finds it undefined (the pass that
    // fills it asks PassContext::persistent() whether it must), later ones find what the frames
    // before them left, in desc.layout.
    ImageRef persistentImage(std::string name, const PersistentImageDesc& desc,
                             HostDataRef<PersistentKey> key);
    // A history: two images of `desc` kept across frames, the one the frame before wrote
    // (`previous`, read) and the one this frame writes (`current`), swapped by each frame that
    // records it. PassContext::history() says whether `previous` holds the frame just before's.
    struct HistoryImages {
        ImageRef previous, current;
    };
    HistoryImages historyImages(std::string name, const PersistentImageDesc& desc,
                                HostDataRef<PersistentKey> key);

    // Keeps the passes that produce this version (and what they need) from being culled.
    void markOutput(ImageRef image);
    void markOutput(BufferRef buffer);

    // Appended to the name of every resource and pass declared from now on (empty: none), so that
    // one builder can add the same nodes more than once (a chain per light: " (light 1)").
    void setNameSuffix(std::string suffix) { nameSuffix_ = std::move(suffix); }
    const std::string& nameSuffix() const { return nameSuffix_; }

    void setScreenExtent(VkExtent2D extent) { screen_ = extent; }
    VkExtent2D screenExtent() const { return screen_; }

    // Per-frame change of an import's handle or states. The format, extent, usage and layouts must
    // stay what the graph was compiled with, but that an import declared with extentVaries may be
    // smaller, and that an image's initial layout may be UNDEFINED
    // for a frame (its contents discarded: an image not yet filled), where the graph transitions
    // it at its first use (the executor refuses the frame otherwise). Anything else needs a new
    // graph.
    void updateImport(ImageRef image, const ImportedImage& desc);
    void updateImport(BufferRef buffer, const ImportedBuffer& desc);

    uint32_t id() const { return id_; }
    const std::vector<ResourceDecl>& resources() const { return resources_; }
    std::vector<ResourceDecl>& resources() { return resources_; }
    const std::vector<PassDecl>& passes() const { return passes_; }
    std::vector<PassDecl>& passes() { return passes_; }
    const ResourceDecl& resource(uint32_t id) const { return resources_.at(id); }

    // The extent an image resolves to at the current screen size, or at `screen`.
    VkExtent2D imageExtent(uint32_t resource) const;
    VkExtent2D imageExtent(uint32_t resource, VkExtent2D screen) const;

  private:
    friend class PassBuilder;
    uint32_t id_;
    VkExtent2D screen_{0, 0};
    std::string nameSuffix_;
    std::vector<ResourceDecl> resources_;
    std::vector<PassDecl> passes_;
    std::vector<HostDataDecl> hostData_;
};

}  // namespace rg
