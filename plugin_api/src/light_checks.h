#pragma once
// A light of the frame (its parameters, its shadow map and light color, its own settings) checked
// and added to the frame's part of a setup.
#include <string>

#include <lightscatter/lightscatter.h>
#include "frame_setup.h"

namespace lightscatter::detail {

// How the engine named a light's fields: `light`, `shadowMap`, `lightColor` and `custom` for a
// frame that gave `light`, lights[i].light ... lights[i].settings (or `custom` without own
// settings) for the list.
struct LightPaths {
    std::string light = "light", shadowMap = "shadowMap", lightColor = "lightColor",
                settings = "custom";
};

// `setup` holds the frame's part (setupFrameWide); `withImages` false skips the image handles.
void setupLight(ls::LightSetup& setup, const LightInput& light, const LightPaths& paths,
                bool withImages = true);

}  // namespace lightscatter::detail
