// Dynamic resolution as engines do it: the engine's images have the maximum size, and each frame
// renders into a top-left rectangle of them (ImageInput::extent the frame's). What lies outside the
// rectangle is the engine's: no method may write it, in the color or in inscatterOut.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "plugin_fixture.h"
#include "support/gpu_test.h"

namespace plugin_test {
namespace {

using lightscatter::Method;
using lightscatter::Profile;

constexpr VkExtent2D kImages{96, 64};

// The grille under the spot, shadowed for every method that casts shadows.
FrameSpec sceneFor(const lightscatter::MethodInfo& method, VkExtent2D screen) {
    FrameSpec spec = sceneWith(spotOverGrille(), screen);
    spec.shadowed = method.shadowMap;
    return spec;
}

// Pixels of `after` outside the top-left `frame` rectangle that differ from `before` (RGBA rows of
// kImages.width), and pixels inside it that changed at all.
struct Changes {
    size_t outside = 0, inside = 0;
};
Changes changes(const std::vector<float>& before, const std::vector<float>& after,
                VkExtent2D frame) {
    Changes c;
    for (uint32_t y = 0; y < kImages.height; ++y)
        for (uint32_t x = 0; x < kImages.width; ++x) {
            const size_t i = (size_t{y} * kImages.width + x) * 4;
            bool differs = false;
            for (size_t k = 0; k < 4; ++k) differs |= before[i + k] != after[i + k];
            if (!differs) continue;
            if (x < frame.width && y < frame.height)
                ++c.inside;
            else
                ++c.outside;
        }
    return c;
}

class DynamicResolutionGpu : public PluginGpuTest {};

// Every method, at frame sizes that are not multiples of any method's tile or workgroup, after a
// frame of the full size (the case: rows between a small frame's height and the next
// multiple of 8 were composited again).
TEST_F(DynamicResolutionGpu, NoMethodWritesOutsideTheFrame) {
    lightscatter::PluginCreateInfo info;
    info.context = contextOf(dev());
    info.maxRenderSize = kImages;
    const lightscatter::Settings settings = smallSettings(kImages);
    for (const lightscatter::MethodInfo& about : lightscatter::methodInfo()) {
        const Method method = about.method;
        TestFrame frame(dev(), sceneFor(about, kImages));
        lightscatter::Plugin dynamic(info);
        for (const VkExtent2D size : {kImages, VkExtent2D{61, 37}, VkExtent2D{45, 29}}) {
            SCOPED_TRACE(std::string(lightscatter::methodName(method)) + " at " +
                         std::to_string(size.width) + "x" + std::to_string(size.height));
            auto desc = frame.description(method, Profile::Custom, settings);
            desc.depth.extent = desc.color.extent = desc.inscatterOut->extent = size;
            const std::vector<float> color = frame.color(), lin = frame.inscatter();
            dynamic.render(desc);
            const Changes inColor = changes(color, frame.color(), size);
            const Changes inLin = changes(lin, frame.inscatter(), size);
            EXPECT_EQ(inColor.outside, 0u) << "pixels of the engine's color outside the frame";
            EXPECT_EQ(inLin.outside, 0u) << "pixels of inscatterOut outside the frame";
            // The frame itself was rendered (a test that wrote nothing would pass the above).
            EXPECT_GT(inColor.inside, size_t{size.width} * size.height / 2);
        }
    }
}

// What a maximum render size changes in a frame: nothing but rounding. A frame smaller than the
// maximum renders what a plugin without one renders at its size (froxels' grid has the maximum's
// columns, and the frame reads only its own).
TEST_F(DynamicResolutionGpu, AFrameWithinTheMaximumRendersAsAtItsOwnSize) {
    lightscatter::PluginCreateInfo info;
    info.context = contextOf(dev());
    info.maxRenderSize = kImages;
    const lightscatter::Settings settings = smallSettings(kImages);
    for (const lightscatter::MethodInfo& about : lightscatter::methodInfo()) {
        const Method method = about.method;
        lightscatter::Plugin dynamic(info);
        for (const VkExtent2D size : {VkExtent2D{61, 37}, VkExtent2D{80, 56}}) {
            SCOPED_TRACE(std::string(lightscatter::methodName(method)) + " at " +
                         std::to_string(size.width) + "x" + std::to_string(size.height));
            TestFrame frame(dev(), sceneFor(about, size));
            const auto desc = frame.description(method, Profile::Custom, settings);
            dynamic.render(desc);
            const std::vector<float> color = frame.color(), lin = frame.inscatter();
            frame.resetColor();
            plugin().render(desc);
            const std::vector<float> again = frame.color(), linAgain = frame.inscatter();
            if (method != Method::Froxels) {
                EXPECT_EQ(color, again);
                EXPECT_EQ(lin, linAgain);
                continue;
            }
            // Froxels' grid has the maximum's columns and rows, so the sampler's normalised
            // coordinates differ by rounding from a grid of the frame's size: equal to a float's
            // last bits. (Before, the frame's last half column blended with the column beyond the
            // frame: up to 2e-3 off, 7% of small values.)
            double peak = 0, worst = 0;
            for (size_t i = 0; i < color.size(); ++i) {
                if (i % 4 == 3) continue;
                peak = std::max({peak, double(std::abs(lin[i])), double(std::abs(color[i]))});
                worst = std::max({worst, double(std::abs(color[i] - again[i])),
                                  double(std::abs(lin[i] - linAgain[i]))});
            }
            ASSERT_GT(peak, 1e-3);
            EXPECT_LE(worst, 1e-6 * peak);
        }
    }
}

}  // namespace
}  // namespace plugin_test
