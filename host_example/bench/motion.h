#pragma once
// The slow motions of a benchmark's temporal-stability mode: the light or the camera moves a
// little every frame, and the frames are compared with the float64 reference at the same poses.
#include <string>
#include <vector>

#include "scene/scene.h"

namespace host::bench {

// Still: nothing moves, so that what a method that keeps history (froxels' temporal mode) settles
// on after the warm-up is judged on the same frames as its motions.
enum class MotionKind { Light, Camera, Still };

struct Motion {
    std::vector<MotionKind> what;  // each measured on its own, from the scene's own pose
    int frames = 60;
    // A sun turns towards the camera's right (its shafts sweep across the view); a spot or point
    // light moves to the camera's right. Only the scene's first light moves.
    double lightDegreesPerFrame = 0.1;
    double lightMetresPerFrame = 0.02;
    // The camera moves to its right and turns about its up vector (towards its right).
    double cameraMetresPerFrame = 0.02;
    double cameraDegreesPerFrame = 0.1;
};

[[nodiscard]] const char* motionName(MotionKind what);

// The scene at frame `frame` of the motion; frame 0 is `start` itself.
[[nodiscard]] SceneDesc poseAt(const SceneDesc& start, MotionKind what, const Motion& motion,
                               int frame);

}  // namespace host::bench
