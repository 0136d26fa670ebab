// Epipolar's own constants (epipolar_constants_fields.h, std140), beside the frame's (frame.glsl):
// the light's, or in a cube face's passes the face's.
#ifndef LS_EPIPOLAR_CONSTANTS_GLSL
#define LS_EPIPOLAR_CONSTANTS_GLSL
#include "epipolar_bindings.h"
#include "frame.glsl"

layout(std140, set = 0, binding = LS_BINDING_EPIPOLAR) uniform EpipolarConstants {
#define LS_VEC4 vec4
#include "epipolar_constants_fields.h"
#undef LS_VEC4
} epipolar;

// World -> clip of the shadow map the pass reads. With LS_CUBE_SHADOW the pass reads one face of a
// point light's cube, as a spot light's map: the face's matrix, from the frame's six.
#if defined(LS_CUBE_SHADOW) && LS_CUBE_SHADOW
mat4 shadowViewProj() { return frame.cubeFaceViewProj[int(epipolar.cubeFace.x)]; }
#else
mat4 shadowViewProj() { return frame.lightViewProj; }
#endif

// Whether the samples carry the shadowed fraction (ratio mode) rather than Lin. A point or spot
// light in a non-uniform medium carries Lin whatever the settings (interpolatesLin in
// epipolar_constants.h), which the specialisation constants already say: its variants hold no
// ratio-mode code, which lavapipe would run untaken.
bool carriesShadowedFraction() {
    if (kMedia != 0 && kLightType != LIGHT_DIRECTIONAL) return false;
    return epipolar.marching.y > 0.5;
}

#endif
