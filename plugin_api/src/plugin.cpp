// lightscatter::Plugin: a frame checked at the edge into one list of lights (frame_setup.h), each
// light's method chosen (method_choice.h), its state kept by its id (light_states.h), the graph of
// the frame's configuration taken from the cache (graph_cache.h) and recorded with this frame's
// values. Nothing waits for the GPU, nothing is submitted but by render().
#include <cstdlib>
#include <deque>
#include <limits>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <lightscatter/lightscatter.h>
#include "color_target.h"
#include "device_shared.h"
#include "frame_reports.h"
#include "frame_setup.h"
#include "graph_cache.h"
#include "image_formats.h"
#include "image_roles.h"
#include "light_states.h"
#include "lin_storage.h"
#include "method_choice.h"
#include "rendergraph/report.h"
#include "rendergraph/vk_error.h"
#include "shared/point_table.h"
#include "step_counters.h"
#include "volume_out.h"

namespace lightscatter {

using detail::CachedGraph;
using detail::FrameGraph;
using detail::GraphConfig;

namespace {

bool poisonFromEnvironment() {
    const char* v = std::getenv("LS_POISON_TRANSIENTS");
    return v && *v && std::string(v) != "0";
}

// A light's state lives this many frames past its last frame (beyond the frames in flight), so
// that a light leaving the view for a moment comes back to its table and data.
constexpr uint64_t kAbsentFramesKept = 60;

}  // namespace

struct Plugin::Impl {
    explicit Impl(const PluginCreateInfo& info)
        : device(detail::externalDevice(info)),
          caps(device),
          framesInFlight(info.framesInFlight),
          maxRenderSize(info.maxRenderSize),
          store(device, retired),
          graphs(device, caps, detail::sharedFor(info), retired, store),
          steps(device) {
        depthStencil = detail::stencilFormat(caps);
        coordinates = detail::coordinateFormat(caps);
        if (depthStencil == VK_FORMAT_UNDEFINED)
            throw std::runtime_error(
                "lightscatter: the device has no depth-stencil format with stencil");
    }

    // Everything a frame's graph still holds goes before the store, the heap and the device.
    ~Impl() {
        frames.clear();
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
        detail::checkColorBlend(frame, caps);
        c.choices = detail::chooseLightMethods(frame.method, c.frame, frame);
        if (frame.volumeOut) {
            const VkExtent2D screen =
                maxRenderSize.width != 0 ? maxRenderSize : c.frame.lights[0].screen;
            detail::checkVolumeOut(*frame.volumeOut, c.frame, c.choices, screen);
            // The engine's volume is written even where no light reaches the view: the first
            // light's chain then fills the grid with the medium's transmittance alone.
            c.frame.touchesView[detail::gridLight(c.frame)] = true;
        }
        const VkExtent2D screen = c.frame.lights[0].screen;
        if (maxRenderSize.width != 0 &&
            (screen.width > maxRenderSize.width || screen.height > maxRenderSize.height))
            throw InvalidInput("lightscatter: depth.extent " + std::to_string(screen.width) + "x" +
                               std::to_string(screen.height) + " is larger than maxRenderSize " +
                               std::to_string(maxRenderSize.width) + "x" +
                               std::to_string(maxRenderSize.height) + " (PluginCreateInfo)");
        // Last, the rules of the images together: each image's own rules name a lone fault first.
        const std::vector<detail::ImageRole> roles = detail::imageRoles(frame, c.frame);
        detail::checkSharedImages(roles);
        detail::checkImageFormats(roles, caps);
        return c;
    }

    // One light's constants.
    ls::FrameConstants frameConstants(const ls::LightSetup& setup,
                                      const ls::MethodUnit& method) const {
        const ls::TableLayout table =
            ls::tableLayoutFor(setup.medium, setup.light.radius, ls::kTableWidth, ls::kTableHeight);
        const ls::FrameParams params{.screen = setup.screen,
                                     .maxScreen = maxRenderSize,
                                     .simplifiedA0 = setup.settings.simplifiedA0,
                                     .simplifiedA1 = setup.settings.simplifiedA1,
                                     .linStorage = detail::linStorageScale(setup, method),
                                     .preExposure = setup.preExposure};
        return ls::makeFrameConstants(setup.camera, setup.light, setup.medium, params, table);
    }

    // The frame N - framesInFlight and everything before it have completed (the engine's promise
    // when it records frame N): what they alone used is destroyed.
    void collect(uint64_t completed) {
        retired.collect(completed);
        graphs.collect(completed);
    }

    // A frame ready to record: its graph (cached), its values and handles. A frame's values are
    // its own, so frames may be recorded ahead.
    struct Prepared {
        CachedGraph* graph = nullptr;
        detail::ValidatedFrame frame;
        std::vector<detail::MethodChoice> choices;  // per light, in the frame's (ids') order
        std::vector<ls::LightFrame> values;         // per light
        std::vector<rg::PersistentKey> keys;        // per light: its id
        rg::PersistentKey frameKey;
        ls::PreviousFrame previous;
        rg::FrameData data;
        std::vector<PassTime> cpuWork;
        bool graphCompiled = false;
        VkExtent2D screen{0, 0};  // the frame's (within the graph's, with maxRenderSize)
    };

