#pragma once
// Realises a compiled graph on a device and runs it: memory blocks with transient resources bound
// at their planned offsets, one command buffer per frame, barriers batched per pass, debug-utils
// names and labels, and per-pass GPU timestamps. The executor is reused frame after frame until the
// graph changes; only imported handles may change between frames (RenderGraph::updateImport), and
// the host data given to each record() (FrameData).
//
// Nothing here waits for the GPU but run(), on its own fence: the owner destroys an executor only
// once every frame recorded with it has completed (rg::RetireList), and frame N is recorded only
// once frame N - kTimingSlots has completed.
#include <vulkan/vulkan.h>

#include <map>
#include <string>
#include <vector>

#include "compiled_graph.h"
#include "device.h"
#include "host_data.h"
#include "pass_context.h"
#include "render_graph.h"
#include "transient_heap.h"

namespace rg {

struct PassTiming {
    std::string name;
    double milliseconds = 0.0;
    // Samples that passed the tests of a graphics pass that counts them (PassBuilder::
    // countSamples; an occlusion query without the precise bit, exact on the usual drivers); -1:
    // not counted.
    int64_t samples = -1;
};

struct FrameTimings {
    uint64_t frame = 0;              // the frame these times belong to
    std::vector<PassTiming> passes;  // execution order
    double totalMilliseconds = 0.0;  // first pass start to last pass end
    bool valid = false;              // false: not finished on the GPU, or not a frame still held
};

// What a graph's passes do to its transients, all passes together: a later user of the same memory
// (another graph on a shared TransientHeap) waits on these.
struct TransientScope {
    VkPipelineStageFlags2 stages = VK_PIPELINE_STAGE_2_NONE;
    VkAccessFlags2 writes = VK_ACCESS_2_NONE;
};

class GraphExecutor {
  public:
    // With a heap, the transients are placed in its memory (TransientHeap::reserve must have made
    // room for compiled.blocks) instead of blocks of the executor's own; the heap must outlive
    // the executor, and an executor placed before the heap's generation changed must not record.
    // With a store, the graph's persistent images and histories are its (the store must outlive
    // the executor); a graph that declares some needs one.
    GraphExecutor(const Device& device, RenderGraph& graph, CompiledGraph compiled,
                  const TransientHeap* heap = nullptr, PersistentStore* store = nullptr);
    ~GraphExecutor();
    GraphExecutor(const GraphExecutor&) = delete;
    GraphExecutor& operator=(const GraphExecutor&) = delete;

    // Records the frame into the executor's own command buffer, submits, waits, and returns the
    // timings of this frame (numbered as record() numbers it).
    FrameTimings run(uint64_t frame = 0, const FrameData& data = {},
                     const TransientScope* before = nullptr, VkExtent2D screen = {0, 0});

    // For engines that own submission: records the frame into `cmd` and returns its number, `frame`
    // when the caller numbers its frames (increasing), else the executor's next. Each of the last
    // kTimingSlots frames has timestamp queries of its own, reset on the host here, so frames may
    // be recorded ahead of their submission; the frame kTimingSlots before this one must have
    // finished. `data` holds the host data the passes read (RenderGraph::hostData). `before`: what
    // used the transients' memory in the frame before when that was another graph (a shared
    // TransientHeap); each first use of a transient then waits on it too.
    //
    // Views of imported images are made for each frame and destroyed kTimingSlots frames later
    // (or by releaseCompleted()), never looked up by handle: an engine that destroys an image and
    // gets the same handle back for a new one gets views of the new one.
    //
    // `screen`: the frame's screen, at most the graph's (zero: the graph's). The passes that render
    // over the screen render over it, and PassContext::extent() of screen-sized images is it: the
    // graph's transients are sized for its largest screen (dynamic resolution).
    static constexpr uint32_t kTimingSlots = 8;
    uint64_t record(VkCommandBuffer cmd, uint64_t frame = 0, const FrameData& data = {},
                    const TransientScope* before = nullptr, VkExtent2D screen = {0, 0});
    // The passes of the last frame recorded that filled a persistent image (PassContext::wrote).
    const std::vector<std::string>& lastFilled() const { return lastFilled_; }
    // Destroys the views of imported images made for frames up to `completed`, which the GPU
    // has finished.
    void releaseCompleted(uint64_t completed);
    // Every stage and write access of the graph's passes on its transients.
    const TransientScope& transientScope() const { return transientScope_; }
    // A recorded frame's timings, read without waiting (valid is false until the GPU has finished
    // it, and for a frame that is not among the last kTimingSlots recorded); readTimings() reads
    // the last frame recorded.
    FrameTimings readTimings(uint64_t frame);
    // Records a frame into the executor's own command buffer and throws it away (no frame number
    // or timing slot is used), so that what passes create on first use (pipelines) exists, or has
    // failed, before an engine's command buffer is touched.
    void rehearse(const FrameData& data = {}, VkExtent2D screen = {0, 0});
    FrameTimings readTimings();

