// How a frame's settings are made from its profile and FrameDescription::custom
// (lightscatter::profileSettings(profile, custom)): every field is the engine's but those the
// profile decides (SettingsField::profileSized). The merge starts from custom, so a field added to
// a table is the engine's without a word; this test fails if it ever is not.
#include <gtest/gtest.h>

#include <cstring>
#include <type_traits>

#include <lightscatter/lightscatter.h>

using lightscatter::Profile;
using lightscatter::Settings;

namespace {

// The fields the profile decides, copied from `from` into `to`.
void copyProfileSized(Settings& to, const Settings& from) {
    for (const lightscatter::SettingsField& f : lightscatter::settingsFields())
        if (f.profileSized) f.set(to, f.get(from, 0), 0);
}

}  // namespace

TEST(SettingsMerge, EveryFieldButTheProfileSizedOnesIsTheEngines) {
    static_assert(std::is_trivially_copyable_v<Settings>);
    // A custom no default resembles: every byte of it 0x5A (never read as a value, only copied).
    Settings custom;
    std::memset(static_cast<void*>(&custom), 0x5A, sizeof custom);
    for (Profile p : {Profile::HighQuality, Profile::Balanced, Profile::HighPerformance,
                      Profile::LowHighQuality, Profile::LowBalanced, Profile::LowHighPerformance}) {
        Settings merged = lightscatter::profileSettings(p, custom);
        const Settings profile = lightscatter::profileSettings(p);
        EXPECT_EQ(merged.epipolar.slices, profile.epipolar.slices) << lightscatter::profileName(p);
        EXPECT_EQ(merged.epipolar.samplesPerSlice, profile.epipolar.samplesPerSlice);
        EXPECT_EQ(merged.shadowMapSize, profile.shadowMapSize);
        EXPECT_EQ(merged.planes.count, profile.planes.count);
        EXPECT_EQ(merged.planes.target, profile.planes.target);
        copyProfileSized(merged, custom);
        EXPECT_EQ(std::memcmp(static_cast<const void*>(&merged), static_cast<const void*>(&custom),
                              sizeof custom),
                  0)
            << lightscatter::profileName(p)
            << ": a field of custom did not reach the frame's settings";
    }
    Settings asGiven = lightscatter::profileSettings(Profile::Custom, custom);
    EXPECT_EQ(std::memcmp(static_cast<const void*>(&asGiven), static_cast<const void*>(&custom),
                          sizeof custom),
              0);
}

// The test above would pass for a merge that copies nothing at all if the profile-sized fields
// were the only difference: a custom with the defaults' values shows the profile does change them.
TEST(SettingsMerge, TheProfileDecidesItsFields) {
    Settings custom;
    custom.epipolar.slices = 8;
    custom.epipolar.fixup = false;
    const Settings merged = lightscatter::profileSettings(Profile::HighQuality, custom);
    EXPECT_EQ(merged.epipolar.slices, 2048u);
    EXPECT_FALSE(merged.epipolar.fixup);
}

// The profiles' values are seed 000's (epipolar's sizes and the shadow map) and ours (the planes).
TEST(SettingsMerge, TheProfilesValuesAreTheSeeds) {
    struct Row {
        Profile profile;
        uint32_t slices, samples, shadowMap, planes;
        lightscatter::PlaneTarget target;
    };
    using T = lightscatter::PlaneTarget;
    for (const Row& r : {Row{Profile::HighQuality, 2048, 1024, 4096, 256, T::Float32},
                         Row{Profile::Balanced, 1024, 1024, 2048, 128, T::Float16},
                         Row{Profile::HighPerformance, 1024, 512, 1024, 100, T::Rgba8Channels},
                         Row{Profile::LowHighQuality, 1024, 1024, 2048, 128, T::Float16},
                         Row{Profile::LowBalanced, 512, 512, 1024, 64, T::Float16},
                         Row{Profile::LowHighPerformance, 512, 256, 512, 48, T::Rgba8Channels}}) {
        const Settings s = lightscatter::profileSettings(r.profile);
        EXPECT_EQ(s.epipolar.slices, r.slices) << lightscatter::profileName(r.profile);
        EXPECT_EQ(s.epipolar.samplesPerSlice, r.samples);
        EXPECT_EQ(s.shadowMapSize, r.shadowMap);
        EXPECT_EQ(s.planes.count, r.planes);
        EXPECT_EQ(s.planes.target, r.target);
    }
    // Custom: the defaults as they are.
    const Settings custom = lightscatter::profileSettings(Profile::Custom);
    EXPECT_EQ(custom.epipolar.slices, Settings{}.epipolar.slices);
}
