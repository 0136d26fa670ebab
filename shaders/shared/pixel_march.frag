#version 450
#extension GL_GOOGLE_include_directive : require
// Seed 000's starting point: a pixel marches its own ray through every shadow-map texel it
// crosses. Brute force runs it on every pixel (the on-GPU reference the other methods are compared
// with); the epipolar fix-up on the pixels its unwarp could not serve, with an optional step cap,
// compositing what it marches into the engine's color (LS_COMPOSITE) as the unwarp does. With
// LS_NO_SHADOW_MAP (and LS_LIGHT_COLOR) it marches an unshadowed light whose color varies along
// the ray, a piece per row or column of the color's texels crossed.
#include "camera.glsl"
layout(binding = LS_BINDING_DEPTH) uniform sampler2D depthBuffer;  // the engine's depth
#if defined(LS_CUBE_SHADOW) && LS_CUBE_SHADOW
layout(binding = LS_BINDING_SHADOW_MAP) uniform sampler2DArray shadowMap;  // a point light's six cube faces
#elif defined(LS_NO_SHADOW_MAP) && LS_NO_SHADOW_MAP
#else
layout(binding = LS_BINDING_SHADOW_MAP) uniform sampler2D shadowMap;
#endif
#if LS_NEEDS_TABLE
layout(binding = LS_BINDING_POINT_TABLE) uniform sampler2D pointTable;
#endif
#if LS_LIGHT_COLOR
layout(binding = LS_BINDING_LIGHT_COLOR) uniform sampler2D lightColorMap;
#endif
#include "march.glsl"
#if defined(LS_COMPOSITE) && LS_COMPOSITE
#include "composite_into.glsl"
// The stencil test before the shader: a fragment that fails it must not store (late tests would
// run the shader, stores and all, for every pixel).
layout(early_fragment_tests) in;
#define LS_PIXEL_MARCH_COMPOSITES 1
#else
#define LS_PIXEL_MARCH_COMPOSITES 0
layout(location = 0) out vec4 outInscatter;
#endif
#define LS_UINT uint
layout(push_constant) uniform Push {
#include "pixel_march_push_fields.h"
} pc;
#undef LS_UINT

void main() {
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    vec3 v = pixelRayDirection(pixel);
    float S = rayLength(pixelCameraZ(depthBuffer, pixel), v);
#if defined(LS_CUBE_SHADOW) && LS_CUBE_SHADOW
    vec3 lin = marchRayCube(frame.cameraPos.xyz, v, S, pc.maxSteps);
#else
    vec3 lin = marchRay(frame.cameraPos.xyz, v, S, pc.maxSteps);
#endif
#if defined(LS_COMPOSITE) && LS_COMPOSITE
    compositeInto(pixel, lin, S, pc.addOnly != 0u);
#else
    outInscatter = vec4(storedLin(lin), 1.0);
#endif
}
