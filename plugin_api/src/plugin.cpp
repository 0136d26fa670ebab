#include <algorithm>
#include <array>
#include <cstdlib>
#include <deque>
#include <map>
#include <mutex>
#include <optional>
#include <string>
#include <tuple>

#include <lightscatter/lightscatter.h>
#include "epipolar/step_counts.h"
#include "frame_graph.h"
#include "frame_setup.h"
#include "graph_config.h"
#include "lin_storage.h"
#include "method_choice.h"
#include "planes/tiling_noise.h"
#include "rendergraph/compile.h"
#include "rendergraph/device_caps_vulkan.h"
#include "rendergraph/executor.h"
#include "rendergraph/format_info.h"
#include "rendergraph/host_buffer.h"
#include "rendergraph/owned_image.h"
#include "rendergraph/report.h"
#include "rendergraph/vk_error.h"
#include "shared/point_table.h"
#include "volume_out.h"

namespace lightscatter {

using detail::FrameGraph;
using detail::GraphConfig;

namespace {

bool poisonFromEnvironment() {
    const char* v = std::getenv("LS_POISON_TRANSIENTS");
    return v && *v && std::string(v) != "0";
}

// Refuses a creation before anything is made from it.
const PluginCreateInfo& checked(const PluginCreateInfo& info) {
    const VulkanContext& c = info.context;
    auto null = [](const char* field) {
        throw InvalidInput(std::string("lightscatter: context.") + field + " is VK_NULL_HANDLE");
    };
    if (info.framesInFlight < 1 || info.framesInFlight > kMaxFramesInFlight)
        throw InvalidInput("lightscatter: framesInFlight is " +
                           std::to_string(info.framesInFlight) + "; it must be 1 to " +
                           std::to_string(kMaxFramesInFlight));
    if (!c.instance) null("instance");
    if (!c.physicalDevice) null("physicalDevice");
    if (!c.device) null("device");
    if (!c.queue) null("queue");
    detail::checkEnabledFeatures(c.enabledFeatures);
    return info;
}

// The pipelines and samplers of one device, shared by every plugin on it (views of one engine, or
// plugins on several threads): a wrapper of the device of its own, so that it outlives any one
// plugin. Plugins that load Vulkan differently, or allocate differently, keep theirs apart.
struct DeviceShared {
    explicit DeviceShared(const rg::ExternalDevice& d) : device(d), state(device) {}
    rg::Device device;
    ls::SharedState state;
};

ls::Shared sharedFor(const rg::ExternalDevice& d) {
    using Key = std::tuple<VkDevice, PFN_vkGetInstanceProcAddr, const VkAllocationCallbacks*>;
    static std::mutex mutex;
    static std::map<Key, std::weak_ptr<DeviceShared>> devices;
    std::lock_guard lock(mutex);
    const Key key{d.device, d.getInstanceProcAddr, d.allocator};
    std::shared_ptr<DeviceShared> found = devices[key].lock();
    if (!found) {
        found = std::make_shared<DeviceShared>(d);
        devices[key] = found;
        // Devices of plugins all gone are forgotten (a handle may be reused for a new device).
        std::erase_if(devices, [](const auto& entry) { return entry.second.expired(); });
    }
    return ls::Shared(found, &found->state);
}

rg::ExternalDevice externalDevice(const PluginCreateInfo& info) {
    const VulkanContext& c = checked(info).context;
    return {c.instance,    c.physicalDevice,         c.device,      c.queue,
            c.queueFamily, info.getInstanceProcAddr, info.allocator};
}

// A compiled frame graph, and the executor that runs it; kept while frames recorded with it may
// still be reported on or running on the GPU (RecordedFrame and the retire list hold it).
struct Running {
    std::shared_ptr<FrameGraph> built;  // the graph its executor references
    std::unique_ptr<rg::GraphExecutor> executor;
    bool rehearsed = false;
};

// What a recorded frame's report needs besides its timestamps.
struct RecordedFrame {
    uint64_t frame = 0;
    std::shared_ptr<Running> graph;  // the graph it was recorded with
    std::string method, reason, notice;
    std::vector<FrameReport::Light> lights;
    std::vector<std::string> passNames;
    std::vector<std::string> setupPasses;
    std::vector<PassTime> cpuWork;
    bool countedSteps = false;  // its march added into stepBuffers[frame % kTimedFrames]
    uint32_t stepSlices = 0;    // ... for this many slices
    bool graphCompiled = false;
};

// A compiled graph the plugin keeps for the configuration it was built for, so that a light
// leaving and coming back, auto switching methods back and forth or a setting toggled reuse it.
struct CachedGraph {
    GraphConfig config;
    size_t hash = 0;
    std::shared_ptr<FrameGraph> built;
    rg::CompiledGraph compiled;        // to make the executor again when the heap grows
    std::shared_ptr<Running> running;  // null until used after the heap grew
    uint64_t lastUse = 0;              // the last frame recorded with it
};

// A prefilter for the cache: the configuration's frame-wide sizes and each light's kind. Equal
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
    for (const detail::LightGraphConfig& l : c.lights) {
        mix(reinterpret_cast<uintptr_t>(l.method));
        mix(static_cast<uint64_t>(l.chain.light));
        mix(l.chain.shadowed);
        mix(l.chain.shadowMapSize);
        mix(l.touchesView);
    }
    return h;
}

}  // namespace

