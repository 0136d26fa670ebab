// Method and profile names (the command line's contract) and the seed's quality profiles.
#include <lightscatter/lightscatter.h>
#include "method_units.h"
#include "registry/method_registry.h"
#include "settings_checks.h"

namespace lightscatter {
namespace {

constexpr const char* kAutoName = "auto";

// Names a method had before, still parsed so that command lines and files written with them keep
// working; methodName() and methodNames() give only the current ones. "slices" was the planes
// method's name until "slice" came to mean only an epipolar line.
struct FormerName {
    const char* name;
    Method method;
};
constexpr FormerName kFormerNames[] = {{"slices", Method::Planes}};

struct ProfileRow {
    Profile profile;
    const char* name;
    uint32_t slices, samples, shadowMap;
    uint32_t planes;  // the planes method (seed 002)
    PlaneTarget planeTarget;
};

// Seed 000, "Performance": 2560x1600 on a GeForce GTX 680 and the smaller set used on a Quadro
// 1000M and Intel HD Graphics. The plane counts are ours (docs/methods.md); high-performance is
// seed 002's own configuration, 100 planes into the four channels of an 8-bit target.
constexpr PlaneTarget kF16 = PlaneTarget::Float16, kF32 = PlaneTarget::Float32,
                      kRgba8 = PlaneTarget::Rgba8Channels;
constexpr ProfileRow kProfiles[] = {
    {Profile::HighQuality, "high-quality", 2048, 1024, 4096, 256, kF32},
    {Profile::Balanced, "balanced", 1024, 1024, 2048, 128, kF16},
    {Profile::HighPerformance, "high-performance", 1024, 512, 1024, 100, kRgba8},
    {Profile::LowHighQuality, "low-high-quality", 1024, 1024, 2048, 128, kF16},
    {Profile::LowBalanced, "low-balanced", 512, 512, 1024, 64, kF16},
    {Profile::LowHighPerformance, "low-high-performance", 512, 256, 512, 48, kRgba8},
    {Profile::Custom, "custom", 1024, 1024, 2048, 128, kF16},
};

}  // namespace

namespace detail {

const ls::MethodUnit* methodUnit(Method m) {
    const auto& all = ls::methodRegistry();
    const auto i = static_cast<size_t>(m);
    return i < all.size() ? all[i] : nullptr;
}

}  // namespace detail

const char* methodName(Method m) {
    const ls::MethodUnit* unit = detail::methodUnit(m);
    return unit ? unit->name() : m == Method::Auto ? kAutoName : "unknown";
}

const char* profileName(Profile p) {
    for (const auto& row : kProfiles)
        if (row.profile == p) return row.name;
    return "unknown";
}

std::optional<Method> parseMethod(const std::string& name) {
    if (name == kAutoName) return Method::Auto;
    const auto& all = ls::methodRegistry();
    for (size_t i = 0; i < all.size(); ++i)
        if (name == all[i]->name()) return static_cast<Method>(i);
    for (const auto& former : kFormerNames)
        if (name == former.name) return former.method;
    return std::nullopt;
}

std::optional<Profile> parseProfile(const std::string& name) {
    for (const auto& row : kProfiles)
        if (name == row.name) return row.profile;
    return std::nullopt;
}

std::vector<std::string> methodNames() {
    std::vector<std::string> v;
    for (const ls::MethodUnit* m : ls::methodRegistry()) v.emplace_back(m->name());
    v.emplace_back(kAutoName);
    return v;
}

std::vector<std::string> profileNames() {
    std::vector<std::string> v;
    for (const auto& row : kProfiles) v.emplace_back(row.name);
    return v;
}

Settings profileSettings(Profile profile) {
    return detail::withProfileSizes(Settings{}, profile);
}

Settings detail::withProfileSizes(Settings s, Profile profile) {
    if (profile == Profile::Custom) return s;
    for (const auto& row : kProfiles) {
        if (row.profile != profile) continue;
        s.slices = row.slices;
        s.samplesPerSlice = row.samples;
        s.shadowMapSize = row.shadowMap;
        s.planeCount = row.planes;
        s.planeTarget = row.planeTarget;
    }
    return s;
}

std::vector<FroxelPreset> froxelPresets() {
    return {{"froxels-hdrp", 8, 64}, {"froxels-unreal", 16, 64}};
}

bool applyFroxelPreset(const std::string& name, Settings& s) {
    const std::string suffix = "-temporal";
    const bool temporal = name.size() > suffix.size() &&
                          name.compare(name.size() - suffix.size(), suffix.size(), suffix) == 0;
    const std::string preset = temporal ? name.substr(0, name.size() - suffix.size()) : name;
    for (const FroxelPreset& p : froxelPresets())
        if (preset == p.name) {
            s.froxelTile = p.tile;
            s.froxelSlices = p.slices;
            s.froxelTemporal = temporal;
            return true;
        }
    return false;
}

std::vector<const char*> requiredDeviceExtensions() {
    return {VK_KHR_PUSH_DESCRIPTOR_EXTENSION_NAME};
}

}  // namespace lightscatter
