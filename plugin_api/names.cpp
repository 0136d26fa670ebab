// Method and profile names (the command line's contract) and the seed's quality profiles.
#include "lightscatter.h"

namespace lightscatter {
namespace {

struct ProfileRow {
    Profile profile;
    const char* name;
    uint32_t slices, samples, shadowMap;
};

// Seed 000, "Performance": 2560x1600 on a GeForce GTX 680 and the smaller set used on a Quadro 1000M
// and Intel HD Graphics.
constexpr ProfileRow kProfiles[] = {
    {Profile::HighQuality, "high-quality", 2048, 1024, 4096},
    {Profile::Balanced, "balanced", 1024, 1024, 2048},
    {Profile::HighPerformance, "high-performance", 1024, 512, 1024},
    {Profile::LowHighQuality, "low-high-quality", 1024, 1024, 2048},
    {Profile::LowBalanced, "low-balanced", 512, 512, 1024},
    {Profile::LowHighPerformance, "low-high-performance", 512, 256, 512},
    {Profile::Custom, "custom", 1024, 1024, 2048},
};

constexpr std::pair<Method, const char*> kMethods[] = {
    {Method::Epipolar, "epipolar"},
    {Method::BruteForce, "brute-force"},
    {Method::Analytic, "analytic"},
    {Method::ConeMarch, "cone-march"},
    {Method::Auto, "auto"},
};

}  // namespace

const char* methodName(Method m) {
    for (const auto& [method, name] : kMethods)
        if (method == m) return name;
    return "unknown";
}

const char* profileName(Profile p) {
    for (const auto& row : kProfiles)
        if (row.profile == p) return row.name;
    return "unknown";
}

std::optional<Method> parseMethod(const std::string& name) {
    for (const auto& [method, n] : kMethods)
        if (name == n) return method;
    return std::nullopt;
}

std::optional<Profile> parseProfile(const std::string& name) {
    for (const auto& row : kProfiles)
        if (name == row.name) return row.profile;
    return std::nullopt;
}

std::vector<std::string> methodNames() {
    std::vector<std::string> v;
    for (const auto& [method, name] : kMethods) v.emplace_back(name);
    return v;
}

std::vector<std::string> profileNames() {
    std::vector<std::string> v;
    for (const auto& row : kProfiles) v.emplace_back(row.name);
    return v;
}

Settings profileSettings(Profile profile) {
    Settings s;
    for (const auto& row : kProfiles) {
        if (row.profile != profile) continue;
        s.slices = row.slices;
        s.samplesPerSlice = row.samples;
        s.shadowMapSize = row.shadowMap;
    }
    return s;
}

std::vector<const char*> requiredDeviceExtensions() { return {VK_KHR_PUSH_DESCRIPTOR_EXTENSION_NAME}; }

}  // namespace lightscatter
