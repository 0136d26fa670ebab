// The plugin in an engine's frame loop (issue #24): the pre-exposure, dynamic resolution within a
// maximum, a lost device, and the version. An engine image made again with the handle of the one
// it replaces is recycled_handle_gpu_test.cpp's; the frame loop itself (frames in flight,
// recording ahead, events, threads) is tests/consumer/frame_loop's.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <vector>

#include "plugin_fixture.h"
#include "support/gpu_test.h"

namespace plugin_test {
namespace {

using lightscatter::Method;
using lightscatter::Profile;

bool contains(const std::string& text, const std::string& part) {
    return text.find(part) != std::string::npos;
}

class FrameLoopGpu : public PluginGpuTest {};

// color = color * exp(-betaT S) + k Lin; inscatterOut keeps Lin unexposed.
TEST_F(FrameLoopGpu, PreExposureScalesLinInTheComposite) {
    TestFrame frame(dev(), sceneWith(spotOverGrille(), {48, 32}));
    auto desc =
        frame.description(Method::BruteForce, Profile::Custom, smallSettings(frame.spec().screen));
    plugin().render(desc);
    const std::vector<float> once = frame.color(), lin = frame.inscatter();
    frame.resetColor();
    desc.preExposure = 4.0f;
    plugin().render(desc);
    const std::vector<float> exposed = frame.color();
    EXPECT_EQ(frame.inscatter(), lin);
    double peak = 0, worst = 0;
    for (size_t i = 0; i < lin.size(); ++i) {
        if (i % 4 == 3) continue;
        peak = std::max(peak, double(lin[i]));
        // The extinguished background is the same in both: the difference is 3 Lin.
        worst = std::max(worst, std::abs(double(exposed[i]) - once[i] - 3.0 * lin[i]));
    }
    ASSERT_GT(peak, 1e-3) << "no light in the frame: the comparison would mean nothing";
    EXPECT_LT(worst, 1e-5 * (1.0 + 4.0 * peak));

    desc.preExposure = -1.0f;
    try {
        plugin().render(desc);
        ADD_FAILURE() << "a negative pre-exposure was accepted";
    } catch (const lightscatter::InvalidInput& e) {
        EXPECT_TRUE(contains(e.what(), "preExposure = -1")) << e.what();
    }
}

// With a maximum render size, frames of any size within it reuse one graph per configuration and
// render exactly what a plugin without a maximum renders at their size.
TEST_F(FrameLoopGpu, DynamicResolutionRendersEverySizeWithinTheMaximumWithOneGraph) {
    lightscatter::PluginCreateInfo info;
    info.context = contextOf(dev());
    info.maxRenderSize = {96, 64};
    lightscatter::Plugin dynamic(info);
    const lightscatter::Settings settings = smallSettings({96, 64});
    for (const Method method : {Method::Epipolar, Method::BruteForce, Method::Planes}) {
        bool first = true;
        for (const VkExtent2D size : {VkExtent2D{64, 48}, VkExtent2D{80, 56}, VkExtent2D{96, 64},
                                      VkExtent2D{48, 32}, VkExtent2D{64, 48}}) {
            SCOPED_TRACE(std::string(lightscatter::methodName(method)) + " at " +
                         std::to_string(size.width) + "x" + std::to_string(size.height));
            TestFrame frame(dev(), sceneWith(spotOverGrille(), size));
            const auto desc = frame.description(method, Profile::Custom, settings);
            const lightscatter::FrameReport r = dynamic.render(desc);
            EXPECT_EQ(r.graphCompiled, first);
            first = false;
            const std::vector<float> color = frame.color(), lin = frame.inscatter();
            frame.resetColor();
            plugin().render(desc);
            EXPECT_EQ(color, frame.color());
            EXPECT_EQ(lin, frame.inscatter());
        }
    }
    TestFrame tooLarge(dev(), sceneWith(spotOverGrille(), {128, 64}));
    try {
        dynamic.render(tooLarge.description(Method::Epipolar, Profile::Custom, settings));
        ADD_FAILURE() << "a frame larger than maxRenderSize was accepted";
    } catch (const lightscatter::InvalidInput& e) {
        EXPECT_TRUE(contains(e.what(), "depth.extent 128x64")) << e.what();
        EXPECT_TRUE(contains(e.what(), "maxRenderSize 96x64")) << e.what();
    }
}

// An interposer on the loader that makes chosen calls report a lost device, as a driver does once
// the GPU is gone.
struct LostDevice {
    static inline PFN_vkGetInstanceProcAddr loader = nullptr;
    static inline PFN_vkGetDeviceProcAddr deviceLoader = nullptr;
    static inline PFN_vkWaitForFences waitForFences = nullptr;
    static inline PFN_vkGetQueryPoolResults queryResults = nullptr;
    static inline bool lost = false;

