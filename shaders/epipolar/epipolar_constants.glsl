// Epipolar's own constants (epipolar_constants_fields.h, std140), beside the frame's (frame.glsl):
// the light's, or in a cube face's passes the face's.
#ifndef LS_EPIPOLAR_CONSTANTS_GLSL
#define LS_EPIPOLAR_CONSTANTS_GLSL
#include "bindings.h"

layout(std140, set = 0, binding = LS_BINDING_EPIPOLAR) uniform EpipolarConstants {
#define LS_VEC4 vec4
#include "epipolar_constants_fields.h"
#undef LS_VEC4
} epipolar;

#endif
