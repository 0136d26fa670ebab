#pragma once
// The froxel grid's own settings, Settings::froxels (ranges and docs: its field table,
// lightscatter::settingsFields(), names "froxels.*"), taken from `custom` with every profile. A
// "slice" here is a depth slice of the grid.
#include <cstdint>

namespace lightscatter {

struct FroxelsSettings {
    // The grid's columns are tile x tile pixels (8 is the preset "froxels-hdrp", 240x135 columns
    // at 1920x1080, 16 the preset "froxels-unreal": MethodInfo::presets, applyMethodPreset()),
    // cut into `slices` depth slices whose camera-space z grows geometrically from the near plane
    // to farDistance (metres; 0: the medium's maxDistance, or the far plane where it is nearer;
    // else above the near plane and at most maxDistance). Beyond it the grid's last slice holds:
    // in-scattering further away is lost.
    uint32_t tile = 8;
    uint32_t slices = 64;
    float farDistance = 0.0f;
    // The temporal mode engines run froxels in: each frame samples every froxel at another point
    // of its own within it (blue noise moved by a low-discrepancy step each frame) and blends its
    // in-scattering with the frame before's, reprojected to where that froxel was and clamped to
    // the range of this frame's froxels around it: new = lerp(this frame's, history,
    // historyWeight) where the history covers the froxel; in a frame where the camera moved, with
    // a memory (1 / (1 - historyWeight) frames) 2.5 times shorter, so that the history is
    // resampled fewer times (0.9 becomes 0.75). A light that moved or turned by more than a
    // degree since the frame before drops the history, as a camera cut does. The one case
    // where a frame's output depends on earlier frames; FrameDescription::resetHistory starts it
    // anew (a camera cut). The history is two grid-sized float32 3D images, the plugin's memory,
    // kept across frames by its render graph.
    bool temporal = false;
    float historyWeight = 0.9f;
    // With `temporal`: frames in which neither the camera nor a light changed since the frame
    // before refine the image finer than a froxel, as TAA upsampling does. The whole grid's columns
    // step across a froxel from frame to frame (a low-discrepancy sequence), and each pixel
    // gathers the Lin of the column nearest it, weighed by its distance to that column's ray. A
    // frame in which the camera moved keeps the temporal mode as above; one in which only a light
    // changed takes each froxel at its centre, as the plain grid. Each pixel adds to the grid's
    // fetch the detail it gathered (carried from where the frame before saw its surface, less the
    // further it moved), fading only as far as the fetch's own change hides, and while the camera
    // moves it keeps gathering this frame's nearest column: the image neither jumps to the grid's
    // when a motion starts nor flickers more than the plain grid while it lasts. The grid (the
    // history the next moving frame blends with, and FrameDescription::volumeOut's) stays as the
    // last frame that moved left it. What it gains, measured: docs/methods.md, "Still frames
    // refined per pixel".
    // Costs two screen-sized float32 RGBA images (the plugin's memory), a second integration of
    // the grid in a still frame, and the apply's five more fetches a pixel there (eight in a frame
    // that moved); refused without `temporal`.
    bool pixelHistory = false;
};

}  // namespace lightscatter