struct Plugin::Impl {
    explicit Impl(const PluginCreateInfo& info)
        : device(externalDevice(info)),
          caps(device),
          shared(sharedFor(externalDevice(info))),
          framesInFlight(info.framesInFlight),
          maxRenderSize(info.maxRenderSize),
          heap(device, "plugin transient heap") {
        depthStencil = detail::stencilFormat(caps);
        coordinates = detail::coordinateFormat(caps);
        if (depthStencil == VK_FORMAT_UNDEFINED)
            throw std::runtime_error(
                "lightscatter: the device has no depth-stencil format with stencil");
    }

    // Everything a frame's graph and history still hold goes before the heap and the device.
    ~Impl() {
        frames.clear();
        graphs.clear();
        retired.collectAll();
    }

    // Everything that can refuse a frame, before anything is built: the checked frame and each
    // light's method.
    struct Chosen {
        detail::ValidatedFrame frame;
        std::vector<detail::MethodChoice> choices;  // per light
    };
    Chosen choose(const FrameDescription& frame) const {
        Chosen c{detail::validateFrame(frame)};
        c.choices = detail::chooseLightMethods(frame.method, c.frame, frame);
        if (frame.volumeOut) {
            const VkExtent2D screen =
                maxRenderSize.width != 0 ? maxRenderSize : c.frame.lights[0].screen;
            detail::checkVolumeOut(*frame.volumeOut, c.frame, c.choices, screen);
            // The engine's volume is written even where no light reaches the view: the first
            // light's chain then fills the grid with the medium's transmittance alone.
            c.frame.touchesView[detail::gridLight(c.frame)] = true;
        }
        return c;
    }

    // What prepare() refuses, found the same way, with nothing built or changed.
    void check(const FrameDescription& frame) const { choose(frame); }

    // One light's constants.
    ls::FrameConstants frameConstants(const ls::LightSetup& setup) const {
        const ls::TableLayout table =
            ls::tableLayoutFor(setup.medium, setup.light.radius, ls::kTableWidth, ls::kTableHeight);
        const ls::FrameParams params{.screen = setup.screen,
                                     .maxScreen = maxRenderSize,
                                     .simplifiedA0 = setup.settings.simplifiedA0,
                                     .simplifiedA1 = setup.settings.simplifiedA1,
                                     .linStorage = detail::linStorageScale(setup),
                                     .preExposure = setup.preExposure};
        return ls::makeFrameConstants(setup.camera, setup.light, setup.medium, params, table);
    }

