#include "enum_checks.h"

#include <cstdint>
#include <vector>

#include "field_checks.h"

namespace lightscatter::detail {
namespace {

// One message for every enum: the value as the integer it is (its name would be "unknown"), and
// what it may be.
[[noreturn]] void notA(const std::string& field, int64_t value, const char* type,
                       const std::vector<std::string>& names) {
    std::string list;
    for (size_t i = 0; i < names.size(); ++i)
        list += (i == 0 ? "" : i + 1 == names.size() ? " or " : ", ") + names[i];
    fail(field + " = " + std::to_string(value) + ": not a " + type + " value (must be " + list +
         ")");
}

template <class Enum>
int64_t raw(Enum e) {
    return static_cast<int64_t>(e);
}

}  // namespace

void checkMethod(Method m, const std::string& field) {
    if (parseMethod(methodName(m)) == m) return;
    notA(field, raw(m), "Method", methodNames());
}

void checkProfile(Profile p, const std::string& field) {
    if (parseProfile(profileName(p)) == p) return;
    notA(field, raw(p), "Profile", profileNames());
}

void checkLightType(LightType t, const std::string& field) {
    if (t == LightType::Directional || t == LightType::Spot || t == LightType::Point) return;
    notA(field, raw(t), "LightType", {"Directional", "Spot", "Point"});
}

void checkRangeFalloff(RangeFalloff f, const std::string& field) {
    if (f == RangeFalloff::Cut || f == RangeFalloff::Window) return;
    notA(field, raw(f), "RangeFalloff", {"Cut", "Window"});
}

void checkMiePhase(MiePhase p, const std::string& field) {
    if (p == MiePhase::CornetteShanks || p == MiePhase::Isotropic || p == MiePhase::Hazy) return;
    notA(field, raw(p), "MiePhase", {"CornetteShanks", "Isotropic", "Hazy"});
}

}  // namespace lightscatter::detail
