#pragma once
// The frame graphs a plugin keeps: compiled the first time their configuration is met, kept for
// when it comes back (a light leaving and returning, auto switching, a size coming back), their
// transients in one heap. Nothing waits: what the cache or the heap lets go is retired until the
// frames that used it have completed.
#include <memory>
#include <vector>

#include "frame_graph.h"
#include "graph_config.h"
#include "rendergraph/compile.h"
#include "rendergraph/device_caps_vulkan.h"
#include "rendergraph/executor.h"
#include "rendergraph/persistent_store.h"
#include "rendergraph/retire_list.h"
#include "rendergraph/transient_heap.h"

namespace lightscatter::detail {

// A compiled frame graph and the executor that runs it; kept while frames recorded with it may
// still be reported on or running on the GPU (the reports and the retire list hold it).
struct Running {
    std::shared_ptr<FrameGraph> built;  // the graph its executor references
    std::unique_ptr<rg::GraphExecutor> executor;
    bool rehearsed = false;
};

struct CachedGraph {
    GraphConfig config;
    size_t hash = 0;
    std::shared_ptr<FrameGraph> built;
    rg::CompiledGraph compiled;        // to make the executor again when the heap grows
    std::shared_ptr<Running> running;  // null until used after the heap grew
    uint64_t lastUse = 0;              // the last frame recorded with it
};

class GraphCache {
  public:
    // The cache keeps the last kCachedGraphs graphs it used.
    static constexpr size_t kCachedGraphs = 8;
    GraphCache(const rg::Device& device, const rg::VulkanDeviceCaps& caps, ls::Shared shared,
               rg::RetireList& retired, rg::PersistentStore& store);
    // The device's shared state: its pipelines, and what the engine enabled on it.
    const ls::Shared& shared() const { return shared_; }
    ~GraphCache();
    GraphCache(const GraphCache&) = delete;
    GraphCache& operator=(const GraphCache&) = delete;

    // The graph for `c`, compiled (`compiled` set) the first time it is met, its executor made
    // anew when the heap grew since. `lastFrame`: the last frame recorded, which may still use
    // what is let go.
    CachedGraph& graphFor(const GraphConfig& c, uint64_t lastFrame, bool& compiled);
    // Frames up to `completed` have completed: the executors let go of their views of them.
    void collect(uint64_t completed);
    // The graph recorded last, for tools; null before the first frame.
    const CachedGraph* last() const;

  private:
    void retire(CachedGraph& g, uint64_t lastFrame);

    const rg::Device& device_;
    const rg::VulkanDeviceCaps& caps_;
    ls::Shared shared_;
    rg::RetireList& retired_;
    rg::PersistentStore& store_;
    // Declared before the graphs: they are placed in it, and go first.
    rg::TransientHeap heap_;
    std::vector<std::unique_ptr<CachedGraph>> graphs_;
};

}  // namespace lightscatter::detail