    // The frame N - framesInFlight and everything before it have completed (the engine's promise
    // when it records frame N): what they alone used is destroyed.
    void collect(uint64_t completed) {
        retired.collect(completed);
        for (const auto& g : graphs)
            if (g->running) g->running->executor->releaseCompleted(completed);
    }

    // Retires a cached graph's executor: frames recorded with it may still run.
    void retire(CachedGraph& g) {
        if (!g.running) return;
        retired.retire(lastFrame, [keep = std::move(g.running)] {});
    }

    // The cached graph for `c`, compiled the first time it is met; its executor made anew when the
    // heap grew since. Nothing waits: what the cache or the heap lets go is retired.
    CachedGraph& graphFor(const GraphConfig& c) {
        const size_t hash = configHash(c);
        auto found = std::find_if(graphs.begin(), graphs.end(),
                                  [&](const auto& g) { return g->hash == hash && g->config == c; });
        if (found == graphs.end()) {
            auto g = std::make_unique<CachedGraph>();
            g->config = c;
            g->hash = hash;
            g->built = std::make_shared<FrameGraph>(detail::buildFrameGraph(c, shared));
            rg::CompileOptions options;
            options.poisonTransients = c.poisonTransients;
            g->compiled = rg::compile(*g->built->graph, caps, options);
            ++graphsCompiled;
            if (graphs.size() >= kCachedGraphs) {
                // The least recently used goes.
                auto oldest = std::min_element(
                    graphs.begin(), graphs.end(),
                    [](const auto& a, const auto& b) { return a->lastUse < b->lastUse; });
                retire(**oldest);
                graphs.erase(oldest);
            }
            graphs.push_back(std::move(g));
            found = graphs.end() - 1;
        }
        CachedGraph& g = **found;
        if (!heap.fits(g.compiled.blocks)) {
            // Every executor placed in memory about to be replaced goes first.
            const bool replaces =
                std::any_of(g.compiled.blocks.begin(), g.compiled.blocks.end(), [&](const auto& b) {
                    return heap.size(b.memoryType) != 0 && heap.size(b.memoryType) < b.size;
                });
            if (replaces)
                for (auto& other : graphs) retire(*other);
            heap.reserve(g.compiled.blocks, retired, lastFrame, "the plugin's transient textures");
        }
        if (!g.running) {
            auto r = std::make_shared<Running>();
            r->built = g.built;
            r->executor =
                std::make_unique<rg::GraphExecutor>(device, *g.built->graph, g.compiled, &heap);
            g.running = std::move(r);
        }
        return g;
    }

    // The step counter of the frame about to be recorded: one buffer per frame that may be in
    // flight, as with the timestamp queries, so that a frame's counts wait for its report. A
    // buffer too small for this frame's graph is replaced (the frame that used it last is done).
    void importStepCounter(const FrameGraph& fg, uint32_t slices) {
        if (!fg.stepCounts.valid()) return;
        const uint64_t frame = lastFrame + 1;
        auto& buffer = stepBuffers[frame % kTimedFrames];
        const rg::ImportedBuffer d = detail::stepCountImport(VK_NULL_HANDLE, slices);
        if (buffer && buffer->size() < d.size)
            retired.retire(lastFrame,
                           [old = std::shared_ptr<rg::HostBuffer>(std::move(buffer))] {});
        if (!buffer)
            buffer =
                std::make_unique<rg::HostBuffer>(device, d.size, d.usage, "ray-march step counts");
        fg.graph->updateImport(fg.stepCounts, detail::stepCountImport(buffer->buffer(), slices));
    }

    std::optional<StepCounts> readStepCounts(uint64_t frame, uint32_t slices) const {
        const auto& buffer = stepBuffers[frame % kTimedFrames];
        if (!buffer) return std::nullopt;
        const auto sum = ls::sumStepCounts(static_cast<const uint32_t*>(buffer->data()), slices);
        auto at = [&](ls::StepCount k) { return sum[static_cast<uint32_t>(k)]; };
        StepCounts s;
        s.samples = at(ls::StepCount::Samples);
        s.rays = at(ls::StepCount::Rays);
        s.lineSteps = at(ls::StepCount::LineSteps);
        s.treeNodes = at(ls::StepCount::TreeNodes);
        s.degenerateRays = at(ls::StepCount::DegenerateRays);
        s.degenerateSteps = at(ls::StepCount::DegenerateSteps);
        return s;
    }

