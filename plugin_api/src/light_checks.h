#pragma once
// A light of the frame (its parameters, its shadow map and light color, its own settings) checked
// and added to the frame's part of a setup.
#include <string>

#include <lightscatter/lightscatter.h>
#include "frame_setup.h"

namespace lightscatter::detail {

// `setup` holds the frame's part (setupFramePart); `withImages` false skips the image handles.
void setupLight(ls::LightSetup& setup, const LightInput& light, const LightPaths& paths,
                bool withImages = true);

}  // namespace lightscatter::detail
