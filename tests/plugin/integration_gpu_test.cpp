// What an engine integrating the plugin runs into (issue #9): the device contract (features it must
// enable, checked at construction), descriptions that used to pass and misbehave (camera planes
// that disagree with the projection, a zero shadow matrix, impossible layouts, a null command
// buffer), the engine's debug names, and per-frame reports. Every refusal names the field, leaves
// the engine's images as they were and raises no validation message.
#include <cmath>
#include <cstring>
#include <functional>

#include "plugin_fixture.h"
#include "rendergraph/vk_error.h"

using namespace plugin_test;
using lightscatter::Method;

namespace {

FrameSpec spotFrame() {
    FrameSpec s;
    s.screen = {24, 16};
    s.view = defaultView(s.screen);  // a projection for 0.1 .. 50 m
    s.light = spotOverGrille();
    s.medium = fog();
    return s;
}

bool contains(const std::string& text, const std::string& part) {
    return text.find(part) != std::string::npos;
}

// A command pool and command buffers of the engine's own.
class EngineCommands {
  public:
    EngineCommands(const rg::Device& device, uint32_t count) : device_(device) {
        VkCommandPoolCreateInfo info{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
        info.queueFamilyIndex = device.queueFamily();
        RG_VK(vkCreateCommandPool(device.device(), &info, nullptr, &pool_));
        VkCommandBufferAllocateInfo alloc{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
        alloc.commandPool = pool_;
        alloc.commandBufferCount = count;
        cmds_.resize(count);
        RG_VK(vkAllocateCommandBuffers(device.device(), &alloc, cmds_.data()));
    }
    ~EngineCommands() {
        vkQueueWaitIdle(device_.queue());
        vkDestroyCommandPool(device_.device(), pool_, nullptr);
    }
    VkCommandBuffer begin(uint32_t i) {
        VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
        RG_VK(vkBeginCommandBuffer(cmds_[i], &begin));
        return cmds_[i];
    }
    void submitAndWait(uint32_t i) {
        RG_VK(vkEndCommandBuffer(cmds_[i]));
        VkSubmitInfo submit{VK_STRUCTURE_TYPE_SUBMIT_INFO};
        submit.commandBufferCount = 1;
        submit.pCommandBuffers = &cmds_[i];
        RG_VK(vkQueueSubmit(device_.queue(), 1, &submit, VK_NULL_HANDLE));
        RG_VK(vkQueueWaitIdle(device_.queue()));
    }

  private:
    const rg::Device& device_;
    VkCommandPool pool_ = VK_NULL_HANDLE;
    std::vector<VkCommandBuffer> cmds_;
};

}  // namespace

class PluginIntegrationGpu : public PluginGpuTest {
  protected:
    // Expects `change` to make the frame invalid with a message naming `field` (and containing
    // `rule`), and the engine's color to be untouched by the refused call.
    void expectRefused(const std::function<void(lightscatter::FrameDescription&)>& change,
                       const std::string& field, const std::string& rule = "") {
        TestFrame frame(dev(), spotFrame());
        const auto before = frame.color();
        auto desc = frame.description(Method::Epipolar, lightscatter::Profile::Custom,
                                      smallSettings(frame.spec().screen));
        change(desc);
        try {
            plugin().render(desc);
            ADD_FAILURE() << "accepted; expected a refusal naming " << field;
        } catch (const lightscatter::InvalidInput& e) {
            EXPECT_TRUE(contains(e.what(), field)) << e.what();
            EXPECT_TRUE(contains(e.what(), rule)) << e.what();
            EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos)
                << "one line: " << e.what();
        }
        EXPECT_EQ(frame.color(), before) << field;
    }

