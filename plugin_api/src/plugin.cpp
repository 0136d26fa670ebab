#include <algorithm>
#include <array>
#include <cstdlib>
#include <deque>
#include <optional>
#include <string>

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
#include "rendergraph/report.h"
#include "rendergraph/vk_error.h"
#include "shared/point_table.h"

namespace lightscatter {

using detail::FrameGraph;
using detail::GraphConfig;

namespace {

bool poisonFromEnvironment() {
    const char* v = std::getenv("LS_POISON_TRANSIENTS");
    return v && *v && std::string(v) != "0";
}

// Refuses a context before anything is made from it.
const VulkanContext& checked(const VulkanContext& c) {
    auto null = [](const char* field) {
        throw InvalidInput(std::string("lightscatter: context.") + field + " is VK_NULL_HANDLE");
    };
    if (!c.instance) null("instance");
    if (!c.physicalDevice) null("physicalDevice");
    if (!c.device) null("device");
    if (!c.queue) null("queue");
    detail::checkEnabledFeatures(c.enabledFeatures);
    return c;
}

// What a recorded frame's report needs besides its timestamps.
struct RecordedFrame {
    uint64_t frame = 0;
    uint64_t graph = 0;  // the frame graph it was recorded with
    std::string method, reason, notice;
    std::vector<std::string> passNames;
    bool tableRefilled = false;
    bool noiseMade = false;
    std::vector<PassTime> cpuWork;
    bool countedSteps = false;  // its march added into stepBuffers[frame % kTimedFrames]
};

}  // namespace

struct Plugin::Impl {
    explicit Impl(const VulkanContext& c)
        : device(rg::ExternalDevice{checked(c).instance, c.physicalDevice, c.device, c.queue,
                                    c.queueFamily}),
          caps(device),
          shared(std::make_shared<ls::SharedState>(device)) {
        depthStencil = detail::stencilFormat(caps);
        coordinates = detail::coordinateFormat(caps);
        if (depthStencil == VK_FORMAT_UNDEFINED)
            throw std::runtime_error(
                "lightscatter: the device has no depth-stencil format with stencil");
    }

    // Everything that can refuse a frame, before anything is built: the checked frame and its
    // method.
    struct Chosen {
        detail::ValidatedFrame frame;
        detail::MethodChoice choice;
    };
    static Chosen choose(const FrameDescription& frame) {
        Chosen c{detail::validateFrame(frame)};
        c.choice = detail::chooseFrameMethod(frame.method, c.frame, frame);
        return c;
    }

    // What prepare() refuses, found the same way, with nothing built or changed.
    static void check(const FrameDescription& frame) { choose(frame); }

    static ls::ScatterSpec scatterSpec(const detail::FrameSetup& setup) {
        ls::ScatterSpec spec;
        spec.light = setup.light.kind;
        spec.phase = setup.medium.phase;
        spec.minMaxTrees = setup.epipolar.minMaxTrees;
        spec.lightColor = setup.lightColor;
        spec.bilinearShadow = setup.epipolar.bilinearShadow;
        spec.simplifiedModel = setup.simplified;
        spec.cubeShadow = setup.shadowed && setup.light.kind == ls::LightType::Point;
        return spec;
    }

    // One light's constants and shader options.
    static void fillShared(ls::SharedState& s, const detail::FrameSetup& setup) {
        const ls::TableLayout table =
            ls::tableLayoutFor(setup.medium, setup.light.radius, ls::kTableWidth, ls::kTableHeight);
        s.spec = scatterSpec(setup);
        s.constants = ls::makeFrameConstants(setup.camera, setup.light, setup.medium,
                                             setup.epipolar, setup.screen, table);
        // Seed 004's I / (a1 r^2 + a0) as (I / a1) / (r^2 + a0 / a1); the floor keeps a ray through
        // the light finite when a0 is 0, as the floor on r0 does for the full model; the ceilings
        // keep a denormal a1 from making them infinite.
        const float a1 = setup.settings.simplifiedA1;
        s.constants.simplified = {std::clamp(setup.settings.simplifiedA0 / a1, 1e-12f, 1e30f),
                                  std::min(1.0f / a1, 1e30f), 0.0f, 0.0f};
        const float storage = detail::linStorageScale(setup);
        s.constants.linStorage = {storage, 1.0f / storage, 0.0f, 0.0f};
    }

