// The slice planes' per-frame placement (passes/slices/slice_geometry.h, SlicePush), pushed each
// frame: where the planes are, how much of Lin each one carries, and the noise's scroll.
#ifndef LS_SLICE_PUSH_GLSL
#define LS_SLICE_PUSH_GLSL

#define LS_MAT4 mat4
#define LS_VEC4 vec4
#define LS_INIT(x)
layout(push_constant) uniform SlicePush {
#include "slice_push_fields.h"
} slice;
#undef LS_MAT4
#undef LS_VEC4
#undef LS_INIT

#endif
