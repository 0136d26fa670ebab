// How a frame's settings are made from its profile and FrameDescription::custom: every field is the
// engine's but the profile's sizes. The merge starts from custom, so a field added to Settings is
// the engine's without a word; this test fails if it ever is not.
#include <gtest/gtest.h>

#include <cstring>
#include <type_traits>

#include <lightscatter/lightscatter.h>
#include "settings_checks.h"

using lightscatter::Profile;
using lightscatter::Settings;

namespace {

// The profile's sizes of `from`, copied into `to`.
void copyProfileSizes(Settings& to, const Settings& from) {
    to.slices = from.slices;
    to.samplesPerSlice = from.samplesPerSlice;
    to.shadowMapSize = from.shadowMapSize;
    to.planeCount = from.planeCount;
    to.planeTarget = from.planeTarget;
}

}  // namespace

TEST(SettingsMerge, EveryFieldButTheProfileSizesIsTheEngines) {
    static_assert(std::is_trivially_copyable_v<Settings>);
    // A custom no default resembles: every byte of it 0x5A (never read as a value, only copied).
    Settings custom;
    std::memset(static_cast<void*>(&custom), 0x5A, sizeof custom);
    for (Profile p : {Profile::HighQuality, Profile::Balanced, Profile::HighPerformance,
                      Profile::LowHighQuality, Profile::LowBalanced, Profile::LowHighPerformance}) {
        Settings merged = lightscatter::detail::mergedSettings(p, custom);
        const Settings profile = lightscatter::profileSettings(p);
        EXPECT_EQ(merged.slices, profile.slices) << lightscatter::profileName(p);
        EXPECT_EQ(merged.samplesPerSlice, profile.samplesPerSlice);
        EXPECT_EQ(merged.shadowMapSize, profile.shadowMapSize);
        EXPECT_EQ(merged.planeCount, profile.planeCount);
        EXPECT_EQ(merged.planeTarget, profile.planeTarget);
        copyProfileSizes(merged, custom);
        EXPECT_EQ(std::memcmp(static_cast<const void*>(&merged), static_cast<const void*>(&custom),
                              sizeof custom),
                  0)
            << lightscatter::profileName(p)
            << ": a field of custom did not reach the frame's settings";
    }
    Settings asGiven = lightscatter::detail::mergedSettings(Profile::Custom, custom);
    EXPECT_EQ(std::memcmp(static_cast<const void*>(&asGiven), static_cast<const void*>(&custom),
                          sizeof custom),
              0);
}

// The test above would pass for a merge that copies nothing at all if the profile's sizes were
// the only difference: a custom with the defaults' values shows the profile's sizes do change.
TEST(SettingsMerge, TheProfileDecidesItsSizes) {
    Settings custom;
    custom.slices = 8;
    custom.fixup = false;
    const Settings merged = lightscatter::detail::mergedSettings(Profile::HighQuality, custom);
    EXPECT_EQ(merged.slices, 2048u);
    EXPECT_FALSE(merged.fixup);
}
