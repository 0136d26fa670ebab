// What each method is and takes, and every field of Settings, from the registry: the methods'
// own descriptions, capabilities, field tables and presets.
#include <lightscatter/lightscatter.h>
#include "method_units.h"
#include "registry/method_registry.h"
#include "shared/settings_table.h"

namespace lightscatter {
namespace {

MethodInfo infoOf(Method method, const ls::MethodUnit& unit) {
    const ls::MethodCaps c = unit.caps();
    MethodInfo i;
    i.method = method;
    i.name = unit.name();
    i.description = unit.description();
    i.directional = c.directional;
    i.spot = c.spot;
    i.point = c.point;
    i.shadowMap = c.shadowMap;
    i.cubeShadow = c.cubeShadow;
    i.lightColor = c.lightColor;
    i.unshadowedLightColor = c.unshadowedLightColor;
    i.noise = c.noise;
    i.simplifiedModel = c.simplifiedModel;
    i.skipsShadowSampling = c.skipsShadowSampling;
    i.readsOccluders = c.readsOccluders;
    i.media = c.media;
    i.onePerFrame = c.onePerFrame;
    i.exportsVolume = c.exportsVolume;
    i.keepsHistory = c.keepsHistory;
    i.countsSteps = c.countsSteps;
    i.profileSized = c.profileSized;
    i.settings = unit.settingsFields();
    i.presets = unit.presets();
    return i;
}

}  // namespace

const std::vector<MethodInfo>& methodInfo() {
    static const std::vector<MethodInfo> all = [] {
        std::vector<MethodInfo> v;
        const auto& units = ls::methodRegistry();
        for (size_t i = 0; i < units.size(); ++i)
            v.push_back(infoOf(static_cast<Method>(i), *units[i]));
        return v;
    }();
    return all;
}

const std::vector<SettingsField>& settingsFields() {
    static const std::vector<SettingsField> all = [] {
        std::vector<SettingsField> v = ls::sharedSettingsFields();
        for (const MethodInfo& m : methodInfo())
            v.insert(v.end(), m.settings.begin(), m.settings.end());
        return v;
    }();
    return all;
}

const SettingsField* findSettingsField(const std::string& name) {
    for (const SettingsField& f : settingsFields())
        if (f.name == name) return &f;
    for (const SettingsField& f : settingsFields())
        for (const std::string& former : f.formerNames)
            if (former == name) return &f;
    return nullptr;
}

std::optional<Method> applyMethodPreset(const std::string& name, Settings& settings) {
    for (const MethodInfo& m : methodInfo())
        for (const MethodPreset& p : m.presets)
            if (p.name == name) {
                p.apply(settings);
                return m.method;
            }
    return std::nullopt;
}

}  // namespace lightscatter