    // One path for every frame: each light's values and its method's CPU work, the graph for the
    // frame's configuration (cached), and this frame's handles and values. Nothing is submitted
    // and nothing waits; a frame's values are its own (Prepared), so frames may be recorded ahead.
    struct Prepared {
        CachedGraph* graph = nullptr;
        std::vector<ls::LightFrame> values;  // per light, in the frame's order
        ls::NoiseFrame noise;
        rg::FrameData data;
        std::vector<std::string> setupPasses;
        std::vector<PassTime> cpuWork;
        std::vector<detail::MethodChoice> choices;  // per light
        std::vector<Settings> settings;             // per light: what its chain runs with
        bool keepsHistory = false;                  // the frame reads and writes the history
        ls::HistoryFrame historyValues;
        bool graphCompiled = false;
        VkExtent2D screen{0, 0};  // the frame's (within the graph's, with maxRenderSize)
    };
    Prepared prepare(const FrameDescription& frame) {
        Chosen chosen = choose(frame);
        const detail::ValidatedFrame& v = chosen.frame;
        const VkExtent2D screen = v.lights[0].screen;
        if (maxRenderSize.width != 0 &&
            (screen.width > maxRenderSize.width || screen.height > maxRenderSize.height))
            throw InvalidInput("lightscatter: depth.extent " + std::to_string(screen.width) + "x" +
                               std::to_string(screen.height) + " is larger than maxRenderSize " +
                               std::to_string(maxRenderSize.width) + "x" +
                               std::to_string(maxRenderSize.height) + " (PluginCreateInfo)");
        const size_t n = v.lights.size();
        Prepared p;
        p.choices = chosen.choices;
        for (const ls::LightSetup& s : v.lights) p.settings.push_back(s.settings);
        std::vector<const ls::MethodUnit*> methods(n);
        for (size_t i = 0; i < n; ++i) methods[i] = &chosen.choices[i].unit();
        p.screen = screen;
        p.values.resize(n);
        if (lightTables.size() < n) lightTables.resize(n);
        if (lightData.size() < n) {
            lightData.resize(n);
            dataMethod.resize(n, nullptr);
        }
        std::vector<const ls::LightData*> data(n, nullptr);
        for (size_t i = 0; i < n; ++i) {
            const ls::LightSetup& s = v.lights[i];
            const ls::MethodUnit& method = *methods[i];
            p.values[i].constants = frameConstants(s);
            p.values[i].screenRect = s.screenRect;
            if (!v.touchesView[i]) continue;  // no chain: nothing to prepare
            if (dataMethod[i] != &method) {
                lightData[i] = method.makeData();
                dataMethod[i] = &method;
            }
            for (ls::CpuWork& w : method.prepare(lightData[i].get(), p.values[i], s))
                p.cpuWork.push_back({w.name, w.milliseconds, -1});
            data[i] = lightData[i].get();
            p.values[i].data = data[i];
            if (method.readsTable(s)) {
                if (!lightTables[i])
                    lightTables[i] =
                        std::make_unique<ls::PointTable>(device, ls::kTableWidth, ls::kTableHeight);
                p.values[i].fillTable =
                    lightTables[i]->needsFill(p.values[i].constants, s.medium.phase);
                if (p.values[i].fillTable)
                    p.setupPasses.push_back(n == 1 ? "point-light table"
                                                   : "point-light table (light " +
                                                         std::to_string(i) + ")");
            }
        }
        detail::GraphOptions options;
        options.depthStencil = depthStencil;
        options.coordinates = coordinates;
        options.poisonTransients = frame.debug.poisonTransients || poisonFromEnvironment();
        options.countSteps = frame.debug.countSteps;
        options.maxScreen = maxRenderSize;
        const GraphConfig c = detail::graphConfig(v, methods, detail::frameImports(frame), options,
                                                  data, lastConfig ? &*lastConfig : nullptr);
        if (c.ownNoise) {
            if (!tilingNoise) tilingNoise = std::make_unique<ls::TilingNoise>(device);
            p.noise.make = !tilingNoise->made();
            if (p.noise.make) p.setupPasses.push_back("tiling noise");
        }
        const uint64_t compiledBefore = graphsCompiled;
        p.graph = &graphFor(c);
        p.graphCompiled = graphsCompiled != compiledBefore;
        lastConfig = c;
        const FrameGraph& fg = *p.graph->built;
        // This frame's handles and stages; layouts are part of the configuration.
        fg.graph->updateImport(fg.depth, detail::importDescription(frame.depth));
        fg.graph->updateImport(fg.color, detail::importDescription(frame.color));
        if (fg.inscatterOut.valid())
            fg.graph->updateImport(fg.inscatterOut, detail::importDescription(*frame.inscatterOut));
        if (fg.volumeOut.valid())
            fg.graph->updateImport(fg.volumeOut, detail::importDescription(*frame.volumeOut));
        if (fg.noise.valid())
            fg.graph->updateImport(fg.noise, frame.noise
                                                 ? detail::importDescription(*frame.noise)
                                                 : detail::persistentImport(detail::ownNoiseState(),
                                                                            tilingNoise->image(),
                                                                            tilingNoise->made()));
        if (fg.makeNoise.valid()) p.data.set(fg.makeNoise, p.noise);
        const std::vector<LightInput> inputs = detail::lightInputs(frame);
        for (size_t i = 0; i < n; ++i) {
            const auto& images = fg.lights[i];
            p.data.set(images.values, p.values[i]);
            if (images.shadowMap.valid())
                fg.graph->updateImport(images.shadowMap,
                                       detail::importDescription(*inputs[i].shadowMap));
            if (images.lightColor.valid())
                fg.graph->updateImport(images.lightColor,
                                       detail::importDescription(*inputs[i].lightColor));
            if (images.table.valid())
                fg.graph->updateImport(images.table, detail::persistentImport(
                                                         c.lights[i].table, lightTables[i]->image(),
                                                         lightTables[i]->filled()));
        }
        importStepCounter(fg, c.stepCountSlices);
        if (fg.history.valid()) importHistory(p, fg, c.history, frame.resetHistory);
        Running& r = *p.graph->running;
        if (!r.rehearsed) {
            // Passes make their pipelines on first use: that happens here, on a command buffer of
            // the executor's own that is never submitted, before the engine's is touched. A graph
            // that fails it is made again by the next frame.
            try {
                r.executor->rehearse(p.data, p.screen);
            } catch (...) {
                p.graph->running.reset();
                throw;
            }
            r.rehearsed = true;
        }
        return p;
    }