    const CompiledGraph& compiled() const { return compiled_; }
    const RenderGraph& graph() const { return graph_; }
    const Device& device() const { return device_; }

    // Resolved objects (also what PassContext hands out).
    VkImage image(uint32_t resource) const;
    VkImageView view(uint32_t resource, VkImageAspectFlags aspect) const;
    VkBuffer buffer(uint32_t resource) const;

  private:
    friend class PassContext;
    struct ImageObjects {
        VkImage image = VK_NULL_HANDLE;
        VkImageView full = VK_NULL_HANDLE;
        VkImageView depth = VK_NULL_HANDLE;
        VkImageView stencil = VK_NULL_HANDLE;
    };

    // The graph's persistent images for this frame, from the store under this frame's keys (made
    // there where new); and, once the frame is recorded, what it left in them.
    void bindPersistent(const FrameData& data, uint64_t frame);
    void commitPersistent(uint64_t frame);
    struct Bound {
        PersistentStore::Entry* entry = nullptr;
        uint32_t image = 0;  // which of the entry's images
        HistoryState history;
        bool wrote = false;
        uint64_t stamp = 0;
        std::string writer;  // the pass that filled it
    };
    Bound& bound(ImageRef ref, const char* asking);

    void destroy();
    void createMemory();
    void createResource(uint32_t resource);
    std::string blockContents(uint32_t block) const;
    ImageObjects makeViews(uint32_t resource, VkImage image);
    void refreshImports(uint32_t slot);
    void destroyViews(ImageObjects& o);
    void recordBarriers(VkCommandBuffer cmd, const std::vector<BarrierPlan>& barriers);
    std::vector<BarrierPlan> poisonFirstUses(VkCommandBuffer cmd,
                                             const std::vector<BarrierPlan>& barriers);
    void recordPass(VkCommandBuffer cmd, uint32_t position, const TransientScope* before);

    const Device& device_;
    RenderGraph& graph_;
    CompiledGraph compiled_;
    const TransientHeap* heap_ = nullptr;
    PersistentStore* store_ = nullptr;
    std::vector<Bound> bound_;  // by resource: this frame's persistent images
    bool rehearsing_ = false;
    std::vector<std::string> lastFilled_;
    uint64_t heapGeneration_ = 0;
    std::vector<VkDeviceMemory> blocks_;  // the heap's, or the executor's own
    std::vector<ImageObjects> images_;    // by resource; imported ones refreshed per frame
    std::vector<VkBuffer> buffers_;
    // Views of imported images, made for the frame of each timing slot.
    std::vector<std::vector<ImageObjects>> importViews_;
    TransientScope transientScope_;
    const FrameData* frameData_ = nullptr;  // while record() runs
    VkExtent2D frameScreen_{0, 0};          // the screen of the frame being recorded
    VkExtent2D renderExtent(uint32_t position) const;
    std::vector<RenderingFormats> formats_;  // by pass position
    VkQueryPool queries_ = VK_NULL_HANDLE;
    VkQueryPool samples_ = VK_NULL_HANDLE;  // occlusion queries of the passes that count samples
    std::vector<int32_t> countIndex_;       // by pass position: its occlusion query, or -1
    uint32_t countedPerFrame_ = 0;
    VkCommandPool pool_ = VK_NULL_HANDLE;
    VkCommandBuffer cmd_ = VK_NULL_HANDLE;
    VkFence fence_ = VK_NULL_HANDLE;
    uint32_t queriesPerFrame_ = 0;
    uint32_t firstQuery_ = 0;           // the slot being recorded
    uint32_t slot_ = 0;                 // ... and its slot
    uint64_t lastFrame_ = 0;            // 0: nothing recorded yet
    std::vector<uint64_t> slotFrames_;  // the frame whose queries each slot holds
};

}  // namespace rg