    void prepare(Prepared& p, const FrameDescription& frame) {
        Chosen chosen = choose(frame);
        p.frame = std::move(chosen.frame);
        p.choices = std::move(chosen.choices);
        const detail::ValidatedFrame& v = p.frame;
        const size_t n = v.lights.size();
        const uint64_t number = lastFrame + 1;
        // A light absent long enough is forgotten, with what the graph kept for it.
        if (number > framesInFlight + kAbsentFramesKept) {
            const uint64_t keptFrom = number - framesInFlight - kAbsentFramesKept;
            lights.release(keptFrom);
            store.release(keptFrom, lastFrame);
        }
        p.screen = v.lights[0].screen;
        p.values.resize(n);
        std::vector<const ls::MethodUnit*> methods(n);
        std::vector<const ls::LightData*> data(n, nullptr);
        std::vector<const ls::ChainOptions*> previous(n, nullptr);
        for (size_t i = 0; i < n; ++i) {
            const ls::LightSetup& s = v.lights[i];
            const ls::MethodUnit& method = p.choices[i].unit();
            methods[i] = &method;
            p.keys.push_back({v.given[i].id});
            p.values[i].constants = frameConstants(s, method);
            p.values[i].screenRect = s.screenRect;
            detail::LightStates::State& state = lights.of(v.given[i].id, method, number);
            if (state.options) previous[i] = &*state.options;
            if (!v.touchesView[i]) continue;  // no chain: nothing to prepare
            for (ls::CpuWork& w : method.prepare(state.data.get(), p.values[i], s))
                p.cpuWork.push_back({w.name, w.milliseconds, -1});
            data[i] = p.values[i].data = state.data.get();
        }
        detail::GraphOptions options;
        options.depthStencil = depthStencil;
        options.coordinates = coordinates;
        options.poisonTransients = frame.debug.poisonTransients || poisonFromEnvironment();
        options.countSteps = frame.debug.countSteps;
        options.maxScreen = maxRenderSize;
        options.dualSourceBlend = graphs.shared()->capabilities.dualSourceBlend;
        options.colorBlends = frame.color.format != VK_FORMAT_UNDEFINED &&
                              detail::formatBlends(frame.color.format, caps);
        const GraphConfig c = detail::graphConfig(v, methods, detail::frameImports(frame, v),
                                                  options, data, previous);
        p.graph = &graphs.graphFor(c, lastFrame, p.graphCompiled);
        for (size_t i = 0; i < n; ++i)
            lights.of(v.given[i].id, *methods[i], number).options = c.lights[i].chain.options;
        const FrameGraph& fg = *p.graph->built;
        importImages(p, fg, frame);
        p.previous.constants = previousConstants;
        p.previous.beforeMoved = previousMoved;
        lightChanges(p, previousLights);
        p.data.set(fg.frameKey, p.frameKey).set(fg.previous, p.previous);
        p.data.discardHistories(frame.resetHistory);
        for (size_t i = 0; i < n; ++i)
            p.data.set(fg.lights[i].values, p.values[i]).set(fg.lights[i].key, p.keys[i]);
        steps.import(fg, number, c.stepCountBytes, lastFrame, retired);
        detail::Running& r = *p.graph->running;
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
    }

    // This frame's handles and stages of the engine's images; layouts are part of the
    // configuration.
    static void importImages(const Prepared& p, const FrameGraph& fg, const FrameDescription& f) {
        rg::RenderGraph& g = *fg.graph;
        g.updateImport(fg.depth, detail::importDescription(f.depth));
        if (fg.color.valid()) g.updateImport(fg.color, detail::importDescription(f.color));
        if (fg.inscatterOut.valid())
            g.updateImport(fg.inscatterOut, detail::importDescription(*f.inscatterOut));
        if (fg.transmittanceOut.valid())
            g.updateImport(fg.transmittanceOut, detail::importDescription(*f.transmittanceOut));
        if (fg.volumeOut.valid())
            g.updateImport(fg.volumeOut, detail::importDescription(*f.volumeOut));
        if (fg.noise.valid()) g.updateImport(fg.noise, detail::importDescription(*f.noise));
        for (size_t i = 0; i < p.frame.given.size(); ++i) {
            const LightInput& in = p.frame.given[i].input;
            const auto& images = fg.lights[i];
            if (images.shadowMap.valid())
                g.updateImport(images.shadowMap, detail::importDescription(*in.shadowMap));
            if (images.lightColor.valid())
                g.updateImport(images.lightColor, detail::importDescription(*in.lightColor));
        }
    }

