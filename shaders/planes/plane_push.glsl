// The planes' per-frame placement (passes/planes/plane_geometry.h, PlanePush), pushed each
// frame: where the planes are, how much of Lin each one carries, and the noise's scroll.
#ifndef LS_PLANE_PUSH_GLSL
#define LS_PLANE_PUSH_GLSL

#define LS_MAT4 mat4
#define LS_VEC4 vec4
#define LS_INIT(x)
layout(push_constant) uniform PlanePush {
#include "plane_push_fields.h"
} placement;
#undef LS_MAT4
#undef LS_VEC4
#undef LS_INIT

#endif