    // The frame's history images, made (again) for the shape the frame keeps, and what the frame
    // knows of them: the frame before's state where it left one of this shape and no reset came.
    void importHistory(Prepared& p, const FrameGraph& fg, const detail::ImportState& state,
                       bool reset) {
        History& h = history;
        if (h.state != state) {
            if (h.images[0])  // frames recorded with the old images may still run
                retired.retire(
                    lastFrame,
                    [old = std::make_shared<decltype(h.images)>(std::move(h.images))] {});
            for (int i = 0; i < 2; ++i)
                h.images[i] = std::make_unique<rg::OwnedImage>(
                    device, state.format, state.extent, state.usage,
                    i == 0 ? "frame history A" : "frame history B", 1, 0, state.depth);
            h.state = state;
            h.filled = {};
            h.valid = false;
        }
        p.keepsHistory = true;
        p.historyValues.valid = h.valid && !reset;
        p.historyValues.index = p.historyValues.valid ? h.index : 0;
        p.historyValues.previous = h.previous;
        p.data.set(fg.historyValues, p.historyValues);
        const uint32_t read = h.next ^ 1u;
        fg.graph->updateImport(
            fg.history, detail::historyImport(state, h.images[read]->image(), h.filled[read]));
        fg.graph->updateImport(
            fg.historyOut,
            detail::historyImport(state, h.images[h.next]->image(), h.filled[h.next]));
    }

