// The viewer's "save settings" against the command its message gives: every field at each end of
// its range (and of its slider), under auto and every method, is saved as what ran and read back
// by `view SCENE --method M --profile custom --settings FILE` to the same settings; what the
// plugin refuses is not saved, and the message says so (issue #42: FLT_MAX was saved as
// 3.4028235e+38 and refused as not finite, and the noise edited under a method that ignores it was
// saved and then refused by that command).
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include "command_options.h"
#include "settings_fields.h"
#include "settings_panel.h"

namespace {

namespace fs = std::filesystem;
using Kind = host::SettingField::Kind;

// The values a field is tried at: its bounds (the float past an exclusive one, FLT_MAX for
// "finite"), 0 where 0 turns it off, its slider's ends, every choice, both booleans; and the value
// past its upper bound, which a script's step may save before the frame that refuses it.
std::vector<double> extremes(const host::SettingField& f) {
    const double kFloatMax = std::numeric_limits<float>::max();
    switch (f.kind) {
        case Kind::Boolean:
            return {0.0, 1.0};
        case Kind::Choice: {
            std::vector<double> all;
            for (size_t i = 0; i < f.choices.size(); ++i) all.push_back(double(i));
            return all;
        }
        case Kind::Whole:
            if (f.max < 4294967295.0) return {f.min, f.max, f.sliderMin, f.sliderMax, f.max + 1};
            return {f.min, f.max, f.sliderMin, f.sliderMax};
        case Kind::Number:
        case Kind::Vector4: {
            const float lo = f.minExclusive
                                 ? std::nextafter(float(f.min), std::numeric_limits<float>::max())
                                 : float(std::max(f.min, -kFloatMax));
            std::vector<double> v{lo, std::min(f.max, kFloatMax), f.sliderMin, f.sliderMax};
            if (f.zeroIsOff) v.push_back(0.0);
            if (f.max < kFloatMax)
                v.push_back(std::nextafter(float(f.max), std::numeric_limits<float>::infinity()));
            return v;
        }
    }
    return {};
}

std::vector<std::string> words(const std::string& line) {
    std::istringstream in(line);
    std::vector<std::string> out;
    for (std::string w; in >> w;) out.push_back(w);
    return out;
}

TEST(SettingsRoundTrip, WhatThePanelSavesTheCommandItGivesReadsBack) {
    const fs::path dir =
        fs::temp_directory_path() / ("settings_round_trip_" + std::to_string(::getpid()));
    fs::create_directories(dir);
    const std::string file = (dir / "saved.json").string();
    std::vector<lightscatter::Method> methods{lightscatter::Method::Auto};
    for (const lightscatter::MethodInfo& m : lightscatter::methodInfo())
        methods.push_back(m.method);
    const host::SettingsPanel panel;
    size_t saved = 0, refused = 0;
    for (const lightscatter::Method method : methods)
        for (const host::SettingField& f : host::settingFields())
            for (const double value : extremes(f)) {
                SCOPED_TRACE(std::string(lightscatter::methodName(method)) + " " + f.name + " = " +
                             std::to_string(value));
                host::RenderOptions o;
                o.method = method;
                o.profile = lightscatter::Profile::Custom;
                for (int c = 0; c < (f.kind == Kind::Vector4 ? 4 : 1); ++c)
                    host::setFieldValue(o.custom, f, value, c);
                fs::remove(file);
                const std::string message = panel.save(o, file);
                const lightscatter::Settings ran = host::SettingsPanel::effective(host::asRun(o));
                bool pluginTakesIt = true;
                try {
                    lightscatter::checkSettings(ran);
                } catch (const lightscatter::InvalidInput&) {
                    pluginTakesIt = false;
                }
                if (!pluginTakesIt) {
                    EXPECT_EQ(message.rfind("not saved: ", 0), 0u) << message;
                    EXPECT_FALSE(fs::exists(file));
                    ++refused;
                    continue;
                }
                const std::string lead = "wrote " + file + ": lightscatter view SCENE ";
                ASSERT_EQ(message.rfind(lead, 0), 0u) << message;
                host::Args args(words(message.substr(lead.size())));
                host::SceneOptions read;
                try {
                    read = host::takeSceneOptions(args, nullptr);
                } catch (const std::exception& e) {
                    ADD_FAILURE() << message << " is refused: " << e.what();
                    continue;
                }
                args.finish();
                EXPECT_EQ(read.render.method, method);
                EXPECT_EQ(host::settingsFileText(host::SettingsPanel::effective(read.render)),
                          host::settingsFileText(ran));
                ++saved;
            }
    fs::remove_all(dir);
    // Most ends are valid ones; the rest (a slider's end off a power of two, ...) are refused.
    EXPECT_GT(saved, 1000u);
    EXPECT_GT(refused, 0u);
}

// A field edited under a method that ignores it is saved as the frame ran it: the noise under
// epipolar is off in the file, and on under planes, which honours it.
TEST(SettingsRoundTrip, AnIgnoredSettingIsSavedAsItRan) {
    const std::string file =
        (fs::temp_directory_path() / ("ignored_" + std::to_string(::getpid()) + ".json")).string();
    host::RenderOptions o;
    o.profile = lightscatter::Profile::Custom;
    o.custom.noiseAmplitude = 0.5f;
    for (const auto& [method, amplitude] :
         {std::pair{lightscatter::Method::Epipolar, 0.0f}, {lightscatter::Method::Planes, 0.5f}}) {
        o.method = method;
        const std::string message = host::SettingsPanel().save(o, file);
        EXPECT_NE(message.find(std::string("--method ") + lightscatter::methodName(method)),
                  std::string::npos)
            << message;
        host::Args args({"--method", lightscatter::methodName(method), "--profile", "custom",
                         "--settings", file});
        EXPECT_EQ(host::takeSceneOptions(args, nullptr).render.custom.noiseAmplitude, amplitude);
    }
    fs::remove(file);
}

}  // namespace