    // Builds the graph for `c` unless the current one was built for it.
    void ensureGraph(const GraphConfig& c, const std::vector<const ls::LightData*>& data) {
        if (config && *config == c) return;
        // The old graph's memory goes first (the new one may need it); until the new one is
        // complete there is none, so that a failure leaves nothing half-built behind.
        executor.reset();
        config.reset();
        ++graphGeneration;
        FrameGraph built = detail::buildFrameGraph(c, lightShared, data);
        rg::CompileOptions options;
        options.poisonTransients = c.poisonTransients;
        rg::CompiledGraph compiled = rg::compile(*built.graph, caps, options);
        fg = std::move(built);
        executor = std::make_unique<rg::GraphExecutor>(device, *fg.graph, std::move(compiled));
        rehearsed = false;
        config = c;
        // The old graph's frames are done (the executor waited for the device): their counters go.
        for (auto& b : stepBuffers) b.reset();
    }

    // The step counter of the frame about to be recorded: one buffer per frame that may be in
    // flight, as with the timestamp queries, so that a frame's counts wait for its report.
    void importStepCounter() {
        if (!fg.stepCounts.valid()) return;
        auto& buffer = stepBuffers[(lastFrame + 1) % kTimedFrames];
        const uint32_t slices = config->stepCountSlices;
        if (!buffer) {
            const rg::ImportedBuffer d = detail::stepCountImport(VK_NULL_HANDLE, slices);
            buffer =
                std::make_unique<rg::HostBuffer>(device, d.size, d.usage, "ray-march step counts");
        }
        fg.graph->updateImport(fg.stepCounts, detail::stepCountImport(buffer->buffer(), slices));
    }

