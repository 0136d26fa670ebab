// The epipolar method against brute force on small scenes, for each shadowed light type.
#include <cstdio>

#include "plugin_fixture.h"

using namespace plugin_test;
using lightscatter::Method;

namespace {

FrameSpec spotSpec() {
    FrameSpec s;
    s.view = defaultView(s.screen);
    s.light = spotOverGrille();
    s.medium = fog();
    return s;
}

}  // namespace

class EpipolarGpu : public PluginGpuTest {};

TEST_F(EpipolarGpu, SpotMatchesBruteForce) {
    TestFrame frame(dev(), spotSpec());
    auto r1 = run(frame, Method::BruteForce);
    const auto brute = frame.inscatter();
    frame.resetColor();
    auto r2 = run(frame, Method::Epipolar);
    const auto epi = frame.inscatter();
    const ErrorStats e = compare(epi, brute);
    std::printf("spot: peak %.4g mean %.4g rms %.4g max %.4g (brute %.1f ms, epipolar %.1f ms)\n",
                e.peak, e.meanRelative, e.rmsRelative, e.maxRelative, r1.totalMilliseconds,
                r2.totalMilliseconds);
    for (const auto& p : r2.passes) std::printf("  %-40s %8.3f ms\n", p.name.c_str(), p.milliseconds);
    for (const auto& p : r1.passes) std::printf("  %-40s %8.3f ms\n", p.name.c_str(), p.milliseconds);
    EXPECT_GT(e.peak, 0.0);
    EXPECT_EQ(e.nonFinite, 0u);
}
