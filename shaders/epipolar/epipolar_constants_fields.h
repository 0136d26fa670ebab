// The fields of EpipolarConstants, the constants only epipolar's passes read, written once for both
// languages as the frame constants' are (shaders/shared/frame_constants_fields.h):
// epipolar_constants.glsl declares its std140 uniform block with them,
// passes/epipolar/epipolar_constants.h its C++ struct, each defining LS_VEC4 before including this.
// Only vec4 members: std140 then places every member where the C++ struct does, and
// epipolar_constants.h checks the size of the whole.
LS_VEC4 sampling;  // x: slices, y: samples per slice, z: initial step, w: refinement threshold
// x: min/max tree levels, y: 1 when samples carry the shadowed fraction instead of Lin, z: the
// in-scattering refinement threshold (0: off), w: the fix-up's max steps (0: all)
LS_VEC4 marching;
LS_VEC4 unwarp;  // x: bilateral threshold, yzw: -
// x: the faces of a point light's cube whose frustum reaches the view, one bit per face in Vulkan's
// order (+X bit 0, -X, +Y, -Y, +Z, -Z bit 5); 63 for a light without a cube. yzw: -
LS_VEC4 cubeFaces;
// The border the lines leave by, in NDC (lo.xy, hi.xy): the centres of the outer pixels of the
// light's screen rectangle (passes/epipolar/screen_share.h), the whole screen's shrunk boundary
// where its rays may cross every pixel
LS_VEC4 bounds;
// x: the march's phases P (its order, marchTexel in epipolar_constants.glsl; 1: a sample's own
// texel), y: its phase blocks per row (marchBlocksPerRow in epipolar_constants.h), z: 1 where the
// first march takes the samples of the tiles from the refinement's list (marchesFromList in
// epipolar_constants.h), w: -
LS_VEC4 march;
// The slices the light's lines take of those its border is divided into (y, a quarter per edge, in
// the border's order): x, the first; the light's own count is sampling.x. Where that is a part of
// the border (a spot seen from outside its cone, a light off the screen:
// passes/epipolar/screen_share.h), z: how many of them a lit pixel may read, from the light's slice
// w on, the wedge a later light's unwarp and fix-up draw; z is 0 where they are the whole border.
LS_VEC4 window;
