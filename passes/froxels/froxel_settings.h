#pragma once
// The froxel grid (the method froxels), as its nodes take it: its size, and how far its slices
// reach.
#include <cstdint>

namespace ls {

struct FroxelSettings {
    bool operator==(const FroxelSettings&) const = default;
    uint32_t tile = 8;           // pixels per froxel on x and y
    uint32_t slices = 64;        // depth slices
    float farDistance = 0.0f;    // metres; 0: the medium's maxDistance (and the camera's far plane)
    bool temporal = false;       // jittered samples blended with the reprojected history
    float historyWeight = 0.9f;  // the history's share
    bool pixelHistory = false;   // still frames gathered per pixel (FroxelApplyInputs)
};

}  // namespace ls
