// Lin is linear in the light's intensity however bright the light: every method leaves Lin to the
// composite in a screen texture, float16 for most (at most 65504), and a frame whose Lin can be
// brighter stores it scaled by a power of two (plugin_api/src/lin_storage.h) instead of clamped.
#include <cmath>

#include "plugin_fixture.h"

using namespace plugin_test;
using lightscatter::Method;

namespace {

constexpr VkExtent2D kStorageScreen{16, 16};
constexpr float kBright = 1e9f;  // W/sr or W/m^2: lightscatter.h's largest intensity

struct StorageCase {
    const char* name;
    FrameSpec spec;
    std::vector<Method> methods;
};

std::vector<StorageCase> storageCases() {
    lightscatter::Light point;
    point.type = lightscatter::LightType::Point;
    point.position = {0.5f, 2.0f, 1.0f};
    std::vector<StorageCase> c{
        {"sun",
         sceneWith(sunThroughGrille(), kStorageScreen),
         {Method::Epipolar, Method::BruteForce, Method::ConeMarch, Method::Planes}},
        {"spot",
         sceneWith(spotOverGrille(), kStorageScreen),
         {Method::Epipolar, Method::BruteForce, Method::ConeMarch, Method::Planes,
          Method::BeamTreeAnalytic, Method::BeamTreeSampling}},
        {"unshadowed spot",
         sceneWith(spotOverGrille(), kStorageScreen),
         {Method::Analytic, Method::BeamTreeAnalytic}},
        {"point",
         sceneWith(point, kStorageScreen),
         {Method::Epipolar, Method::BruteForce, Method::Analytic, Method::ConeMarch,
          Method::Planes}},
    };
    c[2].spec.shadowed = false;
    c[3].spec.shadowed = false;
    for (StorageCase& k : c) {
        k.spec.light.intensity = {1.0f, 1.0f, 1.0f};
        k.spec.light.shadowMapSize = 64;
    }
    return c;
}

}  // namespace

class LinStorageGpu : public PluginGpuTest {};

TEST_F(LinStorageGpu, ABrightLightsLinIsScaledNotClamped) {
    for (const StorageCase& k : storageCases()) {
        TestFrame frame(dev(), k.spec);
        for (Method method : k.methods) {
            lightscatter::Settings s = smallSettings(kStorageScreen);
            s.shadowMapSize = 64;
            s.planes.count = 32;
            auto d = frame.description(method, lightscatter::Profile::Custom, s);
            plugin().render(d);
            const std::vector<float> unit = frame.inscatter();
            d.light.intensity = {kBright, kBright, kBright};
            frame.resetColor();
            plugin().render(d);
            const std::vector<float> bright = frame.inscatter();
            float peak = 0.0f, worst = 0.0f;
            for (size_t i = 0; i < unit.size(); ++i)
                if (i % 4 != 3) peak = std::max(peak, unit[i]);
            for (size_t i = 0; i < unit.size(); ++i)
                if (i % 4 != 3) worst = std::max(worst, std::fabs(bright[i] / kBright - unit[i]));
            EXPECT_GT(peak, 0.0f) << k.name << ", " << lightscatter::methodName(method);
            // float16 keeps 11 bits, and the planes add up in it: 1% of the peak (a clamped
            // Lin is off by orders of magnitude).
            EXPECT_LE(worst, 1e-2f * peak)
                << k.name << ", " << lightscatter::methodName(method)
                << ": Lin at 1e9 W/sr is not 1e9 times Lin at 1 W/sr (peak " << peak << ")";
        }
    }
}
