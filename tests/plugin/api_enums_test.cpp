// The API's entry points that take a public enum outside a frame (issue #42): a value cast from an
// integer that names no enumerator is refused naming the argument, as a frame's fields are
// (api_hostile_gpu_test.cpp); before, budget() and profileSettings() took Profile 99 for Custom.
#include <gtest/gtest.h>

#include <functional>
#include <string>

#include <lightscatter/lightscatter.h>

// A namespace of its own: the test files are compiled in batches (unity build).
namespace api_enums_test {
namespace {

template <class Enum>
Enum bad(int value) {
    return static_cast<Enum>(value);
}

std::string refusal(const std::function<void()>& call) {
    try {
        call();
    } catch (const lightscatter::InvalidInput& e) {
        return e.what();
    }
    return "(accepted)";
}

using lightscatter::BudgetLight;
using lightscatter::LightType;
using lightscatter::Method;
using lightscatter::Profile;

TEST(ApiEnums, BudgetRefusesEnumsOutOfRange) {
    const std::string profile = refusal([] { lightscatter::budget(bad<Profile>(99), 64, 64, 64); });
    EXPECT_NE(profile.find("budget profile = 99: not a Profile value"), std::string::npos)
        << profile;
    const std::string type = refusal([] {
        lightscatter::budget(Profile::Balanced, 64, 64, 64,
                             {BudgetLight{LightType::Spot, true, Method::Epipolar},
                              BudgetLight{bad<LightType>(7), true, Method::Epipolar}});
    });
    EXPECT_NE(type.find("budget lights[1].type = 7: not a LightType value"), std::string::npos)
        << type;
    const std::string method = refusal([] {
        lightscatter::budget(Profile::Balanced, 64, 64, 64,
                             {BudgetLight{LightType::Spot, true, bad<Method>(42)}});
    });
    EXPECT_NE(method.find("budget lights[0].method = 42: not a Method value"), std::string::npos)
        << method;
    lightscatter::Settings custom;
    custom.shadowFilter = bad<lightscatter::ShadowFilter>(3);
    const std::string filter = refusal(
        [&] { lightscatter::budget(Profile::Custom, 64, 64, 64, {BudgetLight{}}, &custom); });
    EXPECT_NE(filter.find("shadowFilter = 3"), std::string::npos) << filter;
}

TEST(ApiEnums, ProfileSettingsRefusesAProfileOutOfRange) {
    const std::string r = refusal([] { lightscatter::profileSettings(bad<Profile>(99)); });
    EXPECT_NE(r.find("profile = 99: not a Profile value"), std::string::npos) << r;
    EXPECT_EQ(refusal([] { lightscatter::profileSettings(Profile::Custom); }), "(accepted)");
}

TEST(ApiEnums, ShaftIntensityRefusesEnumsOutOfRange) {
    const lightscatter::Medium medium;
    const lightscatter::ShaftGoal goal;
    const std::string type =
        refusal([&] { lightscatter::shaftIntensity(bad<LightType>(7), medium, goal); });
    EXPECT_NE(type.find("shaftIntensity: type = 7: not a LightType value"), std::string::npos)
        << type;
    lightscatter::Medium hazy;
    hazy.phase = bad<lightscatter::MiePhase>(9);
    const std::string phase =
        refusal([&] { lightscatter::shaftIntensity(LightType::Spot, hazy, goal); });
    EXPECT_NE(phase.find("shaftIntensity: medium.phase = 9: not a MiePhase value"),
              std::string::npos)
        << phase;
    EXPECT_EQ(refusal([&] { lightscatter::shaftIntensity(LightType::Spot, medium, goal); }),
              "(accepted)");
}

TEST(ApiEnums, CheckSettingsRefusesEveryChoiceOutOfRange) {
    for (const lightscatter::SettingsField& f : lightscatter::settingsFields()) {
        if (f.kind != lightscatter::SettingsField::Kind::Choice) continue;
        lightscatter::Settings s;
        f.set(s, static_cast<double>(f.choices.size()) + 2.0, 0);
        const std::string r = refusal([&] { lightscatter::checkSettings(s); });
        EXPECT_NE(r.find("custom." + f.name + " = "), std::string::npos) << f.name << ": " << r;
    }
}

}  // namespace
}  // namespace api_enums_test