    // The frame was recorded: what it fills is filled for the frames after it, and it is kept in
    // the history for its report.
    uint64_t recorded(const Prepared& p) {
        const GraphConfig& c = p.graph->config;
        if (p.keepsHistory) {
            history.filled[history.next] = true;
            history.previous = p.values[0].constants;
            history.index = p.historyValues.index + 1;
            history.valid = true;
            history.next ^= 1u;
        } else {
            history.valid = false;  // a frame without it breaks the sequence
        }
        for (size_t i = 0; i < p.values.size(); ++i)
            if (p.values[i].fillTable)
                lightTables[i]->recordedFill(p.values[i].constants, c.lights[i].chain.spec.phase);
        if (p.noise.make) tilingNoise->recordedMake();
        lastExecutor = p.graph->running->executor.get();
        p.graph->lastUse = lastFrame;
        RecordedFrame f;
        f.frame = lastFrame;
        f.graph = p.graph->running;
        const FrameGraph& fg = *p.graph->built;
        for (const auto& pass : f.graph->executor->compiled().passes)
            f.passNames.push_back(fg.graph->passes()[pass.pass].name);
        f.setupPasses = p.setupPasses;
        f.graphCompiled = p.graphCompiled;
        f.countedSteps = fg.stepCounts.valid();
        f.stepSlices = c.stepCountSlices;
        f.cpuWork = p.cpuWork;
        describeMethods(f, p);
        frames.push_back(std::move(f));
        while (frames.size() > kTimedFrames) frames.pop_front();
        return lastFrame;
    }

    // Records the prepared frame into `cmd` as frame lastFrame + 1.
    uint64_t record(VkCommandBuffer cmd, const Prepared& p) {
        const uint64_t number = lastFrame + 1;
        rg::GraphExecutor& e = *p.graph->running->executor;
        e.record(cmd, number, p.data, before(e), p.screen);
        lastFrame = number;
        return recorded(p);
    }

    // What a first use of the shared heap waits on: the uses of the graph recorded last, when it
    // is another one.
    const rg::TransientScope* before(const rg::GraphExecutor& e) const {
        return lastExecutor && lastExecutor != &e ? &lastScope() : nullptr;
    }
    const rg::TransientScope& lastScope() const {
        // lastExecutor is alive: it was recorded last, so nothing retired it yet, or its Running is
        // still in the frame history.
        return lastExecutor->transientScope();
    }

    // The report's methods: each light's (FrameReport::lights), and the frame's: the method of
    // every light with a chain, each named once in the lights' order ("none" without one). With one
    // method for every light, the reason is Auto's for the first light that has a chain, or the
    // frame's summary; with several, the summary, which names each light's method.
    void describeMethods(RecordedFrame& f, const Prepared& p) const {
        const GraphConfig& c = p.graph->config;
        const FrameGraph& fg = *p.graph->built;
        std::vector<std::string> names;
        const detail::MethodChoice* first = nullptr;
        for (size_t i = 0; i < c.lights.size(); ++i) {
            const detail::MethodChoice& choice = p.choices[i];
            FrameReport::Light l;
            l.method = c.lights[i].touchesView ? methodName(choice.method) : "none";
            l.reason = choice.reason.empty() ? (c.lights[i].touchesView
                                                    ? c.lights[i].method->summary(c.lights[i].chain)
                                                    : "the light reaches no view ray (or nothing "
                                                      "scatters): no chain")
                                             : choice.reason;
            l.notice = choice.notice;
            l.settings = p.settings[i];
            f.lights.push_back(l);
            if (!c.lights[i].touchesView) continue;
            if (!first) first = &choice;
            if (std::find(names.begin(), names.end(), l.method) == names.end())
                names.push_back(l.method);
        }
        if (names.empty()) {
            f.method = "none";
            f.reason = p.choices[0].reason.empty() ? fg.summary : p.choices[0].reason;
            f.notice = p.choices[0].notice;
        } else {
            for (size_t k = 0; k < names.size(); ++k) f.method += (k ? "+" : "") + names[k];
            f.reason = names.size() == 1 && c.lights.size() == 1 && !first->reason.empty()
                           ? first->reason
                           : fg.summary;
            // The notices of the lights' methods, each once.
            for (const FrameReport::Light& l : f.lights)
                if (!l.notice.empty() && f.notice.find(l.notice) == std::string::npos)
                    f.notice += (f.notice.empty() ? "" : "; ") + l.notice;
        }
        f.reason += frameNotes(p);
    }