    std::optional<StepCounts> readStepCounts(uint64_t frame) const {
        const auto& buffer = stepBuffers[frame % kTimedFrames];
        if (!buffer) return std::nullopt;
        const auto sum = ls::sumStepCounts(static_cast<const uint32_t*>(buffer->data()),
                                           config->stepCountSlices);
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

    void rehearseOnce() {
        if (rehearsed) return;
        // Passes build their pipelines on first use: do that on a command buffer of our own.
        try {
            executor->rehearse();
        } catch (...) {
            executor.reset();
            config.reset();
            throw;
        }
        rehearsed = true;
    }

    // One path for every frame: each light's constants, its method's CPU work and its table, the
    // graph for the frame's configuration, and this frame's handles.
    void prepare(const FrameDescription& frame) {
        Chosen chosen = choose(frame);
        const detail::ValidatedFrame& v = chosen.frame;
        const ls::MethodUnit& method = chosen.choice.unit();
        const size_t n = v.lights.size();
        lastChoice = chosen.choice;
        while (lightShared.size() < n) lightShared.push_back(ls::SharedState::sibling(*shared));
        if (lightTables.size() < n) lightTables.resize(n);
        if (lightData.size() < n) {
            lightData.resize(n);
            dataMethod.resize(n, nullptr);
        }
        cpuWork.clear();
        tableRefilled = false;
        std::vector<const ls::LightData*> data(n, nullptr);
        for (size_t i = 0; i < n; ++i) {
            const detail::FrameSetup& s = v.lights[i];
            fillShared(*lightShared[i], s);
            if (!v.touchesView[i]) continue;  // no chain: nothing to prepare
            if (dataMethod[i] != &method) {
                lightData[i] = method.makeData();
                dataMethod[i] = &method;
            }
            for (ls::CpuWork& w : method.prepare(lightData[i].get(), *lightShared[i], s))
                cpuWork.push_back({w.name, w.milliseconds, -1});
            data[i] = lightData[i].get();
            if (method.readsTable(s)) {
                if (!lightTables[i])
                    lightTables[i] =
                        std::make_unique<ls::PointTable>(device, ls::kTableWidth, ls::kTableHeight);
                tableRefilled = lightTables[i]->update(lightShared[i]) || tableRefilled;
            }
        }
        detail::GraphOptions options;
        options.depthStencil = depthStencil;
        options.coordinates = coordinates;
        options.poisonTransients = frame.debug.poisonTransients || poisonFromEnvironment();
        options.countSteps = frame.debug.countSteps;
        const GraphConfig c = detail::graphConfig(v, method, detail::frameImports(frame), options,
                                                  data, config ? &*config : nullptr);
        noiseMade = false;
        if (c.ownNoise) {
            if (!tilingNoise) tilingNoise = std::make_unique<ls::TilingNoise>(device);
            noiseMade = tilingNoise->ensure(lightShared[0]);
        }
        ensureGraph(c, data);
        // This frame's handles and stages; layouts are part of the configuration.
        fg.graph->updateImport(fg.depth, detail::importDescription(frame.depth));
        fg.graph->updateImport(fg.color, detail::importDescription(frame.color));
        if (fg.inscatterOut.valid())
            fg.graph->updateImport(fg.inscatterOut, detail::importDescription(*frame.inscatterOut));
        if (fg.noise.valid())
            fg.graph->updateImport(fg.noise, frame.noise
                                                 ? detail::importDescription(*frame.noise)
                                                 : detail::persistentImport(detail::ownNoiseState(),
                                                                            tilingNoise->image()));
        const std::vector<LightInput> inputs = detail::lightInputs(frame);
        for (size_t i = 0; i < n; ++i) {
            const auto& images = fg.lights[i];
            if (images.shadowMap.valid())
                fg.graph->updateImport(images.shadowMap,
                                       detail::importDescription(*inputs[i].shadowMap));
            if (images.lightColor.valid())
                fg.graph->updateImport(images.lightColor,
                                       detail::importDescription(*inputs[i].lightColor));
            if (images.table.valid())
                fg.graph->updateImport(
                    images.table,
                    detail::persistentImport(c.lights[i].table, lightTables[i]->image()));
        }
        importStepCounter();
        rehearseOnce();
    }

    // What changed this frame without a rebuild (epipolar's cube faces reaching the view), per
    // light that has a chain.
    std::string frameNotes() const {
        if (!config) return {};
        std::string notes;
        for (size_t i = 0; i < config->lights.size(); ++i) {
            if (!config->lights[i].touchesView) continue;
            const std::string note =
                config->method->frameNote(*lightShared[i], config->lights[i].chain);
            if (note.empty()) continue;
            notes += config->lights.size() == 1 ? "; " + note
                                                : "; light " + std::to_string(i) + "'s " + note;
        }
        return notes;
    }

    // Numbers the frame just prepared and keeps what its report will need.
    uint64_t nextFrame() {
        RecordedFrame f;
        f.frame = ++lastFrame;
        f.graph = graphGeneration;
        for (const auto& p : executor->compiled().passes)
            f.passNames.push_back(fg.graph->passes()[p.pass].name);
        f.tableRefilled = tableRefilled;
        f.noiseMade = noiseMade;
        f.countedSteps = fg.stepCounts.valid();
        f.cpuWork = cpuWork;
        const bool anyChain =
            config && std::any_of(config->lights.begin(), config->lights.end(),
                                  [](const detail::LightGraphConfig& l) { return l.touchesView; });
        f.method = anyChain ? methodName(lastChoice.method) : "none";
        f.reason = (lastChoice.reason.empty() ? fg.summary : lastChoice.reason) + frameNotes();
        f.notice = lastChoice.notice;
        frames.push_back(std::move(f));
        while (frames.size() > kTimedFrames) frames.pop_front();
        return lastFrame;
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
        if (f->graph != graphGeneration)
            throw InvalidInput(
                "lightscatter: " + which +
                "the frame graph was rebuilt since (a new size, format, layout, method or "
                "profile), and that frame's queries with it");
        const rg::FrameTimings t = executor->readTimings(frame);
        FrameReport r;
        r.frame = frame;
        r.timed = t.valid;
        r.device = device.name();
        r.depthStencilFormat = rg::formatName(depthStencil);
        if (t.valid) {
            for (const auto& p : t.passes) r.passes.push_back({p.name, p.milliseconds, p.samples});
            r.totalMilliseconds = t.totalMilliseconds;
            if (f->countedSteps) r.steps = readStepCounts(frame);
        }
        r.passNames = f->passNames;
        r.method = f->method;
        r.reason = f->reason;
        r.notice = f->notice;
        if (f->tableRefilled) r.setupPasses.push_back("point-light table");
        if (f->noiseMade) r.setupPasses.push_back("tiling noise");
        r.cpuWork = f->cpuWork;
        return r;
    }

    rg::Device device;
    rg::VulkanDeviceCaps caps;
    ls::Shared shared;  // the pipelines and samplers every light's state shares
    VkFormat depthStencil = VK_FORMAT_UNDEFINED;
    VkFormat coordinates = VK_FORMAT_R32G32_SFLOAT;
    // Per light, in the frame's order: its constants and options (over `shared`'s pipelines), its
    // point-light table, and its method's state (made by dataMethod[i]).
    std::vector<ls::Shared> lightShared;
    std::vector<std::unique_ptr<ls::PointTable>> lightTables;
    std::vector<std::unique_ptr<ls::LightData>> lightData;
    std::vector<const ls::MethodUnit*> dataMethod;
    bool tableRefilled = false;
    std::unique_ptr<ls::TilingNoise> tilingNoise;
    bool noiseMade = false;
    std::vector<PassTime> cpuWork;  // this frame's
    std::optional<GraphConfig> config;
    bool rehearsed = false;
    detail::MethodChoice lastChoice;  // of the frame prepared last
    FrameGraph fg;
    std::unique_ptr<rg::GraphExecutor> executor;
    // DebugOptions::countSteps: frame n's step counter is stepBuffers[n % kTimedFrames].
    std::array<std::unique_ptr<rg::HostBuffer>, kTimedFrames> stepBuffers;
    uint64_t graphGeneration = 0;
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

Plugin::Plugin(const VulkanContext& context)
    : impl_(translated([&] { return std::make_unique<Impl>(context); })) {}

Plugin::~Plugin() {
    if (impl_) impl_->executor.reset();
}

uint64_t Plugin::record(VkCommandBuffer cmd, const FrameDescription& frame) {
    if (!cmd)
        throw InvalidInput(
            "lightscatter: record: cmd is VK_NULL_HANDLE: pass the engine's command "
            "buffer, in the recording state");
    return translated([&] {
        impl_->prepare(frame);
        const uint64_t number = impl_->nextFrame();
        impl_->executor->record(cmd, number);
        return number;
    });
}

FrameReport Plugin::render(const FrameDescription& frame) {
    return translated([&] {
        impl_->prepare(frame);
        const uint64_t number = impl_->nextFrame();
        impl_->executor->run(number);
        return impl_->report(number);
    });
}

void Plugin::check(const FrameDescription& frame) const {
    translated([&] { Impl::check(frame); });
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
    if (!impl_->executor) return {};
    return rg::reportDot(*impl_->fg.graph, impl_->executor->compiled());
}

std::string Plugin::graphJson() const {
    if (!impl_->executor) return {};
    return rg::reportJson(*impl_->fg.graph, impl_->executor->compiled()).dump(2);
}

}  // namespace lightscatter
