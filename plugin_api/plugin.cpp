#include <algorithm>
#include <array>
#include <cstdlib>
#include <deque>
#include <optional>
#include <string>

#include "epipolar/step_counts.h"
#include "frame_graph.h"
#include "frame_setup.h"
#include "lightscatter.h"
#include "lin_storage.h"
#include "method_choice.h"
#include "point_table.h"
#include "rendergraph/compile.h"
#include "rendergraph/device_caps_vulkan.h"
#include "rendergraph/executor.h"
#include "rendergraph/format_info.h"
#include "rendergraph/host_buffer.h"
#include "rendergraph/report.h"
#include "rendergraph/vk_error.h"
#include "tiling_noise.h"

namespace lightscatter {

using detail::FrameGraph;
using detail::GraphConfig;
using detail::ImportState;

namespace {

constexpr uint32_t kTableWidth = 512;
constexpr uint32_t kTableHeight = 256;

bool poisonFromEnvironment() {
    const char* v = std::getenv("LS_POISON_TRANSIENTS");
    return v && *v && std::string(v) != "0";
}

ImportState state(const ImageInput& in) {
    return {in.format, in.extent, in.usage, in.layout, in.finalLayout, in.arrayLayers};
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

    void prepare(const FrameDescription& frame) {
        if (frame.lights.size() >= 2) return prepareLights(frame, chooseForLights(frame));
        if (frame.lights.size() == 1) {
            // One light in the list is the single light: every method takes it.
            detail::setupLights(frame);
            const FrameDescription single = detail::withLight(frame, 0);
            try {
                prepareOne(single, chooseForOne(single));
            } catch (const InvalidInput& e) {
                throw InvalidInput(detail::lightMessage(e.what(), 0));
            }
            return;
        }
        prepareOne(frame, chooseForOne(frame));
    }

    // What prepare() refuses, found the same way, with nothing built or changed.
    static void check(const FrameDescription& frame) {
        if (frame.lights.size() >= 2) {
            chooseForLights(frame);
        } else if (frame.lights.size() == 1) {
            detail::setupLights(frame);
            try {
                chooseForOne(detail::withLight(frame, 0));
            } catch (const InvalidInput& e) {
                throw InvalidInput(detail::lightMessage(e.what(), 0));
            }
        } else {
            chooseForOne(frame);
        }
    }

    // A frame's validated setup and its method: everything that can refuse it, before anything is
    // built.
    struct OneLight {
        detail::FrameSetup setup;
        bool touchesView = false;
        detail::MethodChoice choice;
    };
    static OneLight chooseForOne(const FrameDescription& frame) {
        OneLight o{detail::setupFrame(frame)};
        o.touchesView = detail::lightTouchesView(o.setup.camera, o.setup.light, o.setup.medium);
        o.choice = detail::chooseMethod(frame.method, o.setup, o.touchesView);
        if (o.choice.method == Method::BeamTreeAnalytic || o.choice.method == Method::BeamTreeSampling)
            o.setup.beamOccluders = detail::beamOccluders(frame.occluders);
        return o;
    }
    struct SeveralLights {
        std::vector<detail::FrameSetup> setups;
        std::vector<bool> touches;
        bool anyTouches = false;
        detail::MethodChoice choice;
    };
    static SeveralLights chooseForLights(const FrameDescription& frame) {
        SeveralLights l;
        l.setups = detail::setupLights(frame);
        const size_t n = l.setups.size();
        l.choice.method = frame.method;
        if (frame.method == Method::Auto) {
            l.choice.method = Method::Epipolar;
            l.choice.reason = std::to_string(n) + " lights: epipolar sampling per shadowed light";
        } else if (frame.method != Method::Epipolar && frame.method != Method::BruteForce) {
            throw InvalidInput(std::string("lightscatter: method ") + methodName(frame.method) +
                               " renders one light per frame so far; lights holds " +
                               std::to_string(n) +
                               " (use epipolar, brute-force or auto, or one light)");
        }
        l.touches.resize(n);
        for (size_t i = 0; i < n; ++i) {
            const detail::FrameSetup& s = l.setups[i];
            l.touches[i] = detail::lightTouchesView(s.camera, s.light, s.medium);
            l.anyTouches = l.anyTouches || l.touches[i];
            try {
                detail::chooseMethod(l.choice.method, s, l.touches[i]);
            } catch (const InvalidInput& e) {
                throw InvalidInput(
                    detail::lightMessage(e.what(), i, frame.lights[i].settings.has_value()));
            }
        }
        return l;
    }

    static ls::ScatterSpec scatterSpec(const detail::FrameSetup& setup) {
        ls::ScatterSpec spec;
        spec.light = setup.light.kind;
        spec.isotropicMie = setup.medium.isotropicMie;
        spec.hazyMie = setup.medium.hazyMie;
        spec.minMaxTrees = setup.epipolar.minMaxTrees;
        spec.lightColor = setup.lightColor;
        spec.bilinearShadow = setup.epipolar.bilinearShadow;
        spec.simplifiedModel = setup.simplified;
        spec.cubeShadow = setup.shadowed && setup.light.kind == ls::LightKind::Point;
        return spec;
    }

    // One light's constants and shader options.
    static void fillShared(ls::SharedState& s, const detail::FrameSetup& setup) {
        const ls::TableLayout table =
            ls::tableLayoutFor(setup.medium, setup.light.radius, kTableWidth, kTableHeight);
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
        if (!s.spec.cubeShadow) return;
        // Epipolar marches a cube map face by face, each as a spot light's map with its own matrix.
        for (int face = 0; face < 6; ++face) {
            auto& f = s.cubeFaces[face];
            if (!f) f = ls::SharedState::sibling(s);
            f->spec = s.spec;
            f->constants = s.constants;
            f->constants.lightViewProj = s.constants.cubeFaceViewProj[face];
            const bool inView =
                detail::cubeFaceTouchesView(setup.camera, setup.light, setup.medium, face);
            f->constants.cubeFace = {static_cast<float>(face), inView ? 1.0f : 0.0f, 0.0f, 0.0f};
        }
    }

    static ImportState tableState() {
        return {VK_FORMAT_R32G32B32A32_SFLOAT,
                {kTableWidth, kTableHeight},
                VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_SAMPLED_BIT,
                VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
                VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
    }

    // Builds the graph for `c` unless the current one was built for it.
    void ensureGraph(const GraphConfig& c) {
        if (config && *config == c) return;
        // The old graph's memory goes first (the new one may need it); until the new one is
        // complete there is none, so that a failure leaves nothing half-built behind.
        executor.reset();
        config.reset();
        ++graphGeneration;
        FrameGraph built =
            detail::buildFrameGraph(c, shared, slicePlacement, beamFrame, lightShared);
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
        if (!buffer) {
            const rg::ImportedBuffer d = detail::stepCountImport(VK_NULL_HANDLE, config->slices);
            buffer =
                std::make_unique<rg::HostBuffer>(device, d.size, d.usage, "ray-march step counts");
        }
        fg.graph->updateImport(fg.stepCounts,
                               detail::stepCountImport(buffer->buffer(), config->slices));
    }

    std::optional<StepCounts> readStepCounts(uint64_t frame) const {
        const auto& buffer = stepBuffers[frame % kTimedFrames];
        if (!buffer) return std::nullopt;
        const auto sum =
            ls::sumStepCounts(static_cast<const uint32_t*>(buffer->data()), config->slices);
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

    // Several lights: one method for the frame, one chain per light that reaches the view.
    // What every frame's graph takes from the engine and the (first) light's setup: the epipolar
    // sampling, the screen, the engine's images and the debug options.
    void describeFrame(GraphConfig& c, const FrameDescription& frame,
                       const detail::FrameSetup& setup) const {
        c.fixup = setup.epipolar.fixup;
        c.inscatterRefinement = setup.epipolar.inscatterRefinementThreshold > 0.0f;
        c.slices = setup.epipolar.slices;
        c.samples = setup.epipolar.samples;
        c.screen = setup.screen;
        c.depthStencil = depthStencil;
        c.coordinates = coordinates;
        c.depth = state(frame.depth);
        c.color = state(frame.color);
        if (frame.inscatterOut) c.inscatterOut = state(*frame.inscatterOut);
        c.poisonTransients = frame.debug.poisonTransients || poisonFromEnvironment();
        c.countSteps = frame.debug.countSteps && c.method == Method::Epipolar;
        c.reversedZ = setup.camera.reversedZ;
    }

    void prepareLights(const FrameDescription& frame, const SeveralLights& chosen) {
        const std::vector<detail::FrameSetup>& setups = chosen.setups;
        const std::vector<bool>& touches = chosen.touches;
        const detail::MethodChoice& choice = chosen.choice;
        const size_t n = setups.size();
        lastChoice = choice;
        const detail::FrameSetup& first = setups[0];
        GraphConfig c;
        c.method = choice.method;
        c.touchesView = chosen.anyTouches;
        c.extinction = glm::any(glm::greaterThan(first.medium.betaT(), glm::vec3(0.0f)));
        describeFrame(c, frame, first);
        while (lightShared.size() < n) lightShared.push_back(ls::SharedState::sibling(*shared));
        lightTables.resize(std::max(lightTables.size(), n));
        tableRefilled = false;
        for (size_t i = 0; i < n; ++i) {
            const detail::FrameSetup& s = setups[i];
            detail::LightChainConfig l;
            l.light = s.light.kind;
            l.shadowed = s.shadowed;
            l.touchesView = touches[i];
            l.minMaxTrees = s.epipolar.minMaxTrees;
            l.fixup = s.epipolar.fixup;
            l.inscatterRefinement = s.epipolar.inscatterRefinementThreshold > 0.0f;
            l.slices = s.epipolar.slices;
            l.samples = s.epipolar.samples;
            l.shadowMapSize = s.light.shadowMapSize;
            if (frame.lights[i].shadowMap) l.shadowMap = state(*frame.lights[i].shadowMap);
            if (frame.lights[i].lightColor) l.lightColor = state(*frame.lights[i].lightColor);
            fillShared(*lightShared[i], s);
            if (touches[i] && l.light != ls::LightKind::Directional) {
                l.table = tableState();
                if (!lightTables[i])
                    lightTables[i] =
                        std::make_unique<detail::PointTable>(device, kTableWidth, kTableHeight);
                tableRefilled = lightTables[i]->update(lightShared[i]) || tableRefilled;
            }
            c.lights.push_back(l);
        }
        beamFrameBuilt = false;
        noiseMade = false;
        ensureGraph(c);
        fg.graph->updateImport(fg.depth, detail::importDescription(frame.depth));
        fg.graph->updateImport(fg.color, detail::importDescription(frame.color));
        if (fg.inscatterOut.valid())
            fg.graph->updateImport(fg.inscatterOut, detail::importDescription(*frame.inscatterOut));
        for (size_t i = 0; i < n; ++i) {
            const auto& images = fg.lights[i];
            if (images.shadowMap.valid())
                fg.graph->updateImport(images.shadowMap,
                                       detail::importDescription(*frame.lights[i].shadowMap));
            if (images.lightColor.valid())
                fg.graph->updateImport(images.lightColor,
                                       detail::importDescription(*frame.lights[i].lightColor));
            if (images.table.valid())
                fg.graph->updateImport(
                    images.table,
                    detail::persistentImport(c.lights[i].table, lightTables[i]->image()));
        }
        importStepCounter();
        rehearseOnce();
    }

    void prepareOne(const FrameDescription& frame, const OneLight& chosen) {
        const detail::FrameSetup& setup = chosen.setup;
        const bool touchesView = chosen.touchesView;
        const detail::MethodChoice& choice = chosen.choice;

        lastChoice = choice;
        GraphConfig c;
        c.method = choice.method;
        c.light = setup.light.kind;
        c.shadowed = setup.shadowed;
        c.touchesView = touchesView;
        c.extinction = glm::any(glm::greaterThan(setup.medium.betaT(), glm::vec3(0.0f)));
        c.coneSamples = setup.settings.coneSamples;
        c.coneLimited = setup.settings.coneLimited;
        c.coneJitter = setup.settings.coneJitter;
        c.shadowSampling = setup.settings.shadowSampling;
        c.minMaxTrees = setup.epipolar.minMaxTrees;
        describeFrame(c, frame, setup);
        c.shadowMapSize = setup.light.shadowMapSize;
        if (frame.shadowMap) c.shadowMap = state(*frame.shadowMap);
        if (frame.lightColor) c.lightColor = state(*frame.lightColor);
        if (c.method == Method::Slices) {
            c.sliceTarget = detail::sliceAccumulation(setup.settings.sliceTarget);
            c.sliceBlur = setup.settings.sliceBlur;
            c.sliceDither = setup.settings.sliceDither;
            c.noise = setup.noise;
            if (setup.noise && frame.noise) c.engineNoise = state(*frame.noise);
        }
        // Only the table-based nodes (epipolar, brute force, the unshadowed closed form) read it.
        const bool needsTable = c.touchesView && c.light != ls::LightKind::Directional &&
                                (c.method == Method::Epipolar || c.method == Method::BruteForce ||
                                 c.method == Method::BeamTreeAnalytic);
        if (needsTable) c.table = tableState();

        fillShared(*shared, setup);
        if (c.method == Method::Slices) {
            ls::SliceSettings ss;
            ss.planes = setup.settings.slicePlanes;
            ss.planeScaling = setup.settings.slicePlaneScaling;
            ss.eightBitTarget = setup.settings.sliceTarget == SliceTarget::Rgba8Channels;
            ss.range = setup.settings.sliceRange;
            ss.ambient = setup.settings.sliceAmbient;
            ss.noiseAmplitude = setup.settings.noiseAmplitude;
            ss.noiseScale = setup.settings.noiseScale;
            const auto& v = setup.settings.noiseVelocity;
            ss.noiseVelocity = {v[0], v[1], v[2], v[3]};
            *slicePlacement =
                ls::placeSlices(setup.camera, setup.light, setup.medium, ss, setup.timeSeconds);
        }
        beamFrameBuilt = false;
        if ((c.method == Method::BeamTreeAnalytic || c.method == Method::BeamTreeSampling) &&
            c.touchesView) {
            ls::SliceSettings planes;
            planes.planes = setup.settings.slicePlanes;
            *beamFrame = ls::buildBeamTreeFrame(
                setup.camera, setup.light, setup.medium, setup.beamOccluders, planes,
                c.method == Method::BeamTreeSampling ? ls::LitSpace::Planes
                                                     : ls::LitSpace::ClosedForm);
            beamFrameBuilt = true;
            // The triangle buffer grows in powers of two (a rebuild), never shrinks.
            uint32_t capacity = config ? std::max(config->beamCapacity, 3u * 4096u) : 3u * 4096u;
            while (capacity < beamFrame->points.size()) capacity *= 2;
            c.beamCapacity = capacity;
        }
        noiseMade = false;
        if (c.noise && c.engineNoise.format == VK_FORMAT_UNDEFINED) {
            if (!tilingNoise) tilingNoise = std::make_unique<detail::TilingNoise>(device);
            noiseMade = tilingNoise->ensure(shared);
        }
        if (needsTable) {
            if (!pointTable)
                pointTable =
                    std::make_unique<detail::PointTable>(device, kTableWidth, kTableHeight);
            tableRefilled = pointTable->update(shared);
        } else {
            tableRefilled = false;
        }

        ensureGraph(c);
        // This frame's handles and stages; layouts are part of the configuration.
        fg.graph->updateImport(fg.depth, detail::importDescription(frame.depth));
        fg.graph->updateImport(fg.color, detail::importDescription(frame.color));
        if (fg.shadowMap.valid())
            fg.graph->updateImport(fg.shadowMap, detail::importDescription(*frame.shadowMap));
        if (fg.lightColor.valid())
            fg.graph->updateImport(fg.lightColor, detail::importDescription(*frame.lightColor));
        if (fg.inscatterOut.valid())
            fg.graph->updateImport(fg.inscatterOut, detail::importDescription(*frame.inscatterOut));
        if (fg.noise.valid()) {
            if (frame.noise) {
                fg.graph->updateImport(fg.noise, detail::importDescription(*frame.noise));
            } else {
                fg.graph->updateImport(fg.noise, detail::persistentImport(detail::ownNoiseState(),
                                                                          tilingNoise->image()));
            }
        }
        if (fg.table.valid())
            fg.graph->updateImport(fg.table,
                                   detail::persistentImport(c.table, pointTable->image()));
        importStepCounter();
        rehearseOnce();
    }

    // Epipolar marches a point light's cube map face by face, and only the faces that reach the
    // view do work: which ones did, per cube-shadowed light.
    std::string cubeFacesNote() const {
        if (!config || config->method != Method::Epipolar) return {};
        auto faces = [](const ls::SharedState& s) {
            std::string list;
            for (int f = 0; f < 6; ++f)
                if (s.cubeFaces[f] && s.cubeFaces[f]->inView())
                    list += std::string(list.empty() ? "" : ", ") + ls::cubeFaceName(f);
            return list.empty() ? std::string("none") : list;
        };
        std::string note;
        if (config->lights.empty()) {
            if (config->touchesView && shared->spec.cubeShadow)
                note = "; cube faces reaching the view: " + faces(*shared);
        } else {
            for (size_t i = 0; i < config->lights.size(); ++i)
                if (config->lights[i].touchesView && lightShared[i]->spec.cubeShadow)
                    note += "; light " + std::to_string(i) +
                            "'s cube faces reaching the view: " + faces(*lightShared[i]);
        }
        return note.empty() ? note : note + " (the others' passes record no work)";
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
        if (beamFrameBuilt)
            f.cpuWork.push_back({"beam tree (CPU, seed 004)", beamFrame->buildMilliseconds});
        f.method = config && config->touchesView ? methodName(lastChoice.method) : "none";
        f.reason = (lastChoice.reason.empty() ? fg.summary : lastChoice.reason) + cubeFacesNote();
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
    ls::Shared shared;
    VkFormat depthStencil = VK_FORMAT_UNDEFINED;
    VkFormat coordinates = VK_FORMAT_R32G32_SFLOAT;
    std::unique_ptr<detail::PointTable> pointTable;
    bool tableRefilled = false;
    std::unique_ptr<detail::TilingNoise> tilingNoise;
    bool noiseMade = false;
    // Where this frame's slice planes go; the slices nodes read it when they record.
    std::shared_ptr<ls::SlicePlacement> slicePlacement = std::make_shared<ls::SlicePlacement>();
    // This frame's beam tree triangles (beam-tree-analytic); the nodes upload them when they
    // record.
    std::shared_ptr<ls::BeamTreeFrame> beamFrame = std::make_shared<ls::BeamTreeFrame>();
    bool beamFrameBuilt = false;
    // Several lights: each one's constants and options (over `shared`'s pipelines), and each
    // point or spot light's table.
    std::vector<ls::Shared> lightShared;
    std::vector<std::unique_ptr<detail::PointTable>> lightTables;
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
