// Method and profile names (the command line's contract).
#include <lightscatter/lightscatter.h>
#include "method_units.h"

namespace lightscatter {
namespace {

constexpr const char* kAutoName = "auto";

// Names a method had before, still parsed so that command lines and files written with them keep
// working; methodName() and methodNames() give only the current ones. "slices" was the planes
// method's name until "slice" came to mean an epipolar line (and, in froxels, a depth slice of the
// grid), never a plane.
struct FormerName {
    const char* name;
    Method method;
};
constexpr FormerName kFormerNames[] = {{"slices", Method::Planes}};

struct ProfileRow {
    Profile profile;
    const char* name;
};

// The sizes each profile decides are the fields' own (SettingsField::profileValues).
constexpr ProfileRow kProfiles[] = {
    {Profile::HighQuality, "high-quality"},
    {Profile::Balanced, "balanced"},
    {Profile::HighPerformance, "high-performance"},
    {Profile::LowHighQuality, "low-high-quality"},
    {Profile::LowBalanced, "low-balanced"},
    {Profile::LowHighPerformance, "low-high-performance"},
    {Profile::Custom, "custom"},
};

}  // namespace

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

std::vector<const char*> requiredDeviceExtensions() {
    return {VK_KHR_PUSH_DESCRIPTOR_EXTENSION_NAME};
}

}  // namespace lightscatter
