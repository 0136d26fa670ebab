// The camera's near plane and field of view at the limits lightscatter.h states, against the
// float64 model: inside them every method renders as it does with an ordinary camera; beyond
// them the frame is refused naming camera.projection. lightscatter.h's limits cite the
// measurements these bounds hold (32x18, unshadowed lights; mean relative error of Lin).
#include <cmath>
#include <cstdio>

#include "model_conversion.h"
#include "plugin_fixture.h"

using namespace plugin_test;
using lightscatter::Method;
namespace limits = lightscatter::limits;

namespace {

constexpr VkExtent2D kLimitsScreen{32, 18};
const glm::vec3 kEye{0.0f, 2.5f, 9.0f}, kTarget{0.0f, 1.5f, 0.0f};

// sum |a - b| / sum |b| over every channel; non-finite values fail it.
double meanRelative(const std::vector<float>& got, const std::vector<float>& want) {
    double diff = 0, sum = 0;
    for (size_t i = 0; i < want.size(); ++i) {
        if (i % 4 == 3) continue;
        if (!std::isfinite(got[i])) return 1e30;
        diff += std::fabs(got[i] - want[i]);
        sum += std::fabs(want[i]);
    }
    return sum > 0 ? diff / sum : 1e30;
}

// The error each method is allowed here: its error with an ordinary camera, with room. planes
// samples at its planes' midpoints (measured 0.035 to 0.064 on these frames).
double bound(Method m) {
    return m == Method::Planes ? 0.1 : 2e-3;
}

const Method kMethods[] = {Method::BruteForce, Method::Epipolar, Method::ConeMarch, Method::Planes};

FrameSpec unshadowed(lightscatter::Light light, const View& view) {
    FrameSpec s = sceneWith(light, kLimitsScreen);
    s.shadowed = false;
    s.view = view;
    return s;
}

}  // namespace

class CameraLimitsGpu : public PluginGpuTest {
  protected:
    void expectAccurate(const FrameSpec& spec, const std::string& what) {
        TestFrame frame(dev(), spec);
        const std::vector<float> want = float64Unshadowed(frame);
        for (Method method : kMethods) {
            plugin().render(frame.description(method, lightscatter::Profile::Custom,
                                              smallSettings(kLimitsScreen)));
            const double e = meanRelative(frame.inscatter(), want);
            std::printf("%-40s %-12s %.4f\n", what.c_str(), lightscatter::methodName(method), e);
            EXPECT_LE(e, bound(method)) << what << ", " << lightscatter::methodName(method);
        }
    }
    void expectRefused(const FrameSpec& spec, const std::string& fragment) {
        TestFrame frame(dev(), spec);
        try {
            plugin().render(frame.description(Method::BruteForce, lightscatter::Profile::Custom,
                                              smallSettings(kLimitsScreen)));
            ADD_FAILURE() << "accepted; expected a refusal saying " << fragment;
        } catch (const lightscatter::InvalidInput& e) {
            const std::string m = e.what();
            EXPECT_NE(m.find("camera.projection"), std::string::npos) << m;
            EXPECT_NE(m.find(fragment), std::string::npos) << m;
        }
    }
};

// Reversed depth stores near / distance, which float32 resolves for any near plane down to
// limits::kMinNearPlane. Before the camera's rays were made from the projection's rows, near 1e-8
// m gave an error of 1.0 (black) with every method, and 1e-5 m 0.24.
TEST_F(CameraLimitsGpu, ATinyNearPlaneWithReversedDepthRendersCorrectly) {
    const float aspect = float(kLimitsScreen.width) / float(kLimitsScreen.height);
    for (bool infinite : {false, true})
        for (float nearPlane : {1e-8f, limits::kMinNearPlane}) {
            const View view =
                lookAt(kEye, kTarget, 60.0f, aspect, nearPlane, 50.0f, true, infinite);
            expectAccurate(unshadowed(spotOverGrille(), view),
                           std::string(infinite ? "reversed infinite" : "reversed") + ", near " +
                               std::to_string(nearPlane));
        }
    const View tooNear = lookAt(kEye, kTarget, 60.0f, aspect, 1e-30f, 50.0f, true, true);
    expectRefused(unshadowed(spotOverGrille(), tooNear), "must be at least 1e-29 m");
}

// Standard depth steps by 2^-24 near 1: the far plane (or the sky) may be at most 2^20 times the
// near plane. Near 1e-8 m with a far plane of 50 m collapses everything beyond 0.17 m onto depth 1,
// and a float32 projection cannot even hold that far plane (it rounds to an infinite one).
TEST_F(CameraLimitsGpu, StandardDepthRefusesANearPlaneItCannotResolve) {
    const float aspect = float(kLimitsScreen.width) / float(kLimitsScreen.height);
    expectRefused(unshadowed(spotOverGrille(), lookAt(kEye, kTarget, 60.0f, aspect, 1e-8f, 50.0f)),
                  "cannot hold a far plane more than about 2^24 times its near plane, 1e-08 m");
    expectRefused(unshadowed(spotOverGrille(), lookAt(kEye, kTarget, 60.0f, aspect, 1e-5f, 50.0f)),
                  "with standard depth a D32_SFLOAT depth buffer steps by 2^-24");
    FrameSpec sky = unshadowed(spotOverGrille(),
                               lookAt(kEye, kTarget, 60.0f, aspect, 1e-5f, 50.0f, false, true));
    expectRefused(sky, "the sky (medium.maxDistance) at 60 m");
    // Within the ratio, it renders as an ordinary camera does.
    expectAccurate(unshadowed(spotOverGrille(), lookAt(kEye, kTarget, 60.0f, aspect, 1e-4f, 50.0f)),
                   "standard, near 1e-4");
}

// A sun lights every pixel, so every ray is judged.
TEST_F(CameraLimitsGpu, TheFieldOfViewWithinItsLimitsRendersCorrectly) {
    const float aspect = float(kLimitsScreen.width) / float(kLimitsScreen.height);
    for (float fov : {limits::kMinFovDegrees, 1.0f, 170.0f}) {
        const View view = lookAt(kEye, kTarget, fov, aspect, 0.1f, 50.0f);
        expectAccurate(unshadowed(sunThroughGrille(), view), "fov " + std::to_string(fov));
    }
    // 177 degrees across (the widest), 30 up and down.
    const float across =
        std::tan(glm::radians(limits::kMaxFovDegrees) / 2.0f) / std::tan(glm::radians(15.0f));
    expectAccurate(
        unshadowed(sunThroughGrille(), lookAt(kEye, kTarget, 30.0f, across, 0.1f, 50.0f)),
        "fov 177 across");
    expectRefused(
        unshadowed(sunThroughGrille(), lookAt(kEye, kTarget, 1e-20f, aspect, 0.1f, 50.0f)),
        "degrees across (from P[0][0]): must be in [0.0001, 177]");
    expectRefused(unshadowed(sunThroughGrille(), lookAt(kEye, kTarget, 178.0f, 1.0f, 0.1f, 50.0f)),
                  "field of view of 178 degrees across");
}