    // What changed this frame without a rebuild (epipolar's cube faces reaching the view), per
    // light that has a chain.
    std::string frameNotes(const Prepared& p) const {
        const GraphConfig& c = p.graph->config;
        std::string notes;
        for (size_t i = 0; i < c.lights.size(); ++i) {
            if (!c.lights[i].touchesView) continue;
            const std::string note = c.lights[i].method->frameNote(p.values[i], c.lights[i].chain);
            if (note.empty()) continue;
            notes +=
                c.lights.size() == 1 ? "; " + note : "; light " + std::to_string(i) + "'s " + note;
        }
        return notes;
    }

    FrameReport report(uint64_t frame) const {
        const std::string which = "report(" + std::to_string(frame) + "): ";
        if (frame == 0 || frame > lastFrame)
            throw InvalidInput("lightscatter: " + which +
                               "no such frame was recorded (the last is " +
                               std::to_string(lastFrame) + ")");
        const RecordedFrame* f = nullptr;
        for (const auto& r : frames)
            if (r.frame == frame) f = &r;
        if (!f)
            throw InvalidInput("lightscatter: " + which + "the times of only the last " +
                               std::to_string(kTimedFrames) + " frames are kept (the last is " +
                               std::to_string(lastFrame) + ")");
        const rg::FrameTimings t = f->graph->executor->readTimings(frame);
        FrameReport r;
        r.frame = frame;
        r.timed = t.valid;
        r.device = device.name();
        r.depthStencilFormat = rg::formatName(depthStencil);
        if (t.valid) {
            for (const auto& p : t.passes) r.passes.push_back({p.name, p.milliseconds, p.samples});
            r.totalMilliseconds = t.totalMilliseconds;
            if (f->countedSteps) r.steps = readStepCounts(frame, f->stepSlices);
        }
        r.passNames = f->passNames;
        r.method = f->method;
        r.reason = f->reason;
        r.notice = f->notice;
        r.lights = f->lights;
        r.setupPasses = f->setupPasses;
        r.graphCompiled = f->graphCompiled;
        r.cpuWork = f->cpuWork;
        return r;
    }

    // The graph of the last frame recorded, for tools.
    const CachedGraph* lastGraph() const {
        const CachedGraph* last = nullptr;
        for (const auto& g : graphs)
            if (g->running && (!last || g->lastUse > last->lastUse)) last = g.get();
        return last;
    }

    static constexpr size_t kCachedGraphs = 8;