    // How the frame's lights differ from the last recorded frame's (ls::PreviousFrame): another
    // set of ids, or one of them moved or changed (ls::sameLight, ls::lightJump).
    static void lightChanges(Prepared& p,
                             const std::vector<std::pair<uint64_t, ls::FrameConstants>>& before) {
        ls::PreviousFrame& r = p.previous;
        r.lightsChanged = false;
        r.lightJump = 0.0f;
        if (p.keys.size() != before.size()) {
            r.lightsChanged = true;
            r.lightJump = std::numeric_limits<float>::infinity();
            return;
        }
        for (size_t i = 0; i < p.keys.size(); ++i) {
            if (p.keys[i].value != before[i].first) {
                r.lightsChanged = true;
                r.lightJump = std::numeric_limits<float>::infinity();
                return;
            }
            const ls::FrameConstants& now = p.values[i].constants;
            r.lightsChanged = r.lightsChanged || !ls::sameLight(before[i].second, now);
            r.lightJump = std::max(r.lightJump, ls::lightJump(before[i].second, now));
        }
    }

    // The frame was recorded: it is kept for its report.
    uint64_t recorded(const Prepared& p) {
        const GraphConfig& c = p.graph->config;
        previousMoved = p.previous.lightsChanged ||
                        previousConstants.viewProj != p.values[0].constants.viewProj;
        previousConstants = p.values[0].constants;
        previousLights.clear();
        for (size_t i = 0; i < p.keys.size(); ++i)
            previousLights.emplace_back(p.keys[i].value, p.values[i].constants);
        lastExecutor = p.graph->running->executor.get();
        p.graph->lastUse = lastFrame;
        detail::RecordedFrame f;
        f.frame = lastFrame;
        f.graph = p.graph->running;
        const FrameGraph& fg = *p.graph->built;
        for (const auto& pass : f.graph->executor->compiled().passes)
            f.passNames.push_back(fg.graph->passes()[pass.pass].name);
        f.setupPasses = f.graph->executor->lastFilled();
        f.graphCompiled = p.graphCompiled;
        f.stepCounter = fg.stepCounts.valid() ? c.stepCounter : nullptr;
        f.stepBytes = c.stepCountBytes;
        f.cpuWork = p.cpuWork;
        std::vector<Settings> settings;
        std::vector<size_t> given;
        for (size_t i = 0; i < p.frame.lights.size(); ++i) {
            settings.push_back(p.frame.lights[i].settings);
            given.push_back(p.frame.given[i].given);
        }
        detail::describeMethods(f, c, fg.summary, p.choices, settings, p.values, given);
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
        // lastExecutor is alive: it was recorded last, so nothing retired it yet, or its Running
        // is still among the frames kept for their reports.
        return lastExecutor && lastExecutor != &e ? &lastExecutor->transientScope() : nullptr;
    }

    FrameReport report(uint64_t frame) const {
        const std::string which = "report(" + std::to_string(frame) + "): ";
        if (frame == 0 || frame > lastFrame)
            throw InvalidInput("lightscatter: " + which +
                               "no such frame was recorded (the last is " +
                               std::to_string(lastFrame) + ")");
        const detail::RecordedFrame* f = nullptr;
        for (const auto& r : frames)
            if (r.frame == frame) f = &r;
        if (!f)
            throw InvalidInput("lightscatter: " + which + "the times of only the last " +
                               std::to_string(kTimedFrames) + " frames are kept (the last is " +
                               std::to_string(lastFrame) + ")");
        return detail::reportOf(*f, device.name(), depthStencil, steps);
    }

    rg::Device device;
    rg::VulkanDeviceCaps caps;
    uint32_t framesInFlight = 2;
    VkExtent2D maxRenderSize{0, 0};
    VkFormat depthStencil = VK_FORMAT_UNDEFINED;
    VkFormat coordinates = VK_FORMAT_R32G32_SFLOAT;
    // Declared before what retires into it, so that it is destroyed after them.
    rg::RetireList retired;
    rg::PersistentStore store;  // what the graphs keep across frames, by key
    detail::GraphCache graphs;
    detail::LightStates lights;
    detail::StepCounters steps;
    // The last recorded frame's first light's constants: the camera and the medium a history was
    // written with.
    ls::FrameConstants previousConstants{};
    bool previousMoved = true;  // PreviousFrame::beforeMoved of the next frame
    // Its lights, by id, in its order: what lightChanges() compares a frame's with.
    std::vector<std::pair<uint64_t, ls::FrameConstants>> previousLights;
    const rg::GraphExecutor* lastExecutor = nullptr;  // recorded the last frame
    uint64_t lastFrame = 0;
    std::deque<detail::RecordedFrame> frames;  // the last kTimedFrames
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
        Impl::Prepared p;
        i.prepare(p, frame);
        return i.record(cmd, p);
    });
}

FrameReport Plugin::render(const FrameDescription& frame) {
    return translated([&] {
        Impl& i = *impl_;
        const uint64_t number = i.lastFrame + 1;
        if (number > i.framesInFlight) i.collect(number - i.framesInFlight);
        Impl::Prepared p;
        i.prepare(p, frame);
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
    translated([&] { impl_->choose(frame); });
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
    const CachedGraph* g = impl_->graphs.last();
    if (!g) return {};
    return rg::reportDot(*g->built->graph, g->running->executor->compiled());
}

std::string Plugin::graphJson() const {
    const CachedGraph* g = impl_->graphs.last();
    if (!g) return {};
    return rg::reportJson(*g->built->graph, g->running->executor->compiled()).dump(2);
}

}  // namespace lightscatter