    static VKAPI_ATTR VkResult VKAPI_CALL wait(VkDevice d, uint32_t n, const VkFence* f,
                                               VkBool32 all, uint64_t timeout) {
        const VkResult r = waitForFences(d, n, f, all, timeout);
        return lost ? VK_ERROR_DEVICE_LOST : r;
    }
    static VKAPI_ATTR VkResult VKAPI_CALL results(VkDevice d, VkQueryPool pool, uint32_t first,
                                                  uint32_t count, size_t size, void* data,
                                                  VkDeviceSize stride, VkQueryResultFlags flags) {
        const VkResult r = queryResults(d, pool, first, count, size, data, stride, flags);
        return lost ? VK_ERROR_DEVICE_LOST : r;
    }
    static PFN_vkVoidFunction swap(const char* name, PFN_vkVoidFunction real) {
        if (!std::strcmp(name, "vkWaitForFences")) {
            waitForFences = reinterpret_cast<PFN_vkWaitForFences>(real);
            return reinterpret_cast<PFN_vkVoidFunction>(&wait);
        }
        if (!std::strcmp(name, "vkGetQueryPoolResults")) {
            queryResults = reinterpret_cast<PFN_vkGetQueryPoolResults>(real);
            return reinterpret_cast<PFN_vkVoidFunction>(&results);
        }
        if (!std::strcmp(name, "vkGetDeviceProcAddr")) {
            deviceLoader = reinterpret_cast<PFN_vkGetDeviceProcAddr>(real);
            return reinterpret_cast<PFN_vkVoidFunction>(&getDeviceProcAddr);
        }
        return real;
    }
    static VKAPI_ATTR PFN_vkVoidFunction VKAPI_CALL getDeviceProcAddr(VkDevice d, const char* n) {
        return swap(n, deviceLoader(d, n));
    }
    static VKAPI_ATTR PFN_vkVoidFunction VKAPI_CALL getInstanceProcAddr(VkInstance i,
                                                                        const char* n) {
        return swap(n, loader(i, n));
    }
};

// A lost device is a DeviceError naming the call, from render() and from report(); the plugin is
// then destroyed without a word from the layer.
TEST_F(FrameLoopGpu, ALostDeviceIsADeviceErrorAndThePluginIsStillDestroyed) {
    LostDevice::loader = vkGetInstanceProcAddr;
    LostDevice::lost = false;
    lightscatter::PluginCreateInfo info;
    info.context = contextOf(dev());
    info.getInstanceProcAddr = &LostDevice::getInstanceProcAddr;
    {
        lightscatter::Plugin lost(info);
        TestFrame frame(dev(), sceneWith(spotOverGrille(), {48, 32}));
        const auto desc =
            frame.description(Method::Epipolar, Profile::Custom, smallSettings({48, 32}));
        const uint64_t done = lost.render(desc).frame;
        LostDevice::lost = true;
        try {
            lost.report(done);
            ADD_FAILURE() << "report() of a lost device returned";
        } catch (const lightscatter::DeviceError& e) {
            EXPECT_TRUE(contains(e.what(), "vkGetQueryPoolResults")) << e.what();
            EXPECT_TRUE(contains(e.what(), "VK_ERROR_DEVICE_LOST")) << e.what();
        }
        try {
            lost.render(desc);
            ADD_FAILURE() << "render() on a lost device returned";
        } catch (const lightscatter::DeviceError& e) {
            EXPECT_TRUE(contains(e.what(), "vkWaitForFences")) << e.what();
            EXPECT_TRUE(contains(e.what(), "VK_ERROR_DEVICE_LOST")) << e.what();
        }
        // This device is not lost: what render() submitted runs to its end before the plugin
        // goes, as a lost device's work never would.
        vkQueueWaitIdle(dev().queue());
    }
    LostDevice::lost = false;
}

TEST(FrameLoop, TheLibraryIsTheHeadersVersion) {
    const lightscatter::Version v = lightscatter::version();
    EXPECT_EQ(v.major, uint32_t{LIGHTSCATTER_VERSION_MAJOR});
    EXPECT_EQ(v.minor, uint32_t{LIGHTSCATTER_VERSION_MINOR});
    EXPECT_EQ(v.patch, uint32_t{LIGHTSCATTER_VERSION_PATCH});
    static_assert(
        std::is_same_v<lightscatter::Plugin::HeaderVersion, lightscatter::HeaderVersion_0_6>);
}

}  // namespace
}  // namespace plugin_test