    rg::Device device;
    rg::VulkanDeviceCaps caps;
    ls::Shared shared;  // the samplers and pipelines every light's passes share
    uint32_t framesInFlight = 2;
    VkExtent2D maxRenderSize{0, 0};
    VkFormat depthStencil = VK_FORMAT_UNDEFINED;
    VkFormat coordinates = VK_FORMAT_R32G32_SFLOAT;
    // Per light, in the frame's order: its point-light table and its method's state (made by
    // dataMethod[i]).
    std::vector<std::unique_ptr<ls::PointTable>> lightTables;
    std::vector<std::unique_ptr<ls::LightData>> lightData;
    std::vector<const ls::MethodUnit*> dataMethod;
    std::unique_ptr<ls::TilingNoise> tilingNoise;
    // The frame-wide method's history (shared/frame_history.h): two images, alternated.
    struct History {
        detail::ImportState state;  // their shape; absent before the first frame that keeps one
        std::array<std::unique_ptr<rg::OwnedImage>, 2> images;
        std::array<bool, 2> filled{};
        uint32_t next = 0;   // the image the next frame writes
        bool valid = false;  // the other holds the last recorded frame's state
        uint32_t index = 0;  // frames since the history began, the last recorded one included
        ls::FrameConstants previous{};  // the last recorded frame's first light's constants
    } history;
    // Declared before the graphs: they are placed in it, and go first.
    rg::TransientHeap heap;
    rg::RetireList retired;
    std::vector<std::unique_ptr<CachedGraph>> graphs;
    std::optional<GraphConfig> lastConfig;
    const rg::GraphExecutor* lastExecutor = nullptr;  // recorded the last frame
    uint64_t graphsCompiled = 0;
    // DebugOptions::countSteps: frame n's step counter is stepBuffers[n % kTimedFrames].
    std::array<std::unique_ptr<rg::HostBuffer>, kTimedFrames> stepBuffers;
    uint64_t lastFrame = 0;
    std::deque<RecordedFrame> frames;  // the last kTimedFrames
};

namespace {

// Vulkan failures leave the plugin as lightscatter::DeviceError; the rest passes unchanged.
template <typename F>
auto translated(F&& f) -> decltype(f()) {
    try {
        return f();
    } catch (const rg::VulkanError& e) {
        throw DeviceError(std::string("lightscatter: ") + e.what());
    }
}

}  // namespace

Plugin::Plugin(const PluginCreateInfo& info, HeaderVersion)
    : impl_(translated([&] { return std::make_unique<Impl>(info); })) {}

Plugin::Plugin(const VulkanContext& context) : Plugin(PluginCreateInfo{2, context}) {}

// Waits for nothing (see the header): what the plugin made goes now.
Plugin::~Plugin() = default;

uint64_t Plugin::record(VkCommandBuffer cmd, const FrameDescription& frame) {
    if (!cmd)
        throw InvalidInput(
            "lightscatter: record: cmd is VK_NULL_HANDLE: pass the engine's command "
            "buffer, in the recording state");
    return translated([&] {
        Impl& i = *impl_;
        // Recording frame N promises that frame N - framesInFlight has completed.
        const uint64_t number = i.lastFrame + 1;
        if (number > i.framesInFlight) i.collect(number - i.framesInFlight);
        const Impl::Prepared p = i.prepare(frame);
        return i.record(cmd, p);
    });
}

FrameReport Plugin::render(const FrameDescription& frame) {
    return translated([&] {
        Impl& i = *impl_;
        const uint64_t number = i.lastFrame + 1;
        if (number > i.framesInFlight) i.collect(number - i.framesInFlight);
        const Impl::Prepared p = i.prepare(frame);
        rg::GraphExecutor& e = *p.graph->running->executor;
        e.run(number, p.data, i.before(e), p.screen);
        i.lastFrame = number;
        i.recorded(p);
        // Frames run in the order they were recorded: this one done, so is every one before.
        i.collect(number);
        return i.report(number);
    });
}

void Plugin::check(const FrameDescription& frame) const {
    translated([&] { impl_->check(frame); });
}

FrameReport Plugin::report(uint64_t frame) {
    return translated([&] { return impl_->report(frame); });
}

FrameReport Plugin::report() {
    return translated([&] {
        if (impl_->lastFrame == 0) return FrameReport{};
        return impl_->report(impl_->lastFrame);
    });
}

std::string Plugin::graphDot() const {
    const CachedGraph* g = impl_->lastGraph();
    if (!g) return {};
    return rg::reportDot(*g->built->graph, g->running->executor->compiled());
}

std::string Plugin::graphJson() const {
    const CachedGraph* g = impl_->lastGraph();
    if (!g) return {};
    return rg::reportJson(*g->built->graph, g->running->executor->compiled()).dump(2);
}

}  // namespace lightscatter
