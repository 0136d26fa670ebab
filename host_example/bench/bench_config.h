#pragma once
// What a benchmark runs: scenes x configurations (methods, profiles, and one-parameter sweeps from
// the balanced profile, or the config's sweepProfile), read from a JSON file (bench/*.json).
#include <optional>
#include <string>
#include <vector>

#include <lightscatter/lightscatter.h>
#include <vulkan/vulkan.h>
#include "motion.h"

namespace host::bench {

struct BenchRun {
    std::string scene;  // path of SCENE.json
    std::string label;  // e.g. "epipolar balanced", "epipolar.slices=512"
    // "profiles", "configurations" (or a configuration's own "family"), or a sweep's key as
    // written: "shadowMapSize", "size", a settings field ("epipolar.slices", "samplesPerSlice")
    std::string family;
    lightscatter::Method method = lightscatter::Method::Epipolar;
    lightscatter::Profile profile = lightscatter::Profile::Balanced;
    // Used as Custom when custom is true; its froxel grid (a preset's) with every profile.
    lightscatter::Settings settings;
    bool custom = false;
    VkExtent2D size{0, 0};
    uint32_t shadowMapSize = 0;  // 0: the scene's
    // "profileShadowMap": the shadow map's size for a shadowed scene, from the profile that
    // decides it (shadowMapFrom names it: epipolar's own profile, the largest of the
    // configuration's profiles for the other methods, as seed 000's brute force ran at the
    // high-quality map); 0: the scene's.
    uint32_t profileShadowMap = 0;
    std::string shadowMapFrom;
    bool measureError = false;  // at the config's error size only (the reference is slow)
    int round = 0;              // "profileOrder"'s rounds: which one, from 0
};

// "profileOrder": epipolar's profile runs repeated at each of `sizes`, and after the benchmark each
// profile of a chain (high-quality, balanced, high-performance; low-high-quality, low-balanced,
// low-high-performance) checked no slower than the one before it, within `tolerance`
// (profile_order.h). With `rounds`, each scene's profile runs are repeated that many times in
// turn, and a profile's time is the median of its rounds' medians.
struct ProfileOrder {
    std::vector<VkExtent2D> sizes;
    double tolerance = 0.05;
    int rounds = 1;
};

struct BenchConfig {
    std::string name;
    int frames = 10;
    int warmup = 3;
    VkExtent2D size{480, 270};  // where errors are measured
    bool measureError =
        true;  // false: timings only, no float64 reference (e.g. 1080p, many objects)
    std::vector<std::string> scenes;
    std::vector<BenchRun> runs;  // expanded
    // The temporal-stability mode: every run that measures error renders the motion's frames
    // (for each motion in turn) instead of `frames` still ones, and is judged against the
    // reference at every pose.
    std::optional<Motion> motion;
    std::optional<ProfileOrder> profileOrder;
};

// Throws std::runtime_error naming the file and field.
BenchConfig loadBenchConfig(const std::string& path, const std::string& projectRoot);

}  // namespace host::bench
