#pragma once
// The engine's Settings: merged with the profile's, checked, and handed to the methods in their
// terms.
#include <string>

#include <lightscatter/lightscatter.h>
#include "shared/light_setup.h"

namespace lightscatter::detail {

// The settings a frame runs with: `custom`, with the profile's sizes where the profile is not
// Custom (Settings' comments say which fields those are).
Settings mergedSettings(Profile profile, const Settings& custom);
// `s` with the profile's sizes (its slices, samplesPerSlice, shadowMapSize, planeCount and
// planeTarget); Custom leaves it as it is.
Settings withProfileSizes(Settings s, Profile profile);
void checkSettings(const Settings& s, const std::string& at = "custom");

// The settings' part the methods read, in their terms, into `s` (a light with a shadow map of
// `shadowMapSize`, 0 without one).
void applySettings(ls::LightSetup& s, const Settings& settings, uint32_t shadowMapSize);

}  // namespace lightscatter::detail