    std::vector<float> render(const std::function<void(lightscatter::FrameDescription&)>& change) {
        TestFrame frame(dev(), spotFrame());
        auto desc = frame.description(Method::Epipolar, lightscatter::Profile::Custom,
                                      smallSettings(frame.spec().screen));
        change(desc);
        plugin().render(desc);
        return frame.color();
    }
};

// --- The device contract -------------------------------------------------------------------------

TEST_F(PluginIntegrationGpu, TheFeatureChainCreatesADeviceThePluginAccepts) {
    lightscatter::DeviceFeatures features = lightscatter::requiredDeviceFeatures();
    const auto extensions = lightscatter::requiredDeviceExtensions();
    const float priority = 1.0f;
    VkDeviceQueueCreateInfo queue{VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO};
    queue.queueFamilyIndex = dev().queueFamily();
    queue.queueCount = 1;
    queue.pQueuePriorities = &priority;
    VkDeviceCreateInfo info{VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO};
    info.pNext = features.chain();
    info.queueCreateInfoCount = 1;
    info.pQueueCreateInfos = &queue;
    info.enabledExtensionCount = static_cast<uint32_t>(extensions.size());
    info.ppEnabledExtensionNames = extensions.data();
    VkDevice device;
    RG_VK(vkCreateDevice(dev().physical(), &info, nullptr, &device));
    VkQueue q;
    vkGetDeviceQueue(device, dev().queueFamily(), 0, &q);
    EXPECT_NO_THROW(
        lightscatter::Plugin({dev().instance(), dev().physical(), device, q, dev().queueFamily(),
                              features.chain(), dev().instanceApiVersion()}));
    vkDestroyDevice(device, nullptr);
}

// A device made without one feature: the plugin refuses it at construction, naming the feature,
// instead of validation reporting VUID-RuntimeSpirv-LocalSizeId-06434 (maintenance4) or
// VUID-vkResetQueryPool-None-02665 (hostQueryReset) once frames run, and nothing without it.
TEST_F(PluginIntegrationGpu, ADeviceWithoutARequiredFeatureIsRefusedNamingIt) {
    struct Case {
        const char* feature;
        std::function<void(lightscatter::DeviceFeatures&)> drop;
    };
    const Case cases[] = {
        {"maintenance4", [](auto& f) { f.vulkan13.maintenance4 = VK_FALSE; }},
        {"hostQueryReset", [](auto& f) { f.vulkan12.hostQueryReset = VK_FALSE; }},
        {"synchronization2", [](auto& f) { f.vulkan13.synchronization2 = VK_FALSE; }},
        {"shaderStorageImageExtendedFormats",
         [](auto& f) { f.core.features.shaderStorageImageExtendedFormats = VK_FALSE; }},
        {"shaderClipDistance", [](auto& f) { f.core.features.shaderClipDistance = VK_FALSE; }},
        {"fragmentStoresAndAtomics",
         [](auto& f) { f.core.features.fragmentStoresAndAtomics = VK_FALSE; }},
    };
    for (const Case& c : cases) {
        lightscatter::DeviceFeatures features = lightscatter::requiredDeviceFeatures();
        c.drop(features);
        const auto extensions = lightscatter::requiredDeviceExtensions();
        const float priority = 1.0f;
        VkDeviceQueueCreateInfo queue{VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO};
        queue.queueFamilyIndex = dev().queueFamily();
        queue.queueCount = 1;
        queue.pQueuePriorities = &priority;
        VkDeviceCreateInfo info{VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO};
        info.pNext = features.chain();
        info.queueCreateInfoCount = 1;
        info.pQueueCreateInfos = &queue;
        info.enabledExtensionCount = static_cast<uint32_t>(extensions.size());
        info.ppEnabledExtensionNames = extensions.data();
        VkDevice device;
        RG_VK(vkCreateDevice(dev().physical(), &info, nullptr, &device));
        VkQueue q;
        vkGetDeviceQueue(device, dev().queueFamily(), 0, &q);
        try {
            lightscatter::Plugin p({dev().instance(), dev().physical(), device, q,
                                    dev().queueFamily(), features.chain(),
                                    dev().instanceApiVersion()});
            ADD_FAILURE() << "a device without " << c.feature << " was accepted";
        } catch (const lightscatter::InvalidInput& e) {
            EXPECT_TRUE(contains(e.what(), "context.enabledFeatures")) << e.what();
            EXPECT_TRUE(contains(e.what(), c.feature)) << e.what();
        }
        vkDestroyDevice(device, nullptr);
    }
}

TEST_F(PluginIntegrationGpu, AContextWithoutItsFeatureChainIsRefused) {
    const rg::Device& d = dev();
    try {
        lightscatter::Plugin p({d.instance(), d.physical(), d.device(), d.queue(), d.queueFamily(),
                                nullptr, d.instanceApiVersion()});
        ADD_FAILURE() << "a context without enabledFeatures was accepted";
    } catch (const lightscatter::InvalidInput& e) {
        EXPECT_TRUE(contains(e.what(), "context.enabledFeatures is null")) << e.what();
    }
    try {
        lightscatter::Plugin p({d.instance(), d.physical(), VK_NULL_HANDLE, d.queue(),
                                d.queueFamily(), &d.enabledFeatures(), d.instanceApiVersion()});
        ADD_FAILURE() << "a context without a device was accepted";
    } catch (const lightscatter::InvalidInput& e) {
        EXPECT_TRUE(contains(e.what(), "context.device")) << e.what();
    }
}

// --- Camera planes -------------------------------------------------------------------------------

TEST_F(PluginIntegrationGpu, PlanesThatDisagreeWithTheProjectionAreRefused) {
    // The projection is built for 0.1 .. 50 m; 1000 (the old default) would have moved the sky.
    expectRefused([](auto& d) { d.camera.farPlane = 1000.0f; }, "camera.farPlane = 1000",
                  "puts the far plane at 50");
    expectRefused([](auto& d) { d.camera.nearPlane = 0.5f; }, "camera.nearPlane = 0.5",
                  "puts the near plane at 0.1");
    expectRefused([](auto& d) { d.camera.reversedZ = true; }, "camera.reversedZ is true");
    expectRefused([](auto& d) { d.camera.infiniteFar = true; }, "camera.infiniteFar is true");
    // A projection that looks down +Z (left-handed) has no near plane in front of the camera.
    expectRefused([](auto& d) { d.camera.projection[11] = 1.0f; }, "camera.projection");
    // GLM's perspective as it is (clip y up): the shafts would be mirrored top to bottom.
    expectRefused([](auto& d) { d.camera.projection[5] = -d.camera.projection[5]; },
                  "camera.projection maps view-space up to clip y up");
}

TEST_F(PluginIntegrationGpu, PlanesComeFromTheProjection) {
    // Left at 0 they are read from the matrix: the same image as with the right planes given.
    const auto given = render([](auto& d) {
        d.camera.nearPlane = 0.1f;
        d.camera.farPlane = 50.0f;
    });
    const auto derived = render([](auto& d) {
        d.camera.nearPlane = 0.0f;
        d.camera.farPlane = 0.0f;
    });
    ASSERT_EQ(given.size(), derived.size());
    double worst = 0.0, peak = 0.0;
    for (size_t i = 0; i < given.size(); ++i) {
        worst = std::max(worst, std::fabs(double(given[i]) - double(derived[i])));
        peak = std::max(peak, std::fabs(double(given[i])));
    }
    EXPECT_LE(worst, 1e-4 * peak);
}

TEST_F(PluginIntegrationGpu, ReversedAndInfiniteProjectionsAreRecognised) {
    for (const bool reversed : {false, true})
        for (const bool infinite : {false, true}) {
            FrameSpec spec = spotFrame();
            spec.view = lookAt({0.0f, 2.5f, 9.0f}, {0.0f, 1.5f, 0.0f}, 60.0f, 1.5f, 0.1f, 50.0f,
                               reversed, infinite);
            TestFrame frame(dev(), spec);
            auto desc = frame.description(Method::Epipolar, lightscatter::Profile::Custom,
                                          smallSettings(spec.screen));
            desc.camera.nearPlane = desc.camera.farPlane = 0.0f;
            EXPECT_NO_THROW(plugin().render(desc)) << reversed << infinite;
            desc.camera.reversedZ = !reversed;
            EXPECT_THROW(plugin().render(desc), lightscatter::InvalidInput) << reversed << infinite;
        }
}

// --- Other holes ---------------------------------------------------------------------------------

TEST_F(PluginIntegrationGpu, AZeroShadowMatrixIsRefused) {
    expectRefused([](auto& d) { d.light.shadowViewProjection = {}; },
                  "light.shadowViewProjection is singular");
    expectRefused(
        [](auto& d) {
            for (int c = 0; c < 4; ++c)
                d.light.shadowViewProjection[size_t(c * 4 + 2)] = 0.0f;  // no depth row
        },
        "light.shadowViewProjection is singular");
}

TEST_F(PluginIntegrationGpu, LayoutsTheImageCannotHoldAreRefused) {
    expectRefused([](auto& d) { d.depth.layout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL; },
                  "depth.layout COLOR_ATTACHMENT_OPTIMAL", "color layout");
    expectRefused(
        [](auto& d) {
            d.depth.usage = VK_IMAGE_USAGE_SAMPLED_BIT;  // as the engine says it created it
            d.depth.finalLayout = VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL;
        },
        "depth.finalLayout DEPTH_ATTACHMENT_OPTIMAL", "DEPTH_STENCIL_ATTACHMENT usage");
    expectRefused(
        [](auto& d) { d.shadowMap->layout = VK_IMAGE_LAYOUT_DEPTH_STENCIL_READ_ONLY_OPTIMAL; },
        "shadowMap.layout DEPTH_STENCIL_READ_ONLY_OPTIMAL");
    expectRefused([](auto& d) { d.color.layout = VK_IMAGE_LAYOUT_DEPTH_READ_ONLY_OPTIMAL; },
                  "color.layout DEPTH_READ_ONLY_OPTIMAL", "no depth");
    expectRefused([](auto& d) { d.color.finalLayout = VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL; },
                  "color.finalLayout SHADER_READ_ONLY_OPTIMAL", "SAMPLED");
    expectRefused(
        [](auto& d) {
            d.color.usage = VK_IMAGE_USAGE_STORAGE_BIT;
            d.color.layout = VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL;
        },
        "color.layout TRANSFER_DST_OPTIMAL", "TRANSFER_DST");
    expectRefused([](auto& d) { d.depth.layout = VK_IMAGE_LAYOUT_UNDEFINED; },
                  "depth.layout UNDEFINED", "the plugin reads it");
    expectRefused([](auto& d) { d.inscatterOut->finalLayout = VK_IMAGE_LAYOUT_PREINITIALIZED; },
                  "inscatterOut.finalLayout PREINITIALIZED");
}

// volumeOut is froxels' grid: a 3D R16G16B16A16_SFLOAT storage image of froxelVolume()'s extent,
// in a frame whose method is froxels. The refusals come before the handle is touched, so the
// color's stands in for it.
TEST_F(PluginIntegrationGpu, AVolumeOutputTheFrameCannotFillIsRefused) {
    auto volume = [](lightscatter::FrameDescription& d) {
        lightscatter::ImageInput v = d.color;
        v.format = VK_FORMAT_R16G16B16A16_SFLOAT;
        const lightscatter::FroxelVolume grid = lightscatter::froxelVolume(d);
        v.extent = {grid.width, grid.height};
        v.depth = grid.depth;
        d.volumeOut = v;
    };
    expectRefused(volume, "volumeOut is given but the frame runs epipolar", "only froxels");
    expectRefused(
        [&](auto& d) {
            d.method = Method::Froxels;
            volume(d);
            d.volumeOut->depth += 1;
        },
        "volumeOut.extent", "differs from the froxels grid's");
    expectRefused(
        [&](auto& d) {
            d.method = Method::Froxels;
            volume(d);
            d.volumeOut->format = VK_FORMAT_R32G32B32A32_SFLOAT;
        },
        "volumeOut.format R32G32B32A32_SFLOAT", "must be R16G16B16A16_SFLOAT");
    expectRefused(
        [&](auto& d) {
            d.method = Method::Froxels;
            volume(d);
            d.volumeOut->depth = 0;
        },
        "volumeOut.extent", "must not be empty");
    expectRefused(
        [&](auto& d) {
            d.method = Method::Froxels;
            volume(d);
            d.volumeOut->usage = VK_IMAGE_USAGE_SAMPLED_BIT;
        },
        "volumeOut.usage lacks STORAGE");
    expectRefused([](auto& d) { d.color.depth = 2; }, "color.depth = 2", "a 2D image");
}

TEST_F(PluginIntegrationGpu, LayoutsTheImageCanHoldAreAccepted) {
    // A sampled depth image may rest in DEPTH_READ_ONLY_OPTIMAL; Lin alone may start UNDEFINED.
    FrameSpec spec = spotFrame();
    TestFrame frame(dev(), spec);
    TestImage depth(dev(), VK_FORMAT_D32_SFLOAT, spec.screen, VK_IMAGE_USAGE_SAMPLED_BIT,
                    VK_IMAGE_LAYOUT_DEPTH_READ_ONLY_OPTIMAL, "engine depth, read-only layout");
    depth.upload(renderDepth(spec.scene, spec.view, spec.screen.width, spec.screen.height));
    auto desc = frame.description(Method::Epipolar, lightscatter::Profile::Custom,
                                  smallSettings(spec.screen));
    desc.depth = depth.input();
    desc.inscatterOut->layout = VK_IMAGE_LAYOUT_UNDEFINED;
    EXPECT_NO_THROW(plugin().render(desc));
}

TEST_F(PluginIntegrationGpu, RecordingIntoANullCommandBufferIsRefused) {
    TestFrame frame(dev(), spotFrame());
    const auto desc = frame.description(Method::Epipolar, lightscatter::Profile::Custom,
                                        smallSettings(frame.spec().screen));
    try {
        plugin().record(VK_NULL_HANDLE, desc);
        ADD_FAILURE() << "record(VK_NULL_HANDLE) was accepted";
    } catch (const lightscatter::InvalidInput& e) {
        EXPECT_TRUE(contains(e.what(), "record: cmd is VK_NULL_HANDLE")) << e.what();
    }
}

TEST_F(PluginIntegrationGpu, CustomSettingsErrorsNameTheFieldTheEngineSets) {
    expectRefused([](auto& d) { d.custom.epipolar.slices = 30; }, "custom.epipolar.slices = 30");
    TestFrame frame(dev(), spotFrame());
    auto desc = frame.description(Method::Epipolar, lightscatter::Profile::Custom,
                                  smallSettings(frame.spec().screen));
    desc.custom.epipolar.samplesPerSlice = 1;
    try {
        plugin().render(desc);
        ADD_FAILURE() << "accepted";
    } catch (const lightscatter::InvalidInput& e) {
        EXPECT_TRUE(contains(e.what(), "custom.epipolar.samplesPerSlice")) << e.what();
        EXPECT_FALSE(contains(e.what(), "settings.")) << e.what();
    }
}

// The engine's debug names stay: the validation layer, which prints an object's name in its
// messages, still calls the image by the engine's name after the plugin has used it.
TEST_F(PluginIntegrationGpu, TheEnginesDebugNamesAreKept) {
    TestFrame frame(dev(), spotFrame());
    auto desc = frame.description(Method::Epipolar, lightscatter::Profile::Custom,
                                  smallSettings(frame.spec().screen));
    auto setName = reinterpret_cast<PFN_vkSetDebugUtilsObjectNameEXT>(
        vkGetInstanceProcAddr(dev().instance(), "vkSetDebugUtilsObjectNameEXT"));
    ASSERT_NE(setName, nullptr);
    VkDebugUtilsObjectNameInfoEXT name{VK_STRUCTURE_TYPE_DEBUG_UTILS_OBJECT_NAME_INFO_EXT};
    name.objectType = VK_OBJECT_TYPE_IMAGE;
    name.objectHandle = reinterpret_cast<uint64_t>(desc.color.image);
    name.pObjectName = "MyEngine HDR color";
    RG_VK(setName(dev().device(), &name));
    plugin().render(desc);

    // A deliberate misuse the layer reports by naming the image: the subresource layout of an
    // optimally tiled image (the layer skips the call).
    ASSERT_EQ(dev().takeMessages().size(), 0u);
    VkImageSubresource sub{VK_IMAGE_ASPECT_COLOR_BIT, 0, 0};
    VkSubresourceLayout layout;
    vkGetImageSubresourceLayout(dev().device(), desc.color.image, &sub, &layout);
    const auto messages = dev().takeMessages();
    ASSERT_FALSE(messages.empty()) << "the validation layer reported nothing to read the name from";
    for (const auto& m : messages) {
        EXPECT_TRUE(contains(m, "MyEngine HDR color")) << m;
        EXPECT_FALSE(contains(m, "(imported)")) << m;
    }
}

// --- Frames and their reports --------------------------------------------------------------------

TEST_F(PluginIntegrationGpu, EachRecordedFrameHasItsOwnReport) {
    TestFrame frame(dev(), spotFrame());
    const auto desc = frame.description(Method::Epipolar, lightscatter::Profile::Custom,
                                        smallSettings(frame.spec().screen));
    plugin().render(desc);  // the graph for this description exists before the frames below
    EngineCommands engine(dev(), 2);

    // Two frames recorded before either is submitted.
    const uint64_t first = plugin().record(engine.begin(0), desc);
    const uint64_t second = plugin().record(engine.begin(1), desc);
    EXPECT_EQ(second, first + 1);
    EXPECT_EQ(plugin().report().frame, second);  // the last one recorded
    for (uint64_t f : {first, second}) {
        const auto r = plugin().report(f);
        EXPECT_EQ(r.frame, f);
        EXPECT_FALSE(r.timed) << "frame " << f << " has not run yet";
        EXPECT_TRUE(r.passes.empty());
        EXPECT_FALSE(r.passNames.empty());
    }

    engine.submitAndWait(0);
    const auto one = plugin().report(first);
    EXPECT_EQ(one.frame, first);
    EXPECT_TRUE(one.timed);
    EXPECT_FALSE(one.passes.empty());
    EXPECT_FALSE(plugin().report(second).timed) << "frame 2's times are not frame 1's";

    engine.submitAndWait(1);
    const auto two = plugin().report(second);
    EXPECT_EQ(two.frame, second);
    EXPECT_TRUE(two.timed);
    EXPECT_EQ(two.passes.size(), one.passes.size());
    EXPECT_TRUE(plugin().report(first).timed);  // still held
}

TEST_F(PluginIntegrationGpu, ReportsOfFramesNoLongerHeldAreRefused) {
    TestFrame frame(dev(), spotFrame());
    auto desc = frame.description(Method::Epipolar, lightscatter::Profile::Custom,
                                  smallSettings(frame.spec().screen));
    const uint64_t old = plugin().render(desc).frame;
    for (uint64_t i = 0; i < lightscatter::Plugin::kTimedFrames; ++i) plugin().render(desc);
    EXPECT_THROW(plugin().report(old), lightscatter::InvalidInput);
    EXPECT_THROW(plugin().report(0), lightscatter::InvalidInput);
    EXPECT_THROW(plugin().report(plugin().report().frame + 1), lightscatter::InvalidInput);

    // A frame of a graph no longer in use keeps its times (its queries go when it leaves the
    // history, issue #24).
    const lightscatter::FrameReport before = plugin().report();
    desc.custom.epipolar.slices += 4;  // a new graph
    plugin().render(desc);
    const lightscatter::FrameReport again = plugin().report(before.frame);
    EXPECT_TRUE(again.timed);
    EXPECT_EQ(again.passNames, before.passNames);
    ASSERT_EQ(again.passes.size(), before.passes.size());
    for (size_t i = 0; i < again.passes.size(); ++i)
        EXPECT_EQ(again.passes[i].milliseconds, before.passes[i].milliseconds);
}

// Seed 004's occluders: bad boxes are refused naming the occluder, the box and the rule, by the
// methods that read them; the others ignore them (issue #22).
TEST_F(PluginIntegrationGpu, BadOccludersAreRefused) {
    auto one = [](const std::function<void(lightscatter::Occluder&)>& change) {
        return [change](lightscatter::FrameDescription& d) {
            d.method = Method::BeamTreeAnalytic;
            d.occluders.assign(3, lightscatter::Occluder{});
            change(d.occluders[2]);
        };
    };
    expectRefused(one([](auto& o) { o.outer.center[1] = std::nanf(""); }),
                  "occluders[2].outer.center", "non-finite");
    expectRefused(one([](auto& o) { o.outer.halfExtents[0] = -1.0f; }),
                  "occluders[2].outer.halfExtents[0]", "must be > 0");
    expectRefused(one([](auto& o) { o.outer.center[2] = 1e20f; }),
                  "occluders[2].outer.center[2] = 1e+20", "must be within +-1e+08 m");
    expectRefused(one([](auto& o) { o.outer.halfExtents[1] = 3e38f; }),
                  "occluders[2].outer.halfExtents[1]", "must be within +-1e+08 m");
    expectRefused(one([](auto& o) {
                      o.outer.axes[1] = {0.0f, 2.0f, 0.0f};
                  }),
                  "occluders[2].outer.axes[1]", "must be unit");
    expectRefused(one([](auto& o) {
                      o.outer.axes[1] = {1.0f, 0.0f, 0.0f};
                  }),
                  "occluders[2].outer.axes[0] and [1]", "not orthogonal");
    expectRefused(one([](auto& o) {
                      o.inner = lightscatter::OccluderBox{};
                      o.inner->center = {0.3f, 0.0f, 0.0f};  // pokes out of the outer box
                  }),
                  "occluders[2].inner is not inside occluders[2].outer");
    expectRefused(
        [](auto& d) {
            d.method = Method::BeamTreeSampling;
            d.occluders.resize(lightscatter::kMaxOccluders + 1);
        },
        "occluders has 4097 entries", "at most 4096");
    // Epipolar reads no occluder: a bad box changes nothing.
    const auto ignored = render([](auto& d) {
        d.occluders.assign(3, lightscatter::Occluder{});
        d.occluders[2].outer.halfExtents[0] = -1.0f;
    });
    // A good set is accepted (and, with no method reading it yet, changes nothing).
    const auto plain = render([](auto&) {});
    const auto withOccluders = render([](auto& d) {
        d.occluders.assign(2, lightscatter::Occluder{});
        d.occluders[1].outer.center = {0.0f, 0.0f, 3.0f};
        d.occluders[1].inner = lightscatter::OccluderBox{};
        d.occluders[1].inner->center = {0.0f, 0.0f, 3.0f};
        d.occluders[1].inner->halfExtents = {0.25f, 0.25f, 0.25f};
    });
    EXPECT_EQ(plain, withOccluders);
    EXPECT_EQ(plain, ignored);
}
