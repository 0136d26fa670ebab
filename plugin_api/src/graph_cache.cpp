#include "graph_cache.h"

#include <algorithm>

namespace lightscatter::detail {
namespace {

// A prefilter for the cache: the configuration's screen and formats and each light's kind. Equal
// configurations have equal hashes; the cache compares configurations themselves after it.
size_t configHash(const GraphConfig& c) {
    size_t h = 0;
    auto mix = [&h](uint64_t v) {
        h ^= std::hash<uint64_t>()(v) + 0x9e3779b97f4a7c15ull + (h << 6) + (h >> 2);
    };
    mix(c.screen.width);
    mix(c.screen.height);
    mix(c.color.format);
    mix(c.depth.format);
    mix(c.lights.size());
    for (const LightGraphConfig& l : c.lights) {
        mix(reinterpret_cast<uintptr_t>(l.method));
        mix(static_cast<uint64_t>(l.chain.light));
        mix(l.chain.shadowed);
        mix(l.chain.shadowMapSize);
        mix(l.touchesView);
    }
    return h;
}

}  // namespace

GraphCache::GraphCache(const rg::Device& device, const rg::VulkanDeviceCaps& caps,
                       ls::Shared shared, rg::RetireList& retired, rg::PersistentStore& store)
    : device_(device),
      caps_(caps),
      shared_(std::move(shared)),
      retired_(retired),
      store_(store),
      heap_(device, "plugin transient heap") {}

GraphCache::~GraphCache() {
    graphs_.clear();
}

void GraphCache::retire(CachedGraph& g, uint64_t lastFrame) {
    if (!g.running) return;
    retired_.retire(lastFrame, [keep = std::move(g.running)] {});
}

CachedGraph& GraphCache::graphFor(const GraphConfig& c, uint64_t lastFrame, bool& compiled) {
    compiled = false;
    const size_t hash = configHash(c);
    auto found = std::find_if(graphs_.begin(), graphs_.end(),
                              [&](const auto& g) { return g->hash == hash && g->config == c; });
    if (found == graphs_.end()) {
        auto g = std::make_unique<CachedGraph>();
        g->config = c;
        g->hash = hash;
        g->built = std::make_shared<FrameGraph>(buildFrameGraph(c, shared_));
        rg::CompileOptions options;
        options.poisonTransients = c.poisonTransients;
        g->compiled = rg::compile(*g->built->graph, caps_, options);
        compiled = true;
        if (graphs_.size() >= kCachedGraphs) {
            // The least recently used goes.
            auto oldest = std::min_element(
                graphs_.begin(), graphs_.end(),
                [](const auto& a, const auto& b) { return a->lastUse < b->lastUse; });
            retire(**oldest, lastFrame);
            graphs_.erase(oldest);
        }
        graphs_.push_back(std::move(g));
        found = graphs_.end() - 1;
    }
    CachedGraph& g = **found;
    if (!heap_.fits(g.compiled.blocks)) {
        // Every executor placed in memory about to be replaced goes first.
        const bool replaces =
            std::any_of(g.compiled.blocks.begin(), g.compiled.blocks.end(), [&](const auto& b) {
                return heap_.size(b.memoryType) != 0 && heap_.size(b.memoryType) < b.size;
            });
        if (replaces)
            for (auto& other : graphs_) retire(*other, lastFrame);
        heap_.reserve(g.compiled.blocks, retired_, lastFrame, "the plugin's transient textures");
    }
    if (!g.running) {
        auto r = std::make_shared<Running>();
        r->built = g.built;
        r->executor = std::make_unique<rg::GraphExecutor>(device_, *g.built->graph, g.compiled,
                                                          &heap_, &store_);
        g.running = std::move(r);
    }
    return g;
}

void GraphCache::collect(uint64_t completed) {
    for (const auto& g : graphs_)
        if (g->running) g->running->executor->releaseCompleted(completed);
}

const CachedGraph* GraphCache::last() const {
    const CachedGraph* last = nullptr;
    for (const auto& g : graphs_)
        if (g->running && (!last || g->lastUse > last->lastUse)) last = g.get();
    return last;
}

}  // namespace lightscatter::detail
